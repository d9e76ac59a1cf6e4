// The C ABI <tomc/tomc.h> from its caller's side: a positioning move through the generated MC_* structs, the
// real-time runner with a user program, alarms, and bad input of every kind: each a status and a message that
// names the problem, never a crash or an exception.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <string>
#include <thread>
#include <utility>

#include "build_paths.hpp"
#include "tomc/tomc.h"

namespace {

// The examples' slide: a linear positioning axis (5 mm leadscrew, 2:1 gear, 100 mm/s, 1000 mm/s²,
// software limits -10 .. 300 mm) on the simulated drive with telegram 3.
constexpr const char* kSlide = R"({
  "cycle_time": 0.001,
  "technology_objects": [
    {"name": "Slide", "type": "TO_PositioningAxis",
     "config": {"Mechanics.LeadScrew": 5.0, "LoadGear.Numerator": 2, "LoadGear.Denominator": 1,
                "DynamicLimits.MaxJerk": 0.0, "DynamicLimits.MaxVelocity": 120.0, "DynamicLimits.Velocity": 120.0,
                "DynamicDefaults.Velocity": 100.0, "DynamicDefaults.Acceleration": 1000.0,
                "DynamicDefaults.Deceleration": 1000.0, "PositionLimits_SW.Active": true,
                "PositionLimits_SW.MinPosition": -10.0, "PositionLimits_SW.MaxPosition": 300.0},
     "drive": {"adapter": "simulated", "telegram": 3, "load_inertia_kgm2": 1.0e-4}},
    {"name": "Conveyor", "type": "TO_SpeedAxis", "drive": {"adapter": "simulated", "telegram": 1}}
  ]
})";

std::string last_error() {
  return tomc_last_error();
}

// The runtime of `machine` and, for each {name, &object}, that TO of it (use in ASSERT_NO_FATAL_FAILURE).
void create_with_objects(const char* machine, tomc_runtime*& runtime,
                         std::initializer_list<std::pair<const char*, tomc_object**>> objects) {
  ASSERT_EQ(tomc_runtime_create(machine, &runtime), TOMC_OK) << last_error();
  for (const auto& [name, object] : objects)
    ASSERT_EQ(tomc_runtime_find_object(runtime, name, object), TOMC_OK) << name << ": " << last_error();
}

struct Machine {
  tomc_runtime* runtime = nullptr;
  tomc_object* slide = nullptr;
  tomc_object* conveyor = nullptr;
  Machine() {
    EXPECT_EQ(tomc_runtime_create(kSlide, &runtime), TOMC_OK) << last_error();
    EXPECT_EQ(tomc_runtime_find_object(runtime, "Slide", &slide), TOMC_OK) << last_error();
    EXPECT_EQ(tomc_runtime_find_object(runtime, "Conveyor", &conveyor), TOMC_OK) << last_error();
  }
  ~Machine() { tomc_runtime_destroy(runtime); }
};

// MC_Power and then MC_Home (set position 0) on the Slide, called after every cycle until homed.
void enable_and_home(const Machine& m, tomc_MC_Power& power, tomc_MC_Home& home) {
  power.Enable = true;
  for (int k = 0; k < 200 && !home.Done; ++k) {
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_Power_call(m.slide, &power), TOMC_OK) << last_error();
    home.Execute = power.Status;
    ASSERT_EQ(tomc_MC_Home_call(m.slide, &home), TOMC_OK) << last_error();
  }
  ASSERT_TRUE(home.Done);
}

// MC_Power, MC_Home (set position 0) and MC_MoveAbsolute, called after every cycle as a user program would.
struct PositioningProgram {
  tomc_MC_Power power;
  tomc_MC_Home home;
  tomc_MC_MoveAbsolute move;
  explicit PositioningProgram(double target) {
    tomc_MC_Power_init(&power);
    tomc_MC_Home_init(&home);
    tomc_MC_MoveAbsolute_init(&move);
    power.Enable = true;
    move.Position = target;
  }
  tomc_status operator()(tomc_object* axis) {
    tomc_status s = tomc_MC_Power_call(axis, &power);
    home.Execute = power.Status;
    if (s == TOMC_OK) s = tomc_MC_Home_call(axis, &home);
    move.Execute = home.Done;
    if (s == TOMC_OK) s = tomc_MC_MoveAbsolute_call(axis, &move);
    return s;
  }
};

// MC_Power Enable = TRUE on `object`, one call after each cycle, until Status (at most 200 cycles).
bool enabled(tomc_runtime* runtime, tomc_object* object, tomc_MC_Power& power) {
  power.Enable = true;
  for (int k = 0; k < 200 && !power.Status; ++k) {
    if (tomc_runtime_step(runtime, 1) != TOMC_OK || tomc_MC_Power_call(object, &power) != TOMC_OK)
      return false;
  }
  return power.Status;
}

double read(const tomc_object* o, const char* path) {
  double value = std::nan("");
  EXPECT_EQ(tomc_read_lreal(o, path, &value), TOMC_OK) << last_error();
  return value;
}

bool read_bit(const tomc_object* o, const char* path) {
  bool value = false;
  EXPECT_EQ(tomc_read_bool(o, path, &value), TOMC_OK) << last_error();
  return value;
}

// Decisions E3 (the generated MC_* structs) and E2; spec 03 §4.1, §4.3, §4.5.
TEST(CApi, PositioningMoveThroughTheGeneratedStructs) {
  Machine m;
  PositioningProgram program(200.0);
  int cycles = 0;
  for (; cycles < 5000 && !program.move.Done && !program.move.Error; ++cycles) {
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK) << last_error();
    ASSERT_EQ(program(m.slide), TOMC_OK) << last_error();
  }
  EXPECT_TRUE(program.move.Done);
  EXPECT_FALSE(program.move.Error) << program.move.ErrorID;
  EXPECT_NEAR(read(m.slide, "Position"), 200.0, 1e-9);
  EXPECT_NEAR(read(m.slide, "ActualPosition"), 200.0, 0.01);
  // 2.1 s of motion at 100 mm/s and 1000 mm/s², after enabling and homing.
  EXPECT_GT(cycles, 2100);
  bool enabled = false;
  EXPECT_EQ(tomc_read_bool(m.slide, "StatusWord.X0", &enabled), TOMC_OK) << last_error();
  EXPECT_TRUE(enabled);
  int64_t status_word = 0;
  EXPECT_EQ(tomc_read_int(m.slide, "StatusWord", &status_word), TOMC_OK) << last_error();
  EXPECT_EQ(status_word & 1, 1);
  uint64_t count = 0;
  EXPECT_EQ(tomc_runtime_cycle_count(m.runtime, &count), TOMC_OK);
  EXPECT_EQ(count, static_cast<uint64_t>(cycles));
}

// The host controller's door (spec 03 §4.17, decision L5): a CNC that interpolates itself feeds the axis its
// setpoints every cycle through MC_MotionInPosition; each is the TO's setpoint (Position, Velocity) in the
// next MC_Interpolator, without profile and without dynamic limits. Here a sine of 2 mm amplitude at 2 Hz
// (peak 25.1 mm/s, 316 mm/s²) after enabling; the falling edge of Enable keeps the last position with
// velocity 0. A step beyond the permitted following error is the host's mistake: alarm 521.
TEST(CApi, MotionInPositionFeedsTheHostsSetpointsEveryCycle) {
  Machine m;
  tomc_MC_Power power;
  tomc_MC_Home home;
  tomc_MC_MotionInPosition feed;
  tomc_MC_Power_init(&power);
  tomc_MC_Home_init(&home);
  tomc_MC_MotionInPosition_init(&feed);
  EXPECT_FALSE(feed.Enable);  // the manual's defaults (generate.py's table)
  EXPECT_EQ(feed.Position, 0.0);
  ASSERT_NO_FATAL_FAILURE(enable_and_home(m, power, home));
  const double pi = std::acos(-1.0);
  const auto x = [&](int k) { return 2.0 * std::sin(2.0 * pi * 2.0 * k * 0.001); };
  const auto v = [&](int k) { return 2.0 * 2.0 * pi * 2.0 * std::cos(2.0 * pi * 2.0 * k * 0.001); };
  feed.Enable = true;
  for (int k = 0; k <= 1000; ++k) {
    feed.Position = x(k);
    feed.Velocity = v(k);
    ASSERT_EQ(tomc_MC_MotionInPosition_call(m.slide, &feed), TOMC_OK) << last_error();
    ASSERT_TRUE(feed.Busy) << k;
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK) << last_error();
    ASSERT_NEAR(read(m.slide, "Position"), x(k), 1e-12) << k;  // written before the cycle: its setpoint
    ASSERT_NEAR(read(m.slide, "Velocity"), v(k), 1e-12) << k;
  }
  int64_t function_state = 0;
  EXPECT_EQ(tomc_read_int(m.slide, "StatusMotionIn.FunctionState", &function_state), TOMC_OK) << last_error();
  EXPECT_EQ(function_state, 2);
  EXPECT_NEAR(read(m.slide, "ActualPosition"), x(1000), 0.1);  // the drive follows (Kv lag only)
  feed.Enable = false;
  ASSERT_EQ(tomc_MC_MotionInPosition_call(m.slide, &feed), TOMC_OK);
  EXPECT_FALSE(feed.Busy);
  ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
  EXPECT_NEAR(read(m.slide, "Position"), x(1000), 1e-12);
  EXPECT_EQ(read(m.slide, "Velocity"), 0.0);
  // A setpoint that is not a number is refused with an ErrorID, never taken.
  feed.Enable = true;
  feed.Position = std::nan("");
  ASSERT_EQ(tomc_MC_MotionInPosition_call(m.slide, &feed), TOMC_OK);
  EXPECT_TRUE(feed.Error);
  EXPECT_NE(feed.ErrorID, 0);
  feed.Enable = false;
  ASSERT_EQ(tomc_MC_MotionInPosition_call(m.slide, &feed), TOMC_OK);
  // A 50 mm step: alarm 521 (following error), the TO disabled, the job ended with Error.
  feed.Enable = true;
  feed.Position = 50.0;
  feed.Velocity = 0.0;
  for (int k = 0; k < 100; ++k) {
    ASSERT_EQ(tomc_MC_MotionInPosition_call(m.slide, &feed), TOMC_OK);
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
    ASSERT_EQ(tomc_MC_Power_call(m.slide, &power), TOMC_OK);
  }
  EXPECT_TRUE(feed.Error);
  EXPECT_FALSE(power.Status);
  int64_t alarm = 0;
  EXPECT_EQ(tomc_read_int(m.slide, "ErrorDetail.Number", &alarm), TOMC_OK) << last_error();
  EXPECT_EQ(alarm, 521);
}

