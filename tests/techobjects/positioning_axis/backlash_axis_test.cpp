// Backlash compensation on the positioning axis, end to end on the simulated drive with a backlash dead band
// between motor and load (spec 01 §5.9 and §12 scenarios 21–23, spec 04 §8 rule 10, §5.2 StatusWord2.X2,
// seed 004 §6.4.8). Unless a test says otherwise: the default linear axis (mm, 10 mm/rev leadscrew,
// motor-shaft encoder, Kv 50 1/s, 100 % precontrol, DynamicDefaults 100 mm/s and 1000 mm/s², positioning
// window 0.01 mm) on a drive whose load lags the motor by a 0.2 mm backlash; servo = interpolator = 1 ms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "positioning_axis_fixture.hpp"

namespace {

using namespace tomc;
using techobjects::StatusWord2Bit;
using techobjects::StatusWordBit;
using tomc::testing::linear_axis_data;
using tomc::testing::linear_drive;
using tomc::testing::PositioningAxisMachine;

constexpr double kBacklash = 0.2;  // mm

techobjects::PositioningAxisData compensated(double size = kBacklash, double velocity = 0.0) {
  auto d = linear_axis_data();
  d.Sensor[0].Backlash.Enable = true;
  d.Sensor[0].Backlash.Size = size;
  d.Sensor[0].Backlash.Velocity = velocity;
  return d;
}

drives::SimulatedDriveParameters drive_with_backlash() {
  auto p = linear_drive();
  p.backlash = kBacklash;
  return p;
}

bool passing(const PositioningAxisMachine& m) {
  return techobjects::test(m.db().StatusWord2, StatusWord2Bit::kPassingBacklash);
}

// What a relative move looked like, cycle by cycle from its edge.
struct MoveRecord {
  int done_at = -1;         // cycles from the edge call (cycle 1) to Done
  int passing_from = -1;    // first cycle with StatusWord2.X2
  int passing_cycles = 0;   // cycles with X2
  double jump = 0.0;        // continuous actual − ActualPosition in the first X2 cycle
  bool actual_held = true;  // ActualPosition unchanged while X2 (to rounding, 1e-9 mm)
  bool load_still = true;   // the load did not move while X2 (the motor was in the gap)
  double load_start = 0.0;
  double actual_start = 0.0;
};

MoveRecord move_relative(PositioningAxisMachine& m, double distance, double velocity = 100.0) {
  MoveRecord r;
  r.load_start = m.drive->load_position();
  r.actual_start = m.db().ActualPosition;
  m.move_relative.Distance = distance;
  m.move_relative.Velocity = velocity;
  m.move_relative.Execute = true;
  double held = 0.0;
  double load_at_passing = 0.0;
  for (int k = 1; k <= 5000 && r.done_at < 0; ++k) {
    m.run(1);
    if (passing(m)) {
      if (r.passing_from < 0) {
        r.passing_from = k;
        held = m.db().ActualPosition;
        load_at_passing = m.drive->load_position();
        r.jump = m.axis->continuous_actual_position() - m.db().ActualPosition;
      }
      ++r.passing_cycles;
      if (std::fabs(m.db().ActualPosition - held) > 1e-9) r.actual_held = false;
      if (std::fabs(m.drive->load_position() - load_at_passing) > 1e-9) r.load_still = false;
    }
    if (m.move_relative.Done) r.done_at = k;
  }
  m.move_relative.Execute = false;
  m.run(300);  // settled (Kv 50 1/s: 15 time constants), so that the next move starts from rest
  return r;
}

// Enabled, a first positive motion of 10 mm (which makes the side of the gap known), then homed on the load's
// true position (as a commissioning engineer would after measuring it), then 5 mm more in the same direction.
void prepare(PositioningAxisMachine& m) {
  ASSERT_GT(m.enable(), 0);
  ASSERT_GT(move_relative(m, 10.0).done_at, 0);
  ASSERT_TRUE(m.home_at(m.drive->load_position()));
  const MoveRecord r = move_relative(m, 5.0);
  ASSERT_GT(r.done_at, 0);
  ASSERT_EQ(r.passing_from, -1);  // no reversal, no compensation
  ASSERT_NEAR(m.drive->load_position(), m.db().ActualPosition, 0.01);
}

// spec 01 §12 scenario 21, spec 04 §8 rule 10, §5.2 X2: Size 0.2 mm, Velocity 0.0, a homed axis that moved
// positive; MC_MoveRelative −5 mm. The job moves from the interpolator of cycle 2 (edge in cycle 1), so the
// servo of cycle 3 sees the first negative setpoint: X2 from cycle 3, where the actual value is shifted by
// +0.2 mm at once (against the new direction). While X2: ActualPosition does not change and neither does the
// load (the motor is in the gap). The load ends 5 mm from its start within the positioning window; the way
// back by +5 mm is compensated the same way.
TEST(BacklashAxis, ReversalIsCompensatedWithinOneServoCycle) {
  PositioningAxisMachine m(compensated(), drive_with_backlash());
  prepare(m);
  const MoveRecord back = move_relative(m, -5.0);
  ASSERT_GT(back.done_at, 0);
  EXPECT_EQ(back.passing_from, 3);
  EXPECT_NEAR(back.jump, kBacklash, 1e-6);
  EXPECT_TRUE(back.actual_held);
  EXPECT_TRUE(back.load_still);
  // The motor crosses the gap by the setpoint's own travel 0.5·1000 mm/s²·t² plus the controller's answer to
  // the 0.2 mm deviation, 0.2·(1 − e^(−50 t)): 0.098 + 0.101 mm at t = 14 ms, plus two cycles of loop delay.
  EXPECT_GE(back.passing_cycles, 12);
  EXPECT_LE(back.passing_cycles, 20);
  EXPECT_NEAR(m.drive->load_position(), back.load_start - 5.0, m.db().PositioningMonitoring.Window);
  EXPECT_NEAR(m.db().ActualPosition, back.actual_start - 5.0, m.db().PositioningMonitoring.Window);
  EXPECT_FALSE(passing(m));

  const MoveRecord forth = move_relative(m, 5.0);
  ASSERT_GT(forth.done_at, 0);
  EXPECT_EQ(forth.passing_from, 3);
  EXPECT_NEAR(forth.jump, -kBacklash, 1e-6);
  EXPECT_TRUE(forth.actual_held);
  EXPECT_TRUE(forth.load_still);
  EXPECT_NEAR(m.drive->load_position(), forth.load_start + 5.0, m.db().PositioningMonitoring.Window);
  EXPECT_NEAR(m.drive->load_position(), m.db().ActualPosition, m.db().PositioningMonitoring.Window);
  EXPECT_EQ(m.db().ErrorWord, 0u);
}

// The same machine without compensation: the axis reports the target, but after each reversal the load is off
// by the backlash (spec 01 §5.9 "without compensation the axis is not moved to the correct position").
TEST(BacklashAxis, WithoutCompensationTheLoadMissesByTheBacklash) {
  PositioningAxisMachine m(linear_axis_data(), drive_with_backlash());
  prepare(m);
  const MoveRecord back = move_relative(m, -5.0);
  ASSERT_GT(back.done_at, 0);
  EXPECT_EQ(back.passing_from, -1);
  EXPECT_NEAR(m.db().ActualPosition, back.actual_start - 5.0, m.db().PositioningMonitoring.Window);
  EXPECT_NEAR(m.drive->load_position(), back.load_start - 5.0 + kBacklash, 0.01);
  const MoveRecord forth = move_relative(m, 5.0);
  ASSERT_GT(forth.done_at, 0);
  EXPECT_NEAR(m.drive->load_position(), forth.load_start + 5.0 - kBacklash, 0.01);
  EXPECT_NEAR(m.drive->load_position() - m.db().ActualPosition, 0.0, 0.01);  // back at the homing side
}

// spec 01 §12 scenario 22: Backlash.Velocity 2 mm/s applies the 0.2 mm over 0.1 s = 100 servo cycles; X2
// lasts exactly those 100 cycles (the setpoint's own travel has crossed the gap long before) and the load
// still ends at its target.
TEST(BacklashAxis, BacklashVelocitySpreadsTheShiftOverSizeByVelocity) {
  PositioningAxisMachine m(compensated(kBacklash, 2.0), drive_with_backlash());
  prepare(m);
  const MoveRecord back = move_relative(m, -5.0);
  ASSERT_GT(back.done_at, 0);
  EXPECT_EQ(back.passing_from, 3);
  EXPECT_EQ(back.passing_cycles, 100);
  EXPECT_NEAR(back.jump, 0.002, 1e-6);  // 2 mm/s × 1 ms in the first cycle
  EXPECT_TRUE(back.actual_held);
  EXPECT_NEAR(m.drive->load_position(), back.load_start - 5.0, m.db().PositioningMonitoring.Window);
  EXPECT_NEAR(m.db().ActualPosition, back.actual_start - 5.0, m.db().PositioningMonitoring.Window);
}

// spec 01 §12 scenario 23: after power-up the side of the gap is unknown (the simulated motor starts in the
// middle of it) and the first motion is not compensated: +5 mm moves the load 5 − 0.1 mm. The next reversal
// is compensated: −5 mm moves the load by 5 mm. A first motion shorter than the backlash followed by a
// reversal does not yet count as crossed.
TEST(BacklashAxis, FirstMotionOfANonHomedAxisIsNotCompensated) {
  {
    PositioningAxisMachine m(compensated(), drive_with_backlash());
    ASSERT_GT(m.enable(), 0);
    EXPECT_FALSE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));
    const MoveRecord first = move_relative(m, 5.0);
    ASSERT_GT(first.done_at, 0);
    EXPECT_EQ(first.passing_from, -1);
    EXPECT_NEAR(m.drive->load_position() - first.load_start, 5.0 - 0.5 * kBacklash, 0.01);
    const MoveRecord back = move_relative(m, -5.0);
    ASSERT_GT(back.done_at, 0);
    EXPECT_EQ(back.passing_from, 3);
    EXPECT_NEAR(m.drive->load_position() - back.load_start, -5.0, 0.01);
  }
  {
    PositioningAxisMachine m(compensated(), drive_with_backlash());
    ASSERT_GT(m.enable(), 0);
    ASSERT_GT(move_relative(m, 0.05).done_at, 0);  // inside the gap: the load does not move
    const MoveRecord back = move_relative(m, -1.0);
    ASSERT_GT(back.done_at, 0);
    EXPECT_EQ(back.passing_from, -1);  // still the first motion: 0.05 + 1 mm from the highest point only now
    const MoveRecord forth = move_relative(m, 1.0);
    EXPECT_EQ(forth.passing_from, 3);  // this reversal is compensated
  }
}

