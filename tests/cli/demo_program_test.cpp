// The user program of `tomc demo` on a positioning axis and an external encoder (tools/tomc/demo_program.*),
// stepped by hand: the axis is powered, homed (MC_Home Mode 0 or 3) and positioned in a loop (MC_MoveAbsolute
// between positions, MC_MoveRelative steps on a modulo axis); the switch "automatic" off disables it so that
// the axis control panel can take master control (spec 02 §9.2, decision W15), on again resumes the loop.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <memory>
#include <vector>

#include "build_paths.hpp"
#include "demo_faults.hpp"
#include "demo_program.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/scenario/machine.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace {

using namespace tomc;
using cli::DemoPositioning;
using cli::DemoPositioningProgram;
using techobjects::StatusWordBit;

struct DemoMachine {
  explicit DemoMachine(techobjects::PositioningAxisData data, DemoPositioning plan, double units_per_rev)
      : runtime(techobjects::RuntimeConfig{0.001, 1, 1}) {
    drives::DeviceConfig device;
    device.drive_telegram = 3;
    drives::SimulatedDriveParameters p;
    p.load_units_per_revolution = units_per_rev;
    auto owned = std::make_unique<drives::SimulatedDrive>(device, p);
    drive = owned.get();
    auto& io = runtime.add_device(std::move(owned));
    axis = &runtime.emplace<techobjects::PositioningAxis>("Axis", &io, data);
    program = std::make_unique<DemoPositioningProgram>(*axis, std::move(plan));
    runtime.set_user_program([this](techobjects::Runtime& rt) { (*program)(rt.clock()); });
    runtime.start();
  }
  template <typename Predicate>
  int run_until(Predicate done, int limit) {
    for (int i = 1; i <= limit; ++i) {
      runtime.step();
      if (done()) return i;
    }
    return -1;
  }
  bool bit(StatusWordBit b) const { return techobjects::test(axis->data().StatusWord, b); }

  techobjects::Runtime runtime;
  drives::SimulatedDrive* drive = nullptr;
  techobjects::PositioningAxis* axis = nullptr;
  std::unique_ptr<DemoPositioningProgram> program;
};