// A host that superimposes one axis on another (spec 03 §4.17.4, seed 004 §6.14.3.2): the machine file names
// Feeder as a possible superimposing axis of Carriage ("SuperimposingAxes"), MC_MotionInSuperimposedAxes
// adds Feeder's setpoint to Carriage's base motion in the same cycle, and an axis not configured so is
// refused with 16#8190. MC_MotionInSuperimposed feeds a superimposition of the host's own.
TEST(CApi, MotionInSuperimposedAxesAddsTheConfiguredAxisInTheSameCycle) {
  constexpr const char* kTwoAxes = R"({
    "cycle_time": 0.001,
    "technology_objects": [
      {"name": "Feeder", "type": "TO_PositioningAxis", "config": {"VirtualAxis.Mode": 1}},
      {"name": "Other", "type": "TO_PositioningAxis", "config": {"VirtualAxis.Mode": 1}},
      {"name": "Carriage", "type": "TO_PositioningAxis", "config": {"VirtualAxis.Mode": 1},
       "SuperimposingAxes": ["Feeder"]}
    ]
  })";
  tomc_runtime* runtime = nullptr;
  tomc_object* feeder = nullptr;
  tomc_object* other = nullptr;
  tomc_object* carriage = nullptr;
  ASSERT_NO_FATAL_FAILURE(create_with_objects(
      kTwoAxes, runtime, {{"Feeder", &feeder}, {"Other", &other}, {"Carriage", &carriage}}));
  tomc_MC_Power p1, p2, p3;
  tomc_MC_MoveVelocity jog;
  tomc_MC_MotionInSuperimposedAxes axes;
  tomc_MC_MotionInSuperimposed own;
  for (auto* p : {&p1, &p2, &p3}) {
    tomc_MC_Power_init(p);
    p->Enable = true;
  }
  tomc_MC_MoveVelocity_init(&jog);
  tomc_MC_MotionInSuperimposedAxes_init(&axes);
  tomc_MC_MotionInSuperimposed_init(&own);
  for (int k = 0; k < 5; ++k) {
    ASSERT_EQ(tomc_runtime_step(runtime, 1), TOMC_OK);
    ASSERT_EQ(tomc_MC_Power_call(feeder, &p1), TOMC_OK);
    ASSERT_EQ(tomc_MC_Power_call(other, &p2), TOMC_OK);
    ASSERT_EQ(tomc_MC_Power_call(carriage, &p3), TOMC_OK);
  }
  ASSERT_TRUE(p1.Status && p2.Status && p3.Status);
  // Not a configured superimposing axis: refused, ErrorWord.X16.
  axes.SuperimposingAxis = other;
  axes.Enable = true;
  ASSERT_EQ(tomc_MC_MotionInSuperimposedAxes_call(carriage, &axes), TOMC_OK) << last_error();
  EXPECT_TRUE(axes.Error);
  EXPECT_EQ(axes.ErrorID, 0x8190);
  axes.Enable = false;
  ASSERT_EQ(tomc_MC_MotionInSuperimposedAxes_call(carriage, &axes), TOMC_OK);
  // Feeder: superimposed on Carriage, then moved at 40 mm/s.
  axes.SuperimposingAxis = feeder;
  axes.Enable = true;
  ASSERT_EQ(tomc_MC_MotionInSuperimposedAxes_call(carriage, &axes), TOMC_OK);
  ASSERT_TRUE(axes.Busy) << axes.ErrorID;
  jog.Velocity = 40.0;
  jog.Execute = true;
  ASSERT_EQ(tomc_MC_MoveVelocity_call(feeder, &jog), TOMC_OK);
  for (int k = 0; k < 300; ++k) {
    ASSERT_EQ(tomc_runtime_step(runtime, 1), TOMC_OK);
    ASSERT_EQ(tomc_MC_MotionInSuperimposedAxes_call(carriage, &axes), TOMC_OK);
    ASSERT_NEAR(read(carriage, "Position"), read(feeder, "Position"), 1e-9) << k;  // no cycle offset
  }
  EXPECT_NEAR(read(carriage, "Velocity"), 40.0, 1e-9);
  EXPECT_NEAR(read(carriage, "StatusPositioning.SuperimposedDistance"), read(feeder, "Position"), 1e-9);
  // The falling edge keeps the superimposed position; Feeder goes on alone.
  axes.Enable = false;
  ASSERT_EQ(tomc_MC_MotionInSuperimposedAxes_call(carriage, &axes), TOMC_OK);
  const double kept = read(carriage, "Position");
  ASSERT_EQ(tomc_runtime_step(runtime, 10), TOMC_OK);
  EXPECT_NEAR(read(carriage, "Position"), kept, 1e-9);
  EXPECT_GT(read(feeder, "Position"), kept);
  // Both motions finished: the superimposition joined the base (SuperimposedDistance 0). The host's own
  // superimposition: Distance is absolute (x = x_base + Distance).
  EXPECT_EQ(read(carriage, "StatusPositioning.SuperimposedDistance"), 0.0);
  own.Enable = true;
  own.Distance = 1.0;
  ASSERT_EQ(tomc_MC_MotionInSuperimposed_call(carriage, &own), TOMC_OK) << last_error();
  ASSERT_TRUE(own.Busy) << own.ErrorID;
  ASSERT_EQ(tomc_runtime_step(runtime, 1), TOMC_OK);
  EXPECT_NEAR(read(carriage, "Position"), kept + 1.0, 1e-9);
  tomc_runtime_destroy(runtime);
}

// MC_MotionInVelocity through the C ABI on a positioning and on a speed axis (spec 03 §4.17.1).
TEST(CApi, MotionInVelocityOnPositioningAndSpeedAxes) {
  Machine m;
  tomc_MC_Power power;
  tomc_MC_MotionInVelocity feed;
  tomc_MC_Power_init(&power);
  tomc_MC_MotionInVelocity_init(&feed);
  EXPECT_TRUE(feed.PositionControlled);
  ASSERT_TRUE(enabled(m.runtime, m.slide, power));
  feed.Enable = true;
  feed.Velocity = 30.0;
  ASSERT_EQ(tomc_MC_MotionInVelocity_call(m.slide, &feed), TOMC_OK) << last_error();
  ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
  EXPECT_EQ(read(m.slide, "Velocity"), 30.0);
  // spec 03 §4.17.1: also an instruction of the speed axis (decision U14); MC_MotionInPosition is not.
  tomc_MC_Power conveyor_power;
  tomc_MC_MotionInVelocity conveyor_feed;
  tomc_MC_MotionInPosition position_feed;
  tomc_MC_Power_init(&conveyor_power);
  tomc_MC_MotionInVelocity_init(&conveyor_feed);
  tomc_MC_MotionInPosition_init(&position_feed);
  ASSERT_TRUE(enabled(m.runtime, m.conveyor, conveyor_power));
  conveyor_feed.Enable = true;
  conveyor_feed.Velocity = 120.0;
  ASSERT_EQ(tomc_MC_MotionInVelocity_call(m.conveyor, &conveyor_feed), TOMC_OK) << last_error();
  EXPECT_TRUE(conveyor_feed.Busy);
  ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
  EXPECT_EQ(read(m.conveyor, "Velocity"), 120.0);
  EXPECT_EQ(tomc_MC_MotionInPosition_call(m.conveyor, &position_feed), TOMC_ERROR_WRONG_OBJECT_TYPE);
}

