// TO_PositioningAxis on the simulated PROFIdrive drive, cycle by cycle (spec 02 §2–§7, spec 03 §3, §4.3–§4.6,
// spec 04 §5, §8). Unless a test says otherwise: the default linear axis of positioning_axis_data.hpp (mm,
// 10 mm/rev leadscrew, DynamicDefaults 100 mm/s and 1000 mm/s², positioning window 0.01 mm with a 10 ms
// dwell) with trapezoid profiles (MaxJerk 0), telegram 3, servo = interpolator = user program = 1 ms.
// Cycle accounting as in the speed-axis tests: a job submitted in the user program of cycle k moves from the
// interpolator of cycle k+1, so a profile of n interpolator cycles ends in the interpolator of cycle k+n.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <cmath>

#include "positioning_axis_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::ErrorWordBit;
using techobjects::StatusWordBit;
using techobjects::WarningWordBit;
using tomc::testing::linear_axis_data;
using tomc::testing::linear_drive;
using tomc::testing::PositioningAxisMachine;
namespace eid = techobjects::error_id;

bool status(const PositioningAxisMachine& m, StatusWordBit bit) {
  return techobjects::test(m.db().StatusWord, bit);
}
bool error_bit(const PositioningAxisMachine& m, ErrorWordBit bit) {
  return techobjects::test(m.db().ErrorWord, bit);
}

// spec 03 §4.1 StartMode 1: enabled with position control (StatusWord.X28 FALSE); StartMode 0 without.
TEST(PositioningAxis, PowerEnablesWithOrWithoutPositionControl) {
  PositioningAxisMachine m;
  const int cycles = m.enable();
  ASSERT_GT(cycles, 0);
  EXPECT_LE(cycles, 8);
  EXPECT_TRUE(status(m, StatusWordBit::kEnable));
  EXPECT_FALSE(status(m, StatusWordBit::kNonPositionControlled));
  EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));  // incremental encoder: not homed after power-up
  EXPECT_EQ(m.db().StatusSensor[0].State, static_cast<std::int32_t>(techobjects::SensorState::VALID));

  PositioningAxisMachine n;
  n.power.StartMode = 0;
  ASSERT_GT(n.enable(), 0);
  n.run(1);
  EXPECT_TRUE(status(n, StatusWordBit::kNonPositionControlled));
}

// spec 02 §2.2, spec 03 §4.6, §3.7 T-A: 100 mm at 100 mm/s and 1000 mm/s² is 0.1 s + 0.9 s + 0.1 s = 1100
// interpolator cycles; Done once the actual position has been inside the 0.01 mm window for MinDwellTime
// (10 ms = 10 servo cycles, spec 02 §6.1).
TEST(PositioningAxis, MoveRelativeTrapezoidAndDoneAfterTheWindow) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 100.0;
  m.move_relative.Velocity = 100.0;
  m.move_relative.Execute = true;
  m.run(1);  // edge: Busy and Active at once (spec 03 §3.2 E2)
  EXPECT_TRUE(m.move_relative.Busy);
  EXPECT_TRUE(m.move_relative.Active);
  m.run(1);
  EXPECT_TRUE(status(m, StatusWordBit::kPositioningCommand));
  EXPECT_FALSE(status(m, StatusWordBit::kDone));
  int setpoint_at_target = -1;
  int done_at = -1;
  // k counts cycles from the edge call (cycle 1); the profile's 1100 interpolator steps end in cycle 1101.
  for (int k = 3; k <= 1300 && done_at < 0; ++k) {
    m.run(1);
    if (setpoint_at_target < 0 && m.db().Position == 100.0) setpoint_at_target = k;
    if (m.move_relative.Done) done_at = k;
    EXPECT_LE(m.db().Velocity, 100.0 + 1e-9);
  }
  EXPECT_EQ(setpoint_at_target, 1 + 1100);
  ASSERT_GT(done_at, 1 + 1100 + 10);
  EXPECT_LT(done_at, 1 + 1100 + 40);
  EXPECT_NEAR(m.db().ActualPosition, 100.0, m.db().PositioningMonitoring.Window);
  EXPECT_FALSE(m.move_relative.Busy);
  m.run(1);
  EXPECT_TRUE(m.move_relative.Done);  // Execute still TRUE: Done stays (E5)
  EXPECT_TRUE(status(m, StatusWordBit::kDone));
  EXPECT_FALSE(status(m, StatusWordBit::kPositioningCommand));
  EXPECT_TRUE(status(m, StatusWordBit::kStandstill));
  m.move_relative.Execute = false;
  m.run(1);
  EXPECT_FALSE(m.move_relative.Done);
}

