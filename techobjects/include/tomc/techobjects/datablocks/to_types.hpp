#pragma once
// The manual's shared data-block types, defined once for every TO (issue 14): the values of the enumerated
// DB variables (spec 04 §6.1), the unit codes (spec 04 §3.11), VREF, and the TO_Struct_* structures that more
// than one TO type carries (spec 04 §3, §4: `Extrapolation` of P/Y and E, `DynamicLimits` of S and P/Y, ...).
// The default values are the positioning axis' (positioning_axis_data.hpp explains each choice); a TO whose
// start values differ gives them where it declares the member (speed_axis_data.hpp,
// external_encoder_data.hpp).

#include <array>
#include <cstdint>

#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"

namespace tomc::techobjects {

// VREF: an I/O or DB bit reference (spec 04 §0.4; layout inferred from man. §6.10.2). Member names as printed
// there.
struct Vref {
  std::uint32_t RID = 0;        // DWORD, e.g. 16#02000001 = BOOL
  std::uint8_t AREA = 0;        // BYTE, e.g. 16#84 = DB area
  std::uint16_t DB_NUMBER = 0;  // UINT
  std::uint32_t OFFSET = 0;     // UDINT, bit offset = byte * 8 + bit
  friend constexpr bool operator==(const Vref&, const Vref&) noexcept = default;
};

// ---- values of the enumerated DB variables (spec 04 §6.1) ----
// For comparisons with the raw DINT/UDINT/WORD members.

// Simulation.Mode (UDINT), VirtualAxis.Mode (UDINT)
inline constexpr std::uint32_t kModeOff = 0;
inline constexpr std::uint32_t kModeOn = 1;

// Actor.Type (DINT)
enum class ActorType : std::int32_t { kAnalogOutput = 0, kProfidriveTelegram = 1 };
// Actor.DataAdaption (DINT)
enum class DataAdaptionMode : std::int32_t { kManual = 0, kAutomatic = 1 };
// Actor.RemoveEnableReaction (WORD); 16#0/2/4/6 are invalid (spec 04 §3.3)
enum class RemoveEnableMode : std::uint16_t {
  kOff1RampStop = 0x1,
  kOff2CoastStop = 0x3,
  kOff3QuickStop = 0x5,
  kOff3QuickStopCompatibleV7 = 0x7,  // default (manual)
};
// TorqueLimiting.LimitBase (DINT)
enum class TorqueLimitBase : std::int32_t { kMotorSide = 0, kLoadSide = 1 };
// TorqueLimiting.PositionBasedMonitorings (DINT)
enum class PositionBasedMonitoringMode : std::int32_t { kDeactivated = 0, kActive = 1 };
// StatusDrive.AdaptionState (DINT); enumerators are the literal strings of the manual
enum class DriveAdaptionState : std::int32_t {
  NOT_ADAPTED = 0,
  IN_ADAPTION = 1,
  ADAPTED = 2,
  NOT_APPLICABLE = 3,
  ADAPTION_ERROR = 4,
};
// StatusMotionIn.FunctionState (DINT); S: 0, 1 only
enum class MotionInFunctionState : std::int32_t { kNone = 0, kMotionInVelocity = 1, kMotionInPosition = 2 };
// ErrorDetail.Reaction (DINT) of S and P/Y (spec 04 §4.10, §7): AlarmReaction of alarms.hpp

// Unit codes of `Units.*` (UDINT) available on the speed axis (spec 04 §3.11, man. §10.2.7).
namespace unit_code {
// VelocityUnit
inline constexpr std::uint32_t kPerSecond = 1082;  // 1/s
inline constexpr std::uint32_t kPerMinute = 1083;  // 1/min
inline constexpr std::uint32_t kPerHour = 1528;    // 1/h
// TimeUnit
inline constexpr std::uint32_t kSecond = 1054;
// TorqueUnit
inline constexpr std::uint32_t kNewtonMetre = 1126;
inline constexpr std::uint32_t kKilonewtonMetre = 1128;
inline constexpr std::uint32_t kPoundForceInch =
    1529;  // printed "lbf (pound force inch)" (spec 04 §14 item 5)
inline constexpr std::uint32_t kPoundForceFoot = 1530;
inline constexpr std::uint32_t kOunceForceInch = 1531;
inline constexpr std::uint32_t kOunceForceFoot = 1532;
inline constexpr std::uint32_t kPoundalInch = 1533;
inline constexpr std::uint32_t kPoundalFoot = 1534;
// ForceUnit
inline constexpr std::uint32_t kNewton = 1120;
inline constexpr std::uint32_t kKilonewton = 1122;
inline constexpr std::uint32_t kPoundForce = 1094;
inline constexpr std::uint32_t kOunceForce = 1093;
inline constexpr std::uint32_t kPoundal = 1535;
// MassUnit
inline constexpr std::uint32_t kKilogram = 1088;
inline constexpr std::uint32_t kGram = 1089;
inline constexpr std::uint32_t kMilligram = 1090;
inline constexpr std::uint32_t kTonne = 1092;
inline constexpr std::uint32_t kPound = 1540;
// IneritaUnit (sic)
inline constexpr std::uint32_t kKilogramSquareMetre = 1118;
inline constexpr std::uint32_t kPoundSquareFoot = 1541;
}  // namespace unit_code

// ---- values of the enumerated DB variables of P/Y and E (spec 04 §6.1) ----
// Shared with speed_axis_data.hpp: kModeOff/kModeOn, ActorType, DataAdaptionMode (also Sensor.DataAdaption),
// RemoveEnableMode, TorqueLimitBase, PositionBasedMonitoringMode, DriveAdaptionState (also
// StatusSensor.AdaptionState), MotionInFunctionState. Enumerators in capitals are the manual's literal
// strings.

// Actor.MotorType (DINT)
enum class ActorMotorType : std::int32_t { kRotaryStandardMotor = 0, kLinearMotor = 1 };
// Sensor.Type (DINT)
enum class SensorEncoderType : std::int32_t { INCREMENTAL = 0, ABSOLUTE = 1, CYCLIC_ABSOLUTE = 2 };
// Sensor.System (DINT)
enum class SensorMeasuringSystem : std::int32_t { LINEAR = 0, ROTATORY = 1 };
// Sensor.MountingMode (DINT)
enum class SensorMountingMode : std::int32_t { kMotorShaft = 0, kLoadSide = 1, kExternalMeasuringSystem = 2 };
// Sensor.ActualVelocityMode (DINT)
enum class SensorActualVelocityMode : std::int32_t { kDifferentiatePosition = 0, kProfidriveNist = 1 };
// Sensor.Parameter.BehaviorGx_XIST1 (DINT); 1 is the default (manual)
enum class SensorXist1Behavior : std::int32_t { kResolutionBits = 0, kFull32Bit = 1 };
// Sensor.ActiveHoming.Mode, Sensor.PassiveHoming.Mode (DINT)
enum class SensorHomingMode : std::int32_t {
  kZeroMarkViaTelegram = 0,
  kZeroMarkViaTelegramAndReferenceCam = 1,
  kReferenceMarkViaDigitalInput = 2,
};
// Sensor.ActiveHoming.Direction (0, 1), Sensor.PassiveHoming.Direction (0...2),
// Sensor.Backlash.DirectionAbsoluteHoming (0, 1) (DINT)
enum class HomingDirection : std::int32_t { kPositive = 0, kNegative = 1, kCurrentDirection = 2 };
// CrossPlcSynchronousOperation.Interface[i].TelegramVersion (WORD)
enum class LeadingValueTelegramVersion : std::uint16_t { kVersion1 = 1, kVersion2 = 2 };
// Extrapolation.Settings.ExtrapolatedVelocityMode (DINT)
enum class ExtrapolatedVelocityMode : std::int32_t {
  kFilteredVelocity = 0,
  kExtrapolatedVelocity = 1,
  kDifferentiatedVelocity = 2,
};
// Properties.MotionType (DINT)
enum class PropertiesMotionType : std::int32_t { kLinear = 0, kRotary = 1 };
// PositionLimits_SW.LimitReachedBehavior (DINT)
enum class SoftwareLimitReachedBehavior : std::int32_t { kStopMaxDynamics = 0, kStopCurrentDynamics = 1 };
// PositionLimits_SW.LimitExceededBehavior, PositionLimits_HW.ApproachBehavior (DINT)
enum class LimitViolationBehavior : std::int32_t { kDisableAxis = 0, kEmergencyStopKeepEnabled = 1 };
// PositionLimits_HW.Mode (DINT)
enum class HardwareLimitSwitchMode : std::int32_t { kNonPassable = 0, kPassable = 1 };
// PositionControl.ControlDifferenceQuantization.Mode (DINT)
enum class QuantizationMode : std::int32_t { kNone = 0, kEncoderResolution = 1, kDirectValue = 2 };
// PositionControl.VelocityModePowerOn (DINT)
enum class VelocityModePowerOn : std::int32_t { kEmergencyStop = 0, kImmediatelyZero = 1 };
// TorquePreControl.Mode (DINT)
enum class TorquePreControlMode : std::int32_t { kOff = 0, kAccelerationBased = 1 };
// SetpointFilter.DynamicFilter.Mode (DINT)
enum class DynamicFilterMode : std::int32_t { kOff = 0, kPt1Pt2DeadTime = 1, kMovingAverageDeadTime = 2 };
// StatusSensor.State (DINT)
enum class SensorState : std::int32_t { NOT_VALID = 0, WAITING_FOR_VALID = 1, VALID = 2 };
// StatusSensor.Adjusted (DINT)
enum class SensorAdjusted : std::int32_t { kNotAdjusted = 0, kAdjusted = 1 };
// ErrorDetail.Reaction of S and P/Y: AlarmReaction (alarms.hpp); of E: ExternalEncoderReaction
// (external_encoder_data.hpp).

// Unit codes of `Units.LengthUnit` and the position-based `Units.VelocityUnit` (UDINT) of P/Y and E (spec 04
// §3.11, man. §10.3.12, §10.4.7). "HighResolution" = the manual's "*": position values with six decimals.
namespace unit_code {
// LengthUnit
inline constexpr std::uint32_t kMetre = 1010;
inline constexpr std::uint32_t kMillimetre = 1013;
inline constexpr std::uint32_t kMillimetreHighResolution = 1536;
inline constexpr std::uint32_t kKilometre = 1011;
inline constexpr std::uint32_t kMicrometre = 1014;
inline constexpr std::uint32_t kNanometre = 1015;
inline constexpr std::uint32_t kInch = 1019;
inline constexpr std::uint32_t kFoot = 1018;
inline constexpr std::uint32_t kMile = 1021;
inline constexpr std::uint32_t kRadian = 1004;
inline constexpr std::uint32_t kDegree = 1005;
inline constexpr std::uint32_t kDegreeHighResolution = 1537;
// VelocityUnit
inline constexpr std::uint32_t kDegreePerSecond = 1521;
inline constexpr std::uint32_t kDegreePerSecondHighResolution = 1539;
inline constexpr std::uint32_t kDegreePerMinute = 1522;
inline constexpr std::uint32_t kRadianPerSecond = 1086;
inline constexpr std::uint32_t kRadianPerMinute = 1523;
inline constexpr std::uint32_t kMillimetrePerSecond = 1062;
inline constexpr std::uint32_t kMillimetrePerSecondHighResolution = 1538;
inline constexpr std::uint32_t kMetrePerSecond = 1061;
inline constexpr std::uint32_t kMillimetrePerMinute = 1524;  // printed "m/min" like 1525 (spec 04 §14 item 5)
inline constexpr std::uint32_t kMetrePerMinute = 1525;
inline constexpr std::uint32_t kMillimetrePerHour = 1526;
inline constexpr std::uint32_t kMetrePerHour = 1063;
inline constexpr std::uint32_t kKilometrePerMinute = 1527;
inline constexpr std::uint32_t kKilometrePerHour = 1064;
inline constexpr std::uint32_t kInchPerSecond = 1066;
inline constexpr std::uint32_t kInchPerMinute = 1069;
inline constexpr std::uint32_t kFootPerSecond = 1067;
inline constexpr std::uint32_t kFootPerMinute = 1070;
inline constexpr std::uint32_t kMilePerHour = 1075;
}  // namespace unit_code

// ---- TO_Struct_* shared by several TO types ----

// ---- §3.7 CrossPlcSynchronousOperation (man. §10.3.8) ----
struct TO_Struct_CrossPlcSynchronousOperation {
  struct TO_Struct_CrossPlcLeadingValueInterface {
    bool EnableLeadingValueOutput = false;  // RON; chosen: FALSE (no cross-PLC leading value)
    Vref AddressOut;                        // RON; chosen: all zero
    // RON, 1 or 2; chosen: 1 = version 1, the one of technology >= V10.0 (tomc models V10.0)
    std::uint16_t TelegramVersion = static_cast<std::uint16_t>(LeadingValueTelegramVersion::kVersion1);
  };
  std::array<TO_Struct_CrossPlcLeadingValueInterface, 32> Interface;  // ARRAY [1..32]
  double LocalLeadingValueDelayTime = 0.0;  // RES, 0.0 ... 1.0E9 s; chosen: 0 (no delay)
};

// ---- §3.8 Extrapolation (man. §10.3.9) ----
// Chosen: no filtering, no tolerance band, no hysteresis (all 0.0); the leading-axis time is computed by
// the system.
struct TO_Struct_Extrapolation {
  double LeadingAxisDependentTime = 0.0;    // RON, no range; chosen: 0 (computed by the system, below)
  double FollowingAxisDependentTime = 0.0;  // DIR; chosen: 0

