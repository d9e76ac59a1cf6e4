// The scenario engine at run time: trace format, event timing, instance creation, every fault kind and the
// expectation check (docs/scenarios.md). The spec behaviour itself is tested by the *.json scenarios here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "build_paths.hpp"
#include "tomc/scenario/scenario.hpp"

namespace {

using tomc::scenario::Json;
using tomc::scenario::Scenario;

std::unique_ptr<Scenario> load(const std::string& text) {
  auto result = Scenario::load_text(text, "test");
  EXPECT_TRUE(result.problems.empty()) << ::testing::PrintToString(result.problems);
  return std::move(result.scenario);
}

std::vector<std::vector<std::string>> run_csv(Scenario& s) {
  std::ostringstream out;
  const auto result = s.run(&out);
  EXPECT_TRUE(result.ok()) << ::testing::PrintToString(result.failed_expectations);
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream cell_stream(line);
    for (std::string cell; std::getline(cell_stream, cell, ',');)
      cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

constexpr const char* kAxis = R"(
  { "name": "Axis1", "type": "TO_SpeedAxis", "config": { "DynamicLimits.MaxJerk": 0 },
    "drive": { "telegram": 3 } })";

std::string scenario(int cycles, const std::string& timeline, const std::string& trace,
                     const std::string& expect = "[]") {
  return R"({ "cycle_time": 0.001, "cycles": )" + std::to_string(cycles) + R"(, "technology_objects": [)" +
         kAxis + R"(], "timeline": )" + timeline + R"(, "trace": )" + trace + R"(, "expect": )" + expect +
         "}";
}

// docs/scenarios.md "`trace`: names and CSV" (the header, values of every type, bits).
TEST(ScenarioRun, TraceFormat) {
  auto s = load(scenario(3,
                         R"([{ "cycle": 1, "instance": "power1", "instruction": "MC_Power", "axis": "Axis1",
                               "inputs": { "Enable": true } },
                             { "cycle": 2, "set": { "Axis1.Override.Velocity": 12.5 } }])",
                         R"(["power1.Busy", "power1.ErrorID", "Axis1.StatusWord", "Axis1.Override.Velocity",
                             "Axis1.DynamicDefaults.Velocity", "Axis1.StatusWord.X6"])"));
  ASSERT_TRUE(s);
  EXPECT_EQ(s->trace_header(),
            "cycle,time,power1.Busy,power1.ErrorID,Axis1.StatusWord,Axis1.Override.Velocity,"
            "Axis1.DynamicDefaults.Velocity,Axis1.StatusWord.X6");
  const auto rows = run_csv(*s);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1], (std::vector<std::string>{"0", "0", "0", "0", "64", "100", "1500", "1"}));
  // Created in cycle 1: Busy from its first call; reals with %.17g.
  EXPECT_EQ(rows[2][0], "1");
  EXPECT_EQ(rows[2][1], "0.001");
  EXPECT_EQ(rows[2][2], "1");
  // `set` in cycle 2 is visible in the row of cycle 2 (applied before the user program).
  EXPECT_EQ(rows[3][1], "0.002");
  EXPECT_EQ(rows[3][5], "12.5");
}

// docs/scenarios.md "`trace`: names and CSV" (LREALs print with the digits that read back).
TEST(ScenarioRun, RealsRoundTrip) {
  auto s = load(scenario(1, "[]", R"(["Axis1.Override.Velocity"])"));
  ASSERT_TRUE(s);
  // Not a run value, but the formatting path: the configured 100 prints as "100", and 0.1-like values as 17
  // digits.
  auto t = load(R"({ "cycle_time": 0.001, "cycles": 1, "technology_objects": [
      { "name": "A", "type": "TO_SpeedAxis", "config": { "Override.Velocity": 0.1 }, "drive": { "telegram": 1 } }],
      "trace": ["A.Override.Velocity"] })");
  ASSERT_TRUE(t);
  const auto rows = run_csv(*t);
  EXPECT_EQ(rows[1][2], "0.10000000000000001");
}

