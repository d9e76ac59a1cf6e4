#pragma once
// The technology data block of TO_SpeedAxis (spec 04 §1 column S; man. §10.2). Members carry the manual's
// variable names, so `<TO>.DynamicDefaults.Velocity` is `data.DynamicDefaults.Velocity`; nested struct types
// carry the manual's TIA type names (TO_Struct_*). Data types follow spec 04 §0.4: LREAL -> double, DINT ->
// int32_t, UDINT -> uint32_t, BOOL -> bool, WORD/DWORD -> uint16_t/uint32_t, VREF -> Vref, DB_ANY ->
// uint16_t.
//
// Start values: the manual gives almost none (spec 04 §14 item 1). Where it does, the value is marked
// "manual"; every other start value is marked "chosen" with the reason. Status variables (§2, §4, §5) start
// at zero/FALSE: the runtime owns them.
//
// Left out on purpose: `ControlPanel` and `InternalToTrace` (spec 04 §4.11, man. §10.2.20/§10.2.21: "no data
// relevant for the user", used internally by the axis control panel and by Trace; tomc does not reproduce the
// binary DB layout, so no opaque placeholder is kept). T_i/T_o/T_DC (MC_WriteParameter 1010..1012, spec 04
// §0.3) are no DB variables and belong to the drive connection.

#include <cstdint>

#include "tomc/techobjects/alarms.hpp"
#include "tomc/techobjects/status_bits.hpp"

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

struct SpeedAxisData {
  static constexpr TechnologyObjectType kTechnologyObjectType = TechnologyObjectType::kSpeedAxis;

  // ---- §2 actual values and setpoints (man. §10.2.1), all RON ----
  double Velocity = 0.0;          // speed setpoint (also shown as "load-side speed", spec 04 §14 item 12)
  double ActualSpeed = 0.0;       // actual motor speed in 1/min (PROFIdrive); 0.0 with an analog setpoint
  double Acceleration = 0.0;      // acceleration setpoint
  double VelocitySetpoint = 0.0;  // speed setpoint output to the drive, -1.0E12 ... 1.0E12

  // ---- §3.1 Simulation (man. §10.2.2) ----
  struct TO_Struct_AxisSimulation {
    std::uint32_t Mode =
        kModeOff;  // RES; chosen: 0 = normal operation (a real or simulated drive is connected)
  } Simulation;

  // ---- §3.2 VirtualAxis (man. §10.2.3) ----
  struct TO_Struct_VirtualAxis {
    std::uint32_t Mode = kModeOff;  // RON (download only); chosen: 0 = not virtual
  } VirtualAxis;

  // ---- §3.3 Actor (man. §10.2.4) ----
  struct TO_Struct_Actor {
    // RON; chosen: 1 = PROFIdrive telegram (the drives of tomc are PROFIdrive drives)
    std::int32_t Type = static_cast<std::int32_t>(ActorType::kProfidriveTelegram);
    bool InverseDirection = false;  // RES; chosen: FALSE (no inversion)
    // RES; chosen: 0 = manual (the simulated drive has no parameters to adopt)
    std::int32_t DataAdaption = static_cast<std::int32_t>(DataAdaptionMode::kManual);
    double Efficiency = 1.0;  // RES; chosen: 1.0 (loss-free gearbox)
    // RES, MC_WriteParameter 1020; manual: 16#7 (man. §10.2.4, §9.15)
    std::uint16_t RemoveEnableReaction =
        static_cast<std::uint16_t>(RemoveEnableMode::kOff3QuickStopCompatibleV7);

    struct TO_Struct_ActorInterface {
      Vref AddressIn;                  // RON; chosen: all zero (no address assigned)
      Vref AddressOut;                 // RON; chosen: all zero
      bool EnableDriveOutput = false;  // RES; chosen: FALSE (only analog drives use it)
      Vref EnableDriveOutputAddress;   // RON; chosen: all zero
      bool DriveReadyInput = false;    // RES; chosen: FALSE (only analog drives use it)
      Vref DriveReadyInputAddress;     // RON; chosen: all zero
      bool EnableTorqueData =
          false;                  // RES; manual: TRUE only if telegram 750 is configured; none is by default
      Vref TorqueDataAddressIn;   // RON; chosen: all zero
      Vref TorqueDataAddressOut;  // RON; chosen: all zero
    } Interface;

    struct TO_Struct_ActorDriveParameter {
      double ReferenceSpeed = 3000.0;  // RES; chosen: 3000 1/min = p2000 of tomc's simulated drive
      double MaxSpeed = 3000.0;  // RES; chosen: = ReferenceSpeed (PROFIdrive allows up to 2 x ReferenceSpeed)
      double ReferenceTorque = 4.0;  // RES; chosen: 4 Nm = p2003 of tomc's simulated drive
    } DriveParameter;
  } Actor;

  // ---- §3.4 TorqueLimiting (man. §10.2.5) ----
  struct TO_Struct_TorqueLimiting {
    // RES; chosen: 0 = motor side
    std::int32_t LimitBase = static_cast<std::int32_t>(TorqueLimitBase::kMotorSide);
    // RES; chosen: 0 = position-based monitorings deactivated while limiting (the speed axis has none anyway)
    std::int32_t PositionBasedMonitorings =
        static_cast<std::int32_t>(PositionBasedMonitoringMode::kDeactivated);