// MC_MoveSuperimposed through the C ABI (spec 03 §4.10): 20 mm superimposed on the 200 mm base move end at
// 220 mm, both Done; then MC_HaltSuperimposed without a superimposed motion is Done at once (spec 01 §8.14).
TEST(CApi, SuperimposedMoveThroughTheGeneratedStructs) {
  Machine m;
  PositioningProgram program(200.0);
  tomc_MC_MoveSuperimposed superimposed;
  tomc_MC_MoveSuperimposed_init(&superimposed);
  EXPECT_EQ(superimposed.VelocityDiff, -1.0);
  superimposed.Distance = 20.0;
  superimposed.VelocityDiff = 20.0;
  int cycles = 0;
  for (; cycles < 8000 && !(program.move.Done && superimposed.Done); ++cycles) {
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK) << last_error();
    ASSERT_EQ(program(m.slide), TOMC_OK) << last_error();
    superimposed.Execute = superimposed.Execute || program.move.Busy;  // once the base move runs
    ASSERT_EQ(tomc_MC_MoveSuperimposed_call(m.slide, &superimposed), TOMC_OK) << last_error();
    ASSERT_FALSE(superimposed.Error) << superimposed.ErrorID;
  }
  EXPECT_TRUE(program.move.Done);
  EXPECT_TRUE(superimposed.Done);
  EXPECT_NEAR(read(m.slide, "Position"), 220.0, 1e-9);
  tomc_MC_HaltSuperimposed halt;
  tomc_MC_HaltSuperimposed_init(&halt);
  halt.Execute = true;
  ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK) << last_error();
  ASSERT_EQ(tomc_MC_HaltSuperimposed_call(m.slide, &halt), TOMC_OK) << last_error();
  EXPECT_TRUE(halt.Done);
  EXPECT_FALSE(halt.Busy);
  // A speed axis has no superimposed motion (spec 01 §1.3 table).
  EXPECT_EQ(tomc_MC_HaltSuperimposed_call(m.conveyor, &halt), TOMC_ERROR_WRONG_OBJECT_TYPE);
}

// MC_TorqueAdditive and MC_TorqueRange through the C structs (spec 03 §4.18.1/§4.18.2) on a drive with
// supplementary telegram 750: StatusTorqueData shows them; the speed axis without 750 rejects with 16#8144.
TEST(CApi, TorqueJobsOnTelegram750) {
  tomc_runtime* runtime = nullptr;
  ASSERT_EQ(tomc_runtime_create(R"({"cycle_time": 0.001, "technology_objects": [
      {"name": "Winder", "type": "TO_PositioningAxis",
       "drive": {"adapter": "simulated", "telegram": 3, "supplementary_telegram": 750}},
      {"name": "Conveyor", "type": "TO_SpeedAxis", "drive": {"adapter": "simulated", "telegram": 1}}]})",
                                &runtime),
            TOMC_OK)
      << last_error();
  tomc_object* winder = nullptr;
  tomc_object* conveyor = nullptr;
  ASSERT_EQ(tomc_runtime_find_object(runtime, "Winder", &winder), TOMC_OK);
  ASSERT_EQ(tomc_runtime_find_object(runtime, "Conveyor", &conveyor), TOMC_OK);
  tomc_MC_Power power;
  tomc_MC_TorqueAdditive additive;
  tomc_MC_TorqueRange range;
  tomc_MC_TorqueRange conveyor_range;
  tomc_MC_Power_init(&power);
  tomc_MC_TorqueAdditive_init(&additive);
  tomc_MC_TorqueRange_init(&range);
  tomc_MC_TorqueRange_init(&conveyor_range);
  EXPECT_EQ(range.UpperLimit, 1.0e12);  // the manual's defaults
  EXPECT_EQ(range.LowerLimit, -1.0e12);
  power.Enable = true;
  additive.Value = 0.75;
  range.UpperLimit = 2.0;
  range.LowerLimit = -1.0;
  conveyor_range.Enable = true;
  for (int k = 0; k < 200; ++k) {
    ASSERT_EQ(tomc_runtime_step(runtime, 1), TOMC_OK) << last_error();
    additive.Enable = power.Status;
    range.Enable = power.Status;
    ASSERT_EQ(tomc_MC_Power_call(winder, &power), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_TorqueAdditive_call(winder, &additive), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_TorqueRange_call(winder, &range), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_TorqueRange_call(conveyor, &conveyor_range), TOMC_OK) << last_error();
  }
  EXPECT_TRUE(additive.Busy);
  EXPECT_TRUE(range.Busy);
  EXPECT_EQ(read(winder, "StatusTorqueData.TotalTorqueAdditive"), 0.75);
  int64_t active = 0;
  EXPECT_EQ(tomc_read_int(winder, "StatusTorqueData.CommandTorqueRangeActive", &active), TOMC_OK);
  EXPECT_EQ(active, 1);
  EXPECT_TRUE(conveyor_range.Error);
  EXPECT_EQ(conveyor_range.ErrorID, 0x8144);
  tomc_runtime_destroy(runtime);
}

