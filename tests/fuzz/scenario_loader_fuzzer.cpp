// The scenario loader (`tomc sim`, tools/scenario/scenario.hpp) with arbitrary bytes: a Scenario or at least
// one problem line naming a JSON path, never a crash, an exception or both; a loaded scenario of at most 200
// cycles is run with its trace written, and its trace has a header and one row per cycle. The machine part
// of the file is also what machine_config_fuzzer covers through the C ABI; this one adds the timeline,
// faults, traces and expectations. Built as a libFuzzer target (build-fuzz, clang) and, with
// TOMC_FUZZ_REPLAY, as a ctest that replays the seed corpus (tests/fuzz/scenario_corpus).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

#include "tomc/scenario/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto loaded = tomc::scenario::Scenario::load_text(text, "fuzz");
  if ((loaded.scenario == nullptr) == loaded.problems.empty()) {
    std::fprintf(stderr, "scenario %p with %zu problems\n", static_cast<void*>(loaded.scenario.get()),
                 loaded.problems.size());
    std::abort();
  }
  for (const auto& line : loaded.problems) {
    if (line.empty()) std::abort();
  }
  if (loaded.scenario == nullptr || loaded.scenario->cycles() > 200) return 0;
  std::ostringstream trace;
  const auto result = loaded.scenario->run(&trace);
  std::size_t rows = 0;
  for (const char c : trace.str())
    rows += c == '\n' ? 1 : 0;
  if (result.cycles_run != loaded.scenario->cycles() || rows != result.cycles_run + 1) {
    std::fprintf(stderr, "%llu cycles run of %llu, %zu trace lines\n",
                 static_cast<unsigned long long>(result.cycles_run),
                 static_cast<unsigned long long>(loaded.scenario->cycles()), rows);
    std::abort();
  }
  return 0;
}

#ifdef TOMC_FUZZ_REPLAY
#include "replay_main.hpp"
#endif
