// The ring buffer of a leader's delayed setpoints (spec 07 §1.5; decision C26).
#include "tomc/techobjects/synchronous/delayed_leading_value.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tomc::techobjects {

DelayedLeadingValue::DelayedLeadingValue(double delay_s, double interpolator_cycle_s) {
  if (!(interpolator_cycle_s > 0.0) || !std::isfinite(interpolator_cycle_s))
    throw std::invalid_argument("the interpolator cycle time must be positive");
  if (!(delay_s >= 0.0) || !std::isfinite(delay_s))
    throw std::invalid_argument(std::to_string(delay_s) + " s is not a delay time (0 or more)");
  const double cycles = delay_s / interpolator_cycle_s;
  if (cycles > static_cast<double>(kMaxDelayCycles) * (1.0 + 1e-9)) {
    throw std::invalid_argument(std::to_string(delay_s) + " s is more than " +
                                std::to_string(kMaxDelayCycles) + " interpolator cycles of " +
                                std::to_string(interpolator_cycle_s) +
                                " s, the length of the delayed leading value's history (decision C26)");
  }
  // A delay a rounding away from a whole number of cycles is that number (no interpolation).
  const double whole = std::round(cycles);
  const bool exact = std::fabs(cycles - whole) <= 1e-9 * std::max(1.0, cycles);
  cycles_ = static_cast<std::size_t>(exact ? whole : std::floor(cycles));
  fraction_ = exact ? 0.0 : cycles - std::floor(cycles);
  history_.resize(cycles_ + 2);
}

void DelayedLeadingValue::push(const MotionState& setpoint) noexcept {
  const std::size_t size = history_.size();
  if (!filled_) {
    for (MotionState& s : history_)
      s = setpoint;
    filled_ = true;
  }
  newest_ = (newest_ + 1) % size;
  history_[newest_] = setpoint;
  const MotionState& a = history_[(newest_ + size - cycles_) % size];
  const MotionState& b = history_[(newest_ + size - cycles_ - 1) % size];
  const double f = fraction_;
  value_ = MotionState{a.position + f * (b.position - a.position), a.velocity + f * (b.velocity - a.velocity),
                       a.acceleration + f * (b.acceleration - a.acceleration)};
}

}  // namespace tomc::techobjects
