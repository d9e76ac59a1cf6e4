// MC_MotionInSuperimposed / MC_MotionInSuperimposedAxes on the positioning axis (spec 03 §4.17.3–4.17.4,
// spec 02 §8.3, seed 004 §6.14.3), cycle by cycle: the setpoints act directly (no profile, no dynamic
// limits), Distance is the absolute superimposition (x = x_base + Distance), the falling edge keeps the
// position, the §9.19.1 row R6 / column C7 (spec 03 §6.1), StatusWord2.X6/X8, StatusMotionIn, ErrorWord.X16.
// Accounting as in motion_in_test.cpp: inputs written by the user program of cycle k are the superimposed
// setpoints of the interpolator of cycle k+1 (decision L5); MotionInSuperimposedAxes adds the superimposing
// axis' setpoint of the same cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_motion_in.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"

namespace {

using namespace tomc;
using techobjects::ErrorWordBit;
using techobjects::PositioningAxis;
using techobjects::StatusWord2Bit;
namespace eid = techobjects::error_id;

constexpr double kDt = 0.001;

techobjects::PositioningAxisData virtual_axis_data() {
  auto d = tomc::testing::linear_axis_data();
  d.VirtualAxis.Mode = techobjects::kModeOn;
  return d;
}

bool x6(const techobjects::PositioningAxisData& db) {
  return techobjects::test(db.StatusWord2, StatusWord2Bit::kMotionInSuperimposedCommand);
}
bool x7(const techobjects::PositioningAxisData& db) {
  return techobjects::test(db.StatusWord2, StatusWord2Bit::kHaltSuperimposedCommand);
}
bool x8(const techobjects::PositioningAxisData& db) {
  return techobjects::test(db.StatusWord2, StatusWord2Bit::kMotionInSuperimposedAxesCommand);
}
bool max_velocity_exceeded(const techobjects::PositioningAxisData& db) {
  return (db.StatusMotionIn.StatusWord & 1u) != 0;
}

// One positioning axis whose user program feeds MC_MotionInSuperimposed with a ramp: the k-th call with
// Enable = TRUE gives Distance = k · step and VelocityDiff = step / dt (consistent setpoints).
struct FeedMachine : tomc::testing::PositioningAxisMachine {
  explicit FeedMachine(techobjects::PositioningAxisData data = tomc::testing::linear_axis_data(),
                       bool with_drive = true)
      : PositioningAxisMachine(data, tomc::testing::linear_drive(), 3, with_drive) {
    user = [this] {
      if (feeding && mis.Enable) {
        ++calls;
        mis.Distance = offset + calls * step;
        mis.VelocityDiff = step / kDt;
      }
      mis(*axis);
    };
  }
  void start_feed(double step_per_cycle, double start = 0.0) {
    step = step_per_cycle;
    offset = start;
    calls = 0;
    feeding = true;
    mis.Enable = true;
  }
  // The base motion: MoveRelative `distance` at 50 mm/s, 500 mm/s² (0.1 s ramps) from a homed axis at 0.
  void start_base(double distance) {
    ASSERT_GT(enable(), 0);
    ASSERT_TRUE(home_at(0.0));
    move_relative.Distance = distance;
    move_relative.Velocity = 50.0;
    move_relative.Acceleration = 500.0;
    move_relative.Deceleration = 500.0;
    move_relative.Execute = true;
  }
  double superimposed_distance() const { return db().StatusPositioning.SuperimposedDistance; }

