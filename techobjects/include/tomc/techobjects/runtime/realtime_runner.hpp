#pragma once
// Runs a cycle function on its own thread at a fixed period with absolute deadlines (clock_nanosleep on
// CLOCK_MONOTONIC), optionally SCHED_FIFO and mlockall, counting overruns and recording wake-up jitter into a
// fixed histogram (no allocation in the loop). The deterministic Runtime::step() is what it usually runs.

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>

namespace tomc::techobjects {

struct RealTimeRunnerConfig {
  std::chrono::nanoseconds period{1'000'000};
  int fifo_priority = 0;     // 1..99 = SCHED_FIFO at that priority; 0 = normal scheduling
  bool lock_memory = false;  // mlockall(MCL_CURRENT | MCL_FUTURE) and pre-fault the stack
  // 0, or wake this long before each deadline and spin on the clock (vDSO, no system call) to it: the cycle
  // then starts at its deadline however late the kernel woke the thread, up to the margin, at the cost of
  // about margin − wake-up latency of CPU per cycle. 0 ≤ margin < period.
  std::chrono::nanoseconds wake_margin{0};
};

struct RunnerStatistics {
  std::uint64_t cycles = 0;
  std::uint64_t overruns = 0;  // cycles that ended after the next deadline (those periods are skipped)
  std::uint64_t skipped_periods = 0;
  // Start latency (cycle start minus deadline), microseconds, at 1 us resolution up to kMaxJitterUs: the
  // wake-up latency, or with a wake margin what of it the margin did not absorb.
  double jitter_min_us = 0.0;
  double jitter_median_us = 0.0;
  double jitter_p99_us = 0.0;
  double jitter_max_us = 0.0;
  std::string setup_warnings;  // e.g. "SCHED_FIFO: Operation not permitted"
  // With a wake margin: the mean time spun per cycle (its CPU cost), and the cycles that woke after their
  // deadline (wake-up latency above the margin).
  double spin_mean_us = 0.0;
  std::uint64_t late_wakeups = 0;
};

class RealTimeRunner {
 public:
  static constexpr std::size_t kMaxJitterUs = 4096;
  using Cycle = std::function<void()>;  // must not throw

  RealTimeRunner(RealTimeRunnerConfig config, Cycle cycle);
  ~RealTimeRunner();
  RealTimeRunner(const RealTimeRunner&) = delete;
  RealTimeRunner& operator=(const RealTimeRunner&) = delete;

  void start();
  void stop();  // joins the thread
  bool running() const noexcept { return running_.load(std::memory_order_acquire); }
  RunnerStatistics statistics() const;

 private:
  void loop() noexcept;
  void record_jitter(std::int64_t nanoseconds) noexcept;

  RealTimeRunnerConfig config_;
  Cycle cycle_;
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> stop_requested_{false};
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<std::uint64_t> overruns_{0};
  std::atomic<std::uint64_t> skipped_{0};
  std::atomic<std::uint64_t> spin_ns_{0};
  std::atomic<std::uint64_t> late_wakeups_{0};
  std::atomic<std::int64_t> jitter_min_ns_{INT64_MAX};
  std::atomic<std::int64_t> jitter_max_ns_{0};
  std::array<std::atomic<std::uint32_t>, kMaxJitterUs + 1> histogram_{};  // last bucket: >= kMaxJitterUs
  std::string setup_warnings_;  // written by the thread before it sets setup_done_
  std::atomic<bool> setup_done_{false};
};

}  // namespace tomc::techobjects
