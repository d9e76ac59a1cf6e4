// MC_SynchronizedMotionSimulation on TO_SynchronousAxis against spec 07 §4.4 and §8 SIM-1, with the ErrorIDs
// 16#8076 (a new synchronous job while simulated, spec 07 §1.10), 16#8075 / 16#80A9 (no synchronous
// operation / not Synchronous) and tomc's 16#8152 (leader or follower moving at the start, decision C18).
// Set-up of §8 (gearing_fixture.hpp): cycle 1 ms, leader L and follower F virtual, linear mm, F homed at 0.
#include <gtest/gtest.h>

#include <cmath>

#include "gearing_fixture.hpp"
#include "tomc/instructions/mc_leading_value_additive.hpp"
#include "tomc/instructions/mc_move_superimposed.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/instructions/mc_synchronized_motion_simulation.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::StatusSynchronizedMotionBit;
using techobjects::StatusWordBit;
using techobjects::SynchronousAxis;
using tomc::testing::GearingMachine;
namespace eid = techobjects::error_id;

struct SimulationMachine : GearingMachine {
  SimulationMachine() {
    user = [this] {
      simulation(*F);
      reset_F(*F);
      superimposed_F(*F);
      additive(*F);
    };
  }
  // MC_GearIn 1/1 at rest: InGear at once (GI-1), then the simulation's rising edge.
  void geared_and_simulated() {
    gear.Execute = true;
    run(2);
    ASSERT_TRUE(gear.InGear);
    simulation.Enable = true;
    run(1);
    ASSERT_TRUE(simulation.InSimulation) << simulation.ErrorID;
    run(1);  // the status of the next MC_Interpolator
  }
  void move_leader(double distance) {
    move_rel_L.Execute = false;
    run(1);
    move_rel_L.Distance = distance;
    move_rel_L.Velocity = 50.0;
    move_rel_L.Acceleration = move_rel_L.Deceleration = 1000.0;
    move_rel_L.Execute = true;
    ASSERT_GT(run_until([&] { return move_rel_L.Done; }, 2000), 0);
  }
  void power_follower(bool on) {
    power_F.Enable = on;
    run(on ? 3 : 2);
  }
  bool synchronous() const { return techobjects::test(f().StatusWord, StatusWordBit::kSynchronous); }
  bool x3() const {
    return (F->synchronized_motion().StatusWord >>
            static_cast<unsigned>(StatusSynchronizedMotionBit::kInSimulation)) &
           1u;
  }
  double function_following() const { return F->synchronized_motion().FunctionFollowingValue.Position; }

  instructions::MC_SynchronizedMotionSimulation<SynchronousAxis> simulation;
  instructions::MC_Reset<SynchronousAxis> reset_F;
  instructions::MC_MoveSuperimposed<SynchronousAxis> superimposed_F;
  instructions::MC_LeadingValueAdditive<SynchronousAxis> additive;
};

