// TO_PositioningAxis, one application cycle.
// MC_Servo:        drive/encoder frames -> actual values -> position control -> servo-rate monitoring
//                  (following error, positioning window, standstill, hardware limits) -> drive setpoint
// MC_Interpolator: MC_Reset -> alarm reactions -> enable/disable -> live job inputs (override, jog) ->
//                  setpoint generation -> software-limit look-ahead -> job completion -> status
#include <algorithm>
#include <cmath>
#include <limits>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

constexpr double kStandstillEpsilon = 1e-9;  // position units / s

// floor((x - start) / length): the modulo cycle index of a continuous position.
std::int64_t cycle_index(double x, double start, double length) noexcept {
  return static_cast<std::int64_t>(std::floor((x - start) / length));
}

}  // namespace

// =========================================================================================================
// MC_Servo

void PositioningAxis::servo(const CycleClock& clock) noexcept {
  if (!servo_cycle_known_ || clock.servo_cycle_s != servo_cycle_s_) {
    servo_cycle_s_ = clock.servo_cycle_s;
    servo_cycle_known_ = true;
    configure_components();  // the cycle time enters the chain, the controller and the monitors
    if (retained_restored_ && retained_.valid) {
      // Power-up of an absolute encoder with its retained adjustment (spec 01 §3.7, spec 02 §5.9).
      RetainedSensorState r;
      r.AbsEncoderOffset = retained_.AbsEncoderOffset;
      r.MeasuringRangeCount = retained_.MeasuringRangeCount;
      r.LastAbsoluteValue = retained_.LastAbsoluteValue;
      encoder_.chain().power_up(&r);
      // The backlash was crossed in DirectionAbsoluteHoming before the adjustment (spec 02 §5.11 Mode 6/7).
      backlash_.assume_contact(
          db_.Sensor[db_.OperativeSensor - 1].Backlash.DirectionAbsoluteHoming == 0 ? 1 : -1);
    }
    // The other absolute encoders with their own retained adjustments, whatever the start-up encoder has.
    power_up_additional_encoders();
  }
  // Dynamic filter (spec 02 §7.6): x_ipo -> x_f, in position control only; before the actual values, which a
  // virtual axis takes from x_f.
  filtered_ = dynamic_filter_.update(setpoint_, !follows_actual() && position_controlled_);
  if (drive_used()) {
    read_actual_values();
    // Backlash compensation (spec 01 §5.9): a correction of the motor encoder's actual value — of the
    // start-up encoder it is configured for; after MC_SetSensor to another encoder (e.g. on the load side,
    // which sees no backlash) nothing is added (decision B4).
    if (db_.OperativeSensor == db_.PositionControl.InitialOperativeSensor)
      actual_position_ += backlash_.compensate(encoder_.chain(), actual_valid_,
                                               !follows_actual() && position_controlled_, filtered_.velocity);
  } else {
    simulate_actual_values();
  }
  control();
  servo_monitoring();
  servo_torque_limiting();
  servo_torque_data();
  homing_observe();
  if (retained_.valid && drive_used()) {
    // A cyclic absolute encoder's traversed measuring ranges are kept retentively as they change.
    const RetainedSensorState r = encoder_.chain().retained_state();
    retained_.MeasuringRangeCount = r.MeasuringRangeCount;
    retained_.LastAbsoluteValue = r.LastAbsoluteValue;
  }

  // What the drive is asked to do (the axis core: spec 02 §3.1, §3.4).
  if (drive_used()) {
    command_.encoder = encoder_.source();
    command_.encoder_control = encoder_.control_word();  // absolute value cyclically, error acknowledge
    if (!additional_.all().empty()) write_additional_encoder_controls();
    drive_.request(core_.drive_request(db_.Actor.RemoveEnableReaction));
    drive_.write(command_);
  } else if (device_ != nullptr) {
    drive_.keep_off();  // simulated with a drive kept for a later restart: the link on, the drive off (B8)
  }
}

void PositioningAxis::read_actual_values() noexcept {
  drive_.read();
  db_.StatusDrive.InOperation = drive_.in_operation();
  db_.StatusDrive.CommunicationOK = drive_.communication_ok();
  db_.StatusDrive.Error = drive_.drive_status().state == tg::DriveState::kFault;
  db_.ActualSpeed = drive_.actual_speed_rpm();
  encoder_.read(drive_, device_->fresh);
  const bool encoder_error = encoder_.error();
  auto& sensor = db_.StatusSensor[db_.OperativeSensor - 1];
  sensor.CommunicationOK =
      drive_.communication_ok() || drive_.communication_fault() == CommunicationFault::kDriveFault;
  sensor.Error = encoder_error;
  if (encoder_error && (!encoder_fault_seen_ || !core_.held_off())) {
    raise(kAlarmSensorFault, encoder_.error_code());  // the code is in Gx_XIST2 (spec 06 §6.3)
    // An incremental encoder that failed has lost its reference (spec 04 §8 rule 8): not homed, and the
    // encoder is no longer "referenced" (Adjusted 0, seed 004 §6.11: only an absolute encoder keeps it; H11).
    if (!encoder_.chain().absolute_type()) {
      homed_ = false;
      sensor.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kNotAdjusted);
    }
  }
  encoder_fault_seen_ = encoder_error;
  actual_valid_ = encoder_.chain().position_valid() && !encoder_error && drive_.communication_ok();
  sensor.State =
      static_cast<std::int32_t>(actual_valid_ ? SensorState::VALID : SensorState::WAITING_FOR_VALID);
  actual_position_ = encoder_.chain().continuous_position();
  if (sensor_switch_difference_ != 0.0) {
    // MC_SetSensor Mode 1: D·exp(-t/T) on top of the new encoder (spec 01 §3.8); T = 0: at once.
    const double t = db_.PositionControl.SmoothingTimeByChangeDifference;
    sensor_switch_difference_ *= t > 0.0 ? std::exp(-servo_cycle_s_ / t) : 0.0;
    if (std::fabs(sensor_switch_difference_) < 1e-12) sensor_switch_difference_ = 0.0;
    actual_position_ += sensor_switch_difference_;
  }
  actual_velocity_ = encoder_.chain().velocity();
  if (!additional_.all().empty()) read_additional_encoders();  // most axes have one encoder
  core_.supervise_drive(drive_);
}