  instructions::MC_MotionInSuperimposed<PositioningAxis> mis;
  bool feeding = false;
  int calls = 0;
  double step = 0.0;
  double offset = 0.0;
};

// spec 03 §4.17.3 function diagram (① MoveRelative as the base, ② Enable_2 applies Pos_2/Vel_2 on top),
// seed 004 §6.14.3.1: "the sum of the additional path and the base position is the axis' setpoint position";
// the velocity shown is the total (spec 02 §8.3). 300 calls of +0.02 mm (20 mm/s) on a base cruising at
// 50 mm/s; the falling edge keeps 6 mm; the base ends Done at 50 and the axis at 56; SuperimposedDistance
// returns to 0 once both motions are finished.
TEST(MotionInSuperimposed, DistanceIsTheAbsoluteSuperimpositionOnTheBaseMotion) {
  FeedMachine m;
  m.start_base(50.0);
  m.run(200);  // 0.2 s: the base cruises at 50 mm/s
  ASSERT_TRUE(m.move_relative.Busy);
  m.start_feed(0.02);
  m.run(1);  // the rising edge: job accepted, the first input (0.02) written
  ASSERT_TRUE(m.mis.Busy);
  ASSERT_FALSE(m.mis.Error) << m.mis.ErrorID;
  for (int k = 1; k < 300; ++k) {
    m.run(1);  // the interpolator takes the input of the call before
    ASSERT_NEAR(m.superimposed_distance(), 0.02 * k, 1e-12) << "cycle " << k;
    ASSERT_NEAR(m.axis->superimposed().state().velocity, 20.0, 1e-9);
    ASSERT_TRUE(x6(m.db()));
  }
  EXPECT_NEAR(m.db().Velocity, 70.0, 1e-9);  // 50 base + 20 superimposed, both at constant velocity
  EXPECT_FALSE(max_velocity_exceeded(m.db()));
  EXPECT_FALSE(techobjects::test(m.db().StatusWord, techobjects::StatusWordBit::kMoveSuperimposedCommand));
  m.mis.Enable = false;
  m.run(1);  // the falling edge after the 300th input was taken
  EXPECT_FALSE(m.mis.Busy);
  EXPECT_FALSE(m.mis.CommandAborted);
  m.run(1);
  EXPECT_NEAR(m.superimposed_distance(), 6.0, 1e-12);  // the position is kept
  EXPECT_NEAR(m.db().Velocity, 50.0, 1e-9);            // the superimposed velocity is 0
  EXPECT_FALSE(x6(m.db()));
  ASSERT_GT(m.run_until([&] { return m.move_relative.Done; }, 2000), 0);
  m.run(2);
  EXPECT_NEAR(m.db().Position, 56.0, 1e-9);
  EXPECT_EQ(m.superimposed_distance(), 0.0);  // both motions finished: reset (spec 02 §8 status table)
  EXPECT_NEAR(m.db().Position, 56.0, 1e-9);   // ... and the setpoint does not move
}

// spec 02 §8.3: a MotionInSuperimposed job needs no base motion, and neither the superimposed nor the total
// motion is limited: 600 mm/s on an axis whose MaxVelocity is 500 is executed as given and flagged in
// StatusMotionIn.StatusWord.X0 MaxVelocityExceeded, which the next MotionIn job clears (decision U12).
TEST(MotionInSuperimposed, IsNotLimitedAndFlagsMaxVelocityExceeded) {
  FeedMachine m(virtual_axis_data(), false);
  ASSERT_GT(m.enable(), 0);
  m.start_feed(0.6);  // 600 mm/s
  m.run(1);
  ASSERT_TRUE(m.mis.Busy);
  m.run(10);
  EXPECT_NEAR(m.db().Velocity, 600.0, 1e-9);
  EXPECT_NEAR(m.db().Position, 6.0, 1e-9);
  EXPECT_TRUE(max_velocity_exceeded(m.db()));
  // A step is executed as given (the user answers for consistent setpoints, seed 004 §6.14.3.1).
  m.feeding = false;
  m.mis.Distance = 20.0;
  m.mis.VelocityDiff = 0.0;
  m.run(2);
  EXPECT_NEAR(m.db().Position, 20.0, 1e-9);
  EXPECT_EQ(m.db().Velocity, 0.0);
  m.mis.Enable = false;
  m.run(2);
  EXPECT_TRUE(max_velocity_exceeded(m.db()));  // a flag of the last job, kept
  m.start_feed(0.01, 20.0);
  m.run(2);
  EXPECT_FALSE(max_velocity_exceeded(m.db()));
  EXPECT_NEAR(m.db().Velocity, 10.0, 1e-9);
}

// §9.19.1 R6 x C7 = A: MC_MoveSuperimposed replaces the MotionInSuperimposed job; the move starts from the
// superimposed state (20 mm/s) and travels its Distance from the superimposed position the job had (spec 03
// §4.17.3 note 4: the current dynamics are carried into the replacing job): no velocity step.
TEST(MotionInSuperimposed, MoveSuperimposedReplacesItFromItsState) {
  FeedMachine m(virtual_axis_data(), false);
  ASSERT_GT(m.enable(), 0);
  m.start_feed(0.02);
  m.run(101);  // 100 inputs taken: 2 mm at 20 mm/s
  ASSERT_NEAR(m.superimposed_distance(), 2.0, 1e-12);
  m.move_superimposed.Distance = 10.0;
  m.move_superimposed.VelocityDiff = 40.0;
  m.move_superimposed.Acceleration = 500.0;
  m.move_superimposed.Deceleration = 500.0;
  m.move_superimposed.Execute = true;
  m.run(1);  // the MoveSuperimposed edge, in the user program before MotionIn's call
  ASSERT_TRUE(m.move_superimposed.Busy);
  m.run(1);
  EXPECT_TRUE(m.mis.CommandAborted);
  EXPECT_FALSE(m.mis.Busy);
  EXPECT_FALSE(x6(m.db()));
  double last_v = m.db().Velocity;
  const int cycles = m.run_until(
      [&] {
        EXPECT_LE(std::fabs(m.db().Velocity - last_v), 500.0 * kDt + 1e-9);
        last_v = m.db().Velocity;
        return m.move_superimposed.Done;
      },
      2000);
  ASSERT_GT(cycles, 0);
  // 2 mm before the job, the 0.02 mm the replaced job's last input added, then the job's 10 mm; the base
  // stands at 0, so both motions are finished and the superimposition joined it (SuperimposedDistance 0).
  EXPECT_NEAR(m.db().Position, 12.02, 1e-9);
  EXPECT_EQ(m.superimposed_distance(), 0.0);
}

// §9.19.1 R4 x C7 = A: a base job (MC_MoveVelocity) aborts MotionInSuperimposed; its superimposed velocity
// goes over into the base motion, which ramps from 20 to 30 mm/s with the job's acceleration.
TEST(MotionInSuperimposed, ABaseJobAbortsItAndTakesItsVelocityOver) {
  FeedMachine m(virtual_axis_data(), false);
  ASSERT_GT(m.enable(), 0);
  m.start_feed(0.02);
  m.run(50);
  m.move_velocity.Velocity = 30.0;
  m.move_velocity.Acceleration = 100.0;
  m.move_velocity.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.move_velocity.Busy);
  m.run(1);
  EXPECT_TRUE(m.mis.CommandAborted);
  double last_v = m.db().Velocity;
  EXPECT_NEAR(last_v, 20.1, 1e-9);  // 20 + one cycle of 100 mm/s²
  const int cycles = m.run_until(
      [&] {
        EXPECT_LE(std::fabs(m.db().Velocity - last_v), 100.0 * kDt + 1e-9);
        last_v = m.db().Velocity;
        return m.move_velocity.InVelocity;
      },
      500);
  EXPECT_GT(cycles, 0);
  EXPECT_NEAR(m.db().Velocity, 30.0, 1e-9);
}

