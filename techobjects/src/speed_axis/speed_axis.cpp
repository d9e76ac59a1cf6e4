// TO_SpeedAxis behaviour on the axis core (axis_core.hpp). Servo: read_actual_values -> write_setpoint.
// Interpolator: take_reset -> apply_alarm_reactions -> update_power_phase -> update_live_motion ->
// generate_setpoint -> update_status.
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/axis/jog.hpp"
#include "tomc/techobjects/axis/setup_checks.hpp"
#include "tomc/techobjects/datablocks/data_block_access.hpp"
#include "tomc/telegrams/layout.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

constexpr double kStandstillEpsilon = 1e-9;  // rev/s

bool finite(double x) {
  return std::isfinite(x);
}

}  // namespace

SpeedAxis::SpeedAxis(std::string name, DeviceIo* device, const SpeedAxisData& start_values,
                     const DriveConnectionConfig& drive)
    : AxisObject(std::move(name), device, start_values) {
  check_start_values(name_, speed_axis_variables(), *start_);
  // VirtualAxis.Mode is RON (a virtual axis never has a drive); Simulation.Mode is RES: the device stays, a
  // restart that ends the simulation uses it (seed 004 §6.1.7, decision B8; drive_used()).
  if (start_->VirtualAxis.Mode == kModeOn) device_ = nullptr;
  if (device_ != nullptr) {
    drive_ = DriveConnection(*device_, with_reference_values(drive, start_->Actor));
    const std::uint16_t telegram = device_->adapter->config().drive_telegram;
    const auto setpoint = tg::find_layout(telegram, tg::Direction::kSetpoint);
    const auto actual = tg::find_layout(telegram, tg::Direction::kActual);
    drive_has_momred_ = setpoint && setpoint->carries(tg::Signal::MOMRED);
    drive_has_meldw_ = actual && actual->carries(tg::Signal::MELDW);
  }
  db_.StatusDrive.AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_APPLICABLE);
}

// ---------------------------------------------------------------------------------------------------------
// Units: the data block is in Units.VelocityUnit (1/s, 1/min, 1/h) and 1/s², 1/s³; internally revolutions/s.

double SpeedAxis::velocity_unit_per_revolution_per_second() const noexcept {
  switch (db_.Units.VelocityUnit) {
    case unit_code::kPerSecond:
      return 1.0;
    case unit_code::kPerHour:
      return 3600.0;
    default:
      return 60.0;  // 1/min
  }
}

double SpeedAxis::override_factor() const noexcept {
  return core_.override_factor(db_.Override);
}

double SpeedAxis::velocity_limit() const noexcept {
  return AxisCore::velocity_limit(db_.DynamicLimits, units());
}

std::optional<std::uint16_t> SpeedAxis::resolve_dynamics(double acceleration, double deceleration,
                                                         double jerk, ProfileLimits& out) noexcept {
  return core_.resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), acceleration, deceleration, jerk,
                                db_.DynamicDefaults, db_.DynamicLimits, units(), out);
}

// ---------------------------------------------------------------------------------------------------------
// Job API

std::array<RunningJob, 2> SpeedAxis::running_jobs(std::size_t& n) const noexcept {
  std::array<RunningJob, 2> running{};
  n = 0;
  if (motion_.id != 0) {
    running[n++] = motion_.kind == JobKind::kHalt               ? RunningJob::kHaltAll
                   : motion_.kind == JobKind::kMotionInVelocity ? RunningJob::kMotionIn  // C8
                                                                : RunningJob::kBaseMotionActive;
  }
  if (core_.stop_running()) running[n++] = RunningJob::kStop;
  return running;
}

std::uint16_t SpeedAxis::arbitrate_motion(NewJob row) noexcept {
  std::size_t n = 0;
  const auto running = running_jobs(n);
  ArbitrationContext ctx;
  ctx.running_job_ends_by_itself = motion_.kind == JobKind::kHalt;
  ctx.virtual_or_simulated_axis = virtual_axis();
  ctx.running_stop_weight = core_.stop.weight;
  const Decision d = arbitrate(row, std::span<const RunningJob>(running.data(), n), ctx);
  if (d.reject) return error_id::kRejectedByRunningJob;
  for (std::size_t i = 0; i < n; ++i) {
    if ((d.abort_mask & (1u << i)) == 0) continue;
    if (running[i] == RunningJob::kStop) {
      core_.abort_stop();
    } else {
      abort_motion(0);
    }
  }
  return 0;
}

