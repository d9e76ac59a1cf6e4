#pragma once
// The motion laws of gearing (spec 07 §6): synchronization by dynamic parameters (MC_GearIn, §6.3), the
// leader-domain blend used to synchronize and desynchronize over a leading-value distance (MC_GearInPos
// profiles 1/3, MC_GearOut profile 1, §6.4, §6.7). Pure functions of the given states; noexcept, no
// allocation.

#include <array>
#include <cstddef>

#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::techobjects {

// One interpolator step of a velocity-tracking synchronization (spec 07 §6.3): from the follower state
// towards target velocity vT (and acceleration aT) with the acceleration limit while |v| grows and the
// deceleration limit while it shrinks; jerk 0 = trapezoid. `locked` when the target is met (then the state is
// exactly vT/aT); `position` is integrated.
struct SynchronizationStep {
  MotionState state{};
  bool locked = false;
};
SynchronizationStep synchronization_step(const MotionState& follower, double target_velocity,
                                         double target_acceleration, const ProfileLimits& limits,
                                         double cycle) noexcept;

// y(x) = Y(x) + d0·H0(ξ) + L·d1·H1(ξ) + L²·d2·H2(ξ), ξ = (x − x_a)/L ∈ [0, 1], with the straight target line
// Y(x) = y_target + k·(x − x_target) (spec 07 §6.4): position, slope and curvature match the follower at ξ =
// 0 and the line at ξ = 1, so there is no velocity or acceleration step at either end. L is signed (negative
// for a leader moving negative).
class LeaderDomainBlend {
 public:
  // Start at leader position x_a with leader velocity/acceleration (v_a, a_a) and the follower state.
  void start(double x_a, double length, double x_target, double y_target, double slope,
             const MotionState& follower, double leader_velocity, double leader_acceleration) noexcept;
  // The same blend onto any target function Y (camming, spec 07 §6.4): given Y, Y', Y'' at x_a, the blend
  // is only the deviation y − Y(x) (the line is 0); the caller adds the target's own state.
  void start_deviation(double x_a, double length, double target, double target_slope, double target_curvature,
                       const MotionState& follower, double leader_velocity,
                       double leader_acceleration) noexcept;
  // The follower at leader state (x, v_x, a_x). Beyond ξ = 1 the line itself.
  MotionState at(double x, double v_x, double a_x) const noexcept;
  // The follower's jerk at x for a leader at constant velocity v_x: d³y/dx³·v_x³ (the line and the
  // deviation's target add none: MC_GearInPos / MC_CamIn profile 0 blend onto a straight line, spec 07 §6.8).
  double jerk(double x, double v_x) const noexcept;
  // The leader positions inside the blend where, at a constant leader velocity, the follower's acceleration
  // (d³y/dx³ = 0: at most 2) or its jerk (the vertex of d³y/dx³) has an extremum, for checks between samples.
  std::size_t extrema(std::array<double, 3>& x) const noexcept;
  // Fraction of the leading-value distance covered (0 ... 1, clamped).
  double progress(double x) const noexcept;
  double line(double x) const noexcept { return y_target_ + slope_ * (x - x_target_); }

 private:
  void deviate(const MotionState& follower, double v_a, double a_a, double y, double dy, double ddy) noexcept;

  double x_a_ = 0.0;
  double length_ = 1.0;
  double x_target_ = 0.0;
  double y_target_ = 0.0;
  double slope_ = 1.0;
  double d0_ = 0.0;
  double d1_ = 0.0;
  double d2_ = 0.0;
};

}  // namespace tomc::techobjects
