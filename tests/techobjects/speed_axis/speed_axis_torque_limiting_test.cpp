// MC_TorqueLimiting on TO_SpeedAxis (spec 01 §8.10, spec 03 §4.18.3): torque limiting through MOMRED of
// telegrams 10x, InLimitation from MELDW; fixed-stop detection belongs to positioning/synchronous axes.
#include <gtest/gtest.h>

#include <cmath>

#include "speed_axis_fixture.hpp"
#include "tomc/instructions/mc_torque_limiting.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::StatusWordBit;
namespace eid = techobjects::error_id;

struct TorqueSpeedAxis : tomc::testing::SpeedAxisMachine {
  explicit TorqueSpeedAxis(std::uint16_t telegram = 102, techobjects::SpeedAxisData data = {})
      : SpeedAxisMachine(telegram, data) {
    user = [this] { torque(*axis); };
  }
  std::uint16_t momred() const { return axis->drive()->drive_setpoint().MOMRED; }
  bool status(StatusWordBit bit) const { return techobjects::test(axis->data().StatusWord, bit); }
  instructions::MC_TorqueLimiting<techobjects::SpeedAxis> torque;
};

// spec 03 §4.18.3 "Applies to": fixed-stop detection (Mode 1) only on positioning and synchronous axes;
// limiting needs a telegram with torque reduction (decision F1).
TEST(SpeedAxisTorqueLimiting, Rejections) {
  {
    TorqueSpeedAxis m;
    m.torque.Enable = true;
    m.torque.Mode = 1;
    m.run(1);
    EXPECT_EQ(m.torque.ErrorID, eid::kInvalidMode);
    EXPECT_FALSE(m.torque.Busy);
  }
  {
    TorqueSpeedAxis m(2);  // telegram 2: no MOMRED
    m.torque.Enable = true;
    m.run(1);
    EXPECT_EQ(m.torque.ErrorID, eid::kNoTorqueReduction);
  }
  {
    TorqueSpeedAxis m;
    m.enable();
    m.stop.Execute = true;
    m.run(2);
    m.torque.Enable = true;
    m.run(1);
    EXPECT_EQ(m.torque.ErrorID, eid::kLockedByStop);  // spec 01 §12 scenario 36
  }
}

// spec 01 §8.10: load side (LimitBase 1) through the gear, T_motor = T_load / (i·η): 4 N·m at the load over a
// 2:1 gear with η = 1 are 2 N·m at the motor, half the 4 N·m reference: MOMRED 0x2000; STW2.8 and X26 while
// active.
TEST(SpeedAxisTorqueLimiting, LoadSideLimitThroughTheGear) {
  techobjects::SpeedAxisData d;
  d.TorqueLimiting.LimitBase = 1;
  d.LoadGear.Numerator = 2;
  TorqueSpeedAxis m(102, d);
  m.torque.Enable = true;  // Limit -1: LimitDefaults.Torque 4 N·m
  m.run(2);
  EXPECT_TRUE(m.torque.Busy);
  EXPECT_EQ(m.momred(), 0x2000);
  EXPECT_TRUE(m.axis->drive()->drive_setpoint().STW2.test(telegrams::Stw2Bit::kTravelToFixedStop));
  EXPECT_TRUE(m.status(StatusWordBit::kTorqueLimitingCommand));
  m.torque.Enable = false;
  m.run(2);
  EXPECT_EQ(m.momred(), 0);
  EXPECT_FALSE(m.axis->drive()->drive_setpoint().STW2.test(telegrams::Stw2Bit::kTravelToFixedStop));
  EXPECT_FALSE(m.status(StatusWordBit::kTorqueLimitingCommand));
}

// The drive accelerates at the reduced torque: with 0.1 N·m the motor torque stays at the limit while the
// speed ramps up, and InLimitation (X27) shows it (MELDW.1 cleared at 90 % of the limit, p2194).
// spec 01 §8.10 (torque limiting; InLimitation at p2194 = 90 % of the limit), spec 04 §5.1 (StatusWord.X27
// InLimitation).
TEST(SpeedAxisTorqueLimiting, InLimitationWhileTheDriveAcceleratesAtTheLimit) {
  TorqueSpeedAxis m;
  m.enable();
  m.torque.Enable = true;
  m.torque.Limit = 0.1;
  m.move.Velocity = 3000.0;
  m.move.Acceleration = 100000.0;
  m.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.torque.InLimitation; }, 200), 0);
  EXPECT_TRUE(m.status(StatusWordBit::kInLimitation));
  m.run(20);
  EXPECT_NEAR(std::fabs(m.drive->motor_torque_nm()), 0.1, 0.005);
  EXPECT_LT(std::fabs(m.axis->data().ActualSpeed), 2900.0);  // not yet at speed: the limit holds it back
  m.torque.Enable = false;
  m.run(2);
  EXPECT_FALSE(m.torque.InLimitation);
  EXPECT_FALSE(m.status(StatusWordBit::kInLimitation));
}

}  // namespace