void SpeedAxis::abort_motion(std::uint16_t error_id) noexcept {
  if (motion_.id == 0) return;
  core_.jobs.set(motion_.id, error_id == 0 ? JobState::kAborted : JobState::kError, error_id);
  motion_ = Motion{};
}

void SpeedAxis::plan_velocity(double target, const ProfileLimits& limits, bool abort_acceleration) noexcept {
  MotionState start = setpoint_;
  if (abort_acceleration) start.acceleration = 0.0;  // MC_Halt/MC_Stop.AbortAcceleration (spec 03 §4.4)
  ProfileLimits l = limits;
  if (!(l.velocity > 0.0)) l.velocity = std::numeric_limits<double>::infinity();
  // A jerk-limited replan carries the velocity on by a0²/(2j) before the acceleration is gone, through the
  // job's jerk (seed 004 §6.7.7, docs/decisions.md S4); a ramp to standstill does not reverse (R1).
  l.jerk = replanning_jerk(start.velocity, start.acceleration, l.jerk, target == 0.0);
  if (profile_.plan(start, target, l)) {
    profile_time_ = 0.0;
    generator_active_ = true;
  }
}

PowerState SpeedAxis::power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept {
  return core_.power(enable, start_mode, stop_mode);
}

Submission SpeedAxis::reset(bool restart) noexcept {
  return core_.reset(restart);
}

Submission SpeedAxis::move_velocity(const MoveVelocityInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!finite(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);
  if (in.Direction < 0 || in.Direction > 2) return Submission::reject(error_id::kInvalidDirection);
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(in.Acceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = core_.motion_prerequisites()) return Submission::reject(e);
  if (const auto e = arbitrate_motion(NewJob::kBaseMotion)) return Submission::reject(e);
  const double unit = velocity_unit_per_revolution_per_second();
  double v = in.Velocity / unit;
  if (in.Direction == 1) v = std::fabs(v);
  if (in.Direction == 2) v = -std::fabs(v);
  // Current = TRUE keeps the present velocity and direction (spec 03 §4.8).
  const double command = in.Current ? setpoint_.velocity / std::max(override_factor(), 1e-12) : v;
  motion_ = Motion{core_.jobs.create(JobKind::kMoveVelocity, JobState::kActive), JobKind::kMoveVelocity,
                   limits, command, 0.0};
  const double target = std::clamp(command * override_factor(), -limits.velocity, limits.velocity);
  if (std::fabs(command * override_factor()) > limits.velocity + 1e-12)
    core_.raise(kAlarmDynamicsLimitedVelocity);
  motion_.planned_target = target;
  plan_velocity(target, limits, false);
  return Submission::accept(motion_.id);
}

