// Simulated drive, torque limits and torque signals: MOMRED of telegram 102 (spec 06 §9), telegram 750
// M_LIMIT_POS / M_LIMIT_NEG / M_ADD1 / M_ACT (spec 06 §8, §2.14), all N2 of the reference torque p2003.
#include <gtest/gtest.h>

#include <cmath>

#include "drive_harness.hpp"

namespace tomc::drives::test {
namespace {

// With the torque at a constant limit Tm, J dω/dt = Tm − B ω − Tc, so from rest
//   ω(t) = (Tm − Tc)/B (1 − e^{−B t / J}).
double accelerated_rpm(const SimulatedDriveParameters& p, double torque, double t) {
  const double J = reflected_inertia(p);
  const double B = p.viscous_friction_nm_per_rad_s;
  return rad_s_to_rpm((torque - p.coulomb_friction_nm) / B * (1.0 - std::exp(-B * t / J)));
}

// spec 06 §9: T_limit = T_ref (1 − MOMRED/16384); MOMRED 0x3000 = 75 % reduction -> 4 Nm * 0.25 = 1 Nm.
TEST(TorqueSim, Momred102LimitsTorqueDuringHardAcceleration) {
  SimulatedDriveParameters p;  // reference torque 4 Nm = torque limit p1520
  Harness h(drive_config(102), p);
  h.drive_sp.MOMRED = 0x3000;
  h.power_up_to_s4();
  h.speed_rpm(3000.0);  // a step: the unlimited demand J * Δω / T is ~44 Nm
  double max_torque = 0.0;
  for (int k = 0; k < 50; ++k) {
    ASSERT_TRUE(h.cycle());
    max_torque = std::max(max_torque, std::fabs(h.drive.motor_torque_nm()));
    EXPECT_DOUBLE_EQ(h.drive.motor_torque_nm(), 1.0) << "at the limit in cycle " << k;
  }
  EXPECT_LE(max_torque, 1.0);
  // 50 ms at 1 Nm: the speed follows the analytic solution (1547 rpm), not the 4 Nm one (6150 rpm).
  const double expected = accelerated_rpm(p, 1.0, 0.050);
  EXPECT_NEAR(h.nist_rpm(), expected, 0.01 * expected);

  // Braking back to 0 with the same reduction: -1 Nm.
  h.run(500);
  h.speed_rpm(0.0);
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(h.cycle());
    EXPECT_DOUBLE_EQ(h.drive.motor_torque_nm(), -1.0) << "cycle " << k;
  }

  // MOMRED 0: no reduction, the full 4 Nm.
  Harness full(drive_config(102), p);
  full.power_up_to_s4();
  full.speed_rpm(3000.0);
  full.run(10);
  EXPECT_DOUBLE_EQ(full.drive.motor_torque_nm(), 4.0);
  EXPECT_NEAR(full.nist_rpm(), accelerated_rpm(p, 4.0, 0.010), 0.01 * accelerated_rpm(p, 4.0, 0.010));
}

// spec 06 §8: M_LIMIT_POS / M_LIMIT_NEG (N2 of p2003) bound the torque; M_ACT reports it in N2.
TEST(TorqueSim, Telegram750LimitsAndActualTorque) {
  SimulatedDriveParameters p;
  Harness h(drive_config(3, 750), p);
  h.supplementary.M_LIMIT_POS = 0x2000;                              // +2 Nm
  h.supplementary.M_LIMIT_NEG = static_cast<std::int16_t>(-0x1000);  // -1 Nm
  h.power_up_to_s4();
  h.speed_rpm(3000.0);
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(h.cycle());
    EXPECT_DOUBLE_EQ(h.drive.motor_torque_nm(), 2.0);
    EXPECT_EQ(h.supplementary_actual.M_ACT, 0x2000) << "M_ACT = 2 Nm / 4 Nm * 16384";
  }
  EXPECT_NEAR(h.nist_rpm(), accelerated_rpm(p, 2.0, 0.020), 0.01 * accelerated_rpm(p, 2.0, 0.020));

