// Backlash compensation as a component (spec 01 §5.9, §12 scenarios 21–23, spec 04 §8 rule 10, §5.2 X2):
// motor positions in, corrections of the actual value out. The model of backlash.hpp: actual = motor + c.
#include "tomc/techobjects/position/backlash.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using tomc::techobjects::BacklashCompensation;
using tomc::techobjects::BacklashConfig;
using tomc::techobjects::BacklashInput;

constexpr double kSize = 0.2;  // mm
constexpr double kTs = 0.001;  // s
constexpr double kTol = 1e-12;

// Feeds the component like the axis does and keeps actual = motor + c.
struct Rig {
  explicit Rig(BacklashConfig config = BacklashConfig{true, kSize, 0.0, kTs}) {
    EXPECT_TRUE(b.configure(config));
    step(0.0);  // reference
  }
  // One servo cycle with the motor at `m`; returns the correction of this cycle.
  double step(double m, bool setpoint_operation = true, double v = 0.0) {
    motor = m;
    const double c = b.update(BacklashInput{m, true, setpoint_operation, v});
    correction += c;
    return c;
  }
  double actual() const { return motor + correction; }
  double shown() const { return actual() - b.held_travel(); }
  BacklashCompensation b;
  double motor = 0.0;
  double correction = 0.0;
};

// spec 01 §5.9 "non-homed axes": the first motion is not compensated; once the motor has gone Size in one
// direction the side is known. Moving +0.15 and back −0.1 leaves it unknown (no point lies Size behind),
// going on to −0.05 (0.2 below the highest point 0.15) makes it known: in contact on the negative side.
TEST(Backlash, FirstMotionOfANonHomedAxisIsNotCompensated) {
  Rig r;
  EXPECT_EQ(r.b.contact(), 0);
  for (double m : {0.05, 0.10, 0.15, 0.10, 0.05, 0.0}) {
    EXPECT_EQ(r.step(m, true, m > r.motor ? 10.0 : -10.0), 0.0);
    EXPECT_FALSE(r.b.known());
    EXPECT_FALSE(r.b.passing());
  }
  EXPECT_EQ(r.step(-0.05, true, -10.0), 0.0);
  EXPECT_TRUE(r.b.known());
  EXPECT_EQ(r.b.contact(), -1);
  EXPECT_EQ(r.correction, 0.0);  // nothing was compensated on the way
}

// spec 01 §12 scenario 21 (Velocity 0.0): the reversal shifts the actual value by Size within one servo
// cycle, against the new direction (c −= d·Size, d = −1: +0.2); PassingBacklash stays TRUE until the motor
// has crossed the gap; ActualPosition (actual − held_travel) does not change meanwhile (spec 04 §5.2 X2).
TEST(Backlash, ReversalShiftsByTheSizeInOneCycleAndHoldsActualPosition) {
  Rig r;
  double m = 0.0;
  for (int k = 0; k < 10; ++k)
    r.step(m += 0.05, true, 50.0);  // 0.5 mm positive: contact on the positive side
  ASSERT_EQ(r.b.contact(), 1);
  const double before = r.shown();
  // Reversal: the setpoint velocity turns negative; the motor has not moved yet in this cycle.
  EXPECT_NEAR(r.step(m, true, -50.0), +kSize, kTol);
  EXPECT_TRUE(r.b.passing());
  EXPECT_NEAR(r.actual(), before + kSize,
              kTol);  // the control deviation that drives the motor through the gap
  EXPECT_NEAR(r.shown(), before, kTol);
  // The motor crosses the gap in 4 steps of 0.05 mm: no further correction, ActualPosition stays.
  for (int k = 1; k <= 4; ++k) {
    EXPECT_EQ(r.step(m -= 0.05, true, -50.0), 0.0);
    EXPECT_NEAR(r.shown(), before, kTol);
    EXPECT_EQ(r.b.passing(), k < 4) << k;
  }
  // Crossed: the actual value is the load's again and follows the motor.
  EXPECT_NEAR(r.actual(), before, kTol);
  r.step(m -= 0.05, true, -50.0);
  EXPECT_NEAR(r.shown(), before - 0.05, kTol);
  EXPECT_EQ(r.b.contact(), -1);
}

