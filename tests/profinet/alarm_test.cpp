// RTA alarm frames (IEC 61158-6-10 Alarm): a diagnosis alarm of a drive, its acknowledge, the transport ACK;
// malformed frames; no allocation (the controller acknowledges from its cyclic thread).
#include <gtest/gtest.h>

#include <array>

#include "counting_allocator.hpp"
#include "sample_frames.hpp"
#include "tomc/profinet/alarm.hpp"

namespace pn = tomc::profinet;

namespace {

const pn::EthernetHeader kToController{{0x02, 0, 0, 0, 0, 1}, {0x02, 0, 0, 0, 0, 2}, pn::VlanTag{6, 0}};

using pn::testing::diagnosis_alarm;

std::size_t be16_at(const std::array<std::uint8_t, 256>& b, std::size_t at) {
  return static_cast<std::size_t>(b[at] << 8 | b[at + 1]);
}

}  // namespace

// IEC 61158-6-10 RTA DATA with an AlarmNotificationHigh block (FrameID 0xFC01, PDUType 0x11), decision I4
// (big-endian).
TEST(Alarm, NotificationLayoutAndRoundTrip) {
  std::array<std::uint8_t, 256> bytes{};
  std::size_t written = 0;
  const pn::RtaFrame alarm = diagnosis_alarm();
  ASSERT_EQ(pn::encode(kToController, alarm, bytes, written), pn::ProfinetError::kNone);
  // After the tagged Ethernet header (18) and FrameID 0xFC01: endpoints 1 and 3, PDUType DATA version 1
  // (0x11), AddFlags WindowSize 1 + TACK (0x11), SendSeqNum 0, AckSeqNum 0xFFFE.
  EXPECT_EQ(be16_at(bytes, 18), 0xFC01u);
  EXPECT_EQ(be16_at(bytes, 20), 1u);
  EXPECT_EQ(be16_at(bytes, 22), 3u);
  EXPECT_EQ(bytes[24], 0x11);
  EXPECT_EQ(bytes[25], 0x11);
  EXPECT_EQ(be16_at(bytes, 28), 0xFFFEu);
  // VarPartLen = AlarmNotificationHigh block: 4 + 2 (version) + 2+4+2+2+4+4+2 + 2 (USI) + 6.
  EXPECT_EQ(be16_at(bytes, 30), 4u + 2 + 20 + 2 + 6);
  EXPECT_EQ(be16_at(bytes, 32), 0x0001u);
  EXPECT_EQ(written, 32u + 34);

  pn::RtaFrame decoded;
  ASSERT_EQ(pn::decode_rta(std::span(bytes).first(written), decoded), pn::ProfinetError::kNone);
  EXPECT_EQ(decoded.block.sequence_number(), 5);
  EXPECT_EQ(decoded.block.subslot, 2);
  EXPECT_EQ(decoded.block.user_structure_identifier, 0x8000);
  EXPECT_EQ(decoded.block.payload_length, 6);
  EXPECT_EQ(decoded.block.payload[5], 0x09);
  EXPECT_TRUE(decoded.block.high_priority);
  EXPECT_FALSE(decoded.block.is_ack);
}