// §9.19.1 R3 x C7 = "-": MC_Halt Mode 1 stops the base motion only; the MotionInSuperimposed job goes on.
TEST(MotionInSuperimposed, HaltMode1LeavesItRunning) {
  FeedMachine m;
  m.start_base(50.0);
  m.run(200);
  m.start_feed(0.01);
  m.run(20);
  m.halt.Mode = 1;
  m.halt.Deceleration = 500.0;
  m.halt.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.halt.Done; }, 500), 0);
  EXPECT_TRUE(m.mis.Busy);
  EXPECT_TRUE(m.move_relative.CommandAborted);
  m.run(1);
  EXPECT_NEAR(m.db().Velocity, 10.0, 1e-9);  // the superimposed 10 mm/s alone
  EXPECT_TRUE(x6(m.db()));
}

// spec 03 §4.17.3 note 4: MC_HaltSuperimposed (AbortAcceleration = FALSE) brakes the superimposed motion from
// its velocity and acceleration; the acceleration is ramped down through the jerk, not stepped.
TEST(MotionInSuperimposed, HaltSuperimposedRampsItsAccelerationDownThroughTheJerk) {
  FeedMachine m(virtual_axis_data(), false);
  ASSERT_GT(m.enable(), 0);
  m.feeding = false;
  m.mis.Enable = true;
  m.mis.AccelerationDiff = 100.0;
  // An accelerating superimposition: x = a t² / 2, v = a t, a = 100 mm/s², fed for 0.2 s.
  for (int k = 1; k <= 200; ++k) {
    const double t = k * kDt;
    m.mis.Distance = 50.0 * t * t;
    m.mis.VelocityDiff = 100.0 * t;
    m.run(1);
  }
  m.halt_superimposed.Deceleration = 200.0;
  m.halt_superimposed.Jerk = 10000.0;
  m.halt_superimposed.AbortAcceleration = false;
  m.halt_superimposed.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.halt_superimposed.Busy);
  m.run(1);
  EXPECT_TRUE(m.mis.CommandAborted);
  EXPECT_TRUE(x7(m.db()));
  double last_a = m.axis->superimposed().state().acceleration;
  EXPECT_GT(last_a, 100.0 - 10000.0 * kDt - 1e-9);  // from +100, not from 0 or -200
  const int cycles = m.run_until(
      [&] {
        const double a = m.axis->superimposed().state().acceleration;
        EXPECT_LE(std::fabs(a - last_a), 10000.0 * kDt + 1e-6);
        last_a = a;
        return m.halt_superimposed.Done;
      },
      2000);
  ASSERT_GT(cycles, 0);
  EXPECT_EQ(m.axis->superimposed().state().velocity, 0.0);
  EXPECT_FALSE(x7(m.db()));
}

