#pragma once
// Where the tests find the build's programs (build/bin/tomc, helpers built beside them) and the repository
// (examples, scenarios, GSDML files): at run time, from the running program's own directory, which is the
// build's bin directory (CMAKE_RUNTIME_OUTPUT_DIRECTORY), and the build's CMakeCache.txt, which names the
// source directory. They used to be compiled in as absolute -D values, which are part of ccache's hash: every
// clone at another path recompiled each source of those test executables (docs/reliability.md §6).
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

namespace tomc::testing {

// The directory of the running program.
inline const std::string& bin_dir() {
  static const std::string dir = [] {
    char buffer[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof buffer - 1);
    const std::string exe(buffer, n > 0 ? static_cast<std::size_t>(n) : 0);
    if (exe.empty()) {  // a test would otherwise run "/tomc" and fail far from the cause
      std::fprintf(stderr, "build_paths.hpp: cannot read /proc/self/exe\n");
      std::abort();
    }
    return exe.substr(0, exe.rfind('/'));
  }();
  return dir;
}

// The repository: CMAKE_HOME_DIRECTORY of the build directory above bin/ (the program aborts with a message
// if there is none).
inline const std::string& source_dir() {
  static const std::string dir = [] {
    std::ifstream cache(bin_dir() + "/../CMakeCache.txt");
    constexpr std::string_view kKey = "CMAKE_HOME_DIRECTORY:INTERNAL=";
    for (std::string line; std::getline(cache, line);)
      if (line.starts_with(kKey)) return line.substr(kKey.size());
    std::fprintf(stderr, "build_paths.hpp: no %s in %s/../CMakeCache.txt\n", kKey.data(), bin_dir().c_str());
    std::abort();
  }();
  return dir;
}

}  // namespace tomc::testing

// Each a `const char*` that stays valid for the program's life.
#define TOMC_BUILD_PATH_(base, relative)                 \
  ([]() -> const char* {                                 \
    static const std::string path = (base) + (relative); \
    return path.c_str();                                 \
  }())
#define TOMC_BINARY TOMC_BUILD_PATH_(::tomc::testing::bin_dir(), "/tomc")
#define TOMC_LOOPBACK_PROBE TOMC_BUILD_PATH_(::tomc::testing::bin_dir(), "/loopback_probe")
#define TOMC_LINK_CAPTURE TOMC_BUILD_PATH_(::tomc::testing::bin_dir(), "/link_capture")
#define TOMC_CYCLONE_GATEWAY TOMC_BUILD_PATH_(::tomc::testing::bin_dir(), "/cyclone_gateway")
#define TOMC_LIMITED_SERVER TOMC_BUILD_PATH_(::tomc::testing::bin_dir(), "/diagnostics_limited_server")
#define TOMC_SOURCE_DIR TOMC_BUILD_PATH_(::tomc::testing::source_dir(), "")
#define TOMC_EXAMPLES_DIR TOMC_BUILD_PATH_(::tomc::testing::source_dir(), "/examples")
#define TOMC_GSDML_DIR TOMC_BUILD_PATH_(::tomc::testing::source_dir(), "/drives/profinet/gsdml")