// docs/scenarios.md "`timeline`: events" and "Instruction inputs"; spec 03 §3.6 (call order).
TEST(ScenarioRun, InputsKeepTheirValuesAndEventsOfOneCycleApplyInOrder) {
  auto s = load(scenario(6,
                         R"([{ "cycle": 0, "instance": "p", "instruction": "MC_Power", "axis": "Axis1",
                               "inputs": { "Enable": true, "StopMode": 1 } },
                             { "cycle": 3, "instance": "p", "inputs": { "StopMode": 2 } },
                             { "cycle": 3, "instance": "p", "inputs": { "StopMode": 3 } }])",
                         R"(["p.Enable", "p.StopMode"])"));
  ASSERT_TRUE(s);
  const auto rows = run_csv(*s);
  EXPECT_EQ(rows[3][3], "1");
  EXPECT_EQ(rows[4][3], "3");
  EXPECT_EQ(rows[6][2], "1");  // Enable kept from cycle 0
  EXPECT_EQ(rows[6][3], "3");
}

// docs/scenarios.md "`timeline`: events" (an instance exists from its first event on).
TEST(ScenarioRun, InstancesAreCalledOnlyOnceCreated) {
  // An MC_Reset traced before its first event shows its initial outputs; its edge is its first call.
  auto s = load(scenario(4,
                         R"([{ "cycle": 2, "instance": "r", "instruction": "MC_Reset", "axis": "Axis1",
                               "inputs": { "Execute": true } }])",
                         R"(["r.Execute", "r.Done", "r.Busy"])"));
  ASSERT_TRUE(s);
  const auto rows = run_csv(*s);
  EXPECT_EQ(rows[2][2], "0");
  EXPECT_EQ(rows[3][2], "1");
  // Reset of a TO without alarms: accepted at the edge (Busy or already Done by the next cycle).
  EXPECT_TRUE(rows[3][4] == "1" || rows[3][3] == "1");
  EXPECT_EQ(rows[4][3], "1");
}

std::unique_ptr<Scenario> enabled_axis_with(const std::string& fault_events, const std::string& expect) {
  return load(scenario(200,
                       R"([{ "cycle": 0, "instance": "p", "instruction": "MC_Power", "axis": "Axis1",
                             "inputs": { "Enable": true } },)" +
                           fault_events + "]",
                       R"(["p.Status", "Axis1.ErrorDetail.Number", "Axis1.drive.active_fault"])", expect));
}

// docs/scenarios.md "`inject` / `clear`"; spec 06 §6.4 (G1_ZSW.15, the error code); decision S2 (401).
TEST(ScenarioRun, EncoderErrorOfTheMotorEncoderFaultsTheDrive) {
  // A motor-shaft G1 error faults the drive with F31110 (docs/simulated-drive.md), seen as alarm 401.
  auto s = enabled_axis_with(
      R"({ "cycle": 50, "inject": { "target": "Axis1", "fault": "encoder_error", "code": "16#2" } },
                                { "cycle": 100, "clear": { "target": "Axis1", "fault": "encoder_error", "encoder": 1 } })",
      R"([{ "cycle": 40, "values": { "p.Status": true } },
                                 { "cycle": 60, "values": { "p.Status": false, "Axis1.ErrorDetail.Number": 401,
                                                            "Axis1.drive.active_fault": 31110 } }])");
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->run(nullptr).ok());
}

// docs/scenarios.md "`trace`: names and CSV" (alarm names) and "`inject` / `clear`".
TEST(ScenarioRun, AlarmTraceNamesShowPendingAndAdditionalValue) {
  // "<TO>.alarm.<n>" and "<TO>.alarm.<n>.additional_value": raised in cycle 50, acknowledged by MC_Reset.
  auto s = enabled_axis_with(
      R"({ "cycle": 50, "inject": { "target": "Axis1", "fault": "technology_alarm", "alarm": 501,
                                    "additional_value": 7 } },
         { "cycle": 60, "instance": "r", "instruction": "MC_Reset", "axis": "Axis1", "inputs": { "Execute": true } })",
      R"([{ "cycle": 49, "values": { "Axis1.alarm.501": false, "Axis1.alarm.501.additional_value": 0 } },
          { "cycle": 55, "values": { "Axis1.alarm.501": true, "Axis1.alarm.501.additional_value": 7,
                                     "Axis1.alarm.401": false } },
          { "cycle": 70, "values": { "Axis1.alarm.501": false, "Axis1.alarm.501.additional_value": 0 } }])");
  ASSERT_TRUE(s);
  const auto result = s->run(nullptr);
  EXPECT_TRUE(result.ok()) << ::testing::PrintToString(result.failed_expectations);
  EXPECT_EQ(result.expectations_checked, 7u);
}

