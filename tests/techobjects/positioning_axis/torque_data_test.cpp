// Telegram 750 on TO_PositioningAxis: MC_TorqueAdditive (M_ADD1) and MC_TorqueRange (M_LIMIT_POS/M_LIMIT_NEG)
// with their handshakes (spec 03 §4.18.1/§4.18.2), preconditions (spec 01 §8.12/§8.13, §12 scenario 36), the
// mutual exclusion with MC_TorqueLimiting, StatusTorqueData (spec 04 §4.7), the wire values of spec 06 §8
// (TV14–TV16), the simulated drive applying them, and the acceleration-based torque precontrol (spec 02 §7.4
// eq. 6, §7.5). One Runtime::step() = MC_Servo, MC_Interpolator, user program: a value given in the user
// program of cycle k goes out in the MC_Servo of cycle k+1.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_torque_additive.hpp"
#include "tomc/instructions/mc_torque_limiting.hpp"
#include "tomc/instructions/mc_torque_range.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/axis/torque_data.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace {

using namespace tomc;
namespace fixture = tomc::testing;
namespace eid = techobjects::error_id;
using techobjects::PositioningAxis;

constexpr double kPi = std::numbers::pi;

// Telegram `telegram` + 750, reference torque 10 Nm in the TO and the drive (the figures of TV15/TV16).
struct TorqueDataMachine : fixture::PositioningAxisMachine {
  explicit TorqueDataMachine(techobjects::PositioningAxisData data = reference_10(),
                             std::uint16_t telegram = 3, std::uint16_t supplementary = 750)
      : PositioningAxisMachine(data, drive_10(), telegram, true, supplementary) {
    user = [this] {
      additive(*axis);
      range(*axis);
      limiting(*axis);
    };
  }
  static techobjects::PositioningAxisData reference_10() {
    auto d = fixture::linear_axis_data();
    d.Actor.DriveParameter.ReferenceTorque = 10.0;
    return d;
  }
  static drives::SimulatedDriveParameters drive_10() {
    auto p = fixture::linear_drive();
    p.reference_torque_nm = 10.0;
    p.torque_limit_nm = 10.0;
    return p;
  }
  const telegrams::SetpointSignals& sent() const { return axis->drive()->supplementary_setpoint(); }
  double continuous_actual() const { return axis->continuous_actual_position(); }
  instructions::MC_TorqueAdditive<PositioningAxis> additive;
  instructions::MC_TorqueRange<PositioningAxis> range;
  instructions::MC_TorqueLimiting<PositioningAxis> limiting;
};

