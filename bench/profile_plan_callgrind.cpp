// Fixed workload for callgrind: PositionProfile::plan over the random replans of bench/profile_cases.hpp,
// 1,000 per category (all six, or the one given as argument 0..5). scripts/bench: instructions per plan.
#include <cstdio>
#include <cstdlib>

#include "profile_cases.hpp"

extern "C" __attribute__((noinline, noipa)) double profile_plan(const tomc::bench::PlanCase* cases, int n) {
  tomc::techobjects::PositionProfile profile;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    profile.plan(cases[i].start, cases[i].target, cases[i].limits);
    sum += profile.duration();
  }
  return sum;
}

int main(int argc, char** argv) {
  constexpr int kPerCategory = 1000;
  const int only = argc > 1 ? std::atoi(argv[1]) : -1;
  int plans = 0;
  double sum = 0;
  for (int category = 0; category < 6; ++category) {
    if (only >= 0 && category != only) continue;
    const auto cases = tomc::bench::make_plan_cases(category, kPerCategory, 23);
    sum += profile_plan(cases.data(), kPerCategory);
    plans += kPerCategory;
  }
  std::printf("cycles=%d units=1 duration_sum=%g\n", plans, sum);
  return 0;
}
