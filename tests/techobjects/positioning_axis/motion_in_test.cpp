// MC_MotionInVelocity / MC_MotionInPosition on the positioning axis (spec 03 §4.17, §3.3 L4, §8.2 T22–T24,
// seed 004 §9.17), cycle by cycle. Accounting: inputs written by the user program of cycle k are the
// setpoints of the interpolator of cycle k+1 (tomc's MC_PreServo-written setpoints act in the next
// MC_Interpolator, decision L5).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "profile_motion_in_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::StatusWordBit;
using tomc::testing::ProfileMachine;
namespace eid = techobjects::error_id;

bool status(const ProfileMachine& m, StatusWordBit bit) {
  return techobjects::test(m.db().StatusWord, bit);
}

techobjects::PositioningAxisData virtual_axis_data() {
  auto d = tomc::testing::linear_axis_data();
  d.VirtualAxis.Mode = techobjects::kModeOn;
  return d;
}

// spec 03 §8.2 T22: the rising edge makes the setpoint velocity 20 without a ramp, Busy; 30 is the setpoint
// one cycle after it is written; the falling edge gives velocity and acceleration 0 and ends Busy; no Done.
TEST(MotionIn, VelocitySetpointsActDirectlyAndTheFallingEdgeZeroesThem) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  m.motion_in_velocity.Velocity = 20.0;
  m.motion_in_velocity.Enable = true;
  m.run(1);  // cycle 1: the edge
  EXPECT_TRUE(m.motion_in_velocity.Busy);
  EXPECT_FALSE(m.motion_in_velocity.Error);
  m.run(1);  // cycle 2
  EXPECT_EQ(m.db().Velocity, 20.0);
  EXPECT_EQ(m.db().Acceleration, 0.0);
  EXPECT_TRUE(status(m, StatusWordBit::kMotionInCommand));
  EXPECT_EQ(m.db().StatusMotionIn.FunctionState, 1);
  const double x2 = m.db().Position;
  m.run(1);
  EXPECT_NEAR(m.db().Position, x2 + 0.02, 1e-12);  // 20 mm/s for 1 ms
  m.motion_in_velocity.Velocity = 30.0;
  m.motion_in_velocity.Acceleration = 5.0;
  m.run(1);  // written in this cycle's user program
  EXPECT_EQ(m.db().Velocity, 20.0);
  m.run(1);
  EXPECT_EQ(m.db().Velocity, 30.0);
  EXPECT_EQ(m.db().Acceleration, 5.0);
  m.motion_in_velocity.Enable = false;
  m.run(1);  // the falling edge
  EXPECT_FALSE(m.motion_in_velocity.Busy);
  EXPECT_FALSE(m.motion_in_velocity.CommandAborted);
  const double x_end = m.axis->setpoint().position;
  m.run(1);
  EXPECT_EQ(m.db().Velocity, 0.0);
  EXPECT_EQ(m.db().Acceleration, 0.0);
  EXPECT_EQ(m.axis->setpoint().position, x_end);
  EXPECT_FALSE(status(m, StatusWordBit::kMotionInCommand));
  EXPECT_EQ(m.db().StatusMotionIn.FunctionState, 0);
}

// spec 03 §8.2 T23: MotionInPosition's setpoints are taken as given; at the falling edge velocity and
// acceleration drop to 0 and the position setpoint keeps its last value (123.4, reached in steps of 0.1 mm).
TEST(MotionIn, PositionFallingEdgeKeepsThePosition) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(123.4 - 12.0));
  m.motion_in_position.Enable = true;
  m.motion_in_position.Velocity = 100.0;
  for (int k = 1; k <= 120; ++k) {  // 100 mm/s for 120 ms
    m.motion_in_position.Position = 123.4 - 12.0 + 0.1 * k;
    m.run(1);
    if (k > 1) {
      ASSERT_NEAR(m.db().Position, 123.4 - 12.0 + 0.1 * (k - 1), 1e-9) << k;
      ASSERT_EQ(m.db().Velocity, 100.0);
    }
  }
  EXPECT_EQ(m.db().StatusMotionIn.FunctionState, 2);
  EXPECT_FALSE(status(m, StatusWordBit::kNonPositionControlled));  // always position-controlled [S6]
  m.run(1);
  EXPECT_NEAR(m.db().Position, 123.4, 1e-9);
  m.motion_in_position.Enable = false;
  m.run(2);
  EXPECT_NEAR(m.db().Position, 123.4, 1e-9);
  EXPECT_EQ(m.db().Velocity, 0.0);
  EXPECT_EQ(m.db().Acceleration, 0.0);
  EXPECT_FALSE(m.axis->alarms().pending(techobjects::kAlarmFollowingError));
}