// IEC 61158-6-10 AlarmAckHigh (0x8001) mirrors the notification's type, API, slot, subslot, specifier.
TEST(Alarm, AcknowledgeMirrorsTheNotification) {
  const pn::RtaFrame alarm = diagnosis_alarm();
  pn::RtaFrame ack;
  ack.frame_id = alarm.frame_id;
  ack.destination_endpoint = alarm.source_endpoint;
  ack.source_endpoint = alarm.destination_endpoint;
  ack.send_sequence = 0;
  ack.ack_sequence = alarm.send_sequence;
  ack.has_block = true;
  ack.block = pn::alarm_ack_for(alarm.block);
  std::array<std::uint8_t, 256> bytes{};
  std::size_t written = 0;
  ASSERT_EQ(pn::encode(kToController, ack, bytes, written), pn::ProfinetError::kNone);
  EXPECT_EQ(be16_at(bytes, 32), 0x8001u);      // AlarmAckHigh
  EXPECT_EQ(be16_at(bytes, 34), 2u + 12 + 4);  // version, type/API/slot/subslot/specifier, PNIOStatus
  pn::RtaFrame decoded;
  ASSERT_EQ(pn::decode_rta(std::span(bytes).first(written), decoded), pn::ProfinetError::kNone);
  EXPECT_TRUE(decoded.block.is_ack);
  EXPECT_EQ(decoded.block.specifier, alarm.block.specifier);
  EXPECT_TRUE(decoded.block.status.ok());

  // The transport ACK has no block and is padded to the Ethernet minimum.
  pn::RtaFrame transport;
  transport.pdu_type = pn::RtaPduType::kAck;
  transport.tack = false;
  ASSERT_EQ(pn::encode({}, transport, bytes, written), pn::ProfinetError::kNone);
  EXPECT_EQ(written, pn::kMinimumFrameBytes);
  ASSERT_EQ(pn::decode_rta(std::span(bytes).first(written), decoded), pn::ProfinetError::kNone);
  EXPECT_EQ(decoded.pdu_type, pn::RtaPduType::kAck);
  EXPECT_FALSE(decoded.has_block);
}

// IEC 61158-6-10 RTA (version, VarPartLen, block type, FrameID checked); ARCHITECTURE-GUIDE §7 (outside
// bytes never crash).
TEST(Alarm, MalformedFramesAreErrors) {
  std::array<std::uint8_t, 256> bytes{};
  std::size_t written = 0;
  ASSERT_EQ(pn::encode(kToController, diagnosis_alarm(), bytes, written), pn::ProfinetError::kNone);
  pn::RtaFrame decoded;
  auto version = bytes;
  version[24] = 0x21;
  EXPECT_EQ(pn::decode_rta(std::span(version).first(written), decoded), pn::ProfinetError::kBadValue);
  auto var_part = bytes;
  var_part[30] = 0x10;
  EXPECT_EQ(pn::decode_rta(std::span(var_part).first(written), decoded), pn::ProfinetError::kTruncated);
  auto block = bytes;
  block[33] = 0x08;  // IODWriteReqHeader inside an alarm
  EXPECT_EQ(pn::decode_rta(std::span(block).first(written), decoded), pn::ProfinetError::kWrongBlockType);
  auto id = bytes;
  id[19] = 0x02;
  EXPECT_EQ(pn::decode_rta(std::span(id).first(written), decoded), pn::ProfinetError::kWrongFrameId);
  for (std::size_t n = 0; n < 32; ++n) {
    EXPECT_NE(pn::decode_rta(std::span(bytes).first(n), decoded), pn::ProfinetError::kNone) << n;
  }
  pn::RtaFrame too_big = diagnosis_alarm();
  too_big.block.payload_length = pn::kMaxAlarmPayload + 1;
  EXPECT_EQ(pn::encode(kToController, too_big, bytes, written), pn::ProfinetError::kTooMany);
}

// Decision I3 (RTA alarms: fixed-capacity structures, no allocation).
TEST(Alarm, EncodeAndDecodeDoNotAllocate) {
  std::array<std::uint8_t, 256> bytes{};
  const pn::RtaFrame alarm = diagnosis_alarm();
  pn::RtaFrame decoded;
  std::uint32_t errors = 0;
  const std::uint64_t before = tomc::testing::allocation_count();
  for (int i = 0; i < 10000; ++i) {
    std::size_t written = 0;
    errors += pn::encode(kToController, alarm, bytes, written) != pn::ProfinetError::kNone;
    errors += pn::decode_rta(std::span(bytes).first(written), decoded) != pn::ProfinetError::kNone;
  }
  EXPECT_EQ(tomc::testing::allocation_count() - before, 0u);
  EXPECT_EQ(errors, 0u);
}
