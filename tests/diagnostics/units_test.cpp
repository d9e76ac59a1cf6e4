// Units of the page (units.hpp, issue 21): the quantity of each data-block variable by its manual name, the
// symbols of the Units.* codes (spec 04 §3.11) and the units of a configured TO (man. §6.1.3: accelerations
// in the velocity unit's length per s²).
#include <gtest/gtest.h>

#include "tomc/diagnostics/units.hpp"
#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/speed_axis_data.hpp"

namespace {

using namespace tomc;
using diagnostics::Quantity;
namespace to = tomc::techobjects;

Quantity quantity(std::span<const to::VariableInfo> table, std::string_view path) {
  const to::VariableInfo* v = to::find_variable(table, path);
  EXPECT_NE(v, nullptr) << path;
  return v == nullptr ? Quantity::kNone : diagnostics::quantity_of(*v);
}

// spec 04 §3 (P/Y data block): each row a variable of the manual and what it measures.
TEST(Units, QuantityOfPositioningAxisVariables) {
  const auto table = to::positioning_axis_variables();
  const struct {
    const char* path;
    Quantity quantity;
  } cases[] = {
      {"ActualPosition", Quantity::kPosition},
      {"Position", Quantity::kPosition},
      {"StatusPositioning.FollowingError", Quantity::kPosition},
      {"StatusPositioning.TargetPosition", Quantity::kPosition},
      {"StatusPositioning.Distance", Quantity::kPosition},
      {"PositionLimits_SW.MaxPosition", Quantity::kPosition},
      {"Modulo.Length", Quantity::kPosition},
      {"FollowingError.MaxValue", Quantity::kPosition},
      {"PositioningMonitoring.Window", Quantity::kPosition},
      {"Sensor[1].Backlash.Size", Quantity::kPosition},
      {"ActualVelocity", Quantity::kVelocity},
      {"DynamicLimits.MaxVelocity", Quantity::kVelocity},
      {"FollowingError.MinVelocity", Quantity::kVelocity},
      {"StandstillSignal.VelocityThreshold", Quantity::kVelocity},
      {"DynamicDefaults.Acceleration", Quantity::kAcceleration},
      {"DynamicDefaults.EmergencyDeceleration", Quantity::kAcceleration},
      {"ActualAcceleration", Quantity::kAcceleration},
      {"DynamicLimits.MaxJerk", Quantity::kJerk},
      {"ActualSpeed", Quantity::kMotorSpeed},
      {"Actor.DriveParameter.ReferenceSpeed", Quantity::kMotorSpeed},
      {"Actor.DriveParameter.ReferenceTorque", Quantity::kTorque},
      {"StatusTorqueData.ActualForce", Quantity::kForce},
      {"PositioningMonitoring.ToleranceTime", Quantity::kTime},
      {"Extrapolation.VelocityFilter.T1", Quantity::kTime},
      {"DynamicAxisModel.VelocityTimeConstant", Quantity::kTime},
      {"Override.Velocity", Quantity::kPercent},
      {"StatusWord", Quantity::kNone},  // DWORD
      {"Units.LengthUnit", Quantity::kNone},
      {"PositionControl.Kv", Quantity::kNone},
  };
  for (const auto& c : cases)
    EXPECT_EQ(quantity(table, c.path), c.quantity) << c.path;
}

// spec 04 §3.11 tables: the codes and their symbols.
TEST(Units, SymbolsOfTheUnitCodes) {
  EXPECT_EQ(diagnostics::length_unit_symbol(1013), "mm");
  EXPECT_EQ(diagnostics::length_unit_symbol(1536), "mm");  // high resolution
  EXPECT_EQ(diagnostics::length_unit_symbol(1005), "°");
  EXPECT_EQ(diagnostics::length_unit_symbol(1019), "in");
  EXPECT_EQ(diagnostics::velocity_unit_symbol(1062), "mm/s");
  EXPECT_EQ(diagnostics::velocity_unit_symbol(1525), "m/min");
  EXPECT_EQ(diagnostics::velocity_unit_symbol(1524), "mm/min");  // printed m/min; decision U2
  EXPECT_EQ(diagnostics::velocity_unit_symbol(1083), "1/min");
  EXPECT_EQ(diagnostics::torque_unit_symbol(1126), "N·m");
  EXPECT_EQ(diagnostics::force_unit_symbol(1120), "N");
  EXPECT_EQ(diagnostics::length_unit_symbol(9999), "");  // not in the tables: no unit rather than a wrong one
  EXPECT_EQ(diagnostics::velocity_unit_symbol(1013), "");
}

TEST(Units, OfAConfiguredObject) {
  to::PositioningAxisData p;
  p.Units.LengthUnit = to::unit_code::kDegree;
  p.Units.VelocityUnit = to::unit_code::kDegreePerMinute;
  const auto rotary = diagnostics::object_units(to::positioning_axis_variables(), &p);
  EXPECT_EQ(rotary.position, "°");
  EXPECT_EQ(rotary.velocity, "°/min");
  EXPECT_EQ(rotary.acceleration, "°/s²");  // man. §6.1.3: the length of the velocity unit per s²
  EXPECT_EQ(rotary.jerk, "°/s³");
  EXPECT_EQ(rotary.symbol(Quantity::kTorque), "N·m");
  EXPECT_EQ(rotary.symbol(Quantity::kMotorSpeed), "1/min");
  EXPECT_EQ(rotary.symbol(Quantity::kNone), "");

  const to::SpeedAxisData s;  // Units.VelocityUnit 1/min: accelerations in 1/s², jerks in 1/s³
  const auto speed = diagnostics::object_units(to::speed_axis_variables(), &s);
  EXPECT_EQ(speed.position, "");  // a speed axis has no position
  EXPECT_EQ(speed.velocity, "1/min");
  EXPECT_EQ(speed.acceleration, "1/s²");
  EXPECT_EQ(speed.jerk, "1/s³");
}

}  // namespace