// spec 06 TV14: no MC_TorqueAdditive, no MC_TorqueRange -> 00 00 40 00 C0 00 (limits = ±ReferenceTorque,
// spec 01 §8.13). TV15: T_ref 10 Nm, M_ADD +2.5 Nm, limits ±5 Nm -> 10 00 20 00 E0 00.
TEST(TorqueData, WireValuesOfTv14AndTv15) {
  TorqueDataMachine m;
  ASSERT_GT(m.enable(), 0);
  EXPECT_EQ(m.sent().M_ADD1, 0);
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x4000);
  EXPECT_EQ(m.sent().M_LIMIT_NEG, static_cast<std::int16_t>(-0x4000));  // 0xC000

  m.additive.Enable = true;
  m.additive.Value = 2.5;
  m.range.Enable = true;
  m.range.UpperLimit = 5.0;
  m.range.LowerLimit = -5.0;
  m.run(1);  // both accepted in the call: Busy at once (spec 03 §4.18.1/§4.18.2)
  EXPECT_TRUE(m.additive.Busy);
  EXPECT_TRUE(m.range.Busy);
  EXPECT_FALSE(m.additive.Error);
  EXPECT_FALSE(m.range.Error);
  EXPECT_EQ(m.sent().M_ADD1, 0) << "sent by the next MC_Servo";
  m.run(1);
  EXPECT_EQ(m.sent().M_ADD1, 0x1000);
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x2000);
  EXPECT_EQ(m.sent().M_LIMIT_NEG, static_cast<std::int16_t>(-0x2000));  // 0xE000
  EXPECT_EQ(m.db().StatusTorqueData.CommandAdditiveTorqueActive, 1);
  EXPECT_EQ(m.db().StatusTorqueData.CommandTorqueRangeActive, 1);
  EXPECT_DOUBLE_EQ(m.db().StatusTorqueData.TotalTorqueAdditive, 2.5);

  // Value and limits are taken on every call (the winder's tension changes while Enable stays TRUE).
  m.additive.Value = -1.25;
  m.range.UpperLimit = 7.5;
  m.run(2);
  EXPECT_EQ(m.sent().M_ADD1, static_cast<std::int16_t>(-0x0800));
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x3000);

  // Function diagram B of §4.18.1: Enable FALSE sends zero in the next MC_Servo; MC_TorqueRange FALSE sends
  // the reference torque again.
  m.additive.Enable = false;
  m.range.Enable = false;
  m.run(1);
  EXPECT_FALSE(m.additive.Busy);
  EXPECT_FALSE(m.range.Busy);
  m.run(1);
  EXPECT_EQ(m.sent().M_ADD1, 0);
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x4000);
  EXPECT_EQ(m.sent().M_LIMIT_NEG, static_cast<std::int16_t>(-0x4000));
  EXPECT_EQ(m.db().StatusTorqueData.CommandAdditiveTorqueActive, 0);
  EXPECT_EQ(m.db().StatusTorqueData.CommandTorqueRangeActive, 0);
  EXPECT_DOUBLE_EQ(m.db().StatusTorqueData.TotalTorqueAdditive, 0.0);
}

// spec 01 §8.12/§8.13, seed L4224: with Actor.InverseDirection the additive torque is negated and the limits
// are inverted (upper' = −lower, lower' = −upper); ActualTorque is shown in the axis' direction.
TEST(TorqueData, InverseDirectionNegatesAndSwaps) {
  auto d = TorqueDataMachine::reference_10();
  d.Actor.InverseDirection = true;
  TorqueDataMachine m(d);
  ASSERT_GT(m.enable(), 0);
  m.additive.Enable = true;
  m.additive.Value = 2.5;
  m.range.Enable = true;
  m.range.UpperLimit = 5.0;
  m.range.LowerLimit = -2.5;
  m.run(2);
  EXPECT_EQ(m.sent().M_ADD1, static_cast<std::int16_t>(-0x1000));
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x1000);                              // −(−2.5 Nm)
  EXPECT_EQ(m.sent().M_LIMIT_NEG, static_cast<std::int16_t>(-0x2000));  // −(5 Nm)
  EXPECT_DOUBLE_EQ(m.db().StatusTorqueData.TotalTorqueAdditive, 2.5);   // the technology value
}