// docs/scenarios.md "`inject` / `clear`"; spec 06 §5.2 (sign-of-life monitoring); decision S2.
TEST(ScenarioRun, SignOfLifeFreezeAndLinkLoss) {
  auto s = enabled_axis_with(
      R"({ "cycle": 50, "inject": { "target": "Axis1", "fault": "sign_of_life_freeze" } },
                                { "cycle": 60, "clear": { "target": "Axis1", "fault": "sign_of_life_freeze" } })",
      R"([{ "cycle": 58, "values": { "p.Status": false, "Axis1.ErrorDetail.Number": 406 } }])");
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->run(nullptr).ok());
  s = enabled_axis_with(R"({ "cycle": 50, "inject": { "target": "Axis1", "fault": "link_loss" } },
                           { "cycle": 150, "clear": { "target": "Axis1", "fault": "link_loss" } })",
                        R"([{ "cycle": 60, "values": { "p.Status": false, "Axis1.ErrorDetail.Number": 405 } },
                            { "cycle": 199, "values": { "Axis1.drive.active_fault": 8501 } }])");
  ASSERT_TRUE(s);
  const auto result = s->run(nullptr);
  EXPECT_TRUE(result.ok()) << ::testing::PrintToString(result.failed_expectations);
}

// docs/scenarios.md "`expect`: expected values (tomc extension)".
TEST(ScenarioRun, FailedExpectationsAreReportedEach) {
  auto s = load(scenario(5, "[]", "[]",
                         R"([{ "cycle": 4, "values": { "Axis1.Override.Velocity": 99, "Axis1.Velocity": 0 } },
                             { "cycle": 1, "values": { "Axis1.Override.Velocity": 100.5 }, "tolerance": 0.25 }])"));
  ASSERT_TRUE(s);
  const auto result = s->run(nullptr);
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.expectations_checked, 3u);
  ASSERT_EQ(result.failed_expectations.size(), 2u);
  // In time order, each with its index in the file.
  EXPECT_EQ(result.failed_expectations[0],
            "expect[1] (cycle 1): Axis1.Override.Velocity = 100, expected 100.5 (tolerance 0.25)");
  EXPECT_EQ(result.failed_expectations[1],
            "expect[0] (cycle 4): Axis1.Override.Velocity = 100, expected 99 (tolerance 1e-9)");
}

// tomc's own (scenario.hpp): a Scenario runs once because the Runtime cannot be rewound; a second run() is
// an error, not a silent replay.
TEST(ScenarioRun, RunsOnce) {
  auto s = load(scenario(2, "[]", "[]"));
  ASSERT_TRUE(s);
  EXPECT_EQ(s->run(nullptr).cycles_run, 2u);
  const auto again = s->run(nullptr);
  EXPECT_EQ(again.cycles_run, 0u);
  ASSERT_EQ(again.runtime_errors.size(), 1u);
}

// spec 01 §2.5 (virtual axis: no drive, enabled at once); docs/scenarios.md "`technology_objects[i]`".
TEST(ScenarioRun, VirtualAxisWithoutDrive) {
  auto s = load(R"({ "cycle_time": 0.001, "cycles": 120, "technology_objects": [
      { "name": "V", "type": "TO_SpeedAxis", "config": { "VirtualAxis.Mode": 1, "DynamicLimits.MaxJerk": 0 } }],
    "timeline": [
      { "cycle": 0, "instance": "p", "instruction": "MC_Power", "axis": "V", "inputs": { "Enable": true } },
      { "cycle": 5, "instance": "m", "instruction": "MC_MoveVelocity", "axis": "V",
        "inputs": { "Execute": true, "Velocity": 600, "Acceleration": 100 } }],
    "expect": [ { "cycle": 105, "values": { "m.InVelocity": true, "V.Velocity": 600 } } ] })");
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->run(nullptr).ok());
}

// Determinism (issue 22): every scenario file of the repository (tests/scenarios, its open_issues, the
// examples `tomc sim` runs) gives a byte-identical trace on a second run: time is the cycle counter, never
// the wall clock, and nothing depends on addresses or on the order of a hash container. The second run is the
// one ctest's `scenario.<name>` made with `tomc sim --out` in another process (ctest starts these tests after
// them, DEPENDS in CMakeLists.txt) when its trace file is newer than the scenario file, `tomc` and this
// program; otherwise (the tests run alone) this program runs the file twice. ctest runs it in six shards, so
// that `ctest -j2` can balance them (decision V14). A failure names the file and the first line that differs.
namespace fs = std::filesystem;

struct ScenarioFile {
  fs::path json;
  fs::path sim_trace;  // where the ctest `scenario.<name>` writes its trace (tests/scenarios/CMakeLists.txt)
};

