// TO_PositioningAxis: MC_TorqueLimiting — force/torque limiting (Mode 0) and fixed-stop detection with
// clamping (Mode 1), spec 01 §8.10/§8.11, spec 03 §4.18.3, seed 004 §6.7.9.1/§6.7.9.2. Decisions F1–F7.
// Telegram 750: MC_TorqueAdditive, MC_TorqueRange, torque precontrol, StatusTorqueData (decisions Q1–Q6).
#include <cmath>
#include <numbers>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/motion/axis_units.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

std::uint16_t PositioningAxis::torque_limiting_rejection(const TorqueLimitingInputs& in) const noexcept {
  if (in.Mode != 0 && in.Mode != 1) return error_id::kInvalidMode;
  if (!std::isfinite(in.Limit) || in.Limit > 1.0e12) return error_id::kInvalidTorqueLimit;
  if (!core_.torque.active) {
    // The axis control panel has master control: the user program starts no job (spec 02 §9.2, W2).
    if (const auto e = core_.control.program_job_rejection()) return e;
    // Start conditions (spec 01 §8.10, §12 scenario 36): no MC_Stop, no error that prevents enabling.
    if (core_.stop.id != 0 && core_.stop.execute) return error_id::kLockedByStop;
    if (core_.alarms.strongest_reaction() == AlarmReaction::kRemoveEnable)
      return error_id::kAxisBlockedByAlarm;
  }
  // Limiting needs a drive telegram with torque reduction (telegrams 10x); a virtual or simulated axis
  // accepts the job and outputs nothing (spec 01 §2.5 table).
  if (drive_used() && !drive_has_momred_ && in.Mode == 0) return error_id::kNoTorqueReduction;
  if (in.Mode == 1 && !(core_.torque.active && core_.torque.mode == 1)) {
    // Fixed-stop detection: enabled, position-controlled, consistent tolerances (spec 03 §4.18.3, §8.11).
    if (core_.phase != PowerPhase::kEnabled) return error_id::kAxisNotEnabled;
    if (!position_controlled_) return error_id::kNotPositionControlled;
    const auto& c = db_.Clamping;
    const bool fe_monitored = db_.FollowingError.EnableMonitoring;
    if (c.PositionTolerance >= c.FollowingErrorDeviation ||
        (fe_monitored && db_.FollowingError.MaxValue <= c.FollowingErrorDeviation)) {
      return error_id::kInvalidClampingConfiguration;
    }
  }
  // Mutual exclusion with MC_TorqueRange (spec 03 §4.18.3 priority).
  if (!core_.torque.active && core_.torque_data.range_active()) return error_id::kTorqueLimitingExclusion;
  return 0;
}

TorqueLimitingState PositioningAxis::torque_limiting(const TorqueLimitingInputs& in) noexcept {
  TorqueLimitingState s =
      core_.torque.call(in, [this](const TorqueLimitingInputs& i) { return torque_limiting_rejection(i); });
  s.InClamping = core_.torque.active && clamping_.clamped();
  s.InLimitation = core_.torque.active && core_.in_limitation;
  return s;
}

TorqueDataConditions PositioningAxis::torque_data_conditions() const noexcept {
  const bool linear_motor = db_.Actor.MotorType == static_cast<std::int32_t>(ActorMotorType::kLinearMotor);
  return core_.torque_data_conditions(drive_used() ? &drive_ : nullptr,
                                      linear_motor ? db_.Actor.LinearMotorDriveParameter.ReferenceForce
                                                   : db_.Actor.DriveParameter.ReferenceTorque,
                                      db_.Actor.InverseDirection);
}

TorqueJobState PositioningAxis::torque_additive(const TorqueAdditiveInputs& in) noexcept {
  return core_.torque_data.additive(in, torque_data_conditions());
}

TorqueJobState PositioningAxis::torque_range(const TorqueRangeInputs& in) noexcept {
  return core_.torque_data.range(in, torque_data_conditions());
}

double PositioningAxis::torque_precontrol() const noexcept {
  // Only with Mode 1, in position-controlled operation of a drive that follows the TO's setpoint (spec 02
  // §7.5; a virtual or simulated axis has no drive: "precontrol has no effect", spec 01 §2.5).
  if (db_.TorquePreControl.Mode != static_cast<std::int32_t>(TorquePreControlMode::kAccelerationBased) ||
      !drive_used() || !position_controlled_ || follows_actual() || !core_.drive_follows_setpoint())
    return 0.0;
  TorquePrecontrolMechanics m;
  m.linear_motor = db_.Actor.MotorType == static_cast<std::int32_t>(ActorMotorType::kLinearMotor);
  m.motor_inertia =
      m.linear_motor ? db_.Actor.LinearMotorDriveParameter.MotorMass : db_.Actor.DriveParameter.MotorInertia;
  m.load_inertia = db_.Actor.LoadInertia;
  if (db_.Properties.MotionType == static_cast<std::int32_t>(PropertiesMotionType::kLinear)) {
    const auto metres = length_unit_scale(db_.Units.LengthUnit);
    m.metres_or_radians_per_unit = metres ? metres->base : 0.0;
  } else {
    m.metres_or_radians_per_unit = 2.0 * std::numbers::pi / units_.units_per_revolution;
  }
  m.motor_revolutions_per_unit = encoder_.chain().scaling().motor_revolutions_per_unit();
  m.scale_percent = db_.TorquePreControl.Scale;
  // The setpoint acceleration after the dynamic filter, the one the position controller uses (eq. 6).
  return precontrol_torque(filtered_.acceleration, m);
}

