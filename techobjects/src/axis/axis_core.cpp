// The behaviour every axis TO shares (axis_core.hpp). Each rule names where the manual states it.
#include "tomc/techobjects/axis/axis_core.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

bool finite(double x) noexcept {
  return std::isfinite(x);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// MC_Power, MC_Reset

PowerState AxisCore::power(bool enable_in, std::int32_t start_mode_in, std::int32_t stop_mode_in) noexcept {
  PowerState s;
  if (const auto e = control.program_job_rejection()) {
    // The panel holds control priority: the program's MC_Power changes nothing (spec 02 §9.2, decision W2).
    s.Error = enable_in;
    s.ErrorID = enable_in ? e : 0;
  } else if (start_mode_in != 0 && start_mode_in != 1) {
    s.Error = true;
    s.ErrorID = error_id::kInvalidStartMode;
  } else if (stop_mode_in < 0 || stop_mode_in > 3) {
    s.Error = true;
    s.ErrorID = error_id::kInvalidStopMode;
  } else {
    if (enable_in && !enable) start_mode = start_mode_in;
    enable = enable_in;
    if (!enable_in) stop_mode = stop_mode_in;
  }
  s.Status = phase == PowerPhase::kEnabled && !enable_removed();
  s.Busy = enable || phase != PowerPhase::kDisabled;
  return s;
}

Submission AxisCore::reset(bool restart_in) noexcept {
  if (const auto e = control.program_job_rejection()) return Submission::reject(e);
  if (restart_in && (phase != PowerPhase::kDisabled || enable)) {
    return Submission::reject(error_id::kRestartNeedsDisabledAxis);
  }
  reset_pending_ = true;
  restart_requested_ = restart_in;
  reset_job_ = jobs.create(AxisJobKind::kReset, JobState::kActive);
  return Submission::accept(reset_job_);
}

std::optional<bool> AxisCore::begin_reset(std::uint64_t now) noexcept {
  if (!reset_pending_) return std::nullopt;
  reset_pending_ = false;
  (void)alarms.acknowledge(restart_requested_, now);
  acknowledged_at_ = now;
  return restart_requested_;
}

// ---------------------------------------------------------------------------------------------------------
// MC_Stop

JobId AxisCore::start_stop(int weight, const ProfileLimits& limits) noexcept {
  if (stop.id != 0) jobs.set(stop.id, JobState::kAborted);
  stop = StopJob{jobs.create(AxisJobKind::kStop, JobState::kActive), weight, limits, true, false};
  return stop.id;
}

void AxisCore::stop_execute(JobId job, bool execute) noexcept {
  if (job != 0 && job == stop.id) {
    stop.execute = execute;
    if (!execute && stop.done) stop = StopJob{};  // Done and released: no longer a running MC_Stop
  }
}

void AxisCore::abort_stop() noexcept {
  if (stop.id == 0) return;
  jobs.set(stop.id, JobState::kAborted);  // MC_Stop reports CommandAborted, not Error (seed §6.9.4)
  stop = StopJob{};
}

void AxisCore::stop_reached_standstill() noexcept {
  if (stop.id == 0 || stop.done) return;
  stop.done = true;
  jobs.set(stop.id, JobState::kDone);
  if (!stop.execute) stop = StopJob{};
}

// ---------------------------------------------------------------------------------------------------------
// Prerequisites and dynamics

std::uint16_t AxisCore::motion_prerequisites() const noexcept {
  if (phase != PowerPhase::kEnabled) return error_id::kAxisNotEnabled;
  if (blocked()) return error_id::kAxisBlockedByAlarm;
  if (stop_locks()) return error_id::kLockedByStop;
  return 0;
}

std::optional<std::uint16_t> AxisCore::resolve_dynamics(double velocity, double acceleration,
                                                        double deceleration, double jerk,
                                                        const TO_Struct_DynamicDefaults& d,
                                                        const TO_Struct_DynamicLimits& l, DynamicUnits u,
                                                        ProfileLimits& out) noexcept {
  const bool has_velocity = !std::isnan(velocity);
  if (has_velocity && (!finite(velocity) || velocity == 0.0)) return error_id::kInvalidVelocity;
  if (!finite(acceleration) || acceleration == 0.0) return error_id::kInvalidAcceleration;
  if (!finite(deceleration) || deceleration == 0.0) return error_id::kInvalidDeceleration;
  if (!finite(jerk)) return error_id::kInvalidJerk;
  double a = acceleration < 0.0 ? d.Acceleration : acceleration;
  double dec = deceleration < 0.0 ? d.Deceleration : deceleration;
  double j = jerk < 0.0 ? d.Jerk : jerk;
  double v = has_velocity ? (velocity < 0.0 ? d.Velocity : velocity) : 0.0;
  const double v_limit = std::min(l.MaxVelocity, l.Velocity);  // spec 01 §8.3
  if (has_velocity && v > v_limit) {
    v = v_limit;
    raise(kAlarmDynamicsLimitedVelocity);
  }
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
  out.velocity = (has_velocity ? v : v_limit) / u.velocity;
  out.acceleration = a / u.acceleration;
  out.deceleration = dec / u.acceleration;
  out.jerk = j / u.acceleration;
  return std::nullopt;
}

std::optional<Submission> AxisCore::stop_request(const StopInputs& in, const TO_Struct_DynamicDefaults& d,
                                                 const TO_Struct_DynamicLimits& l, DynamicUnits u,
                                                 std::span<const RunningJob> running, int& weight,
                                                 ProfileLimits& limits) noexcept {
  if (const auto e = control.program_job_rejection()) return Submission::reject(e);
  weight = stop_weight_of_mc_stop_mode(in.Mode);
  if (weight == 0) return Submission::reject(error_id::kInvalidMode);  // Mode 1 and anything else
  const double inf = std::numeric_limits<double>::infinity();
  if (in.Mode == 0) {
    limits = emergency_ramp(d, u);
    limits.velocity = inf;
  } else if (in.Mode == 2) {
    limits = max_dynamics_ramp(l, u);
    limits.velocity = inf;
  } else if (const auto e = resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), in.Deceleration,
                                             in.Deceleration, in.Jerk, d, l, u, limits)) {
    return Submission::reject(*e);
  }
  if (phase != PowerPhase::kEnabled) return Submission::reject(error_id::kAxisNotEnabled);
  if (stop_outweighed(weight)) {
    return Submission::accept(jobs.create(AxisJobKind::kStop, JobState::kAborted));
  }
  ArbitrationContext ctx;
  ctx.new_stop_weight = weight;
  ctx.running_stop_weight = stop.weight;
  if (arbitrate(NewJob::kStop, running, ctx).reject)
    return Submission::reject(error_id::kRejectedByRunningJob);
  return std::nullopt;
}

