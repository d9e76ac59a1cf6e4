// The simulated quadrature counter and the controller's counter extension (quadrature_counter.hpp).
#include "tomc/drives/io/quadrature_counter.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::drives::io {

namespace {
std::uint64_t mask_of(std::uint8_t width_bits) noexcept {
  const int w = std::clamp<int>(width_bits, 2, 32);
  return (std::uint64_t{1} << w) - 1u;
}
}  // namespace

QuadratureCounter::QuadratureCounter(const QuadratureEncoderParameters& parameters,
                                     double shaft_revolutions) noexcept
    : parameters_(parameters), origin_revolutions_(shaft_revolutions), shaft_(shaft_revolutions) {
  sample_.count = wrap(0.0);
}

std::uint32_t QuadratureCounter::wrap(double counts) const noexcept {
  // Whole counts (a decoder counts edges), two's complement wrap at the register width.
  const auto whole = static_cast<std::int64_t>(std::floor(counts)) +
                     static_cast<std::int64_t>(parameters_.count_at_power_on);
  return static_cast<std::uint32_t>(static_cast<std::uint64_t>(whole) & mask_of(parameters_.width_bits));
}

void QuadratureCounter::set_connected(bool connected) noexcept {
  connected_ = connected;
  sample_.signal_lost = !connected;
}

void QuadratureCounter::arm_zero_mark() noexcept {
  armed_ = true;
  sample_.latched = false;
}

void QuadratureCounter::update(double shaft_revolutions) noexcept {
  const double previous = shaft_;
  shaft_ = shaft_revolutions;
  if (!connected_) {  // no edges reach the decoder: the count stays, the zero mark is not seen
    origin_revolutions_ += shaft_ - previous;
    return;
  }
  if (armed_) {
    // A zero mark lies between the two positions: the mark k sits at offset + k revolutions.
    const double offset = parameters_.zero_mark_offset_revolutions;
    const double k_prev = std::floor(previous - offset);
    const double k_now = std::floor(shaft_ - offset);
    if (k_prev != k_now) {
      const double mark = offset + std::max(k_prev, k_now);
      sample_.latched_count = wrap((mark - origin_revolutions_) * counts_per_revolution());
      sample_.latched = true;
      armed_ = false;
    }
  }
  sample_.count = wrap((shaft_ - origin_revolutions_) * counts_per_revolution());
}

CounterExtension::CounterExtension(std::uint8_t width_bits) noexcept
    : width_(static_cast<std::uint8_t>(std::clamp<int>(width_bits, 2, 32))), mask_(mask_of(width_bits)) {}

std::int64_t CounterExtension::difference(std::uint32_t raw, std::uint32_t from) const noexcept {
  // Modulo-2^width difference, sign-extended: the shorter way round the counter range.
  const std::uint64_t d = (static_cast<std::uint64_t>(raw) - from) & mask_;
  const std::uint64_t half = (mask_ >> 1) + 1u;
  return d >= half ? static_cast<std::int64_t>(d) - static_cast<std::int64_t>(mask_ + 1u)
                   : static_cast<std::int64_t>(d);
}

std::int64_t CounterExtension::update(std::uint32_t raw) noexcept {
  if (!started_) {
    started_ = true;
    last_raw_ = raw;
    value_ = difference(raw, 0);
    return value_;
  }
  value_ += difference(raw, last_raw_);
  last_raw_ = raw;
  return value_;
}

std::int64_t CounterExtension::extend(std::uint32_t raw_nearby) const noexcept {
  return value_ + difference(raw_nearby, last_raw_);
}

}  // namespace tomc::drives::io