// Decision E4; spec 04 §0.2 (the access column: DIR/CAL writable, RON/RES not).
TEST(CApi, WritesFollowTheManualsAccessRules) {
  Machine m;
  // DIR: written by the user program, effective at the next MC_Servo.
  EXPECT_EQ(tomc_write_lreal(m.slide, "Override.Velocity", 50.0), TOMC_OK) << last_error();
  EXPECT_EQ(read(m.slide, "Override.Velocity"), 50.0);
  // Out of the manual's range 0 .. 200 %: refused, the value unchanged.
  EXPECT_EQ(tomc_write_lreal(m.slide, "Override.Velocity", 250.0), TOMC_ERROR_OUT_OF_RANGE);
  EXPECT_NE(last_error().find("Slide.Override.Velocity"), std::string::npos) << last_error();
  EXPECT_NE(last_error().find("200"), std::string::npos) << last_error();
  EXPECT_EQ(read(m.slide, "Override.Velocity"), 50.0);
  EXPECT_EQ(tomc_write_lreal(m.slide, "Override.Velocity", std::nan("")), TOMC_ERROR_OUT_OF_RANGE);
  // A status variable (RON), a restart-relevant one (RES) and a status-word bit.
  EXPECT_EQ(tomc_write_lreal(m.slide, "Position", 1.0), TOMC_ERROR_ACCESS);
  EXPECT_NE(last_error().find("Slide.Position"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_write_lreal(m.slide, "Mechanics.LeadScrew", 10.0), TOMC_ERROR_ACCESS);
  EXPECT_EQ(read(m.slide, "Mechanics.LeadScrew"), 5.0);
  EXPECT_EQ(tomc_write_bool(m.slide, "StatusWord.X0", true), TOMC_ERROR_ACCESS);
  // BOOL and integers.
  EXPECT_EQ(tomc_write_bool(m.slide, "PositionLimits_SW.Active", false), TOMC_OK) << last_error();
  bool active = true;
  EXPECT_EQ(tomc_read_bool(m.slide, "PositionLimits_SW.Active", &active), TOMC_OK) << last_error();
  EXPECT_FALSE(active);
}

// Decisions E4 (typed calls refuse another type) and E2 (a message naming it).
TEST(CApi, WrongTypesAndUnknownPathsAreRefusedWithTheirNames) {
  Machine m;
  bool b = false;
  double x = 0.0;
  int64_t i = 0;
  EXPECT_EQ(tomc_read_bool(m.slide, "Position", &b), TOMC_ERROR_WRONG_TYPE);
  EXPECT_NE(last_error().find("Slide.Position is LREAL, not BOOL"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_read_lreal(m.slide, "StatusWord", &x), TOMC_ERROR_WRONG_TYPE);
  EXPECT_NE(last_error().find("DWORD"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_read_int(m.slide, "Position", &i), TOMC_ERROR_WRONG_TYPE);
  EXPECT_EQ(tomc_write_int(m.slide, "Override.Velocity", 5), TOMC_ERROR_WRONG_TYPE);
  EXPECT_EQ(tomc_write_lreal(m.slide, "PositionLimits_SW.Active", 1.0), TOMC_ERROR_WRONG_TYPE);
  EXPECT_EQ(tomc_read_lreal(m.slide, "Dynamic.Nothing", &x), TOMC_ERROR_UNKNOWN_PATH);
  EXPECT_NE(last_error().find("Slide.Dynamic.Nothing: no such variable of TO_PositioningAxis"),
            std::string::npos)
      << last_error();
  EXPECT_EQ(tomc_read_bool(m.slide, "StatusWord.X40", &b), TOMC_ERROR_UNKNOWN_PATH);
  EXPECT_EQ(tomc_write_lreal(m.slide, "", 1.0), TOMC_ERROR_UNKNOWN_PATH);
  // A speed axis has no position.
  EXPECT_EQ(tomc_read_lreal(m.conveyor, "Position", &x), TOMC_ERROR_UNKNOWN_PATH);
  EXPECT_NE(last_error().find("TO_SpeedAxis"), std::string::npos) << last_error();
  tomc_object* none = reinterpret_cast<tomc_object*>(&x);
  EXPECT_EQ(tomc_runtime_find_object(m.runtime, "Table", &none), TOMC_ERROR_UNKNOWN_OBJECT);
  EXPECT_EQ(none, nullptr);
  EXPECT_NE(last_error().find("'Table' (have: Slide, Conveyor)"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_runtime_object_at(m.runtime, 2, &none), TOMC_ERROR_UNKNOWN_OBJECT);
}

// Decision E2 (every entry point returns a status, never crashes).
TEST(CApi, NullArgumentsAreRefusedNeverDereferenced) {
  Machine m;
  double x = 0.0;
  bool b = false;
  int64_t i = 0;
  size_t n = 0;
  tomc_object* o = nullptr;
  tomc_runtime* r = nullptr;
  const auto refused = [](tomc_status s, const char* function) {
    EXPECT_EQ(s, TOMC_ERROR_NULL_ARGUMENT) << function;
    EXPECT_NE(last_error().find(function), std::string::npos) << last_error();
    EXPECT_NE(last_error().find("is NULL"), std::string::npos) << last_error();
  };
  refused(tomc_runtime_create(nullptr, &r), "tomc_runtime_create");
  refused(tomc_runtime_create(kSlide, nullptr), "tomc_runtime_create");
  refused(tomc_runtime_create_from_file(nullptr, &r), "tomc_runtime_create_from_file");
  refused(tomc_runtime_step(nullptr, 1), "tomc_runtime_step");
  refused(tomc_runtime_start(nullptr), "tomc_runtime_start");
  refused(tomc_runtime_set_user_program(nullptr, nullptr, nullptr), "tomc_runtime_set_user_program");
  refused(tomc_runtime_run_realtime(m.runtime, nullptr), "tomc_runtime_run_realtime");
  refused(tomc_runtime_stop_realtime(nullptr), "tomc_runtime_stop_realtime");
  refused(tomc_runtime_runner_statistics(m.runtime, nullptr), "tomc_runtime_runner_statistics");
  refused(tomc_runtime_object_count(nullptr, &n), "tomc_runtime_object_count");
  refused(tomc_runtime_find_object(m.runtime, nullptr, &o), "tomc_runtime_find_object");
  refused(tomc_runtime_find_object(nullptr, "Slide", &o), "tomc_runtime_find_object");
  refused(tomc_read_lreal(nullptr, "Position", &x), "tomc_read_lreal");
  refused(tomc_read_lreal(m.slide, nullptr, &x), "tomc_read_lreal");
  refused(tomc_read_lreal(m.slide, "Position", nullptr), "tomc_read_lreal");
  refused(tomc_read_bool(m.slide, "StatusWord.X0", nullptr), "tomc_read_bool");
  refused(tomc_read_int(nullptr, "StatusWord", &i), "tomc_read_int");
  refused(tomc_write_lreal(nullptr, "Override.Velocity", 1.0), "tomc_write_lreal");
  refused(tomc_write_bool(m.slide, nullptr, b), "tomc_write_bool");
  refused(tomc_object_alarm_count(nullptr, &n), "tomc_object_alarm_count");
  refused(tomc_object_alarm(m.slide, 0, nullptr), "tomc_object_alarm");
  refused(tomc_object_name(nullptr, nullptr), "tomc_object_name");
  tomc_MC_Power power;
  tomc_MC_Power_init(&power);
  refused(tomc_MC_Power_call(nullptr, &power), "MC_Power");
  refused(tomc_MC_Power_call(m.slide, nullptr), "MC_Power");
  tomc_MC_Power_init(nullptr);  // does nothing
  tomc_runtime_destroy(nullptr);
}

// Decision E2 ({size, version}: a mismatch is TOMC_ERROR_VERSION).
TEST(CApi, StructsOfAnotherLayoutAreRefused) {
  Machine m;
  tomc_MC_MoveAbsolute move;
  std::memset(&move, 0, sizeof move);  // never initialised
  move.Execute = true;
  EXPECT_EQ(tomc_MC_MoveAbsolute_call(m.slide, &move), TOMC_ERROR_VERSION);
  EXPECT_NE(last_error().find("this library expects " + std::to_string(sizeof move)), std::string::npos)
      << last_error();
  EXPECT_FALSE(move.Busy);
  tomc_MC_MoveAbsolute_init(&move);
  move.header.version = TOMC_ABI_VERSION + 1;  // a program built against a later header
  EXPECT_EQ(tomc_MC_MoveAbsolute_call(m.slide, &move), TOMC_ERROR_VERSION);
  tomc_runner_config config{{sizeof(tomc_runner_config) - 8, TOMC_ABI_VERSION}, 0, 0, -1, false};
  EXPECT_EQ(tomc_runtime_run_realtime(m.runtime, &config), TOMC_ERROR_VERSION);
  tomc_alarm alarm{};
  EXPECT_EQ(tomc_object_alarm(m.slide, 0, &alarm), TOMC_ERROR_VERSION);
}

// Decision E3 (each MC_* call takes the TO types of its table entry); spec 03 §1 (the instructions per TO).
TEST(CApi, InstructionsOfAnotherTechnologyObjectTypeAreRefused) {
  Machine m;
  tomc_MC_MoveAbsolute move;
  tomc_MC_MoveAbsolute_init(&move);
  move.Execute = true;
  EXPECT_EQ(tomc_MC_MoveAbsolute_call(m.conveyor, &move), TOMC_ERROR_WRONG_OBJECT_TYPE);
  EXPECT_NE(last_error().find("MC_MoveAbsolute: not an instruction of TO_SpeedAxis (Conveyor)"),
            std::string::npos)
      << last_error();
  tomc_MC_GearIn gear;
  tomc_MC_GearIn_init(&gear);
  EXPECT_EQ(tomc_MC_GearIn_call(m.slide, &gear), TOMC_ERROR_WRONG_OBJECT_TYPE);
  // The speed axis' own instructions work: MC_MoveVelocity at 600 1/min.
  tomc_MC_Power power;
  tomc_MC_MoveVelocity velocity;
  tomc_MC_Power_init(&power);
  tomc_MC_MoveVelocity_init(&velocity);
  power.Enable = true;
  velocity.Velocity = 600.0;
  for (int i = 0; i < 3000 && !velocity.InVelocity; ++i) {
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
    ASSERT_EQ(tomc_MC_Power_call(m.conveyor, &power), TOMC_OK) << last_error();
    velocity.Execute = power.Status;
    ASSERT_EQ(tomc_MC_MoveVelocity_call(m.conveyor, &velocity), TOMC_OK) << last_error();
  }
  EXPECT_TRUE(velocity.InVelocity);
  EXPECT_NEAR(read(m.conveyor, "Velocity"), 600.0, 1e-9);
}

// Synchronous operation through the generated structs: MC_GearIn 2/1 at rest, then MC_PhasingRelative with
// dynamic parameters (spec 07 §8 PH-1): the follower's extra travel 2·10 = 20 mm, CoveredPhaseShift 10, and
// an MC_OffsetRelative while it runs is refused with 16#808A.
TEST(CApi, PhasingAndOffsetThroughTheGeneratedStructs) {
  constexpr const char* kGearing = R"({
    "cycle_time": 0.001,
    "technology_objects": [
      {"name": "L", "type": "TO_PositioningAxis", "config": {"VirtualAxis.Mode": 1}},
      {"name": "F", "type": "TO_SynchronousAxis", "config": {"VirtualAxis.Mode": 1, "DynamicLimits.MaxJerk": 0.0},
       "LeadingValueInterconnections": [{"Leader": "L", "Coupling": "Setpoint"}]}
    ]
  })";
  tomc_runtime* runtime = nullptr;
  tomc_object* leader = nullptr;
  tomc_object* follower = nullptr;
  ASSERT_NO_FATAL_FAILURE(create_with_objects(kGearing, runtime, {{"L", &leader}, {"F", &follower}}));
  tomc_MC_Power power_l;
  tomc_MC_Power power_f;
  tomc_MC_GearIn gear;
  tomc_MC_PhasingRelative phasing;
  tomc_MC_OffsetRelative offset;
  tomc_MC_Power_init(&power_l);
  tomc_MC_Power_init(&power_f);
  tomc_MC_GearIn_init(&gear);
  tomc_MC_PhasingRelative_init(&phasing);
  tomc_MC_OffsetRelative_init(&offset);
  power_l.Enable = power_f.Enable = true;
  gear.Master = phasing.Master = leader;
  gear.RatioNumerator = 2;
  phasing.PhaseShift = 10.0;
  phasing.Velocity = 100.0;
  phasing.Acceleration = phasing.Deceleration = 1000.0;
  phasing.Jerk = 0.0;
  offset.Offset = 1.0;
  offset.OffsetDistance = 10.0;
  uint16_t offset_error = 0;
  for (int cycle = 0; cycle < 600; ++cycle) {
    ASSERT_EQ(tomc_runtime_step(runtime, 1), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_Power_call(leader, &power_l), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_Power_call(follower, &power_f), TOMC_OK) << last_error();
    gear.Execute = power_l.Status && power_f.Status;
    ASSERT_EQ(tomc_MC_GearIn_call(follower, &gear), TOMC_OK) << last_error();
    phasing.Execute = gear.InGear;
    ASSERT_EQ(tomc_MC_PhasingRelative_call(follower, &phasing), TOMC_OK) << last_error();
    offset.Execute = phasing.StartPhasing;
    ASSERT_EQ(tomc_MC_OffsetRelative_call(follower, &offset), TOMC_OK) << last_error();
    if (offset.Error) offset_error = offset.ErrorID;
  }
  EXPECT_TRUE(phasing.Done);
  EXPECT_NEAR(phasing.CoveredPhaseShift, 10.0, 1e-12);
  EXPECT_NEAR(read(follower, "Position"), 20.0, 1e-9);
  EXPECT_EQ(offset_error, 0x808A);
  // StatusSynchronizedMotion by the manual's path (spec 07 §1.9), with its types, read only (RON).
  EXPECT_DOUBLE_EQ(read(follower, "StatusSynchronizedMotion.PhaseShift"), 10.0);
  EXPECT_DOUBLE_EQ(read(follower, "StatusSynchronizedMotion.FunctionLeadingValue.Position"),
                   read(leader, "Position") + 10.0);
  int64_t function_state = 0;
  int64_t actual_master = 0;
  EXPECT_EQ(tomc_read_int(follower, "StatusSynchronizedMotion.FunctionState", &function_state), TOMC_OK)
      << last_error();
  EXPECT_EQ(function_state, 1);  // MC_GearIn
  EXPECT_EQ(tomc_read_int(follower, "StatusSynchronizedMotion.ActualMaster", &actual_master), TOMC_OK)
      << last_error();
  EXPECT_EQ(actual_master, 1);  // the first possible leading value
  EXPECT_FALSE(read_bit(follower, "StatusSynchronizedMotion.StatusWord.X3"));
  bool flag = false;
  double x = 0.0;
  EXPECT_EQ(tomc_read_bool(follower, "StatusSynchronizedMotion.PhaseShift", &flag), TOMC_ERROR_WRONG_TYPE);
  EXPECT_NE(last_error().find("is LREAL"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_read_lreal(follower, "StatusSynchronizedMotion.FunctionState", &x), TOMC_ERROR_WRONG_TYPE);
  EXPECT_EQ(tomc_read_lreal(follower, "StatusSynchronizedMotion.NoSuchMember", &x), TOMC_ERROR_UNKNOWN_PATH);
  EXPECT_EQ(tomc_read_lreal(leader, "StatusSynchronizedMotion.PhaseShift", &x), TOMC_ERROR_UNKNOWN_PATH);
  EXPECT_EQ(tomc_write_lreal(follower, "StatusSynchronizedMotion.PhaseShift", 1.0), TOMC_ERROR_ACCESS);
  // MC_SynchronizedMotionSimulation through its generated struct (spec 07 §4.4): the gearing goes on while
  // the follower is disabled; a new MC_GearIn meanwhile is refused with 16#8076.
  tomc_MC_SynchronizedMotionSimulation simulation;
  tomc_MC_SynchronizedMotionSimulation_init(&simulation);
  simulation.Enable = true;
  ASSERT_EQ(tomc_MC_SynchronizedMotionSimulation_call(follower, &simulation), TOMC_OK) << last_error();
  EXPECT_TRUE(simulation.InSimulation) << simulation.ErrorID;
  power_f.Enable = false;
  for (int cycle = 0; cycle < 5; ++cycle) {
    ASSERT_EQ(tomc_runtime_step(runtime, 1), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_Power_call(follower, &power_f), TOMC_OK) << last_error();
    ASSERT_EQ(tomc_MC_GearIn_call(follower, &gear), TOMC_OK) << last_error();
  }
  EXPECT_FALSE(power_f.Status);
  EXPECT_TRUE(gear.InGear);
  EXPECT_TRUE(read_bit(follower, "StatusSynchronizedMotion.StatusWord.X3"));  // InSimulation
  tomc_MC_GearIn again;
  tomc_MC_GearIn_init(&again);
  again.Master = leader;
  again.Execute = true;
  ASSERT_EQ(tomc_MC_GearIn_call(follower, &again), TOMC_OK) << last_error();
  EXPECT_EQ(again.ErrorID, 0x8076);
  tomc_runtime_destroy(runtime);
}

// Decision E2; docs/scenarios.md "Exit status and messages" (every problem with its path).
TEST(CApi, MalformedConfigurationsGiveEveryProblemWithItsPath) {
  tomc_runtime* r = reinterpret_cast<tomc_runtime*>(&r);
  EXPECT_EQ(tomc_runtime_create("{\"technology_objects\": [", &r), TOMC_ERROR_CONFIG);
  EXPECT_EQ(r, nullptr);
  EXPECT_NE(last_error().find("not valid JSON"), std::string::npos) << last_error();
  // A number beyond a double (found by machine_config_fuzzer: it was TOMC_ERROR_INTERNAL).
  EXPECT_EQ(tomc_runtime_create(R"({"cycle_time": 2e308, "technology_objects": []})", &r), TOMC_ERROR_CONFIG);
  EXPECT_NE(last_error().find("number overflow"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_runtime_create("[1, 2]", &r), TOMC_ERROR_CONFIG);
  EXPECT_EQ(tomc_runtime_create("{}", &r), TOMC_ERROR_CONFIG);
  EXPECT_NE(last_error().find("technology_objects: expected a non-empty array"), std::string::npos)
      << last_error();
  EXPECT_EQ(tomc_runtime_create(R"({"cycle_time": 5, "technology_objects": [
      {"name": "Slide", "type": "TO_PositioningAxis",
       "config": {"Mechanics.LeadScrew": -5.0, "Mechanics.Nothing": 1, "Position": 3.0},
       "drive": {"adapter": "simulated", "telegram": 3}},
      {"name": "Slide", "type": "TO_Nothing"}], "extra": 1})",
                                &r),
            TOMC_ERROR_CONFIG);
  EXPECT_EQ(r, nullptr);
  const std::string e = last_error();
  for (const char* path : {"extra:", "cycle_time:", "technology_objects[0].config.Mechanics.LeadScrew:",
                           "technology_objects[0].config.Mechanics.Nothing:",
                           "technology_objects[0].config.Position:", "technology_objects[1]"}) {
    EXPECT_NE(e.find(path), std::string::npos) << path << " missing in:\n" << e;
  }
  // A cam's problems with their paths too (cams are TOs of the C ABI since issue 19).
  EXPECT_EQ(tomc_runtime_create(R"({"cycle_time": 0.001, "technology_objects": [
      {"name": "Knife", "type": "TO_Cam_10k", "Points": [[0, 0], [360]]}]})",
                                &r),
            TOMC_ERROR_CONFIG);
  EXPECT_NE(last_error().find("technology_objects[0].Points[1]"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_runtime_create_from_file("/nonexistent/machine.json", &r), TOMC_ERROR_SYSTEM);
  EXPECT_NE(last_error().find("/nonexistent/machine.json: cannot open"), std::string::npos) << last_error();
}

