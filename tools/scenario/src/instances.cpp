// The parameter tables of the MC_* instructions on TO_SpeedAxis (spec 03 §4) and their type-erased instances.
#include "instances.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <type_traits>

#include "tomc/instructions/mc_cam_in.hpp"
#include "tomc/instructions/mc_cam_out.hpp"
#include "tomc/instructions/mc_gear_in.hpp"
#include "tomc/instructions/mc_gear_in_pos.hpp"
#include "tomc/instructions/mc_gear_in_velocity.hpp"
#include "tomc/instructions/mc_gear_out.hpp"
#include "tomc/instructions/mc_get_cam_value.hpp"
#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_halt_superimposed.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_interpolate_cam.hpp"
#include "tomc/instructions/mc_leading_value_additive.hpp"
#include "tomc/instructions/mc_motion_in.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_move_jog.hpp"
#include "tomc/instructions/mc_move_relative.hpp"
#include "tomc/instructions/mc_move_superimposed.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_phasing.hpp"
#include "tomc/instructions/mc_position_profile.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/instructions/mc_save_absolute_encoder_data.hpp"
#include "tomc/instructions/mc_set_axis_stw.hpp"
#include "tomc/instructions/mc_set_sensor.hpp"
#include "tomc/instructions/mc_stop.hpp"
#include "tomc/instructions/mc_synchronized_motion_simulation.hpp"
#include "tomc/instructions/mc_torque_additive.hpp"
#include "tomc/instructions/mc_torque_limiting.hpp"
#include "tomc/instructions/mc_torque_range.hpp"
#include "tomc/instructions/mc_write_parameter.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::scenario::detail {
namespace {

using techobjects::ExternalEncoder;
using techobjects::PositioningAxis;
using techobjects::SpeedAxis;
using techobjects::SynchronousAxis;
using Source = const techobjects::LeadingValueSource*;
using CamReference = techobjects::Cam*;
using ProfileReference = techobjects::TimePositionSource;

// The axis type an instruction class works on: MC_Power<SpeedAxis> -> SpeedAxis.
template <typename FB>
struct axis_of;
template <template <typename> class Instruction, typename Axis>
struct axis_of<Instruction<Axis>> {
  using type = Axis;
};
// The cam instructions are not templates: their TO is always a cam.
// MC_GearOut and MC_CamOut are one instruction class (mc_gear_out.hpp); their tables name its members.
template <typename Axis, bool kCamming>
struct axis_of<instructions::detail::SynchronousOut<Axis, kCamming>> {
  using type = Axis;
};
template <>
struct axis_of<instructions::MC_InterpolateCam> {
  using type = techobjects::Cam;
};
template <>
struct axis_of<instructions::MC_GetCamFollowingValue> {
  using type = techobjects::Cam;
};
template <>
struct axis_of<instructions::MC_GetCamFollowingValueCyclic> {
  using type = techobjects::Cam;
};
template <>
struct axis_of<instructions::MC_GetCamLeadingValue> {
  using type = techobjects::Cam;
};

template <typename FB>
using Member = std::variant<bool FB::*, std::int16_t FB::*, std::int32_t FB::*, std::uint16_t FB::*,
                            double FB::*, Source FB::*, CamReference FB::*, ProfileReference FB::*>;

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
  } else if constexpr (std::is_same_v<T, Source>) {
    return ParameterType::kTechnologyObject;
  } else if constexpr (std::is_same_v<T, CamReference>) {
    return ParameterType::kCam;
  } else if constexpr (std::is_same_v<T, ProfileReference>) {
    return ParameterType::kTimePosition;
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
  explicit InstanceOf(const std::array<Parameter<FB>, N>& table, techobjects::RetentiveStore* store = nullptr)
      : table_(table), store_(store) {
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
          } else if constexpr (std::is_same_v<T, Source> || std::is_same_v<T, CamReference> ||
                               std::is_same_v<T, ProfileReference>) {
            // set_object() / set_profile() set these
          } else {
            fb_.*member = static_cast<T>(value);
          }
        },
        table_[parameter].member);
  }
  double get(std::size_t parameter) const noexcept override {
    return std::visit(
        [&](auto member) {
          using T = std::remove_cv_t<std::remove_reference_t<decltype(fb_.*member)>>;
          if constexpr (std::is_same_v<T, Source> || std::is_same_v<T, CamReference> ||
                        std::is_same_v<T, ProfileReference>) {
            return std::numeric_limits<double>::quiet_NaN();
          } else {
            return static_cast<double>(fb_.*member);
          }
        },
        table_[parameter].member);
  }
  void set_object(std::size_t parameter, const MachineObject& object) noexcept override {
    if (auto* member = std::get_if<Source FB::*>(&table_[parameter].member))
      fb_.** member = object.leading_value_source();
    if (auto* member = std::get_if<CamReference FB::*>(&table_[parameter].member)) fb_.** member = object.cam;
    // MC_PositionProfile.TimePosition naming a TO_Cam (spec 03 §4.7).
    if (auto* member = std::get_if<ProfileReference FB::*>(&table_[parameter].member))
      fb_.** member = object.cam;
  }
  void set_profile(std::size_t parameter, const techobjects::TimePositionProfile* profile) noexcept override {
    if (auto* member = std::get_if<ProfileReference FB::*>(&table_[parameter].member))
      fb_.*(*member) = profile;
  }
  // The loader creates an instance only for a TO of the instruction's axis type.
  void call(techobjects::TechnologyObject* object) noexcept override {
    using Target = typename axis_of<FB>::type;
    if constexpr (std::is_same_v<Target, techobjects::RetentiveStore>) {
      fb_(*store_);
    } else {
      fb_(static_cast<Target&>(*object));
    }
  }

 private:
  const std::array<Parameter<FB>, N>& table_;
  techobjects::RetentiveStore* store_;  // MC_SaveAbsoluteEncoderData only
  std::array<ParameterInfo, N> infos_{};
  FB fb_{};
};

template <typename FB, std::size_t N>
std::unique_ptr<Instance> make(const std::array<Parameter<FB>, N>& table) {
  return std::make_unique<InstanceOf<FB, N>>(table);
}

// Parameter order as in the manual's instruction descriptions: inputs, then outputs.
template <typename Axis>
using Power = instructions::MC_Power<Axis>;
template <typename Axis>
const auto kPower = std::to_array<Parameter<Power<Axis>>>({
    in("Enable", &Power<Axis>::Enable),
    in("StartMode", &Power<Axis>::StartMode),
    in("StopMode", &Power<Axis>::StopMode),
    out("Status", &Power<Axis>::Status),
    out("Busy", &Power<Axis>::Busy),
    out("Error", &Power<Axis>::Error),
    out("ErrorID", &Power<Axis>::ErrorID),
});

