// Drive-autonomous stop reactions of Safety Integrated (spec 01 §4 table, seed 004 §6.3.1, spec 01 §12
// scenario 19): STO coasts the drive (OFF2) -> technology alarm 421, reaction "remove enable"; SS1 brakes it
// on the OFF3 ramp -> alarm 550, reaction "follow setpoint" (the TO stays enabled and its setpoint tracks the
// braking drive), then STO -> 421. Once the safety function is deselected, MC_Reset acknowledges both and the
// axis, MC_Power.Enable held TRUE, enables again. Not 402: the alarm names the cause.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "positioning_axis_fixture.hpp"

namespace {

using namespace tomc;
namespace fixture = tomc::testing;
using drives::SimulatedDrive;
using techobjects::AlarmReaction;

bool pending(const fixture::PositioningAxisMachine& m, std::uint32_t number) {
  const auto a = m.axis->alarms().alarms();
  return std::any_of(a.begin(), a.end(), [&](const auto& p) { return p.number == number; });
}

// Enabled and moving at 200 mm/s (1200 1/min at the 10 mm leadscrew).
void moving(fixture::PositioningAxisMachine& m) {
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 200.0;
  m.move_velocity.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_velocity.InVelocity; }, 500), 0);
  m.run(20);
}

// MC_Reset once the drive is out of its safety function: the axis comes back with Enable held TRUE.
void acknowledge_and_reenable(fixture::PositioningAxisMachine& m) {
  m.reset.Execute = true;
  m.run(1);
  m.reset.Execute = false;
  EXPECT_GT(m.run_until([&] { return m.power.Status; }, 300), 0) << "enabled again (spec 01 §12 scenario 19)";
  EXPECT_TRUE(m.axis->alarms().alarms().empty());
  EXPECT_EQ(m.drive->state(), telegrams::DriveState::kS4Operation);
}

// spec 01 §4 (seed 004 §6.3.1: STO = OFF2 coast-down, alarm 421, reaction remove enable; re-enable only
// once STO is inactive).
TEST(DriveSafeStop, StoRaises421AndRemovesTheEnable) {
  fixture::PositioningAxisMachine m;
  moving(m);
  m.drive->select_safety_function(SimulatedDrive::SafetyFunction::kSto);
  // The drive's next actual frame shows OFF2 active; the TO raises 421 in the MC_Servo that reads it.
  const int cycles = m.run_until([&] { return pending(m, techobjects::kAlarmDriveSto); }, 5);
  EXPECT_GE(cycles, 1);
  EXPECT_LE(cycles, 2);
  EXPECT_EQ(m.db().ErrorDetail.Number, techobjects::kAlarmDriveSto);
  EXPECT_EQ(m.db().ErrorDetail.Reaction, static_cast<std::int32_t>(AlarmReaction::kRemoveEnable));
  m.run(2);
  EXPECT_FALSE(pending(m, techobjects::kAlarmDriveNotReady));
  EXPECT_FALSE(m.power.Status);
  EXPECT_TRUE(m.move_velocity.Error || m.move_velocity.CommandAborted) << "the job ended";
  EXPECT_EQ(m.drive->state(), telegrams::DriveState::kS1SwitchingOnInhibited);
  // Coasting: no braking torque, the load runs down on friction alone.
  EXPECT_DOUBLE_EQ(m.drive->motor_torque_nm(), 0.0);
  // Still selected: an MC_Reset does not bring the axis back (it stays disabled, Enable held TRUE).
  m.reset.Execute = true;
  m.run(1);
  m.reset.Execute = false;
  m.run(100);
  EXPECT_FALSE(m.power.Status);
  m.drive->select_safety_function(SimulatedDrive::SafetyFunction::kNone);
  m.run(5);
  acknowledge_and_reenable(m);
}

// spec 01 §4 (seed 004 §6.3.1: SS1 brakes on OFF3 then OFF2; alarm 550 with follow-up; keep MC_Power
// enabled until STO 421).
TEST(DriveSafeStop, Ss1Raises550FollowsTheBrakingDriveThenSto) {
  fixture::PositioningAxisMachine m;
  moving(m);
  m.drive->select_safety_function(SimulatedDrive::SafetyFunction::kSs1);
  const int cycles = m.run_until([&] { return pending(m, techobjects::kAlarmDriveSafeStop); }, 5);
  EXPECT_GE(cycles, 1);
  EXPECT_LE(cycles, 2);
  EXPECT_EQ(m.db().ErrorDetail.Reaction, static_cast<std::int32_t>(AlarmReaction::kFollowSetpoint));
  EXPECT_FALSE(pending(m, techobjects::kAlarmDriveSto));
  // OFF3 ramp p1135 = 0.2 s from 3000 1/min: 1200 1/min take 80 ms. Meanwhile the TO stays enabled and its
  // setpoint follows the actual position (no following error builds up, no 521).
  m.run(40);
  EXPECT_EQ(m.drive->state(), telegrams::DriveState::kS5bQuickStop);
  EXPECT_TRUE(m.power.Status) << "keep the TO enabled: the autonomous braking is not interrupted";
  EXPECT_NEAR(m.db().Position, m.db().ActualPosition, 1.0);
  EXPECT_LT(std::fabs(m.drive->motor_speed_rpm()), 1200.0 * 0.7);
  // At standstill SS1 switches the torque off: STO, alarm 421.
  EXPECT_GT(m.run_until([&] { return pending(m, techobjects::kAlarmDriveSto); }, 100), 0);
  EXPECT_FALSE(pending(m, techobjects::kAlarmDriveNotReady));
  EXPECT_FALSE(pending(m, techobjects::kAlarmFollowingError));
  m.drive->select_safety_function(SimulatedDrive::SafetyFunction::kNone);
  m.run(5);
  acknowledge_and_reenable(m);
}

// The TO's own stop reactions ask for OFF3 in STW1 (RemoveEnableReaction 16#7): that is no autonomous stop.
// spec 01 §4 (421/550 are for autonomous drive stops), spec 02 §3.1 (MC_Power StopMode 1 asks the drive for
// OFF3).
TEST(DriveSafeStop, TheTosOwnQuickStopIsNotASafeStop) {
  fixture::PositioningAxisMachine m;
  moving(m);
  m.power.Enable = false;
  m.power.StopMode = 1;  // the drive stops on its OFF3 ramp at the TO's request
  m.run(200);
  EXPECT_FALSE(pending(m, techobjects::kAlarmDriveSafeStop));
  EXPECT_FALSE(pending(m, techobjects::kAlarmDriveSto));
  m.power.Enable = true;
  EXPECT_GT(m.run_until([&] { return m.power.Status; }, 300), 0);
  m.run(20);
  EXPECT_TRUE(m.axis->alarms().alarms().empty());
}

}  // namespace