// Decisions E1 (the machine loader in libtomc) and C22 (TO_Cam as a tomc_object).
TEST(CApi, TheExamplesMachineFilesLoad) {
  // With their cams (the demo's knife, the rotary knife's cut cam): TO_Cam objects since issue 19.
  for (const char* file : {"positioning_machine.json", "gearing_machine.json", "flying_saw.json",
                           "demo_machine.json", "rotary_knife.json"}) {
    tomc_runtime* r = nullptr;
    // Appended, not `std::string(...) + "/" + file`: with the tests' precompiled header GCC 12 reports a
    // false -Warray-bounds inside libstdc++'s operator+ for some path lengths (a known GCC 12 false
    // positive).
    std::string path = TOMC_EXAMPLES_DIR;
    path.append("/").append(file);
    EXPECT_EQ(tomc_runtime_create_from_file(path.c_str(), &r), TOMC_OK) << file << ": " << last_error();
    size_t count = 0;
    EXPECT_EQ(tomc_runtime_object_count(r, &count), TOMC_OK);
    EXPECT_GE(count, 1u) << file;
    tomc_runtime_destroy(r);
  }
  // The rotary knife's cut cam is a TO_Cam of the C ABI, interpolated by the file ("Interpolate": true).
  tomc_runtime* r = nullptr;
  std::string path = TOMC_EXAMPLES_DIR;
  path.append("/rotary_knife.json");
  ASSERT_EQ(tomc_runtime_create_from_file(path.c_str(), &r), TOMC_OK) << last_error();
  tomc_object* cam = nullptr;
  ASSERT_EQ(tomc_runtime_find_object(r, "CutCam", &cam), TOMC_OK) << last_error();
  tomc_object_type type = TOMC_TO_SPEED_AXIS;
  ASSERT_EQ(tomc_object_type_of(cam, &type), TOMC_OK);
  EXPECT_EQ(type, TOMC_TO_CAM);
  tomc_runtime_destroy(r);
}

