// TO_SpeedAxis with MC_Power, MC_Reset, MC_MoveVelocity, MC_MoveJog, MC_Halt and MC_Stop on the simulated
// PROFIdrive drive, cycle by cycle. Numbers: Units.VelocityUnit = 1/min, so 1500 1/min = 25 1/s;
// accelerations in 1/s² (spec 04 §3.14). Unless a test says otherwise: MaxJerk = 0 (no jerk limit), so
// profiles are trapezoids. Cycle accounting: a job submitted by the user program of cycle k moves from the
// interpolator of cycle k+1 on, so a profile of n interpolator cycles is reached in the user program of cycle
// k+n (run count n+1 with the edge); status words are written by the interpolator and show a job from the
// cycle after its call; instances called before the instance that aborts them see CommandAborted one cycle
// later (spec 03 §3.6 call order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <limits>

#include "speed_axis_fixture.hpp"
#include "tomc/instructions/mc_motion_in.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using tomc::testing::SpeedAxisMachine;
namespace eid = techobjects::error_id;

techobjects::SpeedAxisData trapezoid_data() {
  techobjects::SpeedAxisData d;
  d.DynamicLimits.MaxJerk = 0.0;
  return d;
}

bool status_bit(const SpeedAxisMachine& m, techobjects::StatusWordBit bit) {
  return techobjects::test(m.axis->data().StatusWord, bit);
}

// spec 01 §6, spec 03 §4.1: Status once the drive is in operation; the drive walks S1 -> S2 -> S3 -> S4.
TEST(SpeedAxis, PowerEnablesThroughTheDriveStateMachine) {
  SpeedAxisMachine m(2, trapezoid_data());
  m.power.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.power.Busy);
  EXPECT_FALSE(m.power.Status);
  const int cycles = m.run_until([&] { return m.power.Status; }, 50);
  EXPECT_GT(cycles, 0);
  EXPECT_LE(cycles, 8);
  EXPECT_TRUE(m.axis->data().StatusDrive.InOperation);
  EXPECT_TRUE(m.axis->data().StatusDrive.CommunicationOK);
  EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kEnable));
  EXPECT_EQ(m.drive->state(), telegrams::DriveState::kS4Operation);
}

// spec 02 §2.1 / spec 03 §4.8: 1500 1/min at 50 1/s² takes 0.5 s = 500 cycles; InVelocity then; Busy stays.
TEST(SpeedAxis, MoveVelocityReachesItsSpeed) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 50.0;
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move.Busy);
  EXPECT_FALSE(m.move.InVelocity);
  m.run(1);
  EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kVelocityCommand));
  const int cycles = m.run_until([&] { return m.move.InVelocity; }, 1000);
  EXPECT_EQ(cycles + 1, 500);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 1500.0);
  EXPECT_TRUE(m.move.Busy);
  EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kConstantVelocity));
  m.run(20);
  EXPECT_NEAR(m.drive->motor_speed_rpm(), 1500.0, 1.0);
  EXPECT_NEAR(m.axis->data().ActualSpeed, 1500.0, 1.0);
}

TEST(SpeedAxis, AcceleratingAndDeceleratingBits) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 600.0;
  m.move.Acceleration = 50.0;
  m.move.Deceleration = 100.0;
  m.move.Execute = true;
  m.run(50);
  EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kAccelerating));
  EXPECT_FALSE(status_bit(m, techobjects::StatusWordBit::kDecelerating));
  m.run(300);
  m.move2.Velocity = 0.0;  // 0.0 is allowed: brakes, InVelocity at zero speed (spec 03 §4.8)
  m.move2.Deceleration = 100.0;
  m.move2.Execute = true;
  m.run(20);
  EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kDecelerating));
  EXPECT_TRUE(m.move.CommandAborted);
  // 600 1/min = 10 1/s at 100 1/s²: 0.1 s
  const int cycles = m.run_until([&] { return m.move2.InVelocity; }, 500);
  EXPECT_EQ(cycles + 20, 101);
  EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kDone));
}

// spec 01 §8.4: the override acts at once with the job's dynamics; InVelocity drops and comes back.
TEST(SpeedAxis, OverrideScalesTheRunningVelocity) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1200.0;
  m.move.Acceleration = 100.0;
  m.move.Deceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  ASSERT_TRUE(m.axis->write("Override.Velocity", 50.0).ok());
  m.run(1);
  EXPECT_FALSE(m.move.InVelocity);
  // 1200 -> 600 1/min = 20 -> 10 1/s at 100 1/s²: 0.1 s
  const int cycles = m.run_until([&] { return m.move.InVelocity; }, 500);
  EXPECT_EQ(cycles + 1, 100);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 600.0);
  // Out of range values are refused (0..200 %).
  EXPECT_FALSE(m.axis->write("Override.Velocity", 250.0).ok());
}