// A setpoint that is not a number ends the job with Error 16#8186; the superimposed part brakes with
// DynamicDefaults (1000 mm/s²) instead of jumping (decision U11); no MC_HaltSuperimposed bit shows.
TEST(MotionInSuperimposed, NonFiniteSetpointEndsItWithErrorAndTheSuperimpositionBrakes) {
  FeedMachine m(virtual_axis_data(), false);
  ASSERT_GT(m.enable(), 0);
  m.start_feed(0.05);  // 50 mm/s
  m.run(20);
  m.feeding = false;
  m.mis.VelocityDiff = std::numeric_limits<double>::quiet_NaN();
  m.run(1);
  EXPECT_TRUE(m.mis.Error);
  EXPECT_EQ(m.mis.ErrorID, eid::kInvalidMotionInSetpoint);
  EXPECT_FALSE(m.mis.Busy);
  double last_v = m.db().Velocity;
  const int cycles = m.run_until(
      [&] {
        EXPECT_FALSE(x7(m.db()));
        EXPECT_LE(m.db().Velocity, last_v + 1e-12);
        EXPECT_GE(last_v - m.db().Velocity, 0.0);
        EXPECT_LE(last_v - m.db().Velocity, 1000.0 * kDt + 1e-9);
        last_v = m.db().Velocity;
        return m.db().Velocity == 0.0;
      },
      200);
  EXPECT_GE(cycles, 45);  // 50 mm/s at 1000 mm/s²: 50 cycles
  EXPECT_FALSE(x6(m.db()));
  // At the rising edge a non-finite input is rejected at once.
  m.mis.Enable = false;
  m.run(1);
  m.mis.Distance = std::numeric_limits<double>::infinity();
  m.mis.VelocityDiff = 0.0;
  m.mis.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.mis.Error);
  EXPECT_EQ(m.mis.ErrorID, eid::kInvalidMotionInSetpoint);
}