// spec 03 §8.2 T24, seed 004 §9.17.2.2 section B: a position step larger than the permitted following error
// (MaxValue 10 mm) with the monitoring active raises 521, which disables the TO (MC_Power.Status FALSE) and
// ends the job with Error; with the monitoring off the step is executed and no alarm follows.
TEST(MotionIn, PositionStepRaises521WithMonitoringAndIsExecutedWithout) {
  for (const bool monitoring : {true, false}) {
    auto data = tomc::testing::linear_axis_data();
    data.FollowingError.EnableMonitoring = monitoring;
    ProfileMachine m(data);
    ASSERT_GT(m.enable(), 0);
    const double x0 = m.db().Position;
    m.motion_in_position.Position = x0 + 50.0;
    m.motion_in_position.Enable = true;
    const int alarm =
        m.run_until([&] { return m.axis->alarms().pending(techobjects::kAlarmFollowingError); }, 300);
    if (monitoring) {
      ASSERT_GT(alarm, 0);
      EXPECT_LE(alarm, 20);
      m.run(2);
      EXPECT_FALSE(m.power.Status);
      EXPECT_TRUE(m.motion_in_position.Error);
      EXPECT_FALSE(m.motion_in_position.Busy);
    } else {
      EXPECT_LT(alarm, 0);
      m.run(1000);
      EXPECT_TRUE(m.power.Status);
      EXPECT_NEAR(m.db().ActualPosition, x0 + 50.0, 0.01);
    }
  }
}

// spec 03 §4.17 [S6]: PositionControlled FALSE forces non-position-controlled operation (StatusWord.X28),
// TRUE position control; seed 004 §9.17.1.2 section A: without position control no following error builds.
TEST(MotionIn, VelocityForcesTheControlModeItIsGiven) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  m.motion_in_velocity.Velocity = 50.0;
  m.motion_in_velocity.PositionControlled = false;
  m.motion_in_velocity.Enable = true;
  m.run(100);
  EXPECT_TRUE(status(m, StatusWordBit::kNonPositionControlled));
  EXPECT_NEAR(m.db().Position, m.db().ActualPosition, 1e-9);  // the setpoint tracks the actual value
  m.motion_in_velocity.Enable = false;
  m.run(1);
  m.motion_in_velocity.PositionControlled = true;
  m.motion_in_velocity.Enable = true;
  m.run(2);
  EXPECT_FALSE(status(m, StatusWordBit::kNonPositionControlled));
}

