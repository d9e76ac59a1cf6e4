// One technology object and its simulated drive from JSON (machine.hpp, docs/scenarios.md).
#include "tomc/scenario/machine.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <memory>
#include <stdexcept>

#include "json_reader.hpp"

namespace tomc::scenario {

namespace to = tomc::techobjects;
using detail::ObjectReader;

namespace {

constexpr std::array<std::string_view, 4> kToTypeNames{"TO_SpeedAxis", "TO_PositioningAxis",
                                                       "TO_SynchronousAxis", "TO_ExternalEncoder"};

std::string list_of(std::span<const std::string_view> names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

}  // namespace

bool is_identifier(std::string_view name) noexcept {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::optional<MachineObject> load_technology_object(const Json& value, const std::string& path,
                                                    double cycle_time_s, to::Runtime& runtime,
                                                    std::span<const MachineObject> existing,
                                                    Problems& problems, std::string_view tool) {
  ObjectReader r(value, path, problems);
  if (!r.valid()) return std::nullopt;
  MachineObject entry;
  if (const Json* v = r.get("name", true)) {
    if (auto name = detail::read_string(*v, r.path_of("name"), problems)) {
      const bool duplicate = std::any_of(existing.begin(), existing.end(),
                                         [&](const MachineObject& o) { return o.name == *name; });
      if (!is_identifier(*name)) {
        problems.add(r.path_of("name"),
                     "'" + *name + "' is not a name (letters, digits, _; not starting with a digit)");
      } else if (duplicate) {
        problems.add(r.path_of("name"), "'" + *name + "' is defined twice");
      } else {
        entry.name = *name;
      }
    }
  }
  bool speed_axis = false;
  if (const Json* v = r.get("type", true)) {
    if (auto t = detail::read_string(*v, r.path_of("type"), problems)) {
      const auto it = std::find(kToTypeNames.begin(), kToTypeNames.end(), *t);
      if (it == kToTypeNames.end()) {
        problems.add(r.path_of("type"),
                     "unknown technology object type '" + *t + "' (one of " + list_of(kToTypeNames) + ")");
      } else if (it != kToTypeNames.begin()) {
        problems.add(r.path_of("type"),
                     *t + " is not yet supported by " + std::string(tool) + " (supported: TO_SpeedAxis)");
      } else {
        speed_axis = true;
      }
    }
  }
  const std::size_t before = problems.size();
  to::SpeedAxisData data;
  DriveSettings drive;
  bool has_drive = false;
  if (speed_axis) {
    if (const Json* v = r.get("config")) load_speed_axis_config(*v, r.path_of("config"), data, problems);
    // The simulated drive is parameterised like the TO unless the file says otherwise (p2000 =
    // ReferenceSpeed, p2003 = ReferenceTorque), as automatic data adaption would do; a mismatch must be asked
    // for explicitly.
    drive.parameters.reference_speed_rpm = data.Actor.DriveParameter.ReferenceSpeed;
    drive.parameters.reference_torque_nm = data.Actor.DriveParameter.ReferenceTorque;
    if (const Json* v = r.get("drive")) {
      load_drive(*v, r.path_of("drive"), cycle_time_s, drive, problems);
      has_drive = true;
    } else if (data.VirtualAxis.Mode != to::kModeOn && data.Simulation.Mode != to::kModeOn) {
      problems.add(r.path_of("drive"),
                   "missing (a TO_SpeedAxis needs a drive unless VirtualAxis.Mode or "
                   "Simulation.Mode is 1)");
    }
  } else {
    // The type is unusable, so its config cannot be checked; still accept the keys to avoid noise.
    r.get("config");
    r.get("drive");
  }
  r.finish();
  if (!entry.name.empty() && speed_axis && problems.size() == before) {
    drives::SimulatedDrive* drive_ptr = nullptr;
    to::DeviceIo* io = nullptr;
    if (has_drive) {
      auto owned = std::make_unique<drives::SimulatedDrive>(drive.device_config(), drive.parameters);
      drive_ptr = owned.get();
      io = &runtime.add_device(std::move(owned));
    }
    try {
      entry.axis = &runtime.emplace<to::SpeedAxis>(entry.name, io, data);
      entry.drive = drive_ptr;
      entry.built = true;
    } catch (const std::invalid_argument& e) {
      // The loader checked every value already; this catches a cross-check the TO may add later.
      problems.add(r.path_of("config"), e.what());
    }
  }
  if (entry.name.empty()) return std::nullopt;
  return entry;
}

}  // namespace tomc::scenario
