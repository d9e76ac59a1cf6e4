// spec 01 §8.5: the effective velocity of a positioning job is min(v_cmd · Override, v_limit): the override
// applies before the limit clamp (the seed's examples 4 and 7 discriminate the order). On the default linear
// axis v_limit = min(DynamicLimits.MaxVelocity, DynamicLimits.Velocity) = 500 mm/s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "positioning_axis_fixture.hpp"

namespace {

using tomc::testing::PositioningAxisMachine;

// Runs a 1000 mm MC_MoveRelative at `velocity` under `override_percent` and returns the highest setpoint
// velocity (mm/s) on the way.
double cruise_velocity(double velocity, double override_percent) {
  PositioningAxisMachine m;
  EXPECT_GT(m.enable(), 0);
  EXPECT_TRUE(m.axis->write("Override.Velocity", override_percent).ok());
  m.move_relative.Distance = 1000.0;
  m.move_relative.Velocity = velocity;
  m.move_relative.Acceleration = 2000.0;
  m.move_relative.Deceleration = 2000.0;
  m.move_relative.Execute = true;
  double fastest = 0.0;
  EXPECT_GT(m.run_until(
                [&] {
                  fastest = std::max(fastest, std::fabs(m.db().Velocity));
                  return m.move_relative.Done || m.move_relative.Error;
                },
                6000),
            0);
  EXPECT_TRUE(m.move_relative.Done);
  EXPECT_NEAR(m.db().ActualPosition, 1000.0, m.db().PositioningMonitoring.Window);
  return fastest;
}

// Example 4 of spec 01 §8.5: v_cmd · Override above the limit runs at the limit, never above it (§8.3: the
// limits apply to every motion the TO generates).
TEST(PositioningVelocityOverride, OverrideAboveTheLimitRunsAtTheLimit) {
  EXPECT_NEAR(cruise_velocity(400.0, 200.0), 500.0, 1e-9);
  EXPECT_NEAR(cruise_velocity(400.0, 100.0), 400.0, 1e-9);
}

// Example 7 of spec 01 §8.5: a job velocity above the limit (600 > 500) at 50 % runs at 300, not at
// 50 % of the clamped 500.
TEST(PositioningVelocityOverride, OverrideAppliesBeforeTheLimitClamp) {
  EXPECT_NEAR(cruise_velocity(600.0, 50.0), 300.0, 1e-9);
}

// spec 01 §8.4: a change during the motion is effective at once, with the same order of override and clamp.
TEST(PositioningVelocityOverride, OverrideChangeDuringTheMoveIsClampedToo) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 1000.0;
  m.move_relative.Velocity = 300.0;
  m.move_relative.Acceleration = 2000.0;
  m.move_relative.Execute = true;
  m.run(500);
  EXPECT_NEAR(m.db().Velocity, 300.0, 1e-9);
  ASSERT_TRUE(m.axis->write("Override.Velocity", 200.0).ok());
  double fastest = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  fastest = std::max(fastest, std::fabs(m.db().Velocity));
                  return m.move_relative.Done;
                },
                6000),
            0);
  EXPECT_NEAR(fastest, 500.0, 1e-9);
}

}  // namespace