template <typename Axis>
using Reset = instructions::MC_Reset<Axis>;
template <typename Axis>
const auto kReset = std::to_array<Parameter<Reset<Axis>>>({
    in("Execute", &Reset<Axis>::Execute),
    in("Restart", &Reset<Axis>::Restart),
    out("Done", &Reset<Axis>::Done),
    out("Busy", &Reset<Axis>::Busy),
    out("CommandAborted", &Reset<Axis>::CommandAborted),
    out("Error", &Reset<Axis>::Error),
    out("ErrorID", &Reset<Axis>::ErrorID),
});

template <typename Axis>
using MoveVelocity = instructions::MC_MoveVelocity<Axis>;
template <typename Axis>
const auto kMoveVelocity = std::to_array<Parameter<MoveVelocity<Axis>>>({
    in("Execute", &MoveVelocity<Axis>::Execute),
    in("Velocity", &MoveVelocity<Axis>::Velocity),
    in("Acceleration", &MoveVelocity<Axis>::Acceleration),
    in("Deceleration", &MoveVelocity<Axis>::Deceleration),
    in("Jerk", &MoveVelocity<Axis>::Jerk),
    in("Direction", &MoveVelocity<Axis>::Direction),
    in("Current", &MoveVelocity<Axis>::Current),
    in("PositionControlled", &MoveVelocity<Axis>::PositionControlled),
    out("InVelocity", &MoveVelocity<Axis>::InVelocity),
    out("Busy", &MoveVelocity<Axis>::Busy),
    out("CommandAborted", &MoveVelocity<Axis>::CommandAborted),
    out("Error", &MoveVelocity<Axis>::Error),
    out("ErrorID", &MoveVelocity<Axis>::ErrorID),
});

template <typename Axis>
using MoveJog = instructions::MC_MoveJog<Axis>;
template <typename Axis>
const auto kMoveJog = std::to_array<Parameter<MoveJog<Axis>>>({
    in("JogForward", &MoveJog<Axis>::JogForward),
    in("JogBackward", &MoveJog<Axis>::JogBackward),
    in("Velocity", &MoveJog<Axis>::Velocity),
    in("Acceleration", &MoveJog<Axis>::Acceleration),
    in("Deceleration", &MoveJog<Axis>::Deceleration),
    in("Jerk", &MoveJog<Axis>::Jerk),
    in("PositionControlled", &MoveJog<Axis>::PositionControlled),
    out("InVelocity", &MoveJog<Axis>::InVelocity),
    out("Busy", &MoveJog<Axis>::Busy),
    out("CommandAborted", &MoveJog<Axis>::CommandAborted),
    out("Error", &MoveJog<Axis>::Error),
    out("ErrorID", &MoveJog<Axis>::ErrorID),
});

template <typename Axis>
using Halt = instructions::MC_Halt<Axis>;
template <typename Axis>
const auto kHalt = std::to_array<Parameter<Halt<Axis>>>({
    in("Execute", &Halt<Axis>::Execute),
    in("Deceleration", &Halt<Axis>::Deceleration),
    in("Jerk", &Halt<Axis>::Jerk),
    in("AbortAcceleration", &Halt<Axis>::AbortAcceleration),
    in("Mode", &Halt<Axis>::Mode),
    out("Done", &Halt<Axis>::Done),
    out("Busy", &Halt<Axis>::Busy),
    out("CommandAborted", &Halt<Axis>::CommandAborted),
    out("Error", &Halt<Axis>::Error),
    out("ErrorID", &Halt<Axis>::ErrorID),
});

template <typename Axis>
using Stop = instructions::MC_Stop<Axis>;
template <typename Axis>
const auto kStop = std::to_array<Parameter<Stop<Axis>>>({
    in("Execute", &Stop<Axis>::Execute),
    in("Mode", &Stop<Axis>::Mode),
    in("Deceleration", &Stop<Axis>::Deceleration),
    in("Jerk", &Stop<Axis>::Jerk),
    in("AbortAcceleration", &Stop<Axis>::AbortAcceleration),
    out("Done", &Stop<Axis>::Done),
    out("Busy", &Stop<Axis>::Busy),
    out("CommandAborted", &Stop<Axis>::CommandAborted),
    out("Error", &Stop<Axis>::Error),
    out("ErrorID", &Stop<Axis>::ErrorID),
});

template <typename Axis>
using SetAxisStw = instructions::MC_SetAxisSTW<Axis>;
template <typename Axis>
const auto kSetAxisStw = std::to_array<Parameter<SetAxisStw<Axis>>>({
    in("Execute", &SetAxisStw<Axis>::Execute),
    in("STW1", &SetAxisStw<Axis>::STW1),
    in("STW1BitMask", &SetAxisStw<Axis>::STW1BitMask),
    in("STW2", &SetAxisStw<Axis>::STW2),
    in("STW2BitMask", &SetAxisStw<Axis>::STW2BitMask),
    out("Done", &SetAxisStw<Axis>::Done),
    out("Busy", &SetAxisStw<Axis>::Busy),
    out("CommandAborted", &SetAxisStw<Axis>::CommandAborted),
    out("Error", &SetAxisStw<Axis>::Error),
    out("ErrorID", &SetAxisStw<Axis>::ErrorID),
});

template <typename Axis>
using WriteParameter = instructions::MC_WriteParameter<Axis>;
template <typename Axis>
const auto kWriteParameter = std::to_array<Parameter<WriteParameter<Axis>>>({
    in("Execute", &WriteParameter<Axis>::Execute),
    in("ParameterNumber", &WriteParameter<Axis>::ParameterNumber),
    in("Value", &WriteParameter<Axis>::Value),
    out("Done", &WriteParameter<Axis>::Done),
    out("Busy", &WriteParameter<Axis>::Busy),
    out("CommandAborted", &WriteParameter<Axis>::CommandAborted),
    out("Error", &WriteParameter<Axis>::Error),
    out("ErrorID", &WriteParameter<Axis>::ErrorID),
});

