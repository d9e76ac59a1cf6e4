// MC_PositionProfile on the positioning axis (spec 03 §4.7, seed 004 §6.8.4, §9.7): a transition profile
// with the job's dynamics where the axis is not ready to follow the profile, then the time-position profile
// itself (StatusWord2.X10 OnProfile), limited to DynamicLimits (alarms 501/502, OnProfile FALSE while
// limited), Done at its end after the positioning window (spec 03 §3.5).
#include <algorithm>
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::techobjects {

namespace {

constexpr int kRelative = 0;
constexpr int kAbsolute = 1;

bool same_velocity(double a, double b) noexcept {
  return std::fabs(a - b) <= 1e-9 * std::max(1.0, std::fabs(b));
}

}  // namespace

Submission PositioningAxis::position_profile(const PositionProfileInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (in.BufferMode != 0 && in.BufferMode != 1) return Submission::reject(error_id::kInvalidBufferMode);
  if (in.ProfileReference != kRelative && in.ProfileReference != kAbsolute)
    return Submission::reject(error_id::kInvalidPositionProfileReference);
  if (const auto e = in.TimePosition.validate(in.StartTime)) return Submission::reject(e);
  if (std::isnan(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);  // as MoveAbsolute
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(in.Velocity, in.Acceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  // seed 004 §9.7.1 prerequisites: homed for an absolute profile.
  if (in.ProfileReference == kAbsolute && !homed()) return Submission::reject(error_id::kAxisNotHomed);
  Motion m;
  m.kind = JobKind::kPositionProfile;
  m.limits = limits;
  m.command_velocity = (in.Velocity < 0.0 ? db_.DynamicDefaults.Velocity : in.Velocity) / units_.velocity;
  m.set_time_source(in.TimePosition);
  m.distance = in.StartTime;
  m.direction = in.ProfileReference;
  // An absolute profile that moves at StartTime can be joined only by an axis already on it (decision L3);
  // checked before the matrix aborts anything. An appended job is checked when it becomes active.
  const MotionState start = in.TimePosition.evaluate(in.StartTime);
  const MotionState base = base_setpoint();  // the profile is a base motion (a superimposed one goes on)
  if (in.BufferMode == 0 && in.ProfileReference == kAbsolute && start.velocity != 0.0 &&
      !(std::fabs(base.position - start.position) <= 1e-9 * std::max(1.0, std::fabs(start.position)) &&
        same_velocity(base.velocity, start.velocity))) {
    return Submission::reject(error_id::kProfileStartNotReachable);
  }
  bool queue = false;
  if (const auto e =
          arbitrate_motion(in.BufferMode == 1 ? NewJob::kAppendedMotion : NewJob::kBaseMotion, queue))
    return Submission::reject(e);
  if (queue) {
    m.id = core_.jobs.create(JobKind::kPositionProfile, JobState::kPending);
    pending_ = m;
    return Submission::accept(m.id);
  }
  m.id = core_.jobs.create(JobKind::kPositionProfile, JobState::kActive);
  start_time_profile(m);
  return Submission::accept(m.id);
}

// BufferMode 1: the appended job starts in the cycle the running one is Done (spec 03 §3.7 T-E).
void PositioningAxis::start_motion(const Motion& motion) noexcept {
  if (motion.kind == JobKind::kPositionProfile) {
    // The user's structure may have changed while the job waited: checked again before it is read.
    if (const auto e = motion.time_source().validate(motion.distance)) {
      core_.jobs.set(motion.id, JobState::kError, e);
      return;
    }
    start_time_profile(motion);
  } else {
    start_positioning(motion);
  }
}

// seed 004 §6.8.4 "transition profile": needed where the setpoint position (absolute) or the setpoint
// velocity does not match the profile at StartTime. Relative: a velocity change to the profile's velocity
// (the profile then starts where the transition ends: "the calculation gives the length of the transition
// and hence the start position of the profile"). Absolute: a positioning to the profile's start point
// (shortest path on a modulo axis), which ends at rest.
void PositioningAxis::start_time_profile(Motion motion) noexcept {
  const MotionState start = motion.time_source().evaluate(motion.distance);
  const MotionState base = base_setpoint();
  motion.interpolation_done = false;
  motion.profile_limited = false;
  motion.absolute_position = 0.0;
  double target = start.position;
  if (motion.direction == kAbsolute && modulo()) {
    target = absolute_target(start.position, 3, base.position).value_or(base.position);
    motion.absolute_position = target - start.position;
  }
  motion_ = motion;
  position_controlled_ = true;  // like MoveAbsolute/MoveRelative (spec 02 §7.7)
  core_.jobs.set(motion_.id, JobState::kActive);
  positioning_.cancel();
  positioning_start_pending_ = false;
  check_profile_limits(motion_);
  const bool velocity_matches = same_velocity(base.velocity, start.velocity);
  if (motion.direction == kRelative) {
    if (velocity_matches) {
      enter_time_profile(base.position);  // "ready to follow directly: OnProfile at once"
    } else {
      // The job's Velocity bounds the way there, not the profile's own velocity at StartTime.
      ProfileLimits l = motion_.limits;
      l.velocity = std::max(l.velocity, std::fabs(start.velocity));
      plan_velocity(start.velocity, l, false);
    }
    return;
  }
  const bool at_start =
      std::fabs(base.position - target) <= 1e-9 * std::max(1.0, std::fabs(target)) && velocity_matches;
  if (at_start) {
    enter_time_profile(base.position);
  } else if (start.velocity != 0.0) {
    // An appended absolute job whose profile moves at StartTime, behind a job that stopped elsewhere.
    core_.jobs.set(motion_.id, JobState::kError, error_id::kProfileStartNotReachable);
    motion_ = Motion{};
  } else {
    // The job's Velocity within the limit; the override does not act on a PositionProfile job (decision L4),
    // so the transition always ends and the profile always follows (0 % would stop it for good).
    ProfileLimits l = motion_.limits;
    l.velocity = std::min(motion_.command_velocity, velocity_limit());
    plan_position(target, l);
  }
}

void PositioningAxis::enter_time_profile(double base_position, double elapsed) noexcept {
  motion_.distance = std::min(motion_.distance + elapsed, motion_.time_source().end_time());
  if (motion_.direction == kRelative) {
    motion_.absolute_position = base_position - motion_.time_source().evaluate(motion_.distance).position;
  }
  motion_.target =
      motion_.time_source().evaluate(motion_.time_source().end_time()).position + motion_.absolute_position;
  generator_ = Generator::kTimeProfile;
}

// seed 004 §6.8.4 "dynamic limits while following the profile": a profile asking more than
// DynamicLimits.MaxVelocity / MaxAcceleration raises 501 / 502 when the job starts.
void PositioningAxis::check_profile_limits(const Motion& motion) noexcept {
  const ProfileDynamics d = motion.time_source().max_dynamics(motion.distance);
  const double v_max = db_.DynamicLimits.MaxVelocity / units_.velocity;
  const double a_max =
      std::min(db_.DynamicLimits.MaxAcceleration, db_.DynamicLimits.MaxDeceleration) / units_.acceleration;
  if (d.velocity > v_max * (1.0 + 1e-9)) raise(kAlarmDynamicsLimitedVelocity);
  if (d.acceleration > a_max * (1.0 + 1e-9)) raise(kAlarmDynamicsLimitedAcceleration);
}

// One interpolator cycle on the profile. Within DynamicLimits the setpoint is the profile; beyond them
// (OnProfile FALSE, seed 004 §6.8.4) it chases the profile with MaxVelocity and the acceleration limits —
// the velocity that would let it brake onto the profile, clamped — until it is within one cycle's step of
// it again (decision L4).
// Out of line even under link-time optimisation (decision P28): a path the steady cycle does not take, kept
// out of the frame of the function that calls it every cycle, whose stack lines the cycle touches.
[[gnu::noinline]] void PositioningAxis::follow_time_profile() noexcept {
  if (motion_.kind != JobKind::kPositionProfile) {  // the job ended without a new generator: hold
    generator_ = Generator::kIdle;
    setpoint_.position += setpoint_.velocity * core_.ipo_cycle_s;
    setpoint_.acceleration = 0.0;
    return;
  }
  const TimePositionSource profile = motion_.time_source();
  // The user changed the profile while the job ran: stop with the job's deceleration, never a wild step and
  // never a read outside the points (the count is checked every cycle: end_time() and evaluate() index by
  // it).
  const auto fail = [this](std::uint16_t error) noexcept {
    core_.jobs.set(motion_.id, JobState::kError, error);
    const ProfileLimits stop = motion_.limits;
    motion_ = Motion{};
    plan_velocity(0.0, stop, false);
  };
  if (const std::uint16_t e = profile.still_valid()) {
    fail(e);
    return;
  }
  const double dt = core_.ipo_cycle_s;
  motion_.distance = std::min(motion_.distance + dt, profile.end_time());
  MotionState wanted = profile.evaluate(motion_.distance);
  wanted.position += motion_.absolute_position;
  if (!std::isfinite(wanted.position) || !std::isfinite(wanted.velocity)) {
    fail(error_id::kTimePositionNotFinite);
    return;
  }
  const double v_max = db_.DynamicLimits.MaxVelocity / units_.velocity;
  const double accel_max = db_.DynamicLimits.MaxAcceleration / units_.acceleration;
  const double decel_max = db_.DynamicLimits.MaxDeceleration / units_.acceleration;
  const auto acceleration_limit = [&](double a, double v) noexcept {
    return a * v > 0.0 ? accel_max : decel_max;  // |v| grows: acceleration; shrinks: deceleration
  };
  const MotionState now = setpoint_;
  // A point edited while the job runs can move the profile by more than a cycle at v_max: chased, no step.
  const bool wanted_within = std::fabs(wanted.position - now.position) <= v_max * dt * (1.0 + 1e-9) &&
                             std::fabs(wanted.velocity) <= v_max * (1.0 + 1e-9) &&
                             std::fabs(wanted.acceleration) <=
                                 acceleration_limit(wanted.acceleration, wanted.velocity) * (1.0 + 1e-9);
  if (profile.cam() != nullptr) {
    // A cam's polynomials have no closed-form extremes: 501/502 when the profile asks for more (L8).
    if (std::fabs(wanted.velocity) > v_max * (1.0 + 1e-9)) raise(kAlarmDynamicsLimitedVelocity);
    if (std::fabs(wanted.acceleration) >
        acceleration_limit(wanted.acceleration, wanted.velocity) * (1.0 + 1e-9))
      raise(kAlarmDynamicsLimitedAcceleration);
  }
  if (!motion_.profile_limited && wanted_within) {
    setpoint_ = wanted;
  } else {
    const double error = wanted.position - now.position;
    const double brake = std::min(accel_max, decel_max);
    const double chase = std::clamp(
        wanted.velocity + std::copysign(std::sqrt(2.0 * brake * std::fabs(error)), error), -v_max, v_max);
    const double limit = acceleration_limit(chase - now.velocity, now.velocity == 0.0 ? chase : now.velocity);
    const double v = now.velocity + std::clamp(chase - now.velocity, -limit * dt, limit * dt);
    setpoint_ = MotionState{now.position + 0.5 * (now.velocity + v) * dt, v, (v - now.velocity) / dt};
    // Back on the profile once one more cycle within the limits reaches it.
    const bool rejoin =
        wanted_within && std::fabs(wanted.velocity - now.velocity) <= limit * dt &&
        std::fabs(wanted.position - (now.position + 0.5 * (now.velocity + wanted.velocity) * dt)) <=
            0.5 * limit * dt * dt + 1e-12;
    if (rejoin) setpoint_ = wanted;
    motion_.profile_limited = !rejoin;
  }
  if (motion_.distance >= profile.end_time() && !motion_.profile_limited) {
    // The end of the profile, at rest: Done after the positioning window (spec 03 §3.5).
    setpoint_ = MotionState{wanted.position, 0.0, 0.0};
    generator_ = Generator::kIdle;
    motion_.interpolation_done = true;
    positioning_target_ = positioning_reference();
    positioning_start_pending_ = true;
  }
}

}  // namespace tomc::techobjects
