// MC_TorqueLimiting on TO_PositioningAxis: force/torque limiting through MOMRED (spec 01 §8.10), fixed-stop
// detection and clamping (spec 01 §8.11, seed 004 §6.7.9.2), the instruction's rules (spec 03 §4.18.3, L3,
// T26/T27) and the spec 01 §12 scenarios 35–37.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_torque_limiting.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/axis/torque_limiting.hpp"

namespace {

using namespace tomc;
namespace fixture = tomc::testing;
using fixture::PositioningAxisMachine;
using techobjects::StatusWordBit;

// A machine whose user program also calls an MC_TorqueLimiting instance.
struct TorqueMachine : PositioningAxisMachine {
  explicit TorqueMachine(techobjects::PositioningAxisData data = fixture::linear_axis_data(),
                         drives::SimulatedDriveParameters drive = fixed_stop_drive(),
                         std::uint16_t telegram = 105)
      : PositioningAxisMachine(data, drive, telegram) {
    user = [this] { torque(*axis); };
  }
  static drives::SimulatedDriveParameters fixed_stop_drive() {
    drives::SimulatedDriveParameters p = fixture::linear_drive();
    p.machine.positive_fixed_stop = 32.0;
    p.machine.negative_fixed_stop = -32.0;
    return p;
  }
  std::uint16_t momred() const { return axis->drive()->drive_setpoint().MOMRED; }
  bool stw2_fixed_stop() const {
    return axis->drive()->drive_setpoint().STW2.test(telegrams::Stw2Bit::kTravelToFixedStop);
  }
  bool status(StatusWordBit bit) const { return techobjects::test(db().StatusWord, bit); }
  instructions::MC_TorqueLimiting<techobjects::PositioningAxis> torque;
};

// spec 01 §12 scenario 35: LimitDefaults.Torque 5 Nm, Limit -1 -> 5 Nm both ways; with ReferenceTorque 10 Nm
// on the motor side the drive gets 50 % reduction: MOMRED = 0x2000 (16384 = 100 %, spec 06 §9). STW2.8 is set
// while the instruction is active and cleared with Enable FALSE.
TEST(TorqueLimiting, DefaultLimitIsHalfTheReferenceTorque) {
  auto d = fixture::linear_axis_data();
  d.TorqueLimiting.LimitDefaults.Torque = 5.0;
  d.Actor.DriveParameter.ReferenceTorque = 10.0;
  TorqueMachine m(d);
  m.run(5);
  EXPECT_EQ(m.momred(), 0);
  m.torque.Enable = true;  // Limit -1.0, Mode 0: need not be enabled (spec 03 §4.18.3)
  m.run(2);
  EXPECT_TRUE(m.torque.Busy);
  EXPECT_FALSE(m.torque.Error);
  EXPECT_EQ(m.momred(), 0x2000);
  EXPECT_TRUE(m.stw2_fixed_stop());
  EXPECT_TRUE(m.status(StatusWordBit::kTorqueLimitingCommand));
  m.torque.Limit = 2.5;  // taken on the next call without an edge (spec 03 §4.18.3 note 5, T27)
  m.run(2);
  EXPECT_EQ(m.momred(), 0x3000);  // 75 % reduction
  m.torque.Enable = false;
  m.run(2);
  EXPECT_FALSE(m.torque.Busy);
  EXPECT_EQ(m.momred(), 0);
  EXPECT_FALSE(m.stw2_fixed_stop());
  EXPECT_FALSE(m.status(StatusWordBit::kTorqueLimitingCommand));
}

// spec 01 §8.10 [derived] conversions, table-driven: rotary load side T/(i·η); linear load side F·h/(2π·i·η);
// motor side and linear motor as given.
TEST(TorqueLimiting, LimitConversions) {
  using techobjects::TorqueLimitMechanics;
  struct Row {
    TorqueLimitMechanics m;
    double limit;
    double motor;
  };
  const Row rows[] = {
      {{false, false, false, 3.0, 0.9, 0.0}, 6.0, 6.0},                     // motor side
      {{false, false, true, 3.0, 0.9, 0.0}, 6.0, 6.0 / 2.7},                // rotary, load side
      {{true, false, true, 1.0, 1.0, 0.010}, 1000.0, 10.0 / (2.0 * M_PI)},  // linear, load side, 10 mm/rev
      {{true, false, true, 2.0, 0.8, 0.005}, 500.0, 2.5 / (2.0 * M_PI * 1.6)},
      {{true, true, true, 2.0, 0.8, 0.005}, 500.0, 500.0},  // linear motor: the force itself
  };
  for (const auto& r : rows)
    EXPECT_NEAR(techobjects::motor_torque_limit(r.limit, r.m), r.motor, 1e-12);
}

// spec 01 §8.10 on the TO: linear axis, load side (LimitBase 1), 10 mm leadscrew, 1000 N -> 1.5915 Nm of the
// 4 Nm reference: MOMRED = 16384·(1 - 1.5915/4) = 9865.
TEST(TorqueLimiting, ForceOnTheLoadSideOfALinearAxis) {
  auto d = fixture::linear_axis_data();
  d.TorqueLimiting.LimitBase = 1;
  TorqueMachine m(d);
  m.torque.Enable = true;
  m.torque.Limit = 1000.0;
  m.run(2);
  EXPECT_EQ(m.momred(), 9865);
}

// spec 01 §12 scenario 36 and spec 03 §4.18.3: rejections with their ErrorIDs; the error clears with Enable
// FALSE.
TEST(TorqueLimiting, Rejections) {
  {  // an active MC_Stop
    TorqueMachine m;
    m.enable();
    m.stop.Execute = true;
    m.run(2);
    m.torque.Enable = true;
    m.run(1);
    EXPECT_TRUE(m.torque.Error);
    EXPECT_EQ(m.torque.ErrorID, techobjects::error_id::kLockedByStop);
    EXPECT_EQ(m.momred(), 0);
    m.stop.Execute = false;
    m.run(2);
    EXPECT_TRUE(m.torque.Error);  // latched while Enable stays TRUE
    m.torque.Enable = false;
    m.run(1);
    EXPECT_FALSE(m.torque.Error);
    m.torque.Enable = true;
    m.run(1);
    EXPECT_TRUE(m.torque.Busy);
  }
  struct Row {
    std::int32_t mode;
    double limit;
    bool enabled;
    std::uint16_t telegram;
    std::uint16_t error;
  };
  const Row rows[] = {
      {2, -1.0, true, 105, techobjects::error_id::kInvalidMode},
      {0, std::numeric_limits<double>::quiet_NaN(), true, 105, techobjects::error_id::kInvalidTorqueLimit},
      {0, 1.0e13, true, 105, techobjects::error_id::kInvalidTorqueLimit},
      {0, 1.0, true, 3, techobjects::error_id::kNoTorqueReduction},  // telegram 3: no MOMRED
      {1, 1.0, false, 105, techobjects::error_id::kAxisNotEnabled},  // fixed stop needs an enabled TO
      {1, 1.0, true, 3, 0},  // detection without limiting works on any telegram
      {0, 1.0e12, true, 105, 0},
  };
  for (const auto& r : rows) {
    TorqueMachine m(fixture::linear_axis_data(), TorqueMachine::fixed_stop_drive(), r.telegram);
    if (r.enabled) {
      ASSERT_GT(m.enable(), 0);
    }
    m.torque.Enable = true;
    m.torque.Mode = r.mode;
    m.torque.Limit = r.limit;
    m.run(1);
    EXPECT_EQ(m.torque.ErrorID, r.error) << "mode " << r.mode << " limit " << r.limit;
    EXPECT_EQ(m.torque.Busy, r.error == 0);
  }
}

// spec 01 §8.11 / §12 scenario 37: PositionTolerance >= FollowingErrorDeviation, or a maximum following error
// <= FollowingErrorDeviation with following-error monitoring on, is rejected.
TEST(TorqueLimiting, ClampingConfigurationIsChecked) {
  auto d = fixture::linear_axis_data();
  d.Clamping.FollowingErrorDeviation = 2.0;
  d.Clamping.PositionTolerance = 2.0;
  TorqueMachine a(d);
  a.enable();
  a.torque.Enable = true;
  a.torque.Mode = 1;
  a.run(1);
  EXPECT_EQ(a.torque.ErrorID, techobjects::error_id::kInvalidClampingConfiguration);
  d.Clamping.PositionTolerance = 1.0;
  d.FollowingError.MaxValue = 2.0;
  TorqueMachine b(d);
  b.enable();
  b.torque.Enable = true;
  b.torque.Mode = 1;
  b.run(1);
  EXPECT_EQ(b.torque.ErrorID, techobjects::error_id::kInvalidClampingConfiguration);
  d.FollowingError.EnableMonitoring = false;  // without following-error monitoring the maximum does not count
  TorqueMachine c(d);
  c.enable();
  c.torque.Enable = true;
  c.torque.Mode = 1;
  c.run(1);
  EXPECT_EQ(c.torque.ErrorID, 0);
  EXPECT_TRUE(c.torque.Busy);
}

// spec 01 §12 scenario 37 with T27: deviation 2 mm, tolerance 1 mm; a MoveAbsolute towards the stop at 32 mm
// ends with CommandAborted once the following error exceeds 2 mm; the setpoint stays; position control
// stays; the torque instruction stays Busy; a changed Limit is taken while clamped.
TEST(TorqueLimiting, FixedStopAbortsTheMoveAndFreezesTheSetpoint) {
  auto d = fixture::linear_axis_data();
  d.Clamping.FollowingErrorDeviation = 2.0;
  d.Clamping.PositionTolerance = 1.0;
  TorqueMachine m(d);
  m.enable();
  ASSERT_TRUE(m.home_at(0.0));
  m.torque.Enable = true;
  m.torque.Mode = 1;
  m.torque.Limit = 0.4;
  m.run(1);
  ASSERT_TRUE(m.torque.Busy);
  m.move_absolute.Position = 50.0;
  m.move_absolute.Velocity = 20.0;
  m.move_absolute.Execute = true;
  const int n = m.run_until([&] { return m.torque.InClamping; }, 5000);
  ASSERT_GT(n, 0);
  EXPECT_TRUE(m.move_absolute.CommandAborted);
  EXPECT_FALSE(m.move_absolute.Done);
  EXPECT_NEAR(m.drive->load_position(), 32.0, 1e-6);
  EXPECT_GT(m.db().StatusPositioning.FollowingError, 2.0);
  EXPECT_TRUE(m.status(StatusWordBit::kInClamping));
  const double frozen = m.db().Position;
  const std::uint16_t momred_04 = m.momred();
  m.torque.Limit = 0.2;
  m.run(200);
  EXPECT_DOUBLE_EQ(m.db().Position, frozen);  // "the setpoint is no longer changed"
  EXPECT_FALSE(m.status(StatusWordBit::kNonPositionControlled));
  EXPECT_TRUE(m.torque.Busy);
  EXPECT_TRUE(m.torque.InClamping);
  EXPECT_GT(m.momred(), momred_04);  // smaller limit, more reduction
  EXPECT_NEAR(std::fabs(m.drive->motor_torque_nm()), 0.2, 0.01);
  EXPECT_EQ(m.db().ErrorDetail.Number, 0u);
}

// seed 004 §6.7.9.2: while clamped, a job further into the stop ends at once (decision F3); a
// position-controlled job away from the stop releases the clamping when it leaves the tolerance, without an
// alarm, and runs on.
TEST(TorqueLimiting, ReleaseOnlyByAJobAwayFromTheStop) {
  TorqueMachine m;
  m.enable();
  ASSERT_TRUE(m.home_at(0.0));
  m.torque.Enable = true;
  m.torque.Mode = 1;
  m.torque.Limit = 0.5;
  m.move_velocity.Velocity = 10.0;
  m.move_velocity.Direction = 1;
  m.move_velocity.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.torque.InClamping; }, 6000), 0);
  EXPECT_TRUE(m.move_velocity.CommandAborted);
  m.move_velocity.Execute = false;
  m.run(5);
  m.move_relative.Distance = 5.0;  // further into the stop
  m.move_relative.Velocity = 10.0;
  m.move_relative.Execute = true;
  m.run(3);
  EXPECT_TRUE(m.move_relative.CommandAborted);
  EXPECT_TRUE(m.torque.InClamping);
  m.move_relative.Execute = false;
  m.run(2);
  m.move_absolute.Position = 10.0;
  m.move_absolute.Velocity = 10.0;
  m.move_absolute.Execute = true;
  const int released = m.run_until([&] { return !m.torque.InClamping; }, 1000);
  ASSERT_GT(released, 0);
  EXPECT_LT(m.db().ActualPosition, 32.0 - m.db().Clamping.PositionTolerance);
  EXPECT_TRUE(m.move_absolute.Busy);
  EXPECT_EQ(m.db().ErrorDetail.Number, 0u);
  ASSERT_GT(m.run_until([&] { return m.move_absolute.Done; }, 5000), 0);
  EXPECT_NEAR(m.db().ActualPosition, 10.0, 0.01);
}

