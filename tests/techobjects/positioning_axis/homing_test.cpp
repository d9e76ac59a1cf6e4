// MC_Home on TO_PositioningAxis, every mode, on the simulated drive (spec 02 §5, spec 03 §4.3, §6.1; spec 02
// §11 scenarios 31–40). The machine: the default linear axis (10 mm per motor revolution); the motor encoder
// has a zero mark every revolution at 0.25 rev, i.e. at 2.5, 12.5, 22.5 ... mm; the reference cam / homing
// digital input is the simulated machine's `reference_cam` window, wired high-active (SwitchLevel TRUE).
#include <gtest/gtest.h>

#include <cmath>

#include "positioning_axis_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::ErrorWordBit;
using techobjects::SensorHomingMode;
using techobjects::StatusWordBit;
using tomc::testing::linear_axis_data;
using tomc::testing::linear_drive;
using tomc::testing::PositioningAxisMachine;
namespace eid = techobjects::error_id;

bool status(const PositioningAxisMachine& m, StatusWordBit bit) {
  return techobjects::test(m.db().StatusWord, bit);
}

techobjects::PositioningAxisData homing_data(SensorHomingMode method) {
  auto d = linear_axis_data();
  d.Sensor[0].ActiveHoming.Mode = static_cast<std::int32_t>(method);
  d.Sensor[0].PassiveHoming.Mode = static_cast<std::int32_t>(method);
  d.Homing.ApproachVelocity = 20.0;
  d.Homing.ReferencingVelocity = 5.0;
  return d;
}

drives::SimulatedDriveParameters cam_drive(double from, double to) {
  auto p = linear_drive();
  p.machine.reference_cam = drives::PositionWindow{from, to};
  return p;
}

void start_home(PositioningAxisMachine& m, std::int16_t mode, double position = 0.0) {
  m.home.Mode = mode;
  m.home.Position = position;
  m.home.Execute = true;
}

// spec 02 §5.5 B (ActiveHoming.Mode 0): towards the zero mark in the homing direction at ReferencingVelocity;
// at the mark ActualPosition := Position − HomePositionOffset and X5; then to Position at ApproachVelocity;
// Done.
TEST(Homing, ActiveZeroMarkOnly) {
  auto d = homing_data(SensorHomingMode::kZeroMarkViaTelegram);
  d.Sensor[0].ActiveHoming.HomePositionOffset = 5.0;
  PositioningAxisMachine m(d);
  ASSERT_GT(m.enable(), 0);
  start_home(m, 3, 100.0);
  m.run(2);
  EXPECT_TRUE(m.home.Busy);
  EXPECT_TRUE(status(m, StatusWordBit::kHomingCommand));
  EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));
  double fastest = 0.0;
  const int homed = m.run_until(
      [&] {
        if (status(m, StatusWordBit::kHomingDone)) return true;  // (this cycle already heads for home)
        fastest = std::max(fastest, m.db().Velocity);
        return false;
      },
      5000);
  ASSERT_GT(homed, 0);
  EXPECT_NEAR(fastest, 5.0, 1e-9);  // ReferencingVelocity
  // The mark at 2.5 mm of the load became 95 (= 100 - 5).
  EXPECT_NEAR(m.db().ActualPosition - (m.drive->load_position() - 2.5), 95.0, 0.02);
  ASSERT_GT(m.run_until([&] { return m.home.Done; }, 5000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 100.0, 0.01);
  EXPECT_NEAR(m.drive->load_position(), 7.5, 0.02);  // 5 mm past the mark
  EXPECT_DOUBLE_EQ(m.home.ReferenceMarkPosition, 95.0);
  EXPECT_FALSE(status(m, StatusWordBit::kHomingCommand));
  EXPECT_EQ(m.db().StatusSensor[0].Adjusted, 1);
}

// spec 02 §5.5 A (ActiveHoming.Mode 1): approach the cam [40, 45] positive at ApproachVelocity; the zero mark
// counts after the cam was left in the homing direction: positive -> the mark at 52.5; negative -> the axis
// reverses at the cam and takes the mark at 32.5 (spec 02 §10 items 5, 6).
TEST(Homing, ActiveReferenceCamAndZeroMark) {
  for (const bool negative : {false, true}) {
    auto d = homing_data(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam);
    d.Sensor[0].ActiveHoming.Direction = negative ? 1 : 0;
    d.Homing.HomePosition = 200.0;
    PositioningAxisMachine m(d, cam_drive(40.0, 45.0));
    ASSERT_GT(m.enable(), 0);
    start_home(m, 5);
    ASSERT_GT(m.run_until([&] { return m.home.Done; }, 20000), 0) << negative;
    EXPECT_NEAR(m.drive->load_position(), negative ? 32.5 : 52.5, 0.02) << negative;
    EXPECT_NEAR(m.db().ActualPosition, 200.0, 0.01);
    EXPECT_TRUE(status(m, StatusWordBit::kHomingDone));
  }
}

