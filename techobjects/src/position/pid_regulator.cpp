// PID position control (pid_regulator.hpp).
#include "tomc/techobjects/position/pid_regulator.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::techobjects {

namespace {
bool non_negative_finite(double v) noexcept {
  return std::isfinite(v) && v >= 0.0;
}
}  // namespace

bool PidRegulator::valid(const PidGains& g) noexcept {
  return non_negative_finite(g.Kv) && non_negative_finite(g.IntegralTime) &&
         non_negative_finite(g.DerivativeTime) && non_negative_finite(g.IntegralLimit) &&
         non_negative_finite(g.DeadBand) && non_negative_finite(g.OutputLimit) && g.DerivativeCycles >= 1 &&
         g.DerivativeCycles <= kMaxDerivativeCycles;
}

bool PidRegulator::configure(const PidGains& gains, double servo_cycle_s) noexcept {
  if (!valid(gains) || !(std::isfinite(servo_cycle_s) && servo_cycle_s > 0.0)) return false;
  active_ = gains;
  ts_ = servo_cycle_s;
  has_pending_ = apply_pending_ = false;
  classify();
  reset();
  return true;
}

bool PidRegulator::load(const PidGains& gains) noexcept {
  if (!valid(gains)) return false;
  pending_ = gains;
  has_pending_ = true;
  apply_pending_ = false;
  return true;
}

void PidRegulator::reset() noexcept {
  integral_ = 0.0;
  derivative_ = 0.0;
  e_at_last_sample_ = 0.0;
  cycles_since_sample_ = 0;
  started_ = false;
}

PidTerms PidRegulator::update_pid(double control_difference) noexcept {
  if (apply_pending_) {
    // New gains at a cycle boundary; I and the D history stay (a bumpless change of the gains' effect is the
    // user's choice of when to apply). A new DerivativeCycles starts a fresh D sample.
    if (pending_.DerivativeCycles != active_.DerivativeCycles) cycles_since_sample_ = 0;
    active_ = pending_;
    has_pending_ = apply_pending_ = false;
    if (active_.IntegralTime == 0.0) integral_ = 0.0;
    classify();
  }
  const PidGains& g = active_;
  const double e = std::fabs(control_difference) <= g.DeadBand ? 0.0 : control_difference;
  if (!started_) {
    started_ = true;
    e_at_last_sample_ = e;  // no derivative kick from the first sample
  }

  PidTerms t;
  t.p = g.Kv * e;

  // D: every n cycles from the difference over those n cycles, held in between (H3: a slower D sample).
  if (g.DerivativeTime > 0.0) {
    if (++cycles_since_sample_ >= g.DerivativeCycles) {
      const double n = static_cast<double>(g.DerivativeCycles);
      derivative_ = g.Kv * g.DerivativeTime * (e - e_at_last_sample_) / (n * ts_);
      e_at_last_sample_ = e;
      cycles_since_sample_ = 0;
    }
  } else {
    derivative_ = 0.0;
    e_at_last_sample_ = e;
  }
  t.d = derivative_;

  // I with its clamp, and conditional integration against the output saturation.
  if (g.IntegralTime > 0.0) {
    double candidate = integral_ + g.Kv * (ts_ / g.IntegralTime) * e;
    if (g.IntegralLimit > 0.0) candidate = std::clamp(candidate, -g.IntegralLimit, g.IntegralLimit);
    if (g.OutputLimit > 0.0) {
      const double total = t.p + candidate + t.d;
      const bool winding_up = (total > g.OutputLimit && candidate > integral_) ||
                              (total < -g.OutputLimit && candidate < integral_);
      if (winding_up) candidate = integral_;
    }
    integral_ = candidate;
  }
  t.i = integral_;

  const double sum = t.p + t.i + t.d;
  t.output = g.OutputLimit > 0.0 ? std::clamp(sum, -g.OutputLimit, g.OutputLimit) : sum;
  t.saturated = t.output != sum;
  return t;
}

}  // namespace tomc::techobjects
