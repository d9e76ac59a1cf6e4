#include "tomc/techobjects/positioning_axis/superimposed_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tomc::techobjects {
namespace {

// A headroom change smaller than this share of VelocityDiff does not replan (a base ramp would otherwise
// replan on every cycle for a difference no one can see); shrinking always replans.
constexpr double kRaiseHysteresis = 1e-3;

}  // namespace

void SuperimposedMotion::move(JobId id, double distance, const ProfileLimits& limits) noexcept {
  id_ = id;
  job_ = Job::kMove;
  limits_ = limits;
  target_ = state_.position + distance;
  replan(limits.velocity, 0.0);
}

void SuperimposedMotion::halt(JobId id, const ProfileLimits& limits, bool abort_acceleration) noexcept {
  id_ = id;
  job_ = Job::kHalt;
  limits_ = limits;
  if (abort_acceleration) state_.acceleration = 0.0;  // spec 03 §4.11 AbortAcceleration
  abort_step_ = abort_acceleration;
  plan_halt();
}

void SuperimposedMotion::plan_halt() noexcept {
  ProfileLimits l = limits_;
  l.velocity = std::numeric_limits<double>::infinity();
  l.jerk = replanning_jerk(state_.velocity, state_.acceleration, l.jerk, true);  // decision R1
  VelocityProfile stop;
  if (stop.plan(state_, 0.0, l)) {
    profile_.emplace<RunningProfile>().adopt(stop, state_, 0.0, l);
    time_ = 0.0;
    planned_ = true;
  }
}

// Planned into a temporary and taken over only when the plan succeeds: a running profile is never restarted.
// A velocity headroom below VelocityDiff moves with the base's acceleration towards the limit
// (`base_approach`): the job's Deceleration counts relative to it, so that the total comes back within the
// velocity limit however the job's Deceleration compares with the base's acceleration (decision U18).
void SuperimposedMotion::replan(double velocity_limit, double base_approach) noexcept {
  ProfileLimits l = limits_;
  if (velocity_limit < limits_.velocity) l.deceleration += std::max(base_approach, 0.0);
  if (velocity_limit > 0.0) {
    l.velocity = velocity_limit;
    PositionProfile to_target;
    if (!to_target.plan(state_, target_, l)) return;
    profile_.emplace<RunningProfile>().adopt(to_target, state_, target_, l);
  } else {
    // No headroom in the direction of travel: the superimposed part stops and waits (as an override of 0 %).
    VelocityProfile stop;
    if (!stop.plan(state_, 0.0, l)) return;
    profile_.emplace<RunningProfile>().adopt(stop, state_, 0.0, l);
  }
  planned_velocity_ = velocity_limit;
  time_ = 0.0;
  planned_ = true;
}

void SuperimposedMotion::start_motion_in(JobId id, Job kind) noexcept {
  id_ = id;
  job_ = kind;
  planned_ = false;
  // Until the first setpoint: the present superimposition stays (absolute, as the inputs are).
  profile_ = MotionState{distance(), state_.velocity, state_.acceleration};
}

void SuperimposedMotion::follow(const MotionState& superimposition) noexcept {
  // state_ counts from the last fold(); the input is the whole superimposition (decision U9).
  state_ = MotionState{superimposition.position - folded_distance_, superimposition.velocity,
                       superimposition.acceleration};
}

void SuperimposedMotion::end_motion_in() noexcept {
  state_.velocity = 0.0;
  state_.acceleration = 0.0;
  end_job();
}

double SuperimposedMotion::approach(const Headroom& headroom) const noexcept {
  return target_ - state_.position >= 0.0 ? headroom.base_acceleration_up : -headroom.base_acceleration_down;
}

