#pragma once
// Building the technology objects of a machine and their simulated drives from JSON: one entry of the
// `technology_objects` array of docs/scenarios.md ("name", "type", "config", "drive"). `tomc sim` and
// `tomc demo` share it, so a machine configured for one runs in the other unchanged.
//
// Nothing here throws for bad input; problems are reported with their JSON paths.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/scenario/config.hpp"
#include "tomc/techobjects/runtime.hpp"
#include "tomc/techobjects/speed_axis.hpp"

namespace tomc::scenario {

struct MachineObject {
  std::string name;
  bool built = false;  // false: its definition had problems; the name still resolves to avoid follow-up noise
  techobjects::SpeedAxis* axis = nullptr;   // the TO (TO_SpeedAxis: the only type tomc builds yet)
  drives::SimulatedDrive* drive = nullptr;  // nullptr for a virtual or simulated axis
};

// Letters, digits and _, not starting with a digit: names prefix trace names and URLs ("<name>.<path>").
bool is_identifier(std::string_view name) noexcept;

// Reads technology_objects[i] at `path` and, if it has no problems, adds its drive and the TO to `runtime`
// (which must not have started). `existing` are the objects read before (names must be unique). Returns the
// entry whenever it has a usable name (built or not), nullopt otherwise. `tool` names the program in "not yet
// supported by ..." messages.
std::optional<MachineObject> load_technology_object(const Json& value, const std::string& path,
                                                    double cycle_time_s, techobjects::Runtime& runtime,
                                                    std::span<const MachineObject> existing,
                                                    Problems& problems, std::string_view tool = "tomc sim");

}  // namespace tomc::scenario
