// Positioning axes on several cores (issue 23): one Runtime per thread, each thread pinned to its own core
// and running N positioning axes (bench/positioning_machine.hpp: simulated drive on telegram 3, steady
// motion) in a 1 ms cycle paced with clock_nanosleep on absolute time, as a PLC runs several motion contexts.
// Per cycle it records MC_Servo + MC_Interpolator of the N axes (the TO with its telegram codec; the drive
// model and the user program run in the same cycle but outside the timed part) and the whole Runtime::step().
// Prints, per axes count and thread count, the median, p99 and maximum per cycle over all threads' cycles.
// Usage: positioning_cores [cycles] [axes per thread ...]   (defaults: 2000 cycles; 256 512 1024 2048 4096)
// Figures and the command: docs/performance.md.
#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <barrier>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "positioning_machine.hpp"

namespace {

struct Samples {
  std::vector<double> servo_interpolator_us;
  std::vector<double> step_us;
};

void pin_to_core(unsigned core) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(core % std::max(1u, std::thread::hardware_concurrency()), &set);
  pthread_setaffinity_np(pthread_self(), sizeof(set), &set);
}

void add_nanoseconds(timespec& t, long ns) {
  t.tv_nsec += ns;
  while (t.tv_nsec >= 1'000'000'000L) {
    t.tv_nsec -= 1'000'000'000L;
    ++t.tv_sec;
  }
}

// One thread: its own machine (built on its core, so its memory is first touched there), then `cycles` paced
// cycles after all threads are ready.
void run_context(unsigned core, int axes, int cycles, std::barrier<>& ready, Samples& out) {
  pin_to_core(core);
  tomc::bench::PositioningMachine machine(axes, true, 0);
  machine.group().timed = true;
  out.servo_interpolator_us.reserve(static_cast<std::size_t>(cycles));
  out.step_us.reserve(static_cast<std::size_t>(cycles));
  ready.arrive_and_wait();
  timespec next{};
  clock_gettime(CLOCK_MONOTONIC, &next);
  for (int k = 0; k < cycles; ++k) {
    add_nanoseconds(next, 1'000'000L);
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
    const auto before = machine.group().elapsed;
    const auto t0 = std::chrono::steady_clock::now();
    machine.step();
    const auto t1 = std::chrono::steady_clock::now();
    out.servo_interpolator_us.push_back(
        std::chrono::duration<double, std::micro>(machine.group().elapsed - before).count());
    out.step_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
  }
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string one;
  f >> one;
  return one;
}

}  // namespace

int main(int argc, char** argv) {
  const int cycles = argc > 1 ? std::atoi(argv[1]) : 2000;
  std::vector<int> axes_counts;
  for (int i = 2; i < argc; ++i)
    axes_counts.push_back(std::atoi(argv[i]));
  if (axes_counts.empty()) axes_counts = {256, 512, 1024, 2048, 4096};
  std::printf(
      "| Axes per thread | Threads | MC_Servo + MC_Interpolator per cycle: median / p99 / max (µs) | whole "
      "step: median / p99 (µs) | load average |\n|---|---|---|---|---|\n");
  for (const int axes : axes_counts) {
    for (const unsigned threads : {1u, 2u}) {
      std::vector<Samples> samples(threads);
      std::barrier ready(static_cast<std::ptrdiff_t>(threads));
      std::vector<std::thread> pool;
      for (unsigned t = 0; t < threads; ++t)
        pool.emplace_back(run_context, t, axes, cycles, std::ref(ready), std::ref(samples[t]));
      for (auto& t : pool)
        t.join();
      std::vector<double> servo, step;
      for (const Samples& s : samples) {
        servo.insert(servo.end(), s.servo_interpolator_us.begin(), s.servo_interpolator_us.end());
        step.insert(step.end(), s.step_us.begin(), s.step_us.end());
      }
      std::printf("| %d | %u | %.0f / %.0f / %.0f | %.0f / %.0f | %s |\n", axes, threads,
                  percentile(servo, 0.5), percentile(servo, 0.99), percentile(servo, 1.0),
                  percentile(step, 0.5), percentile(step, 0.99), load_average().c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
