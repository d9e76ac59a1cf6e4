// RT_CLASS_1 cyclic frames (IEC 61158-6-10 data-RTC-PDU): layout checks, the bytes of a telegram-1 drive's
// frame, decode of the C_SDU and APDU status, bad frames, no allocation.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "counting_allocator.hpp"
#include "tomc/profinet/cyclic.hpp"

namespace pn = tomc::profinet;

namespace {

constexpr pn::MacAddress kController{0x02, 0, 0, 0, 0, 0x01};
constexpr pn::MacAddress kDevice{0x02, 0, 0, 0, 0, 0x02};

// The input CR of a drive with telegram 1 (4 bytes ZSW1 + NIST_A): DAP, interface and port submodules
// without data (IOPS only), the telegram submodule (4 bytes + IOPS), and the IOCS for the output
// submodule (STW1 + NSOLL_A) the controller sends.
pn::CyclicLayout drive_input_layout() {
  pn::CyclicLayout layout;
  layout.frame_id = 0x8001;
  layout.c_sdu_length = 40;
  layout.data_objects[0] = {0, 1, 0, 0};
  layout.data_objects[1] = {0, 0x8000, 1, 0};
  layout.data_objects[2] = {0, 0x8001, 2, 0};
  layout.data_objects[3] = {1, 2, 3, 4};
  layout.data_object_count = 4;
  layout.iocs[0] = {1, 2, 8, 0};
  layout.iocs_count = 1;
  return layout;
}

}  // namespace

// Decisions I2/I9 (RT_CLASS_1 FrameIDs 0x8000–0xBBFF, legacy 0xC000–0xF7FF decoded; RT_CLASS_3 and
// multicast refused), IEC 61158-6-10 C_SDU layout.
TEST(Cyclic, LayoutChecks) {
  pn::CyclicCodec codec;
  EXPECT_EQ(pn::CyclicCodec::create(drive_input_layout(), codec), pn::ProfinetError::kNone);
  auto layout = drive_input_layout();
  layout.frame_id = 0x0100;  // RT_CLASS_3 (IRT): not supported
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kWrongFrameId);
  layout.frame_id = 0xBC00;  // multicast
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kWrongFrameId);
  layout.frame_id = 0xC001;  // legacy RT_CLASS_1 range: accepted
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kNone);
  layout = drive_input_layout();
  layout.c_sdu_length = 39;
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kBadValue);
  layout = drive_input_layout();
  layout.iocs[0].frame_offset = 7;  // the IOPS of the telegram submodule
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kBadBlockLength);
  layout = drive_input_layout();
  layout.data_objects[3].data_length = 40;  // leaves the C_SDU
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kBadBlockLength);
  layout = drive_input_layout();
  layout.data_object_count = pn::kMaxDataObjectsPerIocr + 1;
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kTooMany);
}

// IEC 61158-6-10 RT frame (VLAN priority 6, EtherType 0x8892, FrameID, C_SDU, APDU status), decision I4;
// ZSW1/NIST_A as spec 06 §2.1.
TEST(Cyclic, FrameBytesOfATelegram1Drive) {
  pn::CyclicCodec codec;
  ASSERT_EQ(pn::CyclicCodec::create(drive_input_layout(), codec), pn::ProfinetError::kNone);
  std::array<std::uint8_t, 40> c_sdu{};
  for (std::size_t i = 0; i < 4; ++i)
    codec.iops(c_sdu, i) = pn::kIoxsGood;
  codec.iocs(c_sdu, 0) = pn::kIoxsGood;
  const std::array<std::uint8_t, 4> zsw1_nist{0x0B, 0x37, 0x40, 0x00};  // ZSW1 0x0B37, NIST_A 100 %
  std::copy(zsw1_nist.begin(), zsw1_nist.end(), codec.data(c_sdu, 3).begin());

  std::array<std::uint8_t, 128> frame{};
  std::size_t written = 0;
  const pn::EthernetHeader header{kController, kDevice, pn::VlanTag{pn::kPriorityCyclic, 0}};
  ASSERT_EQ(codec.encode(header, c_sdu, {0x1234, pn::data_status::kRunning, 0}, frame, written),
            pn::ProfinetError::kNone);
  EXPECT_EQ(written, codec.frame_bytes(true));
  EXPECT_EQ(written, 64u);
  // VLAN tag: TPID 0x8100, priority 6 -> TCI 0xC000; then 0x8892 and the FrameID.
  const std::array<std::uint8_t, 8> tag{0x81, 0x00, 0xC0, 0x00, 0x88, 0x92, 0x80, 0x01};
  EXPECT_TRUE(std::equal(tag.begin(), tag.end(), frame.begin() + 12));
  const std::array<std::uint8_t, 9> data{0x80, 0x80, 0x80, 0x0B, 0x37, 0x40, 0x00, 0x80, 0x80};
  EXPECT_TRUE(std::equal(data.begin(), data.end(), frame.begin() + 20));
  // APDU status: CycleCounter 0x1234, DataStatus 0x35 (primary, valid, run, no problem), TransferStatus 0.
  EXPECT_EQ(frame[60], 0x12);
  EXPECT_EQ(frame[61], 0x34);
  EXPECT_EQ(frame[62], 0x35);
  EXPECT_EQ(frame[63], 0x00);

  std::array<std::uint8_t, 40> received{};
  pn::ApduStatus status;
  ASSERT_EQ(codec.decode(std::span(frame).first(written), received, status), pn::ProfinetError::kNone);
  EXPECT_EQ(received, c_sdu);
  EXPECT_EQ(codec.read_iops(received, 3), pn::kIoxsGood);
  EXPECT_EQ(codec.read_iocs(received, 0), pn::kIoxsGood);
  EXPECT_EQ(codec.read_data(received, 3)[1], 0x37);
  EXPECT_EQ(status, (pn::ApduStatus{0x1234, 0x35, 0}));
  EXPECT_EQ(pn::peek_frame_id(std::span(frame).first(written)), 0x8001);
}

