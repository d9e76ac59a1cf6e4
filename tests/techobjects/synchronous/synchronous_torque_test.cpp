// Telegram 750 on TO_SynchronousAxis (spec 03 §4.18.1/§4.18.2 "Applies to: synchronous axis"; spec 02 §7.5
// "PA, SyA"): a gearing follower on the simulated drive (telegram 3 + 750) takes MC_TorqueAdditive and
// MC_TorqueRange, and its torque precontrol follows the acceleration of its synchronous setpoint.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gearing_fixture.hpp"
#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_torque_additive.hpp"
#include "tomc/instructions/mc_torque_range.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace {

using namespace tomc;
using techobjects::PositioningAxis;
using techobjects::SynchronousAxis;

// Leader: a virtual axis; follower: the default linear axis (10 mm/rev, 79 kg, motor 1e-4 kg·m²) on a drive.
// spec 03 §4.18.1, §4.18.2; spec 02 §7.5.
TEST(SynchronousTorqueData, GearingFollowerPrecontrolAndTorqueJobs) {
  constexpr double kPi = std::numbers::pi;
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig device;
  device.drive_telegram = 3;
  device.supplementary_telegram = 750;
  auto& io =
      runtime.add_device(std::make_unique<drives::SimulatedDrive>(device, tomc::testing::linear_drive()));
  auto leader_owned = std::make_unique<PositioningAxis>("L", nullptr, tomc::testing::virtual_linear());
  PositioningAxis* leader = leader_owned.get();
  auto follower_data = tomc::testing::linear_axis_data();
  follower_data.TorquePreControl.Mode = 1;
  auto& follower =
      runtime.emplace<SynchronousAxis>("F", &io, follower_data,
                                       std::vector<techobjects::LeadingValueInterconnection>{
                                           {leader, leader, techobjects::LeadingValueCoupling::kSetpoint}});
  runtime.add_technology_object(std::move(leader_owned));
  instructions::MC_Power<PositioningAxis> power_l;
  instructions::MC_Power<SynchronousAxis> power_f;
  instructions::MC_MoveVelocity<PositioningAxis> move_l;
  instructions::MC_GearIn<SynchronousAxis> gear;
  instructions::MC_TorqueAdditive<SynchronousAxis> additive;
  instructions::MC_TorqueRange<SynchronousAxis> range;
  gear.Master = leader;
  runtime.set_user_program([&](techobjects::Runtime&) {
    power_l(*leader);
    power_f(follower);
    move_l(*leader);
    gear(follower);
    additive(follower);
    range(follower);
  });
  runtime.start();
  auto run = [&](int n) {
    for (int i = 0; i < n; ++i)
      runtime.step();
  };
  power_l.Enable = power_f.Enable = true;
  for (int i = 0; i < 200 && !power_f.Status; ++i)
    run(1);
  ASSERT_TRUE(power_f.Status);
  gear.RatioNumerator = 1;
  gear.RatioDenominator = 2;
  gear.Execute = true;
  run(3);
  ASSERT_TRUE(gear.InGear);
  // The leader accelerates at 1000 mm/s²; the follower (1:2) at 500 mm/s²: T = J_m·2π·a/h + m·a·h/(2π).
  move_l.Velocity = 100.0;
  move_l.Acceleration = 1000.0;
  move_l.Execute = true;
  run(30);
  const double a = 0.5;  // m/s²
  const double expected = 1.0e-4 * 2.0 * kPi * a / 0.010 + 79.0 * a * 0.010 / (2.0 * kPi);
  EXPECT_NEAR(follower.data().StatusTorqueData.TotalTorqueAdditive, expected, 1e-9);
  const auto& sent = follower.drive()->supplementary_setpoint();
  EXPECT_EQ(sent.M_ADD1, telegrams::torque_to_n2(expected, 4.0));
  additive.Enable = true;
  additive.Value = 0.5;
  range.Enable = true;
  range.UpperLimit = 2.0;
  range.LowerLimit = -1.0;
  run(2);
  EXPECT_TRUE(additive.Busy);
  EXPECT_TRUE(range.Busy);
  EXPECT_EQ(sent.M_ADD1, telegrams::torque_to_n2(expected + 0.5, 4.0));
  EXPECT_EQ(sent.M_LIMIT_POS, 0x2000);
  EXPECT_EQ(sent.M_LIMIT_NEG, static_cast<std::int16_t>(-0x1000));
  EXPECT_TRUE(gear.InGear) << "neither job interrupts the synchronous operation (spec 03 §4.18 priority)";
}

}  // namespace
