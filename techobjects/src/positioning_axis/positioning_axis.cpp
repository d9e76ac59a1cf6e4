// TO_PositioningAxis: configuration, the job API called by the instructions, alarms and data-block access.
// The cycle (MC_Servo, MC_Interpolator) is in positioning_axis_cycle.cpp.
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/axis/jog.hpp"
#include "tomc/techobjects/axis/setup_checks.hpp"
#include "tomc/techobjects/datablocks/data_block_access.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/telegrams/codec.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

// PositionControl.Pid.* (tomc extension, issue 20) into the controller's configuration; velocities from the
// velocity unit to the controller's units per second.
void pid_config(const PositioningAxisData& db, double velocity_factor, PositionControlConfig& pc) {
  const auto& pid = db.PositionControl.Pid;
  pc.IntegralTime = pid.IntegralTime;
  pc.DerivativeTime = pid.DerivativeTime;
  pc.DerivativeCycles = pid.DerivativeCycles;
  pc.IntegralLimit = pid.IntegralLimit / velocity_factor;
  pc.DeadBand = pid.DeadBand;
  pc.OutputLimit = pid.OutputLimit / velocity_factor;
}

// PositionControl.ControlDifferenceQuantization (spec 01 §3.11): Mode 1 = one increment of the operative
// encoder (re-adapted whenever the encoder is configured), Mode 2 = Value; both in the position unit.
double control_difference_quantization(const PositioningAxisData& db, double units_per_count) {
  const auto& q = db.PositionControl.ControlDifferenceQuantization;
  switch (static_cast<QuantizationMode>(q.Mode)) {
    case QuantizationMode::kEncoderResolution:
      return units_per_count;
    case QuantizationMode::kDirectValue:
      return q.Value;
    case QuantizationMode::kNone:
      break;
  }
  return 0.0;
}

bool finite(double x) {
  return std::isfinite(x);
}

bool carries(std::uint16_t telegram, tg::Signal signal, tg::Direction direction = tg::Direction::kActual) {
  if (telegram == 0) return false;
  const auto codec = tg::TelegramCodec::create(telegram, direction);
  return static_cast<bool>(codec) && codec->carries(signal);
}

}  // namespace