Submission SpeedAxis::halt(const HaltInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (in.Mode != 0 && in.Mode != 1) return Submission::reject(error_id::kInvalidMode);
  ProfileLimits limits;
  // MC_Halt has no Acceleration input: the deceleration serves both signs of the ramp.
  if (const auto e = resolve_dynamics(in.Deceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = core_.motion_prerequisites()) return Submission::reject(e);
  if (const auto e = arbitrate_motion(in.Mode == 1 ? NewJob::kHaltBaseOnly : NewJob::kBaseMotion)) {
    return Submission::reject(e);
  }
  motion_ = Motion{core_.jobs.create(JobKind::kHalt, JobState::kActive), JobKind::kHalt, limits, 0.0, 0.0};
  plan_velocity(0.0, limits, in.AbortAcceleration);
  return Submission::accept(motion_.id);
}

Submission SpeedAxis::stop(const StopInputs& in) noexcept {
  std::size_t n = 0;
  const auto running = running_jobs(n);
  int weight = 0;
  ProfileLimits limits;
  if (const auto decided =
          core_.stop_request(in, db_.DynamicDefaults, db_.DynamicLimits, units(),
                             std::span<const RunningJob>(running.data(), n), weight, limits)) {
    return *decided;
  }
  abort_motion(0);
  const JobId id = core_.start_stop(weight, limits);
  plan_velocity(0.0, limits, in.AbortAcceleration);
  return Submission::accept(id);
}

Submission SpeedAxis::jog(JobId running, const JogInputs& in) noexcept {
  const auto start = [&]() noexcept -> std::uint16_t {
    ProfileLimits limits;
    if (const auto e = resolve_dynamics(in.Acceleration, in.Deceleration, in.Jerk, limits)) return *e;
    if (const auto e = core_.motion_prerequisites()) return e;
    if (const auto e = arbitrate_motion(NewJob::kBaseMotion)) return e;
    // Nothing planned yet (planned target +inf): the jog plans in its first cycle whatever its target, also 0
    // under a 0 % override, so the aborted job's ramp does not go on with its own deceleration (spec 01 §8.8;
    // the same fault as the positioning axis', decision U18).
    motion_ = Motion{core_.jobs.create(JobKind::kJog, JobState::kActive), JobKind::kJog, limits, 0.0,
                     std::numeric_limits<double>::infinity()};
    return 0;
  };
  const auto brake = [&](const ProfileLimits& limits) noexcept { plan_velocity(0.0, limits, false); };
  return evaluate_jog(core_, motion_, running, in, velocity_unit_per_revolution_per_second(), start, brake);
}

Submission SpeedAxis::write_parameter(std::int32_t parameter_number, double value) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (parameter_number != 1020)
    return core_.write_communication_time(parameter_number, value, db_.StatusWord);
  const VariableInfo* v = find_by_write_parameter(speed_axis_variables(), 1020);
  if (v == nullptr || v->write(db_, value) != ValueError::kNone) {
    return Submission::reject(error_id::kInvalidParameterValue);
  }
  (void)v->write(*start_, value);  // RES written this way survives a TO restart (spec 04 §0.3)
  return Submission::accept(core_.jobs.create(JobKind::kWriteParameter, JobState::kDone));
}

TorqueLimitingState SpeedAxis::torque_limiting(const TorqueLimitingInputs& in) noexcept {
  TorqueLimitingState s = core_.torque.call(in, [this](const TorqueLimitingInputs& i) -> std::uint16_t {
    // Fixed-stop detection needs position control: positioning and synchronous axes (spec 03 §4.18.3).
    if (i.Mode != 0) return error_id::kInvalidMode;
    if (!std::isfinite(i.Limit) || i.Limit > 1.0e12) return error_id::kInvalidTorqueLimit;
    if (!core_.torque.active) {  // start conditions (spec 01 §8.10, §12 scenario 36; decision F7)
      if (const auto e = core_.control.program_job_rejection()) return e;
      if (core_.stop_locks()) return error_id::kLockedByStop;
      if (core_.alarms.strongest_reaction() == AlarmReaction::kRemoveEnable)
        return error_id::kAxisBlockedByAlarm;
    }
    if (drive_used() && !drive_has_momred_) return error_id::kNoTorqueReduction;  // F1
    // Mutual exclusion with MC_TorqueRange (spec 03 §4.18.3 priority).
    if (!core_.torque.active && core_.torque_data.range_active()) return error_id::kTorqueLimitingExclusion;
    return 0;
  });
  s.InLimitation = core_.torque.active && core_.in_limitation;
  return s;
}

TorqueDataConditions SpeedAxis::torque_data_conditions() const noexcept {
  return core_.torque_data_conditions(drive_used() ? &drive_ : nullptr,
                                      db_.Actor.DriveParameter.ReferenceTorque, db_.Actor.InverseDirection);
}

TorqueJobState SpeedAxis::torque_additive(const TorqueAdditiveInputs& in) noexcept {
  return core_.torque_data.additive(in, torque_data_conditions());
}

TorqueJobState SpeedAxis::torque_range(const TorqueRangeInputs& in) noexcept {
  return core_.torque_data.range(in, torque_data_conditions());
}

// =========================================================================================================
// MC_Servo

void SpeedAxis::servo(const CycleClock&) noexcept {
  read_actual_values();
  write_setpoint();
}