  struct TO_Struct_ExtrapolationSettings {
    std::int32_t SystemDefinedExtrapolation = 1;  // RES; chosen: 1 = active
    // RES; chosen: 0 = filtered actual velocity
    std::int32_t ExtrapolatedVelocityMode =
        static_cast<std::int32_t>(tomc::techobjects::ExtrapolatedVelocityMode::kFilteredVelocity);
  } Settings;
  struct TO_Struct_ExtrapolationPositionFilter {
    double T1 = 0.0;  // DIR; chosen
    double T2 = 0.0;  // DIR; chosen
  } PositionFilter;
  struct TO_Struct_ExtrapolationVelocityFilter {
    double T1 = 0.0;  // DIR; chosen
    double T2 = 0.0;  // DIR; chosen
  } VelocityFilter;
  struct TO_Struct_ExtrapolationVelocityTolerance {
    double Range = 0.0;  // DIR; chosen
  } VelocityTolerance;
  struct TO_Struct_ExtrapolationHysteresis {
    double Value = 0.0;  // DIR; chosen
  } Hysteresis;
};

// ---- §3.9 LoadGear (man. §10.3.10) ----
struct TO_Struct_LoadGear {
  std::uint32_t Numerator = 1;    // RES; chosen: 1 = gear_motor_revolutions of the simulated drive
  std::uint32_t Denominator = 1;  // RES; chosen: 1 = gear_load_revolutions
};

// ---- §3.12 Mechanics (man. §10.3.13) ----
struct TO_Struct_Mechanics {
  double LeadScrew = 10.0;  // RES; chosen: 10 mm/rev
};

// ---- §3.19 Override (man. §10.3.20) ----
struct TO_Struct_Override {
  double Velocity = 100.0;  // DIR, 0.0 ... 200.0 %; chosen: 100 % (no correction)
};

// ---- §3.26 StandstillSignal (man. §10.3.27) ----
struct TO_Struct_StandstillSignal {
  double VelocityThreshold = 1.0;  // DIR; chosen: 1 mm/s (= 6 1/min, below the drive's 20 1/min p1226)
  double MinDwellTime = 0.01;      // DIR; chosen: 10 ms
};

// ---- §4.2 StatusDrive (man. §10.3.29), RON ----
struct TO_Struct_StatusDrive {
  bool InOperation = false;
  bool CommunicationOK = false;
  bool Error = false;
  std::int32_t AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_ADAPTED);
};