std::vector<ScenarioFile> scenario_files() {
  const fs::path source(TOMC_SOURCE_DIR);
  const fs::path traces = fs::path(tomc::testing::bin_dir()) / ".." / "tests" / "scenarios";
  std::vector<ScenarioFile> files;
  for (const auto& [dir, prefix] :
       {std::pair{"tests/scenarios", ""}, std::pair{"tests/scenarios/open_issues", "open_issue_"}}) {
    if (!fs::is_directory(source / dir)) continue;  // open_issues/ only while there are some
    for (const auto& entry : fs::directory_iterator(source / dir)) {
      if (entry.path().extension() == ".json")
        files.push_back({entry.path(), traces / (prefix + entry.path().stem().string() + ".csv")});
    }
  }
  for (const char* example :
       {"speed_axis_conveyor", "positioning_machine", "gearing_machine", "rotary_knife", "flying_saw"})
    files.push_back(
        {source / "examples" / (std::string(example) + ".json"), traces / (std::string(example) + ".csv")});
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.json < b.json; });
  return files;
}

// The trace `tomc sim` wrote, if it was written after the file, `tomc` and this program last changed.
std::optional<std::string> fresh_sim_trace(const ScenarioFile& file) {
  std::error_code error;
  const auto written = fs::last_write_time(file.sim_trace, error);
  if (error) return std::nullopt;
  for (const fs::path& input : {file.json, fs::path(TOMC_BINARY), fs::path("/proc/self/exe")}) {
    const auto changed = fs::last_write_time(input, error);
    if (error || changed >= written) return std::nullopt;
  }
  std::ifstream in(file.sim_trace, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string trace_of(const fs::path& file) {
  auto loaded = Scenario::load_file(file);
  EXPECT_TRUE(loaded.scenario) << file << ": " << (loaded.problems.empty() ? "" : loaded.problems.front());
  std::ostringstream trace;
  if (loaded.scenario) (void)loaded.scenario->run(&trace);
  return trace.str();
}

// TOMC_SCENARIO_SHARD="k/n" (set by each of the ctest entries): the files whose place in the sorted list is k
// modulo n; unset, all of them.
std::pair<std::size_t, std::size_t> shard() {
  const char* value = std::getenv("TOMC_SCENARIO_SHARD");
  std::size_t k = 0;
  std::size_t n = 1;
  if (value != nullptr && (std::sscanf(value, "%zu/%zu", &k, &n) != 2 || n == 0 || k >= n)) {
    ADD_FAILURE() << "TOMC_SCENARIO_SHARD='" << value << "': expected k/n with k < n";
    return {0, 1};
  }
  return {k, n};
}

// Issue 22 (docs/reliability.md §3); decision V14 (the shards and the trace of `tomc sim`), described above.
TEST(ScenarioDeterminism, TwoRunsOfEveryScenarioFileGiveByteIdenticalTraces) {
  const std::vector<ScenarioFile> files = scenario_files();
  ASSERT_GE(files.size(), 50u);
  const auto [k, n] = shard();
  int shared = 0;
  int mine = 0;
  for (std::size_t i = k; i < files.size(); i += n) {
    const ScenarioFile& file = files[i];
    ++mine;
    const std::string first = trace_of(file.json);
    std::optional<std::string> sim = fresh_sim_trace(file);
    // A trace cut short (its `tomc sim` ended by a timeout or a sanitizer while writing) is no second run:
    // the file runs twice here instead (review of stop 32).
    if (sim && std::count(sim->begin(), sim->end(), '\n') != std::count(first.begin(), first.end(), '\n'))
      sim.reset();
    shared += sim ? 1 : 0;
    // State that leaks from one run into the next within a process (a static, a global counter) shows only
    // in a second run in the same process: the shard's first file always gets one.
    if (i == k) {
      EXPECT_EQ(trace_of(file.json), first) << file.json << ": a second run in this program differs";
    }
    const std::string second = sim ? *sim : trace_of(file.json);
    EXPECT_GT(first.size(), 0u) << file.json;
    if (first == second) continue;
    const auto at =
        std::mismatch(first.begin(), first.end(), second.begin(), second.end()).first - first.begin();
    const auto line = std::count(first.begin(), first.begin() + at, '\n') + 1;
    ADD_FAILURE() << file.json << ": the traces differ from line " << line << " (second run: "
                  << (sim ? "`tomc sim`'s " + file.sim_trace.string() : std::string("in this program"))
                  << ")";
  }
  std::cout << shared << " of " << mine
            << " files compared with the trace of `tomc sim`, the others run twice here\n";
}

}  // namespace
