#pragma once
// A planned VelocityProfile or PositionProfile as a running job evaluates it (decision M12, the 8 KiB per
// axis TO): the plan's inputs and two of its segments instead of all kMaxProfileSegments (192 bytes instead
// of a 480-byte variant of both planners). A plan is a pure function of its inputs (start state, target,
// limits), so when the job's time passes the kept segments the plan is made again from the same inputs into a
// temporary on the stack and the next two segments are kept: the same segments, bit for bit, and the same
// states as the planner's at() — at most once per two segments of the plan (a plan has at most 10), in
// MC_Interpolator. A look-ahead beyond the kept segments (the software-limit look-ahead, one interpolator
// cycle) plans a temporary the same way without changing what is kept. No heap, no exceptions, bounded loops.

#include <array>
#include <cstdint>
#include <span>

#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::techobjects {

class RunningProfile {
 public:
  enum class Kind : std::uint8_t { kVelocity, kPosition };

  // Takes over a successful plan: `plan` was planned with exactly these inputs (plan(start, target, limits)
  // returned true). Its first two segments are kept.
  void adopt(const VelocityProfile& plan, const MotionState& start, double target_velocity,
             const ProfileLimits& limits) noexcept;
  void adopt(const PositionProfile& plan, const MotionState& start, double target_position,
             const ProfileLimits& limits) noexcept;

  Kind kind() const noexcept { return kind_; }
  double duration() const noexcept { return duration_; }  // as the planner's
  // The state at t, as the planner's at(t). advance_to(): t not before the one of the last call since
  // adopt() (the job's time): it may plan again to keep the segments of t. at(): any t, what is kept stays.
  MotionState advance_to(double t) noexcept;
  MotionState at(double t) const noexcept;

 private:
  static constexpr std::size_t kKept = 2;
  // The segments of `plan` from the one in progress at t: kept_[0..], first_, next_start_.
  void keep(std::span<const ProfileSegment> segments, double t) noexcept;
  // The plan made again from the inputs, evaluated at t (a temporary; `keep_it`: its segments at t are kept).
  MotionState replan_at(double t, RunningProfile* keep_it) const noexcept;
  // t is evaluated by a kept segment, or beyond the plan's end, as the planner would (its at() takes the last
  // segment that has started, the first one before it).
  bool kept(double t) const noexcept {
    return !(t < duration_) || count_ == 0 || ((t >= kept_[0].start_time || first_ == 0) && t < next_start_);
  }
  MotionState kept_state(double t) const noexcept;

  std::array<ProfileSegment, kKept> kept_{};
  MotionState start_{};
  ProfileLimits limits_{};
  double target_ = 0.0;
  double duration_ = 0.0;
  double next_start_ = 0.0;  // start_time of the segment after the kept ones (duration_ after the last)
  MotionState end_{};  // the planner's exact final state; beyond duration() it continues at end_.velocity
  Kind kind_ = Kind::kVelocity;
  std::uint8_t count_ = 0;  // segments of the whole plan
  std::uint8_t first_ = 0;  // index of kept_[0] in the plan
};

}  // namespace tomc::techobjects
