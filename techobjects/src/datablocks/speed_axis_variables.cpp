// The reflection table of TO_SpeedAxis (spec 04 §1 column S; man. §10.2) and the table-independent helpers of
// variables.hpp. Each row names the SpeedAxisData member once: the path string is that member expression
// stringized, and a static_assert holds the row's data type against the C++ member type, so path, member and
// type cannot drift apart.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/variable_table_support.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {
namespace {

using namespace detail;  // the shared table helpers

// ---- ranges of the speed-axis tables (man. §10.2) ----
constexpr double k1e12 = 1.0E12;
constexpr double kSpeedAxisMaxAcceleration = 2.7777777777778E8;  // DynamicLimits / DynamicDefaults, S column
constexpr double kSpeedAxisMaxJerk = 4629629.629;  // DynamicLimits.MaxJerk / DynamicDefaults.Jerk, S

// ---- permitted values ----
// Units.* codes of the speed axis (man. §10.2.7, spec 04 §3.11).
constexpr std::array<double, 3> kVelocityUnits{unit_code::kPerSecond, unit_code::kPerMinute,
                                               unit_code::kPerHour};

// One row: `member` is the SpeedAxisData member expression and, stringized, the manual path.
#define TOMC_S_ROW(...) TOMC_DB_ROW(SpeedAxisData, kSpeedAxis, __VA_ARGS__)
#define TOMC_SPEED_AXIS_VARIABLE(member, ...) TOMC_S_ROW(#member, member, __VA_ARGS__)
// A VREF (spec 04 §0.4) as its four members, all RON configuration.
#define TOMC_SPEED_AXIS_VREF(member) TOMC_DB_VREF_ROWS(TOMC_S_ROW, #member, member, kRON)

// clang-format off
constexpr auto kSpeedAxisVariables = std::to_array<VariableInfo>({
    // man. §10.2.1 actual values and setpoints (spec 04 §2), RON
    TOMC_SPEED_AXIS_VARIABLE(Velocity, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(ActualSpeed, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(Acceleration, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(VelocitySetpoint, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    // man. §10.2.2 Simulation (spec 04 §3.1)
    TOMC_SPEED_AXIS_VARIABLE(Simulation.Mode, kUdint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.2.3 VirtualAxis (spec 04 §3.2)
    TOMC_SPEED_AXIS_VARIABLE(VirtualAxis.Mode, kUdint, kRON, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.2.4 Actor (spec 04 §3.3)
    TOMC_SPEED_AXIS_VARIABLE(Actor.Type, kDint, kRON, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(Actor.InverseDirection, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(Actor.DataAdaption, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(Actor.Efficiency, kLreal, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(Actor.RemoveEnableReaction, kWord, kRES, kConfiguration, 0.0, 7.0,
                             kRemoveEnableReactionValues, 1020),
    TOMC_SPEED_AXIS_VREF(Actor.Interface.AddressIn),
    TOMC_SPEED_AXIS_VREF(Actor.Interface.AddressOut),
    TOMC_SPEED_AXIS_VARIABLE(Actor.Interface.EnableDriveOutput, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VREF(Actor.Interface.EnableDriveOutputAddress),
    TOMC_SPEED_AXIS_VARIABLE(Actor.Interface.DriveReadyInput, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VREF(Actor.Interface.DriveReadyInputAddress),
    TOMC_SPEED_AXIS_VARIABLE(Actor.Interface.EnableTorqueData, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VREF(Actor.Interface.TorqueDataAddressIn),
    TOMC_SPEED_AXIS_VREF(Actor.Interface.TorqueDataAddressOut),
    TOMC_SPEED_AXIS_VARIABLE(Actor.DriveParameter.ReferenceSpeed, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(Actor.DriveParameter.MaxSpeed, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(Actor.DriveParameter.ReferenceTorque, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.2.5 TorqueLimiting (spec 04 §3.4)
    TOMC_SPEED_AXIS_VARIABLE(TorqueLimiting.LimitBase, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(TorqueLimiting.PositionBasedMonitorings, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(TorqueLimiting.LimitDefaults.Torque, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(TorqueLimiting.LimitDefaults.Force, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.2.6 LoadGear (spec 04 §3.9)
    TOMC_SPEED_AXIS_VARIABLE(LoadGear.Numerator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(LoadGear.Denominator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0),
    // man. §10.2.7 Units (spec 04 §3.11), RON; no range printed, the permitted codes are the listed ones
    TOMC_SPEED_AXIS_VARIABLE(Units.VelocityUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kVelocityUnits, 0),
    TOMC_SPEED_AXIS_VARIABLE(Units.TimeUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kTimeUnits, 0),
    TOMC_SPEED_AXIS_VARIABLE(Units.TorqueUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kTorqueUnits, 0),
    TOMC_SPEED_AXIS_VARIABLE(Units.ForceUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kForceUnits, 0),
    TOMC_SPEED_AXIS_VARIABLE(Units.MassUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kMassUnits, 0),
    TOMC_SPEED_AXIS_VARIABLE(Units.IneritaUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kInertiaUnits, 0),
    // man. §10.2.8 DynamicLimits (spec 04 §3.14, column "Range S")
    TOMC_SPEED_AXIS_VARIABLE(DynamicLimits.MaxVelocity, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicLimits.Velocity, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicLimits.MaxAcceleration, kLreal, kDIR, kConfiguration, 0.0,
                             kSpeedAxisMaxAcceleration, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicLimits.MaxDeceleration, kLreal, kDIR, kConfiguration, 0.0,
                             kSpeedAxisMaxAcceleration, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicLimits.MaxJerk, kLreal, kDIR, kConfiguration, 0.0, kSpeedAxisMaxJerk, kAny, 0),
    // man. §10.2.9 DynamicDefaults (spec 04 §3.15, column "Range S")
    TOMC_SPEED_AXIS_VARIABLE(DynamicDefaults.Velocity, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicDefaults.Acceleration, kLreal, kCAL, kConfiguration, 0.0,
                             kSpeedAxisMaxAcceleration, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicDefaults.Deceleration, kLreal, kCAL, kConfiguration, 0.0,
                             kSpeedAxisMaxAcceleration, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicDefaults.Jerk, kLreal, kCAL, kConfiguration, 0.0, kSpeedAxisMaxJerk, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(DynamicDefaults.EmergencyDeceleration, kLreal, kDIR, kConfiguration, 0.0,
                             kSpeedAxisMaxAcceleration, kAny, 0),
    // man. §10.2.10 Override (spec 04 §3.19), percent
    TOMC_SPEED_AXIS_VARIABLE(Override.Velocity, kLreal, kDIR, kConfiguration, 0.0, 200.0, kAny, 0),
    // man. §10.2.11 StatusDrive (spec 04 §4.2), RON
    TOMC_SPEED_AXIS_VARIABLE(StatusDrive.InOperation, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(StatusDrive.CommunicationOK, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(StatusDrive.Error, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(StatusDrive.AdaptionState, kDint, kRON, kStatus, 0.0, 4.0, kAny, 0),
    // man. §10.2.12 StatusTorqueData (spec 04 §4.7; the manual prints no range for the DINTs, spec 04 gives 0, 1)
    TOMC_SPEED_AXIS_VARIABLE(StatusTorqueData.CommandAdditiveTorqueActive, kDint, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(StatusTorqueData.CommandTorqueRangeActive, kDint, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(StatusTorqueData.ActualTorque, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    // man. §10.2.13 StatusMotionIn (spec 04 §4.8): S has 0, 1 only
    TOMC_SPEED_AXIS_VARIABLE(StatusMotionIn.FunctionState, kDint, kRON, kStatus, 0.0, 1.0, kAny, 0),
    // man. §10.2.14 StatusInterpreterMotion (spec 04 §4.9); W of Interpreter not printed: status structure -> RON
    TOMC_SPEED_AXIS_VARIABLE(StatusInterpreterMotion.Interpreter, kDbAny, kRON, kStatus, 0.0, kWordMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(StatusInterpreterMotion.StatusWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    // man. §10.2.15 ... §10.2.19 bit words (spec 04 §5) and ErrorDetail (spec 04 §4.10), RON
    TOMC_SPEED_AXIS_VARIABLE(StatusWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(StatusWord2, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(ErrorWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(ErrorDetail.Number, kUdint, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(ErrorDetail.Reaction, kDint, kRON, kStatus, 0.0, 5.0, kAny, 0),
    TOMC_SPEED_AXIS_VARIABLE(WarningWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
});
// clang-format on

#undef TOMC_SPEED_AXIS_VREF
#undef TOMC_SPEED_AXIS_VARIABLE

// ---- compile-time consistency of a table ----
template <std::size_t N>
constexpr bool ranges_valid(const std::array<VariableInfo, N>& table) {
  for (const VariableInfo& info : table) {
    if (!(info.minimum <= info.maximum)) return false;
    if (info.minimum < type_minimum(info.type) || info.maximum > type_maximum(info.type)) return false;
  }
  return true;
}
static_assert(detail::paths_unique(kSpeedAxisVariables), "duplicate path in the speed-axis table");
static_assert(ranges_valid(kSpeedAxisVariables), "a speed-axis range is empty or exceeds its data type");

}  // namespace

// ---- generic helpers ----

std::string_view to_string(VariableType type) noexcept {
  switch (type) {
    case VariableType::kBool:
      return "BOOL";
    case VariableType::kByte:
      return "BYTE";
    case VariableType::kWord:
      return "WORD";
    case VariableType::kDword:
      return "DWORD";
    case VariableType::kInt:
      return "INT";
    case VariableType::kUint:
      return "UINT";
    case VariableType::kDint:
      return "DINT";
    case VariableType::kUdint:
      return "UDINT";
    case VariableType::kDbAny:
      return "DB_ANY";
    case VariableType::kLreal:
      return "LREAL";
  }
  return "?";
}

std::string_view to_string(Access access) noexcept {
  switch (access) {
    case Access::kRON:
      return "RON";
    case Access::kDIR:
      return "DIR";
    case Access::kCAL:
      return "CAL";
    case Access::kRES:
      return "RES";
    case Access::kDL:
      return "DL";
  }
  return "?";
}

std::string_view to_string(AccessError error) noexcept {
  switch (error) {
    case AccessError::kNone:
      return "ok";
    case AccessError::kStatusVariable:
      return "status variable, written by the technology object only";
    case AccessError::kReadOnly:
      return "read only (RON)";
    case AccessError::kStartValueOnly:
      return "restart relevant (RES): only the start value can be changed";
  }
  return "?";
}

std::string_view to_string(ValueError error) noexcept {
  switch (error) {
    case ValueError::kNone:
      return "ok";
    case ValueError::kNotANumber:
      return "not a number";
    case ValueError::kNotBoolean:
      return "not a BOOL (0 or 1)";
    case ValueError::kNotInteger:
      return "not an integer";
    case ValueError::kOutOfRange:
      return "out of range";
    case ValueError::kNotAllowed:
      return "not a permitted value";
    case ValueError::kWrongDataBlock:
      return "variable of another technology object type";
  }
  return "?";
}

ValueError check_value(const VariableInfo& info, double value) noexcept {
  if (std::isnan(value)) return ValueError::kNotANumber;
  if (info.type == VariableType::kBool) {
    if (value != 0.0 && value != 1.0) return ValueError::kNotBoolean;
  } else if (is_integer(info.type) && std::isfinite(value) && std::trunc(value) != value) {
    return ValueError::kNotInteger;
  }
  if (!(value >= info.minimum && value <= info.maximum)) return ValueError::kOutOfRange;
  if (!info.allowed_values.empty() &&
      std::find(info.allowed_values.begin(), info.allowed_values.end(), value) == info.allowed_values.end()) {
    return ValueError::kNotAllowed;
  }
  return ValueError::kNone;
}

AccessError check_write_access(const VariableInfo& info, WriteContext context) noexcept {
  if (info.role == VariableRole::kStatus) return AccessError::kStatusVariable;
  const bool read_only = info.access == Access::kRON || info.access == Access::kDL;
  switch (context) {
    case WriteContext::kConfiguration:
      return AccessError::kNone;
    case WriteContext::kStartValue:
      return read_only ? AccessError::kReadOnly : AccessError::kNone;
    case WriteContext::kUserProgram:
      if (read_only) return AccessError::kReadOnly;
      return info.access == Access::kRES ? AccessError::kStartValueOnly : AccessError::kNone;
  }
  return AccessError::kReadOnly;
}

const VariableInfo* find_variable(std::span<const VariableInfo> table, std::string_view path) noexcept {
  const auto it =
      std::find_if(table.begin(), table.end(), [path](const VariableInfo& v) { return v.path == path; });
  return it == table.end() ? nullptr : &*it;
}

const VariableInfo* find_by_write_parameter(std::span<const VariableInfo> table,
                                            std::uint16_t parameter_number) noexcept {
  if (parameter_number == 0) return nullptr;
  const auto it = std::find_if(table.begin(), table.end(), [parameter_number](const VariableInfo& v) {
    return v.write_parameter == parameter_number;
  });
  return it == table.end() ? nullptr : &*it;
}

std::optional<BitPath> parse_bit_path(std::string_view path) noexcept {
  const auto dot = path.rfind('.');
  if (dot == std::string_view::npos || dot == 0) return std::nullopt;
  const std::string_view word = path.substr(0, dot);
  std::string_view selector = path.substr(dot + 1);
  if (word.back() == '.') return std::nullopt;
  if (!selector.empty() && selector.front() == '%') selector.remove_prefix(1);  // SCL slice "%X5"
  if (selector.size() < 2 || selector.size() > 3 || selector.front() != 'X') return std::nullopt;
  const std::string_view digits = selector.substr(1);
  if (digits.size() == 2 && digits.front() == '0') return std::nullopt;  // no leading zeros
  unsigned bit = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    bit = bit * 10 + static_cast<unsigned>(c - '0');
  }
  if (bit > 31) return std::nullopt;
  return BitPath{word, static_cast<std::uint8_t>(bit)};
}

std::optional<BitReference> find_bit(std::span<const VariableInfo> table, std::string_view path) noexcept {
  const auto parsed = parse_bit_path(path);
  if (!parsed) return std::nullopt;
  const VariableInfo* word = find_variable(table, parsed->word);
  if (word == nullptr || parsed->bit >= bit_width(word->type)) return std::nullopt;
  return BitReference{word, parsed->bit};
}

// ---- TO_SpeedAxis ----

std::span<const VariableInfo> speed_axis_variables() noexcept {
  return kSpeedAxisVariables;
}

const VariableInfo* find_speed_axis_variable(std::string_view path) noexcept {
  return find_variable(kSpeedAxisVariables, path);
}

std::optional<BitReference> find_speed_axis_bit(std::string_view path) noexcept {
  return find_bit(kSpeedAxisVariables, path);
}

}  // namespace tomc::techobjects
