// Simulated drive, the simulated machine and the link: fixed stops (travel to fixed stop, spec 06 §3.3/§3.4
// bit 8), position-based inputs (limit switches, reference cam), and link loss (DriveAdapter contract,
// LinkHealth, setpoint timeout fault with its fault reaction, recovery by acknowledge per spec 06 §4.3 /
// TV26).
#include <gtest/gtest.h>

#include <cmath>

#include "drive_harness.hpp"
#include "tomc/telegrams/encoder.hpp"

namespace tomc::drives::test {
namespace {

// The load runs into a fixed stop at +90 degrees: it stops exactly there, at_fixed_stop is reported, and the
// speed controller (its integral winds up while blocked) raises the torque to the limit (MOMRED 0x3000 -> 1
// Nm). Time to the limit: at standstill the proportional part gives K_p * ω_set with K_p ≈ J/T = 0.15
// Nm/(rad/s), i.e. 0.47 Nm at 30 rpm, plus Tc; the integral adds J ω_set / T^2 = 236 Nm/s: (1 - 0.47 -
// 0.02)/236 = 2.2 ms.
// Decision R10 (a PI integral winds up only at a fixed stop, so the torque rises to its limit), spec 06 §9
// (MOMRED), §3.3/§3.4 (STW2.8/ZSW2.8).
TEST(MachineSim, FixedStopBlocksLoadAndTorqueRisesToLimit) {
  SimulatedDriveParameters p;
  p.machine.positive_fixed_stop = 90.0;
  Harness h(drive_config(102), p);
  h.drive_sp.MOMRED = 0x3000;
  h.drive_sp.STW2.set(tg::Stw2Bit::kTravelToFixedStop);  // STW2.8 selected before reaching the stop
  h.power_up_to_s4();
  EXPECT_TRUE(h.actual.ZSW2.test(tg::Zsw2Bit::kTravelToFixedStopActive));
  const double n = 30.0;  // 180 degrees/s: reaches 90 degrees after ~0.5 s
  h.speed_rpm(n);
  const int reached = h.run_until([&] { return h.drive.machine_inputs().at_fixed_stop; }, 1000);
  ASSERT_LE(reached, 1000);
  EXPECT_NEAR(reached, 500, 5);
  EXPECT_EQ(h.drive.load_position(), 90.0);
  const double w = rpm_to_rad_s(n);
  const double J = reflected_inertia(p);
  const double T = p.speed_loop_time_constant_s;
  const double t_limit = (1.0 - J / T * w - p.coulomb_friction_nm) / (J * w / (T * T));
  const int limit_cycles = h.run_until([&] { return h.drive.motor_torque_nm() >= 1.0; }, 100);
  EXPECT_LE(limit_cycles, static_cast<int>(std::ceil(t_limit / p.servo_cycle_s)) + 1);
  const std::uint32_t xist1_at_stop = h.actual.G1_XIST1;
  EXPECT_EQ(xist1_at_stop, static_cast<std::uint32_t>(90.0 / 360.0 * 4194304.0));
  for (int k = 0; k < 200; ++k) {
    ASSERT_TRUE(h.cycle());
    EXPECT_DOUBLE_EQ(h.drive.motor_torque_nm(), 1.0);
    EXPECT_TRUE(h.drive.machine_inputs().at_fixed_stop);
    EXPECT_EQ(h.drive.load_position(), 90.0);
    EXPECT_EQ(h.actual.G1_XIST1, xist1_at_stop);
    EXPECT_EQ(h.nist_rpm(), 0.0);
  }
  // Moving away (negative speed) leaves the stop.
  h.speed_rpm(-30.0);
  h.run(20);
  EXPECT_FALSE(h.drive.machine_inputs().at_fixed_stop);
  EXPECT_LT(h.drive.load_position(), 90.0);
  // Free again: the motor delivers only the friction torque -(B w + Tc).
  EXPECT_NEAR(h.drive.motor_torque_nm(), -(p.viscous_friction_nm_per_rad_s * w + p.coulomb_friction_nm),
              1e-3);
}

// Limit switches (active at and beyond their position) and the reference cam (active inside its window) as
// the load moves; the load position is taken from the encoder (XIST1 -> counts -> degrees), not from the
// model.
// docs/simulated-drive.md "Parameters and defaults" (`machine`: limit switches, reference cam), the inputs
// decision P10 hands to the TO.
TEST(MachineSim, LimitSwitchesAndReferenceCamFollowTheLoad) {
  SimulatedDriveParameters p;
  p.initial_load_position = 0.0;
  p.machine.negative_limit_switch = -20.0;
  p.machine.positive_limit_switch = 200.0;
  p.machine.reference_cam = PositionWindow{100.0, 110.0};
  p.encoder1.determinable_revolutions = 0;  // incremental, counts from 0 at load 0
  Harness h(drive_config(3), p);
  h.power_up_to_s4();
  const double degrees_per_count = 360.0 / 4194304.0;
  const double margin = 360.0 * 0.001 * 60.0 / 60.0;  // one cycle of travel at 60 rpm (0.36 degree)
  int cam_changes = 0;
  int pos_changes = 0;
  int neg_changes = 0;
  bool cam = false;
  bool pos = false;
  bool neg = false;
  auto check = [&] {
    const double x = static_cast<double>(static_cast<std::int32_t>(h.actual.G1_XIST1)) * degrees_per_count;
    const auto in = h.drive.machine_inputs();
    if (in.reference_cam != cam) ++cam_changes;
    if (in.positive_limit_switch != pos) ++pos_changes;
    if (in.negative_limit_switch != neg) ++neg_changes;
    cam = in.reference_cam;
    pos = in.positive_limit_switch;
    neg = in.negative_limit_switch;
    if (std::fabs(x - 100.0) > margin && std::fabs(x - 110.0) > margin) {
      EXPECT_EQ(in.reference_cam, x > 100.0 && x < 110.0) << "x = " << x;
    }
    if (std::fabs(x - 200.0) > margin) {
      EXPECT_EQ(in.positive_limit_switch, x > 200.0) << "x = " << x;
    }
    if (std::fabs(x + 20.0) > margin) {
      EXPECT_EQ(in.negative_limit_switch, x < -20.0) << "x = " << x;
    }
  };
  h.speed_rpm(60.0);               // 360 degrees/s
  for (int k = 0; k < 700; ++k) {  // up to ~250 degrees
    ASSERT_TRUE(h.cycle());
    check();
  }
  h.speed_rpm(-60.0);
  for (int k = 0; k < 900; ++k) {  // back to ~-70 degrees
    ASSERT_TRUE(h.cycle());
    check();
  }
  EXPECT_EQ(cam_changes, 4);  // in and out, twice
  EXPECT_EQ(pos_changes, 2);
  EXPECT_EQ(neg_changes, 1);
  EXPECT_TRUE(neg);
}

// Link loss: read_actual() returns false and leaves the frames untouched, LinkHealth counts the misses; after
// setpoint_timeout_cycles missed setpoints the drive raises F08501 with the OFF3 reaction. Clearing the link
// and acknowledging recovers (TV26 sequence).
// Decision R7 (F08501 after setpoint_timeout_cycles, OFF3), spec 06 §11 TV26 (acknowledge),
// docs/simulated-drive.md "One cycle" step 1.
TEST(MachineSim, LinkLossSetpointTimeoutAndRecovery) {
  SimulatedDriveParameters p;  // setpoint_timeout_cycles 20, communication_fault_reaction OFF3
  Harness h(drive_config(3), p);
  h.run_at_speed(3000.0);
  const LinkHealth before = h.drive.link_health();
  EXPECT_TRUE(before.up);
  EXPECT_EQ(before.consecutive_missed, 0u);
  EXPECT_EQ(before.missed_total, 0u);
  EXPECT_EQ(before.exchanges, 204u);  // 4 power-up cycles + 200 settling cycles

  h.drive.set_link_lost(true);
  const DeviceFrames frozen = h.actual_frames;
  for (std::uint32_t k = 1; k <= p.setpoint_timeout_cycles; ++k) {
    EXPECT_FALSE(h.cycle());
    EXPECT_EQ(h.actual_frames.slots[0].bytes, frozen.slots[0].bytes) << "actual frames untouched";
    const LinkHealth lh = h.drive.link_health();
    EXPECT_FALSE(lh.up);
    EXPECT_EQ(lh.consecutive_missed, k);
    EXPECT_EQ(lh.missed_total, k);
    EXPECT_EQ(lh.exchanges, 204u + k);
    if (k < p.setpoint_timeout_cycles) {
      EXPECT_EQ(h.drive.active_fault(), 0u) << "missed " << k;
      EXPECT_EQ(h.drive.state(), tg::DriveState::kS4Operation);
    }
  }
  EXPECT_EQ(h.drive.active_fault(), kFaultSetpointTimeout);
  EXPECT_EQ(h.drive.state(), tg::DriveState::kS5bQuickStop);  // OFF3 reaction
  // The quick stop (30000 rpm/s) leaves S5b in cycle 103 after the fault cycle (stop_test.cpp derivation).
  const int stopped =
      h.run_until([&] { return h.drive.state() == tg::DriveState::kS1SwitchingOnInhibited; }, 500);
  EXPECT_NEAR(stopped, 103, 2);
  EXPECT_LT(std::fabs(h.drive.motor_speed_rpm()), p.standstill_threshold_rpm);

  // Link back: the answer shows the fault, the cause is gone, acknowledge recovers.
  h.drive.set_link_lost(false);
  h.speed_rpm(0.0);
  h.stw1(0x047E);
  EXPECT_TRUE(h.cycle());
  const LinkHealth after = h.drive.link_health();
  EXPECT_TRUE(after.up);
  EXPECT_EQ(after.consecutive_missed, 0u);
  EXPECT_EQ(after.missed_total, 20u + static_cast<std::uint64_t>(stopped));
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  h.run(2);
  h.stw1(0x04FE);
  EXPECT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0270");
  EXPECT_EQ(h.drive.active_fault(), 0u);
  h.stw1(0x047E);
  EXPECT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0231");
  h.stw1(0x047F);
  h.run(2);
  EXPECT_EQ(hex16(h.zsw1()), "0x0337");
  h.speed_rpm(1000.0);
  h.run(100);
  EXPECT_NEAR(h.nist_rpm(), 1000.0, 0.5);
  EXPECT_EQ(h.drive.active_fault(), 0u);
}

// Backlash between motor and load (docs/simulated-drive.md, the machine spec 01 §5.9 compensates): 2° of
// play, the motor starting in the middle of it. Motor position from G1_XIST1 (motor encoder, 2^22 counts per
// revolution, 8.6e-5° each), load position from the model. The load stands until the motor has crossed half
// the play, then follows 1° behind; after a reversal it stands while the motor crosses the whole play (its
// speed is 0 meanwhile) and then follows 1° ahead.
TEST(MachineSim, BacklashIsADeadBandBetweenMotorAndLoad) {
  SimulatedDriveParameters p;
  p.backlash = 2.0;
  Harness h(drive_config(3), p);
  h.power_up_to_s4();
  const double count = 360.0 / 4194304.0;
  auto motor = [&] { return static_cast<double>(h.actual.G1_XIST1) * count; };
  h.speed_rpm(30.0);  // 180°/s
  const int started = h.run_until([&] { return h.drive.load_position() > 0.0; }, 200);
  ASSERT_LE(started, 200);
  EXPECT_NEAR(motor() - h.drive.load_position(), 1.0, 2 * count);
  EXPECT_NEAR(h.drive.backlash_offset(), 1.0, 1e-12);
  h.run(200);
  EXPECT_NEAR(motor() - h.drive.load_position(), 1.0, 2 * count);
  EXPECT_NEAR(h.drive.load_speed(), 180.0, 0.5);

  h.speed_rpm(-30.0);
  h.run_until([&] { return h.nist_rpm() < 0.0; }, 100);  // the motor has turned round
  const double load = h.drive.load_position();
  int standing = 0;
  while (motor() > load - 1.0 + 2 * count && standing < 100) {
    EXPECT_EQ(h.drive.load_position(), load);
    EXPECT_EQ(h.drive.load_speed(), 0.0);
    h.cycle();
    ++standing;
  }
  // 2° at 180°/s = 11 ms, the motor still accelerating from the reversal: 12 ± 3 cycles.
  EXPECT_NEAR(standing, 12, 3);
  h.run(50);
  EXPECT_NEAR(h.drive.load_position() - motor(), 1.0, 2 * count);
  EXPECT_NEAR(h.drive.load_speed(), -180.0, 0.5);
}

// A fixed stop with backlash: the load stops at the stop, the motor half the play beyond it.
// Decision P25 (at a fixed stop the load stops there and the motor half the play beyond).
TEST(MachineSim, FixedStopWithBacklash) {
  SimulatedDriveParameters p;
  p.backlash = 2.0;
  p.machine.positive_fixed_stop = 10.0;
  Harness h(drive_config(3), p);
  h.power_up_to_s4();
  h.speed_rpm(30.0);
  ASSERT_LE(h.run_until([&] { return h.drive.machine_inputs().at_fixed_stop; }, 500), 500);
  h.run(5);
  EXPECT_EQ(h.drive.load_position(), 10.0);
  EXPECT_NEAR(static_cast<double>(h.actual.G1_XIST1) * 360.0 / 4194304.0, 11.0, 2 * 360.0 / 4194304.0);
  EXPECT_EQ(h.drive.load_speed(), 0.0);
}

}  // namespace
}  // namespace tomc::drives::test
