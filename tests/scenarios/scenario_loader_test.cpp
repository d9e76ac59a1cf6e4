// Every problem the scenario loader reports (docs/scenarios.md): each names its JSON path, and all problems
// of a file are reported together. The loader is tested through the library; scenario_cli_test.cpp checks
// that the CLI passes the lines through with exit status 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "tomc/scenario/config.hpp"
#include "tomc/scenario/scenario.hpp"

namespace {

using tomc::scenario::Json;
using tomc::scenario::Problems;
using tomc::scenario::Scenario;

// A valid one-axis scenario; tests patch one part of it.
Json base() {
  return Json::parse(R"({
    "cycle_time": 0.001,
    "cycles": 10,
    "technology_objects": [
      { "name": "Axis1", "type": "TO_SpeedAxis", "config": {}, "drive": { "adapter": "simulated", "telegram": 2 } }
    ],
    "timeline": [
      { "cycle": 0, "instance": "power1", "instruction": "MC_Power", "axis": "Axis1", "inputs": { "Enable": true } }
    ],
    "trace": [ "power1.Status" ]
  })");
}

std::vector<std::string> problems_of(const Json& document) {
  auto result = Scenario::load(document);
  EXPECT_EQ(result.scenario == nullptr, !result.problems.empty());
  return result.problems;
}

// The one problem of `document`; fails if there is not exactly one.
std::string problem_of(const Json& document) {
  const auto problems = problems_of(document);
  EXPECT_EQ(problems.size(), 1u) << ::testing::PrintToString(problems);
  return problems.empty() ? std::string() : problems.front();
}

Json with_config(const char* config) {
  Json d = base();
  d["technology_objects"][0]["config"] = Json::parse(config);
  return d;
}

Json with_drive(const char* drive) {
  Json d = base();
  d["technology_objects"][0]["drive"] = Json::parse(drive);
  return d;
}

Json with_event(const char* event) {
  Json d = base();
  d["timeline"].push_back(Json::parse(event));
  return d;
}

// docs/scenarios.md "A complete example" and "Top level".
TEST(ScenarioLoader, ValidScenarioLoads) {
  const auto result = Scenario::load(base());
  ASSERT_TRUE(result.scenario) << ::testing::PrintToString(result.problems);
  EXPECT_EQ(result.scenario->cycles(), 10u);
  EXPECT_DOUBLE_EQ(result.scenario->cycle_time(), 0.001);
  EXPECT_EQ(result.scenario->trace_header(), "cycle,time,power1.Status");
}

// ---- TO configuration ----

// docs/scenarios.md "`config`: start values by data-block path"; spec 04 (each variable's range).
TEST(ScenarioConfig, OutOfRangeNamesThePathAndTheRange) {
  EXPECT_EQ(problem_of(with_config(R"({"DynamicLimits.MaxVelocity": 1e13})")),
            "technology_objects[0].config.DynamicLimits.MaxVelocity: 1e13 out of range 0..1e12");
}

// docs/scenarios.md "`config`: start values by data-block path".
TEST(ScenarioConfig, UnknownPathWithSuggestion) {
  EXPECT_EQ(problem_of(with_config(R"({"DynamicLimits.MaxVelocityy": 1})")),
            "technology_objects[0].config.DynamicLimits.MaxVelocityy: unknown variable of TO_SpeedAxis");
  EXPECT_EQ(problem_of(with_config(R"({"dynamiclimits.maxvelocity": 1})")),
            "technology_objects[0].config.dynamiclimits.maxvelocity: unknown variable of TO_SpeedAxis (did "
            "you mean "
            "'DynamicLimits.MaxVelocity'?)");
  EXPECT_NE(problem_of(with_config(R"({"DynamicLimits": {"MaxVelocity": 1}})"))
                .find("keys are full data-block paths such as 'DynamicLimits.MaxVelocity'"),
            std::string::npos);
}

// docs/scenarios.md "`config`: start values by data-block path"; spec 04 §0.2 (access column).
TEST(ScenarioConfig, StatusVariablesAreNotConfiguration) {
  EXPECT_EQ(problem_of(with_config(R"({"StatusWord": 1})")),
            "technology_objects[0].config.StatusWord: cannot be configured: status variable, written by the "
            "technology object only");
}

// docs/scenarios.md "`config`: start values by data-block path"; spec 04 §0.4 (data types).
TEST(ScenarioConfig, WrongTypes) {
  EXPECT_EQ(problem_of(with_config(R"({"Override.Velocity": "50"})")),
            "technology_objects[0].config.Override.Velocity: expected a number (LREAL), got a string");
  EXPECT_EQ(
      problem_of(with_config(R"({"Actor.InverseDirection": 1})")),
      "technology_objects[0].config.Actor.InverseDirection: expected true or false (BOOL), got a number");
  EXPECT_EQ(problem_of(with_config(R"({"LoadGear.Numerator": true})")),
            "technology_objects[0].config.LoadGear.Numerator: expected an integer (UDINT), got a boolean");
  EXPECT_EQ(problem_of(with_config(R"({"LoadGear.Numerator": 1.5})")),
            "technology_objects[0].config.LoadGear.Numerator: 1.5 is not an integer (UDINT)");
  EXPECT_EQ(problem_of(with_config(R"([1])")),
            "technology_objects[0].config: expected an object of data-block paths, got an array");
}

// docs/scenarios.md "`config`: start values by data-block path"; spec 04 §0.4.
TEST(ScenarioConfig, PermittedValuesAndHexLiterals) {
  EXPECT_EQ(
      problem_of(with_config(R"({"Actor.RemoveEnableReaction": 2})")),
      "technology_objects[0].config.Actor.RemoveEnableReaction: 2 is not a permitted value (1, 3, 5, 7)");
  EXPECT_EQ(
      problem_of(with_config(R"({"Actor.RemoveEnableReaction": "16#Z"})")),
      "technology_objects[0].config.Actor.RemoveEnableReaction: '16#Z' is not a WORD literal such as 16#7 "
      "or 0x7");
  EXPECT_TRUE(problems_of(with_config(R"({"Actor.RemoveEnableReaction": "16#3"})")).empty());
  EXPECT_TRUE(problems_of(with_config(R"({"Actor.RemoveEnableReaction": "0x5"})")).empty());
}

// docs/scenarios.md "`config`: start values by data-block path" (every problem of a file at once).
TEST(ScenarioConfig, EveryProblemIsReported) {
  const auto problems = problems_of(with_config(
      R"({"DynamicLimits.MaxVelocity": 1e13, "Nope": 1, "StatusWord": 0, "Override.Velocity": false})"));
  EXPECT_EQ(problems.size(), 4u) << ::testing::PrintToString(problems);
}

// docs/scenarios.md "`config`: start values by data-block path".
TEST(ScenarioConfig, LoaderWritesStartValues) {
  tomc::techobjects::SpeedAxisData data;
  Problems problems;
  tomc::scenario::load_speed_axis_config(
      Json::parse(
          R"({"DynamicDefaults.Velocity": 750.5, "Actor.InverseDirection": true, "Units.VelocityUnit": 1082,
                      "comment": "ignored"})"),
      "config", data, problems);
  EXPECT_TRUE(problems.empty()) << ::testing::PrintToString(problems.lines());
  EXPECT_DOUBLE_EQ(data.DynamicDefaults.Velocity, 750.5);
  EXPECT_TRUE(data.Actor.InverseDirection);
  EXPECT_EQ(data.Units.VelocityUnit, 1082u);
  EXPECT_DOUBLE_EQ(data.DynamicLimits.MaxVelocity, 3000.0);  // untouched default
}

// ---- drive ----

// The analog actor (docs/analog-drives.md) is a telegram-3 drive to the TO; its own keys live in "analog".
TEST(ScenarioDrive, AnalogAdapter) {
  EXPECT_TRUE(problems_of(with_drive(R"({"adapter": "analog", "telegram": 3,
      "analog": {"volts_at_reference": 10, "overdrive_percent": 100, "dac_bits": 16, "dac_full_scale_volts": 10,
                 "offset_volts": 0.01, "amplifier_offset_volts": -0.01, "ready_delay_s": 0}})"))
                  .empty());
  EXPECT_EQ(
      problem_of(with_drive(R"({"adapter": "analog", "telegram": 2})")),
      "technology_objects[0].drive.telegram: 2: the analog actor is a telegram-3 drive to the TO (write 3, "
      "or 2 with an encoder_telegram 81/83)");
  // A separate 81/83 encoder (spec 01 §3.3 "1 + 81/83"): the actor is then a telegram-2 drive.
  EXPECT_TRUE(
      problems_of(with_drive(R"({"adapter": "analog", "telegram": 2, "encoder_telegram": 83})")).empty());
  EXPECT_TRUE(
      problems_of(with_drive(R"({"adapter": "analog", "telegram": 2, "encoder_telegram": 81})")).empty());
  EXPECT_EQ(problem_of(with_drive(R"({"adapter": "analog", "telegram": 3, "encoder_telegram": 81})")),
            "technology_objects[0].drive.telegram: 3: with a separate encoder (encoder_telegram) the analog "
            "actor is a telegram-2 drive (write 2; telegram 3 carries the counter as its encoder)");
  EXPECT_EQ(problem_of(with_drive(R"({"adapter": "analog", "telegram": 3, "supplementary_telegram": 750})")),
            "technology_objects[0].drive.supplementary_telegram: the analog actor has no telegram 750");
  {
    Json e = base();
    e["timeline"].push_back(
        Json::parse(R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "encoder_signal_lost"}})"));
    EXPECT_EQ(
        problem_of(e),
        "timeline[1].inject.target: Axis1 has no analog drive with an encoder on its counter (a separate "
        "81/83 encoder fails with encoder_error)");
    e["technology_objects"][0]["drive"] = Json::parse(R"({"adapter": "analog", "telegram": 3})");
    EXPECT_TRUE(problems_of(e).empty());
  }
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "analog": {}})")),
            "technology_objects[0].drive.analog: only with \"adapter\": \"analog\"");
  EXPECT_EQ(
      problem_of(with_drive(R"({"adapter": "analog", "telegram": 3, "analog": {"overdrive_percent": 120,
      "dac_full_scale_volts": 10}})")),
      "technology_objects[0].drive.analog: the overdrive range (12 V) exceeds the DAC's full scale (10 V)");
  EXPECT_NE(problem_of(with_drive(R"({"adapter": "analog", "telegram": 3, "analog": {"dac_bits": 20}})"))
                .find("technology_objects[0].drive.analog.dac_bits: 20"),
            std::string::npos);
  Json d = base();
  d["timeline"].push_back(
      Json::parse(R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "amplifier_fault"}})"));
  EXPECT_EQ(problem_of(d),
            "timeline[1].inject.target: Axis1 has no analog or stepper drive (\"adapter\": \"analog\" or "
            "\"stepper\")");
  d = base();
  d["trace"] = Json::array({"Axis1.analog.output_volts"});
  EXPECT_EQ(problem_of(d), "trace[0]: 'Axis1' has no analog drive");
  // TarOffs inputs (docs/analog-drives.md) are set like variables, on an analog drive only, as BOOL.
  d = base();
  d["timeline"].push_back(Json::parse(R"({"cycle": 1, "set": {"Axis1.analog.TarOffs.En": true}})"));
  EXPECT_EQ(problem_of(d),
            "timeline[1].set.Axis1.analog.TarOffs.En: Axis1 has no analog drive (\"adapter\": \"analog\")");
  d["technology_objects"][0]["drive"] = Json::parse(R"({"adapter": "analog", "telegram": 3})");
  EXPECT_TRUE(problems_of(d).empty());
  d["timeline"][1]["set"]["Axis1.analog.TarOffs.Reset"] = 1;
  EXPECT_EQ(problem_of(d), "timeline[1].set.Axis1.analog.TarOffs.Reset: expected true or false");
}

