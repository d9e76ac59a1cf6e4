// Gearing on TO_SynchronousAxis, the scenarios of spec 07 §8 (GI-*, GP-*, GV-*, EX-1) with their numbers.
// Set-up in gearing_fixture.hpp. "At t" = the cycle the condition first holds, ±1 cycle as §8 allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gearing_fixture.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::StatusWordBit;
using tomc::testing::GearingMachine;
using tomc::testing::virtual_linear;
using tomc::testing::virtual_rotary_modulo;
namespace eid = techobjects::error_id;

bool bit(const techobjects::PositioningAxisData& d, StatusWordBit b) {
  return techobjects::test(d.StatusWord, b);
}

// The leader at constant velocity v (MC_MoveVelocity, acceleration 10000), returns when it is there.
void leader_at(GearingMachine& m, double v) {
  m.move_L.Velocity = v;
  m.move_L.Acceleration = 10000.0;
  m.move_L.Deceleration = 10000.0;
  m.move_L.Execute = false;
  m.run(1);
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_L.InVelocity; }, 2000), 0);
}

// spec 07 §8 GI-1: both at rest: InGear at once, X22, FunctionState 1, ActualMaster = L.
TEST(Gearing, GI1StandstillCoupling) {
  GearingMachine m;
  m.gear.RatioNumerator = 2;
  m.gear.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.gear.Busy);
  m.run(1);
  EXPECT_TRUE(m.gear.InGear);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronous));
  EXPECT_EQ(m.F->synchronized_motion().FunctionState, 1);
  EXPECT_EQ(m.F->synchronized_motion().ActualMaster, 1);
  EXPECT_EQ(m.F->read("StatusSynchronizedMotion.FunctionState"), 1.0);
}

// spec 07 §8 GI-2: locked 2:1, L moves +10 at 50: F ends at 20.000000 and F.Velocity = 2·L.Velocity every
// cycle.
TEST(Gearing, GI2LockedRatio) {
  GearingMachine m;
  m.gear.RatioNumerator = 2;
  m.gear.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear.InGear);
  m.move_rel_L.Distance = 10.0;
  m.move_rel_L.Velocity = 50.0;
  m.move_rel_L.Execute = true;
  bool every_cycle = true;
  ASSERT_GT(m.run_until(
                [&] {
                  every_cycle = every_cycle && std::fabs(m.f().Velocity - 2.0 * m.l().Velocity) < 1e-9;
                  return m.move_rel_L.Done;
                },
                2000),
            0);
  EXPECT_TRUE(every_cycle);
  EXPECT_NEAR(m.f().Position, 20.0, 1e-9);
  EXPECT_TRUE(m.gear.InGear);
}

// spec 07 §8 GI-3: rotary modulo leader and follower locked −3/1 at 0/0; L +10° -> F −30° = 330° (modulo).
TEST(Gearing, GI3NegativeRatioModulo) {
  GearingMachine m(virtual_rotary_modulo(), virtual_rotary_modulo());
  m.gear.RatioNumerator = -3;
  m.gear.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear.InGear);
  m.move_rel_L.Distance = 10.0;
  m.move_rel_L.Velocity = 50.0;
  m.move_rel_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_rel_L.Done; }, 2000), 0);
  EXPECT_NEAR(m.f().Position, 330.0, 1e-9);
  EXPECT_EQ(m.f().ModuloCycle, -1);
}

// spec 07 §8 GI-4: L at 100, F at rest, GearIn 2/1 with Acceleration 1000, Jerk 0: X21 from t0, InGear at t0
// + 0.200 s, F travelled 20.0 ± 0.2 during synchronization; afterwards F.Velocity = 200 and ΔF = 2·ΔL
// exactly.
TEST(Gearing, GI4SynchronizeToAMovingLeader) {
  GearingMachine m;
  leader_at(m, 100.0);
  m.gear.RatioNumerator = 2;
  m.gear.Acceleration = 1000.0;
  m.gear.Jerk = 0.0;
  m.gear.Execute = true;
  const double f0 = m.f().Position;
  m.run(1);  // t0: the edge
  m.run(1);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronizing));
  const int cycles = m.run_until([&] { return m.gear.InGear; }, 1000);
  EXPECT_NEAR(cycles + 1, 200, 1);
  EXPECT_NEAR(m.f().Position - f0, 20.0, 0.2);
  EXPECT_FALSE(bit(m.f(), StatusWordBit::kSynchronizing));
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronous));
  const double fs = m.f().Position;
  const double ls = m.l().Position;
  m.run(300);
  EXPECT_NEAR(m.f().Velocity, 200.0, 1e-9);
  EXPECT_NEAR(m.f().Position - fs, 2.0 * (m.l().Position - ls), 1e-9);
}

// spec 07 §8 GI-5: F in MoveVelocity(300), L at 100; GearIn 1/1 with Deceleration 2000: the MoveVelocity is
// aborted in that cycle (R8 x C3 = A); F decelerates at 2000 and is InGear after 0.100 s.
TEST(Gearing, GI5SlowDownSynchronization) {
  GearingMachine m;
  leader_at(m, 100.0);
  m.move_F.Velocity = 300.0;
  m.move_F.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_F.InVelocity; }, 1000), 0);
  m.gear.Deceleration = 2000.0;
  m.gear.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_F.CommandAborted || !m.move_F.Busy);
  m.run(1);
  EXPECT_TRUE(m.move_F.CommandAborted);
  const int cycles = m.run_until([&] { return m.gear.InGear; }, 1000);
  EXPECT_NEAR(cycles + 2, 100, 1);
}

// spec 07 §8 GI-6: RatioNumerator 0 -> 16#8017; RatioDenominator 0 or −5 -> 16#8018; the follower as its
// leader's leader -> 16#8019. A running job is not affected.
TEST(Gearing, GI6ParameterErrors) {
  GearingMachine m;
  m.move_F.Velocity = 10.0;
  m.move_F.Execute = true;
  m.run(5);
  const auto check = [&](std::int32_t n, std::int32_t d, std::uint16_t expected) {
    m.gear.RatioNumerator = n;
    m.gear.RatioDenominator = d;
    m.gear.Execute = true;
    m.run(1);
    EXPECT_TRUE(m.gear.Error);
    EXPECT_EQ(m.gear.ErrorID, expected);
    m.gear.Execute = false;
    m.run(1);
  };
  check(0, 1, eid::kInvalidRatioNumerator);
  check(1, 0, eid::kInvalidRatioDenominator);
  check(1, -5, eid::kInvalidRatioDenominator);
  m.gear.Master = m.F;  // itself
  check(1, 1, eid::kRecursiveLeadingValue);
  EXPECT_TRUE(m.move_F.Busy);
}

// spec 07 §8 GI-7: a leader that is not interconnected: alarm 601, ErrorWord.X14; the job ends with an error
// (O-5: 16#8001), no InGear.
TEST(Gearing, GI7LeaderNotInterconnected) {
  GearingMachine m;
  techobjects::PositioningAxis stranger("Stranger", nullptr, virtual_linear());
  m.gear.Master = &stranger;
  m.gear.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.gear.Error);
  EXPECT_EQ(m.gear.ErrorID, eid::kAbortedByAlarmReaction);
  EXPECT_TRUE(m.F->alarms().pending(techobjects::kAlarmLeadingAxisDefective));
  m.run(1);
  EXPECT_TRUE(techobjects::test(m.f().ErrorWord, techobjects::ErrorWordBit::kSynchronousError));
  EXPECT_FALSE(m.gear.InGear);
}