// Virtual axis (spec 01 §2.5): the setpoint is taken over as the actual value one servo cycle later.
// Simulation (§2.6): delayed by T_t of the simulated control loop.
void PositioningAxis::simulate_actual_values() noexcept {
  const double previous = actual_position_;
  if (follows_actual()) {
    // Following the actual value (disabled, StopMode 1/3, remove enable) nothing moves a virtual or
    // simulated axis: it stands where it is.
    if (auto* loop = simulation_delay()) loop->fill(actual_position_);
    actual_velocity_ = 0.0;
  } else if (simulated()) {
    const auto& pc = db_.PositionControl;
    const double t_add = db_.DynamicAxisModel.AdditionalPositionTimeConstant;
    const double tt =
        pc.Kpc > 0.0 ? core_.ipo_cycle_s + servo_cycle_s_ + db_.DynamicAxisModel.VelocityTimeConstant + t_add
                     : core_.ipo_cycle_s + (pc.Kv > 0.0 ? 1.0 / pc.Kv : 0.0) + t_add;
    auto* loop = simulation_delay();  // always there on an axis that uses no drive (choose_control_loop)
    loop->push(filtered_.position);
    actual_position_ = loop->delayed(tt / servo_cycle_s_);
    actual_velocity_ = (actual_position_ - previous) / servo_cycle_s_;
  } else {
    actual_position_ = filtered_.position;  // x_f: "the dynamic filter is active" (seed 004 §6.1.5)
    actual_velocity_ = filtered_.velocity;
  }
  actual_valid_ = true;
  // Every used encoder of a simulated axis is simulated (seed 004 §6.2.4.5, decision B7).
  if (!additional_.all().empty() && simulated()) simulate_additional_encoders(actual_position_ - previous);
  db_.StatusDrive.InOperation = core_.phase == PowerPhase::kEnabled;
  db_.StatusDrive.CommunicationOK = true;
  auto& sensor = db_.StatusSensor[db_.OperativeSensor - 1];
  sensor.State = static_cast<std::int32_t>(SensorState::VALID);
  sensor.CommunicationOK = true;
  sensor.Error = false;
}

void PositioningAxis::control() noexcept {
  const bool drive_follows_to =
      core_.phase == PowerPhase::kEnabled ||
      (core_.phase == PowerPhase::kDisabling && core_.stop_mode != 1 && core_.stop_mode != 3);
  const bool active = drive_follows_to && !follows_actual();
  double velocity = 0.0;  // load velocity to the drive, position units / s
  PositionControlOutput out{};
  if (active && position_controlled_ && !drive_used()) {
    // Virtual axis / simulation (spec 01 §2.5, §2.6): no control loop; the following error is what the
    // simulated delay leaves (0 on a virtual axis, whose actual value is the setpoint of the cycle before).
    out.following_error = db_.VirtualAxis.Mode == kModeOn ? 0.0 : setpoint_.position - actual_position_;
    velocity = filtered_.velocity;
  } else if (active && position_controlled_) {
    out = controller()->update(
        PositionControlInput{setpoint_.position, filtered_.position, filtered_.velocity, actual_position_});
    velocity = out.velocity_setpoint;
  } else {
    if (auto* controller = this->controller()) controller->reset();
    if (active) velocity = setpoint_.velocity;  // non-position-controlled operation (spec 02 §7.7)
  }
  db_.StatusServo.BalancedPosition = active && position_controlled_ ? out.balanced_position : 0.0;
  db_.StatusServo.ControlDifference = out.control_difference;
  db_.StatusServo.PositionAfterDynamicFilter = filtered_.position;
  db_.StatusPositioning.FollowingError = active && position_controlled_ ? out.following_error : 0.0;
  if (!drive_used()) {
    db_.VelocitySetpoint = 0.0;  // spec 01 §2.5 table
    return;
  }
  const double max = db_.Actor.DriveParameter.MaxSpeed;
  const double rpm = std::clamp(encoder_.chain().scaling().motor_speed(velocity), -max, max);
  db_.VelocitySetpoint = encoder_.chain().scaling().load_velocity(rpm) * units_.velocity;
  command_.speed_rpm = rpm;
  if (db_.PositionControl.EnableDSC && active && position_controlled_) {
    command_.xerr = encoder_.chain().scaling().xerr(out.dsc_position_error);
    command_.kpc = tg::kpc_from_kv(out.dsc_kpc);
  } else {
    command_.xerr = 0;
    command_.kpc = 0;
  }
}