// spec 02 §11 scenario 31 (Mode 5, digital input): HomePosition 100, HomePositionOffset 5, ApproachVelocity
// 50, ReferencingVelocity 5: at the mark edge ActualPosition = 95 and X5 in the same cycle, then to 100 at 50
// mm/s; X11 throughout. The input [40, 45], homing positive, positive side: the mark is leaving the input at
// 45 mm.
TEST(Homing, ActiveDigitalInputScenario31) {
  auto d = homing_data(SensorHomingMode::kReferenceMarkViaDigitalInput);
  d.Homing.HomePosition = 100.0;
  d.Sensor[0].ActiveHoming.HomePositionOffset = 5.0;
  d.Homing.ApproachVelocity = 50.0;
  d.Homing.ReferencingVelocity = 5.0;
  PositioningAxisMachine m(d, cam_drive(40.0, 45.0));
  ASSERT_GT(m.enable(), 0);
  start_home(m, 5);
  m.run(1);  // the edge call; X11 shows from the next interpolator on
  bool command_throughout = true;
  const int homed = m.run_until(
      [&] {
        command_throughout = command_throughout && status(m, StatusWordBit::kHomingCommand);
        return status(m, StatusWordBit::kHomingDone);
      },
      20000);
  ASSERT_GT(homed, 0);
  EXPECT_TRUE(command_throughout);
  // The edge is seen at the servo rate: within one cycle at 5 mm/s (0.005 mm) plus the loop's lag.
  EXPECT_NEAR(m.db().ActualPosition - (m.drive->load_position() - 45.0), 95.0, 0.03);
  double fastest = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  fastest = std::max(fastest, m.db().Velocity);
                  return m.home.Done;
                },
                5000),
            0);
  EXPECT_NEAR(fastest, 50.0, 1e-9);
  EXPECT_NEAR(m.db().ActualPosition, 100.0, 0.01);
  EXPECT_NEAR(m.drive->load_position(), 50.0, 0.05);
  EXPECT_DOUBLE_EQ(m.home.ReferenceMarkPosition, 95.0);
  m.run(1);
  EXPECT_FALSE(status(m, StatusWordBit::kHomingCommand));
}

// spec 02 §5.4 side table: homing positive with the negative side (SideInput FALSE) makes the edge onto the
// input the mark: the axis backs off the input after the approach and takes the mark at 40 mm moving
// positive.
TEST(Homing, ActiveDigitalInputNegativeSide) {
  auto d = homing_data(SensorHomingMode::kReferenceMarkViaDigitalInput);
  d.Sensor[0].ActiveHoming.SideInput = false;
  PositioningAxisMachine m(d, cam_drive(40.0, 45.0));
  ASSERT_GT(m.enable(), 0);
  start_home(m, 3, 0.0);
  ASSERT_GT(m.run_until([&] { return m.home.Done; }, 20000), 0);
  EXPECT_NEAR(m.drive->load_position(), 40.0, 0.05);
  EXPECT_NEAR(m.db().ActualPosition, 0.0, 0.01);
}

// spec 02 §5.5 D, §4.2: with Homing.AutoReversal the positive limit switch (80 mm) is a reversal cam: no
// alarm 531; the search goes on negative at ApproachVelocity, finds the cam [20, 25] and homes on it.
TEST(Homing, ReversalAtTheHardwareLimitSwitch) {
  auto d = homing_data(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam);
  d.Homing.AutoReversal = true;
  d.PositionLimits_HW.Active = true;
  auto p = cam_drive(20.0, 25.0);
  p.initial_load_position = 50.0;
  p.machine.positive_limit_switch = 80.0;
  p.machine.negative_limit_switch = -80.0;
  PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);
  start_home(m, 3, 0.0);
  double highest = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  highest = std::max(highest, m.drive->load_position());
                  return m.home.Done;
                },
                40000),
            0);
  EXPECT_GE(highest, 80.0);
  EXPECT_FALSE(m.axis->alarms().pending(techobjects::kAlarmHardwareLimit));
  EXPECT_NEAR(m.drive->load_position(), 32.5, 0.02);  // left the cam at 25 positive, next mark 32.5
}