template <typename Axis>
using TorqueLimiting = instructions::MC_TorqueLimiting<Axis>;
template <typename Axis>
const auto kTorqueLimiting = std::to_array<Parameter<TorqueLimiting<Axis>>>({
    in("Enable", &TorqueLimiting<Axis>::Enable),
    in("Limit", &TorqueLimiting<Axis>::Limit),
    in("Mode", &TorqueLimiting<Axis>::Mode),
    out("InClamping", &TorqueLimiting<Axis>::InClamping),
    out("InLimitation", &TorqueLimiting<Axis>::InLimitation),
    out("Busy", &TorqueLimiting<Axis>::Busy),
    out("Error", &TorqueLimiting<Axis>::Error),
    out("ErrorID", &TorqueLimiting<Axis>::ErrorID),
});

template <typename Axis>
using TorqueAdditive = instructions::MC_TorqueAdditive<Axis>;
template <typename Axis>
const auto kTorqueAdditive = std::to_array<Parameter<TorqueAdditive<Axis>>>({
    in("Enable", &TorqueAdditive<Axis>::Enable),
    in("Value", &TorqueAdditive<Axis>::Value),
    out("Busy", &TorqueAdditive<Axis>::Busy),
    out("Error", &TorqueAdditive<Axis>::Error),
    out("ErrorID", &TorqueAdditive<Axis>::ErrorID),
});

template <typename Axis>
using TorqueRange = instructions::MC_TorqueRange<Axis>;
template <typename Axis>
const auto kTorqueRange = std::to_array<Parameter<TorqueRange<Axis>>>({
    in("Enable", &TorqueRange<Axis>::Enable),
    in("UpperLimit", &TorqueRange<Axis>::UpperLimit),
    in("LowerLimit", &TorqueRange<Axis>::LowerLimit),
    out("Busy", &TorqueRange<Axis>::Busy),
    out("Error", &TorqueRange<Axis>::Error),
    out("ErrorID", &TorqueRange<Axis>::ErrorID),
});

template <typename Axis>
using MoveAbsolute = instructions::MC_MoveAbsolute<Axis>;
template <typename Axis>
const auto kMoveAbsolute = std::to_array<Parameter<MoveAbsolute<Axis>>>({
    in("Execute", &MoveAbsolute<Axis>::Execute),
    in("Position", &MoveAbsolute<Axis>::Position),
    in("Velocity", &MoveAbsolute<Axis>::Velocity),
    in("Acceleration", &MoveAbsolute<Axis>::Acceleration),
    in("Deceleration", &MoveAbsolute<Axis>::Deceleration),
    in("Jerk", &MoveAbsolute<Axis>::Jerk),
    in("BufferMode", &MoveAbsolute<Axis>::BufferMode),
    in("Direction", &MoveAbsolute<Axis>::Direction),
    out("Done", &MoveAbsolute<Axis>::Done),
    out("Busy", &MoveAbsolute<Axis>::Busy),
    out("Active", &MoveAbsolute<Axis>::Active),
    out("CommandAborted", &MoveAbsolute<Axis>::CommandAborted),
    out("Error", &MoveAbsolute<Axis>::Error),
    out("ErrorID", &MoveAbsolute<Axis>::ErrorID),
});

template <typename Axis>
using MoveRelative = instructions::MC_MoveRelative<Axis>;
template <typename Axis>
const auto kMoveRelative = std::to_array<Parameter<MoveRelative<Axis>>>({
    in("Execute", &MoveRelative<Axis>::Execute),
    in("Distance", &MoveRelative<Axis>::Distance),
    in("Velocity", &MoveRelative<Axis>::Velocity),
    in("Acceleration", &MoveRelative<Axis>::Acceleration),
    in("Deceleration", &MoveRelative<Axis>::Deceleration),
    in("Jerk", &MoveRelative<Axis>::Jerk),
    in("BufferMode", &MoveRelative<Axis>::BufferMode),
    out("Done", &MoveRelative<Axis>::Done),
    out("Busy", &MoveRelative<Axis>::Busy),
    out("Active", &MoveRelative<Axis>::Active),
    out("CommandAborted", &MoveRelative<Axis>::CommandAborted),
    out("Error", &MoveRelative<Axis>::Error),
    out("ErrorID", &MoveRelative<Axis>::ErrorID),
});

template <typename Axis>
using MoveSuperimposed = instructions::MC_MoveSuperimposed<Axis>;
template <typename Axis>
const auto kMoveSuperimposed = std::to_array<Parameter<MoveSuperimposed<Axis>>>({
    in("Execute", &MoveSuperimposed<Axis>::Execute),
    in("Distance", &MoveSuperimposed<Axis>::Distance),
    in("VelocityDiff", &MoveSuperimposed<Axis>::VelocityDiff),
    in("Acceleration", &MoveSuperimposed<Axis>::Acceleration),
    in("Deceleration", &MoveSuperimposed<Axis>::Deceleration),
    in("Jerk", &MoveSuperimposed<Axis>::Jerk),
    out("Done", &MoveSuperimposed<Axis>::Done),
    out("Busy", &MoveSuperimposed<Axis>::Busy),
    out("CommandAborted", &MoveSuperimposed<Axis>::CommandAborted),
    out("Error", &MoveSuperimposed<Axis>::Error),
    out("ErrorID", &MoveSuperimposed<Axis>::ErrorID),
});

template <typename Axis>
using HaltSuperimposed = instructions::MC_HaltSuperimposed<Axis>;
template <typename Axis>
const auto kHaltSuperimposed = std::to_array<Parameter<HaltSuperimposed<Axis>>>({
    in("Execute", &HaltSuperimposed<Axis>::Execute),
    in("Deceleration", &HaltSuperimposed<Axis>::Deceleration),
    in("Jerk", &HaltSuperimposed<Axis>::Jerk),
    in("AbortAcceleration", &HaltSuperimposed<Axis>::AbortAcceleration),
    out("Done", &HaltSuperimposed<Axis>::Done),
    out("Busy", &HaltSuperimposed<Axis>::Busy),
    out("CommandAborted", &HaltSuperimposed<Axis>::CommandAborted),
    out("Error", &HaltSuperimposed<Axis>::Error),
    out("ErrorID", &HaltSuperimposed<Axis>::ErrorID),
});