void PositioningAxis::servo_monitoring() noexcept {
  const bool controlled = core_.phase == PowerPhase::kEnabled && !follows_actual() && position_controlled_;
  // Following error (spec 02 §6.2): 521 removes the enable, 522 warns; both on the rising edge. Off while
  // torque limiting suspends the position-based monitorings (spec 01 §8.10).
  if (controlled && !position_monitorings_suspended()) {
    const auto check = following_error_.check(db_.StatusPositioning.FollowingError, setpoint_.velocity);
    if (check.alarm != following_error_state_) {
      if (check.alarm == FollowingErrorAlarm::kError521) raise(kAlarmFollowingError);
      if (check.alarm == FollowingErrorAlarm::kWarning522) raise(kAlarmFollowingErrorWarning);
    }
    following_error_state_ = check.alarm;
  } else {
    following_error_state_ = FollowingErrorAlarm::kNone;
  }

  // Standstill signal (spec 02 §6.3).
  (void)standstill_.update(actual_velocity_);

  // Positioning monitoring (spec 02 §6.1): started in the servo cycle that uses the final setpoint.
  // With a superimposed motion still moving the axis is not in position yet: the check waits for it. A
  // MotionIn superimposition has no end to wait for: the base job is checked on the base motion, the actual
  // position less the superimposed setpoint (decision U13; seed 004 §9.17.4 section B: A1 Done, A2 active).
  if (positioning_start_pending_ && (superimposed_.settled() || superimposed_.motion_in())) {
    positioning_start_pending_ = false;
    positioning_on_base_ = superimposed_.motion_in();
    positioning_.start(positioning_target_);
  }
  if (positioning_.status().outcome == PositioningOutcome::kInProgress) {
    if (controlled && position_monitorings_suspended()) {
      positioning_.complete();
    } else if (controlled) {
      const double superimposed = positioning_on_base_ ? superimposed_.state().position : 0.0;
      const PositioningStatus st = positioning_.update(actual_position_ - superimposed);
      if (st.outcome == PositioningOutcome::kFault) raise(kAlarmPositioning, st.additional_value);
    } else {
      positioning_.cancel();
    }
  }

  // Hardware limit switches (spec 02 §4.1–§4.4): inactive on virtual and simulated axes (spec 01 §2.5).
  if (drive_used()) {
    limits::HardwareLimitInput hw;
    hw.min_switch_input = inputs_.MinSwitch;
    hw.max_switch_input = inputs_.MaxSwitch;
    hw.position = actual_position_;
    hw.velocity = setpoint_.velocity;
    // Active homing with AutoReversal: the limit switches are reversal cams, no alarm 531 (spec 02 §4.2).
    hw.homing_reversal =
        motion_.kind == JobKind::kHome && db_.Homing.AutoReversal && homing_.phase != HomingPhase::kToHome;
    const auto r = hardware_limits_.update(hw);
    if (r.alarm.raised())
      raise_with(r.alarm.alarm, static_cast<std::uint32_t>(r.alarm.side), r.alarm.reaction);
    // The monitor reports a reversal cam while the switch is active; homing reacts to reaching it.
    if (r.reversal_cam != limits::LimitSide::kNone && r.reversal_cam != reversal_cam_seen_) {
      reversal_cam_ = r.reversal_cam;
    }
    reversal_cam_seen_ = r.reversal_cam;
  }

  // A modulo axis faster than one modulo length per servo cycle cannot be resolved (spec 04 §8 rule 15):
  // alarm 412, the axis is disabled. A possible leading value is limited to half of it instead (spec 01
  // §8.6).
  if (modulo() && !possible_leading_value_ &&
      std::fabs(actual_velocity_) > db_.Modulo.Length / servo_cycle_s_)
    raise(kAlarmModuloTooFast);

  db_.ActualAcceleration = (actual_velocity_ - last_actual_velocity_) / servo_cycle_s_ * units_.acceleration;
  last_actual_velocity_ = actual_velocity_;
}

// Direct homing moves the actual value and the setpoint together, so that no compensating motion results
// (spec 02 §5.7 [Derived]); a profile in progress moves with them.
void PositioningAxis::shift_position(double delta) noexcept {
  if (delta == 0.0) return;
  setpoint_.position += delta;
  actual_position_ += delta;
  profile_offset_ += delta;
  motion_.target += delta;
  // MC_PositionProfile: the profile's positions move with the axis too (its transition moved above).
  if (motion_.kind == JobKind::kPositionProfile) motion_.absolute_position += delta;
  if (pending_.kind == JobKind::kMoveAbsolute && !modulo()) pending_.target = pending_.absolute_position;
  positioning_target_ += delta;
  limit_stop_position_ += delta;
  clamping_.shift(delta);
  // Histories move with the coordinates: no following-error step, no transient.
  std::visit([delta](auto& loop) { loop.shift(delta); }, control_loop_);
  dynamic_filter_.shift(delta);
  software_limits_.configure(limits::software_limit_config(db_.PositionLimits_SW, db_.Modulo));
}

// =========================================================================================================
// MC_Interpolator

void PositioningAxis::interpolate(const CycleClock& clock) noexcept {
  core_.cycle = clock.interpolator_cycles + 1;
  if (core_.ipo_cycle_s != clock.interpolator_cycle_s) {
    core_.ipo_cycle_s = clock.interpolator_cycle_s;
    configure_extrapolation();
  }
  // The actual value as a leading value, once per interpolator cycle (spec 07 §1.4).
  extrapolation_.update(actual_position_, actual_velocity_);
  show_extrapolation(extrapolation_, units_.velocity, db_.StatusExtrapolation);

  if (const auto restart_requested = core_.begin_reset(core_.cycle)) {  // MC_Reset
    software_limits_.acknowledge();
    hardware_limits_.acknowledge();
    if (device_ != nullptr) {  // also a drive the axis keeps unused (decision B8)
      drive_.acknowledge();
      encoder_.acknowledge();
      for (AdditionalEncoder& e : additional_.all())
        e.channel.acknowledge();
    }
    if (*restart_requested) restart();
    core_.finish_reset();
  }

  apply_alarm_reactions();
  update_power_phase();
  apply_clamping();
  run_homing();
  run_synchronous();
  update_live_motion();
  const MotionState previous = setpoint_;
  generate_setpoint();
  monitor_software_limits(previous);
  complete_jobs();
  update_status();
  if (delayed_) {  // the setpoint of this cycle, as followers coupled "Delayed" see it later (spec 07 §1.5)
    delayed_->push(setpoint_);
    auto& shown = db_.StatusProvidedLeadingValue.DelayedLeadingValue;
    shown.Position = delayed_->value().position;
    shown.Velocity = delayed_->value().velocity;
    shown.Acceleration = delayed_->value().acceleration;
  }
}

void PositioningAxis::apply_alarm_reactions() noexcept {
  const ReactionChange change = core_.reaction_change();
  if (change == ReactionChange::kNone) return;
  if (change == ReactionChange::kReleased) {
    limit_stop_ = false;
    return;
  }
  // A stop reaction takes over: motion jobs end with 16#8001 (spec 03 §6.6).
  const ProfileLimits current =
      motion_.id != 0 ? motion_.limits : AxisCore::default_ramp(db_.DynamicDefaults, dynamic_units());
  abort_synchronous(error_id::kAbortedByAlarmReaction);
  abort_superimposed(error_id::kAbortedByAlarmReaction);
  abort_motion(error_id::kAbortedByAlarmReaction);
  abort_pending(error_id::kAbortedByAlarmReaction);
  if (passive_.id != 0) {  // passive homing needs an enabled, unblocked axis (spec 02 §5.6)
    end_passive_homing(JobState::kError, error_id::kAbortedByAlarmReaction);
  }
  if (core_.stop_keeps_control(!limit_stop_)) return;
  auto ramp = core_.reaction_ramp(current, db_.DynamicDefaults, db_.DynamicLimits, dynamic_units());
  if (!ramp) {
    generator_ = Generator::kIdle;  // the drive brakes (remove enable) or is followed (follow setpoint)
    limit_stop_ = false;
    return;
  }
  if (limit_stop_) {
    // The software-limit look-ahead: the motion is decoupled and stops at the limit (spec 02 §4.5). The
    // look-ahead started the stop so that the reaction's deceleration reaches the limit exactly.
    ramp->velocity = std::max(std::fabs(setpoint_.velocity), 1e-9);
    ramp->acceleration = std::max(ramp->acceleration, ramp->deceleration);
    plan_position(limit_stop_position_, *ramp);
  } else {
    plan_velocity(0.0, *ramp, false);
  }
}