PositioningAxis::PositioningAxis(std::string name, DeviceIo* device, const PositioningAxisData& start_values,
                                 const DriveConnectionConfig& drive)
    : AxisObject(std::move(name), device, start_values),
      encoder_(AxisMechanics{}, EncoderMechanics{}, 0.001, EncoderSource::kDriveG1) {
  const auto fail = [&](std::string_view path, std::string_view message) {
    fail_start_value(name_, path, message);
  };
  check_start_values(name_, positioning_axis_variables(), *start_);
  units_ = checked_unit_factors(name_, start_->Units.LengthUnit, start_->Units.VelocityUnit,
                                start_->Properties.MotionType, "axis");
  const std::uint32_t op = start_->PositionControl.InitialOperativeSensor;
  if (op < 1 || op > 4 || !start_->Sensor[op - 1].Existent) {
    fail("PositionControl.InitialOperativeSensor", "names an encoder whose Sensor[n].Existent is FALSE");
  }
  db_.OperativeSensor = op;
  // VirtualAxis.Mode changes only with a new download (RON, seed 004 §6.1.5): a virtual axis never has a
  // drive. Simulation.Mode is RES (§6.1.7): the device stays for the axis' life, a restart that ends the
  // simulation uses it (decision B8); drive_used() decides, the control loop follows it.
  if (start_->VirtualAxis.Mode == kModeOn) device_ = nullptr;
  choose_control_loop();
  // "To use a technology object in simulation, encoder 1 must be used for position control" (seed 004
  // §6.1.7, decisions B7, B8; at a restart: alarm 102).
  if (simulated() && op != 1) {
    fail("PositionControl.InitialOperativeSensor",
         "a simulated axis closes the position loop on encoder 1 (seed 004 §6.1.7)");
  }
  // Every other existing encoder gets its storage now (decision B1), also on a virtual or simulated axis,
  // which simulates every encoder configured as used (seed 004 §6.2.4.5, B7).
  std::size_t count = 0;
  for (std::uint32_t n = 1; n <= 4; ++n)
    count += n != op && start_->Sensor[n - 1].Existent ? 1 : 0;
  additional_.reserve(count);
  {
    std::size_t i = 0;
    for (std::uint32_t n = 1; n <= 4; ++n)
      if (n != op && start_->Sensor[n - 1].Existent)
        additional_.all()[i++].number = static_cast<std::uint8_t>(n);
  }
  if (device_ != nullptr) {
    // Which telegram carries the operative encoder (decision P3).
    const auto& cfg = device_->adapter->config();
    const auto source = find_encoder_source(cfg, start_->Sensor[op - 1].Interface.Number);
    if (!source) {
      fail("Sensor[" + std::to_string(op) + "].Interface.Number",
           "the device's telegrams carry no such encoder (drive telegram " +
               std::to_string(cfg.drive_telegram) + ", encoder telegram " +
               std::to_string(cfg.encoder_telegrams[0]) + ")");
    }
    encoder_ = EncoderChannel(AxisMechanics{}, EncoderMechanics{}, 0.001, *source);
    drive_ = DriveConnection(*device_, with_reference_values(drive, start_->Actor));
    // Each other encoder's own telegram part.
    std::array<EncoderSource, 4> taken{*source};
    std::size_t i = 0;
    for (AdditionalEncoder& e : additional_.all()) {
      const auto s = find_encoder_source(cfg, start_->Sensor[e.number - 1].Interface.Number,
                                         std::span<const EncoderSource>(taken.data(), i + 1));
      if (!s) {
        fail(
            "Sensor[" + std::to_string(e.number) + "].Interface.Number",
            "the device's telegrams carry no further encoder (the other encoders of the axis read them all)");
      }
      taken[++i] = *s;
      e.channel = EncoderChannel(AxisMechanics{}, EncoderMechanics{}, 0.001, *s);
    }
  }
  configure_components();
  if (const auto& p = encoder_.chain().config_problem()) fail(p->path, p->message);
  for (const AdditionalEncoder& e : additional_.all()) {
    if (const auto& p = e.channel.chain().config_problem()) {
      const bool encoder_path = p->path.starts_with("Sensor.");
      fail(encoder_path ? "Sensor[" + std::to_string(e.number) + "]" + std::string(p->path.substr(6))
                        : std::string(p->path),
           p->message);
    }
  }
  // Backlash compensation exists for motor-shaft encoders only (spec 01 §5.2, §5.9, spec 04 §3.6).
  if (start_->Sensor[op - 1].Backlash.Enable &&
      start_->Sensor[op - 1].MountingMode != static_cast<std::int32_t>(EncoderMounting::kMotorShaft)) {
    fail("Sensor[" + std::to_string(op) + "].Backlash.Enable",
         "backlash compensation needs the encoder on the motor shaft (MountingMode 0)");
  }
  // DSC: the drive closes the position loop on XERR/KPC of the setpoint telegram, computed on the motor
  // encoder (seed 004 §6.13.1, spec 06 §2 "DSC needs 5, 6, 105 or 106 and the motor encoder as the TO's first
  // encoder"). Without XERR/KPC the axis would send speed precontrol only and never close the loop.
  if (start_->PositionControl.EnableDSC && device_ != nullptr) {
    const std::uint16_t telegram = device_->adapter->config().drive_telegram;
    if (!carries(telegram, tg::Signal::XERR, tg::Direction::kSetpoint) ||
        !carries(telegram, tg::Signal::KPC, tg::Direction::kSetpoint)) {
      fail("PositionControl.EnableDSC",
           "DSC needs XERR and KPC in the setpoint telegram: drive telegram 5, 6, "
           "105 or 106, not " +
               std::to_string(telegram) + " (seed 004 §6.13.1)");
    }
    if (encoder_.source() != EncoderSource::kDriveG1) {
      fail("PositionControl.EnableDSC",
           "DSC needs the drive's motor encoder (G1 of the drive telegram) as the operative encoder: set "
           "Sensor[" +
               std::to_string(op) + "].Interface.Number to 1 (seed 004 §6.13.1)");
    }
  }
  if (device_ != nullptr) {
    const std::uint16_t telegram = device_->adapter->config().drive_telegram;
    drive_has_momred_ = carries(telegram, tg::Signal::MOMRED, tg::Direction::kSetpoint);
    drive_has_meldw_ = carries(telegram, tg::Signal::MELDW);
  }
  db_.StatusDrive.AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_APPLICABLE);
  position_controlled_ = true;
}