// spec 07 §8 GI-8: the leader not position-controlled (StartMode 0): alarm 603 on F, F disabled, the job ends
// with Error.
TEST(Gearing, GI8LeaderNotPositionControlled) {
  GearingMachine m;
  m.power_L.Enable = false;
  m.run(5);
  m.power_L.StartMode = 0;
  m.power_L.Enable = true;
  m.run(5);
  ASSERT_TRUE(bit(m.l(), StatusWordBit::kNonPositionControlled));
  m.gear.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.gear.Error);
  EXPECT_TRUE(m.F->alarms().pending(techobjects::kAlarmLeaderNotPositionControlled));
  m.run(2);
  EXPECT_FALSE(m.power_F.Status);  // remove enable
}

// spec 07 §8 GI-9: leader switchover: A1 (L) InGear, A2 (L2) starts: A1 CommandAborted, ActualMaster = L2.
TEST(Gearing, GI9LeaderSwitchover) {
  GearingMachine m;
  m.gear.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear.InGear);
  m.gear2.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.gear.CommandAborted);
  EXPECT_TRUE(m.gear2.InGear);
  EXPECT_EQ(m.F->synchronized_motion().ActualMaster, 2);
}

// spec 07 §8 GI-10: F geared at 200 mm/s: a BufferMode-1 MoveAbsolute is rejected (N) and the gearing
// continues; MC_Halt (Deceleration 4000) aborts it: X22 FALSE, FunctionState 0; F stops after 0.05 s and 5.0
// mm.
TEST(Gearing, GI10HaltEndsGearingBufferedRejected) {
  GearingMachine m;
  leader_at(m, 100.0);
  m.gear.RatioNumerator = 2;
  m.gear.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear.InGear; }, 1000), 0);
  m.move_abs_F.BufferMode = 1;
  m.move_abs_F.Position = 0.0;
  m.move_abs_F.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_abs_F.Error);
  EXPECT_EQ(m.move_abs_F.ErrorID, eid::kRejectedByRunningJob);
  EXPECT_TRUE(m.gear.InGear);
  const double p0 = m.f().Position;
  m.halt_F.Deceleration = 4000.0;
  m.halt_F.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.gear.CommandAborted);
  EXPECT_FALSE(bit(m.f(), StatusWordBit::kSynchronous));
  EXPECT_EQ(m.F->synchronized_motion().FunctionState, 0);
  const int cycles = m.run_until([&] { return m.halt_F.Done; }, 1000);
  EXPECT_NEAR(cycles + 2, 50, 2);
  EXPECT_NEAR(m.f().Position - p0, 5.0, 0.25);
}

// spec 07 §8 GI-12: disabling the leader does not end the gearing: F follows its emergency ramp
// offset-exactly; disabling F ends it (CommandAborted).
TEST(Gearing, GI12LeaderDisabledFollowerDisabled) {
  GearingMachine m;
  leader_at(m, 100.0);
  m.gear.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear.InGear; }, 1000), 0);
  const double offset = m.f().Position - m.l().Position;
  m.power_L.Enable = false;  // StopMode 0: emergency ramp
  ASSERT_GT(m.run_until([&] { return m.l().Velocity == 0.0; }, 1000), 0);
  m.run(5);
  EXPECT_TRUE(m.gear.InGear);
  EXPECT_NEAR(m.f().Position - m.l().Position, offset, 1e-9);
  EXPECT_EQ(m.f().Velocity, 0.0);
  m.power_F.Enable = false;
  m.run(3);
  EXPECT_TRUE(m.gear.CommandAborted);
}

// spec 07 §8 GI-13: F.MaxVelocity 150, locked 2/1 with L at 50 (F at 100): L to 100 -> F 200 without
// limitation or alarm 501, StatusSynchronizedMotion.StatusWord.X0 while |F.Velocity| > 150, FALSE again with
// L at 60.
TEST(Gearing, GI13NoLimitsInSynchronousTravel) {
  auto f = virtual_linear();
  f.DynamicLimits.MaxVelocity = 150.0;
  f.DynamicLimits.Velocity = 150.0;
  f.DynamicDefaults.Velocity = 100.0;
  GearingMachine m(virtual_linear(), f);
  leader_at(m, 50.0);
  m.gear.RatioNumerator = 2;
  m.gear.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear.InGear; }, 1000), 0);
  leader_at(m, 100.0);
  m.run(5);
  EXPECT_NEAR(m.f().Velocity, 200.0, 1e-9);
  EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  EXPECT_EQ(m.F->read("StatusSynchronizedMotion.StatusWord.X0"), 1.0);
  leader_at(m, 60.0);
  m.run(2);
  EXPECT_EQ(m.F->read("StatusSynchronizedMotion.StatusWord.X0"), 0.0);
}

// spec 07 §8 GI-14: F.MaxVelocity 150, MaxAcceleration 2000; L at 100; GearIn 2/1 with Acceleration 5000:
// alarm 502, the ramp at 2000; F reaches 150 and stays Synchronizing (no InGear, no 501); L slows to 60
// (target 120): InGear.
TEST(Gearing, GI14LimitsDuringSynchronization) {
  auto f = virtual_linear();
  f.DynamicLimits.MaxVelocity = 150.0;
  f.DynamicLimits.Velocity = 150.0;
  f.DynamicLimits.MaxAcceleration = 2000.0;
  f.DynamicDefaults.Velocity = 100.0;
  f.DynamicDefaults.Acceleration = 1000.0;
  GearingMachine m(virtual_linear(), f);
  leader_at(m, 100.0);
  m.gear.RatioNumerator = 2;
  m.gear.Acceleration = 5000.0;
  m.gear.Execute = true;
  m.run(3);
  EXPECT_TRUE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedAcceleration));
  EXPECT_NEAR(m.f().Acceleration, 2000.0, 1e-9);
  m.run(200);
  EXPECT_NEAR(m.f().Velocity, 150.0, 1e-9);
  EXPECT_FALSE(m.gear.InGear);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronizing));
  EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  leader_at(m, 60.0);
  ASSERT_GT(m.run_until([&] { return m.gear.InGear; }, 1000), 0);
  EXPECT_NEAR(m.f().Velocity, 120.0, 1e-9);
}

// spec 07 §8 GI-15: L modulo 0..360, F linear, locked 1/1 with L at 350, F at 0: L +20 (across 360 -> 0): F =
// 20 (not −340).
TEST(Gearing, GI15ModuloLeaderWrap) {
  GearingMachine m(virtual_rotary_modulo(), virtual_linear());
  m.move_rel_L.Distance = 350.0;
  m.move_rel_L.Velocity = 360.0;
  m.move_rel_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_rel_L.Done; }, 3000), 0);
  m.move_rel_L.Execute = false;
  m.run(1);
  m.gear.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear.InGear);
  const double f0 = m.f().Position;
  m.move_rel_L.Distance = 20.0;
  m.move_rel_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_rel_L.Done; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, 10.0, 1e-9);
  EXPECT_NEAR(m.f().Position - f0, 20.0, 1e-9);
}

// spec 07 §8 GI-17: F's software limit 500 with LimitReachedBehavior 1: as a following axis it stops with
// maximum dynamics (reaction 2) at 533, ErrorWord.X8.
TEST(Gearing, GI17SoftwareLimitOfAFollower) {
  auto f = virtual_linear();
  f.PositionLimits_SW.Active = true;
  f.PositionLimits_SW.MaxPosition = 500.0;
  f.PositionLimits_SW.LimitReachedBehavior = 1;
  GearingMachine m(virtual_linear(), f);
  leader_at(m, 100.0);
  m.gear.Execute = true;
  ASSERT_GT(
      m.run_until([&] { return m.F->alarms().pending(techobjects::kAlarmSoftwareLimitReached); }, 10000), 0);
  EXPECT_EQ(m.f().ErrorDetail.Reaction,
            static_cast<std::int32_t>(techobjects::AlarmReaction::kStopMaxDynamics));
  m.run(200);
  EXPECT_LE(m.f().Position, 500.0 + 1e-6);
  EXPECT_TRUE(techobjects::test(m.f().ErrorWord, techobjects::ErrorWordBit::kSWLimit));
  EXPECT_TRUE(m.gear.Error);
}

