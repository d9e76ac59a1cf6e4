// MC_MoveSuperimposed / MC_HaltSuperimposed on the positioning axis: seed 004 §6.7.10 (spec 01 §8.14), the
// instructions of spec 03 §4.10–4.11 with their function diagrams, MC_Halt Mode 1 vs Mode 0 (spec 03 §4.4),
// the §9.19.1 row R6 and column C7 (spec 03 §6.1) and the test scenarios T28, T39, T40, T50, T51 of spec 03
// §8 and 39, 40 of spec 01. Simulated drive, 1 ms servo = interpolator cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_halt_superimposed.hpp"
#include "tomc/instructions/mc_motion_in.hpp"
#include "tomc/instructions/mc_move_superimposed.hpp"
#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"

namespace {

using tomc::instructions::MC_MoveSuperimposed;
using tomc::techobjects::PositioningAxis;
using tomc::techobjects::StatusWord2Bit;
using tomc::techobjects::StatusWordBit;
namespace error_id = tomc::techobjects::error_id;

bool bit(std::uint32_t word, StatusWordBit b) {
  return (word >> static_cast<unsigned>(b)) & 1u;
}
bool bit(std::uint32_t word, StatusWord2Bit b) {
  return (word >> static_cast<unsigned>(b)) & 1u;
}

struct SuperimposedMachine : tomc::testing::PositioningAxisMachine {
  SuperimposedMachine() : SuperimposedMachine(tomc::testing::linear_axis_data()) {}
  explicit SuperimposedMachine(const tomc::techobjects::PositioningAxisData& data)
      : PositioningAxisMachine(data) {
    user = [this] { move_superimposed2(*axis); };
  }
  MC_MoveSuperimposed<PositioningAxis>
      move_superimposed2;  // the fixture has move_superimposed, halt_superimposed
};

// Base MoveRelative of 50 mm at 50 mm/s (trapezoid, 500 mm/s²) from a homed axis at 0.
void start_base_move_relative(SuperimposedMachine& m, double distance = 50.0) {
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_relative.Distance = distance;
  m.move_relative.Velocity = 50.0;
  m.move_relative.Acceleration = 500.0;
  m.move_relative.Deceleration = 500.0;
  m.move_relative.Execute = true;
  m.run(200);  // ① : 0.2 s into the base move, 50 mm/s reached after 0.1 s
  ASSERT_TRUE(m.move_relative.Busy);
}

// Spec 03 §4.10 function diagram, section A (T39): MoveRelative 50 as the base, MoveSuperimposed 50 at ①:
// the axis travels 50 + 50 = 100 and both jobs end Done; StatusWord.X23 while the superimposed job runs.
TEST(MoveSuperimposed, AddsItsDistanceToTheBaseMotion) {
  SuperimposedMachine m;
  start_base_move_relative(m);
  m.move_superimposed.Distance = 50.0;
  m.move_superimposed.VelocityDiff = 50.0;
  m.move_superimposed.Acceleration = 500.0;
  m.move_superimposed.Deceleration = 500.0;
  m.move_superimposed.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.move_superimposed.Busy);
  m.run(1);
  EXPECT_TRUE(bit(m.db().StatusWord, StatusWordBit::kMoveSuperimposedCommand));
  double fastest = 0.0;
  const int cycles = m.run_until(
      [&] {
        fastest = std::max(fastest, m.db().Velocity);
        return m.move_relative.Done && m.move_superimposed.Done;
      },
      5000);
  ASSERT_GT(cycles, 0);
  EXPECT_NEAR(m.db().Position, 100.0, 1e-9);
  EXPECT_NEAR(fastest, 100.0, 1e-9);  // summed dynamics: 50 + 50 mm/s
  EXPECT_FALSE(bit(m.db().StatusWord, StatusWordBit::kMoveSuperimposedCommand));
  EXPECT_FALSE(m.move_superimposed.Error);
  EXPECT_FALSE(m.move_relative.CommandAborted);  // "the base motion is not influenced" (spec 01 §8.14)
}

// Section B: −50 at ②: the axis reverses; net travel 50 − 50 = 0, Done_2.
// spec 03 §4.10 section B (−50 superimposed on 50: net travel 0, Done_2).
TEST(MoveSuperimposed, NegativeDistanceReversesTheAxis) {
  SuperimposedMachine m;
  start_base_move_relative(m);
  m.move_superimposed.Distance = -50.0;
  m.move_superimposed.VelocityDiff = 100.0;
  m.move_superimposed.Acceleration = 1000.0;
  m.move_superimposed.Deceleration = 1000.0;
  m.move_superimposed.Execute = true;
  double slowest = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  slowest = std::min(slowest, m.db().Velocity);
                  return m.move_relative.Done && m.move_superimposed.Done;
                },
                5000),
            0);
  EXPECT_NEAR(m.db().Position, 0.0, 1e-9);
  EXPECT_LT(slowest, -40.0);  // 50 − 100 mm/s: the total runs backwards
}