// The stepper actor (docs/analog-drives.md, spec 01 §3.11) is a telegram-3 drive to the TO; its own keys live
// in "stepper". With the PTO's pulse count as the position the TO's encoder must count motor steps.
TEST(ScenarioDrive, StepperAdapter) {
  EXPECT_TRUE(problems_of(with_drive(R"({"adapter": "stepper", "telegram": 3,
      "stepper": {"steps_per_revolution": 1600, "max_frequency_hz": 50000, "feedback": "pulses",
                  "pull_in_rate_hz": 1000, "pull_out_rate_hz": 30000, "max_acceleration_hz_per_s": 200000,
                  "ready_delay_s": 0}})"))
                  .empty());
  Json d = base();
  d["technology_objects"][0]["type"] = "TO_PositioningAxis";
  d["technology_objects"][0]["drive"] = Json::parse(R"({"adapter": "stepper", "telegram": 3})");
  EXPECT_EQ(
      problem_of(d),
      "technology_objects[0].drive.stepper.steps_per_revolution: 1600: with \"feedback\": \"pulses\" the "
      "TO's encoder counts motor steps (Sensor[1] StepsPerRevolution · 2^FineResolutionXist1 = 4194304)");
  d["technology_objects"][0]["config"]["Sensor[1].Parameter.StepsPerRevolution"] = 1600;
  d["technology_objects"][0]["config"]["Sensor[1].Parameter.FineResolutionXist1"] = 0;
  EXPECT_TRUE(problems_of(d).empty());
  d["technology_objects"][0]["drive"]["stepper"]["feedback"] = "encoder";
  d["technology_objects"][0]["config"] = Json::object();
  EXPECT_TRUE(problems_of(d).empty());
  EXPECT_EQ(
      problem_of(with_drive(R"({"adapter": "stepper", "telegram": 1})")),
      "technology_objects[0].drive.telegram: 1: the stepper actor is a telegram-3 drive to the TO (write 3)");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "stepper": {}})")),
            "technology_objects[0].drive.stepper: only with \"adapter\": \"stepper\"");
  EXPECT_EQ(
      problem_of(with_drive(
          R"({"adapter": "stepper", "telegram": 3, "stepper": {"pull_in_rate_hz": 5000, "pull_out_rate_hz": 4000}})")),
      "technology_objects[0].drive.stepper: pull_in_rate_hz (5000) must not exceed pull_out_rate_hz (4000)");
  EXPECT_NE(
      problem_of(with_drive(R"({"adapter": "stepper", "telegram": 3, "stepper": {"feedback": "none"}})"))
          .find("technology_objects[0].drive.stepper.feedback"),
      std::string::npos);
  d = base();
  d["trace"] = Json::array({"Axis1.stepper.lost_steps"});
  EXPECT_EQ(problem_of(d), "trace[0]: 'Axis1' has no stepper drive");
}

// docs/scenarios.md "`drive`: adapter, telegram and the simulated machine".
TEST(ScenarioDrive, AdapterAndTelegram) {
  EXPECT_NE(problem_of(with_drive(R"({"adapter": "dds", "telegram": 2})"))
                .find("technology_objects[0].drive.adapter: the gateway adapter is an object: {\"type\": "
                      "\"dds_gateway\""),
            std::string::npos);
  EXPECT_EQ(
      problem_of(with_drive(R"({"adapter": "servo", "telegram": 3})")),
      "technology_objects[0].drive.adapter: 'servo' is not an adapter ('simulated', 'analog', 'stepper', or "
      "a dds_gateway object)");
  EXPECT_EQ(problem_of(with_drive(R"({"adapter": "simulated"})")),
            "technology_objects[0].drive.telegram: missing");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 81})")),
            "technology_objects[0].drive.telegram: 81 is not a drive telegram (1, 2, 3, 4, 5, 6, 102, 103, "
            "105, 106)");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": "2"})")),
            "technology_objects[0].drive.telegram: expected an integer, got a string");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 2, "supplementary_telegram": 751})")),
            "technology_objects[0].drive.supplementary_telegram: 751 is not 0 or 750");
  EXPECT_EQ(problem_of(with_drive(R"(3)")), "technology_objects[0].drive: expected an object, got a number");
  EXPECT_TRUE(problems_of(with_drive(R"({"telegram": 105, "supplementary_telegram": 750})")).empty());
}

// docs/scenarios.md "`drive`: adapter, telegram and the simulated machine".
TEST(ScenarioDrive, ModelParameters) {
  EXPECT_EQ(
      problem_of(with_drive(R"({"telegram": 2, "servo_cycle_s": 0.002})")),
      "technology_objects[0].drive.servo_cycle_s: 0.002 differs from cycle_time 0.001 (the drive runs in the "
      "MC_Servo cycle; leave it out)");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 2, "substeps": 0})")),
            "technology_objects[0].drive.substeps: 0 out of range 1..1000");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 2, "reference_speed_rpm": 0})")),
            "technology_objects[0].drive.reference_speed_rpm: 0 out of range: must be greater than 0");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 2, "coulomb_friction_nm": -1})")),
            "technology_objects[0].drive.coulomb_friction_nm: -1 out of range: must be at least 0");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 2, "isochronous": "yes"})")),
            "technology_objects[0].drive.isochronous: expected true or false, got a string");
  EXPECT_EQ(
      problem_of(with_drive(R"({"telegram": 2, "communication_fault_reaction": "OFF4"})")),
      "technology_objects[0].drive.communication_fault_reaction: 'OFF4' is not one of OFF1, OFF2, OFF3");
  EXPECT_NE(problem_of(with_drive(R"({"telegram": 2, "motor_inertia": 1})"))
                .find("technology_objects[0].drive.motor_inertia: unknown key (known here: 'adapter', "
                      "'encoder_telegram', 'telegram'"),
            std::string::npos);
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 2, "initial_load_position": null})")),
            "technology_objects[0].drive.initial_load_position: expected a number, got null");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 2, "backlash": -0.1})")),
            "technology_objects[0].drive.backlash: -0.1 out of range: must be at least 0");
}

// docs/scenarios.md "`drive`: adapter, telegram and the simulated machine".
TEST(ScenarioDrive, EncodersAndMachine) {
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "encoder1": {"shaft": "gear"}})")),
            "technology_objects[0].drive.encoder1.shaft: 'gear' is not one of motor, load");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "encoder2": {"fine_resolution_xist1": 40}})")),
            "technology_objects[0].drive.encoder2.fine_resolution_xist1: 40 out of range 0..31");
  EXPECT_NE(problem_of(with_drive(R"({"telegram": 3, "encoder1": {"steps": 1}})"))
                .find("encoder1.steps: unknown key"),
            std::string::npos);
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "encoder1": []})")),
            "technology_objects[0].drive.encoder1: expected an object, got an array");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "machine": {"reference_cam": {"from": 5, "to": 1}}})")),
            "technology_objects[0].drive.machine.reference_cam: from (5) is greater than to (1)");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "machine": {"probe1": {"from": 5}}})")),
            "technology_objects[0].drive.machine.probe1.to: missing");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "machine": {"probe2": 4}})")),
            "technology_objects[0].drive.machine.probe2: expected an object, got a number");
  EXPECT_EQ(
      problem_of(
          with_drive(R"({"telegram": 3, "machine": {"negative_fixed_stop": 10, "positive_fixed_stop": 0}})")),
      "technology_objects[0].drive.machine: negative_fixed_stop (10) must be below positive_fixed_stop (0)");
  EXPECT_EQ(problem_of(with_drive(R"({"telegram": 3, "machine": {"positive_limit_switch": "far"}})")),
            "technology_objects[0].drive.machine.positive_limit_switch: expected a number, got a string");
}

