// The reflection table of TO_ExternalEncoder (spec 04 §1 column E; man. §10.4). Built like the
// positioning-axis table (positioning_axis_variables.cpp): each row names the ExternalEncoderData member
// once, the path string is that member expression stringized (CrossPlcSynchronousOperation.Interface[n]:
// 1-based in the path, C++ element n - 1), and a static_assert holds the row's data type against the C++
// member type. `Sensor` and `StatusSensor` are single structures on E (man. §10.4.2, §10.4.13).

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>

#include "tomc/techobjects/datablocks/external_encoder_data.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {
namespace {

using namespace detail;  // the shared table helpers and permitted values

constexpr double k1e12 = 1.0E12;
constexpr double k1e9 = 1.0E9;

// ---- permitted values (Units.*: detail::kLengthUnits, kPositionVelocityUnits) ----
// ErrorDetail.Reaction: 0 none, 10 remove enable (man. §10.4.17, as printed; spec 04 §14 item 7).
constexpr std::array<double, 2> kReactionValues{static_cast<double>(ExternalEncoderReaction::kNone),
                                                static_cast<double>(ExternalEncoderReaction::kRemoveEnable)};

// One row: `path_literal` is the manual path, `member` the ExternalEncoderData member expression it names.
#define TOMC_E_ROW(...) TOMC_DB_ROW(ExternalEncoderData, kExternalEncoder, __VA_ARGS__)
// A scalar member: the path is the member expression.
#define TOMC_E_VARIABLE(member, ...) TOMC_E_ROW(#member, member, __VA_ARGS__)
// A member of element n (1-based) of an ARRAY [1..m]: path "<array>[n].<member>", C++ element n - 1.
#define TOMC_E_ELEMENT(array, n, member, ...) \
  TOMC_E_ROW(#array "[" #n "]." #member, array[n - 1].member, __VA_ARGS__)

#define TOMC_E_VREF_ROWS(path_literal, member, access_code) \
  TOMC_DB_VREF_ROWS(TOMC_E_ROW, path_literal, member, access_code)
#define TOMC_E_VREF(member, access_code) TOMC_E_VREF_ROWS(#member, member, access_code)
#define TOMC_E_ELEMENT_VREF(array, n, member, access_code) \
  TOMC_E_VREF_ROWS(#array "[" #n "]." #member, array[n - 1].member, access_code)

// clang-format off

// man. §10.4.3 CrossPlcSynchronousOperation.Interface[n] (spec 04 §3.7), all RON; AddressOut: no range printed
#define TOMC_E_CROSS_PLC_INTERFACE(n)                                                                          \
    TOMC_E_ELEMENT(CrossPlcSynchronousOperation.Interface, n, EnableLeadingValueOutput, kBool, kRON,           \
                   kConfiguration, 0.0, 1.0, kAny, 0),                                                         \
    TOMC_E_ELEMENT_VREF(CrossPlcSynchronousOperation.Interface, n, AddressOut, kRON),                          \
    TOMC_E_ELEMENT(CrossPlcSynchronousOperation.Interface, n, TelegramVersion, kWord, kRON, kConfiguration,    \
                   1.0, 2.0, kAny, 0)

constexpr auto kExternalEncoderVariables = std::to_array<VariableInfo>({
    // man. §10.4.1 actual values (spec 04 §2, column E), RON
    TOMC_E_VARIABLE(ActualPosition, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_E_VARIABLE(ActualVelocity, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_E_VARIABLE(ActualAcceleration, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_E_VARIABLE(ActualModuloCycle, kDint, kRON, kStatus, kDintMin, kDintMax, kAny, 0),
    // man. §10.4.2 Sensor (spec 04 §3.6, rows with TO "P,E"; E variants: Resolution range, SwitchLevel RON)
    TOMC_E_VARIABLE(Sensor.Type, kDint, kRON, kConfiguration, 0.0, 2.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.InverseDirection, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.System, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.MountingMode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.DataAdaption, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.ActualVelocityMode, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_E_VREF(Sensor.Interface.AddressIn, kRON),
    TOMC_E_VREF(Sensor.Interface.AddressOut, kRON),
    TOMC_E_VARIABLE(Sensor.Interface.Number, kUdint, kRON, kConfiguration, 1.0, 2.0, kAny, 0),
    // printed -1.0E12 ... 1.0E12 on E (1.0E-12 ... on P/Y; spec 04 §14 item 9)
    TOMC_E_VARIABLE(Sensor.Parameter.Resolution, kLreal, kRES, kConfiguration, -k1e12, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Sensor.Parameter.StepsPerRevolution, kUdint, kRES, kConfiguration, 1.0, 8388608.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.Parameter.FineResolutionXist1, kUdint, kRES, kConfiguration, 0.0, 31.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.Parameter.FineResolutionXist2, kUdint, kRES, kConfiguration, 0.0, 31.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.Parameter.DeterminableRevolutions, kUdint, kRES, kConfiguration, 0.0, 8388608.0, kAny,
                    0),
    TOMC_E_VARIABLE(Sensor.Parameter.DistancePerRevolution, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Sensor.Parameter.BehaviorGx_XIST1, kDint, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.Parameter.ReferenceSpeed, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Sensor.Parameter.ReferenceVelocity, kLreal, kRES, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Sensor.PassiveHoming.Mode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.PassiveHoming.SideInput, kBool, kCAL, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(Sensor.PassiveHoming.Direction, kDint, kCAL, kConfiguration, 0.0, 2.0, kAny, 0),
    TOMC_E_VREF(Sensor.PassiveHoming.DigitalInputAddress, kRON),
    TOMC_E_VARIABLE(Sensor.PassiveHoming.SwitchLevel, kBool, kRON, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.4.3 CrossPlcSynchronousOperation (spec 04 §3.7)
    TOMC_E_CROSS_PLC_INTERFACE(1),  TOMC_E_CROSS_PLC_INTERFACE(2),  TOMC_E_CROSS_PLC_INTERFACE(3),
    TOMC_E_CROSS_PLC_INTERFACE(4),  TOMC_E_CROSS_PLC_INTERFACE(5),  TOMC_E_CROSS_PLC_INTERFACE(6),
    TOMC_E_CROSS_PLC_INTERFACE(7),  TOMC_E_CROSS_PLC_INTERFACE(8),  TOMC_E_CROSS_PLC_INTERFACE(9),
    TOMC_E_CROSS_PLC_INTERFACE(10), TOMC_E_CROSS_PLC_INTERFACE(11), TOMC_E_CROSS_PLC_INTERFACE(12),
    TOMC_E_CROSS_PLC_INTERFACE(13), TOMC_E_CROSS_PLC_INTERFACE(14), TOMC_E_CROSS_PLC_INTERFACE(15),
    TOMC_E_CROSS_PLC_INTERFACE(16), TOMC_E_CROSS_PLC_INTERFACE(17), TOMC_E_CROSS_PLC_INTERFACE(18),
    TOMC_E_CROSS_PLC_INTERFACE(19), TOMC_E_CROSS_PLC_INTERFACE(20), TOMC_E_CROSS_PLC_INTERFACE(21),
    TOMC_E_CROSS_PLC_INTERFACE(22), TOMC_E_CROSS_PLC_INTERFACE(23), TOMC_E_CROSS_PLC_INTERFACE(24),
    TOMC_E_CROSS_PLC_INTERFACE(25), TOMC_E_CROSS_PLC_INTERFACE(26), TOMC_E_CROSS_PLC_INTERFACE(27),
    TOMC_E_CROSS_PLC_INTERFACE(28), TOMC_E_CROSS_PLC_INTERFACE(29), TOMC_E_CROSS_PLC_INTERFACE(30),
    TOMC_E_CROSS_PLC_INTERFACE(31), TOMC_E_CROSS_PLC_INTERFACE(32),
    TOMC_E_VARIABLE(CrossPlcSynchronousOperation.LocalLeadingValueDelayTime, kLreal, kRES, kConfiguration, 0.0,
                    k1e9, kAny, 0),
    // man. §10.4.4 Extrapolation (spec 04 §3.8); LeadingAxisDependentTime: no range printed
    TOMC_E_VARIABLE(Extrapolation.LeadingAxisDependentTime, kLreal, kRON, kConfiguration, kLrealMin, kLrealMax,
                    kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.FollowingAxisDependentTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.Settings.SystemDefinedExtrapolation, kDint, kRES, kConfiguration, 0.0, 1.0,
                    kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.Settings.ExtrapolatedVelocityMode, kDint, kRES, kConfiguration, 0.0, 2.0, kAny,
                    0),
    TOMC_E_VARIABLE(Extrapolation.PositionFilter.T1, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.PositionFilter.T2, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.VelocityFilter.T1, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.VelocityFilter.T2, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.VelocityTolerance.Range, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Extrapolation.Hysteresis.Value, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.4.5 LoadGear (spec 04 §3.9)
    TOMC_E_VARIABLE(LoadGear.Numerator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0),
    TOMC_E_VARIABLE(LoadGear.Denominator, kUdint, kRES, kConfiguration, 1.0, kUdintMax, kAny, 0),
    // man. §10.4.6 Properties (spec 04 §3.10)
    TOMC_E_VARIABLE(Properties.MotionType, kDint, kRON, kConfiguration, 0.0, 1.0, kAny, 0),
    // man. §10.4.7 Units (spec 04 §3.11, column E), RON
    TOMC_E_VARIABLE(Units.LengthUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kLengthUnits, 0),
    TOMC_E_VARIABLE(Units.VelocityUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kPositionVelocityUnits, 0),
    TOMC_E_VARIABLE(Units.TimeUnit, kUdint, kRON, kConfiguration, 0.0, kUdintMax, kTimeUnits, 0),
    // man. §10.4.8 Mechanics (spec 04 §3.12)
    TOMC_E_VARIABLE(Mechanics.LeadScrew, kLreal, kRES, kConfiguration, 1.0E-12, k1e12, kAny, 0),
    // man. §10.4.9 Modulo (spec 04 §3.13)
    TOMC_E_VARIABLE(Modulo.Enable, kBool, kRES, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(Modulo.Length, kLreal, kRES, kConfiguration, 0.001, k1e12, kAny, 0),
    TOMC_E_VARIABLE(Modulo.StartValue, kLreal, kRES, kConfiguration, -k1e12, k1e12, kAny, 0),
    // man. §10.4.10 Homing (spec 04 §3.18: HomePosition only)
    TOMC_E_VARIABLE(Homing.HomePosition, kLreal, kCAL, kConfiguration, -k1e12, k1e12, kAny, 0),
    // man. §10.4.11 StandstillSignal (spec 04 §3.26)
    TOMC_E_VARIABLE(StandstillSignal.VelocityThreshold, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    TOMC_E_VARIABLE(StandstillSignal.MinDwellTime, kLreal, kDIR, kConfiguration, 0.0, k1e12, kAny, 0),
    // man. §10.4.12 StatusProvidedLeadingValue (spec 04 §4.4), RON
    TOMC_E_VARIABLE(StatusProvidedLeadingValue.DelayedLeadingValue.Position, kLreal, kRON, kStatus, -k1e12, k1e12,
                    kAny, 0),
    TOMC_E_VARIABLE(StatusProvidedLeadingValue.DelayedLeadingValue.Velocity, kLreal, kRON, kStatus, -k1e12, k1e12,
                    kAny, 0),
    TOMC_E_VARIABLE(StatusProvidedLeadingValue.DelayedLeadingValue.Acceleration, kLreal, kRON, kStatus, -k1e12,
                    k1e12, kAny, 0),
    // man. §10.4.13 StatusSensor (spec 04 §4.5), RON; AdaptionState: printed "-", its values are 0 ... 4
    TOMC_E_VARIABLE(StatusSensor.State, kDint, kRON, kStatus, 0.0, 2.0, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.CommunicationOK, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.Error, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.AbsEncoderOffset, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.Control, kBool, kRON, kStatus, 0.0, 1.0, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.Position, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.Velocity, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.AdaptionState, kDint, kRON, kStatus, 0.0, 4.0, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.ModuloCycle, kDint, kRON, kStatus, kDintMin, kDintMax, kAny, 0),
    TOMC_E_VARIABLE(StatusSensor.Adjusted, kDint, kRON, kStatus, 0.0, 1.0, kAny, 0),
    // man. §10.4.14 StatusExtrapolation (spec 04 §4.6), RON
    TOMC_E_VARIABLE(StatusExtrapolation.FilteredPosition, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_E_VARIABLE(StatusExtrapolation.FilteredVelocity, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_E_VARIABLE(StatusExtrapolation.ExtrapolatedPosition, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    TOMC_E_VARIABLE(StatusExtrapolation.ExtrapolatedVelocity, kLreal, kRON, kStatus, -k1e12, k1e12, kAny, 0),
    // man. §10.4.15 ... §10.4.18 bit words (spec 04 §5, no StatusWord2 on E) and ErrorDetail (spec 04 §4.10)
    TOMC_E_VARIABLE(StatusWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_E_VARIABLE(ErrorWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_E_VARIABLE(ErrorDetail.Number, kUdint, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_E_VARIABLE(ErrorDetail.Reaction, kDint, kRON, kStatus, 0.0, 10.0, kReactionValues, 0),
    TOMC_E_VARIABLE(WarningWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
});
// clang-format on

#undef TOMC_E_CROSS_PLC_INTERFACE
#undef TOMC_E_ELEMENT_VREF
#undef TOMC_E_VREF
#undef TOMC_E_VREF_ROWS
#undef TOMC_E_ELEMENT
#undef TOMC_E_VARIABLE
#undef TOMC_E_ROW

static_assert(detail::paths_unique(kExternalEncoderVariables),
              "duplicate path in the external-encoder table");
static_assert(detail::ranges_valid(kExternalEncoderVariables),
              "an external-encoder range is empty, exceeds its data type or excludes a permitted value");

}  // namespace

// ---- TO_ExternalEncoder ----

std::span<const VariableInfo> external_encoder_variables() noexcept {
  return kExternalEncoderVariables;
}

const VariableInfo* find_external_encoder_variable(std::string_view path) noexcept {
  return find_variable(kExternalEncoderVariables, path);
}

std::optional<BitReference> find_external_encoder_bit(std::string_view path) noexcept {
  return find_bit(kExternalEncoderVariables, path);
}

}  // namespace tomc::techobjects
