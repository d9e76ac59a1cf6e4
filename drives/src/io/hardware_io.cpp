// DAC code conversions of the hardware I/O layer (hardware_io.hpp).
#include "tomc/drives/io/hardware_io.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::drives::io {

namespace {
double half_range(const DacFormat& f) noexcept {
  return std::ldexp(1.0, std::clamp<int>(f.bits, 2, 32) - 1);
}
}  // namespace

double dac_step_volts(const DacFormat& format) noexcept {
  return format.full_scale_volts / half_range(format);
}

std::int32_t dac_code(double volts, const DacFormat& format) noexcept {
  const double half = half_range(format);
  if (std::isnan(volts)) return 0;
  const double code = std::nearbyint(volts / format.full_scale_volts * half);
  return static_cast<std::int32_t>(std::clamp(code, -half, half - 1.0));
}

double dac_volts(std::int32_t code, const DacFormat& format) noexcept {
  return static_cast<double>(code) * dac_step_volts(format);
}

const char* to_string(IoStatus status) noexcept {
  switch (status) {
    case IoStatus::kOk:
      return "ok";
    case IoStatus::kReadFailed:
      return "read failed";
    case IoStatus::kWriteFailed:
      return "write failed";
    case IoStatus::kDeviceLost:
      return "device lost";
  }
  return "?";
}

}  // namespace tomc::drives::io