// Everything derived from the data block and the cycle time. Runs at construction, on the first servo
// cycle (when the cycle time is known) and after a restart; no allocation.
void PositioningAxis::configure_components() noexcept {
  // The axis mechanics only feed the encoders' chains, which keep what they need (decision M5).
  AxisMechanics mechanics;
  mechanics.MotionType = static_cast<AxisMotionType>(db_.Properties.MotionType);
  mechanics.LoadGear = GearRatio{db_.LoadGear.Numerator, db_.LoadGear.Denominator};
  mechanics.Mechanics.LeadScrew = db_.Mechanics.LeadScrew * units_.leadscrew;
  mechanics.Actor.InverseDirection = db_.Actor.InverseDirection;
  mechanics.Actor.DriveParameter.ReferenceSpeed = db_.Actor.DriveParameter.ReferenceSpeed;
  mechanics.Modulo = ModuloConfig{db_.Modulo.Enable, db_.Modulo.StartValue, db_.Modulo.Length};
  mechanics.RotaryUnitsPerRevolution = units_.units_per_revolution;
  configure_encoders(mechanics);

  if (auto* controller = this->controller()) {
    (void)controller->configure(
        position_control_config(control_difference_quantization(db_, encoder_.chain().units_per_count())));
  }
  configure_monitoring();
  configure_extrapolation();
  software_limits_.configure(limits::software_limit_config(db_.PositionLimits_SW, db_.Modulo));
  hardware_limits_.configure(limits::hardware_limit_config(db_.PositionLimits_HW));
  configure_backlash_and_filter();
}

// A drive in use closes the position loop (PositionController); a virtual or simulated axis has only the
// simulated control loop's delay (spec 01 §2.5, §2.6) in the same storage. At construction and at every
// restart (decision B8); the variant's storage is the object's own: no allocation.
void PositioningAxis::choose_control_loop() noexcept {
  drive_used_ = AxisObject::drive_used();
  if (drive_used()) {
    if (controller() == nullptr) control_loop_.emplace<PositionController>();
  } else if (simulation_delay() == nullptr) {
    control_loop_.emplace<BasicSetpointDelayLine<kSimulationDelayCycles>>();
  }
}

// The position controller's configuration from the data block, the communication times in force and the
// cycle time; the controller keeps only what its cycle reads (decision M5).
PositionControlConfig PositioningAxis::position_control_config(double quantization) const noexcept {
  PositionControlConfig pc;
  pc.Kv = db_.PositionControl.Kv;
  pc.Kpc = db_.PositionControl.Kpc;
  pc.VelocityTimeConstant = db_.DynamicAxisModel.VelocityTimeConstant;
  pc.EnableDSC = db_.PositionControl.EnableDSC;
  pc.AdditionalSetpointDelayTime = db_.FollowingError.AdditionalSetpointDelayTime;
  pc.ServoCycle = servo_cycle_s_;
  pc.Ti = core_.communication_times.Ti;
  pc.To = core_.communication_times.To;
  pc.Tdc = core_.communication_times.Tdc;
  pid_config(db_, units_.velocity, pc);
  pc.ControlDifferenceQuantization = quantization;
  return pc;
}

// Backlash compensation (spec 01 §5.9) and dynamic filter (spec 02 §7.6): DIR variables, re-read after a
// user-program write; both keep their state unless Backlash.Enable/Size change (which needs re-homing).
void PositioningAxis::configure_backlash_and_filter() noexcept {
  const auto& s = db_.Sensor[db_.PositionControl.InitialOperativeSensor - 1];
  const bool motor_shaft = s.MountingMode == static_cast<std::int32_t>(EncoderMounting::kMotorShaft);
  (void)backlash_.configure(BacklashConfig{s.Backlash.Enable && motor_shaft && drive_used(), s.Backlash.Size,
                                           s.Backlash.Velocity / units_.velocity, servo_cycle_s_});
  const auto& f = db_.SetpointFilter.DynamicFilter;
  (void)dynamic_filter_.configure(DynamicFilterConfig{f.Mode, f.T1, f.T2, f.Tt, servo_cycle_s_});
}

// Extrapolation of the actual value as a leading value (spec 07 §1.4, extrapolation_config).
void PositioningAxis::configure_extrapolation() noexcept {
  extrapolation_.configure(extrapolation_config(db_.Extrapolation, core_.communication_times.Ti,
                                                core_.ipo_cycle_s, units_.velocity));
}