// T40: X23 while MoveSuperimposed runs; HaltSuperimposed in the next cycle aborts it (R6 x C7 = A), X23 = 0,
// StatusWord2.X7 = 1; after its Done X7 = 0 and the base motion is still Busy (spec 03 §4.11 steps 1–4).
TEST(HaltSuperimposed, ReplacesTheMoveAndLeavesTheBase) {
  SuperimposedMachine m;
  start_base_move_relative(m, 200.0);
  m.move_superimposed.Distance = 100.0;
  m.move_superimposed.VelocityDiff = 100.0;
  m.move_superimposed.Acceleration = 500.0;
  m.move_superimposed.Deceleration = 500.0;
  m.move_superimposed.Execute = true;
  m.run(50);  // superimposed at 25 mm/s, accelerating
  ASSERT_TRUE(bit(m.db().StatusWord, StatusWordBit::kMoveSuperimposedCommand));
  m.halt_superimposed.Deceleration = 1000.0;
  m.halt_superimposed.Jerk = 0.0;
  m.halt_superimposed.Execute = true;
  m.run(2);  // the aborted instance shows CommandAborted at its next call
  EXPECT_TRUE(m.move_superimposed.CommandAborted);
  EXPECT_TRUE(m.halt_superimposed.Busy);
  EXPECT_FALSE(bit(m.db().StatusWord, StatusWordBit::kMoveSuperimposedCommand));
  EXPECT_TRUE(bit(m.db().StatusWord2, StatusWord2Bit::kHaltSuperimposedCommand));
  // 25 mm/s braked at 1000 mm/s² (trapezoid): 25 ms.
  const int cycles = m.run_until([&] { return m.halt_superimposed.Done; }, 200);
  EXPECT_NEAR(cycles + 1, 25, 2);
  EXPECT_FALSE(bit(m.db().StatusWord2, StatusWord2Bit::kHaltSuperimposedCommand));
  EXPECT_TRUE(m.move_relative.Busy);
  EXPECT_NEAR(m.db().Velocity, 50.0, 1e-9);  // the base alone again
  EXPECT_NEAR(m.axis->superimposed().state().velocity, 0.0, 1e-12);
}

// spec 03 §4.11 AbortAcceleration, on a jerk-limited superimposed acceleration (jerk 10^5 mm/s³, 20 ms into
// the ramp: a_sup = 2000 mm/s²): FALSE ramps the acceleration down with the jerk (100 mm/s² per cycle) before
// braking; TRUE sets it to 0 at once and brakes.
TEST(HaltSuperimposed, AbortAccelerationTakesTheAccelerationAwayAtOnce) {
  for (const bool abort_acceleration : {false, true}) {
    SCOPED_TRACE(abort_acceleration);
    auto data = tomc::testing::linear_axis_data();
    data.DynamicLimits.MaxJerk = 1.0e5;
    SuperimposedMachine m(data);
    ASSERT_GT(m.enable(), 0);
    m.move_superimposed.Distance = 100.0;
    m.move_superimposed.VelocityDiff = 200.0;
    m.move_superimposed.Acceleration = 4000.0;
    m.move_superimposed.Deceleration = 4000.0;
    m.move_superimposed.Jerk = 1.0e5;
    m.move_superimposed.Execute = true;
    m.run(21);  // submitted in cycle 1, 20 cycles of +j: a = 2000 mm/s²
    ASSERT_NEAR(m.db().Acceleration, 2000.0, 1e-6);
    m.halt_superimposed.Deceleration = 4000.0;
    m.halt_superimposed.Jerk = 1.0e5;
    m.halt_superimposed.AbortAcceleration = abort_acceleration;
    m.halt_superimposed.Execute = true;
    m.run(1);  // the halt was planned in this cycle's user program; its first setpoint comes next
    const double a0 = m.db().Acceleration;
    m.run(1);
    const double a1 = m.db().Acceleration;
    if (abort_acceleration) {
      EXPECT_NEAR(a1, -100.0, 1e-6);  // from 0 at once, then -j·T
    } else {
      EXPECT_NEAR(a1, a0 - 100.0, 1e-6);  // continuous: 100 mm/s² less per cycle
      EXPECT_GT(a1, 0.0);
    }
    ASSERT_GT(m.run_until([&] { return m.halt_superimposed.Done; }, 2000), 0);
    EXPECT_NEAR(m.db().Velocity, 0.0, 1e-9);
    EXPECT_NEAR(m.db().Acceleration, 0.0, 1e-9);
  }
}

// Spec 01 scenario 40 / §8.14: HaltSuperimposed without a superimposed motion is Done at once, Busy FALSE.
TEST(HaltSuperimposed, WithoutSuperimposedMotionIsDoneAtOnce) {
  SuperimposedMachine m;
  ASSERT_GT(m.enable(), 0);
  m.halt_superimposed.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.halt_superimposed.Done);
  EXPECT_FALSE(m.halt_superimposed.Busy);
  EXPECT_FALSE(m.halt_superimposed.Error);
}

// T28: base MoveAbsolute at 100 mm/s plus MoveSuperimposed with VelocityDiff 50: 150 mm/s.
void start_t28(SuperimposedMachine& m) {
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_absolute.Position = 1000.0;
  m.move_absolute.Velocity = 100.0;
  m.move_absolute.Acceleration = 1000.0;
  m.move_absolute.Deceleration = 1000.0;
  m.move_absolute.Execute = true;
  m.run(150);
  m.move_superimposed.Distance = 200.0;
  m.move_superimposed.VelocityDiff = 50.0;
  m.move_superimposed.Acceleration = 1000.0;
  m.move_superimposed.Deceleration = 1000.0;
  m.move_superimposed.Execute = true;
  m.run(100);
  ASSERT_NEAR(m.db().Velocity, 150.0, 1e-9);
}