// spec 01 §8.8, spec 03 §3.4 (decision U18): an MC_MoveJog that replaces a MoveVelocity braking under a 0 %
// override brakes with its own Deceleration. 1200 1/min = 20 1/s braked at 50 1/s² for 20 ms (19 1/s left),
// then the jog (its target 0 at 0 %) at 100 1/s² (MaxDeceleration): 6 1/min less per cycle, standstill 190 ms
// later — not the 380 ms of the aborted job's ramp, which went on while the jog's target equalled the target
// a new job started with.
TEST(SpeedAxis, JogAtZeroOverrideBrakesWithItsOwnDeceleration) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1200.0;
  m.move.Acceleration = 100.0;
  m.move.Deceleration = 50.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  ASSERT_TRUE(m.axis->write("Override.Velocity", 0.0).ok());
  m.run(20);
  EXPECT_NEAR(m.axis->data().Velocity, 1140.0, 6.0);  // 20 ms at 50 1/s² = 60 1/min less, ±2 cycles
  m.jog.Velocity = 300.0;
  m.jog.Acceleration = 100.0;
  m.jog.Deceleration = 100.0;
  m.jog.JogForward = true;
  double last = m.axis->data().Velocity;
  double largest_step = 0.0;
  const int cycles = m.run_until(
      [&] {
        const double v = m.axis->data().Velocity;
        largest_step = std::max(largest_step, std::fabs(v - last));
        last = v;
        return v == 0.0;
      },
      1000);
  EXPECT_TRUE(m.move.CommandAborted);
  EXPECT_FALSE(m.jog.Error);
  EXPECT_GE(cycles, 187);
  EXPECT_LE(cycles, 194) << "braked with the aborted MoveVelocity's 50 1/s² instead of the jog's 100";
  EXPECT_LE(largest_step, 6.0 + 1e-6);  // 100 1/s² for 1 ms = 6 1/min
}

// spec 03 §4.4: MC_Halt aborts MoveVelocity (CommandAborted) and is Done at standstill.
TEST(SpeedAxis, HaltStopsAndAllowsNewJobs) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.halt.Deceleration = 50.0;
  m.halt.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.halt.Busy);
  m.run(1);
  EXPECT_TRUE(m.move.CommandAborted);
  EXPECT_FALSE(m.move.Busy);
  // 25 1/s at 50 1/s²: 0.5 s = 500 interpolator cycles after the edge
  const int cycles = m.run_until([&] { return m.halt.Done; }, 1000);
  EXPECT_EQ(cycles + 2, 501);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 0.0);
  // New motion is allowed after MC_Halt.
  m.move.Execute = false;
  m.run(1);
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move.Busy);
  EXPECT_FALSE(m.move.Error);
}

// spec 03 §4.13 function diagram: MC_Stop aborts, brakes (Mode 0: EmergencyDeceleration, no jerk), Done at
// standstill; a MoveVelocity while Execute is TRUE is rejected; after Execute falls it runs.
TEST(SpeedAxis, StopBlocksNewMotionWhileExecuteIsTrue) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.stop.Mode = 0;
  m.stop.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.stop.Busy);
  m.run(1);
  EXPECT_TRUE(m.move.CommandAborted);
  EXPECT_TRUE(techobjects::test(m.axis->data().StatusWord2, techobjects::StatusWord2Bit::kStopCommand));
  // 25 1/s at EmergencyDeceleration 200 1/s²: 0.125 s = 125 interpolator cycles after the edge
  const int cycles = m.run_until([&] { return m.stop.Done; }, 1000);
  EXPECT_EQ(cycles + 2, 126);
  // Rejected while the lock holds, even after Done.
  m.move.Execute = false;
  m.run(1);
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move.Error);
  EXPECT_NE(m.move.ErrorID, 0);
  m.move.Execute = false;
  m.stop.Execute = false;
  m.run(2);
  EXPECT_FALSE(techobjects::test(m.axis->data().StatusWord2, techobjects::StatusWord2Bit::kStopCommand));
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move.Busy);
  EXPECT_FALSE(m.move.Error);
}

// spec 03 §4.13 (MC_Stop.Mode: 0, 1 invalid, 2, 3).
TEST(SpeedAxis, StopModeOneIsInvalid) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.stop.Mode = 1;
  m.stop.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.stop.Error);
  EXPECT_EQ(m.stop.ErrorID, eid::kInvalidMode);
}

// spec 03 §2.1: 0.0 for Acceleration/Deceleration is invalid; a non-finite Velocity too.
TEST(SpeedAxis, InvalidParametersAreRejected) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Acceleration = 0.0;
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move.Error);
  EXPECT_EQ(m.move.ErrorID, eid::kInvalidAcceleration);
  m.move.Execute = false;
  m.run(1);
  EXPECT_FALSE(m.move.Error);
  m.move.Acceleration = -1.0;
  m.move.Velocity = std::nan("");
  m.move.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move.ErrorID, eid::kInvalidVelocity);
}

// spec 03 §4.8 prerequisites (the TO must be enabled: 16#8103, docs/errors.md).
TEST(SpeedAxis, MotionNeedsAnEnabledAxis) {
  SpeedAxisMachine m(2, trapezoid_data());
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move.Error);
  EXPECT_EQ(m.move.ErrorID, eid::kAxisNotEnabled);
}

