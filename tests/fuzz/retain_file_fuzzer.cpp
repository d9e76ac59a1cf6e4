// The retentive store file (techobjects/runtime/retentive_store.hpp) with arbitrary bytes: parse_retain_file
// returns ok with records or corrupt with a message naming the line, never a crash or an exception; an ok
// file's records are well-formed (a name without blanks, finite offset) and survive write -> read unchanged.
// Most random bytes stop at the checksum, so when the first byte is odd the rest gets a valid checksum line
// appended: the record parser behind it is reached. Built as a libFuzzer target (build-fuzz, clang) and, with
// TOMC_FUZZ_REPLAY, as a ctest that replays the seed corpus (tests/fuzz/retain_file_corpus).
#include <unistd.h>

#include <cinttypes>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "tomc/techobjects/runtime/retentive_store.hpp"

namespace {

// FNV-1a 64, the file format's checksum (retentive_store.hpp), as the fix-up needs it.
std::string checksum_line(const std::string& body) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const unsigned char c : body)
    h = (h ^ c) * 1099511628211ULL;
  char line[32];
  std::snprintf(line, sizeof line, "checksum %016" PRIx64 "\n", h);
  return line;
}

void check_round_trip(const tomc::techobjects::RetainFile& parsed) {
  namespace fs = std::filesystem;
  const fs::path file = fs::temp_directory_path() / ("tomc-retain-fuzz-" + std::to_string(::getpid()));
  std::string error;
  if (!tomc::techobjects::write_retain_file(file, parsed.records, error)) {
    std::fprintf(stderr, "write failed: %s\n", error.c_str());
    std::abort();
  }
  const auto again = tomc::techobjects::read_retain_file(file);
  fs::remove(file);
  if (again.status != tomc::techobjects::RetainFileStatus::kOk ||
      again.records.size() != parsed.records.size())
    std::abort();
  for (std::size_t i = 0; i < again.records.size(); ++i) {
    const auto& a = parsed.records[i];
    const auto& b = again.records[i];
    if (a.name != b.name || a.data.valid != b.data.valid ||
        a.data.AbsEncoderOffset != b.data.AbsEncoderOffset ||
        a.data.MeasuringRangeCount != b.data.MeasuringRangeCount ||
        a.data.LastAbsoluteValue != b.data.LastAbsoluteValue || a.data.sequence != b.data.sequence) {
      std::fprintf(stderr, "record %zu changed in the round trip\n", i);
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  if ((data[0] & 1u) != 0) text += checksum_line(text);
  const auto parsed = tomc::techobjects::parse_retain_file(text, "fuzz");
  using tomc::techobjects::RetainFileStatus;
  if (parsed.status == RetainFileStatus::kCorrupt) {
    if (parsed.message.rfind("fuzz:", 0) != 0 || !parsed.records.empty()) std::abort();
    return 0;
  }
  if (parsed.status != RetainFileStatus::kOk) std::abort();  // bytes are never "missing" or "unreadable"
  for (const auto& r : parsed.records) {
    if (r.name.empty() || r.name.find_first_of(" \t\n\r") != std::string::npos) std::abort();
    if (!std::isfinite(r.data.AbsEncoderOffset)) std::abort();
  }
  check_round_trip(parsed);
  return 0;
}

#ifdef TOMC_FUZZ_REPLAY
#include "replay_main.hpp"
#endif