// The monitors' DIR variables (positions in position units, velocities converted from the data block's
// velocity unit). Re-read after a user-program write; the monitors keep their state.
void PositioningAxis::configure_monitoring() noexcept {
  const auto& fe = db_.FollowingError;
  following_error_.configure(FollowingErrorMonitoringConfig{fe.EnableMonitoring, fe.MinValue, fe.MaxValue,
                                                            fe.MinVelocity / units_.velocity, fe.WarningLevel,
                                                            db_.DynamicLimits.MaxVelocity / units_.velocity});
  const auto& pm = db_.PositioningMonitoring;
  (void)positioning_.configure(
      PositioningMonitoringConfig{pm.Window, pm.ToleranceTime, pm.MinDwellTime, servo_cycle_s_});
  (void)standstill_.configure(StandstillSignalConfig{db_.StandstillSignal.VelocityThreshold / units_.velocity,
                                                     db_.StandstillSignal.MinDwellTime, servo_cycle_s_});
}

// ---------------------------------------------------------------------------------------------------------
// Helpers

// spec 01 §8.5: v_eff = min(v_cmd · Override, v_limit) — the override applies before the limit clamp.
bool PositioningAxis::homed() const noexcept {
  return homed_;
}

// spec 03 §2.1, spec 04 §8 rule 1: < 0 -> DynamicDefaults, = 0 invalid (jerk: trapezoid), > 0 as given;
// limited to DynamicLimits with warnings 501/502/503. Velocity < 0 -> DynamicDefaults.Velocity; pass NaN to
// leave the velocity to the caller (MoveVelocity, Jog). MaxJerk caps a job without jerk (decision S3).
std::optional<std::uint16_t> PositioningAxis::resolve_dynamics(double velocity, double acceleration,
                                                               double deceleration, double jerk,
                                                               ProfileLimits& out) noexcept {
  auto error = core_.resolve_dynamics(velocity, acceleration, deceleration, jerk, db_.DynamicDefaults,
                                      db_.DynamicLimits, dynamic_units(), out);
  // A modulo axis that leads a synchronous axis moves at most half a modulo length per servo cycle (spec 01
  // §8.6): the velocity is limited, with warning 501 when the job asked for more (MoveVelocity and Jog, which
  // pass NaN, compare their own velocity with out.velocity).
  const double leader_limit = modulo_leader_velocity_limit();
  if (!error && out.velocity > leader_limit) {
    if (!std::isnan(velocity)) raise(kAlarmDynamicsLimitedVelocity);
    out.velocity = leader_limit;
  }
  return error;
}

std::array<RunningJob, 5> PositioningAxis::running_jobs(std::size_t& n) const noexcept {
  std::array<RunningJob, 5> running{};
  n = 0;
  // A running synchronous job is a column of §9.19.2, not of §9.19.1 (arbitrate_synchronous).
  if (motion_.id != 0 && !synchronous_kind(motion_.kind)) {
    // MC_Halt Mode 1 is a C3 job, Mode 0 the C5 one (spec 03 §6.1).
    const bool halt_all = motion_.kind == JobKind::kHalt && !motion_.halt_base_only;
    running[n++] = halt_all                         ? RunningJob::kHaltAll
                   : motion_.kind == JobKind::kHome ? RunningJob::kActiveHoming
                   : motion_.kind == JobKind::kMotionInVelocity || motion_.kind == JobKind::kMotionInPosition
                       ? RunningJob::kMotionIn
                       : RunningJob::kBaseMotionActive;
  }
  if (pending_.id != 0) running[n++] = RunningJob::kBaseMotionPending;
  if (passive_.id != 0) running[n++] = RunningJob::kPassiveHoming;
  if (core_.stop.id != 0 && (!core_.stop.done || core_.stop.execute)) running[n++] = RunningJob::kStop;
  if (superimposed_.job() != SuperimposedMotion::Job::kNone) running[n++] = RunningJob::kSuperimposed;  // C7
  return running;
}

// The §9.19.1 row of a new motion job against every running job (spec 03 §6.7): aborts applied on accept.
std::uint16_t PositioningAxis::arbitrate_motion(NewJob row, bool& queue) noexcept {
  std::size_t n = 0;
  const auto running = running_jobs(n);
  ArbitrationContext ctx;
  // C3 "-/N": positioning and MC_Halt end by themselves, MoveVelocity/Jog do not (spec 03 §6.1 [AMB-11]).
  ctx.running_job_ends_by_itself = motion_.kind == JobKind::kMoveAbsolute ||
                                   motion_.kind == JobKind::kMoveRelative || motion_.kind == JobKind::kHalt ||
                                   motion_.kind == JobKind::kPositionProfile;
  ctx.virtual_or_simulated_axis = virtual_axis();
  ctx.running_stop_weight = core_.stop.weight;
  const Decision d = arbitrate(row, std::span<const RunningJob>(running.data(), n), ctx);
  if (d.reject) return error_id::kRejectedByRunningJob;
  if (const std::uint16_t e = arbitrate_synchronous(row)) return e;  // §9.19.2 on a synchronous axis
  queue = d.queue;
  for (std::size_t i = 0; i < n; ++i) {
    if ((d.abort_mask & (1u << i)) == 0) continue;
    switch (running[i]) {
      case RunningJob::kStop:
        core_.abort_stop();
        break;
      case RunningJob::kBaseMotionPending:
        abort_pending(0);
        break;
      case RunningJob::kPassiveHoming:
        end_passive_homing(JobState::kAborted);
        break;
      case RunningJob::kSuperimposed:  // a new superimposed job continues from its state (R6 x C7)
        abort_superimposed(0, row != NewJob::kSuperimposed);
        break;
      default:
        abort_motion(0);
        break;
    }
  }
  return 0;
}