// spec 02 §3.1 StopMode 0: the TO ramps with EmergencyDeceleration; then the drive is switched off (OFF1) and
// Busy and Status fall.
TEST(SpeedAxis, DisableWithEmergencyStop) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.power.Enable = false;
  m.power.StopMode = 0;
  m.run(2);
  EXPECT_TRUE(m.move.CommandAborted);
  EXPECT_TRUE(m.power.Busy);
  const int cycles = m.run_until([&] { return !m.power.Busy && !m.power.Status; }, 1000);
  EXPECT_NEAR(cycles + 2, 126, 2);  // 25 1/s at 200 1/s²
  // Then OFF1: the drive ramps the small rest (speed-loop lag) down and reports S2.
  EXPECT_GT(
      m.run_until([&] { return m.drive->state() == telegrams::DriveState::kS2ReadyForSwitchingOn; }, 100), 0);
}

// StopMode 1: the drive brakes on its OFF3 ramp; StopMode 3: OFF2, coasting (spec 02 §3.1).
TEST(SpeedAxis, DisableWithQuickStopAndCoast) {
  for (int mode : {1, 3}) {
    SpeedAxisMachine m(2, trapezoid_data());
    ASSERT_GT(m.enable(), 0);
    m.move.Velocity = 1500.0;
    m.move.Acceleration = 100.0;
    m.move.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
    m.run(20);
    m.power.Enable = false;
    m.power.StopMode = static_cast<std::int16_t>(mode);
    m.run(4);  // call, interpolator, servo sends the OFF word, the drive evaluates it
    if (mode == 1) {
      EXPECT_EQ(m.drive->state(), telegrams::DriveState::kS5bQuickStop);
      // p1135 = 0.2 s from 6000 rpm: 1500 rpm in about 50 ms
      EXPECT_GT(m.run_until([&] { return !m.power.Busy; }, 500), 0);
      EXPECT_LT(std::fabs(m.drive->motor_speed_rpm()), 20.0);
    } else {
      EXPECT_EQ(m.drive->state(), telegrams::DriveState::kS1SwitchingOnInhibited);
      EXPECT_GT(std::fabs(m.drive->motor_speed_rpm()), 1000.0);  // coasting on friction only
      EXPECT_FALSE(m.power.Status);
    }
  }
}

// spec 02 §3.4, spec 03 §3.3 L2: a drive fault raises alarm 401 with "remove enable"; running jobs end with
// 16#8001; Status drops while Busy stays; MC_Reset after the cause is gone re-enables automatically.
TEST(SpeedAxis, DriveFaultRemovesEnableAndResetRecovers) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 600.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.drive->inject_fault(7860, drives::SimulatedDriveParameters::FaultReaction::kOff2);
  const int cycles = m.run_until([&] { return m.move.Error; }, 20);
  EXPECT_GT(cycles, 0);
  EXPECT_EQ(m.move.ErrorID, eid::kAbortedByAlarmReaction);
  EXPECT_EQ(m.axis->data().ErrorDetail.Number, techobjects::kAlarmDriveFault);
  EXPECT_EQ(m.axis->data().ErrorDetail.Reaction, 4);
  EXPECT_TRUE(techobjects::test(m.axis->data().ErrorWord, techobjects::ErrorWordBit::kDriveFault));
  m.run(1);
  EXPECT_FALSE(m.power.Status);
  EXPECT_TRUE(m.power.Busy);
  m.drive->clear_injected_fault();
  m.run(200);  // let the coasting drive come to rest
  m.reset.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.reset.Done);
  EXPECT_EQ(m.axis->data().ErrorDetail.Number, 0u);
  const int back = m.run_until([&] { return m.power.Status; }, 100);
  EXPECT_GT(back, 0);
  EXPECT_EQ(m.drive->active_fault(), 0u);
}

// A frozen drive sign-of-life raises alarm 406 (docs/decisions.md) and removes the enable.
// Decision S2 (alarm 406, reaction 4 remove enable), spec 06 §5.2 (controller-side monitor).
TEST(SpeedAxis, SignOfLifeFailureRaisesAnAlarm) {
  SpeedAxisMachine m(3, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.drive->freeze_sign_of_life(true);
  m.run(5);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmDriveSignOfLife));
  EXPECT_FALSE(m.power.Status);
}