// spec 01 §12 scenario 23 (second part), spec 04 §8 rule 10: Backlash.Size is DIR — a write takes effect
// without a restart, but the side of the gap is unknown again (the axis must be homed again): the next
// reversal is not compensated, the one after it with the new size.
TEST(BacklashAxis, ChangingTheSizeAtRunTimeNeedsAFirstMotionAgain) {
  PositioningAxisMachine m(compensated(), drive_with_backlash());
  prepare(m);
  const auto w = m.axis->write("Sensor[1].Backlash.Size", 0.25);
  ASSERT_TRUE(w.ok());
  EXPECT_EQ(m.axis->backlash().config().Size, 0.25);
  EXPECT_FALSE(m.axis->backlash().known());
  const MoveRecord back = move_relative(m, -5.0);
  EXPECT_EQ(back.passing_from, -1);
  const MoveRecord forth = move_relative(m, 5.0);
  EXPECT_EQ(forth.passing_from, 3);
  EXPECT_NEAR(forth.jump, -0.25, 1e-6);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));  // not reset (spec 02 §5.12)
}

// spec 01 §5.9 follow-up model, here with MC_MoveVelocity PositionControlled = FALSE (no position control,
// the setpoint follows the actual value): no shift ahead; the TO's actual position stays while the motor
// crosses the gap and is coupled to the motor again afterwards, so it moves exactly as the load does, also
// through a reversal.
TEST(BacklashAxis, WithoutPositionControlTheActualValueFollowsTheLoad) {
  PositioningAxisMachine m(compensated(), drive_with_backlash());
  prepare(m);
  const double load0 = m.drive->load_position();
  const double actual0 = m.db().ActualPosition;
  m.move_velocity.PositionControlled = false;
  m.move_velocity.Velocity = -20.0;
  m.move_velocity.Execute = true;
  double worst = 0.0;
  for (int k = 0; k < 300; ++k) {
    m.run(1);
    worst =
        std::max(worst, std::fabs((m.db().ActualPosition - actual0) - (m.drive->load_position() - load0)));
    EXPECT_FALSE(passing(m));
  }
  EXPECT_LT(m.drive->load_position() - load0, -2.0);  // it moved
  EXPECT_LT(worst, 1e-4);                             // within a few encoder counts (2.4 µm each)
  EXPECT_EQ(m.axis->backlash().contact(), -1);
}

