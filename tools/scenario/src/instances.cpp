// The parameter tables of the MC_* instructions on TO_SpeedAxis (spec 03 §4) and their type-erased instances.
#include "instances.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_move_jog.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/instructions/mc_set_axis_stw.hpp"
#include "tomc/instructions/mc_stop.hpp"
#include "tomc/instructions/mc_write_parameter.hpp"

namespace tomc::scenario::detail {
namespace {

using techobjects::SpeedAxis;

template <typename FB>
using Member =
    std::variant<bool FB::*, std::int16_t FB::*, std::int32_t FB::*, std::uint16_t FB::*, double FB::*>;

template <typename FB>
struct Parameter {
  ParameterInfo info;
  Member<FB> member;
};

template <typename T>
constexpr ParameterType type_of() {
  if constexpr (std::is_same_v<T, bool>) {
    return ParameterType::kBool;
  } else if constexpr (std::is_same_v<T, std::int16_t>) {
    return ParameterType::kInt;
  } else if constexpr (std::is_same_v<T, std::int32_t>) {
    return ParameterType::kDint;
  } else if constexpr (std::is_same_v<T, std::uint16_t>) {
    return ParameterType::kWord;
  } else {
    static_assert(std::is_same_v<T, double>);
    return ParameterType::kLreal;
  }
}

// The PLC type follows from the C++ member type, so a table row cannot disagree with the instruction class.
template <typename FB, typename T>
constexpr Parameter<FB> in(std::string_view name, T FB::*member) {
  return {{name, type_of<T>(), true}, member};
}
template <typename FB, typename T>
constexpr Parameter<FB> out(std::string_view name, T FB::*member) {
  return {{name, type_of<T>(), false}, member};
}

template <typename FB, std::size_t N>
class InstanceOf final : public Instance {
 public:
  explicit InstanceOf(const std::array<Parameter<FB>, N>& table) : table_(table) {
    for (std::size_t i = 0; i < N; ++i)
      infos_[i] = table_[i].info;
  }
  std::span<const ParameterInfo> parameters() const noexcept override { return infos_; }
  void set(std::size_t parameter, double value) noexcept override {
    std::visit(
        [&](auto member) {
          using T = std::remove_reference_t<decltype(fb_.*member)>;
          if constexpr (std::is_same_v<T, bool>) {
            fb_.*member = value != 0.0;
          } else {
            fb_.*member = static_cast<T>(value);
          }
        },
        table_[parameter].member);
  }
  double get(std::size_t parameter) const noexcept override {
    return std::visit([&](auto member) { return static_cast<double>(fb_.*member); },
                      table_[parameter].member);
  }
  void call(SpeedAxis& axis) noexcept override { fb_(axis); }