// MC_Reset on an enabled axis without a drive fault sends no fault acknowledge (its STW1 has ON = 0, an
// OFF1): the drive stays in operation at speed and the axis enabled. Before issue 22 the drive ramped down
// for a cycle and the TO's 20-cycle hold-off after MC_Reset hid it; the hold-off also hid a link loss that
// began within it. Now the link loss of the next cycles is raised at the 4th missing frame
// (link_loss_tolerance 3). Both found by the fault-matrix property
// (tests/techobjects/runtime/fault_matrix_property_test.cpp).
TEST(SpeedAxis, ResetOfAHealthyAxisKeepsItRunningAndLinkLossIsRaisedAtOnce) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 3000), 0);
  m.run(50);  // the motor settles at the setpoint (speed-loop lag)
  m.reset.Execute = true;
  for (int i = 0; i < 5; ++i) {
    m.run(1);
    EXPECT_EQ(m.drive->state(), telegrams::DriveState::kS4Operation) << "cycle " << i;
  }
  EXPECT_TRUE(m.reset.Done);
  EXPECT_TRUE(m.power.Status);
  EXPECT_NEAR(m.drive->motor_speed_rpm(), 1500.0, 1.0);
  m.drive->set_link_lost(true);
  m.run(3);  // 3 missing frames: within the tolerance
  EXPECT_FALSE(m.axis->alarms().pending(techobjects::kAlarmDriveCommunication));
  m.run(1);  // the 4th: alarm 405, remove enable in this cycle
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmDriveCommunication));
  EXPECT_EQ(m.axis->data().ErrorDetail.Reaction, 4);
  EXPECT_FALSE(status_bit(m, techobjects::StatusWordBit::kEnable));
}

// spec 03 §3.4: J1 jog, J4 both inputs -> 16#8007 and braking, error until both are FALSE, J2 Busy ends at
// rest.
TEST(SpeedAxis, JogBothDirectionsIsAnError) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.jog.Velocity = 300.0;
  m.jog.Acceleration = 50.0;
  m.jog.Deceleration = 50.0;
  m.jog.JogForward = true;
  // 300 1/min = 5 1/s at 50 1/s²: 0.1 s
  const int cycles = m.run_until([&] { return m.jog.InVelocity; }, 500);
  EXPECT_EQ(cycles, 101);
  EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kJogCommand));
  m.jog.JogBackward = true;
  m.run(1);
  EXPECT_TRUE(m.jog.Error);
  EXPECT_EQ(m.jog.ErrorID, eid::kJogWrongDirection);
  m.run(150);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 0.0);  // braked with the last valid deceleration
  EXPECT_TRUE(m.jog.Error);                        // held while an input is TRUE
  m.jog.JogForward = false;
  m.run(1);
  EXPECT_TRUE(m.jog.Error);
  m.jog.JogBackward = false;
  m.run(1);
  EXPECT_FALSE(m.jog.Error);
  // Backward jog, then release: Busy until standstill (J2).
  m.jog.JogBackward = true;
  m.run(200);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, -300.0);
  m.jog.JogBackward = false;
  m.run(1);
  EXPECT_TRUE(m.jog.Busy);
  const int stopped = m.run_until([&] { return !m.jog.Busy; }, 500);
  EXPECT_NEAR(stopped, 100, 1);
}

// A virtual axis (VirtualAxis.Mode = 1) has no drive: enabled at once, actual = setpoint (spec 01 §2.5).
TEST(SpeedAxis, VirtualAxis) {
  auto data = trapezoid_data();
  data.VirtualAxis.Mode = techobjects::kModeOn;
  SpeedAxisMachine m(2, data, {}, false);
  EXPECT_EQ(m.enable(), 2);  // the call, then the next interpolator enables without waiting for a drive
  m.move.Velocity = 600.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  EXPECT_EQ(m.run_until([&] { return m.move.InVelocity; }, 500), 101);
  m.run(1);
  EXPECT_DOUBLE_EQ(m.axis->data().ActualSpeed, 600.0);
}

// spec 01 §7, spec 03 §4.2: Restart needs a disabled TO; it applies restart-relevant start values.
TEST(SpeedAxis, RestartAppliesStartValues) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.axis->write_start_value("DynamicLimits.MaxVelocity", 2000.0).ok());
  EXPECT_TRUE(
      techobjects::test(m.axis->data().StatusWord, techobjects::StatusWordBit::kOnlineStartValuesChanged));
  EXPECT_DOUBLE_EQ(m.axis->data().DynamicLimits.MaxVelocity, 3000.0);
  // A restart-relevant variable cannot be written directly.
  EXPECT_FALSE(m.axis->write("DynamicLimits.MaxVelocity", 2000.0).ok());
  m.reset.Restart = true;
  m.reset.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.reset.Error);
  EXPECT_EQ(m.reset.ErrorID, eid::kRestartNeedsDisabledAxis);
  m.reset.Execute = false;
  m.power.Enable = false;
  ASSERT_GT(m.run_until([&] { return !m.power.Busy; }, 100), 0);
  m.reset.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.reset.Done);
  EXPECT_DOUBLE_EQ(m.axis->data().DynamicLimits.MaxVelocity, 2000.0);
  EXPECT_FALSE(
      techobjects::test(m.axis->data().StatusWord, techobjects::StatusWordBit::kOnlineStartValuesChanged));
  // The restart does not disturb the running PROFIdrive link: no sign-of-life fault, and the axis enables
  // again.
  m.run(50);
  EXPECT_EQ(m.drive->active_fault(), 0u);
  m.power.Enable = true;
  EXPECT_GT(m.run_until([&] { return m.power.Status; }, 100), 0);
}

