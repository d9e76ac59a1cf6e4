#pragma once
// What the random property tests of the synchronous axis share (gearing_property_test.cpp,
// camming_property_test.cpp): the seed (a fixed base, TOMC_PROPERTY_SEED overrides it), the random draws,
// the fixed rings of the last events and cycles printed when a check fails, and the judge of a
// synchronization with dynamic parameters against the follower's DynamicLimits (spec 07 §6.8, decision C23).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <random>
#include <string>

namespace tomc::testing {

// The base seed of a property test: `fallback`, or TOMC_PROPERTY_SEED when it is set.
inline std::uint32_t property_base_seed(std::uint32_t fallback) {
  const char* s = std::getenv("TOMC_PROPERTY_SEED");
  return s != nullptr ? static_cast<std::uint32_t>(std::strtoul(s, nullptr, 10)) : fallback;
}

// The random draws of a run, from its seed.
class PropertyRandom {
 public:
  explicit PropertyRandom(std::uint32_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  int pick(int n) { return static_cast<int>(rng_() % static_cast<std::uint32_t>(n)); }
  std::uint32_t next() { return rng_(); }

 private:
  std::mt19937 rng_;
};

// The last N events (cycle, what, up to 6 values), printed after a failure: a fixed ring, no allocation.
template <std::size_t N>
class EventRing {
 public:
  void note(int cycle, const char* what, std::initializer_list<double> values = {}) {
    Event& e = events_[static_cast<std::size_t>(count_++) % N];
    e = Event{cycle, what, {}, 0};
    for (double v : values)
      if (e.n < e.v.size()) e.v[e.n++] = v;
  }
  void print() const {
    std::printf("last events (cycle, what, values):\n");
    for (int i = std::max(0, count_ - static_cast<int>(N)); i < count_; ++i) {
      const Event& e = events_[static_cast<std::size_t>(i) % N];
      std::printf("  %d %s", e.cycle, e.what);
      for (std::size_t k = 0; k < e.n; ++k)
        std::printf(" %g", e.v[k]);
      std::printf("\n");
    }
  }

 private:
  struct Event {
    int cycle = 0;
    const char* what = "";
    std::array<double, 6> v{};
    std::size_t n = 0;
  };
  std::array<Event, N> events_{};
  int count_ = 0;
};

// The last N cycles of a test's own State, printed after a failure with the test's line printer.
template <typename State, std::size_t N>
class StateRing {
 public:
  void push(const State& s) { states_[static_cast<std::size_t>(count_++) % N] = s; }
  template <typename Print>
  void print(const char* header, Print line) const {
    std::printf("last cycles (%s):\n", header);
    for (int i = std::max(0, count_ - static_cast<int>(N)); i < count_; ++i)
      line(states_[static_cast<std::size_t>(i) % N]);
  }

 private:
  std::array<State, N> states_{};
  int count_ = 0;
};

// Synchronization with dynamic parameters (MC_GearInPos / MC_CamIn profile 0, spec 07 §6.8; SYNC8 "in
// advance using dynamic parameters"; decision C23): MaxVelocity and MaxAcceleration / MaxDeceleration (by
// the direction of |v|), and MaxJerk when it is > 0, hold — above them only what the follower carried in
// at the start, not growing. The manual superimposes later changes of the leader's dynamics, so a cycle is
// judged only while the leader keeps its velocity of the start and does not accelerate.
class DynamicSyncJudge {
 public:
  struct Limits {
    double velocity, acceleration, deceleration, jerk;
  };
  struct Verdict {
    bool judged = false;
    std::string problem;  // empty: within the limits
  };
  // Every cycle: `synchronizing` (a profile-0 synchronization runs), the leader's velocity and acceleration,
  // the follower's setpoint and that of the previous cycle.
  Verdict judge(bool synchronizing, double leader_velocity, double leader_acceleration, double v, double a,
                double previous_v, double previous_a, const Limits& l, double cycle) {
    Verdict out;
    if (synchronizing && !was_synchronizing_)
      start_ = Start{leader_velocity, std::fabs(previous_v), std::fabs(previous_a)};
    const bool constant = synchronizing && leader_acceleration == 0.0 &&
                          std::fabs(leader_velocity - start_.leader_velocity) <=
                              1e-12 * std::max(1.0, std::fabs(leader_velocity));
    if (constant) {
      out.judged = true;
      const double limit = v * a < 0.0 ? l.deceleration : l.acceleration;
      if (std::fabs(v) > std::max(l.velocity, start_.velocity) * (1.0 + 1e-9)) {
        out.problem = "above MaxVelocity: v " + std::to_string(v);
      } else if (std::fabs(a) > std::max(limit, start_.acceleration) * (1.0 + 1e-9)) {
        out.problem = "beyond MaxAcceleration/MaxDeceleration: a " + std::to_string(a) + ", limit " +
                      std::to_string(std::max(limit, start_.acceleration));
      } else if (l.jerk > 0.0 && was_constant_ && std::fabs(a - previous_a) / cycle > l.jerk * (1.0 + 1e-6)) {
        out.problem = "beyond MaxJerk: " + std::to_string(std::fabs(a - previous_a) / cycle);
      }
    }
    was_synchronizing_ = synchronizing;
    was_constant_ = constant;
    return out;
  }

 private:
  struct Start {
    double leader_velocity = 0, velocity = 0, acceleration = 0;
  };
  Start start_{};
  bool was_synchronizing_ = false;
  bool was_constant_ = false;
};

}  // namespace tomc::testing