// docs/scenarios.md "`drive`: adapter, telegram and the simulated machine".
TEST(ScenarioDrive, EveryFieldIsRead) {
  tomc::scenario::DriveSettings s;
  Problems problems;
  tomc::scenario::load_drive(Json::parse(R"({
      "adapter": "simulated", "telegram": 3, "supplementary_telegram": 750, "servo_cycle_s": 0.002, "substeps": 8,
      "reference_speed_rpm": 1500, "max_speed_rpm": 3000, "reference_torque_nm": 10, "torque_limit_nm": 8,
      "off1_ramp_down_time_s": 2, "off3_ramp_down_time_s": 0.5, "standstill_threshold_rpm": 5,
      "speed_deviation_tolerance_rpm": 50, "sign_of_life_tolerance": "16#FFFF", "isochronous": false,
      "setpoint_timeout_cycles": 7, "communication_fault_reaction": "OFF1", "speed_loop_time_constant_s": 0.004,
      "motor_inertia_kgm2": 0.001, "load_inertia_kgm2": 0.01, "viscous_friction_nm_per_rad_s": 0.002,
      "coulomb_friction_nm": 0.1, "gear_motor_revolutions": 3, "gear_load_revolutions": 1,
      "load_units_per_revolution": 10, "initial_load_position": -4, "backlash": 0.05,
      "initial_backlash_offset": -0.025,
      "encoder1": { "shaft": "load", "linear": true, "resolution": 0.01, "steps_per_revolution": 4096,
                    "fine_resolution_xist1": 2, "fine_resolution_xist2": 3, "determinable_revolutions": 0,
                    "xist1_width_bits": 16, "xist1_at_power_on": "0x100", "reference_mark_interval_revolutions": 2,
                    "reference_mark_offset_revolutions": 0.5, "absolute_offset_revolutions": 1.5,
                    "nist_reference_speed": 600 },
      "encoder2": { "shaft": "motor" },
      "machine": { "negative_limit_switch": -100, "positive_limit_switch": 100, "reference_cam": {"from": 1, "to": 2},
                   "probe1": {"from": 3, "to": 4}, "probe2": null, "negative_fixed_stop": -200,
                   "positive_fixed_stop": 200 }
    })"),
                             "drive", 0.002, s, problems);
  ASSERT_TRUE(problems.empty()) << ::testing::PrintToString(problems.lines());
  const auto& p = s.parameters;
  EXPECT_EQ(s.telegram, 3);
  EXPECT_EQ(s.supplementary_telegram, 750);
  EXPECT_EQ(s.device_config().drive_telegram, 3);
  EXPECT_EQ(s.device_config().supplementary_telegram, 750);
  EXPECT_DOUBLE_EQ(p.servo_cycle_s, 0.002);
  EXPECT_EQ(p.substeps, 8u);
  EXPECT_DOUBLE_EQ(p.reference_speed_rpm, 1500);
  EXPECT_DOUBLE_EQ(p.max_speed_rpm, 3000);
  EXPECT_DOUBLE_EQ(p.reference_torque_nm, 10);
  EXPECT_DOUBLE_EQ(p.torque_limit_nm, 8);
  EXPECT_DOUBLE_EQ(p.off1_ramp_down_time_s, 2);
  EXPECT_DOUBLE_EQ(p.off3_ramp_down_time_s, 0.5);
  EXPECT_DOUBLE_EQ(p.standstill_threshold_rpm, 5);
  EXPECT_DOUBLE_EQ(p.speed_deviation_tolerance_rpm, 50);
  EXPECT_EQ(p.sign_of_life_tolerance, 0xFFFF);
  EXPECT_FALSE(p.isochronous);
  EXPECT_EQ(p.setpoint_timeout_cycles, 7u);
  EXPECT_EQ(p.communication_fault_reaction, tomc::drives::SimulatedDriveParameters::FaultReaction::kOff1);
  EXPECT_DOUBLE_EQ(p.speed_loop_time_constant_s, 0.004);
  EXPECT_DOUBLE_EQ(p.motor_inertia_kgm2, 0.001);
  EXPECT_DOUBLE_EQ(p.load_inertia_kgm2, 0.01);
  EXPECT_DOUBLE_EQ(p.viscous_friction_nm_per_rad_s, 0.002);
  EXPECT_DOUBLE_EQ(p.coulomb_friction_nm, 0.1);
  EXPECT_DOUBLE_EQ(p.gear_motor_revolutions, 3);
  EXPECT_DOUBLE_EQ(p.gear_load_revolutions, 1);
  EXPECT_DOUBLE_EQ(p.load_units_per_revolution, 10);
  EXPECT_DOUBLE_EQ(p.initial_load_position, -4);
  EXPECT_DOUBLE_EQ(p.backlash, 0.05);
  EXPECT_DOUBLE_EQ(p.initial_backlash_offset, -0.025);
  EXPECT_EQ(p.encoder1.shaft, tomc::drives::SimulatedEncoderParameters::Shaft::kLoad);
  EXPECT_TRUE(p.encoder1.linear);
  EXPECT_DOUBLE_EQ(p.encoder1.resolution, 0.01);
  EXPECT_EQ(p.encoder1.steps_per_revolution, 4096u);
  EXPECT_EQ(p.encoder1.fine_resolution_xist1, 2);
  EXPECT_EQ(p.encoder1.fine_resolution_xist2, 3);
  EXPECT_EQ(p.encoder1.determinable_revolutions, 0u);
  EXPECT_EQ(p.encoder1.xist1_width_bits, 16);
  EXPECT_EQ(p.encoder1.xist1_at_power_on, 0x100u);
  EXPECT_DOUBLE_EQ(p.encoder1.reference_mark_interval_revolutions, 2);
  EXPECT_DOUBLE_EQ(p.encoder1.reference_mark_offset_revolutions, 0.5);
  EXPECT_DOUBLE_EQ(p.encoder1.absolute_offset_revolutions, 1.5);
  EXPECT_DOUBLE_EQ(p.encoder1.nist_reference_speed, 600);
  EXPECT_EQ(p.encoder2.shaft, tomc::drives::SimulatedEncoderParameters::Shaft::kMotor);
  EXPECT_EQ(p.machine.negative_limit_switch, -100);
  EXPECT_EQ(p.machine.positive_limit_switch, 100);
  ASSERT_TRUE(p.machine.reference_cam);
  EXPECT_DOUBLE_EQ(p.machine.reference_cam->to, 2);
  ASSERT_TRUE(p.machine.probe1);
  EXPECT_DOUBLE_EQ(p.machine.probe1->from, 3);
  EXPECT_FALSE(p.machine.probe2);
  EXPECT_EQ(p.machine.negative_fixed_stop, -200);
  EXPECT_EQ(p.machine.positive_fixed_stop, 200);
}

// ---- scenario level ----

// docs/scenarios.md "Top level".
TEST(ScenarioLoader, TopLevel) {
  Json d = base();
  d.erase("cycle_time");
  EXPECT_EQ(problem_of(d), "cycle_time: missing");
  d = base();
  d["cycle_time"] = 0;
  EXPECT_EQ(problem_of(d), "cycle_time: 0 out of range: must be greater than 0");
  d = base();
  d["cycles"] = 0;
  EXPECT_EQ(problem_of(d), "cycles: 0 out of range 1..1000000000");
  d = base();
  d["cycles"] = 2.5;
  EXPECT_EQ(problem_of(d), "cycles: 2.5 is not an integer");
  d = base();
  d["cylces"] = 3;
  EXPECT_NE(problem_of(d).find("cylces: unknown key"), std::string::npos);
  d = base();
  d["comment"] = "allowed everywhere";
  EXPECT_TRUE(problems_of(d).empty());
  EXPECT_EQ(problem_of(Json::parse("[]")), ": expected an object, got an array");
}