// MC_Halt Mode 1 (R3 x C7 = "-"): A1 CommandAborted, A2 stays Busy; Done when the base velocity is 0 — the
// axis then moves at the superimposed 50 mm/s.
// spec 03 §8 T28 (MC_Halt Mode 1 vs Mode 0), §6.1 (R3 × C7 = "–").
TEST(HaltSuperimposed, HaltMode1StopsTheBaseOnly) {
  SuperimposedMachine m;
  start_t28(m);
  m.halt.Mode = 1;
  m.halt.Deceleration = 1000.0;
  m.halt.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move_absolute.CommandAborted);
  EXPECT_TRUE(m.move_superimposed.Busy);
  // 100 mm/s at 1000 mm/s²: the base stands after 100 ms.
  const int cycles = m.run_until([&] { return m.halt.Done; }, 500);
  EXPECT_NEAR(cycles + 1, 100, 2);
  EXPECT_TRUE(m.move_superimposed.Busy);
  EXPECT_NEAR(m.db().Velocity, 50.0, 1e-9);
  ASSERT_GT(m.run_until([&] { return m.move_superimposed.Done; }, 5000), 0);
}

// MC_Halt Mode 0 (R4 x C7 = A): A1 and A2 CommandAborted; Done when the total velocity is 0 (150 mm/s at
// 1000 mm/s²: 150 ms).
// spec 03 §8 T28 (MC_Halt Mode 0), §6.1 (R4 × C7 = A).
TEST(HaltSuperimposed, HaltMode0StopsBoth) {
  SuperimposedMachine m;
  start_t28(m);
  m.halt.Mode = 0;
  m.halt.Deceleration = 1000.0;
  m.halt.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move_absolute.CommandAborted);
  EXPECT_TRUE(m.move_superimposed.CommandAborted);
  const int cycles = m.run_until([&] { return m.halt.Done; }, 500);
  EXPECT_NEAR(cycles + 1, 150, 2);
  EXPECT_NEAR(m.db().Velocity, 0.0, 1e-9);
}

// T50: a second MoveSuperimposed aborts the first and continues from its state; MoveAbsolute BufferMode 0
// aborts the superimposed motion (R4 x C7 = A) and takes its velocity over without a step.
// spec 03 §8 T50 (superimposed independence, R6), §6.1 (R4 × C7 = A).
TEST(MoveSuperimposed, PriorityRowR6AndColumnC7) {
  SuperimposedMachine m;
  start_t28(m);
  const double travelled_before = m.axis->superimposed().state().position;
  m.move_superimposed2.Distance = 10.0;
  m.move_superimposed2.VelocityDiff = 50.0;
  m.move_superimposed2.Acceleration = 1000.0;
  m.move_superimposed2.Deceleration = 1000.0;
  m.move_superimposed2.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move_superimposed.CommandAborted);
  EXPECT_TRUE(m.move_superimposed2.Busy);
  EXPECT_TRUE(m.move_absolute.Busy);  // R6 x C3 = "-"
  ASSERT_GT(m.run_until([&] { return m.move_superimposed2.Done; }, 2000), 0);
  EXPECT_NEAR(m.axis->superimposed().state().position, travelled_before + 2 * 50.0 * 0.001 + 10.0, 0.06);
  EXPECT_NEAR(m.db().StatusPositioning.SuperimposedDistance, m.axis->superimposed().state().position, 1e-12);

  SuperimposedMachine n;
  start_t28(n);
  n.move_absolute2.Position = 2000.0;
  n.move_absolute2.Velocity = 100.0;
  n.move_absolute2.Acceleration = 1000.0;
  n.move_absolute2.Deceleration = 1000.0;
  n.move_absolute2.Execute = true;
  double previous = n.db().Velocity, steepest = 0.0;
  n.run(1);
  steepest = std::fabs(n.db().Velocity - previous);
  previous = n.db().Velocity;
  n.run(1);
  steepest = std::max(steepest, std::fabs(n.db().Velocity - previous));
  previous = n.db().Velocity;
  EXPECT_TRUE(n.move_superimposed.CommandAborted);
  EXPECT_TRUE(n.move_absolute.CommandAborted);
  ASSERT_GT(n.run_until(
                [&] {
                  steepest = std::max(steepest, std::fabs(n.db().Velocity - previous));
                  previous = n.db().Velocity;
                  return n.db().Velocity <= 100.0 + 1e-9;
                },
                500),
            0);
  EXPECT_LE(steepest, 1000.0 * 0.001 + 1e-9);  // 150 -> 100 mm/s with the new job's deceleration
}

// T51: MC_Stop aborts a running MoveSuperimposed (R7 x C7 = A); the stop brakes the total motion.
// spec 03 §8 T51 (MC_Stop row R7), §6.1 (R6 × C6 = N), §4.13 (16#8102 while MC_Stop.Execute is TRUE).
TEST(MoveSuperimposed, StopAbortsIt) {
  SuperimposedMachine m;
  start_t28(m);
  m.stop.Mode = 3;
  m.stop.Deceleration = 1500.0;
  m.stop.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move_superimposed.CommandAborted);
  EXPECT_TRUE(m.move_absolute.CommandAborted);
  const int cycles = m.run_until([&] { return m.stop.Done; }, 500);
  EXPECT_NEAR(cycles + 1, 100, 2);  // 150 mm/s at 1500 mm/s²
  // While the stop holds Execute, a superimposed job is rejected (R6 x C6 = N).
  m.move_superimposed2.Distance = 1.0;
  m.move_superimposed2.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_superimposed2.Error);
  EXPECT_EQ(m.move_superimposed2.ErrorID, error_id::kLockedByStop);
}