// SIM-1 (spec 07 §8, §4.4): GearIn 1/1 InGear, L at rest; simulation on: InSimulation, X3, InGear stays
// while StatusWord.X22 goes FALSE. F disabled, L +10: the synchronous operation goes on (its following value
// 10) while F stays at 0; a new MC_GearIn -> 16#8076. F enabled and moved to 10 with MC_MoveAbsolute,
// Enable FALSE: F follows L at once, L +5 -> F 15 on the gear line, no re-synchronization.
TEST(SynchronizedMotionSimulation, SIM1FollowerDisabledLeaderMovesThenBackOnTheGearLine) {
  SimulationMachine m;
  m.geared_and_simulated();
  EXPECT_TRUE(m.simulation.Busy);
  EXPECT_TRUE(m.x3());
  EXPECT_FALSE(m.synchronous());
  EXPECT_TRUE(m.gear.InGear);
  EXPECT_TRUE(m.gear.Busy);
  m.power_follower(false);
  EXPECT_TRUE(m.gear.InGear);  // disabling does not end a simulated synchronous operation
  m.move_leader(10.0);
  EXPECT_NEAR(m.l().Position, 10.0, 1e-9);
  EXPECT_NEAR(m.function_following(), 10.0, 1e-9);
  EXPECT_NEAR(m.f().Position, 0.0, 1e-9);
  EXPECT_TRUE(m.gear.InGear);
  EXPECT_FALSE(m.synchronous());
  EXPECT_TRUE(m.simulation.InSimulation);
  m.gear2.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.gear2.Error);
  EXPECT_EQ(m.gear2.ErrorID, eid::kSynchronousOperationSimulated);  // 16#8076
  m.gear2.Execute = false;
  // Enable FALSE while F is disabled: the end needs an enabled follower; every call tries again.
  m.simulation.Enable = false;
  m.run(2);
  EXPECT_TRUE(m.simulation.InSimulation);
  EXPECT_TRUE(m.simulation.Error);
  EXPECT_EQ(m.simulation.ErrorID, eid::kAxisNotEnabled);
  m.simulation.Enable = true;  // TRUE again before the end could happen: the simulation goes on
  m.run(1);
  EXPECT_TRUE(m.simulation.InSimulation);
  EXPECT_FALSE(m.simulation.Error);
  m.power_follower(true);
  m.move_abs_F.Position = 10.0;
  m.move_abs_F.Velocity = 50.0;
  m.move_abs_F.Acceleration = m.move_abs_F.Deceleration = 1000.0;
  m.move_abs_F.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_abs_F.Done; }, 2000), 0);
  EXPECT_NEAR(m.f().Position, 10.0, 1e-9);
  EXPECT_TRUE(m.gear.InGear);  // a single-axis job moved the follower and aborted nothing synchronous
  m.simulation.Enable = false;
  m.run(1);
  EXPECT_FALSE(m.simulation.InSimulation);
  EXPECT_FALSE(m.simulation.Busy);
  EXPECT_FALSE(m.simulation.Error);
  m.run(1);
  EXPECT_FALSE(m.x3());
  EXPECT_TRUE(m.synchronous());
  EXPECT_NEAR(m.f().Position, 10.0, 1e-9);  // no step: F was where the synchronous setpoint is
  m.move_leader(5.0);
  EXPECT_NEAR(m.f().Position, 15.0, 1e-9);
  EXPECT_NEAR(m.f().Velocity, 0.0, 1e-9);
  EXPECT_TRUE(m.gear.InGear);
}

// Spec 07 §4.4: MC_Stop "does not interrupt a synchronous operation in simulation" (seed 004 L10064); the
// follower brakes (here: stands) and the gearing goes on. While MC_Stop holds the axis the end is refused
// (§9.19.1 C6 "N" for the taking-over gearing, 16#8101), after it the synchronous setpoint takes effect at
// once: a step of 4, the leader's travel under simulation (the user's procedure would have moved F first).
TEST(SynchronizedMotionSimulation, StopDoesNotInterruptAndTheEndTakesTheSynchronousSetpointAtOnce) {
  SimulationMachine m;
  m.geared_and_simulated();
  m.stop_F.Execute = true;
  m.run(5);
  EXPECT_TRUE(m.stop_F.Done);
  EXPECT_TRUE(m.gear.InGear);
  EXPECT_FALSE(m.gear.CommandAborted);
  m.move_leader(4.0);
  EXPECT_NEAR(m.function_following(), 4.0, 1e-9);
  m.simulation.Enable = false;
  m.run(1);
  EXPECT_TRUE(m.simulation.InSimulation);
  EXPECT_EQ(m.simulation.ErrorID, eid::kRejectedByRunningJob);
  m.stop_F.Execute = false;
  m.run(2);
  EXPECT_FALSE(m.simulation.InSimulation);
  EXPECT_FALSE(m.simulation.Error);
  EXPECT_NEAR(m.f().Position, 4.0, 1e-9);
  EXPECT_TRUE(m.synchronous());
}