// A cam in a machine file (docs/scenarios.md "Cams", decisions C7): its elements beside config, every problem
// named by its JSON path.
TEST(ScenarioLoader, Cams) {
  const auto with_cam = [](const char* cam) {
    Json d = base();
    d["technology_objects"].push_back(Json::parse(cam));
    return d;
  };
  EXPECT_TRUE(problems_of(with_cam(R"({"name": "C", "type": "TO_Cam", "Points": [[0, 0], [1, 1]],
      "Interpolate": true})"))
                  .empty());
  EXPECT_EQ(problem_of(with_cam(R"({"name": "C", "type": "TO_Cam", "Points": [[0, 0], [1]]})")),
            "technology_objects[1].Points[1]: expected [x, y]");
  EXPECT_EQ(
      problem_of(with_cam(R"({"name": "C", "type": "TO_Cam", "Points": [[0, 0]], "Interpolate": true})")),
      "technology_objects[1].Interpolate: MC_InterpolateCam fails with 16#80AC: the cam elements make no "
      "cam (a single point, points out of order, a segment with xmin >= xmax, a value that is not finite)");
  EXPECT_EQ(
      problem_of(with_cam(R"({"name": "C", "type": "TO_Cam", "Points": [[0, 0], [5, 1], [2, 2]],
      "Interpolate": true})")),
      "technology_objects[1].Interpolate: MC_InterpolateCam fails with 16#80AC: the cam elements make no "
      "cam (a single point, points out of order, a segment with xmin >= xmax, a value that is not finite) "
      "(element 3)");
  EXPECT_EQ(
      problem_of(with_cam(R"({"name": "C", "type": "TO_Cam", "Points": {"file": "no_such_file.csv"}})")),
      "technology_objects[1].Points.file: cannot read 'no_such_file.csv'");
  EXPECT_EQ(problem_of(with_cam(R"({"name": "C", "type": "TO_Cam", "Segments": [{"xmin": 0, "a0": 1}]})")),
            "technology_objects[1].Segments[0].xmax: missing");
  EXPECT_NE(problem_of(with_cam(R"({"name": "C", "type": "TO_Cam",
      "MotionLaws": [{"law": "Cycloid", "x0": 0, "y0": 0, "x1": 1, "y1": 1}]})"))
                .find("technology_objects[1].MotionLaws[0].law: 'Cycloid' is not one of"),
            std::string::npos);
  EXPECT_EQ(problem_of(with_cam(R"({"name": "C", "type": "TO_Cam", "drive": {"telegram": 3}})")),
            "technology_objects[1].drive: a cam has no drive (it is a transfer function, spec 07 §3.1)");
  EXPECT_EQ(problem_of(with_cam(R"({"name": "C", "type": "TO_Cam",
      "config": {"InterpolationSettings.InterpolationMode": 3}})")),
            "technology_objects[1].config.InterpolationSettings.InterpolationMode: 3 out of range 0..2");
  EXPECT_EQ(
      problem_of(with_cam(R"({"name": "C", "type": "TO_Cam", "config": {"StatusCam.EndLeadingValue": 3}})")),
      "technology_objects[1].config.StatusCam.EndLeadingValue: cannot be configured: status variable, "
      "written by "
      "the technology object only");
  Json points = Json::array();
  for (int i = 0; i < 1001; ++i)
    points.push_back(Json::array({i, 0}));
  Json d = with_cam(R"({"name": "C", "type": "TO_Cam"})");
  d["technology_objects"][1]["Points"] = points;
  EXPECT_EQ(problem_of(d), "technology_objects[1].Points: 1001 points, a TO_Cam holds 1000");
  d["technology_objects"][1]["type"] = "TO_Cam_10k";
  EXPECT_TRUE(problems_of(d).empty());
  // The cam instructions on a cam; MC_CopyCamData (arrays) is not available in scenarios.
  d = with_cam(R"({"name": "C", "type": "TO_Cam", "Points": [[0, 0], [1, 1]]})");
  d["timeline"].push_back(Json::parse(
      R"({"cycle": 1, "instance": "i", "instruction": "MC_InterpolateCam", "axis": "C", "inputs": {"Execute": true}})"));
  EXPECT_TRUE(problems_of(d).empty());
  d["timeline"][1]["instruction"] = "MC_CopyCamData";
  EXPECT_NE(problem_of(d).find("timeline[1].instruction: MC_CopyCamData is not yet supported by tomc sim"),
            std::string::npos);
  d["timeline"][1]["instruction"] = "MC_Power";
  EXPECT_NE(problem_of(d).find("MC_Power is not an instruction of TO_Cam C"), std::string::npos);
}

// docs/scenarios.md "`technology_objects[i]`".
TEST(ScenarioLoader, TechnologyObjects) {
  Json d = base();
  d["technology_objects"] = Json::array();
  EXPECT_EQ(problem_of(d),
            "technology_objects: expected a non-empty array of technology objects, got an empty array");
  d = base();
  d["technology_objects"][0]["type"] = "TO_OutputCam";
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].type: TO_OutputCam is not yet supported by tomc (supported: "
            "TO_SpeedAxis, TO_PositioningAxis, TO_SynchronousAxis, TO_ExternalEncoder, TO_Cam, TO_Cam_10k, "
            "TO_Cam_600Seg, TO_Cam_6kSeg)");
  d["technology_objects"][0]["type"] = "TO_Spindle";
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].type: unknown technology object type 'TO_Spindle' (one of "
            "TO_SpeedAxis, TO_PositioningAxis, TO_SynchronousAxis, TO_ExternalEncoder, TO_Cam, TO_Cam_10k, "
            "TO_Cam_600Seg, TO_Cam_6kSeg)");
  // A positioning axis needs an encoder: telegram 2 carries none (spec 01 §3.3), named by the TO's path.
  d["technology_objects"][0]["type"] = "TO_PositioningAxis";
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].config: Axis1.Sensor[1].Interface.Number: the device's telegrams carry no "
            "such encoder (drive telegram 2, encoder telegram 0)");
  // Units must fit the motion type (spec 04 §3.11).
  d["technology_objects"][0]["drive"] = Json::parse(R"({"telegram": 3})");
  d["technology_objects"][0]["config"] =
      Json::parse(R"({"Units.LengthUnit": 1005, "Units.VelocityUnit": 1521})");
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].config: Axis1.Units.LengthUnit: a linear axis needs a length unit (m, mm, "
            "in, ...)");
  d["technology_objects"][0]["config"] = Json::parse(R"({"Sensor[1].Parameter.StepsPerRevolution": 0})");
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].config.Sensor[1].Parameter.StepsPerRevolution: 0 out of range 1..8388608");
  d["technology_objects"][0]["config"] = Json::object();
  d["technology_objects"][0]["type"] = "TO_Conveyor";
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].type: unknown technology object type 'TO_Conveyor' (one of "
            "TO_SpeedAxis, TO_PositioningAxis, TO_SynchronousAxis, TO_ExternalEncoder, TO_Cam, TO_Cam_10k, "
            "TO_Cam_600Seg, TO_Cam_6kSeg)");
  d = base();
  d["technology_objects"][0]["name"] = "Axis 1";
  EXPECT_NE(problems_of(d).front().find("technology_objects[0].name: 'Axis 1' is not a name"),
            std::string::npos);
  d = base();
  d["technology_objects"].push_back(d["technology_objects"][0]);
  EXPECT_EQ(problem_of(d), "technology_objects[1].name: 'Axis1' is defined twice");
  d = base();
  d["technology_objects"][0].erase("drive");
  EXPECT_NE(problem_of(d).find("technology_objects[0].drive: missing"), std::string::npos);
  // A virtual axis needs no drive.
  d["technology_objects"][0]["config"]["VirtualAxis.Mode"] = 1;
  EXPECT_TRUE(problems_of(d).empty());
}

// docs/scenarios.md "`timeline`: events".
TEST(ScenarioLoader, EventTiming) {
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 10, "instance": "power1"})")),
            "timeline[1].cycle: 10 out of range 0..9");
  Json d = base();
  d["timeline"][0]["cycle"] = 5;
  d["timeline"].push_back(Json::parse(R"({"cycle": 4, "instance": "power1"})"));
  EXPECT_EQ(problem_of(d),
            "timeline[1].cycle: 4 is before the previous event's cycle 5 (events must be in time order)");
  EXPECT_TRUE(
      problems_of(with_event(R"({"cycle": 0, "instance": "power1", "inputs": {"Enable": false}})")).empty());
  EXPECT_EQ(problem_of(with_event(R"({"instance": "power1"})")), "timeline[1].cycle: missing");
  Json t = base();
  t["timeline"] = Json::object();
  EXPECT_EQ(problem_of(t), "timeline: expected an array of events, got an object");
}

// docs/scenarios.md "`timeline`: events".
TEST(ScenarioLoader, EventKinds) {
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1})")),
            "timeline[1]: an event needs one of 'instance', 'set', 'inject', 'clear'");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "set": {}})")),
            "timeline[1]: an event does one thing: it has both 'instance' and 'set'");
  EXPECT_NE(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "input": {}})"))
                .find("timeline[1].input: unknown key"),
            std::string::npos);
  EXPECT_EQ(problem_of(with_event(R"(17)")), "timeline[1]: expected an object, got a number");
}

// docs/scenarios.md "`timeline`: events" (the first event of an instance names its instruction).
TEST(ScenarioLoader, InstanceCreation) {
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "move1", "axis": "Axis1"})")),
            "timeline[1].instruction: missing (the first event of instance 'move1' must give instruction and "
            "axis)");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "move1", "instruction": "MC_MoveVelocity"})")),
            "timeline[1].axis: missing (the first event of instance 'move1' must give instruction and axis)");
  EXPECT_NE(
      problem_of(with_event(R"({"cycle": 1, "instance": "m", "instruction": "MC_Fly", "axis": "Axis1"})"))
          .find("timeline[1].instruction: unknown instruction 'MC_Fly' (supported: MC_Power, MC_Reset"),
      std::string::npos);
  EXPECT_NE(
      problem_of(
          with_event(R"({"cycle": 1, "instance": "m", "instruction": "MC_MoveAbsolute", "axis": "Axis1"})"))
          .find(
              "timeline[1].instruction: MC_MoveAbsolute is not an instruction of TO_SpeedAxis Axis1 (spec 01 "
              "§1.3; its instructions: MC_Power, MC_Reset"),
      std::string::npos);
  EXPECT_NE(
      problem_of(
          with_event(R"({"cycle": 1, "instance": "m", "instruction": "MC_MeasuringInput", "axis": "Axis1"})"))
          .find("timeline[1].instruction: MC_MeasuringInput is not yet supported by tomc sim"),
      std::string::npos);
  EXPECT_EQ(
      problem_of(with_event(R"({"cycle": 1, "instance": "m", "instruction": "MC_Halt", "axis": "Axis2"})")),
      "timeline[1].axis: unknown technology object 'Axis2' (defined: Axis1)");
  EXPECT_EQ(problem_of(with_event(
                R"({"cycle": 1, "instance": "Axis1", "instruction": "MC_Halt", "axis": "Axis1"})")),
            "timeline[1].instance: 'Axis1' is already the name of a technology object");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "instruction": "MC_Halt"})")),
            "timeline[1].instruction: instance 'power1' is an MC_Power (timeline[0]); one name denotes one "
            "instance");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "axis": "Axis9"})")),
            "timeline[1].axis: instance 'power1' works on Axis1 (timeline[0]), not Axis9");
  EXPECT_NE(
      problem_of(with_event(R"({"cycle": 1, "instance": "2x", "instruction": "MC_Halt", "axis": "Axis1"})"))
          .find("timeline[1].instance: '2x' is not a name"),
      std::string::npos);
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": 5})")),
            "timeline[1].instance: expected a string, got a number");
}