// spec 03 §4.5 prerequisites: absolute positioning needs a homed axis; MC_Home Mode 0 homes it (spec 02
// §5.7).
TEST(PositioningAxis, MoveAbsoluteNeedsAHomedAxis) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_absolute.Position = -50.0;
  m.move_absolute.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_absolute.Error);
  EXPECT_EQ(m.move_absolute.ErrorID, eid::kAxisNotHomed);
  m.move_absolute.Execute = false;
  m.run(1);
  ASSERT_TRUE(m.home_at(0.0));
  EXPECT_TRUE(status(m, StatusWordBit::kHomingDone));
  m.move_absolute.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_absolute.Done; }, 2000), 0);
  EXPECT_NEAR(m.db().ActualPosition, -50.0, 0.01);
  EXPECT_EQ(m.db().Position, -50.0);
}

// spec 02 §5.7, §5.8, spec 03 §4.3: Mode 0 sets, Mode 1 shifts the actual position; Modes 11/12 set/shift the
// setpoint and keep the following distance. No compensating motion: the setpoint moves with the actual value.
TEST(PositioningAxis, DirectHomingModesMoveActualAndSetpointTogether) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.run(50);
  const double following = m.db().Position - m.db().ActualPosition;
  m.home.Mode = 0;
  m.home.Position = 250.0;
  m.home.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.home.Done);
  EXPECT_DOUBLE_EQ(m.db().ActualPosition, 250.0);
  EXPECT_DOUBLE_EQ(m.home.ReferenceMarkPosition, 250.0);
  EXPECT_NEAR(m.db().Position - m.db().ActualPosition, following, 1e-9);
  m.home.Execute = false;
  m.run(1);
  m.home.Mode = 1;
  m.home.Position = -20.0;
  m.home.Execute = true;
  m.run(1);
  EXPECT_NEAR(m.db().ActualPosition, 230.0, 1e-6);
  m.home.Execute = false;
  m.run(1);
  m.home.Mode = 12;
  m.home.Position = 5.0;
  m.home.Execute = true;
  const double actual_before = m.db().ActualPosition;
  const double setpoint_before = m.db().Position;
  m.run(1);
  EXPECT_NEAR(m.db().Position, setpoint_before + 5.0, 1e-6);
  EXPECT_NEAR(m.db().ActualPosition, actual_before + 5.0, 1e-6);
  m.home.Execute = false;
  m.run(1);
  m.home.Mode = 11;
  m.home.Position = 0.0;
  m.home.Execute = true;
  m.run(1);
  EXPECT_NEAR(m.db().Position, 0.0, 1e-9);
  m.home.Execute = false;
  // The axis did not move: no following error built up, nothing ran away.
  m.run(100);
  EXPECT_NEAR(m.db().ActualPosition, 0.0, 0.01);
  EXPECT_LT(std::fabs(m.db().StatusPositioning.FollowingError), 0.01);
  EXPECT_EQ(m.db().ErrorWord, 0u);
}

// spec 03 §3.7 T-E, spec 02 §2.3: an appended job is Busy but not Active while the running one moves; it
// becomes Active in the cycle the running job is Done; the axis stops in between.
TEST(PositioningAxis, BufferModeAppendStartsWhenTheRunningJobIsDone) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_absolute.Position = 100.0;
  m.move_absolute.Execute = true;
  m.run(200);
  m.move_absolute2.Position = 150.0;
  m.move_absolute2.BufferMode = 1;
  m.move_absolute2.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_absolute.Busy);
  EXPECT_TRUE(m.move_absolute.Active);
  EXPECT_TRUE(m.move_absolute2.Busy);
  EXPECT_FALSE(m.move_absolute2.Active);
  const int done1 = m.run_until([&] { return m.move_absolute.Done; }, 2000);
  ASSERT_GT(done1, 0);
  EXPECT_TRUE(m.move_absolute2.Active);  // same cycle as Done_1 (spec 03 §4.5 diagram B)
  EXPECT_NEAR(m.db().ActualPosition, 100.0, 0.01);
  EXPECT_EQ(m.db().Velocity, 0.0);  // the axis stopped between the jobs
  ASSERT_GT(m.run_until([&] { return m.move_absolute2.Done; }, 2000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 150.0, 0.01);
  EXPECT_FALSE(m.move_absolute.CommandAborted);
}

