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

#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/to_types.hpp"

namespace tomc::techobjects {

struct SpeedAxisData : AxisStatusWords {
  static constexpr TechnologyObjectType kTechnologyObjectType = TechnologyObjectType::kSpeedAxis;

  // ---- §2 actual values and setpoints (man. §10.2.1), all RON ----
  double Velocity = 0.0;          // speed setpoint (also shown as "load-side speed", spec 04 §14 item 12)
  double ActualSpeed = 0.0;       // actual motor speed in 1/min (PROFIdrive); 0.0 with an analog setpoint
  double Acceleration = 0.0;      // acceleration setpoint
  double VelocitySetpoint = 0.0;  // speed setpoint output to the drive, -1.0E12 ... 1.0E12

  TO_Struct_AxisSimulation Simulation;

  // ---- §3.2 VirtualAxis (man. §10.2.3) ----
  TO_Struct_VirtualAxis VirtualAxis;

  // ---- §3.3 Actor (man. §10.2.4) ----
  TO_Struct_Actor Actor;  // the S part: Type ... DriveParameter.ReferenceTorque (spec 04 §3.3)

  // ---- §3.4 TorqueLimiting (man. §10.2.5) ----
  // Speed-axis defaults (chosen): LimitDefaults.Force 100 N (linear case only, unused by a speed axis).
  TO_Struct_TorqueLimiting TorqueLimiting{.LimitDefaults = {.Torque = 4.0, .Force = 100.0}};

  // ---- §3.9 LoadGear (man. §10.2.6) ----
  TO_Struct_LoadGear LoadGear;

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
  // Speed in Units.VelocityUnit, acceleration in 1/s², jerk in 1/s³ (spec 04 §3.11 derived units). Speed-axis
  // defaults (chosen): MaxVelocity = Actor.DriveParameter.MaxSpeed, Velocity = MaxVelocity.
  TO_Struct_DynamicLimits DynamicLimits{.MaxVelocity = 3000.0,
                                        .Velocity = 3000.0,
                                        .MaxAcceleration = 100.0,
                                        .MaxDeceleration = 100.0,
                                        .MaxJerk = 1000.0};

  // ---- §3.15 DynamicDefaults (man. §10.2.9) ----
  // Speed-axis defaults (chosen): Velocity half the maximum, Acceleration/Deceleration half the maxima, no
  // jerk limitation, EmergencyDeceleration >= MaxDeceleration as spec 04 §3.15 recommends.
  TO_Struct_DynamicDefaults DynamicDefaults{.Velocity = 1500.0,
                                            .Acceleration = 50.0,
                                            .Deceleration = 50.0,
                                            .Jerk = 0.0,
                                            .EmergencyDeceleration = 200.0};

  // ---- §3.19 Override (man. §10.2.10) ----
  TO_Struct_Override Override;

  // ---- §4.2 StatusDrive (man. §10.2.11), RON ----
  TO_Struct_StatusDrive StatusDrive;

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

  // §4.9 StatusInterpreterMotion, §5 bit words and §4.10 ErrorDetail (man. §10.2.14 ... §10.2.19):
  // AxisStatusWords
};

}  // namespace tomc::techobjects
