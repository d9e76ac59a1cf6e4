// Dynamic filter (spec 02 §7.6, spec 04 §3.22, seed 004 §6.13.6): step and ramp responses against the
// discrete formulas of dynamic_filter.hpp, the 16·T_s limit, pass-through, homing shift.
#include "tomc/techobjects/position/dynamic_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using tomc::techobjects::DynamicFilter;
using tomc::techobjects::DynamicFilterConfig;
using tomc::techobjects::MotionState;

constexpr double kExact = 1e-12;

DynamicFilter make(std::int32_t mode, double t1, double t2, double tt, double ts) {
  DynamicFilter f;
  EXPECT_TRUE(f.configure(DynamicFilterConfig{mode, t1, t2, tt, ts}));
  return f;
}

void expect_near_all(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t k = 0; k < actual.size(); ++k)
    EXPECT_NEAR(actual[k], expected[k], kExact) << "k = " << k;
}

// Position outputs for a unit step at k = 0 (the filter has seen 0 before), cycles 0 ... n−1.
std::vector<double> step_response(DynamicFilter& f, int n) {
  for (int i = 0; i < 40; ++i)
    (void)f.update(MotionState{0.0, 0.0, 0.0}, true);
  std::vector<double> out;
  for (int k = 0; k < n; ++k)
    out.push_back(f.update(MotionState{1.0, 0.0, 0.0}, true).position);
  return out;
}

// spec 02 §11 scenario 43 (seed 004 §6.13.6.2): T_s = 4 ms, T1 = 13 ms: the current value and the last 3 at
// full weight, the 4th-oldest at 1/4 -> 1/4.25, 2/4.25, 3/4.25, 4/4.25, then 1.0 from k = 4 on.
TEST(DynamicFilter, MovingAverageWithResidualWeightScenario43) {
  DynamicFilter f = make(2, 0.013, 0.0, 0.0, 0.004);
  const auto y = step_response(f, 8);
  EXPECT_NEAR(y[0], 1.0 / 4.25, kExact);
  EXPECT_NEAR(y[1], 2.0 / 4.25, kExact);
  EXPECT_NEAR(y[2], 3.0 / 4.25, kExact);
  EXPECT_NEAR(y[3], 4.0 / 4.25, kExact);
  for (int k = 4; k < 8; ++k)
    EXPECT_NEAR(y[k], 1.0, kExact) << k;
  // Lag behind a ramp: (N(N+1)/2 + r(N+1)) / (N+1+r) = (6 + 1)/4.25 cycles of 4 ms.
  EXPECT_NEAR(f.effective_delay(), 7.0 / 4.25 * 0.004, kExact);
}

// seed 004 §6.13.6.2: T_s = 4 ms, T1 = 12 ms: the average of the current value and the last 3; the lag behind
// a ramp is 0.5·T1 = 6 ms (the AdditionalSetpointDelayTime of the seed's example 1 with T1 = 4 ms is 2 ms).
TEST(DynamicFilter, MovingAverageOfWholeCyclesLagsHalfItsWindow) {
  DynamicFilter f = make(2, 0.012, 0.0, 0.0, 0.004);
  const auto y = step_response(f, 5);
  EXPECT_NEAR(y[0], 0.25, kExact);
  EXPECT_NEAR(y[1], 0.50, kExact);
  EXPECT_NEAR(y[2], 0.75, kExact);
  EXPECT_NEAR(y[3], 1.00, kExact);
  EXPECT_NEAR(f.effective_delay(), 0.006, kExact);

  // Ramp of 100 mm/s: after the window has filled, x_f = x_ipo − 100 · 0.006 exactly.
  DynamicFilter g = make(2, 0.012, 0.0, 0.0, 0.004);
  for (int k = 0; k < 50; ++k) {
    const double x = 100.0 * 0.004 * k;
    const MotionState out = g.update(MotionState{x, 100.0, 0.0}, true);
    if (k >= 3) {
      EXPECT_NEAR(out.position, x - 0.6, 1e-9) << k;
    }
    EXPECT_NEAR(out.velocity, 100.0, 1e-9);  // the velocity channel is averaged too: constant stays
  }
}

