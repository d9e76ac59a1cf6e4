#pragma once
// Internal: MC_* instruction instances behind one interface, so the scenario can create them by name, set
// their inputs from JSON and read any parameter for the trace. Each instruction is described once by a table
// of its parameters (name, data type, input/output, member pointer); adding an instruction is one table.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "tomc/scenario/machine.hpp"
#include "tomc/techobjects/motion/time_position_profile.hpp"
#include "tomc/techobjects/runtime/retentive_store.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/synchronous/leading_value.hpp"

namespace tomc::scenario::detail {

// The PLC data types of instruction parameters.
// kTechnologyObject: an input naming a leading value (MC_GearIn.Master), kCam one naming a cam
// (MC_CamIn.Cam), both given in JSON as the TO's name.
// kTimePosition: MC_PositionProfile.TimePosition, given in JSON as an array of [time, position] pairs that
// the scenario keeps as the user's profile structure (decision L1).
enum class ParameterType : std::uint8_t {
  kBool,
  kInt,
  kDint,
  kWord,
  kLreal,
  kTechnologyObject,
  kCam,
  kTimePosition
};
std::string_view to_string(ParameterType type) noexcept;

struct ParameterInfo {
  std::string_view name;
  ParameterType type;
  bool input;
};

class Instance {
 public:
  virtual ~Instance() = default;
  virtual std::span<const ParameterInfo> parameters() const noexcept = 0;
  // Index into parameters(); already validated values only (the loader checked type and range).
  virtual void set(std::size_t parameter, double value) noexcept = 0;
  virtual double get(std::size_t parameter) const noexcept = 0;  // NaN for a TO parameter
  // A kTechnologyObject or kCam parameter: the object as a leading value or as a cam.
  virtual void set_object(std::size_t parameter, const MachineObject& object) noexcept = 0;
  // A kTimePosition parameter: the profile (kept by the scenario for as long as it runs).
  virtual void set_profile(std::size_t parameter,
                           const techobjects::TimePositionProfile* profile) noexcept = 0;
  // `object` is of the TO type the instance was made for (make_instance); nullptr for an instruction without
  // an Axis input (make_save_absolute_encoder_data).
  virtual void call(techobjects::TechnologyObject* object) noexcept = 0;

  std::optional<std::size_t> find(std::string_view name) const noexcept;
};

using scenario::TechnologyObjectKind;

// Instruction names known to tomc sim for a TO type, in the order of the manual (spec 01 §1.3).
std::span<const std::string_view> instructions_for(TechnologyObjectKind kind) noexcept;
// MC_* instructions of the manual that tomc does not implement yet (a clear "not yet supported").
bool is_planned_instruction(std::string_view name) noexcept;
// nullptr for a name not in instructions_for(kind).
std::unique_ptr<Instance> make_instance(std::string_view instruction, TechnologyObjectKind kind);
// MC_SaveAbsoluteEncoderData (spec 03 §4.16): no Axis input; it backs up every TO's absolute-encoder
// adjustment in the scenario's retentive store ("retain_file").
inline constexpr std::string_view kSaveAbsoluteEncoderData = "MC_SaveAbsoluteEncoderData";
std::unique_ptr<Instance> make_save_absolute_encoder_data(techobjects::RetentiveStore& store);

}  // namespace tomc::scenario::detail
