#pragma once
// Setpoint profile planners of the technology objects (spec 01 §8.7 velocity profiles, §8.8 job replacement,
// §8.9 emergency-stop ramp). Pure math for the servo cycle: no heap, no exceptions, no I/O, bounded loops.
//
// A profile is a fixed-capacity list of segments of constant jerk, evaluated in closed form.
//
// Limit semantics (Siemens, spec 01 §8.1–§8.3): `acceleration` bounds |a| while |v| grows (a·v > 0),
// `deceleration` while |v| shrinks (a·v < 0); `jerk` 0 = no jerk limitation (acceleration steps, §8.2).
// Treatment of v = 0 crossings:
//  * jerk = 0: the acceleration steps at v = 0 from the deceleration limit to the acceleration limit
//    (time-optimal; at the instant v = 0 both values are admissible).
//  * jerk > 0: the acceleration is continuous, so its value a_c at v = 0 must be admissible on both sides:
//    a_c ≤ min(acceleration, deceleration). A velocity change through zero keeps a as high as the limits let
//    it: deceleration limit while |v| shrinks, a_c as high as min(..) and the two halves allow, acceleration
//    limit after (time-optimal; the crossing happens with a ≠ 0). Only when the current acceleration forces
//    a_c above min(..) (a0 ramped back at once still crosses above it) is a0 ramped back to min(..) and held.
// Start states outside the limits (spec 01 §8.8, job replacement): an initial |a0| above the applicable limit
// is brought back with the jerk (never increased); an initial a0 that pushes |v| outward makes |v| overshoot
// by a0²/(2j) before it can turn — physically unavoidable with a jerk limit. With jerk 0, a0 is irrelevant
// (the acceleration steps at once).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace tomc::techobjects {

struct MotionState {
  double position = 0;
  double velocity = 0;
  double acceleration = 0;
};

// Limits of one job. acceleration applies while |v| grows, deceleration while |v| shrinks (Siemens
// semantics); jerk 0 = no jerk limitation (trapezoid: acceleration steps).
struct ProfileLimits {
  double velocity = 0;
  double acceleration = 0;
  double deceleration = 0;
  double jerk = 0;
};

// One piece of constant jerk; it lasts until the next segment's start_time (the last one until duration()).
// position/velocity/acceleration are the state at start_time (the acceleration may step there when jerk = 0).
struct ProfileSegment {
  double start_time = 0;
  double position = 0;
  double velocity = 0;
  double acceleration = 0;
  double jerk = 0;
};

// The state `t` into the profile within segment `s` (t at or after its start_time), in closed form. Shared by
// PiecewiseJerkProfile and RunningProfile (running_profile.hpp), so that both give the same bits.
inline MotionState segment_state(const ProfileSegment& s, double t) noexcept {
  const double d = t - s.start_time > 0.0 ? t - s.start_time : 0.0;  // std::max(0.0, t - start_time)
  return MotionState{s.position + d * (s.velocity + d * (s.acceleration / 2 + d * s.jerk / 6)),
                     s.velocity + d * (s.acceleration + d * s.jerk / 2), s.acceleration + d * s.jerk};
}

// Worst case: a velocity change through zero (2 × 3 segments) + cruise + braking (3) = 10; 3·10^6 random
// plans from any state see at most 9 (decision U2: 10, not 12, to make room for the superimposed profile).
// A plan that would need more is marked truncated(); the property tests assert it never is.
inline constexpr std::size_t kMaxProfileSegments = 10;
// Fixed bound of one PositionProfile root search (bracketed, Chandrupatla's method); a plan runs at most 3
// of them (decision S18), so at most 4 + 3 × 101 evaluations of a closed-form velocity change and stop.
// The randomized tests and the benchmark see at most 9 iterations per search.
inline constexpr int kMaxPositionIterations = 100;

// The segment storage shared by both planners.
class PiecewiseJerkProfile {
 public:
  MotionState at(double t) const noexcept;
  double duration() const noexcept { return duration_; }
  std::span<const ProfileSegment> segments() const noexcept { return {segments_.data(), count_}; }
  bool truncated() const noexcept { return truncated_; }  // more segments than kMaxProfileSegments were built
  const MotionState& end_state() const noexcept { return end_; }

