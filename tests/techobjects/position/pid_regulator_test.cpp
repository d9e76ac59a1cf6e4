// PID option of the position controller (issue 20): closed-form discrete responses of pid_regulator.hpp, the
// legacy conversions of legacy_regulator.hpp, and the JOINT regulator/DAC examples of spec 05b Part D (3–6)
// through the analog actor's DAC (16-bit ±10 V, ±1 LSB as Part D allows).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "tomc/drives/io/hardware_io.hpp"
#include "tomc/techobjects/position/legacy_regulator.hpp"
#include "tomc/techobjects/position/pid_regulator.hpp"

namespace tomc::techobjects {
namespace {

constexpr double kTs = 0.010;

PidRegulator regulator(const PidGains& g, double ts = kTs) {
  PidRegulator r;
  EXPECT_TRUE(r.configure(g, ts));
  return r;
}

// Decision A8 (all Pid.* 0 = the S7's P controller, bit-identical); spec 02 §7.4.
TEST(PidRegulator, DefaultIsTheS7PController) {
  PidGains g;
  g.Kv = 33.0;
  auto r = regulator(g);
  for (const double e : {0.0, 1.0, -2.5, 1e-3, 1e3}) {
    const auto t = r.update(e);
    EXPECT_EQ(t.output, 33.0 * e);
    EXPECT_EQ(t.i, 0.0);
    EXPECT_EQ(t.d, 0.0);
  }
}

// Constant error e0 (step): I(k) = k·Kv·Ts/Ti·e0 — the integral equals P after Ti/Ts samples.
// spec 05b A.2 (the PID regulator), C.2; decision A8.
TEST(PidRegulator, IntegralStepResponseClosedForm) {
  PidGains g;
  g.Kv = 100.0;
  g.IntegralTime = 0.1;
  auto r = regulator(g);
  for (int k = 1; k <= 25; ++k) {
    const auto t = r.update(10.0);
    EXPECT_NEAR(t.i, k * 100.0 * (kTs / 0.1) * 10.0, 1e-9) << "sample " << k;
    EXPECT_NEAR(t.output, 1000.0 + t.i, 1e-9);
  }
}

// The integral clamp: it reaches IntegralLimit and stays there; a reversed error unwinds it at once.
// Decision A9 (anti-windup: the integral clamp).
TEST(PidRegulator, IntegralClampAndUnwind) {
  PidGains g;
  g.Kv = 100.0;
  g.IntegralTime = 0.1;
  g.IntegralLimit = 250.0;
  auto r = regulator(g);
  // +100 per sample at e = 10: 100, 200, 250, 250, ...
  const double expected[] = {100.0, 200.0, 250.0, 250.0, 250.0};
  for (const double i : expected)
    EXPECT_DOUBLE_EQ(r.update(10.0).i, i);
  EXPECT_DOUBLE_EQ(r.update(-10.0).i, 150.0);
}

// Anti-windup with the output clamp: while P + I is at OutputLimit, I does not grow; when the error drops the
// output leaves saturation in the same sample (no wound-up integral to burn off).
// Decision A9 (anti-windup: conditional integration at OutputLimit).
TEST(PidRegulator, ConditionalIntegrationAtTheOutputLimit) {
  PidGains g;
  g.Kv = 100.0;
  g.IntegralTime = 0.1;
  g.OutputLimit = 1500.0;
  auto r = regulator(g);
  EXPECT_DOUBLE_EQ(r.update(10.0).i, 100.0);  // 1000 + 100
  EXPECT_DOUBLE_EQ(r.update(10.0).i, 200.0);
  EXPECT_DOUBLE_EQ(r.update(10.0).i, 300.0);
  EXPECT_DOUBLE_EQ(r.update(10.0).i, 400.0);
  EXPECT_DOUBLE_EQ(r.update(10.0).i, 500.0);  // 1500: at the limit
  for (int k = 0; k < 50; ++k) {
    const auto t = r.update(10.0);
    EXPECT_DOUBLE_EQ(t.i, 500.0);
    EXPECT_DOUBLE_EQ(t.output, 1500.0);
  }
  const auto t = r.update(2.0);  // P 200 + I 520: out of saturation at once
  EXPECT_DOUBLE_EQ(t.i, 520.0);
  EXPECT_DOUBLE_EQ(t.output, 720.0);
  EXPECT_FALSE(t.saturated);
}

// Error ramp e(k) = r·k: D = Kv·Td·r/Ts every sample; with a D sample of n cycles D = Kv·Td·(n·r)/(n·Ts),
// updated every n cycles and held.
// spec 05b A.2 (the derivative term and its sample time); decision A8.
TEST(PidRegulator, DerivativeOnARampAndItsOwnSampleTime) {
  PidGains g;
  g.Kv = 100.0;
  g.DerivativeTime = 0.02;
  auto r = regulator(g);
  r.update(0.0);
  for (int k = 1; k <= 5; ++k)
    EXPECT_NEAR(r.update(k * 1.0).d, 100.0 * 0.02 * 1.0 / kTs, 1e-9);
  g.DerivativeCycles = 3;
  auto slow = regulator(g);
  slow.update(0.0);
  // D samples every 3 cycles counted from the first update (k = 0): at k = 2, 5, 8, ... A step of the error
  // by 3 at k = 1 is seen by the sample at k = 2 (3/(3·Ts)), held at k = 3 and 4, gone at the sample k = 5.
  const double d3 = 100.0 * 0.02 * 3.0 / (3 * kTs);
  const double expected[] = {0.0, d3, d3, d3, 0.0, 0.0};
  for (const double d : expected)
    EXPECT_NEAR(slow.update(3.0).d, d, 1e-9);
}

// spec 05b A.2 (the dead band JOINT leaves to the framework); decision A8 (`PositionControl.Pid.DeadBand`).
TEST(PidRegulator, DeadBand) {
  PidGains g;
  g.Kv = 10.0;
  g.IntegralTime = 0.05;
  g.DeadBand = 0.5;
  auto r = regulator(g);
  for (const double e : {0.5, -0.5, 0.25, 0.0}) {
    const auto t = r.update(e);
    EXPECT_EQ(t.output, 0.0) << e;
  }
  EXPECT_DOUBLE_EQ(r.update(0.6).p, 6.0);
}

// H3 FLdRP/FUpDRP: a loaded set acts only after apply(), from the next update on.
// spec 05b §B.10 (H3 FLdRP buffers the PID set, FUpDRP activates it; out of range is an error), decision
// A8.
TEST(PidRegulator, DoubleBufferedGains) {
  PidGains g;
  g.Kv = 10.0;
  auto r = regulator(g);
  PidGains next = g;
  next.Kv = 20.0;
  ASSERT_TRUE(r.load(next));
  EXPECT_DOUBLE_EQ(r.update(1.0).output, 10.0);
  EXPECT_DOUBLE_EQ(r.update(1.0).output, 10.0);
  r.apply();
  EXPECT_DOUBLE_EQ(r.update(1.0).output, 20.0);
  next.DerivativeCycles = 0;  // invalid: refused, the active set stays
  EXPECT_FALSE(r.load(next));
  PidGains negative = g;
  negative.IntegralTime = -1.0;
  EXPECT_FALSE(r.configure(negative, kTs));
  EXPECT_DOUBLE_EQ(r.gains().Kv, 20.0);
}

// The P controller runs a short path (no option set); switching a D term on later (load + apply, spec 05b
// C.2) must see the last control difference of that path: a constant error then gives no derivative kick, and
// a ramp the closed-form D of its first sample.
TEST(PidRegulator, DerivativeSwitchedOnAfterPOnlyCyclesHasNoKick) {
  PidGains g;
  g.Kv = 10.0;
  auto r = regulator(g);
  for (int k = 0; k < 3; ++k)
    EXPECT_DOUBLE_EQ(r.update(2.0).output, 20.0);
  PidGains with_d = g;
  with_d.DerivativeTime = 0.05;
  ASSERT_TRUE(r.load(with_d));
  r.apply();
  const auto same = r.update(2.0);  // e unchanged since the last P-only cycle: D = 0
  EXPECT_DOUBLE_EQ(same.d, 0.0);
  EXPECT_DOUBLE_EQ(same.output, 20.0);
  const auto ramp = r.update(2.5);  // D = Kv·Td·Δe/Ts = 10·0.05·0.5/0.01 = 25
  EXPECT_NEAR(ramp.d, 25.0, 1e-9);
  EXPECT_NEAR(ramp.output, 25.0 + 25.0, 1e-9);
  ASSERT_TRUE(r.load(g));  // back to P alone: the short path again, D gone
  r.apply();
  EXPECT_DOUBLE_EQ(r.update(1.0).output, 10.0);
  EXPECT_DOUBLE_EQ(r.update(-1.0).d, 0.0);
}

// Closed loop on an ideal velocity actuator x(k+1) = x(k) + Ts·u(k) following a ramp v·t without precontrol:
// P alone leaves the steady-state error v/Kv; with I it goes to zero (a type-2 loop).
// spec 05b A.2, C.2 (the integral removes the ramp's steady-state error); decision A8.
TEST(PidRegulator, RampSteadyStateErrorZeroWithIntegral) {
  const double v = 50.0;
  for (const double ti : {0.0, 0.2}) {
    PidGains g;
    g.Kv = 20.0;
    g.IntegralTime = ti;
    auto r = regulator(g, 0.001);
    double x = 0.0;
    double e = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double setpoint = v * k * 0.001;
      e = setpoint - x;
      x += 0.001 * r.update(e).output;
    }
    if (ti == 0.0) {
      EXPECT_NEAR(e, v / 20.0, 1e-6);  // v/Kv: Kv·e·Ts must equal the setpoint's step v·Ts
    } else {
      EXPECT_NEAR(e, 0.0, 1e-6);
    }
  }
}

// ---- legacy conversions, spec 05b C.2 and Part D (JOINT test axis: TCamp 10 ms, maxvel 10 000 pulses/s)
// ----

const drives::io::DacFormat kJointDac{16, 10.0};

std::int32_t joint_dac_bits(double velocity, const LegacyRegulator& reg) {
  const double volts = velocity / 10000.0 * 10.0 + reg.offset_volts;
  return drives::io::dac_code(volts, kJointDac);
}

// spec 05b A.8 (the JOINT per-axis parameters), C.2; decisions A18, A19.
TEST(LegacyRegulator, JointConversion) {
  JointRegulatorParameters p;
  p.pgain = 1000;
  p.feedfw = 985;
  p.integt = 100;
  p.derivt = 20;
  p.offset = 328;
  const auto r = from_joint(p, 0.010);
  EXPECT_EQ(r.problem, "");
  EXPECT_DOUBLE_EQ(r.gains.Kv, 100.0);  // spec 05b C.2: 1000 @ 10 ms -> 100 1/s
  EXPECT_DOUBLE_EQ(r.Kpc, 98.5);
  EXPECT_DOUBLE_EQ(r.gains.IntegralTime, 0.1);
  EXPECT_DOUBLE_EQ(r.gains.DerivativeTime, 0.02);
  EXPECT_EQ(r.gains.DerivativeCycles, 1u);
  EXPECT_NEAR(r.offset_volts, 0.1001, 1e-4);
  EXPECT_DOUBLE_EQ(r.gains.OutputLimit, 10000.0);
  EXPECT_EQ(from_joint(p, 0.002).gains.DerivativeCycles, 5u);  // D sample = TCamp in 2 ms cycles
  p.feedfw = 3000;
  EXPECT_DOUBLE_EQ(from_joint(p, 0.010).Kpc, 150.0);  // legacy 300 % clamped (spec 05b C.2)
  p.TCamp = 0.0;
  EXPECT_NE(from_joint(p, 0.010).problem.find("TCamp"), std::string::npos);
}

// spec 05b Part D 3: pgain 1000, folterr 50 -> ≈ 16383 (5 V); folterr 150 -> 32767; pgain 500 -> ≈ 8191.
TEST(LegacyRegulator, JointPartD3ProportionalTerm) {
  struct Row {
    std::int32_t pgain;
    double folterr;
    std::int32_t bits;
  };
  for (const Row row : {Row{1000, 50.0, 16383}, Row{1000, 150.0, 32767}, Row{500, 50.0, 8191}}) {
    JointRegulatorParameters p;
    p.pgain = row.pgain;
    const auto reg = from_joint(p, 0.010);
    PidRegulator r;
    ASSERT_TRUE(r.configure(reg.gains, 0.010));
    EXPECT_NEAR(joint_dac_bits(r.update(row.folterr).output, reg), row.bits, 1)
        << row.pgain << " " << row.folterr;
  }
}

// Part D 4: folterr 0, v_theor 50 Um/s = 5000 pulses/s: feedfw 1000 -> ≈ 16383, 985 -> ≈ 16137.
// spec 05b Part D 4 (feed-forward).
TEST(LegacyRegulator, JointPartD4FeedForward) {
  for (const auto& [feedfw, bits] : {std::pair{1000, 16383}, std::pair{985, 16137}}) {
    JointRegulatorParameters p;
    p.feedfw = feedfw;
    const auto reg = from_joint(p, 0.010);
    const double precontrol = reg.Kpc / 100.0 * 5000.0;  // kpc·v_f (spec 02 §7.4 (5a))
    EXPECT_NEAR(joint_dac_bits(precontrol, reg), bits, 1) << feedfw;
  }
}

// Part D 5: pgain 1000, integt 100 ms, folterr 10 (propreg ≈ 3276): after 10 samples intreg ≈ 3276; integt 0
// -> intreg stays 0.
// spec 05b Part D 5 (integral).
TEST(LegacyRegulator, JointPartD5Integral) {
  for (const std::int32_t integt : {100, 0}) {
    JointRegulatorParameters p;
    p.integt = integt;
    const auto reg = from_joint(p, 0.010);
    PidRegulator r;
    ASSERT_TRUE(r.configure(reg.gains, 0.010));
    PidTerms t;
    for (int k = 0; k < 10; ++k)
      t = r.update(10.0);
    EXPECT_NEAR(joint_dac_bits(t.p, reg), 3276, 1);
    EXPECT_NEAR(joint_dac_bits(t.i, reg), integt == 0 ? 0 : 3276, 1) << integt;
  }
}

// Part D 6: pgain 1000, derivt 20 ms, folterr growing by 1 pulse per sample -> derreg ≈ 655 every sample.
// spec 05b Part D 6 (derivative).
TEST(LegacyRegulator, JointPartD6Derivative) {
  JointRegulatorParameters p;
  p.derivt = 20;
  const auto reg = from_joint(p, 0.010);
  PidRegulator r;
  ASSERT_TRUE(r.configure(reg.gains, 0.010));
  r.update(0.0);
  for (int k = 1; k <= 5; ++k)
    EXPECT_NEAR(joint_dac_bits(r.update(k).d, reg), 655, 1) << "sample " << k;
}

// H3 (spec 05b B.4): U = kp·e + ki·Σe + kd·Δe in output codes (4095 = 10 V); run in the H3's own sample
// time the converted regulator gives the same U, with IL bounding ki·Σe.
TEST(LegacyRegulator, H3ConversionReproducesTheModuleLaw) {
  H3RegulatorParameters p;
  p.kp = 8.0;
  p.ki = 0.5;
  p.kd = 40.0;
  p.IntL = 300.0;
  p.SampI = 2;                         // D every 3 samples
  p.velocity_at_10V = 4095.0 * 100.0;  // one code = 100 counts/s
  const auto reg = from_h3(p, kH3SampleTime);
  ASSERT_EQ(reg.problem, "");
  EXPECT_EQ(reg.gains.DerivativeCycles, 3u);
  EXPECT_EQ(reg.Kpc, 0.0);
  PidRegulator r;
  ASSERT_TRUE(r.configure(reg.gains, kH3SampleTime));
  double sum = 0.0;
  double e_prev_sample = 0.0;
  double d_held = 0.0;
  for (int n = 0; n < 200; ++n) {
    const double e = 5.0 + 0.25 * n;  // a growing error
    sum += e;
    const double integral = std::clamp(p.ki * sum, -p.IntL, p.IntL);
    if ((n + 1) % 3 == 0) {
      d_held = p.kd * (e - e_prev_sample);
      e_prev_sample = e;
    }
    if (n == 0) e_prev_sample = e;
    const double u = p.kp * e + integral + (n == 0 ? 0.0 : d_held);
    EXPECT_NEAR(r.update(e).output / 100.0, u, 1e-6) << "sample " << n;
  }
  p.IntL = 0.0;  // IL = 0: no integral at all
  EXPECT_EQ(from_h3(p, kH3SampleTime).gains.IntegralTime, 0.0);
  p.SampI = 256;
  EXPECT_NE(from_h3(p, kH3SampleTime).problem.find("SampI"), std::string::npos);
}

}  // namespace
}  // namespace tomc::techobjects