void PositioningAxis::update_power_phase() noexcept {
  switch (core_.update_power_phase(virtual_axis() || (drive_.in_operation() && actual_valid_))) {
    case PowerEvent::kEnabled:
      // Enabled at the actual position; a moving axis is braked by the position loop (spec 01 §6.2).
      position_controlled_ = core_.start_mode == 1;
      superimposed_.fold();
      superimposed_.reset_distance();
      setpoint_ = MotionState{actual_position_, 0.0, 0.0};
      generator_ = Generator::kIdle;
      if (auto* controller = this->controller()) controller->reset();
      positioning_.cancel();
      break;
    case PowerEvent::kDisabling:
      // MC_Power.Enable = FALSE aborts every job (spec 03 §6.6) and stops per StopMode (spec 02 §3.1).
      abort_synchronous(0);
      abort_superimposed(0);
      abort_motion(0);
      abort_pending(0);
      if (passive_.id != 0) end_passive_homing(JobState::kAborted);
      limit_stop_ = false;
      if (const auto ramp = core_.disable_ramp(db_.DynamicDefaults, db_.DynamicLimits, dynamic_units())) {
        plan_velocity(0.0, *ramp, false);
      } else {
        generator_ = Generator::kIdle;
      }
      break;
    case PowerEvent::kNone:
      break;
  }
}

// Inputs that act while a job runs: the override (spec 01 §8.4) and the jog inputs (spec 03 §3.4).
void PositioningAxis::update_live_motion() noexcept {
  const double ovr = override_factor();
  switch (motion_.kind) {
    case JobKind::kJog:
    case JobKind::kMoveVelocity: {
      const double target =
          std::clamp(motion_.command_velocity * ovr, -motion_.limits.velocity, motion_.limits.velocity);
      if (std::fabs(target - motion_.planned_velocity) > 1e-12 ||
          (motion_.kind == JobKind::kJog && generator_ == Generator::kIdle &&
           std::fabs(setpoint_.velocity - target) > kStandstillEpsilon)) {
        motion_.planned_velocity = target;
        plan_velocity(target, motion_.limits, false);
      }
      break;
    }
    case JobKind::kMoveAbsolute:
    case JobKind::kMoveRelative: {
      if (motion_.interpolation_done) break;
      const double v = positioning_velocity(motion_);
      if (std::fabs(v - motion_.planned_velocity) > 1e-12) {
        plan_positioning(v);  // the override changed: replan from the present state
      }
      break;
    }
    default:
      break;
  }
}

void PositioningAxis::plan_velocity(double target, const ProfileLimits& limits,
                                    bool abort_acceleration) noexcept {
  MotionState start = base_setpoint();
  if (abort_acceleration) start.acceleration = 0.0;
  ProfileLimits l = limits;
  if (!(l.velocity > 0.0)) l.velocity = std::numeric_limits<double>::infinity();
  l.jerk = replanning_jerk(start.velocity, start.acceleration, l.jerk, target == 0.0);
  VelocityProfile planned;
  if (planned.plan(start, target, l)) {
    profile_.adopt(planned, start, target, l);
    profile_time_ = 0.0;
    profile_offset_ = 0.0;
    generator_ = Generator::kVelocity;
  }
}

void PositioningAxis::plan_position(double target, const ProfileLimits& limits) noexcept {
  // The job's jerk, whatever the start state (seed 004 §6.7.7, decision S4).
  const MotionState start = base_setpoint();
  PositionProfile planned;
  if (planned.plan(start, target, limits)) {
    profile_.adopt(planned, start, target, limits);
    profile_time_ = 0.0;
    profile_offset_ = 0.0;
    generator_ = Generator::kPosition;
  }
}

void PositioningAxis::plan_positioning(double v) noexcept {
  motion_.planned_velocity = v;
  if (v > 0.0) {
    ProfileLimits l = motion_.limits;
    l.velocity = v;
    plan_position(motion_.target, l);
  } else {
    plan_velocity(0.0, motion_.limits, false);  // override 0 %: stop, the job stays active
  }
}

void PositioningAxis::generate_setpoint() noexcept {
  if (follows_actual()) {
    abort_superimposed(error_id::kAbortedByAlarmReaction);  // its reaction has normally ended it already
    setpoint_ = MotionState{actual_position_, actual_velocity_, 0.0};  // follow-up (spec 02 §3.2)
    generator_ = Generator::kIdle;
    return;
  }
  setpoint_ = base_setpoint();  // the generators below produce the base motion; run_superimposed() adds
  switch (generator_) {
    case Generator::kVelocity: {
      profile_time_ += core_.ipo_cycle_s;
      if (profile_time_ >= profile_.duration() - 1e-9) {
        const MotionState end = profile_.at(profile_.duration());
        setpoint_ =
            MotionState{end.position + profile_offset_ + end.velocity * (profile_time_ - profile_.duration()),
                        end.velocity, 0.0};
        generator_ = Generator::kIdle;  // from here the velocity is constant (0 after a stop)
        if (motion_.kind == JobKind::kPositionProfile) {  // the relative transition ended within this cycle
          enter_time_profile(setpoint_.position, profile_time_ - profile_.duration());
        }
      } else {
        setpoint_ = profile_.advance_to(profile_time_);
        setpoint_.position += profile_offset_;
      }
      break;
    }
    case Generator::kPosition: {
      profile_time_ += core_.ipo_cycle_s;
      if (profile_time_ >= profile_.duration() - 1e-9) {
        setpoint_ = MotionState{profile_.at(profile_.duration() + 1.0).position + profile_offset_, 0.0, 0.0};
        generator_ = Generator::kIdle;
        const bool homing_to_home = motion_.kind == JobKind::kHome && homing_.phase == HomingPhase::kToHome;
        if (motion_.kind == JobKind::kMoveAbsolute || motion_.kind == JobKind::kMoveRelative ||
            homing_to_home) {
          if (!motion_.interpolation_done && (motion_.planned_velocity > 0.0 || homing_to_home)) {
            motion_.interpolation_done = true;
            positioning_target_ = positioning_reference();
            positioning_start_pending_ = true;
          }
        }
        if (motion_.kind == JobKind::kPositionProfile) {  // the absolute transition ended
          enter_time_profile(setpoint_.position);
        }
      } else {
        setpoint_ = profile_.advance_to(profile_time_);
        setpoint_.position += profile_offset_;
      }
      break;
    }
    case Generator::kIdle:
      setpoint_.position += setpoint_.velocity * core_.ipo_cycle_s;
      setpoint_.acceleration = 0.0;
      break;
    case Generator::kSynchronous:
      setpoint_ = synchronous_setpoint();
      break;
    case Generator::kTimeProfile:
      follow_time_profile();
      break;
    case Generator::kMotionIn:
      follow_motion_in();
      break;
  }
  run_superimposed();
  // Without position control the setpoint position tracks the actual one (spec 02 §7.7); the velocity
  // setpoint goes to the drive directly.
  if (!position_controlled_) setpoint_.position = actual_position_;
}