void SpeedAxis::read_actual_values() noexcept {
  const double gear =
      static_cast<double>(db_.LoadGear.Numerator) / static_cast<double>(db_.LoadGear.Denominator);
  const double sign = db_.Actor.InverseDirection ? -1.0 : 1.0;
  if (!drive_used()) {
    actual_velocity_ = setpoint_.velocity;  // virtual axis / simulation: the actual value is the setpoint
    db_.ActualSpeed = sign * actual_velocity_ * 60.0 * gear;
    db_.StatusDrive.InOperation = core_.phase == PowerPhase::kEnabled;
    db_.StatusDrive.CommunicationOK = true;
    return;
  }
  drive_.read();
  db_.ActualSpeed = drive_.actual_speed_rpm();
  actual_velocity_ = sign * db_.ActualSpeed / 60.0 / gear;
  db_.StatusDrive.InOperation = drive_.in_operation();
  db_.StatusDrive.CommunicationOK = drive_.communication_ok();
  db_.StatusDrive.Error = drive_.drive_status().state == tg::DriveState::kFault;
  if (drive_.device_config().supplementary_telegram == 750) {
    db_.StatusTorqueData.ActualTorque = sign * tg::n2_to_torque(drive_.supplementary_actual().M_ACT,
                                                                db_.Actor.DriveParameter.ReferenceTorque);
  }
  core_.supervise_drive(drive_);
}

// Speed setpoint to the drive: load-side velocity through the load gear, limited to MaxSpeed (spec 01 §3.6).
void SpeedAxis::write_setpoint() noexcept {
  const double gear =
      static_cast<double>(db_.LoadGear.Numerator) / static_cast<double>(db_.LoadGear.Denominator);
  const double sign = db_.Actor.InverseDirection ? -1.0 : 1.0;
  double rpm = 0.0;
  const bool setpoint_to_drive = !core_.enable_removed() &&
                                 core_.reaction_in_force != AlarmReaction::kFollowSetpoint &&
                                 core_.drive_follows_setpoint();
  if (setpoint_to_drive) {
    const double max = db_.Actor.DriveParameter.MaxSpeed;
    rpm = std::clamp(sign * setpoint_.velocity * 60.0 * gear, -max, max);
  }
  db_.VelocitySetpoint = sign * rpm / 60.0 / gear * velocity_unit_per_revolution_per_second();
  if (!drive_used()) {
    if (device_ != nullptr) drive_.keep_off();  // simulated, its drive kept for a later restart (B8)
    return;
  }
  // MC_TorqueLimiting (spec 01 §8.10): the speed axis is rotary; load side through the gear (and efficiency).
  double motor_limit = 0.0;
  const bool torque_output = core_.torque.active || core_.torque.stw2_fixed_stop || command_.momred != 0;
  if (core_.torque.active) {
    TorqueLimitMechanics m;
    m.load_side = db_.TorqueLimiting.LimitBase == static_cast<std::int32_t>(TorqueLimitBase::kLoadSide);
    m.gear_ratio = gear;
    m.efficiency = db_.Actor.Efficiency;
    const double limit =
        core_.torque.limit >= 0.0 ? core_.torque.limit : db_.TorqueLimiting.LimitDefaults.Torque;
    motor_limit = motor_torque_limit(limit, m);
  }
  core_.in_limitation =
      torque_output &&
      drive_torque_limit(command_, drive_.drive_actual(), core_.torque, motor_limit,
                         db_.Actor.DriveParameter.ReferenceTorque, drive_has_momred_, drive_has_meldw_);
  // Telegram 750 (spec 01 §8.12/§8.13): MC_TorqueAdditive and MC_TorqueRange; no precontrol on a speed axis.
  core_.torque_data.write(drive_, core_.torque_data.additive_value(),
                          db_.Actor.DriveParameter.ReferenceTorque, db_.Actor.InverseDirection);
  drive_.request(core_.drive_request(db_.Actor.RemoveEnableReaction));
  command_.speed_rpm = rpm;
  drive_.write(command_);
}

// =========================================================================================================
// MC_Interpolator

void SpeedAxis::interpolate(const CycleClock& clock) noexcept {
  core_.cycle = clock.interpolator_cycles + 1;  // 0 means "never" for the acknowledge time
  core_.ipo_cycle_s = clock.interpolator_cycle_s;
  take_reset();
  apply_alarm_reactions();
  update_power_phase();
  update_live_motion();
  generate_setpoint();
  update_status();
}

// MC_Reset: acknowledge (and restart) in the interpolator cycle after the call.
void SpeedAxis::take_reset() noexcept {
  const auto restart_requested = core_.begin_reset(core_.cycle);
  if (!restart_requested) return;
  if (device_ != nullptr) drive_.acknowledge();  // also a drive kept unused (decision B8)
  if (*restart_requested) restart();
  core_.finish_reset();
}

