// The dynamic filter on the positioning axis (spec 02 §7.6, §7.4 (1), spec 04 §3.22, §4.3, seed 004 §6.12.2,
// §6.13.6): StatusServo.PositionAfterDynamicFilter against the formulas, the following error with
// FollowingError.AdditionalSetpointDelayTime, virtual axes, the 16-cycle limit and DIR writes. Default linear
// axis on the simulated drive (mm, Kv 50 1/s, Kpc 100 %, T_vtc 2 ms), servo = interpolator = 1 ms.
// Timing: the servo of cycle k filters the setpoint the interpolator of cycle k − 1 produced, i.e. the data
// block's Position at the end of cycle k − 1.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>

#include "positioning_axis_fixture.hpp"

namespace {

using namespace tomc;
using tomc::testing::linear_axis_data;
using tomc::testing::linear_drive;
using tomc::testing::PositioningAxisMachine;

techobjects::PositioningAxisData filtered(std::int32_t mode, double t1, double t2, double tt) {
  auto d = linear_axis_data();
  d.SetpointFilter.DynamicFilter.Mode = mode;
  d.SetpointFilter.DynamicFilter.T1 = t1;
  d.SetpointFilter.DynamicFilter.T2 = t2;
  d.SetpointFilter.DynamicFilter.Tt = tt;
  return d;
}

// spec 02 §7.6 Mode 2, seed 004 §6.13.6.2: T1 = 4 ms at T_s = 1 ms averages the current value and the last 4:
// PositionAfterDynamicFilter(k) = (Position(k−1) + ... + Position(k−5)) / 5 throughout a 100 mm move.
TEST(DynamicFilterAxis, PositionAfterDynamicFilterIsTheMovingAverage) {
  PositioningAxisMachine m(filtered(2, 0.004, 0.0, 0.0));
  ASSERT_GT(m.enable(), 0);
  std::deque<double> positions;  // Position at the end of the previous cycles, newest first
  m.move_relative.Distance = 100.0;
  m.move_relative.Execute = true;
  int checked = 0;
  for (int k = 0; k < 1300; ++k) {
    positions.push_front(m.db().Position);
    if (positions.size() > 5) positions.pop_back();
    m.run(1);
    if (positions.size() == 5) {
      const double mean = (positions[0] + positions[1] + positions[2] + positions[3] + positions[4]) / 5.0;
      ASSERT_NEAR(m.db().StatusServo.PositionAfterDynamicFilter, mean, 1e-9) << k;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1290);
  ASSERT_TRUE(m.move_relative.Done);
  EXPECT_NEAR(m.db().ActualPosition, 100.0, m.db().PositioningMonitoring.Window);
  EXPECT_EQ(m.db().StatusServo.PositionAfterDynamicFilter, 100.0);
}

// Filter off (Mode 0, the default): PositionAfterDynamicFilter is the interpolator's setpoint of the cycle
// before.
// spec 02 §7.6 (Mode 0: no filter), spec 04 §4.3 (StatusServo.PositionAfterDynamicFilter).
TEST(DynamicFilterAxis, WithoutFilterTheSetpointPassesThrough) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 10.0;
  m.move_relative.Execute = true;
  for (int k = 0; k < 200; ++k) {
    const double before = m.db().Position;
    m.run(1);
    ASSERT_EQ(m.db().StatusServo.PositionAfterDynamicFilter, before) << k;
  }
}

// Following error at constant velocity (spec 02 §7.6, seed 004 §6.12.2): it is computed against the setpoint
// before the filter, so a PT1 of T1 = 5 ms adds v·T1 = 100 mm/s · 5 ms = 0.5 mm; with
// AdditionalSetpointDelayTime = T1 + T2 + Tt = 5 ms the following error is that of the axis without filter.
TEST(DynamicFilterAxis, AdditionalSetpointDelayTimeCompensatesTheFilterInTheFollowingError) {
  auto following_error_at_constant_velocity = [](const techobjects::PositioningAxisData& d) {
    PositioningAxisMachine m(d);
    EXPECT_GT(m.enable(), 0);
    m.move_relative.Distance = 100.0;
    m.move_relative.Velocity = 100.0;
    m.move_relative.Execute = true;
    m.run(600);  // 0.1 s acceleration, then 100 mm/s until 1.0 s
    return m.db().StatusPositioning.FollowingError;
  };
  const double plain = following_error_at_constant_velocity(linear_axis_data());
  auto d = filtered(1, 0.005, 0.0, 0.0);
  const double uncompensated = following_error_at_constant_velocity(d);
  d.FollowingError.AdditionalSetpointDelayTime = 0.005;
  const double compensated = following_error_at_constant_velocity(d);
  EXPECT_NEAR(plain, 100.0 * 0.002, 0.001);  // v·T_vtc with 100 % precontrol (position_control.hpp)
  EXPECT_NEAR(uncompensated, plain + 0.5, 0.001);
  EXPECT_NEAR(compensated, plain, 0.001);
  // Mode 2 with T1 = 10 ms lags 0.5·T1 = 5 ms: the same AdditionalSetpointDelayTime fits.
  auto ma = filtered(2, 0.010, 0.0, 0.0);
  ma.FollowingError.AdditionalSetpointDelayTime = 0.005;
  EXPECT_NEAR(following_error_at_constant_velocity(ma), plain, 0.001);
}

// The filter only delays and smooths: a positioning move with PT2 + dead time (T1 = T2 = 5 ms, Tt = 2 ms)
// still reaches its target, Done after the window; the interpolator's profile itself is unchanged (1100
// cycles).
// spec 02 §7.6 (the filter delays the setpoint; AdditionalSetpointDelayTime = T1 + T2 + Tt, decision P22)
// and §6.1 (Done after the positioning window).
TEST(DynamicFilterAxis, PositioningWithTheFilterReachesTheTarget) {
  auto d = filtered(1, 0.005, 0.005, 0.002);
  d.FollowingError.AdditionalSetpointDelayTime = 0.012;
  PositioningAxisMachine m(d);
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 100.0;
  m.move_relative.Velocity = 100.0;
  m.move_relative.Execute = true;
  int at_target = -1;  // cycles from the edge call (cycle 1), as in positioning_axis_test.cpp
  int done = -1;
  for (int k = 1; k <= 2000 && done < 0; ++k) {
    m.run(1);
    if (at_target < 0 && m.db().Position == 100.0) at_target = k;
    if (m.move_relative.Done) done = k;
  }
  EXPECT_EQ(at_target, 1 + 1100);
  ASSERT_GT(done, 1 + 1100 + 12);  // the actual value arrives at least the filter's 12 ms later
  EXPECT_NEAR(m.db().ActualPosition, 100.0, m.db().PositioningMonitoring.Window);
  EXPECT_NEAR(m.drive->load_position(), 100.0, m.db().PositioningMonitoring.Window);
  EXPECT_EQ(m.db().ErrorWord, 0u);
}

// Virtual axis (seed 004 §6.1.5: "the dynamic filter is active"): the actual value is the filtered setpoint.
// A 3 ms dead time: PositionAfterDynamicFilter(k) = Position(k − 4), and ActualPosition equals it.
TEST(DynamicFilterAxis, VirtualAxisTakesTheFilteredSetpoint) {
  auto d = filtered(1, 0.0, 0.0, 0.003);
  d.VirtualAxis.Mode = techobjects::kModeOn;
  PositioningAxisMachine m(d, linear_drive(), 3, false);
  m.power.Enable = true;
  m.run(2);
  ASSERT_TRUE(m.power.Status);
  std::deque<double> positions;
  m.move_relative.Distance = 10.0;
  m.move_relative.Execute = true;
  for (int k = 0; k < 300; ++k) {
    positions.push_front(m.db().Position);
    if (positions.size() > 4) positions.pop_back();
    m.run(1);
    if (positions.size() == 4) {
      ASSERT_NEAR(m.db().StatusServo.PositionAfterDynamicFilter, positions[3], 1e-9) << k;
    }
    ASSERT_EQ(m.db().ActualPosition, m.db().StatusServo.PositionAfterDynamicFilter) << k;
  }
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 500), 0);
  EXPECT_DOUBLE_EQ(m.db().ActualPosition, 10.0);
}