// The setpoint the generator will give `dt` after the present one unless a job changes it (as
// generate_setpoint() evaluates the profiles).
MotionState PositioningAxis::predicted_setpoint(double dt) const noexcept {
  const double t = profile_time_ + dt;
  const MotionState base = base_setpoint();
  MotionState s{base.position + base.velocity * dt, base.velocity, 0.0};
  if (generator_ == Generator::kVelocity) {
    const double end = profile_.duration();
    if (t >= end - 1e-9) {
      const MotionState e = profile_.at(end);
      s = MotionState{e.position + profile_offset_ + e.velocity * (t - end), e.velocity, 0.0};
    } else {
      s = profile_.at(t);
      s.position += profile_offset_;
    }
  } else if (generator_ == Generator::kPosition) {
    const double end = profile_.duration();
    if (t >= end - 1e-9) {
      s = MotionState{profile_.at(end + 1.0).position + profile_offset_, 0.0, 0.0};
    } else {
      s = profile_.at(t);
      s.position += profile_offset_;
    }
  } else if (generator_ == Generator::kTimeProfile && motion_.kind == JobKind::kPositionProfile) {
    s = motion_.time_source().evaluate(motion_.distance + dt);
    s.position += motion_.absolute_position;
  }
  const MotionState sup = superimposed_.predicted(dt);
  return MotionState{s.position + sup.position, s.velocity + sup.velocity, s.acceleration + sup.acceleration};
}

// Software limit switches (spec 02 §4.5): setpoint-based look-ahead, effective only on a homed axis.
void PositioningAxis::monitor_software_limits(const MotionState& previous_setpoint) noexcept {
  if (core_.phase != PowerPhase::kEnabled || follows_actual()) return;
  const auto& limits = software_limits_.effective_limits();
  if (!limits.monitored || !homed_) {
    // Not effective (not active, or not homed): the monitor only resets its state, as its update() does for
    // an input it does not monitor; no look-ahead to prepare, no input to build (issue 23).
    software_limits_.reset();
    return;
  }
  const std::int32_t reaction =
      limits::sw_limit_reached_reaction(db_.PositionLimits_SW.LimitReachedBehavior, false);
  const auto& l = db_.DynamicLimits;
  limits::SoftwareLimitInput in;
  const double start = db_.Modulo.StartValue;
  const double length = db_.Modulo.Length;
  const std::int64_t k = modulo() ? cycle_index(setpoint_.position, start, length) : 0;
  const double shift = modulo() ? static_cast<double>(k) * length : 0.0;
  in.position = setpoint_.position - shift;
  // The look-ahead knows a job from its first setpoint on: a motion that starts from standstill within one
  // step of a limit has passed it in this setpoint already. The monitor sees it at the limit (it raises 533
  // for the approach, not 534 for passing) and the setpoint stops there (spec 02 §4.5: decoupled, stopped at
  // the limit). A moving setpoint is the look-ahead's job.
  const double previous = previous_setpoint.position - shift;
  const bool from_standstill = previous_setpoint.velocity == 0.0 && previous_setpoint.acceleration == 0.0;
  double crossed = std::numeric_limits<double>::quiet_NaN();
  if (from_standstill) {
    const double hi = limits.max_position;
    const double lo = limits.min_position;
    const double tolerance = 1e-9 * std::max({1.0, std::fabs(hi), std::fabs(lo)});  // as the monitor's
    if (previous <= hi + tolerance && in.position > hi + tolerance) crossed = hi;
    if (previous >= lo - tolerance && in.position < lo - tolerance) crossed = lo;
    if (!std::isnan(crossed)) in.position = crossed;
  }
  in.velocity = setpoint_.velocity;
  in.acceleration = setpoint_.acceleration;
  in.homed = true;
  in.following_axis = following_in_synchronous_operation();
  if (reaction == limits::kReactionStopMaxDynamics) {
    in.stop_deceleration = l.MaxDeceleration / units_.acceleration;
    in.stop_jerk = l.MaxJerk / units_.acceleration;
  } else {
    const ProfileLimits cur =
        motion_.id != 0 ? motion_.limits
                        : ProfileLimits{0.0, 0.0, db_.DynamicDefaults.Deceleration / units_.acceleration,
                                        db_.DynamicDefaults.Jerk / units_.acceleration};
    in.stop_deceleration = cur.deceleration;
    in.stop_jerk = cur.jerk;
  }
  in.cycle_time = core_.ipo_cycle_s;
  // The next setpoint as the profile will produce it; a synchronous axis' depends on its leader (the monitor
  // then extrapolates with constant acceleration).
  if (std::isnan(crossed) && generator_ != Generator::kSynchronous) {
    const MotionState next = predicted_setpoint(core_.ipo_cycle_s);
    in.next_known = true;
    in.next_position = next.position - shift;
    in.next_velocity = next.velocity;
    in.next_acceleration = next.acceleration;
  }
  const auto r = software_limits_.update(in);
  if (!std::isnan(crossed)) {
    // The setpoint stops at the limit, base and superimposed alike; 533's reaction follows in this cycle.
    abort_superimposed(error_id::kAbortedByAlarmReaction);
    setpoint_ = MotionState{crossed + shift, 0.0, 0.0};
  }
  if (r.stop_now) {
    limit_stop_ = true;
    limit_stop_position_ = r.stop_position + static_cast<double>(k) * (modulo() ? length : 0.0);
  }
  if (r.alarm.raised()) {
    raise_with(r.alarm.alarm, static_cast<std::uint32_t>(r.alarm.side), r.alarm.reaction);
    apply_alarm_reactions();  // the reaction takes effect in the cycle of the alarm
  }
}