// Decision E2; spec 02 §1.3 (technology alarms), docs/errors.md.
TEST(CApi, AlarmsOfTheTechnologyObject) {
  Machine m;
  PositioningProgram program(400.0);  // beyond the software limit switch at 300 mm
  for (int i = 0; i < 6000 && !program.move.Error && !program.move.Done; ++i) {
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
    ASSERT_EQ(program(m.slide), TOMC_OK) << last_error();
  }
  EXPECT_TRUE(program.move.Error);
  size_t count = 0;
  ASSERT_EQ(tomc_object_alarm_count(m.slide, &count), TOMC_OK);
  ASSERT_EQ(count, 1u);
  tomc_alarm alarm = {TOMC_STRUCT_HEADER(tomc_alarm), 0, 0, 0, 0, 0};
  ASSERT_EQ(tomc_object_alarm(m.slide, 0, &alarm), TOMC_OK) << last_error();
  EXPECT_EQ(alarm.number, 533u);  // software limit switch reached
  EXPECT_EQ(alarm.reaction, 2u);  // stop with maximum dynamic values
  EXPECT_GT(alarm.raised_cycle, 0u);
  EXPECT_EQ(tomc_object_alarm(m.slide, 1, &alarm), TOMC_ERROR_OUT_OF_RANGE);
  // MC_Reset acknowledges it.
  tomc_MC_Reset reset;
  tomc_MC_Reset_init(&reset);
  reset.Execute = true;
  for (int i = 0; i < 100 && !reset.Done; ++i) {
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
    ASSERT_EQ(tomc_MC_Reset_call(m.slide, &reset), TOMC_OK) << last_error();
  }
  EXPECT_TRUE(reset.Done);
  ASSERT_EQ(tomc_object_alarm_count(m.slide, &count), TOMC_OK);
  EXPECT_EQ(count, 0u);
}

struct RealtimeProgram {
  tomc_object* slide = nullptr;
  PositioningProgram program{10.0};
  std::atomic<bool> done{false};
  std::atomic<int> failures{0};
};

void realtime_user_program(tomc_runtime*, void* context) {
  auto* p = static_cast<RealtimeProgram*>(context);
  if (p->program(p->slide) != TOMC_OK) p->failures.fetch_add(1);
  if (p->program.move.Done) p->done.store(true);
}

// Decision E5 (only the runner's thread uses the TOs while it runs).
TEST(CApi, RealTimeRunnerRunsTheUserProgramInItsThread) {
  Machine m;
  RealtimeProgram program;
  program.slide = m.slide;
  ASSERT_EQ(tomc_runtime_set_user_program(m.runtime, realtime_user_program, &program), TOMC_OK);
  tomc_runner_config config = {TOMC_STRUCT_HEADER(tomc_runner_config), 0, 0, 0, false};
  config.fifo_priority = 120;
  EXPECT_EQ(tomc_runtime_run_realtime(m.runtime, &config), TOMC_ERROR_OUT_OF_RANGE);
  config.fifo_priority = 0;
  config.cpu = -2;
  EXPECT_EQ(tomc_runtime_run_realtime(m.runtime, &config), TOMC_ERROR_OUT_OF_RANGE);
  config.cpu = 0;
  ASSERT_EQ(tomc_runtime_run_realtime(m.runtime, &config), TOMC_OK) << last_error();
  // While it runs, the TOs belong to the runner's thread.
  double x = 0.0;
  EXPECT_EQ(tomc_read_lreal(m.slide, "Position", &x), TOMC_ERROR_STATE);
  EXPECT_NE(last_error().find("user program"), std::string::npos) << last_error();
  EXPECT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_ERROR_STATE);
  EXPECT_EQ(tomc_runtime_run_realtime(m.runtime, &config), TOMC_ERROR_STATE);
  tomc_MC_Halt halt;
  tomc_MC_Halt_init(&halt);
  EXPECT_EQ(tomc_MC_Halt_call(m.slide, &halt), TOMC_ERROR_STATE);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!program.done.load() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(tomc_runtime_stop_realtime(m.runtime), TOMC_OK) << last_error();
  EXPECT_TRUE(program.done.load());
  EXPECT_EQ(program.failures.load(), 0);
  EXPECT_NEAR(read(m.slide, "Position"), 10.0, 1e-9);
  tomc_runner_statistics statistics;
  std::memset(&statistics, 0, sizeof statistics);
  statistics.header = tomc_struct_header TOMC_STRUCT_HEADER(tomc_runner_statistics);
  ASSERT_EQ(tomc_runtime_runner_statistics(m.runtime, &statistics), TOMC_OK) << last_error();
  EXPECT_GT(statistics.cycles, 100u);
  uint64_t cycles = 0;
  EXPECT_EQ(tomc_runtime_cycle_count(m.runtime, &cycles), TOMC_OK);
  EXPECT_EQ(cycles, statistics.cycles);
  // Stepped again in this thread after the runner.
  EXPECT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK) << last_error();
  EXPECT_EQ(tomc_runtime_stop_realtime(m.runtime), TOMC_ERROR_STATE);
  EXPECT_EQ(tomc_runtime_set_user_program(m.runtime, nullptr, nullptr), TOMC_ERROR_STATE);
}

// One HTTP/1.0 GET on 127.0.0.1: the whole answer.
std::string http_get(int port, const std::string& path) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return {};
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::string answer;
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) {
    const std::string request =
        "GET " + path + " HTTP/1.0\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n\r\n";
    if (::write(fd, request.data(), request.size()) == static_cast<ssize_t>(request.size())) {
      char buffer[4096];
      for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;)
        answer.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  return answer;
}

// Issue 15 (docs/embedding.md "The C ABI"): the diagnostics server of a C runtime; decision E5.
TEST(CApi, DiagnosticsServerServesTheMachine) {
  Machine m;
  tomc_diagnostics_config config = {TOMC_STRUCT_HEADER(tomc_diagnostics_config), nullptr, 70000, nullptr};
  EXPECT_EQ(tomc_runtime_serve_diagnostics(m.runtime, &config), TOMC_ERROR_OUT_OF_RANGE);
  int32_t port = 0;
  EXPECT_EQ(tomc_runtime_diagnostics_port(m.runtime, &port), TOMC_ERROR_STATE);
  config.port = 0;  // any free port on 127.0.0.1
  ASSERT_EQ(tomc_runtime_serve_diagnostics(m.runtime, &config), TOMC_OK) << last_error();
  EXPECT_EQ(tomc_runtime_serve_diagnostics(m.runtime, &config), TOMC_ERROR_STATE);
  ASSERT_EQ(tomc_runtime_diagnostics_port(m.runtime, &port), TOMC_OK);
  EXPECT_GT(port, 0);
  ASSERT_EQ(tomc_runtime_step(m.runtime, 20), TOMC_OK);
  const std::string objects = http_get(port, "/api/objects");
  EXPECT_NE(objects.find("200 OK"), std::string::npos) << objects.substr(0, 200);
  EXPECT_NE(objects.find("\"Slide\""), std::string::npos);
  EXPECT_NE(objects.find("\"Conveyor\""), std::string::npos);
  ASSERT_EQ(tomc_runtime_stop_diagnostics(m.runtime), TOMC_OK);
  EXPECT_EQ(http_get(port, "/api/objects"), "");  // nobody listens any more
  EXPECT_EQ(tomc_runtime_stop_diagnostics(m.runtime), TOMC_ERROR_STATE);
  EXPECT_EQ(tomc_runtime_step(m.runtime, 5), TOMC_OK);  // the cycle goes on without the server
}

// Decision E2 (tomc_status and its names).
TEST(CApi, StatusNamesAndVersion) {
  EXPECT_STREQ(tomc_status_name(TOMC_ERROR_WRONG_TYPE), "TOMC_ERROR_WRONG_TYPE");
  EXPECT_STREQ(tomc_status_name(static_cast<tomc_status>(99)), "TOMC_ERROR_UNKNOWN_STATUS");
  EXPECT_STREQ(tomc_version(), "0.1.0");
}

// MC_PositionProfile through the C ABI (spec 03 §4.7): the host fills tomc_time_position_profile (the layout
// of tomc's point structure, decision L1) and the Slide follows it relatively: 40 mm in 0.5 s, Done at the
// end, StatusWord2.X9 while the job runs. A profile with one point is refused with 16#8180.
TEST(CApi, PositionProfileFollowsTheHostsTimePositionPoints) {
  Machine m;
  tomc_MC_Power power;
  tomc_MC_Home home;
  tomc_MC_Power_init(&power);
  tomc_MC_Home_init(&home);
  ASSERT_NO_FATAL_FAILURE(enable_and_home(m, power, home));
  tomc_time_position_profile points;
  std::memset(&points, 0, sizeof(points));
  points.NumberOfPoints = 4;
  points.Point[0] = {0.0, 0.0};
  points.Point[1] = {0.1, 5.0};
  points.Point[2] = {0.4, 35.0};
  points.Point[3] = {0.5, 40.0};
  tomc_MC_PositionProfile profile;
  tomc_MC_PositionProfile_init(&profile);
  EXPECT_EQ(profile.TimePosition, nullptr);  // the manual's defaults (generate.py's table)
  EXPECT_EQ(profile.ProfileReference, 0);
  const double x0 = read(m.slide, "Position");
  profile.TimePosition = &points;
  profile.Execute = true;
  bool x9 = false;
  for (int k = 0; k < 1000 && !profile.Done; ++k) {
    ASSERT_EQ(tomc_MC_PositionProfile_call(m.slide, &profile), TOMC_OK) << last_error();
    ASSERT_FALSE(profile.Error) << profile.ErrorID;
    ASSERT_EQ(tomc_runtime_step(m.runtime, 1), TOMC_OK);
    int64_t sw2 = 0;
    ASSERT_EQ(tomc_read_int(m.slide, "StatusWord2", &sw2), TOMC_OK);
    x9 = x9 || ((sw2 >> 9) & 1) != 0;
  }
  EXPECT_TRUE(profile.Done);
  EXPECT_TRUE(x9);
  EXPECT_NEAR(read(m.slide, "Position"), x0 + 40.0, 1e-9);
  points.NumberOfPoints = 1;
  profile.Execute = false;
  ASSERT_EQ(tomc_MC_PositionProfile_call(m.slide, &profile), TOMC_OK);
  profile.Execute = true;
  ASSERT_EQ(tomc_MC_PositionProfile_call(m.slide, &profile), TOMC_OK);
  EXPECT_TRUE(profile.Error);
  EXPECT_EQ(profile.ErrorID, 0x8180);
}

}  // namespace