// Failure (decision H3): both limit switches reached without the cam -> alarm 560 (additional value 1),
// ErrorWord.X10, the job ends with 16#8001, the axis stops and stays not homed.
TEST(Homing, NoCamBetweenTheLimitSwitches) {
  auto d = homing_data(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam);
  d.Homing.AutoReversal = true;
  d.PositionLimits_HW.Active = true;
  auto p = linear_drive();
  p.machine.positive_limit_switch = 30.0;
  p.machine.negative_limit_switch = -30.0;
  PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);
  start_home(m, 3, 0.0);
  ASSERT_GT(m.run_until([&] { return m.home.Error; }, 40000), 0);
  EXPECT_EQ(m.home.ErrorID, eid::kAbortedByAlarmReaction);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmHomingFailed));
  EXPECT_EQ(m.db().ErrorDetail.Number, techobjects::kAlarmHomingFailed);
  m.run(1);
  EXPECT_TRUE(techobjects::test(m.db().ErrorWord, ErrorWordBit::kHomingError));
  EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));
  m.run(500);
  EXPECT_TRUE(status(m, StatusWordBit::kStandstill));
  EXPECT_LE(m.drive->load_position(), -30.0 + 1.0);
}

// Without AutoReversal a limit switch during homing is an ordinary 531 (spec 02 §4.2): the homing job ends
// with 16#8001.
TEST(Homing, LimitSwitchWithoutReversalRaises531) {
  auto d = homing_data(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam);
  d.PositionLimits_HW.Active = true;
  auto p = linear_drive();
  p.machine.positive_limit_switch = 30.0;
  PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);
  start_home(m, 3, 0.0);
  ASSERT_GT(m.run_until([&] { return m.home.Error; }, 20000), 0);
  EXPECT_EQ(m.home.ErrorID, eid::kAbortedByAlarmReaction);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmHardwareLimit));
  EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));
}

// spec 02 §5.6, §11 scenario 33: passive Mode 8 resets "homed" at the start and sets it at the mark, during a
// motion the user commands (zero mark at 2.5 mm while moving +30 mm): ActualPosition = Position + 27.5.
// Mode 2 keeps "homed" until the mark.
TEST(Homing, PassiveZeroMarkDuringAUserMove) {
  for (const std::int16_t mode : {8, 2}) {
    PositioningAxisMachine m(homing_data(SensorHomingMode::kZeroMarkViaTelegram));
    ASSERT_GT(m.enable(), 0);
    ASSERT_TRUE(m.home_at(0.0));
    start_home(m, mode, 1000.0);
    m.run(2);
    EXPECT_TRUE(m.home.Busy);
    EXPECT_EQ(status(m, StatusWordBit::kHomingDone), mode == 2) << mode;
    m.move_relative.Distance = 30.0;
    m.move_relative.Velocity = 10.0;
    m.move_relative.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.home.Done; }, 5000), 0) << mode;
    EXPECT_TRUE(status(m, StatusWordBit::kHomingDone));
    EXPECT_DOUBLE_EQ(m.home.ReferenceMarkPosition, 1000.0);
    ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 5000), 0);
    EXPECT_NEAR(m.db().ActualPosition, 1000.0 + 27.5, 0.02) << mode;
  }
}

// spec 02 §11 scenario 34: passive Mode 10 with a digital input: ActualPosition = HomePosition (20) at the
// mark, the offset (5) is ignored, and no extra motion occurs. The input [40, 45], moving positive, positive
// side: the mark is leaving the input at 45 mm.
TEST(Homing, PassiveDigitalInputScenario34) {
  auto d = homing_data(SensorHomingMode::kReferenceMarkViaDigitalInput);
  d.Homing.HomePosition = 20.0;
  d.Sensor[0].ActiveHoming.HomePositionOffset = 5.0;
  PositioningAxisMachine m(d, cam_drive(40.0, 45.0));
  ASSERT_GT(m.enable(), 0);
  start_home(m, 10);
  m.run(2);
  m.move_velocity.Velocity = 10.0;
  m.move_velocity.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.home.Done; }, 10000), 0);
  EXPECT_NEAR(m.db().ActualPosition - (m.drive->load_position() - 45.0), 20.0, 0.03);
  EXPECT_TRUE(m.move_velocity.Busy);  // the user's motion goes on
}