// Decision U3 / spec 01 §8.8 ("current dynamics are carried into the new motion"), spec 03 §3.4: an
// MC_MoveJog that replaces the base job under Override.Velocity 0 % (its velocity target 0) hands the
// superimposed state over and brakes the total with its own Deceleration from there. The fault
// PositioningProperty .RotaryModuloAxis found (base seed 10, its seed 113, cycle 98793: a step of the
// superimposed 360 °/s): the jog planned nothing in its first cycle, so the aborted job's braking profile
// went on without the folded superimposed part.
TEST(MoveSuperimposed, JogAtZeroOverrideCarriesTheSuperimposedStateOver) {
  SuperimposedMachine m;
  start_t28(m);  // base 100 + superimposed 50 = 150 mm/s
  ASSERT_TRUE(m.axis->write("Override.Velocity", 0.0).ok());
  m.run(20);  // the base brakes at 1000 mm/s² (spec 01 §8.4), the superimposed part stays at 50
  ASSERT_NEAR(m.axis->superimposed().state().velocity, 50.0, 1e-9);
  ASSERT_NEAR(m.db().Velocity, 130.0, 1.0 + 1e-9);
  m.jog.JogBackward = true;
  m.jog.Velocity = 80.0;
  m.jog.Acceleration = 2000.0;
  m.jog.Deceleration = 2000.0;
  double previous = m.db().Velocity;
  m.run(1);
  ASSERT_TRUE(m.jog.Busy);
  // The hand-over cycle and every one after it: at most the jog's 2000 mm/s² (2 mm/s per 1 ms cycle), never
  // the step of the 50 mm/s superimposed velocity.
  double steepest = previous - m.db().Velocity;
  previous = m.db().Velocity;
  EXPECT_LE(steepest, 2.0 + 1e-9);
  const int cycles = m.run_until(
      [&] {
        steepest = std::max(steepest, std::fabs(m.db().Velocity - previous));
        previous = m.db().Velocity;
        return m.db().Velocity == 0.0;
      },
      500);
  EXPECT_LE(steepest, 2.0 + 1e-9);
  EXPECT_TRUE(m.move_superimposed.CommandAborted);
  EXPECT_TRUE(m.move_absolute.CommandAborted);
  // From ~129 mm/s at the jog's 2000 mm/s² (not the aborted job's 1000): 65 ± 2 cycles.
  EXPECT_NEAR(cycles + 1, 65, 2);
}

// Spec 01 scenario 39 (§8.14): base MoveVelocity at 100 mm/s, MaxVelocity 150; MoveSuperimposed +10 mm with
// VelocityDiff 100: the total never exceeds 150 mm/s; SuperimposedDistance is 10 when done and stays 10 while
// the base continues; it returns to 0 only when the base motion is finished too.
TEST(MoveSuperimposed, TotalVelocityStaysWithinTheLimitAndTheDistanceIsShown) {
  auto data = tomc::testing::linear_axis_data();
  data.DynamicLimits.MaxVelocity = 150.0;
  SuperimposedMachine m(data);
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 100.0;
  m.move_velocity.Acceleration = 1000.0;
  m.move_velocity.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_velocity.InVelocity; }, 500), 0);
  m.move_superimposed.Distance = 10.0;
  m.move_superimposed.VelocityDiff = 100.0;
  m.move_superimposed.Acceleration = 1000.0;
  m.move_superimposed.Deceleration = 1000.0;
  m.move_superimposed.Execute = true;
  double fastest = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  fastest = std::max(fastest, m.db().Velocity);
                  return m.move_superimposed.Done;
                },
                2000),
            0);
  EXPECT_LE(fastest, 150.0 + 1e-9);
  EXPECT_NEAR(fastest, 150.0, 1e-6);  // the 50 mm/s the base leaves are used
  EXPECT_NEAR(m.db().StatusPositioning.SuperimposedDistance, 10.0, 1e-9);
  m.run(100);
  EXPECT_NEAR(m.db().StatusPositioning.SuperimposedDistance, 10.0, 1e-9);
  EXPECT_NEAR(m.db().Velocity, 100.0, 1e-9);
  m.halt.Deceleration = 1000.0;
  m.halt.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.halt.Done; }, 500), 0);
  m.run(1);
  EXPECT_EQ(m.db().StatusPositioning.SuperimposedDistance, 0.0);
  const double stopped_at = m.db().Position;
  m.run(10);
  EXPECT_EQ(m.db().Position, stopped_at);  // folding into the base moves nothing
}