// spec 03 §4.6: an appended MC_MoveRelative counts from the end of the job before it.
TEST(PositioningAxis, AppendedMoveRelativeCountsFromTheEndOfTheRunningJob) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 50.0;
  m.move_relative.Execute = true;
  m.run(100);
  m.move_relative2.Distance = 30.0;
  m.move_relative2.BufferMode = 1;
  m.move_relative2.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_relative2.Done; }, 3000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 80.0, 0.01);
  EXPECT_TRUE(m.move_relative.Done);
}

// spec 02 §2.3 BufferMode 0, spec 03 §6.1 R4 x C3 = A: the running job reports CommandAborted; the axis goes
// to the new target from its present state.
TEST(PositioningAxis, BufferModeAbortReplacesTheRunningJob) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_absolute.Position = 1000.0;
  m.move_absolute.Execute = true;
  m.run(300);
  m.move_absolute2.Position = 20.0;
  m.move_absolute2.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move_absolute.CommandAborted);
  EXPECT_TRUE(m.move_absolute2.Active);
  ASSERT_GT(m.run_until([&] { return m.move_absolute2.Done; }, 3000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 20.0, 0.01);
}

// spec 03 §6.1 R5 x C3 "-/N" [AMB-11]: nothing can be appended behind an endless MC_MoveVelocity.
TEST(PositioningAxis, AppendingBehindMoveVelocityIsRejected) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 50.0;
  m.move_velocity.Execute = true;
  m.run(10);
  m.move_relative.Distance = 10.0;
  m.move_relative.BufferMode = 1;
  m.move_relative.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_relative.Error);
  EXPECT_EQ(m.move_relative.ErrorID, eid::kRejectedByRunningJob);
  EXPECT_TRUE(m.move_velocity.Busy);
}

// spec 03 §2.1: Velocity 0.0 and BufferMode outside 0/1 are invalid for positioning jobs.
TEST(PositioningAxis, InvalidPositioningInputsAreRejected) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 10.0;
  m.move_relative.Velocity = 0.0;
  m.move_relative.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move_relative.ErrorID, eid::kInvalidVelocity);
  m.move_relative.Execute = false;
  m.run(1);
  m.move_relative.Velocity = -1.0;
  m.move_relative.BufferMode = 2;
  m.move_relative.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move_relative.ErrorID, eid::kInvalidBufferMode);
  m.move_relative.Execute = false;
  m.run(1);
  m.move_relative.BufferMode = 0;
  m.move_relative.Distance = std::nan("");
  m.move_relative.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move_relative.ErrorID, eid::kInvalidPosition);
  EXPECT_EQ(m.db().Position, 0.0);  // nothing moved
}

techobjects::PositioningAxisData rotary_modulo_data() {
  techobjects::PositioningAxisData d;
  d.Properties.MotionType = static_cast<std::int32_t>(techobjects::PropertiesMotionType::kRotary);
  d.Units.LengthUnit = techobjects::unit_code::kDegree;
  d.Units.VelocityUnit = techobjects::unit_code::kDegreePerSecond;
  d.Modulo.Enable = true;
  d.Modulo.Length = 360.0;
  d.Modulo.StartValue = 0.0;
  d.DynamicLimits.MaxVelocity = 3600.0;
  d.DynamicLimits.Velocity = 3600.0;
  d.DynamicLimits.MaxAcceleration = 36000.0;
  d.DynamicLimits.MaxDeceleration = 36000.0;
  d.DynamicLimits.MaxJerk = 0.0;
  d.DynamicDefaults.Velocity = 360.0;
  d.DynamicDefaults.Acceleration = 3600.0;
  d.DynamicDefaults.Deceleration = 3600.0;
  d.DynamicDefaults.EmergencyDeceleration = 36000.0;
  d.FollowingError.MinValue = 5.0;
  d.FollowingError.MaxValue = 50.0;
  d.FollowingError.MinVelocity = 36.0;
  d.PositioningMonitoring.Window = 0.05;
  d.StandstillSignal.VelocityThreshold = 3.0;
  return d;
}

drives::SimulatedDriveParameters rotary_drive() {
  drives::SimulatedDriveParameters p;
  p.load_units_per_revolution = 360.0;
  return p;
}