// Two moving averages in series (T1 > 0, T2 > 0): the boxes [1 1 1 1]/4 convolve to [1 2 3 4 3 2 1]/16, so
// the step response is 1, 3, 6, 10, 13, 15, 16 sixteenths; lag 0.5·T1 + 0.5·T2 = 12 ms.
TEST(DynamicFilter, TwoMovingAveragesInSeries) {
  DynamicFilter f = make(2, 0.012, 0.012, 0.0, 0.004);
  const auto y = step_response(f, 8);
  const double expected[] = {1, 3, 6, 10, 13, 15, 16, 16};
  for (int k = 0; k < 8; ++k)
    EXPECT_NEAR(y[k], expected[k] / 16.0, kExact) << k;
  EXPECT_NEAR(f.effective_delay(), 0.012, kExact);
  // T2 alone is one moving average like T1 alone (spec 02 §7.6 table).
  DynamicFilter g = make(2, 0.0, 0.012, 0.0, 0.004);
  const auto z = step_response(g, 4);
  EXPECT_NEAR(z[0], 0.25, kExact);
  EXPECT_NEAR(z[3], 1.0, kExact);
}

// Dead time only (Mode 1 or 2 with T1 = T2 = 0): an exact delay; a fraction of a cycle interpolates linearly
// between the two neighbouring samples, which delays a ramp exactly.
// spec 02 §7.6 (dead time Tt of the dynamic filter), decision P22 (a fractional cycle interpolates
// linearly).
TEST(DynamicFilter, DeadTimeIsAnExactDelay) {
  for (std::int32_t mode : {1, 2}) {
    DynamicFilter f = make(mode, 0.0, 0.0, 0.002, 0.001);
    const auto y = step_response(f, 5);
    expect_near_all(y, {0, 0, 1, 1, 1});
    DynamicFilter g = make(mode, 0.0, 0.0, 0.0025, 0.001);
    const auto z = step_response(g, 5);
    expect_near_all(z, {0, 0, 0.5, 1, 1});
    EXPECT_NEAR(g.effective_delay(), 0.0025, kExact);
  }
}

// Mode 1 PT1, backward Euler: y(k) = 1 − a^(k+1), a = T/(T + T_s). T1 alone or T2 alone (spec 02 §7.6 table).
TEST(DynamicFilter, Pt1StepResponse) {
  for (const auto& [t1, t2] : {std::pair{0.003, 0.0}, std::pair{0.0, 0.003}}) {
    DynamicFilter f = make(1, t1, t2, 0.0, 0.001);
    const auto y = step_response(f, 30);
    const double a = 0.003 / (0.003 + 0.001);
    for (int k = 0; k < 30; ++k)
      EXPECT_NEAR(y[k], 1.0 - std::pow(a, k + 1), kExact) << k;
    EXPECT_NEAR(f.effective_delay(), 0.003, kExact);
  }
}

// Mode 1 PT2 = two PT1 in series. Closed forms of the cascade's step response with a_i = T_i/(T_i + T_s),
// b_i = 1 − a_i:
//   a1 ≠ a2:  y(k) = 1 − (b2·a1^(k+2) − b1·a2^(k+2)) / (a1 − a2)
//   a1 = a2:  y(k) = 1 − a^(k+1) − (k+1)·b·a^(k+1)
// Never above 1 and rising (D >= 1: no oscillation, seed 004 §6.13.6.1).
TEST(DynamicFilter, Pt2StepResponseMatchesTheClosedForm) {
  const double ts = 0.001;
  {
    DynamicFilter f = make(1, 0.004, 0.002, 0.0, ts);
    const auto y = step_response(f, 60);
    const double a1 = 0.004 / (0.004 + ts), a2 = 0.002 / (0.002 + ts);
    const double b1 = 1 - a1, b2 = 1 - a2;
    for (int k = 0; k < 60; ++k) {
      EXPECT_NEAR(y[k], 1.0 - (b2 * std::pow(a1, k + 2) - b1 * std::pow(a2, k + 2)) / (a1 - a2), kExact) << k;
      EXPECT_LE(y[k], 1.0);
      if (k > 0) {
        EXPECT_GT(y[k], y[k - 1]);
      }
    }
  }
  {
    DynamicFilter f = make(1, 0.003, 0.003, 0.0, ts);
    const auto y = step_response(f, 60);
    const double a = 0.003 / (0.003 + ts), b = 1 - a;
    for (int k = 0; k < 60; ++k)
      EXPECT_NEAR(y[k], 1.0 - std::pow(a, k + 1) - (k + 1) * b * std::pow(a, k + 1), kExact) << k;
  }
}