 private:
  friend class ProfileBuilder;
  std::array<ProfileSegment, kMaxProfileSegments> segments_{};
  std::uint32_t count_ = 0;
  bool truncated_ = false;
  double duration_ = 0;
  MotionState end_{};  // exact final state; beyond duration() the profile continues at end_.velocity
};

// MC_MoveVelocity, MC_MoveJog, MC_Halt (target 0), stop ramps and the emergency-stop ramp (§8.9: jerk 0 and
// deceleration = EmergencyDeceleration).
class VelocityProfile {
 public:
  // From any state (v0, a0 with |a0| possibly above the new limits) to target velocity with a = 0 at the end.
  // The target is clamped to ±limits.velocity when limits.velocity is > 0 and finite (0 or +inf: no clamp).
  // Returns false only for invalid input: acceleration/deceleration <= 0 or not finite, jerk < 0 or NaN,
  // velocity NaN, non-finite start state or target. On false the previous profile is kept.
  // jerk = +inf is treated as 0 (no jerk limitation).
  bool plan(const MotionState& start, double target_velocity, const ProfileLimits& limits) noexcept;
  MotionState at(double t) const noexcept { return profile_.at(t); }  // t from 0; beyond duration(): cruise
  double duration() const noexcept { return profile_.duration(); }    // time to target velocity with a = 0
  std::span<const ProfileSegment> segments() const noexcept { return profile_.segments(); }
  bool truncated() const noexcept { return profile_.truncated(); }
  const MotionState& end_state() const noexcept { return profile_.end_state(); }  // exact, a = 0
  // Velocity error of the closed-form end state before it was snapped to the target (for tests).
  double end_error() const noexcept { return end_error_; }

 private:
  PiecewiseJerkProfile profile_;
  double end_error_ = 0;
};

// MC_MoveAbsolute / MC_MoveRelative: rest at the target.
class PositionProfile {
 public:
  // From any state (any v0 incl. above limits.velocity or away from the target, any a0) to rest at target,
  // time-optimal within the positioning template start -> peak (a = 0) -> cruise -> 0 (issue 23, S18).
  // Returns false for invalid input (as VelocityProfile, and limits.velocity <= 0 or not finite).
  bool plan(const MotionState& start, double target_position, const ProfileLimits& limits) noexcept;
  MotionState at(double t) const noexcept { return profile_.at(t); }  // beyond duration(): rest at target
  double duration() const noexcept { return profile_.duration(); }
  std::span<const ProfileSegment> segments() const noexcept { return profile_.segments(); }
  bool truncated() const noexcept { return profile_.truncated(); }
  const MotionState& end_state() const noexcept { return profile_.end_state(); }  // exact, at rest
  // Position error of the closed-form end state before it was snapped to the target (for tests).
  double end_error() const noexcept { return end_error_; }
  // Peak (or cruise) velocity the plan settled on, and the iterations of its longest root search (<= the
  // bound).
  double peak_velocity() const noexcept { return peak_velocity_; }
  int iterations() const noexcept { return iterations_; }

  // Distance covered by "velocity profile start -> peak, then velocity profile peak -> 0" (no cruise): the
  // function the planner solves for the peak. Exposed for the monotonicity tests. Limits must be valid.
  static double distance_via_peak(const MotionState& start, double peak,
                                  const ProfileLimits& limits) noexcept;

 private:
  PiecewiseJerkProfile profile_;
  double end_error_ = 0;
  double peak_velocity_ = 0;
  int iterations_ = 0;
};

// The jerk to plan a replacing profile with. Seed 004 §6.7.7 (spec 01 §8.8): the acceleration a0 moves to the
// new job's "tramite lo strappo" — through the new job's jerk j, changing the velocity by a0²/(2j) on the
// way, also past the velocity limit (decision S4: the manual's "movimento imprevisto"; the job's jerk is
// kept). One exception, decision R1: a ramp to standstill (to_standstill: MC_Halt, MC_Stop, stop reactions,
// override 0 %) never reverses: if a0 already carries v through zero, the jerk becomes a0²/(2|v0|) so that v
// and a reach 0 together. Returns that raised jerk or `jerk` unchanged (also for jerk 0).
double replanning_jerk(double v0, double a0, double jerk, bool to_standstill) noexcept;

}  // namespace tomc::techobjects
