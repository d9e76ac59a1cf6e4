#pragma once
// Units of what the page shows (issue 21): each LREAL variable of a data block measures a quantity (a
// position, a velocity, a time, ...) whose unit the TO's configuration chooses (Units.LengthUnit,
// Units.VelocityUnit, Units.TorqueUnit, Units.ForceUnit; spec 04 §3.11, man. §6.1.3). The quantity is read
// from the variable's manual name; the symbol from the configured unit codes.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::diagnostics {

enum class Quantity : std::uint8_t {
  kNone,          // a count, a code, a factor, a BOOL: no unit shown
  kPosition,      // Units.LengthUnit
  kVelocity,      // Units.VelocityUnit
  kAcceleration,  // derived from the velocity unit: m/min -> m/s² (man. §6.1.3)
  kJerk,          // m/min -> m/s³
  kMotorSpeed,    // 1/min (Actor.DriveParameter.ReferenceSpeed, ActualSpeed)
  kTorque,        // Units.TorqueUnit
  kForce,         // Units.ForceUnit
  kTime,          // s
  kPercent,       // %
};

// The quantity of a data-block variable by its manual path ("DynamicLimits.MaxVelocity",
// "Sensor[1].Parameter.ReferenceSpeed", "PositioningMonitoring.ToleranceTime"). kNone for anything not LREAL.
Quantity quantity_of(const techobjects::VariableInfo& variable) noexcept;

// Symbols of the Units.* codes (spec 04 §3.11); "" for a code the tables do not list.
std::string_view length_unit_symbol(std::uint32_t code) noexcept;
std::string_view velocity_unit_symbol(std::uint32_t code) noexcept;
std::string_view torque_unit_symbol(std::uint32_t code) noexcept;
std::string_view force_unit_symbol(std::uint32_t code) noexcept;

// The unit symbols of one TO, read once from its data block before the cycle runs (the Units.* variables
// are RON configuration: fixed after download).
struct ObjectUnits {
  std::string position;
  std::string velocity;
  std::string acceleration;
  std::string jerk;
  std::string torque;
  std::string force;
  std::string_view symbol(Quantity q) const noexcept;
};
ObjectUnits object_units(std::span<const techobjects::VariableInfo> table, const void* data_block);

}  // namespace tomc::diagnostics