// spec 02 §11 scenario 35: passive cam + zero mark; reversing after leaving the cam and before the mark
// disarms the search: the cam must be detected again; MC_Home stays Busy.
TEST(Homing, PassiveCamReversalNeedsTheCamAgain) {
  auto d = homing_data(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam);
  d.Sensor[0].PassiveHoming.Direction = 0;  // positive
  PositioningAxisMachine m(d, cam_drive(40.0, 45.0));
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  start_home(m, 8, 500.0);
  m.run(2);
  // Through the cam to 47 mm (left it at 45, the next mark is 52.5), then back to 30 and forward to 60 (Mode
  // 8 has reset "homed": relative moves).
  m.move_relative.Distance = 47.0;
  m.move_relative.Velocity = 10.0;
  m.move_relative.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 10000), 0);
  m.move_relative2.Distance = -17.0;
  m.move_relative2.Velocity = 10.0;
  m.move_relative2.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_relative2.Done; }, 10000), 0);
  EXPECT_TRUE(m.home.Busy);  // the mark at 42.5 (inside the cam, moving back) did not count
  m.move_relative.Execute = false;
  m.run(1);
  m.move_relative.Distance = 30.0;
  m.move_relative.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.home.Done; }, 10000), 0);
  EXPECT_NEAR(m.db().ActualPosition - (m.drive->load_position() - 52.5), 500.0, 0.02);
}

// spec 02 §5.6, §11 scenario 36: MC_Home Mode 9 aborts a passive homing that has not homed yet: the passive
// job reports CommandAborted, Mode 9 Done.
TEST(Homing, Mode9AbortsPassiveHoming) {
  PositioningAxisMachine m(homing_data(SensorHomingMode::kZeroMarkViaTelegram));
  ASSERT_GT(m.enable(), 0);
  start_home(m, 8, 10.0);
  m.run(5);
  ASSERT_TRUE(m.home.Busy);
  instructions::MC_Home<techobjects::PositioningAxis> abort;
  abort.Mode = 9;
  abort.Execute = true;
  m.user = [&] { abort(*m.axis); };
  m.run(1);
  EXPECT_TRUE(abort.Done);
  m.run(1);
  EXPECT_TRUE(m.home.CommandAborted);
  EXPECT_FALSE(status(m, StatusWordBit::kHomingCommand));
}

// spec 03 §6.1 R1: active homing aborts a running MoveVelocity (C3) and is rejected by a running MC_Stop
// (C6); R4 x C2: a new MoveVelocity aborts active homing (CommandAborted), the axis is left not homed.
TEST(Homing, PriorityCellsOfActiveHoming) {
  PositioningAxisMachine m(homing_data(SensorHomingMode::kZeroMarkViaTelegram));
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = -10.0;
  m.move_velocity.Execute = true;
  m.run(100);
  start_home(m, 3, 0.0);
  m.run(2);
  EXPECT_TRUE(m.move_velocity.CommandAborted);
  EXPECT_TRUE(m.home.Busy);
  m.move_velocity.Execute = false;
  m.run(1);
  m.move_velocity.Execute = true;  // a new job aborts the homing
  m.run(2);
  EXPECT_TRUE(m.home.CommandAborted);
  EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));
  m.move_velocity.Execute = false;
  m.home.Execute = false;
  m.run(50);
  // R1 x C6 = N: an MC_Stop still braking (its Execute already FALSE, so no lock) rejects active homing.
  m.stop.Mode = 3;
  m.stop.Deceleration = 10.0;
  m.stop.Execute = true;
  m.run(1);
  m.stop.Execute = false;
  m.run(10);
  ASSERT_TRUE(m.stop.Busy);
  m.home.Execute = true;
  m.run(1);
  EXPECT_EQ(m.home.ErrorID, eid::kRejectedByRunningJob);
}

// Failure cases: homing needs an enabled axis for 3/5 and 2/8/10 (16#8103); Mode 4 is reserved; 6/7 need an
// absolute encoder (16#8107).
// spec 03 §4.3 (Mode 0…13, 4 reserved; active/passive homing need an enabled TO: 16#8103), spec 02 §5.1
// (6/7 need an absolute encoder: 16#8107, docs/errors.md).
TEST(Homing, RejectedJobs) {
  PositioningAxisMachine m(homing_data(SensorHomingMode::kZeroMarkViaTelegram));
  m.run(10);
  for (const std::int16_t mode : {3, 5, 2, 8, 10}) {
    start_home(m, mode);
    m.run(1);
    EXPECT_EQ(m.home.ErrorID, eid::kAxisNotEnabled) << mode;
    m.home.Execute = false;
    m.run(1);
  }
  for (const auto& [mode, error] : {std::pair<std::int16_t, std::uint16_t>{4, eid::kInvalidMode},
                                    {14, eid::kInvalidMode},
                                    {6, eid::kHomingModeNotAvailable},
                                    {7, eid::kHomingModeNotAvailable}}) {
    start_home(m, mode);
    m.run(1);
    EXPECT_EQ(m.home.ErrorID, error) << mode;
    m.home.Execute = false;
    m.run(1);
  }
}

