// Cost of TO_SynchronousAxis per follower and cycle (issues 9, 19), Google Benchmark, on the machine of
// gearing_machine.hpp (one leader on a simulated drive at 100 mm/s, N followers on simulated drives, telegram
// 3, MC_GearIn 1:1 — or, the "camming" variants, MC_CamIn on a cyclic spline cam — steady synchronous
// travel):
//   BM_GearingCycle/followers            — one whole Runtime::step(): MC_Servo + MC_Interpolator of the
//   leader
//       and every follower, the user program (MC_Power, MC_GearIn per follower) and the simulated drives; CPU
//       time per follower;
//   BM_GearingServoInterpolator/followers — of the same cycle only the followers' MC_Servo + MC_Interpolator
//       (the TO with its telegram codec; no drive model, no user program, no leader), timed around the group;
//       median of per-cycle samples per follower, also with the two clock reads per phase subtracted;
//   BM_DelayedLeadingValue/cycles       — what a leader adds to its MC_Interpolator while a follower couples
//       "Delayed" (decision C26): one push of its setpoint into the ring and the interpolated value, for a
//       delay of `cycles` + 0.5 interpolator cycles.
// Figures and commands: docs/performance.md "Synchronous axis (issue 9)", "Camming (issue 19)" and "The
// delayed leading value".
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "gearing_machine.hpp"
#include "tomc/techobjects/synchronous/delayed_leading_value.hpp"

namespace {

using tomc::bench::Function;
using tomc::bench::GearingMachine;

double median(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// What the two steady_clock reads around each of the two phases add to a cycle's sample.
double clock_overhead_ns() {
  std::vector<double> samples;
  samples.reserve(20000);
  for (int i = 0; i < 20000; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto t1 = std::chrono::steady_clock::now();
    const auto t2 = std::chrono::steady_clock::now();
    samples.push_back(std::chrono::duration<double, std::nano>(t2 - t0).count() -
                      std::chrono::duration<double, std::nano>(t2 - t1).count());
  }
  return 2.0 * median(samples);
}

void BM_GearingCycle(benchmark::State& state, Function function) {
  const auto followers = static_cast<int>(state.range(0));
  GearingMachine m(followers, function);
  for (auto _ : state)
    m.step();
  state.SetItemsProcessed(state.iterations() * followers);
  state.counters["ns_per_follower"] =  // CPU time, as positioning_bench
      benchmark::Counter(static_cast<double>(state.iterations() * followers),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_GearingServoInterpolator(benchmark::State& state, Function function) {
  const auto followers = static_cast<int>(state.range(0));
  GearingMachine m(followers, function);
  const double overhead = clock_overhead_ns();
  std::vector<double> samples;
  samples.reserve(1 << 22);
  m.group().timed = true;
  for (auto _ : state) {
    const auto before = m.group().elapsed;
    m.step();
    const double seconds = std::chrono::duration<double>(m.group().elapsed - before).count();
    state.SetIterationTime(seconds);
    if (samples.size() < samples.capacity()) samples.push_back(seconds * 1e9);
  }
  const double total = std::chrono::duration<double>(m.group().elapsed).count();
  state.counters["ns_per_follower"] =
      benchmark::Counter(total * 1e9 / static_cast<double>(state.iterations() * followers));
  state.SetItemsProcessed(state.iterations() * followers);
  const double med = median(samples);
  state.counters["median_ns_per_follower"] = med / followers;
  state.counters["median_minus_clock_ns_per_follower"] = (med - overhead) / followers;
  // Still in synchronous travel at the end (the workload is what it claims to be).
  if (!m.programs().front().synchronous()) state.SkipWithError("a follower left synchronous travel");
}

void BM_DelayedLeadingValue(benchmark::State& state) {
  const double cycles = static_cast<double>(state.range(0)) + 0.5;
  tomc::techobjects::DelayedLeadingValue delayed(cycles * 0.001, 0.001);
  tomc::techobjects::MotionState setpoint{0.0, 100.0, 0.0};
  for (auto _ : state) {
    setpoint.position += 0.1;  // 100 mm/s at 1 ms
    delayed.push(setpoint);
    benchmark::DoNotOptimize(delayed.value());
  }
}

}  // namespace

BENCHMARK(BM_DelayedLeadingValue)->Arg(2)->Arg(1000 - 1)->ArgName("cycles");
BENCHMARK_CAPTURE(BM_GearingCycle, gearing, Function::kGearing)
    ->Arg(1)
    ->Arg(64)
    ->Arg(1024)
    ->ArgName("followers");
BENCHMARK_CAPTURE(BM_GearingServoInterpolator, gearing, Function::kGearing)
    ->Arg(1)
    ->Arg(64)
    ->Arg(1024)
    ->ArgName("followers")
    ->UseManualTime();
BENCHMARK_CAPTURE(BM_GearingCycle, camming, Function::kCamming)
    ->Arg(1)
    ->Arg(64)
    ->Arg(1024)
    ->ArgName("followers");
BENCHMARK_CAPTURE(BM_GearingServoInterpolator, camming, Function::kCamming)
    ->Arg(1)
    ->Arg(64)
    ->Arg(1024)
    ->ArgName("followers")
    ->UseManualTime();