// Seed 004 §6.7.10.1 (spec 01 §8.14, decision U16): the superimposed motion's acceleration is at most what
// the base motion's present acceleration leaves of MaxAcceleration (total speeding up) / MaxDeceleration
// (total slowing down); with no headroom it cannot change its velocity that way. Limits 1000 mm/s² both,
// MaxVelocity 1000 mm/s; MoveSuperimposed with Acceleration = Deceleration = 1000 mm/s², VelocityDiff 100.
// The base ramps with `base_ramp` mm/s² for 100 mm/s; the superimposed job starts `delay` ms into the ramp.
// Every cycle: |total acceleration| <= 1000 and the total's velocity change <= 1000 mm/s² x 1 ms.
// MaxVelocity 1000 mm/s, MaxAcceleration = MaxDeceleration = 1000 mm/s².
tomc::techobjects::PositioningAxisData thousand_limits_data() {
  auto data = tomc::testing::linear_axis_data();
  data.DynamicLimits.MaxVelocity = 1000.0;
  data.DynamicLimits.MaxAcceleration = 1000.0;
  data.DynamicLimits.MaxDeceleration = 1000.0;
  return data;
}

struct AccelerationHeadroomCase {
  const char* name;
  double base_from, base_to, base_ramp;  // MoveVelocity from -> to (mm/s) at base_ramp mm/s²
  int delay;                             // ms into the base ramp
  double distance;                       // MoveSuperimposed.Distance, mm
  double still_for;                      // ms the superimposed part cannot move (headroom 0)
  double done_after;  // ms from the job's start to Done, computed below (< 0: not computed)
  double jerk = 0.0;  // of the base and the superimposed job, mm/s³ (0: none)
};

// seed 004 §6.7.10.1 (spec 01 §8.14: the total motion is limited to the dynamic limits), decisions U16 and
// U17.
TEST(MoveSuperimposed, TotalAccelerationStaysWithinTheLimits) {
  const AccelerationHeadroomCase cases[] = {
      // Headroom 1000 - 800 = 200 for the 100 ms left of the ramp (v 20 mm/s, 1 mm), then 9 mm from 20 mm/s
      // at 1000: peak sqrt((2·1000·9 + 20²)/2) = 95.92 -> 75.92 + 95.92 ms. Without U16: 200 ms.
      {"base accelerates at 800", 0.0, 100.0, 800.0, 25, 10.0, 0.0, 100.0 + 75.92 + 95.92},
      // Base at MaxAcceleration: headroom 0 for the 75 ms left of the ramp, the superimposed part stays at 0;
      // then 10 mm at 1000 mm/s², peak 100 = VelocityDiff: 200 ms.
      {"base accelerates at the limit", 0.0, 100.0, 1000.0, 25, 10.0, 75.0, 75.0 + 200.0},
      // Base slows from 100 to 20 mm/s at 800: a negative superimposed job may slow the total by only 200
      // more for the 100 ms of the ramp (-20 mm/s, -1 mm), then -1 mm from -20 mm/s at 1000:
      // peak sqrt((2·1000·1 + 20²)/2) = 34.64 -> 14.64 + 34.64 ms. Without U16: 2·sqrt(2/1000) s = 89.44 ms.
      {"base decelerates at 800", 100.0, 20.0, 800.0, 0, -2.0, 0.0, 100.0 + 14.64 + 34.64},
      // Jerk-limited base ramp and job, MaxJerk 10^5 mm/s³ (U17): the headroom changes in every cycle of the
      // base's jerk phases, and the superimposed jerk is what the base's leaves of MaxJerk; the total's
      // acceleration and jerk stay within the limits in every cycle (no closed-form Done time).
      {"base and job jerk-limited", 0.0, 100.0, 800.0, 5, 10.0, 0.0, -1.0, 1e5},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    auto data = thousand_limits_data();
    data.DynamicLimits.MaxJerk = c.jerk;  // 0: no jerk limit
    SuperimposedMachine m(data);
    ASSERT_GT(m.enable(), 0);
    m.move_velocity.Acceleration = 1000.0;
    m.move_velocity.Deceleration = 1000.0;
    if (c.base_from != 0.0) {
      m.move_velocity.Velocity = c.base_from;
      m.move_velocity.Execute = true;
      ASSERT_GT(m.run_until([&] { return m.move_velocity.InVelocity; }, 500), 0);
      m.move_velocity.Execute = false;
      m.run(1);
    }
    m.move_velocity.Velocity = c.base_to;
    m.move_velocity.Acceleration = c.base_ramp;
    m.move_velocity.Deceleration = c.base_ramp;
    m.move_velocity.Jerk = c.jerk;
    m.move_velocity.Execute = true;
    m.run(c.delay);
    m.move_superimposed.Distance = c.distance;
    m.move_superimposed.VelocityDiff = 100.0;
    m.move_superimposed.Acceleration = 1000.0;
    m.move_superimposed.Deceleration = 1000.0;
    m.move_superimposed.Jerk = c.jerk;
    m.move_superimposed.Execute = true;
    double steepest = 0.0, steepest_change = 0.0, velocity = m.db().Velocity;
    double sharpest = 0.0, acceleration = m.db().Acceleration;  // the total's jerk, mm/s³
    int cycles = 0;
    ASSERT_GT(m.run_until(
                  [&] {
                    ++cycles;
                    steepest = std::max(steepest, std::fabs(m.db().Acceleration));
                    steepest_change =
                        std::max(steepest_change, std::fabs(m.db().Velocity - velocity) / 0.001);
                    sharpest = std::max(sharpest, std::fabs(m.db().Acceleration - acceleration) / 0.001);
                    velocity = m.db().Velocity;
                    acceleration = m.db().Acceleration;
                    if (cycles < c.still_for - 1) {
                      EXPECT_EQ(m.db().StatusPositioning.SuperimposedDistance, 0.0) << cycles;
                    }
                    return m.move_superimposed.Done;
                  },
                  1000),
              0);
    EXPECT_LE(steepest, 1000.0 + 1e-6);
    EXPECT_LE(steepest_change, 1000.0 + 1e-6);
    if (c.jerk > 0.0) {
      EXPECT_LE(sharpest, c.jerk * (1.0 + 1e-6));
    }
    if (c.done_after >= 0.0) {
      EXPECT_NEAR(cycles, c.done_after, 3.0);
    }
    EXPECT_NEAR(m.db().StatusPositioning.SuperimposedDistance, c.distance, 1e-9);
    EXPECT_NEAR(m.db().Velocity, c.base_to, 1e-9);
  }
}

