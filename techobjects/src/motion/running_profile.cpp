// A running job's profile with two of its segments kept (decision M12); running_profile.hpp.
#include "tomc/techobjects/motion/running_profile.hpp"

#include <limits>

namespace tomc::techobjects {

namespace {

template <typename Planner>
void take(const Planner& plan, double& duration, MotionState& end, std::uint8_t& count) noexcept {
  duration = plan.duration();
  end = plan.end_state();
  count = static_cast<std::uint8_t>(plan.segments().size());
}

}  // namespace

void RunningProfile::adopt(const VelocityProfile& plan, const MotionState& start, double target_velocity,
                           const ProfileLimits& limits) noexcept {
  kind_ = Kind::kVelocity;
  start_ = start;
  target_ = target_velocity;
  limits_ = limits;
  take(plan, duration_, end_, count_);
  keep(plan.segments(), 0.0);
}

void RunningProfile::adopt(const PositionProfile& plan, const MotionState& start, double target_position,
                           const ProfileLimits& limits) noexcept {
  kind_ = Kind::kPosition;
  start_ = start;
  target_ = target_position;
  limits_ = limits;
  take(plan, duration_, end_, count_);
  keep(plan.segments(), 0.0);
}

void RunningProfile::keep(std::span<const ProfileSegment> segments, double t) noexcept {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // The planner's choice (PiecewiseJerkProfile::at): the last segment that has started, else the first.
  std::size_t i = segments.empty() ? 0 : segments.size() - 1;
  while (i > 0 && segments[i].start_time > t)
    --i;
  first_ = static_cast<std::uint8_t>(i);
  for (std::size_t k = 0; k < kKept; ++k) {
    if (i + k < segments.size()) {
      kept_[k] = segments[i + k];
    } else {
      kept_[k] = ProfileSegment{};
      kept_[k].start_time = kNever;  // never chosen
    }
  }
  next_start_ = i + kKept < segments.size() ? segments[i + kKept].start_time : kNever;
}

MotionState RunningProfile::kept_state(double t) const noexcept {
  if (!(t < duration_) || count_ == 0) {
    // Beyond the end, as PiecewiseJerkProfile::at: at the exact final velocity with a = 0.
    const double dt = t - duration_ > 0.0 ? t - duration_ : 0.0;
    return MotionState{end_.position + end_.velocity * dt, end_.velocity, 0.0};
  }
  return segment_state(t >= kept_[1].start_time ? kept_[1] : kept_[0], t);
}

MotionState RunningProfile::replan_at(double t, RunningProfile* keep_it) const noexcept {
  // The inputs planned successfully once; the same call gives the same plan.
  if (kind_ == Kind::kVelocity) {
    VelocityProfile plan;
    (void)plan.plan(start_, target_, limits_);
    if (keep_it != nullptr) keep_it->keep(plan.segments(), t);
    return plan.at(t);
  }
  PositionProfile plan;
  (void)plan.plan(start_, target_, limits_);
  if (keep_it != nullptr) keep_it->keep(plan.segments(), t);
  return plan.at(t);
}

MotionState RunningProfile::advance_to(double t) noexcept {
  return kept(t) ? kept_state(t) : replan_at(t, this);
}

MotionState RunningProfile::at(double t) const noexcept {
  return kept(t) ? kept_state(t) : replan_at(t, nullptr);
}

}  // namespace tomc::techobjects
