// Real-time discipline of TO_PositioningAxis (issue 5): after Runtime::start(), MC_Servo, MC_Interpolator and
// the MC_* instructions allocate nothing, whatever the axis does. A counting global operator new watches five
// axes (linear on telegram 3 with software and hardware limit switches, linear on telegram 105 with DSC and
// a jerk limit, rotary modulo, virtual, simulated) while a scripted user program runs them through every job
// kind in a loop: MC_Power on/off with each StopMode, direct homing (also during motion), MC_MoveAbsolute
// with an appended MC_MoveRelative, a new MC_MoveAbsolute every few cycles (replanning from motion),
// MC_MoveVelocity with override changes, MC_Halt, MC_Stop Modes 0/1/2, MC_MoveJog both ways, the software
// limit stop (533), the hardware limit switch (531), alarms with reactions 3 and 4, a drive fault, MC_Reset
// with and without Restart. The test also checks that the script did reach every job kind and alarm.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "counting_allocator.hpp"
#include "positioning_axis_fixture.hpp"
#include "profile_motion_in_fixture.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_set_sensor.hpp"

namespace {

using namespace tomc;
using techobjects::AlarmReaction;
using techobjects::StatusWordBit;
using tomc::testing::PositioningAxisMachine;
using Fault = drives::SimulatedDriveParameters::FaultReaction;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 30'000;  // per axis
#else
constexpr int kCycles = 250'000;
#endif

// One axis and the script that runs it. Every step starts, is polled once per cycle until it is finished or
// its time is up, and then ends; the script loops.
struct Axis {
  std::string name;
  std::unique_ptr<PositioningAxisMachine> m;
  bool software_limits = false;
  bool hardware_switch = false;
  bool drive = false;
};

struct Step {
  std::string name;
  std::function<void(PositioningAxisMachine&)> start;
  std::function<bool(PositioningAxisMachine&, int)> finished;  // (machine, cycles since start)
  std::function<void(PositioningAxisMachine&)> end;
  int max_cycles = 3000;
};

// Rising edges of the instances' Done (InVelocity, CommandAborted): the job kinds the script reached. Fixed
// arrays: the bookkeeping itself must not allocate inside the counted loop.
enum Reached {
  kAbsolute,
  kRelative,
  kVelocity,
  kHalt,
  kStop,
  kHome,
  kJog,
  kReset,
  kAborted,
  kSuperimposed,
  kHaltSuperimposed,
  kReachedCount
};
constexpr const char* kReachedNames[kReachedCount] = {"MC_MoveAbsolute",
                                                      "MC_MoveRelative",
                                                      "MC_MoveVelocity",
                                                      "MC_Halt",
                                                      "MC_Stop",
                                                      "MC_Home",
                                                      "MC_MoveJog",
                                                      "MC_Reset",
                                                      "MC_MoveAbsolute aborted",
                                                      "MC_MoveSuperimposed",
                                                      "MC_HaltSuperimposed"};
struct Edges {
  std::array<bool, kReachedCount> last{};
  std::array<long, kReachedCount> count{};
  void see(Reached what, bool value) {
    if (value && !last[what]) ++count[what];
    last[what] = value;
  }
};

bool status(const PositioningAxisMachine& m, StatusWordBit bit) {
  return techobjects::test(m.db().StatusWord, bit);
}

std::vector<Step> script(const Axis& a) {
  using M = PositioningAxisMachine;
  const auto nothing = [](M&) {};
  std::vector<Step> s;
  auto pulse_reset = [&s, nothing](bool restart) {
    s.push_back({restart ? "reset with restart" : "reset",
                 [restart](M& m) {
                   m.reset.Restart = restart;
                   m.reset.Execute = true;
                 },
                 [](M& m, int) { return m.reset.Done || m.reset.Error; },
                 [](M& m) { m.reset.Execute = false; }, 10});
  };
  auto enable = [&s, nothing] {
    s.push_back({"enable", [](M& m) { m.power.Enable = true; }, [](M& m, int) { return m.power.Status; },
                 nothing, 500});
  };
  // MC_MoveVelocity at 50 mm/s until InVelocity; a job the MC_Stop lock still rejected is retried.
  auto move_velocity = [&s, nothing](bool release) {
    s.push_back({"move velocity", nothing,
                 [](M& m, int k) {
                   auto& mv = m.move_velocity;
                   if (mv.Error || !mv.Execute) mv.Execute = !mv.Execute;
                   return k > 50 && mv.InVelocity;
                 },
                 release ? std::function<void(M&)>([](M& m) { m.move_velocity.Execute = false; })
                         : std::function<void(M&)>(nothing)});
  };
  auto wait = [&s, nothing](int cycles) {
    s.push_back({"wait", nothing, [cycles](M&, int k) { return k >= cycles; }, nothing, cycles + 1});
  };

  enable();
  s.push_back({"home",
               [](M& m) {
                 m.home.Mode = 0;
                 m.home.Position = 0.0;
                 m.home.Execute = true;
               },
               [](M& m, int) { return m.home.Done; }, [](M& m) { m.home.Execute = false; }, 10});
  // MC_MoveAbsolute with an appended MC_MoveRelative (BufferMode 1).
  s.push_back({"absolute + appended relative",
               [](M& m) {
                 m.move_absolute.Position = 100.0;
                 m.move_absolute.Velocity = 200.0;
                 m.move_absolute.Execute = true;
                 m.move_relative.Distance = -30.0;
                 m.move_relative.BufferMode = 1;
                 m.move_relative.Execute = true;
               },
               [](M& m, int) { return m.move_relative.Done; },
               [](M& m) {
                 m.move_absolute.Execute = false;
                 m.move_relative.Execute = false;
                 m.move_relative.BufferMode = 0;
               }});
  // A new MC_MoveAbsolute every 5 cycles: each plans from the moving state of the one it aborts.
  s.push_back({"replanning", nothing,
               [](M& m, int k) {
                 if (k % 5 == 0) {
                   const bool first = (k / 5) % 2 == 0;
                   auto& next = first ? m.move_absolute : m.move_absolute2;
                   auto& other = first ? m.move_absolute2 : m.move_absolute;
                   next.Position = first ? 60.0 + k * 0.1 : 20.0 + k * 0.05;
                   next.Jerk = (k / 5) % 3 == 0 ? 0.0 : -1.0;
                   next.Execute = true;
                   other.Execute = false;
                 }
                 return k >= 300;
               },
               nothing, 301});
  s.push_back({"halt", [](M& m) { m.halt.Execute = true; }, [](M& m, int) { return m.halt.Done; },
               [](M& m) {
                 m.halt.Execute = false;
                 m.move_absolute.Execute = false;
                 m.move_absolute2.Execute = false;
               }});
  // MC_MoveVelocity with override changes (spec 01 §8.4).
  s.push_back({"move velocity + override",
               [](M& m) {
                 m.move_velocity.Velocity = 50.0;
                 m.move_velocity.Execute = true;
               },
               [](M& m, int k) {
                 if (k == 100) (void)m.axis->write("Override.Velocity", 150.0);
                 if (k == 200) (void)m.axis->write("Override.Velocity", 100.0);
                 return k > 250 && m.move_velocity.InVelocity;
               },
               nothing});
  for (std::int32_t mode : {0, 2}) {  // Mode 1 is not one of S7-1500's (16#8114)
    s.push_back({"stop mode " + std::to_string(mode),
                 [mode](M& m) {
                   m.move_velocity.Execute = false;
                   m.stop.Mode = mode;
                   m.stop.Execute = true;
                 },
                 [](M& m, int) { return m.stop.Done; }, [](M& m) { m.stop.Execute = false; }});
    if (mode == 0) move_velocity(false);
  }
  s.push_back({"jog forward", [](M& m) { m.jog.JogForward = true; }, [](M&, int k) { return k >= 150; },
               [](M& m) { m.jog.JogForward = false; }, 151});
  s.push_back({"jog backward", [](M& m) { m.jog.JogBackward = true; }, [](M&, int k) { return k >= 150; },
               [](M& m) { m.jog.JogBackward = false; }, 151});
  s.push_back({"jog ends", nothing, [](M& m, int) { return !m.jog.Busy; }, nothing});
  // Superimposed motion on a base move (spec 01 §8.14): a MoveSuperimposed, replaced by a second one, braked
  // by MC_HaltSuperimposed, then one that runs to its end.
  s.push_back({"superimposed",
               [](M& m) {
                 m.move_relative.Distance = 60.0;
                 m.move_relative.Execute = true;
               },
               [](M& m, int k) {
                 m.move_superimposed.Distance = k < 60 ? 15.0 : -10.0;
                 m.move_superimposed.Execute = (k >= 10 && k < 30) || (k >= 40 && k < 50) || k >= 300;
                 m.halt_superimposed.Jerk = k % 2 == 0 ? 0.0 : -1.0;
                 m.halt_superimposed.Execute = k >= 80 && k < 90;  // braked within 200 cycles
                 return m.move_relative.Done && (k < 300 || m.move_superimposed.Done);
               },
               [](M& m) {
                 m.move_relative.Execute = false;
                 m.move_superimposed.Execute = false;
                 m.halt_superimposed.Execute = false;
               }});
  // Direct homing while a positioning job runs (spec 02 §5.7).
  s.push_back({"homing during motion",
               [](M& m) {
                 m.move_relative.Distance = 50.0;
                 m.move_relative.Execute = true;
               },
               [](M& m, int k) {
                 m.home.Mode = 1;
                 m.home.Position = 5.0;
                 m.home.Execute = k >= 100 && k < 110;
                 return m.move_relative.Done;
               },
               [](M& m) {
                 m.move_relative.Execute = false;
                 m.home.Execute = false;
               }});
  if (a.software_limits) {
    // Past MaxPosition: the look-ahead stops the axis at the limit with 533 (spec 02 §4.5).
    s.push_back({"software limit",
                 [](M& m) {
                   m.move_absolute.Position = 400.0;
                   m.move_absolute.Velocity = 300.0;
                   m.move_absolute.Execute = true;
                 },
                 [](M& m, int) {
                   return m.move_absolute.Error &&
                          m.axis->alarms().pending(techobjects::kAlarmSoftwareLimitReached);
                 },
                 [](M& m) { m.move_absolute.Execute = false; }});
    wait(200);
    pulse_reset(false);
    s.push_back({"back from the limit",
                 [](M& m) {
                   m.move_absolute2.Position = 0.0;
                   m.move_absolute2.Execute = true;
                 },
                 [](M& m, int) { return m.move_absolute2.Done; },
                 [](M& m) { m.move_absolute2.Execute = false; }});
  }
  // Alarm reactions 3 (emergency ramp) and 4 (remove enable) while moving, then MC_Reset.
  for (AlarmReaction r : {AlarmReaction::kStopEmergencyRamp, AlarmReaction::kRemoveEnable}) {
    move_velocity(true);
    s.push_back({"alarm reaction " + std::to_string(static_cast<int>(r)),
                 [r](M& m) {
                   (void)m.axis->inject_alarm(r == AlarmReaction::kRemoveEnable
                                                  ? techobjects::kAlarmDriveFault
                                                  : techobjects::kAlarmSoftwareLimitExceeded,
                                              0, r);
                 },
                 [](M& m, int) { return status(m, StatusWordBit::kStandstill); }, nothing});
    pulse_reset(false);
    enable();
  }
  if (a.drive) {
    // A drive fault (OFF3): 401 removes the enable; the fault cleared, MC_Reset acknowledges both.
    s.push_back({"drive fault",
                 [](M& m) {
                   m.move_velocity.Execute = true;
                   m.drive->inject_fault(7000, Fault::kOff3);
                 },
                 [](M& m, int) { return m.axis->alarms().pending(techobjects::kAlarmDriveFault); },
                 [](M& m) {
                   m.drive->clear_injected_fault();
                   m.move_velocity.Execute = false;
                 },
                 100});
    wait(300);
    pulse_reset(false);
    enable();
  }
  // MC_Power off with each StopMode while moving (spec 02 §3.1).
  for (std::int16_t mode : {0, 1, 2, 3}) {
    move_velocity(true);
    s.push_back({"power off, StopMode " + std::to_string(mode),
                 [mode](M& m) {
                   m.power.StopMode = mode;
                   m.power.Enable = false;
                 },
                 [](M& m, int k) { return k > 300 && !m.power.Busy; }, nothing});
    enable();
  }
  // MC_Reset Restart on a disabled axis: re-initialised, the incremental encoder loses the reference.
  s.push_back(
      {"power off", [](M& m) { m.power.Enable = false; }, [](M& m, int) { return !m.power.Busy; }, nothing});
  pulse_reset(true);
  enable();
  if (a.hardware_switch) {
    // Not homed after the restart: no software limits; the hardware switch at 250 mm removes the enable.
    s.push_back({"hardware limit switch",
                 [](M& m) {
                   m.move_velocity.Velocity = 100.0;
                   m.move_velocity.Execute = true;
                 },
                 [](M& m, int) { return m.axis->alarms().pending(techobjects::kAlarmHardwareLimit); },
                 [](M& m) {
                   m.move_velocity.Execute = false;
                   m.move_velocity.Velocity = 50.0;
                 },
                 5000});
    wait(400);
    pulse_reset(false);
    enable();
    s.push_back({"jog clear", [](M& m) { m.jog.JogBackward = true; },
                 [](M& m, int) { return !status(m, StatusWordBit::kHWLimitMaxActive); },
                 [](M& m) { m.jog.JogBackward = false; }, 5000});
    s.push_back({"jog ends", nothing, [](M& m, int) { return !m.jog.Busy; }, nothing});
    s.push_back({"back to the start",
                 [](M& m) {
                   m.move_relative.Distance = -240.0;
                   m.move_relative.Execute = true;
                 },
                 [](M& m, int) { return m.move_relative.Done; },
                 [](M& m) { m.move_relative.Execute = false; }});
  }
  return s;
}

// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), over the jobs of spec 03 §4 on every axis
// variant.
TEST(PositioningAllocation, EveryJobKindRunsWithoutAllocating) {
  std::vector<Axis> axes;
  {
    auto d = tomc::testing::linear_axis_data();
    d.PositionLimits_SW.Active = true;
    d.PositionLimits_SW.MinPosition = -50.0;
    d.PositionLimits_SW.MaxPosition = 200.0;
    d.PositionLimits_HW.Active = true;
    auto p = tomc::testing::linear_drive();
    p.machine.positive_limit_switch = 250.0;
    axes.push_back(
        {"linear, telegram 3, limits", std::make_unique<PositioningAxisMachine>(d, p, 3), true, true, true});
  }
  {
    auto d = tomc::testing::linear_axis_data();
    d.DynamicLimits.MaxJerk = 100000.0;
    d.PositionControl.EnableDSC = true;
    axes.push_back({"linear, telegram 105, DSC, jerk",
                    std::make_unique<PositioningAxisMachine>(d, tomc::testing::linear_drive(), 105), false,
                    false, true});
  }
  {
    auto d = tomc::testing::linear_axis_data();
    d.Properties.MotionType = static_cast<std::int32_t>(techobjects::PropertiesMotionType::kRotary);
    d.Units.LengthUnit = techobjects::unit_code::kDegree;
    d.Units.VelocityUnit = techobjects::unit_code::kDegreePerSecond;
    d.Modulo.Enable = true;
    d.Modulo.Length = 360.0;
    d.FollowingError.MinValue = 5.0;
    d.FollowingError.MaxValue = 50.0;
    auto p = tomc::testing::linear_drive();
    p.load_units_per_revolution = 360.0;
    axes.push_back({"rotary modulo", std::make_unique<PositioningAxisMachine>(d, p, 3), false, false, true});
  }
  {
    auto d = tomc::testing::linear_axis_data();
    d.VirtualAxis.Mode = techobjects::kModeOn;
    d.PositionLimits_SW.Active = true;
    d.PositionLimits_SW.MinPosition = -50.0;
    d.PositionLimits_SW.MaxPosition = 200.0;
    axes.push_back({"virtual",
                    std::make_unique<PositioningAxisMachine>(d, tomc::testing::linear_drive(), 3, false),
                    true, false, false});
  }
  {
    auto d = tomc::testing::linear_axis_data();
    d.Simulation.Mode = techobjects::kModeOn;
    d.DynamicLimits.MaxJerk = 100000.0;
    axes.push_back({"simulation",
                    std::make_unique<PositioningAxisMachine>(d, tomc::testing::linear_drive(), 3, false),
                    false, false, false});
  }
  struct Program {
    std::vector<Step> steps;
    std::size_t step = 0;
    int since = 0;
    bool started = false;
    long loops = 0;
    std::vector<long> timeouts;  // per step
    Edges edges;
  };
  std::vector<Program> programs;
  for (const auto& a : axes) {
    programs.emplace_back();
    programs.back().steps = script(a);
    programs.back().timeouts.assign(programs.back().steps.size(), 0);
  }
  std::vector<std::uint64_t> alarm_sequence(axes.size(), 0);

  const auto before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < kCycles; ++cycle) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      auto& m = *axes[i].m;
      auto& p = programs[i];
      Step& st = p.steps[p.step];
      if (!p.started) {
        st.start(m);
        p.started = true;
        p.since = 0;
      }
      m.run(1);
      ++p.since;
      const bool finished = st.finished(m, p.since);
      if (finished || p.since >= st.max_cycles) {
        if (!finished) ++p.timeouts[p.step];
        st.end(m);
        p.started = false;
        if (++p.step == p.steps.size()) {
          p.step = 0;
          ++p.loops;
        }
      }
      p.edges.see(kAbsolute, m.move_absolute.Done || m.move_absolute2.Done);
      p.edges.see(kRelative, m.move_relative.Done);
      p.edges.see(kVelocity, m.move_velocity.InVelocity);
      p.edges.see(kHalt, m.halt.Done);
      p.edges.see(kStop, m.stop.Done);
      p.edges.see(kHome, m.home.Done);
      p.edges.see(kJog, m.jog.InVelocity);
      p.edges.see(kReset, m.reset.Done);
      p.edges.see(kAborted, m.move_absolute.CommandAborted || m.move_absolute2.CommandAborted);
      p.edges.see(kSuperimposed, m.move_superimposed.Done);
      p.edges.see(kHaltSuperimposed, m.halt_superimposed.Done);
    }
  }
  const auto allocated = tomc::testing::allocation_count() - before;
  EXPECT_EQ(allocated, 0u) << "allocations in " << kCycles << " cycles of " << axes.size() << " axes";

  // The script reached what it is about on every axis, in at least two full loops.
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const auto& a = axes[i];
    const auto& p = programs[i];
    SCOPED_TRACE(a.name);
    EXPECT_GE(p.loops, 2);
    for (int k = 0; k < kReachedCount; ++k)
      EXPECT_GE(p.edges.count[static_cast<std::size_t>(k)], p.loops) << kReachedNames[k];
    for (std::size_t k = 0; k < p.steps.size(); ++k) {
      if (p.timeouts[k] != 0)
        ADD_FAILURE() << "step " << k << " '" << p.steps[k].name << "' timed out " << p.timeouts[k]
                      << " times";
    }
    // Alarms raised by the script itself (not only injected): 533 at the software limit, 531 at the switch.
    std::vector<techobjects::AlarmEvent> events(techobjects::AlarmLog::kCapacity);
    const auto n = a.m->axis->alarms().log().copy_since(0, events);
    bool saw533 = false, saw531 = false, saw401 = false;
    for (std::size_t k = 0; k < n; ++k) {
      saw533 |= events[k].number == techobjects::kAlarmSoftwareLimitReached;
      saw531 |= events[k].number == techobjects::kAlarmHardwareLimit;
      saw401 |= events[k].number == techobjects::kAlarmDriveFault;
    }
    if (a.software_limits) {
      EXPECT_TRUE(saw533);
    }
    if (a.hardware_switch) {
      EXPECT_TRUE(saw531);
    }
    EXPECT_TRUE(saw401);
    EXPECT_FALSE(a.m->axis->alarms().pending(techobjects::kAlarmFollowingError));
  }
}