// spec 07 §8 GI-18: the leader reverses during synchronization: alarm 608 (stop with maximum dynamics), the
// gearing ends.
TEST(Gearing, GI18ReversalDuringSynchronization) {
  GearingMachine m;
  leader_at(m, 100.0);
  m.gear.RatioNumerator = 2;
  m.gear.Acceleration = 1000.0;
  m.gear.Execute = true;
  m.run(50);
  ASSERT_TRUE(bit(m.f(), StatusWordBit::kSynchronizing));
  m.move_L.Velocity = -100.0;
  m.move_L.Execute = false;
  m.run(1);
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear.Error; }, 200), 0);
  EXPECT_TRUE(m.F->alarms().pending(techobjects::kAlarmSynchronizationError));
  EXPECT_EQ(m.gear.ErrorID, eid::kAbortedByAlarmReaction);
}

// spec 07 §8 GP-1's job: MC_GearInPos 1/1, synchronous at L = 200 with F = 50 after 100 of leading value
// (profile 1).
void start_gp1_gear_in_pos(GearingMachine& m) {
  m.gear_pos.MasterSyncPosition = 200.0;
  m.gear_pos.SlaveSyncPosition = 50.0;
  m.gear_pos.SyncProfileReference = 1;
  m.gear_pos.MasterStartDistance = 100.0;
  m.gear_pos.Execute = true;
  m.run(1);
}

// spec 07 §8 GP-1: MC_GearInPos 1/1, MasterSyncPosition 200, SlaveSyncPosition 50, profile 1,
// MasterStartDistance 100, L at +100 from 0: pending (WaitingFunctionState 2) until L = 100, StartSync / X21
// there, InSync / X22 at L = 200 with F = 50.0; F(L = 150) = 9.375 [IMPL quintic]; afterwards F = 50 + (L −
// 200).
TEST(Gearing, GP1GearInPosOverALeadingValueDistance) {
  GearingMachine m;
  start_gp1_gear_in_pos(m);
  EXPECT_TRUE(m.gear_pos.Busy);
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = 1.0e9;  // at 100 from the first cycle: the leader's position is 0.1 per cycle
  m.move_L.Execute = true;
  m.run(2);
  EXPECT_EQ(m.F->synchronized_motion().WaitingFunctionState, 2);
  EXPECT_FALSE(m.gear_pos.StartSync);
  ASSERT_GT(m.run_until([&] { return m.gear_pos.StartSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, 100.0, 0.2);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronizing));
  ASSERT_GT(m.run_until([&] { return m.l().Position >= 150.0 - 1e-9; }, 3000), 0);
  EXPECT_NEAR(m.f().Position, 9.375, 0.05);
  ASSERT_GT(m.run_until([&] { return m.gear_pos.InSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, 200.0, 0.11);
  EXPECT_NEAR(m.f().Position - (m.l().Position - 150.0), 0.0, 1e-6);
  ASSERT_GT(m.run_until([&] { return m.l().Position >= 250.0 - 1e-9; }, 3000), 0);
  EXPECT_NEAR(m.f().Position, 50.0 + (m.l().Position - 200.0), 1e-6);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronous));
  EXPECT_EQ(m.F->synchronized_motion().FunctionState, 2);
}

// The V10 leading value reversal tolerance (spec 07 §1.6 [OPEN], tomc extension; decision C27) during
// synchronization at its edge: GP-1's MC_GearInPos (profile 1, synchronous at L = 200 after 100 of leading
// value), L moved to 150 (mid-synchronization), back by `back`, then on to 210. Moving back by at most the
// tolerance keeps the synchronization (InSync at L = 200, F = 50 + (L − 200)); 0.001 more is alarm 608 and
// the job ends with 16#8001; tolerance 0: any reversal the leader's velocity shows is (GI-18; 0.1 mm back
// takes 9 cycles at 5,000 mm/s² — a move back that starts and ends within one cycle shows no velocity).
// spec 07 §1.6, §1.10 (alarm 608) and §8 (GI-18); decision C27.
TEST(Gearing, ReversalToleranceDuringSynchronizationAtItsEdge) {
  struct Row {
    float tolerance;
    double back;
    bool alarm;
  };
  for (const Row& r : {Row{0.5F, 0.5, false}, Row{0.5F, 0.501, true}, Row{0.0F, 0.1, true}}) {
    GearingMachine m(virtual_linear(), virtual_linear(), {}, {}, r.tolerance);
    start_gp1_gear_in_pos(m);
    for (const double distance : {150.0, -r.back, 60.0 + r.back}) {
      m.move_rel_L.Distance = distance;
      m.move_rel_L.Execute = false;
      m.run(1);
      m.move_rel_L.Execute = true;
      ASSERT_GT(m.run_until([&] { return m.move_rel_L.Done || m.gear_pos.Error; }, 3000), 0);
      if (m.gear_pos.Error) break;
      if (distance == 150.0) {
        ASSERT_TRUE(m.gear_pos.StartSync && bit(m.f(), StatusWordBit::kSynchronizing));
      }
    }
    EXPECT_EQ(m.F->alarms().pending(techobjects::kAlarmSynchronizationError), r.alarm) << r.tolerance;
    EXPECT_EQ(m.gear_pos.Error, r.alarm) << r.tolerance << " " << r.back;
    if (r.alarm) {  // in the move back, as soon as it went beyond the tolerance
      EXPECT_EQ(m.gear_pos.ErrorID, eid::kAbortedByAlarmReaction);
      EXPECT_LT(m.l().Position, 150.0 - r.tolerance);
      EXPECT_GE(m.l().Position, 150.0 - r.back - 1e-9);
    } else {
      EXPECT_TRUE(m.gear_pos.InSync);
      EXPECT_NEAR(m.l().Position, 210.0, 1e-9);
      EXPECT_NEAR(m.f().Position, 60.0, 1e-6);
    }
  }
}

// spec 07 §8 GP-2: profile 3 (subsequent): MasterSyncPosition 100, SlaveSyncPosition 0, MasterStartDistance
// 50: StartSync at L = 100, InSync at L = 150, then F = L − 100.
TEST(Gearing, GP2SubsequentSynchronization) {
  GearingMachine m;
  m.gear_pos.MasterSyncPosition = 100.0;
  m.gear_pos.SlaveSyncPosition = 0.0;
  m.gear_pos.SyncProfileReference = 3;
  m.gear_pos.MasterStartDistance = 50.0;
  m.gear_pos.Execute = true;
  m.run(1);
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = 1.0e9;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear_pos.StartSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, 100.0, 0.11);
  ASSERT_GT(m.run_until([&] { return m.gear_pos.InSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, 150.0, 0.11);
  ASSERT_GT(m.run_until([&] { return m.l().Position >= 200.0 - 1e-9; }, 3000), 0);
  EXPECT_NEAR(m.f().Position, m.l().Position - 100.0, 1e-6);
}

// spec 07 §8 GP-3: a pending GearInPos lets a running MoveVelocity on F continue; an MC_Halt before the start
// does not abort the pending job (S3 "-"); at the start the Halt is aborted (R10 x C3 = A).
TEST(Gearing, GP3PendingLetsRunningJobsContinue) {
  GearingMachine m;
  m.move_F.Velocity = 20.0;
  m.move_F.Execute = true;
  m.run(5);
  m.gear_pos.MasterSyncPosition = 200.0;
  m.gear_pos.MasterStartDistance = 100.0;
  m.gear_pos.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move_F.Busy);
  EXPECT_TRUE(m.gear_pos.Busy);
  m.halt_F.Deceleration = 10.0;
  m.halt_F.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move_F.CommandAborted);
  EXPECT_TRUE(m.gear_pos.Busy);
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = 1.0e9;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear_pos.StartSync; }, 3000), 0);
  m.run(1);
  EXPECT_TRUE(m.halt_F.CommandAborted);
}

