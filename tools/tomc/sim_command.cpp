// `tomc sim SCENARIO.json [--out TRACE.csv]`: runs a scenario on simulated drives (docs/scenarios.md) — the
// offline PLC simulator for users and the format of the spec tests. Exit status: 0 ran and every expectation
// held, 1 ran but an expectation failed, 2 the scenario (or the command line) is malformed.
#include <fstream>
#include <iostream>
#include <optional>
#include <ostream>
#include <string>

#include "cli_error.hpp"
#include "commands.hpp"
#include "tomc/scenario/scenario.hpp"

namespace tomc::cli {
namespace {

// Distinct from kExitBadInput: a CI job must tell "the machine misbehaved" from "the file is broken".
constexpr int kExitExpectationFailed = 1;

constexpr std::string_view kSimUsage =
    "usage: tomc sim SCENARIO.json [--out TRACE.csv]\n"
    "\n"
    "Runs the scenario cycle by cycle (MC_Servo, MC_Interpolator, user program) on simulated drives and\n"
    "writes the trace as CSV to TRACE.csv, or to stdout without --out. The format is in docs/scenarios.md.\n"
    "\n"
    "exit status: 0 ran and every expectation held, 1 an expectation failed, 2 malformed scenario\n"
    "(one line per problem on stderr, each naming its JSON path).\n";

struct SimOptions {
  std::optional<std::string> scenario;
  std::optional<std::string> out;
  bool help = false;
};

SimOptions parse_sim_options(std::span<const std::string_view> args) {
  SimOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view a = args[i];
    if (a == "--help" || a == "-h") {
      o.help = true;
    } else if (a == "--out") {
      if (i + 1 >= args.size()) throw UsageError("sim: --out needs a file name");
      o.out = std::string(args[++i]);
    } else if (a.starts_with("--out=")) {
      o.out = std::string(a.substr(6));
    } else if (a.starts_with("-") && a != "-") {
      throw UsageError("sim: unknown option '" + std::string(a) + "' (try: tomc sim --help)");
    } else if (o.scenario) {
      throw UsageError("sim: one scenario file at a time, got '" + *o.scenario + "' and '" + std::string(a) +
                       "'");
    } else {
      o.scenario = std::string(a);
    }
  }
  if (o.out && o.out->empty()) throw UsageError("sim: --out needs a file name");
  return o;
}

}  // namespace

int sim_command(std::span<const std::string_view> args, std::ostream& out) {
  const SimOptions o = parse_sim_options(args);
  if (o.help) {
    out << kSimUsage;
    return 0;
  }
  if (!o.scenario) throw UsageError("sim: missing SCENARIO.json (try: tomc sim --help)");

  scenario::LoadResult loaded = scenario::Scenario::load_file(*o.scenario);
  if (!loaded.scenario) {
    // Every problem at once, one line each, so the file can be fixed in one pass.
    for (const auto& line : loaded.problems)
      std::cerr << "tomc: " << *o.scenario << ": " << line << '\n';
    return kExitBadInput;
  }

  std::ofstream file;
  std::ostream* trace = &out;
  if (o.out) {
    file.open(*o.out, std::ios::binary | std::ios::trunc);
    if (!file) throw UsageError("sim: cannot write '" + *o.out + "'");
    trace = &file;
  }
  const scenario::RunResult result = loaded.scenario->run(trace);
  for (const auto& line : result.warnings)
    std::cerr << "tomc: " << *o.scenario << ": warning: " << line << '\n';
  if (o.out) {
    file.close();
    if (!file) throw UsageError("sim: writing '" + *o.out + "' failed");
  }
  for (const auto& line : result.runtime_errors)
    std::cerr << "tomc: " << *o.scenario << ": " << line << '\n';
  for (const auto& line : result.failed_expectations)
    std::cerr << "tomc: " << *o.scenario << ": " << line << '\n';
  if (o.out) {
    // stdout is free when the trace went to a file: say what happened.
    out << *o.scenario << ": " << result.cycles_run << " cycles, " << result.expectations_checked
        << " expected values checked, " << result.failed_expectations.size() << " failed; trace in " << *o.out
        << '\n';
  }
  return result.ok() ? 0 : kExitExpectationFailed;
}

}  // namespace tomc::cli