// docs/scenarios.md "Instruction inputs".
TEST(ScenarioLoader, Inputs) {
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "inputs": {"Enabled": true}})")),
            "timeline[1].inputs.Enabled: unknown input of MC_Power (inputs: Enable, StartMode, StopMode)");
  EXPECT_EQ(
      problem_of(with_event(R"({"cycle": 1, "instance": "power1", "inputs": {"Status": true}})")),
      "timeline[1].inputs.Status: 'Status' is an output of MC_Power (inputs: Enable, StartMode, StopMode)");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "inputs": {"Enable": 1}})")),
            "timeline[1].inputs.Enable: expected true or false, got a number");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "inputs": {"StopMode": 40000}})")),
            "timeline[1].inputs.StopMode: 40000 out of range -32768..32767");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "inputs": {"StartMode": 1e10}})")),
            "timeline[1].inputs.StartMode: 1e10 out of range -2147483648..2147483647");
  EXPECT_EQ(
      problem_of(with_event(
          R"({"cycle": 1, "instance": "v", "instruction": "MC_MoveVelocity", "axis": "Axis1", "inputs": {"Velocity": "fast"}})")),
      "timeline[1].inputs.Velocity: expected a number, got a string");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "instance": "power1", "inputs": [true]})")),
            "timeline[1].inputs: expected an object, got an array");
  // WORD inputs take PLC hex literals.
  EXPECT_TRUE(
      problems_of(with_event(
                      R"({"cycle": 1, "instance": "stw", "instruction": "MC_SetAxisSTW", "axis": "Axis1",
                      "inputs": {"STW1": "16#0100", "STW1BitMask": 256, "STW2": "0x80"}})"))
          .empty());
  EXPECT_EQ(problem_of(
                with_event(R"({"cycle": 1, "instance": "stw", "instruction": "MC_SetAxisSTW", "axis": "Axis1",
                                      "inputs": {"STW2": 70000}})")),
            "timeline[1].inputs.STW2: 70000 out of range 0..65535");
  EXPECT_EQ(problem_of(
                with_event(R"({"cycle": 1, "instance": "stw", "instruction": "MC_SetAxisSTW", "axis": "Axis1",
                                      "inputs": {"STW2": "16#10000"}})")),
            "timeline[1].inputs.STW2: 16#10000 out of range 0..65535");
  EXPECT_EQ(problem_of(
                with_event(R"({"cycle": 1, "instance": "stw", "instruction": "MC_SetAxisSTW", "axis": "Axis1",
                                      "inputs": {"STW2": "high"}})")),
            "timeline[1].inputs.STW2: 'high' is not a hex literal such as 16#7 or 0x7");
  EXPECT_EQ(problem_of(
                with_event(R"({"cycle": 1, "instance": "stw", "instruction": "MC_SetAxisSTW", "axis": "Axis1",
                                      "inputs": {"STW2": -1}})")),
            "timeline[1].inputs.STW2: -1 out of range 0..65535");
}

// docs/scenarios.md "`set`: write TO variables as user code"; spec 04 §0.2 (what user code may write).
TEST(ScenarioLoader, SetEvents) {
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "set": {"Override.Velocity": 50}})")),
            "timeline[1].set.Override.Velocity: expected '<technology object>.<variable path>', e.g. "
            "'Axis1.Override.Velocity'");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "set": {"Axis1.Override.Speed": 50}})")),
            "timeline[1].set.Axis1.Override.Speed: unknown variable of TO_SpeedAxis Axis1");
  EXPECT_EQ(
      problem_of(with_event(R"({"cycle": 1, "set": {"Axis1.DynamicLimits.MaxVelocity": 50}})")),
      "timeline[1].set.Axis1.DynamicLimits.MaxVelocity: the user program cannot write it: restart relevant "
      "(RES): only the start value can be changed");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "set": {"Axis1.VirtualAxis.Mode": 1}})")),
            "timeline[1].set.Axis1.VirtualAxis.Mode: the user program cannot write it: read only (RON)");
  EXPECT_EQ(
      problem_of(with_event(R"({"cycle": 1, "set": {"Axis1.Velocity": 1}})")),
      "timeline[1].set.Axis1.Velocity: the user program cannot write it: status variable, written by the "
      "technology object only");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "set": {"Axis1.Override.Velocity": 250}})")),
            "timeline[1].set.Axis1.Override.Velocity: 250 out of range 0..200");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "set": {}})")),
            "timeline[1].set: expected at least one '<TO>.<variable>' to write");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "set": 3})")),
            "timeline[1].set: expected an object, got a number");
}

// docs/scenarios.md "`inject` / `clear`: simulated faults".
TEST(ScenarioLoader, FaultEvents) {
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "inject": {"target": "Axis2", "fault": "drive_fault"}})")),
            "timeline[1].inject.target: unknown technology object 'Axis2'");
  EXPECT_EQ(problem_of(with_event(R"({"cycle": 1, "inject": {"target": "Axis1"}})")),
            "timeline[1].inject.fault: missing");
  EXPECT_EQ(
      problem_of(with_event(R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "fire"}})")),
      "timeline[1].inject.fault: 'fire' is not one of drive_fault, encoder_error, sign_of_life_freeze, "
      "link_loss, technology_alarm, fixed_stop_break, amplifier_fault, encoder_signal_lost, safe_torque_off, "
      "safe_stop_1");
  EXPECT_EQ(problem_of(with_event(
                R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "drive_fault", "code": 0}})")),
            "timeline[1].inject.code: 0 out of range 1..4294967295");
  EXPECT_EQ(
      problem_of(with_event(
          R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "drive_fault", "reaction": "OFF0"}})")),
      "timeline[1].inject.reaction: 'OFF0' is not one of OFF1, OFF2, OFF3");
  EXPECT_EQ(problem_of(with_event(
                R"({"cycle": 1, "clear": {"target": "Axis1", "fault": "encoder_error", "encoder": 3}})")),
            "timeline[1].clear.encoder: 3 out of range 1..2");
  EXPECT_NE(
      problem_of(
          with_event(R"({"cycle": 1, "clear": {"target": "Axis1", "fault": "drive_fault", "code": 5}})"))
          .find("timeline[1].clear.code: unknown key"),
      std::string::npos);
  EXPECT_NE(
      problem_of(
          with_event(
              R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "link_loss", "reaction": "OFF1"}})"))
          .find("timeline[1].inject.reaction: unknown key"),
      std::string::npos);
  Json d = base();
  d["technology_objects"][0].erase("drive");
  d["technology_objects"][0]["config"]["VirtualAxis.Mode"] = 1;
  d["timeline"].push_back(
      Json::parse(R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "link_loss"}})"));
  EXPECT_EQ(problem_of(d), "timeline[1].inject.target: Axis1 has no simulated drive to inject faults into");
}

// docs/scenarios.md "`trace`: names and CSV".
TEST(ScenarioLoader, TraceNames) {
  auto traced = [](const char* name) {
    Json d = base();
    d["trace"] = Json::array({name});
    return d;
  };
  EXPECT_EQ(problem_of(traced("Status")),
            "trace[0]: 'Status' is not a trace name ('<TO>.<variable>' or '<instance>.<parameter>')");
  EXPECT_EQ(problem_of(traced("power2.Status")),
            "trace[0]: 'power2' is neither a technology object nor an instance of the timeline");
  EXPECT_EQ(problem_of(traced("Axis1.Speed")), "trace[0]: 'Speed' is not a variable of TO_SpeedAxis Axis1");
  EXPECT_EQ(problem_of(traced("Axis1.StatusWord.X32")),
            "trace[0]: 'StatusWord.X32' is not a variable of TO_SpeedAxis Axis1");
  EXPECT_EQ(
      problem_of(traced("power1.Done")),
      "trace[0]: 'Done' is not a parameter of MC_Power (Enable, StartMode, StopMode, Status, Busy, Error, "
      "ErrorID)");
  EXPECT_EQ(
      problem_of(traced("Axis1.drive.temperature")),
      "trace[0]: 'temperature' is not a drive value (state, active_fault, motor_speed_rpm, motor_torque_nm, "
      "load_position, load_speed)");
  EXPECT_EQ(problem_of(traced("Axis1.alarm.999")), "trace[0]: alarm 999 is not defined (docs/errors.md)");
  EXPECT_EQ(problem_of(traced("Axis1.alarm.560.additional")),
            "trace[0]: 'alarm.560.additional' is not an alarm trace name ('alarm.<number>' or "
            "'alarm.<number>.additional_value')");
  EXPECT_EQ(problem_of(traced("Axis1.alarm.")),
            "trace[0]: 'alarm.' is not an alarm trace name ('alarm.<number>' or "
            "'alarm.<number>.additional_value')");
  EXPECT_TRUE(problems_of(traced("Axis1.alarm.401")).empty());
  EXPECT_TRUE(problems_of(traced("Axis1.alarm.401.additional_value")).empty());
  EXPECT_TRUE(problems_of(traced("Axis1.StatusWord.%X5")).empty());
  EXPECT_TRUE(problems_of(traced("power1.Enable")).empty());  // inputs can be traced too
  Json d = base();
  d["trace"] = Json::array({"power1.Status", "power1.Status"});
  EXPECT_EQ(problem_of(d), "trace[1]: 'power1.Status' is traced twice");
  d["trace"] = Json::array({3});
  EXPECT_EQ(problem_of(d), "trace[0]: expected a string, got a number");
  d["trace"] = "power1.Status";
  EXPECT_EQ(problem_of(d), "trace: expected an array of trace names, got a string");
  d = base();
  d["technology_objects"][0].erase("drive");
  d["technology_objects"][0]["config"]["Simulation.Mode"] = 1;
  d["trace"] = Json::array({"Axis1.drive.state"});
  EXPECT_EQ(problem_of(d), "trace[0]: 'Axis1' has no simulated drive");
}

