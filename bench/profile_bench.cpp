// Profile planners (spec 01 §8.7–§8.9): plan() for random replanning cases (random start states with a0 and
// v0 beyond the limits, limits over several orders of magnitude, jerk 0 and > 0), the worst of a set of hard
// cases, and at(). Figures and the command that produced them: docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tomc/techobjects/motion/profiles.hpp"

namespace {

using namespace tomc::techobjects;

// SplitMix64, as in the tests: the same cases everywhere.
struct Random {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
  }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  bool chance(double p) { return uniform(0, 1) < p; }
};

struct Case {
  MotionState start;
  double target;  // velocity or position
  ProfileLimits limits;
};

std::vector<Case> make_cases(bool position, std::size_t count, std::uint64_t seed) {
  Random r{seed};
  std::vector<Case> cases(count);
  for (Case& c : cases) {
    c.limits.velocity = r.log_uniform(1e-2, 1e3);
    c.limits.acceleration = c.limits.velocity / r.log_uniform(1e-3, 1e2);
    c.limits.deceleration =
        r.chance(0.2) ? c.limits.acceleration : c.limits.velocity / r.log_uniform(1e-3, 1e2);
    const double a_max = std::max(c.limits.acceleration, c.limits.deceleration);
    c.limits.jerk = r.chance(0.3) ? 0.0 : a_max / r.log_uniform(1e-4, 1e1);
    c.start.position = r.uniform(-1e3, 1e3);
    c.start.velocity = r.chance(0.2) ? 0.0 : r.uniform(-2, 2) * c.limits.velocity;
    c.start.acceleration = r.chance(0.4) ? 0.0 : r.uniform(-2, 2) * a_max;
    if (position) {
      const double stop_scale = c.limits.velocity * c.limits.velocity / c.limits.deceleration;
      c.target = c.start.position + (r.chance(0.5) ? 1 : -1) * stop_scale * r.log_uniform(1e-4, 1e2);
    } else {
      c.target = r.uniform(-1.2, 1.2) * c.limits.velocity;
    }
  }
  return cases;
}

void BM_VelocityProfilePlan(benchmark::State& state) {
  const auto cases = make_cases(false, 4096, 1);
  VelocityProfile profile;
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & 4095];
    benchmark::DoNotOptimize(profile.plan(c.start, c.target, c.limits));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_VelocityProfilePlan);

void BM_PositionProfilePlan(benchmark::State& state) {
  const auto cases = make_cases(true, 4096, 2);
  PositionProfile profile;
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = cases[i++ & 4095];
    benchmark::DoNotOptimize(profile.plan(c.start, c.target, c.limits));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_PositionProfilePlan);

// The hard cases: the 32 with the most root-search iterations among 100 000 random ones. Each is timed on its
// own (median of 201 runs); the counters report the slowest case and its iteration count.
void BM_PositionProfilePlanHardCases(benchmark::State& state) {
  auto cases = make_cases(true, 100'000, 3);
  PositionProfile profile;
  std::vector<std::pair<int, std::size_t>> by_iterations;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    profile.plan(cases[i].start, cases[i].target, cases[i].limits);
    by_iterations.emplace_back(profile.iterations(), i);
  }
  std::sort(by_iterations.rbegin(), by_iterations.rend());
  std::vector<Case> hard;
  for (std::size_t k = 0; k < 32; ++k)
    hard.push_back(cases[by_iterations[k].second]);

  double worst_ns = 0;
  for (const Case& c : hard) {
    std::vector<double> samples;
    for (int k = 0; k < 201; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(profile.plan(c.start, c.target, c.limits));
      benchmark::ClobberMemory();
      samples.push_back(
          std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(samples.begin(), samples.begin() + 100, samples.end());
    worst_ns = std::max(worst_ns, samples[100]);
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const Case& c = hard[i++ & 31];
    benchmark::DoNotOptimize(profile.plan(c.start, c.target, c.limits));
    benchmark::ClobberMemory();
  }
  state.counters["worst_case_ns"] = worst_ns;
  state.counters["max_iterations"] = by_iterations[0].first;
}
BENCHMARK(BM_PositionProfilePlanHardCases);

void BM_PositionProfileAt(benchmark::State& state) {
  PositionProfile profile;
  // Through zero with jerk, cruise, brake: 10 segments.
  profile.plan({0.0, -5.0, 3.0}, 100.0, {10.0, 4.0, 6.0, 20.0});
  Random r{4};
  std::vector<double> times(4096);
  for (double& t : times)
    t = r.uniform(0, profile.duration());
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(profile.at(times[i++ & 4095]));
  state.counters["segments"] = static_cast<double>(profile.segments().size());
}
BENCHMARK(BM_PositionProfileAt);

}  // namespace