// spec 01 §12 scenario 22: Backlash.Velocity = 2 mm/s shifts 0.002 mm per 1 ms cycle: 0.2 mm in 100 cycles
// (0.1 s); PassingBacklash lasts at least that long even though the motor crossed earlier.
TEST(Backlash, VelocitySpreadsTheShift) {
  Rig r(BacklashConfig{true, kSize, 2.0, kTs});
  double m = 0.0;
  for (int k = 0; k < 10; ++k)
    r.step(m -= 0.05, true, -50.0);
  ASSERT_EQ(r.b.contact(), -1);
  int cycles = 0;
  double shifted = 0.0;
  for (int k = 0; k < 200 && (k == 0 || r.b.passing()); ++k) {
    const double c = r.step(m += (k < 40 ? 0.005 : 0.0), true, 50.0);
    shifted += c;
    if (c != 0.0) {
      ++cycles;
      EXPECT_NEAR(c, -0.002, 1e-12);
    }
  }
  EXPECT_EQ(cycles, 100);
  EXPECT_NEAR(shifted, -kSize, 1e-12);
  EXPECT_FALSE(r.b.passing());
  EXPECT_EQ(r.b.contact(), 1);
}

// Follow-up mode / no position control (spec 01 §5.9 "funzionamento a seguire"): no shift ahead; the actual
// value stays where the load is while the motor crosses the gap and is coupled again once it is crossed.
TEST(Backlash, FollowUpCouplesTheActualValueOnlyAfterTheGap) {
  Rig r;
  double m = 0.0;
  for (int k = 0; k < 10; ++k)
    r.step(m += 0.05, false);
  ASSERT_EQ(r.b.contact(), 1);
  const double load = r.actual();
  for (int k = 1; k <= 4; ++k) {
    EXPECT_NEAR(r.step(m -= 0.05, false), 0.05, kTol);
    EXPECT_NEAR(r.actual(), load, kTol);
    EXPECT_FALSE(r.b.passing());
  }
  EXPECT_NEAR(r.step(m -= 0.05, false), 0.0, kTol);
  EXPECT_NEAR(r.actual(), load - 0.05, kTol);
  // Half-way back and then position control with a positive motion: only the remaining 0.1 mm is shifted.
  r.step(m += 0.1, false);
  EXPECT_NEAR(r.b.gap_position(), 0.1, kTol);
  EXPECT_NEAR(r.step(m, true, 0.0), 0.0, kTol);  // enabled, standing: nothing yet
  EXPECT_NEAR(r.step(m, true, 20.0), -0.1, kTol);
  EXPECT_TRUE(r.b.passing());
}

// The motor still runs on in the old direction for a few cycles after the reversal began (position-loop lag):
// the gap position stays in contact, the shift is done, and PassingBacklash waits for the crossing.
// seed 004 §6.4.8 (spec 01 §5.9; StatusWord2.X2 "ActualPosition is not changing", spec 04 §5.2), decision
// P19 (X2 until the crossing is complete).
TEST(Backlash, ReversalWhileTheMotorStillRunsOn) {
  Rig r;
  double m = 0.0;
  for (int k = 0; k < 10; ++k)
    r.step(m += 0.05, true, 50.0);
  const double before = r.shown();
  EXPECT_NEAR(r.step(m += 0.02, true, -50.0), kSize, kTol);
  r.step(m += 0.01, true, -50.0);  // still positive: the load moves with it
  EXPECT_TRUE(r.b.passing());
  EXPECT_NEAR(r.shown(), before, kTol);  // held at the value of the reversal
  for (int k = 0; k < 4; ++k)
    r.step(m -= 0.05, true, -50.0);
  EXPECT_FALSE(r.b.passing());
  EXPECT_NEAR(r.b.gap_position(), 0.0, kTol);
}

