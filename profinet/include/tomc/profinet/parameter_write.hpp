#pragma once
// Changing one drive parameter through PROFIdrive base-mode parameter access, as `tomc gateway` does at
// start-up for the file's "parameters" (decision I33): read it (its answer gives the parameter's format),
// send the change request (request ID 0x02) with the file's value in that format, read it back and compare.
// Socket-free: the caller's exchange writes a request to record index 0xB02E and reads the response.

#include <cstdint>
#include <functional>
#include <string>
#include <variant>

#include "tomc/profinet/parameter_access.hpp"

namespace tomc::profinet {

struct ParameterWrite {
  std::uint16_t number = 0;  // e.g. 2000
  std::uint16_t subindex = 0;
  double value = 0.0;  // in the parameter's own format (FloatingPoint, Unsigned16, ...)
};

// Writes `request` and reads the response: the response, or why there is none ("no answer to the parameter
// request", "parameter read refused, PNIOStatus 0xDE80B800").
using ParameterExchange =
    std::function<std::variant<ParameterResponse, std::string>(const ParameterRequest&)>;

// "" when the drive took the value and reads it back; otherwise one line naming the parameter and the
// reason: "p2000 = 250000: the drive refused the change, PROFIdrive error 0x02 (low or high limit exceeded)",
// "p0922 = 3: ... 0x01 (parameter value cannot be changed)", "p2000 = 1e+40 does not fit its format
// FloatingPoint", "p1082[2] = 3000 reads back as 2999". `axis` is the drive object (DO ID) of the requests;
// `reference` counts the requests' references (1..255, each response must mirror its own).
std::string write_parameter(const ParameterWrite& write, std::uint8_t axis, std::uint8_t& reference,
                            const ParameterExchange& exchange);

// "p2000", "p1082[2]".
std::string parameter_name(std::uint16_t number, std::uint16_t subindex);
// "FloatingPoint", "Unsigned16", ... ; "format 0x41" for others.
std::string parameter_format_name(std::uint8_t format);

}  // namespace tomc::profinet
