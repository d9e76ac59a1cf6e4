// TO_SpeedAxis: a restart with a changed Simulation.Mode (decision B8). Simulation.Mode is RES (seed 004
// §10.2.2, §6.1.7 "can be changed while the user program runs"): a start value written before MC_Reset
// Restart = TRUE decides whether the axis uses its drive after the restart. Simulated drive on telegram 2.
#include <gtest/gtest.h>

#include "speed_axis_fixture.hpp"
#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/telegrams/drive_state.hpp"

namespace {

using tomc::testing::SpeedAxisMachine;
namespace tt = tomc::techobjects;
namespace tg = tomc::telegrams;

tt::SpeedAxisData trapezoid_data(std::uint32_t simulation = tt::kModeOff) {
  tt::SpeedAxisData d;
  d.DynamicLimits.MaxJerk = 0.0;
  d.Simulation.Mode = simulation;
  return d;
}

bool restart(SpeedAxisMachine& m) {
  m.power.Enable = false;
  EXPECT_GT(m.run_until([&] { return !m.power.Busy; }, 2000), 0);
  m.reset.Restart = true;
  m.reset.Execute = true;
  m.run(2);
  const bool done = m.reset.Done;
  m.reset.Execute = false;
  m.reset.Restart = false;
  m.run(1);
  return done;
}

// 600 1/min (10 1/s) at 100 1/s²: InVelocity after 0.1 s, 100 cycles and the call's (spec 01 §8.7, as the
// virtual axis of speed_axis_test.cpp).
int run_at_600(SpeedAxisMachine& m) {
  m.move.Velocity = 600.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  return m.run_until([&] { return m.move.InVelocity; }, 10000);
}

// 0 -> 1 (seed 004 §6.1.7: no setpoint to the drive; MC_Power enables at once): after the restart the axis
// runs at 600 1/min in the data block (the setpoint taken as the actual value, spec 01 §2.6) while the drive,
// asked to stay off, never reaches S4 and its motor stands; StatusWord.X25 AxisSimulation.
TEST(SpeedAxisSimulationRestart, RealToSimulatedAndBack) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 2);  // through the drive's state machine
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 1).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_TRUE(tt::test(m.axis->data().StatusWord, tt::StatusWordBit::kAxisSimulation));
  EXPECT_EQ(m.axis->drive(), nullptr);
  EXPECT_EQ(m.enable(), 2);
  EXPECT_EQ(run_at_600(m), 101);
  m.run(1);
  EXPECT_DOUBLE_EQ(m.axis->data().ActualSpeed, 600.0);
  EXPECT_NE(m.drive->state(), tg::DriveState::kS4Operation);
  EXPECT_EQ(m.drive->motor_speed_rpm(), 0.0);
  EXPECT_EQ(m.drive->active_fault(), 0u);  // the link ran on: no sign-of-life fault

  // 1 -> 0: the drive is used again, the actual speed is the drive's.
  m.move.Execute = false;
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 0).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_FALSE(tt::test(m.axis->data().StatusWord, tt::StatusWordBit::kAxisSimulation));
  ASSERT_NE(m.axis->drive(), nullptr);
  EXPECT_GT(m.enable(), 2);
  EXPECT_EQ(m.drive->state(), tg::DriveState::kS4Operation);
  EXPECT_GT(run_at_600(m), 0);
  m.run(200);
  EXPECT_NEAR(m.drive->motor_speed_rpm(), 600.0, 1.0);
  EXPECT_NEAR(m.axis->data().ActualSpeed, m.drive->motor_speed_rpm(), 1.0);
  EXPECT_TRUE(m.axis->alarms().alarms().empty());
}

// Seed 004 §6.1.7 "at the end of the simulation a valid drive integration must be present": a speed axis
// built without a drive stays simulated; the restart that would end the simulation is alarm 102 (additional
// value 1, ErrorWord.X1 ConfigFault) and the axis cannot be enabled until a restart with Simulation.Mode 1.
TEST(SpeedAxisSimulationRestart, EndingTheSimulationWithoutADriveIsARestartError) {
  SpeedAxisMachine m(2, trapezoid_data(tt::kModeOn), {}, false);
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 0).ok());
  ASSERT_TRUE(restart(m));
  const auto& alarms = m.axis->alarms().alarms();
  ASSERT_EQ(alarms.size(), 1u);
  EXPECT_EQ(alarms[0].number, tt::kAlarmConfiguration);
  EXPECT_EQ(alarms[0].additional_value, tt::kConfigurationNoDrive);
  EXPECT_TRUE((m.axis->data().ErrorWord >> static_cast<unsigned>(tt::ErrorWordBit::kConfigFault)) & 1u);
  EXPECT_EQ(m.axis->data().Simulation.Mode, 1u);
  EXPECT_TRUE(tt::test(m.axis->data().StatusWord, tt::StatusWordBit::kOnlineStartValuesChanged));
  m.power.Enable = true;
  m.run(50);
  EXPECT_FALSE(m.power.Status);
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 1).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_TRUE(m.axis->alarms().alarms().empty());
  EXPECT_EQ(m.enable(), 2);
}

}  // namespace