namespace {

// Steps one cycle, then calls each given instruction with its TO (the program of a PLC cycle).
template <typename... Calls>
void cycle(tomc_runtime* runtime, Calls&&... calls) {
  ASSERT_EQ(tomc_runtime_step(runtime, 1), TOMC_OK) << last_error();
  for (const tomc_status status : {calls()...})
    ASSERT_EQ(status, TOMC_OK) << last_error();
}

}  // namespace

// Cams through the C ABI (issue 19): a TO_Cam from the machine file, its instructions with the cam as their
// technology object (MC_InterpolateCam, MC_GetCamFollowingValue/LeadingValue, MC_CopyCamData; spec 07 §3.2,
// §3.6) and a follower cammed from C (MC_CamIn profile 2, MC_CamOut profile 5; spec 07 §3.4, §3.5): the cam
// C of spec 07 §8 "Camming", (0, 0), (180, 100), (360, 0), linear.
TEST(CApi, CammingAFollowerFromC) {
  constexpr const char* kCamming = R"({
    "cycle_time": 0.001,
    "technology_objects": [
      {"name": "L", "type": "TO_PositioningAxis", "config": {"VirtualAxis.Mode": 1}},
      {"name": "F", "type": "TO_SynchronousAxis", "config": {"VirtualAxis.Mode": 1, "DynamicLimits.MaxJerk": 0.0},
       "LeadingValueInterconnections": [{"Leader": "L", "Coupling": "Setpoint"}]},
      {"name": "C", "type": "TO_Cam", "Points": [[0, 0], [180, 100], [360, 0]]}
    ]
  })";
  tomc_runtime* runtime = nullptr;
  tomc_object* leader = nullptr;
  tomc_object* follower = nullptr;
  tomc_object* cam = nullptr;
  ASSERT_NO_FATAL_FAILURE(
      create_with_objects(kCamming, runtime, {{"L", &leader}, {"F", &follower}, {"C", &cam}}));
  tomc_object_type type = TOMC_TO_SPEED_AXIS;
  ASSERT_EQ(tomc_object_type_of(cam, &type), TOMC_OK);
  EXPECT_EQ(type, TOMC_TO_CAM);

  // Not interpolated after the download (spec 07 §3.2): the read instruction says so (16#8150, decision C3).
  tomc_MC_GetCamFollowingValue following;
  tomc_MC_GetCamFollowingValue_init(&following);
  following.Execute = true;
  following.LeadingValue = 90.0;
  ASSERT_EQ(tomc_MC_GetCamFollowingValue_call(cam, &following), TOMC_OK) << last_error();
  EXPECT_EQ(following.ErrorID, 0x8150);
  following.Execute = false;
  ASSERT_EQ(tomc_MC_GetCamFollowingValue_call(cam, &following), TOMC_OK) << last_error();
  tomc_MC_InterpolateCam interpolate;
  tomc_MC_InterpolateCam_init(&interpolate);
  interpolate.Execute = true;
  ASSERT_EQ(tomc_MC_InterpolateCam_call(cam, &interpolate), TOMC_OK) << last_error();
  EXPECT_TRUE(interpolate.Done) << interpolate.ErrorID;
  EXPECT_EQ(read_bit(cam, "StatusWord.X5"), true);  // Interpolated
  int64_t points = 0;
  ASSERT_EQ(tomc_read_int(cam, "StatusCam.NumberOfValidPoints", &points), TOMC_OK) << last_error();
  EXPECT_EQ(points, 3);
  following.Execute = true;
  following.SlaveScaling = 2.0;
  ASSERT_EQ(tomc_MC_GetCamFollowingValue_call(cam, &following), TOMC_OK) << last_error();
  EXPECT_TRUE(following.Done);
  EXPECT_DOUBLE_EQ(following.Value, 100.0);  // 2·f(90)
  EXPECT_DOUBLE_EQ(following.FirstDerivative, 2.0 * 100.0 / 180.0);
  // MC_GetCamFollowingValueCyclic (spec 07 §3.6): each call reads its own LeadingValue; outside the cam
  // 16#8064.
  tomc_MC_GetCamFollowingValueCyclic cyclic;
  tomc_MC_GetCamFollowingValueCyclic_init(&cyclic);
  cyclic.Enable = true;
  for (const auto& [x, y] : {std::pair{90.0, 50.0}, std::pair{270.0, 50.0}, std::pair{360.0, 0.0}}) {
    cyclic.LeadingValue = x;
    ASSERT_EQ(tomc_MC_GetCamFollowingValueCyclic_call(cam, &cyclic), TOMC_OK) << last_error();
    EXPECT_TRUE(cyclic.Valid && cyclic.Busy) << x;
    EXPECT_DOUBLE_EQ(cyclic.Value, y) << x;
  }
  cyclic.LeadingValue = 361.0;
  ASSERT_EQ(tomc_MC_GetCamFollowingValueCyclic_call(cam, &cyclic), TOMC_OK) << last_error();
  EXPECT_FALSE(cyclic.Valid);
  EXPECT_EQ(cyclic.ErrorID, 0x8064);
  // spec 07 §3.6 example: following value 0.5·100 from approach 225: direction 1 -> 270, 2 -> 90.
  tomc_MC_GetCamLeadingValue leading;
  tomc_MC_GetCamLeadingValue_init(&leading);
  leading.Execute = true;
  leading.FollowingValue = 50.0;
  leading.ApproachLeadingValue = 225.0;
  leading.ApproachDirection = 2;
  ASSERT_EQ(tomc_MC_GetCamLeadingValue_call(cam, &leading), TOMC_OK) << last_error();
  EXPECT_NEAR(leading.Value, 90.0, 1e-9) << leading.ErrorID;
  // The instructions of an axis are not the cam's, nor the cam's an axis' (TOMC_ERROR_WRONG_OBJECT_TYPE).
  EXPECT_EQ(tomc_MC_InterpolateCam_call(follower, &interpolate), TOMC_ERROR_WRONG_OBJECT_TYPE);
  tomc_MC_Power power_l;
  tomc_MC_Power_init(&power_l);
  EXPECT_EQ(tomc_MC_Power_call(cam, &power_l), TOMC_ERROR_WRONG_OBJECT_TYPE);

  tomc_MC_Power power_f;
  tomc_MC_Home home;
  tomc_MC_MoveRelative move;
  tomc_MC_CamIn cam_in;
  tomc_MC_CamOut cam_out;
  tomc_MC_Power_init(&power_f);
  tomc_MC_Home_init(&home);
  tomc_MC_MoveRelative_init(&move);
  tomc_MC_CamIn_init(&cam_in);
  tomc_MC_CamOut_init(&cam_out);
  power_l.Enable = power_f.Enable = true;
  auto program = [&] {
    cycle(
        runtime, [&] { return tomc_MC_Power_call(leader, &power_l); },
        [&] { return tomc_MC_Power_call(follower, &power_f); },
        [&] { return tomc_MC_Home_call(follower, &home); },
        [&] { return tomc_MC_MoveRelative_call(leader, &move); },
        [&] { return tomc_MC_CamIn_call(follower, &cam_in); },
        [&] { return tomc_MC_CamOut_call(follower, &cam_out); });
  };
  for (int i = 0; i < 5; ++i)
    program();
  home.Execute = true;  // MC_CamIn needs a homed follower (spec 07 §3.4)
  program();
  ASSERT_TRUE(home.Done) << home.ErrorID;
  // MC_CamIn.Cam must be a TO_Cam.
  cam_in.Master = leader;
  cam_in.Cam = leader;
  cam_in.Execute = true;
  EXPECT_EQ(tomc_MC_CamIn_call(follower, &cam_in), TOMC_ERROR_WRONG_OBJECT_TYPE);
  EXPECT_NE(last_error().find("MC_CamIn.Cam: not a TO_Cam"), std::string::npos) << last_error();
  // Profile 2, cyclic (CM-1 without scaling): synchronous at once; the leader moves 90: F = f(90) = 50.
  cam_in.Cam = cam;
  cam_in.SyncProfileReference = 2;
  cam_in.ApplicationMode = 1;
  program();
  ASSERT_TRUE(cam_in.InSync) << std::hex << cam_in.ErrorID;
  EXPECT_EQ(read_bit(cam, "StatusWord.X0"), true);  // in use
  move.Distance = 90.0;
  move.Velocity = 100.0;
  move.Execute = true;
  for (int i = 0; i < 3000 && !move.Done; ++i)
    program();
  ASSERT_TRUE(move.Done);
  program();
  EXPECT_NEAR(read(follower, "Position"), 50.0, 1e-9);
  EXPECT_TRUE(read_bit(follower, "StatusWord.X22"));  // Synchronous
  // A cam in use is not interpolated (16#80AB); MC_CopyCamData is allowed and takes effect with the next
  // MC_InterpolateCam (spec 07 §3.6).
  interpolate.Execute = false;
  ASSERT_EQ(tomc_MC_InterpolateCam_call(cam, &interpolate), TOMC_OK);
  interpolate.Execute = true;
  ASSERT_EQ(tomc_MC_InterpolateCam_call(cam, &interpolate), TOMC_OK);
  EXPECT_EQ(interpolate.ErrorID, 0x80AB);
  const tomc_cam_point line[] = {{0.0, 0.0}, {360.0, 360.0}};
  tomc_MC_CopyCamData copy;
  tomc_MC_CopyCamData_init(&copy);
  copy.ArrayOfPoints = line;
  copy.ArrayOfPointsLength = 2;
  copy.NumberOfPoints = 2;
  copy.Execute = true;
  ASSERT_EQ(tomc_MC_CopyCamData_call(cam, &copy), TOMC_OK) << last_error();
  EXPECT_TRUE(copy.Done) << std::hex << copy.ErrorID;
  EXPECT_EQ(read_bit(cam, "StatusWord.X4"), true);  // CamDataChanged
  // More points than the array holds: refused, nothing read beyond it (16#8151, decision C3).
  tomc_MC_CopyCamData beyond;
  tomc_MC_CopyCamData_init(&beyond);
  beyond.ArrayOfPoints = line;
  beyond.ArrayOfPointsLength = 2;
  beyond.NumberOfPoints = 3;
  beyond.Execute = true;
  ASSERT_EQ(tomc_MC_CopyCamData_call(cam, &beyond), TOMC_OK) << last_error();
  EXPECT_EQ(beyond.ErrorID, 0x8151);
  // MC_CamOut profile 5 against an active camming: Done, the camming goes on (spec 07 §3.5).
  cam_out.SyncProfileReference = 5;
  cam_out.Execute = true;
  program();
  EXPECT_TRUE(cam_out.Done) << std::hex << cam_out.ErrorID;
  EXPECT_TRUE(cam_in.InSync);
  // MC_CamIn's EndOfProfile: through the end of the cam at 360 (leader 90 -> 400).
  bool end_of_profile = false;
  move.Execute = false;
  program();
  move.Distance = 310.0;
  move.Velocity = 1000.0;
  move.Execute = true;
  for (int i = 0; i < 3000 && !move.Done; ++i) {
    program();
    end_of_profile = end_of_profile || cam_in.EndOfProfile;
  }
  EXPECT_TRUE(end_of_profile);
  EXPECT_NEAR(read(follower, "Position"), 40.0 * 100.0 / 180.0, 1e-9);  // f(40) in the second period
  // The copied line after the camming ends (MC_Halt releases the cam) and MC_InterpolateCam.
  tomc_MC_Halt halt;
  tomc_MC_Halt_init(&halt);
  halt.Execute = true;
  ASSERT_EQ(tomc_MC_Halt_call(follower, &halt), TOMC_OK) << last_error();
  program();
  EXPECT_TRUE(cam_in.CommandAborted);
  EXPECT_EQ(read_bit(cam, "StatusWord.X0"), false);
  interpolate.Execute = false;
  ASSERT_EQ(tomc_MC_InterpolateCam_call(cam, &interpolate), TOMC_OK);
  interpolate.Execute = true;
  ASSERT_EQ(tomc_MC_InterpolateCam_call(cam, &interpolate), TOMC_OK);
  EXPECT_TRUE(interpolate.Done) << std::hex << interpolate.ErrorID;
  following.Execute = false;
  ASSERT_EQ(tomc_MC_GetCamFollowingValue_call(cam, &following), TOMC_OK);
  following.Execute = true;
  following.SlaveScaling = 1.0;
  ASSERT_EQ(tomc_MC_GetCamFollowingValue_call(cam, &following), TOMC_OK);
  EXPECT_DOUBLE_EQ(following.Value, 90.0);
  tomc_runtime_destroy(runtime);
}

