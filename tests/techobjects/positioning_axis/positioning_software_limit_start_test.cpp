// spec 02 §4.5: software limit switches are monitored on the setpoint with a look-ahead; a motion that would
// pass a limit is decoupled and stopped at the limit position, and from the limit (or within one
// interpolator step of it) moving outwards raises 533 again. The look-ahead sees a new job only from its
// first setpoint on, so the stop must take effect in that same cycle: the setpoint never passes the limit
// (the first step of a trapezoid from standstill at the limit used to pass it by a·T²/2 and raise 534,
// removing the enable, instead of 533).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "positioning_axis_fixture.hpp"
#include "tomc/techobjects/axis/alarms.hpp"

namespace {

using tomc::testing::PositioningAxisMachine;

PositioningAxisMachine& at_the_limit(PositioningAxisMachine& m) {
  EXPECT_GT(m.enable(), 0);
  EXPECT_TRUE(m.home_at(0.0));
  m.move_absolute.Position = 300.0;
  m.move_absolute.Execute = true;
  EXPECT_GT(
      m.run_until([&] { return m.axis->alarms().pending(tomc::techobjects::kAlarmSoftwareLimitReached); },
                  5000),
      0);
  m.move_absolute.Execute = false;
  m.run(500);  // stopped at the limit
  EXPECT_NEAR(m.axis->setpoint().position, 200.0, 1e-9);
  m.reset.Execute = true;
  m.run(2);
  m.reset.Execute = false;
  m.run(1);
  EXPECT_EQ(m.db().ErrorWord, 0u);
  return m;
}

bool techobjects_enabled(const PositioningAxisMachine& m) {
  return tomc::techobjects::test(m.db().StatusWord, tomc::techobjects::StatusWordBit::kEnable);
}

tomc::techobjects::PositioningAxisData limited(double max_jerk) {
  auto d = tomc::testing::linear_axis_data();
  d.PositionLimits_SW.Active = true;
  d.PositionLimits_SW.MinPosition = -50.0;
  d.PositionLimits_SW.MaxPosition = 200.0;
  d.DynamicLimits.MaxJerk = max_jerk;
  return d;
}

// From standstill at MaxPosition, a trapezoid (first step a·T²/2 = 2.5 µm at 5000 mm/s²) and a jerk-limited
// MC_MoveRelative outwards: 533 again, the setpoint stays at the limit.
// spec 02 §4.5 (setpoint look-ahead: a motion that would pass the limit stops at it, alarm 533).
TEST(PositioningSoftwareLimit, AMotionStartingAtTheLimitDoesNotPassIt) {
  for (double jerk : {0.0, 100000.0}) {
    PositioningAxisMachine m(limited(jerk));
    at_the_limit(m);
    m.move_relative.Distance = 10.0;
    m.move_relative.Acceleration = 5000.0;
    m.move_relative.Execute = true;
    double highest = m.axis->setpoint().position;
    const int alarm = m.run_until(
        [&] {
          highest = std::max(highest, m.axis->setpoint().position);
          return m.axis->alarms().pending(tomc::techobjects::kAlarmSoftwareLimitReached);
        },
        100);
    ASSERT_GT(alarm, 0) << "MaxJerk " << jerk;
    m.run(200);
    highest = std::max(highest, m.axis->setpoint().position);
    EXPECT_LE(highest, 200.0) << "MaxJerk " << jerk;
    EXPECT_TRUE(m.move_relative.Error);
    EXPECT_NEAR(m.axis->setpoint().position, 200.0, 1e-12);
    EXPECT_EQ(m.db().Velocity, 0.0);
    EXPECT_FALSE(m.axis->alarms().pending(tomc::techobjects::kAlarmSoftwareLimitExceeded));
  }
}

// Moving clear from the limit (towards the work area) stays possible after MC_Reset (spec 02 §4.5).
TEST(PositioningSoftwareLimit, MovingClearFromTheLimitStillWorks) {
  PositioningAxisMachine m(limited(0.0));
  at_the_limit(m);
  m.move_relative.Distance = -10.0;
  m.move_relative.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 2000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 190.0, m.db().PositioningMonitoring.Window);
  EXPECT_EQ(m.db().ErrorWord, 0u);
}

}  // namespace

namespace {

// spec 02 §4.5 with a jerk-limited profile: the look-ahead has to foresee the next setpoint as the profile
// produces it. Extrapolated with constant acceleration, a rising acceleration (jerk 1e5 mm/s³, +100 mm/s²
// per cycle) was missed by one cycle: the stop began too late and the setpoint passed MaxPosition (by
// 0.23 mm from 179.46 mm towards 266 mm). From start positions across the whole acceleration phase, every
// approach stops at the limit with the setpoint continuous (|dv/dt| <= MaxDeceleration) and no 534.
TEST(PositioningSoftwareLimit, AJerkLimitedApproachStopsAtTheLimit) {
  for (double start = 170.0; start < 190.0; start += 0.37) {
    PositioningAxisMachine m(limited(100000.0));
    ASSERT_GT(m.enable(), 0);
    ASSERT_TRUE(m.home_at(start));
    m.run(20);
    m.move_absolute.Position = 266.0;
    m.move_absolute.Velocity = 500.0;
    m.move_absolute.Acceleration = 4887.67;
    m.move_absolute.Execute = true;
    double highest = m.axis->setpoint().position;
    double steepest = 0.0;
    double v_before = m.db().Velocity;
    m.run_until(
        [&] {
          highest = std::max(highest, m.axis->setpoint().position);
          steepest = std::max(steepest, std::fabs(m.db().Velocity - v_before) / 0.001);
          v_before = m.db().Velocity;
          return m.axis->alarms().pending(tomc::techobjects::kAlarmSoftwareLimitReached) &&
                 m.db().Velocity == 0.0;
        },
        2000);
    EXPECT_LE(highest, 200.0 + 1e-9) << "from " << start;
    EXPECT_LE(steepest, 5000.0 * (1 + 1e-9)) << "from " << start;
    EXPECT_TRUE(m.axis->alarms().pending(tomc::techobjects::kAlarmSoftwareLimitReached)) << "from " << start;
    EXPECT_FALSE(m.axis->alarms().pending(tomc::techobjects::kAlarmSoftwareLimitExceeded))
        << "from " << start;
    EXPECT_TRUE(techobjects_enabled(m)) << "from " << start;
  }
}

}  // namespace
