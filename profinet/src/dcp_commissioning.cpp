#include "tomc/profinet/dcp_commissioning.hpp"

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace tomc::profinet {

namespace {

std::vector<std::uint8_t> encoded(const EthernetHeader& header, const DcpMessage& message) {
  std::vector<std::uint8_t> bytes(1514);
  WireWriter out(bytes);
  encode(header, message, out);
  bytes.resize(out.ok() ? out.position() : 0);
  return bytes;
}

// The DCP message of `frame` and its sender, if it decodes.
std::optional<DcpMessage> decoded(std::span<const std::uint8_t> frame, MacAddress& source) {
  WireReader in(frame);
  const EthernetHeader header = decode_ethernet(in);
  DcpMessage message = decode_dcp(in);
  if (!in.ok()) return std::nullopt;
  source = header.source;
  return message;
}

std::string dotted(const Ipv4Address& a) {
  return std::to_string(a[0]) + "." + std::to_string(a[1]) + "." + std::to_string(a[2]) + "." +
         std::to_string(a[3]);
}

std::string hex4(std::uint16_t value) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%04X", static_cast<unsigned>(value));
  return text;
}

}  // namespace

std::optional<std::string> dcp_hello_name(std::span<const std::uint8_t> frame) {
  MacAddress source{};
  const std::optional<DcpMessage> message = decoded(frame, source);
  if (!message || message->frame_id != kFrameIdDcpHello || message->service != DcpService::kHello ||
      message->type != DcpServiceType::kRequest || !message->fields.name_of_station ||
      message->fields.name_of_station->empty()) {
    return std::nullopt;
  }
  return message->fields.name_of_station;
}

std::vector<std::uint8_t> DcpScan::request() const {
  return encoded(EthernetHeader{kDcpIdentifyMulticast, own_mac_, std::nullopt},
                 dcp_identify_request(xid_, std::nullopt));
}

bool DcpScan::on_frame(std::span<const std::uint8_t> frame) {
  MacAddress source{};
  const std::optional<DcpMessage> message = decoded(frame, source);
  if (!message || message->service != DcpService::kIdentify || message->type != DcpServiceType::kSuccess ||
      message->xid != xid_) {
    return false;
  }
  DcpStation station{source, message->fields, message->ip_block_info};
  const auto at = std::lower_bound(stations_.begin(), stations_.end(), source,
                                   [](const DcpStation& s, const MacAddress& mac) { return s.mac < mac; });
  if (at != stations_.end() && at->mac == source) {
    *at = std::move(station);
  } else {
    stations_.insert(at, std::move(station));
  }
  return true;
}

std::vector<std::uint8_t> dcp_set_name_request(const MacAddress& own_mac, const MacAddress& device,
                                               std::uint32_t xid, const std::string& name, bool permanent,
                                               const std::optional<IpSuite>& ip) {
  return encoded(EthernetHeader{device, own_mac, std::nullopt}, dcp_set_request(xid, name, ip, permanent));
}

std::optional<Ipv4Address> parse_ipv4(std::string_view text) {
  Ipv4Address address{};
  std::size_t at = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    if (k > 0) {
      if (at >= text.size() || text[at] != '.') return std::nullopt;
      ++at;
    }
    unsigned value = 0;
    std::size_t digits = 0;
    for (; at < text.size() && text[at] >= '0' && text[at] <= '9' && digits < 3; ++at, ++digits)
      value = value * 10 + static_cast<unsigned>(text[at] - '0');
    if (digits == 0 || value > 255) return std::nullopt;
    address[k] = static_cast<std::uint8_t>(value);
  }
  if (at != text.size()) return std::nullopt;
  return address;
}

std::optional<std::string> dcp_set_name_result(std::span<const std::uint8_t> frame, const MacAddress& device,
                                               std::uint32_t xid, bool ip_set) {
  MacAddress source{};
  const std::optional<DcpMessage> message = decoded(frame, source);
  if (!message || source != device || message->service != DcpService::kSet || message->xid != xid ||
      message->type == DcpServiceType::kRequest) {
    return std::nullopt;
  }
  if (message->type != DcpServiceType::kSuccess) return "the device does not support DCP Set";
  // Each option set needs its own entry without error: the name, and with it the IP suite (IP parameter).
  const auto answered = [&](std::uint16_t option, const std::string& refused,
                            const std::string& missing) -> std::string {
    for (const DcpSetResult& result : message->results) {
      if (result.option != option) continue;
      return result.error == 0 ? std::string{} : refused + ": BlockError " + std::to_string(result.error);
    }
    return missing;
  };
  std::string why = answered(dcp_option::kNameOfStation, "the device refused the name",
                             "the device's Set response does not answer the name of station");
  if (why.empty() && ip_set) {
    why = answered(dcp_option::kIpParameter, "the device refused the IP suite",
                   "the device's Set response does not answer the IP suite");
  }
  return why;
}

std::string describe(const DcpStation& station) {
  const DcpDeviceFields& f = station.fields;
  std::string line = f.name_of_station && !f.name_of_station->empty() ? *f.name_of_station : "(no name)";
  line += "  " + to_string(station.mac) + "  ";
  line += f.ip && f.ip->address != Ipv4Address{} ? dotted(f.ip->address) + "/" + dotted(f.ip->netmask)
                                                 : "(no IP)";
  if (f.vendor_id || f.device_id)
    line += "  VendorID " + hex4(f.vendor_id.value_or(0)) + " DeviceID " + hex4(f.device_id.value_or(0));
  if (f.vendor && !f.vendor->empty()) line += "  " + *f.vendor;
  return line;
}

}  // namespace tomc::profinet
