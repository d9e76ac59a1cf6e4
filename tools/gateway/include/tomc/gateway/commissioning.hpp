#pragma once
// DCP commissioning over a raw socket, for `tomc gateway --identify` and `tomc gateway --set-name`
// (docs/profinet-gateway.md "Commissioning", decision I32): the protocol steps are tomc::profinet's
// `DcpScan` and `dcp_set_name_*` (tested in memory); these functions only add the socket and bounded waits.
// Not used by the running gateway, which identifies its devices by name (start_up.hpp).

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "tomc/profinet/dcp_commissioning.hpp"

namespace tomc::profinet_gateway {

// Every station that answers a DCP Identify All on `interface` within `wait`, in MAC order. Throws
// std::runtime_error when the raw socket cannot be opened (no such interface, no CAP_NET_RAW).
std::vector<profinet::DcpStation> identify_all(const std::string& interface, std::chrono::milliseconds wait);

// DCP Set NameOfStation of the device with `mac` (`permanent`: kept across power cycles), sent up to three
// times with `wait` for the answer each: "" when the device answered that it took the name, otherwise why
// not. Throws like identify_all.
// With `ip`, the IP suite is set in the same DCP Set (decision I37) and must be taken too.
std::string set_name_of_station(const std::string& interface, const profinet::MacAddress& mac,
                                const std::string& name, bool permanent, std::chrono::milliseconds wait,
                                const std::optional<profinet::IpSuite>& ip = std::nullopt);

}  // namespace tomc::profinet_gateway
