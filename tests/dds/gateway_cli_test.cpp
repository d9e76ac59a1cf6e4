// The gateway from a user's side: `tomc sim` pointed at `tomc gateway-sim` by configuration alone gives the
// same trace as the embedded simulated drive; `tomc gateway-sim` reports a broken configuration by JSON path;
// the dds_gateway adapter object in scenario files is validated like the rest (docs/scenarios.md, "drive").
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "build_paths.hpp"
#include "gateway_process.hpp"
#include "tomc/scenario/scenario.hpp"

#ifndef TOMC_SOURCE_DIR
#error "TOMC_SOURCE_DIR must name the repository"
#endif

namespace {

using tomc::testing::gateway_config;
using tomc::testing::GatewayProcess;
using tomc::testing::test_directory;
using tomc::testing::test_partition;

struct CliRun {
  int status = -1;
  std::string out;
  std::string err;
};

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

CliRun tomc_cli(const std::filesystem::path& dir, const std::string& arguments) {
  const auto out = dir / "stdout.txt";
  const auto err = dir / "stderr.txt";
  const std::string command =
      std::string(TOMC_BINARY) + " " + arguments + " >" + out.string() + " 2>" + err.string();
  CliRun r;
  const int raw = std::system(command.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// spec 03 §4.8 trapezoid scenario of the speed axis, once on the embedded drive and once on the same drive
// model behind `tomc gateway-sim`: the trace (every traced variable, every cycle) is byte for byte the same,
// and every expectation of the scenario holds through the gateway too.
TEST(GatewayCli, ScenarioThroughTheGatewayGivesTheEmbeddedTrace) {
  const int domain = 151;
  const auto dir = test_directory("scenario");
  const std::string source = std::string(TOMC_SOURCE_DIR) + "/tests/scenarios/move_velocity_trapezoid.json";
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(slurp(source));
  auto& drive = doc["technology_objects"][0]["drive"];
  // The one change: the adapter. The answer timeout is generous so that a loaded CI machine cannot turn a
  // slow answer into a missed cycle (which would be a different, correct, trace).
  drive["adapter"] = {{"type", "dds_gateway"},
                      {"domain", domain},
                      {"device", "axis1"},
                      {"partition", test_partition()},
                      {"answer_timeout_s", 2.0}};
  std::ofstream(dir / "gateway_scenario.json") << doc.dump(2);
  const int telegram = drive["telegram"].get<int>();
  GatewayProcess gateway(dir, gateway_config(domain, {{"axis1", telegram}}));

  const CliRun embedded = tomc_cli(dir, "sim " + source + " --out " + (dir / "embedded.csv").string());
  ASSERT_EQ(embedded.status, 0) << embedded.err;
  const CliRun through = tomc_cli(
      dir, "sim " + (dir / "gateway_scenario.json").string() + " --out " + (dir / "gateway.csv").string());
  ASSERT_EQ(through.status, 0) << through.err << gateway.log();
  EXPECT_EQ(through.err, "");  // no warning: the device answered
  const std::string a = slurp(dir / "embedded.csv");
  const std::string b = slurp(dir / "gateway.csv");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b) << "the traces differ";
  std::filesystem::remove_all(dir);
}

// No gateway on the domain: the scenario still runs (the TO raises its link alarm), and the user is told why.
// docs/gateway.md §7 (no fresh answers: CommunicationOK FALSE, alarm 405), decision N7 (the warning says
// why).
TEST(GatewayCli, ScenarioWithoutAGatewayWarnsAndRaisesTheLinkAlarm) {
  const auto dir = test_directory("nogateway");
  const std::string scenario = R"({ "cycle_time": 0.001, "cycles": 10,
    "technology_objects": [ { "name": "Axis1", "type": "TO_SpeedAxis",
      "drive": { "telegram": 2, "adapter": { "type": "dds_gateway", "domain": 153, "device": "axis1",
                 "partition": ")" +
                               test_partition() +
                               R"(", "connect_timeout_s": 0.3, "answer_timeout_s": 0.001 } } } ],
    "expect": [ { "cycle": 9, "values": { "Axis1.ErrorDetail.Number": 405, "Axis1.StatusDrive.CommunicationOK": false } } ] })";
  std::ofstream(dir / "s.json") << scenario;
  const CliRun r = tomc_cli(dir, "sim " + (dir / "s.json").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: axis1: no gateway: no gateway has announced itself on DDS domain 153"),
            std::string::npos)
      << r.err;
  std::filesystem::remove_all(dir);
}