ProfileLimits AxisCore::emergency_ramp(const TO_Struct_DynamicDefaults& d, DynamicUnits u) noexcept {
  const double e = d.EmergencyDeceleration / u.acceleration;
  return ProfileLimits{0.0, e, e, 0.0};  // no jerk limit (spec 02 §3.7)
}

ProfileLimits AxisCore::max_dynamics_ramp(const TO_Struct_DynamicLimits& l, DynamicUnits u) noexcept {
  const double a = u.acceleration;
  return ProfileLimits{0.0, l.MaxDeceleration / a, l.MaxDeceleration / a, l.MaxJerk / a};
}

ProfileLimits AxisCore::default_ramp(const TO_Struct_DynamicDefaults& d, DynamicUnits u) noexcept {
  const double a = u.acceleration;
  return ProfileLimits{0.0, d.Deceleration / a, d.Deceleration / a, d.Jerk / a};
}

// ---------------------------------------------------------------------------------------------------------
// Alarm reactions (spec 02 §1, seed §6.9.4)

ReactionChange AxisCore::take_reaction() noexcept {
  const AlarmReaction r = alarms.strongest_reaction();
  if (r == reaction_in_force) return ReactionChange::kNone;
  const bool escalation = reaction_rank(r) > reaction_rank(reaction_in_force);
  const AlarmReaction before = reaction_in_force;
  reaction_in_force = r;
  if (escalation) return ReactionChange::kEscalated;
  // Acknowledged: no longer blocked. After "remove enable" an MC_Power whose Enable stayed TRUE enables the
  // axis again (spec 03 §3.3 L2).
  if (r == AlarmReaction::kNone &&
      (before == AlarmReaction::kRemoveEnable || before == AlarmReaction::kFollowSetpoint) &&
      phase == PowerPhase::kEnabled) {
    phase = enable ? PowerPhase::kEnabling : PowerPhase::kDisabled;
    enabling_since_ = cycle;
  }
  return ReactionChange::kReleased;
}

bool AxisCore::stop_keeps_control(bool stop_may_keep) noexcept {
  const int alarm_weight = stop_weight_of_reaction(static_cast<int>(reaction_in_force));
  const bool keeps = stop.id != 0 && stop.weight >= alarm_weight &&
                     reaction_in_force != AlarmReaction::kFollowSetpoint && stop_may_keep;
  if (!keeps) abort_stop();
  return keeps;
}