// MC_PositionProfile with the manual's TimePosition, a TO_Cam (spec 03 §4.7, seed 004 §6.8.4, decision L8),
// from C: the cam handle goes into tomc's input TimePositionCam (decision U15). Cam P5 is the VDI 2143
// Polynomial5 from (0 s, 0 mm) to (1 s, 40 mm), y(t) = 40 (10t³ − 15t⁴ + 6t⁵), at rest at both ends; the
// relative job follows it at once: profile time n ms after the n-th cycle following the edge, y(0.25) =
// 4.140625 mm, y(0.5) = 20 mm at 75 mm/s, 40 mm at rest after 1 s. A cam not interpolated: 16#8150. Not a
// TO_Cam, or a cam beside the point structure: TOMC_ERROR_WRONG_OBJECT_TYPE with the input's name.
// spec 03 §4.7, seed 004 §6.8.4; decisions L8, U15.
TEST(CApi, PositionProfileFollowsATOCamFromC) {
  constexpr const char* kProfile = R"({
    "cycle_time": 0.001,
    "technology_objects": [
      {"name": "P5", "type": "TO_Cam",
       "MotionLaws": [{"law": "Polynomial5", "x0": 0, "y0": 0, "x1": 1, "y1": 40}], "Interpolate": true},
      {"name": "Raw", "type": "TO_Cam", "Points": [[0, 0], [1, 10]]},
      {"name": "Slide", "type": "TO_PositioningAxis", "config": {"VirtualAxis.Mode": 1, "DynamicLimits.MaxJerk": 0.0}}
    ]
  })";
  tomc_runtime* runtime = nullptr;
  tomc_object* p5 = nullptr;
  tomc_object* raw = nullptr;
  tomc_object* slide = nullptr;
  ASSERT_NO_FATAL_FAILURE(
      create_with_objects(kProfile, runtime, {{"P5", &p5}, {"Raw", &raw}, {"Slide", &slide}}));
  tomc_MC_Power power;
  tomc_MC_Power_init(&power);
  power.Enable = true;
  for (int i = 0; i < 5; ++i)
    cycle(runtime, [&] { return tomc_MC_Power_call(slide, &power); });
  ASSERT_TRUE(power.Status);

  tomc_MC_PositionProfile profile;
  tomc_MC_PositionProfile_init(&profile);
  EXPECT_EQ(profile.TimePositionCam, nullptr);  // default: the point structure's input decides
  profile.Execute = true;
  profile.TimePositionCam = slide;
  EXPECT_EQ(tomc_MC_PositionProfile_call(slide, &profile), TOMC_ERROR_WRONG_OBJECT_TYPE);
  EXPECT_NE(last_error().find("MC_PositionProfile.TimePositionCam: not a TO_Cam"), std::string::npos)
      << last_error();
  tomc_time_position_profile points;
  std::memset(&points, 0, sizeof(points));
  points.NumberOfPoints = 2;
  points.Point[1] = {1.0, 10.0};
  profile.TimePosition = &points;
  profile.TimePositionCam = p5;
  EXPECT_EQ(tomc_MC_PositionProfile_call(slide, &profile), TOMC_ERROR_WRONG_OBJECT_TYPE);
  EXPECT_NE(last_error().find("MC_PositionProfile.TimePositionCam: TimePosition is given too"),
            std::string::npos)
      << last_error();
  profile.TimePosition = nullptr;

  profile.TimePositionCam = raw;  // not interpolated (spec 07 §3.2)
  ASSERT_EQ(tomc_MC_PositionProfile_call(slide, &profile), TOMC_OK) << last_error();
  EXPECT_TRUE(profile.Error);
  EXPECT_EQ(profile.ErrorID, 0x8150);
  profile.Execute = false;
  cycle(runtime, [&] { return tomc_MC_PositionProfile_call(slide, &profile); });

  profile.TimePositionCam = p5;
  profile.Execute = true;
  const double x0 = read(slide, "Position");
  ASSERT_EQ(tomc_MC_PositionProfile_call(slide, &profile), TOMC_OK) << last_error();
  ASSERT_TRUE(profile.Busy) << std::hex << profile.ErrorID;
  const auto follow = [&](int cycles) {
    for (int i = 0; i < cycles; ++i)
      cycle(runtime, [&] { return tomc_MC_PositionProfile_call(slide, &profile); });
  };
  follow(250);
  EXPECT_TRUE(read_bit(slide, "StatusWord2.X9"));  // PositionProfile active
  EXPECT_NEAR(read(slide, "Position") - x0, 4.140625, 1e-9);
  follow(250);
  EXPECT_NEAR(read(slide, "Position") - x0, 20.0, 1e-9);
  EXPECT_NEAR(read(slide, "Velocity"), 75.0, 1e-9);
  follow(500);
  EXPECT_NEAR(read(slide, "Position") - x0, 40.0, 1e-9);
  EXPECT_NEAR(read(slide, "Velocity"), 0.0, 1e-9);
  for (int i = 0; i < 200 && !profile.Done; ++i)
    follow(1);
  EXPECT_TRUE(profile.Done) << std::hex << profile.ErrorID;
  EXPECT_FALSE(profile.Error);
  tomc_runtime_destroy(runtime);
}