template <typename Axis>
using SetSensor = instructions::MC_SetSensor<Axis>;
template <typename Axis>
const auto kSetSensor = std::to_array<Parameter<SetSensor<Axis>>>({
    in("Execute", &SetSensor<Axis>::Execute),
    in("Sensor", &SetSensor<Axis>::Sensor),
    in("Mode", &SetSensor<Axis>::Mode),
    in("ReferenceSensor", &SetSensor<Axis>::ReferenceSensor),
    out("Done", &SetSensor<Axis>::Done),
    out("Busy", &SetSensor<Axis>::Busy),
    out("CommandAborted", &SetSensor<Axis>::CommandAborted),
    out("Error", &SetSensor<Axis>::Error),
    out("ErrorID", &SetSensor<Axis>::ErrorID),
});

template <typename Axis>
using Home = instructions::MC_Home<Axis>;
template <typename Axis>
const auto kHome = std::to_array<Parameter<Home<Axis>>>({
    in("Execute", &Home<Axis>::Execute),
    in("Position", &Home<Axis>::Position),
    in("Mode", &Home<Axis>::Mode),
    in("Sensor", &Home<Axis>::Sensor),
    out("ReferenceMarkPosition", &Home<Axis>::ReferenceMarkPosition),
    out("Done", &Home<Axis>::Done),
    out("Busy", &Home<Axis>::Busy),
    out("CommandAborted", &Home<Axis>::CommandAborted),
    out("Error", &Home<Axis>::Error),
    out("ErrorID", &Home<Axis>::ErrorID),
});

using GearIn = instructions::MC_GearIn<SynchronousAxis>;
const auto kGearIn = std::to_array<Parameter<GearIn>>({
    in("Master", &GearIn::Master),
    in("Execute", &GearIn::Execute),
    in("RatioNumerator", &GearIn::RatioNumerator),
    in("RatioDenominator", &GearIn::RatioDenominator),
    in("Acceleration", &GearIn::Acceleration),
    in("Deceleration", &GearIn::Deceleration),
    in("Jerk", &GearIn::Jerk),
    out("InGear", &GearIn::InGear),
    out("Busy", &GearIn::Busy),
    out("CommandAborted", &GearIn::CommandAborted),
    out("Error", &GearIn::Error),
    out("ErrorID", &GearIn::ErrorID),
});

using GearInPos = instructions::MC_GearInPos<SynchronousAxis>;
const auto kGearInPos = std::to_array<Parameter<GearInPos>>({
    in("Master", &GearInPos::Master),
    in("Execute", &GearInPos::Execute),
    in("RatioNumerator", &GearInPos::RatioNumerator),
    in("RatioDenominator", &GearInPos::RatioDenominator),
    in("MasterSyncPosition", &GearInPos::MasterSyncPosition),
    in("SlaveSyncPosition", &GearInPos::SlaveSyncPosition),
    in("SyncProfileReference", &GearInPos::SyncProfileReference),
    in("MasterStartDistance", &GearInPos::MasterStartDistance),
    in("Velocity", &GearInPos::Velocity),
    in("Acceleration", &GearInPos::Acceleration),
    in("Deceleration", &GearInPos::Deceleration),
    in("Jerk", &GearInPos::Jerk),
    in("SyncDirection", &GearInPos::SyncDirection),
    out<GearInPos, bool>("StartSync", &GearInPos::StartSync),
    out<GearInPos, bool>("InSync", &GearInPos::InSync),
    out<GearInPos, bool>("Busy", &GearInPos::Busy),
    out<GearInPos, bool>("CommandAborted", &GearInPos::CommandAborted),
    out<GearInPos, bool>("Error", &GearInPos::Error),
    out<GearInPos, std::uint16_t>("ErrorID", &GearInPos::ErrorID),
});

using GearInVelocity = instructions::MC_GearInVelocity<SynchronousAxis>;
const auto kGearInVelocity = std::to_array<Parameter<GearInVelocity>>({
    in("Master", &GearInVelocity::Master),
    in("Execute", &GearInVelocity::Execute),
    in("ContinuousUpdate", &GearInVelocity::ContinuousUpdate),
    in("RatioNumerator", &GearInVelocity::RatioNumerator),
    in("RatioDenominator", &GearInVelocity::RatioDenominator),
    in("Acceleration", &GearInVelocity::Acceleration),
    in("Deceleration", &GearInVelocity::Deceleration),
    in("Jerk", &GearInVelocity::Jerk),
    in("PositionControlled", &GearInVelocity::PositionControlled),
    out("StartSync", &GearInVelocity::StartSync),
    out("InSync", &GearInVelocity::InSync),
    out("ContinuousUpdateActive", &GearInVelocity::ContinuousUpdateActive),
    out("Busy", &GearInVelocity::Busy),
    out("CommandAborted", &GearInVelocity::CommandAborted),
    out("Error", &GearInVelocity::Error),
    out("ErrorID", &GearInVelocity::ErrorID),
});

// MC_GearOut and MC_CamOut: one instruction class, one table (mc_gear_out.hpp).
template <bool kCamming>
using SyncOut = instructions::detail::SynchronousOut<SynchronousAxis, kCamming>;
template <bool kCamming>
const auto kSyncOut = std::to_array<Parameter<SyncOut<kCamming>>>({
    in("Execute", &SyncOut<kCamming>::Execute),
    in("SlavePosition", &SyncOut<kCamming>::SlavePosition),
    in("SyncProfileReference", &SyncOut<kCamming>::SyncProfileReference),
    in("MasterStopDistance", &SyncOut<kCamming>::MasterStopDistance),
    in("Deceleration", &SyncOut<kCamming>::Deceleration),
    in("Jerk", &SyncOut<kCamming>::Jerk),
    in("SyncOutDirection", &SyncOut<kCamming>::SyncOutDirection),
    out("StartSyncOut", &SyncOut<kCamming>::StartSyncOut),
    out("Done", &SyncOut<kCamming>::Done),
    out("Busy", &SyncOut<kCamming>::Busy),
    out("CommandAborted", &SyncOut<kCamming>::CommandAborted),
    out("Error", &SyncOut<kCamming>::Error),
    out("ErrorID", &SyncOut<kCamming>::ErrorID),
});