  // Steady 3000 rpm: the motor delivers the friction torque B ω + Tc = 1e-4 * 314.16 + 0.02 = 0.05142 Nm.
  h.run(500);
  ASSERT_NEAR(h.nist_rpm(), 3000.0, 0.1);
  const double friction = p.viscous_friction_nm_per_rad_s * rpm_to_rad_s(3000.0) + p.coulomb_friction_nm;
  EXPECT_EQ(h.supplementary_actual.M_ACT, tg::torque_to_n2(friction, p.reference_torque_nm));  // 211
  EXPECT_EQ(h.supplementary_actual.M_ACT, 211);

  // Braking: the negative limit.
  h.speed_rpm(0.0);
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(h.cycle());
    EXPECT_DOUBLE_EQ(h.drive.motor_torque_nm(), -1.0);
    EXPECT_EQ(h.supplementary_actual.M_ACT, -0x1000);
  }
}

// At standstill with a zero speed setpoint the motor holds without torque: M_ACT = 0; M_ADD1 below the
// static friction Tc (0.02 Nm) is held by friction and shows in M_ACT as it is.
// spec 06 §8 (M_ADD1 / M_ACT in N2 of the reference torque), docs/simulated-drive.md "One cycle" step 3
// (static friction Tc holds the shaft).
TEST(TorqueSim, Telegram750StandstillTorque) {
  SimulatedDriveParameters p;
  Harness h(drive_config(3, 750), p);
  h.power_up_to_s4();
  h.run(10);
  EXPECT_EQ(h.supplementary_actual.M_ACT, 0);
  EXPECT_EQ(h.drive.motor_torque_nm(), 0.0);
  h.supplementary.M_ADD1 = 41;  // 41 / 16384 * 4 Nm = 0.0100 Nm < Tc
  h.run(10);
  EXPECT_EQ(h.supplementary_actual.M_ACT, 41);
  EXPECT_EQ(h.nist_rpm(), 0.0);
}

// spec 06 §8: M_ADD1 is added to the speed controller's torque, e.g. as acceleration pre-control J*a. The
// speed loop (a first-order lag, time constant T, integrated in h = cycle/substeps steps with q = e^{-h/T})
// follows a setpoint staircase rising by a*cycle each cycle with an end-of-cycle lag of
//   e = a cycle / (e^{cycle/T} − 1)                     (9.25 rpm for a = 6000 rpm/s, T = 2 ms)
// and with pre-control torque J a' the lag falls by a' h / (1 − q) (≈ a' (T + h/2), 12.76 rpm).
TEST(TorqueSim, Telegram750AdditiveTorqueAsAccelerationPrecontrol) {
  SimulatedDriveParameters p;
  const double a = 6000.0;  // rpm/s
  const double cycle = p.servo_cycle_s;
  const double T = p.speed_loop_time_constant_s;
  const double h_step = cycle / p.substeps;
  const double q = std::exp(-h_step / T);
  const double J = reflected_inertia(p);
  const std::int16_t m_add = tg::torque_to_n2(J * rpm_to_rad_s(a), p.reference_torque_nm);
  ASSERT_EQ(m_add, 772);                                                                  // 0.1885 Nm
  const double a_pre = rad_s_to_rpm(tg::n2_to_torque(m_add, p.reference_torque_nm) / J);  // rpm/s

  auto ramp_lag = [&](bool precontrol) {
    Harness h(drive_config(3, 750), p);
    h.power_up_to_s4();
    h.supplementary.M_ADD1 = precontrol ? m_add : 0;
    double n_set = 500.0;  // start on a steady speed (Coulomb friction continuous)
    h.speed_rpm(n_set);
    h.run(100);
    for (int k = 0; k < 100; ++k) {
      n_set += a * cycle;
      h.speed_rpm(n_set);
      EXPECT_TRUE(h.cycle());
    }
    return n_set - h.nist_rpm();
  };
  const double lag_plain = ramp_lag(false);
  const double lag_pre = ramp_lag(true);
  const double expected_plain = a * cycle / (std::exp(cycle / T) - 1.0);
  const double expected_pre = expected_plain - a_pre * h_step / (1.0 - q);
  EXPECT_NEAR(lag_plain, expected_plain, 0.2);
  EXPECT_NEAR(lag_pre, expected_pre, 0.2);
  EXPECT_LT(std::fabs(lag_pre), 0.5 * lag_plain);
}

}  // namespace
}  // namespace tomc::drives::test