// The simulated drive applies the limits (p1522/p1523) and reports M_ACT (spec 06 §8). A MoveVelocity at
// MaxAcceleration 5000 mm/s² (≈ 0.94 Nm for motor and load) under MC_TorqueRange +0.5/−0.25 Nm: the motor
// torque stays at the upper limit as sent (N2: 819 = 0.49988 Nm) and ActualTorque shows it; braking meets
// the lower one (−410 = −0.25024 Nm).
TEST(TorqueData, DriveAppliesRangeAndReportsActualTorque) {
  TorqueDataMachine m;
  ASSERT_GT(m.enable(), 0);
  m.range.Enable = true;
  m.range.UpperLimit = 0.5;
  m.range.LowerLimit = -0.25;
  m.run(2);
  ASSERT_EQ(m.sent().M_LIMIT_POS, 819);
  ASSERT_EQ(m.sent().M_LIMIT_NEG, -410);
  const double upper = telegrams::n2_to_torque(819, 10.0);
  const double lower = telegrams::n2_to_torque(-410, 10.0);
  m.move_velocity.Velocity = 400.0;
  m.move_velocity.Acceleration = 5000.0;
  m.move_velocity.Deceleration = 5000.0;
  m.move_velocity.Execute = true;
  m.run(20);
  EXPECT_DOUBLE_EQ(m.drive->motor_torque_nm(), upper);
  EXPECT_EQ(m.axis->drive()->supplementary_actual().M_ACT, 819);
  EXPECT_DOUBLE_EQ(m.db().StatusTorqueData.ActualTorque, upper);
  // Following-error monitoring is off while MC_TorqueRange limits (spec 01 §8.13, PositionBasedMonitorings
  // 0): the limited drive lags behind the setpoint, and no alarm 521 comes.
  m.run(100);
  EXPECT_GT(std::fabs(m.db().StatusPositioning.FollowingError), m.db().FollowingError.MaxValue);
  EXPECT_TRUE(m.axis->alarms().alarms().empty());
  m.move_velocity.Execute = false;
  m.halt.Deceleration = 5000.0;
  m.halt.Execute = true;
  bool braked_at_limit = false;
  for (int k = 0; k < 300 && !braked_at_limit; ++k) {
    m.run(1);
    braked_at_limit = m.drive->motor_torque_nm() == lower;
    EXPECT_GE(m.drive->motor_torque_nm(), lower);
  }
  EXPECT_TRUE(braked_at_limit);
}

// MC_TorqueAdditive −1.25 Nm on an enabled axis at standstill (M_ADD1 = −2048, the value of TV16): sent in
// the MC_Servo after the call, it enters the simulated drive's torque demand in the step after that — a
// disturbance torque the drive's speed loop and the TO's position loop then work off. ActualTorque follows
// the motor torque through M_ACT (N2 of 10 Nm, one step 10/16384 Nm).
// spec 01 §8.12 (MC_TorqueAdditive), spec 06 §8 and §11 TV16 (M_ADD1/M_ACT in N2 of the reference torque:
// −1.25 Nm = −2048).
TEST(TorqueData, AdditiveTorqueReachesTheMotor) {
  TorqueDataMachine m;
  ASSERT_GT(m.enable(), 0);
  m.run(10);
  const double at_rest = m.continuous_actual();
  m.additive.Enable = true;
  m.additive.Value = -1.25;
  m.run(1);  // the call
  m.run(1);  // MC_Servo sends M_ADD1
  EXPECT_EQ(m.sent().M_ADD1, static_cast<std::int16_t>(-0x0800));
  EXPECT_NEAR(m.drive->motor_torque_nm(), 0.0, 1e-9);
  m.run(1);  // the drive integrates with it
  EXPECT_LT(m.drive->motor_torque_nm(), -0.8);
  const double lsb = 10.0 / 16384.0;
  for (int k = 0; k < 20; ++k) {
    m.run(1);
    EXPECT_NEAR(m.db().StatusTorqueData.ActualTorque, m.drive->motor_torque_nm(), lsb) << "cycle " << k;
  }
  EXPECT_LT(m.continuous_actual(), at_rest) << "pushed in the direction of the additive torque";
  EXPECT_GT(m.drive->motor_torque_nm(), -0.1) << "the loops work the disturbance off";
}

