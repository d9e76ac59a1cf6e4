#pragma once
// Random positioning replans in the six start categories of issue 23 (rest to rest, moving toward, moving
// away, over the velocity limit, over the acceleration limit, reversal), jerk-limited, asymmetric
// acceleration/deceleration, limits over two orders of magnitude. Shared by profile_optimality and
// profile_plan_callgrind so both see the same cases.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::bench {

inline constexpr std::array<const char*, 6> kProfileCategories{
    "rest to rest", "moving toward", "moving away", "over the velocity limit", "over the acceleration limit",
    "reversal"};

struct PlanCase {
  techobjects::MotionState start;
  double target = 0;
  techobjects::ProfileLimits limits;
};

// SplitMix64: the same cases on every platform.
class CaseRandom {
 public:
  explicit CaseRandom(std::uint64_t seed) : state_(seed) {}
  double uniform(double lo, double hi) {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  bool chance(double p) { return uniform(0, 1) < p; }

 private:
  std::uint64_t state_;
};

inline std::vector<PlanCase> make_plan_cases(int category, std::size_t count, std::uint64_t seed) {
  CaseRandom r(seed * 8 + static_cast<std::uint64_t>(category));
  std::vector<PlanCase> cases(count);
  for (PlanCase& c : cases) {
    auto& l = c.limits;
    l.velocity = r.log_uniform(0.1, 10.0);
    l.acceleration = l.velocity / r.log_uniform(0.02, 2.0);  // acceleration time
    l.deceleration = r.chance(0.3) ? l.acceleration : l.velocity / r.log_uniform(0.02, 2.0);
    l.jerk = std::max(l.acceleration, l.deceleration) / r.log_uniform(0.005, 0.5);  // rounding time
    const double a_both = std::min(l.acceleration, l.deceleration);
    c.start = {r.uniform(-10.0, 10.0), r.uniform(0.0, 1.0) * l.velocity, r.uniform(-1.0, 1.0) * a_both};
    double distance = l.velocity * l.velocity / l.deceleration * r.log_uniform(0.01, 10.0);
    switch (category) {
      case 0:
        c.start.velocity = c.start.acceleration = 0;
        break;
      case 1:
        break;
      case 2:
        c.start.velocity = -c.start.velocity;
        break;
      case 3:
        c.start.velocity = r.uniform(1.05, 2.0) * l.velocity;
        break;
      case 4:
        c.start.acceleration = r.uniform(1.05, 2.0) * l.acceleration;
        break;
      default:
        distance = -distance;
        break;
    }
    c.target = c.start.position + distance;
  }
  return cases;
}

}  // namespace tomc::bench