// spec 03 §4.5 Direction on a modulo axis, spec 01 §2.4: from 350° to 10° positively is +20° (the modulo
// cycle counts up), negatively −340°, the shortest path +20°. A target outside [0, 360) is rejected.
TEST(PositioningAxis, ModuloDirectionsAndTheModuloCycle) {
  struct Case {
    std::int16_t direction;
    double travel;
    std::int32_t cycle;
  };
  for (const Case c : {Case{1, 20.0, 0}, Case{2, -340.0, -1}, Case{3, 20.0, 0}}) {
    PositioningAxisMachine m(rotary_modulo_data(), rotary_drive());
    ASSERT_GT(m.enable(), 0);
    // Direct homing from 0° to 350° counts the shorter way, backwards: cycle -1 (spec 01 §2.4.1).
    ASSERT_TRUE(m.home_at(350.0));
    EXPECT_EQ(m.db().ActualModuloCycle, -1);
    m.move_absolute.Position = 10.0;
    m.move_absolute.Direction = c.direction;
    m.move_absolute.Execute = true;
    double lowest = 1e9;
    double highest = -1e9;
    const double start = m.axis->setpoint().position;
    const int done = m.run_until(
        [&] {
          lowest = std::min(lowest, m.axis->setpoint().position - start);
          highest = std::max(highest, m.axis->setpoint().position - start);
          return m.move_absolute.Done;
        },
        3000);
    ASSERT_GT(done, 0) << "Direction " << c.direction;
    EXPECT_NEAR(m.db().ActualPosition, 10.0, 0.05) << "Direction " << c.direction;
    EXPECT_NEAR(m.axis->setpoint().position - start, c.travel, 1e-9) << "Direction " << c.direction;
    EXPECT_NEAR(c.travel > 0 ? highest : lowest, c.travel, 1e-9);
    EXPECT_EQ(m.db().ModuloCycle, c.cycle) << "Direction " << c.direction;
    EXPECT_EQ(m.db().ActualModuloCycle, c.cycle) << "Direction " << c.direction;
  }
  PositioningAxisMachine m(rotary_modulo_data(), rotary_drive());
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_absolute.Position = 360.0;
  m.move_absolute.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move_absolute.ErrorID, eid::kInvalidPosition);
}

// spec 01 §2.4: a rotary modulo axis turning on shows positions in [0, 360) and counts its cycles.
TEST(PositioningAxis, ModuloPositionWrapsWhileTurning) {
  PositioningAxisMachine m(rotary_modulo_data(), rotary_drive());
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 1000.0;
  m.move_relative.Execute = true;
  bool wrapped_in_range = true;
  ASSERT_GT(m.run_until(
                [&] {
                  wrapped_in_range = wrapped_in_range && m.db().Position >= 0.0 && m.db().Position < 360.0 &&
                                     m.db().ActualPosition >= 0.0 && m.db().ActualPosition < 360.0;
                  return m.move_relative.Done;
                },
                5000),
            0);
  EXPECT_TRUE(wrapped_in_range);
  EXPECT_NEAR(m.db().ActualPosition, 280.0, 0.05);  // 1000 = 2 x 360 + 280
  EXPECT_EQ(m.db().ModuloCycle, 2);
  EXPECT_EQ(m.db().ActualModuloCycle, 2);
}

techobjects::PositioningAxisData software_limited_data() {
  auto d = linear_axis_data();
  d.PositionLimits_SW.Active = true;
  d.PositionLimits_SW.MinPosition = -50.0;
  d.PositionLimits_SW.MaxPosition = 200.0;
  return d;
}