// A synchronous axis' StatusSynchronizedMotion.* (spec 07 §1.9) is traceable; an unknown member, or the
// structure on another TO type, is a problem naming the TO.
TEST(ScenarioLoader, SynchronousMotionTraceNames) {
  auto traced = [](const char* name) {
    Json d = base();
    d["technology_objects"].push_back(Json::parse(R"({ "name": "L", "type": "TO_PositioningAxis",
      "config": { "VirtualAxis.Mode": 1 } })"));
    d["technology_objects"].push_back(Json::parse(R"({ "name": "F", "type": "TO_SynchronousAxis",
      "config": { "VirtualAxis.Mode": 1 }, "LeadingValueInterconnections": [ { "Leader": "L" } ] })"));
    d["trace"] = Json::array({name});
    return d;
  };
  EXPECT_TRUE(problems_of(traced("F.StatusSynchronizedMotion.FunctionState")).empty());
  EXPECT_TRUE(problems_of(traced("F.StatusSynchronizedMotion.EffectiveLeadingValue.Velocity")).empty());
  EXPECT_TRUE(problems_of(traced("F.StatusSynchronizedMotion.StatusWord.X4")).empty());
  EXPECT_EQ(problem_of(traced("F.StatusSynchronizedMotion.Nothing")),
            "trace[0]: 'StatusSynchronizedMotion.Nothing' is not a variable of TO_SynchronousAxis F");
  EXPECT_EQ(problem_of(traced("F.StatusSynchronizedMotion.StatusWord.X32")),
            "trace[0]: 'StatusSynchronizedMotion.StatusWord.X32' is not a variable of TO_SynchronousAxis F");
  EXPECT_EQ(problem_of(traced("L.StatusSynchronizedMotion.FunctionState")),
            "trace[0]: 'StatusSynchronizedMotion.FunctionState' is not a variable of TO_PositioningAxis L");
}

// LeadingValueInterconnections belongs beside 'config' (decision Y2). Put inside 'config' of a synchronous
// axis, the message names the right TO type and where the key belongs (before issue 14: "unknown variable of
// TO_PositioningAxis"); on another TO type it says that only a synchronous axis has it.
TEST(ScenarioLoader, MisplacedLeadingValueInterconnections) {
  Json d = base();
  d["technology_objects"].push_back(Json::parse(R"({ "name": "L", "type": "TO_PositioningAxis",
    "config": { "VirtualAxis.Mode": 1 } })"));
  d["technology_objects"].push_back(Json::parse(R"({ "name": "F", "type": "TO_SynchronousAxis",
    "config": { "VirtualAxis.Mode": 1, "LeadingValueInterconnections": [ { "Leader": "L" } ] } })"));
  const auto problems = problems_of(d);
  const auto found = std::find_if(problems.begin(), problems.end(), [](const std::string& p) {
    return p.find("config.LeadingValueInterconnections") != std::string::npos;
  });
  ASSERT_NE(found, problems.end());
  EXPECT_EQ(
      *found,
      "technology_objects[2].config.LeadingValueInterconnections: not a variable of TO_SynchronousAxis: "
      "LeadingValueInterconnections belongs beside 'config', at "
      "technology_objects[2].LeadingValueInterconnections");

  Json p = base();
  p["technology_objects"].push_back(Json::parse(R"({ "name": "P", "type": "TO_PositioningAxis",
    "config": { "VirtualAxis.Mode": 1, "LeadingValueInterconnections": [] } })"));
  const auto positioning = problems_of(p);
  const auto other = std::find_if(positioning.begin(), positioning.end(), [](const std::string& s) {
    return s.find("config.LeadingValueInterconnections") != std::string::npos;
  });
  ASSERT_NE(other, positioning.end());
  EXPECT_NE(other->find("only a TO_SynchronousAxis has LeadingValueInterconnections"), std::string::npos)
      << *other;
}

// A leader L and a follower F with one interconnection `interconnection` (its JSON without the braces).
Json with_interconnection(const std::string& interconnection) {
  Json d = base();
  d["technology_objects"].push_back(Json::parse(R"({ "name": "L", "type": "TO_PositioningAxis",
    "config": { "VirtualAxis.Mode": 1 } })"));
  d["technology_objects"].push_back(Json::parse(R"({ "name": "E", "type": "TO_ExternalEncoder",
    "drive": { "adapter": "simulated", "encoder_telegram": 81 } })"));
  d["technology_objects"].push_back(Json::parse(R"({ "name": "F", "type": "TO_SynchronousAxis",
    "config": { "VirtualAxis.Mode": 1 }, "LeadingValueInterconnections": [ { )" +
                                                interconnection + " } ] }"));
  return d;
}

// LeadingValueReversalTolerance: 0…1e9 in the leader's length unit (spec 07 §1.6 [OPEN]; decision C27: at
// most 1e9, so its conversion to float is defined). The bounds load; beyond them the key's path is named.
TEST(ScenarioLoader, ReversalToleranceBounds) {
  const std::string key = R"("Leader": "L", "LeadingValueReversalTolerance": )";
  for (const char* accepted : {"0", "1e9"})
    EXPECT_TRUE(problems_of(with_interconnection(key + accepted)).empty()) << accepted;
  EXPECT_EQ(problem_of(with_interconnection(key + "1.000001e9")),
            "technology_objects[3].LeadingValueInterconnections[0].LeadingValueReversalTolerance: 1000001000 "
            "out of range 0..1e9");
  EXPECT_EQ(problem_of(with_interconnection(key + "-0.1")),
            "technology_objects[3].LeadingValueInterconnections[0].LeadingValueReversalTolerance: -0.1 out "
            "of range 0..1e9");
}

// "Delayed" to an external encoder (decision C26: only an axis keeps the history of its setpoint) is a
// problem of the interconnection's Coupling naming the follower and the leader; to an axis it loads.
TEST(ScenarioLoader, DelayedCouplingToAnExternalEncoderNamesTheInterconnection) {
  EXPECT_EQ(
      problem_of(with_interconnection(R"("Leader": "E", "Coupling": "Delayed")")),
      "technology_objects[3].LeadingValueInterconnections[0].Coupling: 'F' cannot couple \"Delayed\" to "
      "'E', a TO_ExternalEncoder (only a positioning or synchronous axis can, decision C26)");
  EXPECT_TRUE(problems_of(with_interconnection(R"("Leader": "E", "Coupling": "ActualValue")")).empty());
  EXPECT_TRUE(problems_of(with_interconnection(R"("Leader": "L", "Coupling": "Delayed")")).empty());
}

// MC_CamIn.Cam names a cam of the scenario (spec 07 §3.4): another TO type or an unknown name is a problem of
// the event's input, with its path.
TEST(ScenarioLoader, CamInputNamesACam) {
  Json d = base();
  d["technology_objects"].push_back(Json::parse(R"({ "name": "L", "type": "TO_PositioningAxis",
    "config": { "VirtualAxis.Mode": 1 } })"));
  d["technology_objects"].push_back(Json::parse(R"({ "name": "F", "type": "TO_SynchronousAxis",
    "config": { "VirtualAxis.Mode": 1 }, "LeadingValueInterconnections": [ { "Leader": "L" } ] })"));
  d["technology_objects"].push_back(
      Json::parse(R"({ "name": "C", "type": "TO_Cam", "Points": [[0, 0], [1, 1]] })"));
  const auto cam_in = [&](const char* cam) {
    Json e = d;
    e["timeline"].push_back(
        Json::parse(std::string(R"({"cycle": 1, "instance": "c", "instruction": "MC_CamIn",
      "axis": "F", "inputs": {"Master": "L", "Cam": )") +
                    cam + "}}"));
    return problems_of(e);
  };
  EXPECT_TRUE(cam_in(R"("C")").empty());
  const auto not_a_cam = cam_in(R"("L")");
  ASSERT_FALSE(not_a_cam.empty());
  EXPECT_EQ(not_a_cam.front(), "timeline[1].inputs.Cam: 'L' is a TO_PositioningAxis, not a cam");
  const auto unknown = cam_in(R"("D")");
  ASSERT_FALSE(unknown.empty());
  EXPECT_EQ(unknown.front(), "timeline[1].inputs.Cam: unknown technology object 'D'");
}

// docs/scenarios.md "`expect`: expected values (tomc extension)".
TEST(ScenarioLoader, Expectations) {
  auto expecting = [](const char* expect) {
    Json d = base();
    d["expect"] = Json::parse(expect);
    return d;
  };
  EXPECT_TRUE(problems_of(expecting(R"([{"cycle": 9, "values": {"power1.Status": true, "Axis1.Velocity": 0},
                                         "tolerance": 0.5, "comment": "x"}])"))
                  .empty());
  EXPECT_EQ(problem_of(expecting(R"([{"cycle": 10, "values": {"power1.Status": true}}])")),
            "expect[0].cycle: 10 out of range 0..9");
  EXPECT_EQ(problem_of(expecting(R"([{"cycle": 1, "values": {}}])")),
            "expect[0].values: expected at least one trace name");
  EXPECT_EQ(problem_of(expecting(R"([{"cycle": 1}])")), "expect[0].values: missing");
  EXPECT_EQ(
      problem_of(expecting(R"([{"cycle": 1, "values": {"power1.Ready": 1}}])")),
      "expect[0].values.power1.Ready: 'Ready' is not a parameter of MC_Power (Enable, StartMode, StopMode, "
      "Status, Busy, Error, ErrorID)");
  EXPECT_EQ(problem_of(expecting(R"([{"cycle": 1, "values": {"power1.Status": "yes"}}])")),
            "expect[0].values.power1.Status: expected a number, got a string");
  EXPECT_EQ(problem_of(expecting(R"([{"cycle": 1, "values": {"power1.Status": 1}, "tolerance": -1}])")),
            "expect[0].tolerance: -1 out of range: must be at least 0");
  EXPECT_EQ(problem_of(expecting(R"({"cycle": 1})")),
            "expect: expected an array of expectations, got an object");
}

// docs/scenarios.md "Exit status and messages" (malformed JSON named with its line).
TEST(ScenarioLoader, MalformedJsonAndFiles) {
  auto result = Scenario::load_text("{\"cycles\": 3,\n  \"cycle_time\": }", "x.json");
  ASSERT_EQ(result.problems.size(), 1u);
  EXPECT_EQ(result.problems[0].rfind("x.json: malformed JSON: parse error at line 2", 0), 0u)
      << result.problems[0];
  // A number beyond a double is nlohmann's out_of_range.406, not a parse_error: it once escaped the loader
  // and ended the process (scenario_loader_fuzzer, reliability.md §2).
  result = Scenario::load_text("{\"cycles\": 7777e5777755555555555555555555552777}", "y.json");
  ASSERT_EQ(result.problems.size(), 1u);
  EXPECT_EQ(result.problems[0].rfind("y.json: malformed JSON: number overflow", 0), 0u) << result.problems[0];
  result = Scenario::load_file("/nonexistent/scenario.json");
  ASSERT_EQ(result.problems.size(), 1u);
  EXPECT_EQ(result.problems[0], "/nonexistent/scenario.json: cannot read: No such file or directory");
}

// docs/scenarios.md "`trace`: names and CSV" (how numbers are written).
TEST(ScenarioLoader, FormatNumber) {
  using tomc::scenario::format_number;
  EXPECT_EQ(format_number(1e13), "1e13");
  EXPECT_EQ(format_number(2.5e-5), "2.5e-5");
  EXPECT_EQ(format_number(0.001), "0.001");
  EXPECT_EQ(format_number(-3), "-3");
  EXPECT_EQ(format_number(1e100), "1e100");
}

}  // namespace