using CamIn = instructions::MC_CamIn<SynchronousAxis>;
const auto kCamIn = std::to_array<Parameter<CamIn>>({
    in("Master", &CamIn::Master),
    in("Cam", &CamIn::Cam),
    in("Execute", &CamIn::Execute),
    in("MasterOffset", &CamIn::MasterOffset),
    in("SlaveOffset", &CamIn::SlaveOffset),
    in("MasterScaling", &CamIn::MasterScaling),
    in("SlaveScaling", &CamIn::SlaveScaling),
    in("MasterSyncPosition", &CamIn::MasterSyncPosition),
    in("SyncProfileReference", &CamIn::SyncProfileReference),
    in("MasterStartDistance", &CamIn::MasterStartDistance),
    in("Velocity", &CamIn::Velocity),
    in("Acceleration", &CamIn::Acceleration),
    in("Deceleration", &CamIn::Deceleration),
    in("Jerk", &CamIn::Jerk),
    in("ApplicationMode", &CamIn::ApplicationMode),
    in("SyncDirection", &CamIn::SyncDirection),
    out<CamIn, bool>("StartSync", &CamIn::StartSync),
    out<CamIn, bool>("InSync", &CamIn::InSync),
    out<CamIn, bool>("Busy", &CamIn::Busy),
    out<CamIn, bool>("CommandAborted", &CamIn::CommandAborted),
    out<CamIn, bool>("Error", &CamIn::Error),
    out<CamIn, std::uint16_t>("ErrorID", &CamIn::ErrorID),
    out("EndOfProfile", &CamIn::EndOfProfile),
});

// Leading and following value offsets (spec 07 §4.1, §4.2): the members of the shared bases are named with
// the instruction's type, so that one table row per output holds for Absolute and Relative alike.
template <typename FB>
constexpr auto shift_outputs() {
  return std::to_array<Parameter<FB>>({
      out<FB, bool>("Done", &FB::Done),
      out<FB, bool>("Busy", &FB::Busy),
      out<FB, bool>("CommandAborted", &FB::CommandAborted),
      out<FB, bool>("Error", &FB::Error),
      out<FB, std::uint16_t>("ErrorID", &FB::ErrorID),
  });
}
template <typename FB, std::size_t N, std::size_t M>
constexpr auto join(const std::array<Parameter<FB>, N>& a, const std::array<Parameter<FB>, M>& b) {
  std::array<Parameter<FB>, N + M> r{};
  for (std::size_t i = 0; i < N; ++i)
    r[i] = a[i];
  for (std::size_t i = 0; i < M; ++i)
    r[N + i] = b[i];
  return r;
}
template <typename FB>
constexpr auto phasing_inputs() {
  return std::to_array<Parameter<FB>>({
      in<FB, Source>("Master", &FB::Master),
      in<FB, bool>("Execute", &FB::Execute),
      in<FB, double>("PhaseShift", &FB::PhaseShift),
      in<FB, double>("Velocity", &FB::Velocity),
      in<FB, double>("Acceleration", &FB::Acceleration),
      in<FB, double>("Deceleration", &FB::Deceleration),
      in<FB, double>("Jerk", &FB::Jerk),
      in<FB, std::int32_t>("ProfileReference", &FB::ProfileReference),
      in<FB, double>("PhasingDistance", &FB::PhasingDistance),
      in<FB, double>("StartPosition", &FB::StartPosition),
      in<FB, std::int32_t>("Direction", &FB::Direction),
      out<FB, bool>("StartPhasing", &FB::StartPhasing),
  });
}
template <typename FB>
constexpr auto offset_inputs() {
  return std::to_array<Parameter<FB>>({
      in<FB, bool>("Execute", &FB::Execute),
      in<FB, double>("Offset", &FB::Offset),
      in<FB, std::int32_t>("ProfileReference", &FB::ProfileReference),
      in<FB, double>("OffsetDistance", &FB::OffsetDistance),
      in<FB, double>("StartPosition", &FB::StartPosition),
      in<FB, std::int32_t>("Direction", &FB::Direction),
      out<FB, bool>("StartOffset", &FB::StartOffset),
  });
}
using PhasingAbsolute = instructions::MC_PhasingAbsolute<SynchronousAxis>;
using PhasingRelative = instructions::MC_PhasingRelative<SynchronousAxis>;
using OffsetAbsolute = instructions::MC_OffsetAbsolute<SynchronousAxis>;
using OffsetRelative = instructions::MC_OffsetRelative<SynchronousAxis>;
const auto kPhasingAbsolute =
    join(join(phasing_inputs<PhasingAbsolute>(), shift_outputs<PhasingAbsolute>()),
         std::to_array({out("AbsolutePhaseShift", &PhasingAbsolute::AbsolutePhaseShift)}));
const auto kPhasingRelative =
    join(join(phasing_inputs<PhasingRelative>(), shift_outputs<PhasingRelative>()),
         std::to_array({out("CoveredPhaseShift", &PhasingRelative::CoveredPhaseShift)}));
const auto kOffsetAbsolute = join(join(offset_inputs<OffsetAbsolute>(), shift_outputs<OffsetAbsolute>()),
                                  std::to_array({out("AbsoluteOffset", &OffsetAbsolute::AbsoluteOffset)}));
const auto kOffsetRelative = join(join(offset_inputs<OffsetRelative>(), shift_outputs<OffsetRelative>()),
                                  std::to_array({out("CoveredOffset", &OffsetRelative::CoveredOffset)}));

using LeadingValueAdditive = instructions::MC_LeadingValueAdditive<SynchronousAxis>;
const auto kLeadingValueAdditive = std::to_array<Parameter<LeadingValueAdditive>>({
    in("Enable", &LeadingValueAdditive::Enable),
    in("Position", &LeadingValueAdditive::Position),
    in("Velocity", &LeadingValueAdditive::Velocity),
    in("Acceleration", &LeadingValueAdditive::Acceleration),
    out("Busy", &LeadingValueAdditive::Busy),
    out("Error", &LeadingValueAdditive::Error),
    out("ErrorID", &LeadingValueAdditive::ErrorID),
});

using SynchronizedMotionSimulation = instructions::MC_SynchronizedMotionSimulation<SynchronousAxis>;
const auto kSynchronizedMotionSimulation = std::to_array<Parameter<SynchronizedMotionSimulation>>({
    in("Enable", &SynchronizedMotionSimulation::Enable),
    out("InSimulation", &SynchronizedMotionSimulation::InSimulation),
    out("Busy", &SynchronizedMotionSimulation::Busy),
    out("Error", &SynchronizedMotionSimulation::Error),
    out("ErrorID", &SynchronizedMotionSimulation::ErrorID),
});

