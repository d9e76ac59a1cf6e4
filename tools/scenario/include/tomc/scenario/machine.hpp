#pragma once
// Building the technology objects of a machine and their simulated drives from JSON: one entry of the
// `technology_objects` array of docs/scenarios.md ("name", "type", "config", "drive", and for a synchronous
// axis "LeadingValueInterconnections", for a cam its elements). `tomc sim` and `tomc demo` share it, so a
// machine configured for one runs in the other unchanged.
//
// Nothing here throws for bad input; problems are reported with their JSON paths.

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "tomc/drives/simulated_actor_drive.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/scenario/config.hpp"
#include "tomc/scenario/gateway_adapter.hpp"
#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::scenario {

// The TO types a machine file builds.
enum class TechnologyObjectKind : std::uint8_t {
  kSpeedAxis,
  kPositioningAxis,
  kSynchronousAxis,
  kExternalEncoder,
  kCam  // TO_Cam, TO_Cam_10k, TO_Cam_600Seg, TO_Cam_6kSeg
};

struct MachineObject {
  std::string name;
  bool built = false;  // false: its definition had problems; the name still resolves to avoid follow-up noise
  TechnologyObjectKind kind = TechnologyObjectKind::kSpeedAxis;
  techobjects::TechnologyObject* object = nullptr;  // the one of the typed pointers below that is set
  techobjects::SpeedAxis* speed_axis = nullptr;
  techobjects::PositioningAxis* positioning_axis = nullptr;  // also set for a synchronous axis
  techobjects::SynchronousAxis* synchronous_axis = nullptr;
  techobjects::ExternalEncoder* external_encoder = nullptr;
  techobjects::Cam* cam = nullptr;
  drives::SimulatedDrive* drive = nullptr;  // the simulated PROFIdrive drive, if that is the adapter
  drives::SimulatedAnalogDrive* analog_drive = nullptr;  // the analog actor and its amplifier, if that is it
  drives::SimulatedStepperDrive* stepper_drive = nullptr;  // the stepper actor and its motor, if that is it
  const drives::MotorLoad* mechanics = nullptr;  // the simulated machine of either; nullptr otherwise

  std::string_view type_name() const noexcept;
  const techobjects::VariableInfo* find_variable(std::string_view path) const noexcept;
  std::optional<techobjects::BitReference> find_bit(std::string_view path) const noexcept;
  // Reads a variable (or one bit of a word) of this TO's data block, for traces and expectations.
  std::function<double()> reader(const techobjects::VariableInfo* info,
                                 std::optional<techobjects::BitReference> bit) const;
  // Reads any path of the TO as its read() does (also StatusSynchronizedMotion.* of a synchronous axis).
  double read(std::string_view path) const noexcept;
  techobjects::WriteResult write(std::string_view variable, double value) const noexcept;
  bool inject_alarm(std::uint32_t number, std::uint32_t additional,
                    techobjects::AlarmReaction reaction) const noexcept;
  // The technology alarms of the TO (pending and history).
  const techobjects::AlarmList& alarms() const noexcept;
  // The TO as a leading value (positioning/synchronous axis, external encoder); nullptr for a speed axis.
  const techobjects::LeadingValueSource* leading_value_source() const noexcept;
};

// Letters, digits and _, not starting with a digit: names prefix trace names and URLs ("<name>.<path>").
bool is_identifier(std::string_view name) noexcept;

// Reads technology_objects[i] at `path` and, if it has no problems, adds its drive and the TO to `runtime`
// (which must not have started). `existing` are the objects read before (names must be unique; a synchronous
// axis' leading values must be among them). Returns the entry whenever it has a usable name (built or not),
// nullopt otherwise. `tool` names the program in "not yet supported by ..." messages. Drives whose adapter is
// a Fast DDS gateway are built through `gateways`; without it such a drive is a problem of the file. A cam's
// points file is read relative to `directory` (the machine file's folder; empty: the working directory).
std::optional<MachineObject> load_technology_object(const Json& value, const std::string& path,
                                                    double cycle_time_s, techobjects::Runtime& runtime,
                                                    std::span<const MachineObject> existing,
                                                    Problems& problems, std::string_view tool = "tomc sim",
                                                    GatewayLinks* gateways = nullptr,
                                                    const std::filesystem::path& directory = {});

// The simulated machine's position switches reach every positioning axis as a PLC's servo process image would
// (spec 02 §4.4 "TPA OB Servo"): a pre-servo hook on `runtime`, at the levels PositionLimits_HW.*SwitchLevel
// say the switches are wired for; the reference cam is the homing digital input. Does nothing without such
// axes.
void wire_machine_inputs(techobjects::Runtime& runtime, std::span<const MachineObject> objects);

}  // namespace tomc::scenario