namespace {

// docs/scenarios.md: a technology alarm is injected with a defined number and a reaction 0..5, and it is
// acknowledged by MC_Reset, never "cleared".
TEST(ScenarioLoader, TechnologyAlarmInjection) {
  EXPECT_TRUE(
      problems_of(
          with_event(
              R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "technology_alarm", "alarm": 533, "reaction": 2}})"))
          .empty());
  EXPECT_EQ(problem_of(with_event(
                R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "technology_alarm", "alarm": 999}})")),
            "timeline[1].inject.alarm: alarm 999 is not defined (docs/errors.md)");
  EXPECT_EQ(
      problem_of(with_event(R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "technology_alarm"}})")),
      "timeline[1].inject.alarm: missing");
  EXPECT_EQ(
      problem_of(with_event(R"({"cycle": 1, "clear": {"target": "Axis1", "fault": "technology_alarm"}})")),
      "timeline[1].clear.fault: a technology alarm is acknowledged with MC_Reset, not cleared");
  const auto out_of_range = problem_of(with_event(
      R"({"cycle": 1, "inject": {"target": "Axis1", "fault": "technology_alarm", "alarm": 533, "reaction": 6}})"));
  EXPECT_NE(out_of_range.find("timeline[1].inject.reaction"), std::string::npos) << out_of_range;
}

}  // namespace

namespace {

// A technology object with a legacy parameter set (docs/analog-drives.md, spec 05b Part C) in place of
// its config and drive.
Json with_legacy(const char* legacy, double cycle_time = 0.001) {
  Json d = base();
  d["cycle_time"] = cycle_time;
  d["technology_objects"][0] = Json::parse(R"({"name": "Axis1", "type": "TO_PositioningAxis"})");
  d["technology_objects"][0]["legacy"] = Json::parse(legacy);
  return d;
}

constexpr const char* kH3Example = R"({"system": "H3", "unit_mm": 0.1, "velocity_at_10V": 1000, "MCFac": 100,
    "MCW": "16#41B", "PosEr": 2000, "KProp": 150, "KInt": 50, "KDer": 50, "IntL": 500, "SampI": 15,
    "Veloc": 500, "Accel": 100})";

Json h3_with(const char* key, const Json& value) {
  Json d = with_legacy(kH3Example);
  d["technology_objects"][0]["legacy"][key] = value;
  return d;
}

// spec 05b Part D 33: out-of-range H3 values are errors naming the register (FLdVA with Veloc -100, FLdRP
// with KProp 40000 or SampI 256, MCW 61BH with two stop bits); SampI 2 is accepted.
TEST(LegacyParameters, H3RangeErrorsPartD33) {
  EXPECT_TRUE(problems_of(with_legacy(kH3Example)).empty());
  EXPECT_TRUE(problems_of(h3_with("SampI", 2)).empty());
  EXPECT_EQ(problem_of(h3_with("Veloc", -100)),
            "technology_objects[0].legacy.Veloc: -100 out of range 0..1073741823");
  EXPECT_EQ(problem_of(h3_with("KProp", 40000)),
            "technology_objects[0].legacy.KProp: 40000 out of range 0..32767");
  EXPECT_EQ(problem_of(h3_with("SampI", 256)), "technology_objects[0].legacy.SampI: 256 out of range 0..255");
  EXPECT_EQ(
      problem_of(h3_with("MCW", "16#61B")),
      "technology_objects[0].legacy.MCW: bits 8, 9, 10 (stop type): exactly one must be set, 2 are (spec "
      "05b B.9)");
  EXPECT_EQ(
      problem_of(h3_with("MCW", "16#41C")),
      "technology_objects[0].legacy.MCW: low byte 16#1C is not a position-error reaction (16#1A flag and "
      "motor off, 16#1B flag only; spec 05b B.9)");
  EXPECT_EQ(problem_of(h3_with("KProp", 0)),
            "technology_objects[0].legacy.KProp: must be > 0 (I and D are expressed relative to the P gain)");
  EXPECT_EQ(
      problem_of(h3_with("MCFac", 0.0001)),
      "technology_objects[0].legacy.MCFac: 1e-4 counts per 0.1 mm is no whole number of ×4 counts over 1 "
      "... 1000 mm");
  EXPECT_EQ(problem_of(h3_with("Veloc", 2000)),
            "technology_objects[0].legacy.Veloc: 2000 exceeds velocity_at_10V 1000");
  Json d = with_legacy(kH3Example);
  d["technology_objects"][0]["type"] = "TO_SpeedAxis";
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].legacy: only a TO_PositioningAxis or TO_SynchronousAxis takes a legacy "
            "parameter set (a JOINT or H3 axis is a positioning axis)");
}

constexpr const char* kJointAxis = R"({"system": "JOINT", "TCamp": 10, "measure": 1, "pulse": 100,
    "maxvel": 100, "unitvel": 1, "decpt": 0, "pgain": 1000})";

Json joint_with(const char* key, const Json& value) {
  Json d = with_legacy(kJointAxis, 0.01);
  d["technology_objects"][0]["legacy"][key] = value;
  return d;
}

// spec 05b A.8 ranges and Part D 2 (measure/pulse within 0.00935 ... 1), TCamp = the MC_Servo cycle.
TEST(LegacyParameters, JointRangeErrors) {
  EXPECT_TRUE(problems_of(with_legacy(kJointAxis, 0.01)).empty());
  EXPECT_TRUE(problems_of(joint_with("measure", 1000)).size() == 1);  // 1000/100 = 10 Um per pulse
  Json d = joint_with("measure", 1);
  d["technology_objects"][0]["legacy"]["pulse"] = 200;  // 0.005
  EXPECT_EQ(
      problem_of(d),
      "technology_objects[0].legacy.measure: measure/pulse = 0.005 is outside 0.00935 ... 1 Um per pulse "
      "(spec 05b A.3)");
  d = joint_with("measure", 2);
  d["technology_objects"][0]["legacy"]["pulse"] = 1;  // 2
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].legacy.measure: measure/pulse = 2 is outside 0.00935 ... 1 Um per pulse "
            "(spec 05b A.3)");
  EXPECT_EQ(
      problem_of(with_legacy(kJointAxis, 0.001)),
      "technology_objects[0].legacy.TCamp: 10 ms differs from cycle_time 0.001 s (the regulator runs in "
      "the MC_Servo cycle, spec 05b C.1)");
  EXPECT_EQ(problem_of(joint_with("TCamp", 256)),
            "technology_objects[0].legacy.TCamp: 256 out of range 1..255");
  EXPECT_EQ(problem_of(joint_with("pgain", 40000)),
            "technology_objects[0].legacy.pgain: 40000 out of range 0..32767");
  EXPECT_EQ(problem_of(joint_with("offset", -40000)),
            "technology_objects[0].legacy.offset: -40000 out of range -32768..32767");
  EXPECT_EQ(problem_of(joint_with("ramptype", 1)),
            "technology_objects[0].legacy.ramptype: 1: epicycloidal ramps are not mapped (spec 05b C.3: an "
            "extension); only 0 (trapezoidal)");
  EXPECT_EQ(problem_of(joint_with("setvel", 150)),
            "technology_objects[0].legacy.setvel: 150 exceeds maxvel 100");
  EXPECT_EQ(problem_of(joint_with("maxpos", 50)),
            "technology_objects[0].legacy.minpos: missing: give both software limits or neither");
  EXPECT_EQ(problem_of(joint_with("prsmode", 3)),
            "technology_objects[0].legacy.prsmode: 3 out of range 0..2");
  EXPECT_EQ(problem_of(joint_with("sprsvel", 101)),
            "technology_objects[0].legacy.sprsvel: 101 exceeds maxvel 100");
  EXPECT_EQ(problem_of(joint_with("system", "EANPOS")),
            "technology_objects[0].legacy.system: 'EANPOS' is not one of JOINT, H3");
}

}  // namespace