// TorqueLimiting.PositionBasedMonitorings (spec 01 §8.10): 0 switches following-error monitoring off while
// limiting is active, 1 keeps it. A limit far below what the move needs makes the following error grow past
// FollowingError.MaxValue (10 mm).
TEST(TorqueLimiting, PositionBasedMonitorings) {
  for (const std::int32_t keep : {0, 1}) {
    auto d = fixture::linear_axis_data();
    d.TorqueLimiting.PositionBasedMonitorings = keep;
    TorqueMachine m(d, fixture::linear_drive());
    m.enable();
    ASSERT_TRUE(m.home_at(0.0));
    m.torque.Enable = true;
    m.torque.Limit = 0.0005;  // Nm: the motor barely moves the load
    m.move_absolute.Position = 200.0;
    m.move_absolute.Velocity = 100.0;
    m.move_absolute.Execute = true;
    m.run(1500);
    if (keep == 0) {
      EXPECT_GT(std::fabs(m.db().Position - m.db().ActualPosition), 10.0);
      EXPECT_EQ(m.db().ErrorDetail.Number, 0u);
      EXPECT_TRUE(m.power.Status);
    } else {
      EXPECT_EQ(m.db().ErrorDetail.Number, 521u);
      EXPECT_FALSE(m.power.Status);
    }
  }
}

