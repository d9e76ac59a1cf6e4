#pragma once
// `tomc demo --free-running`: the cycle function stepped back to back on its own thread, without waiting for
// a period (the machine's time is Runtime::step()'s virtual clock, so the TOs see the same cycles as in real
// time, only sooner). For the soak (docs/reliability.md §7), which needs 10^8 cycles in an hour instead of
// 28 h. No drive may be paced by real time (a Fast DDS gateway): the caller checks. Statistics as the
// RealTimeRunner's: cycles; no overruns, no jitter (there is no deadline).

#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace tomc::cli {

class FreeRunner {
 public:
  using Cycle = std::function<void(std::uint64_t cycle)>;  // must not throw; the steps done so far

  explicit FreeRunner(Cycle cycle) : cycle_(std::move(cycle)) {}
  ~FreeRunner() { stop(); }
  FreeRunner(const FreeRunner&) = delete;
  FreeRunner& operator=(const FreeRunner&) = delete;

  void start() {
    thread_ = std::thread([this] {
      std::uint64_t n = 0;
      while (!stop_requested_.load(std::memory_order_relaxed)) {
        cycle_(n);
        cycles_.store(++n, std::memory_order_relaxed);
      }
    });
  }
  void stop() {
    stop_requested_.store(true, std::memory_order_relaxed);
    if (thread_.joinable()) thread_.join();
  }
  techobjects::RunnerStatistics statistics() const {
    techobjects::RunnerStatistics s;
    s.cycles = cycles_.load(std::memory_order_relaxed);
    s.setup_warnings = "free-running: cycles stepped back to back on virtual time";
    return s;
  }

 private:
  Cycle cycle_;
  std::thread thread_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<std::uint64_t> cycles_{0};
};

}  // namespace tomc::cli
