// spec 01 §2.5, §2.6, spec 02 §3.1: a virtual or simulated axis has no drive: its actual value is its
// setpoint. When the TO follows the actual value (MC_Power Enable = FALSE with StopMode 1/3, alarm reaction
// "remove enable") nothing moves it any more: it stands at once, ActualVelocity 0 and StatusWord.X7
// Standstill, and MC_Power ends (Busy FALSE) so that it can be enabled again.
#include <gtest/gtest.h>

#include "positioning_axis_fixture.hpp"
#include "tomc/techobjects/axis/alarms.hpp"

namespace {

using tomc::testing::PositioningAxisMachine;

PositioningAxisMachine& moving_virtual_axis(PositioningAxisMachine& m) {
  m.power.Enable = true;
  EXPECT_GT(m.run_until([&] { return m.power.Status; }, 10), 0);
  m.move_velocity.Velocity = 50.0;
  m.move_velocity.Execute = true;
  EXPECT_GT(m.run_until([&] { return m.move_velocity.InVelocity; }, 500), 0);
  return m;
}

// A virtual axis (VirtualAxis.Mode) or a simulated one (Simulation.Mode: the setpoint delayed by the
// simulated control loop, spec 01 §2.6).
tomc::techobjects::PositioningAxisData virtual_data(bool simulation = false) {
  auto d = tomc::testing::linear_axis_data();
  (simulation ? d.Simulation.Mode : d.VirtualAxis.Mode) = tomc::techobjects::kModeOn;
  return d;
}

bool standstill(const PositioningAxisMachine& m) {
  return tomc::techobjects::test(m.db().StatusWord, tomc::techobjects::StatusWordBit::kStandstill);
}

// spec 01 §2.5/§2.6 and spec 02 §3.1 (a virtual or simulated axis following its actual value stands at
// once).
TEST(PositioningVirtualAxis, DisablingWithStopMode1EndsAtOnce) {
  for (int i = 0; i < 4; ++i) {
    const std::int16_t mode = i % 2 == 0 ? 1 : 3;
    PositioningAxisMachine m(virtual_data(i >= 2), tomc::testing::linear_drive(), 3, false);
    moving_virtual_axis(m);
    m.power.StopMode = mode;
    m.power.Enable = false;
    ASSERT_GT(m.run_until([&] { return !m.power.Busy; }, 100), 0) << "StopMode " << mode;
    m.run(1);  // the MC_Servo after the disable
    EXPECT_EQ(m.db().ActualVelocity, 0.0);
    const double stopped = m.db().ActualPosition;
    m.run(50);
    EXPECT_EQ(m.db().ActualPosition, stopped);
    EXPECT_TRUE(standstill(m));
    m.power.Enable = true;
    EXPECT_GT(m.run_until([&] { return m.power.Status; }, 10), 0);
  }
}

// spec 02 §3.1/§3.2: StopMode 0 brakes on the setpoint, then the TO is disabled and its setpoint follows the
// actual value. The actual value of a virtual or simulated axis lags its setpoint, so the TO is disabled once
// it has arrived: the position after disabling is where the braking ramp ended, no step back (a leader's step
// would pass to its followers).
TEST(PositioningVirtualAxis, DisablingWithStopMode0KeepsTheEndOfTheRamp) {
  for (bool simulation : {false, true}) {
    PositioningAxisMachine m(virtual_data(simulation), tomc::testing::linear_drive(), 3, false);
    moving_virtual_axis(m);
    m.power.StopMode = 0;
    m.power.Enable = false;
    double ramp_end = 0.0;
    ASSERT_GT(m.run_until(
                  [&] {
                    if (m.db().Velocity == 0.0 && ramp_end == 0.0) ramp_end = m.db().Position;
                    return !m.power.Busy;
                  },
                  500),
              0);
    m.run(20);
    EXPECT_DOUBLE_EQ(m.db().Position, ramp_end) << simulation;
    EXPECT_DOUBLE_EQ(m.db().ActualPosition, ramp_end) << simulation;
  }
}

// spec 02 §3.4 (reaction "remove enable") on a virtual/simulated axis (spec 01 §2.5, §2.6): standstill at
// once, MC_Reset recovers.
TEST(PositioningVirtualAxis, RemoveEnableStopsTheAxis) {
  for (bool simulation : {false, true}) {
    PositioningAxisMachine m(virtual_data(simulation), tomc::testing::linear_drive(), 3, false);
    moving_virtual_axis(m);
    ASSERT_TRUE(m.axis->inject_alarm(tomc::techobjects::kAlarmDriveFault, 0,
                                     tomc::techobjects::AlarmReaction::kRemoveEnable));
    ASSERT_GT(m.run_until([&] { return standstill(m); }, 100), 0);
    EXPECT_EQ(m.db().ActualVelocity, 0.0);
    m.reset.Execute = true;
    m.run(2);
    EXPECT_GT(m.run_until([&] { return m.power.Status; }, 10), 0);
  }
}

}  // namespace