// spec 02 §7.6: "effective delay = T1 + T2 + Tt -> FollowingError.AdditionalSetpointDelayTime". PT2 + dead
// time behind a ramp of 250 mm/s: x_f = x_ipo − 250 · (0.002 + 0.003 + 0.0015) once the transient has decayed
// ((3/4)^300 ≈ 1e-38), for position and (the same filter) a velocity ramp.
TEST(DynamicFilter, Pt2WithDeadTimeLagsARampByTheSumOfItsTimes) {
  DynamicFilter f = make(1, 0.002, 0.003, 0.0015, 0.001);
  EXPECT_NEAR(f.effective_delay(), 0.0065, kExact);
  MotionState out;
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.001 * k;
    out = f.update(MotionState{250.0 * t, 250.0, 0.0}, true);
  }
  EXPECT_NEAR(out.position, 250.0 * (0.300 - 0.0065), 1e-9);
  EXPECT_NEAR(out.velocity, 250.0, 1e-9);
  // Acceleration ramp through the acceleration channel: lags the same 6.5 ms.
  DynamicFilter g = make(1, 0.002, 0.003, 0.0015, 0.001);
  for (int k = 0; k <= 300; ++k)
    out = g.update(MotionState{0.0, 1000.0 * 0.001 * k, 1000.0}, true);
  EXPECT_NEAR(out.velocity, 1000.0 * (0.300 - 0.0065), 1e-9);
  EXPECT_NEAR(out.acceleration, 1000.0, 1e-9);
}

// spec 02 §7.6, §10 #17, §11 scenario 44: T1 = T2 = 1 ms gives D = 1 and ω = 1000 rad/s; with T_s = 1 ms a
// T1 of 43.5 ms acts as 16 ms, no error. A moving average of 16 ms averages the current value and the last
// 16 (full after 17 cycles); a 100 ms dead time delays by 16 cycles.
TEST(DynamicFilter, TimesAreLimitedToSixteenServoCyclesWithoutError) {
  EXPECT_DOUBLE_EQ(tomc::techobjects::pt2_damping(0.001, 0.001), 1.0);
  EXPECT_DOUBLE_EQ(tomc::techobjects::pt2_angular_frequency(0.001, 0.001), 1000.0);
  EXPECT_GT(tomc::techobjects::pt2_damping(0.004, 0.001), 1.0);  // D >= 1: never oscillates

  DynamicFilter f;
  EXPECT_TRUE(f.configure(DynamicFilterConfig{1, 0.0435, 0.0, 0.0, 0.001}));
  EXPECT_NEAR(f.effective_T1(), 0.016, kExact);
  EXPECT_NEAR(f.effective_delay(), 0.016, kExact);

  DynamicFilter ma = make(2, 0.0435, 0.0, 0.0, 0.001);
  const auto y = step_response(ma, 18);
  EXPECT_NEAR(y[0], 1.0 / 17.0, kExact);
  EXPECT_NEAR(y[15], 16.0 / 17.0, kExact);
  EXPECT_NEAR(y[16], 1.0, kExact);
  EXPECT_NEAR(ma.effective_delay(), 0.008, kExact);

  DynamicFilter dead = make(2, 0.0, 0.0, 0.1, 0.001);
  EXPECT_NEAR(dead.effective_Tt(), 0.016, kExact);
  const auto z = step_response(dead, 18);
  EXPECT_NEAR(z[15], 0.0, kExact);
  EXPECT_NEAR(z[16], 1.0, kExact);
}

