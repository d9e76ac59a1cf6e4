// The TO_SpeedAxis data block and its reflection table against spec 04 §2-§4 (column S) and man. §10.2. The
// expected table below is transcribed from the spec independently of the production table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {
namespace {

using enum VariableType;
using enum Access;
using enum VariableRole;

constexpr double kLrealMin = std::numeric_limits<double>::lowest();
constexpr double kLrealMax = std::numeric_limits<double>::max();
constexpr double kUdintMax = 4294967295.0;

struct Expected {
  std::string path;
  VariableType type;
  Access access;
  double minimum;
  double maximum;
  VariableRole role;
  std::uint16_t write_parameter;
  double
      start_value;  // the manual's where it gives one (marked), else the value chosen in speed_axis_data.hpp
};

void add_vref(std::vector<Expected>& rows, const std::string& path) {
  // spec 04 §0.4 VREF { DWORD RID; BYTE AREA; UINT DB_NUMBER; UDINT OFFSET }; §3.3 range 0...65535, RON
  rows.push_back({path + ".RID", kDword, kRON, 0, kUdintMax, kConfiguration, 0, 0});
  rows.push_back({path + ".AREA", kByte, kRON, 0, 255, kConfiguration, 0, 0});
  rows.push_back({path + ".DB_NUMBER", kUint, kRON, 0, 65535, kConfiguration, 0, 0});
  rows.push_back({path + ".OFFSET", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 0});
}

std::vector<Expected> expected_speed_axis() {
  std::vector<Expected> rows = {
      // spec 04 §2 (man. §10.2.1): all RON, "-" = data-type limits
      {"Velocity", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualSpeed", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"Acceleration", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"VelocitySetpoint", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      // spec 04 §3.1
      {"Simulation.Mode", kUdint, kRES, 0, 1, kConfiguration, 0, 0},
      // spec 04 §3.2
      {"VirtualAxis.Mode", kUdint, kRON, 0, 1, kConfiguration, 0, 0},
      // spec 04 §3.3 (rows with TO "S,P")
      {"Actor.Type", kDint, kRON, 0, 1, kConfiguration, 0, 1},
      {"Actor.InverseDirection", kBool, kRES, 0, 1, kConfiguration, 0, 0},
      {"Actor.DataAdaption", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"Actor.Efficiency", kLreal, kRES, 0.0, 1.0, kConfiguration, 0, 1.0},
      {"Actor.RemoveEnableReaction", kWord, kRES, 0x0, 0x7, kConfiguration, 1020,
       0x7},  // default 16#7: manual
  };
  add_vref(rows, "Actor.Interface.AddressIn");
  add_vref(rows, "Actor.Interface.AddressOut");
  rows.push_back({"Actor.Interface.EnableDriveOutput", kBool, kRES, 0, 1, kConfiguration, 0, 0});
  add_vref(rows, "Actor.Interface.EnableDriveOutputAddress");
  rows.push_back({"Actor.Interface.DriveReadyInput", kBool, kRES, 0, 1, kConfiguration, 0, 0});
  add_vref(rows, "Actor.Interface.DriveReadyInputAddress");
  rows.push_back({"Actor.Interface.EnableTorqueData", kBool, kRES, 0, 1, kConfiguration, 0, 0});
  add_vref(rows, "Actor.Interface.TorqueDataAddressIn");
  add_vref(rows, "Actor.Interface.TorqueDataAddressOut");
  const std::vector<Expected> rest = {
      {"Actor.DriveParameter.ReferenceSpeed", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {"Actor.DriveParameter.MaxSpeed", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {"Actor.DriveParameter.ReferenceTorque", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 4.0},
      // spec 04 §3.4
      {"TorqueLimiting.LimitBase", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"TorqueLimiting.PositionBasedMonitorings", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"TorqueLimiting.LimitDefaults.Torque", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 4.0},
      {"TorqueLimiting.LimitDefaults.Force", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 100.0},
      // spec 04 §3.9
      {"LoadGear.Numerator", kUdint, kRES, 1, kUdintMax, kConfiguration, 0, 1},
      {"LoadGear.Denominator", kUdint, kRES, 1, kUdintMax, kConfiguration, 0, 1},
      // spec 04 §3.11 (S column), all RON UDINT codes
      {"Units.VelocityUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1083},
      {"Units.TimeUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1054},
      {"Units.TorqueUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1126},
      {"Units.ForceUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1120},
      {"Units.MassUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1088},
      {"Units.IneritaUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1118},
      // spec 04 §3.14, column "Range S"
      {"DynamicLimits.MaxVelocity", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {"DynamicLimits.Velocity", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {"DynamicLimits.MaxAcceleration", kLreal, kDIR, 0.0, 2.7777777777778E8, kConfiguration, 0, 100.0},
      {"DynamicLimits.MaxDeceleration", kLreal, kDIR, 0.0, 2.7777777777778E8, kConfiguration, 0, 100.0},
      {"DynamicLimits.MaxJerk", kLreal, kDIR, 0.0, 4629629.629, kConfiguration, 0, 1000.0},
      // spec 04 §3.15, column "Range S"
      {"DynamicDefaults.Velocity", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 1500.0},
      {"DynamicDefaults.Acceleration", kLreal, kCAL, 0.0, 2.7777777777778E8, kConfiguration, 0, 50.0},
      {"DynamicDefaults.Deceleration", kLreal, kCAL, 0.0, 2.7777777777778E8, kConfiguration, 0, 50.0},
      {"DynamicDefaults.Jerk", kLreal, kCAL, 0.0, 4629629.629, kConfiguration, 0, 0.0},
      {"DynamicDefaults.EmergencyDeceleration", kLreal, kDIR, 0.0, 2.7777777777778E8, kConfiguration, 0,
       200.0},
      // spec 04 §3.19
      {"Override.Velocity", kLreal, kDIR, 0.0, 200.0, kConfiguration, 0, 100.0},
      // spec 04 §4.2, RON
      {"StatusDrive.InOperation", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusDrive.CommunicationOK", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusDrive.Error", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusDrive.AdaptionState", kDint, kRON, 0, 4, kStatus, 0, 0},
      // spec 04 §4.7 (the three S members)
      {"StatusTorqueData.CommandAdditiveTorqueActive", kDint, kRON, 0, 1, kStatus, 0, 0},
      {"StatusTorqueData.CommandTorqueRangeActive", kDint, kRON, 0, 1, kStatus, 0, 0},
      {"StatusTorqueData.ActualTorque", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      // spec 04 §4.8 (S: 0, 1)
      {"StatusMotionIn.FunctionState", kDint, kRON, 0, 1, kStatus, 0, 0},
      // spec 04 §4.9
      {"StatusInterpreterMotion.Interpreter", kDbAny, kRON, 0, 65535, kStatus, 0, 0},
      {"StatusInterpreterMotion.StatusWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      // spec 04 §5 (all DWORD, RON) and §4.10
      {"StatusWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"StatusWord2", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorDetail.Number", kUdint, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorDetail.Reaction", kDint, kRON, 0, 5, kStatus, 0, 0},
      {"WarningWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
  };
  rows.insert(rows.end(), rest.begin(), rest.end());
  return rows;
}

const VariableInfo& must_find(std::string_view path) {
  const VariableInfo* info = find_speed_axis_variable(path);
  if (info == nullptr) throw std::runtime_error("missing " + std::string(path));
  return *info;
}

// ---- the table against the spec ----

// spec 04 §2–§5 (column S), §0.2 (access), §0.4 (types and ranges).
TEST(SpeedAxisVariables, EveryPathOfColumnSWithTypeAccessRangeAndStartValue) {
  const auto expected = expected_speed_axis();
  const SpeedAxisData defaults{};
  std::set<std::string> seen;
  for (const auto& row : expected) {
    SCOPED_TRACE(row.path);
    EXPECT_TRUE(seen.insert(row.path).second) << "expected table lists the path twice";
    const VariableInfo* info = find_speed_axis_variable(row.path);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->path, row.path);
    EXPECT_EQ(to_string(info->type), to_string(row.type));
    EXPECT_EQ(to_string(info->access), to_string(row.access));
    EXPECT_EQ(info->minimum, row.minimum);
    EXPECT_EQ(info->maximum, row.maximum);
    EXPECT_EQ(info->role, row.role);
    EXPECT_EQ(info->write_parameter, row.write_parameter);
    EXPECT_EQ(info->owner, TechnologyObjectType::kSpeedAxis);
    EXPECT_EQ(info->read(defaults), row.start_value);
    EXPECT_EQ(check_value(*info, info->read(defaults)), ValueError::kNone) << "start value is not valid";
  }
  // Nothing more: the production table has exactly these rows.
  EXPECT_EQ(speed_axis_variables().size(), expected.size());
  for (const auto& info : speed_axis_variables())
    EXPECT_TRUE(seen.count(std::string(info.path))) << info.path;
}

// spec 04 §6.1 (the data-block enums: permitted values only).
TEST(SpeedAxisVariables, PermittedValues) {
  // spec 04 §3.3 / §6.1: 16#1, 16#3, 16#5, 16#7; 16#0/2/4/6 invalid
  const auto& reaction = must_find("Actor.RemoveEnableReaction");
  for (double v : {1.0, 3.0, 5.0, 7.0})
    EXPECT_EQ(check_value(reaction, v), ValueError::kNone) << v;
  for (double v : {0.0, 2.0, 4.0, 6.0})
    EXPECT_EQ(check_value(reaction, v), ValueError::kNotAllowed) << v;
  EXPECT_EQ(check_value(reaction, 8.0), ValueError::kOutOfRange);

  // spec 04 §3.11, S column (man. §10.2.7)
  const std::vector<std::pair<std::string, std::vector<double>>> units = {
      {"Units.VelocityUnit", {1082, 1083, 1528}},
      {"Units.TimeUnit", {1054}},
      {"Units.TorqueUnit", {1126, 1128, 1529, 1530, 1531, 1532, 1533, 1534}},
      {"Units.ForceUnit", {1120, 1122, 1094, 1093, 1535}},
      {"Units.MassUnit", {1088, 1089, 1090, 1092, 1540}},
      {"Units.IneritaUnit", {1118, 1541}},
  };
  for (const auto& [path, codes] : units) {
    SCOPED_TRACE(path);
    const auto& info = must_find(path);
    ASSERT_EQ(info.allowed_values.size(), codes.size());
    for (double code : codes)
      EXPECT_EQ(check_value(info, code), ValueError::kNone) << code;
    // positioning-axis codes are not speed-axis codes: 1013 mm (LengthUnit), 1062 mm/s (VelocityUnit)
    EXPECT_EQ(check_value(info, 1013), ValueError::kNotAllowed);
    EXPECT_EQ(check_value(info, 1062), ValueError::kNotAllowed);
  }
  // Everything else takes every value in its range.
  for (const auto& info : speed_axis_variables()) {
    if (info.path == "Actor.RemoveEnableReaction" || info.path.starts_with("Units.")) continue;
    EXPECT_TRUE(info.allowed_values.empty()) << info.path;
  }
}

// spec 04 §3 (the start values).
TEST(SpeedAxisVariables, ManualStartValuesInTheStruct) {
  const SpeedAxisData data{};
  EXPECT_EQ(data.Actor.RemoveEnableReaction, 0x7);  // man. §10.2.4 / §9.15: 16#7 default
  EXPECT_EQ(data.Override.Velocity, 100.0);
  EXPECT_EQ(data.LoadGear.Numerator, 1u);
  EXPECT_EQ(data.LoadGear.Denominator, 1u);
  EXPECT_EQ(data.Units.TimeUnit, 1054u);  // the only time unit of axes (spec 04 §3.11)
  EXPECT_EQ(data.DynamicDefaults.Jerk, 0.0);
  EXPECT_EQ(data.StatusWord, 0u);
  EXPECT_EQ(data.Actor.Interface.AddressIn, Vref{});
  EXPECT_EQ(data.ErrorDetail.Reaction, static_cast<std::int32_t>(AlarmReaction::kNone));
  // ErrorDetail.Reaction 0 ... 5 (spec 04 §4.10) is the range of the alarm model's reactions.
  EXPECT_EQ(must_find("ErrorDetail.Reaction").maximum, static_cast<double>(AlarmReaction::kFollowSetpoint));
  // chosen defaults stay consistent with the rules of spec 04 §3.3 / §3.14 / §3.15
  EXPECT_LE(data.Actor.DriveParameter.MaxSpeed, 2.0 * data.Actor.DriveParameter.ReferenceSpeed);
  EXPECT_LE(data.DynamicDefaults.Velocity, data.DynamicLimits.MaxVelocity);
  EXPECT_LE(data.DynamicDefaults.Acceleration, data.DynamicLimits.MaxAcceleration);
  EXPECT_LE(data.DynamicDefaults.Deceleration, data.DynamicLimits.MaxDeceleration);
  EXPECT_GE(data.DynamicDefaults.EmergencyDeceleration, data.DynamicLimits.MaxDeceleration);
}

// ---- accessors ----

// A valid value that differs from `current`.
double other_valid_value(const VariableInfo& info, double current) {
  if (info.type == kBool) return current == 0.0 ? 1.0 : 0.0;
  if (!info.allowed_values.empty()) {
    for (double v : info.allowed_values) {
      if (v != current) return v;
    }
  }
  if (info.type == kLreal) {
    const double lo = std::max(info.minimum, -1.0E12), hi = std::min(info.maximum, 1.0E12);
    const double v = lo + (hi - lo) * 0.3125;  // exact in binary for the ranges here
    return v != current ? v : lo;
  }
  return info.maximum != current ? info.maximum : info.minimum;
}

// spec 04 §1 (the structure map: one path, one member).
TEST(SpeedAxisVariables, RoundTripTouchesOnlyItsOwnMember) {
  const auto table = speed_axis_variables();
  for (const auto& info : table) {
    SCOPED_TRACE(std::string(info.path));
    SpeedAxisData data{};
    const SpeedAxisData untouched{};
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
      if (&other != &info) {
        EXPECT_EQ(other.read(data), other.read(untouched)) << "also changed " << other.path;
      }
    }
  }
}

// spec 04 §1 (the structure map: one path, one member).
TEST(SpeedAxisVariables, AccessorsReachTheNamedMember) {
  SpeedAxisData data{};
  ASSERT_EQ(must_find("DynamicDefaults.Velocity").write(data, 750.25), ValueError::kNone);
  EXPECT_EQ(data.DynamicDefaults.Velocity, 750.25);
  ASSERT_EQ(must_find("Actor.DriveParameter.ReferenceSpeed").write(data, 1500.0), ValueError::kNone);
  EXPECT_EQ(data.Actor.DriveParameter.ReferenceSpeed, 1500.0);
  ASSERT_EQ(must_find("Actor.Interface.TorqueDataAddressOut.OFFSET").write(data, 4294967295.0),
            ValueError::kNone);
  EXPECT_EQ(data.Actor.Interface.TorqueDataAddressOut.OFFSET, 4294967295u);  // UDINT exactly
  ASSERT_EQ(must_find("Actor.Interface.EnableTorqueData").write(data, 1.0), ValueError::kNone);
  EXPECT_TRUE(data.Actor.Interface.EnableTorqueData);
  ASSERT_EQ(must_find("LoadGear.Denominator").write(data, 7.0), ValueError::kNone);
  EXPECT_EQ(data.LoadGear.Denominator, 7u);

  data.StatusWord = 0xDEADBEEF;
  data.ErrorDetail.Reaction = 4;
  data.StatusDrive.CommunicationOK = true;
  data.ActualSpeed = -1234.5;
  EXPECT_EQ(must_find("StatusWord").read(data), 3735928559.0);
  EXPECT_EQ(must_find("ErrorDetail.Reaction").read(data), 4.0);
  EXPECT_EQ(must_find("StatusDrive.CommunicationOK").read(data), 1.0);
  EXPECT_EQ(must_find("ActualSpeed").read(data), -1234.5);
}

// spec 04 §0.4 (types and ranges: an invalid value changes nothing).
TEST(SpeedAxisVariables, InvalidValuesAreRejectedAndLeaveTheDataUnchanged) {
  struct Case {
    std::string path;
    double value;
    ValueError error;
  };
  const std::vector<Case> cases = {
      {"Override.Velocity", 200.0000001, ValueError::kOutOfRange},  // spec 04 §3.19: 0.0 ... 200.0 %
      {"Override.Velocity", -0.5, ValueError::kOutOfRange},
      {"Override.Velocity", std::nan(""), ValueError::kNotANumber},
      {"Actor.Efficiency", 1.01, ValueError::kOutOfRange},
      {"DynamicLimits.MaxJerk", 4629629.7, ValueError::kOutOfRange},
      {"DynamicDefaults.Acceleration", 2.8E8, ValueError::kOutOfRange},
      {"VelocitySetpoint", 1.1E12, ValueError::kOutOfRange},
      {"Velocity", std::numeric_limits<double>::infinity(), ValueError::kOutOfRange},
      {"LoadGear.Numerator", 0.0, ValueError::kOutOfRange},  // 1 ... 4294967295
      {"LoadGear.Numerator", 4294967296.0, ValueError::kOutOfRange},
      {"LoadGear.Numerator", 2.5, ValueError::kNotInteger},
      {"Simulation.Mode", 2.0, ValueError::kOutOfRange},
      {"Actor.InverseDirection", 0.5, ValueError::kNotBoolean},
      {"Actor.InverseDirection", 2.0, ValueError::kNotBoolean},
      {"Actor.RemoveEnableReaction", 2.0, ValueError::kNotAllowed},
      {"Actor.Interface.AddressIn.AREA", 256.0, ValueError::kOutOfRange},
      {"ErrorDetail.Reaction", 6.0, ValueError::kOutOfRange},
      {"StatusMotionIn.FunctionState", 2.0, ValueError::kOutOfRange},  // 2 = MotionInPosition: P only
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.path + " = " + std::to_string(c.value));
    const auto& info = must_find(c.path);
    SpeedAxisData data{};
    const double before = info.read(data);
    EXPECT_EQ(check_value(info, c.value), c.error);
    EXPECT_EQ(info.write(data, c.value), c.error);
    EXPECT_EQ(info.read(data), before);
  }
  EXPECT_FALSE(to_string(ValueError::kNotAllowed).empty());
}

// A data block of another TO type: the speed-axis accessors refuse it.
struct OtherDataBlock {
  static constexpr TechnologyObjectType kTechnologyObjectType = TechnologyObjectType::kPositioningAxis;
  double payload = 5.0;
};

// spec 04 §1 (the structure map: one path, one member).
TEST(SpeedAxisVariables, AccessorsRefuseAnotherDataBlock) {
  OtherDataBlock other;
  const auto& info = must_find("Override.Velocity");
  EXPECT_TRUE(std::isnan(info.read(other)));
  EXPECT_EQ(info.write(other, 50.0), ValueError::kWrongDataBlock);
  EXPECT_EQ(other.payload, 5.0);
}

// ---- access (spec 04 §0.2) ----

// spec 04 §0.2 (the W column), §0.3 (MC_WriteParameter).
TEST(SpeedAxisVariables, WriteAccessFollowsTheWColumn) {
  struct Case {
    std::string path;
    AccessError configuration, start_value, user_program;
  };
  using enum AccessError;
  const std::vector<Case> cases = {
      {"Override.Velocity", kNone, kNone, kNone},                    // DIR
      {"DynamicDefaults.Velocity", kNone, kNone, kNone},             // CAL
      {"DynamicLimits.MaxVelocity", kNone, kNone, kStartValueOnly},  // RES
      {"Actor.DriveParameter.ReferenceSpeed", kNone, kNone, kStartValueOnly},
      {"Simulation.Mode", kNone, kNone, kStartValueOnly},   // RES (RON in V2.0)
      {"VirtualAxis.Mode", kNone, kReadOnly, kReadOnly},    // RON, download only
      {"Units.VelocityUnit", kNone, kReadOnly, kReadOnly},  // RON configuration
      {"Actor.Interface.AddressIn.DB_NUMBER", kNone, kReadOnly, kReadOnly},
      {"Velocity", kStatusVariable, kStatusVariable, kStatusVariable},  // RON status
      {"StatusWord", kStatusVariable, kStatusVariable, kStatusVariable},
      {"ErrorDetail.Number", kStatusVariable, kStatusVariable, kStatusVariable},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.path);
    const auto& info = must_find(c.path);
    EXPECT_EQ(check_write_access(info, WriteContext::kConfiguration), c.configuration);
    EXPECT_EQ(check_write_access(info, WriteContext::kStartValue), c.start_value);
    EXPECT_EQ(check_write_access(info, WriteContext::kUserProgram), c.user_program);
  }
  // Table-wide: user code writes exactly the DIR and CAL variables.
  for (const auto& info : speed_axis_variables()) {
    const bool writable = check_write_access(info, WriteContext::kUserProgram) == kNone;
    EXPECT_EQ(writable, info.access == kDIR || info.access == kCAL) << info.path;
    if (info.role == kStatus) {
      EXPECT_EQ(info.access, kRON) << info.path;  // spec 04 §2, §4, §5: all RON
    }
  }
}

// spec 04 §0.3 (the MC_WriteParameter numbers).
TEST(SpeedAxisVariables, WriteParameterNumbers) {
  // spec 04 §0.3: 1020 Actor.RemoveEnableReaction (S, P, Y); 1000 is P/Y only; 1010-1012 are no DB variables
  const VariableInfo* info = find_by_write_parameter(speed_axis_variables(), 1020);
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->path, "Actor.RemoveEnableReaction");
  for (std::uint16_t n : {0, 1000, 1010, 1011, 1012}) {
    EXPECT_EQ(find_by_write_parameter(speed_axis_variables(), n), nullptr) << n;
  }
}

// ---- lookup ----

// spec 04 §1 (only the paths of the structure map).
TEST(SpeedAxisVariables, UnknownPathsAreRejected) {
  for (const char* path : {
           "",
           "DynamicDefaults",            // a structure, not a variable
           "Actor.Interface.AddressIn",  // a VREF: its members are the variables
           "dynamicdefaults.velocity",   // case-sensitive
           "DynamicDefaults.Velocity ",  // no trimming
           ".DynamicDefaults.Velocity",
           "DynamicDefaults.Velocity.X0",        // bit paths go through find_speed_axis_bit
           "Position",                           // P/Y only (spec 04 §2)
           "ActualVelocity",                     // the speed axis has none (spec 04 §14 item 12)
           "Actor.MotorType",                    // P only (spec 04 §3.3)
           "Actor.DriveParameter.MotorInertia",  // P only
           "Actor.LoadInertia",                  // P only
           "StatusTorqueData.ActualForce",       // P/Y only (spec 04 §4.7)
           "StatusMotionIn.StatusWord",          // P/Y only (spec 04 §4.8)
           "Units.LengthUnit",                   // P/Y, E only (spec 04 §3.11)
           "Units.InertiaUnit",                  // the manual prints IneritaUnit
           "PositionLimits_SW.Active",
           "Homing.HomePosition",
           "ControlPanel",  // internal (spec 04 §4.11)
           "InternalToTrace",
       }) {
    EXPECT_EQ(find_speed_axis_variable(path), nullptr) << '"' << path << '"';
  }
}

// spec 04 §5 (the bit words).
TEST(ParseBitPath, ValidAndInvalid) {
  EXPECT_EQ(parse_bit_path("StatusWord.X5"), (BitPath{"StatusWord", 5}));
  EXPECT_EQ(parse_bit_path("StatusWord.%X5"), (BitPath{"StatusWord", 5}));  // SCL slice (spec 04 §0.1)
  EXPECT_EQ(parse_bit_path("StatusWord.X0"), (BitPath{"StatusWord", 0}));
  EXPECT_EQ(parse_bit_path("StatusWord.X31"), (BitPath{"StatusWord", 31}));
  EXPECT_EQ(parse_bit_path("StatusInterpreterMotion.StatusWord.X1"),
            (BitPath{"StatusInterpreterMotion.StatusWord", 1}));
  for (const char* path :
       {"StatusWord.X32", "StatusWord.X99", "StatusWord.X100", "StatusWord.X", "StatusWord.X05",
        "StatusWord.x5", "StatusWord.X-1", "StatusWord.X+1", "StatusWord.Y5", "StatusWord.%5", "StatusWord.%",
        "StatusWord", "X5", ".X5", "StatusWord..X5", "StatusWord.X5 ", ""}) {
    EXPECT_EQ(parse_bit_path(path), std::nullopt) << '"' << path << '"';
  }
}

// spec 04 §5 (the bit words).
TEST(SpeedAxisBits, ResolveAgainstTheTable) {
  const auto done = find_speed_axis_bit("StatusWord.X6");
  ASSERT_TRUE(done.has_value());
  EXPECT_EQ(done->word->path, "StatusWord");
  EXPECT_EQ(done->bit, 6);
  EXPECT_TRUE(find_speed_axis_bit("WarningWord.X31").has_value());
  EXPECT_TRUE(find_speed_axis_bit("Actor.RemoveEnableReaction.X15").has_value());  // WORD: 16 bits
  EXPECT_FALSE(find_speed_axis_bit("Actor.RemoveEnableReaction.X16").has_value());
  EXPECT_TRUE(find_speed_axis_bit("Actor.Interface.AddressIn.AREA.X7").has_value());  // BYTE: 8 bits
  EXPECT_FALSE(find_speed_axis_bit("Actor.Interface.AddressIn.AREA.X8").has_value());
  EXPECT_FALSE(find_speed_axis_bit("Override.Velocity.X0").has_value());   // LREAL: no bits
  EXPECT_FALSE(find_speed_axis_bit("ErrorDetail.Number.X0").has_value());  // UDINT: no bits
  EXPECT_FALSE(find_speed_axis_bit("StatusWord.X32").has_value());
  EXPECT_FALSE(find_speed_axis_bit("StatusWord3.X0").has_value());
}

// spec 04 §5 (the bit words).
TEST(SpeedAxisBits, ReadAndWriteThroughTheWord) {
  SpeedAxisData data{};
  const auto done = find_speed_axis_bit("StatusWord.X6");
  ASSERT_TRUE(done.has_value());
  EXPECT_FALSE(done->read(data));
  ASSERT_EQ(done->write(data, true), ValueError::kNone);
  EXPECT_EQ(data.StatusWord, 1u << 6);
  EXPECT_TRUE(test(data.StatusWord, StatusWordBit::kDone));

  const auto top = find_speed_axis_bit("StatusWord.%X31");
  ASSERT_TRUE(top.has_value());
  ASSERT_EQ(top->write(data, true), ValueError::kNone);
  EXPECT_EQ(data.StatusWord, 0x80000040u);
  EXPECT_TRUE(top->read(data));
  ASSERT_EQ(done->write(data, false), ValueError::kNone);
  EXPECT_EQ(data.StatusWord, 0x80000000u);

  assign(data.StatusWord2, StatusWord2Bit::kStopCommand, true);
  EXPECT_TRUE(find_speed_axis_bit("StatusWord2.X0")->read(data));
  assign(data.ErrorWord, ErrorWordBit::kDriveFault, true);
  EXPECT_TRUE(find_speed_axis_bit("ErrorWord.X4")->read(data));
  EXPECT_FALSE(find_speed_axis_bit("ErrorWord.X5")->read(data));

  // A bit write that would make the word invalid is refused: RemoveEnableReaction 16#7 -> 16#6.
  const auto off1 = find_speed_axis_bit("Actor.RemoveEnableReaction.X0");
  ASSERT_TRUE(off1.has_value());
  EXPECT_EQ(off1->write(data, false), ValueError::kNotAllowed);
  EXPECT_EQ(data.Actor.RemoveEnableReaction, 0x7);
}

// spec 04 §0.4 (data types).
TEST(VariableType, NamesAndWidths) {
  EXPECT_EQ(to_string(kLreal), "LREAL");
  EXPECT_EQ(to_string(kDint), "DINT");
  EXPECT_EQ(to_string(kUdint), "UDINT");
  EXPECT_EQ(to_string(kDword), "DWORD");
  EXPECT_EQ(to_string(kDbAny), "DB_ANY");
  EXPECT_EQ(to_string(kRES), "RES");
  EXPECT_EQ(bit_width(kDword), 32u);
  EXPECT_EQ(bit_width(kWord), 16u);
  EXPECT_EQ(bit_width(kByte), 8u);
  EXPECT_EQ(bit_width(kUdint), 0u);
  EXPECT_FALSE(is_integer(kLreal));
  EXPECT_FALSE(is_integer(kBool));
  EXPECT_TRUE(is_integer(kUdint));
}

}  // namespace
}  // namespace tomc::techobjects