// spec 01 §8.5: the velocity is limited to min(MaxVelocity, Velocity) with warning 501.
TEST(SpeedAxis, VelocityLimitedWithWarning) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.axis->write("DynamicLimits.Velocity", 1000.0).ok());
  m.move.Velocity = 2500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 1000.0);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  EXPECT_TRUE(techobjects::test(m.axis->data().WarningWord, techobjects::WarningWordBit::kDynamicWarning));
}

// spec 03 §4.14: only STW1 bits 8, 9, 11..15 and STW2 bits 0..11 are the user's; the drive receives them.
TEST(SpeedAxis, SetAxisStwWritesTheUsersBits) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.set_stw.STW1 = 0x0100;  // jog 1 bit of the drive
  m.set_stw.STW1BitMask = 0x0100;
  m.set_stw.STW2 = 0x0080;  // parking axis selection
  m.set_stw.STW2BitMask = 0x0080;
  m.set_stw.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.set_stw.Done);
  const auto& sp = m.axis->drive()->drive_setpoint();
  EXPECT_EQ(sp.STW1.value() & 0x0100, 0x0100);
  EXPECT_EQ(sp.STW1.value() & 0x04FF, 0x047F);  // the TO's bits untouched: still operating
  EXPECT_EQ(sp.STW2.value() & 0x0FFF, 0x0080);
  EXPECT_TRUE(m.axis->drive()->in_operation());
  // A mask over the TO's bits (STW1 bit 0) or the sign-of-life (STW2 12..15) is refused.
  m.set_stw.Execute = false;
  m.run(1);
  m.set_stw.STW1BitMask = 0x0001;
  m.set_stw.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.set_stw.Error);
  EXPECT_EQ(m.set_stw.ErrorID, eid::kInvalidBitMask);
  m.set_stw.Execute = false;
  m.run(1);
  m.set_stw.STW1BitMask = 0;
  m.set_stw.STW2BitMask = 0xF000;
  m.set_stw.Execute = true;
  m.run(1);
  EXPECT_EQ(m.set_stw.ErrorID, eid::kInvalidBitMask);
}

// spec 03 §4.15: 1020 RemoveEnableReaction takes effect at once (here: OFF2 instead of OFF3 on a drive
// fault); 1010..1012 after restart; unknown numbers and values are rejected.
TEST(SpeedAxis, WriteParameter) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.write_parameter.ParameterNumber = 1020;
  m.write_parameter.Value = 3.0;  // 16#3: OFF2
  m.write_parameter.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.write_parameter.Done);
  EXPECT_EQ(m.axis->data().Actor.RemoveEnableReaction, 3);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  // A communication alarm (remove enable) now coasts the drive: OFF2 (spec 02 §3.4).
  m.drive->freeze_sign_of_life(true);
  m.run(8);
  // OFF2 switched the pulses off at once (S1; the sequencer then re-arms S2): no ramp, the motor coasts.
  const auto state = m.drive->state();
  EXPECT_TRUE(state == telegrams::DriveState::kS1SwitchingOnInhibited ||
              state == telegrams::DriveState::kS2ReadyForSwitchingOn);
  EXPECT_GT(std::fabs(m.drive->motor_speed_rpm()), 1000.0);
  // Invalid value 16#2 and unknown number.
  m.write_parameter.Execute = false;
  m.run(1);
  m.write_parameter.Value = 2.0;
  m.write_parameter.Execute = true;
  m.run(1);
  EXPECT_EQ(m.write_parameter.ErrorID, eid::kInvalidParameterValue);
  m.write_parameter.Execute = false;
  m.run(1);
  m.write_parameter.ParameterNumber = 1000;  // positioning axes only
  m.write_parameter.Execute = true;
  m.run(1);
  EXPECT_EQ(m.write_parameter.ErrorID, eid::kInvalidParameterNumber);
  m.write_parameter.Execute = false;
  m.run(1);
  m.write_parameter.ParameterNumber = 1010;
  m.write_parameter.Value = 0.000125;
  m.write_parameter.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.write_parameter.Done);
  EXPECT_DOUBLE_EQ(m.axis->communication_times().Ti, 0.0);  // after restart only
  EXPECT_TRUE(
      techobjects::test(m.axis->data().StatusWord, techobjects::StatusWordBit::kOnlineStartValuesChanged));
}

// spec 02 §3.1 StopMode 2: the TO ramps with MaxDeceleration (100 1/s², MaxJerk 0 here): 25 1/s in 0.25 s.
TEST(SpeedAxis, DisableWithMaximumDynamics) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.power.Enable = false;
  m.power.StopMode = 2;
  const int cycles = m.run_until([&] { return !m.power.Busy; }, 1000);
  EXPECT_NEAR(cycles, 251, 1);  // the call, then 250 interpolator cycles of ramp
}