// A reversal back during the crossing turns the shift round; PassingBacklash continues.
// spec 01 §5.9 (backlash compensated at each reversal), decision P19 (a reversal during the crossing turns
// the shift round).
TEST(Backlash, SecondReversalDuringTheCrossing) {
  Rig r;
  double m = 0.0;
  for (int k = 0; k < 10; ++k)
    r.step(m += 0.05, true, 50.0);
  const double before = r.shown();
  r.step(m, true, -50.0);                            // c += 0.2
  r.step(m -= 0.05, true, -50.0);                    // a quarter crossed
  EXPECT_NEAR(r.step(m, true, 50.0), -kSize, kTol);  // back: shift to the positive side again
  EXPECT_TRUE(r.b.passing());
  r.step(m += 0.05, true, 50.0);
  EXPECT_FALSE(r.b.passing());
  EXPECT_NEAR(r.actual(), before, kTol);
}

// spec 04 §8 rule 10: changing Enable or Size (at run time, without restart) makes the side unknown — the
// next motion is a first motion again and the axis must be homed again; Velocity changes act at once.
TEST(Backlash, ChangingEnableOrSizeNeedsANewFirstMotion) {
  Rig r;
  double m = 0.0;
  for (int k = 0; k < 10; ++k)
    r.step(m += 0.05, true, 50.0);
  ASSERT_TRUE(r.b.known());
  EXPECT_TRUE(r.b.configure(BacklashConfig{true, kSize, 5.0, kTs}));
  EXPECT_TRUE(r.b.known());
  EXPECT_TRUE(r.b.configure(BacklashConfig{true, 0.3, 5.0, kTs}));
  EXPECT_FALSE(r.b.known());
  EXPECT_EQ(r.step(m -= 0.05, true, -50.0), 0.0);  // no compensation
  for (int k = 0; k < 6; ++k)
    r.step(m -= 0.05, true, -50.0);
  EXPECT_EQ(r.b.contact(), -1);  // 0.35 mm negative >= 0.3
  EXPECT_TRUE(r.b.configure(BacklashConfig{false, 0.3, 5.0, kTs}));
  EXPECT_FALSE(r.b.active());
  EXPECT_EQ(r.step(m += 1.0, true, 50.0), 0.0);
  EXPECT_FALSE(r.b.passing());
}

// Absolute encoder after power-up (spec 02 §5.11 Mode 6/7): the side is the one of the adjustment; a first
// motion against it crosses the backlash compensated.
TEST(Backlash, AssumedContactOfAnAdjustedAbsoluteEncoder) {
  Rig r;
  r.b.assume_contact(+1);  // DirectionAbsoluteHoming = 0 (positive)
  EXPECT_EQ(r.b.contact(), 1);
  EXPECT_EQ(r.step(0.0, true, 10.0), 0.0);             // the same direction: nothing
  EXPECT_NEAR(r.step(0.0, true, -10.0), kSize, kTol);  // the other one: compensated at once
  r.b.reset();
  EXPECT_FALSE(r.b.known());
}

// An invalid encoder value makes the next valid one a new reference (e.g. the chain restarted from 0).
// Decision P18 (the correction lives in the actual-value chain); tomc's own: an invalid value restarts the
// reference, no motion is invented.
TEST(Backlash, InvalidEncoderValueRestartsTheReference) {
  Rig r;
  double m = 0.0;
  for (int k = 0; k < 10; ++k)
    r.step(m += 0.05, true, 50.0);
  EXPECT_EQ(r.b.update(BacklashInput{0.0, false, true, 0.0}), 0.0);
  EXPECT_EQ(r.b.update(BacklashInput{-1000.0, true, true, 0.0}), 0.0);  // new origin: no motion
  EXPECT_EQ(r.b.contact(), 1);
}

// spec 04 §3.6 (Sensor[n].Backlash.Size ≥ 0, finite Velocity), ARCHITECTURE-GUIDE §6 (bad values never
// reach the cycle).
TEST(Backlash, InvalidConfigurationIsRejected) {
  BacklashCompensation b;
  EXPECT_FALSE(b.configure(BacklashConfig{true, -0.1, 0.0, kTs}));
  EXPECT_FALSE(b.configure(BacklashConfig{true, 0.1, std::nan(""), kTs}));
  EXPECT_FALSE(b.configure(BacklashConfig{true, 0.1, 0.0, 0.0}));
  EXPECT_FALSE(b.config().Enable);
  EXPECT_FALSE(b.active());
}

}  // namespace