bool SuperimposedMotion::limit_acceleration(const MotionState& before, double dt,
                                            const Headroom& headroom) noexcept {
  const double low = -std::max(headroom.acceleration_negative, 0.0);
  const double high = std::max(headroom.acceleration_positive, 0.0);
  // The jerk of the total (U17): the sample may differ from the last one by what the base's jerk leaves of
  // MaxJerk; where that range and the acceleration headroom do not meet, the acceleration limit wins.
  const bool step = abort_step_;  // AbortAcceleration's step is the manual's, not limited
  abort_step_ = false;
  // A base whose own jerk is above MaxJerk leaves no jerk headroom that way: held (U16's rule), not pushed.
  const double rise_jerk = std::max(headroom.jerk_positive, 0.0);
  const double fall_jerk = std::max(headroom.jerk_negative, 0.0);
  double rise = step ? high : std::clamp(before.acceleration + rise_jerk * dt, low, high);
  double fall = step ? low : std::clamp(before.acceleration - fall_jerk * dt, low, high);
  double mean_low = low, mean_high = high;
  // The total beyond the velocity limit (U18): its acceleration may not point further beyond. The
  // superimposed part brakes it back with the job's Deceleration relative to the base (as replan() does),
  // reached as fast as the jerk window lets it, whatever the profile asks for.
  if (state_.velocity > headroom.velocity_positive) {
    rise = std::min(rise, std::max(fall, -headroom.base_acceleration_up - limits_.deceleration));
    mean_high = std::min(mean_high, rise);
  } else if (state_.velocity < -headroom.velocity_negative) {
    fall = std::max(fall, std::min(rise, -headroom.base_acceleration_down + limits_.deceleration));
    mean_low = std::max(mean_low, fall);
  }
  // The sample and the cycle's mean (its velocity step) both: a profile's acceleration changes within a
  // cycle.
  const double mean = (state_.velocity - before.velocity) / dt;
  if (state_.acceleration >= fall && state_.acceleration <= rise && mean >= mean_low && mean <= mean_high) {
    return false;
  }
  const double a = std::clamp(state_.acceleration, fall, rise);
  // No headroom in a direction: the superimposed velocity cannot change that way and is held (U16).
  state_ =
      MotionState{before.position + before.velocity * dt + 0.5 * a * dt * dt, before.velocity + a * dt, a};
  // From the cut state: the next cycle continues from where the axis is.
  if (job_ == Job::kHalt) {
    plan_halt();
  } else {
    replan(planned_velocity_, approach(headroom));
  }
  return true;
}

bool SuperimposedMotion::advance(double dt, const Headroom& headroom) noexcept {
  const double headroom_positive = headroom.velocity_positive;
  const double headroom_negative = headroom.velocity_negative;
  if (job_ == Job::kMotionIn) {
    if (const auto* input = std::get_if<MotionState>(&profile_)) follow(*input);
    return false;
  }
  if (job_ == Job::kMotionInAxes) return false;  // follow() took this cycle's setpoint
  if (job_ == Job::kMove) {
    const double direction = target_ - state_.position;
    const double ahead = direction >= 0.0 ? headroom_positive : headroom_negative;
    const double allowed = std::clamp(ahead, 0.0, limits_.velocity);
    const double tolerance = 1e-9 * limits_.velocity;
    const bool at_target = !planned_ && state_.position == target_;
    if (!at_target && (allowed < planned_velocity_ - tolerance ||
                       allowed > planned_velocity_ + kRaiseHysteresis * limits_.velocity ||
                       (allowed == limits_.velocity && planned_velocity_ < allowed - tolerance))) {
      replan(allowed, approach(headroom));
    }
  }
  if (!planned_) {
    state_.position += state_.velocity * dt;
    state_.acceleration = 0.0;
    return false;
  }
  time_ += dt;
  RunningProfile& profile = std::get<RunningProfile>(profile_);  // planned_: a profile runs
  const bool position = profile.kind() == RunningProfile::Kind::kPosition;
  const double duration = profile.duration();
  const bool finished = time_ >= duration - 1e-9;
  const MotionState before = state_;
  if (!finished) {
    state_ = profile.advance_to(time_);
  } else if (position) {
    state_ = MotionState{target_, 0.0, 0.0};  // exact: the job's distance
  } else {
    state_ = MotionState{profile.at(duration).position, 0.0, 0.0};
  }
  // The headroom holds in every cycle, the last one's step to the end included (U17): a cut replans.
  if ((job_ == Job::kMove || job_ == Job::kHalt) && limit_acceleration(before, dt, headroom)) return false;
  if (!finished) return false;
  planned_ = false;
  // A stop for lack of headroom is not the end of a move: it waits for headroom (next advance replans).
  return position || job_ == Job::kHalt;
}

MotionState SuperimposedMotion::predicted(double dt) const noexcept {
  if (!planned_) return MotionState{state_.position + state_.velocity * dt, state_.velocity, 0.0};
  const double t = time_ + dt;
  const auto& p = std::get<RunningProfile>(profile_);
  if (p.kind() == RunningProfile::Kind::kPosition) {
    return t >= p.duration() ? MotionState{target_, 0.0, 0.0} : p.at(t);
  }
  return t >= p.duration() ? MotionState{p.at(p.duration()).position, 0.0, 0.0} : p.at(t);
}

void SuperimposedMotion::fold() noexcept {
  folded_distance_ += state_.position;
  state_ = MotionState{};
  planned_ = false;
  end_job();
}

}  // namespace tomc::techobjects