// spec 02 §3.4: RemoveEnableReaction 16#1 makes "remove enable" an OFF1 (the drive ramps on p1121, S5a).
TEST(SpeedAxis, RemoveEnableWithOff1) {
  auto data = trapezoid_data();
  data.Actor.RemoveEnableReaction = 0x1;
  SpeedAxisMachine m(3, data);
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.drive->freeze_sign_of_life(true);  // alarm 406, reaction 4
  ASSERT_GT(m.run_until([&] { return m.drive->state() == telegrams::DriveState::kS5aRampStop; }, 20), 0);
  // p1121 = 1 s from 6000 rpm: 1500 rpm take about 0.25 s, then the drive is ready for switching on (S2).
  const int stopped =
      m.run_until([&] { return m.drive->state() == telegrams::DriveState::kS2ReadyForSwitchingOn; }, 1000);
  EXPECT_NEAR(stopped, 250, 10);
  EXPECT_FALSE(m.power.Status);
  EXPECT_TRUE(m.power.Busy);
}

// spec 01 §6.1: a drive that cannot switch on keeps MC_Power Busy without Status; the TO reports why.
TEST(SpeedAxis, DriveThatNeverBecomesReady) {
  SpeedAxisMachine m(2, trapezoid_data());
  m.run(3);
  m.drive->inject_fault(7900, drives::SimulatedDriveParameters::FaultReaction::kOff2);
  m.power.Enable = true;
  m.run(3000);
  EXPECT_TRUE(m.power.Busy);
  EXPECT_FALSE(m.power.Status);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmDriveFault));
  EXPECT_FALSE(m.axis->data().StatusDrive.InOperation);
}

// spec 03 §6.1 R4 x C6 = N: MC_Halt and MC_MoveJog are rejected while MC_Stop runs; R4 x C3 = A: a jog aborts
// a running MoveVelocity.
TEST(SpeedAxis, PriorityCellsOfTheSpeedAxisInstructions) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 600.0;
  m.move.Execute = true;
  m.run(50);
  m.jog.JogForward = true;
  m.run(2);
  EXPECT_TRUE(m.move.CommandAborted);
  EXPECT_TRUE(m.jog.Busy);
  m.stop.Mode = 3;
  m.stop.Deceleration = 10.0;
  m.stop.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.jog.CommandAborted);
  EXPECT_TRUE(m.stop.Busy);
  m.halt.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.halt.Error);
  EXPECT_NE(m.halt.ErrorID, 0);
  EXPECT_TRUE(m.stop.Busy);  // the running MC_Stop continues
  // A heavier MC_Stop (Mode 0) aborts the running one (legend B).
  m.stop.Execute = false;
  m.run(1);
  m.stop.Mode = 0;
  m.stop.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.stop.Busy);
  EXPECT_GT(m.run_until([&] { return m.stop.Done; }, 1000), 0);
}

// spec 04 §3.11 / spec 01 §5.4–§5.5: the velocity unit, the load gear (motor : load revolutions) and the
// drive direction inversion reach the drive as the matching motor speed.
TEST(SpeedAxis, UnitsLoadGearAndInversion) {
  struct Case {
    std::uint32_t unit;
    double velocity;  // in the unit
    std::uint32_t numerator, denominator;
    bool inverse;
    double motor_rpm;  // expected at the drive
  } cases[] = {
      {techobjects::unit_code::kPerMinute, 1500.0, 1, 1, false, 1500.0},
      {techobjects::unit_code::kPerSecond, 25.0, 1, 1, false, 1500.0},
      {techobjects::unit_code::kPerHour, 90000.0, 1, 1, false, 1500.0},
      {techobjects::unit_code::kPerMinute, 750.0, 2, 1, false, 1500.0},
      {techobjects::unit_code::kPerMinute, 1500.0, 1, 1, true, -1500.0},
  };
  for (const auto& c : cases) {
    auto data = trapezoid_data();
    data.Units.VelocityUnit = c.unit;
    data.LoadGear.Numerator = c.numerator;
    data.LoadGear.Denominator = c.denominator;
    data.Actor.InverseDirection = c.inverse;
    // Limits and defaults in the same unit (the data block is in the configured unit).
    const double per_minute = c.unit == techobjects::unit_code::kPerSecond ? 1.0 / 60.0
                              : c.unit == techobjects::unit_code::kPerHour ? 60.0
                                                                           : 1.0;
    data.DynamicLimits.MaxVelocity = 3000.0 * per_minute;
    data.DynamicLimits.Velocity = 3000.0 * per_minute;
    SpeedAxisMachine m(2, data);
    ASSERT_GT(m.enable(), 0);
    m.move.Velocity = c.velocity;
    m.move.Acceleration = 100.0;
    m.move.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 2000), 0);
    m.run(30);
    EXPECT_NEAR(m.drive->motor_speed_rpm(), c.motor_rpm, 1.0)
        << c.unit << " " << c.numerator << " " << c.inverse;
    EXPECT_NEAR(m.axis->data().ActualSpeed, c.motor_rpm, 1.0);
    EXPECT_DOUBLE_EQ(m.axis->data().Velocity, c.velocity);
  }
}