void PositioningAxis::abort_motion(std::uint16_t error_id) noexcept {
  if (motion_.id == 0) return;
  if (synchronous_kind(motion_.kind)) {
    abort_synchronous(error_id);  // the synchronous axis ends its job and its state
    return;
  }
  if (motion_.kind == JobKind::kHome) {
    homing_.phase = HomingPhase::kIdle;
    encoder_.cancel_reference_mark();
  }
  core_.jobs.set(motion_.id, error_id == 0 ? JobState::kAborted : JobState::kError, error_id);
  motion_ = Motion{};
  positioning_.cancel();
  positioning_start_pending_ = false;
}

void PositioningAxis::abort_pending(std::uint16_t error_id) noexcept {
  if (pending_.id == 0) return;
  core_.jobs.set(pending_.id, error_id == 0 ? JobState::kAborted : JobState::kError, error_id);
  pending_ = Motion{};
}

// The continuous target of MC_MoveAbsolute (spec 03 §4.5): on a linear axis the position itself; on a modulo
// axis the position within the range, reached in the direction asked for from `from` (spec 01 §2.4).
std::optional<double> PositioningAxis::absolute_target(double position, std::int32_t direction,
                                                       double from) const noexcept {
  if (!modulo()) return position;
  const double start = db_.Modulo.StartValue;
  const double length = db_.Modulo.Length;
  if (position < start || position >= start + length) return std::nullopt;  // decision P5
  const ModuloPosition here = modulo_wrap(from, start, length);
  double d = position - here.position;  // in (-length, length)
  switch (direction) {
    case 1:  // positive: 0 <= d < length
      if (d < 0.0) d += length;
      break;
    case 2:  // negative: -length < d <= 0
      if (d > 0.0) d -= length;
      break;
    default:  // 3: shortest path (tie: decision of modulo_shortest_distance)
      d = modulo_shortest_distance(here.position, position, start, length);
      break;
  }
  return from + d;
}

// Makes `motion` the running positioning job and plans its profile from the present setpoint.
void PositioningAxis::start_positioning(Motion motion) noexcept {
  // Positions of base jobs are those of the base motion: a superimposed distance adds to them (spec 01
  // §8.14, decision U3).
  const double base_position = base_setpoint().position;
  if (motion.relative_to_end) motion.target = base_position + motion.distance;
  if (motion.kind == JobKind::kMoveAbsolute && modulo()) {
    if (const auto t = absolute_target(motion.absolute_position, motion.direction, base_position)) {
      motion.target = *t;
    }
  }
  motion.interpolation_done = false;
  motion_ = motion;
  position_controlled_ = true;  // MoveAbsolute/MoveRelative force position control (spec 02 §7.7)
  core_.jobs.set(motion_.id, JobState::kActive);
  positioning_.cancel();
  positioning_start_pending_ = false;
  plan_positioning(positioning_velocity(motion_));
}

// ---------------------------------------------------------------------------------------------------------
// Job API

PowerState PositioningAxis::power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept {
  return core_.power(enable, start_mode, stop_mode);
}

Submission PositioningAxis::reset(bool restart) noexcept {
  const Submission s = core_.reset(restart);
  if (s.error_id == 0) superimposing_error_ = false;  // ErrorWord.X16 is acknowledged as the alarms are
  return s;
}

