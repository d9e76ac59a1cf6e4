// PositionProfile::plan against an optimality reference (issue 23), per start category of
// bench/profile_cases.hpp: time per plan (mean, p99, max over the cases; each case the fastest of 3 batches
// of 8 plans), the planned duration against the exact optimum of the positioning template (every timed case,
// `shortest_over_peaks` with 2,000 peaks, 200,000 where the coarse grid finds no admissible peak) and against
// the brute-force reference of tests/support/profile_reference.hpp (on the first cases of each category), and
// the largest segment jerk against the job's.
// Usage: profile_optimality [timed cases per category] [reference cases per category]
// Figures and the command: docs/performance.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "profile_cases.hpp"
#include "profile_reference.hpp"

namespace {

using tomc::bench::PlanCase;
using tomc::techobjects::PositionProfile;

double nanoseconds_per_plan(const PlanCase& c, PositionProfile& profile) {
  constexpr int kBatch = 8;
  double best = INFINITY;
  for (int batch = 0; batch < 3; ++batch) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < kBatch; ++k) {
      profile.plan(c.start, c.target, c.limits);
      asm volatile("" : : "r"(&profile) : "memory");
    }
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / kBatch);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t timed = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 4000;
  const std::size_t referenced = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 100;
  std::printf(
      "| Category | ns per plan: mean / p99 / max | duration / template optimum − 1: median / max | "
      "duration / reference: mean / max (cases) | largest jerk / job's |\n|---|---|---|---|---|\n");
  double all_max_ratio = 0, all_max_ns = 0, all_max_template = -INFINITY;
  for (int category = 0; category < 6; ++category) {
    const auto cases = tomc::bench::make_plan_cases(category, std::max(timed, referenced), 23);
    PositionProfile profile;
    std::vector<double> ns;
    double jerk_ratio = 0;
    for (std::size_t i = 0; i < timed; ++i) {
      ns.push_back(nanoseconds_per_plan(cases[i], profile));
      for (const auto& s : profile.segments())
        jerk_ratio = std::max(jerk_ratio, std::abs(s.jerk) / cases[i].limits.jerk);
    }
    std::sort(ns.begin(), ns.end());
    std::vector<double> template_gap;
    for (std::size_t i = 0; i < timed; ++i) {
      const PlanCase& c = cases[i];
      profile.plan(c.start, c.target, c.limits);
      double optimum = tomc::testing::shortest_over_peaks(c.start, c.target, c.limits, 2000);
      if (!std::isfinite(optimum))
        optimum = tomc::testing::shortest_over_peaks(c.start, c.target, c.limits, 200000);
      template_gap.push_back(profile.duration() / optimum - 1);
    }
    std::sort(template_gap.begin(), template_gap.end());
    all_max_template = std::max(all_max_template, template_gap.back());
    double mean_ns = 0;
    for (const double x : ns)
      mean_ns += x / static_cast<double>(ns.size());
    double ratio_sum = 0, ratio_max = 0;
    std::size_t compared = 0;
    for (std::size_t i = 0; i < referenced; ++i) {
      const PlanCase& c = cases[i];
      profile.plan(c.start, c.target, c.limits);
      const double reference = tomc::testing::ProfileReference(c.start, c.target, c.limits).solve(20, 24);
      if (!std::isfinite(reference)) continue;  // no admissible grid point
      const double ratio = profile.duration() / reference;
      ratio_sum += ratio;
      ratio_max = std::max(ratio_max, ratio);
      ++compared;
    }
    const double p99 = ns[std::min(ns.size() - 1, ns.size() * 99 / 100)];
    all_max_ratio = std::max(all_max_ratio, ratio_max);
    all_max_ns = std::max(all_max_ns, ns.back());
    std::printf("| %s | %.0f / %.0f / %.0f | %.1e / %.1e | ", tomc::bench::kProfileCategories[category],
                mean_ns, p99, ns.back(), template_gap[template_gap.size() / 2], template_gap.back());
    if (compared > 0) {
      std::printf("%.6f / %.6f (%zu) | %.3f |\n", ratio_sum / static_cast<double>(compared), ratio_max,
                  compared, jerk_ratio);
    } else {
      std::printf("– | %.3f |\n", jerk_ratio);
    }
  }
  std::printf("worst: %.0f ns per plan, duration %.6f x the reference, %.2e above the template optimum\n",
              all_max_ns, all_max_ratio, all_max_template);
  return 0;
}