// The cam instructions (spec 07 §3.2, §3.6). MC_CopyCamData takes arrays, which a scenario event cannot give:
// a machine file gives a cam's elements beside its config (docs/scenarios.md "Cams").
using InterpolateCam = instructions::MC_InterpolateCam;
const auto kInterpolateCam = std::to_array<Parameter<InterpolateCam>>({
    in("Execute", &InterpolateCam::Execute),
    out("Done", &InterpolateCam::Done),
    out("Busy", &InterpolateCam::Busy),
    out("Error", &InterpolateCam::Error),
    out("ErrorID", &InterpolateCam::ErrorID),
});
using GetCamFollowingValue = instructions::MC_GetCamFollowingValue;
const auto kGetCamFollowingValue = std::to_array<Parameter<GetCamFollowingValue>>({
    in<GetCamFollowingValue, bool>("Execute", &GetCamFollowingValue::Execute),
    in("LeadingValue", &GetCamFollowingValue::LeadingValue),
    in<GetCamFollowingValue, double>("MasterOffset", &GetCamFollowingValue::MasterOffset),
    in<GetCamFollowingValue, double>("SlaveOffset", &GetCamFollowingValue::SlaveOffset),
    in<GetCamFollowingValue, double>("MasterScaling", &GetCamFollowingValue::MasterScaling),
    in<GetCamFollowingValue, double>("SlaveScaling", &GetCamFollowingValue::SlaveScaling),
    out<GetCamFollowingValue, bool>("Done", &GetCamFollowingValue::Done),
    out<GetCamFollowingValue, bool>("Busy", &GetCamFollowingValue::Busy),
    out<GetCamFollowingValue, bool>("Error", &GetCamFollowingValue::Error),
    out<GetCamFollowingValue, std::uint16_t>("ErrorID", &GetCamFollowingValue::ErrorID),
    out("Value", &GetCamFollowingValue::Value),
    out("FirstDerivative", &GetCamFollowingValue::FirstDerivative),
    out("SecondDerivative", &GetCamFollowingValue::SecondDerivative),
});
using GetCamFollowingValueCyclic = instructions::MC_GetCamFollowingValueCyclic;
const auto kGetCamFollowingValueCyclic = std::to_array<Parameter<GetCamFollowingValueCyclic>>({
    in("Enable", &GetCamFollowingValueCyclic::Enable),
    in("LeadingValue", &GetCamFollowingValueCyclic::LeadingValue),
    in<GetCamFollowingValueCyclic, double>("MasterOffset", &GetCamFollowingValueCyclic::MasterOffset),
    in<GetCamFollowingValueCyclic, double>("SlaveOffset", &GetCamFollowingValueCyclic::SlaveOffset),
    in<GetCamFollowingValueCyclic, double>("MasterScaling", &GetCamFollowingValueCyclic::MasterScaling),
    in<GetCamFollowingValueCyclic, double>("SlaveScaling", &GetCamFollowingValueCyclic::SlaveScaling),
    out("Valid", &GetCamFollowingValueCyclic::Valid),
    out("Busy", &GetCamFollowingValueCyclic::Busy),
    out("Error", &GetCamFollowingValueCyclic::Error),
    out("ErrorID", &GetCamFollowingValueCyclic::ErrorID),
    out("Value", &GetCamFollowingValueCyclic::Value),
    out("FirstDerivative", &GetCamFollowingValueCyclic::FirstDerivative),
    out("SecondDerivative", &GetCamFollowingValueCyclic::SecondDerivative),
});
using GetCamLeadingValue = instructions::MC_GetCamLeadingValue;
const auto kGetCamLeadingValue = std::to_array<Parameter<GetCamLeadingValue>>({
    in<GetCamLeadingValue, bool>("Execute", &GetCamLeadingValue::Execute),
    in("FollowingValue", &GetCamLeadingValue::FollowingValue),
    in("ApproachLeadingValue", &GetCamLeadingValue::ApproachLeadingValue),
    in("ApproachDirection", &GetCamLeadingValue::ApproachDirection),
    in<GetCamLeadingValue, double>("MasterOffset", &GetCamLeadingValue::MasterOffset),
    in<GetCamLeadingValue, double>("SlaveOffset", &GetCamLeadingValue::SlaveOffset),
    in<GetCamLeadingValue, double>("MasterScaling", &GetCamLeadingValue::MasterScaling),
    in<GetCamLeadingValue, double>("SlaveScaling", &GetCamLeadingValue::SlaveScaling),
    out<GetCamLeadingValue, bool>("Done", &GetCamLeadingValue::Done),
    out<GetCamLeadingValue, bool>("Busy", &GetCamLeadingValue::Busy),
    out<GetCamLeadingValue, bool>("Error", &GetCamLeadingValue::Error),
    out<GetCamLeadingValue, std::uint16_t>("ErrorID", &GetCamLeadingValue::ErrorID),
    out("Value", &GetCamLeadingValue::Value),
});

template <typename Axis>
using PositionProfile = instructions::MC_PositionProfile<Axis>;
template <typename Axis>
const auto kPositionProfile = std::to_array<Parameter<PositionProfile<Axis>>>({
    in("TimePosition", &PositionProfile<Axis>::TimePosition),
    in("Execute", &PositionProfile<Axis>::Execute),
    in("BufferMode", &PositionProfile<Axis>::BufferMode),
    in("StartTime", &PositionProfile<Axis>::StartTime),
    in("ProfileReference", &PositionProfile<Axis>::ProfileReference),
    in("Velocity", &PositionProfile<Axis>::Velocity),
    in("Acceleration", &PositionProfile<Axis>::Acceleration),
    in("Deceleration", &PositionProfile<Axis>::Deceleration),
    in("Jerk", &PositionProfile<Axis>::Jerk),
    out("Done", &PositionProfile<Axis>::Done),
    out("Busy", &PositionProfile<Axis>::Busy),
    out("Active", &PositionProfile<Axis>::Active),
    out("CommandAborted", &PositionProfile<Axis>::CommandAborted),
    out("Error", &PositionProfile<Axis>::Error),
    out("ErrorID", &PositionProfile<Axis>::ErrorID),
});

template <typename Axis>
using MotionInVelocity = instructions::MC_MotionInVelocity<Axis>;
template <typename Axis>
const auto kMotionInVelocity = std::to_array<Parameter<MotionInVelocity<Axis>>>({
    in("Enable", &MotionInVelocity<Axis>::Enable),
    in("Velocity", &MotionInVelocity<Axis>::Velocity),
    in("Acceleration", &MotionInVelocity<Axis>::Acceleration),
    in("PositionControlled", &MotionInVelocity<Axis>::PositionControlled),
    out("Busy", &MotionInVelocity<Axis>::Busy),
    out("CommandAborted", &MotionInVelocity<Axis>::CommandAborted),
    out("Error", &MotionInVelocity<Axis>::Error),
    out("ErrorID", &MotionInVelocity<Axis>::ErrorID),
});

