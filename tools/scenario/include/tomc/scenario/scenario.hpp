#pragma once
// The scenario engine behind `tomc sim` (docs/scenarios.md): a JSON file describes technology objects on
// simulated drives, a timeline of instruction inputs, variable writes and injected faults, the variables to
// trace and (extension) expected values. load() validates the whole file up front and builds the Runtime, the
// devices, the TOs and the instruction instances; run() executes every cycle exactly as a PLC would.
//
// Library code does not throw for bad input: problems come back as lines "<JSON path>: <message>".

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "tomc/scenario/config.hpp"

namespace tomc::scenario {

class Scenario;

struct LoadResult {
  std::unique_ptr<Scenario> scenario;  // nullptr when problems is not empty
  std::vector<std::string> problems;   // one line each
};

struct RunResult {
  std::uint64_t cycles_run = 0;
  std::size_t expectations_checked = 0;
  std::vector<std::string> failed_expectations;  // one line each, "expect[i] (cycle k): ..."
  std::vector<std::string> runtime_errors;       // e.g. a `set` refused at run time (never expected)
  std::vector<std::string> warnings;             // e.g. a device behind a gateway that does not answer
  bool ok() const noexcept { return failed_expectations.empty() && runtime_errors.empty(); }
};

class Scenario {
 public:
  ~Scenario();
  Scenario(const Scenario&) = delete;
  Scenario& operator=(const Scenario&) = delete;

  // Validates and builds. `source` names the document in messages about malformed JSON; files the document
  // names (a cam's points) are relative to `directory` (load_file: the scenario file's folder).
  static LoadResult load(const Json& document, const std::filesystem::path& directory = {});
  static LoadResult load_text(std::string_view text, std::string_view source,
                              const std::filesystem::path& directory = {});
  static LoadResult load_file(const std::filesystem::path& file);

  double cycle_time() const noexcept;
  std::uint64_t cycles() const noexcept;
  // The CSV header: "cycle,time,<trace names>".
  std::string trace_header() const;

  // Runs every cycle once (a Scenario runs once: the Runtime cannot be rewound). Writes the header and one
  // row per cycle to `trace` unless it is nullptr; checks the expectations after their cycle.
  RunResult run(std::ostream* trace);

  struct Impl;

 private:
  explicit Scenario(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tomc::scenario