// spec 02 §4.5, §1.3: the look-ahead stops the motion exactly at the software limit with alarm 533 (reaction
// 2, max dynamics; the TO stays enabled); the job ends with 16#8001; X16, ErrorWord.X8. After MC_Reset the
// axis moves back into the work area; moving out again raises 533 again.
TEST(PositioningAxis, SoftwareLimitStopsAtTheLimitPosition) {
  PositioningAxisMachine m(software_limited_data());
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_absolute.Position = 300.0;
  m.move_absolute.Execute = true;
  double highest = 0.0;
  const int alarm = m.run_until(
      [&] {
        highest = std::max(highest, m.axis->setpoint().position);
        return m.axis->alarms().pending(techobjects::kAlarmSoftwareLimitReached);
      },
      5000);
  ASSERT_GT(alarm, 0);
  EXPECT_TRUE(m.move_absolute.Error);
  EXPECT_EQ(m.move_absolute.ErrorID, eid::kAbortedByAlarmReaction);
  EXPECT_EQ(m.db().ErrorDetail.Number, techobjects::kAlarmSoftwareLimitReached);
  EXPECT_EQ(m.db().ErrorDetail.Reaction,
            static_cast<std::int32_t>(techobjects::AlarmReaction::kStopMaxDynamics));
  m.run_until(
      [&] {
        highest = std::max(highest, m.axis->setpoint().position);
        return m.db().Velocity == 0.0;
      },
      1000);
  m.run(50);
  EXPECT_NEAR(m.db().Position, 200.0, 1e-6);
  EXPECT_LE(highest, 200.0 + 1e-6);  // never past the limit
  EXPECT_NEAR(m.db().ActualPosition, 200.0, 0.05);
  EXPECT_TRUE(status(m, StatusWordBit::kSWLimitMaxActive));
  EXPECT_TRUE(error_bit(m, ErrorWordBit::kSWLimit));
  EXPECT_TRUE(status(m, StatusWordBit::kEnable));  // reaction 2 keeps the axis enabled

  // Acknowledge and move back (spec 02 §4.5 "moving clear").
  m.move_absolute.Execute = false;
  m.reset.Execute = true;
  m.run(2);
  m.reset.Execute = false;
  EXPECT_EQ(m.db().ErrorWord, 0u);
  m.move_absolute2.Position = 100.0;
  m.move_absolute2.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_absolute2.Done; }, 3000), 0);
  EXPECT_FALSE(status(m, StatusWordBit::kSWLimitMaxActive));
  // Out again: 533 again.
  m.move_absolute.Position = 250.0;
  m.move_absolute.Execute = true;
  ASSERT_GT(
      m.run_until([&] { return m.axis->alarms().pending(techobjects::kAlarmSoftwareLimitReached); }, 3000),
      0);
}

// spec 02 §4.5: software limits act only on a homed axis.
TEST(PositioningAxis, SoftwareLimitsNeedAHomedAxis) {
  PositioningAxisMachine m(software_limited_data());
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 300.0;
  m.move_relative.Velocity = 300.0;
  m.move_relative.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 3000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 300.0, 0.01);
  EXPECT_EQ(m.db().ErrorWord, 0u);
}

// spec 02 §4.2–§4.3: a non-passable hardware limit switch raises 531 in the servo cycle the input shows its
// active level; ApproachBehavior 0 removes the enable (the drive brakes with OFF3); X18, ErrorWord.X9. After
// MC_Reset the axis may move clear in the negative direction; X18 goes once the input is inactive.
TEST(PositioningAxis, HardwareLimitSwitchRemovesTheEnable) {
  auto d = linear_axis_data();
  d.PositionLimits_HW.Active = true;
  auto p = linear_drive();
  p.machine.positive_limit_switch = 150.0;
  PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 100.0;
  m.move_velocity.Execute = true;
  const int alarm =
      m.run_until([&] { return m.axis->alarms().pending(techobjects::kAlarmHardwareLimit); }, 3000);
  ASSERT_GT(alarm, 0);
  EXPECT_GE(m.drive->load_position(), 150.0);
  EXPECT_LT(m.drive->load_position(), 150.0 + 100.0 * 0.003);  // seen within a few cycles of reaching it
  EXPECT_TRUE(status(m, StatusWordBit::kHWLimitMaxActive));
  EXPECT_TRUE(error_bit(m, ErrorWordBit::kHWLimit));
  EXPECT_EQ(m.db().ErrorDetail.Reaction,
            static_cast<std::int32_t>(techobjects::AlarmReaction::kRemoveEnable));
  EXPECT_TRUE(m.move_velocity.Error);
  EXPECT_FALSE(m.power.Status);
  m.run(500);  // OFF3 ramp of the drive
  EXPECT_TRUE(status(m, StatusWordBit::kStandstill));
  // Acknowledge: the TO re-enables (Enable stayed TRUE, spec 03 §3.3 L2), then jog clear.
  m.move_velocity.Execute = false;
  m.reset.Execute = true;
  m.run(2);
  m.reset.Execute = false;
  ASSERT_GT(m.run_until([&] { return m.power.Status; }, 200), 0);
  m.jog.JogBackward = true;
  m.jog.Velocity = 20.0;
  ASSERT_GT(m.run_until([&] { return !status(m, StatusWordBit::kHWLimitMaxActive); }, 3000), 0);
  EXPECT_LT(m.drive->load_position(), 150.0);
  EXPECT_FALSE(m.axis->alarms().pending(techobjects::kAlarmHardwareLimit));
}

