#include "tomc/techobjects/position/backlash.hpp"

#include <algorithm>
#include <cmath>

#include "tomc/techobjects/position/actual_value_chain.hpp"

namespace tomc::techobjects {

namespace {

constexpr double kDirectionEpsilon = 1e-9;  // position units / s: below this the setpoint has no direction
// The gap counts as crossed when the motor is this fraction of Size from the contact: the position loop
// approaches the contact exponentially when the setpoint does not move on (decision P18).
constexpr double kCrossedFraction = 1e-3;

bool valid_value(double v) noexcept {
  return std::isfinite(v) && v >= 0.0;
}

}  // namespace

bool BacklashCompensation::configure(const BacklashConfig& config) noexcept {
  if (!valid_value(config.Size) || !valid_value(config.Velocity)) return false;
  if (!std::isfinite(config.ServoCycle) || config.ServoCycle <= 0.0) return false;
  const bool model_changed = config.Enable != config_.Enable || config.Size != config_.Size;
  config_ = config;
  if (model_changed) reset();  // spec 04 §8 rule 10: the axis must be homed again
  return true;
}

void BacklashCompensation::reset() noexcept {
  known_ = false;
  lowest_ = last_motor_;
  highest_ = last_motor_;
  gap_ = 0.0;
  applied_ = 0.0;
  direction_ = 0;
  passing_ = false;
  held_ = 0.0;
}

void BacklashCompensation::become_known(double gap) noexcept {
  known_ = true;
  gap_ = gap;
  applied_ = gap;
  direction_ = gap > 0.0 ? 1 : -1;
  passing_ = false;
  held_ = 0.0;
}

void BacklashCompensation::assume_contact(int direction) noexcept {
  if (direction == 0) return;
  become_known(direction > 0 ? config_.Size : 0.0);
}

int BacklashCompensation::contact() const noexcept {
  if (!known_) return 0;
  if (gap_ >= config_.Size) return 1;
  if (gap_ <= 0.0) return -1;
  return 0;
}

double BacklashCompensation::update(const BacklashInput& in) noexcept {
  if (!in.motor_valid || !std::isfinite(in.motor_position)) {
    have_reference_ = false;  // e.g. a restarted chain counts from a new origin
    return 0.0;
  }
  if (!have_reference_) {
    have_reference_ = true;
    last_motor_ = in.motor_position;
    if (!known_) lowest_ = highest_ = in.motor_position;
    return 0.0;
  }
  const double motion = in.motor_position - last_motor_;
  last_motor_ = in.motor_position;
  if (!active()) return 0.0;
  const double size = config_.Size;

  if (!known_) {
    // First motion of a non-homed axis (spec 01 §5.9): no compensation until the gap has been crossed.
    lowest_ = std::min(lowest_, in.motor_position);
    highest_ = std::max(highest_, in.motor_position);
    if (in.motor_position - lowest_ >= size) {
      become_known(size);
    } else if (highest_ - in.motor_position >= size) {
      become_known(0.0);
    }
    return 0.0;
  }

  gap_ = std::clamp(gap_ + motion, 0.0, size);
  if (!in.setpoint_operation) {
    // Follow-up: the actual value follows the load, coupled again once the gap is crossed.
    const double correction = -(gap_ - applied_);
    applied_ = gap_;
    direction_ = 0;
    passing_ = false;
    held_ = 0.0;
    return correction;
  }

  const int d = in.setpoint_velocity > kDirectionEpsilon    ? 1
                : in.setpoint_velocity < -kDirectionEpsilon ? -1
                                                            : 0;
  if (d != 0 && d != direction_) {
    direction_ = d;
    const double contact = d > 0 ? size : 0.0;
    if (applied_ != contact && !passing_) {
      passing_ = true;  // the start of a reversing motion (spec 01 §5.9 ①)
      held_ = 0.0;
    }
  }
  if (!passing_) return 0.0;
  const double contact = direction_ > 0 ? size : 0.0;
  if (applied_ == contact && std::fabs(gap_ - contact) <= kCrossedFraction * size) {
    passing_ = false;  // spec 01 §5.9 ②: crossed; from now on ActualPosition follows again
    held_ = 0.0;
    return 0.0;
  }
  const double step = config_.Velocity > 0.0 ? config_.Velocity * config_.ServoCycle : size;
  double next = applied_ < contact ? std::min(applied_ + step, contact) : std::max(applied_ - step, contact);
  if (std::fabs(contact - next) <= 1e-9 * size) next = contact;  // no rounding crumb as an extra cycle
  const double correction = -(next - applied_);
  applied_ = next;
  held_ += motion + correction;  // the actual value changes by both; ActualPosition does not (X2)
  return correction;
}

double BacklashCompensation::compensate(ActualValueChain& chain, bool valid, bool setpoint_operation,
                                        double setpoint_velocity) noexcept {
  BacklashInput in;
  in.motor_position = static_cast<double>(chain.encoder_counts()) * chain.units_per_count();
  in.motor_valid = valid;
  in.setpoint_operation = setpoint_operation;
  in.setpoint_velocity = setpoint_velocity;
  const double correction = update(in);
  if (correction != 0.0) chain.shift_offset(correction);
  return correction;
}

}  // namespace tomc::techobjects