// spec 02 §3.5: alarm reactions 1/2/3 brake with the current dynamics, the maximum dynamics or the emergency
// ramp; the TO stays enabled but blocked; the motion job ends with 16#8001; MC_Reset unblocks.
TEST(SpeedAxis, AlarmReactionsWithBrakingRamps) {
  struct Case {
    techobjects::AlarmReaction reaction;
    int ramp_cycles;  // 25 1/s at: the job's 50 1/s², MaxDeceleration 100, EmergencyDeceleration 200
  } cases[] = {{techobjects::AlarmReaction::kStopCurrentDynamics, 500},
               {techobjects::AlarmReaction::kStopMaxDynamics, 250},
               {techobjects::AlarmReaction::kStopEmergencyRamp, 125}};
  for (const auto& c : cases) {
    SpeedAxisMachine m(2, trapezoid_data());
    ASSERT_GT(m.enable(), 0);
    m.move.Velocity = 1500.0;
    m.move.Acceleration = 100.0;
    m.move.Deceleration = 50.0;
    m.move.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
    // Raised before the cycle: the interpolator of that cycle applies the reaction (issue 4: in the same
    // cycle).
    ASSERT_TRUE(m.axis->inject_alarm(techobjects::kAlarmSoftwareLimitReached, 0, c.reaction));
    m.run(1);
    EXPECT_TRUE(m.move.Error);
    EXPECT_EQ(m.move.ErrorID, eid::kAbortedByAlarmReaction);
    EXPECT_EQ(m.axis->data().ErrorDetail.Reaction, static_cast<std::int32_t>(c.reaction));
    EXPECT_TRUE(status_bit(m, techobjects::StatusWordBit::kDecelerating));
    const int cycles = m.run_until([&] { return m.axis->data().Velocity == 0.0; }, 2000);
    EXPECT_EQ(cycles + 1, c.ramp_cycles) << static_cast<int>(c.reaction);
    // Enabled but blocked: Status stays, new jobs are refused until acknowledged.
    EXPECT_TRUE(m.power.Status);
    m.move.Execute = false;
    m.run(1);
    m.move.Execute = true;
    m.run(1);
    EXPECT_EQ(m.move.ErrorID, eid::kAxisBlockedByAlarm);
    m.move.Execute = false;
    m.reset.Execute = true;
    m.run(2);
    EXPECT_TRUE(m.reset.Done);
    m.move.Execute = true;
    m.run(1);
    EXPECT_TRUE(m.move.Busy);
  }
}

// seed 004 §6.9.4 example 2: MC_Stop Mode 3 is active and an alarm with reaction 2 comes: the max-dynamics
// stop replaces it and MC_Stop reports CommandAborted (not Error).
TEST(SpeedAxis, HeavierAlarmReactionReplacesMcStop) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.stop.Mode = 3;
  m.stop.Deceleration = 10.0;
  m.stop.Execute = true;
  m.run(10);
  ASSERT_TRUE(m.stop.Busy);
  ASSERT_TRUE(m.axis->inject_alarm(techobjects::kAlarmSoftwareLimitReached, 0,
                                   techobjects::AlarmReaction::kStopMaxDynamics));
  m.run(1);
  EXPECT_TRUE(m.stop.CommandAborted);
  EXPECT_FALSE(m.stop.Error);
  // The rest brakes with MaxDeceleration 100 1/s² instead of 10.
  EXPECT_LT(m.run_until([&] { return m.axis->data().Velocity == 0.0; }, 2000), 260);
}

// seed 004 §6.9.4 example 1: an alarm with reaction 2 is active and MC_Stop Mode 0 comes: the emergency stop
// takes over; MC_Stop is Done at standstill. A lighter MC_Stop (Mode 3) is not accepted: CommandAborted.
TEST(SpeedAxis, HeavierMcStopReplacesAlarmReaction) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  ASSERT_TRUE(m.axis->inject_alarm(techobjects::kAlarmSoftwareLimitReached, 0,
                                   techobjects::AlarmReaction::kStopMaxDynamics));
  m.run(2);
  m.stop.Mode = 3;
  m.stop.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.stop.CommandAborted);
  m.stop.Execute = false;
  m.run(1);
  m.stop.Mode = 0;
  m.stop.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.stop.Busy);
  // 25 1/s braked from the start at 100 1/s² for 4 cycles (0.4 1/s), the rest at 200 1/s²: about 123 cycles.
  const int cycles = m.run_until([&] { return m.stop.Done; }, 1000);
  EXPECT_NEAR(cycles, 123, 2);
}

// spec 02 §1.1 reaction 5: the setpoint follows the actual value; no motion job runs.
TEST(SpeedAxis, FollowSetpointReaction) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.move.Velocity = 600.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move.InVelocity; }, 1000), 0);
  m.run(20);
  ASSERT_TRUE(
      m.axis->inject_alarm(techobjects::kAlarmDriveSafeStop, 0, techobjects::AlarmReaction::kFollowSetpoint));
  m.run(1);
  EXPECT_TRUE(m.move.Error);
  EXPECT_NEAR(m.axis->data().Velocity, m.axis->data().ActualSpeed, 1e-6);  // load = motor here (gear 1:1)
  EXPECT_FALSE(m.axis->inject_alarm(999, 0, techobjects::AlarmReaction::kNone));
}