// spec 02 §6.2: a following error above the permitted value raises 521 (remove enable), ErrorWord.X11. A
// drive that cannot produce the torque for the programmed acceleration falls behind.
TEST(PositioningAxis, FollowingErrorAboveTheLimitRemovesTheEnable) {
  auto d = linear_axis_data();
  d.DynamicLimits.MaxAcceleration = 50000.0;
  d.DynamicLimits.MaxDeceleration = 50000.0;
  auto p = linear_drive();
  p.torque_limit_nm = 0.2;
  PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 400.0;
  m.move_relative.Velocity = 400.0;
  m.move_relative.Acceleration = 40000.0;
  m.move_relative.Execute = true;
  const int alarm =
      m.run_until([&] { return m.axis->alarms().pending(techobjects::kAlarmFollowingError); }, 2000);
  ASSERT_GT(alarm, 0);
  EXPECT_TRUE(error_bit(m, ErrorWordBit::kFollowingErrorFault));
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmFollowingErrorWarning));  // 522 came first
  EXPECT_TRUE(techobjects::test(m.db().WarningWord, WarningWordBit::kFollowingErrorWarning));
  EXPECT_EQ(m.db().ErrorDetail.Reaction,
            static_cast<std::int32_t>(techobjects::AlarmReaction::kRemoveEnable));
  EXPECT_FALSE(m.power.Status);
}

// spec 02 §6.1: a target the axis cannot reach (a fixed stop 0.5 mm before it) raises 541 with additional
// value 1 once ToleranceTime (1 s) has passed after the end of interpolation; ErrorWord.X12.
TEST(PositioningAxis, PositioningMonitoringToleranceTime) {
  auto p = linear_drive();
  p.machine.positive_fixed_stop = 99.5;
  PositioningAxisMachine m(linear_axis_data(), p);
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 100.0;
  m.move_relative.Execute = true;
  int end_of_interpolation = -1;
  const int alarm = m.run_until(
      [&] {
        if (end_of_interpolation < 0 && m.db().Position == 100.0)
          end_of_interpolation = m.runtime.clock().servo_cycles;
        return m.axis->alarms().pending(techobjects::kAlarmPositioning);
      },
      4000);
  ASSERT_GT(alarm, 0);
  ASSERT_GT(end_of_interpolation, 0);
  // Monitoring starts (elapsed 0) in the servo cycle after the last interpolation step; the alarm comes in
  // the first cycle with elapsed > ToleranceTime = 1000 cycles, i.e. 1 + 1001 cycles after that step.
  EXPECT_EQ(static_cast<int>(m.runtime.clock().servo_cycles) - end_of_interpolation, 1 + 1001);
  EXPECT_EQ(m.axis->alarms().alarms()[0].additional_value, techobjects::kPositioningTargetNotReached);
  EXPECT_TRUE(error_bit(m, ErrorWordBit::kPositioningFault) ||
              m.axis->alarms().pending(techobjects::kAlarmPositioning));
  m.run(1);
  EXPECT_TRUE(error_bit(m, ErrorWordBit::kPositioningFault));
  EXPECT_TRUE(m.move_relative.Error);
  EXPECT_EQ(m.move_relative.ErrorID, eid::kAbortedByAlarmReaction);
}

// spec 02 §3.6, spec 03 §4.4: MC_Halt aborts the positioning job and is Done at standstill; StatusWord.X6
// follows after the positioning window at the stop position (spec 04 §8 rule 2).
TEST(PositioningAxis, HaltStopsAPositioningMove) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 500.0;
  m.move_relative.Execute = true;
  m.run(300);
  m.halt.Deceleration = 500.0;
  m.halt.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.halt.Busy);
  const int done = m.run_until([&] { return m.halt.Done; }, 1000);
  EXPECT_TRUE(m.move_relative.CommandAborted);
  // 100 mm/s at 500 mm/s² = 0.2 s.
  EXPECT_GE(done, 199);
  EXPECT_LE(done, 201);
  ASSERT_GT(m.run_until([&] { return status(m, StatusWordBit::kDone); }, 200), 0);
  EXPECT_NEAR(m.db().ActualPosition, m.db().Position, m.db().PositioningMonitoring.Window);
}