// spec 07 §8 GP-4's sequence: MC_GearInPos (profile 3 over 10 from L = 0) in sync with L at 100 mm/s; MC_Home
// Mode 3 -> 16#80A1 (spec 07 §1.10), the gearing goes on; then MC_GearIn InGear and MC_Home Mode 3 again
// (what that does, the callers check).
void home_during_gear_in_pos_then_during_gear_in(GearingMachine& m) {
  m.gear_pos.MasterSyncPosition = 0.0;
  m.gear_pos.SyncProfileReference = 3;
  m.gear_pos.MasterStartDistance = 10.0;
  m.gear_pos.Execute = true;
  m.run(1);
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = 1.0e9;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear_pos.InSync; }, 3000), 0);
  m.home_F.Mode = 3;
  m.home_F.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.home_F.Error);
  EXPECT_EQ(m.home_F.ErrorID, eid::kHomingDuringGearInPos);
  EXPECT_TRUE(m.gear_pos.InSync);
  m.home_F.Execute = false;
  m.run(1);
  m.gear.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear.InGear; }, 2000), 0);
  m.home_F.Execute = true;
  m.run(2);
}

// spec 07 §8 GP-4: MC_Home Mode 3 during an active GearInPos -> 16#80A1, the gearing continues. During a
// plain GearIn it aborts the gearing — except on a virtual or simulated follower (footnote 1 of §9.19.2), as
// F is here: there the homing is executed at once and the gearing goes on.
TEST(Gearing, GP4HomingAgainstGearing) {
  GearingMachine m;
  home_during_gear_in_pos_then_during_gear_in(m);
  EXPECT_TRUE(m.home_F.Done);
  EXPECT_FALSE(m.gear.CommandAborted);
  EXPECT_TRUE(m.gear.InGear);
}

// spec 07 §8 GP-4 on a real follower (spec 07 §1.10 16#80A1; §9.19.2 row "MC_Home Mode 3, 5", footnote 1 only
// for a virtual or simulated axis): F on a simulated PROFIdrive drive (telegram 3). MC_Home Mode 3 during an
// active MC_GearInPos -> 16#80A1, the gearing goes on; during a plain MC_GearIn it is accepted and aborts the
// gearing (S1 "A"), where GP-4's virtual follower kept it.
TEST(Gearing, GP4HomingAgainstGearingOnADrivenFollower) {
  auto driven = virtual_linear();
  driven.VirtualAxis.Mode = techobjects::kModeOff;
  GearingMachine m(virtual_linear(), driven, {}, [](techobjects::Runtime& r) -> techobjects::DeviceIo* {
    drives::DeviceConfig device;
    device.drive_telegram = 3;
    drives::SimulatedDriveParameters drive;
    drive.load_units_per_revolution = 10.0;
    return &r.add_device(std::make_unique<drives::SimulatedDrive>(device, drive));
  });
  ASSERT_GT(m.run_until([&] { return m.power_F.Status; }, 3000), 0);
  m.home_F.Mode = 0;
  m.home_F.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.home_F.Done; }, 100), 0);
  m.home_F.Execute = false;
  home_during_gear_in_pos_then_during_gear_in(m);
  EXPECT_FALSE(m.home_F.Error) << m.home_F.ErrorID;
  EXPECT_TRUE(m.gear.CommandAborted);  // a real follower: the homing ends the gearing
  EXPECT_FALSE(m.gear.InGear);
}

// spec 07 §8 GP-5: GearInPos 2/1 in sync, L at 100 (F at 200 mm/s); GearOut(SlavePosition 1000, profile 0,
// Deceleration 1000, Jerk 0): WaitingFunctionState 4 until F = 980; StartSyncOut and StatusWord2.X1 at F =
// 980, the gearing CommandAborted in that cycle; FunctionState 4; Done at F = 1000 after 0.200 s with X7.
TEST(Gearing, GP5GearOutByDynamicParameters) {
  GearingMachine m;
  m.gear_pos.RatioNumerator = 2;
  m.gear_pos.MasterSyncPosition = 0.0;
  m.gear_pos.SyncProfileReference = 3;
  m.gear_pos.MasterStartDistance = 10.0;
  m.gear_pos.Execute = true;
  m.run(1);
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = 1.0e9;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear_pos.InSync && m.f().Position >= 500.0; }, 5000), 0);
  m.gear_out.SlavePosition = 1000.0;
  m.gear_out.SyncProfileReference = 0;
  m.gear_out.Deceleration = 1000.0;
  m.gear_out.Jerk = 0.0;
  m.gear_out.Execute = true;
  m.run(2);
  EXPECT_EQ(m.F->synchronized_motion().WaitingFunctionState, 4);
  ASSERT_GT(m.run_until([&] { return m.gear_out.StartSyncOut; }, 5000), 0);
  EXPECT_NEAR(m.f().Position, 980.0, 0.5);
  EXPECT_TRUE(techobjects::test(m.f().StatusWord2, techobjects::StatusWord2Bit::kDesynchronizingCommand));
  EXPECT_TRUE(m.gear_pos.CommandAborted);
  EXPECT_EQ(m.F->synchronized_motion().FunctionState, 4);
  const int cycles = m.run_until([&] { return m.gear_out.Done; }, 1000);
  EXPECT_NEAR(cycles, 200, 3);
  EXPECT_NEAR(m.f().Position, 1000.0, 1e-6);
  m.run(20);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kStandstill));
  EXPECT_EQ(m.F->synchronized_motion().FunctionState, 0);
}

// GearOut profile 1 (spec 07 §2.4, §6.7): the follower stops at SlavePosition over MasterStopDistance of
// leader travel. Ratio 2, L at 100: over 100 units of L the follower covers 2 x 100 / 2 = 100, so
// desynchronization starts at F = 900 and ends 100 / 100 = 1 s (1000 cycles) later at 1000, following the
// leader all the way (the gearing job has ended by then: the blend keeps its leading value).
TEST(Gearing, GP7GearOutOverALeadingValueDistance) {
  GearingMachine m;
  m.gear_pos.RatioNumerator = 2;
  m.gear_pos.MasterSyncPosition = 0.0;
  m.gear_pos.SyncProfileReference = 3;
  m.gear_pos.MasterStartDistance = 10.0;
  m.gear_pos.Execute = true;
  m.run(1);
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = 1.0e9;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear_pos.InSync && m.f().Position >= 500.0; }, 5000), 0);
  m.gear_out.SlavePosition = 1000.0;
  m.gear_out.SyncProfileReference = 1;
  m.gear_out.MasterStopDistance = 100.0;
  m.gear_out.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear_out.StartSyncOut; }, 5000), 0);
  EXPECT_NEAR(m.f().Position, 900.0, 0.5);
  EXPECT_TRUE(m.gear_pos.CommandAborted);
  const double f_start = m.f().Position;
  m.run(500);  // half of the leader distance: the quintic blend is symmetric, half of its travel is done
  EXPECT_GT(m.f().Position, f_start + 40.0);
  EXPECT_GT(m.f().Velocity, 50.0);
  const int cycles = m.run_until([&] { return m.gear_out.Done; }, 1000);
  EXPECT_NEAR(cycles + 500, 1000, 3);
  EXPECT_NEAR(m.f().Position, 1000.0, 1e-6);
  EXPECT_DOUBLE_EQ(m.f().Velocity, 0.0);
  EXPECT_FALSE(m.gear_out.Error);
}