// Decision I23 (a frame is offered only to the AR of its FrameID); a truncated frame is an error and leaves
// the image as it was.
TEST(Cyclic, ForeignOrShortFramesLeaveTheImageUntouched) {
  pn::CyclicCodec codec;
  ASSERT_EQ(pn::CyclicCodec::create(drive_input_layout(), codec), pn::ProfinetError::kNone);
  std::array<std::uint8_t, 40> c_sdu{};
  c_sdu.fill(0x55);
  std::array<std::uint8_t, 128> frame{};
  std::size_t written = 0;
  ASSERT_EQ(codec.encode({kController, kDevice, std::nullopt}, c_sdu, {}, frame, written),
            pn::ProfinetError::kNone);
  EXPECT_EQ(written, 60u);

  std::array<std::uint8_t, 40> image{};
  pn::ApduStatus status{7, 0, 0};
  auto other = frame;
  other[15] = 0x02;  // FrameID 0x8002
  EXPECT_EQ(codec.decode(std::span(other).first(written), image, status), pn::ProfinetError::kWrongFrameId);
  for (std::size_t n = 0; n < written; ++n) {
    EXPECT_NE(codec.decode(std::span(frame).first(n), image, status), pn::ProfinetError::kNone) << n;
  }
  auto not_profinet = frame;
  not_profinet[12] = 0x08;
  not_profinet[13] = 0x00;
  EXPECT_EQ(codec.decode(std::span(not_profinet).first(written), image, status),
            pn::ProfinetError::kWrongEtherType);
  EXPECT_EQ(pn::peek_frame_id(std::span(not_profinet).first(written)), 0);
  EXPECT_EQ(image, (std::array<std::uint8_t, 40>{}));
  EXPECT_EQ(status.cycle_counter, 7);
  // An image of the wrong size is refused before anything is read or written.
  std::array<std::uint8_t, 39> small{};
  EXPECT_EQ(codec.decode(std::span(frame).first(written), small, status), pn::ProfinetError::kBadBlockLength);
  EXPECT_EQ(codec.encode({}, small, {}, frame, written), pn::ProfinetError::kBadBlockLength);
  std::array<std::uint8_t, 59> short_out{};
  EXPECT_EQ(codec.encode({}, c_sdu, {}, short_out, written), pn::ProfinetError::kBufferTooSmall);
}

// Decision I3 (cyclic frames: fixed-capacity structures, no allocation).
TEST(Cyclic, EncodeAndDecodeDoNotAllocate) {
  pn::CyclicCodec codec;
  ASSERT_EQ(pn::CyclicCodec::create(drive_input_layout(), codec), pn::ProfinetError::kNone);
  std::array<std::uint8_t, 40> c_sdu{};
  std::array<std::uint8_t, 40> image{};
  std::array<std::uint8_t, 128> frame{};
  const pn::EthernetHeader header{kController, kDevice, pn::VlanTag{6, 0}};
  const std::uint64_t before = tomc::testing::allocation_count();
  std::uint32_t errors = 0;
  for (std::uint16_t cycle = 0; cycle < 10000; ++cycle) {
    std::size_t written = 0;
    c_sdu[4] = static_cast<std::uint8_t>(cycle);
    pn::ApduStatus status{static_cast<std::uint16_t>(cycle * 32), pn::data_status::kRunning, 0};
    errors += codec.encode(header, c_sdu, status, frame, written) != pn::ProfinetError::kNone;
    errors += codec.decode(std::span(frame).first(written), image, status) != pn::ProfinetError::kNone;
    errors += image[4] != c_sdu[4];
  }
  EXPECT_EQ(tomc::testing::allocation_count() - before, 0u);
  EXPECT_EQ(errors, 0u);
}