template <typename Axis>
using MotionInPosition = instructions::MC_MotionInPosition<Axis>;
template <typename Axis>
const auto kMotionInPosition = std::to_array<Parameter<MotionInPosition<Axis>>>({
    in("Enable", &MotionInPosition<Axis>::Enable),
    in("Position", &MotionInPosition<Axis>::Position),
    in("Velocity", &MotionInPosition<Axis>::Velocity),
    in("Acceleration", &MotionInPosition<Axis>::Acceleration),
    out("Busy", &MotionInPosition<Axis>::Busy),
    out("CommandAborted", &MotionInPosition<Axis>::CommandAborted),
    out("Error", &MotionInPosition<Axis>::Error),
    out("ErrorID", &MotionInPosition<Axis>::ErrorID),
});

template <typename Axis>
using MotionInSuperimposed = instructions::MC_MotionInSuperimposed<Axis>;
template <typename Axis>
const auto kMotionInSuperimposed = std::to_array<Parameter<MotionInSuperimposed<Axis>>>({
    in("Enable", &MotionInSuperimposed<Axis>::Enable),
    in("Distance", &MotionInSuperimposed<Axis>::Distance),
    in("VelocityDiff", &MotionInSuperimposed<Axis>::VelocityDiff),
    in("AccelerationDiff", &MotionInSuperimposed<Axis>::AccelerationDiff),
    out("Busy", &MotionInSuperimposed<Axis>::Busy),
    out("CommandAborted", &MotionInSuperimposed<Axis>::CommandAborted),
    out("Error", &MotionInSuperimposed<Axis>::Error),
    out("ErrorID", &MotionInSuperimposed<Axis>::ErrorID),
});

template <typename Axis>
using MotionInSuperimposedAxes = instructions::MC_MotionInSuperimposedAxes<Axis>;
template <typename Axis>
const auto kMotionInSuperimposedAxes = std::to_array<Parameter<MotionInSuperimposedAxes<Axis>>>({
    in("SuperimposingAxis", &MotionInSuperimposedAxes<Axis>::SuperimposingAxis),
    in("Enable", &MotionInSuperimposedAxes<Axis>::Enable),
    out("Busy", &MotionInSuperimposedAxes<Axis>::Busy),
    out("CommandAborted", &MotionInSuperimposedAxes<Axis>::CommandAborted),
    out("Error", &MotionInSuperimposedAxes<Axis>::Error),
    out("ErrorID", &MotionInSuperimposedAxes<Axis>::ErrorID),
});

using SaveAbsoluteEncoderData = instructions::MC_SaveAbsoluteEncoderData<techobjects::RetentiveStore>;
const auto kSaveAbsoluteEncoderDataTable = std::to_array<Parameter<SaveAbsoluteEncoderData>>({
    in("Execute", &SaveAbsoluteEncoderData::Execute),
    out("Done", &SaveAbsoluteEncoderData::Done),
    out("Busy", &SaveAbsoluteEncoderData::Busy),
    out("CommandAborted", &SaveAbsoluteEncoderData::CommandAborted),
    out("Error", &SaveAbsoluteEncoderData::Error),
    out("ErrorID", &SaveAbsoluteEncoderData::ErrorID),
});

// The instructions each TO type accepts (spec 01 §1.3), in the order of the manual.
constexpr std::array<std::string_view, 12> kSpeedAxisInstructions{
    "MC_Power",          "MC_Reset",       "MC_MoveVelocity",   "MC_MoveJog",          "MC_Halt",
    "MC_Stop",           "MC_SetAxisSTW",  "MC_WriteParameter", "MC_MotionInVelocity", "MC_TorqueLimiting",
    "MC_TorqueAdditive", "MC_TorqueRange",
};
constexpr std::array<std::string_view, 22> kPositioningAxisInstructions{
    "MC_Power",
    "MC_Reset",
    "MC_Home",
    "MC_Halt",
    "MC_MoveAbsolute",
    "MC_MoveRelative",
    "MC_PositionProfile",
    "MC_MoveVelocity",
    "MC_MoveJog",
    "MC_MoveSuperimposed",
    "MC_HaltSuperimposed",
    "MC_SetSensor",
    "MC_Stop",
    "MC_SetAxisSTW",
    "MC_WriteParameter",
    "MC_MotionInVelocity",
    "MC_MotionInPosition",
    "MC_MotionInSuperimposed",
    "MC_MotionInSuperimposedAxes",
    "MC_TorqueLimiting",
    "MC_TorqueAdditive",
    "MC_TorqueRange",
};
// A synchronous axis accepts every instruction of a positioning axis (spec 01 §1.3) and these.
constexpr std::array<std::string_view, 12> kSynchronousOnlyInstructions{
    "MC_GearIn",         "MC_GearInPos",      "MC_GearInVelocity",       "MC_GearOut",
    "MC_CamIn",          "MC_CamOut",         "MC_PhasingAbsolute",      "MC_PhasingRelative",
    "MC_OffsetAbsolute", "MC_OffsetRelative", "MC_LeadingValueAdditive", "MC_SynchronizedMotionSimulation",
};
template <std::size_t A, std::size_t B>
constexpr std::array<std::string_view, A + B> joined(const std::array<std::string_view, A>& a,
                                                     const std::array<std::string_view, B>& b) {
  std::array<std::string_view, A + B> all{};
  for (std::size_t i = 0; i < A; ++i)
    all[i] = a[i];
  for (std::size_t i = 0; i < B; ++i)
    all[A + i] = b[i];
  return all;
}
constexpr auto kSynchronousAxisInstructions =
    joined(kPositioningAxisInstructions, kSynchronousOnlyInstructions);
constexpr std::array<std::string_view, 4> kExternalEncoderInstructions{"MC_Power", "MC_Reset", "MC_Home",
                                                                       "MC_WriteParameter"};
constexpr std::array<std::string_view, 4> kCamInstructions{
    "MC_InterpolateCam", "MC_GetCamFollowingValue", "MC_GetCamFollowingValueCyclic", "MC_GetCamLeadingValue"};