// MC_PositionProfile and MotionIn (issue 18) allocate nothing either: a loop of 1,500-cycle phases — a
// relative profile, an absolute profile too fast for MaxVelocity (transition, limited following) with a
// profile appended by BufferMode 1, MotionInVelocity with a changing velocity, MotionInPosition following a
// sine, MotionInVelocity replaced by MC_MoveVelocity and stopped by MC_Halt.
TEST(PositioningAllocation, PositionProfileAndMotionInRunWithoutAllocating) {
  tomc::testing::ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  const techobjects::TimePositionProfile slow = tomc::testing::ramp_profile();
  techobjects::TimePositionProfile fast = slow;
  for (auto& p : fast.Point)
    p.Position *= 5.0;  // peak near 590 mm/s, MaxVelocity 500
  m.profile.TimePosition = &slow;
  m.profile2.TimePosition = &slow;
  constexpr int kPhase = 1500;
  long profiles_done = 0, limited = 0, on_profile = 0, motion_in_cycles = 0, replaced = 0;
  const auto before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < kCycles / 4; ++cycle) {
    const int phase = (cycle / kPhase) % 5;
    const int t = cycle % kPhase;
    m.profile.Execute = false;
    m.profile2.Execute = false;
    m.move_velocity.Execute = false;
    m.halt.Execute = false;
    switch (phase) {
      case 0:
        m.profile.TimePosition = &slow;
        m.profile.ProfileReference = 0;
        m.profile.Execute = t < 5;
        break;
      case 1:
        m.profile.TimePosition = &fast;
        m.profile.ProfileReference = 1;
        m.profile.Execute = t < 5;
        m.profile2.BufferMode = 1;
        m.profile2.Execute = t >= 10 && t < 15;
        break;
      case 2:
        m.motion_in_velocity.Enable = t < kPhase - 100;
        m.motion_in_velocity.Velocity = 50.0 * std::sin(t * 0.01);
        m.motion_in_velocity.Acceleration = 0.5 * std::cos(t * 0.01);
        break;
      case 3:
        if (t == 0) m.motion_in_position.Position = m.db().Position;
        m.motion_in_position.Enable = t < kPhase - 100;
        m.motion_in_position.Velocity = 5.0 * std::cos(t * 0.001);
        m.motion_in_position.Position += m.motion_in_position.Velocity * 0.001;
        break;
      default:
        m.motion_in_velocity.Enable = t < 500;
        m.motion_in_velocity.Velocity = 30.0;
        m.move_velocity.Velocity = 10.0;
        m.move_velocity.Execute = t >= 200 && t < 205;
        m.halt.Execute = t >= 600 && t < 605;
        break;
    }
    m.run(1);
    if (m.profile.Done || m.profile2.Done) ++profiles_done;
    if (m.x9() && !m.x10()) ++limited;
    if (m.x10()) ++on_profile;
    if (m.motion_in_velocity.Busy || m.motion_in_position.Busy) ++motion_in_cycles;
    if (m.motion_in_velocity.CommandAborted) ++replaced;
  }
  const auto allocated = tomc::testing::allocation_count() - before;
  EXPECT_EQ(allocated, 0u);
  // The loop reached what it is about.
  EXPECT_GT(profiles_done, 0);
  EXPECT_GT(limited, 0);
  EXPECT_GT(on_profile, 0);
  EXPECT_GT(motion_in_cycles, 0);
  EXPECT_GT(replaced, 0);
}