// Seed 004 §6.7.10.2 (L4411–4415, spec 07 §4.4): superimposed motion on the simulated follower is lost at the
// end: MC_MoveSuperimposed +3 moves F to 3 while L stands; the end puts F on the synchronous setpoint 0 (a
// step of 3, the manual's warning) and ends a still-running superimposed job (§9.19.1 R8 × C7 "A").
TEST(SynchronizedMotionSimulation, SuperimposedMotionIsLostAtTheEnd) {
  SimulationMachine m;
  m.geared_and_simulated();
  m.superimposed_F.Distance = 3.0;
  m.superimposed_F.VelocityDiff = 50.0;
  m.superimposed_F.Acceleration = m.superimposed_F.Deceleration = 1000.0;
  m.superimposed_F.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.superimposed_F.Done; }, 1000), 0);
  EXPECT_NEAR(m.f().Position, 3.0, 1e-9);
  EXPECT_TRUE(m.gear.InGear);
  m.superimposed_F.Execute = false;
  m.run(1);
  m.superimposed_F.Distance = 1.0;
  m.superimposed_F.Execute = true;
  m.run(3);
  EXPECT_TRUE(m.superimposed_F.Busy);
  m.simulation.Enable = false;
  m.run(2);
  EXPECT_FALSE(m.simulation.InSimulation);
  EXPECT_TRUE(m.superimposed_F.CommandAborted);
  EXPECT_NEAR(m.f().Position, 0.0, 1e-9);
  EXPECT_TRUE(m.synchronous());
}

// Spec 07 §4.4 requirements: Synchronous (16#8075 without gearing), the leader at standstill (tomc 16#8152);
// a TO restart ends the simulation and aborts the synchronous operation; MC_LeadingValueAdditive may start
// on a disabled follower while simulated (§4.3 requirement) and moves the simulated following value.
TEST(SynchronizedMotionSimulation, RequirementsRestartAndAdditiveWhileDisabled) {
  SimulationMachine m;
  m.simulation.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.simulation.Error);
  EXPECT_EQ(m.simulation.ErrorID, eid::kNoSynchronousOperation);  // 16#8075
  m.simulation.Enable = false;
  m.run(1);
  EXPECT_FALSE(m.simulation.Error);
  m.gear.Execute = true;
  m.move_L.Velocity = 20.0;
  m.move_L.Acceleration = m.move_L.Deceleration = 10000.0;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_L.InVelocity && m.gear.InGear; }, 2000), 0);
  m.simulation.Enable = true;
  m.run(1);
  EXPECT_EQ(m.simulation.ErrorID, eid::kSimulationNeedsStandstill);  // 16#8152
  EXPECT_FALSE(m.simulation.InSimulation);
  m.simulation.Enable = false;
  m.halt_F.Execute = false;
  m.move_L.Execute = false;
  m.stop_F.Execute = false;
  m.run(1);
  instructions::MC_Halt<techobjects::PositioningAxis> halt_L;
  halt_L.Deceleration = 10000.0;
  halt_L.Execute = true;
  halt_L(*m.leader_axis);
  ASSERT_GT(m.run_until(
                [&] {
                  halt_L(*m.leader_axis);
                  return halt_L.Done;
                },
                100),
            0);
  const double at = m.l().Position;
  m.simulation.Enable = true;
  m.run(1);
  ASSERT_TRUE(m.simulation.InSimulation) << m.simulation.ErrorID;
  m.power_follower(false);
  const double before = m.function_following();
  m.additive.Enable = true;
  m.additive.Position = 2.5;
  m.run(1);
  EXPECT_TRUE(m.additive.Busy);
  EXPECT_FALSE(m.additive.Error);
  m.run(1);                                                 // taken by the next MC_Interpolator
  EXPECT_NEAR(m.function_following(), before + 2.5, 1e-9);  // ratio 1: the leading value + 2.5
  EXPECT_NEAR(m.F->synchronized_motion().EffectiveLeadingValue.Position, at + 2.5, 1e-9);
  m.reset_F.Restart = true;
  m.reset_F.Execute = true;
  m.run(3);
  EXPECT_TRUE(m.reset_F.Done);
  EXPECT_FALSE(m.simulation.InSimulation);
  m.run(1);
  EXPECT_FALSE(m.x3());
  EXPECT_FALSE(m.gear.Busy);
  EXPECT_TRUE(m.gear.CommandAborted);
}

}  // namespace
