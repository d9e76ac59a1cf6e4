// `tomc demo` as a user runs it: help, a bad configuration (every problem named by its JSON path, exit 2),
// bad options, and a short run of a configuration of one's own in the tomc sim format.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include "build_paths.hpp"

namespace {

struct DemoRun {
  int status = -1;
  std::string out;
  std::string err;
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

DemoRun tomc(const std::vector<std::string>& args) {
  const std::string err_file = ::testing::TempDir() + "tomc_demo_stderr_" + std::to_string(getpid()) + ".txt";
  std::string cmd = quote(TOMC_BINARY);
  for (const auto& a : args)
    cmd += " " + quote(a);
  cmd += " 2>" + quote(err_file);
  DemoRun run;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return run;
  char buf[4096];
  std::size_t n = 0;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0)
    run.out.append(buf, n);
  const int status = pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  std::stringstream ss;
  ss << err.rdbuf();
  run.err = ss.str();
  return run;
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name + "_" + std::to_string(getpid()) + ".json";
  std::ofstream(path) << text;
  return path;
}

// One speed axis "Fan" on a simulated drive (telegram 1), in the tomc sim format.
std::string fan_machine(const std::string& name, const std::string& cycle_time) {
  return write_file(name, R"({
    "cycle_time": )" + cycle_time +
                              R"(,
    "technology_objects": [
      {"name": "Fan", "type": "TO_SpeedAxis", "config": {"DynamicLimits.MaxVelocity": 1000.0},
       "drive": {"adapter": "simulated", "telegram": 1}}
    ]
  })");
}

// README.md "`tomc demo`: the diagnostics page of a running machine" (its usage).
TEST(DemoCli, Help) {
  const DemoRun r = tomc({"demo", "--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("usage: tomc demo"), std::string::npos);
}

// README.md "`tomc demo`: the diagnostics page of a running machine" (options; bad ones: status 2).
TEST(DemoCli, BadOptions) {
  EXPECT_EQ(tomc({"demo", "--port", "70000"}).status, 2);
  EXPECT_EQ(tomc({"demo", "--port", "x"}).status, 2);
  EXPECT_EQ(tomc({"demo", "--token", "a", "--generate-token"}).status, 2);
  EXPECT_EQ(tomc({"demo", "--seconds", "-1"}).status, 2);
  EXPECT_EQ(tomc({"demo", "--frobnicate"}).status, 2);
  EXPECT_EQ(tomc({"demo", "--allow-host", ""}).status, 2);
  EXPECT_EQ(tomc({"demo", "--inject-faults", "39"}).status, 2);  // shorter than a fault is held (2 x 20)
  EXPECT_EQ(tomc({"demo", "--inject-faults", "x"}).status, 2);
  const DemoRun gateway = tomc({"demo", "--free-running", "--gateway", "5"});
  EXPECT_EQ(gateway.status, 2);
  EXPECT_NE(gateway.err.find("real time"), std::string::npos) << gateway.err;
  const DemoRun missing = tomc({"demo", "--config", "/nonexistent/machine.json"});
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos);
}

// docs/scenarios.md "Exit status and messages" (every problem with its JSON path, 2).
TEST(DemoCli, EveryProblemOfAConfigurationIsNamed) {
  const std::string path = write_file("bad_machine", R"({
    "cycle_time": 0.001,
    "technology_objects": [
      {"name": "A", "type": "TO_SpeedAxis", "config": {"DynamicLimits.MaxVelocity": -1},
       "drive": {"adapter": "simulated", "telegram": 2}},
      {"name": "B", "type": "TO_PositioningAxis"}
    ],
    "program": {"C": {"velocities": [1]}, "A": {"dwell_s": 0}},
    "diagnostics": {"port": 99999, "colour": "red", "allowed_hosts": ["plc7.local", 7], "export_priority": "high"},
    "extra": 1
  })");
  const DemoRun r = tomc({"demo", "--config", path});
  EXPECT_EQ(r.status, 2) << r.err;
  for (const char* expected : {"technology_objects[0].config.DynamicLimits.MaxVelocity",
                               "technology_objects[1].drive: missing (a TO_PositioningAxis needs a drive",
                               "program.C: no technology object", "program.A.dwell_s", "diagnostics.port",
                               "diagnostics.allowed_hosts: expected an array of host names",
                               "diagnostics.export_priority: expected \"idle\" (default) or \"normal\"",
                               "diagnostics.colour: unknown key", "extra: unknown key"}) {
    EXPECT_NE(r.err.find(expected), std::string::npos) << expected << "\n" << r.err;
  }
  EXPECT_EQ(tomc({"demo", "--config", write_file("not_json", "{ nope")}).status, 2);
}