// spec 07 §2.4, §6.7, decisions Y11/Y13: a linear follower moving away from SlavePosition (here behind it)
// can reach it only by turning back: MC_GearOut ends with 16#8037 and the follower stays in synchronous
// travel — it never turns back to the stop position (with profile 0 it did, found by gearing_property_test: a
// reversal at the job's deceleration, above MaxAcceleration). Profiles 0 and 1.
TEST(Gearing, GearOutToAStopPositionBehindTheFollowerIsRefused) {
  for (const std::int32_t profile : {0, 1}) {
    SCOPED_TRACE(profile);
    GearingMachine m;
    m.gear_pos.RatioNumerator = 2;
    m.gear_pos.MasterSyncPosition = 0.0;
    m.gear_pos.SyncProfileReference = 3;
    m.gear_pos.MasterStartDistance = 10.0;
    m.gear_pos.Execute = true;
    m.run(1);
    m.move_L.Velocity = 100.0;
    m.move_L.Acceleration = 1.0e9;
    m.move_L.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.gear_pos.InSync && m.f().Position >= 500.0; }, 5000), 0);
    m.gear_out.SlavePosition = 100.0;  // 400 behind, F moving +200 mm/s
    m.gear_out.SyncProfileReference = profile;
    m.gear_out.MasterStopDistance = 100.0;
    m.gear_out.Deceleration = 1000.0;
    m.gear_out.Execute = true;
    for (int i = 0; i < 500; ++i) {
      m.run(1);
      ASSERT_FALSE(m.gear_out.StartSyncOut) << i;
      ASSERT_NEAR(m.f().Velocity, 200.0, 1e-9) << i;
    }
    EXPECT_TRUE(m.gear_out.Error);
    EXPECT_EQ(m.gear_out.ErrorID, techobjects::error_id::kInvalidSlavePosition);
    EXPECT_FALSE(m.gear_out.Busy);
    EXPECT_TRUE(m.gear_pos.InSync);
  }
}

// spec 07 §6.5 (decision Y12): MC_GearInPos profile 0 starts when the leader crosses its start position
// (MasterSyncPosition minus the computed synchronization length). A start position the leader has passed
// already is not caught up with: a linear leader leaves the job pending, the follower does not jump (it did:
// found by gearing_property_test, a step of thousands of mm onto the gear line); a modulo leader synchronizes
// on its next pass, continuously.
TEST(Gearing, GearInPosProfile0StartPositionAlreadyPassed) {
  {
    GearingMachine m;
    leader_at(m, 100.0);
    m.gear_pos.SyncProfileReference = 0;
    m.gear_pos.MasterSyncPosition = m.l().Position + 1.0;  // length >= v²/A = 10: the start lies behind L
    m.gear_pos.SlaveSyncPosition = 0.0;
    m.gear_pos.Velocity = 500.0;
    m.gear_pos.Acceleration = 1000.0;
    m.gear_pos.Deceleration = 1000.0;
    m.gear_pos.Jerk = 0.0;
    m.gear_pos.Execute = true;
    for (int i = 0; i < 500; ++i) {
      m.run(1);
      ASSERT_FALSE(m.gear_pos.Error) << i;
      ASSERT_FALSE(m.gear_pos.StartSync) << i;
      ASSERT_EQ(m.f().Position, 0.0) << i;
    }
    EXPECT_TRUE(m.gear_pos.Busy);
    EXPECT_EQ(m.F->synchronized_motion().WaitingFunctionState, 2);
  }
  {
    GearingMachine m(virtual_rotary_modulo(), virtual_rotary_modulo());
    leader_at(m, 100.0);
    m.gear_pos.SyncProfileReference = 0;
    m.gear_pos.MasterSyncPosition = std::fmod(m.l().Position + 1.0, 360.0);
    m.gear_pos.SlaveSyncPosition = 90.0;
    m.gear_pos.Velocity = 500.0;
    m.gear_pos.Acceleration = 1000.0;
    m.gear_pos.Deceleration = 1000.0;
    m.gear_pos.Jerk = 0.0;
    m.gear_pos.Execute = true;
    double previous = m.F->setpoint().position;
    bool started = false;
    int cycles = 0;
    for (; cycles < 8000 && !m.gear_pos.InSync; ++cycles) {
      m.run(1);
      started = started || m.gear_pos.StartSync;
      // No step: at most the job's Velocity (500 °/s = 0.5° per cycle) plus rounding.
      ASSERT_LE(std::fabs(m.F->setpoint().position - previous), 0.5 + 1e-6) << cycles;
      previous = m.F->setpoint().position;
    }
    EXPECT_TRUE(started);
    EXPECT_TRUE(m.gear_pos.InSync);
    EXPECT_GT(cycles, 3000);  // the next pass: 360° at 100 °/s, less the synchronization length
    EXPECT_NEAR(m.f().Position,
                std::fmod(90.0 + (m.l().Position - m.gear_pos.MasterSyncPosition) + 720.0, 360.0), 1e-6);
  }
}

// spec 07 §8 GP-6: GearOut profile 5 cancels a pending GearInPos (CommandAborted, GearOut Done); GearOut
// without gearing
// -> 16#8077.
TEST(Gearing, GP6GearOutCancelAndNoGearing) {
  GearingMachine m;
  m.gear_out.SyncProfileReference = 0;
  m.gear_out.Execute = true;
  m.run(1);
  EXPECT_EQ(m.gear_out.ErrorID, eid::kNoGearing);
  m.gear_out.Execute = false;
  m.run(1);
  m.gear_pos.MasterSyncPosition = 200.0;
  m.gear_pos.MasterStartDistance = 100.0;
  m.gear_pos.Execute = true;
  m.run(2);
  m.gear_out.SyncProfileReference = 5;
  m.gear_out.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.gear_out.Done);
  m.run(1);
  EXPECT_TRUE(m.gear_pos.CommandAborted);
}

// A follower geared 1/1 with MC_GearIn while both stand, then the leader at 100 (F = L from then on).
void geared_at_100(GearingMachine& m) {
  m.gear.Execute = true;
  m.run(2);  // the call in cycle 1 starts the job, cycle 2 locks it (GI-1)
  ASSERT_TRUE(m.gear.InGear);
  leader_at(m, 100.0);
}

// MC_GearOut with the follower already inside the stop travel (spec 07 §6.7, §6.1 item 3, decision Y11).
// Profile 1 over MasterStopDistance 100 needs 1·100/2 = 50 of follower travel; SlavePosition 20 ahead of a
// linear follower cannot be reached without reversing: the job ends with 16#8037 and the gearing goes on, F =
// L (before the fix a blend started that overshot the stop position by about 5 and came back).
TEST(Gearing, GP8GearOutProfile1InsideTheStopTravelLinear) {
  GearingMachine m;
  geared_at_100(m);
  m.run(100);
  const double f0 = m.f().Position;
  m.gear_out.SlavePosition = f0 + 20.0;
  m.gear_out.SyncProfileReference = 1;
  m.gear_out.MasterStopDistance = 100.0;
  m.gear_out.Execute = true;
  m.run(2);  // started by the call in the first cycle, checked in the second
  EXPECT_TRUE(m.gear_out.Error);
  EXPECT_EQ(m.gear_out.ErrorID, eid::kInvalidSlavePosition);
  EXPECT_FALSE(m.gear_out.StartSyncOut);
  const double offset = m.f().Position - m.l().Position;
  for (int i = 0; i < 1000; ++i) {
    m.run(1);
    ASSERT_TRUE(m.gear.InGear) << "cycle " << i;
    ASSERT_NEAR(m.f().Position - m.l().Position, offset, 1e-9) << "cycle " << i;
    ASSERT_NEAR(m.f().Velocity, 100.0, 1e-9) << "cycle " << i;  // never braking, never reversing
  }
  EXPECT_NEAR(m.f().Position, f0 + 100.2, 1e-6);  // 1002 cycles at 0.1 per cycle
  EXPECT_EQ(m.F->synchronized_motion().FunctionState, 1);
}

