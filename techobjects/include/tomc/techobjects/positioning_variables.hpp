#pragma once
// Reflection tables of TO_PositioningAxis (spec 04 §1 column P/Y; man. §10.3; the synchronous axis shares it)
// and TO_ExternalEncoder (column E; man. §10.4), with the VariableInfo / find_variable / find_bit machinery
// of variables.hpp. One row per leaf variable; arrays are reflected element by element with the manual's
// 1-based index: `Sensor[1].Parameter.StepsPerRevolution` ... `Sensor[4].Parameter.StepsPerRevolution`,
// `StatusSensor[1..4].*`, `CrossPlcSynchronousOperation.Interface[1..32].*`. Lookup is exact, so an index
// outside the array (`Sensor[0]`, `Sensor[5]`) or written differently (`Sensor[01]`) is an unknown path;
// parse_array_element() and array_upper_bound() let a caller report why.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

#include "tomc/techobjects/external_encoder_data.hpp"
#include "tomc/techobjects/positioning_axis_data.hpp"
#include "tomc/techobjects/variables.hpp"

namespace tomc::techobjects {

// ---- TO_PositioningAxis / TO_SynchronousAxis (spec 04 §1 column P/Y; man. §10.3) ----

// Every leaf variable of PositioningAxisData, in the order of the manual's chapter 10.3.
std::span<const VariableInfo> positioning_axis_variables() noexcept;
const VariableInfo* find_positioning_axis_variable(std::string_view path) noexcept;
std::optional<BitReference> find_positioning_axis_bit(std::string_view path) noexcept;

// ---- TO_ExternalEncoder (spec 04 §1 column E; man. §10.4) ----

// Every leaf variable of ExternalEncoderData, in the order of the manual's chapter 10.4.
std::span<const VariableInfo> external_encoder_variables() noexcept;
const VariableInfo* find_external_encoder_variable(std::string_view path) noexcept;
std::optional<BitReference> find_external_encoder_bit(std::string_view path) noexcept;

// ---- array elements in paths ----

struct ArrayElementPath {
  std::string_view array;   // "Sensor", "CrossPlcSynchronousOperation.Interface"
  std::uint32_t index;      // 1-based, as in the manual
  std::string_view member;  // "Parameter.StepsPerRevolution"; empty if the path ends at "]"
  friend constexpr bool operator==(const ArrayElementPath&, const ArrayElementPath&) noexcept = default;
};
// Splits the first "<array>[<n>]" of a path. n is decimal without sign, blanks or leading zeros, and at
// least 1 (ARRAY [1..n]); "]" is followed by the end of the path or by ".<member>". nullopt for a path
// without
// "[" or with a malformed index. Purely syntactic: the upper bound is the table's (array_upper_bound).
std::optional<ArrayElementPath> parse_array_element(std::string_view path) noexcept;
// The highest index of `array` in the table (4 for "Sensor" of P, 32 for "CrossPlcSynchronousOperation.
// Interface"); 0 if the table has no such array (the external encoder's Sensor is a single structure).
std::uint32_t array_upper_bound(std::span<const VariableInfo> table, std::string_view array) noexcept;

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

}  // namespace detail
}  // namespace tomc::techobjects