// Superimposed motion needs position-controlled operation (spec 02 §2.3): 16#8108 without it.
TEST(MotionInSuperimposed, NeedsPositionControl) {
  FeedMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 10.0;
  m.move_velocity.PositionControlled = false;
  m.move_velocity.Execute = true;
  m.run(5);
  m.start_feed(0.01);
  m.run(1);
  EXPECT_TRUE(m.mis.Error);
  EXPECT_EQ(m.mis.ErrorID, eid::kNotPositionControlled);
  EXPECT_TRUE(m.move_velocity.Busy);  // rejected: the running job is untouched
}

// ---- MC_MotionInSuperimposedAxes ----

// TO_1 (base motion), TO_2 (its possible superimposing axis) and TO_3 (the same base motion as TO_1, never
// superimposed: TO_1's base without reading TO_1's internals); virtual axes, 1 ms. TO_1 is added first, so
// the runtime's ordering, not the order of addition, makes TO_2 run before it.
struct TwoAxes {
  explicit TwoAxes(bool configure = true) : runtime(techobjects::RuntimeConfig{kDt, 1, 1}) {
    to1 = &runtime.emplace<PositioningAxis>("TO_1", nullptr, virtual_axis_data());
    to2 = &runtime.emplace<PositioningAxis>("TO_2", nullptr, virtual_axis_data());
    to3 = &runtime.emplace<PositioningAxis>("TO_3", nullptr, virtual_axis_data());
    if (configure) to1->add_possible_superimposing_axis(*to2);
    runtime.set_user_program([this](techobjects::Runtime&) {
      power1(*to1);
      power2(*to2);
      power3(*to3);
      home1(*to1);
      home2(*to2);
      home3(*to3);
      abs1(*to1);
      abs3(*to3);
      rel2(*to2);
      reset1(*to1);
      axes(*to1);
    });
    runtime.start();
  }
  void run(int n) {
    for (int i = 0; i < n; ++i)
      runtime.step();
  }
  template <typename P>
  int run_until(P done, int limit) {
    for (int i = 1; i <= limit; ++i) {
      runtime.step();
      if (done()) return i;
    }
    return -1;
  }
  void enable_and_home() {
    power1.Enable = power2.Enable = power3.Enable = true;
    run(5);
    ASSERT_TRUE(power1.Status && power2.Status && power3.Status);
    home1.Mode = home2.Mode = home3.Mode = 0;
    home1.Execute = home2.Execute = home3.Execute = true;
    run(1);
    home1.Execute = home2.Execute = home3.Execute = false;
    run(1);
  }
  // A1 on TO_1 and the same job on TO_3: MoveAbsolute to `position` at 100 mm/s (1000 mm/s²).
  void move_base(double position) {
    for (auto* fb : {&abs1, &abs3}) {
      fb->Position = position;
      fb->Velocity = 100.0;
      fb->Execute = false;
    }
    run(1);
    abs1.Execute = abs3.Execute = true;
  }
  // A3 on TO_2: MoveRelative `distance` at 100 mm/s.
  void move_superimposing(double distance) {
    rel2.Execute = false;
    run(1);
    rel2.Distance = distance;
    rel2.Velocity = 100.0;
    rel2.Execute = true;
  }
  const techobjects::PositioningAxisData& db1() const { return to1->data(); }

