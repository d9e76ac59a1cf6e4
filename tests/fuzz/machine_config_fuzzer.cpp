// The C ABI's configuration entry (tomc_runtime_create) with arbitrary bytes: a runtime or TOMC_ERROR_CONFIG
// with a message, never a crash, an exception, another status or a half-made runtime. A loaded runtime is
// stepped a few cycles. Built as a libFuzzer target (build-fuzz, clang) and, with TOMC_FUZZ_REPLAY, as a
// ctest that replays the seed corpus (tests/fuzz/machine_config_corpus) in the ordinary build.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tomc/tomc.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);  // NUL-terminated for the C ABI
  tomc_runtime* runtime = reinterpret_cast<tomc_runtime*>(&runtime);  // must be reset to NULL on failure
  const tomc_status status = tomc_runtime_create(text.c_str(), &runtime);
  if (status == TOMC_OK) {
    if (runtime == nullptr) std::abort();
    if (tomc_runtime_step(runtime, 5) != TOMC_OK) std::abort();
    tomc_runtime_destroy(runtime);
    return 0;
  }
  if (status != TOMC_ERROR_CONFIG || runtime != nullptr || std::strlen(tomc_last_error()) == 0) {
    std::fprintf(stderr, "status %s, runtime %p, message '%s'\n", tomc_status_name(status),
                 static_cast<void*>(runtime), tomc_last_error());
    std::abort();
  }
  return 0;
}

#ifdef TOMC_FUZZ_REPLAY
#include "replay_main.hpp"
#endif