// The same with profile 0: braking distance 100² / (2·100) = 50 > 20: 16#8037, the gearing goes on.
// spec 07 §6.7, §6.1 item 3; decision Y11 (MC_GearOut inside the stop travel).
TEST(Gearing, GP8GearOutProfile0InsideTheBrakingDistanceLinear) {
  GearingMachine m;
  geared_at_100(m);
  m.run(100);
  const double f0 = m.f().Position;
  m.gear_out.SlavePosition = f0 + 20.0;
  m.gear_out.SyncProfileReference = 0;
  m.gear_out.Deceleration = 100.0;
  m.gear_out.Jerk = 0.0;
  m.gear_out.Execute = true;
  m.run(2);
  EXPECT_EQ(m.gear_out.ErrorID, eid::kInvalidSlavePosition);
  m.run(500);
  EXPECT_TRUE(m.gear.InGear);
  EXPECT_NEAR(m.f().Position, f0 + 50.2, 1e-6);
}

// A stop position behind a linear follower (it moves away from it) is "past it": 16#8037 too.
// spec 07 §6.7, §6.1 item 3; decision Y11 (MC_GearOut inside the stop travel).
TEST(Gearing, GP8GearOutStopPositionBehindLinear) {
  GearingMachine m;
  geared_at_100(m);
  m.run(100);
  m.gear_out.SlavePosition = m.f().Position - 5.0;
  m.gear_out.SyncProfileReference = 1;
  m.gear_out.MasterStopDistance = 10.0;
  m.gear_out.Execute = true;
  m.run(2);
  EXPECT_EQ(m.gear_out.ErrorID, eid::kInvalidSlavePosition);
  EXPECT_TRUE(m.gear.InGear);
}

// A modulo follower inside the stop travel waits for the next occurrence of SlavePosition that lies at least
// the stop travel ahead (spec 07 §6.1 item 3, §6.7): F (0..360) at 100 mm/s, SlavePosition 20 ahead, stop
// travel 50: it stops at SlavePosition one revolution later, having started 50 before it, and never reverses.
TEST(Gearing, GP8GearOutProfile1InsideTheStopTravelModulo) {
  GearingMachine m(virtual_linear(), virtual_rotary_modulo());
  geared_at_100(m);
  m.run(100);  // F shows about 10.x
  const double shown = m.f().Position;
  const double slave_position = shown + 20.0;
  m.gear_out.SlavePosition = slave_position;
  m.gear_out.SyncProfileReference = 1;
  m.gear_out.MasterStopDistance = 100.0;
  m.gear_out.Execute = true;
  const double l0 = m.l().Position;
  ASSERT_GT(m.run_until([&] { return m.gear_out.StartSyncOut; }, 10000), 0);
  EXPECT_FALSE(m.gear_out.Error);
  // Started 50 before the occurrence 360 further on: the leader (= unwrapped F) moved 360 + 20 - 50 = 330.
  EXPECT_NEAR(m.l().Position - l0, 330.0, 0.11);
  double previous = m.l().Position;
  ASSERT_GT(m.run_until(
                [&] {
                  EXPECT_GE(m.f().Velocity, -1e-9);  // no reversal
                  previous = m.l().Position;
                  return m.gear_out.Done;
                },
                2000),
            0);
  EXPECT_NEAR(m.f().Position, slave_position, 1e-6);
  EXPECT_NEAR(previous - l0, 330.0 + 100.0, 0.11);
}

// A start seen exactly at the crossing on a modulo follower (the remaining distance a rounding below the stop
// travel) starts there; it used to move the stop position one revolution further each time and never stop.
// spec 07 §6.7, §6.1 item 3; decision Y11 (MC_GearOut inside the stop travel).
TEST(Gearing, GP8GearOutProfile1ModuloStartAtTheCrossing) {
  GearingMachine m(virtual_linear(), virtual_rotary_modulo());
  geared_at_100(m);
  m.gear_out.SlavePosition = 120.0;
  m.gear_out.SyncProfileReference = 1;
  m.gear_out.MasterStopDistance = 100.0;
  m.gear_out.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear_out.Done; }, 10000), 0);
  EXPECT_NEAR(m.f().Position, 120.0, 1e-6);
  EXPECT_LT(m.l().Position, 120.0 + 50.0 + 0.2);  // the first pass, not a later revolution
}

// MC_GearOut profile 0 starts braking without skipping a cycle's travel (spec 07 §6.7): the follower's step
// per cycle never exceeds the synchronous one (2·100·T) when the stop profile takes over.
TEST(Gearing, GP5GearOutProfile0StartHasNoVelocitySpike) {
  GearingMachine m;
  m.gear.RatioNumerator = 2;
  geared_at_100(m);
  m.gear_out.SlavePosition = 1000.0;
  m.gear_out.SyncProfileReference = 0;
  m.gear_out.Deceleration = 1000.0;
  m.gear_out.Jerk = 0.0;
  m.gear_out.Execute = true;
  double last = m.f().Position;
  double largest_step = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  largest_step = std::max(largest_step, m.f().Position - last);
                  last = m.f().Position;
                  return m.gear_out.Done;
                },
                20000),
            0);
  EXPECT_LE(largest_step, 0.2 + 1e-9);
  EXPECT_NEAR(m.f().Position, 1000.0, 1e-6);
}

// GearInPos profile 0 stays within the job's Velocity and Acceleration (decision Y6, spec 07 §2.2 "the
// configured follower limits apply", §6.8): L at 100, F at rest at 0, 1/1 onto (300, 100) with Velocity 300,
// Acceleration 2000. The fixed-point length estimate it replaced oscillated and gave a blend of 686 mm/s and
// 8000 mm/s².
TEST(Gearing, GP9GearInPosProfile0WithinTheJobDynamics) {
  GearingMachine m;
  m.gear_pos.MasterSyncPosition = 300.0;
  m.gear_pos.SlaveSyncPosition = 100.0;
  m.gear_pos.SyncProfileReference = 0;
  m.gear_pos.Velocity = 300.0;
  m.gear_pos.Acceleration = 2000.0;
  m.gear_pos.Deceleration = 2000.0;
  m.gear_pos.Jerk = 0.0;
  m.gear_pos.Execute = true;
  m.run(1);
  leader_at(m, 100.0);
  double v_max = 0.0;
  double a_max = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  v_max = std::max(v_max, std::fabs(m.f().Velocity));
                  a_max = std::max(a_max, std::fabs(m.f().Acceleration));
                  return m.gear_pos.InSync;
                },
                5000),
            0);
  EXPECT_LE(v_max, 300.0);
  EXPECT_LE(a_max, 2000.0);
  EXPECT_GT(v_max, 250.0);  // and not needlessly slow: close to the job's Velocity
  EXPECT_NEAR(m.l().Position, 300.0, 0.11);
  EXPECT_NEAR(m.f().Position - (m.l().Position - 200.0), 0.0, 1e-6);
}

// Alarm 501 with additional value 1: a pending MC_GearInPos/MC_CamIn profile 0 that may not start
// synchronizing (decision C23); 0 is a job's dynamics clipped at its start.
bool wait_indicated(const GearingMachine& m) {
  for (const auto& a : m.F->alarms().alarms())
    if (a.number == techobjects::kAlarmDynamicsLimitedVelocity && a.additional_value == 1) return true;
  return false;
}

