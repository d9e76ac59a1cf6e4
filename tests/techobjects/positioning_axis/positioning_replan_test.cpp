// Seed 004 §6.7.7 (spec 01 §8.8, spec 03 §4.5 note) with decision S4 as re-decided in issue 23: a
// jerk-limited job that replaces the active one carries the current acceleration over to its own "tramite lo
// strappo", through its own jerk j, so the velocity moves on by a0²/(2j) before it turns, past the velocity
// limit if the state says so (the manual's "movimento imprevisto"; its remedy is the user's: a job without
// jerk limit or a higher jerk). The jerk is never raised (before issue 23 the velocity limit won and the jerk
// was raised: the two tests that showed that expected the old S4). A ramp to standstill never reverses
// (decision R1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "positioning_axis_fixture.hpp"
#include "tomc/techobjects/axis/alarms.hpp"

namespace {

using tomc::testing::PositioningAxisMachine;

// Job 1: 500 mm/s, 5000 mm/s², jerk 1e5 mm/s³: a = 5000 from v = 125 mm/s (0.05 s) on. Replaced at v0 ≥ 300
// mm/s (a0 = 5000) by job 2 with half that jerk (as A2 of §6.7.7): v peaks at v0 + a0²/(2j) = v0 + 250 mm/s,
// above the 500 mm/s limit (before issue 23: jerk raised to a0²/(2(500 − v0)), peak 500), and every
// cycle's acceleration step stays within j·T.
TEST(PositioningReplan, AReplacingJobKeepsItsJerkPastTheVelocityLimit) {
  PositioningAxisMachine m;  // v_limit 500 mm/s, MaxJerk 0: job jerks as given
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 2000.0;
  m.move_relative.Velocity = 500.0;
  m.move_relative.Acceleration = 5000.0;
  m.move_relative.Deceleration = 5000.0;
  m.move_relative.Jerk = 100000.0;
  m.move_relative.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.db().Velocity >= 300.0; }, 500), 0);
  const double v0 = m.db().Velocity;
  const double a0 = m.db().Acceleration;
  ASSERT_NEAR(a0, 5000.0, 1e-6);
  m.move_relative2.Distance = 1000.0;
  m.move_relative2.Velocity = 450.0;
  m.move_relative2.Acceleration = 5000.0;
  m.move_relative2.Deceleration = 5000.0;
  m.move_relative2.Jerk = 50000.0;
  m.move_relative2.Execute = true;
  const double cycle = tomc::testing::linear_drive().servo_cycle_s;
  double fastest = v0, steepest = 0.0, previous_a = a0;
  const int done = m.run_until(
      [&] {
        fastest = std::max(fastest, std::fabs(m.db().Velocity));
        steepest = std::max(steepest, std::fabs(m.db().Acceleration - previous_a));
        previous_a = m.db().Acceleration;
        return m.move_relative2.Done || m.move_relative2.Error;
      },
      20000);
  ASSERT_GT(done, 0);
  EXPECT_TRUE(m.move_relative2.Done);
  EXPECT_LE(steepest, 50000.0 * cycle * (1 + 1e-9));
  // Job 2 starts in the next MC_Interpolator (decision S5), after one more cycle of job 1 (+a0·T); the peak
  // lies between two cycles: sampled within j·T²/8 of that v0 + a0·T + a0²/(2j).
  EXPECT_NEAR(fastest, v0 + a0 * cycle + 250.0, 50000.0 * cycle * cycle / 8 + 1e-9) << "from v0 " << v0;
  EXPECT_GT(fastest, 500.0);
}

}  // namespace

namespace {

// A braking state: MC_Halt with 5000 mm/s² and a steep jerk from 400 mm/s, taken when v <= 100 mm/s; the
// deceleration is still 5000 mm/s², enough to carry v through zero with any jerk below a0²/(2 v0).
void brake_hard_to_100(PositioningAxisMachine& m) {
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 400.0;
  m.move_velocity.Acceleration = 5000.0;
  m.move_velocity.Execute = true;
  m.run(500);
  m.halt.Deceleration = 5000.0;
  m.halt.Jerk = 1.0e6;
  m.halt.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.db().Velocity <= 100.0; }, 1000), 0);
  m.halt.Execute = false;
  m.run(1);
  ASSERT_GT(m.db().Velocity, 50.0);
  ASSERT_LT(m.db().Acceleration, -4999.0);
}

// spec 02 §3.6, spec 01 §8.8, decision R1: a new MC_Halt with a jerk of 1000 mm/s³ from v0 = 92.5 mm/s and
// a0 = -5000 mm/s² would take a0²/(2j) = 12500 mm/s off the velocity before the deceleration is gone: the
// axis would reverse to beyond -500 mm/s (and trip 521). A stop to standstill does not reverse: the jerk is
// raised to a0²/(2 v0) so that v and a reach 0 together.
TEST(PositioningReplan, AHaltWithASofterJerkDoesNotReverse) {
  PositioningAxisMachine m;
  brake_hard_to_100(m);
  m.halt.Jerk = 1000.0;
  m.halt.Execute = true;
  double lowest = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  lowest = std::min(lowest, m.db().Velocity);
                  return m.halt.Done;
                },
                2000),
            0);
  EXPECT_GE(lowest, -1e-9);
  EXPECT_FALSE(m.axis->alarms().pending(tomc::techobjects::kAlarmFollowingError));
}

// The braking state (v0 ≈ 92.5 mm/s, a0 = −5000 mm/s²) replaced by a reversing MC_MoveVelocity to −200 mm/s
// with the halt's jerk 1e6 mm/s³: a0²/(2j) = 12.5 mm/s, so v passes zero still braking (S17: with a ≠ 0) and
// goes on to −200 mm/s without overshoot; the acceleration steps at most j·T per cycle.
// spec 01 §8.8 (job replacement with jerk), decisions S4 and S17 (the job's jerk kept through v = 0).
TEST(PositioningReplan, AReversalKeepsTheJobsJerk) {
  PositioningAxisMachine m;
  brake_hard_to_100(m);
  m.move_velocity.Execute = false;
  m.run(1);
  m.move_velocity.Velocity = -200.0;
  m.move_velocity.Jerk = 1.0e6;
  m.move_velocity.Execute = true;
  double fastest = 0.0, steepest = 0.0, previous_a = m.db().Acceleration;
  ASSERT_GT(m.run_until(
                [&] {
                  fastest = std::max(fastest, std::fabs(m.db().Velocity));
                  steepest = std::max(steepest, std::fabs(m.db().Acceleration - previous_a));
                  previous_a = m.db().Acceleration;
                  return m.move_velocity.InVelocity;
                },
                20000),
            0);
  EXPECT_LE(fastest, 200.0 + 1e-9);
  EXPECT_LE(steepest, 1.0e6 * tomc::testing::linear_drive().servo_cycle_s * (1 + 1e-9));
  EXPECT_NEAR(m.db().Velocity, -200.0, 1e-9);
  EXPECT_FALSE(m.axis->alarms().pending(tomc::techobjects::kAlarmFollowingError));
}

}  // namespace