// Two encoders (telegram 4: G1 motor, G2 load side) with MC_SetSensor switching back and forth in all four
// modes while the axis moves, encoder 2 failing and being acknowledged, MC_Home Mode 13 on the encoder
// outside the loop, and MC_Reset with Restart: nothing allocates (decision B1, spec 01 §3.8); the same
// script on a simulated and a virtual axis with two encoders (decision B7; no encoder error to inject).
TEST(PositioningAllocation, TwoEncodersAndSetSensorRunWithoutAllocating) {
  for (const std::uint32_t kind : {0u, 1u, 2u}) {  // on a drive, simulated, virtual
    SCOPED_TRACE(kind);
    auto data = tomc::testing::linear_axis_data();
    data.Sensor[1].Existent = true;
    data.Sensor[1].Interface.Number = 2;
    data.Sensor[1].MountingMode = 1;  // load side
    data.PositionControl.SmoothingTimeByChangeDifference = 0.005;
    data.Simulation.Mode = kind == 1 ? techobjects::kModeOn : 0;
    data.VirtualAxis.Mode = kind == 2 ? techobjects::kModeOn : 0;
    PositioningAxisMachine m(data, tomc::testing::linear_drive(), 4, kind == 0);
    instructions::MC_SetSensor<techobjects::PositioningAxis> set_sensor;
    m.user = [&] { set_sensor(*m.axis); };
    ASSERT_GT(m.enable(), 0);
    ASSERT_TRUE(m.home_at(0.0));
    constexpr int kPhase = 1000;
    long switches = 0, errors = 0, restarts = 0;
    const auto before = tomc::testing::allocation_count();
    // Every phase at least once, also in the sanitizer builds' shorter runs.
    const int cycles = std::max(kCycles / 10, 6 * kPhase);
    for (int cycle = 0; cycle < cycles; ++cycle) {
      const int phase = (cycle / kPhase) % 6;
      const int t = cycle % kPhase;
      m.move_velocity.Velocity = (phase % 2 == 0 ? 20.0 : -20.0);
      m.move_velocity.Execute = t < 5 && phase < 4;
      m.halt.Execute = t >= 800 && t < 805;
      set_sensor.Sensor = static_cast<std::int16_t>(1 + (phase + t / 100) % 2);
      set_sensor.Mode = (t / 100) % 4;
      set_sensor.ReferenceSensor = static_cast<std::int16_t>(1 + phase % 2);
      set_sensor.Execute = t % 100 >= 50 && t % 100 < 52;
      if (kind == 0 && phase == 4 && t == 100) m.drive->inject_encoder_error(2, 1);
      if (kind == 0 && phase == 4 && t == 300) m.drive->clear_encoder_error(2);
      m.reset.Restart = phase == 5;
      m.reset.Execute = (phase == 4 && t >= 400 && t < 410) || (phase == 5 && t >= 900 && t < 910);
      if (phase == 5 && t == 850) m.power.Enable = false;
      if (phase == 0 && t == 0) m.power.Enable = true;
      m.home.Mode = 13;
      m.home.Sensor = 2;
      m.home.Position = 1.0;
      m.home.Execute = phase == 1 && t >= 600 && t < 602;
      m.run(1);
      if (set_sensor.Done) ++switches;
      if (m.axis->alarms().pending(techobjects::kAlarmAdditionalSensorFault)) ++errors;
      if (m.reset.Done && m.reset.Restart) ++restarts;
    }
    const auto allocated = tomc::testing::allocation_count() - before;
    EXPECT_EQ(allocated, 0u);
    EXPECT_GT(switches, 0);
    EXPECT_EQ(errors > 0, kind == 0);
    EXPECT_GT(restarts, 0);
  }
}