// MC_GearInPos profile 0 and MaxVelocity (spec 07 §2.2 "synchronization completes only below MaxVelocity",
// §6.8; decision C23). F: MaxVelocity 150; ratio 2/1, the leader at 100 mm/s: the synchronous velocity
// 200 mm/s lies above it, so the job waits (WaitingFunctionState 2, no StartSync) instead of running a
// synchronization the follower may not travel — visibly: alarm 501 (additional value 1, WarningWord.X6),
// a warning without reaction. When the leader slows to 60 mm/s (F: 120 mm/s) it synchronizes within 150 mm/s
// and is InSync at MasterSyncPosition 1000 with F = SlaveSyncPosition 300.
TEST(Gearing, GearInPosProfile0WaitsWhileTheSynchronousVelocityIsAboveMaxVelocity) {
  auto f = virtual_linear();
  f.DynamicLimits.MaxVelocity = 150.0;
  f.DynamicLimits.Velocity = 150.0;
  GearingMachine m(virtual_linear(), f);
  leader_at(m, 100.0);
  auto& g = m.gear_pos;
  g.RatioNumerator = 2;
  g.MasterSyncPosition = 1000.0;
  g.SlaveSyncPosition = 300.0;
  g.SyncProfileReference = 0;
  g.Velocity = 150.0;  // within MaxVelocity: no alarm 501 (additional value 0) for the job's own dynamics
  g.Acceleration = g.Deceleration = 2000.0;
  g.Jerk = 0.0;
  g.Execute = true;
  m.run(1);
  ASSERT_TRUE(g.Busy) << std::hex << g.ErrorID;
  m.run(1);
  EXPECT_TRUE(wait_indicated(m));  // from the job's first pending cycle (spec 07 §6.8, decision C23)
  m.run(2999);  // the leader at about 300 mm: far enough before its synchronous point for any length
  EXPECT_TRUE(g.Busy);
  EXPECT_FALSE(g.StartSync);
  EXPECT_FALSE(g.Error);
  EXPECT_EQ(m.F->synchronized_motion().WaitingFunctionState, 2);
  EXPECT_EQ(m.f().Velocity, 0.0);
  EXPECT_TRUE(wait_indicated(m));
  EXPECT_EQ(m.F->alarms().alarms().size(), 1u);        // only the 501 of the wait
  EXPECT_NE(m.F->data().WarningWord & (1u << 6), 0u);  // spec 04 §5.4: X6 DynamicWarning
  EXPECT_EQ(m.F->data().StatusWord & (1u << 21), 0u);  // not Synchronizing
  // MC_Reset acknowledges the 501 while the job still waits: the wait shows again in the next cycle, the job
  // stays pending (a warning's acknowledgement ends no job; decision C23).
  instructions::MC_Reset<techobjects::SynchronousAxis> reset;
  m.user = [&] { reset(*m.F); };
  reset.Execute = true;
  m.run(1);
  reset.Execute = false;
  m.run(1);
  EXPECT_TRUE(wait_indicated(m));
  EXPECT_TRUE(g.Busy);
  EXPECT_EQ(m.F->synchronized_motion().WaitingFunctionState, 2);
  leader_at(m, 60.0);
  double v_max = 0.0;
  int start = -1;
  const int cycles = m.run_until(
      [&] {
        v_max = std::max(v_max, std::fabs(m.f().Velocity));
        if (g.StartSync && start < 0) start = 1;
        return g.InSync;
      },
      20000);
  ASSERT_GT(cycles, 0);
  EXPECT_EQ(start, 1);
  EXPECT_LE(v_max, 150.0);
  EXPECT_NEAR(m.f().Velocity, 120.0, 1e-9);
  EXPECT_NEAR(m.l().Position, 1000.0, 0.06 + 1e-9);
  EXPECT_NEAR(m.f().Position - 2.0 * (m.l().Position - 1000.0), 300.0, 1e-6);
}

// MC_GearInPos profile 0 whose synchronous velocity r·v_leader reaches or passes the job's Velocity but stays
// within MaxVelocity 1000 synchronizes (spec 07 §2.2 profile 0, §6.8: only MaxVelocity decides whether the
// synchronization may complete; the job's Velocity shapes the blend, capped at max(Velocity, r·v_leader),
// decision C23). Ratio 1/1, F at rest at 0, onto (MasterSyncPosition 1000, SlaveSyncPosition 200). Until the
// fix the job waited for ever when r·v_leader > 98 % of Velocity (leader 100, Velocity 100 / 101; defaulted
// Velocity 500 with the leader at 495 / 500 mm/s).
TEST(Gearing, GearInPosProfile0SynchronizesAtAndAboveTheJobVelocityBelowMaxVelocity) {
  struct Case {
    double leader;
    double velocity;  // −1: DynamicDefaults.Velocity 500
  };
  for (const Case c :
       {Case{100.0, 100.0}, Case{100.0, 101.0}, Case{150.0, 100.0}, Case{495.0, -1.0}, Case{500.0, -1.0}}) {
    SCOPED_TRACE("leader " + std::to_string(c.leader) + " mm/s, Velocity " + std::to_string(c.velocity));
    GearingMachine m;
    leader_at(m, c.leader);
    auto& g = m.gear_pos;
    g.MasterSyncPosition = 1000.0;
    g.SlaveSyncPosition = 200.0;
    g.SyncProfileReference = 0;
    g.Velocity = c.velocity;
    g.Acceleration = g.Deceleration = 5000.0;
    g.Jerk = 0.0;
    g.Execute = true;
    const double x0 = m.l().Position;
    m.run(1);
    ASSERT_TRUE(g.Busy) << std::hex << g.ErrorID;
    double v_max = 0.0;
    int start = -1;
    int cycle = 0;
    const int cycles = m.run_until(
        [&] {
          ++cycle;
          v_max = std::max(v_max, std::fabs(m.f().Velocity));
          if (g.StartSync && start < 0) start = cycle;
          return g.InSync;
        },
        20000);
    ASSERT_GT(cycles, 0) << "never synchronized";
    // InSync when the leader reaches 1000 mm at its constant velocity: (1000 − x0)/v_L seconds of 1 ms.
    EXPECT_NEAR(cycles, (1000.0 - x0) / c.leader * 1000.0, 2.0);
    EXPECT_GT(start, 0);
    EXPECT_LT(start, cycles);
    const double cap = std::max(c.velocity < 0.0 ? 500.0 : c.velocity, c.leader);
    EXPECT_LE(v_max, cap * (1.0 + 1e-9));  // the blend within max(Velocity, r·v_leader)
    EXPECT_LT(v_max, 1000.0);              // MaxVelocity
    EXPECT_NEAR(m.f().Velocity, c.leader, 1e-9);
    EXPECT_NEAR(m.l().Position, 1000.0, c.leader * 0.001 + 1e-9);
    EXPECT_NEAR(m.f().Position - (m.l().Position - 1000.0), 200.0, 1e-6);
    EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  }
}

