#pragma once
// An incremental encoder on a counter input, as the simulated backend sees it: A/B quadrature counted ×4
// (every edge of A or B is one count, spec 05b B.5: 500 lines = 2000 counts/rev), a counter register of
// `width_bits` that wraps, and a zero mark once per revolution with a one-shot latch (H3 SetIP, TM PosInput
// "latch on N"). The count is what a decoder shows: whole counts only (quantisation).

#include <cstdint>

#include "tomc/drives/io/hardware_io.hpp"

namespace tomc::drives::io {

struct QuadratureEncoderParameters {
  std::uint32_t lines_per_revolution = 2500;  // A/B periods per revolution; counts = 4 × lines
  std::uint8_t width_bits = 32;               // counter register width (16 or 32 on real cards)
  std::uint32_t count_at_power_on = 0;
  double zero_mark_offset_revolutions = 0.25;  // the zero mark's shaft angle
};

class QuadratureCounter {
 public:
  QuadratureCounter() = default;
  QuadratureCounter(const QuadratureEncoderParameters& parameters, double shaft_revolutions) noexcept;

  // The shaft moved to `shaft_revolutions` (from where the last update left it).
  void update(double shaft_revolutions) noexcept;
  void arm_zero_mark() noexcept;
  // A broken or unplugged encoder: while disconnected the count stands whatever the shaft does (counts are
  // lost) and the card's signal supervision reports it (CounterSample::signal_lost).
  void set_connected(bool connected) noexcept;
  CounterSample sample() const noexcept { return sample_; }
  double counts_per_revolution() const noexcept { return 4.0 * parameters_.lines_per_revolution; }

 private:
  std::uint32_t wrap(double counts) const noexcept;

  QuadratureEncoderParameters parameters_{};
  double origin_revolutions_ = 0.0;  // shaft position where the counter started at count_at_power_on
  double shaft_ = 0.0;
  bool armed_ = false;
  bool connected_ = true;
  CounterSample sample_{};
};

// The controller side of a counter of `width_bits`: extends the wrapping raw count to a continuous 64-bit
// count (overflow-safe as long as the shaft moves less than half the counter range per cycle) and translates
// a latched raw count into the same continuous scale.
class CounterExtension {
 public:
  explicit CounterExtension(std::uint8_t width_bits = 32) noexcept;
  // The first sample sets the origin: continuous = raw (sign-extended).
  std::int64_t update(std::uint32_t raw) noexcept;
  std::int64_t extend(std::uint32_t raw_nearby) const noexcept;  // a raw value within half a range of now
  std::int64_t value() const noexcept { return value_; }

 private:
  std::int64_t difference(std::uint32_t raw, std::uint32_t from) const noexcept;

  std::uint8_t width_ = 32;
  std::uint64_t mask_ = 0xFFFFFFFFu;
  bool started_ = false;
  std::uint32_t last_raw_ = 0;
  std::int64_t value_ = 0;
};

}  // namespace tomc::drives::io