// spec 02 §3.7: MC_Stop Mode 0 brakes with EmergencyDeceleration (10000 mm/s²) without jerk: 100 mm/s in 10
// ms; new motion jobs are rejected while Execute is TRUE (16#8102).
TEST(PositioningAxis, StopBrakesWithTheEmergencyRampAndLocks) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 500.0;
  m.move_relative.Execute = true;
  m.run(300);
  m.stop.Mode = 0;
  m.stop.Execute = true;
  m.run(1);
  const int done = m.run_until([&] { return m.stop.Done; }, 100);
  EXPECT_GE(done, 9);
  EXPECT_LE(done, 11);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord2, techobjects::StatusWord2Bit::kStopCommand));
  m.move_relative2.Distance = 10.0;
  m.move_relative2.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move_relative2.ErrorID, eid::kLockedByStop);
}

// spec 01 §8.4, spec 04 §8 rule 1: the override scales the positioning velocity at once; 50 % doubles the
// cruise time (90 mm at 50 mm/s = 1.8 s) of the 1100-cycle move.
TEST(PositioningAxis, OverrideScalesThePositioningVelocity) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.axis->write("Override.Velocity", 50.0).ok());
  m.move_relative.Distance = 100.0;
  m.move_relative.Execute = true;
  int at_target = -1;
  double fastest = 0.0;
  for (int k = 1; k <= 3000 && at_target < 0; ++k) {
    m.run(1);
    fastest = std::max(fastest, m.db().Velocity);
    if (m.db().Position == 100.0) at_target = k;
  }
  EXPECT_NEAR(fastest, 50.0, 1e-9);
  // 50 mm/s at 1000 mm/s²: 0.05 s + (100 - 2.5) / 50 s + 0.05 s = 2.05 s, ending in cycle 1 + 2050.
  EXPECT_EQ(at_target, 1 + 2050);
}

// spec 01 §2.5: a virtual axis is enabled at once and takes its setpoint over as the actual value one servo
// cycle later; no drive, no following error.
TEST(PositioningAxis, VirtualAxisPassesTheSetpointThrough) {
  auto d = linear_axis_data();
  d.VirtualAxis.Mode = techobjects::kModeOn;
  PositioningAxisMachine m(d, linear_drive(), 3, false);
  m.power.Enable = true;
  m.run(1);
  m.run(1);
  EXPECT_TRUE(m.power.Status);
  m.move_relative.Distance = 10.0;
  m.move_relative.Execute = true;
  m.run(50);
  const double setpoint_before = m.axis->setpoint().position;
  m.run(1);
  EXPECT_DOUBLE_EQ(m.axis->continuous_actual_position(), setpoint_before);
  EXPECT_EQ(m.db().StatusPositioning.FollowingError, 0.0);
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 500), 0);
  EXPECT_DOUBLE_EQ(m.db().ActualPosition, 10.0);
  EXPECT_EQ(m.db().StatusSensor[0].Adjusted, 1);
}

// spec 01 §5, spec 04 §3.11: with a 3:1 load gear, a 5 mm leadscrew and velocities in m/min, 6 m/min is
// 100 mm/s = 20 load rev/s = 60 motor rev/s = 3600 1/min at the drive.
TEST(PositioningAxis, UnitsGearAndLeadscrewReachTheDrive) {
  auto d = linear_axis_data();
  d.LoadGear.Numerator = 3;
  d.LoadGear.Denominator = 1;
  d.Mechanics.LeadScrew = 5.0;
  d.Units.VelocityUnit = techobjects::unit_code::kMetrePerMinute;
  d.Actor.DriveParameter.ReferenceSpeed = 6000.0;
  d.Actor.DriveParameter.MaxSpeed = 6000.0;
  d.DynamicLimits.MaxVelocity = 30.0;  // m/min
  d.DynamicLimits.Velocity = 30.0;
  d.DynamicLimits.MaxAcceleration = 5.0;  // m/s²
  d.DynamicLimits.MaxDeceleration = 5.0;
  d.DynamicDefaults.Velocity = 6.0;
  d.DynamicDefaults.Acceleration = 1.0;
  d.DynamicDefaults.Deceleration = 1.0;
  d.DynamicDefaults.EmergencyDeceleration = 10.0;
  d.FollowingError.MinVelocity = 0.6;  // m/min
  d.StandstillSignal.VelocityThreshold = 0.06;
  auto p = linear_drive();
  p.gear_motor_revolutions = 3.0;
  p.gear_load_revolutions = 1.0;
  p.load_units_per_revolution = 5.0;
  p.reference_speed_rpm = 6000.0;
  p.max_speed_rpm = 6000.0;
  p.torque_limit_nm = 12.0;
  PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 6.0;  // m/min
  m.move_velocity.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_velocity.InVelocity; }, 1000), 0);
  m.run(200);
  EXPECT_NEAR(m.db().Velocity, 6.0, 1e-9);
  EXPECT_NEAR(m.db().ActualVelocity, 6.0, 0.01);
  EXPECT_NEAR(m.drive->motor_speed_rpm(), 3600.0, 5.0);
  EXPECT_NEAR(m.drive->load_speed(), 100.0, 0.2);  // mm/s at the load
  const double p0 = m.db().ActualPosition;
  m.run(1000);
  EXPECT_NEAR(m.db().ActualPosition - p0, 100.0, 0.2);  // positions stay in mm
}