// ARCHITECTURE-GUIDE §6 (every problem with its path), docs/gateway.md §9 (the simulator's file), decision
// T11 (telegram 104).
TEST(GatewayCli, GatewaySimConfigurationProblemsNameTheirPaths) {
  const auto dir = test_directory("badconfig");
  std::ofstream(dir / "gw.json") << R"({ "gateway": "gw1", "domain": 300, "cycle_time": 0.001, "colour": 1,
    "devices": [ { "name": "a", "drive": { "telegram": 104 } },
                 { "name": "a", "drive": { "telegram": 3, "motor_inertia_kgm2": -1 } } ] })";
  const CliRun r = tomc_cli(dir, "gateway-sim --config " + (dir / "gw.json").string());
  EXPECT_EQ(r.status, 2);
  const std::string prefix = "tomc: " + (dir / "gw.json").string() + ": ";
  EXPECT_NE(r.err.find(prefix + "domain: 300 out of range 0..232"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(prefix + "devices[0].drive.telegram: 104 is not a drive telegram"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(prefix + "devices[1].name: 'a' is defined twice"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(prefix + "devices[1].drive.motor_inertia_kgm2: -1 out of range"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(prefix + "colour: unknown key"), std::string::npos) << r.err;

  const CliRun missing = tomc_cli(dir, "gateway-sim --config " + (dir / "nothere.json").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos);
  const CliRun usage = tomc_cli(dir, "gateway-sim --domain 500 --config x");
  EXPECT_EQ(usage.status, 2);
  EXPECT_EQ(usage.err, "tomc: gateway-sim: --domain: '500' is not an integer 0..232\n");
  const CliRun send = tomc_cli(dir, "gateway-sim --send explode --domain 1");
  EXPECT_EQ(send.status, 2);
  EXPECT_EQ(send.err, "tomc: gateway-sim: --send: unknown command 'explode'\n");
  std::filesystem::remove_all(dir);
}

// The adapter object is checked like every other part of a scenario, all problems at once, by JSON path; the
// simulated drive's parameters are refused with the dds_gateway adapter (they belong to the gateway).
// ARCHITECTURE-GUIDE §6 (all problems at once, by JSON path), docs/scenarios.md "`drive`: adapter, telegram
// and the simulated machine", decision T2.
TEST(GatewayCli, AdapterObjectProblemsNameTheirPaths) {
  const auto result = tomc::scenario::Scenario::load_text(R"({ "cycle_time": 0.001, "cycles": 10,
    "technology_objects": [
      { "name": "A", "type": "TO_SpeedAxis",
        "drive": { "telegram": 2, "motor_inertia_kgm2": 0.001,
                   "adapter": { "type": "dds", "domain": 999, "device": "", "byte_order": "middle", "x": 1 } } },
      { "name": "B", "type": "TO_SpeedAxis", "drive": { "telegram": 2, "adapter": "dds" } } ] })",
                                                          "s.json");
  ASSERT_EQ(result.scenario, nullptr);
  const std::vector<std::string> expected = {
      "technology_objects[0].drive.adapter.type: 'dds' is not a gateway adapter type (dds_gateway)",
      "technology_objects[0].drive.adapter.domain: 999 out of range 0..232",
      "technology_objects[0].drive.adapter.device: a device name of 1..63 characters",
      "technology_objects[0].drive.adapter.byte_order: 'middle' is not one of big, little-bytes, "
      "swapped-words, little",
      "technology_objects[0].drive.adapter.x: unknown key",
      "technology_objects[0].drive.motor_inertia_kgm2: a parameter of the simulated drive; with the "
      "dds_gateway "
      "adapter the drive is the gateway's (for the gateway simulator: its --config file)",
      "technology_objects[1].drive.adapter: the gateway adapter is an object: {\"type\": \"dds_gateway\", "
      "\"domain\": 0, \"device\": \"<name at the gateway>\"}",
  };
  std::string all;
  for (const auto& line : result.problems)
    all += line + "\n";
  for (const auto& line : expected)
    EXPECT_NE(all.find(line), std::string::npos) << "missing: " << line << "\nin:\n" << all;
}

}  // namespace

// `tomc demo --gateway DOMAIN` (issue 8: the demo pointed at the gateway simulator with one option): every
// drive of the machine goes through the gateway, each TO's device named like the TO. The demo connects before
// its first cycle: no warning means both directions of every device answered (docs/gateway.md §10).
TEST(GatewayCli, DemoThroughTheGatewayWithOneOption) {
  const int domain = 154;
  const auto dir = test_directory("demo");
  std::ofstream(dir / "machine.json") << R"({ "cycle_time": 0.001, "technology_objects": [
    { "name": "Conveyor", "type": "TO_SpeedAxis", "drive": { "adapter": "simulated", "telegram": 2 } },
    { "name": "Slide", "type": "TO_PositioningAxis", "drive": { "adapter": "simulated", "telegram": 3 } } ] })";
  GatewayProcess gateway(dir, gateway_config(domain, {{"Conveyor", 2}, {"Slide", 3}}));
  const std::string demo = "demo --config " + (dir / "machine.json").string() +
                           " --port 0 --seconds 1 --gateway " + std::to_string(domain) +
                           " --gateway-partition " + test_partition();
  const CliRun r = tomc_cli(dir, demo);
  EXPECT_EQ(r.status, 0) << r.err << gateway.log();
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("Conveyor Slide"), std::string::npos) << r.out;
  std::filesystem::remove_all(dir);
}

// The same without a gateway on the domain: the demo still runs (the TOs raise their link alarms) and says
// why.
// docs/gateway.md §7 (the TOs raise their link alarm), decision N7 (the warning says why).
TEST(GatewayCli, DemoWithoutAGatewayWarns) {
  const auto dir = test_directory("demo_nogw");
  std::ofstream(dir / "machine.json") << R"({ "cycle_time": 0.001, "technology_objects": [
    { "name": "Conveyor", "type": "TO_SpeedAxis", "drive": { "telegram": 2 } } ] })";
  const CliRun r =
      tomc_cli(dir, "demo --config " + (dir / "machine.json").string() +
                        " --port 0 --seconds 0.5 --gateway 155 --gateway-partition " + test_partition());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("tomc: demo: warning: Conveyor: no gateway"), std::string::npos) << r.err;
  const CliRun usage = tomc_cli(dir, "demo --gateway-partition x");
  EXPECT_EQ(usage.status, 2);
  EXPECT_NE(usage.err.find("--gateway-partition needs --gateway"), std::string::npos) << usage.err;
  std::filesystem::remove_all(dir);
}