 private:
  const std::array<Parameter<FB>, N>& table_;
  std::array<ParameterInfo, N> infos_{};
  FB fb_{};
};

template <typename FB, std::size_t N>
std::unique_ptr<Instance> make(const std::array<Parameter<FB>, N>& table) {
  return std::make_unique<InstanceOf<FB, N>>(table);
}

// Parameter order as in the manual's instruction descriptions: inputs, then outputs.
using Power = instructions::MC_Power<SpeedAxis>;
const auto kPower = std::to_array<Parameter<Power>>({
    in("Enable", &Power::Enable),
    in("StartMode", &Power::StartMode),
    in("StopMode", &Power::StopMode),
    out("Status", &Power::Status),
    out("Busy", &Power::Busy),
    out("Error", &Power::Error),
    out("ErrorID", &Power::ErrorID),
});

using Reset = instructions::MC_Reset<SpeedAxis>;
const auto kReset = std::to_array<Parameter<Reset>>({
    in("Execute", &Reset::Execute),
    in("Restart", &Reset::Restart),
    out("Done", &Reset::Done),
    out("Busy", &Reset::Busy),
    out("CommandAborted", &Reset::CommandAborted),
    out("Error", &Reset::Error),
    out("ErrorID", &Reset::ErrorID),
});

using MoveVelocity = instructions::MC_MoveVelocity<SpeedAxis>;
const auto kMoveVelocity = std::to_array<Parameter<MoveVelocity>>({
    in("Execute", &MoveVelocity::Execute),
    in("Velocity", &MoveVelocity::Velocity),
    in("Acceleration", &MoveVelocity::Acceleration),
    in("Deceleration", &MoveVelocity::Deceleration),
    in("Jerk", &MoveVelocity::Jerk),
    in("Direction", &MoveVelocity::Direction),
    in("Current", &MoveVelocity::Current),
    in("PositionControlled", &MoveVelocity::PositionControlled),
    out("InVelocity", &MoveVelocity::InVelocity),
    out("Busy", &MoveVelocity::Busy),
    out("CommandAborted", &MoveVelocity::CommandAborted),
    out("Error", &MoveVelocity::Error),
    out("ErrorID", &MoveVelocity::ErrorID),
});

using MoveJog = instructions::MC_MoveJog<SpeedAxis>;
const auto kMoveJog = std::to_array<Parameter<MoveJog>>({
    in("JogForward", &MoveJog::JogForward),
    in("JogBackward", &MoveJog::JogBackward),
    in("Velocity", &MoveJog::Velocity),
    in("Acceleration", &MoveJog::Acceleration),
    in("Deceleration", &MoveJog::Deceleration),
    in("Jerk", &MoveJog::Jerk),
    in("PositionControlled", &MoveJog::PositionControlled),
    out("InVelocity", &MoveJog::InVelocity),
    out("Busy", &MoveJog::Busy),
    out("CommandAborted", &MoveJog::CommandAborted),
    out("Error", &MoveJog::Error),
    out("ErrorID", &MoveJog::ErrorID),
});

using Halt = instructions::MC_Halt<SpeedAxis>;
const auto kHalt = std::to_array<Parameter<Halt>>({
    in("Execute", &Halt::Execute),
    in("Deceleration", &Halt::Deceleration),
    in("Jerk", &Halt::Jerk),
    in("AbortAcceleration", &Halt::AbortAcceleration),
    in("Mode", &Halt::Mode),
    out("Done", &Halt::Done),
    out("Busy", &Halt::Busy),
    out("CommandAborted", &Halt::CommandAborted),
    out("Error", &Halt::Error),
    out("ErrorID", &Halt::ErrorID),
});

using Stop = instructions::MC_Stop<SpeedAxis>;
const auto kStop = std::to_array<Parameter<Stop>>({
    in("Execute", &Stop::Execute),
    in("Mode", &Stop::Mode),
    in("Deceleration", &Stop::Deceleration),
    in("Jerk", &Stop::Jerk),
    in("AbortAcceleration", &Stop::AbortAcceleration),
    out("Done", &Stop::Done),
    out("Busy", &Stop::Busy),
    out("CommandAborted", &Stop::CommandAborted),
    out("Error", &Stop::Error),
    out("ErrorID", &Stop::ErrorID),
});

using SetAxisStw = instructions::MC_SetAxisSTW<SpeedAxis>;
const auto kSetAxisStw = std::to_array<Parameter<SetAxisStw>>({
    in("Execute", &SetAxisStw::Execute),
    in("STW1", &SetAxisStw::STW1),
    in("STW1BitMask", &SetAxisStw::STW1BitMask),
    in("STW2", &SetAxisStw::STW2),
    in("STW2BitMask", &SetAxisStw::STW2BitMask),
    out("Done", &SetAxisStw::Done),
    out("Busy", &SetAxisStw::Busy),
    out("CommandAborted", &SetAxisStw::CommandAborted),
    out("Error", &SetAxisStw::Error),
    out("ErrorID", &SetAxisStw::ErrorID),
});

using WriteParameter = instructions::MC_WriteParameter<SpeedAxis>;
const auto kWriteParameter = std::to_array<Parameter<WriteParameter>>({
    in("Execute", &WriteParameter::Execute),
    in("ParameterNumber", &WriteParameter::ParameterNumber),
    in("Value", &WriteParameter::Value),
    out("Done", &WriteParameter::Done),
    out("Busy", &WriteParameter::Busy),
    out("CommandAborted", &WriteParameter::CommandAborted),
    out("Error", &WriteParameter::Error),
    out("ErrorID", &WriteParameter::ErrorID),
});

constexpr std::array<std::string_view, 8> kSpeedAxisInstructions{
    "MC_Power", "MC_Reset", "MC_MoveVelocity", "MC_MoveJog",
    "MC_Halt",  "MC_Stop",  "MC_SetAxisSTW",   "MC_WriteParameter",
};

// The other instructions of spec 03 (positioning, synchronous operation, measuring, torque, kinematics...).
constexpr std::array<std::string_view, 26> kPlannedInstructions{
    "MC_Home",
    "MC_MoveAbsolute",
    "MC_MoveRelative",
    "MC_MoveSuperimposed",
    "MC_HaltSuperimposed",
    "MC_TorqueLimiting",
    "MC_TorqueAdditive",
    "MC_TorqueRange",
    "MC_GearIn",
    "MC_GearInPos",
    "MC_GearInVelocity",
    "MC_GearOut",
    "MC_CamIn",
    "MC_CamOut",
    "MC_PhasingAbsolute",
    "MC_PhasingRelative",
    "MC_OffsetAbsolute",
    "MC_OffsetRelative",
    "MC_MeasuringInput",
    "MC_MeasuringInputCyclic",
    "MC_AbortMeasuringInput",
    "MC_OutputCam",
    "MC_CamTrack",
    "MC_ReadParameter",
    "MC_MotionInVelocity",
    "MC_MotionInPosition",
};

}  // namespace

std::string_view to_string(ParameterType type) noexcept {
  switch (type) {
    case ParameterType::kBool:
      return "BOOL";
    case ParameterType::kInt:
      return "INT";
    case ParameterType::kDint:
      return "DINT";
    case ParameterType::kWord:
      return "WORD";
    case ParameterType::kLreal:
      return "LREAL";
  }
  return "?";
}

std::optional<std::size_t> Instance::find(std::string_view name) const noexcept {
  const auto p = parameters();
  const auto it = std::find_if(p.begin(), p.end(), [&](const ParameterInfo& i) { return i.name == name; });
  if (it == p.end()) return std::nullopt;
  return static_cast<std::size_t>(it - p.begin());
}

std::span<const std::string_view> speed_axis_instructions() noexcept {
  return kSpeedAxisInstructions;
}

bool is_planned_instruction(std::string_view name) noexcept {
  return std::find(kPlannedInstructions.begin(), kPlannedInstructions.end(), name) !=
         kPlannedInstructions.end();
}

std::unique_ptr<Instance> make_speed_axis_instance(std::string_view instruction) {
  if (instruction == "MC_Power") return make(kPower);
  if (instruction == "MC_Reset") return make(kReset);
  if (instruction == "MC_MoveVelocity") return make(kMoveVelocity);
  if (instruction == "MC_MoveJog") return make(kMoveJog);
  if (instruction == "MC_Halt") return make(kHalt);
  if (instruction == "MC_Stop") return make(kStop);
  if (instruction == "MC_SetAxisSTW") return make(kSetAxisStw);
  if (instruction == "MC_WriteParameter") return make(kWriteParameter);
  return nullptr;
}

}  // namespace tomc::scenario::detail
