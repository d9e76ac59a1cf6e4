// Unit tables of spec 04 §3.11 (codes as in positioning_axis_data.hpp unit_code).
#include "tomc/techobjects/motion/axis_units.hpp"

#include <numbers>

#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"

namespace tomc::techobjects {
namespace {

constexpr double kInchMetres = 0.0254;
constexpr double kFootMetres = 0.3048;
constexpr double kMileMetres = 1609.344;
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

UnitScale length(double metres) noexcept {
  return UnitScale{UnitDimension::kLength, metres};
}
UnitScale angle(double degrees) noexcept {
  return UnitScale{UnitDimension::kAngle, degrees};
}

}  // namespace

std::optional<UnitScale> length_unit_scale(std::uint32_t code) noexcept {
  using namespace unit_code;
  switch (code) {
    case kMetre:
      return length(1.0);
    case kMillimetre:
    case kMillimetreHighResolution:
      return length(1.0E-3);
    case kKilometre:
      return length(1.0E3);
    case kMicrometre:
      return length(1.0E-6);
    case kNanometre:
      return length(1.0E-9);
    case unit_code::kInch:
      return length(kInchMetres);
    case unit_code::kFoot:
      return length(kFootMetres);
    case unit_code::kMile:
      return length(kMileMetres);
    case kRadian:
      return angle(kDegreesPerRadian);
    case kDegree:
    case kDegreeHighResolution:
      return angle(1.0);
    default:
      return std::nullopt;
  }
}

// Per second. Code 1524 is printed "m/min" like 1525; spec 04 §14 item 5 reads it as mm/min (decision U2).
std::optional<UnitScale> velocity_unit_scale(std::uint32_t code) noexcept {
  using namespace unit_code;
  switch (code) {
    case kDegreePerSecond:
    case kDegreePerSecondHighResolution:
      return angle(1.0);
    case kDegreePerMinute:
      return angle(1.0 / 60.0);
    case kRadianPerSecond:
      return angle(kDegreesPerRadian);
    case kRadianPerMinute:
      return angle(kDegreesPerRadian / 60.0);
    case kMillimetrePerSecond:
    case kMillimetrePerSecondHighResolution:
      return length(1.0E-3);
    case kMetrePerSecond:
      return length(1.0);
    case kMillimetrePerMinute:
      return length(1.0E-3 / 60.0);
    case kMetrePerMinute:
      return length(1.0 / 60.0);
    case kMillimetrePerHour:
      return length(1.0E-3 / 3600.0);
    case kMetrePerHour:
      return length(1.0 / 3600.0);
    case kKilometrePerMinute:
      return length(1.0E3 / 60.0);
    case kKilometrePerHour:
      return length(1.0E3 / 3600.0);
    case kInchPerSecond:
      return length(kInchMetres);
    case kInchPerMinute:
      return length(kInchMetres / 60.0);
    case kFootPerSecond:
      return length(kFootMetres);
    case kFootPerMinute:
      return length(kFootMetres / 60.0);
    case kMilePerHour:
      return length(kMileMetres / 3600.0);
    default:
      return std::nullopt;
  }
}

namespace {

// The length of a velocity unit, which is also the length of its acceleration and jerk unit (man. §6.1.3:
// m/s, m/min, km/min, m/h, km/h -> m/s²; mm/s, mm/min, mm/h -> mm/s²; in -> in/s²; ft, mi/h -> ft/s²).
// Spec 04 §3.11 prints "mm/s³" as the jerk unit of the metre group; tomc keeps m/s³ (decision U3).
double acceleration_length(std::uint32_t velocity_unit) noexcept {
  using namespace unit_code;
  switch (velocity_unit) {
    case kMillimetrePerSecond:
    case kMillimetrePerSecondHighResolution:
    case kMillimetrePerMinute:
    case kMillimetrePerHour:
      return 1.0E-3;
    case kMetrePerSecond:
    case kMetrePerMinute:
    case kMetrePerHour:
    case kKilometrePerMinute:
    case kKilometrePerHour:
      return 1.0;
    case kInchPerSecond:
    case kInchPerMinute:
      return kInchMetres;
    case kFootPerSecond:
    case kFootPerMinute:
    case kMilePerHour:
      return kFootMetres;
    case kRadianPerSecond:
    case kRadianPerMinute:
      return kDegreesPerRadian;
    default:
      return 1.0;  // degrees
  }
}

// Leadscrew pitch unit per position unit (spec 04 §3.11 table "Lead-screw unit by position unit").
double leadscrew_unit_metres(std::uint32_t length_unit) noexcept {
  using namespace unit_code;
  switch (length_unit) {
    case kKilometre:
      return 1.0;  // m/rev
    case kMicrometre:
      return 1.0E-6;
    case kNanometre:
      return 1.0E-9;
    case unit_code::kInch:
    case unit_code::kFoot:
    case unit_code::kMile:
      return kInchMetres;
    default:
      return 1.0E-3;  // mm/rev for m and mm
  }
}

}  // namespace

AxisUnitFactors axis_unit_factors(std::uint32_t length_unit, std::uint32_t velocity_unit) noexcept {
  AxisUnitFactors f;
  const auto l = length_unit_scale(length_unit);
  const auto v = velocity_unit_scale(velocity_unit);
  if (!l || !v || l->dimension != v->dimension) return f;
  f.velocity = l->base / v->base;
  f.acceleration = l->base / acceleration_length(velocity_unit);
  f.leadscrew = l->dimension == UnitDimension::kLength ? leadscrew_unit_metres(length_unit) / l->base : 1.0;
  f.units_per_revolution = 360.0 / l->base;  // ° -> 360, rad -> 2π
  f.valid = true;
  return f;
}

}  // namespace tomc::techobjects
