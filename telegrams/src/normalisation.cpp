// Normalised values, spec 06 §1.2, §7, §8, §9.
#include "tomc/telegrams/normalisation.hpp"

#include <cmath>
#include <cstdint>

namespace tomc::telegrams {
namespace {

// Round half away from zero, then saturate to [lo, hi] (|lo|, |hi| <= 2^31); NaN -> 0. Clamping first keeps
// the integer conversion defined; x - trunc(x) is exact here, so this equals std::round without a libm call
// in the servo path.
double round_saturate(double x, double lo, double hi) noexcept {
  if (std::isnan(x)) return 0.0;
  if (x <= lo) return lo;
  if (x >= hi) return hi;
  const auto t = static_cast<std::int64_t>(x);  // truncation toward zero
  const double fraction = x - static_cast<double>(t);
  std::int64_t r = t;
  if (fraction >= 0.5) ++r;
  if (fraction <= -0.5) --r;
  const auto rounded = static_cast<double>(r);
  return rounded < lo ? lo : (rounded > hi ? hi : rounded);
}

bool usable_reference(double reference) noexcept {
  return std::isfinite(reference) && reference > 0.0;
}

}  // namespace

std::int16_t speed_to_n2(double speed, double reference_speed) noexcept {
  if (!usable_reference(reference_speed) || !std::isfinite(speed)) return 0;  // non-finite -> 0
  return static_cast<std::int16_t>(
      round_saturate(speed / reference_speed * kN2Hundred, INT16_MIN, INT16_MAX));
}

std::int32_t speed_to_n4(double speed, double reference_speed) noexcept {
  if (!usable_reference(reference_speed) || !std::isfinite(speed)) return 0;  // non-finite -> 0
  return static_cast<std::int32_t>(
      round_saturate(speed / reference_speed * kN4Hundred, INT32_MIN, INT32_MAX));
}

double n2_to_speed(std::int16_t raw, double reference_speed) noexcept {
  return static_cast<double>(raw) / kN2Hundred * reference_speed;
}

double n4_to_speed(std::int32_t raw, double reference_speed) noexcept {
  return static_cast<double>(raw) / kN4Hundred * reference_speed;
}

std::int16_t torque_to_n2(double torque, double reference_torque) noexcept {
  return speed_to_n2(torque, reference_torque);  // same N2 rule, spec 06 §8
}

double n2_to_torque(std::int16_t raw, double reference_torque) noexcept {
  return n2_to_speed(raw, reference_torque);
}

std::uint16_t momred_from_reduction_percent(double reduction_percent) noexcept {
  return static_cast<std::uint16_t>(round_saturate(reduction_percent / 100.0 * kN2Hundred, 0.0, kN2Hundred));
}

std::uint16_t momred_from_torque_limit(double torque_limit, double reference_torque) noexcept {
  if (!usable_reference(reference_torque) || std::isnan(torque_limit)) return 0;
  const double limit = std::fmin(std::fmax(torque_limit, 0.0), reference_torque);
  return static_cast<std::uint16_t>(
      round_saturate(kN2Hundred * (1.0 - limit / reference_torque), 0.0, kN2Hundred));
}

double torque_limit_from_momred(std::uint16_t momred, double reference_torque) noexcept {
  const double reduction = std::fmin(static_cast<double>(momred), kN2Hundred) / kN2Hundred;
  return reference_torque * (1.0 - reduction);
}

std::int32_t kpc_from_kv(double kv_per_second) noexcept {
  if (!std::isfinite(kv_per_second)) return 0;  // header: non-finite value -> 0 (KPC = 0 deactivates DSC)
  return static_cast<std::int32_t>(round_saturate(kv_per_second * 1000.0, INT32_MIN, INT32_MAX));
}

double kv_from_kpc(std::int32_t kpc) noexcept {
  return static_cast<double>(kpc) / 1000.0;
}

std::int32_t xerr_from_counts(double counts) noexcept {
  if (!std::isfinite(counts)) return 0;  // header: non-finite value -> 0
  return static_cast<std::int32_t>(round_saturate(counts, INT32_MIN, INT32_MAX));
}

}  // namespace tomc::telegrams