    struct TO_Struct_TorqueLimitingLimitDefaults {
      double Torque = 4.0;   // CAL; chosen: = Actor.DriveParameter.ReferenceTorque
      double Force = 100.0;  // CAL; chosen: 100 N (linear case only, unused by a speed axis)
    } LimitDefaults;
  } TorqueLimiting;

  // ---- §3.9 LoadGear (man. §10.2.6) ----
  struct TO_Struct_LoadGear {
    std::uint32_t Numerator = 1;    // RES; chosen: 1 (no gearbox), the lowest permitted value
    std::uint32_t Denominator = 1;  // RES; chosen: 1
  } LoadGear;

  // ---- §3.11 Units (man. §10.2.7), all RON ----
  struct TO_Struct_Units {
    std::uint32_t VelocityUnit = unit_code::kPerMinute;  // chosen: 1/min
    std::uint32_t TimeUnit = unit_code::kSecond;         // the only code: s
    std::uint32_t TorqueUnit =
        unit_code::kNewtonMetre;  // chosen: Nm (the manual's default torque unit, spec 04 §3.4)
    std::uint32_t ForceUnit =
        unit_code::kNewton;  // chosen: N (the manual's default force unit, spec 04 §3.4)
    std::uint32_t MassUnit = unit_code::kKilogram;  // chosen: kg
    // Name as printed in both DB tables (probably "InertiaUnit", spec 04 §14 item 4); chosen: kg·m²
    std::uint32_t IneritaUnit = unit_code::kKilogramSquareMetre;
  } Units;

  // ---- §3.14 DynamicLimits (man. §10.2.8) ----
  // Speed in Units.VelocityUnit, acceleration in 1/s², jerk in 1/s³ (spec 04 §3.11 derived units).
  struct TO_Struct_DynamicLimits {
    double MaxVelocity = 3000.0;     // RES; chosen: = Actor.DriveParameter.MaxSpeed
    double Velocity = 3000.0;        // DIR; chosen: = MaxVelocity (no extra programmable limit)
    double MaxAcceleration = 100.0;  // DIR; chosen
    double MaxDeceleration = 100.0;  // DIR; chosen
    double MaxJerk = 1000.0;         // DIR; chosen
  } DynamicLimits;

  // ---- §3.15 DynamicDefaults (man. §10.2.9) ----
  struct TO_Struct_DynamicDefaults {
    double Velocity = 1500.0;              // CAL; chosen: half the maximum velocity
    double Acceleration = 50.0;            // CAL; chosen: half MaxAcceleration
    double Deceleration = 50.0;            // CAL; chosen: half MaxDeceleration
    double Jerk = 0.0;                     // CAL; chosen: 0 = no jerk limitation (man. §6.7.1)
    double EmergencyDeceleration = 200.0;  // DIR; chosen: >= MaxDeceleration as spec 04 §3.15 recommends
  } DynamicDefaults;

  // ---- §3.19 Override (man. §10.2.10) ----
  struct TO_Struct_Override {
    double Velocity = 100.0;  // DIR, 0.0 ... 200.0 %; chosen: 100 % (no correction)
  } Override;

  // ---- §4.2 StatusDrive (man. §10.2.11), RON ----
  struct TO_Struct_StatusDrive {
    bool InOperation = false;
    bool CommunicationOK = false;
    bool Error = false;
    std::int32_t AdaptionState = static_cast<std::int32_t>(DriveAdaptionState::NOT_ADAPTED);
  } StatusDrive;

  // ---- §4.7 StatusTorqueData (man. §10.2.12), RON; the speed axis has 3 of the 6 members ----
  struct TO_Struct_StatusTorqueData {
    std::int32_t CommandAdditiveTorqueActive = 0;
    std::int32_t CommandTorqueRangeActive = 0;
    double ActualTorque = 0.0;
  } StatusTorqueData;

  // ---- §4.8 StatusMotionIn (man. §10.2.13), RON; S7-1500T functions ----
  struct TO_Struct_StatusMotionIn {
    std::int32_t FunctionState = static_cast<std::int32_t>(MotionInFunctionState::kNone);
  } StatusMotionIn;

  // ---- §4.9 StatusInterpreterMotion (man. §10.2.14); the Interpreter TO needs S7-1500T ----
  struct TO_Struct_StatusInterpreterMotion {
    std::uint16_t Interpreter = 0;  // DB_ANY, 0 = none; W not given in the manual, status structure -> RON
    std::uint32_t StatusWord = 0;   // DWORD, RON; bits: StatusInterpreterMotionBit
  } StatusInterpreterMotion;

  // ---- §5 bit words (man. §10.2.15 ... §10.2.19), RON; bits: StatusWordBit etc. ----
  std::uint32_t StatusWord = 0;
  std::uint32_t StatusWord2 = 0;
  std::uint32_t ErrorWord = 0;

  // ---- §4.10 ErrorDetail (man. §10.2.18), RON ----
  struct TO_Struct_ErrorDetail {
    std::uint32_t Number = 0;
    std::int32_t Reaction = static_cast<std::int32_t>(AlarmReaction::kNone);
  } ErrorDetail;

  std::uint32_t WarningWord = 0;
};

}  // namespace tomc::techobjects
