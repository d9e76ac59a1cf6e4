// RunningProfile (decision M12): a running job keeps the plan's inputs and two segments instead of the whole
// plan; every state it gives must be the planner's, bit for bit (the axis' setpoints may not change with the
// storage). Checked on the spec 01 §8.7 trapezoid and on random plans from random start states, with the
// interpolator's time running forward (advance_to), the software-limit look-ahead one cycle further (at) and
// looks back (at, any t).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

#include "tomc/techobjects/motion/profiles.hpp"
#include "tomc/techobjects/motion/running_profile.hpp"

namespace {

using tomc::techobjects::MotionState;
using tomc::techobjects::PositionProfile;
using tomc::techobjects::ProfileLimits;
using tomc::techobjects::RunningProfile;
using tomc::techobjects::VelocityProfile;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kRandomCases = 1'000;  // per planner; ASan+UBSan at -O0
#else
constexpr int kRandomCases = 10'000;
#endif

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

::testing::AssertionResult same_state(const MotionState& a, const MotionState& b, double t) {
  if (same_bits(a.position, b.position) && same_bits(a.velocity, b.velocity) &&
      same_bits(a.acceleration, b.acceleration)) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "t " << t << ": kept " << a.position << " / " << a.velocity << " / " << a.acceleration
         << ", planner " << b.position << " / " << b.velocity << " / " << b.acceleration;
}

// The interpolator's walk: t += dt from 0 to past the end; at each t the kept profile's advance_to(t) and
// at(t + dt) (the look-ahead) and at(t / 2) (a look back) against the planner's at().
template <typename Planner>
::testing::AssertionResult walk(const Planner& plan, const RunningProfile& adopted, double dt) {
  RunningProfile running = adopted;
  const double end = plan.duration() + 3 * dt;
  int steps = 0;
  for (double t = 0.0; t <= end && steps < 200'000; t += dt, ++steps) {
    if (auto r = same_state(running.advance_to(t), plan.at(t), t); !r) return r;
    if (auto r = same_state(running.at(t + dt), plan.at(t + dt), t + dt); !r) return r;
    if (steps % 16 == 0) {  // a look back plans a temporary: not every step
      if (auto r = same_state(running.at(t / 2), plan.at(t / 2), t / 2); !r) return r;
    }
  }
  if (running.duration() != plan.duration()) return ::testing::AssertionFailure() << "duration";
  return ::testing::AssertionSuccess();
}

// Spec 01 §8.7: the rest-to-rest trapezoid D = 100, v = 50, a = 100, d = 200 (jerk 0): 3 segments, 2.375 s;
// and the same with jerk 1000 (7 segments: each acceleration change rounded), walked at 1 ms.
TEST(RunningProfile, TrapezoidAndJerkLimitedPositioningAsPlanned) {
  for (const double jerk : {0.0, 1000.0}) {
    const ProfileLimits limits{50.0, 100.0, 200.0, jerk};
    PositionProfile plan;
    ASSERT_TRUE(plan.plan(MotionState{}, 100.0, limits));
    EXPECT_EQ(plan.segments().size(), jerk == 0.0 ? 3u : 7u);
    if (jerk == 0.0) {
      EXPECT_NEAR(plan.duration(), 2.375, 1e-12);
    }
    RunningProfile running;
    running.adopt(plan, MotionState{}, 100.0, limits);
    EXPECT_EQ(running.kind(), RunningProfile::Kind::kPosition);
    EXPECT_TRUE(walk(plan, running, 0.001)) << "jerk " << jerk;
  }
}

// A velocity change through zero with the jerk limited, from a start acceleration above the limit (spec 01
// §8.7, §8.8: from 40 with a0 = 150 to -30): 5 segments, so the kept two are planned again twice on the way.
TEST(RunningProfile, VelocityChangeThroughZeroAsPlanned) {
  const ProfileLimits limits{50.0, 100.0, 200.0, 2000.0};
  const MotionState start{5.0, 40.0, 150.0};
  VelocityProfile plan;
  ASSERT_TRUE(plan.plan(start, -30.0, limits));
  EXPECT_EQ(plan.segments().size(), 5u);
  RunningProfile running;
  running.adopt(plan, start, -30.0, limits);
  EXPECT_EQ(running.kind(), RunningProfile::Kind::kVelocity);
  EXPECT_TRUE(walk(plan, running, 0.001));
  EXPECT_TRUE(walk(plan, running, 0.00025));
}

// Random plans from random states (|v0| and |a0| up to twice the limits, jerk 0 in 30 % of the cases, limits
// over several orders of magnitude), walked at a random interpolator cycle of 0.25…8 ms. Decision M12: the
// kept segments and every re-plan give the planner's states bit for bit.
TEST(RunningProfile, RandomPlansAsPlanned) {
  std::mt19937_64 random(0x4D12'0001);
  const auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  const auto log_uniform = [&](double lo, double hi) {
    return std::exp(uniform(std::log(lo), std::log(hi)));
  };
  for (int i = 0; i < kRandomCases; ++i) {
    ProfileLimits l;
    l.velocity = log_uniform(1e-2, 1e3);
    l.acceleration = l.velocity / log_uniform(1e-3, 1e1);
    l.deceleration = uniform(0, 1) < 0.2 ? l.acceleration : l.velocity / log_uniform(1e-3, 1e1);
    l.jerk = uniform(0, 1) < 0.3 ? 0.0 : std::max(l.acceleration, l.deceleration) / log_uniform(1e-3, 1e0);
    MotionState start;
    start.position = uniform(-1e3, 1e3);
    start.velocity = uniform(0, 1) < 0.2 ? 0.0 : uniform(-2, 2) * l.velocity;
    start.acceleration =
        uniform(0, 1) < 0.4 ? 0.0 : uniform(-2, 2) * std::max(l.acceleration, l.deceleration);
    // The interpolator cycle, at most 2,000 steps per plan (the long plans of slow limits walk coarser).
    const auto cycle = [&](double duration) {
      return std::max(log_uniform(0.00025, 0.008), duration / 2000);
    };
    if (i % 2 == 0) {
      const double target = uniform(-2, 2) * l.velocity;
      VelocityProfile plan;
      ASSERT_TRUE(plan.plan(start, target, l)) << "case " << i;
      RunningProfile running;
      running.adopt(plan, start, target, l);
      ASSERT_TRUE(walk(plan, running, cycle(plan.duration()))) << "velocity case " << i;
    } else {
      const double target = start.position + uniform(-1, 1) * l.velocity * log_uniform(1e-3, 1e1);
      PositionProfile plan;
      ASSERT_TRUE(plan.plan(start, target, l)) << "case " << i;
      RunningProfile running;
      running.adopt(plan, start, target, l);
      ASSERT_TRUE(walk(plan, running, cycle(plan.duration()))) << "position case " << i;
    }
  }
}

// The storage it replaces: a variant of both planners (480 bytes) in the positioning axis and in its
// superimposed motion (decision M12).
TEST(RunningProfile, KeepsLessThanAPlan) {
  EXPECT_LE(sizeof(RunningProfile), 192u);
  EXPECT_LT(sizeof(RunningProfile), sizeof(VelocityProfile));
  EXPECT_LT(sizeof(RunningProfile), sizeof(PositionProfile));
}

}  // namespace