void PositioningAxis::complete_jobs() noexcept {
  const bool settled = generator_ == Generator::kIdle;
  // The base motion's standstill: MC_Halt Mode 1 is Done when the base stops, the superimposed motion may go
  // on (spec 03 §4.4 function diagram, Mode 1).
  const bool at_zero = std::fabs(base_setpoint().velocity) < kStandstillEpsilon;
  const PositioningOutcome outcome = positioning_.status().outcome;
  if (motion_.id != 0) {
    switch (motion_.kind) {
      case JobKind::kHome:  // active homing: Done after the travel to the home position (spec 02 §5.5)
      case JobKind::kMoveAbsolute:
      case JobKind::kMoveRelative:
      case JobKind::kPositionProfile:
        // Done when the target is reached and the dwell time has passed (spec 03 §3.5, spec 02 §6.1).
        if (motion_.interpolation_done && !positioning_start_pending_ &&
            outcome == PositioningOutcome::kDone) {
          core_.jobs.set(motion_.id, JobState::kDone);
          motion_ = Motion{};
          // BufferMode 1: the appended job starts in the cycle the running one is Done (spec 03 §3.7 T-E).
          if (pending_.id != 0) {
            const Motion next = pending_;
            pending_ = Motion{};
            start_motion(next);
          }
        }
        break;
      case JobKind::kHalt:
        if (settled && at_zero) {
          core_.jobs.set(motion_.id, JobState::kDone);
          motion_ = Motion{};
          if (position_controlled_) {  // X6 after a position-controlled stop (spec 04 §8 rule 2)
            positioning_target_ = positioning_reference();
            positioning_start_pending_ = true;
          }
        }
        break;
      case JobKind::kJog:
        if (motion_.jog_stopping && settled && at_zero) {
          core_.jobs.set(motion_.id, JobState::kDone);  // J2
          motion_ = Motion{};
        } else {
          core_.jobs.set_in_velocity(motion_.id, settled && !motion_.jog_stopping);
        }
        break;
      case JobKind::kMoveVelocity:
        core_.jobs.set_in_velocity(motion_.id, settled);
        break;
      default:
        break;
    }
  }
  if (core_.stop.id != 0 && !core_.stop.done && settled && at_zero) {
    core_.stop_reached_standstill();
    if (position_controlled_) {
      positioning_target_ = positioning_reference();
      positioning_start_pending_ = true;
    }
  }
  if (limit_stop_ && settled && at_zero) limit_stop_ = false;
  if (superimposed_.distance() != 0.0) settle_superimposed();
  if (core_.phase == PowerPhase::kDisabling) {
    const bool drive_off = virtual_axis() || !drive_.in_operation();
    // A virtual or simulated axis' actual value lags its setpoint (spec 01 §2.5): it is disabled once the
    // actual value has arrived too, so that the follow-up after disabling takes no step back.
    const bool caught_up = !virtual_axis() || std::fabs(actual_position_ - setpoint_.position) < 1e-9;
    core_.finish_disabling(
        settled && at_zero && caught_up,
        drive_off && std::fabs(actual_velocity_) < db_.StandstillSignal.VelocityThreshold / units_.velocity);
  }
}

