#pragma once
// Units of position-based technology objects (spec 04 §3.11, spec 01 §2.3): the data block holds positions in
// Units.LengthUnit, velocities in Units.VelocityUnit and accelerations/jerks in the unit derived from the
// velocity unit (man. §6.1.3: m/min -> m/s², mm/s -> mm/s²). Internally a TO computes in position units per
// second; these factors convert at the data-block boundary. Pure functions, noexcept, no allocation.

#include <cstdint>
#include <optional>

namespace tomc::techobjects {

// How a unit measures: a length (base metre) or an angle (base degree).
enum class UnitDimension : std::uint8_t { kLength, kAngle };

struct UnitScale {
  UnitDimension dimension = UnitDimension::kLength;
  double base = 1.0;  // metres (length) or degrees (angle) per unit; per second for velocity units
};

// nullopt for a code the tables of spec 04 §3.11 do not list.
std::optional<UnitScale> length_unit_scale(std::uint32_t length_unit) noexcept;
std::optional<UnitScale> velocity_unit_scale(std::uint32_t velocity_unit) noexcept;

// The factors of one TO, resolved once at configuration (valid() = the two units measure the same thing).
struct AxisUnitFactors {
  double velocity = 1.0;      // data-block velocity per (position unit / s)
  double acceleration = 1.0;  // data-block acceleration (and jerk) per (position unit / s²)
  // Leadscrew pitch unit (spec 04 §3.11: mm/rev for m and mm, m/rev for km, in/rev for in/ft/mi, ...) in
  // position units: the actual-value chain takes the pitch in position units per revolution.
  double leadscrew = 1.0;
  double units_per_revolution = 360.0;  // a rotary axis: 360 (°) or 2π (rad)
  bool valid = false;
};
AxisUnitFactors axis_unit_factors(std::uint32_t length_unit, std::uint32_t velocity_unit) noexcept;

}  // namespace tomc::techobjects