void PositioningAxis::servo_torque_data() noexcept {
  auto& status = db_.StatusTorqueData;
  status.CommandAdditiveTorqueActive = core_.torque_data.additive_active() ? 1 : 0;
  status.CommandTorqueRangeActive = core_.torque_data.range_active() ? 1 : 0;
  // A linear motor has force where a standard motor has torque (spec 04 §4.7).
  const bool linear_motor = db_.Actor.MotorType == static_cast<std::int32_t>(ActorMotorType::kLinearMotor);
  // Without telegram 750 nothing goes to the drive: the total is 0, the start conditions are not needed.
  if (!drive_used() || drive_.device_config().supplementary_telegram != 750) {
    (linear_motor ? status.TotalForceAdditive : status.TotalTorqueAdditive) = 0.0;
    return;
  }
  const TorqueDataConditions c = torque_data_conditions();
  const double total = core_.torque_data.additive_value() + torque_precontrol();
  (linear_motor ? status.TotalForceAdditive : status.TotalTorqueAdditive) = total;
  core_.torque_data.write(drive_, total, c.reference, c.inverse);
  (linear_motor ? status.ActualForce : status.ActualTorque) =
      (c.inverse ? -1.0 : 1.0) * telegrams::n2_to_torque(drive_.supplementary_actual().M_ACT, c.reference);
}

void PositioningAxis::servo_torque_limiting() noexcept {
  const bool active = core_.torque.active;
  if (!active) {  // the common case, kept short: only what the end of a job has to clear
    core_.in_limitation = false;
    clamping_.reset();
    if (drive_used() && (core_.torque.stw2_fixed_stop || command_.momred != 0))
      (void)drive_torque_limit(command_, drive_.drive_actual(), core_.torque, 0.0, 1.0, drive_has_momred_,
                               drive_has_meldw_);
    return;
  }
  if (drive_used()) {
    const bool linear_motor = db_.Actor.MotorType == static_cast<std::int32_t>(ActorMotorType::kLinearMotor);
    const bool linear_axis =
        db_.Properties.MotionType == static_cast<std::int32_t>(PropertiesMotionType::kLinear);
    const bool load_side =
        db_.TorqueLimiting.LimitBase == static_cast<std::int32_t>(TorqueLimitBase::kLoadSide);
    double motor_limit = 0.0;
    if (active) {
      const bool force = linear_motor || (linear_axis && load_side);
      const double limit = core_.torque.limit >= 0.0 ? core_.torque.limit
                                                     : (force ? db_.TorqueLimiting.LimitDefaults.Force
                                                              : db_.TorqueLimiting.LimitDefaults.Torque);
      TorqueLimitMechanics m;
      m.linear_axis = linear_axis;
      m.linear_motor = linear_motor;
      m.load_side = load_side;
      m.gear_ratio =
          static_cast<double>(db_.LoadGear.Numerator) / static_cast<double>(db_.LoadGear.Denominator);
      m.efficiency = db_.Actor.Efficiency;
      const auto metres = length_unit_scale(db_.Units.LengthUnit);
      m.leadscrew_per_rev = db_.Mechanics.LeadScrew * units_.leadscrew * (metres ? metres->base : 0.0);
      motor_limit = motor_torque_limit(limit, m);
    }
    const double reference = linear_motor ? db_.Actor.LinearMotorDriveParameter.ReferenceForce
                                          : db_.Actor.DriveParameter.ReferenceTorque;
    core_.in_limitation = drive_torque_limit(command_, drive_.drive_actual(), core_.torque, motor_limit,
                                             reference, drive_has_momred_, drive_has_meldw_);
  } else {
    core_.in_limitation = false;
  }

  // Fixed-stop detection (spec 01 §8.11): only in position-controlled operation of an enabled axis.
  const bool controlled = core_.phase == PowerPhase::kEnabled && !follows_actual() && position_controlled_;
  if (!(active && core_.torque.mode == 1 && controlled)) {
    clamping_.reset();
    return;
  }
  clamping_.configure(db_.Clamping.FollowingErrorDeviation, db_.Clamping.PositionTolerance);
  const bool moving_away =
      motion_.id != 0 && motion_.position_controlled && setpoint_.velocity * clamping_.stop_direction() < 0.0;
  switch (clamping_.update(db_.StatusPositioning.FollowingError, actual_position_, moving_away)) {
    case ClampingEvent::kClamped:
      clamp_abort_pending_ = true;
      break;
    case ClampingEvent::kLost:
      // The stop broke or gave way: alarm, the axis is disabled (seed 004 §6.7.9.2; decision F4).
      raise(kAlarmPositioning, kClampingToleranceLeft);
      break;
    case ClampingEvent::kReleased:
    case ClampingEvent::kNone:
      break;
  }
}

void PositioningAxis::apply_clamping() noexcept {
  if (!clamping_.clamped()) {
    clamp_abort_pending_ = false;
    return;
  }
  // At the stop every motion and synchronous job ends with CommandAborted (spec 03 §4.18.3 note 6); while
  // clamped, a job that drives further into the stop ends the same way (decision F3). The setpoint stays
  // where it is, so the following error — and with it the clamping force — stays constant.
  const bool into_stop = motion_.id != 0 && setpoint_.velocity * clamping_.stop_direction() > 0.0;
  if (!clamp_abort_pending_ && !into_stop) return;
  clamp_abort_pending_ = false;
  abort_superimposed(0);
  abort_motion(0);
  abort_pending(0);
  abort_synchronous(0);
  generator_ = Generator::kIdle;
  setpoint_.velocity = 0.0;
  setpoint_.acceleration = 0.0;
}

}  // namespace tomc::techobjects
