#pragma once
// Connectionless DCE/RPC (C706 ch. 12) as PROFINET IO uses it on UDP port 34964 (IEC 61158-6-10 "RPC"):
// the 80-byte header, whose integers and the first three UUID fields follow the sender's data
// representation (drep byte 0, bit 4: little-endian), then the NDR header of the PNIO operation
// (ArgsMaximum/PNIOStatus, ArgsLength, MaximumCount, Offset, ActualCount; also in drep order), then the PNIO
// blocks, which are always big-endian (blocks.hpp). Field order as in p-net's pf_get_dce_rpc_header and
// Wireshark's packet-dcerpc.c.

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "tomc/profinet/wire.hpp"

namespace tomc::profinet {

inline constexpr std::uint16_t kPnioUdpPort = 34964;
inline constexpr std::size_t kRpcHeaderBytes = 80;
inline constexpr std::size_t kNdrHeaderBytes = 20;

struct Uuid {
  std::uint32_t data1 = 0;
  std::uint16_t data2 = 0;
  std::uint16_t data3 = 0;
  std::array<std::uint8_t, 8> data4{};
  bool operator==(const Uuid&) const = default;
};

std::string to_string(const Uuid& uuid);
void encode(const Uuid& uuid, WireWriter& out, bool little_endian = false) noexcept;
Uuid decode_uuid(WireReader& in, bool little_endian = false) noexcept;

// PNIO interfaces (IEC 61158-6-10): the device's, served by the IO device, and the controller's, served by
// the IO controller for the device's ApplicationReady and alarms over RPC.
inline constexpr Uuid kPnioDeviceInterface{
    0xDEA00001, 0x6C97, 0x11D1, {0x82, 0x71, 0x00, 0xA0, 0x24, 0x42, 0xDF, 0x7D}};
inline constexpr Uuid kPnioControllerInterface{
    0xDEA00002, 0x6C97, 0x11D1, {0x82, 0x71, 0x00, 0xA0, 0x24, 0x42, 0xDF, 0x7D}};
// The object UUID of a PNIO instance: DEA00000-6C97-11D1-8271-{instance}{device ID}{vendor ID}, each 16-bit
// field big-endian in the last six bytes (IEC 61158-6-10 "ObjectUUID"; p-net's EPM entry, Wireshark's
// packet-dcerpc-pn-io.c). A controller addresses the device's instance 1 with the VendorID/DeviceID that the
// device's DCP DeviceID block names.
Uuid pnio_object_uuid(std::uint16_t instance, std::uint16_t device_id, std::uint16_t vendor_id) noexcept;

// The NCA status of a Reject whose object UUID names no object of the server (C706 Appendix E,
// nca_s_unsupported_type: "no implementation of generic operation for object").
inline constexpr std::uint32_t kNcaUnsupportedType = 0x1C010017;

enum class RpcPacketType : std::uint8_t {
  kRequest = 0,
  kPing = 1,
  kResponse = 2,
  kFault = 3,
  kWorking = 4,
  kNoCall = 5,
  kReject = 6,
  kAck = 7,
};

enum class PnioOperation : std::uint16_t { kConnect = 0, kRelease = 1, kRead = 2, kWrite = 3, kControl = 4 };

// Flags1 bits (C706 12.5.2.8).
namespace rpc_flags {
inline constexpr std::uint8_t kLastFragment = 0x02;
inline constexpr std::uint8_t kFragment = 0x04;
inline constexpr std::uint8_t kNoFack = 0x08;
inline constexpr std::uint8_t kIdempotent = 0x20;
}  // namespace rpc_flags

struct RpcHeader {
  RpcPacketType packet_type = RpcPacketType::kRequest;
  std::uint8_t flags1 = rpc_flags::kLastFragment | rpc_flags::kIdempotent;
  std::uint8_t flags2 = 0;
  bool little_endian = true;  // drep; Linux controllers and most devices send little-endian
  Uuid object;
  Uuid interface;
  Uuid activity;
  std::uint32_t server_boot = 0;
  std::uint32_t interface_version = 1;
  std::uint32_t sequence_number = 0;
  std::uint16_t opnum = 0;
  std::uint16_t interface_hint = 0xFFFF;
  std::uint16_t activity_hint = 0xFFFF;
  std::uint16_t body_length = 0;  // set by the encoder
  std::uint16_t fragment_number = 0;
  bool operator==(const RpcHeader&) const = default;
};

// PNIOStatus (IEC 61158-6-10): ErrorCode, ErrorDecode, ErrorCode1, ErrorCode2; all zero is success.
struct PnioStatus {
  std::uint8_t error_code = 0;
  std::uint8_t error_decode = 0;
  std::uint8_t error_code1 = 0;
  std::uint8_t error_code2 = 0;
  bool ok() const noexcept {
    return error_code == 0 && error_decode == 0 && error_code1 == 0 && error_code2 == 0;
  }
  std::uint32_t value() const noexcept {
    return std::uint32_t{error_code} << 24 | std::uint32_t{error_decode} << 16 |
           std::uint32_t{error_code1} << 8 | error_code2;
  }
  static PnioStatus from(std::uint32_t value) noexcept {
    return {static_cast<std::uint8_t>(value >> 24), static_cast<std::uint8_t>(value >> 16),
            static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
  }
  bool operator==(const PnioStatus&) const = default;
};

// A PNIO RPC packet as received: the header, for requests ArgsMaximum, for responses the PNIOStatus, and the
// PNIO blocks (a view into the received bytes).
struct RpcPacket {
  RpcHeader header;
  std::uint32_t args_maximum = 0;
  PnioStatus status;
  std::uint32_t reject_status = 0;  // Reject / Fault: the NCA status of its body
  std::span<const std::uint8_t> blocks;
};

// Writes header, NDR header and the blocks. Requests carry args_maximum (the largest response the caller
// accepts); responses carry status instead. body_length is computed.
void encode_rpc(const RpcHeader& header, std::uint32_t args_maximum, PnioStatus status,
                std::span<const std::uint8_t> blocks, WireWriter& out) noexcept;
// Reads a whole UDP payload. Other packet types than request/response (ping, reject, fault, ...) decode
// their header only and have no blocks (a Reject's or Fault's status goes to reject_status); a version other
// than 4 or an NDR length beyond the packet fails.
RpcPacket decode_rpc(WireReader& in) noexcept;
// The Reject of `request` (C706 12.5.3.7: same activity, sequence number and object; the body is the NCA
// status, in the sender's byte order).
void encode_rpc_reject(const RpcHeader& request, std::uint32_t nca_status, WireWriter& out) noexcept;

}  // namespace tomc::profinet