// A modulo axis reversing just below the range end: the internal actual value is shifted across 360° while
// ActualPosition stays at 359.8° and ActualModuloCycle stays (spec 01 §2.4, §5.9); the table ends at 358.8°
// in the same cycle, and the load agrees.
TEST(BacklashAxis, ModuloAxisReversingAtTheRangeEnd) {
  techobjects::PositioningAxisData d;
  d.Properties.MotionType = static_cast<std::int32_t>(techobjects::PropertiesMotionType::kRotary);
  d.Units.LengthUnit = techobjects::unit_code::kDegree;
  d.Units.VelocityUnit = techobjects::unit_code::kDegreePerSecond;
  d.Modulo.Enable = true;
  d.Modulo.Length = 360.0;
  d.DynamicLimits.MaxJerk = 0.0;
  d.DynamicDefaults.Velocity = 90.0;
  d.DynamicDefaults.Acceleration = 900.0;
  d.DynamicDefaults.Deceleration = 900.0;
  d.FollowingError.MinValue = 5.0;
  d.FollowingError.MaxValue = 50.0;
  d.PositioningMonitoring.Window = 0.05;
  d.Sensor[0].Backlash.Enable = true;
  d.Sensor[0].Backlash.Size = 0.5;
  drives::SimulatedDriveParameters p;
  p.load_units_per_revolution = 360.0;
  p.backlash = 0.5;
  PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);
  ASSERT_GT(move_relative(m, 2.0, 90.0).done_at, 0);
  ASSERT_TRUE(m.home_at(359.5));
  const std::int32_t cycle = m.db().ActualModuloCycle;
  EXPECT_EQ(cycle, -1);  // from 2° to 359.5° the shorter way, backwards (spec 01 §2.4.1)
  const double load_at_home = m.drive->load_position();
  ASSERT_GT(move_relative(m, 0.3, 90.0).done_at, 0);
  ASSERT_NEAR(m.db().ActualPosition, 359.8, 0.05);
  ASSERT_EQ(m.db().ActualModuloCycle, cycle);
  const double shown = m.db().ActualPosition;
  m.move_relative.Distance = -1.0;
  m.move_relative.Velocity = 90.0;
  m.move_relative.Execute = true;
  m.run(3);
  ASSERT_TRUE(passing(m));
  EXPECT_EQ(m.db().ActualPosition, shown);
  EXPECT_EQ(m.db().ActualModuloCycle, cycle);
  EXPECT_EQ(m.db().ModuloCycle, cycle);
  EXPECT_NEAR(m.axis->continuous_actual_position() - m.db().ActualPosition, 0.5, 1e-6);
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 3000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 358.8, 0.05);
  EXPECT_EQ(m.db().ActualModuloCycle, cycle);
  EXPECT_NEAR(m.drive->load_position() - load_at_home, 358.8 - 359.5, 0.05);
}

