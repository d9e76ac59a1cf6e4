#pragma once
// The acyclic real-time alarm protocol (RTA, IEC 61158-6-10 "Alarm"; p-net pf_alarm.c, Wireshark
// packet-pn-rt.c/packet-dcerpc-pn-io.c): FrameID 0xFC01 (high) / 0xFE01 (low), then AlarmDstEndpoint,
// AlarmSrcEndpoint, PDUType (type | version 1 << 4), AddFlags (WindowSize 1, TACK bit 4), SendSeqNum,
// AckSeqNum, VarPartLen and, for DATA, one AlarmNotification or AlarmAck block. Allocation-free: the
// controller's cyclic thread answers alarms.

#include <array>
#include <cstdint>
#include <span>

#include "tomc/profinet/ethernet.hpp"
#include "tomc/profinet/frame_id.hpp"
#include "tomc/profinet/rpc.hpp"

namespace tomc::profinet {

enum class RtaPduType : std::uint8_t { kData = 1, kNack = 2, kAck = 3, kError = 4 };

// AlarmType (IEC 61158-6-10).
namespace alarm_type {
inline constexpr std::uint16_t kDiagnosis = 0x0001;
inline constexpr std::uint16_t kProcess = 0x0002;
inline constexpr std::uint16_t kPull = 0x0003;
inline constexpr std::uint16_t kPlug = 0x0004;
inline constexpr std::uint16_t kStatus = 0x0005;
inline constexpr std::uint16_t kDiagnosisDisappears = 0x000C;
}  // namespace alarm_type

inline constexpr std::size_t kMaxAlarmPayload = 200;  // AlarmCRBlockReq.MaxAlarmDataLength offered

// AlarmNotification (DATA from the device) or AlarmAck (DATA from the controller).
struct AlarmBlock {
  bool high_priority = false;
  bool is_ack = false;
  std::uint16_t alarm_type = alarm_type::kDiagnosis;
  std::uint32_t api = 0;
  std::uint16_t slot = 0;
  std::uint16_t subslot = 0;
  std::uint32_t module_ident = 0;     // notification only
  std::uint32_t submodule_ident = 0;  // notification only
  std::uint16_t specifier =
      0;  // bits 0-10 sequence number, 11 channel, 12 manufacturer, 13 submodule, 15 AR diag
  std::uint16_t user_structure_identifier = 0;  // notification: present when payload_length > 0
  std::array<std::uint8_t, kMaxAlarmPayload> payload{};
  std::uint16_t payload_length = 0;
  PnioStatus status;  // ack only
  std::uint16_t sequence_number() const noexcept { return specifier & 0x07FF; }
};

struct RtaFrame {
  std::uint16_t frame_id = kFrameIdAlarmLow;
  std::uint16_t destination_endpoint = 0;  // the receiver's alarm reference
  std::uint16_t source_endpoint = 0;
  RtaPduType pdu_type = RtaPduType::kData;
  bool tack = true;  // DATA: the sender wants a transport acknowledge
  std::uint16_t send_sequence = 0;
  std::uint16_t ack_sequence = 0;
  bool has_block = false;  // DATA PDUs carry one block
  AlarmBlock block;
  // ERR PDUs: why the sender ends the AR (VarPart: PNIOStatus, IEC 61158-6-10 RTA-ERR-PDU; decision I35).
  PnioStatus error;
};

// Writes the frame with its VLAN tag (priority 6 high, 5 low) and pads to the Ethernet minimum.
ProfinetError encode(const EthernetHeader& header, const RtaFrame& frame, std::span<std::uint8_t> out,
                     std::size_t& written) noexcept;
// Reads a frame from its first byte; a FrameID other than the two alarm IDs fails with kWrongFrameId.
ProfinetError decode_rta(std::span<const std::uint8_t> bytes, RtaFrame& frame) noexcept;

// The acknowledge of an alarm notification: same type, API, slot, subslot and specifier; status OK.
AlarmBlock alarm_ack_for(const AlarmBlock& notification) noexcept;

}  // namespace tomc::profinet