Submission PositioningAxis::move_absolute(const MoveAbsoluteInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!finite(in.Position)) return Submission::reject(error_id::kInvalidPosition);
  // NaN is resolve_dynamics' internal "no velocity" (MoveVelocity, Halt): a user's NaN is an invalid input.
  if (std::isnan(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);
  if (in.BufferMode != 0 && in.BufferMode != 1) return Submission::reject(error_id::kInvalidBufferMode);
  if (modulo() && (in.Direction < 1 || in.Direction > 3))
    return Submission::reject(error_id::kInvalidDirection);
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(in.Velocity, in.Acceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  if (!homed()) return Submission::reject(error_id::kAxisNotHomed);  // spec 03 §4.5 prerequisites
  if (modulo() && !absolute_target(in.Position, in.Direction, base_setpoint().position)) {
    return Submission::reject(error_id::kInvalidPosition);
  }
  bool queue = false;
  if (const auto e =
          arbitrate_motion(in.BufferMode == 1 ? NewJob::kAppendedMotion : NewJob::kBaseMotion, queue))
    return Submission::reject(e);
  Motion m;
  m.kind = JobKind::kMoveAbsolute;
  m.limits = limits;
  m.command_velocity = (in.Velocity < 0.0 ? db_.DynamicDefaults.Velocity : in.Velocity) / units_.velocity;
  m.absolute_position = in.Position;
  m.direction = in.Direction;
  m.target = in.Position;
  if (queue) {
    m.id = core_.jobs.create(JobKind::kMoveAbsolute, JobState::kPending);
    pending_ = m;
    return Submission::accept(m.id);
  }
  m.id = core_.jobs.create(JobKind::kMoveAbsolute, JobState::kActive);
  start_positioning(m);
  return Submission::accept(m.id);
}

Submission PositioningAxis::move_relative(const MoveRelativeInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!finite(in.Distance)) return Submission::reject(error_id::kInvalidPosition);
  if (std::isnan(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);  // as MoveAbsolute
  if (in.BufferMode != 0 && in.BufferMode != 1) return Submission::reject(error_id::kInvalidBufferMode);
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(in.Velocity, in.Acceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  bool queue = false;
  if (const auto e =
          arbitrate_motion(in.BufferMode == 1 ? NewJob::kAppendedMotion : NewJob::kBaseMotion, queue))
    return Submission::reject(e);
  Motion m;
  m.kind = JobKind::kMoveRelative;
  m.limits = limits;
  m.command_velocity = (in.Velocity < 0.0 ? db_.DynamicDefaults.Velocity : in.Velocity) / units_.velocity;
  m.distance = in.Distance;
  // The start position is the setpoint when the job starts (spec 02 §2.2): now, or the end of the running
  // job for an appended one.
  m.relative_to_end = true;
  if (queue) {
    m.id = core_.jobs.create(JobKind::kMoveRelative, JobState::kPending);
    pending_ = m;
    return Submission::accept(m.id);
  }
  m.id = core_.jobs.create(JobKind::kMoveRelative, JobState::kActive);
  start_positioning(m);
  return Submission::accept(m.id);
}

Submission PositioningAxis::move_velocity(const MoveVelocityInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!finite(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);
  if (in.Direction < 0 || in.Direction > 2) return Submission::reject(error_id::kInvalidDirection);
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), in.Acceleration,
                                      in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  bool queue = false;
  if (const auto e = arbitrate_motion(NewJob::kBaseMotion, queue)) return Submission::reject(e);
  double v = in.Velocity / units_.velocity;
  if (in.Direction == 1) v = std::fabs(v);
  if (in.Direction == 2) v = -std::fabs(v);
  const double command = in.Current ? base_setpoint().velocity / std::max(override_factor(), 1e-12) : v;
  Motion m;
  m.id = core_.jobs.create(JobKind::kMoveVelocity, JobState::kActive);
  m.kind = JobKind::kMoveVelocity;
  m.limits = limits;
  m.command_velocity = command;
  m.position_controlled = in.PositionControlled;
  motion_ = m;
  position_controlled_ = in.PositionControlled;  // spec 02 §2.1: the mode persists after the job
  positioning_.cancel();
  positioning_start_pending_ = false;
  const double target = std::clamp(command * override_factor(), -limits.velocity, limits.velocity);
  if (std::fabs(command * override_factor()) > limits.velocity + 1e-12) raise(kAlarmDynamicsLimitedVelocity);
  motion_.planned_velocity = target;
  plan_velocity(target, limits, false);
  return Submission::accept(motion_.id);
}

Submission PositioningAxis::halt(const HaltInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (in.Mode != 0 && in.Mode != 1) return Submission::reject(error_id::kInvalidMode);
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), in.Deceleration,
                                      in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  bool queue = false;
  if (const auto e = arbitrate_motion(in.Mode == 1 ? NewJob::kHaltBaseOnly : NewJob::kBaseMotion, queue))
    return Submission::reject(e);
  abort_pending(0);  // a halt leaves nothing to append to
  Motion m;
  m.id = core_.jobs.create(JobKind::kHalt, JobState::kActive);
  m.kind = JobKind::kHalt;
  m.limits = limits;
  m.halt_base_only = in.Mode == 1;
  motion_ = m;
  positioning_.cancel();
  positioning_start_pending_ = false;
  plan_velocity(0.0, limits, in.AbortAcceleration);
  return Submission::accept(motion_.id);
}