// Decisions W18 (the demo program on positioning axes) and W15; spec 02 §9.2.
TEST(DemoProgram, LinearAxisIsHomedActivelyAndMovesBetweenTwoPositions) {
  techobjects::PositioningAxisData data;
  DemoPositioning plan;
  plan.home_mode = 3;  // the motor encoder's zero mark (default Sensor[1].ActiveHoming.Mode)
  plan.positions = {20.0, 60.0};
  plan.velocity = 100.0;
  plan.dwell_s = 0.2;
  DemoMachine m(data, plan, 10.0);
  ASSERT_GT(m.run_until([&] { return m.program->step() == DemoPositioningProgram::Step::kHoming; }, 500), 0);
  ASSERT_GT(
      m.run_until([&] { return m.bit(StatusWordBit::kHomingDone) && !m.bit(StatusWordBit::kHomingCommand); },
                  20000),
      0);
  ASSERT_GT(m.run_until([&] { return m.program->moves() == 1; }, 5000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Position, 20.0);
  ASSERT_GT(m.run_until([&] { return m.program->moves() == 2; }, 5000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Position, 60.0);
  ASSERT_GT(m.run_until([&] { return m.program->moves() == 3; }, 5000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Position, 20.0);
  EXPECT_FALSE(m.bit(StatusWordBit::kError));

  // Released for the panel: the program disables the axis; the panel could take it now.
  m.program->automatic()->store(false);
  ASSERT_GT(m.run_until([&] { return m.axis->program_released(); }, 5000), 0);
  EXPECT_EQ(m.program->step(), DemoPositioningProgram::Step::kDisabled);
  // Back in automatic: still homed, the loop goes on without homing again.
  m.program->automatic()->store(true);
  ASSERT_GT(m.run_until([&] { return m.program->step() == DemoPositioningProgram::Step::kMoving; }, 500), 0);
  const auto moves = m.program->moves();
  ASSERT_GT(m.run_until([&] { return m.program->moves() == moves + 1; }, 10000), 0);
}

// `tomc demo --inject-faults` (the free-running soak, docs/reliability.md §7): one drive, so the kinds take
// turns fault by fault. Each raises its alarm in the cycle of docs/reliability.md §1's fault table: drive
// fault (spec 06 §3.2) and encoder error (spec 06 §6.4) in the step right after the injection (k), a frozen
// sign-of-life one step later (k+1, spec 06 §5.2); the cause is gone 20 cycles later, and the demo program
// acknowledges the alarm after DemoProgram::kAcknowledgeAfterS (5 s = 5000 cycles) and positions again.
TEST(DemoFaultInjector, EachKindRaisesItsAlarmAndTheDemoProgramRecovers) {
  techobjects::PositioningAxisData data;
  DemoPositioning plan;
  plan.positions = {20.0, 60.0};
  plan.velocity = 100.0;
  plan.dwell_s = 0.2;
  DemoMachine m(data, plan, 10.0);
  constexpr std::uint64_t kPeriod = 8000;
  cli::DemoFaultInjector faults({m.drive}, kPeriod);
  std::uint64_t steps = 0;
  const auto run_to = [&](std::uint64_t end) {
    for (; steps < end; ++steps) {
      faults(steps);
      m.runtime.step();
    }
  };
  struct Expected {
    std::uint32_t alarm;
    std::uint64_t detected_after;  // cycles after the one the fault was injected before
  };
  const Expected table[] = {{techobjects::kAlarmDriveFault, 1},        // ZSW1.3, k
                            {techobjects::kAlarmSensorFault, 1},       // G1_ZSW.15, k
                            {techobjects::kAlarmDriveSignOfLife, 2}};  // ZSW2 counter stops, k+1
  for (std::size_t i = 0; i < std::size(table); ++i) {
    const std::uint64_t injected_at = (i + 1) * kPeriod;
    run_to(injected_at);
    ASSERT_FALSE(m.bit(StatusWordBit::kError)) << i;
    const std::size_t moves = m.program->moves();
    ASSERT_GT(moves, 0u) << i;  // positioning before each fault
    // Not before its detection cycle, then raised in it.
    run_to(injected_at + table[i].detected_after - 1);
    ASSERT_FALSE(m.axis->alarms().pending(table[i].alarm)) << i;
    run_to(injected_at + table[i].detected_after);
    ASSERT_TRUE(m.axis->alarms().pending(table[i].alarm)) << i;
    EXPECT_EQ(faults.injected(), i + 1);
    std::array<techobjects::AlarmEvent, 64> history{};
    const std::size_t n = m.axis->alarms().log().copy_since(0, history);
    ASSERT_GE(n, 1u);
    EXPECT_EQ(history[n - 1].kind, techobjects::AlarmEvent::Kind::kRaised) << i;
    // Cleared after kHoldCycles, acknowledged after 5 s by the program's MC_Reset, positioning again.
    run_to(injected_at + 5000 + 500);
    EXPECT_FALSE(m.axis->alarms().any_error()) << i;
    run_to(injected_at + kPeriod - 1);
    EXPECT_GT(m.program->moves(), moves) << i;
  }
}

// Decision W18 (MC_MoveRelative steps on a modulo axis).
TEST(DemoProgram, ModuloAxisTurnsInRelativeSteps) {
  techobjects::PositioningAxisData data;
  data.Properties.MotionType = static_cast<std::int32_t>(techobjects::PropertiesMotionType::kRotary);
  data.Units.LengthUnit = 1005;
  data.Units.VelocityUnit = 1521;
  data.Modulo.Enable = true;
  data.Modulo.Length = 360.0;
  data.DynamicLimits.MaxVelocity = data.DynamicLimits.Velocity = 3600.0;
  data.DynamicLimits.MaxAcceleration = data.DynamicLimits.MaxDeceleration = 36000.0;
  data.DynamicLimits.MaxJerk = 0.0;
  data.DynamicDefaults.Acceleration = data.DynamicDefaults.Deceleration = 3600.0;
  DemoPositioning plan;
  plan.distance = 90.0;
  plan.velocity = 360.0;
  plan.dwell_s = 0.1;
  DemoMachine m(data, plan, 360.0);
  for (int step = 1; step <= 5; ++step) {
    ASSERT_GT(m.run_until([&] { return m.program->moves() == static_cast<std::size_t>(step); }, 5000), 0)
        << step;
    EXPECT_NEAR(m.axis->data().Position, std::fmod(90.0 * step, 360.0), 1e-9) << step;
  }
  EXPECT_FALSE(m.bit(StatusWordBit::kError));
}

// The built-in demo machine (examples/demo_machine.json, what `tomc demo` runs without --config) has
// positioning and speed axes on the analog actor and on the stepper actor (issue 20 "tomc demo runs
// positioning and speed axes on analog and stepper drives"): loaded by the loader tomc demo uses, each driven
// by its demo program with the plan of the file's "program" section.
TEST(DemoProgram, BuiltInMachineRunsAnalogAndStepperAxes) {
  std::ifstream in(std::string(TOMC_EXAMPLES_DIR) + "/demo_machine.json");
  ASSERT_TRUE(in) << "examples/demo_machine.json";
  const scenario::Json root = scenario::Json::parse(in);
  const double cycle_s = root["cycle_time"].get<double>();
  techobjects::Runtime runtime(techobjects::RuntimeConfig{cycle_s, 1, 1});
  std::vector<scenario::MachineObject> objects;
  scenario::Problems problems;
  for (const auto& object : root["technology_objects"]) {
    const std::string name = object["name"].get<std::string>();
    if (name != "Spindle" && name != "Portal" && name != "Feeder" && name != "Dosing") continue;
    auto o = scenario::load_technology_object(object, name, cycle_s, runtime, objects, problems, "tomc demo");
    ASSERT_TRUE(o && o->built) << name << ": " << (problems.empty() ? "" : problems.lines().front());
    objects.push_back(std::move(*o));
  }
  ASSERT_EQ(objects.size(), 4u);
  const auto& spindle = objects[0];
  const auto& portal = objects[1];
  const auto& feeder = objects[2];
  const auto& dosing = objects[3];
  ASSERT_NE(spindle.analog_drive, nullptr);
  ASSERT_NE(portal.analog_drive, nullptr);
  ASSERT_NE(feeder.stepper_drive, nullptr);
  ASSERT_NE(dosing.stepper_drive, nullptr);
  ASSERT_NE(spindle.speed_axis, nullptr);
  ASSERT_NE(portal.positioning_axis, nullptr);
  ASSERT_NE(feeder.positioning_axis, nullptr);
  ASSERT_NE(dosing.speed_axis, nullptr);

  const auto& program = root["program"];
  const auto speed_plan = [&](const std::string& name) {
    cli::DemoSequence s;
    s.velocities = program[name]["velocities"].get<std::vector<double>>();
    s.dwell_s = program[name]["dwell_s"].get<double>();
    return s;
  };
  const auto positioning_plan = [&](const std::string& name) {
    DemoPositioning p;
    p.home_mode = program[name]["home_mode"].get<std::int32_t>();
    p.home_position = program[name]["home_position"].get<double>();
    p.positions = program[name]["positions"].get<std::vector<double>>();
    p.velocity = program[name]["velocity"].get<double>();
    p.dwell_s = program[name]["dwell_s"].get<double>();
    return p;
  };
  cli::DemoAxisProgram spindle_program(*spindle.speed_axis, speed_plan("Spindle"));
  DemoPositioningProgram portal_program(*portal.positioning_axis, positioning_plan("Portal"));
  DemoPositioningProgram feeder_program(*feeder.positioning_axis, positioning_plan("Feeder"));
  cli::DemoAxisProgram dosing_program(*dosing.speed_axis, speed_plan("Dosing"));
  ASSERT_EQ(spindle_program.sequence().velocities, (std::vector<double>{1500.0, 3000.0, 0.0, -1500.0, 0.0}));
  ASSERT_EQ(dosing_program.sequence().velocities, (std::vector<double>{120.0, 300.0, 0.0, -120.0, 0.0}));
  runtime.set_user_program([&](techobjects::Runtime& rt) {
    for (cli::DemoProgram* p : std::initializer_list<cli::DemoProgram*>{&spindle_program, &portal_program,
                                                                        &feeder_program, &dosing_program})
      (*p)(rt.clock());
  });
  runtime.start();

  // The positioning axes: homed (Mode 0) and positioned between the file's positions, 10 <-> 190 mm and
  // 0 <-> 60 mm, the Feeder without losing a step. The speed axes at the second velocity after 3 s + ramp.
  std::size_t portal_seen = 0, feeder_seen = 0;
  bool spindle_checked = false, dosing_checked = false;
  const auto& ps = portal.positioning_axis->data();
  const auto& fs = feeder.positioning_axis->data();
  for (int cycle = 1; cycle <= 12000; ++cycle) {
    runtime.step();
    if (portal_program.moves() != portal_seen) {
      portal_seen = portal_program.moves();
      const double target = portal_seen % 2 == 1 ? 10.0 : 190.0;
      EXPECT_DOUBLE_EQ(ps.Position, target) << portal_seen;
      // Done comes inside the positioning window (default 0.1 mm): one count is 1 um on this axis.
      EXPECT_NEAR(ps.ActualPosition, target, 0.1) << portal_seen;
    }
    if (feeder_program.moves() != feeder_seen) {
      feeder_seen = feeder_program.moves();
      const double target = feeder_seen % 2 == 1 ? 0.0 : 60.0;
      EXPECT_DOUBLE_EQ(fs.Position, target) << feeder_seen;
      // The pulse count, within the positioning window when Done comes (2 steps of 3.125 um measured).
      EXPECT_NEAR(fs.ActualPosition, target, 0.1) << feeder_seen;
    }
    if (cycle == 5900) {
      // 3000 1/min = 100 % of the reference speed = 10 V; 300 1/min at 1600 steps/rev = 8 kHz.
      EXPECT_NEAR(spindle.speed_axis->data().ActualSpeed, 3000.0, 15.0);  // one count per ms = 14.6 1/min
      EXPECT_NEAR(spindle.analog_drive->actor().output_volts(), 10.0, 1e-6);
      EXPECT_NEAR(dosing.speed_axis->data().ActualSpeed, 300.0, 1e-6);
      EXPECT_NEAR(dosing.stepper_drive->actor().pulse_frequency_hz(), 8000.0, 1e-6);
      spindle_checked = dosing_checked = true;
    }
  }
  EXPECT_TRUE(spindle_checked && dosing_checked);
  EXPECT_GE(portal_seen, 4u);
  EXPECT_GE(feeder_seen, 4u);
  EXPECT_EQ(feeder.stepper_drive->hardware().lost_steps(), 0u);
  for (const auto& o : objects)
    EXPECT_TRUE(o.alarms().alarms().empty()) << o.name << " " << o.alarms().alarms().front().number;
}

}  // namespace

namespace {

// Decision W23: the demo's camming program powers a synchronous axis, sets it to 0 and cams it with MC_CamIn
// (direct synchronous setting) to its first leading value; it then follows the cam (spec 07 §3.3).
TEST(DemoProgram, SynchronousAxisCamsToItsLeader) {
  using namespace tomc;
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  auto virtual_axis = [] {
    techobjects::PositioningAxisData d;
    d.VirtualAxis.Mode = techobjects::kModeOn;
    d.DynamicLimits.MaxJerk = 0.0;
    return d;
  }();
  auto owned_leader = std::make_unique<techobjects::PositioningAxis>("L", nullptr, virtual_axis);
  techobjects::PositioningAxis* leader = owned_leader.get();
  auto& follower = runtime.emplace<techobjects::SynchronousAxis>(
      "F", nullptr, virtual_axis,
      std::vector<techobjects::LeadingValueInterconnection>{
          {leader, leader, techobjects::LeadingValueCoupling::kSetpoint}});
  runtime.add_technology_object(std::move(owned_leader));
  auto& cam = runtime.emplace<techobjects::Cam>("C", techobjects::CamVariant::kCam, 3);
  techobjects::TO_Cam_Struct_SegmentData s;  // y = 2x on [0, 100]: cyclic appending turns it into a gear 2:1
  s.xmin = 0.0;
  s.xmax = 100.0;
  s.a1 = 2.0;
  ASSERT_TRUE(cam.write_segment(1, s, true));
  cli::DemoCammingProgram program(follower, cam, 2);
  instructions::MC_Power<techobjects::PositioningAxis> power_leader;
  instructions::MC_MoveVelocity<techobjects::PositioningAxis> move_leader;
  power_leader.Enable = true;
  move_leader.Velocity = 10.0;
  runtime.set_user_program([&](techobjects::Runtime& rt) {
    power_leader(*leader);
    move_leader.Execute = power_leader.Status;
    move_leader(*leader);
    program(rt.clock());
  });
  runtime.start();
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  for (int i = 0; i < 2000; ++i)
    runtime.step();
  EXPECT_EQ(program.step(), cli::DemoCammingProgram::Step::kCamming);
  EXPECT_TRUE(techobjects::test(follower.data().StatusWord, techobjects::StatusWordBit::kSynchronous));
  EXPECT_EQ(follower.synchronized_motion().FunctionState, 3);
  EXPECT_EQ(follower.synchronized_motion().ActualCam, 3);
  // Following the cam's slope 2 at the leader's 10 mm/s.
  EXPECT_NEAR(follower.data().Velocity, 20.0, 1e-6);
}

}  // namespace
