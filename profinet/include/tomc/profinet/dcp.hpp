#pragma once
// PROFINET DCP (Discovery and basic Configuration Protocol, IEC 61158-6-10 "DCP"): Identify (all or by name
// of station), the device's Identify response, Set of name of station / IP suite with its response, and
// Hello. Layout as in Wireshark's packet-pn-dcp.c and p-net's pf_dcp.c: after the FrameID a 10-byte header
// (ServiceID, ServiceType, Xid, ResponseDelay, DCPDataLength), then blocks Option, Suboption, DCPBlockLength,
// value, each padded to an even length. Responses and Hello put a 2-byte BlockInfo before the value, Set
// requests a 2-byte BlockQualifier; Identify filters have neither.
// Not in the cyclic path: names are std::string.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tomc/profinet/ethernet.hpp"
#include "tomc/profinet/frame_id.hpp"

namespace tomc::profinet {

using Ipv4Address = std::array<std::uint8_t, 4>;

enum class DcpService : std::uint8_t { kGet = 3, kSet = 4, kIdentify = 5, kHello = 6 };
enum class DcpServiceType : std::uint8_t { kRequest = 0, kSuccess = 1, kNotSupported = 5 };

// Option / Suboption pairs used here.
namespace dcp_option {
inline constexpr std::uint16_t kIpParameter = 0x0102;
inline constexpr std::uint16_t kDeviceVendor = 0x0201;
inline constexpr std::uint16_t kNameOfStation = 0x0202;
inline constexpr std::uint16_t kDeviceId = 0x0203;
inline constexpr std::uint16_t kDeviceRole = 0x0204;
inline constexpr std::uint16_t kControlResponse = 0x0504;
inline constexpr std::uint16_t kDeviceInitiative = 0x0601;
inline constexpr std::uint16_t kAllSelector = 0xFFFF;
}  // namespace dcp_option

// Largest name of station (IEC 61158-6-10: 240 octets).
inline constexpr std::size_t kMaxNameOfStation = 240;

struct IpSuite {
  Ipv4Address address{};
  Ipv4Address netmask{};
  Ipv4Address gateway{};
  bool operator==(const IpSuite&) const = default;
};

// What a device says about itself (Identify response, Hello) or what a Set request sets.
struct DcpDeviceFields {
  std::optional<std::string> name_of_station;
  std::optional<IpSuite> ip;
  std::optional<std::string> vendor;  // DeviceVendorValue, e.g. the product family
  std::optional<std::uint16_t> vendor_id;
  std::optional<std::uint16_t> device_id;
  std::optional<std::uint8_t> device_role;         // bit 0 IO device, bit 1 IO controller
  std::optional<std::uint16_t> device_initiative;  // bit 0: the device sends Hello at start-up
  bool operator==(const DcpDeviceFields&) const = default;
};

// One entry of a Set response (Control/Response block): which option it answers and the BlockError
// (0 no error, 1 option unsupported, 2 suboption unsupported or no data set, 3 suboption not set, ...).
struct DcpSetResult {
  std::uint16_t option = 0;
  std::uint8_t error = 0;
  bool operator==(const DcpSetResult&) const = default;
};

struct DcpMessage {
  std::uint16_t frame_id = kFrameIdDcpIdentifyRequest;
  DcpService service = DcpService::kIdentify;
  DcpServiceType type = DcpServiceType::kRequest;
  std::uint32_t xid = 0;
  std::uint16_t response_delay = 0;  // Identify request: ResponseDelayFactor; elsewhere reserved 0
  // Identify request: the filter (no field at all means the All selector). Set request: the fields to set.
  // Identify response / Hello: the device's fields.
  DcpDeviceFields fields;
  bool permanent = false;           // Set request: BlockQualifier bit 0 (store the value across power cycles)
  std::uint16_t ip_block_info = 0;  // responses: bit 0 IP set, bit 1 by DHCP, bit 7 address conflict
  std::vector<DcpSetResult> results;  // Set response
  bool operator==(const DcpMessage&) const = default;
};

// Writes Ethernet header, FrameID, DCP header and blocks; pads to the Ethernet minimum.
void encode(const EthernetHeader& header, const DcpMessage& message, WireWriter& out);
// Decodes the part after the Ethernet header (starting at the FrameID). Blocks of options not listed above
// are skipped; a block that leaves DCPDataLength, a name longer than 240 octets or a truncated value fail.
DcpMessage decode_dcp(WireReader& in);

// Convenience builders for the controller and the device.
DcpMessage dcp_identify_request(std::uint32_t xid, std::optional<std::string> name_of_station);
DcpMessage dcp_set_request(std::uint32_t xid, std::optional<std::string> name_of_station,
                           std::optional<IpSuite> ip, bool permanent);

}  // namespace tomc::profinet