// ---- §4.6 StatusExtrapolation (man. §10.3.33), RON ----
struct TO_Struct_StatusExtrapolation {
  double FilteredPosition = 0.0;
  double FilteredVelocity = 0.0;
  double ExtrapolatedPosition = 0.0;
  double ExtrapolatedVelocity = 0.0;
};

// ---- §4.9 StatusInterpreterMotion (man. §10.3.37); the Interpreter TO needs S7-1500T ----
struct TO_Struct_StatusInterpreterMotion {
  std::uint16_t Interpreter = 0;  // DB_ANY, 0 = none; W not given in the manual, status structure -> RON
  std::uint32_t StatusWord = 0;   // DWORD, RON; bits: StatusInterpreterMotionBit
};

// ---- §4.4 StatusProvidedLeadingValue (man. §10.3.31), RON ----
struct TO_Struct_StatusProvidedLeadingValue {
  struct TO_Struct_ProvidedLeadingValue {
    double Position = 0.0;
    double Velocity = 0.0;
    double Acceleration = 0.0;
  } DelayedLeadingValue;
};

// ---- §3.2 VirtualAxis (man. §10.3.3) ----
struct TO_Struct_VirtualAxis {
  std::uint32_t Mode = kModeOff;  // RON (download only); chosen: 0 = not virtual
};

