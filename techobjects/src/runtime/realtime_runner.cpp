#include "tomc/techobjects/runtime/realtime_runner.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <time.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace tomc::techobjects {
namespace {

constexpr std::int64_t kNsPerSecond = 1'000'000'000;

std::int64_t to_ns(const timespec& t) {
  return static_cast<std::int64_t>(t.tv_sec) * kNsPerSecond + t.tv_nsec;
}
timespec from_ns(std::int64_t ns) {
  timespec t{};
  t.tv_sec = static_cast<time_t>(ns / kNsPerSecond);
  t.tv_nsec = static_cast<long>(ns % kNsPerSecond);
  return t;
}
std::int64_t now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return to_ns(t);
}

// A spin-wait hint to the core (no system call).
inline void cpu_relax() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

void prefault_stack() {
  volatile unsigned char buffer[256 * 1024];
  for (std::size_t i = 0; i < sizeof buffer; i += 4096)
    buffer[i] = 0;
}

}  // namespace

RealTimeRunner::RealTimeRunner(RealTimeRunnerConfig config, Cycle cycle)
    : config_(config), cycle_(std::move(cycle)) {
  if (config_.period.count() <= 0) throw std::invalid_argument("RealTimeRunner: period must be > 0");
  if (!cycle_) throw std::invalid_argument("RealTimeRunner: no cycle function");
  if (config_.fifo_priority < 0 || config_.fifo_priority > 99) {
    throw std::invalid_argument("RealTimeRunner: fifo_priority must be 0..99");
  }
  if (config_.wake_margin.count() < 0 || config_.wake_margin >= config_.period) {
    throw std::invalid_argument("RealTimeRunner: wake_margin must be 0 or more and less than the period");
  }
}

RealTimeRunner::~RealTimeRunner() {
  stop();
}

void RealTimeRunner::start() {
  if (thread_.joinable()) return;
  stop_requested_.store(false);
  setup_done_.store(false);
  setup_warnings_.clear();
  thread_ = std::thread([this] { loop(); });
  while (!running_.load(std::memory_order_acquire) && !stop_requested_.load())
    std::this_thread::yield();
}

void RealTimeRunner::stop() {
  stop_requested_.store(true);
  if (thread_.joinable()) thread_.join();
  running_.store(false, std::memory_order_release);
}

void RealTimeRunner::record_jitter(std::int64_t ns) noexcept {
  if (ns < 0) ns = 0;
  const auto bucket =
      static_cast<std::size_t>(ns / 1000) < kMaxJitterUs ? static_cast<std::size_t>(ns / 1000) : kMaxJitterUs;
  histogram_[bucket].fetch_add(1, std::memory_order_relaxed);
  std::int64_t seen = jitter_min_ns_.load(std::memory_order_relaxed);
  while (ns < seen && !jitter_min_ns_.compare_exchange_weak(seen, ns, std::memory_order_relaxed)) {
  }
  seen = jitter_max_ns_.load(std::memory_order_relaxed);
  while (ns > seen && !jitter_max_ns_.compare_exchange_weak(seen, ns, std::memory_order_relaxed)) {
  }
}

void RealTimeRunner::loop() noexcept {
  // Set-up of the real-time thread: failures are reported, not fatal (a desktop has no RT rights).
  if (config_.lock_memory) {
    if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
      setup_warnings_ += std::string("mlockall: ") + std::strerror(errno) + "; ";
    prefault_stack();
  }
  if (config_.fifo_priority > 0) {
    sched_param param{};
    param.sched_priority = config_.fifo_priority;
    const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    if (error != 0) setup_warnings_ += std::string("SCHED_FIFO: ") + std::strerror(error) + "; ";
  }
  setup_done_.store(true, std::memory_order_release);
  running_.store(true, std::memory_order_release);

  const std::int64_t period = config_.period.count();
  const std::int64_t margin = config_.wake_margin.count();
  std::int64_t deadline = now_ns() + period;
  while (!stop_requested_.load(std::memory_order_relaxed)) {
    const timespec wake = from_ns(deadline - margin);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &wake, nullptr) == EINTR) {
    }
    std::int64_t start = now_ns();
    if (margin > 0) {
      // Bounded: at most `margin` past the wake-up time; the clock read is a vDSO call, no system call.
      const std::int64_t woke = start;
      if (woke > deadline) late_wakeups_.fetch_add(1, std::memory_order_relaxed);
      while (start < deadline) {
        cpu_relax();
        start = now_ns();
      }
      spin_ns_.fetch_add(static_cast<std::uint64_t>(start - woke), std::memory_order_relaxed);
    }
    record_jitter(start - deadline);
    cycle_();
    cycles_.fetch_add(1, std::memory_order_relaxed);
    deadline += period;
    const std::int64_t end = now_ns();
    if (end > deadline) {
      // Overrun: the next deadline has passed. Skip the missed periods instead of running cycles back to
      // back.
      overruns_.fetch_add(1, std::memory_order_relaxed);
      const std::int64_t missed = (end - deadline) / period + 1;
      skipped_.fetch_add(static_cast<std::uint64_t>(missed), std::memory_order_relaxed);
      deadline += missed * period;
    }
  }
}

RunnerStatistics RealTimeRunner::statistics() const {
  RunnerStatistics s;
  s.cycles = cycles_.load();
  s.overruns = overruns_.load();
  s.skipped_periods = skipped_.load();
  s.late_wakeups = late_wakeups_.load();
  if (s.cycles > 0)
    s.spin_mean_us = static_cast<double>(spin_ns_.load()) / 1000.0 / static_cast<double>(s.cycles);
  if (setup_done_.load(std::memory_order_acquire)) s.setup_warnings = setup_warnings_;
  std::uint64_t total = 0;
  for (const auto& b : histogram_)
    total += b.load(std::memory_order_relaxed);
  if (total == 0) return s;
  s.jitter_min_us = static_cast<double>(jitter_min_ns_.load()) / 1000.0;
  s.jitter_max_us = static_cast<double>(jitter_max_ns_.load()) / 1000.0;
  auto percentile = [&](double q) {
    const auto rank = static_cast<std::uint64_t>(q * static_cast<double>(total - 1));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < histogram_.size(); ++i) {
      seen += histogram_[i].load(std::memory_order_relaxed);
      if (seen > rank) return static_cast<double>(i);  // lower edge of the 1 us bucket
    }
    return static_cast<double>(kMaxJitterUs);
  };
  s.jitter_median_us = percentile(0.5);
  s.jitter_p99_us = percentile(0.99);
  return s;
}

}  // namespace tomc::techobjects