// spec 02 §7.2, spec 06 §7: with DSC (telegram 105) the drive closes the position loop: XERR carries the
// control difference in encoder counts and KPC = Kv in 0.001 1/s; the move ends in the window as without DSC.
TEST(PositioningAxis, DscSendsXerrAndKpc) {
  auto d = linear_axis_data();
  d.PositionControl.EnableDSC = true;
  PositioningAxisMachine m(d, linear_drive(), 105);
  ASSERT_GT(m.enable(), 0);
  m.move_relative.Distance = 50.0;
  m.move_relative.Execute = true;
  m.run(200);
  EXPECT_EQ(m.axis->drive()->drive_setpoint().KPC, 50000);
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 2000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 50.0, 0.01);
}

// seed 004 §6.13.1, spec 06 §2: DSC needs XERR/KPC in the setpoint telegram (5, 6, 105, 106) and the motor
// encoder as the TO's encoder. Telegrams 3, 4, 102 and 103 carry G1_XIST1 but no XERR/KPC: before issue 14
// they were accepted, the axis sent precontrol only and never reached its target (alarm 521). Table-driven.
TEST(PositioningAxis, DscIsAConfigurationErrorWithoutXerrAndKpc) {
  struct Row {
    std::uint16_t telegram;
    bool accepted;
  };
  for (const Row row : {Row{3, false}, Row{4, false}, Row{102, false}, Row{103, false}, Row{5, true},
                        Row{6, true}, Row{105, true}, Row{106, true}}) {
    SCOPED_TRACE(row.telegram);
    auto d = linear_axis_data();
    d.PositionControl.EnableDSC = true;
    if (row.accepted) {
      EXPECT_NO_THROW(PositioningAxisMachine(d, linear_drive(), row.telegram));
      continue;
    }
    try {
      PositioningAxisMachine m(d, linear_drive(), row.telegram);
      ADD_FAILURE() << "telegram " << row.telegram << " with EnableDSC was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("PositionControl.EnableDSC"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("XERR"), std::string::npos) << e.what();
    }
  }
}

// seed 004 §6.13.1: with DSC the operative encoder must be the motor encoder (G1 of the drive telegram); the
// second encoder of telegram 106 is refused.
TEST(PositioningAxis, DscNeedsTheMotorEncoder) {
  auto d = linear_axis_data();
  d.PositionControl.EnableDSC = true;
  d.Sensor[0].Interface.Number = 2;  // G2 of telegram 106
  try {
    PositioningAxisMachine m(d, linear_drive(), 106);
    ADD_FAILURE() << "DSC on encoder G2 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("motor encoder"), std::string::npos) << e.what();
  }
}

// spec 04 §8 rule 3, spec 02 §6.3: X7 Standstill after |v_act| stayed below the threshold for MinDwellTime.
TEST(PositioningAxis, StandstillSignalFollowsTheActualVelocity) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 0);
  m.run(20);
  EXPECT_TRUE(status(m, StatusWordBit::kStandstill));
  m.move_velocity.Velocity = 50.0;
  m.move_velocity.Execute = true;
  ASSERT_GT(m.run_until([&] { return !status(m, StatusWordBit::kStandstill); }, 100), 0);
  m.move_velocity.Execute = false;
  m.halt.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.halt.Done; }, 500), 0);
  ASSERT_GT(m.run_until([&] { return status(m, StatusWordBit::kStandstill); }, 100), 0);
}

}  // namespace
