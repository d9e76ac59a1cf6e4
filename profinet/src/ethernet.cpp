#include "tomc/profinet/ethernet.hpp"

#include <cstdio>

namespace tomc::profinet {

void encode(const EthernetHeader& header, WireWriter& out) noexcept {
  out.bytes(header.destination);
  out.bytes(header.source);
  if (header.vlan) {
    out.u16(kEtherTypeVlan);
    out.u16(
        static_cast<std::uint16_t>((header.vlan->priority & 0x7) << 13 | (header.vlan->vlan_id & 0x0FFF)));
  }
  out.u16(header.ether_type);
}

EthernetHeader decode_ethernet(WireReader& in) noexcept {
  EthernetHeader header;
  in.bytes(header.destination.data(), header.destination.size());
  in.bytes(header.source.data(), header.source.size());
  header.ether_type = in.u16();
  if (header.ether_type == kEtherTypeVlan) {
    const std::uint16_t tci = in.u16();
    header.vlan = VlanTag{static_cast<std::uint8_t>(tci >> 13), static_cast<std::uint16_t>(tci & 0x0FFF)};
    header.ether_type = in.u16();
  }
  if (in.ok() && header.ether_type != kEtherTypeProfinet) in.fail(ProfinetError::kWrongEtherType);
  return header;
}

void pad_to_minimum(WireWriter& out) noexcept {
  if (out.position() < kMinimumFrameBytes) out.zeros(kMinimumFrameBytes - out.position());
}

std::string to_string(const MacAddress& mac) {
  char text[18];
  std::snprintf(text, sizeof text, "%02x:%02x:%02x:%02x:%02x:%02x", mac[0], mac[1], mac[2], mac[3], mac[4],
                mac[5]);
  return text;
}

std::optional<MacAddress> parse_mac(std::string_view text) {
  if (text.size() != 17) return std::nullopt;
  MacAddress mac{};
  for (std::size_t i = 0; i < 6; ++i) {
    if (i > 0 && text[i * 3 - 1] != ':') return std::nullopt;
    unsigned value = 0;
    for (std::size_t j = 0; j < 2; ++j) {
      const char c = text[i * 3 + j];
      const int digit = c >= '0' && c <= '9'   ? c - '0'
                        : c >= 'a' && c <= 'f' ? c - 'a' + 10
                        : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                               : -1;
      if (digit < 0) return std::nullopt;
      value = value * 16 + static_cast<unsigned>(digit);
    }
    mac[i] = static_cast<std::uint8_t>(value);
  }
  return mac;
}

}  // namespace tomc::profinet