// ---- §3.15 DynamicDefaults (man. §10.3.16) ----
struct TO_Struct_DynamicDefaults {
  double Velocity = 100.0;       // CAL; chosen: 100 mm/s, a fifth of MaxVelocity
  double Acceleration = 1000.0;  // CAL; chosen: a fifth of MaxAcceleration
  double Deceleration = 1000.0;  // CAL; chosen: a fifth of MaxDeceleration
  double Jerk = 0.0;             // CAL; chosen: 0 = no jerk limitation (man. §6.7.1), as the speed axis
  // DIR; chosen: 10000 mm/s² >= MaxDeceleration as spec 04 §3.15 recommends (≈ 1.9 Nm, below 4 Nm)
  double EmergencyDeceleration = 10000.0;
};

// ---- §3.14 DynamicLimits (man. §10.3.15), mm/s, mm/s², mm/s³ ----
struct TO_Struct_DynamicLimits {
  double MaxVelocity = 500.0;  // RES; chosen: MaxSpeed 3000 1/min x 10 mm/rev = 500 mm/s
  double Velocity = 500.0;     // DIR; chosen: = MaxVelocity (no extra programmable limit)
  // DIR; chosen: 5000 mm/s² needs ≈ 0.9 Nm with the simulated inertia (3.0E-4 kg·m² at the motor), a
  // quarter of the 4 Nm torque limit, leaving headroom for friction and the emergency ramp
  double MaxAcceleration = 5000.0;
  double MaxDeceleration = 5000.0;  // DIR; chosen: = MaxAcceleration
  double MaxJerk = 100000.0;        // DIR; chosen: MaxAcceleration reached in 50 ms
};