// spec 02 §7.6, §11 scenario 44: times above 16 servo cycles are limited without an error or alarm: T1 = 1 s
// at T_s = 1 ms acts as 16 ms.
TEST(DynamicFilterAxis, LongTimesAreLimitedWithoutAlarm) {
  PositioningAxisMachine m(filtered(2, 1.0, 0.0, 1.0));
  ASSERT_GT(m.enable(), 0);
  EXPECT_NEAR(m.axis->dynamic_filter().effective_T1(), 0.016, 1e-12);
  EXPECT_NEAR(m.axis->dynamic_filter().effective_Tt(), 0.016, 1e-12);
  m.move_relative.Distance = 20.0;
  m.move_relative.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 2000), 0);
  EXPECT_EQ(m.axis->alarms().alarms().size(), 0u);
  EXPECT_EQ(m.db().ErrorWord, 0u);
}

// spec 04 §3.22: T1, T2, Tt are DIR (the user program writes them and they act at once, without a step at
// standstill); Mode is RES (start value only, effective after a restart).
TEST(DynamicFilterAxis, TimesAreWritableModeNeedsARestart) {
  PositioningAxisMachine m(filtered(1, 0.002, 0.0, 0.0));
  ASSERT_GT(m.enable(), 0);
  m.run(20);
  const double standing = m.db().StatusServo.PositionAfterDynamicFilter;
  ASSERT_TRUE(m.axis->write("SetpointFilter.DynamicFilter.T1", 0.008).ok());
  ASSERT_TRUE(m.axis->write("SetpointFilter.DynamicFilter.Tt", 0.004).ok());
  m.run(5);
  EXPECT_EQ(m.db().StatusServo.PositionAfterDynamicFilter, standing);
  EXPECT_NEAR(m.axis->dynamic_filter().effective_delay(), 0.012, 1e-12);
  EXPECT_FALSE(m.axis->write("SetpointFilter.DynamicFilter.Mode", 2.0).ok());
  EXPECT_EQ(m.axis->dynamic_filter().config().Mode, 1);
}

}  // namespace
