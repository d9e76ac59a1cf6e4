// Superimposed motion with synchronous operation: spec 07 §8 GI-11 (on the follower and on the leader, seed
// 004 §6.7.10.1) and spec 03 §8 T55 (§9.19.2 footnote 6: MC_GearInVelocity and a superimposed job).
#include <gtest/gtest.h>

#include "gearing_fixture.hpp"
#include "tomc/instructions/mc_move_superimposed.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using tomc::testing::GearingMachine;
namespace eid = techobjects::error_id;

// spec 07 §8 GI-11: 2/1 locked at rest; MoveSuperimposed(10) on F, later MoveSuperimposed(5) on L: GearIn
// stays InGear; L ends at 5 and F at 2·5 + 10 = 20.
TEST(SuperimposedFollower, GI11OnFollowerAndLeader) {
  GearingMachine m;
  instructions::MC_MoveSuperimposed<techobjects::SynchronousAxis> on_f;
  instructions::MC_MoveSuperimposed<techobjects::PositioningAxis> on_l;
  m.user = [&] {
    on_f(*m.F);
    on_l(*m.leader_axis);
  };
  m.gear.RatioNumerator = 2;
  m.gear.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear.InGear);
  on_f.Distance = 10.0;
  on_f.Execute = true;
  ASSERT_GT(m.run_until([&] { return on_f.Done || on_f.Error; }, 2000), 0);
  EXPECT_TRUE(on_f.Done) << on_f.ErrorID;
  EXPECT_TRUE(m.gear.InGear);
  on_l.Distance = 5.0;
  on_l.Execute = true;
  ASSERT_GT(m.run_until([&] { return on_l.Done || on_l.Error; }, 2000), 0);
  EXPECT_TRUE(on_l.Done) << on_l.ErrorID;
  m.run(2);  // the follower follows its leader's last setpoint one cycle later at most
  EXPECT_TRUE(m.gear.InGear);
  EXPECT_TRUE(m.gear.Busy);
  EXPECT_NEAR(m.l().Position, 5.0, 1e-9);
  EXPECT_NEAR(m.f().Position, 20.0, 1e-9);
  // While the gearing runs the follower's superimposed distance stays (spec 01 §8.14: reset when base and
  // superimposed motions are finished).
  EXPECT_NEAR(m.f().StatusPositioning.SuperimposedDistance, 10.0, 1e-9);
}

// T55 (§9.19.2 footnote 6): with MC_GearInVelocity active a superimposed job is accepted when the follower is
// position-controlled (the gearing continues) and rejected when it is not.
TEST(SuperimposedFollower, T55GearInVelocityFootnote6) {
  for (const bool position_controlled : {true, false}) {
    SCOPED_TRACE(position_controlled);
    GearingMachine m;
    instructions::MC_MoveSuperimposed<techobjects::SynchronousAxis> on_f;
    m.user = [&] { on_f(*m.F); };
    m.move_L.Velocity = 100.0;
    m.move_L.Acceleration = 10000.0;
    m.move_L.Execute = true;
    m.run(20);
    m.gear_velocity.RatioNumerator = 1;
    m.gear_velocity.Acceleration = 1000.0;
    m.gear_velocity.PositionControlled = position_controlled;
    m.gear_velocity.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.gear_velocity.InSync; }, 1000), 0);
    on_f.Distance = 2.0;
    on_f.Execute = true;
    m.run(2);
    if (position_controlled) {
      EXPECT_TRUE(on_f.Busy || on_f.Done);
      EXPECT_FALSE(on_f.Error);
      EXPECT_TRUE(m.gear_velocity.InSync);
    } else {
      EXPECT_TRUE(on_f.Error);
      // The footnote's "N": superimposed motion needs position control (spec 03 §4.10), checked first.
      EXPECT_EQ(on_f.ErrorID, eid::kNotPositionControlled);
      EXPECT_TRUE(m.gear_velocity.InSync);
    }
  }
}

}  // namespace