// ---- §3.13 Modulo (man. §10.3.14) ----
struct TO_Struct_Modulo {
  bool Enable = false;      // RES; chosen: FALSE (a linear slide)
  double Length = 360.0;    // RES, 0.001...; chosen: 360 (the usual rotary length; unused while disabled)
  double StartValue = 0.0;  // RES; chosen: 0
};

// ---- §3.10 Properties (man. §10.3.11) ----
struct TO_Struct_Properties {
  // RON; chosen: 0 = linear axis (a lead-screw slide in mm)
  std::int32_t MotionType = static_cast<std::int32_t>(PropertiesMotionType::kLinear);
};

// ---- §3.4 TorqueLimiting (man. §10.3.5) ----
struct TO_Struct_TorqueLimiting {
  // RES; chosen: 0 = motor side
  std::int32_t LimitBase = static_cast<std::int32_t>(TorqueLimitBase::kMotorSide);
  // RES; printed "PositionBasedMonitors" in the P table, named as in the S table and TIA Openness (spec 04
  // §14 item 4); chosen: 0 = position-based monitorings deactivated while limiting
  std::int32_t PositionBasedMonitorings =
      static_cast<std::int32_t>(PositionBasedMonitoringMode::kDeactivated);

  struct TO_Struct_TorqueLimitingLimitDefaults {
    double Torque = 4.0;    // CAL; chosen: = Actor.DriveParameter.ReferenceTorque
    double Force = 2500.0;  // CAL; chosen: = Actor.LinearMotorDriveParameter.ReferenceForce
  } LimitDefaults;
};

// ---- §4.10 ErrorDetail (man. §10.3.41), RON ----
struct TO_Struct_ErrorDetail {
  std::uint32_t Number = 0;
  std::int32_t Reaction = static_cast<std::int32_t>(AlarmReaction::kNone);  // 0 ... 5
};