// spec 03 §4.18.1/§4.18.2 prerequisites, spec 01 §12 scenario 36: no telegram 750, MC_TorqueAdditive on a TO
// that is not enabled, an active MC_Stop, invalid values. Each error stays until Enable goes FALSE.
TEST(TorqueData, Rejections) {
  {
    TorqueDataMachine m(TorqueDataMachine::reference_10(), 3, 0);  // telegram 3 only
    ASSERT_GT(m.enable(), 0);
    m.additive.Enable = true;
    m.range.Enable = true;
    m.run(1);
    EXPECT_EQ(m.additive.ErrorID, eid::kNoTorqueData);
    EXPECT_EQ(m.range.ErrorID, eid::kNoTorqueData);
    EXPECT_FALSE(m.additive.Busy);
    EXPECT_EQ(m.db().StatusTorqueData.CommandAdditiveTorqueActive, 0);
  }
  TorqueDataMachine m;
  m.run(5);
  // Not enabled: MC_TorqueAdditive is rejected; MC_TorqueRange needs no enabled TO ([AMB-10]).
  m.additive.Enable = true;
  m.range.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.additive.Error);
  EXPECT_EQ(m.additive.ErrorID, eid::kAxisNotEnabled);
  EXPECT_TRUE(m.range.Busy);
  EXPECT_FALSE(m.range.Error);
  ASSERT_GT(m.enable(), 0);
  EXPECT_TRUE(m.additive.Error) << "latched until Enable goes FALSE";
  m.additive.Enable = false;
  m.range.Enable = false;
  m.run(1);
  EXPECT_FALSE(m.additive.Error);
  EXPECT_EQ(m.additive.ErrorID, 0);

  // An MC_Stop with Execute TRUE (scenario 36).
  m.stop.Execute = true;
  m.run(2);
  m.additive.Enable = true;
  m.range.Enable = true;
  m.run(1);
  EXPECT_EQ(m.additive.ErrorID, eid::kLockedByStop);
  EXPECT_EQ(m.range.ErrorID, eid::kLockedByStop);
  m.additive.Enable = false;
  m.range.Enable = false;
  m.stop.Execute = false;
  m.run(5);

  // Invalid values: Value outside ±1E12 or not finite; UpperLimit not above LowerLimit.
  m.additive.Enable = true;
  m.additive.Value = std::numeric_limits<double>::quiet_NaN();
  m.range.Enable = true;
  m.range.UpperLimit = 1.0;
  m.range.LowerLimit = 1.0;
  m.run(1);
  EXPECT_EQ(m.additive.ErrorID, eid::kInvalidTorqueValue);
  EXPECT_EQ(m.range.ErrorID, eid::kInvalidTorqueRange);
  m.additive.Enable = false;
  m.range.Enable = false;
  m.run(1);
  m.additive.Value = 2.0e12;
  m.additive.Enable = true;
  m.range.LowerLimit = -1.0;
  m.range.Enable = true;
  m.run(1);
  EXPECT_EQ(m.additive.ErrorID, eid::kInvalidTorqueValue);
  EXPECT_TRUE(m.range.Busy);
  // An invalid value while active ends the job with the error (taken on every call, decision Q1): the
  // limits fall back to ±ReferenceTorque in the next MC_Servo.
  m.range.UpperLimit = -2.0;
  m.run(2);
  EXPECT_EQ(m.range.ErrorID, eid::kInvalidTorqueRange);
  EXPECT_FALSE(m.range.Busy);
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x4000);

  // No other job aborts them (spec 03 §4.18 priority): MC_Stop and alarms leave them running.
  m.additive.Enable = false;
  m.range.Enable = false;
  m.run(1);
  m.additive.Value = 1.0;
  m.additive.Enable = true;
  m.range.UpperLimit = 2.0;
  m.range.Enable = true;
  m.run(1);
  ASSERT_TRUE(m.additive.Busy);
  m.stop.Execute = true;
  m.run(50);
  EXPECT_TRUE(m.additive.Busy);
  EXPECT_TRUE(m.range.Busy);
  EXPECT_EQ(m.sent().M_ADD1, 0x0666);  // round(1/10·16384) = 1638
}

