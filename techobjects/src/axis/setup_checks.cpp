// Start-value checks shared by every TO (setup_checks.hpp).
#include "tomc/techobjects/axis/setup_checks.hpp"

#include "tomc/techobjects/datablocks/to_types.hpp"

namespace tomc::techobjects {

AxisUnitFactors checked_unit_factors(std::string_view to_name, std::uint32_t length_unit,
                                     std::uint32_t velocity_unit, std::int32_t motion_type,
                                     std::string_view what) {
  const AxisUnitFactors units = axis_unit_factors(length_unit, velocity_unit);
  if (!units.valid) {
    fail_start_value(to_name, "Units.VelocityUnit", "does not measure the same quantity as Units.LengthUnit");
  }
  const bool rotary = motion_type == static_cast<std::int32_t>(PropertiesMotionType::kRotary);
  if (rotary != (length_unit_scale(length_unit)->dimension == UnitDimension::kAngle)) {
    fail_start_value(
        to_name, "Units.LengthUnit",
        std::string(rotary ? "a rotary " : "a linear ") + std::string(what) +
            (rotary ? " needs an angle unit (°, rad)" : " needs a length unit (m, mm, in, ...)"));
  }
  return units;
}

}  // namespace tomc::techobjects