// The superimposed MotionIn jobs (issue 18) allocate nothing: two virtual axes, TO_2 a possible
// superimposing axis of TO_1. In 2,000-cycle phases: TO_1's base velocity changes while MotionInSuperimposed
// feeds a sine, which MC_MoveSuperimposed then replaces and MC_HaltSuperimposed stops; then TO_2 jogs back
// and forth while MotionInSuperimposedAxes adds it to TO_1 (TO_2 set by MC_Home Mode 0 to TO_1's
// superimposition first, as the manual's warning asks), and a base job aborts that.
TEST(PositioningAllocation, SuperimposedMotionInRunsWithoutAllocating) {
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  auto data = tomc::testing::linear_axis_data();
  data.VirtualAxis.Mode = techobjects::kModeOn;
  auto& to1 = runtime.emplace<techobjects::PositioningAxis>("TO_1", nullptr, data);
  auto& to2 = runtime.emplace<techobjects::PositioningAxis>("TO_2", nullptr, data);
  to1.add_possible_superimposing_axis(to2);
  instructions::MC_Power<techobjects::PositioningAxis> power1, power2;
  instructions::MC_MoveVelocity<techobjects::PositioningAxis> base;
  instructions::MC_MoveRelative<techobjects::PositioningAxis> step2;
  instructions::MC_Home<techobjects::PositioningAxis> home2;
  instructions::MC_MoveSuperimposed<techobjects::PositioningAxis> move_sup;
  instructions::MC_HaltSuperimposed<techobjects::PositioningAxis> halt_sup;
  instructions::MC_MotionInSuperimposed<techobjects::PositioningAxis> feed;
  instructions::MC_MotionInSuperimposedAxes<techobjects::PositioningAxis> axes;
  axes.SuperimposingAxis = &to2;
  runtime.set_user_program([&](techobjects::Runtime&) {
    power1(to1);
    power2(to2);
    base(to1);
    step2(to2);
    home2(to2);
    move_sup(to1);
    halt_sup(to1);
    feed(to1);
    axes(to1);
  });
  runtime.start();
  power1.Enable = power2.Enable = true;
  for (int i = 0; i < 10; ++i)
    runtime.step();
  ASSERT_TRUE(power1.Status && power2.Status);
  constexpr int kPhase = 2000;
  long fed = 0, followed = 0, replaced = 0, halted = 0;
  double sup = 0.0;
  const auto before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < kCycles / 4; ++cycle) {
    const int t = cycle % kPhase;
    const bool first = (cycle / kPhase) % 2 == 0;
    base.Execute = t % 500 < 5;
    base.Velocity = 20.0 + 10.0 * ((t / 500) % 3);
    if (first) {
      feed.Enable = t < 1000;
      sup += 0.001 * 5.0 * std::cos(t * 0.005);
      feed.Distance = sup;
      feed.VelocityDiff = 5.0 * std::cos(t * 0.005);
      move_sup.Distance = 2.0;
      move_sup.Execute = t >= 800 && t < 805;
      halt_sup.Execute = t >= 1200 && t < 1205;
      axes.Enable = false;
      home2.Execute = step2.Execute = false;
    } else {
      feed.Enable = false;
      move_sup.Execute = halt_sup.Execute = false;
      home2.Mode = 0;
      home2.Position = to1.data().StatusPositioning.SuperimposedDistance;
      home2.Execute = t < 5;
      axes.Enable = t < 1800;
      step2.Distance = t < 1000 ? 15.0 : -15.0;
      step2.Execute = t % 1000 >= 10 && t % 1000 < 15;
    }
    runtime.step();
    if (feed.Busy) ++fed;
    if (axes.Busy) ++followed;
    if (feed.CommandAborted || axes.CommandAborted) ++replaced;
    if (halt_sup.Done) ++halted;
  }
  EXPECT_EQ(tomc::testing::allocation_count() - before, 0u);
  // The loop reached what it is about.
  EXPECT_GT(fed, 0);
  EXPECT_GT(followed, 0);
  EXPECT_GT(replaced, 0);
  EXPECT_GT(halted, 0);
}

}  // namespace
