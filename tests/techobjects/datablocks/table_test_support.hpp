#pragma once
// Shared by the P and E data-block tests: the expected-row type (transcribed from spec 04 independently of
// the production tables), VREF expansion, and generic table checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects::testing {

inline constexpr double kLrealMin = std::numeric_limits<double>::lowest();
inline constexpr double kLrealMax = std::numeric_limits<double>::max();
inline constexpr double kUdintMax = 4294967295.0;
inline constexpr double kDintMin = -2147483648.0;
inline constexpr double kDintMax = 2147483647.0;

struct Expected {
  std::string path;
  VariableType type;
  Access access;
  double minimum;
  double maximum;
  VariableRole role;
  std::uint16_t write_parameter;
  double start_value;  // the manual's where it gives one, else the value chosen in the data header
};

// spec 04 §0.4 VREF { DWORD RID; BYTE AREA; UINT DB_NUMBER; UDINT OFFSET }; the tables give 0 ... 65535 (the
// DB number), the other members keep their data-type limits. All start values zero.
inline void add_vref(std::vector<Expected>& rows, const std::string& path, Access access) {
  rows.push_back(
      {path + ".RID", VariableType::kDword, access, 0, kUdintMax, VariableRole::kConfiguration, 0, 0});
  rows.push_back({path + ".AREA", VariableType::kByte, access, 0, 255, VariableRole::kConfiguration, 0, 0});
  rows.push_back(
      {path + ".DB_NUMBER", VariableType::kUint, access, 0, 65535, VariableRole::kConfiguration, 0, 0});
  rows.push_back(
      {path + ".OFFSET", VariableType::kUdint, access, 0, kUdintMax, VariableRole::kConfiguration, 0, 0});
}

// spec 04 §3.7: CrossPlcSynchronousOperation.Interface[1..32] (P/Y and E alike), all RON.
inline void add_cross_plc_interfaces(std::vector<Expected>& rows) {
  for (int i = 1; i <= 32; ++i) {
    const std::string base = "CrossPlcSynchronousOperation.Interface[" + std::to_string(i) + "]";
    rows.push_back({base + ".EnableLeadingValueOutput", VariableType::kBool, Access::kRON, 0, 1,
                    VariableRole::kConfiguration, 0, 0});
    add_vref(rows, base + ".AddressOut", Access::kRON);
    rows.push_back({base + ".TelegramVersion", VariableType::kWord, Access::kRON, 1, 2,
                    VariableRole::kConfiguration, 0, 1});  // chosen: version 1 (technology >= V10.0)
  }
  rows.push_back({"CrossPlcSynchronousOperation.LocalLeadingValueDelayTime", VariableType::kLreal,
                  Access::kRES, 0.0, 1.0E9, VariableRole::kConfiguration, 0, 0.0});
}

// Every expected row is in the table with exactly these attributes and start value, the start value passes
// check_value, and the table has no further rows.
template <typename Data>
void expect_table_matches(std::span<const VariableInfo> table, const std::vector<Expected>& expected,
                          TechnologyObjectType owner) {
  const Data defaults{};
  std::set<std::string> seen;
  for (const auto& row : expected) {
    SCOPED_TRACE(row.path);
    EXPECT_TRUE(seen.insert(row.path).second) << "expected table lists the path twice";
    const VariableInfo* info = find_variable(table, row.path);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->path, row.path);
    EXPECT_EQ(to_string(info->type), to_string(row.type));
    EXPECT_EQ(to_string(info->access), to_string(row.access));
    EXPECT_EQ(info->minimum, row.minimum);
    EXPECT_EQ(info->maximum, row.maximum);
    EXPECT_EQ(info->role, row.role);
    EXPECT_EQ(info->write_parameter, row.write_parameter);
    EXPECT_EQ(info->owner, owner);
    EXPECT_EQ(info->read(defaults), row.start_value);
    EXPECT_EQ(check_value(*info, info->read(defaults)), ValueError::kNone) << "start value is not valid";
  }
  EXPECT_EQ(table.size(), expected.size());
  for (const auto& info : table)
    EXPECT_TRUE(seen.count(std::string(info.path))) << info.path;
}

// A valid value that differs from `current`.
inline double other_valid_value(const VariableInfo& info, double current) {
  if (info.type == VariableType::kBool) return current == 0.0 ? 1.0 : 0.0;
  for (double v : info.allowed_values) {
    if (v != current) return v;
  }
  if (info.type == VariableType::kLreal) {
    const double lo = std::max(info.minimum, -1.0E12), hi = std::min(info.maximum, 1.0E12);
    const double v = lo + (hi - lo) * 0.3125;
    return v != current ? v : lo;
  }
  return info.maximum != current ? info.maximum : info.minimum;
}

// Writing one variable changes its own member only (the accessor reaches the member its path names).
template <typename Data>
void expect_round_trips(std::span<const VariableInfo> table) {
  const Data untouched{};
  for (const auto& info : table) {
    SCOPED_TRACE(std::string(info.path));
    Data data{};
    const double value = other_valid_value(info, info.read(data));
    ASSERT_NE(value, info.read(data));
    if (check_value(info, value) == ValueError::kNone) {
      ASSERT_EQ(info.write(data, value), ValueError::kNone);
    } else {
      // A single permitted value (Units.TimeUnit): exercise the raw accessor with an in-type value.
      ASSERT_EQ(info.allowed_values.size(), 1u);
      EXPECT_EQ(info.write(data, value), ValueError::kNotAllowed);
      info.write_fn(&data, value);
    }
    EXPECT_EQ(info.read(data), value);
    for (const auto& other : table) {
      if (&other != &info && other.read(data) != other.read(untouched)) {
        ADD_FAILURE() << "also changed " << other.path;
      }
    }
  }
}

}  // namespace tomc::techobjects::testing
