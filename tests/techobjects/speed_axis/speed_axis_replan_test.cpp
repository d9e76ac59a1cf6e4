// spec 01 §8.8 job replacement with a jerk limit, decisions S4 and R1, on the speed axis: a new MC_Halt with
// a much softer jerk than the braking ramp it replaces would carry the speed through zero by a0²/(2j) — here
// from 192 1/min under -80 1/s² with j = 2 1/s³ to about -96,000 1/min, 30 times MaxVelocity. A ramp to
// standstill does not reverse, and no ramp passes the velocity limit.
#include <gtest/gtest.h>

#include <algorithm>

#include "speed_axis_fixture.hpp"

namespace {

using tomc::testing::SpeedAxisMachine;

// Decision R1 of "Positioning axis: replanning" (a ramp to standstill replacing a braking one with a softer
// jerk: the jerk is raised so that v and a reach 0 together; a halt never reverses), spec 03 §4.4.
TEST(SpeedAxisReplan, AHaltWithASofterJerkDoesNotReverse) {
  SpeedAxisMachine m;
  m.power.Enable = true;
  m.run(50);
  m.move.Velocity = 1500.0;
  m.move.Execute = true;
  m.run(3000);
  const double dec = m.axis->data().DynamicLimits.MaxDeceleration;
  m.halt.Deceleration = dec;
  m.halt.Execute = true;  // braking with MaxJerk towards 0
  ASSERT_GT(m.run_until([&] { return m.axis->data().Velocity <= 200.0; }, 5000), 0);
  m.halt.Execute = false;
  m.run(1);
  ASSERT_GT(m.axis->data().Velocity, 100.0);
  ASSERT_LT(m.axis->data().Acceleration, -0.5 * dec);
  m.halt.Jerk = dec / 50.0;  // a replacing MC_Halt with a fiftieth of the jerk
  m.halt.Execute = true;
  double lowest = m.axis->data().Velocity;
  ASSERT_GT(m.run_until(
                [&] {
                  lowest = std::min(lowest, m.axis->data().Velocity);
                  return m.halt.Done;
                },
                20000),
            0);
  EXPECT_GE(lowest, -1e-9);
  EXPECT_EQ(m.axis->data().Velocity, 0.0);
}

}  // namespace