// Decision C24 (spec 07 §2.2: Velocity/Acceleration/Deceleration/Jerk are "profile 0 only"), as C20 for
// MC_CamIn: a distance profile (1, 3) ignores them — an Acceleration of 20,000 above MaxAcceleration 10,000
// raises no alarm 502, a Deceleration of 0.0 and a Jerk that is not a number are not refused, and the job
// synchronizes over MasterStartDistance as GP-2 does (InSync at L = 150, F = L − 100); profile 0 still checks
// them (Deceleration 0.0: 16#8112).
TEST(Gearing, GearInPosDynamicParametersAreProfileZerosOnly) {
  GearingMachine m;
  auto& g = m.gear_pos;
  g.SyncProfileReference = 3;
  g.MasterSyncPosition = 100.0;
  g.SlaveSyncPosition = 0.0;
  g.MasterStartDistance = 50.0;
  g.Acceleration = 20000.0;
  g.Deceleration = 0.0;
  g.Jerk = std::nan("");
  g.Execute = true;
  m.run(1);
  ASSERT_TRUE(g.Busy) << std::hex << g.ErrorID;
  EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedAcceleration));
  leader_at(m, 100.0);
  ASSERT_GT(m.run_until([&] { return g.InSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, 150.0, 0.11);
  EXPECT_NEAR(m.f().Position - (m.l().Position - 100.0), 0.0, 1e-6);
  EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedAcceleration));
  g.Execute = false;
  m.run(1);
  g.SyncProfileReference = 0;
  g.MasterSyncPosition = 2000.0;
  g.Execute = true;
  m.run(1);
  EXPECT_TRUE(g.Error);
  EXPECT_EQ(g.ErrorID, eid::kInvalidDeceleration);
}

// spec 07 §8 GV-1: MC_GearInVelocity(100/100, ContinuousUpdate, Acceleration 1000), L at 100, F at rest:
// InSync after 0.100 s, FunctionState 6; numerator 110 -> F.Velocity = 110 on the next cycle, InSync stays,
// ContinuousUpdateActive. GV-2: PositionControlled FALSE -> X28.
TEST(Gearing, GV1VelocityGearingWithContinuousUpdate) {
  GearingMachine m;
  leader_at(m, 100.0);
  m.gear_velocity.RatioNumerator = 100;
  m.gear_velocity.RatioDenominator = 100;
  m.gear_velocity.ContinuousUpdate = true;
  m.gear_velocity.Acceleration = 1000.0;
  m.gear_velocity.Execute = true;
  m.run(1);
  const int cycles = m.run_until([&] { return m.gear_velocity.InSync; }, 1000);
  EXPECT_NEAR(cycles + 1, 100, 1);
  EXPECT_EQ(m.F->synchronized_motion().FunctionState, 6);
  m.gear_velocity.RatioNumerator = 110;
  m.run(2);
  EXPECT_NEAR(m.f().Velocity, 110.0, 1e-9);
  EXPECT_TRUE(m.gear_velocity.InSync);
  EXPECT_TRUE(m.gear_velocity.ContinuousUpdateActive);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kNonPositionControlled));  // GV-2: PositionControlled FALSE
}

// spec 07 §6.1: leaders before followers, also for a chain L -> F -> F2, whatever the order of addition; a
// cycle in the coupling graph is a configuration error naming it.
TEST(Gearing, ChainsAreEvaluatedLeadersFirstAndCyclesRejected) {
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  auto l = std::make_unique<techobjects::PositioningAxis>("L", nullptr, virtual_linear());
  auto f = std::make_unique<techobjects::SynchronousAxis>(
      "F", nullptr, virtual_linear(),
      std::vector<techobjects::LeadingValueInterconnection>{
          {l.get(), l.get(), techobjects::LeadingValueCoupling::kSetpoint}});
  auto f2 = std::make_unique<techobjects::SynchronousAxis>(
      "F2", nullptr, virtual_linear(),
      std::vector<techobjects::LeadingValueInterconnection>{
          {f.get(), f.get(), techobjects::LeadingValueCoupling::kSetpoint}});
  auto* L = l.get();
  auto* F = f.get();
  auto* F2 = f2.get();
  runtime.add_technology_object(std::move(f2));  // the follower of the follower first
  runtime.add_technology_object(std::move(f));
  runtime.add_technology_object(std::move(l));
  instructions::MC_Power<techobjects::PositioningAxis> pl;
  instructions::MC_Power<techobjects::SynchronousAxis> pf, pf2;
  instructions::MC_GearIn<techobjects::SynchronousAxis> g1, g2, g3;
  instructions::MC_MoveVelocity<techobjects::PositioningAxis> move;
  g1.Master = L;
  g1.RatioNumerator = 2;
  g2.Master = F;
  g2.RatioNumerator = 3;
  pl.Enable = pf.Enable = pf2.Enable = true;
  runtime.set_user_program([&](techobjects::Runtime&) {
    pl(*L);
    pf(*F);
    pf2(*F2);
    g1(*F);
    g2(*F2);
    g3(*F);
    move(*L);
  });
  runtime.start();
  for (int i = 0; i < 3; ++i)
    runtime.step();
  g1.Execute = g2.Execute = true;
  for (int i = 0; i < 3; ++i)
    runtime.step();
  ASSERT_TRUE(g1.InGear && g2.InGear);
  move.Velocity = 10.0;
  move.Execute = true;
  for (int i = 0; i < 500; ++i) {
    runtime.step();
    // The same cycle's values all along the chain: F2 = 3·F = 6·L, no cycle of lag.
    ASSERT_NEAR(F2->setpoint().position, 6.0 * L->setpoint().position, 1e-9) << i;
  }
  // Spec 07 §1.10 16#8019, the branch of two synchronous axes: F2 follows F, so F may not follow F2 (the
  // leader follows this axis) — refused before F2 is even looked up among F's interconnections (no alarm
  // 601); F's running gearing is not affected.
  g3.Master = F2;
  g3.Execute = true;
  runtime.step();
  EXPECT_TRUE(g3.Error);
  EXPECT_EQ(g3.ErrorID, techobjects::error_id::kRecursiveLeadingValue);
  EXPECT_TRUE(g1.InGear);
  EXPECT_FALSE(techobjects::test(F->data().ErrorWord, techobjects::ErrorWordBit::kSynchronousError));

  // A coupling cycle A -> B -> C -> A is a configuration error naming it (spec 07 §1.2).
  struct Linked final : techobjects::TechnologyObject {
    explicit Linked(std::string n) : name_(std::move(n)) {}
    std::string_view name() const noexcept override { return name_; }
    void servo(const techobjects::CycleClock&) noexcept override {}
    void interpolate(const techobjects::CycleClock&) noexcept override {}
    std::span<techobjects::TechnologyObject* const> leaders() const noexcept override { return leaders_; }
    std::string name_;
    std::vector<techobjects::TechnologyObject*> leaders_;
  };
  techobjects::Runtime broken(techobjects::RuntimeConfig{});
  auto& a = broken.emplace<Linked>("A");
  auto& b = broken.emplace<Linked>("B");
  auto& c = broken.emplace<Linked>("C");
  b.leaders_ = {&a};
  c.leaders_ = {&b};
  a.leaders_ = {&c};
  try {
    broken.start();
    FAIL() << "a coupling cycle must not start";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("A -> C -> B -> A"), std::string::npos) << e.what();
  }
}

// spec 07 §8 EX-1: a leader at a constant actual 100 mm/s with SystemDefinedExtrapolation 0, no filters and
// FollowingAxisDependentTime 0.004 s: ExtrapolatedPosition = FilteredPosition + 0.4.
TEST(Gearing, EX1ActualValueExtrapolation) {
  auto l = virtual_linear();
  l.Extrapolation.Settings.SystemDefinedExtrapolation = 0;
  l.Extrapolation.FollowingAxisDependentTime = 0.004;
  GearingMachine m(l, virtual_linear());
  leader_at(m, 100.0);
  m.run(10);
  const auto& e = m.l().StatusExtrapolation;
  EXPECT_NEAR(e.ExtrapolatedPosition - e.FilteredPosition, 0.4, 1e-6);
  EXPECT_NEAR(e.FilteredVelocity, 100.0, 1e-9);
}

}  // namespace
