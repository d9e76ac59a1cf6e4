// The reflection table of TO_PositioningAxis (spec 04 §1 column P/Y; man. §10.3) and the array-path helpers
// of positioning_variables.hpp. As in speed_axis_variables.cpp, each row names the PositioningAxisData member
// once: the path string is that member expression stringized (array elements: "Sensor[" n "]." member, with
// the C++ element n - 1), and a static_assert holds the row's data type against the C++ member type.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {
namespace {

using namespace detail;  // the shared table helpers and permitted values

// ---- ranges of the positioning-axis tables (man. §10.3) ----
constexpr double k1e12 = 1.0E12;
constexpr double k1e9 = 1.0E9;
// Homing.ApproachVelocity / ReferencingVelocity (spec 04 §3.18) are printed per motion type in fixed units:
// linear 0.0 ... 10000.0 mm/s / 0.0 ... 1000.0 mm/s, rotary 0.0 ... 360000.0 °/s / 0.0 ... 36000.0 °/s. A
// row has one range, so it holds the union (the rotary one); the narrower linear limit depends on
// Properties.MotionType and Units and is the configuration checker's business.
constexpr double kHomingApproachVelocityMax = 360000.0;
constexpr double kHomingReferencingVelocityMax = 36000.0;
// FollowingError.MinValue / MaxValue (spec 04 §3.24): linear 0.0 ..., rotary 0.001 ... / 0.002 ...: the union
// starts at 0.0.

// ---- permitted values (Units.*: detail::kLengthUnits, kPositionVelocityUnits) ----

// One row: `path_literal` is the manual path, `member` the PositioningAxisData member expression it names.
#define TOMC_P_ROW(...) TOMC_DB_ROW(PositioningAxisData, kPositioningAxis, __VA_ARGS__)
// A scalar member: the path is the member expression.
#define TOMC_P_VARIABLE(member, ...) TOMC_P_ROW(#member, member, __VA_ARGS__)
// A member of element n (1-based) of an ARRAY [1..m]: path "<array>[n].<member>", C++ element n - 1.
#define TOMC_P_ELEMENT(array, n, member, ...) \
  TOMC_P_ROW(#array "[" #n "]." #member, array[n - 1].member, __VA_ARGS__)

#define TOMC_P_VREF_ROWS(path_literal, member, access_code) \
  TOMC_DB_VREF_ROWS(TOMC_P_ROW, path_literal, member, access_code)
#define TOMC_P_VREF(member, access_code) TOMC_P_VREF_ROWS(#member, member, access_code)
#define TOMC_P_ELEMENT_VREF(array, n, member, access_code) \
  TOMC_P_VREF_ROWS(#array "[" #n "]." #member, array[n - 1].member, access_code)

// clang-format off

// man. §10.3.7 Sensor[n] (spec 04 §3.6, rows with TO "P" or "P,E")
#define TOMC_P_SENSOR(n)                                                                                       \
    TOMC_P_ELEMENT(Sensor, n, Existent, kBool, kRON, kConfiguration, 0.0, 1.0, kAny, 0),                       \
    TOMC_P_ELEMENT(Sensor, n, Type, kDint, kRON, kConfiguration, 0.0, 2.0, kAny, 0),                           \
    TOMC_P_ELEMENT(Sensor, n, InverseDirection, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),               \
    TOMC_P_ELEMENT(Sensor, n, System, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),                         \
    TOMC_P_ELEMENT(Sensor, n, MountingMode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny, 0),                   \
    TOMC_P_ELEMENT(Sensor, n, DataAdaption, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),                   \
    TOMC_P_ELEMENT(Sensor, n, ActualVelocityMode, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),             \
    TOMC_P_ELEMENT_VREF(Sensor, n, Interface.AddressIn, kRON),                                                 \
    TOMC_P_ELEMENT_VREF(Sensor, n, Interface.AddressOut, kRON),                                                \
    TOMC_P_ELEMENT(Sensor, n, Interface.Number, kUdint, kRON, kConfiguration, 1.0, 2.0, kAny, 0),              \
    TOMC_P_ELEMENT(Sensor, n, Parameter.Resolution, kLreal, kRES, kConfiguration, 1.0E-12, k1e12, kAny, 0),    \
    TOMC_P_ELEMENT(Sensor, n, Parameter.StepsPerRevolution, kUdint, kRES, kConfiguration, 1.0, 8388608.0,      \
                   kAny, 0),                                                                                   \
    TOMC_P_ELEMENT(Sensor, n, Parameter.FineResolutionXist1, kUdint, kRES, kConfiguration, 0.0, 31.0, kAny, 0),\
    TOMC_P_ELEMENT(Sensor, n, Parameter.FineResolutionXist2, kUdint, kRES, kConfiguration, 0.0, 31.0, kAny, 0),\
    TOMC_P_ELEMENT(Sensor, n, Parameter.DeterminableRevolutions, kUdint, kRES, kConfiguration, 0.0,            \
                   8388608.0, kAny, 0),                                                                        \
    TOMC_P_ELEMENT(Sensor, n, Parameter.DistancePerRevolution, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, \
                   0),                                                                                         \
    TOMC_P_ELEMENT(Sensor, n, Parameter.BehaviorGx_XIST1, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),     \
    TOMC_P_ELEMENT(Sensor, n, Parameter.ReferenceSpeed, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),    \
    TOMC_P_ELEMENT(Sensor, n, Parameter.ReferenceVelocity, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0), \
    TOMC_P_ELEMENT(Sensor, n, Backlash.Enable, kBool, kDIR, kConfiguration, 0.0, 1.0, kAny, 0),                \
    TOMC_P_ELEMENT(Sensor, n, Backlash.Size, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),               \
    TOMC_P_ELEMENT(Sensor, n, Backlash.Velocity, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),           \
    TOMC_P_ELEMENT(Sensor, n, Backlash.DirectionAbsoluteHoming, kDint, kDIR, kConfiguration, 0.0, 1.0, kAny, 0),\
    TOMC_P_ELEMENT(Sensor, n, ActiveHoming.Mode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny, 0),              \
    TOMC_P_ELEMENT(Sensor, n, ActiveHoming.SideInput, kBool, kCAL, kConfiguration, 0.0, 1.0, kAny, 0),         \
    TOMC_P_ELEMENT(Sensor, n, ActiveHoming.Direction, kDint, kCAL, kConfiguration, 0.0, 1.0, kAny, 0),         \
    TOMC_P_ELEMENT_VREF(Sensor, n, ActiveHoming.DigitalInputAddress, kRON),                                    \
    TOMC_P_ELEMENT(Sensor, n, ActiveHoming.HomePositionOffset, kLreal, kCAL, kConfiguration, -k1e12, k1e12,    \
                   kAny, 0),                                                                                   \
    TOMC_P_ELEMENT(Sensor, n, ActiveHoming.SwitchLevel, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),       \
    TOMC_P_ELEMENT(Sensor, n, PassiveHoming.Mode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny, 0),             \
    TOMC_P_ELEMENT(Sensor, n, PassiveHoming.SideInput, kBool, kCAL, kConfiguration, 0.0, 1.0, kAny, 0),        \
    TOMC_P_ELEMENT(Sensor, n, PassiveHoming.Direction, kDint, kCAL, kConfiguration, 0.0, 2.0, kAny, 0),        \
    TOMC_P_ELEMENT_VREF(Sensor, n, PassiveHoming.DigitalInputAddress, kRON),                                   \
    TOMC_P_ELEMENT(Sensor, n, PassiveHoming.SwitchLevel, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),      \
    TOMC_P_ELEMENT(Sensor, n, MeasuringGear.Numerator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0), \
    TOMC_P_ELEMENT(Sensor, n, MeasuringGear.Denominator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0)

// man. §10.3.8 CrossPlcSynchronousOperation.Interface[n] (spec 04 §3.7), all RON; AddressOut: no range printed
#define TOMC_P_CROSS_PLC_INTERFACE(n)                                                                          \
    TOMC_P_ELEMENT(CrossPlcSynchronousOperation.Interface, n, EnableLeadingValueOutput, kBool, kRON,           \
                   kConfiguration, 0.0, 1.0, kAny, 0),                                                         \
    TOMC_P_ELEMENT_VREF(CrossPlcSynchronousOperation.Interface, n, AddressOut, kRON),                          \
    TOMC_P_ELEMENT(CrossPlcSynchronousOperation.Interface, n, TelegramVersion, kWord, kRON, kConfiguration,    \
                   1.0, 2.0, kAny, 0)

// man. §10.3.32 StatusSensor[n] (spec 04 §4.5), RON
#define TOMC_P_STATUS_SENSOR(n)                                                                                \
    TOMC_P_ELEMENT(StatusSensor, n, State, kDint, kRON, kStatus, 0.0, 2.0, kAny, 0),                           \
    TOMC_P_ELEMENT(StatusSensor, n, CommunicationOK, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),                 \
    TOMC_P_ELEMENT(StatusSensor, n, Error, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),                           \
    TOMC_P_ELEMENT(StatusSensor, n, AbsEncoderOffset, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),   \
    TOMC_P_ELEMENT(StatusSensor, n, Control, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),                         \
    TOMC_P_ELEMENT(StatusSensor, n, Position, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),           \
    TOMC_P_ELEMENT(StatusSensor, n, Velocity, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),           \
    TOMC_P_ELEMENT(StatusSensor, n, AdaptionState, kDint, kRON, kStatus, 0.0, 4.0, kAny, 0),                   \
    TOMC_P_ELEMENT(StatusSensor, n, ModuloCycle, kDint, kRON, kStatus, kDintMin, kDintMax, kAny, 0),           \
    TOMC_P_ELEMENT(StatusSensor, n, Adjusted, kDint, kRON, kStatus, 0.0, 1.0, kAny, 0)

constexpr auto kPositioningAxisVariables = std::to_array<VariableInfo>({
    // man. §10.3.1 actual values and setpoints (spec 04 §2), RON
    TOMC_P_VARIABLE(Position, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(Velocity, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(ActualPosition, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(ActualVelocity, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(ActualSpeed, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(Acceleration, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(ActualAcceleration, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(OperativeSensor, kUdint, kRON, kStatus, 1.0, 4.0, kAny, 0),
    TOMC_P_VARIABLE(ModuloCycle, kDint, kRON, kStatus, kDintMin, kDintMax, kAny, 0),
    TOMC_P_VARIABLE(ActualModuloCycle, kDint, kRON, kStatus, kDintMin, kDintMax, kAny, 0),
    TOMC_P_VARIABLE(VelocitySetpoint, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    // man. §10.3.2 Simulation (spec 04 §3.1)
    TOMC_P_VARIABLE(Simulation.Mode, kUdint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.3.3 VirtualAxis (spec 04 §3.2)
    TOMC_P_VARIABLE(VirtualAxis.Mode, kUdint, kRON, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.3.4 Actor (spec 04 §3.3)
    TOMC_P_VARIABLE(Actor.Type, kDint, kRON, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Actor.InverseDirection, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Actor.DataAdaption, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Actor.Efficiency, kLreal, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Actor.MotorType, kDint, kDL, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Actor.LoadInertia, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Actor.RemoveEnableReaction, kWord, kRES, kConfiguration, 0.0, 7.0,
                    kRemoveEnableReactionValues, 1020),
    TOMC_P_VREF(Actor.Interface.AddressIn, kRON),
    TOMC_P_VREF(Actor.Interface.AddressOut, kRON),
    TOMC_P_VARIABLE(Actor.Interface.EnableDriveOutput, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VREF(Actor.Interface.EnableDriveOutputAddress, kRON),
    TOMC_P_VARIABLE(Actor.Interface.DriveReadyInput, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VREF(Actor.Interface.DriveReadyInputAddress, kRON),
    TOMC_P_VARIABLE(Actor.Interface.EnableTorqueData, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VREF(Actor.Interface.TorqueDataAddressIn, kRON),
    TOMC_P_VREF(Actor.Interface.TorqueDataAddressOut, kRON),
    TOMC_P_VARIABLE(Actor.DriveParameter.ReferenceSpeed, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Actor.DriveParameter.MaxSpeed, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Actor.DriveParameter.ReferenceTorque, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Actor.DriveParameter.MotorInertia, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Actor.LinearMotorDriveParameter.ReferenceVelocity, kLreal, kRES, kConfiguration, 0.0, k1e12,
                    kAny, 0),
    TOMC_P_VARIABLE(Actor.LinearMotorDriveParameter.MaxVelocity, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Actor.LinearMotorDriveParameter.ReferenceForce, kLreal, kRES, kConfiguration, 0.0, k1e12,
                    kAny, 0),
    TOMC_P_VARIABLE(Actor.LinearMotorDriveParameter.MotorMass, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.5 TorqueLimiting (spec 04 §3.4)
    TOMC_P_VARIABLE(TorqueLimiting.LimitBase, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(TorqueLimiting.PositionBasedMonitorings, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(TorqueLimiting.LimitDefaults.Torque, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(TorqueLimiting.LimitDefaults.Force, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.6 Clamping (spec 04 §3.5)
    TOMC_P_VARIABLE(Clamping.FollowingErrorDeviation, kLreal, kDIR, kConfiguration, 0.001, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Clamping.PositionTolerance, kLreal, kDIR, kConfiguration, 0.001, k1e12, kAny, 0),
    // man. §10.3.7 Sensor[1..4] (spec 04 §3.6)
    TOMC_P_SENSOR(1),
    TOMC_P_SENSOR(2),
    TOMC_P_SENSOR(3),
    TOMC_P_SENSOR(4),
    // man. §10.3.8 CrossPlcSynchronousOperation (spec 04 §3.7)
    TOMC_P_CROSS_PLC_INTERFACE(1),  TOMC_P_CROSS_PLC_INTERFACE(2),  TOMC_P_CROSS_PLC_INTERFACE(3),
    TOMC_P_CROSS_PLC_INTERFACE(4),  TOMC_P_CROSS_PLC_INTERFACE(5),  TOMC_P_CROSS_PLC_INTERFACE(6),
    TOMC_P_CROSS_PLC_INTERFACE(7),  TOMC_P_CROSS_PLC_INTERFACE(8),  TOMC_P_CROSS_PLC_INTERFACE(9),
    TOMC_P_CROSS_PLC_INTERFACE(10), TOMC_P_CROSS_PLC_INTERFACE(11), TOMC_P_CROSS_PLC_INTERFACE(12),
    TOMC_P_CROSS_PLC_INTERFACE(13), TOMC_P_CROSS_PLC_INTERFACE(14), TOMC_P_CROSS_PLC_INTERFACE(15),
    TOMC_P_CROSS_PLC_INTERFACE(16), TOMC_P_CROSS_PLC_INTERFACE(17), TOMC_P_CROSS_PLC_INTERFACE(18),
    TOMC_P_CROSS_PLC_INTERFACE(19), TOMC_P_CROSS_PLC_INTERFACE(20), TOMC_P_CROSS_PLC_INTERFACE(21),
    TOMC_P_CROSS_PLC_INTERFACE(22), TOMC_P_CROSS_PLC_INTERFACE(23), TOMC_P_CROSS_PLC_INTERFACE(24),
    TOMC_P_CROSS_PLC_INTERFACE(25), TOMC_P_CROSS_PLC_INTERFACE(26), TOMC_P_CROSS_PLC_INTERFACE(27),
    TOMC_P_CROSS_PLC_INTERFACE(28), TOMC_P_CROSS_PLC_INTERFACE(29), TOMC_P_CROSS_PLC_INTERFACE(30),
    TOMC_P_CROSS_PLC_INTERFACE(31), TOMC_P_CROSS_PLC_INTERFACE(32),
    TOMC_P_VARIABLE(CrossPlcSynchronousOperation.LocalLeadingValueDelayTime, kLreal, kRES, kConfiguration, 0.0,
                    k1e9, kAny, 0),
    // man. §10.3.9 Extrapolation (spec 04 §3.8); LeadingAxisDependentTime: no range printed
    TOMC_P_VARIABLE(Extrapolation.LeadingAxisDependentTime, kLreal, kRON, kConfiguration, kLrealMin, kLrealMax,
                    kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.FollowingAxisDependentTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.Settings.SystemDefinedExtrapolation, kDint, kRES, kConfiguration, 0.0, 1.0,
                    kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.Settings.ExtrapolatedVelocityMode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny,
                    0),
    TOMC_P_VARIABLE(Extrapolation.PositionFilter.T1, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.PositionFilter.T2, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.VelocityFilter.T1, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.VelocityFilter.T2, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.VelocityTolerance.Range, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Extrapolation.Hysteresis.Value, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.10 LoadGear (spec 04 §3.9)
    TOMC_P_VARIABLE(LoadGear.Numerator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0),
    TOMC_P_VARIABLE(LoadGear.Denominator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0),
    // man. §10.3.11 Properties (spec 04 §3.10)
    TOMC_P_VARIABLE(Properties.MotionType, kDint, kRON, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.3.12 Units (spec 04 §3.11), RON; no range printed, the permitted codes are the listed ones
    TOMC_P_VARIABLE(Units.LengthUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kLengthUnits, 0),
    TOMC_P_VARIABLE(Units.VelocityUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kPositionVelocityUnits, 0),
    TOMC_P_VARIABLE(Units.TimeUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kTimeUnits, 0),
    TOMC_P_VARIABLE(Units.TorqueUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kTorqueUnits, 0),
    TOMC_P_VARIABLE(Units.ForceUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kForceUnits, 0),
    TOMC_P_VARIABLE(Units.MassUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kMassUnits, 0),
    TOMC_P_VARIABLE(Units.IneritaUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kInertiaUnits, 0),
    // man. §10.3.13 Mechanics (spec 04 §3.12)
    TOMC_P_VARIABLE(Mechanics.LeadScrew, kLreal, kRES, kConfiguration, 1.0E-12, k1e12, kAny, 0),
    // man. §10.3.14 Modulo (spec 04 §3.13)
    TOMC_P_VARIABLE(Modulo.Enable, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Modulo.Length, kLreal, kRES, kConfiguration, 0.001, k1e12, kAny, 0),
    TOMC_P_VARIABLE(Modulo.StartValue, kLreal, kRES, kConfiguration, -k1e12, k1e12, kAny, 0),
    // man. §10.3.15 DynamicLimits (spec 04 §3.14, column "Range P/Y")
    TOMC_P_VARIABLE(DynamicLimits.MaxVelocity, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicLimits.Velocity, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicLimits.MaxAcceleration, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicLimits.MaxDeceleration, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicLimits.MaxJerk, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.16 DynamicDefaults (spec 04 §3.15, column "Range P/Y")
    TOMC_P_VARIABLE(DynamicDefaults.Velocity, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicDefaults.Acceleration, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicDefaults.Deceleration, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicDefaults.Jerk, kLreal, kCAL, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicDefaults.EmergencyDeceleration, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.17 PositionLimits_SW (spec 04 §3.16)
    TOMC_P_VARIABLE(PositionLimits_SW.Active, kBool, kDIR, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(PositionLimits_SW.MinPosition, kLreal, kDIR, kConfiguration, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositionLimits_SW.MaxPosition, kLreal, kDIR, kConfiguration, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositionLimits_SW.LimitReachedBehavior, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(PositionLimits_SW.LimitExceededBehavior, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.3.18 PositionLimits_HW (spec 04 §3.17); the switch addresses are RES here
    TOMC_P_VARIABLE(PositionLimits_HW.Active, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 1000),
    TOMC_P_VARIABLE(PositionLimits_HW.MinSwitchLevel, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VREF(PositionLimits_HW.MinSwitchAddress, kRES),
    TOMC_P_VARIABLE(PositionLimits_HW.MaxSwitchLevel, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VREF(PositionLimits_HW.MaxSwitchAddress, kRES),
    TOMC_P_VARIABLE(PositionLimits_HW.Mode, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(PositionLimits_HW.ApproachBehavior, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.3.19 Homing (spec 04 §3.18)
    TOMC_P_VARIABLE(Homing.AutoReversal, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Homing.ApproachDirection, kBool, kCAL, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(Homing.ApproachVelocity, kLreal, kCAL, kConfiguration, 0.0, kHomingApproachVelocityMax, kAny, 0),
    TOMC_P_VARIABLE(Homing.ReferencingVelocity, kLreal, kCAL, kConfiguration, 0.0, kHomingReferencingVelocityMax,
                    kAny, 0),
    TOMC_P_VARIABLE(Homing.HomePosition, kLreal, kCAL, kConfiguration, -k1e12, k1e12, kAny, 0),
    // man. §10.3.20 Override (spec 04 §3.19), percent
    TOMC_P_VARIABLE(Override.Velocity, kLreal, kDIR, kConfiguration, 0.0, 200.0, kAny, 0),
    // man. §10.3.21 PositionControl (spec 04 §3.20)
    TOMC_P_VARIABLE(PositionControl.Kv, kLreal, kDIR, kConfiguration, 0.0, 2147480.0, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.Kpc, kLreal, kDIR, kConfiguration, 0.0, 150.0, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.EnableDSC, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.SmoothingTimeByChangeDifference, kLreal, kDIR, kConfiguration, 0.0, k1e12,
                    kAny, 0),
    TOMC_P_VARIABLE(PositionControl.InitialOperativeSensor, kUdint, kRES, kConfiguration, 1.0, 4.0, kAny, 0),
    // Mode: the manual prints "-"; its values are 0 ... 2 (spec 04 §3.20)
    TOMC_P_VARIABLE(PositionControl.ControlDifferenceQuantization.Mode, kDint, kRES, kConfiguration, 0.0, 2.0,
                    kAny, 0),
    TOMC_P_VARIABLE(PositionControl.ControlDifferenceQuantization.Value, kLreal, kRES, kConfiguration, 0.001,
                    k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.VelocityModePowerOn, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    // tomc extension (issue 20): PID position control (pid_regulator.hpp), DIR like Kv
    TOMC_P_VARIABLE(PositionControl.Pid.IntegralTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.Pid.DerivativeTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.Pid.DerivativeCycles, kUdint, kDIR, kConfiguration, 1.0, 256.0, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.Pid.IntegralLimit, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.Pid.DeadBand, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositionControl.Pid.OutputLimit, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.22 TorquePreControl (spec 04 §3.21)
    TOMC_P_VARIABLE(TorquePreControl.Mode, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(TorquePreControl.Scale, kLreal, kDIR, kConfiguration, 0.0, 150.0, kAny, 0),
    // man. §10.3.23 SetpointFilter (spec 04 §3.22)
    TOMC_P_VARIABLE(SetpointFilter.DynamicFilter.Mode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny, 0),
    TOMC_P_VARIABLE(SetpointFilter.DynamicFilter.T1, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(SetpointFilter.DynamicFilter.T2, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(SetpointFilter.DynamicFilter.Tt, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.24 DynamicAxisModel (spec 04 §3.23)
    TOMC_P_VARIABLE(DynamicAxisModel.VelocityTimeConstant, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(DynamicAxisModel.AdditionalPositionTimeConstant, kLreal, kDIR, kConfiguration, 0.0, k1e12,
                    kAny, 0),
    TOMC_P_VARIABLE(DynamicAxisModel.CurrentTimeConstant, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.25 FollowingError (spec 04 §3.24); Min/MaxValue: union of the linear and rotary ranges
    TOMC_P_VARIABLE(FollowingError.EnableMonitoring, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(FollowingError.MinValue, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(FollowingError.MaxValue, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(FollowingError.MinVelocity, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(FollowingError.WarningLevel, kLreal, kDIR, kConfiguration, 0.0, 100.0, kAny, 0),
    TOMC_P_VARIABLE(FollowingError.AdditionalSetpointDelayTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.26 PositioningMonitoring (spec 04 §3.25)
    TOMC_P_VARIABLE(PositioningMonitoring.ToleranceTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositioningMonitoring.MinDwellTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(PositioningMonitoring.Window, kLreal, kDIR, kConfiguration, 0.001, k1e12, kAny, 0),
    // man. §10.3.27 StandstillSignal (spec 04 §3.26)
    TOMC_P_VARIABLE(StandstillSignal.VelocityThreshold, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StandstillSignal.MinDwellTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.3.28 StatusPositioning (spec 04 §4.1), RON
    TOMC_P_VARIABLE(StatusPositioning.Distance, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusPositioning.TargetPosition, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusPositioning.TargetPositionModuloCycle, kDint, kRON, kStatus, kDintMin, kDintMax, kAny, 0),
    TOMC_P_VARIABLE(StatusPositioning.FollowingError, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusPositioning.SetpointExecutionTime, kLreal, kRON, kStatus, 0.0, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusPositioning.SuperimposedDistance, kLreal, kRON, kStatus, 0.0, k1e12, kAny, 0),
    // man. §10.3.29 StatusDrive (spec 04 §4.2), RON
    TOMC_P_VARIABLE(StatusDrive.InOperation, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(StatusDrive.CommunicationOK, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(StatusDrive.Error, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(StatusDrive.AdaptionState, kDint, kRON, kStatus, 0.0, 4.0, kAny, 0),
    // man. §10.3.30 StatusServo (spec 04 §4.3), RON, no range printed
    TOMC_P_VARIABLE(StatusServo.BalancedPosition, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(StatusServo.ControlDifference, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_P_VARIABLE(StatusServo.PositionAfterDynamicFilter, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    // man. §10.3.31 StatusProvidedLeadingValue (spec 04 §4.4), RON
    TOMC_P_VARIABLE(StatusProvidedLeadingValue.DelayedLeadingValue.Position, kLreal, kRON, kStatus, -k1e12, k1e12,
                    kAny, 0),
    TOMC_P_VARIABLE(StatusProvidedLeadingValue.DelayedLeadingValue.Velocity, kLreal, kRON, kStatus, -k1e12, k1e12,
                    kAny, 0),
    TOMC_P_VARIABLE(StatusProvidedLeadingValue.DelayedLeadingValue.Acceleration, kLreal, kRON, kStatus, -k1e12,
                    k1e12, kAny, 0),
    // man. §10.3.32 StatusSensor[1..4] (spec 04 §4.5)
    TOMC_P_STATUS_SENSOR(1),
    TOMC_P_STATUS_SENSOR(2),
    TOMC_P_STATUS_SENSOR(3),
    TOMC_P_STATUS_SENSOR(4),
    // man. §10.3.33 StatusExtrapolation (spec 04 §4.6), RON
    TOMC_P_VARIABLE(StatusExtrapolation.FilteredPosition, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusExtrapolation.FilteredVelocity, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusExtrapolation.ExtrapolatedPosition, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusExtrapolation.ExtrapolatedVelocity, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    // man. §10.3.34 StatusKinematicsMotion (spec 04 §5.5), DWORD, RON
    TOMC_P_VARIABLE(StatusKinematicsMotion, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    // man. §10.3.35 StatusTorqueData (spec 04 §4.7), all six members, RON
    TOMC_P_VARIABLE(StatusTorqueData.CommandAdditiveTorqueActive, kDint, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(StatusTorqueData.CommandTorqueRangeActive, kDint, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_P_VARIABLE(StatusTorqueData.ActualTorque, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusTorqueData.ActualForce, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusTorqueData.TotalTorqueAdditive, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_P_VARIABLE(StatusTorqueData.TotalForceAdditive, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    // man. §10.3.36 StatusMotionIn (spec 04 §4.8): P has 0 ... 2
    TOMC_P_VARIABLE(StatusMotionIn.FunctionState, kDint, kRON, kStatus, 0.0, 2.0, kAny, 0),
    TOMC_P_VARIABLE(StatusMotionIn.ActualSuperimposingAxis, kDbAny, kRON, kStatus, 0.0, kWordMax, kAny, 0),
    TOMC_P_VARIABLE(StatusMotionIn.StatusWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    // man. §10.3.37 StatusInterpreterMotion (spec 04 §4.9); W of Interpreter not printed: status structure -> RON
    TOMC_P_VARIABLE(StatusInterpreterMotion.Interpreter, kDbAny, kRON, kStatus, 0.0, kWordMax, kAny, 0),
    TOMC_P_VARIABLE(StatusInterpreterMotion.StatusWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    // man. §10.3.38 ... §10.3.42 bit words (spec 04 §5) and ErrorDetail (spec 04 §4.10), RON
    TOMC_P_VARIABLE(StatusWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_P_VARIABLE(StatusWord2, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_P_VARIABLE(ErrorWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_P_VARIABLE(ErrorDetail.Number, kUdint, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_P_VARIABLE(ErrorDetail.Reaction, kDint, kRON, kStatus, 0.0, 5.0, kAny, 0),
    TOMC_P_VARIABLE(WarningWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
});
// clang-format on

#undef TOMC_P_STATUS_SENSOR
#undef TOMC_P_CROSS_PLC_INTERFACE
#undef TOMC_P_SENSOR
#undef TOMC_P_ELEMENT_VREF
#undef TOMC_P_VREF
#undef TOMC_P_VREF_ROWS
#undef TOMC_P_ELEMENT
#undef TOMC_P_VARIABLE
#undef TOMC_P_ROW

// Paths are unique (sorted copy: O(n log n) constant-evaluation steps for the ~500 rows).
static_assert(detail::paths_unique(kPositioningAxisVariables),
              "duplicate path in the positioning-axis table");
static_assert(detail::ranges_valid(kPositioningAxisVariables),
              "a positioning-axis range is empty, exceeds its data type or excludes a permitted value");

}  // namespace

// ---- TO_PositioningAxis ----

std::span<const VariableInfo> positioning_axis_variables() noexcept {
  return kPositioningAxisVariables;
}

const VariableInfo* find_positioning_axis_variable(std::string_view path) noexcept {
  return find_variable(kPositioningAxisVariables, path);
}

std::optional<BitReference> find_positioning_axis_bit(std::string_view path) noexcept {
  return find_bit(kPositioningAxisVariables, path);
}

// ---- array elements in paths ----

std::optional<ArrayElementPath> parse_array_element(std::string_view path) noexcept {
  const auto open = path.find('[');
  if (open == std::string_view::npos || open == 0) return std::nullopt;
  const std::string_view array = path.substr(0, open);
  if (array.back() == '.') return std::nullopt;
  const auto close = path.find(']', open);
  if (close == std::string_view::npos) return std::nullopt;
  const std::string_view digits = path.substr(open + 1, close - open - 1);
  // 1 ... 999999999: at most nine digits, so the value fits a uint32_t
  if (digits.empty() || digits.size() > 9 || digits.front() == '0') return std::nullopt;
  std::uint32_t index = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    index = index * 10 + static_cast<std::uint32_t>(c - '0');
  }
  std::string_view member = path.substr(close + 1);
  if (!member.empty()) {
    if (member.front() != '.' || member.size() == 1) return std::nullopt;
    member.remove_prefix(1);
  }
  return ArrayElementPath{array, index, member};
}

std::uint32_t array_upper_bound(std::span<const VariableInfo> table, std::string_view array) noexcept {
  std::uint32_t bound = 0;
  for (const VariableInfo& info : table) {
    if (info.path.size() <= array.size() || !info.path.starts_with(array) || info.path[array.size()] != '[') {
      continue;
    }
    const auto element = parse_array_element(info.path);
    if (element && element->array == array) bound = std::max(bound, element->index);
  }
  return bound;
}

}  // namespace tomc::techobjects