// MC_MoveSuperimposed's rising edge with these inputs (distance mm, VelocityDiff mm/s, mm/s², mm/s³).
void start_move_superimposed(MC_MoveSuperimposed<PositioningAxis>& fb, double distance, double velocity_diff,
                             double acceleration, double deceleration, double jerk) {
  fb.Distance = distance;
  fb.VelocityDiff = velocity_diff;
  fb.Acceleration = acceleration;
  fb.Deceleration = deceleration;
  fb.Jerk = jerk;
  fb.Execute = true;
}

// Spec 01 §8.14 / seed 004 §6.7.10.1 (decision U18): the velocity headroom v_limit − v_base shrinks at the
// base's acceleration; the superimposed job's Deceleration counts relative to it, so the total comes back
// within the limit even where the job brakes more gently than the base accelerates, and a total beyond the
// limit never has its acceleration pushed further. MaxVelocity 500 mm/s, limits 5000 mm/s²; base
// MoveVelocity 0 -> 450 mm/s at 1000 mm/s²; MoveSuperimposed +100 mm at VelocityDiff 100, Acceleration 1000,
// Deceleration 500, started at 200 mm/s (cruising at 100 from 300): from a total of 500 the base gains
// 50 mm/s more in 50 ms, which the job's 500 mm/s² alone follows 25 mm/s above the limit (without U18:
// 525 mm/s, 99 / 105 cycles beyond, 48 / 39 of them with the total's acceleration not taken back). Without
// jerk and with MaxJerk = job and base jerk = 10^5 mm/s³.
TEST(MoveSuperimposed, ShrinkingVelocityHeadroomKeepsTheTotalWithinTheLimit) {
  for (const double jerk : {0.0, 1e5}) {
    SCOPED_TRACE(jerk);
    auto data = tomc::testing::linear_axis_data();
    data.DynamicLimits.MaxVelocity = 500.0;
    data.DynamicLimits.MaxAcceleration = 5000.0;
    data.DynamicLimits.MaxDeceleration = 5000.0;
    data.DynamicLimits.MaxJerk = jerk;
    SuperimposedMachine m(data);
    ASSERT_GT(m.enable(), 0);
    m.move_velocity.Velocity = 450.0;
    m.move_velocity.Acceleration = 1000.0;
    m.move_velocity.Jerk = jerk;
    m.move_velocity.Execute = true;
    ASSERT_GT(m.run_until([&] { return m.db().Velocity >= 200.0; }, 500), 0);
    start_move_superimposed(m.move_superimposed, 100.0, 100.0, 1000.0, 500.0, jerk);
    double fastest = 0.0, acceleration = 0.0;
    int beyond = 0, pushing = 0;
    ASSERT_GT(m.run_until(
                  [&] {
                    const double v = m.db().Velocity, a = m.db().Acceleration;
                    fastest = std::max(fastest, v);
                    if (v > 500.0 + 1e-9) {
                      ++beyond;
                      if (a > 0.0 && a >= acceleration) ++pushing;
                    }
                    acceleration = a;
                    return m.move_superimposed.Done;
                  },
                  2000),
              0);
    EXPECT_EQ(pushing, 0);
    if (jerk == 0.0) {
      EXPECT_NEAR(fastest, 500.0, 1e-6);  // the limit, reached and never exceeded
      EXPECT_EQ(beyond, 0);
    } else {
      // U4's jerk overshoot, a0²/(2j) = 1000²/(2·10^5) = 5 mm/s at most (measured 3.5); back within the
      // limit after the 10 ms jerk phase, 3.5/500 s and the 10 ms out of it, 27 cycles (measured 21).
      EXPECT_LE(fastest, 505.0);
      EXPECT_LE(beyond, 27);
    }
    EXPECT_NEAR(m.db().StatusPositioning.SuperimposedDistance, 100.0, 1e-9);
    EXPECT_NEAR(m.db().Velocity, 450.0, 1e-9);
  }
}