Submission PositioningAxis::stop(const StopInputs& in) noexcept {
  std::size_t n = 0;
  const auto running = running_jobs(n);
  int weight = 0;
  ProfileLimits limits;
  if (const auto decided =
          core_.stop_request(in, db_.DynamicDefaults, db_.DynamicLimits, dynamic_units(),
                             std::span<const RunningJob>(running.data(), n), weight, limits)) {
    return *decided;
  }
  abort_synchronous(0);   // MC_Stop aborts every synchronous job (§9.19.2 row MC_Stop)
  abort_superimposed(0);  // R7 x C7 = A
  abort_motion(0);
  abort_pending(0);
  if (passive_.id != 0) {  // R7 x C1 = A
    end_passive_homing(JobState::kAborted);
  }
  limit_stop_ = false;
  const JobId id = core_.start_stop(weight, limits);
  plan_velocity(0.0, limits, in.AbortAcceleration);
  return Submission::accept(id);
}

Submission PositioningAxis::jog(JobId running, const JogInputs& in) noexcept {
  const auto start = [&]() noexcept -> std::uint16_t {
    ProfileLimits limits;
    if (const auto e = resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), in.Acceleration,
                                        in.Deceleration, in.Jerk, limits))
      return *e;
    if (const auto e = motion_prerequisites()) return e;
    bool queue = false;
    if (const auto e = arbitrate_motion(NewJob::kBaseMotion, queue)) return e;
    Motion m;
    m.id = core_.jobs.create(JobKind::kJog, JobState::kActive);
    m.kind = JobKind::kJog;
    m.limits = limits;
    m.position_controlled = in.PositionControlled;
    // Nothing planned yet: the jog plans in its first cycle whatever its target (0 under a 0 % override),
    // from the base setpoint that now holds a superimposed state folded by the arbitration (U3, U18); the
    // aborted job's profile does not go on.
    m.planned_velocity = std::numeric_limits<double>::infinity();
    motion_ = m;
    position_controlled_ = in.PositionControlled;
    positioning_.cancel();
    positioning_start_pending_ = false;
    return 0;
  };
  const auto brake = [&](const ProfileLimits& limits) noexcept { plan_velocity(0.0, limits, false); };
  return evaluate_jog(core_, motion_, running, in, units_.velocity, start, brake);
}

Submission PositioningAxis::write_parameter(std::int32_t parameter_number, double value) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  switch (parameter_number) {
    case 1000: {
      // PositionLimits_HW.Active: effective at once; TRUE survives until a TO restart (spec 02 §4.4).
      if (value != 0.0 && value != 1.0) return Submission::reject(error_id::kInvalidParameterValue);
      db_.PositionLimits_HW.Active = value == 1.0;
      hardware_limits_.set_active(db_.PositionLimits_HW.Active);
      break;
    }
    case 1010:
    case 1011:
    case 1012:
      return core_.write_communication_time(parameter_number, value, db_.StatusWord);
    case 1020: {
      const VariableInfo* v = find_by_write_parameter(positioning_axis_variables(), 1020);
      if (v == nullptr || v->write(db_, value) != ValueError::kNone) {
        return Submission::reject(error_id::kInvalidParameterValue);
      }
      (void)v->write(*start_, value);
      break;
    }
    default:
      return Submission::reject(error_id::kInvalidParameterNumber);
  }
  return Submission::accept(core_.jobs.create(JobKind::kWriteParameter, JobState::kDone));
}

// ---------------------------------------------------------------------------------------------------------
// As a leading value

LeadingValue PositioningAxis::leading_value(LeadingValueCoupling coupling) const noexcept {
  LeadingValue v;
  v.position_controlled = core_.phase == PowerPhase::kEnabled && position_controlled_ && !follows_actual();
  if (coupling != LeadingValueCoupling::kActualValue) {
    // "Delayed" is the setpoint coupling delayed (SYNC8 "Delay time for setpoint coupling with delayed
    // leading value"); position control is judged now, as for the setpoint.
    const MotionState& s =
        coupling == LeadingValueCoupling::kDelayed && delayed_ ? delayed_->value() : setpoint_;
    v.position = s.position;
    v.velocity = s.velocity;
    v.acceleration = s.acceleration;
    v.valid = true;
  } else {
    v.position = extrapolation_.position();
    v.velocity = extrapolation_.velocity();
    v.acceleration = extrapolation_.acceleration();
    v.valid = actual_valid_;
  }
  return v;
}

