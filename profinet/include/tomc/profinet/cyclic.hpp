#pragma once
// RT_CLASS_1 cyclic data frames (IEC 61158-6-10 "RTC": data-RTC-PDU), one layout per IOCR:
//   FrameID | C_SDU (c_sdu_length bytes: per IODataObject its data then its IOPS, per IOCS entry one
//   byte, at the frame offsets the IOCR block gave, the rest zero) | CycleCounter | DataStatus |
//   TransferStatus
// The layout is checked once at create(); encode/decode are then noexcept, allocation-free and bounded
// (the gateway's cyclic thread calls them for every device every cycle).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "tomc/profinet/ethernet.hpp"
#include "tomc/profinet/frame_id.hpp"

namespace tomc::profinet {

// C_SDU length limits of RT_CLASS_1 over Ethernet (40 keeps the frame at the 60-byte minimum).
inline constexpr std::uint16_t kMinCSduLength = 40;
inline constexpr std::uint16_t kMaxCSduLength = 1440;
inline constexpr std::size_t kMaxDataObjectsPerIocr = 32;

// IOPS / IOCS (IEC 61158-6-10 IOxS): bit 7 DataState good, bits 5-6 the instance that detected a fault.
inline constexpr std::uint8_t kIoxsGood = 0x80;
inline constexpr std::uint8_t kIoxsBad = 0x00;

// DataStatus bits (IEC 61158-6-10 APDU_Status).
namespace data_status {
inline constexpr std::uint8_t kStatePrimary = 0x01;
inline constexpr std::uint8_t kRedundancy = 0x02;
inline constexpr std::uint8_t kDataValid = 0x04;
inline constexpr std::uint8_t kProviderRun = 0x10;
inline constexpr std::uint8_t kStationProblemNormal = 0x20;  // 0: the provider reports a problem
inline constexpr std::uint8_t kIgnore = 0x80;
// Primary, valid, provider in RUN, no station problem: what a running provider sends.
inline constexpr std::uint8_t kRunning = kStatePrimary | kDataValid | kProviderRun | kStationProblemNormal;
}  // namespace data_status

struct ApduStatus {
  std::uint16_t cycle_counter = 0;  // in units of 31.25 us, advanced by send clock factor x reduction ratio
  std::uint8_t data_status = data_status::kRunning;
  std::uint8_t transfer_status = 0;
  bool operator==(const ApduStatus&) const = default;
};

// One IODataObject (submodule data + IOPS) or, with data_length 0 and is_iocs, one IOCS entry.
struct IoDataObject {
  std::uint16_t slot = 0;
  std::uint16_t subslot = 0;
  std::uint16_t frame_offset = 0;
  std::uint16_t data_length = 0;  // submodule data bytes; the IOPS follows at frame_offset + data_length
  bool operator==(const IoDataObject&) const = default;
};

struct CyclicLayout {
  std::uint16_t frame_id = kFrameIdRtClass1First;
  std::uint16_t c_sdu_length = kMinCSduLength;
  std::array<IoDataObject, kMaxDataObjectsPerIocr> data_objects{};
  std::size_t data_object_count = 0;
  std::array<IoDataObject, kMaxDataObjectsPerIocr> iocs{};  // data_length unused (0)
  std::size_t iocs_count = 0;
};

class CyclicCodec {
 public:
  CyclicCodec() noexcept = default;
  // Checks the FrameID range, the C_SDU length limits and that every data object, IOPS and IOCS lies in
  // the C_SDU without overlapping another.
  static ProfinetError create(const CyclicLayout& layout, CyclicCodec& codec) noexcept;

  const CyclicLayout& layout() const noexcept { return layout_; }
  std::size_t frame_bytes(bool vlan) const noexcept {
    return (vlan ? 18u : 14u) + 2u + layout_.c_sdu_length + 4u;
  }

  // Views into a C_SDU image of c_sdu_length bytes (index as in the layout); read_* for received images.
  std::span<std::uint8_t> data(std::span<std::uint8_t> c_sdu, std::size_t index) const noexcept;
  std::span<const std::uint8_t> read_data(std::span<const std::uint8_t> c_sdu,
                                          std::size_t index) const noexcept;
  std::uint8_t& iops(std::span<std::uint8_t> c_sdu, std::size_t index) const noexcept;
  std::uint8_t read_iops(std::span<const std::uint8_t> c_sdu, std::size_t index) const noexcept;
  std::uint8_t& iocs(std::span<std::uint8_t> c_sdu, std::size_t index) const noexcept;
  std::uint8_t read_iocs(std::span<const std::uint8_t> c_sdu, std::size_t index) const noexcept;

  // Writes the whole frame (Ethernet header, FrameID, C_SDU image, APDU status) into out.
  ProfinetError encode(const EthernetHeader& header, std::span<const std::uint8_t> c_sdu, ApduStatus status,
                       std::span<std::uint8_t> out, std::size_t& written) const noexcept;
  // Reads a received frame (from its first byte) of this IOCR: the C_SDU is copied into c_sdu
  // (c_sdu_length bytes). A frame of another FrameID fails with kWrongFrameId and leaves c_sdu untouched.
  ProfinetError decode(std::span<const std::uint8_t> frame, std::span<std::uint8_t> c_sdu,
                       ApduStatus& status) const noexcept;

 private:
  CyclicLayout layout_{};
};

// Reads only the FrameID of a received PROFINET frame (after an optional VLAN tag); 0 if it is none.
std::uint16_t peek_frame_id(std::span<const std::uint8_t> frame) noexcept;

}  // namespace tomc::profinet