// Seed 004 §6.7.10.1 with MaxJerk (decision U17, its negative headroom): a base whose own jerk is above
// MaxJerk leaves the superimposed acceleration where it is; it does not push it the other way to make up for
// the base. MaxJerk 10^5 mm/s³, limits 1000 mm/s² and 1000 mm/s. The base is MC_MotionInVelocity (no
// profile, no limits, spec 03 §4.17.1): it steps its acceleration 0 -> 500 mm/s² (5·10^5 mm/s³), ramps 0 ->
// 100 mm/s in 200 cycles and steps back to 0. MC_MoveSuperimposed (VelocityDiff 50, 1000 mm/s², Jerk 10^5)
// cruises at 50 mm/s meanwhile, far inside every headroom: its velocity and acceleration stay 50 and 0 in
// every cycle (without the rule the window (MaxJerk ∓ j_base)·T pushed it by ∓400 mm/s² in the two step
// cycles); the total's jerk is the base's own, 5·10^5, in those two cycles only.
TEST(MoveSuperimposed, BaseJerkAboveMaxJerkDoesNotPushTheSuperimposedPart) {
  auto data = thousand_limits_data();
  data.DynamicLimits.MaxJerk = 1e5;
  SuperimposedMachine m(data);
  tomc::instructions::MC_MotionInVelocity<PositioningAxis> base;
  m.user = [&] {
    m.move_superimposed2(*m.axis);
    base(*m.axis);
  };
  ASSERT_GT(m.enable(), 0);
  base.Enable = true;
  m.run(2);
  ASSERT_TRUE(base.Busy);
  start_move_superimposed(m.move_superimposed, 100.0, 50.0, 1000.0, 1000.0, 1e5);
  const auto& sup = m.axis->superimposed().state();
  ASSERT_GT(m.run_until([&] { return sup.velocity == 50.0 && sup.acceleration == 0.0; }, 200), 0);
  m.run(5);
  double acceleration = m.db().Acceleration, sharpest = 0.0, furthest = 0.0;
  int steps = 0;  // cycles whose total jerk is above MaxJerk
  for (int cycle = 0; cycle < 260; ++cycle) {
    const bool ramping = cycle < 200;
    base.Acceleration = ramping ? 500.0 : 0.0;
    base.Velocity = ramping ? 500.0 * 0.001 * (cycle + 1) : 100.0;
    m.run(1);
    furthest = std::max({furthest, std::fabs(sup.velocity - 50.0), std::fabs(sup.acceleration)});
    const double jerk = std::fabs(m.db().Acceleration - acceleration) / 0.001;
    sharpest = std::max(sharpest, jerk);
    if (jerk > 1e5 * (1.0 + 1e-9)) ++steps;
    acceleration = m.db().Acceleration;
  }
  EXPECT_EQ(furthest, 0.0);
  EXPECT_NEAR(sharpest, 5e5, 1e-3);  // the base's own steps
  EXPECT_EQ(steps, 2);
  EXPECT_TRUE(m.move_superimposed.Busy);
  EXPECT_NEAR(m.db().Velocity, 150.0, 1e-9);
}

// Seed 004 §6.7.10.1 "the total motion is limited to the configured dynamic limits", for MC_HaltSuperimposed
// too (§6.7.10.2; decision U17). Limits 1000 mm/s²; a base MoveVelocity ramps to +100 mm/s at 1000 mm/s²
// (100 ms) and a superimposed move, started a cycle later, reaches -50 mm/s (VelocityDiff 50, 1000 mm/s²)
// 50 ms into it, when MC_HaltSuperimposed (Deceleration 1000) comes: braking the superimposed part would add
// 1000 mm/s² to the base's 1000, so it holds -50 mm/s for the rest of the base ramp (about 49 ms) and brakes
// in the 50 ms after it, travelling -1.25 - 50 mm/s · rest - 1.25 mm; every cycle |Acceleration| and
// |ΔVelocity|/1 ms <= 1000 (2000 without U17).
TEST(HaltSuperimposed, BrakesWithinWhatTheBaseMotionLeaves) {
  SuperimposedMachine m(thousand_limits_data());
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 100.0;
  m.move_velocity.Acceleration = 1000.0;
  m.move_velocity.Jerk = 0.0;
  m.move_velocity.Execute = true;
  m.run(1);
  m.move_superimposed.Distance = -100.0;
  m.move_superimposed.VelocityDiff = 50.0;
  m.move_superimposed.Acceleration = 1000.0;
  m.move_superimposed.Deceleration = 1000.0;
  m.move_superimposed.Jerk = 0.0;
  m.move_superimposed.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.axis->superimposed().state().velocity <= -50.0 + 1e-9; }, 200), 0);
  const double start = m.db().StatusPositioning.SuperimposedDistance;
  EXPECT_NEAR(start, -1.25, 0.06);
  const double rest = (100.0 - (m.db().Velocity + 50.0)) / 1000.0;  // s of the base ramp left
  EXPECT_NEAR(rest, 0.049, 0.0015);
  m.halt_superimposed.Deceleration = 1000.0;
  m.halt_superimposed.Jerk = 0.0;
  m.halt_superimposed.Execute = true;
  double steepest = 0.0, steepest_change = 0.0, velocity = m.db().Velocity;
  const int cycles = m.run_until(
      [&] {
        steepest = std::max(steepest, std::fabs(m.db().Acceleration));
        steepest_change = std::max(steepest_change, std::fabs(m.db().Velocity - velocity) / 0.001);
        velocity = m.db().Velocity;
        return m.halt_superimposed.Done;
      },
      1000);
  ASSERT_GT(cycles, 0);
  EXPECT_TRUE(m.move_superimposed.CommandAborted);
  EXPECT_LE(steepest, 1000.0 + 1e-6);
  EXPECT_LE(steepest_change, 1000.0 + 1e-6);
  EXPECT_NEAR(cycles, rest * 1000.0 + 50.0, 3.0);
  EXPECT_NEAR(m.db().StatusPositioning.SuperimposedDistance, start - 50.0 * rest - 1.25, 0.1);
  EXPECT_NEAR(m.db().Velocity, 100.0, 1e-9);
}