// Mutual exclusion (spec 03 §4.18.2/§4.18.3 priority, seed L10730): while MC_TorqueLimiting limits,
// MC_TorqueRange is rejected, and vice versa; neither replaces the other.
TEST(TorqueData, TorqueRangeAndTorqueLimitingExcludeEachOther) {
  TorqueDataMachine m(TorqueDataMachine::reference_10(), 105);
  ASSERT_GT(m.enable(), 0);
  m.limiting.Enable = true;
  m.run(1);
  ASSERT_TRUE(m.limiting.Busy);
  m.range.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.range.Error);
  EXPECT_EQ(m.range.ErrorID, eid::kTorqueLimitingExclusion);
  EXPECT_TRUE(m.limiting.Busy) << "the running one is not replaced";
  m.range.Enable = false;
  m.limiting.Enable = false;
  m.run(1);

  m.range.Enable = true;
  m.run(1);
  ASSERT_TRUE(m.range.Busy);
  m.limiting.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.limiting.Error);
  EXPECT_EQ(m.limiting.ErrorID, eid::kTorqueLimitingExclusion);
  EXPECT_TRUE(m.range.Busy);
  m.run(1);
  EXPECT_EQ(m.axis->drive()->drive_setpoint().MOMRED, 0) << "no torque reduction from the rejected job";
  // MC_TorqueAdditive has no such exclusion.
  m.additive.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.additive.Busy);
}

// A virtual axis has no drive: both jobs are accepted and nothing is output (as MC_TorqueLimiting, spec 01
// §2.5; decision Q2); StatusTorqueData shows them active.
TEST(TorqueData, VirtualAxisAcceptsAndOutputsNothing) {
  auto d = TorqueDataMachine::reference_10();
  d.VirtualAxis.Mode = techobjects::kModeOn;
  fixture::PositioningAxisMachine m(d, fixture::linear_drive(), 3, false);
  instructions::MC_TorqueAdditive<PositioningAxis> additive;
  m.user = [&] { additive(*m.axis); };
  ASSERT_GT(m.enable(), 0);
  additive.Enable = true;
  additive.Value = 3.0;
  m.run(2);
  EXPECT_TRUE(additive.Busy);
  EXPECT_EQ(m.db().StatusTorqueData.CommandAdditiveTorqueActive, 1);
  EXPECT_DOUBLE_EQ(m.db().StatusTorqueData.TotalTorqueAdditive, 0.0);
}

// ---- acceleration-based torque precontrol (spec 02 §7.4 eq. 6, §7.5; seed 004 §6.13.5) ----

// M_add = Scale/100 · (J_motor + J_load reflected) · α_motor, table-driven over the mechanics of spec 01
// §5.10:
//   rotary, gear i:      T = J_m·i·α_load + J_L·α_load/i            (α_load = a·2π/360 for a in °/s²)
//   linear, leadscrew h: T = J_m·2π·a/h + m·a·h/(2π)               (a in m/s², h in m)
//   linear motor:        F = (m_motor + m_load)·a
TEST(TorquePrecontrol, TorqueFromAccelerationAndInertia) {
  using techobjects::TorquePrecontrolMechanics;
  struct Row {
    const char* what;
    TorquePrecontrolMechanics m;
    double acceleration;  // position units/s²
    double expected;
  };
  const double deg = kPi / 180.0;
  const Row rows[] = {
      // rotary table in degrees, gear 5 motor revolutions per load revolution: r = 5/360 rev/°
      {"rotary 1:5",
       {false, 2.0e-4, 0.5, deg, 5.0 / 360.0, 100.0},
       360.0,
       2.0e-4 * 5.0 * 2.0 * kPi + 0.5 * 2.0 * kPi / 5.0},
      // linear axis in mm, 10 mm lead screw, 79 kg (the defaults of the data block and the simulated drive)
      {"linear leadscrew",
       {false, 1.0e-4, 79.0, 1.0e-3, 0.1, 100.0},
       1000.0,
       1.0e-4 * 2.0 * kPi * 1.0 / 0.010 + 79.0 * 1.0 * 0.010 / (2.0 * kPi)},
      {"linear leadscrew, Scale 50 %",
       {false, 1.0e-4, 79.0, 1.0e-3, 0.1, 50.0},
       1000.0,
       0.5 * (1.0e-4 * 2.0 * kPi / 0.010 + 79.0 * 0.010 / (2.0 * kPi))},
      {"linear motor: a force", {true, 1.0, 20.0, 1.0e-3, 0.1, 100.0}, -2000.0, -(1.0 + 20.0) * 2.0},
      {"Scale 0 %", {false, 1.0e-4, 79.0, 1.0e-3, 0.1, 0.0}, 1000.0, 0.0},
  };
  for (const auto& r : rows)
    EXPECT_NEAR(techobjects::precontrol_torque(r.acceleration, r.m), r.expected, 1e-12 * (1.0 + std::fabs(r.expected)))
        << r.what;
  EXPECT_NEAR(rows[1].expected, 0.188564, 1e-6);
}

