#pragma once
// Internal: the legacy parameter sets of a DEVICE JOINT axis and of a SAIA PCD4.H3 axis mapped onto the S7
// model as spec 05b Part C says (docs/analog-drives.md "Legacy parameter sets"). A technology object's
// "legacy" object holds the legacy names and values; expand_legacy() turns it into the TO's "config" keys and
// the "drive" keys of its analog actor, which the ordinary loaders then read (explicit "config"/"drive" keys
// of the file win).

#include <optional>
#include <string_view>

#include "tomc/scenario/config.hpp"

namespace tomc::scenario::detail {

struct LegacyExpansion {
  Json config = Json::object();  // data-block paths -> start values
  Json drive = Json::object();   // "adapter": "analog", "telegram": 3, "analog": {...}, motor keys
};

// Every out-of-range legacy value is a problem at `path`.<legacy name>; nullopt when there was any.
std::optional<LegacyExpansion> expand_legacy(const Json& legacy, std::string_view path, double cycle_time_s,
                                             Problems& problems);

// `entry` with its "legacy" object expanded (config and drive merged under the entry's own keys), or nullopt
// with problems. An entry without "legacy" is returned unchanged.
std::optional<Json> with_legacy_expanded(const Json& entry, std::string_view path, double cycle_time_s,
                                         Problems& problems);

}  // namespace tomc::scenario::detail