// spec 02 §9.2 (decision W2): while the axis control panel holds master control, the program's
// MC_TorqueLimiting does not start (16#8012); once the panel gives control back it does.
TEST(TorqueLimiting, RejectedWhileThePanelHoldsMasterControl) {
  TorqueMachine m;
  m.run(2);
  ASSERT_TRUE(m.axis->program_released());
  m.axis->control_priority().grant();
  m.torque.Enable = true;
  m.torque.Limit = 1.0;  // of the 4 Nm reference: MOMRED 75 %
  m.run(2);
  EXPECT_TRUE(m.torque.Error);
  EXPECT_EQ(m.torque.ErrorID, techobjects::error_id::kControlPanelActive);
  EXPECT_EQ(m.momred(), 0);
  m.axis->control_priority().give_back();
  m.torque.Enable = false;
  m.run(1);
  m.torque.Enable = true;
  m.run(2);
  EXPECT_TRUE(m.torque.Busy);
  EXPECT_GT(m.momred(), 0);
}

// spec 03 L3: the torque function stays effective when a TO alarm occurs, as long as Enable stays TRUE.
TEST(TorqueLimiting, StaysEffectiveThroughAlarms) {
  TorqueMachine m;
  m.enable();
  m.torque.Enable = true;
  m.torque.Limit = 1.0;
  m.run(2);
  const std::uint16_t momred = m.momred();
  ASSERT_GT(momred, 0);
  ASSERT_TRUE(
      m.axis->inject_alarm(techobjects::kAlarmPositioning, 1, techobjects::AlarmReaction::kRemoveEnable));
  m.run(5);
  EXPECT_FALSE(m.power.Status);
  EXPECT_TRUE(m.torque.Busy);
  EXPECT_EQ(m.momred(), momred);
}

}  // namespace