// On the axis: MoveVelocity at 1000 mm/s² (trapezoid, no dynamic filter) -> TotalTorqueAdditive =
// 0.188564 Nm while accelerating, 0 at constant velocity, −0.188564 Nm while braking; with MC_TorqueAdditive
// 1 Nm the two add up (seed L7374) and M_ADD1 carries the sum (N2 of 10 Nm). Mode 0 sends nothing.
// spec 02 §7.5 (seed 004 §6.13.5 torque precontrol, added to MC_TorqueAdditive, seed L7374), spec 06 §8
// (M_ADD1).
TEST(TorquePrecontrol, AccelerationBasedPrecontrolOnTheAxis) {
  const double expected = 1.0e-4 * 2.0 * kPi / 0.010 + 79.0 * 0.010 / (2.0 * kPi);
  auto d = TorqueDataMachine::reference_10();
  d.TorquePreControl.Mode = 1;
  TorqueDataMachine m(d);
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 100.0;
  m.move_velocity.Acceleration = 1000.0;
  m.move_velocity.Deceleration = 1000.0;
  m.move_velocity.Execute = true;
  m.run(40);  // the ramp takes 100 ms
  EXPECT_NEAR(m.db().StatusTorqueData.TotalTorqueAdditive, expected, 1e-9);
  EXPECT_EQ(m.sent().M_ADD1, telegrams::torque_to_n2(expected, 10.0));  // 309
  m.additive.Enable = true;
  m.additive.Value = 1.0;
  m.run(2);
  EXPECT_NEAR(m.db().StatusTorqueData.TotalTorqueAdditive, expected + 1.0, 1e-9);
  EXPECT_EQ(m.sent().M_ADD1, telegrams::torque_to_n2(expected + 1.0, 10.0));
  m.additive.Enable = false;
  ASSERT_GT(m.run_until([&] { return m.move_velocity.InVelocity; }, 200), 0);
  m.run(2);
  EXPECT_NEAR(m.db().StatusTorqueData.TotalTorqueAdditive, 0.0, 1e-9);
  EXPECT_EQ(m.sent().M_ADD1, 0);
  m.move_velocity.Execute = false;
  m.halt.Deceleration = 1000.0;
  m.halt.Execute = true;
  m.run(40);
  EXPECT_NEAR(m.db().StatusTorqueData.TotalTorqueAdditive, -expected, 1e-9);
}

// The purpose of the precontrol (seed 004 §6.13.5: "reduces the following error while accelerating"): the
// same ramp on the simulated drive, whose motor and load have the inertia the data block gives, with and
// without precontrol; the following error's peak is smaller with it.
TEST(TorquePrecontrol, ReducesTheFollowingErrorWhileAccelerating) {
  auto peak = [](std::int32_t mode) {
    auto d = TorqueDataMachine::reference_10();
    d.TorquePreControl.Mode = mode;
    TorqueDataMachine m(d);
    EXPECT_GT(m.enable(), 0);
    m.move_velocity.Velocity = 100.0;
    m.move_velocity.Acceleration = 2000.0;
    m.move_velocity.Deceleration = 2000.0;
    m.move_velocity.Execute = true;
    double worst = 0.0;
    for (int k = 0; k < 60; ++k) {
      m.run(1);
      worst = std::max(worst, std::fabs(m.db().StatusPositioning.FollowingError));
    }
    return worst;
  };
  const double without = peak(0);
  const double with = peak(1);
  EXPECT_GT(without, 0.0);
  EXPECT_LT(with, 0.8 * without);  // measured: 0.184 mm without, 0.126 mm with
}

}  // namespace