// What the data block of every axis ends with (spec 04 §4.9, §4.10, §5; man. §10.2.14 ... §10.2.19 for S,
// §10.3.37 ... §10.3.42 for P/Y): StatusInterpreterMotion, the bit words (bits: StatusWordBit etc.) and
// ErrorDetail, all RON. One declaration for the speed and the positioning axis: their data blocks derive from
// it, so the members stay `data.StatusWord` (not a TIA type of its own; tomc does not reproduce the DB
// layout).
struct AxisStatusWords {
  TO_Struct_StatusInterpreterMotion StatusInterpreterMotion;  // the Interpreter TO needs S7-1500T
  std::uint32_t StatusWord = 0;
  std::uint32_t StatusWord2 = 0;
  std::uint32_t ErrorWord = 0;
  TO_Struct_ErrorDetail ErrorDetail;
  std::uint32_t WarningWord = 0;
};

// ---- parts of Sensor[n] (P/Y), Sensor (E), Actor (S, P/Y) and Simulation (S, P/Y) ----

struct TO_Struct_SensorInterface {
  Vref AddressIn;            // RON; chosen: all zero (no address assigned)
  Vref AddressOut;           // RON; chosen: all zero
  std::uint32_t Number = 1;  // RON, 1...2; chosen: 1 = G1 of the drive telegram
};

struct TO_Struct_SensorParameter {
  double Resolution = 0.001;  // RES; chosen: 1 µm (only a linear encoder uses it; 0 is outside the range)
  std::uint32_t StepsPerRevolution = 2048;    // RES; chosen: 2048 = the simulated encoder
  std::uint32_t FineResolutionXist1 = 11;     // RES; chosen: 11 bits = the simulated encoder
  std::uint32_t FineResolutionXist2 = 9;      // RES; chosen: 9 bits = the simulated encoder
  std::uint32_t DeterminableRevolutions = 0;  // RES; manual: 0 for an incremental encoder (Type above)
  // RES; chosen: 10 mm = Mechanics.LeadScrew (only MountingMode 2 uses it)
  double DistancePerRevolution = 10.0;
  // RES; manual: 1 = full 32-bit Gx_XIST1 (the simulated encoder's XIST1 is 32 bits wide)
  std::int32_t BehaviorGx_XIST1 = static_cast<std::int32_t>(SensorXist1Behavior::kFull32Bit);
  double ReferenceSpeed = 3000.0;  // RES; chosen: 3000 1/min = the drive's p2000 (NIST_B reference)
  double ReferenceVelocity =
      500.0;  // RES; chosen: 500 mm/s (linear encoder only) = DynamicLimits.MaxVelocity
};

// StatusSensor of P/Y (Array [1..4]) and E (one), RON (man. §10.3.32, §10.4.13).
struct TO_Struct_StatusSensor {
  std::int32_t State = static_cast<std::int32_t>(SensorState::NOT_VALID);
  bool CommunicationOK = false;
  bool Error = false;
  double AbsEncoderOffset = 0.0;  // retentive in the CPU (spec 04 §8 item 9)
  bool Control = false;
  double Position = 0.0;
  double Velocity = 0.0;
  std::int32_t AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_ADAPTED);
  std::int32_t ModuloCycle = 0;
  std::int32_t Adjusted = static_cast<std::int32_t>(SensorAdjusted::kNotAdjusted);
};

struct TO_Struct_SensorPassiveHoming {
  // RES; chosen: 0 = zero mark via PROFIdrive telegram, as ActiveHoming.Mode
  std::int32_t Mode = static_cast<std::int32_t>(SensorHomingMode::kZeroMarkViaTelegram);
  bool SideInput = true;  // CAL; printed "SidelInput"; chosen: TRUE = positive side
  // CAL; chosen: 2 = current direction of motion (passive homing follows whatever motion runs)
  std::int32_t Direction = static_cast<std::int32_t>(HomingDirection::kCurrentDirection);
  Vref DigitalInputAddress;  // RON; chosen: all zero
  bool SwitchLevel = true;   // RES; chosen: TRUE = high level
};