// The other instructions of spec 03 (positioning, synchronous operation, measuring, torque, kinematics...).
constexpr std::array<std::string_view, 7> kPlannedInstructions{
    "MC_CopyCamData", "MC_MeasuringInput", "MC_MeasuringInputCyclic", "MC_AbortMeasuringInput",
    "MC_OutputCam",   "MC_CamTrack",       "MC_ReadParameter",
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
    case ParameterType::kTechnologyObject:
      return "TO";
    case ParameterType::kCam:
      return "TO_Cam";
    case ParameterType::kTimePosition:
      return "time-position profile";
  }
  return "?";
}

std::optional<std::size_t> Instance::find(std::string_view name) const noexcept {
  const auto p = parameters();
  const auto it = std::find_if(p.begin(), p.end(), [&](const ParameterInfo& i) { return i.name == name; });
  if (it == p.end()) return std::nullopt;
  return static_cast<std::size_t>(it - p.begin());
}

std::span<const std::string_view> instructions_for(TechnologyObjectKind kind) noexcept {
  switch (kind) {
    case TechnologyObjectKind::kSpeedAxis:
      return kSpeedAxisInstructions;
    case TechnologyObjectKind::kPositioningAxis:
      return kPositioningAxisInstructions;
    case TechnologyObjectKind::kSynchronousAxis:
      return kSynchronousAxisInstructions;
    case TechnologyObjectKind::kExternalEncoder:
      return kExternalEncoderInstructions;
    case TechnologyObjectKind::kCam:
      return kCamInstructions;
  }
  return {};
}

bool is_planned_instruction(std::string_view name) noexcept {
  return std::find(kPlannedInstructions.begin(), kPlannedInstructions.end(), name) !=
         kPlannedInstructions.end();
}

namespace {

template <typename Axis>
std::unique_ptr<Instance> make_common(std::string_view instruction) {
  if (instruction == "MC_Power") return make(kPower<Axis>);
  if (instruction == "MC_Reset") return make(kReset<Axis>);
  if (instruction == "MC_WriteParameter") return make(kWriteParameter<Axis>);
  return nullptr;
}

template <typename Axis>
std::unique_ptr<Instance> make_motion(std::string_view instruction) {
  if (auto common = make_common<Axis>(instruction)) return common;
  if (instruction == "MC_MoveVelocity") return make(kMoveVelocity<Axis>);
  if (instruction == "MC_MoveJog") return make(kMoveJog<Axis>);
  if (instruction == "MC_Halt") return make(kHalt<Axis>);
  if (instruction == "MC_Stop") return make(kStop<Axis>);
  if (instruction == "MC_SetAxisSTW") return make(kSetAxisStw<Axis>);
  if (instruction == "MC_TorqueLimiting") return make(kTorqueLimiting<Axis>);
  if (instruction == "MC_TorqueAdditive") return make(kTorqueAdditive<Axis>);
  if (instruction == "MC_TorqueRange") return make(kTorqueRange<Axis>);
  if (instruction == "MC_MotionInVelocity") return make(kMotionInVelocity<Axis>);
  return nullptr;
}

// The instructions of a positioning axis beyond a speed axis' (also those of a synchronous axis).
template <typename Axis>
std::unique_ptr<Instance> make_positioning(std::string_view instruction) {
  if (instruction == "MC_MoveAbsolute") return make(kMoveAbsolute<Axis>);
  if (instruction == "MC_MoveRelative") return make(kMoveRelative<Axis>);
  if (instruction == "MC_MoveSuperimposed") return make(kMoveSuperimposed<Axis>);
  if (instruction == "MC_HaltSuperimposed") return make(kHaltSuperimposed<Axis>);
  if (instruction == "MC_Home") return make(kHome<Axis>);
  if (instruction == "MC_SetSensor") return make(kSetSensor<Axis>);
  if (instruction == "MC_PositionProfile") return make(kPositionProfile<Axis>);
  if (instruction == "MC_MotionInPosition") return make(kMotionInPosition<Axis>);
  if (instruction == "MC_MotionInSuperimposed") return make(kMotionInSuperimposed<Axis>);
  if (instruction == "MC_MotionInSuperimposedAxes") return make(kMotionInSuperimposedAxes<Axis>);
  return make_motion<Axis>(instruction);
}

}  // namespace

std::unique_ptr<Instance> make_save_absolute_encoder_data(techobjects::RetentiveStore& store) {
  return std::make_unique<InstanceOf<SaveAbsoluteEncoderData, kSaveAbsoluteEncoderDataTable.size()>>(
      kSaveAbsoluteEncoderDataTable, &store);
}

std::unique_ptr<Instance> make_instance(std::string_view instruction, TechnologyObjectKind kind) {
  switch (kind) {
    case TechnologyObjectKind::kSpeedAxis:
      return make_motion<SpeedAxis>(instruction);
    case TechnologyObjectKind::kPositioningAxis:
      return make_positioning<PositioningAxis>(instruction);
    case TechnologyObjectKind::kSynchronousAxis:
      if (instruction == "MC_GearIn") return make(kGearIn);
      if (instruction == "MC_GearInPos") return make(kGearInPos);
      if (instruction == "MC_GearInVelocity") return make(kGearInVelocity);
      if (instruction == "MC_GearOut") return make(kSyncOut<false>);
      if (instruction == "MC_CamIn") return make(kCamIn);
      if (instruction == "MC_CamOut") return make(kSyncOut<true>);
      if (instruction == "MC_PhasingAbsolute") return make(kPhasingAbsolute);
      if (instruction == "MC_PhasingRelative") return make(kPhasingRelative);
      if (instruction == "MC_OffsetAbsolute") return make(kOffsetAbsolute);
      if (instruction == "MC_OffsetRelative") return make(kOffsetRelative);
      if (instruction == "MC_LeadingValueAdditive") return make(kLeadingValueAdditive);
      if (instruction == "MC_SynchronizedMotionSimulation") return make(kSynchronizedMotionSimulation);
      return make_positioning<SynchronousAxis>(instruction);
    case TechnologyObjectKind::kExternalEncoder:
      if (instruction == "MC_Home") return make(kHome<ExternalEncoder>);
      return make_common<ExternalEncoder>(instruction);
    case TechnologyObjectKind::kCam:
      if (instruction == "MC_InterpolateCam") return make(kInterpolateCam);
      if (instruction == "MC_GetCamFollowingValue") return make(kGetCamFollowingValue);
      if (instruction == "MC_GetCamFollowingValueCyclic") return make(kGetCamFollowingValueCyclic);
      if (instruction == "MC_GetCamLeadingValue") return make(kGetCamLeadingValue);
      return nullptr;
  }
  return nullptr;
}

}  // namespace tomc::scenario::detail
