#pragma once
// Helpers shared by the reflection tables of every TO type (speed axis, positioning axis, external encoder):
// data-type limits (spec 04 §0.2 "where a range is missing, the data-type limits apply"), the C++ type of
// each data type (spec 04 §0.4), and compile-time checks of a table.

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>

#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {

// ---- building blocks of the reflection tables (also usable by other TO tables) ----
namespace detail {

// Data-type limits (spec 04 §0.2: "where a range is missing, the data-type limits apply").
inline constexpr double kLrealMin = std::numeric_limits<double>::lowest();
inline constexpr double kLrealMax = std::numeric_limits<double>::max();
inline constexpr double kByteMax = 255.0;
inline constexpr double kWordMax = 65535.0;
inline constexpr double kUdintMax = 4294967295.0;
inline constexpr double kDintMin = -2147483648.0;
inline constexpr double kDintMax = 2147483647.0;
inline constexpr double kIntMin = -32768.0;
inline constexpr double kIntMax = 32767.0;

constexpr double type_minimum(VariableType type) noexcept {
  switch (type) {
    case VariableType::kInt:
      return kIntMin;
    case VariableType::kDint:
      return kDintMin;
    case VariableType::kLreal:
      return kLrealMin;
    default:
      return 0.0;
  }
}
constexpr double type_maximum(VariableType type) noexcept {
  switch (type) {
    case VariableType::kBool:
      return 1.0;
    case VariableType::kByte:
      return kByteMax;
    case VariableType::kWord:
    case VariableType::kUint:
    case VariableType::kDbAny:
      return kWordMax;
    case VariableType::kDword:
    case VariableType::kUdint:
      return kUdintMax;
    case VariableType::kInt:
      return kIntMax;
    case VariableType::kDint:
      return kDintMax;
    case VariableType::kLreal:
      return kLrealMax;
  }
  return 0.0;
}

// The C++ type of each data type (spec 04 §0.4).
template <typename T>
constexpr bool cpp_type_matches(VariableType type) noexcept {
  switch (type) {
    case VariableType::kBool:
      return std::is_same_v<T, bool>;
    case VariableType::kByte:
      return std::is_same_v<T, std::uint8_t>;
    case VariableType::kWord:
    case VariableType::kUint:
    case VariableType::kDbAny:
      return std::is_same_v<T, std::uint16_t>;
    case VariableType::kDword:
    case VariableType::kUdint:
      return std::is_same_v<T, std::uint32_t>;
    case VariableType::kInt:
      return std::is_same_v<T, std::int16_t>;
    case VariableType::kDint:
      return std::is_same_v<T, std::int32_t>;
    case VariableType::kLreal:
      return std::is_same_v<T, double>;
  }
  return false;
}

// Only called with values check_value() accepted, so the conversion is exact and in range.
template <typename T>
constexpr T from_double(double value) noexcept {
  if constexpr (std::is_same_v<T, bool>) {
    return value != 0.0;
  } else {
    return static_cast<T>(value);
  }
}

// Every range is non-empty, inside its data type, and every permitted value lies in the range.
constexpr bool ranges_valid(std::span<const VariableInfo> table) noexcept {
  for (const VariableInfo& info : table) {
    if (!(info.minimum <= info.maximum)) return false;
    if (info.minimum < type_minimum(info.type) || info.maximum > type_maximum(info.type)) return false;
    for (const double v : info.allowed_values) {
      if (!(v >= info.minimum && v <= info.maximum)) return false;
    }
  }
  return true;
}

// No path appears twice in a table (sorted copy: O(n log n) constant-evaluation steps for ~500 rows).
template <std::size_t N>
constexpr bool paths_unique(const std::array<VariableInfo, N>& table) {
  std::array<std::string_view, N> paths{};
  for (std::size_t i = 0; i < N; ++i)
    paths[i] = table[i].path;
  std::sort(paths.begin(), paths.end());
  return std::adjacent_find(paths.begin(), paths.end()) == paths.end();
}

// ---- permitted values the TO tables share (spec 04 §3.3, §3.11) ----
// Actor.RemoveEnableReaction: 16#1, 16#3, 16#5, 16#7; 16#0/2/4/6 are invalid (man. §10.2.4, spec 04 §3.3).
inline constexpr std::array<double, 4> kRemoveEnableReactionValues{0x1, 0x3, 0x5, 0x7};
inline constexpr std::array<double, 1> kTimeUnits{unit_code::kSecond};
inline constexpr std::array<double, 8> kTorqueUnits{unit_code::kNewtonMetre,    unit_code::kKilonewtonMetre,
                                                    unit_code::kPoundForceInch, unit_code::kPoundForceFoot,
                                                    unit_code::kOunceForceInch, unit_code::kOunceForceFoot,
                                                    unit_code::kPoundalInch,    unit_code::kPoundalFoot};
inline constexpr std::array<double, 5> kForceUnits{unit_code::kNewton, unit_code::kKilonewton,
                                                   unit_code::kPoundForce, unit_code::kOunceForce,
                                                   unit_code::kPoundal};
inline constexpr std::array<double, 5> kMassUnits{
    unit_code::kKilogram, unit_code::kGram, unit_code::kMilligram, unit_code::kTonne, unit_code::kPound};
inline constexpr std::array<double, 2> kInertiaUnits{unit_code::kKilogramSquareMetre,
                                                     unit_code::kPoundSquareFoot};
inline constexpr std::span<const double> kAny{};
// Units.LengthUnit / VelocityUnit of the position-measuring TOs (P/Y and E; man. §10.3.12, §10.4.7, spec 04
// §3.11).
inline constexpr std::array<double, 12> kLengthUnits{
    unit_code::kMetre,     unit_code::kMillimetre, unit_code::kMillimetreHighResolution,
    unit_code::kKilometre, unit_code::kMicrometre, unit_code::kNanometre,
    unit_code::kInch,      unit_code::kFoot,       unit_code::kMile,
    unit_code::kRadian,    unit_code::kDegree,     unit_code::kDegreeHighResolution};
inline constexpr std::array<double, 19> kPositionVelocityUnits{unit_code::kDegreePerSecond,
                                                               unit_code::kDegreePerSecondHighResolution,
                                                               unit_code::kDegreePerMinute,
                                                               unit_code::kRadianPerSecond,
                                                               unit_code::kRadianPerMinute,
                                                               unit_code::kMillimetrePerSecond,
                                                               unit_code::kMillimetrePerSecondHighResolution,
                                                               unit_code::kMetrePerSecond,
                                                               unit_code::kMillimetrePerMinute,
                                                               unit_code::kMetrePerMinute,
                                                               unit_code::kMillimetrePerHour,
                                                               unit_code::kMetrePerHour,
                                                               unit_code::kKilometrePerMinute,
                                                               unit_code::kKilometrePerHour,
                                                               unit_code::kInchPerSecond,
                                                               unit_code::kInchPerMinute,
                                                               unit_code::kFootPerSecond,
                                                               unit_code::kFootPerMinute,
                                                               unit_code::kMilePerHour};

}  // namespace detail

}  // namespace tomc::techobjects