std::optional<ProfileLimits> AxisCore::reaction_ramp(const ProfileLimits& current,
                                                     const TO_Struct_DynamicDefaults& d,
                                                     const TO_Struct_DynamicLimits& l,
                                                     DynamicUnits u) const noexcept {
  switch (reaction_in_force) {
    case AlarmReaction::kStopCurrentDynamics:
      return current;
    case AlarmReaction::kStopMaxDynamics:
      return max_dynamics_ramp(l, u);
    case AlarmReaction::kStopEmergencyRamp:
      return emergency_ramp(d, u);
    case AlarmReaction::kRemoveEnable:
    case AlarmReaction::kFollowSetpoint:
    case AlarmReaction::kNone:
      break;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------------------
// The drive

void AxisCore::supervise_drive(const DriveConnection& drive) noexcept {
  const auto fault = drive.communication_fault();
  // The hold-off covers a cause still present at the acknowledge; once the connection is healthy it ends, so
  // that a new link or sign-of-life failure is raised in the cycle it is detected (issue 22).
  if (fault == CommunicationFault::kNone) acknowledged_at_ = 0;
  const bool held_off = this->held_off();
  // Drive fault: raised when it appears; raised again if it is still there after an acknowledge's hold-off.
  const bool drive_fault = fault == CommunicationFault::kDriveFault;
  if (drive_fault && (!drive_fault_seen_ || !held_off)) raise(kAlarmDriveFault);
  drive_fault_seen_ = drive_fault;
  if (held_off) return;
  if (fault == CommunicationFault::kLinkLost && drive.cycles_without_fresh_frame() > 0)
    raise(kAlarmDriveCommunication);
  if (fault == CommunicationFault::kSignOfLifeFailed) raise(kAlarmDriveSignOfLife);
  if (safe_stop(drive)) return;  // 421/550 name the cause; 402 would only repeat it
  // The drive left operation on its own while the TO is enabled.
  if (phase == PowerPhase::kEnabled && reaction_in_force == AlarmReaction::kNone &&
      fault == CommunicationFault::kNone && !drive.in_operation()) {
    raise(kAlarmDriveNotReady);
  }
}

bool AxisCore::safe_stop(const DriveConnection& drive) noexcept {
  constexpr std::uint8_t kSafeTorqueOff = 1;
  constexpr std::uint8_t kSafeStopRamp = 2;
  // Only a drive that was told to operate stops autonomously: OFF2/OFF3 active in ZSW1 while the STW1 of the
  // last cycles asked for none of them (the drive-side Safety Integrated reaction, spec 01 §4 table). A drive
  // fault shows both bits as well (spec 06 TV24): that is alarm 401.
  const bool operating = phase == PowerPhase::kEnabled && drive.requested() == tg::DriveRequest::kOperate &&
                         drive.communication_fault() == CommunicationFault::kNone;
  const auto& status = drive.drive_status();
  std::uint8_t now = 0;
  if (operating && status.coast_stop_active) now |= kSafeTorqueOff;
  if (operating && status.quick_stop_active) now |= kSafeStopRamp;
  const std::uint8_t appeared = static_cast<std::uint8_t>(now & ~safe_stop_seen_);
  safe_stop_seen_ = now;
  if (appeared & kSafeTorqueOff) raise(kAlarmDriveSto);      // reaction remove enable
  if (appeared & kSafeStopRamp) raise(kAlarmDriveSafeStop);  // reaction follow setpoint
  return now != 0;
}

tg::DriveRequest AxisCore::drive_request(std::int32_t remove_enable_reaction) const noexcept {
  if (enable_removed()) {
    switch (remove_enable_reaction) {  // Actor.RemoveEnableReaction, spec 02 §3.4
      case 0x1:
        return tg::DriveRequest::kOff;
      case 0x3:
        return tg::DriveRequest::kCoastStop;
      default:
        return tg::DriveRequest::kQuickStop;
    }
  }
  switch (phase) {
    case PowerPhase::kEnabling:
    case PowerPhase::kEnabled:
      return tg::DriveRequest::kOperate;
    case PowerPhase::kDisabling:  // StopMode 0/2: the TO ramps, the drive follows (spec 02 §3.1)
      return stop_mode == 1   ? tg::DriveRequest::kQuickStop
             : stop_mode == 3 ? tg::DriveRequest::kCoastStop
                              : tg::DriveRequest::kOperate;
    case PowerPhase::kDisabled:
      break;
  }
  return stop_mode == 3 ? tg::DriveRequest::kCoastStop : tg::DriveRequest::kOff;
}

// ---------------------------------------------------------------------------------------------------------
// The power phase (spec 01 §6, spec 02 §3.1)

PowerEvent AxisCore::change_power_phase(bool ready) noexcept {
  if (phase == PowerPhase::kDisabled && enable && !enable_removed()) {
    phase = PowerPhase::kEnabling;
    enabling_since_ = cycle;
  }
  if (phase == PowerPhase::kEnabling) {
    if (!enable) {
      phase = PowerPhase::kDisabled;
    } else if (ready) {
      phase = PowerPhase::kEnabled;
      return PowerEvent::kEnabled;
    } else if (static_cast<double>(cycle - enabling_since_) * ipo_cycle_s > enable_timeout_s &&
               reaction_in_force == AlarmReaction::kNone) {
      raise(kAlarmDriveNotReady);  // the drive never became ready
    }
  }
  if (phase == PowerPhase::kEnabled && !enable) {
    // MC_Power.Enable = FALSE aborts every job (spec 03 §6.6) and stops per StopMode.
    abort_stop();
    phase = PowerPhase::kDisabling;
    return PowerEvent::kDisabling;
  }
  return PowerEvent::kNone;
}

std::optional<ProfileLimits> AxisCore::disable_ramp(const TO_Struct_DynamicDefaults& d,
                                                    const TO_Struct_DynamicLimits& l,
                                                    DynamicUnits u) const noexcept {
  if (stop_mode == 0) return emergency_ramp(d, u);
  if (stop_mode == 2) return max_dynamics_ramp(l, u);
  return std::nullopt;
}

void AxisCore::finish_disabling(bool settled, bool drive_stopped) noexcept {
  if (phase != PowerPhase::kDisabling) return;
  if ((stop_mode == 0 || stop_mode == 2) && settled) phase = PowerPhase::kDisabled;
  if (stop_mode == 1 && drive_stopped) phase = PowerPhase::kDisabled;
  if (stop_mode == 3) phase = PowerPhase::kDisabled;
}

// ---------------------------------------------------------------------------------------------------------
// MC_WriteParameter 1010–1012, MC_SetAxisSTW

Submission AxisCore::write_communication_time(std::int32_t number, double value,
                                              std::uint32_t& status_word) noexcept {
  if (number < 1010 || number > 1012) return Submission::reject(error_id::kInvalidParameterNumber);
  if (!finite(value) || value < 0.0) return Submission::reject(error_id::kInvalidParameterValue);
  double& target = number == 1010   ? communication_times_start.Ti
                   : number == 1011 ? communication_times_start.To
                                    : communication_times_start.Tdc;
  target = value;
  assign(status_word, StatusWordBit::kOnlineStartValuesChanged, true);  // effective after restart
  return Submission::accept(jobs.create(AxisJobKind::kWriteParameter, JobState::kDone));
}

Submission AxisCore::set_axis_stw(DriveConnection* drive, std::uint16_t stw1, std::uint16_t stw1_mask,
                                  std::uint16_t stw2, std::uint16_t stw2_mask) noexcept {
  if (const auto e = control.program_job_rejection()) return Submission::reject(e);
  constexpr std::uint16_t kUserStw1 = 0xFB00;  // bits 8, 9, 11..15 (the TO owns 0..7 and 10)
  constexpr std::uint16_t kUserStw2 = 0x0FFF;  // bits 0..11 (12..15: master sign-of-life)
  if ((stw1_mask & ~kUserStw1) != 0 || (stw2_mask & ~kUserStw2) != 0)
    return Submission::reject(error_id::kInvalidBitMask);
  if (drive == nullptr || drive->device_config().drive_telegram == 0)
    return Submission::reject(error_id::kNoDriveTelegram);
  drive->set_user_control_bits(stw1, stw1_mask, stw2, stw2_mask);
  // In effect from the next servo cycle.
  return Submission::accept(jobs.create(AxisJobKind::kSetAxisStw, JobState::kDone));
}

// ---------------------------------------------------------------------------------------------------------
// Restart and status

void AxisCore::restart() noexcept {
  communication_times = communication_times_start;
  stop = StopJob{};
  torque.stw2_fixed_stop = false;  // the restarted connection cleared the STW bits; set again if active
}

void AxisCore::alarm_status(std::uint32_t& error_word, std::uint32_t& warning_word,
                            TO_Struct_ErrorDetail& detail) const noexcept {
  alarm_words(alarms.alarms(), error_word, warning_word);
  const PendingAlarm* top = alarms.error_detail();
  detail.Number = top == nullptr ? 0 : top->number;
  detail.Reaction = static_cast<std::int32_t>(top == nullptr ? AlarmReaction::kNone : top->reaction);
}

}  // namespace tomc::techobjects
