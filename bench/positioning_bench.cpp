// Cost of TO_PositioningAxis per axis and cycle (issue 5), Google Benchmark:
//   BM_PositioningCycle/axes/drive/period   — one whole Runtime::step(): MC_Servo + MC_Interpolator of every
//       axis, the user program (MC_Power, MC_Home, 2 x MC_MoveAbsolute per axis) and, with drive = 1, the
//       simulated drives (telegram 3); period 0 = steady motion, n = a new MC_MoveAbsolute every n cycles;
//   BM_PositioningServoInterpolator/...     — of the same cycle only MC_Servo + MC_Interpolator (the TO with
//       its telegram codec; no drive model, no user program), timed around the group of axes;
//   BM_SteadyClockPair                      — the cost of the two clock reads per phase that timing adds;
//   BM_PositioningMemory                    — sizeof(PositioningAxis) and the heap it and its drive take;
//   BM_TimePositionEvaluate                 — one evaluation of a 128-point MC_PositionProfile profile;
//   BM_PositionProfileAndMotionInStep/job   — one Runtime::step() of a virtual axis on a 128-point profile
//       (job 0) or fed by MC_MotionInPosition every cycle (job 1), instruction calls included (issue 18).
// Figures and commands: docs/performance.md.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "positioning_machine.hpp"
#include "tomc/instructions/mc_motion_in.hpp"
#include "tomc/instructions/mc_position_profile.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/motion/time_position_profile.hpp"

namespace {

using tomc::bench::PositioningMachine;

void per_axis_counter(benchmark::State& state, int axes, double seconds) {
  state.counters["ns_per_axis"] = benchmark::Counter(
      seconds * 1e9 / static_cast<double>(state.iterations() * static_cast<std::int64_t>(axes)));
  state.SetItemsProcessed(state.iterations() * axes);
}

void BM_PositioningCycle(benchmark::State& state) {
  const auto axes = static_cast<int>(state.range(0));
  PositioningMachine m(axes, state.range(1) != 0, static_cast<int>(state.range(2)));
  for (auto _ : state)
    m.step();
  state.SetItemsProcessed(state.iterations() * axes);
  state.counters["ns_per_axis"] =  // CPU time, as runtime_bench
      benchmark::Counter(static_cast<double>(state.iterations() * axes),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Median of per-cycle samples (robust against the preemptions of a shared machine).
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
  return 2.0 * median(samples);  // one read pair per phase, two phases per cycle
}

void BM_PositioningServoInterpolator(benchmark::State& state) {
  const auto axes = static_cast<int>(state.range(0));
  PositioningMachine m(axes, state.range(1) != 0, static_cast<int>(state.range(2)));
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
  per_axis_counter(state, axes, std::chrono::duration<double>(m.group().elapsed).count());
  const double med = median(samples);
  state.counters["median_ns_per_axis"] = med / axes;
  state.counters["median_minus_clock_ns_per_axis"] = (med - overhead) / axes;
}

void BM_SteadyClockPair(benchmark::State& state) {
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(std::chrono::steady_clock::now() - t0);
  }
}

// Bytes per axis: the TO object itself and what constructing it (and its simulated drive) takes from the
// heap.
void BM_PositioningMemory(benchmark::State& state) {
  constexpr int kAxes = 256;
  const bool with_drive = state.range(0) != 0;
  double per_axis = 0;
  for (auto _ : state) {
    const auto before = mallinfo2().uordblks;
    {
      PositioningMachine m(kAxes, with_drive, 0);
      per_axis = static_cast<double>(mallinfo2().uordblks - before) / kAxes;
      benchmark::DoNotOptimize(m.group().axes.size());
    }
  }
  state.counters["sizeof_PositioningAxis"] = static_cast<double>(sizeof(tomc::techobjects::PositioningAxis));
  {  // the object plus what it owns once in a runtime (start values in the runtime's load memory; issue 14)
    PositioningMachine one(1, with_drive, 0);
    state.counters["footprint_PositioningAxis"] =
        static_cast<double>(one.group().axes.front()->memory_footprint());
  }
  state.counters["heap_bytes_per_axis"] = per_axis;  // TO, its program, and with drive = 1 its drive
}

// 128 points over 12.7 s: a sine of 50 mm amplitude, the densest profile the structure holds.
tomc::techobjects::TimePositionProfile dense_profile() {
  tomc::techobjects::TimePositionProfile p;
  p.NumberOfPoints = static_cast<std::int32_t>(tomc::techobjects::kMaxTimePositionPoints);
  for (std::size_t i = 0; i < tomc::techobjects::kMaxTimePositionPoints; ++i)
    p.Point[i] = {0.1 * static_cast<double>(i), 50.0 * std::sin(0.05 * static_cast<double>(i))};
  return p;
}

void BM_TimePositionEvaluate(benchmark::State& state) {
  const auto p = dense_profile();
  double t = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tomc::techobjects::evaluate(p, t));
    t = t < 12.6 ? t + 0.001 : 0.0;
  }
}

void BM_PositionProfileAndMotionInStep(benchmark::State& state) {
  namespace to = tomc::techobjects;
  const bool motion_in = state.range(0) != 0;
  to::Runtime runtime(to::RuntimeConfig{0.001, 1, 1});
  auto data = to::PositioningAxisData{};
  data.VirtualAxis.Mode = to::kModeOn;
  auto& axis = runtime.emplace<to::PositioningAxis>("Axis", nullptr, data);
  const auto profile = dense_profile();
  tomc::instructions::MC_Power<to::PositioningAxis> power;
  tomc::instructions::MC_PositionProfile<to::PositioningAxis> follow;
  tomc::instructions::MC_MotionInPosition<to::PositioningAxis> feed;
  power.Enable = true;
  follow.TimePosition = &profile;
  std::int64_t k = 0;
  runtime.set_user_program([&](to::Runtime&) {
    power(axis);
    if (motion_in) {
      feed.Enable = power.Status;
      feed.Position = 50.0 * std::sin(0.0005 * static_cast<double>(k));
      feed(axis);
    } else {
      follow.Execute = power.Status && !follow.Done;  // a new job once the last one is Done
      follow(axis);
    }
    ++k;
  });
  runtime.start();
  for (int i = 0; i < 50; ++i)
    runtime.step();
  for (auto _ : state)
    runtime.step();
  state.counters["on_job"] = motion_in ? static_cast<double>(feed.Busy) : static_cast<double>(follow.Busy);
}

void axes_args(benchmark::internal::Benchmark* b) {
  for (int drive : {1, 0}) {
    for (int axes : {1, 64, 1024, 4096})
      b->Args({axes, drive, 0});
    for (int period : {1, 10})
      for (int axes : {1, 64, 1024})
        b->Args({axes, drive, period});
  }
  b->ArgNames({"axes", "drive", "period"});
}

}  // namespace

BENCHMARK(BM_PositioningCycle)->Apply(axes_args);
BENCHMARK(BM_PositioningServoInterpolator)->Apply(axes_args)->UseManualTime();
BENCHMARK(BM_SteadyClockPair);
BENCHMARK(BM_PositioningMemory)->Arg(0)->Arg(1)->Iterations(1);
BENCHMARK(BM_TimePositionEvaluate);
BENCHMARK(BM_PositionProfileAndMotionInStep)->Arg(0)->Arg(1)->ArgName("job");
