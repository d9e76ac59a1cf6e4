// The TO_PositioningAxis data block and its reflection table against spec 04 §2-§5 (column P/Y) and man.
// §10.3. The expected table below is transcribed from the spec independently of the production table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "table_test_support.hpp"
#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {
namespace {

using namespace tomc::techobjects::testing;
using enum VariableType;
using enum Access;
using enum VariableRole;

// spec 04 §3.6, rows with TO "P" or "P,E" (P ranges and W), for Sensor[n].
void add_sensor(std::vector<Expected>& rows, int n) {
  const std::string s = "Sensor[" + std::to_string(n) + "].";
  const double existent = n == 1 ? 1 : 0;  // chosen: only encoder 1 configured
  const std::vector<Expected> head = {
      {s + "Existent", kBool, kRON, 0, 1, kConfiguration, 0, existent},
      {s + "Type", kDint, kRON, 0, 2, kConfiguration, 0, 0},  // chosen: INCREMENTAL
      {s + "InverseDirection", kBool, kRES, 0, 1, kConfiguration, 0, 0},
      {s + "System", kDint, kRES, 0, 1, kConfiguration, 0, 1},        // chosen: ROTATORY
      {s + "MountingMode", kDint, kRES, 0, 2, kConfiguration, 0, 0},  // chosen: motor shaft
      {s + "DataAdaption", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {s + "ActualVelocityMode", kDint, kRES, 0, 1, kConfiguration, 0, 0},
  };
  rows.insert(rows.end(), head.begin(), head.end());
  add_vref(rows, s + "Interface.AddressIn", kRON);
  add_vref(rows, s + "Interface.AddressOut", kRON);
  const std::vector<Expected> parameter = {
      {s + "Interface.Number", kUdint, kRON, 1, 2, kConfiguration, 0, 1},
      {s + "Parameter.Resolution", kLreal, kRES, 1.0E-12, 1.0E12, kConfiguration, 0, 0.001},
      {s + "Parameter.StepsPerRevolution", kUdint, kRES, 1, 8388608, kConfiguration, 0, 2048},
      {s + "Parameter.FineResolutionXist1", kUdint, kRES, 0, 31, kConfiguration, 0, 11},
      {s + "Parameter.FineResolutionXist2", kUdint, kRES, 0, 31, kConfiguration, 0, 9},
      {s + "Parameter.DeterminableRevolutions", kUdint, kRES, 0, 8388608, kConfiguration, 0,
       0},  // incremental
      {s + "Parameter.DistancePerRevolution", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 10.0},
      {s + "Parameter.BehaviorGx_XIST1", kDint, kRES, 0, 1, kConfiguration, 0, 1},  // manual: default 1
      {s + "Parameter.ReferenceSpeed", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {s + "Parameter.ReferenceVelocity", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 500.0},
      {s + "Backlash.Enable", kBool, kDIR, 0, 1, kConfiguration, 0, 0},
      {s + "Backlash.Size", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {s + "Backlash.Velocity", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {s + "Backlash.DirectionAbsoluteHoming", kDint, kDIR, 0, 1, kConfiguration, 0, 0},
      {s + "ActiveHoming.Mode", kDint, kRES, 0, 2, kConfiguration, 0, 0},
      {s + "ActiveHoming.SideInput", kBool, kCAL, 0, 1, kConfiguration, 0, 1},  // printed "SidelInput"
      {s + "ActiveHoming.Direction", kDint, kCAL, 0, 1, kConfiguration, 0, 0},
  };
  rows.insert(rows.end(), parameter.begin(), parameter.end());
  add_vref(rows, s + "ActiveHoming.DigitalInputAddress", kRON);
  const std::vector<Expected> homing = {
      {s + "ActiveHoming.HomePositionOffset", kLreal, kCAL, -1.0E12, 1.0E12, kConfiguration, 0, 0.0},
      {s + "ActiveHoming.SwitchLevel", kBool, kRES, 0, 1, kConfiguration, 0, 1},
      {s + "PassiveHoming.Mode", kDint, kRES, 0, 2, kConfiguration, 0, 0},
      {s + "PassiveHoming.SideInput", kBool, kCAL, 0, 1, kConfiguration, 0, 1},
      {s + "PassiveHoming.Direction", kDint, kCAL, 0, 2, kConfiguration, 0, 2},  // current direction
  };
  rows.insert(rows.end(), homing.begin(), homing.end());
  add_vref(rows, s + "PassiveHoming.DigitalInputAddress", kRON);
  const std::vector<Expected> tail = {
      {s + "PassiveHoming.SwitchLevel", kBool, kRES, 0, 1, kConfiguration, 0, 1},
      {s + "MeasuringGear.Numerator", kUdint, kRES, 1, kUdintMax, kConfiguration, 0, 1},  // manual: default 1
      {s + "MeasuringGear.Denominator", kUdint, kRES, 1, kUdintMax, kConfiguration, 0, 1},
  };
  rows.insert(rows.end(), tail.begin(), tail.end());
}

// spec 04 §4.5 StatusSensor[n], RON.
void add_status_sensor(std::vector<Expected>& rows, int n) {
  const std::string s = "StatusSensor[" + std::to_string(n) + "].";
  const std::vector<Expected> r = {
      {s + "State", kDint, kRON, 0, 2, kStatus, 0, 0},
      {s + "CommunicationOK", kBool, kRON, 0, 1, kStatus, 0, 0},
      {s + "Error", kBool, kRON, 0, 1, kStatus, 0, 0},
      {s + "AbsEncoderOffset", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {s + "Control", kBool, kRON, 0, 1, kStatus, 0, 0},
      {s + "Position", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {s + "Velocity", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {s + "AdaptionState", kDint, kRON, 0, 4, kStatus, 0, 0},
      {s + "ModuloCycle", kDint, kRON, kDintMin, kDintMax, kStatus, 0, 0},
      {s + "Adjusted", kDint, kRON, 0, 1, kStatus, 0, 0},
  };
  rows.insert(rows.end(), r.begin(), r.end());
}

std::vector<Expected> expected_positioning_axis() {
  std::vector<Expected> rows = {
      // spec 04 §2 (man. §10.3.1): all RON, "-" = data-type limits
      {"Position", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"Velocity", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualPosition", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualVelocity", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualSpeed", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"Acceleration", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"ActualAcceleration", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"OperativeSensor", kUdint, kRON, 1, 4, kStatus, 0, 1},  // 1...4: starts at 1
      {"ModuloCycle", kDint, kRON, kDintMin, kDintMax, kStatus, 0, 0},
      {"ActualModuloCycle", kDint, kRON, kDintMin, kDintMax, kStatus, 0, 0},
      {"VelocitySetpoint", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      // spec 04 §3.1, §3.2
      {"Simulation.Mode", kUdint, kRES, 0, 1, kConfiguration, 0, 0},
      {"VirtualAxis.Mode", kUdint, kRON, 0, 1, kConfiguration, 0, 0},
      // spec 04 §3.3 (rows with TO "S,P" and "P")
      {"Actor.Type", kDint, kRON, 0, 1, kConfiguration, 0, 1},
      {"Actor.InverseDirection", kBool, kRES, 0, 1, kConfiguration, 0, 0},
      {"Actor.DataAdaption", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"Actor.Efficiency", kLreal, kRES, 0.0, 1.0, kConfiguration, 0, 1.0},
      {"Actor.MotorType", kDint, kDL, 0, 1, kConfiguration, 0, 0},
      {"Actor.LoadInertia", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 79.0},
      {"Actor.RemoveEnableReaction", kWord, kRES, 0x0, 0x7, kConfiguration, 1020, 0x7},  // manual: 16#7
  };
  add_vref(rows, "Actor.Interface.AddressIn", kRON);
  add_vref(rows, "Actor.Interface.AddressOut", kRON);
  rows.push_back({"Actor.Interface.EnableDriveOutput", kBool, kRES, 0, 1, kConfiguration, 0, 0});
  add_vref(rows, "Actor.Interface.EnableDriveOutputAddress", kRON);
  rows.push_back({"Actor.Interface.DriveReadyInput", kBool, kRES, 0, 1, kConfiguration, 0, 0});
  add_vref(rows, "Actor.Interface.DriveReadyInputAddress", kRON);
  rows.push_back({"Actor.Interface.EnableTorqueData", kBool, kRES, 0, 1, kConfiguration, 0, 0});
  add_vref(rows, "Actor.Interface.TorqueDataAddressIn", kRON);
  add_vref(rows, "Actor.Interface.TorqueDataAddressOut", kRON);
  const std::vector<Expected> actor = {
      {"Actor.DriveParameter.ReferenceSpeed", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {"Actor.DriveParameter.MaxSpeed", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 3000.0},
      {"Actor.DriveParameter.ReferenceTorque", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 4.0},
      {"Actor.DriveParameter.MotorInertia", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 1.0E-4},
      {"Actor.LinearMotorDriveParameter.ReferenceVelocity", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0,
       500.0},
      {"Actor.LinearMotorDriveParameter.MaxVelocity", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 500.0},
      {"Actor.LinearMotorDriveParameter.ReferenceForce", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0,
       2500.0},
      {"Actor.LinearMotorDriveParameter.MotorMass", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 1.0},
      // spec 04 §3.4 (P table prints PositionBasedMonitors, §14 item 4)
      {"TorqueLimiting.LimitBase", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"TorqueLimiting.PositionBasedMonitorings", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"TorqueLimiting.LimitDefaults.Torque", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 4.0},
      {"TorqueLimiting.LimitDefaults.Force", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 2500.0},
      // spec 04 §3.5
      {"Clamping.FollowingErrorDeviation", kLreal, kDIR, 0.001, 1.0E12, kConfiguration, 0, 1.0},
      {"Clamping.PositionTolerance", kLreal, kDIR, 0.001, 1.0E12, kConfiguration, 0, 0.5},
  };
  rows.insert(rows.end(), actor.begin(), actor.end());
  for (int n = 1; n <= 4; ++n)
    add_sensor(rows, n);           // spec 04 §3.6
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
      {"Properties.MotionType", kDint, kRON, 0, 1, kConfiguration, 0, 0},  // chosen: linear
      // spec 04 §3.11, P/Y column, all RON UDINT codes
      {"Units.LengthUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1013},    // mm
      {"Units.VelocityUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1062},  // mm/s
      {"Units.TimeUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1054},
      {"Units.TorqueUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1126},
      {"Units.ForceUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1120},
      {"Units.MassUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1088},
      {"Units.IneritaUnit", kUdint, kRON, 0, kUdintMax, kConfiguration, 0, 1118},
      // spec 04 §3.12, §3.13
      {"Mechanics.LeadScrew", kLreal, kRES, 1.0E-12, 1.0E12, kConfiguration, 0, 10.0},
      {"Modulo.Enable", kBool, kRES, 0, 1, kConfiguration, 0, 0},
      {"Modulo.Length", kLreal, kRES, 0.001, 1.0E12, kConfiguration, 0, 360.0},
      {"Modulo.StartValue", kLreal, kRES, -1.0E12, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.14, column "Range P/Y"
      {"DynamicLimits.MaxVelocity", kLreal, kRES, 0.0, 1.0E12, kConfiguration, 0, 500.0},
      {"DynamicLimits.Velocity", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 500.0},
      {"DynamicLimits.MaxAcceleration", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 5000.0},
      {"DynamicLimits.MaxDeceleration", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 5000.0},
      {"DynamicLimits.MaxJerk", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 100000.0},
      // spec 04 §3.15, column "Range P/Y"
      {"DynamicDefaults.Velocity", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 100.0},
      {"DynamicDefaults.Acceleration", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 1000.0},
      {"DynamicDefaults.Deceleration", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 1000.0},
      {"DynamicDefaults.Jerk", kLreal, kCAL, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"DynamicDefaults.EmergencyDeceleration", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 10000.0},
      // spec 04 §3.16
      {"PositionLimits_SW.Active", kBool, kDIR, 0, 1, kConfiguration, 0, 0},
      {"PositionLimits_SW.MinPosition", kLreal, kDIR, -1.0E12, 1.0E12, kConfiguration, 0, -1000.0},
      {"PositionLimits_SW.MaxPosition", kLreal, kDIR, -1.0E12, 1.0E12, kConfiguration, 0, 1000.0},
      {"PositionLimits_SW.LimitReachedBehavior", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"PositionLimits_SW.LimitExceededBehavior", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      // spec 04 §3.17 (+ §0.3: WP 1000)
      {"PositionLimits_HW.Active", kBool, kRES, 0, 1, kConfiguration, 1000, 0},
      {"PositionLimits_HW.MinSwitchLevel", kBool, kRES, 0, 1, kConfiguration, 0, 0},
  };
  rows.insert(rows.end(), rest.begin(), rest.end());
  add_vref(rows, "PositionLimits_HW.MinSwitchAddress", kRES);  // RES, not RON
  rows.push_back({"PositionLimits_HW.MaxSwitchLevel", kBool, kRES, 0, 1, kConfiguration, 0, 0});
  add_vref(rows, "PositionLimits_HW.MaxSwitchAddress", kRES);
  const std::vector<Expected> rest2 = {
      {"PositionLimits_HW.Mode", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"PositionLimits_HW.ApproachBehavior", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      // spec 04 §3.18: L 0...10000 mm/s / R 0...360000 °/s; L 0...1000 mm/s / R 0...36000 °/s -> union
      {"Homing.AutoReversal", kBool, kRES, 0, 1, kConfiguration, 0, 0},
      {"Homing.ApproachDirection", kBool, kCAL, 0, 1, kConfiguration, 0, 0},
      {"Homing.ApproachVelocity", kLreal, kCAL, 0.0, 360000.0, kConfiguration, 0, 20.0},
      {"Homing.ReferencingVelocity", kLreal, kCAL, 0.0, 36000.0, kConfiguration, 0, 5.0},
      {"Homing.HomePosition", kLreal, kCAL, -1.0E12, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.19
      {"Override.Velocity", kLreal, kDIR, 0.0, 200.0, kConfiguration, 0, 100.0},
      // spec 04 §3.20
      {"PositionControl.Kv", kLreal, kDIR, 0.0, 2147480.0, kConfiguration, 0, 50.0},
      {"PositionControl.Kpc", kLreal, kDIR, 0.0, 150.0, kConfiguration, 0, 100.0},  // manual recommendation
      {"PositionControl.EnableDSC", kBool, kRES, 0, 1, kConfiguration, 0, 0},
      {"PositionControl.SmoothingTimeByChangeDifference", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"PositionControl.InitialOperativeSensor", kUdint, kRES, 1, 4, kConfiguration, 0, 1},
      {"PositionControl.ControlDifferenceQuantization.Mode", kDint, kRES, 0, 2, kConfiguration, 0, 0},
      {"PositionControl.ControlDifferenceQuantization.Value", kLreal, kRES, 0.001, 1.0E12, kConfiguration, 0,
       0.001},
      {"PositionControl.VelocityModePowerOn", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      // not in the manual: the PID option of issue 20 (a tomc extension, docs/analog-drives.md), all 0 = off
      {"PositionControl.Pid.IntegralTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"PositionControl.Pid.DerivativeTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"PositionControl.Pid.DerivativeCycles", kUdint, kDIR, 1, 256, kConfiguration, 0, 1},
      {"PositionControl.Pid.IntegralLimit", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"PositionControl.Pid.DeadBand", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"PositionControl.Pid.OutputLimit", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.21
      {"TorquePreControl.Mode", kDint, kRES, 0, 1, kConfiguration, 0, 0},
      {"TorquePreControl.Scale", kLreal, kDIR, 0.0, 150.0, kConfiguration, 0, 100.0},
      // spec 04 §3.22 (manual: filter off, T1 = T2 = Tt = 0)
      {"SetpointFilter.DynamicFilter.Mode", kDint, kRES, 0, 2, kConfiguration, 0, 0},
      {"SetpointFilter.DynamicFilter.T1", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"SetpointFilter.DynamicFilter.T2", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"SetpointFilter.DynamicFilter.Tt", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.23
      {"DynamicAxisModel.VelocityTimeConstant", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.002},
      {"DynamicAxisModel.AdditionalPositionTimeConstant", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      {"DynamicAxisModel.CurrentTimeConstant", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.24: Min/MaxValue L 0.0..., R 0.001... / 0.002... -> union from 0.0
      {"FollowingError.EnableMonitoring", kBool, kRES, 0, 1, kConfiguration, 0, 1},
      {"FollowingError.MinValue", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 2.0},
      {"FollowingError.MaxValue", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 10.0},
      {"FollowingError.MinVelocity", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 10.0},
      {"FollowingError.WarningLevel", kLreal, kDIR, 0.0, 100.0, kConfiguration, 0, 90.0},
      {"FollowingError.AdditionalSetpointDelayTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.0},
      // spec 04 §3.25
      {"PositioningMonitoring.ToleranceTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 1.0},
      {"PositioningMonitoring.MinDwellTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.01},
      {"PositioningMonitoring.Window", kLreal, kDIR, 0.001, 1.0E12, kConfiguration, 0, 0.01},
      // spec 04 §3.26
      {"StandstillSignal.VelocityThreshold", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 1.0},
      {"StandstillSignal.MinDwellTime", kLreal, kDIR, 0.0, 1.0E12, kConfiguration, 0, 0.01},
      // spec 04 §4.1
      {"StatusPositioning.Distance", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusPositioning.TargetPosition", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusPositioning.TargetPositionModuloCycle", kDint, kRON, kDintMin, kDintMax, kStatus, 0, 0},
      {"StatusPositioning.FollowingError", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusPositioning.SetpointExecutionTime", kLreal, kRON, 0.0, 1.0E12, kStatus, 0, 0.0},
      {"StatusPositioning.SuperimposedDistance", kLreal, kRON, 0.0, 1.0E12, kStatus, 0, 0.0},
      // spec 04 §4.2
      {"StatusDrive.InOperation", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusDrive.CommunicationOK", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusDrive.Error", kBool, kRON, 0, 1, kStatus, 0, 0},
      {"StatusDrive.AdaptionState", kDint, kRON, 0, 4, kStatus, 0, 0},
      // spec 04 §4.3 (no range)
      {"StatusServo.BalancedPosition", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"StatusServo.ControlDifference", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      {"StatusServo.PositionAfterDynamicFilter", kLreal, kRON, kLrealMin, kLrealMax, kStatus, 0, 0.0},
      // spec 04 §4.4
      {"StatusProvidedLeadingValue.DelayedLeadingValue.Position", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0,
       0.0},
      {"StatusProvidedLeadingValue.DelayedLeadingValue.Velocity", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0,
       0.0},
      {"StatusProvidedLeadingValue.DelayedLeadingValue.Acceleration", kLreal, kRON, -1.0E12, 1.0E12, kStatus,
       0, 0.0},
  };
  rows.insert(rows.end(), rest2.begin(), rest2.end());
  for (int n = 1; n <= 4; ++n)
    add_status_sensor(rows, n);  // spec 04 §4.5
  const std::vector<Expected> status = {
      // spec 04 §4.6
      {"StatusExtrapolation.FilteredPosition", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusExtrapolation.FilteredVelocity", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusExtrapolation.ExtrapolatedPosition", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusExtrapolation.ExtrapolatedVelocity", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      // spec 04 §5.5
      {"StatusKinematicsMotion", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      // spec 04 §4.7 (all six members on P/Y)
      {"StatusTorqueData.CommandAdditiveTorqueActive", kDint, kRON, 0, 1, kStatus, 0, 0},
      {"StatusTorqueData.CommandTorqueRangeActive", kDint, kRON, 0, 1, kStatus, 0, 0},
      {"StatusTorqueData.ActualTorque", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusTorqueData.ActualForce", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusTorqueData.TotalTorqueAdditive", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      {"StatusTorqueData.TotalForceAdditive", kLreal, kRON, -1.0E12, 1.0E12, kStatus, 0, 0.0},
      // spec 04 §4.8 (P: 0...2)
      {"StatusMotionIn.FunctionState", kDint, kRON, 0, 2, kStatus, 0, 0},
      {"StatusMotionIn.ActualSuperimposingAxis", kDbAny, kRON, 0, 65535, kStatus, 0, 0},
      {"StatusMotionIn.StatusWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      // spec 04 §4.9
      {"StatusInterpreterMotion.Interpreter", kDbAny, kRON, 0, 65535, kStatus, 0, 0},
      {"StatusInterpreterMotion.StatusWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      // spec 04 §5 and §4.10
      {"StatusWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"StatusWord2", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorDetail.Number", kUdint, kRON, 0, kUdintMax, kStatus, 0, 0},
      {"ErrorDetail.Reaction", kDint, kRON, 0, 5, kStatus, 0, 0},
      {"WarningWord", kDword, kRON, 0, kUdintMax, kStatus, 0, 0},
  };
  rows.insert(rows.end(), status.begin(), status.end());
  return rows;
}

const VariableInfo& must_find(std::string_view path) {
  const VariableInfo* info = find_positioning_axis_variable(path);
  if (info == nullptr) throw std::runtime_error("missing " + std::string(path));
  return *info;
}

// ---- the table against the spec ----

// spec 04 §2–§5 (column P), §0.2 (access), §0.4 (types and ranges).
TEST(PositioningAxisVariables, EveryPathOfColumnPWithTypeAccessRangeAndStartValue) {
  const auto expected = expected_positioning_axis();
  expect_table_matches<PositioningAxisData>(positioning_axis_variables(), expected,
                                            TechnologyObjectType::kPositioningAxis);
  // 4 rows per sensor leaf: 48 rows per Sensor element (a VREF as 4), 10 per StatusSensor element
  std::size_t sensor_rows = 0, status_sensor_rows = 0, cross_plc_rows = 0;
  for (const auto& info : positioning_axis_variables()) {
    sensor_rows += info.path.starts_with("Sensor[");
    status_sensor_rows += info.path.starts_with("StatusSensor[");
    cross_plc_rows += info.path.starts_with("CrossPlcSynchronousOperation.Interface[");
  }
  EXPECT_EQ(sensor_rows, 4u * 48u);
  EXPECT_EQ(status_sensor_rows, 4u * 10u);
  EXPECT_EQ(cross_plc_rows, 32u * 6u);
}

// spec 04 §3 (every start value within its own range).
TEST(PositioningAxisVariables, EveryConfigurationStartValuePassesCheckValue) {
  const PositioningAxisData defaults{};
  std::size_t configuration = 0;
  for (const auto& info : positioning_axis_variables()) {
    if (info.role != kConfiguration) continue;
    ++configuration;
    EXPECT_EQ(check_value(info, info.read(defaults)), ValueError::kNone) << info.path;
    EXPECT_EQ(check_write_access(info, WriteContext::kConfiguration), AccessError::kNone) << info.path;
  }
  EXPECT_GT(configuration, 400u);
}

// spec 04 §6.1 (the data-block enums: permitted values only).
TEST(PositioningAxisVariables, PermittedValues) {
  // spec 04 §3.3 / §6.1: 16#1, 16#3, 16#5, 16#7; 16#0/2/4/6 invalid
  const auto& reaction = must_find("Actor.RemoveEnableReaction");
  for (double v : {1.0, 3.0, 5.0, 7.0})
    EXPECT_EQ(check_value(reaction, v), ValueError::kNone) << v;
  for (double v : {0.0, 2.0, 4.0, 6.0})
    EXPECT_EQ(check_value(reaction, v), ValueError::kNotAllowed) << v;

  // spec 04 §3.11, P/Y column (man. §10.3.12)
  const std::vector<std::pair<std::string, std::vector<double>>> units = {
      {"Units.LengthUnit", {1010, 1013, 1536, 1011, 1014, 1015, 1019, 1018, 1021, 1004, 1005, 1537}},
      {"Units.VelocityUnit",
       {1521, 1539, 1522, 1086, 1523, 1062, 1538, 1061, 1524, 1525, 1526, 1063, 1527, 1064, 1066, 1069, 1067,
        1070, 1075}},
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
    EXPECT_EQ(check_value(info, 1083), ValueError::kNotAllowed);  // 1/min: a speed-axis code only
  }
  EXPECT_EQ(unit_code::kMillimetrePerMinute, 1524u);  // printed "m/min" (spec 04 §14 item 5)
  for (const auto& info : positioning_axis_variables()) {
    if (info.path == "Actor.RemoveEnableReaction" || info.path.starts_with("Units.")) continue;
    EXPECT_TRUE(info.allowed_values.empty()) << info.path;
  }
}

// spec 04 §3 (the start values).
TEST(PositioningAxisVariables, StartValuesInTheStruct) {
  const PositioningAxisData data{};
  // manual
  EXPECT_EQ(data.Actor.RemoveEnableReaction, 0x7);
  EXPECT_EQ(data.Sensor[0].Parameter.BehaviorGx_XIST1, 1);
  EXPECT_EQ(data.Sensor[0].MeasuringGear.Numerator, 1u);
  EXPECT_EQ(data.SetpointFilter.DynamicFilter.Mode, static_cast<std::int32_t>(DynamicFilterMode::kOff));
  // chosen: consistent with the simulated drive (docs/simulated-drive.md)
  EXPECT_TRUE(data.Sensor[0].Existent);
  for (std::size_t i = 1; i < data.Sensor.size(); ++i)
    EXPECT_FALSE(data.Sensor[i].Existent) << i;
  EXPECT_EQ(data.Sensor[0].Type, static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL));
  EXPECT_EQ(data.Sensor[0].Parameter.DeterminableRevolutions, 0u);  // incremental (spec 04 §3.6)
  EXPECT_EQ(data.Sensor[0].Parameter.StepsPerRevolution, 2048u);
  EXPECT_EQ(data.Sensor[0].Parameter.FineResolutionXist1, 11u);
  EXPECT_EQ(data.Sensor[0].Parameter.FineResolutionXist2, 9u);
  EXPECT_EQ(data.Properties.MotionType, static_cast<std::int32_t>(PropertiesMotionType::kLinear));
  EXPECT_EQ(data.Units.LengthUnit, unit_code::kMillimetre);
  EXPECT_EQ(data.Mechanics.LeadScrew, 10.0);
  // MaxVelocity = MaxSpeed [1/min] / 60 x LeadScrew x LoadGear Denominator/Numerator
  EXPECT_DOUBLE_EQ(data.DynamicLimits.MaxVelocity, data.Actor.DriveParameter.MaxSpeed / 60.0 *
                                                       data.Mechanics.LeadScrew * data.LoadGear.Denominator /
                                                       data.LoadGear.Numerator);
  // rules of spec 04 §3.3, §3.5, §3.14, §3.15, §3.16, §3.24
  EXPECT_LE(data.Actor.DriveParameter.MaxSpeed, 2.0 * data.Actor.DriveParameter.ReferenceSpeed);
  EXPECT_LE(data.DynamicDefaults.Velocity, data.DynamicLimits.MaxVelocity);
  EXPECT_LE(data.DynamicDefaults.Acceleration, data.DynamicLimits.MaxAcceleration);
  EXPECT_LE(data.DynamicDefaults.Deceleration, data.DynamicLimits.MaxDeceleration);
  EXPECT_GE(data.DynamicDefaults.EmergencyDeceleration, data.DynamicLimits.MaxDeceleration);
  EXPECT_LT(data.PositionLimits_SW.MinPosition, data.PositionLimits_SW.MaxPosition);
  EXPECT_LT(data.Clamping.PositionTolerance, data.Clamping.FollowingErrorDeviation);
  EXPECT_LT(data.Clamping.FollowingErrorDeviation, data.FollowingError.MinValue);
  EXPECT_LE(data.FollowingError.MinValue, data.FollowingError.MaxValue);
  // the linear Homing limits (10000 / 1000 mm/s) hold for the linear default axis
  EXPECT_LE(data.Homing.ApproachVelocity, 10000.0);
  EXPECT_LE(data.Homing.ReferencingVelocity, 1000.0);
  // ErrorDetail.Reaction 0 ... 5 is the alarm model's range
  EXPECT_EQ(must_find("ErrorDetail.Reaction").maximum, static_cast<double>(AlarmReaction::kFollowSetpoint));
}

// ---- accessors ----

// spec 04 §1 (the structure map: one path, one member).
TEST(PositioningAxisVariables, RoundTripTouchesOnlyItsOwnMember) {
  expect_round_trips<PositioningAxisData>(positioning_axis_variables());
}

// spec 04 §1 (the structure map: one path, one member).
TEST(PositioningAxisVariables, ArrayPathsReachTheOneBasedElement) {
  PositioningAxisData data{};
  ASSERT_EQ(must_find("Sensor[1].Parameter.StepsPerRevolution").write(data, 4096.0), ValueError::kNone);
  EXPECT_EQ(data.Sensor[0].Parameter.StepsPerRevolution, 4096u);
  ASSERT_EQ(must_find("Sensor[4].Parameter.StepsPerRevolution").write(data, 1000.0), ValueError::kNone);
  EXPECT_EQ(data.Sensor[3].Parameter.StepsPerRevolution, 1000u);
  EXPECT_EQ(data.Sensor[1].Parameter.StepsPerRevolution, 2048u);
  EXPECT_EQ(data.Sensor[2].Parameter.StepsPerRevolution, 2048u);
  ASSERT_EQ(must_find("Sensor[3].ActiveHoming.DigitalInputAddress.OFFSET").write(data, 4294967295.0),
            ValueError::kNone);
  EXPECT_EQ(data.Sensor[2].ActiveHoming.DigitalInputAddress.OFFSET, 4294967295u);
  ASSERT_EQ(must_find("CrossPlcSynchronousOperation.Interface[32].TelegramVersion").write(data, 2.0),
            ValueError::kNone);
  EXPECT_EQ(data.CrossPlcSynchronousOperation.Interface[31].TelegramVersion, 2);
  ASSERT_EQ(must_find("CrossPlcSynchronousOperation.Interface[1].AddressOut.AREA").write(data, 132.0),
            ValueError::kNone);
  EXPECT_EQ(data.CrossPlcSynchronousOperation.Interface[0].AddressOut.AREA, 132);

  data.StatusSensor[1].State = static_cast<std::int32_t>(SensorState::VALID);
  data.StatusSensor[3].AbsEncoderOffset = 137.812;
  EXPECT_EQ(must_find("StatusSensor[2].State").read(data), 2.0);
  EXPECT_EQ(must_find("StatusSensor[1].State").read(data), 0.0);
  EXPECT_EQ(must_find("StatusSensor[4].AbsEncoderOffset").read(data), 137.812);
}

// spec 04 §1 (the structure map: one path, one member).
TEST(PositioningAxisVariables, AccessorsReachTheNamedMember) {
  PositioningAxisData data{};
  ASSERT_EQ(must_find("PositionControl.Kv").write(data, 33.5), ValueError::kNone);
  EXPECT_EQ(data.PositionControl.Kv, 33.5);
  ASSERT_EQ(must_find("PositionLimits_HW.MaxSwitchAddress.DB_NUMBER").write(data, 65535.0),
            ValueError::kNone);
  EXPECT_EQ(data.PositionLimits_HW.MaxSwitchAddress.DB_NUMBER, 65535);
  EXPECT_EQ(data.PositionLimits_HW.MinSwitchAddress.DB_NUMBER, 0);
  ASSERT_EQ(must_find("SetpointFilter.DynamicFilter.Tt").write(data, 0.004), ValueError::kNone);
  EXPECT_EQ(data.SetpointFilter.DynamicFilter.Tt, 0.004);
  data.StatusPositioning.FollowingError = -0.25;
  data.StatusKinematicsMotion = 0x5;
  data.OperativeSensor = 3;
  EXPECT_EQ(must_find("StatusPositioning.FollowingError").read(data), -0.25);
  EXPECT_EQ(must_find("StatusKinematicsMotion").read(data), 5.0);
  EXPECT_EQ(must_find("OperativeSensor").read(data), 3.0);
}

// spec 04 §0.4 (types and ranges: an invalid value changes nothing).
TEST(PositioningAxisVariables, InvalidValuesAreRejectedAndLeaveTheDataUnchanged) {
  struct Case {
    std::string path;
    double value;
    ValueError error;
  };
  const std::vector<Case> cases = {
      {"Sensor[1].Parameter.StepsPerRevolution", 0.0, ValueError::kOutOfRange},  // §3.6: 1 ... 8388608
      {"Sensor[2].Parameter.StepsPerRevolution", 8388609.0, ValueError::kOutOfRange},
      {"Sensor[1].Parameter.FineResolutionXist1", 32.0, ValueError::kOutOfRange},
      {"Sensor[1].Parameter.Resolution", 0.0, ValueError::kOutOfRange},  // P: 1.0E-12 ...
      {"Sensor[1].Type", 3.0, ValueError::kOutOfRange},
      {"Sensor[4].Interface.Number", 3.0, ValueError::kOutOfRange},
      {"Sensor[1].ActiveHoming.Direction", 2.0, ValueError::kOutOfRange},  // active: 0, 1 only
      {"OperativeSensor", 0.0, ValueError::kOutOfRange},                   // §2: 1 ... 4
      {"PositionControl.InitialOperativeSensor", 5.0, ValueError::kOutOfRange},
      {"PositionControl.Kv", 2147480.5, ValueError::kOutOfRange},
      {"PositionControl.Kpc", 150.5, ValueError::kOutOfRange},
      {"Modulo.Length", 0.0, ValueError::kOutOfRange},  // 0.001 ...
      {"Mechanics.LeadScrew", 0.0, ValueError::kOutOfRange},
      {"PositioningMonitoring.Window", 0.0005, ValueError::kOutOfRange},
      {"FollowingError.WarningLevel", 100.5, ValueError::kOutOfRange},
      {"CrossPlcSynchronousOperation.Interface[7].TelegramVersion", 3.0, ValueError::kOutOfRange},
      {"CrossPlcSynchronousOperation.LocalLeadingValueDelayTime", 1.1E9, ValueError::kOutOfRange},
      {"Homing.ApproachVelocity", 360000.5, ValueError::kOutOfRange},
      {"StatusMotionIn.FunctionState", 3.0, ValueError::kOutOfRange},
      {"ErrorDetail.Reaction", 10.0, ValueError::kOutOfRange},  // 10 is the external encoder's
      {"Actor.RemoveEnableReaction", 6.0, ValueError::kNotAllowed},
      {"Units.LengthUnit", 1083.0, ValueError::kNotAllowed},
      {"PositionLimits_HW.Active", 0.5, ValueError::kNotBoolean},
      {"Sensor[1].MeasuringGear.Denominator", 1.5, ValueError::kNotInteger},
      {"StatusPositioning.Distance", std::nan(""), ValueError::kNotANumber},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.path + " = " + std::to_string(c.value));
    const auto& info = must_find(c.path);
    PositioningAxisData data{};
    const double before = info.read(data);
    EXPECT_EQ(check_value(info, c.value), c.error);
    EXPECT_EQ(info.write(data, c.value), c.error);
    EXPECT_EQ(info.read(data), before);
  }
}

// spec 04 §1 (the structure map: one path, one member).
TEST(PositioningAxisVariables, AccessorsRefuseAnotherDataBlock) {
  SpeedAxisData speed{};
  const auto& info = must_find("Override.Velocity");
  EXPECT_TRUE(std::isnan(info.read(speed)));
  EXPECT_EQ(info.write(speed, 50.0), ValueError::kWrongDataBlock);
  EXPECT_EQ(speed.Override.Velocity, 100.0);
}

// ---- access (spec 04 §0.2) and MC_WriteParameter (spec 04 §0.3) ----

// spec 04 §0.2 (the W column), §0.3 (MC_WriteParameter).
TEST(PositioningAxisVariables, WriteAccessFollowsTheWColumn) {
  struct Case {
    std::string path;
    AccessError configuration, start_value, user_program;
  };
  using enum AccessError;
  const std::vector<Case> cases = {
      {"PositionControl.Kv", kNone, kNone, kNone},                                // DIR
      {"Sensor[2].Backlash.Size", kNone, kNone, kNone},                           // DIR
      {"Homing.ApproachVelocity", kNone, kNone, kNone},                           // CAL
      {"Sensor[1].ActiveHoming.SideInput", kNone, kNone, kNone},                  // CAL
      {"Sensor[1].Parameter.StepsPerRevolution", kNone, kNone, kStartValueOnly},  // RES
      {"PositionLimits_HW.MinSwitchAddress.OFFSET", kNone, kNone, kStartValueOnly},
      {"Actor.MotorType", kNone, kReadOnly, kReadOnly},  // DL: download only
      {"Sensor[1].Existent", kNone, kReadOnly, kReadOnly},
      {"Sensor[1].Interface.AddressIn.RID", kNone, kReadOnly, kReadOnly},
      {"Extrapolation.LeadingAxisDependentTime", kNone, kReadOnly, kReadOnly},
      {"StatusSensor[1].Position", kStatusVariable, kStatusVariable, kStatusVariable},
      {"StatusWord2", kStatusVariable, kStatusVariable, kStatusVariable},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.path);
    const auto& info = must_find(c.path);
    EXPECT_EQ(check_write_access(info, WriteContext::kConfiguration), c.configuration);
    EXPECT_EQ(check_write_access(info, WriteContext::kStartValue), c.start_value);
    EXPECT_EQ(check_write_access(info, WriteContext::kUserProgram), c.user_program);
  }
  for (const auto& info : positioning_axis_variables()) {
    if (info.role == kStatus) {
      EXPECT_EQ(info.access, kRON) << info.path;  // spec 04 §2, §4, §5
    }
  }
}

// spec 04 §0.3 (the MC_WriteParameter numbers).
TEST(PositioningAxisVariables, WriteParameterNumbers) {
  // spec 04 §0.3: 1000 PositionLimits_HW.Active (P, Y), 1020 Actor.RemoveEnableReaction; 1010-1012 no DB
  // variables
  const VariableInfo* hw = find_by_write_parameter(positioning_axis_variables(), 1000);
  ASSERT_NE(hw, nullptr);
  EXPECT_EQ(hw->path, "PositionLimits_HW.Active");
  const VariableInfo* reaction = find_by_write_parameter(positioning_axis_variables(), 1020);
  ASSERT_NE(reaction, nullptr);
  EXPECT_EQ(reaction->path, "Actor.RemoveEnableReaction");
  for (std::uint16_t n : {0, 1010, 1011, 1012, 1001}) {
    EXPECT_EQ(find_by_write_parameter(positioning_axis_variables(), n), nullptr) << n;
  }
  std::size_t with_number = 0;
  for (const auto& info : positioning_axis_variables())
    with_number += info.write_parameter != 0;
  EXPECT_EQ(with_number, 2u);
}

// ---- lookup and array indices ----

// spec 04 §1 (only the paths of the structure map).
TEST(PositioningAxisVariables, UnknownPathsAreRejected) {
  for (const char* path : {
           "",
           "Sensor[0].Type",  // ARRAY [1..4]: 1-based
           "Sensor[5].Type",
           "Sensor[01].Type",
           "Sensor[-1].Type",
           "Sensor[ 1].Type",
           "Sensor[].Type",
           "Sensor[1]",    // a structure
           "Sensor.Type",  // P has an array, E a single structure
           "Sensor[1].Type ",
           "sensor[1].type",
           "Sensor[1].Parameter",
           "Sensor[1].Interface.AddressIn",  // a VREF: its members are the variables
           "StatusSensor[0].State",
           "StatusSensor[5].State",
           "StatusSensor.State",
           "CrossPlcSynchronousOperation.Interface[0].TelegramVersion",
           "CrossPlcSynchronousOperation.Interface[33].TelegramVersion",
           "TorqueLimiting.PositionBasedMonitors",  // printed in the P table; named as in S (§14 item 4)
           "Sensor[1].ActiveHoming.SidelInput",     // printed; SideInput (§14 item 4)
           "Units.InertiaUnit",                     // the manual prints IneritaUnit
           "DynamicLimits.Acceleration",            // does not exist (§14 item 4)
           "StatusSynchronizedMotion.StatusWord",   // Y only, not defined in the source (§14 item 2)
           "ControlPanel",
           "InternalToTrace",
       }) {
    EXPECT_EQ(find_positioning_axis_variable(path), nullptr) << '"' << path << '"';
  }
}

// spec 04 §3.6 (Sensor[1..4]: one-based arrays, bounds from the table).
TEST(ArrayElementPath, ParseValidAndInvalid) {
  EXPECT_EQ(parse_array_element("Sensor[1].Parameter.StepsPerRevolution"),
            (ArrayElementPath{"Sensor", 1, "Parameter.StepsPerRevolution"}));
  EXPECT_EQ(parse_array_element("Sensor[5].Type"),
            (ArrayElementPath{"Sensor", 5, "Type"}));  // bound: table's
  EXPECT_EQ(parse_array_element("StatusSensor[4]"), (ArrayElementPath{"StatusSensor", 4, ""}));
  EXPECT_EQ(parse_array_element("CrossPlcSynchronousOperation.Interface[32].AddressOut.RID"),
            (ArrayElementPath{"CrossPlcSynchronousOperation.Interface", 32, "AddressOut.RID"}));
  for (const char* path : {"Sensor[0].Type", "Sensor[00].Type", "Sensor[01].Type", "Sensor[-1].Type",
                           "Sensor[+1].Type", "Sensor[ 1].Type", "Sensor[1 ].Type", "Sensor[].Type",
                           "Sensor[1.Type", "Sensor[x].Type", "Sensor[1]Type", "Sensor[1].", "[1].Type",
                           "Actor.[1].Type", "Sensor[1234567890].Type", "Sensor.Type", ""}) {
    EXPECT_EQ(parse_array_element(path), std::nullopt) << '"' << path << '"';
  }
}

// spec 04 §3.6 (Sensor[1..4]: one-based arrays, bounds from the table).
TEST(ArrayElementPath, UpperBoundsComeFromTheTable) {
  const auto table = positioning_axis_variables();
  EXPECT_EQ(array_upper_bound(table, "Sensor"), 4u);
  EXPECT_EQ(array_upper_bound(table, "StatusSensor"), 4u);
  EXPECT_EQ(array_upper_bound(table, "CrossPlcSynchronousOperation.Interface"), 32u);
  EXPECT_EQ(array_upper_bound(table, "Actor"), 0u);
  EXPECT_EQ(array_upper_bound(table, "Sens"), 0u);
  EXPECT_EQ(array_upper_bound(external_encoder_variables(), "Sensor"), 0u);  // a single structure on E
  // every index 1 ... bound of every array path is a table row: no gaps
  for (int n = 1; n <= 4; ++n) {
    EXPECT_NE(find_positioning_axis_variable("Sensor[" + std::to_string(n) + "].Parameter.ReferenceSpeed"),
              nullptr);
  }
}

// ---- bits ----

// spec 04 §5 (the bit words).
TEST(PositioningAxisBits, ResolveAgainstTheTable) {
  PositioningAxisData data{};
  const auto homed = find_positioning_axis_bit("StatusWord.X5");
  ASSERT_TRUE(homed.has_value());
  ASSERT_EQ(homed->write(data, true), ValueError::kNone);
  EXPECT_TRUE(test(data.StatusWord, StatusWordBit::kHomingDone));
  assign(data.StatusWord2, StatusWord2Bit::kPassingBacklash, true);
  EXPECT_TRUE(find_positioning_axis_bit("StatusWord2.X2")->read(data));
  assign(data.ErrorWord, ErrorWordBit::kFollowingErrorFault, true);
  EXPECT_TRUE(find_positioning_axis_bit("ErrorWord.%X11")->read(data));
  assign(data.WarningWord, WarningWordBit::kSuperimposingWarning, true);
  EXPECT_TRUE(find_positioning_axis_bit("WarningWord.X16")->read(data));
  data.StatusKinematicsMotion =
      1u << static_cast<unsigned>(StatusKinematicsMotionBit::kMaxDecelerationExceeded);
  EXPECT_TRUE(find_positioning_axis_bit("StatusKinematicsMotion.X2")->read(data));
  data.StatusMotionIn.StatusWord = 1u;
  EXPECT_TRUE(find_positioning_axis_bit("StatusMotionIn.StatusWord.X0")->read(data));
  EXPECT_TRUE(find_positioning_axis_bit("CrossPlcSynchronousOperation.Interface[3].TelegramVersion.X15"));
  EXPECT_TRUE(find_positioning_axis_bit("Sensor[4].Interface.AddressIn.AREA.X7"));
  EXPECT_FALSE(find_positioning_axis_bit("Sensor[4].Interface.AddressIn.AREA.X8"));
  EXPECT_FALSE(find_positioning_axis_bit("Sensor[5].Interface.AddressIn.AREA.X0"));
  EXPECT_FALSE(find_positioning_axis_bit("StatusSensor[1].State.X0"));  // DINT: no bits
  EXPECT_FALSE(find_positioning_axis_bit("StatusWord.X32"));
}

}  // namespace
}  // namespace tomc::techobjects