struct TO_Struct_ActorInterface {
  Vref AddressIn;                  // RON; chosen: all zero (no address assigned)
  Vref AddressOut;                 // RON; chosen: all zero
  bool EnableDriveOutput = false;  // RES; chosen: FALSE (only analog drives use it)
  Vref EnableDriveOutputAddress;   // RON; chosen: all zero
  bool DriveReadyInput = false;    // RES; chosen: FALSE (only analog drives use it)
  Vref DriveReadyInputAddress;     // RON; chosen: all zero
  bool EnableTorqueData = false;   // RES; manual: TRUE only if telegram 750 is configured; none is by default
  Vref TorqueDataAddressIn;        // RON; chosen: all zero
  Vref TorqueDataAddressOut;       // RON; chosen: all zero
};

// Actor of S and P/Y (spec 04 §3.3, man. §10.2.4, §10.3.4): one TO_Struct_Actor; the speed axis has no
// MotorType, LoadInertia, MotorInertia or LinearMotorDriveParameter (its reflection table leaves them out).
struct TO_Struct_Actor {
  // RON; chosen: 1 = PROFIdrive telegram (the drives of tomc are PROFIdrive drives)
  std::int32_t Type = static_cast<std::int32_t>(ActorType::kProfidriveTelegram);
  bool InverseDirection = false;  // RES; chosen: FALSE (no inversion)
  // RES; chosen: 0 = manual (the simulated drive has no parameter channel to adopt from)
  std::int32_t DataAdaption = static_cast<std::int32_t>(DataAdaptionMode::kManual);
  double Efficiency = 1.0;  // RES; chosen: 1.0 (loss-free gearbox and lead screw, as the simulated mechanics)
  // DL; chosen: 0 = rotary standard motor (the simulated drive is a rotary servo motor)
  std::int32_t MotorType = static_cast<std::int32_t>(ActorMotorType::kRotaryStandardMotor);
  // DIR; chosen: 79.0 kg, the simulated drive's load inertia 2.0E-4 kg·m² at the screw expressed as the
  // equivalent load mass of the 10 mm lead screw, m = J·(2π/h)² ≈ 78.96 kg (linear motion: a mass)
  double LoadInertia = 79.0;
  // RES, MC_WriteParameter 1020; manual: 16#7 (man. §10.2.4, §10.3.4, §9.15)
  std::uint16_t RemoveEnableReaction =
      static_cast<std::uint16_t>(RemoveEnableMode::kOff3QuickStopCompatibleV7);

  TO_Struct_ActorInterface Interface;

  // Valid with MotorType = 0.
  struct TO_Struct_ActorDriveParameter {
    double ReferenceSpeed = 3000.0;  // RES; chosen: 3000 1/min = p2000 of tomc's simulated drive
    double MaxSpeed = 3000.0;      // RES; chosen: = ReferenceSpeed, as the speed axis (PROFIdrive allows 2x)
    double ReferenceTorque = 4.0;  // RES; chosen: 4 Nm = p2003 of tomc's simulated drive
    double MotorInertia = 1.0E-4;  // DIR; chosen: 1.0E-4 kg·m² = motor_inertia_kgm2 of the simulated drive
  } DriveParameter;

  // Valid with MotorType = 1 (a linear motor); unused by the default rotary motor. Chosen to describe the
  // same drive seen from the load: 3000 1/min x 10 mm = 500 mm/s, 2π x 4 Nm / 10 mm ≈ 2513 N.
  struct TO_Struct_LinearMotorActorDriveParameter {
    double ReferenceVelocity = 500.0;  // RES; chosen: 500 mm/s
    double MaxVelocity = 500.0;        // RES; chosen: = ReferenceVelocity
    double ReferenceForce = 2500.0;    // RES; chosen: 2500 N (≈ 2513 N, rounded)
    double MotorMass = 1.0;            // DIR; chosen: 1 kg (a small linear motor's moving part)
  } LinearMotorDriveParameter;
};

// ---- §3.1 Simulation (man. §10.3.2) ----
struct TO_Struct_AxisSimulation {
  std::uint32_t Mode = kModeOff;  // RES; chosen: 0 = normal operation (the simulated drive is connected)
};

}  // namespace tomc::techobjects