void PositioningAxis::update_status() noexcept {
  const double start = db_.Modulo.StartValue;
  const double length = db_.Modulo.Length;
  // Setpoints and actual values as the data block shows them (spec 04 §2): modulo-wrapped, data units.
  // While the backlash is crossed, ActualPosition keeps its value (spec 04 §5.2 StatusWord2.X2).
  const double shown_actual = actual_position_ - backlash_.held_travel();
  if (modulo()) {
    const ModuloPosition sp = modulo_wrap(setpoint_.position, start, length);
    const ModuloPosition act = modulo_wrap(shown_actual, start, length);
    db_.Position = sp.position;
    db_.ActualPosition = act.position;
    // The actual counter follows the encoder's rules (spec 01 §2.4.1); the setpoint's is the actual one plus
    // the cycles between them.
    const std::int64_t actual_cycle = drive_used() ? encoder_.chain().modulo_cycle() + act.cycle -
                                                         cycle_index(actual_position_, start, length)
                                                   : act.cycle;
    db_.ActualModuloCycle = static_cast<std::int32_t>(actual_cycle);
    db_.ModuloCycle = static_cast<std::int32_t>(actual_cycle + sp.cycle - act.cycle);
  } else {
    db_.Position = setpoint_.position;
    db_.ActualPosition = shown_actual;
    db_.ModuloCycle = 0;
    db_.ActualModuloCycle = 0;
  }
  db_.Velocity = setpoint_.velocity * units_.velocity;
  db_.Acceleration = setpoint_.acceleration * units_.acceleration;
  db_.ActualVelocity = actual_velocity_ * units_.velocity;
  auto& sensor = db_.StatusSensor[db_.OperativeSensor - 1];
  sensor.Position = db_.ActualPosition;
  sensor.Velocity = db_.ActualVelocity;
  sensor.ModuloCycle = db_.ActualModuloCycle;
  if (virtual_axis()) sensor.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);  // §2.5 table
  if (!additional_.all().empty()) update_additional_encoder_status();

  const bool positioning = motion_.kind == JobKind::kMoveAbsolute || motion_.kind == JobKind::kMoveRelative;
  db_.StatusPositioning.TargetPosition =
      positioning ? (modulo() ? modulo_wrap(motion_.target, start, length).position : motion_.target) : 0.0;
  db_.StatusPositioning.TargetPositionModuloCycle =
      positioning && modulo()
          ? static_cast<std::int32_t>(db_.ModuloCycle + cycle_index(motion_.target, start, length) -
                                      cycle_index(setpoint_.position, start, length))
          : 0;
  db_.StatusPositioning.Distance = positioning ? std::fabs(motion_.target - setpoint_.position) : 0.0;
  db_.StatusPositioning.SuperimposedDistance = superimposed_.distance();
  db_.StatusPositioning.SetpointExecutionTime =
      generator_ == Generator::kPosition ? std::max(0.0, profile_.duration() - profile_time_) : 0.0;

  std::uint32_t sw = db_.StatusWord & (1u << static_cast<unsigned>(StatusWordBit::kOnlineStartValuesChanged));
  std::uint32_t sw2 = 0;
  // No limit switch active or pending (the usual cycle): no bit to merge.
  const bool limits_quiet =
      software_limits_.active_side() == limits::LimitSide::kNone && !software_limits_.alarm_pending() &&
      hardware_limits_.active_side() == limits::LimitSide::kNone && !hardware_limits_.alarm_pending();
  const limits::LimitStatusBits limit_bits =
      limits_quiet ? limits::LimitStatusBits{}
                   : limits::merge(software_limits_.bits(), hardware_limits_.bits());
  std::uint32_t ew = limits_quiet ? 0u : limit_bits.error_word();
  std::uint32_t ww = limits_quiet ? 0u : limit_bits.warning_word();
  core_.update_words(sw, sw2, ew, ww, db_.ErrorDetail, db_.Simulation.Mode == kModeOn);
  const bool enabled = test(sw, StatusWordBit::kEnable);
  const bool settled = generator_ == Generator::kIdle;
  const bool at_zero = std::fabs(setpoint_.velocity) < kStandstillEpsilon;
  const bool job_running = motion_.id != 0 || pending_.id != 0 || (core_.stop.id != 0 && !core_.stop.done) ||
                           !superimposed_.settled();
  db_.StatusSensor[db_.OperativeSensor - 1].AbsEncoderOffset =
      retained_.valid ? retained_.AbsEncoderOffset : 0.0;
  const PositioningOutcome outcome = positioning_.status().outcome;
  assign(sw, StatusWordBit::kHomingDone, homed_);
  // P: Done after the positioning window check (spec 04 §8 rule 2), or no motion job at all.
  assign(sw, StatusWordBit::kDone,
         !job_running && settled && at_zero && outcome != PositioningOutcome::kInProgress &&
             outcome != PositioningOutcome::kFault && !positioning_start_pending_);
  assign(sw, StatusWordBit::kStandstill, standstill_.standstill());
  assign(sw, StatusWordBit::kPositioningCommand, positioning);
  assign(sw, StatusWordBit::kHomingCommand, motion_.kind == JobKind::kHome || passive_.id != 0);
  assign(sw, StatusWordBit::kJogCommand, motion_.kind == JobKind::kJog);
  assign(sw, StatusWordBit::kVelocityCommand, motion_.kind == JobKind::kMoveVelocity);
  // MotionIn (spec 04 §5.1 X31, §4.8 StatusMotionIn.FunctionState)
  const auto motion_in = motion_.kind == JobKind::kMotionInVelocity ? MotionInFunctionState::kMotionInVelocity
                         : motion_.kind == JobKind::kMotionInPosition
                             ? MotionInFunctionState::kMotionInPosition
                             : MotionInFunctionState::kNone;
  assign(sw, StatusWordBit::kMotionInCommand, motion_in != MotionInFunctionState::kNone);
  db_.StatusMotionIn.FunctionState = static_cast<std::int32_t>(motion_in);
  // Superimposed jobs (spec 04 §5.1 X23, §5.2 X6/X7/X8); the braking after a MotionInSuperimposed setpoint
  // that was not a number is no MC_HaltSuperimposed job (id 0).
  const SuperimposedMotion::Job sup_job = superimposed_.job();
  assign(sw, StatusWordBit::kMoveSuperimposedCommand, sup_job == SuperimposedMotion::Job::kMove);
  assign(sw2, StatusWord2Bit::kHaltSuperimposedCommand,
         sup_job == SuperimposedMotion::Job::kHalt && superimposed_.job_id() != 0);
  assign(sw2, StatusWord2Bit::kMotionInSuperimposedCommand, sup_job == SuperimposedMotion::Job::kMotionIn);
  assign(sw2, StatusWord2Bit::kMotionInSuperimposedAxesCommand,
         sup_job == SuperimposedMotion::Job::kMotionInAxes);
  // StatusMotionIn.StatusWord.X0 MaxVelocityExceeded: the total velocity was above DynamicLimits.MaxVelocity
  // during a MotionIn job — a flag, not a clamp (spec 02 §8); kept until the next MotionIn job starts.
  if ((motion_in != MotionInFunctionState::kNone || superimposed_.motion_in()) &&
      std::fabs(setpoint_.velocity) * units_.velocity > db_.DynamicLimits.MaxVelocity)
    db_.StatusMotionIn.StatusWord |= 1u << static_cast<unsigned>(StatusMotionInBit::kMaxVelocityExceeded);
  // Constant velocity: the setpoint neither accelerates now nor did it in the cycle before (a jerk-limited
  // ramp passes a = 0 only for an instant).
  const bool acceleration_zero = std::fabs(setpoint_.acceleration) < 1e-9;
  const bool constant = acceleration_zero && acceleration_was_zero_;
  acceleration_was_zero_ = acceleration_zero;
  assign(sw, StatusWordBit::kConstantVelocity, enabled && constant);
  assign(sw, StatusWordBit::kAccelerating, setpoint_.acceleration * setpoint_.velocity > 0.0);
  assign(sw, StatusWordBit::kDecelerating, setpoint_.acceleration * setpoint_.velocity < 0.0);
  assign(sw, StatusWordBit::kNonPositionControlled, !position_controlled_ || !enabled);
  assign(sw, StatusWordBit::kInClamping, clamping_.clamped());
  if (!limits_quiet) sw |= limit_bits.status_word();
  db_.StatusWord = sw;
  assign(sw2, StatusWord2Bit::kPassingBacklash, backlash_.passing());
  // MC_PositionProfile (seed 004 §6.8.4): X9 while the job is active, X10 while the setpoint is the
  // profile's.
  const bool profile_job = motion_.kind == JobKind::kPositionProfile;
  assign(sw2, StatusWord2Bit::kPositionProfileCommand, profile_job);
  assign(sw2, StatusWord2Bit::kOnProfile,
         profile_job && generator_ == Generator::kTimeProfile && !motion_.profile_limited);
  db_.StatusWord2 = sw2;
  if (superimposing_error_) ew |= 1u << static_cast<unsigned>(ErrorWordBit::kSuperimposingError);
  db_.ErrorWord = ew;
  db_.WarningWord = ww;
  update_synchronous_status();
}