// MC_MotionInVelocity on the speed axis (spec 03 §4.17.1 "Speed, Positioning, Synchronous", §8.2 T22,
// spec 02 §8): the velocity written in cycle k is the setpoint of cycle k+1 without a ramp and without the
// dynamic limits (4000 1/min > MaxVelocity 3000 is taken as given); StatusMotionIn.FunctionState 1 while it
// runs; MC_MoveVelocity replaces it (§9.19.1 R4 x C8 = A) from its velocity with the job's acceleration; the
// falling edge makes velocity and acceleration 0; a NaN ends it with 16#8186 and the axis brakes with the
// defaults.
TEST(SpeedAxisMotionIn, VelocityActsDirectlyAndEndsAsTheManualSays) {
  SpeedAxisMachine m;
  instructions::MC_MotionInVelocity<techobjects::SpeedAxis> feed;
  m.user = [&] { feed(*m.axis); };
  ASSERT_GT(m.enable(), 0);
  feed.Velocity = 600.0;
  feed.Enable = true;
  m.run(1);  // the rising edge
  EXPECT_TRUE(feed.Busy);
  EXPECT_FALSE(feed.Error);
  m.run(1);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 600.0);
  EXPECT_EQ(m.axis->data().StatusMotionIn.FunctionState, 1);
  EXPECT_FALSE(techobjects::test(m.axis->data().StatusWord, techobjects::StatusWordBit::kDone));
  feed.Velocity = 4000.0;
  feed.Acceleration = 10.0;
  m.run(1);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 600.0);
  m.run(1);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 4000.0);  // not limited to MaxVelocity 3000
  EXPECT_DOUBLE_EQ(m.axis->data().Acceleration, 10.0);
  // The falling edge: the setpoints become 0.0.
  feed.Enable = false;
  m.run(1);
  EXPECT_FALSE(feed.Busy);
  m.run(1);
  EXPECT_EQ(m.axis->data().Velocity, 0.0);
  EXPECT_EQ(m.axis->data().StatusMotionIn.FunctionState, 0);
  // Replaced by MC_MoveVelocity (1500 1/min at 50/s²) from 600 1/min.
  feed.Velocity = 600.0;
  feed.Acceleration = 0.0;
  feed.Enable = true;
  m.run(3);
  ASSERT_DOUBLE_EQ(m.axis->data().Velocity, 600.0);
  m.move.Velocity = 1500.0;
  m.move.Acceleration = 50.0;
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move.Busy);
  EXPECT_TRUE(feed.CommandAborted);
  m.run(1);
  // From 600 without a step: at most one cycle of 50/s² (3 1/min), less while the jerk (MaxJerk) builds it
  // up.
  EXPECT_GT(m.axis->data().Velocity, 600.0);
  EXPECT_LE(m.axis->data().Velocity, 603.0 + 1e-9);
  EXPECT_EQ(m.axis->data().StatusMotionIn.FunctionState, 0);
  // A NaN while running: the job ends with Error 16#8186 and the axis brakes.
  m.move.Execute = false;
  feed.Enable = false;
  m.run(1);
  feed.Velocity = 300.0;
  feed.Enable = true;
  m.run(2);
  ASSERT_TRUE(feed.Busy);
  feed.Velocity = std::numeric_limits<double>::quiet_NaN();
  m.run(1);
  EXPECT_TRUE(feed.Error);
  EXPECT_EQ(feed.ErrorID, eid::kInvalidMotionInSetpoint);
  double last = m.axis->data().Velocity;
  const int cycles = m.run_until(
      [&] {
        EXPECT_LE(m.axis->data().Velocity, last + 1e-9);
        last = m.axis->data().Velocity;
        return last == 0.0;
      },
      1000);
  EXPECT_GT(cycles, 90);  // 300 1/min at the default 50/s²: 100 cycles
}

}  // namespace

// spec 03 §4.14, decision K8: STW2 bit 8 is one of the user's MC_SetAxisSTW bits and also the "travel to
// fixed stop" bit MC_TorqueLimiting sets. The one writer applies the torque limit's level only when it
// changes, so a bit the user set stays in the telegram cycle after cycle while no torque limiting runs.
TEST(SpeedAxis, UsersStw2Bit8SurvivesTheServoCommand) {
  SpeedAxisMachine m(2, trapezoid_data());
  ASSERT_GT(m.enable(), 0);
  m.set_stw.STW2 = 0x0100;
  m.set_stw.STW2BitMask = 0x0100;
  m.set_stw.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.set_stw.Done);
  for (int k = 0; k < 20; ++k) {
    m.run(1);
    ASSERT_TRUE(m.axis->drive()->drive_setpoint().STW2.test(telegrams::Stw2Bit::kTravelToFixedStop)) << k;
  }
}
