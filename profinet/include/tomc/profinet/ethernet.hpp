#pragma once
// The Ethernet II header of every PROFINET RT frame: destination, source, an optional IEEE 802.1Q tag
// (RT frames carry priority 6, alarms 5/6, DCP none) and the EtherType 0x8892, followed by the FrameID
// that selects the protocol (frame_id.hpp).

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "tomc/profinet/wire.hpp"

namespace tomc::profinet {

using MacAddress = std::array<std::uint8_t, 6>;

inline constexpr std::uint16_t kEtherTypeProfinet = 0x8892;
inline constexpr std::uint16_t kEtherTypeVlan = 0x8100;
// DCP multicast addresses (IEC 61158-6-10, DCP): Identify requests and Hello.
inline constexpr MacAddress kDcpIdentifyMulticast{0x01, 0x0E, 0xCF, 0x00, 0x00, 0x00};
inline constexpr MacAddress kDcpHelloMulticast{0x01, 0x0E, 0xCF, 0x00, 0x00, 0x01};
// VLAN priorities of the frame kinds (IEC 61158-6-10 Annex: RT_CLASS_1 data 6, alarm high 6, alarm low 5).
inline constexpr std::uint8_t kPriorityCyclic = 6;
inline constexpr std::uint8_t kPriorityAlarmHigh = 6;
inline constexpr std::uint8_t kPriorityAlarmLow = 5;

struct VlanTag {
  std::uint8_t priority = 0;  // PCP, 0..7
  std::uint16_t vlan_id = 0;  // 0: priority tagged only
  bool operator==(const VlanTag&) const = default;
};

struct EthernetHeader {
  MacAddress destination{};
  MacAddress source{};
  std::optional<VlanTag> vlan;
  std::uint16_t ether_type = kEtherTypeProfinet;
  bool operator==(const EthernetHeader&) const = default;
};

// Smallest Ethernet frame without FCS: shorter frames are padded with zeros by the encoders.
inline constexpr std::size_t kMinimumFrameBytes = 60;

void encode(const EthernetHeader& header, WireWriter& out) noexcept;
// Reads the header; a frame whose EtherType (after an optional tag) is not PROFINET fails with
// kWrongEtherType.
EthernetHeader decode_ethernet(WireReader& in) noexcept;
// Pads the frame written so far with zeros up to the Ethernet minimum.
void pad_to_minimum(WireWriter& out) noexcept;

std::string to_string(const MacAddress& mac);
std::optional<MacAddress> parse_mac(std::string_view text);

}  // namespace tomc::profinet
