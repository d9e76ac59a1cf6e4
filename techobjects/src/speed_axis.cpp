// TO_SpeedAxis behaviour. Servo: drive frames -> actual values -> drive supervision -> speed setpoint.
// Interpolator: acknowledge/restart -> alarm reactions -> enable/disable -> jobs -> setpoint -> status.
#include "tomc/techobjects/speed_axis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tomc/techobjects/error_ids.hpp"
#include "tomc/telegrams/layout.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

constexpr std::uint64_t kReRaiseHoldOffCycles =
    20;                                      // a condition still present this long after MC_Reset re-raises
constexpr double kStandstillEpsilon = 1e-9;  // rev/s

bool finite(double x) {
  return std::isfinite(x);
}

}  // namespace

SpeedAxis::SpeedAxis(std::string name, DeviceIo* device, const SpeedAxisData& start_values,
                     const DriveConnectionConfig& drive)
    : name_(std::move(name)), device_(device), start_(start_values), db_(start_values), drive_config_(drive) {
  for (const auto& v : speed_axis_variables()) {
    if (v.role != VariableRole::kConfiguration) continue;
    const ValueError e = check_value(v, v.read(start_));
    if (e != ValueError::kNone) {
      throw std::invalid_argument(name_ + "." + std::string(v.path) + ": " + std::string(to_string(e)));
    }
  }
  if (start_.VirtualAxis.Mode == kModeOn || start_.Simulation.Mode == kModeOn) device_ = nullptr;
  drive_config_.reference_speed_rpm = start_.Actor.DriveParameter.ReferenceSpeed;
  drive_config_.reference_torque_nm = start_.Actor.DriveParameter.ReferenceTorque;
  if (device_ != nullptr) {
    drive_ = DriveConnection(*device_, drive_config_);
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
  if (control_.override_ineffective()) return 1.0;  // spec 02 §9.3: the panel has its own "adapt velocity"
  return std::clamp(db_.Override.Velocity, 0.0, 200.0) / 100.0;  // spec 01 §8.4: 0..200 %
}

double SpeedAxis::velocity_limit() const noexcept {
  // spec 01 §8.3: min(MaxVelocity, Velocity) of the dynamic limits.
  return std::min(db_.DynamicLimits.MaxVelocity, db_.DynamicLimits.Velocity) /
         velocity_unit_per_revolution_per_second();
}

bool SpeedAxis::blocked() const noexcept {
  return reaction_in_force_ != AlarmReaction::kNone;
}

// ---------------------------------------------------------------------------------------------------------
// Job records

JobId SpeedAxis::new_job(JobKind kind, JobState state) noexcept {
  return jobs_.create(kind, state);
}

void SpeedAxis::set_job(JobId id, JobState state, std::uint16_t error_id) noexcept {
  jobs_.set(id, state, error_id);
}

JobStatus SpeedAxis::job_status(JobId id) const noexcept {
  return jobs_.status(id);
}

// ---------------------------------------------------------------------------------------------------------
// Job API

std::uint16_t SpeedAxis::motion_prerequisites() const noexcept {
  if (phase_ != PowerPhase::kEnabled) return error_id::kAxisNotEnabled;
  if (blocked()) return error_id::kAxisBlockedByAlarm;
  if (stop_.id != 0 && stop_.execute) return error_id::kLockedByStop;
  return 0;
}

// spec 03 §2.1 and spec 01 §8.1/§8.5: < 0 -> DynamicDefaults, = 0 invalid (jerk: no jerk limit), > 0 as
// given, then limited to DynamicLimits (warnings 502/503). MaxJerk > 0 also caps a job without jerk limit
// (docs/decisions.md S3): the limits hold for every motion the TO generates.
std::optional<std::uint16_t> SpeedAxis::resolve_dynamics(double acceleration, double deceleration,
                                                         double jerk, ProfileLimits& out) noexcept {
  if (!finite(acceleration) || acceleration == 0.0) return error_id::kInvalidAcceleration;
  if (!finite(deceleration) || deceleration == 0.0) return error_id::kInvalidDeceleration;
  if (!finite(jerk)) return error_id::kInvalidJerk;
  const auto& d = db_.DynamicDefaults;
  const auto& l = db_.DynamicLimits;
  double a = acceleration < 0.0 ? d.Acceleration : acceleration;
  double dec = deceleration < 0.0 ? d.Deceleration : deceleration;
  double j = jerk < 0.0 ? d.Jerk : jerk;
  limited_dynamics_ = false;
  if (a > l.MaxAcceleration) {
    a = l.MaxAcceleration;
    raise(kAlarmDynamicsLimitedAcceleration);
  }
  if (dec > l.MaxDeceleration) {
    dec = l.MaxDeceleration;
    raise(kAlarmDynamicsLimitedAcceleration);
  }
  if (l.MaxJerk > 0.0 && (j == 0.0 || j > l.MaxJerk)) {
    if (j > l.MaxJerk) raise(kAlarmDynamicsLimitedJerk);
    j = l.MaxJerk;
  }
  out.velocity = velocity_limit();
  out.acceleration = a;
  out.deceleration = dec;
  out.jerk = j;
  return std::nullopt;
}

std::uint16_t SpeedAxis::arbitrate_motion(NewJob row) noexcept {
  std::array<RunningJob, 2> running{};
  std::size_t n = 0;
  if (motion_.id != 0) {
    running[n++] = motion_.kind == JobKind::kHalt ? RunningJob::kHaltAll : RunningJob::kBaseMotionActive;
  }
  const bool stop_running = stop_.id != 0 && (!stop_.done || stop_.execute);
  if (stop_running) running[n++] = RunningJob::kStop;
  ArbitrationContext ctx;
  ctx.running_job_ends_by_itself = motion_.kind == JobKind::kHalt;
  ctx.virtual_or_simulated_axis = virtual_axis();
  ctx.running_stop_weight = stop_.weight;
  const Decision d = arbitrate(row, std::span<const RunningJob>(running.data(), n), ctx);
  if (d.reject) return error_id::kRejectedByRunningJob;
  for (std::size_t i = 0; i < n; ++i) {
    if ((d.abort_mask & (1u << i)) == 0) continue;
    if (running[i] == RunningJob::kStop) {
      set_job(stop_.id, JobState::kAborted);
      stop_ = StopJob{};
    } else {
      abort_motion(0);
    }
  }
  return 0;
}

void SpeedAxis::abort_motion(std::uint16_t error_id) noexcept {
  if (motion_.id == 0) return;
  set_job(motion_.id, error_id == 0 ? JobState::kAborted : JobState::kError, error_id);
  motion_ = Motion{};
}

void SpeedAxis::plan_velocity(double target, const ProfileLimits& limits, bool abort_acceleration) noexcept {
  MotionState start = setpoint_;
  if (abort_acceleration) start.acceleration = 0.0;  // MC_Halt/MC_Stop.AbortAcceleration (spec 03 §4.4)
  ProfileLimits l = limits;
  if (!(l.velocity > 0.0)) l.velocity = std::numeric_limits<double>::infinity();
  // A jerk-limited replan carries the velocity on by a0²/(2j) before the acceleration is gone: the velocity
  // limit wins over the job's jerk (docs/decisions.md S4), and a ramp to standstill does not reverse (R1).
  l.jerk = replanning_jerk(start.velocity, start.acceleration, l.jerk, velocity_limit(), target == 0.0);
  if (profile_.plan(start, target, l)) {
    profile_time_ = 0.0;
    generator_active_ = true;
  }
}

PowerState SpeedAxis::power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept {
  PowerState s;
  if (const auto e = control_.program_job_rejection()) {
    // The panel holds control priority: the program's MC_Power changes nothing (spec 02 §9.2).
    s.Error = enable;
    s.ErrorID = enable ? e : 0;
  } else if (start_mode != 0 && start_mode != 1) {
    s.Error = true;
    s.ErrorID = error_id::kInvalidStartMode;
  } else if (stop_mode < 0 || stop_mode > 3) {
    s.Error = true;
    s.ErrorID = error_id::kInvalidStopMode;
  } else {
    enable_ = enable;
    if (!enable) stop_mode_ = stop_mode;
  }
  const bool removed = reaction_in_force_ == AlarmReaction::kRemoveEnable;
  s.Status = phase_ == PowerPhase::kEnabled && !removed;
  s.Busy = enable_ || phase_ != PowerPhase::kDisabled;
  return s;
}

Submission SpeedAxis::reset(bool restart) noexcept {
  if (const auto e = control_.program_job_rejection()) return Submission::reject(e);
  if (restart && (phase_ != PowerPhase::kDisabled || enable_)) {
    return Submission::reject(error_id::kRestartNeedsDisabledAxis);
  }
  reset_pending_ = true;
  restart_requested_ = restart;
  reset_job_ = new_job(JobKind::kReset, JobState::kActive);
  return Submission::accept(reset_job_);
}

Submission SpeedAxis::move_velocity(const MoveVelocityInputs& in) noexcept {
  if (const auto e = control_.program_job_rejection()) return Submission::reject(e);
  if (!finite(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);
  if (in.Direction < 0 || in.Direction > 2) return Submission::reject(error_id::kInvalidDirection);
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(in.Acceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  if (const auto e = arbitrate_motion(NewJob::kBaseMotion)) return Submission::reject(e);
  const double unit = velocity_unit_per_revolution_per_second();
  double v = in.Velocity / unit;
  if (in.Direction == 1) v = std::fabs(v);
  if (in.Direction == 2) v = -std::fabs(v);
  // Current = TRUE keeps the present velocity and direction (spec 03 §4.8).
  const double command = in.Current ? setpoint_.velocity / std::max(override_factor(), 1e-12) : v;
  motion_ = Motion{new_job(JobKind::kMoveVelocity, JobState::kActive), JobKind::kMoveVelocity, limits,
                   command, 0.0};
  const double target = std::clamp(command * override_factor(), -limits.velocity, limits.velocity);
  if (std::fabs(command * override_factor()) > limits.velocity + 1e-12) raise(kAlarmDynamicsLimitedVelocity);
  motion_.planned_target = target;
  plan_velocity(target, limits, false);
  return Submission::accept(motion_.id);
}

Submission SpeedAxis::halt(const HaltInputs& in) noexcept {
  if (const auto e = control_.program_job_rejection()) return Submission::reject(e);
  if (in.Mode != 0 && in.Mode != 1) return Submission::reject(error_id::kInvalidMode);
  ProfileLimits limits;
  // MC_Halt has no Acceleration input: the deceleration serves both signs of the ramp.
  if (const auto e = resolve_dynamics(in.Deceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  if (const auto e = arbitrate_motion(in.Mode == 1 ? NewJob::kHaltBaseOnly : NewJob::kBaseMotion)) {
    return Submission::reject(e);
  }
  motion_ = Motion{new_job(JobKind::kHalt, JobState::kActive), JobKind::kHalt, limits, 0.0, 0.0};
  plan_velocity(0.0, limits, in.AbortAcceleration);
  return Submission::accept(motion_.id);
}

Submission SpeedAxis::stop(const StopInputs& in) noexcept {
  if (const auto e = control_.program_job_rejection()) return Submission::reject(e);
  const int weight = stop_weight_of_mc_stop_mode(in.Mode);
  if (weight == 0)
    return Submission::reject(error_id::kInvalidMode);  // Mode 1 and anything else (spec 03 §4.13)
  ProfileLimits limits;
  const auto& l = db_.DynamicLimits;
  if (in.Mode == 0) {
    limits = ProfileLimits{std::numeric_limits<double>::infinity(), db_.DynamicDefaults.EmergencyDeceleration,
                           db_.DynamicDefaults.EmergencyDeceleration, 0.0};  // no jerk limit (spec 02 §3.7)
  } else if (in.Mode == 2) {
    limits = ProfileLimits{std::numeric_limits<double>::infinity(), l.MaxDeceleration, l.MaxDeceleration,
                           l.MaxJerk};
  } else if (const auto e = resolve_dynamics(in.Deceleration, in.Deceleration, in.Jerk, limits)) {
    return Submission::reject(*e);
  }
  if (phase_ != PowerPhase::kEnabled) return Submission::reject(error_id::kAxisNotEnabled);
  // A stop reaction of an alarm with a higher weight is in force: the MC_Stop ends with CommandAborted, not
  // Error (seed §6.9.4, spec 02 §3.8).
  if (stop_weight_of_reaction(static_cast<int>(reaction_in_force_)) > weight) {
    return Submission::accept(new_job(JobKind::kStop, JobState::kAborted));
  }
  ArbitrationContext ctx;
  std::array<RunningJob, 2> running{};
  std::size_t n = 0;
  if (motion_.id != 0)
    running[n++] = motion_.kind == JobKind::kHalt ? RunningJob::kHaltAll : RunningJob::kBaseMotionActive;
  if (stop_.id != 0) running[n++] = RunningJob::kStop;
  ctx.new_stop_weight = weight;
  ctx.running_stop_weight = stop_.weight;
  const Decision d = arbitrate(NewJob::kStop, std::span<const RunningJob>(running.data(), n), ctx);
  if (d.reject) return Submission::reject(error_id::kRejectedByRunningJob);
  abort_motion(0);
  if (stop_.id != 0) set_job(stop_.id, JobState::kAborted);
  stop_ = StopJob{new_job(JobKind::kStop, JobState::kActive), weight, limits, true, false};
  plan_velocity(0.0, limits, in.AbortAcceleration);
  return Submission::accept(stop_.id);
}

void SpeedAxis::stop_execute(JobId job, bool execute) noexcept {
  if (job != 0 && job == stop_.id) {
    stop_.execute = execute;
    if (!execute && stop_.done) stop_ = StopJob{};  // Done and released: no longer a running MC_Stop
  }
}

Submission SpeedAxis::jog(JobId running, const JogInputs& in) noexcept {
  const bool both = in.JogForward && in.JogBackward;
  const bool any = in.JogForward || in.JogBackward;
  const bool mine = running != 0 && running == motion_.id && motion_.kind == JobKind::kJog;
  if (!mine) {
    if (!any) return Submission{};  // nothing to do, no job
    if (const auto e = control_.program_job_rejection()) return Submission::reject(e);
    if (both) return Submission::reject(error_id::kJogWrongDirection);
    if (!finite(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);
    ProfileLimits limits;
    if (const auto e = resolve_dynamics(in.Acceleration, in.Deceleration, in.Jerk, limits))
      return Submission::reject(*e);
    if (const auto e = motion_prerequisites()) return Submission::reject(e);
    if (const auto e = arbitrate_motion(NewJob::kBaseMotion)) return Submission::reject(e);
    motion_ = Motion{new_job(JobKind::kJog, JobState::kActive), JobKind::kJog, limits, 0.0, 0.0};
    running = motion_.id;
  }
  if (both) {
    // J4: decelerate with the last valid deceleration; the job ends with 16#8007 (the ramp goes on).
    const ProfileLimits limits = motion_.limits;
    set_job(motion_.id, JobState::kError, error_id::kJogWrongDirection);
    motion_ = Motion{};
    plan_velocity(0.0, limits, false);
    return Submission::reject(error_id::kJogWrongDirection);
  }
  // J1/J3/J5: the velocity is live; a released input brakes; a new press during the ramp accelerates again.
  const double magnitude = std::fabs(in.Velocity) / velocity_unit_per_revolution_per_second();  // [AMB-3]
  motion_.jog_stopping = !any;
  motion_.command_velocity = any ? (in.JogForward ? magnitude : -magnitude) : 0.0;
  return Submission::accept(running);
}

Submission SpeedAxis::set_axis_stw(std::uint16_t stw1, std::uint16_t stw1_mask, std::uint16_t stw2,
                                   std::uint16_t stw2_mask) noexcept {
  if (const auto e = control_.program_job_rejection()) return Submission::reject(e);
  constexpr std::uint16_t kUserStw1 = 0xFB00;  // bits 8, 9, 11..15 (the TO owns 0..7 and 10)
  constexpr std::uint16_t kUserStw2 = 0x0FFF;  // bits 0..11 (12..15: master sign-of-life)
  if ((stw1_mask & ~kUserStw1) != 0 || (stw2_mask & ~kUserStw2) != 0)
    return Submission::reject(error_id::kInvalidBitMask);
  if (device_ == nullptr || drive_.device_config().drive_telegram == 0)
    return Submission::reject(error_id::kNoDriveTelegram);
  auto& sp = drive_.drive_setpoint();
  sp.STW1 = tg::Stw1{static_cast<std::uint16_t>((sp.STW1.value() & ~stw1_mask) | (stw1 & stw1_mask))};
  sp.STW2 = tg::Stw2{static_cast<std::uint16_t>((sp.STW2.value() & ~stw2_mask) | (stw2 & stw2_mask))};
  return Submission::accept(
      new_job(JobKind::kSetAxisStw, JobState::kDone));  // in effect from the next servo cycle
}

Submission SpeedAxis::write_parameter(std::int32_t parameter_number, double value) noexcept {
  if (const auto e = control_.program_job_rejection()) return Submission::reject(e);
  switch (parameter_number) {
    case 1010:
    case 1011:
    case 1012: {
      if (!finite(value) || value < 0.0) return Submission::reject(error_id::kInvalidParameterValue);
      double& target = parameter_number == 1010   ? communication_times_start_.Ti
                       : parameter_number == 1011 ? communication_times_start_.To
                                                  : communication_times_start_.Tdc;
      target = value;
      assign(db_.StatusWord, StatusWordBit::kOnlineStartValuesChanged, true);  // effective after restart
      break;
    }
    case 1020: {
      const VariableInfo* v = find_by_write_parameter(speed_axis_variables(), 1020);
      if (v == nullptr || v->write(db_, value) != ValueError::kNone) {
        return Submission::reject(error_id::kInvalidParameterValue);
      }
      (void)v->write(start_, value);  // RES written this way survives a TO restart (spec 04 §0.3)
      break;
    }
    default:
      return Submission::reject(error_id::kInvalidParameterNumber);
  }
  return Submission::accept(new_job(JobKind::kWriteParameter, JobState::kDone));
}

// ---------------------------------------------------------------------------------------------------------
// Alarms

bool SpeedAxis::inject_alarm(std::uint32_t number, std::uint32_t additional_value,
                             AlarmReaction reaction) noexcept {
  return alarms_.raise(number, additional_value, reaction, cycle_);
}

void SpeedAxis::raise(std::uint32_t number, std::uint32_t additional) noexcept {
  (void)alarms_.raise(number, additional, cycle_);
}

void SpeedAxis::supervise_drive() noexcept {
  if (device_ == nullptr) return;
  const bool held_off = cycle_ < acknowledged_at_ + kReRaiseHoldOffCycles && acknowledged_at_ != 0;
  const auto fault = drive_.communication_fault();
  // Drive fault: raised when it appears; raised again if it is still there after an acknowledge's hold-off.
  const bool drive_fault = fault == CommunicationFault::kDriveFault;
  if (drive_fault && (!drive_fault_seen_ || !held_off)) raise(kAlarmDriveFault);
  drive_fault_seen_ = drive_fault;
  if (held_off) return;
  if (fault == CommunicationFault::kLinkLost && drive_.cycles_without_fresh_frame() > 0)
    raise(kAlarmDriveCommunication);
  if (fault == CommunicationFault::kSignOfLifeFailed) raise(kAlarmDriveSignOfLife);
  // The drive left operation on its own while the TO is enabled.
  if (phase_ == PowerPhase::kEnabled && reaction_in_force_ == AlarmReaction::kNone &&
      fault == CommunicationFault::kNone && !drive_.in_operation()) {
    raise(kAlarmDriveNotReady);
  }
}

void SpeedAxis::apply_alarm_reactions() noexcept {
  const AlarmReaction r = alarms_.strongest_reaction();
  if (r == reaction_in_force_) return;
  const bool escalation = reaction_rank(r) > reaction_rank(reaction_in_force_);
  const AlarmReaction before = reaction_in_force_;
  reaction_in_force_ = r;
  if (!escalation) {
    // Acknowledged: the TO is no longer blocked. After "remove enable" an MC_Power whose Enable stayed TRUE
    // enables the TO again (spec 03 §3.3 L2).
    if (r == AlarmReaction::kNone &&
        (before == AlarmReaction::kRemoveEnable || before == AlarmReaction::kFollowSetpoint)) {
      if (phase_ == PowerPhase::kEnabled) {
        phase_ = enable_ ? PowerPhase::kEnabling : PowerPhase::kDisabled;
        enabling_since_ = cycle_;
      }
    }
    return;
  }
  // A stop reaction takes over: motion jobs end with Error 16#8001 (spec 03 §6.6).
  ProfileLimits current = motion_.id != 0
                              ? motion_.limits
                              : ProfileLimits{0.0, db_.DynamicDefaults.Deceleration,
                                              db_.DynamicDefaults.Deceleration, db_.DynamicDefaults.Jerk};
  abort_motion(error_id::kAbortedByAlarmReaction);
  const int alarm_weight = stop_weight_of_reaction(static_cast<int>(r));
  const bool stop_keeps_control =
      stop_.id != 0 && stop_.weight >= alarm_weight && r != AlarmReaction::kFollowSetpoint;
  if (stop_.id != 0 && !stop_keeps_control) {
    set_job(stop_.id, JobState::kAborted);  // MC_Stop reports CommandAborted, not Error (seed §6.9.4)
    stop_ = StopJob{};
  }
  if (stop_keeps_control) return;
  const auto& l = db_.DynamicLimits;
  switch (r) {
    case AlarmReaction::kStopCurrentDynamics:
      plan_velocity(0.0, current, false);
      break;
    case AlarmReaction::kStopMaxDynamics:
      plan_velocity(0.0, ProfileLimits{0.0, l.MaxDeceleration, l.MaxDeceleration, l.MaxJerk}, false);
      break;
    case AlarmReaction::kStopEmergencyRamp:
      plan_velocity(0.0,
                    ProfileLimits{0.0, db_.DynamicDefaults.EmergencyDeceleration,
                                  db_.DynamicDefaults.EmergencyDeceleration, 0.0},
                    false);
      break;
    case AlarmReaction::kRemoveEnable:
    case AlarmReaction::kFollowSetpoint:
      generator_active_ = false;  // the drive brakes (remove enable) or is followed (follow setpoint)
      break;
    case AlarmReaction::kNone:
      break;
  }
}

// ---------------------------------------------------------------------------------------------------------
// The cycle

void SpeedAxis::servo(const CycleClock&) noexcept {
  const double unit = velocity_unit_per_revolution_per_second();
  const double gear =
      static_cast<double>(db_.LoadGear.Numerator) / static_cast<double>(db_.LoadGear.Denominator);
  const double sign = db_.Actor.InverseDirection ? -1.0 : 1.0;
  if (device_ != nullptr) {
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
    supervise_drive();
  } else {
    actual_velocity_ = setpoint_.velocity;  // virtual axis / simulation: the actual value is the setpoint
    db_.ActualSpeed = sign * actual_velocity_ * 60.0 * gear;
    db_.StatusDrive.InOperation = phase_ == PowerPhase::kEnabled;
    db_.StatusDrive.CommunicationOK = true;
  }

  // What the drive is asked to do.
  tg::DriveRequest request = tg::DriveRequest::kOff;
  const bool removed = reaction_in_force_ == AlarmReaction::kRemoveEnable;
  if (removed) {
    switch (db_.Actor.RemoveEnableReaction) {  // spec 02 §3.4
      case 0x1:
        request = tg::DriveRequest::kOff;
        break;
      case 0x3:
        request = tg::DriveRequest::kCoastStop;
        break;
      default:
        request = tg::DriveRequest::kQuickStop;
        break;
    }
  } else if (phase_ == PowerPhase::kEnabling || phase_ == PowerPhase::kEnabled) {
    request = tg::DriveRequest::kOperate;
  } else if (phase_ == PowerPhase::kDisabling) {
    request = stop_mode_ == 1   ? tg::DriveRequest::kQuickStop
              : stop_mode_ == 3 ? tg::DriveRequest::kCoastStop
                                : tg::DriveRequest::kOperate;  // 0/2: the TO ramps, the drive follows
  } else {
    request = stop_mode_ == 3 ? tg::DriveRequest::kCoastStop : tg::DriveRequest::kOff;
  }

  // Speed setpoint to the drive: load-side velocity through the load gear, limited to MaxSpeed (spec 01
  // §3.6).
  double rpm = 0.0;
  const bool setpoint_to_drive = !removed && reaction_in_force_ != AlarmReaction::kFollowSetpoint &&
                                 (phase_ == PowerPhase::kEnabled ||
                                  (phase_ == PowerPhase::kDisabling && stop_mode_ != 1 && stop_mode_ != 3));
  if (setpoint_to_drive) {
    const double max = db_.Actor.DriveParameter.MaxSpeed;
    rpm = std::clamp(sign * setpoint_.velocity * 60.0 * gear, -max, max);
  }
  db_.VelocitySetpoint = sign * rpm / 60.0 / gear * unit;
  if (device_ != nullptr) {
    // MC_TorqueLimiting (spec 01 §8.10): the speed axis is rotary; load side through the gear (and
    // efficiency).
    double motor_limit = 0.0;
    const bool torque_output =
        torque_.active || torque_.stw2_fixed_stop || drive_.drive_setpoint().MOMRED != 0;
    if (torque_.active) {
      TorqueLimitMechanics m;
      m.load_side = db_.TorqueLimiting.LimitBase == static_cast<std::int32_t>(TorqueLimitBase::kLoadSide);
      m.gear_ratio = gear;
      m.efficiency = db_.Actor.Efficiency;
      const double limit = torque_.limit >= 0.0 ? torque_.limit : db_.TorqueLimiting.LimitDefaults.Torque;
      motor_limit = motor_torque_limit(limit, m);
    }
    in_limitation_ = torque_output && drive_torque_limit(drive_, torque_, motor_limit,
                                                         db_.Actor.DriveParameter.ReferenceTorque,
                                                         drive_has_momred_, drive_has_meldw_);
    drive_.request(request);
    drive_.set_speed_setpoint(rpm);
    drive_.write();
  }
}

TorqueLimitingState SpeedAxis::torque_limiting(const TorqueLimitingInputs& in) noexcept {
  TorqueLimitingState s = torque_.call(in, [this](const TorqueLimitingInputs& i) -> std::uint16_t {
    // Fixed-stop detection needs position control: positioning and synchronous axes (spec 03 §4.18.3).
    if (i.Mode != 0) return error_id::kInvalidMode;
    if (!std::isfinite(i.Limit) || i.Limit > 1.0e12) return error_id::kInvalidTorqueLimit;
    if (!torque_.active) {  // start conditions (spec 01 §8.10, §12 scenario 36; decision F7)
      if (const auto e = control_.program_job_rejection()) return e;
      if (stop_.id != 0 && stop_.execute) return error_id::kLockedByStop;
      if (alarms_.strongest_reaction() == AlarmReaction::kRemoveEnable) return error_id::kAxisBlockedByAlarm;
    }
    if (device_ != nullptr && !drive_has_momred_) return error_id::kNoTorqueReduction;  // F1
    return 0;
  });
  s.InLimitation = torque_.active && in_limitation_;
  return s;
}

void SpeedAxis::interpolate(const CycleClock& clock) noexcept {
  cycle_ = clock.interpolator_cycles + 1;  // 0 means "never" for acknowledged_at_
  ipo_cycle_s_ = clock.interpolator_cycle_s;

  // MC_Reset: acknowledge (and restart) in the interpolator cycle after the call.
  if (reset_pending_) {
    reset_pending_ = false;
    alarms_.acknowledge(restart_requested_, cycle_);
    acknowledged_at_ = cycle_;
    if (device_ != nullptr) drive_.acknowledge();
    if (restart_requested_) restart();
    set_job(reset_job_, JobState::kDone);
  }

  apply_alarm_reactions();

  // Enable / disable (spec 01 §6, spec 02 §3.1).
  if (phase_ == PowerPhase::kDisabled && enable_ && reaction_in_force_ != AlarmReaction::kRemoveEnable) {
    phase_ = PowerPhase::kEnabling;
    enabling_since_ = cycle_;
  }
  if (phase_ == PowerPhase::kEnabling) {
    if (!enable_) {
      phase_ = PowerPhase::kDisabled;
    } else if (virtual_axis() || drive_.in_operation()) {
      // A speed axis is enabled with speed setpoint 0: a moving drive is braked by its speed loop (spec 01
      // §6.2).
      phase_ = PowerPhase::kEnabled;
      setpoint_ = MotionState{};
      generator_active_ = false;
    } else if (static_cast<double>(cycle_ - enabling_since_) * ipo_cycle_s_ > enable_timeout_s_ &&
               reaction_in_force_ == AlarmReaction::kNone) {
      raise(kAlarmDriveNotReady);  // the drive never became ready
    }
  }
  if (phase_ == PowerPhase::kEnabled && !enable_) {
    // MC_Power.Enable = FALSE aborts every job (spec 03 §6.6) and stops per StopMode.
    abort_motion(0);
    if (stop_.id != 0) {
      set_job(stop_.id, JobState::kAborted);
      stop_ = StopJob{};
    }
    phase_ = PowerPhase::kDisabling;
    const auto& l = db_.DynamicLimits;
    if (stop_mode_ == 0) {
      plan_velocity(0.0,
                    ProfileLimits{0.0, db_.DynamicDefaults.EmergencyDeceleration,
                                  db_.DynamicDefaults.EmergencyDeceleration, 0.0},
                    false);
    } else if (stop_mode_ == 2) {
      plan_velocity(0.0, ProfileLimits{0.0, l.MaxDeceleration, l.MaxDeceleration, l.MaxJerk}, false);
    } else {
      generator_active_ = false;
      setpoint_ = MotionState{};
    }
  }

  // Jog: the live velocity, override and release (spec 03 §3.4).
  if (motion_.kind == JobKind::kJog) {
    const double target = std::clamp(motion_.command_velocity * override_factor(), -motion_.limits.velocity,
                                     motion_.limits.velocity);
    if (std::fabs(target - motion_.planned_target) > 1e-12 || !generator_active_) {
      motion_.planned_target = target;
      plan_velocity(target, motion_.limits, false);
    }
  } else if (motion_.kind == JobKind::kMoveVelocity) {
    // Override changes act at once, with the job's dynamics (spec 01 §8.4).
    const double target = std::clamp(motion_.command_velocity * override_factor(), -motion_.limits.velocity,
                                     motion_.limits.velocity);
    if (std::fabs(target - motion_.planned_target) > 1e-12) {
      motion_.planned_target = target;
      plan_velocity(target, motion_.limits, false);
      set_job(motion_.id, JobState::kActive);
    }
  }

  generate_setpoint();
  update_status();
}

void SpeedAxis::generate_setpoint() noexcept {
  const bool follows_actual = phase_ == PowerPhase::kDisabled || phase_ == PowerPhase::kEnabling ||
                              reaction_in_force_ == AlarmReaction::kRemoveEnable ||
                              reaction_in_force_ == AlarmReaction::kFollowSetpoint ||
                              (phase_ == PowerPhase::kDisabling && (stop_mode_ == 1 || stop_mode_ == 3));
  if (follows_actual) {
    // Follow-up: the setpoint tracks the actual value (spec 02 §3.2).
    setpoint_ = MotionState{0.0, actual_velocity_, 0.0};
    generator_active_ = false;
  } else if (generator_active_) {
    profile_time_ += ipo_cycle_s_;
    setpoint_ = profile_.at(profile_time_);
    if (profile_time_ >= profile_.duration() - 1e-9) {     // cycle sums of 0.001 s drift by ulps
      setpoint_ = profile_.at(profile_.duration() + 1.0);  // exact end state
      generator_active_ = false;
    }
  }
  const bool settled = !generator_active_;
  const bool at_zero = std::fabs(setpoint_.velocity) < kStandstillEpsilon;

  // Job completion.
  if (motion_.id != 0) {
    if (motion_.kind == JobKind::kHalt && settled && at_zero) {
      set_job(motion_.id, JobState::kDone);
      motion_ = Motion{};
    } else if (motion_.kind == JobKind::kJog && motion_.jog_stopping && settled && at_zero) {
      set_job(motion_.id, JobState::kDone);  // J2: Busy ends at standstill
      motion_ = Motion{};
    } else if (auto* r = jobs_.find(motion_.id)) {
      r->status.in_velocity = settled && !motion_.jog_stopping;
    }
  }
  if (stop_.id != 0 && !stop_.done && settled && at_zero) {
    stop_.done = true;
    set_job(stop_.id, JobState::kDone);
    if (!stop_.execute) stop_ = StopJob{};
  }
  if (phase_ == PowerPhase::kDisabling) {
    const bool drive_off = virtual_axis() || !drive_.in_operation();
    if ((stop_mode_ == 0 || stop_mode_ == 2) && settled && at_zero) phase_ = PowerPhase::kDisabled;
    if (stop_mode_ == 1 && drive_off && std::fabs(actual_velocity_) < 1e-3) phase_ = PowerPhase::kDisabled;
    if (stop_mode_ == 3) phase_ = PowerPhase::kDisabled;
  }
}

void SpeedAxis::update_status() noexcept {
  const double unit = velocity_unit_per_revolution_per_second();
  db_.Velocity = setpoint_.velocity * unit;
  db_.Acceleration = setpoint_.acceleration;

  std::uint32_t sw = db_.StatusWord & (1u << static_cast<unsigned>(StatusWordBit::kOnlineStartValuesChanged));
  const bool enabled = phase_ == PowerPhase::kEnabled && reaction_in_force_ != AlarmReaction::kRemoveEnable;
  assign(sw, StatusWordBit::kEnable, enabled);
  assign(sw, StatusWordBit::kError, alarms_.any_error());
  assign(sw, StatusWordBit::kControlPanelActive, control_.held());
  assign(sw, StatusWordBit::kTorqueLimitingCommand, torque_.active);
  assign(sw, StatusWordBit::kInLimitation, in_limitation_);
  // SA: Done = motion finished and setpoint velocity 0 (spec 04 §8 rule 2).
  assign(sw, StatusWordBit::kDone, !generator_active_ && std::fabs(setpoint_.velocity) < kStandstillEpsilon);
  assign(sw, StatusWordBit::kJogCommand, motion_.kind == JobKind::kJog);
  assign(sw, StatusWordBit::kVelocityCommand, motion_.kind == JobKind::kMoveVelocity);
  assign(sw, StatusWordBit::kConstantVelocity,
         enabled && !generator_active_ && std::fabs(setpoint_.velocity) >= kStandstillEpsilon);
  assign(sw, StatusWordBit::kAccelerating, setpoint_.acceleration * setpoint_.velocity > 0.0);
  assign(sw, StatusWordBit::kDecelerating, setpoint_.acceleration * setpoint_.velocity < 0.0);
  assign(sw, StatusWordBit::kAxisSimulation, db_.Simulation.Mode == kModeOn);
  db_.StatusWord = sw;
  db_.StatusWord2 = 0;
  assign(db_.StatusWord2, StatusWord2Bit::kStopCommand, stop_.id != 0);

  std::uint32_t ew = 0;
  std::uint32_t ww = 0;
  for (const auto& a : alarms_.alarms()) {
    switch (a.number) {
      case kAlarmDriveFault:
      case kAlarmDriveNotReady:
      case kAlarmDriveSto:
      case kAlarmDriveSafeStop:
        assign(ew, ErrorWordBit::kDriveFault, true);
        break;
      case kAlarmDriveCommunication:
      case kAlarmDriveSignOfLife:
        assign(ew, ErrorWordBit::kCommunicationFault, true);
        break;
      case kAlarmDynamicsLimitedVelocity:
      case kAlarmDynamicsLimitedAcceleration:
      case kAlarmDynamicsLimitedJerk:
        assign(ww, WarningWordBit::kDynamicWarning, true);
        break;
      default:
        break;
    }
  }
  db_.ErrorWord = ew;
  db_.WarningWord = ww;
  const PendingAlarm* top = alarms_.error_detail();
  db_.ErrorDetail.Number = top == nullptr ? 0 : top->number;
  db_.ErrorDetail.Reaction = static_cast<std::int32_t>(top == nullptr ? AlarmReaction::kNone : top->reaction);
}

void SpeedAxis::restart() noexcept {
  // MC_Reset Restart = TRUE: re-initialise from the start values (spec 01 §7); RES and DIR values return to
  // them.
  const auto status_word3 = StatusWordBit::kOnlineStartValuesChanged;
  db_ = start_;
  communication_times_ = communication_times_start_;
  assign(db_.StatusWord, status_word3, false);
  db_.StatusDrive.AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_APPLICABLE);
  motion_ = Motion{};
  stop_ = StopJob{};
  generator_active_ = false;
  setpoint_ = MotionState{};
  torque_.stw2_fixed_stop = false;  // the restarted connection cleared the STW bits; set again if active
  drive_config_.reference_speed_rpm = start_.Actor.DriveParameter.ReferenceSpeed;
  drive_config_.reference_torque_nm = start_.Actor.DriveParameter.ReferenceTorque;
  if (device_ != nullptr) drive_.restart(drive_config_);  // the PROFIdrive link runs on
}

// ---------------------------------------------------------------------------------------------------------
// Data-block access from user code

WriteResult SpeedAxis::write(std::string_view path, double value) noexcept {
  WriteResult r;
  const VariableInfo* v = find_speed_axis_variable(path);
  if (v == nullptr) return r;
  r.found = true;
  r.access = check_write_access(*v, WriteContext::kUserProgram);
  if (r.access == AccessError::kNone) r.value = v->write(db_, value);
  return r;
}

WriteResult SpeedAxis::write_start_value(std::string_view path, double value) noexcept {
  WriteResult r;
  const VariableInfo* v = find_speed_axis_variable(path);
  if (v == nullptr) return r;
  r.found = true;
  r.access = check_write_access(*v, WriteContext::kStartValue);
  if (r.access != AccessError::kNone) return r;
  r.value = v->write(start_, value);
  // A changed restart-relevant start value waits for MC_Reset Restart (StatusWord.X3, spec 04 §0.2).
  if (r.value == ValueError::kNone && v->access == Access::kRES && v->read(start_) != v->read(db_)) {
    assign(db_.StatusWord, StatusWordBit::kOnlineStartValuesChanged, true);
  }
  return r;
}

double SpeedAxis::read(std::string_view path) const noexcept {
  if (const VariableInfo* v = find_speed_axis_variable(path)) return v->read(db_);
  if (const auto bit = find_speed_axis_bit(path)) return bit->read(db_) ? 1.0 : 0.0;
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace tomc::techobjects
