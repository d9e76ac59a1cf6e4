// Simulated drive, stop modes (spec 06 §3.1 bits 0..2, §4.1 S5a/S5b, §4.3): OFF1 ramp on p1121, OFF3 ramp on
// p1135, both ended by the standstill threshold p1226; OFF2 coasting on friction alone.
#include <gtest/gtest.h>

#include <cmath>

#include "drive_harness.hpp"

namespace tomc::drives::test {
namespace {

// Stop time of a ramp stop, continuous-time model of the drive:
//  * the ramp-function generator starts at the present speed n0 and falls at a = p1082 / ramp time (p1121 for
//    OFF1, p1135 for OFF3 are times from the maximum speed p1082 to 0, spec 06 §3.1) until it reaches 0 at
//    t_r = n0 / a;
//  * the closed speed loop is a first-order lag T, so during the ramp n(t) = r(t) + a T (1 - e^{-t/T}):
//    the motor runs a*T above the ramp;
//  * after the ramp ends, n decays as n(t_r) e^{-(t - t_r)/T}.
// The drive leaves S5a/S5b in the first cycle that starts with |n| < p1226.
// If a*T < p1226 the threshold is crossed on the ramp: t = (n0 + a T - p1226) / a ("ramp to the threshold
// plus the speed-loop lag"); otherwise after it: t = t_r + T ln(n(t_r) / p1226).
double ramp_stop_time(double n0, double a, double T, double threshold) {
  const double lag = a * T;
  if (lag < threshold) return (n0 + lag - threshold) / a;
  const double t_r = n0 / a;
  return t_r + T * std::log(lag * (1.0 - std::exp(-t_r / T)) / threshold);
}

struct RampStopCase {
  const char* name;
  std::uint16_t stw1;  // the stop word
  std::uint16_t zsw1_ramping;
  tg::DriveState ramping;
  std::uint16_t zsw1_after;
  tg::DriveState after;
  double ramp_time_s;
};

class RampStop : public ::testing::TestWithParam<RampStopCase> {};

// spec 06 §4.1 (S5a/S5b end at standstill), decision R8 (the ramp generator acts only for OFF1/OFF3),
// docs/simulated-drive.md "Parameters and defaults" (p1121, p1135, p1226) and "One cycle" step 3.
TEST_P(RampStop, StopTimeFollowsFromRampParameters) {
  const auto& c = GetParam();
  SimulatedDriveParameters p;  // p2000 3000, p1082 6000, p1121 1 s, p1135 0.2 s, p1226 20 rpm, T 2 ms
  Harness h(drive_config(1), p);
  const double n0 = 3000.0;
  h.run_at_speed(n0);
  ASSERT_NEAR(h.nist_rpm(), n0, 0.5);

  const double a = p.max_speed_rpm / c.ramp_time_s;  // OFF1 6000 rpm/s, OFF3 30000 rpm/s
  const double t_stop = ramp_stop_time(n0, a, p.speed_loop_time_constant_s, p.standstill_threshold_rpm);
  // Cycle k (0 = the cycle that receives the stop word) starts at t = k * cycle.
  const int expected_cycle = static_cast<int>(std::ceil(t_stop / p.servo_cycle_s));
  // OFF1: t = (3000 + 12 - 20) / 6000 = 0.49867 s -> cycle 499; OFF3: a*T = 60 > 20 rpm, so
  // t = 0.1 + 2 ms * ln 3 = 0.10220 s -> cycle 103.

  h.stw1(c.stw1);
  int left_at = -1;
  double previous = n0;
  double speed_early = 0.0;
  double speed_late = 0.0;
  const int quarter = static_cast<int>(0.25 * n0 / a / p.servo_cycle_s);  // a quarter of the ramp time
  for (int k = 0; k < 2000; ++k) {
    ASSERT_TRUE(h.cycle());
    if (k == quarter / 2) speed_early = h.nist_rpm();
    if (k == quarter + quarter / 2) speed_late = h.nist_rpm();
    if (h.zsw1() != c.zsw1_ramping) {
      left_at = k;
      EXPECT_EQ(hex16(h.zsw1()), hex16(c.zsw1_after)) << c.name;
      EXPECT_EQ(h.drive.state(), c.after);
      // NIST of the previous cycle (its end = start of this one) was below the threshold, the one before not.
      EXPECT_LT(std::fabs(previous), p.standstill_threshold_rpm + 0.01);
      break;
    }
    EXPECT_EQ(h.drive.state(), c.ramping) << "cycle " << k;
    previous = h.nist_rpm();
  }
  EXPECT_NEAR(left_at, expected_cycle, 2) << c.name << ": expected t_stop = " << t_stop << " s";
  // The deceleration itself: between two points on the ramp the speed falls at a (the lag is constant there).
  const double dt = static_cast<double>(quarter) * p.servo_cycle_s;
  EXPECT_NEAR((speed_early - speed_late) / dt, a, 0.005 * a) << c.name;
  // After the drive has left the ramp state the pulses are off and the motor no longer brakes electrically.
  h.run(5);
  EXPECT_EQ(h.drive.motor_torque_nm(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Off1Off3, RampStop,
    ::testing::Values(
        // spec 06 §4.3 normal stop: 0x047E, S4 -> S5a (0x0233) -> S2 (0x0231).
        RampStopCase{"OFF1", 0x047E, 0x0233, tg::DriveState::kS5aRampStop, 0x0231,
                     tg::DriveState::kS2ReadyForSwitchingOn, 1.0},
        // spec 06 §4.3 quick stop: 0x047B, S4 -> S5b (0x0213, ZSW1.5 = 0) -> S1 (0x0250, STW1.2 still 0).
        RampStopCase{"OFF3", 0x047B, 0x0213, tg::DriveState::kS5bQuickStop, 0x0250,
                     tg::DriveState::kS1SwitchingOnInhibited, 0.2}),
    [](const auto& info) { return std::string(info.param.name); });

// Quick stop with a ramp so slow that the lag stays below the threshold: the same formula must hold in the
// other branch (a = 6000 / 2 s = 3000 rpm/s, a*T = 6 rpm < 20 rpm: t = (1500 + 6 - 20) / 3000 = 0.4953 s).
// spec 06 §4.1 (S5b ends at standstill, then S1: 0x0250), decision R8, docs/simulated-drive.md "One cycle"
// step 3.
TEST(RampStopSim, Off3WithSlowRampCrossesThresholdOnTheRamp) {
  SimulatedDriveParameters p;
  p.off3_ramp_down_time_s = 2.0;
  Harness h(drive_config(1), p);
  h.run_at_speed(1500.0);
  h.stw1(0x047B);
  const int cycles = h.run_until([&] { return h.drive.state() != tg::DriveState::kS5bQuickStop; }, 3000);
  const double t = ramp_stop_time(1500.0, 3000.0, p.speed_loop_time_constant_s, p.standstill_threshold_rpm);
  // run_until counts the cycle that left S5b as cycle index (cycles - 1).
  EXPECT_NEAR(cycles - 1, std::ceil(t / p.servo_cycle_s), 2);
  EXPECT_EQ(hex16(h.zsw1()), "0x0250");
}

// OFF2 (spec 06 §3.1 bit 1, §4.3 0x047C): pulses off at once, the motor coasts. With the pulses off only
// friction acts: J dω/dt = −B ω − Tc (ω > 0), J = J_motor + J_load / i² (i = motor rev per load rev), so
//   ω(t) = (ω0 + Tc/B) e^{−B t / J} − Tc/B   and the motor stops at   t_s = (J/B) ln(1 + B ω0 / Tc).
TEST(CoastStopSim, Off2DecaysByFrictionOnly) {
  SimulatedDriveParameters p;
  p.gear_motor_revolutions = 2.0;  // J = 1e-4 + 2e-4 / 4 = 1.5e-4 kgm^2
  p.gear_load_revolutions = 1.0;
  p.viscous_friction_nm_per_rad_s = 1.0e-4;
  p.coulomb_friction_nm = 0.02;
  Harness h(drive_config(2), p);
  const double n0 = 3000.0;
  h.run_at_speed(n0);
  ASSERT_NEAR(h.nist_rpm(), n0, 0.5);

  const double J = reflected_inertia(p);
  ASSERT_DOUBLE_EQ(J, 1.5e-4);
  const double B = p.viscous_friction_nm_per_rad_s;
  const double Tc = p.coulomb_friction_nm;
  const double w0 = rpm_to_rad_s(n0);
  auto omega = [&](double t) { return (w0 + Tc / B) * std::exp(-B * t / J) - Tc / B; };
  const double t_stop = J / B * std::log(1.0 + B * w0 / Tc);  // 1.5 * ln(2.5708) = 1.4163 s

  h.stw1(0x047C);
  ASSERT_TRUE(h.cycle());  // cycle 0: OFF2 -> S1 at once, answer at t = 1 ms
  EXPECT_EQ(hex16(h.zsw1()), "0x0260");
  EXPECT_EQ(h.drive.state(), tg::DriveState::kS1SwitchingOnInhibited);
  int k = 0;
  int stopped_at = -1;
  for (; k < 3000; ++k) {
    const double t = (k + 1) * p.servo_cycle_s;  // NIST of cycle k is the speed at the end of that cycle
    if (k > 0) {
      ASSERT_TRUE(h.cycle());
    }
    EXPECT_EQ(h.drive.motor_torque_nm(), 0.0) << "cycle " << k;
    for (double check : {0.1, 0.25, 0.5, 1.0, 1.3}) {
      if (std::fabs(t - check) < 1e-9) {
        const double expected = rad_s_to_rpm(omega(check));
        EXPECT_NEAR(h.nist_rpm(), expected, 0.01 * expected) << "t = " << check;
      }
    }
    if (h.nist_rpm() == 0.0) {
      stopped_at = k;
      break;
    }
  }
  // Stopped at the end of cycle k, i.e. t = (k + 1) ms; the model's step is 0.25 ms.
  EXPECT_NEAR((stopped_at + 1) * p.servo_cycle_s, t_stop, 0.002);
  // Friction never reverses the motor: it stays at rest.
  h.run(100);
  EXPECT_EQ(h.nist_rpm(), 0.0);
  EXPECT_EQ(hex16(h.zsw1()), "0x0260");
}

}  // namespace
}  // namespace tomc::drives::test