  techobjects::Runtime runtime;
  PositioningAxis* to1 = nullptr;
  PositioningAxis* to2 = nullptr;
  PositioningAxis* to3 = nullptr;
  instructions::MC_Power<PositioningAxis> power1, power2, power3;
  instructions::MC_Home<PositioningAxis> home1, home2, home3;
  instructions::MC_MoveAbsolute<PositioningAxis> abs1, abs3;
  instructions::MC_MoveRelative<PositioningAxis> rel2;
  instructions::MC_Reset<PositioningAxis> reset1;
  instructions::MC_MotionInSuperimposedAxes<PositioningAxis> axes;
};

// spec 03 §4.17.4 function diagram. Section A: TO_1 MoveAbsolute 300 at 100 (A1) ①; Enable_2 (A2) ② makes
// TO_2's motion superimpose TO_1's; MoveRelative 200 at 100 on TO_2 (A3): TO_1 moves with the summed dynamics
// (200 mm/s) and reaches 500. Section B: with A1 finished and A2 active, another 200 on TO_2 ③: TO_1 reaches
// 700; Enable_2 reset ④: TO_2's motion no longer moves TO_1. Without cycle offset (seed 004 §6.14.3.2): in
// every cycle TO_1 = TO_1's base (= TO_3) + TO_2, to rounding.
TEST(MotionInSuperimposedAxes, FunctionDiagramSectionsAAndB) {
  TwoAxes m;
  m.enable_and_home();
  m.move_base(300.0);
  m.run(50);  // ①
  m.axes.SuperimposingAxis = m.to2;
  m.axes.Enable = true;  // ②
  m.run(1);
  ASSERT_TRUE(m.axes.Busy);
  ASSERT_FALSE(m.axes.Error) << m.axes.ErrorID;
  m.move_superimposing(200.0);
  double fastest = 0.0;
  const auto same_cycle = [&] {
    EXPECT_NEAR(m.to1->setpoint().position, m.to3->setpoint().position + m.to2->setpoint().position, 1e-9);
    EXPECT_NEAR(m.db1().StatusPositioning.SuperimposedDistance, m.to2->data().Position, 1e-9);
    EXPECT_TRUE(x8(m.db1()));
    EXPECT_EQ(m.db1().StatusMotionIn.ActualSuperimposingAxis, 1);
    fastest = std::max(fastest, m.db1().Velocity);
  };
  ASSERT_GT(m.run_until(
                [&] {
                  same_cycle();
                  return m.abs1.Done && m.rel2.Done;
                },
                6000),
            0);
  m.run(5);
  EXPECT_NEAR(m.db1().Position, 500.0, 1e-9);
  EXPECT_NEAR(fastest, 200.0, 1e-9);  // V_MoveAbsolute + V_MoveRelative
  // Section B ③
  m.move_superimposing(200.0);
  ASSERT_GT(m.run_until(
                [&] {
                  same_cycle();
                  return m.rel2.Done;
                },
                6000),
            0);
  m.run(5);
  EXPECT_NEAR(m.db1().Position, 700.0, 1e-9);
  EXPECT_NEAR(m.db1().StatusPositioning.SuperimposedDistance, 400.0, 1e-9);
  // ④
  m.axes.Enable = false;
  m.run(1);
  EXPECT_FALSE(m.axes.Busy);
  m.move_superimposing(100.0);
  ASSERT_GT(m.run_until([&] { return m.rel2.Done; }, 6000), 0);
  m.run(5);
  EXPECT_NEAR(m.to2->data().Position, 500.0, 1e-9);
  EXPECT_NEAR(m.db1().Position, 700.0, 1e-9);  // TO_2's motion no longer moves TO_1
  EXPECT_FALSE(x8(m.db1()));
  EXPECT_EQ(m.db1().StatusMotionIn.ActualSuperimposingAxis, 0);
  // Both motions finished: the superimposed 400 joined the base, SuperimposedDistance is 0 (spec 04 §4).
  EXPECT_EQ(m.db1().StatusPositioning.SuperimposedDistance, 0.0);
}

