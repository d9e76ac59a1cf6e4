#include "tomc/techobjects/position/dynamic_filter.hpp"

#include <algorithm>
#include <cmath>
#include <new>

namespace tomc::techobjects {

namespace {

constexpr double kMaxCycles = static_cast<double>(kDynamicFilterMaxCycles);
// T/T_s within this of a whole number counts as that number (0.012 / 0.004 is 2.9999999999999996).
constexpr double kWholeCycleTolerance = 1e-9;

bool valid_time(double t) noexcept {
  return std::isfinite(t) && t >= 0.0;
}

}  // namespace

// ---- History ----

void DynamicFilter::History::fill(double v) noexcept {
  values_.fill(v);
  head_ = 0;
}

void DynamicFilter::History::push(double v) noexcept {
  head_ = head_ == 0 ? kDynamicFilterHistory - 1 : head_ - 1;
  values_[head_] = v;
}

void DynamicFilter::History::shift(double delta) noexcept {
  for (double& v : values_)
    v += delta;
}

double DynamicFilter::History::sum(std::size_t n) const noexcept {
  // Ages 0 ... n, newest first (the order of the sum is part of the result): up to the end of the ring,
  // then on from its start.
  const std::size_t first_run = std::min(n + 1, kDynamicFilterHistory - head_);
  double s = 0.0;
  for (std::size_t i = 0; i < first_run; ++i)
    s += values_[head_ + i];
  for (std::size_t i = 0; i < n + 1 - first_run; ++i)
    s += values_[i];
  return s;
}

// ---- DynamicFilter ----

DynamicFilter& DynamicFilter::operator=(const DynamicFilter& other) {
  if (this == &other) return *this;
  config_ = other.config_;
  active_ = other.active_;
  started_ = other.started_;
  t1_ = other.t1_;
  t2_ = other.t2_;
  tt_ = other.tt_;
  coefficients_ = other.coefficients_;
  delay_cycles_ = other.delay_cycles_;
  delay_whole_ = other.delay_whole_;
  delay_fraction_ = other.delay_fraction_;
  moving_average_ = other.moving_average_;
  channels_ = other.channels_ ? std::make_unique<std::array<Channel, 3>>(*other.channels_) : nullptr;
  return *this;
}

bool DynamicFilter::reserve_histories() noexcept {
  if (!channels_) channels_.reset(new (std::nothrow) std::array<Channel, 3>{});
  return channels_ != nullptr;
}

bool DynamicFilter::configure(const DynamicFilterConfig& config) noexcept {
  if (config.Mode < 0 || config.Mode > 2) return false;
  if (!std::isfinite(config.ServoCycle) || config.ServoCycle <= 0.0) return false;
  if (!valid_time(config.T1) || !valid_time(config.T2) || !valid_time(config.Tt)) return false;
  if (config.Mode != 0 && !reserve_histories()) return false;
  config_ = config;
  const double ts = config.ServoCycle;
  const double limit = kMaxCycles * ts;  // spec 02 §7.6: 16 × servo cycle, no alarm
  t1_ = std::min(config.T1, limit);
  t2_ = std::min(config.T2, limit);
  tt_ = std::min(config.Tt, limit);
  const bool was_active = active_;
  active_ = config.Mode != 0 && (t1_ > 0.0 || t2_ > 0.0 || tt_ > 0.0);
  if (active_ && !was_active) started_ = false;  // the history was not kept while inactive
  const bool moving_average =
      config.Mode == static_cast<std::int32_t>(DynamicFilterKind::kMovingAverageDeadTime);
  const double times[2] = {t1_, t2_};
  for (std::size_t i = 0; i < 2; ++i) {
    StageCoefficients& c = coefficients_[i];
    c = StageCoefficients{};
    if (moving_average) {
      const double cycles = std::min(times[i] / ts, kMaxCycles);
      const double whole = std::floor(cycles + kWholeCycleTolerance);
      c.n = static_cast<std::size_t>(whole);
      c.residual = c.n >= kDynamicFilterMaxCycles ? 0.0 : std::max(0.0, cycles - whole);
      if (c.residual < kWholeCycleTolerance) c.residual = 0.0;
      c.scale = 1.0 / (static_cast<double>(c.n) + 1.0 + c.residual);
    } else {
      c.gain = ts / (times[i] + ts);
    }
  }
  delay_cycles_ = std::min(tt_ / ts, kMaxCycles);
  delay_whole_ = static_cast<std::size_t>(std::floor(delay_cycles_));
  delay_fraction_ =
      delay_whole_ >= kDynamicFilterMaxCycles ? 0.0 : delay_cycles_ - static_cast<double>(delay_whole_);
  moving_average_ = moving_average;
  return true;
}

double DynamicFilter::effective_delay() const noexcept {
  if (!active_) return 0.0;
  if (config_.Mode == static_cast<std::int32_t>(DynamicFilterKind::kPt1Pt2DeadTime)) return t1_ + t2_ + tt_;
  double cycles = 0.0;
  for (const StageCoefficients& c : coefficients_) {
    const double n = static_cast<double>(c.n);
    cycles += (0.5 * n * (n + 1.0) + c.residual * (n + 1.0)) / (n + 1.0 + c.residual);
  }
  return cycles * config_.ServoCycle + tt_;
}

void DynamicFilter::fill(Channel& c, double v) noexcept {
  for (Stage& s : c.stages) {
    s.input.fill(v);
    s.state = v;
  }
  c.delay.fill(v);
}

// One sample through the stages of one channel. The moving-average histories and the PT1 states are updated;
// `const` on the coefficients only.
double DynamicFilter::step(Channel& c, double u) const noexcept {
  double x = u;
  for (std::size_t i = 0; i < 2; ++i) {
    Stage& s = c.stages[i];
    const StageCoefficients& k = coefficients_[i];
    if (moving_average_) {
      s.input.push(x);
      if (k.n == 0 && k.residual == 0.0) continue;  // T = 0: the stage drops out
      double sum = s.input.sum(k.n);
      if (k.residual > 0.0) sum += k.residual * s.input.at(k.n + 1);
      x = sum * k.scale;
    } else {
      s.state += k.gain * (x - s.state);
      x = s.state;
    }
  }
  c.delay.push(x);
  if (delay_fraction_ == 0.0) return c.delay.at(delay_whole_);
  return (1.0 - delay_fraction_) * c.delay.at(delay_whole_) + delay_fraction_ * c.delay.at(delay_whole_ + 1);
}

MotionState DynamicFilter::update(const MotionState& in, bool run) noexcept {
  if (!run || !active_ || !channels_) {
    started_ = false;
    return in;
  }
  if (!started_) {
    fill((*channels_)[0], in.position);
    fill((*channels_)[1], in.velocity);
    fill((*channels_)[2], in.acceleration);
    started_ = true;
  }
  return MotionState{step((*channels_)[0], in.position), step((*channels_)[1], in.velocity),
                     step((*channels_)[2], in.acceleration)};
}

void DynamicFilter::shift(double delta) noexcept {
  if (!started_ || delta == 0.0 || !channels_) return;
  Channel& c = (*channels_)[0];
  for (Stage& s : c.stages) {
    s.input.shift(delta);
    s.state += delta;
  }
  c.delay.shift(delta);
}

}  // namespace tomc::techobjects
