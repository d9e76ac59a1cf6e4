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

#include "tomc/techobjects/datablocks/external_encoder_data.hpp"
#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/datablocks/variable_table_support.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

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

}  // namespace tomc::techobjects