// "SuperimposingError: the superimposing axis given in the instruction is not configured as a possible
// superimposing axis" (spec 04 §5.3 ErrorWord.X16, seed 004 §6.14.3.2): the job is rejected with 16#8190 and
// X16 stays until MC_Reset (decision U10).
TEST(MotionInSuperimposedAxes, AnAxisNotConfiguredIsRejectedWithSuperimposingError) {
  TwoAxes m;
  m.enable_and_home();
  m.axes.SuperimposingAxis = m.to3;
  m.axes.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.axes.Error);
  EXPECT_EQ(m.axes.ErrorID, eid::kSuperimposingAxisNotConfigured);
  m.run(1);
  EXPECT_TRUE(techobjects::test(m.db1().ErrorWord, ErrorWordBit::kSuperimposingError));
  m.axes.Enable = false;
  m.reset1.Execute = true;
  m.run(2);
  EXPECT_FALSE(techobjects::test(m.db1().ErrorWord, ErrorWordBit::kSuperimposingError));
  // No interconnection configured at all: the same.
  TwoAxes n(false);
  n.enable_and_home();
  n.axes.SuperimposingAxis = n.to2;
  n.axes.Enable = true;
  n.run(1);
  EXPECT_EQ(n.axes.ErrorID, eid::kSuperimposingAxisNotConfigured);
}

// spec 03 §4.17.4 prerequisites: both TOs enabled and position-controlled: TO_2 disabled -> 16#8191.
TEST(MotionInSuperimposedAxes, TheSuperimposingAxisMustBeEnabled) {
  TwoAxes m;
  m.enable_and_home();
  m.power2.Enable = false;
  m.run(20);
  ASSERT_FALSE(m.power2.Status);
  m.axes.SuperimposingAxis = m.to2;
  m.axes.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.axes.Error);
  EXPECT_EQ(m.axes.ErrorID, eid::kSuperimposingAxisNotReady);
}

// The configuration: not the axis itself, not twice, at most kCapacity axes; a superimposition loop is a
// configuration error at Runtime::start() as a leading-value loop is (spec 07 §1.2).
TEST(MotionInSuperimposedAxes, ConfigurationErrors) {
  techobjects::Runtime runtime(techobjects::RuntimeConfig{kDt, 1, 1});
  auto& a = runtime.emplace<PositioningAxis>("A", nullptr, virtual_axis_data());
  auto& b = runtime.emplace<PositioningAxis>("B", nullptr, virtual_axis_data());
  EXPECT_THROW(a.add_possible_superimposing_axis(a), std::invalid_argument);
  a.add_possible_superimposing_axis(b);
  EXPECT_THROW(a.add_possible_superimposing_axis(b), std::invalid_argument);
  EXPECT_EQ(a.superimposing_axes().size(), 1u);
  EXPECT_EQ(a.memory_footprint(),
            b.memory_footprint() + sizeof(techobjects::SuperimposingAxisTable));  // counted
  b.add_possible_superimposing_axis(a);
  EXPECT_THROW(runtime.start(), std::logic_error);

  techobjects::Runtime many(techobjects::RuntimeConfig{kDt, 1, 1});
  auto& base = many.emplace<PositioningAxis>("Base", nullptr, virtual_axis_data());
  for (std::size_t i = 0; i < techobjects::SuperimposingAxisTable::kCapacity; ++i)
    base.add_possible_superimposing_axis(
        many.emplace<PositioningAxis>("S" + std::to_string(i), nullptr, virtual_axis_data()));
  auto& extra = many.emplace<PositioningAxis>("Extra", nullptr, virtual_axis_data());
  EXPECT_THROW(base.add_possible_superimposing_axis(extra), std::invalid_argument);
}

}  // namespace