// Limits apply to the total motion (spec 01 §8.14, spec 02 §4.5): a base move to 150 mm plus 100 mm
// superimposed runs into the software limit at 200 mm; the look-ahead stops the total exactly there with 533
// and both jobs end with 16#8001.
TEST(MoveSuperimposed, SoftwareLimitStopsTheTotalMotion) {
  auto data = tomc::testing::linear_axis_data();
  data.PositionLimits_SW.Active = true;
  data.PositionLimits_SW.MinPosition = -50.0;
  data.PositionLimits_SW.MaxPosition = 200.0;
  SuperimposedMachine m(data);
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_absolute.Position = 150.0;
  m.move_absolute.Execute = true;
  m.move_superimposed.Distance = 100.0;
  m.move_superimposed.Execute = true;
  double highest = 0.0;
  ASSERT_GT(m.run_until(
                [&] {
                  highest = std::max(highest, m.axis->setpoint().position);
                  return m.axis->alarms().pending(tomc::techobjects::kAlarmSoftwareLimitReached);
                },
                5000),
            0);
  m.run_until(
      [&] {
        highest = std::max(highest, m.axis->setpoint().position);
        return m.db().Velocity == 0.0;
      },
      1000);
  m.run(2);
  EXPECT_TRUE(m.move_absolute.Error);
  EXPECT_EQ(m.move_absolute.ErrorID, error_id::kAbortedByAlarmReaction);
  EXPECT_TRUE(m.move_superimposed.Error);
  EXPECT_EQ(m.move_superimposed.ErrorID, error_id::kAbortedByAlarmReaction);
  EXPECT_NEAR(m.db().Position, 200.0, 1e-6);
  EXPECT_LE(highest, 200.0 + 1e-6);
}

// "Superimposed motion requires position-controlled operation" (spec 03 §4.10): 16#8108 otherwise; and the
// parameter checks of spec 03 §2.1.
TEST(MoveSuperimposed, RejectsWithoutPositionControlAndInvalidParameters) {
  SuperimposedMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 50.0;
  m.move_velocity.PositionControlled = false;
  m.move_velocity.Execute = true;
  m.run(5);
  m.move_superimposed.Distance = 5.0;
  m.move_superimposed.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_superimposed.Error);
  EXPECT_EQ(m.move_superimposed.ErrorID, error_id::kNotPositionControlled);

  SuperimposedMachine n;
  ASSERT_GT(n.enable(), 0);
  struct Case {
    double distance, velocity_diff, acceleration, deceleration, jerk;
    std::uint16_t error;
  };
  const Case cases[] = {
      {std::nan(""), -1.0, -1.0, -1.0, -1.0, error_id::kInvalidPosition},
      {5.0, 0.0, -1.0, -1.0, -1.0, error_id::kInvalidVelocity},
      {5.0, std::nan(""), -1.0, -1.0, -1.0, error_id::kInvalidVelocity},  // NaN is not "the default"
      {5.0, std::numeric_limits<double>::infinity(), -1.0, -1.0, -1.0, error_id::kInvalidVelocity},
      {5.0, -1.0, 0.0, -1.0, -1.0, error_id::kInvalidAcceleration},
      {5.0, -1.0, -1.0, 0.0, -1.0, error_id::kInvalidDeceleration},
      {5.0, -1.0, -1.0, -1.0, std::nan(""), error_id::kInvalidJerk},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.error);
    n.move_superimposed.Execute = false;
    n.run(1);
    n.move_superimposed.Distance = c.distance;
    n.move_superimposed.VelocityDiff = c.velocity_diff;
    n.move_superimposed.Acceleration = c.acceleration;
    n.move_superimposed.Deceleration = c.deceleration;
    n.move_superimposed.Jerk = c.jerk;
    n.move_superimposed.Execute = true;
    n.run(1);
    EXPECT_TRUE(n.move_superimposed.Error);
    EXPECT_EQ(n.move_superimposed.ErrorID, c.error);
  }
  EXPECT_EQ(n.db().Position, 0.0);  // no rejected job moved the axis
}

// VelocityDiff < 0 takes DynamicDefaults.Velocity (spec 01 §8.1 table): 100 mm/s on a standing axis.
TEST(MoveSuperimposed, DefaultsAndAStandingBase) {
  SuperimposedMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_superimposed.Distance = 20.0;
  m.move_superimposed.Execute = true;
  double fastest = 0.0;
  const int cycles = m.run_until(
      [&] {
        fastest = std::max(fastest, m.db().Velocity);
        return m.move_superimposed.Done;
      },
      2000);
  ASSERT_GT(cycles, 0);
  EXPECT_NEAR(fastest, 100.0, 1e-9);
  // 20 mm at 100 mm/s with 1000 mm/s² (defaults, trapezoid): 0.1 s ramp each way + 0.1 s cruise = 0.3 s.
  EXPECT_NEAR(cycles, 300, 2);
  EXPECT_NEAR(m.db().Position, 20.0, 1e-9);
  m.run(2);
  EXPECT_EQ(m.db().StatusPositioning.SuperimposedDistance, 0.0);  // no base motion: settled at once
  EXPECT_TRUE(bit(m.db().StatusWord, StatusWordBit::kDone));
}

}  // namespace