// spec 03 §4.17: the TO's dynamic limits do not apply: 600 mm/s on an axis with MaxVelocity 500, no 501.
TEST(MotionIn, DynamicLimitsDoNotApply) {
  ProfileMachine m(virtual_axis_data(), tomc::testing::linear_drive(), false);
  ASSERT_GT(m.enable(), 0);
  m.motion_in_velocity.Velocity = 600.0;
  m.motion_in_velocity.Acceleration = 1e6;
  m.motion_in_velocity.Enable = true;
  m.run(2);
  EXPECT_EQ(m.db().Velocity, 600.0);
  EXPECT_EQ(m.db().Acceleration, 1e6);
  EXPECT_FALSE(m.axis->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  EXPECT_FALSE(m.axis->alarms().pending(techobjects::kAlarmDynamicsLimitedAcceleration));
}

// spec 03 §4.17 / §4.5 "jerk transitions": the MotionIn acceleration matters for the job that replaces it —
// its acceleration is brought down through that job's jerk. MotionInVelocity 50 mm/s with 500 mm/s², replaced
// by MoveVelocity 50 mm/s with jerk 20000 mm/s³: the acceleration falls by 20 mm/s² a cycle, 25 cycles to 0,
// and the velocity overshoots by a²/2j = 6.25 mm/s. With Acceleration 0 the replacement starts from 0.
TEST(MotionIn, ReplacementReducesTheAccelerationThroughTheJerk) {
  for (const double acceleration : {500.0, 0.0}) {
    auto data = virtual_axis_data();
    data.DynamicLimits.MaxJerk = 1e6;
    ProfileMachine m(data, tomc::testing::linear_drive(), false);
    ASSERT_GT(m.enable(), 0);
    m.motion_in_velocity.Velocity = 50.0;
    m.motion_in_velocity.Acceleration = acceleration;
    m.motion_in_velocity.Enable = true;
    m.run(5);
    ASSERT_EQ(m.db().Acceleration, acceleration);
    m.move_velocity.Velocity = 50.0;
    m.move_velocity.Acceleration = 1000.0;
    m.move_velocity.Deceleration = 1000.0;
    m.move_velocity.Jerk = 20000.0;
    m.move_velocity.Execute = true;
    m.run(1);  // cycle 1: the edge (after MotionIn's call of this cycle)
    double peak = 0.0;
    for (int n = 1; n <= 150; ++n) {  // interpolator n cycles after the edge
      m.run(1);
      if (acceleration > 0.0 && n < 25) {
        EXPECT_NEAR(m.db().Acceleration, acceleration - 20.0 * n, 1e-6) << n;
      }
      peak = std::max(peak, m.db().Velocity);
    }
    EXPECT_TRUE(m.motion_in_velocity.CommandAborted);  // §9.19.1 R4 x C8 = A
    EXPECT_NEAR(m.db().Acceleration, 0.0, 1e-9);       // back at 50 mm/s
    EXPECT_NEAR(m.db().Velocity, 50.0, 1e-9);
    EXPECT_NEAR(peak, 50.0 + acceleration * acceleration / 40000.0, 1e-3);
  }
}

// Bad input is an ErrorID, never a motion: a setpoint that is not a number rejects the new job, and ends a
// running one with Error while the axis brakes with the default deceleration.
// Decision L6 (a NaN/infinite input rejects the new job or ends the running one with 16#8186 and a brake
// with DynamicDefaults), spec 03 §4.17.1.
TEST(MotionIn, NonFiniteSetpointsAreErrors) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  m.motion_in_velocity.Velocity = std::numeric_limits<double>::quiet_NaN();
  m.motion_in_velocity.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.motion_in_velocity.Error);
  EXPECT_EQ(m.motion_in_velocity.ErrorID, eid::kInvalidMotionInSetpoint);
  EXPECT_FALSE(m.motion_in_velocity.Busy);
  m.motion_in_velocity.Enable = false;
  m.run(1);
  EXPECT_FALSE(m.motion_in_velocity.Error);
  m.motion_in_velocity.Velocity = 50.0;
  m.motion_in_velocity.Enable = true;
  m.run(10);
  ASSERT_TRUE(m.motion_in_velocity.Busy);
  m.motion_in_velocity.Velocity = std::numeric_limits<double>::infinity();
  m.run(1);
  EXPECT_TRUE(m.motion_in_velocity.Error);
  EXPECT_EQ(m.motion_in_velocity.ErrorID, eid::kInvalidMotionInSetpoint);
  // DynamicDefaults.Deceleration 1000 mm/s²: 50 mm/s -> 0 in 50 cycles.
  const int stopped = m.run_until([&] { return m.db().Velocity == 0.0; }, 200);
  EXPECT_GE(stopped, 49);
  EXPECT_LE(stopped, 51);
}

}  // namespace