void SpeedAxis::apply_alarm_reactions() noexcept {
  if (core_.reaction_change() != ReactionChange::kEscalated) return;
  // A stop reaction takes over: motion jobs end with Error 16#8001 (spec 03 §6.6).
  const ProfileLimits current =
      motion_.id != 0 ? motion_.limits : AxisCore::default_ramp(db_.DynamicDefaults, units());
  abort_motion(error_id::kAbortedByAlarmReaction);
  if (core_.stop_keeps_control()) return;
  if (const auto ramp = core_.reaction_ramp(current, db_.DynamicDefaults, db_.DynamicLimits, units())) {
    plan_velocity(0.0, *ramp, false);
  } else {
    generator_active_ = false;  // the drive brakes (remove enable) or is followed (follow setpoint)
  }
}

// Enable / disable (spec 01 §6, spec 02 §3.1).
void SpeedAxis::update_power_phase() noexcept {
  switch (core_.update_power_phase(virtual_axis() || drive_.in_operation())) {
    case PowerEvent::kEnabled:
      // A speed axis is enabled with speed setpoint 0: a moving drive is braked by its speed loop (spec 01
      // §6.2).
      setpoint_ = MotionState{};
      generator_active_ = false;
      break;
    case PowerEvent::kDisabling:
      abort_motion(0);
      if (const auto ramp = core_.disable_ramp(db_.DynamicDefaults, db_.DynamicLimits, units())) {
        plan_velocity(0.0, *ramp, false);
      } else {
        generator_active_ = false;
        setpoint_ = MotionState{};
      }
      break;
    case PowerEvent::kNone:
      break;
  }
}

// Jog: the live velocity, override and release (spec 03 §3.4); MoveVelocity: override changes act at once,
// with the job's dynamics (spec 01 §8.4).
void SpeedAxis::update_live_motion() noexcept {
  if (motion_.kind == JobKind::kJog) {
    const double target = std::clamp(motion_.command_velocity * override_factor(), -motion_.limits.velocity,
                                     motion_.limits.velocity);
    if (std::fabs(target - motion_.planned_target) > 1e-12 || !generator_active_) {
      motion_.planned_target = target;
      plan_velocity(target, motion_.limits, false);
    }
  } else if (motion_.kind == JobKind::kMoveVelocity) {
    const double target = std::clamp(motion_.command_velocity * override_factor(), -motion_.limits.velocity,
                                     motion_.limits.velocity);
    if (std::fabs(target - motion_.planned_target) > 1e-12) {
      motion_.planned_target = target;
      plan_velocity(target, motion_.limits, false);
      core_.jobs.set(motion_.id, JobState::kActive);
    }
  }
}

void SpeedAxis::generate_setpoint() noexcept {
  if (core_.follows_actual()) {
    // Follow-up: the setpoint tracks the actual value (spec 02 §3.2).
    setpoint_ = MotionState{0.0, actual_velocity_, 0.0};
    generator_active_ = false;
  } else if (generator_active_) {
    profile_time_ += core_.ipo_cycle_s;
    setpoint_ = profile_.at(profile_time_);
    if (profile_time_ >= profile_.duration() - 1e-9) {     // cycle sums of 0.001 s drift by ulps
      setpoint_ = profile_.at(profile_.duration() + 1.0);  // exact end state
      generator_active_ = false;
    }
  } else if (motion_.kind == JobKind::kMotionInVelocity) {
    // The inputs of the last call, as given (spec 03 §4.17.1: no profile, no dynamic limits).
    setpoint_ = MotionState{0.0, motion_.command_velocity, motion_.planned_target};
  }
  const bool settled = !generator_active_;
  const bool at_zero = std::fabs(setpoint_.velocity) < kStandstillEpsilon;

  // Job completion.
  if (motion_.id != 0) {
    if (motion_.kind == JobKind::kHalt && settled && at_zero) {
      core_.jobs.set(motion_.id, JobState::kDone);
      motion_ = Motion{};
    } else if (motion_.kind == JobKind::kJog && motion_.jog_stopping && settled && at_zero) {
      core_.jobs.set(motion_.id, JobState::kDone);  // J2: Busy ends at standstill
      motion_ = Motion{};
    } else {
      core_.jobs.set_in_velocity(motion_.id, settled && !motion_.jog_stopping);
    }
  }
  if (settled && at_zero) core_.stop_reached_standstill();
  const bool drive_off = virtual_axis() || !drive_.in_operation();
  core_.finish_disabling(settled && at_zero, drive_off && std::fabs(actual_velocity_) < 1e-3);
}