// spec 02 §5.11 (homing with backlash compensation, Mode 3): active homing approaches the zero mark in the
// homing direction, so the gap is crossed before the mark; the compensation needs no homing hook (its
// correction lives in the actual-value chain's offset, which homing sets). Afterwards every move, in either
// direction, moves the load exactly as far as ActualPosition says — for both homing directions.
TEST(BacklashAxis, ActiveHomingWithBacklash) {
  for (const std::int32_t direction : {0, 1}) {
    auto d = compensated();
    d.Sensor[0].ActiveHoming.Mode =
        static_cast<std::int32_t>(techobjects::SensorHomingMode::kZeroMarkViaTelegram);
    d.Sensor[0].ActiveHoming.Direction = direction;
    d.Homing.ApproachVelocity = 20.0;
    d.Homing.ReferencingVelocity = 5.0;
    auto p = drive_with_backlash();
    p.initial_load_position = 30.0;
    PositioningAxisMachine m(d, p);
    ASSERT_GT(m.enable(), 0);
    m.home.Mode = 3;
    m.home.Position = 100.0;
    m.home.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.home.Done; }, 20000), 0) << direction;
    m.home.Execute = false;
    m.run(300);
    EXPECT_NEAR(m.db().ActualPosition, 100.0, 0.01);
    for (const double distance : {-5.0, 5.0, 3.0, -7.0}) {
      const MoveRecord r = move_relative(m, distance);
      ASSERT_GT(r.done_at, 0);
      EXPECT_NEAR(m.db().ActualPosition - r.actual_start, distance, 0.01);
      EXPECT_NEAR(m.drive->load_position() - r.load_start, m.db().ActualPosition - r.actual_start, 1e-3)
          << "direction " << direction << ", move " << distance;
    }
  }
}