// spec 05b Part D 1: the JOINT INTDEVICE declaration, 21 tokens on one line (A.1.1), TCamp 1..255,
// NAxis 2..3, Buffer 3..30000; the line gives TCamp (= the MC_Servo cycle) and the axis' resources (decision
// A23).
constexpr const char* kDeclaration =
    "AX JOINT 10 3 500 2.1 1 3.1 4.1 2.2 2 3.2 4.2 2.3 X X.X 4.3 5.1 5.2 5.3 5.4";

Json declared(const std::string& line, const char* axis = "X") {
  Json d = with_legacy(R"({"system": "JOINT", "measure": 1, "pulse": 100, "maxvel": 100})", 0.01);
  d["technology_objects"][0]["legacy"]["INTDEVICE"] = line;
  d["technology_objects"][0]["legacy"]["axis"] = axis;
  return d;
}

std::string replaced(std::string line, const std::string& from, const std::string& to) {
  return line.replace(line.find(from), from.size(), to);
}

// spec 05b Part D 1 (A.1.1: the JOINT INTDEVICE declaration); decision A23.
TEST(LegacyParameters, JointDeclarationPartD1) {
  EXPECT_TRUE(problems_of(declared(kDeclaration)).empty());
  // The spec's own line (TCamp 2 ms) parses; its TCamp must then be the cycle time.
  Json d = declared("AX JOINT 2 3 500 2.1 1 3.1 4.1 2.2 2 3.2 4.2 2.3 X X.X 4.3 5.1 5.2 5.3 5.4");
  d["cycle_time"] = 0.002;
  EXPECT_TRUE(problems_of(d).empty());
  const std::string at = "technology_objects[0].legacy.INTDEVICE: ";
  // The ranges of TCamp, NAxis and Buffer, as a table: (text replaced in the line, by, the problem).
  for (const auto& [from, to, message] :
       std::initializer_list<std::tuple<const char*, const char*, const char*>>{
           {"JOINT 10", "JOINT 0", "TCamp '0' out of range 1..255"},
           {"JOINT 10", "JOINT 256", "TCamp '256' out of range 1..255"},
           {"10 3 500", "10 1 500", "NAxis '1' out of range 2..3"},
           {"10 3 500", "10 4 500", "NAxis '4' out of range 2..3"},
           {"10 3 500", "10 3 2", "Buffer '2' out of range 3..30000"},
           {"10 3 500", "10 3 30001", "Buffer '30001' out of range 3..30000"}}) {
    EXPECT_EQ(problem_of(declared(replaced(kDeclaration, from, to))), at + message) << from << " -> " << to;
  }
  EXPECT_EQ(
      problem_of(declared(replaced(kDeclaration, " 5.4", ""))),
      at +
          "20 tokens: expected 21 on one line, '<name> JOINT TCamp NAxis Buffer', ICont IntL IAZero IoutA of "
          "X, Y, Z, IOut1 ... IOut4 (X.X / X for an unused one; spec 05b A.1.1)");
  EXPECT_EQ(problem_of(declared(replaced(kDeclaration, "2.1 1", "2.1 a"))),
            at + "IntLX 'a' is no input number (or X)");
  // The axis: Z of a 2-axis device; an axis without its counter or DAC.
  EXPECT_EQ(problem_of(declared(replaced(kDeclaration, "10 3 500", "10 2 500"), "Z")),
            "technology_objects[0].legacy.axis: axis Z is beyond NAxis 2");
  EXPECT_EQ(
      problem_of(declared(replaced(kDeclaration, "2.1 1 3.1 4.1", "2.1 1 3.1 X.X"))),
      at + "axis X needs its counter (IContX) and its DAC (IoutAX): at least one bidirectional counter and "
           "one 16-bit DAC (spec 05b A.1)");
  // TCamp once only; homing needs IAZero (and IntL for mode 1): axis Z has neither.
  d = declared(kDeclaration);
  d["technology_objects"][0]["legacy"]["TCamp"] = 10;
  EXPECT_EQ(problem_of(d), "technology_objects[0].legacy.TCamp: given by the INTDEVICE line");
  d = declared(kDeclaration, "Z");
  d["technology_objects"][0]["legacy"]["prsmode"] = 0;
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].legacy.prsmode: homing needs the enable input IAZero, X.X in the "
            "INTDEVICE line");
  d = declared(replaced(kDeclaration, "2.3 X X.X", "2.3 X 3.3"), "Z");
  d["technology_objects"][0]["legacy"]["prsmode"] = 1;
  EXPECT_EQ(
      problem_of(d),
      "technology_objects[0].legacy.prsmode: 1 needs the zero-pulse input IntL, X in the INTDEVICE line");
}

// ---- "analog": {"comedi": {...}}: the analog actor on a real DAQ card (docs/analog-drives.md, decision A21)
// ----

Json comedi_axis(const char* comedi, bool enable = true, bool ready = true) {
  Json d = base();
  auto& to = d["technology_objects"][0];
  to["config"] =
      Json{{"Actor.Interface.EnableDriveOutput", enable}, {"Actor.Interface.DriveReadyInput", ready}};
  to["drive"] = Json{{"adapter", "analog"}, {"telegram", 3}, {"analog", {{"comedi", Json::parse(comedi)}}}};
  return d;
}

constexpr const char* kComediCard = R"({"device": "/dev/comedi_tomc_test_missing",
    "analog_output": {"subdevice": 1, "channel": 0}, "enable_output": {"subdevice": 2, "channel": 0},
    "ready_input": {"subdevice": 2, "channel": 8}, "counter": {"subdevice": 4, "channel": 0},
    "counter_width_bits": 24})";

// issue 20 "a missing device at start is a configuration error naming the device": from a scenario or
// machine file the card is opened while the file is loaded; without the comedi build the loader says so.
TEST(ComediDrive, MissingCardIsAConfigurationErrorNamingTheDevice) {
  const std::string problem = problem_of(comedi_axis(kComediCard));
#if TOMC_WITH_COMEDI
  EXPECT_EQ(problem.rfind("technology_objects[0].drive.analog.comedi.device: comedi: cannot open "
                          "/dev/comedi_tomc_test_missing: ",
                          0),
            0u)
      << problem;
  EXPECT_NE(problem.find("driver loaded"), std::string::npos) << problem;
  // A file that is there but no comedi device.
  Json d = comedi_axis(kComediCard);
  d["technology_objects"][0]["drive"]["analog"]["comedi"]["device"] = "/dev/null";
  EXPECT_EQ(problem_of(d).rfind(
                "technology_objects[0].drive.analog.comedi.device: comedi: cannot open /dev/null: ", 0),
            0u);
#else
  EXPECT_EQ(
      problem,
      "technology_objects[0].drive.analog.comedi: this tomc is built without the comedi backend (configure "
      "with -DTOMC_WITH_COMEDI=ON, which needs Debian's libcomedi-dev)");
#endif
}

// The card's keys: device file and channels named by path; the wiring must match Actor.Interface (spec 01
// §3.12: enable output and ready input each optional); the simulated amplifier's keys do not apply.
TEST(ComediDrive, CardKeysAndWiringAreChecked) {
  EXPECT_EQ(problems_of(comedi_axis(R"({"analog_output": {"subdevice": 1}, "counter": {"subdevice": 4,
      "channel": 0}, "counter_width_bits": 40})",
                                    false, false)),
            (std::vector<std::string>{
                "technology_objects[0].drive.analog.comedi.device: missing",
                "technology_objects[0].drive.analog.comedi.analog_output.channel: missing",
                "technology_objects[0].drive.analog.comedi.counter_width_bits: 40 out of range 8..32"}));
  EXPECT_EQ(
      problems_of(comedi_axis(R"({"device": "/dev/comedi0", "analog_output": {"subdevice": 1, "channel": 0},
      "counter": {"subdevice": 4, "channel": 0}, "ready_input": {"subdevice": 2, "channel": 8}})",
                              true, false)),
      (std::vector<std::string>{
          "technology_objects[0].drive.analog.comedi.enable_output: missing: the TO's "
          "Actor.Interface.EnableDriveOutput is TRUE",
          "technology_objects[0].drive.analog.comedi.ready_input: the TO's Actor.Interface.DriveReadyInput "
          "is FALSE (set it TRUE or remove the channel)"}));
  Json d = comedi_axis(kComediCard);
  d["technology_objects"][0]["drive"]["analog"]["amplifier_offset_volts"] = 0.1;
  EXPECT_EQ(
      problem_of(d),
      "technology_objects[0].drive.analog.amplifier_offset_volts: a key of the simulated servo amplifier: "
      "with \"comedi\" the amplifier is the real one");
  d = comedi_axis(kComediCard);
  d["technology_objects"][0]["drive"]["encoder_telegram"] = 83;
  d["technology_objects"][0]["drive"]["telegram"] = 2;
  EXPECT_EQ(problem_of(d),
            "technology_objects[0].drive.encoder_telegram: a separate 81/83 encoder is simulated: with "
            "\"comedi\" the position is the card's counter");
}