// An encoder error during active homing: alarm 431 removes the enable, the job ends with 16#8001, an
// incremental encoder is not homed.
// Decision P11 (encoder error: alarm 431, remove enable, an incremental encoder loses HomingDone), spec 03
// §5 (16#8001), spec 02 §5.12.
TEST(Homing, EncoderErrorDuringHoming) {
  PositioningAxisMachine m(homing_data(SensorHomingMode::kZeroMarkViaTelegram));
  ASSERT_GT(m.enable(), 0);
  m.drive->set_link_lost(false);
  start_home(m, 3, 0.0);
  m.run(100);
  m.drive->inject_encoder_error(1, 0x0001);
  ASSERT_GT(m.run_until([&] { return m.home.Error; }, 100), 0);
  EXPECT_EQ(m.home.ErrorID, eid::kAbortedByAlarmReaction);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmSensorFault));
  EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));
}

// spec 01 §2.5: on a virtual axis active homing is executed at once, without motion.
TEST(Homing, VirtualAxisHomesDirectly) {
  auto d = homing_data(SensorHomingMode::kZeroMarkViaTelegram);
  d.VirtualAxis.Mode = techobjects::kModeOn;
  PositioningAxisMachine m(d, linear_drive(), 3, false);
  m.power.Enable = true;
  m.run(2);
  start_home(m, 3, 42.0);
  m.run(1);
  EXPECT_TRUE(m.home.Done);
  EXPECT_DOUBLE_EQ(m.db().ActualPosition, 42.0);
  EXPECT_TRUE(status(m, StatusWordBit::kHomingDone));
}

techobjects::PositioningAxisData absolute_data() {
  auto d = linear_axis_data();
  d.Sensor[0].Type = static_cast<std::int32_t>(techobjects::SensorEncoderType::ABSOLUTE);
  d.Sensor[0].Parameter.DeterminableRevolutions = 4096;  // the simulated encoder's multi-turn range
  return d;
}

// spec 02 §5.9, §11 scenario 39: Mode 7 sets 250.0, stores AbsEncoderOffset, Adjusted; a new runtime that
// restores the retained data on the same mechanics shows 250.0 again, homed, without homing.
TEST(Homing, AbsoluteEncoderAdjustmentSurvivesARestart) {
  techobjects::PositioningAxis::RetainedEncoderData retained;
  double load = 0.0;
  {
    PositioningAxisMachine m(absolute_data());
    m.run(20);
    EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));  // never adjusted
    start_home(m, 7, 250.0);
    m.run(1);
    ASSERT_TRUE(m.home.Done);
    EXPECT_DOUBLE_EQ(m.db().ActualPosition, 250.0);
    EXPECT_EQ(m.db().StatusSensor[0].Adjusted, 1);
    ASSERT_TRUE(m.axis->retained().valid);
    m.home.Execute = false;
    ASSERT_GT(m.enable(), 0);
    m.move_relative.Distance = 12.0;
    m.move_relative.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 3000), 0);
    EXPECT_NEAR(m.db().ActualPosition, 262.0, 0.01);
    EXPECT_NE(m.db().StatusSensor[0].AbsEncoderOffset, 0.0);
    retained = m.axis->retained();
    load = m.drive->load_position();
  }
  auto p = linear_drive();
  p.initial_load_position = load;
  PositioningAxisMachine n(absolute_data(), p);
  n.axis->restore_retained(retained);
  n.run(20);
  EXPECT_TRUE(status(n, StatusWordBit::kHomingDone));
  EXPECT_NEAR(n.db().ActualPosition, 262.0, 0.01);
  // An incremental axis in the same situation starts at 0, not homed (scenario 40).
  PositioningAxisMachine k(linear_axis_data(), p);
  k.axis->restore_retained(retained);
  k.run(20);
  EXPECT_FALSE(status(k, StatusWordBit::kHomingDone));
}