// spec 02 §5.11 Mode 6/7, spec 01 §5.9: an absolute encoder adjusted after positive travel
// (Backlash.DirectionAbsoluteHoming = 0) shows the right position after a power-up with the mechanics
// unchanged, and the gap's side is known at once: the first motion, negative, is compensated ("the axis
// traverses the backlash if the first motion is opposite to DirectionAbsoluteHoming"). With the wrong
// direction configured (1), the TO assumes the other side and the same first motion misses by the backlash.
TEST(BacklashAxis, AbsoluteEncoderPowerUpTakesTheSideOfTheAdjustment) {
  auto d = compensated();
  d.Sensor[0].Type = static_cast<std::int32_t>(techobjects::SensorEncoderType::ABSOLUTE);
  d.Sensor[0].Parameter.DeterminableRevolutions = 4096;  // the simulated encoder's multi-turn range
  techobjects::PositioningAxis::RetainedEncoderData retained;
  auto p = drive_with_backlash();
  {
    PositioningAxisMachine m(d, p);
    ASSERT_GT(m.enable(), 0);
    ASSERT_GT(move_relative(m, 10.0).done_at, 0);  // travel positive before the adjustment
    m.home.Mode = 7;
    m.home.Position = 250.0;
    m.home.Execute = true;
    m.run(1);
    ASSERT_TRUE(m.home.Done);
    m.home.Execute = false;
    ASSERT_GT(move_relative(m, 5.0).done_at, 0);
    EXPECT_NEAR(m.db().ActualPosition, 255.0, 0.01);
    retained = m.axis->retained();
    ASSERT_TRUE(retained.valid);
    p.initial_load_position = m.drive->load_position();
    p.initial_backlash_offset = m.drive->backlash_offset();  // the mechanics keep their state
    EXPECT_NEAR(p.initial_backlash_offset, 0.5 * kBacklash, 1e-12);
  }
  for (const std::int32_t direction : {0, 1}) {
    d.Sensor[0].Backlash.DirectionAbsoluteHoming = direction;
    PositioningAxisMachine n(d, p);
    n.axis->restore_retained(retained);
    n.run(20);
    EXPECT_TRUE(techobjects::test(n.db().StatusWord, StatusWordBit::kHomingDone));
    EXPECT_NEAR(n.db().ActualPosition, 255.0, 0.01);
    EXPECT_EQ(n.axis->backlash().contact(), direction == 0 ? 1 : -1);
    ASSERT_GT(n.enable(), 0);
    const MoveRecord first = move_relative(n, -5.0);
    ASSERT_GT(first.done_at, 0);
    EXPECT_NEAR(n.db().ActualPosition, 250.0, 0.01);
    if (direction == 0) {
      EXPECT_EQ(first.passing_from, 3);
      EXPECT_NEAR(n.drive->load_position() - first.load_start, -5.0, 0.01);
    } else {
      EXPECT_EQ(first.passing_from, -1);
      EXPECT_NEAR(n.drive->load_position() - first.load_start, -5.0 + kBacklash, 0.01);
    }
  }
}

// spec 01 §5.2, §5.9, spec 04 §3.6: only an encoder on the motor shaft has backlash compensation; a load-side
// encoder with Backlash.Enable is a configuration error naming the variable.
TEST(BacklashAxis, LoadSideEncoderWithBacklashIsRejected) {
  auto d = compensated();
  d.Sensor[0].MountingMode = static_cast<std::int32_t>(techobjects::EncoderMounting::kLoadSide);
  try {
    PositioningAxisMachine m(d, drive_with_backlash());
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Axis1.Sensor[1].Backlash.Enable"), std::string::npos) << e.what();
  }
}

}  // namespace
