#pragma once
// Two-process test support: runs `tomc gateway-sim` as a child process (the binary comes from CMake as
// TOMC_BINARY), records its PID, stops it by that PID — SIGTERM for a clean stop, SIGKILL to simulate a crash
// — and makes sure it dies with the test (PR_SET_PDEATHSIG), so no simulator outlives a failed test.
//
// Every test uses its own DDS domain (TOOLCHAIN §8) and a partition unique to this process, so that two test
// runs on the same machine (two build directories) do not talk to each other either.

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>
#include "build_paths.hpp"

#ifndef TOMC_BINARY
#error "TOMC_BINARY must name build/bin/tomc"
#endif

namespace tomc::testing {

inline std::string test_partition() {
  return "tomc-test-" + std::to_string(::getpid());
}

inline std::filesystem::path test_directory(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("tomc-dds-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::create_directories(dir);
  return dir;
}

// A gateway-sim configuration with `devices` as (name, drive telegram) on `domain`. Unless `extra` says
// otherwise, the gateway's watchdog is 1 s: longer than any lock-step wait of the tests for a missing answer
// (a controller that waits longer than the watchdog is dropped by the gateway, docs/gateway.md §10).
inline std::string gateway_config(int domain, const std::vector<std::pair<std::string, int>>& devices,
                                  const std::string& gateway = "gw1", const std::string& extra = "") {
  std::ostringstream s;
  s << "{ \"gateway\": \"" << gateway << "\", \"domain\": " << domain << ", \"cycle_time\": 0.001, ";
  s << (extra.empty() ? std::string("\"watchdog\": 1.0") : extra) << ", ";
  s << "\"devices\": [";
  for (std::size_t i = 0; i < devices.size(); ++i) {
    s << (i ? ", " : "") << "{ \"name\": \"" << devices[i].first
      << "\", \"drive\": { \"telegram\": " << devices[i].second << " } }";
  }
  s << "] }";
  return s.str();
}

class GatewayProcess {
 public:
  GatewayProcess(const std::filesystem::path& directory, const std::string& config_text,
                 std::vector<std::string> extra_arguments = {})
      : config_(directory / "gateway.json") {
    std::ofstream(config_) << config_text;
    std::vector<std::string> args = {TOMC_BINARY,      "gateway-sim", "--config",
                                     config_.string(), "--partition", test_partition()};
    args.insert(args.end(), extra_arguments.begin(), extra_arguments.end());
    start(std::move(args), directory / "gateway.log");
  }
  // Any gateway command line (the program is looked up in PATH unless it is a path), output to `log`.
  GatewayProcess(std::vector<std::string> args, const std::filesystem::path& log) {
    start(std::move(args), log);
  }
  ~GatewayProcess() { terminate(); }
  GatewayProcess(const GatewayProcess&) = delete;
  GatewayProcess& operator=(const GatewayProcess&) = delete;

  pid_t pid() const { return pid_; }
  bool running() const { return pid_ > 0; }

  // A crash: SIGKILL, nothing cleaned up by the simulator. Returns once the process is gone.
  void kill_hard() { stop(SIGKILL); }
  // A clean stop; returns the wait status (-1 if it was not running).
  int terminate() { return stop(SIGTERM); }

  std::string log() const {
    std::ifstream in(log_);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  void start(std::vector<std::string> args, const std::filesystem::path& log_file) {
    log_ = log_file;
    std::vector<char*> argv;
    for (auto& a : args)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string log = log_.string();
    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      // Child: only async-signal-safe calls until exec.
      ::prctl(PR_SET_PDEATHSIG, SIGTERM);
      if (::getppid() != parent) ::_exit(126);
      const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
      if (fd >= 0) {
        ::dup2(fd, 1);
        ::dup2(fd, 2);
      }
      ::execvp(argv[0], argv.data());
      ::_exit(127);
    }
  }

  int stop(int signal) {
    if (pid_ <= 0) return -1;
    ::kill(pid_, signal);
    int status = 0;
    // Bounded: a simulator that does not stop within 10 s is killed, and that is a failure the caller sees.
    for (int i = 0; i < 1000; ++i) {
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        pid_ = -1;
        return status;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return -2;
  }

  pid_t pid_ = -1;
  std::filesystem::path config_;
  std::filesystem::path log_;
};

}  // namespace tomc::testing
