// Units of the page (units.hpp).
#include "tomc/diagnostics/units.hpp"

#include <array>
#include <utility>

#include "tomc/techobjects/datablocks/to_types.hpp"

namespace tomc::diagnostics {

namespace to = tomc::techobjects;

namespace {

bool contains(std::string_view s, std::string_view part) noexcept {
  return s.find(part) != std::string_view::npos;
}

template <std::size_t N>
std::string_view find_symbol(const std::array<std::pair<std::uint32_t, std::string_view>, N>& table,
                             std::uint32_t code) noexcept {
  for (const auto& [c, symbol] : table) {
    if (c == code) return symbol;
  }
  return {};
}

std::uint32_t code_of(std::span<const to::VariableInfo> table, const void* data, std::string_view path) {
  const to::VariableInfo* v = to::find_variable(table, path);
  return v == nullptr ? 0 : static_cast<std::uint32_t>(v->read_fn(data));
}

}  // namespace

Quantity quantity_of(const to::VariableInfo& variable) noexcept {
  if (variable.type != to::VariableType::kLreal) return Quantity::kNone;
  const std::string_view path = variable.path;
  const auto dot = path.rfind('.');
  const std::string_view last = dot == std::string_view::npos ? path : path.substr(dot + 1);
  // Most specific first: "VelocityFilter.T1" is a time, "FollowingError.MinVelocity" a velocity.
  if (path.starts_with("Override.")) return Quantity::kPercent;  // Override.Velocity (spec 04 §3.12)
  if (last == "T1" || last == "T2" || last == "Tt" || contains(last, "Time")) return Quantity::kTime;
  if (contains(last, "Speed")) return Quantity::kMotorSpeed;
  // StatusSynchronizedMotion (spec 07 §1.9): the offset and SlaveOffset are following-axis positions; the
  // leader-side positions (EffectiveLeadingValue/FunctionLeadingValue.Position, PhaseShift, MasterOffset) are
  // in the leading axis' units (§1.2: no conversion), which this TO's Units do not name: no unit.
  if (path.starts_with("StatusSynchronizedMotion.")) {
    if (last == "Offset" || last == "SlaveOffset" ||
        path == "StatusSynchronizedMotion.FunctionFollowingValue.Position")
      return Quantity::kPosition;
    if (last == "Position") return Quantity::kNone;
  }
  if (contains(last, "Torque")) return Quantity::kTorque;
  if (contains(last, "Force")) return Quantity::kForce;
  if (contains(last, "Jerk")) return Quantity::kJerk;
  if (contains(last, "Acceleration") || contains(last, "Deceleration")) return Quantity::kAcceleration;
  if (contains(last, "Velocity") || contains(path, "VelocityTolerance.")) return Quantity::kVelocity;
  // DelayedLeadingValue.Acceleration/.Velocity are caught above; the rest of a leading value is its position.
  if (contains(last, "Position") || contains(last, "FollowingError") || contains(last, "Distance") ||
      last == "ControlDifference" || path.starts_with("FollowingError.") || path.starts_with("Modulo.") ||
      last == "Window" || path.ends_with("Backlash.Size") || path.ends_with("Hysteresis.Value") ||
      path.ends_with("AbsEncoderOffset") || path.ends_with("ControlDifferenceQuantization.Value"))
    return Quantity::kPosition;
  return Quantity::kNone;
}

std::string_view length_unit_symbol(std::uint32_t code) noexcept {
  using namespace to::unit_code;
  static constexpr std::array<std::pair<std::uint32_t, std::string_view>, 12> kSymbols{{
      {kMetre, "m"},
      {kMillimetre, "mm"},
      {kMillimetreHighResolution, "mm"},
      {kKilometre, "km"},
      {kMicrometre, "µm"},
      {kNanometre, "nm"},
      {kInch, "in"},
      {kFoot, "ft"},
      {kMile, "mi"},
      {kRadian, "rad"},
      {kDegree, "°"},
      {kDegreeHighResolution, "°"},
  }};
  return find_symbol(kSymbols, code);
}

std::string_view velocity_unit_symbol(std::uint32_t code) noexcept {
  using namespace to::unit_code;
  static constexpr std::array<std::pair<std::uint32_t, std::string_view>, 22> kSymbols{{
      {kPerSecond, "1/s"},
      {kPerMinute, "1/min"},
      {kPerHour, "1/h"},
      {kDegreePerSecond, "°/s"},
      {kDegreePerSecondHighResolution, "°/s"},
      {kDegreePerMinute, "°/min"},
      {kRadianPerSecond, "rad/s"},
      {kRadianPerMinute, "rad/min"},
      {kMillimetrePerSecond, "mm/s"},
      {kMillimetrePerSecondHighResolution, "mm/s"},
      {kMetrePerSecond, "m/s"},
      {kMillimetrePerMinute, "mm/min"},  // printed "m/min" like 1525; read as mm/min (decision U2)
      {kMetrePerMinute, "m/min"},
      {kMillimetrePerHour, "mm/h"},
      {kMetrePerHour, "m/h"},
      {kKilometrePerMinute, "km/min"},
      {kKilometrePerHour, "km/h"},
      {kInchPerSecond, "in/s"},
      {kInchPerMinute, "in/min"},
      {kFootPerSecond, "ft/s"},
      {kFootPerMinute, "ft/min"},
      {kMilePerHour, "mi/h"},
  }};
  return find_symbol(kSymbols, code);
}

std::string_view torque_unit_symbol(std::uint32_t code) noexcept {
  using namespace to::unit_code;
  static constexpr std::array<std::pair<std::uint32_t, std::string_view>, 8> kSymbols{{
      {kNewtonMetre, "N·m"},
      {kKilonewtonMetre, "kN·m"},
      {kPoundForceInch, "lbf·in"},
      {kPoundForceFoot, "lbf·ft"},
      {kOunceForceInch, "ozf·in"},
      {kOunceForceFoot, "ozf·ft"},
      {kPoundalInch, "pdl·in"},
      {kPoundalFoot, "pdl·ft"},
  }};
  return find_symbol(kSymbols, code);
}

std::string_view force_unit_symbol(std::uint32_t code) noexcept {
  using namespace to::unit_code;
  static constexpr std::array<std::pair<std::uint32_t, std::string_view>, 5> kSymbols{{
      {kNewton, "N"},
      {kKilonewton, "kN"},
      {kPoundForce, "lbf"},
      {kOunceForce, "ozf"},
      {kPoundal, "pdl"},
  }};
  return find_symbol(kSymbols, code);
}

std::string_view ObjectUnits::symbol(Quantity q) const noexcept {
  switch (q) {
    case Quantity::kNone:
      return {};
    case Quantity::kPosition:
      return position;
    case Quantity::kVelocity:
      return velocity;
    case Quantity::kAcceleration:
      return acceleration;
    case Quantity::kJerk:
      return jerk;
    case Quantity::kMotorSpeed:
      return "1/min";
    case Quantity::kTorque:
      return torque;
    case Quantity::kForce:
      return force;
    case Quantity::kTime:
      return "s";
    case Quantity::kPercent:
      return "%";
  }
  return {};
}

ObjectUnits object_units(std::span<const to::VariableInfo> table, const void* data_block) {
  ObjectUnits u;
  u.position = length_unit_symbol(code_of(table, data_block, "Units.LengthUnit"));
  u.velocity = velocity_unit_symbol(code_of(table, data_block, "Units.VelocityUnit"));
  // Accelerations and jerks in the velocity unit's length per s² and s³ (man. §6.1.3: m/min -> m/s²).
  if (const auto slash = u.velocity.find('/'); slash != std::string::npos) {
    const std::string length = u.velocity.substr(0, slash);
    u.acceleration = length + "/s²";
    u.jerk = length + "/s³";
  }
  u.torque = torque_unit_symbol(code_of(table, data_block, "Units.TorqueUnit"));
  u.force = force_unit_symbol(code_of(table, data_block, "Units.ForceUnit"));
  return u;
}

}  // namespace tomc::diagnostics