// Mode 0, or all times 0, or `run` FALSE (follow-up, no position control): the output is the input; and a
// filter that starts running starts from its input (no step).
// spec 02 §7.6 (Mode 0: no filter), decision P24 (without position control the setpoint passes through and
// the filter restarts from its input).
TEST(DynamicFilter, PassThroughAndSteplessStart) {
  DynamicFilter off = make(0, 0.01, 0.01, 0.01, 0.001);
  EXPECT_FALSE(off.active());
  DynamicFilter zero = make(1, 0.0, 0.0, 0.0, 0.001);
  EXPECT_FALSE(zero.active());
  const MotionState in{12.5, 3.0, 7.0};
  for (DynamicFilter* f : {&off, &zero}) {
    const MotionState out = f->update(in, true);
    EXPECT_EQ(out.position, in.position);
    EXPECT_EQ(out.velocity, in.velocity);
    EXPECT_EQ(out.acceleration, in.acceleration);
  }
  DynamicFilter f = make(1, 0.01, 0.0, 0.005, 0.001);
  EXPECT_TRUE(f.active());
  EXPECT_EQ(f.update(MotionState{-4.0, 0.0, 0.0}, false).position, -4.0);
  EXPECT_EQ(f.update(MotionState{100.0, 0.0, 0.0}, true).position, 100.0);  // history filled with 100
  EXPECT_EQ(f.update(MotionState{100.0, 0.0, 0.0}, true).position, 100.0);
}

// Direct homing shifts the coordinate system (decision P7): the history moves along, the output continues on
// the shifted trajectory without a transient.
TEST(DynamicFilter, ShiftMovesTheHistory) {
  DynamicFilter a = make(2, 0.005, 0.003, 0.002, 0.001);
  DynamicFilter b = make(2, 0.005, 0.003, 0.002, 0.001);
  for (int k = 0; k < 20; ++k) {
    const double x = 0.05 * k * k;
    (void)a.update(MotionState{x, 0.1 * k, 0.1}, true);
    (void)b.update(MotionState{x, 0.1 * k, 0.1}, true);
  }
  b.shift(250.0);
  for (int k = 20; k < 40; ++k) {
    const double x = 0.05 * k * k;
    const MotionState oa = a.update(MotionState{x, 0.1 * k, 0.1}, true);
    const MotionState ob = b.update(MotionState{x + 250.0, 0.1 * k, 0.1}, true);
    EXPECT_NEAR(ob.position, oa.position + 250.0, 1e-9) << k;
    EXPECT_EQ(ob.velocity, oa.velocity);
  }
}

// DIR changes at run time keep the history: a standing input stays where it is.
// spec 04 §3.22 (SetpointFilter.DynamicFilter.* are DIR: effective at once), decision P23 (fixed histories
// survive a change).
TEST(DynamicFilter, ReconfigurationKeepsTheHistory) {
  DynamicFilter f = make(2, 0.008, 0.0, 0.0, 0.001);
  for (int k = 0; k < 20; ++k)
    (void)f.update(MotionState{5.0, 0.0, 0.0}, true);
  EXPECT_TRUE(f.configure(DynamicFilterConfig{2, 0.003, 0.004, 0.001, 0.001}));
  EXPECT_EQ(f.update(MotionState{5.0, 0.0, 0.0}, true).position, 5.0);
}

// Values the data block forbids never reach the cycle: rejected, the previous configuration stays.
// spec 04 §3.22 (Mode 0…2, times ≥ 0), decision P23 (values outside the data-block ranges are rejected).
TEST(DynamicFilter, InvalidConfigurationIsRejected) {
  DynamicFilter f = make(1, 0.002, 0.0, 0.0, 0.001);
  EXPECT_FALSE(f.configure(DynamicFilterConfig{3, 0.002, 0.0, 0.0, 0.001}));
  EXPECT_FALSE(f.configure(DynamicFilterConfig{1, -0.001, 0.0, 0.0, 0.001}));
  EXPECT_FALSE(f.configure(DynamicFilterConfig{1, 0.0, std::nan(""), 0.0, 0.001}));
  EXPECT_FALSE(f.configure(DynamicFilterConfig{1, 0.0, 0.0, INFINITY, 0.001}));
  EXPECT_FALSE(f.configure(DynamicFilterConfig{1, 0.002, 0.0, 0.0, 0.0}));
  EXPECT_EQ(f.config().T1, 0.002);
  EXPECT_TRUE(f.active());
}

}  // namespace
