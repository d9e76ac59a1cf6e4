#pragma once
// The torque data of supplementary telegram 750 (spec 01 §3.13, §8.12, §8.13; spec 03 §4.18.1/§4.18.2; spec
// 06 §2.14, §8): MC_TorqueAdditive (M_ADD1), MC_TorqueRange (M_LIMIT_POS / M_LIMIT_NEG), the
// acceleration-based torque precontrol of spec 02 §7.5 and what the TO shows of them in StatusTorqueData.
// Shared by the speed, positioning and synchronous axes; noexcept, no allocation.
#include <cstdint>

#include "tomc/techobjects/drive/drive_connection.hpp"

namespace tomc::techobjects {

// Inputs of MC_TorqueAdditive (spec 03 §4.18.1), taken on every call while Enable is TRUE.
struct TorqueAdditiveInputs {
  bool Enable = false;
  double Value = 0.0;  // additional torque (force with a linear motor) in technology units, ±1.0E12
};

// Inputs of MC_TorqueRange (spec 03 §4.18.2), taken on every call while Enable is TRUE.
struct TorqueRangeInputs {
  bool Enable = false;
  double UpperLimit = 1.0e12;  // must be > LowerLimit
  double LowerLimit = -1.0e12;
};

// Outputs of both Enable-level instructions (no Done, no CommandAborted, spec 03 L3).
struct TorqueJobState {
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;
};

// What decides whether a telegram-750 job may start, gathered by the axis (decision Q2).
struct TorqueDataConditions {
  bool drive = false;         // a drive is connected (FALSE: virtual axis or simulation, nothing is output)
  bool telegram_750 = false;  // the drive has supplementary telegram 750
  bool enabled = false;       // MC_Power.Status (MC_TorqueAdditive only, spec 03 §4.18.1)
  bool stop_locks = false;    // an MC_Stop with Execute = TRUE (spec 01 §8.12/§8.13)
  std::uint16_t panel = 0;    // the axis control panel's rejection (16#8012), 0 = none
  bool torque_limiting = false;  // MC_TorqueLimiting is active (MC_TorqueRange only: mutual exclusion)
  // The wire format of the limits, fixed until a TO restart (RES variables): MC_TorqueRange keeps them as N2.
  double reference = 1.0;  // Actor.DriveParameter.ReferenceTorque (linear motor: ReferenceForce)
  bool inverse = false;    // Actor.InverseDirection
};

// The TO's side of both jobs: 16 bytes per axis (docs/performance.md "Memory per axis"; decision Q3): the
// additive value as a float (7 digits; the wire has 4.5), the limits as the N2 words they are sent as.
class TorqueDataJobs {
 public:
  TorqueJobState additive(const TorqueAdditiveInputs& in, const TorqueDataConditions& c) noexcept;
  TorqueJobState range(const TorqueRangeInputs& in, const TorqueDataConditions& c) noexcept;

  bool additive_active() const noexcept { return additive_active_; }
  bool range_active() const noexcept { return range_active_; }
  double additive_value() const noexcept { return additive_active_ ? static_cast<double>(value_) : 0.0; }

  // MC_Servo: M_ADD1, M_LIMIT_POS, M_LIMIT_NEG of this cycle (spec 06 §8): `total` is the additive torque in
  // technology units (MC_TorqueAdditive plus precontrol), negated with `inverse` (Actor.InverseDirection,
  // spec 01 §8.12) and saturated to N2 (±200 %) of `reference`; without MC_TorqueRange the limits are ±100 %
  // (TV14).
  void write(DriveConnection& drive, double total, double reference, bool inverse) const noexcept;

 private:
  float value_ = 0.0F;               // MC_TorqueAdditive.Value in force
  std::int16_t limit_pos_ = 0x4000;  // MC_TorqueRange in force, as M_LIMIT_POS / M_LIMIT_NEG
  std::int16_t limit_neg_ = -0x4000;
  std::uint16_t additive_error_ = 0;  // latched until Enable goes FALSE (as decision F7)
  std::uint16_t range_error_ = 0;
  bool additive_active_ = false;
  bool range_active_ = false;
};

// Acceleration-based torque precontrol (spec 02 §7.4 eq. 6, §7.5; seed 004 §6.13.5), in technology units on
// the motor side: M_add = Scale/100 · J · α_motor for a standard motor, F_add = Scale/100 · m · a for a
// linear motor. `acceleration` in position units/s², `metres_or_radians_per_unit` the load's SI length
// (linear axis) or angle (rotary axis) per position unit, `motor_revolutions_per_unit` from the setpoint
// scaling.
struct TorquePrecontrolMechanics {
  bool linear_motor = false;
  double motor_inertia = 0.0;  // Actor.DriveParameter.MotorInertia [kg·m²] (linear motor: MotorMass [kg])
  double load_inertia = 0.0;   // Actor.LoadInertia, load side [kg·m²] or [kg]
  double metres_or_radians_per_unit = 0.0;
  double motor_revolutions_per_unit = 0.0;
  double scale_percent = 100.0;  // TorquePreControl.Scale
};
double precontrol_torque(double acceleration, const TorquePrecontrolMechanics& m) noexcept;

}  // namespace tomc::techobjects
