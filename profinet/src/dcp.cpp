#include "tomc/profinet/dcp.hpp"

namespace tomc::profinet {

namespace {

enum class BlockPrefix { kNone, kBlockInfo, kBlockQualifier };

BlockPrefix prefix_of(const DcpMessage& message) {
  if (message.service == DcpService::kHello) return BlockPrefix::kBlockInfo;
  if (message.type != DcpServiceType::kRequest) {
    return message.service == DcpService::kSet ? BlockPrefix::kNone : BlockPrefix::kBlockInfo;
  }
  return message.service == DcpService::kSet ? BlockPrefix::kBlockQualifier : BlockPrefix::kNone;
}

template <typename WriteValue>
void put_block(WireWriter& out, std::uint16_t option, std::size_t value_bytes, BlockPrefix prefix,
               std::uint16_t prefix_value, WriteValue write_value) {
  const std::size_t length = value_bytes + (prefix == BlockPrefix::kNone ? 0 : 2);
  out.u16(option);
  out.u16(static_cast<std::uint16_t>(length));
  if (prefix != BlockPrefix::kNone) out.u16(prefix_value);
  write_value();
  if (length % 2 != 0) out.u8(0);
}

void put_ip(WireWriter& out, const IpSuite& ip) {
  out.bytes(ip.address);
  out.bytes(ip.netmask);
  out.bytes(ip.gateway);
}

void put_fields(WireWriter& out, const DcpMessage& message, BlockPrefix prefix) {
  const DcpDeviceFields& f = message.fields;
  const std::uint16_t qualifier = message.permanent ? 1 : 0;
  const std::uint16_t info = prefix == BlockPrefix::kBlockQualifier ? qualifier : 0;
  if (f.vendor) {
    put_block(out, dcp_option::kDeviceVendor, f.vendor->size(), prefix, info, [&] { out.text(*f.vendor); });
  }
  if (f.name_of_station) {
    put_block(out, dcp_option::kNameOfStation, f.name_of_station->size(), prefix, info,
              [&] { out.text(*f.name_of_station); });
  }
  if (f.vendor_id || f.device_id) {
    put_block(out, dcp_option::kDeviceId, 4, prefix, info, [&] {
      out.u16(f.vendor_id.value_or(0));
      out.u16(f.device_id.value_or(0));
    });
  }
  if (f.device_role) {
    put_block(out, dcp_option::kDeviceRole, 2, prefix, info, [&] {
      out.u8(*f.device_role);
      out.u8(0);
    });
  }
  if (f.ip) {
    const std::uint16_t ip_info = prefix == BlockPrefix::kBlockInfo ? message.ip_block_info : info;
    put_block(out, dcp_option::kIpParameter, 12, prefix, ip_info, [&] { put_ip(out, *f.ip); });
  }
  if (f.device_initiative) {
    put_block(out, dcp_option::kDeviceInitiative, 2, prefix, info, [&] { out.u16(*f.device_initiative); });
  }
}

std::string read_text(WireReader& in, std::size_t bytes) {
  const auto view = in.view(bytes);
  return {reinterpret_cast<const char*>(view.data()), view.size()};
}

void read_block(WireReader& in, DcpMessage& message, std::uint16_t option, std::size_t length,
                BlockPrefix prefix) {
  DcpDeviceFields& f = message.fields;
  // A Set response carries only Control/Response blocks, everything else only device fields.
  const bool set_response = message.service == DcpService::kSet && message.type != DcpServiceType::kRequest;
  if (set_response != (option == dcp_option::kControlResponse)) {
    in.skip(length);
    return;
  }
  if (option == dcp_option::kControlResponse) {
    if (length < 3) return in.fail(ProfinetError::kBadBlockLength);
    DcpSetResult result;
    result.option = in.u16();
    result.error = in.u8();
    in.skip(length - 3);
    if (message.results.size() >= 16) return in.fail(ProfinetError::kTooMany);
    message.results.push_back(result);
    return;
  }
  if (option == dcp_option::kAllSelector) {
    in.skip(length);
    return;
  }
  std::uint16_t prefix_value = 0;
  if (prefix != BlockPrefix::kNone) {
    if (length < 2) return in.fail(ProfinetError::kBadBlockLength);
    prefix_value = in.u16();
    length -= 2;
  }
  const auto need = [&](std::size_t bytes) {
    if (length != bytes) in.fail(ProfinetError::kBadBlockLength);
    return in.ok();
  };
  switch (option) {
    case dcp_option::kNameOfStation:
      if (length > kMaxNameOfStation) return in.fail(ProfinetError::kBadValue);
      f.name_of_station = read_text(in, length);
      break;
    case dcp_option::kDeviceVendor:
      if (length > kMaxNameOfStation) return in.fail(ProfinetError::kBadValue);
      f.vendor = read_text(in, length);
      break;
    case dcp_option::kDeviceId:
      if (!need(4)) return;
      f.vendor_id = in.u16();
      f.device_id = in.u16();
      break;
    case dcp_option::kDeviceRole:
      if (!need(2)) return;
      f.device_role = in.u8();
      in.skip(1);
      break;
    case dcp_option::kIpParameter: {
      if (!need(12)) return;
      IpSuite ip;
      in.bytes(ip.address.data(), 4);
      in.bytes(ip.netmask.data(), 4);
      in.bytes(ip.gateway.data(), 4);
      f.ip = ip;
      if (prefix == BlockPrefix::kBlockInfo) message.ip_block_info = prefix_value;
      break;
    }
    case dcp_option::kDeviceInitiative:
      if (!need(2)) return;
      f.device_initiative = in.u16();
      break;
    default:
      in.skip(length);
      return;
  }
  if (prefix == BlockPrefix::kBlockQualifier) message.permanent = (prefix_value & 1) != 0;
}

}  // namespace

void encode(const EthernetHeader& header, const DcpMessage& message, WireWriter& out) {
  encode(header, out);
  out.u16(message.frame_id);
  out.u8(static_cast<std::uint8_t>(message.service));
  out.u8(static_cast<std::uint8_t>(message.type));
  out.u32(message.xid);
  out.u16(message.response_delay);
  const std::size_t length_at = out.position();
  out.u16(0);
  const std::size_t blocks_start = out.position();
  const BlockPrefix prefix = prefix_of(message);
  if (message.service == DcpService::kSet && message.type != DcpServiceType::kRequest) {
    for (const DcpSetResult& result : message.results) {
      put_block(out, dcp_option::kControlResponse, 3, BlockPrefix::kNone, 0, [&] {
        out.u16(result.option);
        out.u8(result.error);
      });
    }
  } else if (message.service == DcpService::kIdentify && message.type == DcpServiceType::kRequest &&
             message.fields == DcpDeviceFields{}) {
    put_block(out, dcp_option::kAllSelector, 0, BlockPrefix::kNone, 0, [] {});
  } else {
    put_fields(out, message, prefix);
  }
  out.patch_u16(length_at, static_cast<std::uint16_t>(out.position() - blocks_start));
  pad_to_minimum(out);
}

DcpMessage decode_dcp(WireReader& in) {
  DcpMessage message;
  message.frame_id = in.u16();
  if (in.ok() && classify_frame_id(message.frame_id) != FrameKind::kDcp) {
    in.fail(ProfinetError::kWrongFrameId);
    return message;
  }
  const std::uint8_t service = in.u8();
  const std::uint8_t type = in.u8();
  message.xid = in.u32();
  message.response_delay = in.u16();
  const std::uint16_t data_length = in.u16();
  if (!in.ok()) return message;
  if (service < 3 || service > 6 || (type != 0 && type != 1 && type != 5)) {
    in.fail(ProfinetError::kBadValue);
    return message;
  }
  message.service = static_cast<DcpService>(service);
  message.type = static_cast<DcpServiceType>(type);
  if (data_length > in.remaining()) {
    in.fail(ProfinetError::kTruncated);
    return message;
  }
  const BlockPrefix prefix = prefix_of(message);
  const std::size_t end = in.position() + data_length;
  while (in.ok() && in.position() + 4 <= end) {
    const std::uint16_t option = in.u16();
    const std::uint16_t length = in.u16();
    if (in.position() + length > end) {
      in.fail(ProfinetError::kBadBlockLength);
      break;
    }
    read_block(in, message, option, length, prefix);
    if (length % 2 != 0 && in.position() < end) in.skip(1);
  }
  return message;
}

DcpMessage dcp_identify_request(std::uint32_t xid, std::optional<std::string> name_of_station) {
  DcpMessage message;
  message.xid = xid;
  message.response_delay = 1;  // answer at once (delay factor 1: no spreading)
  message.fields.name_of_station = std::move(name_of_station);
  return message;
}

DcpMessage dcp_set_request(std::uint32_t xid, std::optional<std::string> name_of_station,
                           std::optional<IpSuite> ip, bool permanent) {
  DcpMessage message;
  message.frame_id = kFrameIdDcpGetSet;
  message.service = DcpService::kSet;
  message.xid = xid;
  message.fields.name_of_station = std::move(name_of_station);
  message.fields.ip = ip;
  message.permanent = permanent;
  return message;
}

}  // namespace tomc::profinet