// ---- the rows of a reflection table, one macro for every TO type ----
// One row: `Data` the data-block type, `owner` its TechnologyObjectType, `path_literal` the manual path,
// `member` the Data member expression it names; a static_assert holds the row's data type against the C++
// member type. Each table defines its own short form (TOMC_P_ROW = TOMC_DB_ROW(PositioningAxisData, ...)).
#define TOMC_DB_ROW(Data, owner_type, path_literal, member, data_type, access_code, variable_role, lo, hi, \
                    allowed, wp)                                                                           \
  ::tomc::techobjects::VariableInfo {                                                                      \
    .path = path_literal, .type = ::tomc::techobjects::VariableType::data_type,                            \
    .access = ::tomc::techobjects::Access::access_code, .minimum = (lo), .maximum = (hi),                  \
    .allowed_values = (allowed), .role = ::tomc::techobjects::VariableRole::variable_role,                 \
    .write_parameter = (wp), .owner = ::tomc::techobjects::TechnologyObjectType::owner_type,               \
    .read_fn = [](const void* data) noexcept -> double {                                                   \
      static_assert(                                                                                       \
          ::tomc::techobjects::detail::cpp_type_matches<decltype(std::declval<const Data&>().member)>(     \
              ::tomc::techobjects::VariableType::data_type),                                               \
          "data type of " path_literal " does not match its C++ member");                                  \
      return static_cast<double>(static_cast<const Data*>(data)->member);                                  \
    },                                                                                                     \
    .write_fn = [](void* data, double value) noexcept {                                                    \
      auto& target = static_cast<Data*>(data)->member;                                                     \
      target = ::tomc::techobjects::detail::from_double<std::remove_reference_t<decltype(target)>>(value); \
    }                                                                                                      \
  }
// A VREF (spec 04 §0.4) as its four members, configuration, with the access of the VREF, through the table's
// row macro ROW(path, member, ...). The tables give "0 ... 65535" for the VREF as a whole; that range is the
// DB number's, the other members keep their data-type limits.
#define TOMC_DB_VREF_ROWS(ROW, path_literal, member, access_code)                               \
  ROW(path_literal ".RID", member.RID, kDword, access_code, kConfiguration, 0.0,                \
      ::tomc::techobjects::detail::kUdintMax, ::tomc::techobjects::detail::kAny, 0),            \
      ROW(path_literal ".AREA", member.AREA, kByte, access_code, kConfiguration, 0.0,           \
          ::tomc::techobjects::detail::kByteMax, ::tomc::techobjects::detail::kAny, 0),         \
      ROW(path_literal ".DB_NUMBER", member.DB_NUMBER, kUint, access_code, kConfiguration, 0.0, \
          ::tomc::techobjects::detail::kWordMax, ::tomc::techobjects::detail::kAny, 0),         \
      ROW(path_literal ".OFFSET", member.OFFSET, kUdint, access_code, kConfiguration, 0.0,      \
          ::tomc::techobjects::detail::kUdintMax, ::tomc::techobjects::detail::kAny, 0)
