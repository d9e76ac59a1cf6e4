#pragma once
// DCP for commissioning (IEC 61158-6-10 "DCP"), what an engineering tool does before any AR: Identify All
// lists every station on the wire, Set NameOfStation names one by its MAC. Socket-free like the rest of
// tomc::profinet; `tomc gateway --identify` / `--set-name` put these frames on a raw socket
// (tools/gateway/include/tomc/gateway/commissioning.hpp). Not in the cyclic path.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/profinet/dcp.hpp"

namespace tomc::profinet {

// A station as its Identify response describes it.
struct DcpStation {
  MacAddress mac{};
  DcpDeviceFields fields;
  std::uint16_t ip_block_info = 0;  // bit 0 IP set, bit 1 by DHCP, bit 7 address conflict
};

// One Identify All: the request, then every answer to it, one station per MAC (a repeated answer replaces
// the earlier one), in MAC order.
class DcpScan {
 public:
  DcpScan(MacAddress own_mac, std::uint32_t xid) : own_mac_(own_mac), xid_(xid) {}
  // Identify with the All selector to the DCP Identify multicast address.
  std::vector<std::uint8_t> request() const;
  // True if `frame` is a successful Identify response to this request (kept); anything else is ignored.
  bool on_frame(std::span<const std::uint8_t> frame);
  const std::vector<DcpStation>& stations() const noexcept { return stations_; }

 private:
  MacAddress own_mac_;
  std::uint32_t xid_;
  std::vector<DcpStation> stations_;
};

// Set NameOfStation of the device with MAC `device` (unicast), stored across power cycles when `permanent`;
// with `ip`, the IP suite in the same request (IP parameter block, decision I37).
std::vector<std::uint8_t> dcp_set_name_request(const MacAddress& own_mac, const MacAddress& device,
                                               std::uint32_t xid, const std::string& name, bool permanent,
                                               const std::optional<IpSuite>& ip = std::nullopt);
// The device's answer to that request: "" when it took the name (and, with `ip_set`, the IP suite),
// otherwise why not ("the device refused the name: BlockError 3", "the device refused the IP suite:
// BlockError 3"); nullopt when `frame` is not that answer (another xid, sender or service).
std::optional<std::string> dcp_set_name_result(std::span<const std::uint8_t> frame, const MacAddress& device,
                                               std::uint32_t xid, bool ip_set = false);
// "192.168.0.10" -> its address; nullopt for anything else (four decimal numbers 0..255, no leading '+').
std::optional<Ipv4Address> parse_ipv4(std::string_view text);

// The NameOfStation a DCP Hello announces (a device starting up, IEC 61158-6-10 DCP Hello.req); nullopt for
// any other frame or a Hello without a name. The running gateway tries that device at once (decision I36).
std::optional<std::string> dcp_hello_name(std::span<const std::uint8_t> frame);

// One line for a list: "drive-1  02:00:00:00:01:01  10.0.0.11/255.255.255.0  VendorID 0x002A DeviceID
// 0x0C01  tomc emulated drive"; "(no name)" / "(no IP)" when the station has none (as from the factory).
std::string describe(const DcpStation& station);

}  // namespace tomc::profinet
