#pragma once
// The superimposed part of a positioning or synchronous axis' setpoint (seed 004 §6.7.10, spec 01 §8.14,
// spec 03 §4.10–4.11): MC_MoveSuperimposed adds a relative move to whatever the base motion does, and
// MC_HaltSuperimposed brakes that part to standstill. The axis' setpoint is base + superimposed; the data
// block shows the total. Pure motion math for MC_Interpolator: no heap, no exceptions, bounded work (at most
// one replan per cycle, each a bounded plan of profiles.hpp).
//
// Limits (spec 01 §8.14, single-axis base): the superimposed velocity may use only what the base leaves of
// the velocity limit, v_sup ∈ [−(v_limit + v_base), v_limit − v_base], and at most VelocityDiff. The profile
// is replanned (from the present superimposed state, with the job's jerk) whenever that headroom falls below
// the planned velocity or rises again. The same holds for the acceleration (seed 004 §6.7.10.1: "the dynamics
// of the superimposed motion are at most the difference between the base motion's present dynamic values and
// the dynamic limits"): a move's or halt's superimposed acceleration stays within what the base leaves of
// MaxAcceleration / MaxDeceleration in each direction, and its change per cycle within what the base's jerk
// leaves of MaxJerk; where the profile asks for more, the cycle takes the headroom and the profile is
// replanned from that state (decisions U4, U16, U17). A base jerk above MaxJerk holds the superimposed
// acceleration rather than pushing it; a total beyond the velocity limit is braked back (U18).
//
// MC_MotionInSuperimposed and MC_MotionInSuperimposedAxes (spec 03 §4.17.3–4.17.4, seed 004 §6.14.3) set the
// superimposed part directly: no profile, no limits; the distance they give is the absolute value of the
// superimposition, x_set = x_base + Distance, so SuperimposedDistance shows it (decision U9).
#include <cstdint>
#include <variant>

#include "tomc/techobjects/axis/job.hpp"
#include "tomc/techobjects/motion/profiles.hpp"
#include "tomc/techobjects/motion/running_profile.hpp"

namespace tomc::techobjects {

class SuperimposedMotion {
 public:
  // kMotionIn: MC_MotionInSuperimposed (the application's setpoints, set_input()); kMotionInAxes:
  // MC_MotionInSuperimposedAxes (another axis' setpoints, follow()).
  enum class Job : std::uint8_t { kNone, kMove, kHalt, kMotionIn, kMotionInAxes };

  // The superimposed part of the setpoint: position = distance since the last fold().
  const MotionState& state() const noexcept { return state_; }
  // StatusPositioning.SuperimposedDistance: the distance superimposed jobs travelled since both motions
  // last finished (folded parts included).
  double distance() const noexcept { return folded_distance_ + state_.position; }
  JobId job_id() const noexcept { return id_; }
  Job job() const noexcept { return job_; }
  // advance() has work: a job, or a profile still running.
  bool moving() const noexcept { return job_ != Job::kNone || planned_; }
  // No job and no superimposed velocity or acceleration left.
  bool settled() const noexcept {
    return job_ == Job::kNone && !planned_ && state_.velocity == 0.0 && state_.acceleration == 0.0;
  }

  // MC_MoveSuperimposed: `distance` beyond the present superimposed position, from the present superimposed
  // state. limits.velocity is VelocityDiff. A job this one replaces ends without a fold (§9.19.1 R6 x C7).
  void move(JobId id, double distance, const ProfileLimits& limits) noexcept;
  // MC_HaltSuperimposed: brakes the superimposed velocity to 0 (AbortAcceleration: from a = 0 at once).
  void halt(JobId id, const ProfileLimits& limits, bool abort_acceleration) noexcept;
  // MotionIn (kMotionIn / kMotionInAxes): the job starts from the present superimposed state, which stays
  // until the first setpoint arrives. A profile still running (a replaced move or halt) ends here.
  void start_motion_in(JobId id, Job kind) noexcept;
  // MC_MotionInSuperimposed's inputs of the last call: taken over by the next advance().
  void set_input(const MotionState& superimposition) noexcept { profile_ = superimposition; }
  // MC_MotionInSuperimposedAxes: the superimposing axis' setpoint of this cycle, taken over at once.
  void follow(const MotionState& superimposition) noexcept;
  // The falling edge of Enable: velocity and acceleration become 0, the superimposed position is kept
  // (spec 03 §4.17.3 Enable). The job ends (end_job()).
  void end_motion_in() noexcept;
  bool motion_in() const noexcept { return job_ == Job::kMotionIn || job_ == Job::kMotionInAxes; }

