// Telegram 750 on TO_SpeedAxis (spec 03 §4.18.1/§4.18.2 "Applies to: speed axis"): MC_TorqueAdditive and
// MC_TorqueRange, the exclusion with MC_TorqueLimiting (telegram 102 + 750), StatusTorqueData's three members
// (spec 04 §4.7, S column); the speed axis has no torque precontrol (spec 02 §7.5: PA, SY).
#include <gtest/gtest.h>

#include "speed_axis_fixture.hpp"
#include "tomc/instructions/mc_torque_additive.hpp"
#include "tomc/instructions/mc_torque_limiting.hpp"
#include "tomc/instructions/mc_torque_range.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace {

using namespace tomc;
using techobjects::SpeedAxis;
namespace eid = techobjects::error_id;

struct TorqueDataSpeedAxis : tomc::testing::SpeedAxisMachine {
  explicit TorqueDataSpeedAxis(std::uint16_t telegram = 102, std::uint16_t supplementary = 750)
      : SpeedAxisMachine(telegram, {}, {}, true, supplementary) {
    user = [this] {
      additive(*axis);
      range(*axis);
      limiting(*axis);
    };
  }
  const telegrams::SetpointSignals& sent() const { return axis->drive()->supplementary_setpoint(); }
  instructions::MC_TorqueAdditive<SpeedAxis> additive;
  instructions::MC_TorqueRange<SpeedAxis> range;
  instructions::MC_TorqueLimiting<SpeedAxis> limiting;
};

// Reference torque 4 Nm (data block and simulated drive): +1 Nm = 0x1000, limits +0.125/−0.0625 Nm =
// 0x0200/0xFF00. A MoveVelocity at MaxAcceleration 100 1/s² (≈ 0.19 Nm for motor and load) then runs at the
// upper limit; ActualTorque shows it from M_ACT.
TEST(SpeedAxisTorqueData, AdditiveAndRangeOnTelegram750) {
  TorqueDataSpeedAxis m;
  ASSERT_GT(m.enable(), 0);
  m.additive.Enable = true;
  m.additive.Value = 1.0;
  m.range.Enable = true;
  m.range.UpperLimit = 0.125;
  m.range.LowerLimit = -0.0625;
  m.run(1);
  EXPECT_TRUE(m.additive.Busy);
  EXPECT_TRUE(m.range.Busy);
  m.run(1);
  EXPECT_EQ(m.sent().M_ADD1, 0x1000);
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x0200);
  EXPECT_EQ(m.sent().M_LIMIT_NEG, static_cast<std::int16_t>(-0x0100));
  EXPECT_EQ(m.axis->data().StatusTorqueData.CommandAdditiveTorqueActive, 1);
  EXPECT_EQ(m.axis->data().StatusTorqueData.CommandTorqueRangeActive, 1);
  m.additive.Enable = false;
  m.move.Velocity = 3000.0;
  m.move.Acceleration = 100.0;
  m.move.Execute = true;
  m.run(150);  // MaxJerk 1000 1/s³: the full acceleration after 100 ms
  EXPECT_DOUBLE_EQ(m.drive->motor_torque_nm(), 0.125);
  EXPECT_DOUBLE_EQ(m.axis->data().StatusTorqueData.ActualTorque, 0.125);
  EXPECT_EQ(m.sent().M_ADD1, 0);
  EXPECT_EQ(m.axis->data().StatusTorqueData.CommandAdditiveTorqueActive, 0);
  // While MC_TorqueRange limits, MC_TorqueLimiting is rejected (spec 03 §4.18.3 priority).
  m.limiting.Enable = true;
  m.run(1);
  EXPECT_EQ(m.limiting.ErrorID, eid::kTorqueLimitingExclusion);
  m.limiting.Enable = false;
  m.range.Enable = false;
  m.run(2);
  EXPECT_EQ(m.sent().M_LIMIT_POS, 0x4000);
  EXPECT_EQ(m.axis->data().StatusTorqueData.CommandTorqueRangeActive, 0);
  m.limiting.Enable = true;
  m.run(1);
  ASSERT_TRUE(m.limiting.Busy);
  m.range.Enable = true;
  m.run(1);
  EXPECT_EQ(m.range.ErrorID, eid::kTorqueLimitingExclusion);
}

// Without telegram 750 both are rejected (spec 01 §12 scenario 36); MC_TorqueAdditive needs an enabled axis.
TEST(SpeedAxisTorqueData, Rejections) {
  TorqueDataSpeedAxis without(2, 0);
  ASSERT_GT(without.enable(), 0);
  without.additive.Enable = true;
  without.range.Enable = true;
  without.run(1);
  EXPECT_EQ(without.additive.ErrorID, eid::kNoTorqueData);
  EXPECT_EQ(without.range.ErrorID, eid::kNoTorqueData);
  TorqueDataSpeedAxis disabled;
  disabled.additive.Enable = true;
  disabled.run(1);
  EXPECT_EQ(disabled.additive.ErrorID, eid::kAxisNotEnabled);
}

}  // namespace