void SpeedAxis::update_status() noexcept {
  const double unit = velocity_unit_per_revolution_per_second();
  db_.Velocity = setpoint_.velocity * unit;
  db_.Acceleration = setpoint_.acceleration;

  std::uint32_t sw = db_.StatusWord & (1u << static_cast<unsigned>(StatusWordBit::kOnlineStartValuesChanged));
  std::uint32_t sw2 = 0;
  std::uint32_t ew = 0;
  std::uint32_t ww = 0;
  core_.update_words(sw, sw2, ew, ww, db_.ErrorDetail, db_.Simulation.Mode == kModeOn);
  const bool enabled = test(sw, StatusWordBit::kEnable);
  db_.StatusTorqueData.CommandAdditiveTorqueActive = core_.torque_data.additive_active() ? 1 : 0;
  db_.StatusTorqueData.CommandTorqueRangeActive = core_.torque_data.range_active() ? 1 : 0;
  // SA: Done = motion finished and setpoint velocity 0 (spec 04 §8 rule 2).
  // A running MotionIn job is not finished even at velocity 0.
  assign(sw, StatusWordBit::kDone,
         !generator_active_ && motion_.kind != JobKind::kMotionInVelocity &&
             std::fabs(setpoint_.velocity) < kStandstillEpsilon);
  assign(sw, StatusWordBit::kJogCommand, motion_.kind == JobKind::kJog);
  assign(sw, StatusWordBit::kVelocityCommand, motion_.kind == JobKind::kMoveVelocity);
  // S: StatusMotionIn.FunctionState instead of StatusWord.X31 (spec 04 §4.8, §5.1).
  db_.StatusMotionIn.FunctionState = static_cast<std::int32_t>(motion_.kind == JobKind::kMotionInVelocity
                                                                   ? MotionInFunctionState::kMotionInVelocity
                                                                   : MotionInFunctionState::kNone);
  assign(sw, StatusWordBit::kConstantVelocity,
         enabled && !generator_active_ && std::fabs(setpoint_.velocity) >= kStandstillEpsilon &&
             std::fabs(setpoint_.acceleration) < 1e-9);
  assign(sw, StatusWordBit::kAccelerating, setpoint_.acceleration * setpoint_.velocity > 0.0);
  assign(sw, StatusWordBit::kDecelerating, setpoint_.acceleration * setpoint_.velocity < 0.0);
  db_.StatusWord = sw;
  db_.StatusWord2 = sw2;
  db_.ErrorWord = ew;
  db_.WarningWord = ww;
}

void SpeedAxis::restart() noexcept {
  // MC_Reset Restart = TRUE: re-initialise from the start values (spec 01 §7); RES and DIR values return to
  // them. Seed 004 §6.1.7: "at the end of the simulation a valid drive and encoder integration must be
  // present": an axis built without a drive stays in simulation, alarm 102 (decision B8).
  const std::uint32_t simulation_mode = db_.Simulation.Mode;
  const bool no_drive = start_->VirtualAxis.Mode != kModeOn && device_ == nullptr &&
                        simulation_mode == kModeOn && start_->Simulation.Mode != kModeOn;
  db_ = *start_;
  if (no_drive) db_.Simulation.Mode = simulation_mode;
  core_.restart();
  assign(db_.StatusWord, StatusWordBit::kOnlineStartValuesChanged, no_drive);  // X3: a value not taken
  db_.StatusDrive.AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_APPLICABLE);
  motion_ = Motion{};
  generator_active_ = false;
  setpoint_ = MotionState{};
  command_.travel_to_fixed_stop = false;  // the restarted connection clears STW2 (AxisCore::restart)
  if (device_ != nullptr) {
    drive_.restart(with_reference_values(drive_.config(), start_->Actor));  // the PROFIdrive link runs on
  }
  if (no_drive) core_.raise(kAlarmConfiguration, kConfigurationNoDrive);  // after the restart's acknowledge
}

}  // namespace tomc::techobjects