  // What the base motion leaves of the dynamic limits in this cycle, in each direction (+inf: no limit, e.g.
  // a following axis, spec 01 §8.14). A value <= 0 leaves nothing in that direction. The jerk: how fast the
  // superimposed acceleration may rise / fall in this cycle, MaxJerk ∓ the base's jerk (decision U17; a
  // negative value holds the acceleration, U18). The base's acceleration, the larger and the smaller of its
  // sample and its cycle mean: the rate at which the velocity headroom moves (U18).
  struct Headroom {
    double velocity_positive;
    double velocity_negative;
    double acceleration_positive;
    double acceleration_negative;
    double jerk_positive;
    double jerk_negative;
    double base_acceleration_up;
    double base_acceleration_down;
  };
  // One interpolator cycle. Returns true in the cycle the job's motion is complete (the job itself is ended
  // by the caller: end_job()).
  bool advance(double dt, const Headroom& headroom) noexcept;
  // The superimposed setpoint `dt` after the present one, without replanning (software-limit look-ahead).
  MotionState predicted(double dt) const noexcept;
  void end_job() noexcept {
    id_ = 0;
    job_ = Job::kNone;
  }
  // The base motion takes the superimposed state over: an abort by a base job (its velocity and acceleration
  // continue in the base motion's plan, spec 01 §8.8 "current dynamics are carried into the new motion"),
  // or both motions finished. The job ends; distance() keeps counting what was travelled.
  void fold() noexcept;
  // Both motions finished or aborted: SuperimposedDistance returns to 0 (spec 01 §8.14).
  void reset_distance() noexcept { folded_distance_ = 0.0; }

 private:
  void replan(double velocity_limit, double base_approach) noexcept;
  // kMove: the base's acceleration towards the velocity limit in the direction of travel (U18).
  double approach(const Headroom& headroom) const noexcept;
  void plan_halt() noexcept;  // kHalt: braking to standstill from the present state with the job's limits
  // kMove, kHalt: the acceleration of the cycle's sample (its last one, the step to the end, included)
  // beyond the acceleration or jerk headroom is cut to it (the state integrated from `before` with the cut
  // acceleration) and the profile replanned from there. Returns true when it cut.
  bool limit_acceleration(const MotionState& before, double dt, const Headroom& headroom) noexcept;

  // The source of the superimposed part: a profile (kMove, kHalt), or MC_MotionInSuperimposed's inputs of the
  // last call (kMotionIn: the absolute superimposition; no profile runs then, so they take no extra bytes).
  // The profile is kept as its inputs and two segments (running_profile.hpp, decision M12).
  std::variant<RunningProfile, MotionState> profile_;
  MotionState state_{};
  ProfileLimits limits_{};  // the job's: velocity = VelocityDiff
  double target_ = 0.0;     // kMove: the superimposed position to reach
  double time_ = 0.0;       // in the present profile
  double planned_velocity_ = 0.0;
  double folded_distance_ = 0.0;
  JobId id_ = 0;
  Job job_ = Job::kNone;
  bool planned_ = false;  // a profile is running
  // MC_HaltSuperimposed with AbortAcceleration: the next cycle takes the acceleration step the manual asks
  // for, outside the jerk headroom (U17). In the padding after planned_: no growth.
  bool abort_step_ = false;
};

}  // namespace tomc::techobjects
