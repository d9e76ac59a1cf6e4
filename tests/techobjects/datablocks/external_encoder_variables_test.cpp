// The TO_ExternalEncoder data block and its reflection table against spec 04 §2-§5 (column E) and man. §10.4.
// The expected table below is transcribed from the spec independently of the production table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "table_test_support.hpp"
#include "tomc/techobjects/datablocks/external_encoder_data.hpp"
#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {
namespace {

using namespace tomc::techobjects::testing;
using enum VariableType;
using enum Access;
using enum VariableRole;

std::vector<Expected> expected_external_encoder() {
  std::vector<Expected> rows = {
      // spec 04 §2, column E (man. §10.4.1): actual values only, RON
      {"ActualPosition", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualVelocity", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualAcceleration", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualModuloCycle", kDint, kRON, kDintMin, kDintMax, kStatus, 0, 0},
      // spec 04 §3.6, rows with TO "P,E" (a single Sensor; no Existent, Backlash, ActiveHoming,
      // MeasuringGear)
      {"Sensor.Type", kDint, kRON, 0, 2, kConfiguration, 0, 0},  // chosen: INCREMENTAL
      {"Sensor.InverseDirection", kBool, kRES, 0, 1, kConfiguration, 0, 0},
      {"Sensor.System", kDint, kRES, 0, 1, kConfiguration, 0, 1},        // chosen: ROTATORY
      {"Sensor.MountingMode", kDint, kRES, 0, 2, kConfiguration, 0, 1},  // chosen: load side
      {"Sensor.DataAdaption", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"Sensor.ActualVelocityMode", kDint, kRES, 0, 1, kConfiguration, 0, 0},
  };
  add_vref(rows, "Sensor.Interface.AddressIn", kRON);
  add_vref(rows, "Sensor.Interface.AddressOut", kRON);
  const std::vector<Expected> parameter = {
      {"Sensor.Interface.Number", kUdint, kRON, 1, 2, kConfiguration, 0, 1},
      // E prints -1.0E12 ... 1.0E12 (spec 04 §3.6, §14 item 9)
      {"Sensor.Parameter.Resolution", kLreal, kRES, -1.0E12, 1.0E12, kConfiguration, 0, 0.001},
      {"Sensor.Parameter.StepsPerRevolution", kUdint, kRES, 1, 8388608, kConfiguration, 0, 2048},
      {"Sensor.Parameter.FineResolutionXist1", kUdint, kRES, 0, 31, kConfiguration, 0, 11},
      {"Sensor.Parameter.FineResolutionXist2", kUdint, kRES, 0, 31, kConfiguration, 0, 9},
      {"Sensor.Parameter.DeterminableRevolutions", kUdint, kRES, 0, 8388608, kConfiguration, 0, 0},
      {"Sensor.Parameter.DistancePerRevolution", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 360.0},
      {"Sensor.Parameter.BehaviorGx_XIST1", kDint, kRES, 0, 1, kConfiguration, 0, 1},  // manual: default 1
      {"Sensor.Parameter.ReferenceSpeed", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {"Sensor.Parameter.ReferenceVelocity", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 500.0},
      {"Sensor.PassiveHoming.Mode", kDint, kRES, 0, 2, kConfiguration, 0, 0},
      {"Sensor.PassiveHoming.SideInput", kBool, kCAL, 0, 1, kConfiguration, 0, 1},  // printed "Sidelnput"
      {"Sensor.PassiveHoming.Direction", kDint, kCAL, 0, 2, kConfiguration, 0, 2},
  };
  rows.insert(rows.end(), parameter.begin(), parameter.end());
  add_vref(rows, "Sensor.PassiveHoming.DigitalInputAddress", kRON);
  rows.push_back({"Sensor.PassiveHoming.SwitchLevel", kBool, kRON, 0, 1, kConfiguration, 0, 1});  // E: RON
  add_cross_plc_interfaces(rows);  // spec 04 §3.7
  const std::vector<Expected> rest = {
      // spec 04 §3.8
      {"Extrapolation.LeadingAxisDependentTime", kLreal, kRON, kLrealMin, kLrealMax, kConfiguration, 0, 0.0},
      {"Extrapolation.FollowingAxisDependentTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"Extrapolation.Settings.SystemDefinedExtrapolation", kDint, kRES, 0, 1, kConfiguration, 0, 1},
      {"Extrapolation.Settings.ExtrapolatedVelocityMode", kDint, kRES, 0, 2, kConfiguration, 0, 0},
      {"Extrapolation.PositionFilter.T1", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"Extrapolation.PositionFilter.T2", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"Extrapolation.VelocityFilter.T1", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"Extrapolation.VelocityFilter.T2", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"Extrapolation.VelocityTolerance.Range", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"Extrapolation.Hysteresis.Value", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.9, §3.10
      {"LoadGear.Numerator", kUdint, kRES, 1, kUdintMax, kConfiguration, 0, 1},
      {"LoadGear.Denominator", kUdint, kRES, 1, kUdintMax, kConfiguration, 0, 1},
      {"Properties.MotionType", kDint, kRON, 0, 1, kConfiguration, 0, 1},  // chosen: rotary
      // spec 04 §3.11, column E: Length, Velocity, Time only
      {"Units.LengthUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1005},    // °
      {"Units.VelocityUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1521},  // °/s
      {"Units.TimeUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1054},
      // spec 04 §3.12, §3.13
      {"Mechanics.LeadScrew", kLreal, kRES, 1.0E-12, 1.0E12, kConfiguration, 0, 10.0},
      {"Modulo.Enable", kBool, kRES, 0, 1, kConfiguration, 0, 1},
      {"Modulo.Length", kLreal, kRES, 0.001, 1.0E12, kConfiguration, 0, 360.0},
      {"Modulo.StartValue", kLreal, kRES, -1.0E12, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.18 (E: HomePosition only), §3.26
      {"Homing.HomePosition", kLreal, kCAL, -1.0E12, 1.0E12, kConfiguration, 0, 0.0},
      {"StandstillSignal.VelocityThreshold", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 1.0},
      {"StandstillSignal.MinDwellTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.01},
      // spec 04 §4.4
      {"StatusProvidedLeadingValue.DelayedLeadingValue.Position", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0,
       0.0},
      {"StatusProvidedLeadingValue.DelayedLeadingValue.Velocity", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0,
       0.0},
      {"StatusProvidedLeadingValue.DelayedLeadingValue.Acceleration", kLreal, kRON, -1.0E12, 1.0E12, kStatus,
       0, 0.0},
      // spec 04 §4.5 (a single StatusSensor on E)
      {"StatusSensor.State", kDint, kRON, 0, 2, kStatus, 0, 0},
      {"StatusSensor.CommunicationOK", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusSensor.Error", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusSensor.AbsEncoderOffset", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"StatusSensor.Control", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusSensor.Position", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"StatusSensor.Velocity", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"StatusSensor.AdaptionState", kDint, kRON, 0, 4, kStatus, 0, 0},
      {"StatusSensor.ModuloCycle", kDint, kRON, kDintMin, kDintMax, kStatus, 0, 0},
      {"StatusSensor.Adjusted", kDint, kRON, 0, 1, kStatus, 0, 0},
      // spec 04 §4.6
      {"StatusExtrapolation.FilteredPosition", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusExtrapolation.FilteredVelocity", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusExtrapolation.ExtrapolatedPosition", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusExtrapolation.ExtrapolatedVelocity", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      // spec 04 §5 (no StatusWord2 on E) and §4.10 (E: Reaction 0 or 10)
      {"StatusWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorDetail.Number", kUdint, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorDetail.Reaction", kDint, kRON, 0, 10, kStatus, 0, 0},
      {"WarningWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
  };
  rows.insert(rows.end(), rest.begin(), rest.end());
  return rows;
}

const VariableInfo& must_find(std::string_view path) {
  const VariableInfo* info = find_external_encoder_variable(path);
  if (info == nullptr) throw std::runtime_error("missing " + std::string(path));
  return *info;
}

// spec 04 §2–§5 (column E), §0.2 (access), §0.4 (types and ranges).
TEST(ExternalEncoderVariables, EveryPathOfColumnEWithTypeAccessRangeAndStartValue) {
  expect_table_matches<ExternalEncoderData>(external_encoder_variables(), expected_external_encoder(),
                                            TechnologyObjectType::kExternalEncoder);
}

// spec 04 §3 (every start value within its own range).
TEST(ExternalEncoderVariables, EveryConfigurationStartValuePassesCheckValue) {
  const ExternalEncoderData defaults{};
  std::size_t configuration = 0;
  for (const auto& info : external_encoder_variables()) {
    if (info.role != kConfiguration) continue;
    ++configuration;
    EXPECT_EQ(check_value(info, info.read(defaults)), ValueError::kNone) << info.path;
  }
  EXPECT_GT(configuration, 200u);
}

// spec 04 §6.1 (the data-block enums: permitted values only).
TEST(ExternalEncoderVariables, PermittedValues) {
  // spec 04 §4.10 / §6.1: E reaction 0 none, 10 remove enable (as printed, §14 item 7)
  const auto& reaction = must_find("ErrorDetail.Reaction");
  EXPECT_EQ(check_value(reaction, 0.0), ValueError::kNone);
  EXPECT_EQ(check_value(reaction, 10.0), ValueError::kNone);
  for (double v : {1.0, 4.0, 5.0, 9.0})
    EXPECT_EQ(check_value(reaction, v), ValueError::kNotAllowed) << v;
  EXPECT_EQ(check_value(reaction, 11.0), ValueError::kOutOfRange);
  // spec 04 §3.11, column E
  const auto& length = must_find("Units.LengthUnit");
  EXPECT_EQ(length.allowed_values.size(), 12u);
  EXPECT_EQ(check_value(length, 1537), ValueError::kNone);  // ° high resolution
  const auto& velocity = must_find("Units.VelocityUnit");
  EXPECT_EQ(velocity.allowed_values.size(), 19u);
  EXPECT_EQ(check_value(velocity, 1075), ValueError::kNone);        // mi/h
  EXPECT_EQ(check_value(velocity, 1083), ValueError::kNotAllowed);  // 1/min: speed axis only
  EXPECT_EQ(must_find("Units.TimeUnit").allowed_values.size(), 1u);
}

// spec 04 §3 (the start values).
TEST(ExternalEncoderVariables, StartValuesInTheStruct) {
  const ExternalEncoderData data{};
  EXPECT_EQ(data.Sensor.Parameter.BehaviorGx_XIST1, 1);  // manual
  EXPECT_EQ(data.Sensor.Type, static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL));
  EXPECT_EQ(data.Sensor.Parameter.DeterminableRevolutions, 0u);
  EXPECT_EQ(data.Properties.MotionType, static_cast<std::int32_t>(PropertiesMotionType::kRotary));
  EXPECT_EQ(data.Units.LengthUnit, unit_code::kDegree);
  EXPECT_TRUE(data.Modulo.Enable);
  EXPECT_EQ(data.Modulo.Length, 360.0);
  EXPECT_EQ(data.ErrorDetail.Reaction, static_cast<std::int32_t>(ExternalEncoderReaction::kNone));
  EXPECT_EQ(static_cast<std::int32_t>(ExternalEncoderReaction::kRemoveEnable), 10);
}

// spec 04 §1 (the structure map: one path, one member).
TEST(ExternalEncoderVariables, RoundTripTouchesOnlyItsOwnMember) {
  expect_round_trips<ExternalEncoderData>(external_encoder_variables());
}

// spec 04 §0.4 (types and ranges: an invalid value changes nothing).
TEST(ExternalEncoderVariables, AccessorsAndInvalidValues) {
  ExternalEncoderData data{};
  ASSERT_EQ(must_find("Sensor.Parameter.StepsPerRevolution").write(data, 8388608.0), ValueError::kNone);
  EXPECT_EQ(data.Sensor.Parameter.StepsPerRevolution, 8388608u);
  ASSERT_EQ(must_find("Sensor.Parameter.Resolution").write(data, -0.5), ValueError::kNone);  // as printed
  EXPECT_EQ(data.Sensor.Parameter.Resolution, -0.5);
  ASSERT_EQ(must_find("CrossPlcSynchronousOperation.Interface[16].EnableLeadingValueOutput").write(data, 1.0),
            ValueError::kNone);
  EXPECT_TRUE(data.CrossPlcSynchronousOperation.Interface[15].EnableLeadingValueOutput);
  data.StatusSensor.State = static_cast<std::int32_t>(SensorState::VALID);
  EXPECT_EQ(must_find("StatusSensor.State").read(data), 2.0);

  const auto& steps = must_find("Sensor.Parameter.StepsPerRevolution");
  EXPECT_EQ(steps.write(data, 0.0), ValueError::kOutOfRange);
  EXPECT_EQ(must_find("Sensor.Parameter.Resolution").write(data, 1.5E12), ValueError::kOutOfRange);
  EXPECT_EQ(must_find("Modulo.Length").write(data, 0.0), ValueError::kOutOfRange);
  EXPECT_EQ(data.Sensor.Parameter.StepsPerRevolution, 8388608u);
  EXPECT_EQ(data.Modulo.Length, 360.0);

  // a positioning-axis accessor refuses the encoder's data block and vice versa
  PositioningAxisData axis{};
  EXPECT_EQ(must_find("Modulo.Length").write(axis, 720.0), ValueError::kWrongDataBlock);
  EXPECT_TRUE(std::isnan(find_positioning_axis_variable("Modulo.Length")->read(data)));
}

// spec 04 §0.2 (the W column), §0.3 (MC_WriteParameter).
TEST(ExternalEncoderVariables, WriteAccessAndNoWriteParameters) {
  using enum AccessError;
  EXPECT_EQ(check_write_access(must_find("Sensor.PassiveHoming.SwitchLevel"), WriteContext::kStartValue),
            kReadOnly);  // E: RON (P: RES)
  EXPECT_EQ(check_write_access(must_find("Sensor.PassiveHoming.Direction"), WriteContext::kUserProgram),
            kNone);  // CAL
  EXPECT_EQ(check_write_access(must_find("Sensor.Parameter.StepsPerRevolution"), WriteContext::kUserProgram),
            kStartValueOnly);  // RES
  EXPECT_EQ(check_write_access(must_find("StatusSensor.Position"), WriteContext::kConfiguration),
            kStatusVariable);
  // spec 04 §0.3: 1000 and 1020 are axis parameters; 1010-1012 are no DB variables
  for (const auto& info : external_encoder_variables()) {
    EXPECT_EQ(info.write_parameter, 0) << info.path;
    if (info.role == kStatus) {
      EXPECT_EQ(info.access, kRON) << info.path;
    }
  }
}

// spec 04 §1 (only the paths of the structure map).
TEST(ExternalEncoderVariables, UnknownPathsAreRejected) {
  for (const char* path : {
           "Sensor[1].Type",  // a single structure on E (man. §10.4.2)
           "Sensor[0].Type",
           "StatusSensor[1].State",
           "Sensor.Existent",  // P only
           "Sensor.Backlash.Enable",
           "Sensor.ActiveHoming.Mode",
           "Sensor.MeasuringGear.Numerator",
           "Position",  // setpoints: not on E (spec 04 §2)
           "Velocity",
           "OperativeSensor",
           "StatusWord2",  // not on E (spec 04 §5.2)
           "Units.TorqueUnit",
           "Homing.ApproachVelocity",
           "Actor.Type",
           "DynamicLimits.MaxVelocity",
           "CrossPlcSynchronousOperation.Interface[33].AddressOut.RID",
           "InternalToTrace",
       }) {
    EXPECT_EQ(find_external_encoder_variable(path), nullptr) << '"' << path << '"';
  }
  EXPECT_EQ(array_upper_bound(external_encoder_variables(), "CrossPlcSynchronousOperation.Interface"), 32u);
}

// spec 04 §5 (the bit words).
TEST(ExternalEncoderBits, ResolveAgainstTheTable) {
  ExternalEncoderData data{};
  const auto standstill = find_external_encoder_bit("StatusWord.X7");
  ASSERT_TRUE(standstill.has_value());
  ASSERT_EQ(standstill->write(data, true), ValueError::kNone);
  EXPECT_TRUE(test(data.StatusWord, StatusWordBit::kStandstill));
  assign(data.ErrorWord, ErrorWordBit::kSensorFault, true);
  EXPECT_TRUE(find_external_encoder_bit("ErrorWord.X5")->read(data));
  EXPECT_TRUE(find_external_encoder_bit("WarningWord.X31").has_value());
  EXPECT_FALSE(find_external_encoder_bit("StatusWord2.X0").has_value());
}

}  // namespace
}  // namespace tomc::techobjects
