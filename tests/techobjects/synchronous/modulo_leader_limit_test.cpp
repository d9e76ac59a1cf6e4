// The velocity limit of modulo axes (spec 01 §8.6, seed 004 §6.7.5, spec 07 §1.4, spec 01 §12 scenario 33):
// Modulo.Length 360°, T_servo 2 ms. Not a possible leading value: above 360°/2 ms = 180,000 °/s alarm 412 and
// the axis is disabled. A possible leading value of a synchronous axis: limited to 360°/(2·2 ms) = 90,000
// °/s, warning 501 while the limit acts, no 412.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "gearing_fixture.hpp"

namespace {

using namespace tomc;
using techobjects::PositioningAxis;
using techobjects::SynchronousAxis;

struct ModuloMachine {
  explicit ModuloMachine(bool leading_value) : runtime(techobjects::RuntimeConfig{0.002, 1, 1}) {
    auto d = tomc::testing::virtual_rotary_modulo();
    d.DynamicLimits.MaxVelocity = d.DynamicLimits.Velocity = 250000.0;
    d.DynamicLimits.MaxAcceleration = d.DynamicLimits.MaxDeceleration = 1.0e8;
    d.DynamicDefaults.EmergencyDeceleration = 1.0e8;
    auto owned = std::make_unique<PositioningAxis>("L", nullptr, d);
    leader = owned.get();
    if (leading_value) {
      follower = &runtime.emplace<SynchronousAxis>(
          "F", nullptr, tomc::testing::virtual_linear(),
          std::vector<techobjects::LeadingValueInterconnection>{
              {leader, leader, techobjects::LeadingValueCoupling::kSetpoint}});
    }
    runtime.add_technology_object(std::move(owned));
    runtime.set_user_program([this](techobjects::Runtime&) {
      power(*leader);
      move(*leader);
      relative(*leader);
    });
    runtime.start();
    power.Enable = true;
    run(3);
  }
  void run(int n) {
    for (int i = 0; i < n; ++i)
      runtime.step();
  }
  bool pending(std::uint32_t number) const {
    const auto a = leader->alarms().alarms();
    return std::any_of(a.begin(), a.end(), [&](const auto& p) { return p.number == number; });
  }
  techobjects::Runtime runtime;
  PositioningAxis* leader = nullptr;
  SynchronousAxis* follower = nullptr;
  instructions::MC_Power<PositioningAxis> power;
  instructions::MC_MoveVelocity<PositioningAxis> move;
  instructions::MC_MoveRelative<PositioningAxis> relative;
};

// spec 01 §8.6 (not a possible leading value: alarm 412 above one modulo length per servo cycle).
TEST(ModuloVelocityLimit, NotALeadingValue412AboveOneLengthPerServoCycle) {
  ModuloMachine m(false);
  ASSERT_TRUE(m.power.Status);
  m.move.Velocity = 170000.0;  // below 180,000 °/s: allowed
  m.move.Acceleration = 1.0e8;
  m.move.Execute = true;
  m.run(20);
  EXPECT_NEAR(m.leader->data().Velocity, 170000.0, 1e-6);
  EXPECT_FALSE(m.pending(techobjects::kAlarmModuloTooFast));
  m.move.Execute = false;
  m.run(1);
  m.move.Velocity = 190000.0;
  m.move.Execute = true;
  m.run(20);
  EXPECT_TRUE(m.pending(techobjects::kAlarmModuloTooFast));
  EXPECT_FALSE(m.power.Status) << "alarm 412 disables the axis";
}

// spec 01 §8.6, spec 07 §1.4 (a possible leading value: limited to half of it, warning 501).
TEST(ModuloVelocityLimit, PossibleLeadingValueLimitedWith501) {
  ModuloMachine m(true);
  ASSERT_TRUE(m.power.Status);
  m.move.Velocity = 190000.0;
  m.move.Acceleration = 1.0e8;
  m.move.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.pending(techobjects::kAlarmDynamicsLimitedVelocity)) << "501 when the job starts limited";
  m.run(20);
  EXPECT_TRUE(m.move.InVelocity);
  EXPECT_NEAR(m.leader->data().Velocity, 90000.0, 1e-6);
  EXPECT_FALSE(m.pending(techobjects::kAlarmModuloTooFast));
  EXPECT_TRUE(m.power.Status);
  // Below the limit: no warning.
  ModuloMachine slow(true);
  slow.move.Velocity = 80000.0;
  slow.move.Acceleration = 1.0e8;
  slow.move.Execute = true;
  slow.run(20);
  EXPECT_NEAR(slow.leader->data().Velocity, 80000.0, 1e-6);
  EXPECT_FALSE(slow.pending(techobjects::kAlarmDynamicsLimitedVelocity));
  // A positioning job asking for more is limited too (v_eff = min(v, limit), spec 01 §8.5).
  slow.move.Execute = false;
  slow.relative.Distance = 36000.0;  // 100 turns: 0.4 s at the limit
  slow.relative.Velocity = 200000.0;
  slow.relative.Acceleration = slow.relative.Deceleration = 1.0e8;
  slow.relative.Execute = true;
  slow.run(1);
  EXPECT_TRUE(slow.pending(techobjects::kAlarmDynamicsLimitedVelocity));
  double fastest = 0.0;
  for (int k = 0; k < 50; ++k) {
    slow.run(1);
    fastest = std::max(fastest, std::fabs(slow.leader->data().Velocity));
  }
  EXPECT_LE(fastest, 90000.0 + 1e-6);
  EXPECT_GT(fastest, 80000.0);
}

}  // namespace
