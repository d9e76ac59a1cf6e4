// The motion laws of gearing (spec 07 §6.3, §6.4): the synchronization step and the leader-domain blend.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tomc/techobjects/synchronous/synchronous_motion.hpp"

namespace {

using namespace tomc::techobjects;

// spec 07 §6.3: with a constant leader and jerk 0, t_sync = |r·v_L − v0| / A and the follower covers
// (v0 + r·v_L)/2 · t_sync: from rest to 200 at 1000 -> 0.2 s (200 cycles of 1 ms), 20 mm.
TEST(SynchronousMotion, TrapezoidSynchronizationTimeAndDistance) {
  MotionState f{};
  int cycles = 0;
  for (; cycles < 1000; ++cycles) {
    const auto s = synchronization_step(f, 200.0, 0.0, ProfileLimits{1000.0, 1000.0, 1000.0, 0.0}, 0.001);
    f = s.state;
    if (s.locked) break;
  }
  EXPECT_EQ(cycles, 199);  // the 200th step lands on the target and locks
  EXPECT_NEAR(f.position, 20.0, 1e-9);
  EXPECT_EQ(f.velocity, 200.0);
}

// Deceleration governs steps that shrink |v| (Siemens semantics, spec 01 §8.1): 300 -> 100 at 2000 in 0.1 s.
TEST(SynchronousMotion, DecelerationLimitWhileSlowingDown) {
  MotionState f{0.0, 300.0, 0.0};
  int cycles = 0;
  for (; cycles < 1000; ++cycles) {
    const auto s = synchronization_step(f, 100.0, 0.0, ProfileLimits{1000.0, 500.0, 2000.0, 0.0}, 0.001);
    f = s.state;
    if (s.locked) break;
  }
  EXPECT_EQ(cycles + 1, 100);
}

// spec 07 §6.3 ("lim = A if |v| is to grow else D"): a step that brakes through standstill uses the
// deceleration only down to v = 0 and the acceleration from there. From −8.6 towards +18.6 with A 8000, D
// 10000, T 1 ms: 0.86 ms braking, then 0.14 ms at 8000 -> v = +1.12, a = +8000 (not +1.4 at 10000, which
// would exceed the acceleration limit while |v| grows; found by gearing_property_test).
TEST(SynchronousMotion, BrakingThroughStandstillAcceleratesWithTheAccelerationLimit) {
  const MotionState f{0.0, -8.6, -100.0};
  const auto s = synchronization_step(f, 18.6, 0.0, ProfileLimits{1000.0, 8000.0, 10000.0, 0.0}, 0.001);
  EXPECT_FALSE(s.locked);
  EXPECT_NEAR(s.state.velocity, 8000.0 * (0.001 - 8.6 / 10000.0), 1e-12);
  EXPECT_DOUBLE_EQ(s.state.acceleration, 8000.0);
  // Position: the braking triangle plus the accelerating one.
  EXPECT_NEAR(s.state.position, 0.5 * -8.6 * 0.00086 + 0.5 * 1.12 * 0.00014, 1e-12);
  // Reaching the target within the step: at it for the rest of the step, locked.
  const auto t = synchronization_step(MotionState{0.0, -1.0, 0.0}, 0.5, 0.0,
                                      ProfileLimits{1000.0, 8000.0, 10000.0, 0.0}, 0.001);
  EXPECT_TRUE(t.locked);
  EXPECT_DOUBLE_EQ(t.state.velocity, 0.5);
  const double t0 = 1.0 / 10000.0, t1 = 0.5 / 8000.0;
  EXPECT_NEAR(t.state.position, -0.5 * t0 + 0.5 * 0.5 * t1 + 0.5 * (0.001 - t0 - t1), 1e-12);
}

// spec 07 §6.8 (MC_GearIn synchronization: MaxVelocity) with a jerk limit and a start state from synchronous
// travel whose acceleration pushes |v| outward (found by gearing_property_test): the speed of a
// synchronization is limited (spec 07 §2.1), so the jerk is raised (unlike a replacing job, decision S4) and
// |v| stays within the limit; a |v| beyond it already does not grow.
TEST(SynchronousMotion, JerkLimitedStartFromSynchronousTravelKeepsTheVelocityLimit) {
  const ProfileLimits limits{600.0, 8000.0, 10000.0, 1.0e6};
  MotionState f{0.0, -569.656828, -23896.207};
  double worst = 0.0;
  bool locked = false;
  for (int i = 0; i < 5000 && !locked; ++i) {
    const auto s = synchronization_step(f, 296.0, 0.0, limits, 0.001);
    f = s.state;
    locked = s.locked;
    worst = std::max(worst, std::fabs(f.velocity));
  }
  EXPECT_TRUE(locked);
  EXPECT_LE(worst, 600.0 * (1.0 + 1e-9));  // without the raised jerk: about 855
  f = MotionState{0.0, -875.264092, -2463.541};
  const auto s = synchronization_step(f, -600.0, 0.0, limits, 0.001);
  EXPECT_LE(std::fabs(s.state.velocity), 875.264092);
}

// With a jerk limit the acceleration changes by at most jerk·T per cycle and is 0 at the lock.
// spec 07 §6.3 (synchronization with dynamic parameters, the jerk limit).
TEST(SynchronousMotion, JerkLimitedSynchronization) {
  MotionState f{};
  double previous_a = 0.0;
  bool locked = false;
  for (int i = 0; i < 5000 && !locked; ++i) {
    const auto s = synchronization_step(f, 100.0, 0.0, ProfileLimits{1000.0, 1000.0, 1000.0, 20000.0}, 0.001);
    EXPECT_LE(std::fabs(s.state.acceleration - previous_a), 20000.0 * 0.001 + 1e-9);
    EXPECT_LE(s.state.acceleration, 1000.0 + 1e-9);
    previous_a = s.state.acceleration;
    f = s.state;
    locked = s.locked;
  }
  EXPECT_TRUE(locked);
  EXPECT_EQ(f.velocity, 100.0);
}

// spec 07 §8 GP-1: start at x = 100 with the follower at rest at 0, line y = 50 + (x − 200), L = 100: y(150)
// = 9.375; position, slope and curvature continuous at both ends.
TEST(SynchronousMotion, LeaderDomainBlendGP1) {
  LeaderDomainBlend b;
  b.start(100.0, 100.0, 200.0, 50.0, 1.0, MotionState{0.0, 0.0, 0.0}, 100.0, 0.0);
  EXPECT_NEAR(b.at(100.0, 100.0, 0.0).position, 0.0, 1e-12);
  EXPECT_NEAR(b.at(100.0, 100.0, 0.0).velocity, 0.0, 1e-12);
  EXPECT_NEAR(b.at(150.0, 100.0, 0.0).position, 9.375, 1e-12);
  EXPECT_NEAR(b.at(150.0, 100.0, 0.0).velocity, 50.0, 1e-9);  // dF/dL = 0.5 at the midpoint
  const auto end = b.at(200.0, 100.0, 0.0);
  EXPECT_NEAR(end.position, 50.0, 1e-12);
  EXPECT_NEAR(end.velocity, 100.0, 1e-9);
  EXPECT_NEAR(end.acceleration, 0.0, 1e-9);
  EXPECT_NEAR(b.at(250.0, 100.0, 0.0).position, 100.0, 1e-12);
}

// A negative leader direction (signed L) and a moving follower at the start: no velocity step.
// spec 07 §6.4 (the leader-domain blend); decision Y5.
TEST(SynchronousMotion, LeaderDomainBlendNegativeDirection) {
  LeaderDomainBlend b;
  const MotionState f{10.0, -30.0, 0.0};
  b.start(0.0, -50.0, -50.0, -100.0, 2.0, f, -20.0, 0.0);
  const auto start = b.at(0.0, -20.0, 0.0);
  EXPECT_NEAR(start.position, 10.0, 1e-12);
  EXPECT_NEAR(start.velocity, -30.0, 1e-9);
  const auto end = b.at(-50.0, -20.0, 0.0);
  EXPECT_NEAR(end.position, -100.0, 1e-12);
  EXPECT_NEAR(end.velocity, -40.0, 1e-9);
}

}  // namespace
