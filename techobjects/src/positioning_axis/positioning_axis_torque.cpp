// TO_PositioningAxis: MC_TorqueLimiting — force/torque limiting (Mode 0) and fixed-stop detection with
// clamping (Mode 1), spec 01 §8.10/§8.11, spec 03 §4.18.3, seed 004 §6.7.9.1/§6.7.9.2. Decisions F1–F7.
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/motion/axis_units.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

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
  if (device_ != nullptr && !drive_has_momred_ && in.Mode == 0) return error_id::kNoTorqueReduction;
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
  return 0;
}

TorqueLimitingState PositioningAxis::torque_limiting(const TorqueLimitingInputs& in) noexcept {
  TorqueLimitingState s =
      core_.torque.call(in, [this](const TorqueLimitingInputs& i) { return torque_limiting_rejection(i); });
  s.InClamping = core_.torque.active && clamping_.clamped();
  s.InLimitation = core_.torque.active && core_.in_limitation;
  return s;
}

bool PositioningAxis::position_monitorings_suspended() const noexcept {
  return core_.torque.active && db_.TorqueLimiting.PositionBasedMonitorings ==
                                    static_cast<std::int32_t>(PositionBasedMonitoringMode::kDeactivated);
}

void PositioningAxis::servo_torque_limiting() noexcept {
  const bool active = core_.torque.active;
  if (!active) {  // the common case, kept short: only what the end of a job has to clear
    core_.in_limitation = false;
    clamping_.reset();
    if (device_ != nullptr && (core_.torque.stw2_fixed_stop || command_.momred != 0))
      (void)drive_torque_limit(command_, drive_.drive_actual(), core_.torque, 0.0, 1.0, drive_has_momred_,
                               drive_has_meldw_);
    return;
  }
  if (device_ != nullptr) {
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