void PositioningAxis::restart() noexcept {
  // MC_Reset Restart = TRUE: re-initialise from the start values (spec 01 §7). An incremental encoder loses
  // its position and its reference (spec 01 §2.4.1, spec 04 §8 rule 8); HW-limit Active returns to its start
  // value (spec 02 §4.4).
  const auto changed = StatusWordBit::kOnlineStartValuesChanged;
  restart_synchronous();
  // An adjusted absolute encoder stays adjusted until new encoder settings are downloaded, and a restart is
  // not such a download: its retained offset is restored below (spec 02 §5.1, §5.12).
  std::array<std::int32_t, 4> adjusted{};  // StatusSensor[1..4]
  for (std::size_t n = 0; n < adjusted.size(); ++n)
    adjusted[n] = db_.StatusSensor[n].Adjusted;
  // The start values are checked together first: what breaks a rule keeps its value in force and is alarm
  // 102 (decision B8).
  std::uint32_t simulation_mode = db_.Simulation.Mode;
  std::uint32_t initial_sensor = db_.PositionControl.InitialOperativeSensor;
  const std::uint32_t configuration_error = restart_configuration(simulation_mode, initial_sensor);
  // The start-up encoder closes the loop again (spec 04 PositionControl.InitialOperativeSensor).
  const std::uint32_t operative = make_operative(initial_sensor);
  db_ = *start_;
  db_.Simulation.Mode = simulation_mode;
  db_.PositionControl.InitialOperativeSensor = initial_sensor;
  core_.restart();
  // A start value not taken over still waits for a restart (StatusWord.X3, spec 04 §0.2).
  assign(db_.StatusWord, changed, configuration_error != 0);
  db_.OperativeSensor = operative;
  // Whether the drive is used follows the work memory's Simulation.Mode from here on: the control loop too.
  choose_control_loop();
  db_.StatusDrive.AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_APPLICABLE);
  superimposed_ = SuperimposedMotion{};
  sensor_switch_difference_ = 0.0;
  motion_ = Motion{};
  pending_ = Motion{};
  generator_ = Generator::kIdle;
  limit_stop_ = false;
  positioning_start_pending_ = false;
  clamping_.reset();
  clamp_abort_pending_ = false;
  units_ = axis_unit_factors(db_.Units.LengthUnit, db_.Units.VelocityUnit);
  const RetainedSensorState retained = encoder_.chain().retained_state();
  std::array<RetainedSensorState, 3> additional_retained{};
  std::array<std::int64_t, 3> additional_counts{};  // a simulated encoder stays where the load is
  for (std::size_t i = 0; i < additional_.all().size(); ++i) {
    additional_retained[i] = additional_.all()[i].channel.chain().retained_state();
    additional_counts[i] = additional_.all()[i].channel.chain().encoder_counts();
  }
  configure_components();
  for (std::size_t i = 0; i < additional_.all().size(); ++i) {
    ActualValueChain& chain = additional_.all()[i].channel.chain();
    if (chain.absolute_type()) chain.power_up(&additional_retained[i]);
    if (simulated()) seed_simulated_encoder(additional_.all()[i], additional_counts[i]);
  }
  // Every absolute encoder keeps its adjustment over the restart, the operative one or not (an incremental
  // operative encoder does not make the others lose theirs).
  for (std::size_t n = 0; n < adjusted.size(); ++n) {
    const bool absolute = db_.Sensor[n].Type != static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL);
    if (absolute) db_.StatusSensor[n].Adjusted = adjusted[n];
  }
  if (encoder_.chain().absolute_type()) {
    encoder_.chain().power_up(&retained);
  } else {
    homed_ = false;
    actual_position_ = 0.0;
    backlash_.reset();  // not homed: the first motion is not compensated (spec 01 §5.9)
  }
  setpoint_ = MotionState{actual_position_, 0.0, 0.0};
  command_.travel_to_fixed_stop = false;  // the restarted connection clears STW2 (AxisCore::restart)
  if (device_ != nullptr) drive_.restart(with_reference_values(drive_.config(), start_->Actor));
  // After the acknowledgement of the restart (class R): pending until a restart with consistent values.
  if (configuration_error != 0) raise(kAlarmConfiguration, configuration_error);
}

std::uint32_t PositioningAxis::restart_configuration(std::uint32_t& simulation_mode,
                                                     std::uint32_t& initial_sensor) const noexcept {
  const auto& next = *start_;
  // Spec 04 §3.20: the start-up encoder is one of the existing encoders (Sensor[n].Existent is RON, fixed at
  // construction). Otherwise the one in force stays: no encoder is left without its configuration.
  const std::uint32_t op = next.PositionControl.InitialOperativeSensor;
  if (op < 1 || op > 4 || !db_.Sensor[op - 1].Existent) return kConfigurationNoSuchEncoder;
  // Seed 004 §6.1.7: "at the end of the simulation a valid drive and encoder integration must be present".
  // An axis built without a drive stays in simulation.
  const bool virtual_mode = next.VirtualAxis.Mode == kModeOn;
  if (!virtual_mode && device_ == nullptr && simulation_mode == kModeOn && next.Simulation.Mode != kModeOn) {
    return kConfigurationNoDrive;
  }
  // Seed 004 §6.1.7: "to use a technology object in simulation, encoder 1 must be used for position control".
  // Neither value is taken over, so that the axis stays as it was (simulated on encoder 1, or on its drive).
  if (!virtual_mode && next.Simulation.Mode == kModeOn && op != 1) return kConfigurationSimulationEncoder;
  simulation_mode = next.Simulation.Mode;
  initial_sensor = op;
  return 0;
}

}  // namespace tomc::techobjects