void PositioningAxis::provide_delayed_leading_value(double interpolator_cycle_s) {
  if (delayed_) return;
  try {
    delayed_ = std::make_unique<DelayedLeadingValue>(
        db_.CrossPlcSynchronousOperation.LocalLeadingValueDelayTime, interpolator_cycle_s);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(name()) +
                                ".CrossPlcSynchronousOperation.LocalLeadingValueDelayTime: " + e.what());
  }
}

ModuloRange PositioningAxis::leading_value_modulo() const noexcept {
  return ModuloRange{db_.Modulo.Enable, db_.Modulo.StartValue, db_.Modulo.Length};
}

// ---------------------------------------------------------------------------------------------------------
// Retentive data

bool PositioningAxis::absolute_encoder() const noexcept {
  return db_.Sensor[db_.OperativeSensor - 1].Type !=
         static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL);
}

void PositioningAxis::store_adjustment() noexcept {
  const RetainedSensorState r = encoder_.chain().retained_state();
  retained_.adopt(r.AbsEncoderOffset, r.MeasuringRangeCount, r.LastAbsoluteValue);
}

void PositioningAxis::restore_retained(const RetainedEncoderData& data) noexcept {
  if (!absolute_encoder() || !data.valid) return;
  retained_ = data;  // before start: the operative encoder is the start-up one
  retained_restored_ = true;
  homed_ = true;  // an adjusted absolute encoder is homed after power-up (spec 02 §5.12)
  db_.StatusSensor[db_.OperativeSensor - 1].Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
}

void PositioningAxis::restore_retained(std::uint32_t n, const RetainedEncoderData& data) noexcept {
  if (n == db_.OperativeSensor) return restore_retained(data);
  AdditionalEncoder* e = additional_.find(n);
  if (e == nullptr || !e->channel.chain().absolute_type() || !data.valid) return;
  e->retained = data;  // applied by power_up_additional_encoders() in the first servo cycle
  db_.StatusSensor[n - 1].Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
}

void PositioningAxis::report_adjustment_lost(std::uint32_t cause) noexcept {
  if (!absolute_encoder()) return;
  (void)core_.alarms.raise(kAlarmAdjustmentLost, cause, core_.cycle);
}

// ---------------------------------------------------------------------------------------------------------
// Alarms

void PositioningAxis::raise_with(std::uint32_t number, std::uint32_t additional,
                                 std::int32_t reaction) noexcept {
  (void)core_.alarms.raise(number, additional, static_cast<AlarmReaction>(reaction), core_.cycle);
}

// ---------------------------------------------------------------------------------------------------------
// Data-block access

void PositioningAxis::written(std::string_view path) noexcept {
  // DIR values take effect from the next MC_Servo (spec 04 §0.2): the components are re-read. The state of
  // the monitors survives: only what changed is re-configured.
  configure_monitoring();
  if (path.starts_with("Extrapolation.")) configure_extrapolation();
  if (path.starts_with("PositionLimits_SW.")) {
    software_limits_.configure(limits::software_limit_config(db_.PositionLimits_SW, db_.Modulo));
  }
  if (path.starts_with("Sensor[") || path.starts_with("SetpointFilter.")) configure_backlash_and_filter();
  if (path.starts_with("PositionControl.") || path.starts_with("DynamicAxisModel.") ||
      path.starts_with("FollowingError.")) {
    // The quantization stays the one of the encoder it was configured for; the rest are DIR values or change
    // only at a restart.
    if (auto* controller = this->controller()) {
      (void)controller->configure(position_control_config(controller->quantization()));
    }
  }
}

ValueError PositioningAxis::start_value_written(std::string_view path, double value) noexcept {
  // A start value that switches the dynamic filter on reserves its histories now (a user call), so that the
  // MC_Reset Restart that applies it allocates nothing in MC_Interpolator (decision M2).
  if (path == "SetpointFilter.DynamicFilter.Mode" && value != 0.0 && !dynamic_filter_.reserve_histories()) {
    return ValueError::kOutOfRange;  // no memory for the histories: refused, never silently unfiltered
  }
  return ValueError::kNone;
}

}  // namespace tomc::techobjects
