#include "tomc/profinet/rpc.hpp"

#include <cstdio>

namespace tomc::profinet {

namespace {
constexpr std::uint8_t kRpcVersion = 4;
constexpr std::uint8_t kDrepLittleEndian = 0x10;  // integer representation nibble; ASCII characters
}  // namespace

std::string to_string(const Uuid& uuid) {
  char text[37];
  std::snprintf(text, sizeof text, "%08x-%04x-%04x-%02x%02x-%02x%02x%02x%02x%02x%02x", uuid.data1, uuid.data2,
                uuid.data3, uuid.data4[0], uuid.data4[1], uuid.data4[2], uuid.data4[3], uuid.data4[4],
                uuid.data4[5], uuid.data4[6], uuid.data4[7]);
  return text;
}

void encode(const Uuid& uuid, WireWriter& out, bool little_endian) noexcept {
  out.u32(uuid.data1, little_endian);
  out.u16(uuid.data2, little_endian);
  out.u16(uuid.data3, little_endian);
  out.bytes(uuid.data4);
}

Uuid decode_uuid(WireReader& in, bool little_endian) noexcept {
  Uuid uuid;
  uuid.data1 = in.u32(little_endian);
  uuid.data2 = in.u16(little_endian);
  uuid.data3 = in.u16(little_endian);
  in.bytes(uuid.data4.data(), uuid.data4.size());
  return uuid;
}

Uuid pnio_object_uuid(std::uint16_t instance, std::uint16_t device_id, std::uint16_t vendor_id) noexcept {
  Uuid uuid{0xDEA00000, 0x6C97, 0x11D1, {0x82, 0x71, 0, 0, 0, 0, 0, 0}};
  uuid.data4[2] = static_cast<std::uint8_t>(instance >> 8);
  uuid.data4[3] = static_cast<std::uint8_t>(instance);
  uuid.data4[4] = static_cast<std::uint8_t>(device_id >> 8);
  uuid.data4[5] = static_cast<std::uint8_t>(device_id);
  uuid.data4[6] = static_cast<std::uint8_t>(vendor_id >> 8);
  uuid.data4[7] = static_cast<std::uint8_t>(vendor_id);
  return uuid;
}

namespace {

void encode_header(const RpcHeader& header, std::uint16_t body_length, WireWriter& out) noexcept {
  const bool le = header.little_endian;
  out.u8(kRpcVersion);
  out.u8(static_cast<std::uint8_t>(header.packet_type));
  out.u8(header.flags1);
  out.u8(header.flags2);
  out.u8(le ? kDrepLittleEndian : 0);
  out.u8(0);  // floating point: IEEE
  out.u8(0);  // reserved
  out.u8(0);  // serial high
  encode(header.object, out, le);
  encode(header.interface, out, le);
  encode(header.activity, out, le);
  out.u32(header.server_boot, le);
  out.u32(header.interface_version, le);
  out.u32(header.sequence_number, le);
  out.u16(header.opnum, le);
  out.u16(header.interface_hint, le);
  out.u16(header.activity_hint, le);
  out.u16(body_length, le);
  out.u16(header.fragment_number, le);
  out.u8(0);  // authentication protocol: none
  out.u8(0);  // serial low
}

}  // namespace

void encode_rpc(const RpcHeader& header, std::uint32_t args_maximum, PnioStatus status,
                std::span<const std::uint8_t> blocks, WireWriter& out) noexcept {
  const bool le = header.little_endian;
  const bool has_ndr =
      header.packet_type == RpcPacketType::kRequest || header.packet_type == RpcPacketType::kResponse;
  encode_header(header, static_cast<std::uint16_t>(has_ndr ? kNdrHeaderBytes + blocks.size() : 0), out);
  if (!has_ndr) return;
  const auto length = static_cast<std::uint32_t>(blocks.size());
  out.u32(header.packet_type == RpcPacketType::kRequest ? args_maximum : status.value(), le);
  out.u32(length, le);                                                                 // ArgsLength
  out.u32(header.packet_type == RpcPacketType::kRequest ? args_maximum : length, le);  // MaximumCount
  out.u32(0, le);                                                                      // Offset
  out.u32(length, le);                                                                 // ActualCount
  out.bytes(blocks);
}

RpcPacket decode_rpc(WireReader& in) noexcept {
  RpcPacket packet;
  RpcHeader& h = packet.header;
  const std::uint8_t version = in.u8();
  const std::uint8_t type = in.u8();
  h.flags1 = in.u8();
  h.flags2 = in.u8();
  const std::uint8_t drep = in.u8();
  in.skip(3);
  if (!in.ok()) return packet;
  if (version != kRpcVersion || (type & 0x1F) > 10) {
    in.fail(ProfinetError::kBadValue);
    return packet;
  }
  h.packet_type = static_cast<RpcPacketType>(type & 0x1F);
  h.little_endian = (drep & 0xF0) == kDrepLittleEndian;
  const bool le = h.little_endian;
  h.object = decode_uuid(in, le);
  h.interface = decode_uuid(in, le);
  h.activity = decode_uuid(in, le);
  h.server_boot = in.u32(le);
  h.interface_version = in.u32(le);
  h.sequence_number = in.u32(le);
  h.opnum = in.u16(le);
  h.interface_hint = in.u16(le);
  h.activity_hint = in.u16(le);
  h.body_length = in.u16(le);
  h.fragment_number = in.u16(le);
  in.skip(2);
  if (!in.ok()) return packet;
  if (h.body_length > in.remaining()) {
    in.fail(ProfinetError::kTruncated);
    return packet;
  }
  if (h.packet_type != RpcPacketType::kRequest && h.packet_type != RpcPacketType::kResponse) {
    const bool refusal = h.packet_type == RpcPacketType::kReject || h.packet_type == RpcPacketType::kFault;
    if (refusal && h.body_length >= 4) {
      packet.reject_status = in.u32(le);
      in.skip(h.body_length - 4u);
    } else {
      in.skip(h.body_length);
    }
    return packet;
  }
  if (h.body_length < kNdrHeaderBytes) {
    in.fail(ProfinetError::kBadBlockLength);
    return packet;
  }
  const std::uint32_t first = in.u32(le);
  const std::uint32_t args_length = in.u32(le);
  in.skip(8);  // MaximumCount, Offset
  const std::uint32_t actual_count = in.u32(le);
  if (h.packet_type == RpcPacketType::kRequest) {
    packet.args_maximum = first;
  } else {
    packet.status = PnioStatus::from(first);
  }
  if (args_length != actual_count || args_length > h.body_length - kNdrHeaderBytes) {
    in.fail(ProfinetError::kBadBlockLength);
    return packet;
  }
  packet.blocks = in.view(args_length);
  in.skip(h.body_length - kNdrHeaderBytes - args_length);
  return packet;
}

void encode_rpc_reject(const RpcHeader& request, std::uint32_t nca_status, WireWriter& out) noexcept {
  RpcHeader header = request;
  header.packet_type = RpcPacketType::kReject;
  header.flags1 = 0;
  encode_header(header, 4, out);
  out.u32(nca_status, header.little_endian);
}

}  // namespace tomc::profinet