// The program of positioning axes and external encoders (docs/diagnostics.md "tomc demo").
TEST(DemoCli, PositioningProgramProblemsAreNamed) {
  const std::string path = write_file("bad_positioning_program", R"({
    "technology_objects": [
      {"name": "P", "type": "TO_PositioningAxis", "drive": {"adapter": "simulated", "telegram": 3}},
      {"name": "E", "type": "TO_ExternalEncoder", "drive": {"adapter": "simulated", "encoder_telegram": 81}}
    ],
    "program": {
      "P": {"home_mode": 5, "positions": [1, "x"], "distance": 10, "velocity": -1, "speed": 2},
      "E": {"positions": [1]}
    }
  })");
  const DemoRun r = tomc({"demo", "--config", path});
  EXPECT_EQ(r.status, 2) << r.err;
  for (const char* expected :
       {"program.P.home_mode: expected 0 (set position) or 3", "program.P.positions[1]",
        "program.P.distance: either positions or distance", "program.P.velocity",
        "program.P.speed: unknown key", "program.E: an external encoder has no program"}) {
    EXPECT_NE(r.err.find(expected), std::string::npos) << expected << "\n" << r.err;
  }
}

// program.<synchronous axis>.cam (decision W23): the cam must be a TO_Cam of the machine, the application
// mode 0 .. 2, no other keys.
TEST(DemoCli, CammingProgramProblemsAreNamed) {
  const std::string path = write_file("bad_camming_program", R"({
    "technology_objects": [
      {"name": "L", "type": "TO_PositioningAxis", "drive": {"adapter": "simulated", "telegram": 3}},
      {"name": "F", "type": "TO_SynchronousAxis", "drive": {"adapter": "simulated", "telegram": 3},
       "LeadingValueInterconnections": [{"Leader": "L", "Coupling": "Setpoint"}]}
    ],
    "program": {
      "F": {"cam": "L", "application_mode": 5, "master": "L"}
    }
  })");
  const DemoRun r = tomc({"demo", "--config", path});
  EXPECT_EQ(r.status, 2) << r.err;
  for (const char* expected : {"program.F.cam: expected the name of a TO_Cam of this machine",
                               "program.F.application_mode: expected 0 (not cyclic), 1 (cyclic) or 2",
                               "program.F.master: unknown key"}) {
    EXPECT_NE(r.err.find(expected), std::string::npos) << expected << "\n" << r.err;
  }
}

// A machine of one's own, in the tomc sim format, read-only (no token), on any free port, for one second.
// decision W14 (read-only without a token, 127.0.0.1); docs/scenarios.md (the machine format).
TEST(DemoCli, RunsAConfigurationOfOnesOwn) {
  const std::string path = fan_machine("own_machine", "0.002");
  const DemoRun r = tomc({"demo", "--config", path, "--port", "0", "--seconds", "1"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cycle 2 ms: Fan"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("read-only"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("http://127.0.0.1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stopped after"), std::string::npos) << r.out;
}

// The soak's mode (docs/reliability.md §7): virtual time, faults injected into the simulated drive.
TEST(DemoCli, FreeRunningStepsOnVirtualTime) {
  const std::string path = fan_machine("free_machine", "0.001");
  const DemoRun r = tomc(
      {"demo", "--config", path, "--port", "0", "--seconds", "1", "--free-running", "--inject-faults", "40"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cycle 1 ms (free-running: virtual time): Fan"), std::string::npos) << r.out;
  const auto at = r.out.find("stopped after ");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_GT(std::stoull(r.out.substr(at + 14)), 0u) << r.out;
}

}  // namespace