// A lost adjustment is reported, never a silently wrong position: alarm 432, ErrorWord.X10, not homed,
// absolute positioning rejected.
// Decision H5 (a lost adjustment raises alarm 432), spec 04 §5.3 (ErrorWord.X10 HomingError), spec 02 §5.12
// (not homed).
TEST(Homing, LostAdjustmentRaisesAnAlarm) {
  PositioningAxisMachine m(absolute_data());
  m.axis->report_adjustment_lost(2);
  m.run(20);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmAdjustmentLost));
  EXPECT_TRUE(techobjects::test(m.db().ErrorWord, ErrorWordBit::kHomingError));
  EXPECT_FALSE(status(m, StatusWordBit::kHomingDone));
  ASSERT_GT(m.enable(), 0);
  m.move_absolute.Position = 10.0;
  m.move_absolute.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move_absolute.ErrorID, eid::kAxisNotHomed);
}

// spec 02 §5.9: Mode 6 shifts by Position relative to the present actual position and is retentive.
// spec 02 §5.10, §11 scenario 40: Mode 13 on an incremental encoder sets the position, Adjusted, not
// retentive.
TEST(Homing, RelativeAbsoluteAndIncrementalAdjustment) {
  PositioningAxisMachine m(absolute_data());
  m.run(20);
  const double before = m.db().ActualPosition;
  start_home(m, 6, -15.0);
  m.run(1);
  ASSERT_TRUE(m.home.Done);
  EXPECT_NEAR(m.db().ActualPosition, before - 15.0, 1e-9);
  EXPECT_TRUE(m.axis->retained().valid);
  m.home.Execute = false;
  m.run(1);
  start_home(m, 13, 1.0);
  m.run(1);
  EXPECT_EQ(m.home.ErrorID, eid::kHomingModeNotAvailable);  // 13 is for incremental encoders

  PositioningAxisMachine n(linear_axis_data());
  n.run(20);
  start_home(n, 13, 77.0);
  n.run(1);
  ASSERT_TRUE(n.home.Done);
  EXPECT_DOUBLE_EQ(n.db().ActualPosition, 77.0);
  EXPECT_EQ(n.db().StatusSensor[0].Adjusted, 1);
  EXPECT_FALSE(n.axis->retained().valid);  // not retentive
}

// Decision H11 (seed 004 §6.11: Adjusted = "encoder referenced", kept only by an absolute encoder): an
// encoder error takes HomingDone and Adjusted from an incremental encoder, and neither from an absolute one.
TEST(Homing, EncoderErrorResetsAdjustedOnlyOfAnIncrementalEncoder) {
  for (const bool absolute : {false, true}) {
    PositioningAxisMachine m(absolute ? absolute_data() : linear_axis_data());
    m.run(20);
    start_home(m, absolute ? 7 : 13, 10.0);
    m.run(1);
    ASSERT_TRUE(m.home.Done);
    ASSERT_EQ(m.db().StatusSensor[0].Adjusted, 1);
    m.drive->inject_encoder_error(1, 0x0001);
    m.run(3);
    EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmSensorFault));
    EXPECT_EQ(techobjects::test(m.db().StatusWord, techobjects::StatusWordBit::kHomingDone), absolute);
    EXPECT_EQ(m.db().StatusSensor[0].Adjusted, absolute ? 1 : 0);
  }
}

// seed 004 §9.3.1 (spec 03 §4.3): ReferenceMarkPosition is "valid if Done = TRUE" and is the output of the
// instance's own job. A first instance that finished homing and still holds Execute keeps its value when a
// second instance homes the axis later (before issue 14 it showed the second job's value).
TEST(Homing, ReferenceMarkPositionBelongsToTheInstance) {
  PositioningAxisMachine m;
  instructions::MC_Home<techobjects::PositioningAxis> second;
  m.user = [&] { second(*m.axis); };
  ASSERT_GT(m.enable(), 0);
  m.home.Mode = 0;  // direct homing, absolute
  m.home.Position = 10.0;
  m.home.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.home.Done; }, 100), 0);
  EXPECT_DOUBLE_EQ(m.home.ReferenceMarkPosition, 10.0);
  second.Mode = 0;
  second.Position = 50.0;
  second.Execute = true;
  ASSERT_GT(m.run_until([&] { return second.Done; }, 100), 0);
  EXPECT_DOUBLE_EQ(second.ReferenceMarkPosition, 50.0);
  EXPECT_TRUE(m.home.Done);  // Execute still held: Done stays (PLCopen)
  EXPECT_DOUBLE_EQ(m.home.ReferenceMarkPosition, 10.0);
}

}  // namespace
