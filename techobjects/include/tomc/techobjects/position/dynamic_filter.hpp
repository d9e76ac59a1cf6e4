#pragma once
// Dynamic filter of the positioning axis (spec 02 §7.6, spec 04 §3.22, seed 004 §6.13.6): between the
// interpolator's setpoint (x_ipo, v_ipo) and the position controller (x_f, v_f, spec 02 §7.4 (1)); its output
// is StatusServo.PositionAfterDynamicFilter.
//
//   Mode 1, PT1/PT2 + dead time:  G(s) = e^(−s·Tt) / ((1 + s·T1)(1 + s·T2))  (a stage with T = 0 drops out)
//   Mode 2, moving average + dead time: one or two moving averages (windows T1, T2) in series, then Tt.
//   Active when Mode ≠ 0 and at least one of T1, T2, Tt > 0 (spec 02 §7.6).
//
// Per servo cycle k, T_s = servo cycle, every time limited to 16·T_s without an alarm (spec 02 §7.6, §10 #17,
// §11 scenario 44):
//   PT1 (backward Euler):  y(k) = y(k−1) + T_s/(T + T_s)·(u(k) − y(k−1))
//       step response y(k) = 1 − a^(k+1), a = T/(T + T_s); lag behind a ramp of velocity v exactly v·T.
//   Moving average (seed 004 §6.13.6.2): N = floor(T/T_s), r = T/T_s − N:
//       y(k) = (u(k) + u(k−1) + ... + u(k−N) + r·u(k−N−1)) / (N + 1 + r)
//       lag behind a ramp (N(N+1)/2 + r(N+1)) / (N + 1 + r) cycles, = T/2 when T is a multiple of T_s.
//   Dead time: y(k) = u(k − Tt/T_s), fractional delays by linear interpolation (exact for a ramp).
// The effective delay (lag behind a ramp) is T1 + T2 + Tt in Mode 1 and 0.5·T1 + 0.5·T2 + Tt in Mode 2 for
// multiples of T_s; it is what FollowingError.AdditionalSetpointDelayTime should be set to (spec 04 §3.22).
//
// Decisions (docs/decisions.md P19–P21): backward Euler for the PT1 (its ramp lag is the continuous T, so the
// documented AdditionalSetpointDelayTime compensates it exactly, as the symmetry filter of
// position_control.hpp); position, velocity and acceleration pass through the same filter; the history lives
// in fixed arrays sized for the 16·T_s limit, so no permitted configuration can exceed them.
//
// Real time: noexcept, no allocation, bounded loops (at most 17 samples per stage).

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::techobjects {

// T1, T2 and Tt are limited to this many servo cycles (spec 02 §7.6).
inline constexpr std::size_t kDynamicFilterMaxCycles = 16;
// Samples per history: the current one plus 16 older ones (a moving average over 16·T_s uses the current and
// the 16 previous values; a dead time of 16·T_s the value 16 cycles old).
inline constexpr std::size_t kDynamicFilterHistory = kDynamicFilterMaxCycles + 1;

// SetpointFilter.DynamicFilter.Mode (spec 04 §3.22)
enum class DynamicFilterKind : std::int32_t { kOff = 0, kPt1Pt2DeadTime = 1, kMovingAverageDeadTime = 2 };

// PT2 characteristics (seed 004 §6.13.6.1), both time constants > 0: damping D = (T1 + T2)/(2·sqrt(T1·T2)),
// always >= 1 (the filter never oscillates), and angular frequency ω = 1/sqrt(T1·T2).
inline double pt2_damping(double t1, double t2) noexcept {
  return (t1 + t2) / (2.0 * std::sqrt(t1 * t2));
}
inline double pt2_angular_frequency(double t1, double t2) noexcept {
  return 1.0 / std::sqrt(t1 * t2);
}

struct DynamicFilterConfig {
  std::int32_t Mode = 0;      // SetpointFilter.DynamicFilter.Mode, 0 ... 2
  double T1 = 0.0;            // SetpointFilter.DynamicFilter.T1 [s]
  double T2 = 0.0;            // SetpointFilter.DynamicFilter.T2 [s]
  double Tt = 0.0;            // SetpointFilter.DynamicFilter.Tt [s]
  double ServoCycle = 0.001;  // T_s [s], > 0
};

class DynamicFilter {
 public:
  // Rejects (returns false, keeps the previous configuration) a Mode outside 0 ... 2, a negative or
  // non-finite time or a servo cycle <= 0. Times above 16·T_s are limited (no error: spec 02 §7.6). The
  // history is kept, so DIR changes of T1/T2/Tt at run time (spec 04 §3.22) take effect without a step.
  // The histories (1.3 KB) exist only once a Mode 1/2 is configured (issue 14, memory per axis): the first
  // such configure() allocates them (set-up; an axis does it at construction and when the start value of
  // SetpointFilter.DynamicFilter.Mode is written, so that the restart that applies it allocates nothing).
  bool configure(const DynamicFilterConfig& config) noexcept;
  bool has_histories() const noexcept { return channels_ != nullptr; }
  std::size_t history_bytes() const noexcept { return channels_ ? sizeof(*channels_) : 0; }
  // Allocates the histories ahead of a Mode 1/2 that a restart will apply (false: out of memory).
  bool reserve_histories() noexcept;
  DynamicFilter() = default;
  DynamicFilter(const DynamicFilter& other) { *this = other; }
  DynamicFilter& operator=(const DynamicFilter& other);
  DynamicFilter(DynamicFilter&&) noexcept = default;
  DynamicFilter& operator=(DynamicFilter&&) noexcept = default;
  const DynamicFilterConfig& config() const noexcept { return config_; }

  // One servo cycle. With `run` FALSE (follow-up, no position control: the filter acts in position control
  // only, seed 004 §6.13.6) or an inactive filter the output is the input, and the next active cycle starts
  // from a history filled with its input (no step).
  MotionState update(const MotionState& in, bool run) noexcept;

  // Direct homing moves the coordinate system: the position history moves along (the filter is linear with
  // unity gain, so the output moves by the same amount and no transient results).
  void shift(double delta) noexcept;

  bool active() const noexcept { return active_; }
  // After the 16·T_s limit, in seconds.
  double effective_T1() const noexcept { return t1_; }
  double effective_T2() const noexcept { return t2_; }
  double effective_Tt() const noexcept { return tt_; }
  // Lag of the output behind a ramp input in seconds (see above): Mode 1 T1 + T2 + Tt; Mode 2 the exact
  // moving-average lags + Tt. 0 when inactive.
  double effective_delay() const noexcept;

 private:
  // The last kDynamicFilterHistory values of one signal in a ring (stored once: issue 14, memory per axis).
  class History {
   public:
    void fill(double v) noexcept;
    void push(double v) noexcept;
    void shift(double delta) noexcept;
    double at(std::size_t age) const noexcept {  // 0 = newest
      const std::size_t i = head_ + age;
      return values_[i < kDynamicFilterHistory ? i : i - kDynamicFilterHistory];
    }
    // Sum of the ages 0 ... n (n < kDynamicFilterHistory).
    double sum(std::size_t n) const noexcept;

   private:
    std::array<double, kDynamicFilterHistory> values_{};
    std::size_t head_ = 0;
  };
  // One filter stage (PT1 or moving average) of one signal.
  struct Stage {
    History input{};   // moving average: its input values
    double state = 0;  // PT1: y(k − 1)
  };
  struct Channel {  // position, velocity or acceleration
    std::array<Stage, 2> stages{};
    History delay{};  // dead time: the output of the stages
  };
  // Precomputed per stage: PT1 gain, or moving-average N and residual weight r.
  struct StageCoefficients {
    double gain = 1.0;      // PT1: T_s/(T + T_s); 1 = pass
    std::size_t n = 0;      // moving average: full-weight samples besides the current one
    double residual = 0.0;  // moving average: weight of the sample n + 1 cycles old
    double scale = 1.0;     // moving average: 1 / (n + 1 + residual)
  };

  void fill(Channel& c, double v) noexcept;
  double step(Channel& c, double u) const noexcept;

  DynamicFilterConfig config_{};
  bool active_ = false;
  bool started_ = false;
  bool moving_average_ = false;  // the three flags together: no padding (decision M10)
  double t1_ = 0.0;
  double t2_ = 0.0;
  double tt_ = 0.0;
  std::array<StageCoefficients, 2> coefficients_{};
  double delay_cycles_ = 0.0;    // Tt / T_s
  std::size_t delay_whole_ = 0;  // its whole cycles
  double delay_fraction_ = 0.0;  // and the fraction (linear interpolation to the next older sample)
  std::unique_ptr<std::array<Channel, 3>> channels_;  // position, velocity, acceleration; null while off
};

}  // namespace tomc::techobjects
