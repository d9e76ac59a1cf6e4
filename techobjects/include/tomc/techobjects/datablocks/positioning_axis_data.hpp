#pragma once
// The technology data block of TO_PositioningAxis (spec 04 §1 column P/Y; man. §10.3). The synchronous axis
// (TO_SynchronousAxis) has all of these variables (spec 04 §0.1); its synchronous-operation-only variables
// (StatusSynchronizedMotion, leading-value interconnections) are not defined in the source (spec 04 §14 item
// 2) and are not reproduced. Conventions as in speed_axis_data.hpp: members carry the manual's variable
// names, nested struct types the manual's TIA type names, data types follow spec 04 §0.4, and every start
// value is marked "manual" (the source gives it) or "chosen" (with the reason). Status variables (§2, §4, §5)
// start at zero/FALSE unless their range excludes zero.
//
// Arrays: `Sensor[1..4]` and `StatusSensor[1..4]` (ARRAY [1..4] OF ..., spec 04 §0.4) and
// `CrossPlcSynchronousOperation.Interface[1..32]` are std::array, 0-based in C++ and 1-based in the paths of
// the reflection table: `Sensor[1].Parameter.StepsPerRevolution` is `data.Sensor[0].Parameter.
// StepsPerRevolution`. Indices 2...4 of Sensor/StatusSensor are for S7-1500T only.
//
// Default axis (all "chosen", consistent with tomc's simulated drive, docs/simulated-drive.md): a linear axis
// in mm driven through a 10 mm/rev lead screw and a 1:1 load gear by a small servo motor (reference speed
// 3000 1/min, reference torque 4 Nm, motor inertia 1.0E-4 kg·m²) with one encoder on the motor shaft (2048
// steps/rev, fine resolution 11/9 bits, 32-bit Gx_XIST1), evaluated as an incremental encoder.
//
// Left out on purpose, as for the speed axis: `ControlPanel` and `InternalToTrace` (spec 04 §4.11, man.
// §10.3.43/§10.3.44: "no data relevant for the user"); T_i/T_o/T_DC (MC_WriteParameter 1010...1012) are no DB
// variables.

#include <array>
#include <cstdint>

#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/to_types.hpp"

namespace tomc::techobjects {

struct PositioningAxisData : AxisStatusWords {
  static constexpr TechnologyObjectType kTechnologyObjectType = TechnologyObjectType::kPositioningAxis;

  // ---- §2 actual values and setpoints (man. §10.3.1), all RON ----
  double Position = 0.0;            // position setpoint
  double Velocity = 0.0;            // velocity setpoint
  double ActualPosition = 0.0;      // actual position
  double ActualVelocity = 0.0;      // actual velocity
  double ActualSpeed = 0.0;         // actual motor speed in 1/min (PROFIdrive); 0.0 analog / linear motor
  double Acceleration = 0.0;        // acceleration setpoint
  double ActualAcceleration = 0.0;  // actual acceleration
  // 1...4; starts at 1: zero is outside the range, and encoder 1 is the operative one on S7-1500 (the runtime
  // sets it from PositionControl.InitialOperativeSensor on restart)
  std::uint32_t OperativeSensor = 1;
  std::int32_t ModuloCycle = 0;        // modulo cycle of the setpoint
  std::int32_t ActualModuloCycle = 0;  // modulo cycle of the actual value
  double VelocitySetpoint = 0.0;       // velocity setpoint output to the drive, -1.0E12 ... 1.0E12

  TO_Struct_AxisSimulation Simulation;

  // ---- §3.2 VirtualAxis (man. §10.3.3) ----
  TO_Struct_VirtualAxis VirtualAxis;

  // ---- §3.3 Actor (man. §10.3.4) ----
  TO_Struct_Actor Actor;  // MotorType, LoadInertia and the motor data are P/Y only

  // ---- §3.4 TorqueLimiting (man. §10.3.5) ----
  TO_Struct_TorqueLimiting TorqueLimiting;

  // ---- §3.5 Clamping (man. §10.3.6) ----
  struct TO_Struct_Clamping {
    // DIR; chosen: 1 mm, below FollowingError.MinValue (2 mm) as spec 04 §3.5 requires
    double FollowingErrorDeviation = 1.0;
    double PositionTolerance = 0.5;  // DIR; chosen: 0.5 mm, below FollowingErrorDeviation (spec 04 §3.5)
  } Clamping;

  // ---- §3.6 Sensor[1..4] (man. §10.3.7): ARRAY [1..4] OF TO_Struct_Sensor ----
  // Every element has the start values of encoder 1 below except Existent: only Sensor[1] is configured
  // (S7-1500 uses index 1 only; 2...4 are S7-1500T encoders).
  struct TO_Struct_Sensor {
    bool Existent = false;  // RON; chosen: TRUE for Sensor[1] only (see the array below)
    // RON; chosen: 0 = INCREMENTAL. The simulated encoder can report a multi-turn absolute value (4096
    // revolutions), but an incremental evaluation gives a defined, non-retentive state after every restart:
    // the axis is not homed until MC_Home runs, and no retentive StatusSensor.AbsEncoderOffset adjustment
    // (MC_Home 6/7) has to exist first. The manual gives no default.
    std::int32_t Type = static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL);
    bool InverseDirection = false;  // RES; chosen: FALSE
    // RES; chosen: 1 = ROTATORY (the simulated encoder is a rotary encoder on the motor shaft)
    std::int32_t System = static_cast<std::int32_t>(SensorMeasuringSystem::ROTATORY);
    // RES; chosen: 0 = motor shaft (encoder1 of the simulated drive)
    std::int32_t MountingMode = static_cast<std::int32_t>(SensorMountingMode::kMotorShaft);
    // RES; chosen: 0 = manual (the simulated drive has no parameter channel)
    std::int32_t DataAdaption = static_cast<std::int32_t>(DataAdaptionMode::kManual);
    // RES; chosen: 0 = differentiate the position (a high-resolution encoder: 2048 x 2^11 counts/rev)
    std::int32_t ActualVelocityMode =
        static_cast<std::int32_t>(SensorActualVelocityMode::kDifferentiatePosition);

    TO_Struct_SensorInterface Interface;

    TO_Struct_SensorParameter Parameter;

    // Motor-shaft encoders only (TO >= V6.0).
    struct TO_Struct_Backlash {
      bool Enable = false;    // DIR; chosen: FALSE (the simulated mechanics have no backlash)
      double Size = 0.0;      // DIR; chosen: 0
      double Velocity = 0.0;  // DIR; chosen: 0.0 = crossed within one servo cycle
      // DIR; chosen: 0 = positive
      std::int32_t DirectionAbsoluteHoming = static_cast<std::int32_t>(HomingDirection::kPositive);
    } Backlash;

    struct TO_Struct_SensorActiveHoming {
      // RES; chosen: 0 = zero mark via PROFIdrive telegram (the simulated encoder has one per revolution)
      std::int32_t Mode = static_cast<std::int32_t>(SensorHomingMode::kZeroMarkViaTelegram);
      // CAL; printed "SidelInput" (spec 04 §14 item 4); chosen: TRUE = positive edge side
      bool SideInput = true;
      std::int32_t Direction = static_cast<std::int32_t>(HomingDirection::kPositive);  // CAL; chosen
      Vref DigitalInputAddress;         // RON; chosen: all zero (no digital input assigned)
      double HomePositionOffset = 0.0;  // CAL; chosen: 0 (home point at the reference mark)
      bool SwitchLevel = true;          // RES; chosen: TRUE = high level (a high-active 24 V input)
    } ActiveHoming;

    TO_Struct_SensorPassiveHoming PassiveHoming;

    // Rotary encoders only.
    struct TO_Struct_SensorMeasuringGear {
      std::uint32_t Numerator = 1;    // RES; manual: default 1
      std::uint32_t Denominator = 1;  // RES; chosen: 1 (encoder directly on the motor shaft)
    } MeasuringGear;
  };
  static constexpr std::array<TO_Struct_Sensor, 4> initial_sensors() noexcept {
    std::array<TO_Struct_Sensor, 4> sensors{};
    sensors[0].Existent = true;  // chosen: encoder 1 is configured, 2...4 are not
    return sensors;
  }
  std::array<TO_Struct_Sensor, 4> Sensor = initial_sensors();

  // ---- §3.7 CrossPlcSynchronousOperation (man. §10.3.8) ----
  TO_Struct_CrossPlcSynchronousOperation CrossPlcSynchronousOperation;

  // ---- §3.8 Extrapolation (man. §10.3.9) ----
  // Chosen: no filtering, no tolerance band, no hysteresis (all 0.0); the leading-axis time is computed by
  // the system.
  TO_Struct_Extrapolation Extrapolation;

  // ---- §3.9 LoadGear (man. §10.3.10) ----
  TO_Struct_LoadGear LoadGear;

  // ---- §3.10 Properties (man. §10.3.11) ----
  TO_Struct_Properties Properties;

  // ---- §3.11 Units (man. §10.3.12), all RON ----
  struct TO_Struct_Units {
    std::uint32_t LengthUnit = unit_code::kMillimetre;             // chosen: mm (linear axis)
    std::uint32_t VelocityUnit = unit_code::kMillimetrePerSecond;  // chosen: mm/s
    std::uint32_t TimeUnit = unit_code::kSecond;                   // the only code: s
    std::uint32_t TorqueUnit = unit_code::kNewtonMetre;  // chosen: Nm (the manual's default, spec 04 §3.4)
    std::uint32_t ForceUnit = unit_code::kNewton;        // chosen: N (the manual's default, spec 04 §3.4)
    std::uint32_t MassUnit = unit_code::kKilogram;       // chosen: kg
    // Name as printed (probably "InertiaUnit", spec 04 §14 item 4); chosen: kg·m²
    std::uint32_t IneritaUnit = unit_code::kKilogramSquareMetre;
  } Units;

  // ---- §3.12 Mechanics (man. §10.3.13) ----
  TO_Struct_Mechanics Mechanics;

  // ---- §3.13 Modulo (man. §10.3.14) ----
  TO_Struct_Modulo Modulo;

  // ---- §3.14 DynamicLimits (man. §10.3.15), mm/s, mm/s², mm/s³ ----
  TO_Struct_DynamicLimits DynamicLimits;

  // ---- §3.15 DynamicDefaults (man. §10.3.16) ----
  TO_Struct_DynamicDefaults DynamicDefaults;

  // ---- §3.16 PositionLimits_SW (man. §10.3.17) ----
  struct TO_Struct_PositionLimitsSW {
    bool Active = false;           // DIR; chosen: FALSE (the simulated machine has no limits by default)
    double MinPosition = -1000.0;  // DIR; chosen: -1000 mm
    double MaxPosition = 1000.0;   // DIR; chosen: 1000 mm (> MinPosition as required)
    // RES; chosen: 0 = stop with maximum dynamics
    std::int32_t LimitReachedBehavior =
        static_cast<std::int32_t>(SoftwareLimitReachedBehavior::kStopMaxDynamics);
    // RES; chosen: 0 = disable the axis
    std::int32_t LimitExceededBehavior = static_cast<std::int32_t>(LimitViolationBehavior::kDisableAxis);
  } PositionLimits_SW;

  // ---- §3.17 PositionLimits_HW (man. §10.3.18) ----
  struct TO_Struct_PositionLimitsHW {
    // RES, MC_WriteParameter 1000; chosen: FALSE, as the start value of the man. §6.10 example (spec 04
    // §0.3); the simulated machine has no limit switches by default
    bool Active = false;
    bool MinSwitchLevel =
        false;              // RES; chosen: FALSE = low-active (normally closed contact, wire-break safe)
    Vref MinSwitchAddress;  // RES; chosen: all zero (no input assigned)
    bool MaxSwitchLevel = false;  // RES; chosen: FALSE = low-active
    Vref MaxSwitchAddress;        // RES; chosen: all zero
    // RES; chosen: 0 = non-passable switch
    std::int32_t Mode = static_cast<std::int32_t>(HardwareLimitSwitchMode::kNonPassable);
    // RES; chosen: 0 = disable the axis
    std::int32_t ApproachBehavior = static_cast<std::int32_t>(LimitViolationBehavior::kDisableAxis);
  } PositionLimits_HW;

  // ---- §3.18 Homing (man. §10.3.19) ----
  struct TO_Struct_Homing {
    bool AutoReversal = false;         // RES; chosen: FALSE (no hardware limit switches by default)
    bool ApproachDirection = false;    // CAL; chosen: FALSE = positive
    double ApproachVelocity = 20.0;    // CAL; chosen: 20 mm/s
    double ReferencingVelocity = 5.0;  // CAL; chosen: 5 mm/s (slower, for an exact reference-mark capture)
    double HomePosition = 0.0;         // CAL; chosen: 0
  } Homing;

  // ---- §3.19 Override (man. §10.3.20) ----
  TO_Struct_Override Override;

  // ---- §3.20 PositionControl (man. §10.3.21) ----
  struct TO_Struct_PositionControl {
    // DIR; chosen: 50 1/s: with the simulated 2 ms speed loop plus ~3 ms of bus and cycle delay,
    // Kv x T ≈ 0.25 keeps the loop well damped
    double Kv = 50.0;
    double Kpc = 100.0;  // DIR; manual: 100 % recommended for isochronous PROFIdrive (the simulated drive)
    bool EnableDSC = false;  // RES; chosen: FALSE (DSC needs telegram 5/6/105/106)
    double SmoothingTimeByChangeDifference =
        0.0;                                   // DIR; chosen: 0 s (one encoder: no switch-over by default)
    std::uint32_t InitialOperativeSensor = 1;  // RES, 1...4; chosen: 1 (the only encoder on S7-1500)

    struct TO_Struct_PositionDifferenceQuantification {
      std::int32_t Mode = static_cast<std::int32_t>(QuantizationMode::kNone);  // RES; chosen: 0 = none
      double Value = 0.001;  // RES, 0.001...; chosen: 0.001 = the lower limit (unused with Mode 0)
    } ControlDifferenceQuantization;

    // RES; chosen: 0 = brought to zero with the maximum dynamics
    std::int32_t VelocityModePowerOn =
        static_cast<std::int32_t>(tomc::techobjects::VelocityModePowerOn::kEmergencyStop);

    // tomc extension (issue 20; spec 05b C.2, C.8 item 1): PID position control, pid_regulator.hpp. All DIR;
    // all 0 = the S7's P controller. Not with EnableDSC.
    struct TO_Struct_PositionControlPid {
      double IntegralTime = 0.0;           // Ti [s], 0 = no I
      double DerivativeTime = 0.0;         // Td [s], 0 = no D
      std::uint32_t DerivativeCycles = 1;  // D sample in servo cycles, 1 ... 256
      double IntegralLimit = 0.0;          // |I| bound [velocity unit], 0 = none
      double DeadBand = 0.0;               // [length unit]
      double OutputLimit = 0.0;            // |PID| bound [velocity unit], 0 = none
    } Pid;
  } PositionControl;

  // ---- §3.21 TorquePreControl (man. §10.3.22) ----
  struct TO_Struct_TorquePreControl {
    // RES; chosen: 0 = off (needs telegram 750, none is configured by default)
    std::int32_t Mode = static_cast<std::int32_t>(TorquePreControlMode::kOff);
    double Scale = 100.0;  // DIR, 0.0 ... 150.0 %; chosen: 100 %
  } TorquePreControl;

  // ---- §3.22 SetpointFilter (man. §10.3.23) ----
  struct TO_Struct_SetpointFilter {
    struct TO_Struct_DynamicFilter {
      std::int32_t Mode = static_cast<std::int32_t>(DynamicFilterMode::kOff);  // RES; manual: 0 = off
      double T1 = 0.0;  // DIR; manual: 0 (filter inactive)
      double T2 = 0.0;  // DIR; manual: 0
      double Tt = 0.0;  // DIR; manual: 0
    } DynamicFilter;
  } SetpointFilter;

  // ---- §3.23 DynamicAxisModel (man. §10.3.24) ----
  struct TO_Struct_DynamicAxisModel {
    // DIR; chosen: 0.002 s = speed_loop_time_constant_s of the simulated drive. The manual's project default
    // is 0.0 s (spec 04 §14 item 1), which it says to optimize when Kpc > 0; tomc knows its drive's loop.
    double VelocityTimeConstant = 0.002;
    double AdditionalPositionTimeConstant = 0.0;  // DIR; chosen: 0 s
    double CurrentTimeConstant = 0.0;  // DIR; chosen: 0 s (the simulated drive has no current loop)
  } DynamicAxisModel;

  // ---- §3.24 FollowingError (man. §10.3.25) ----
  // The manual's V10 defaults 30° / 360° are for rotary axes; this axis is linear (chosen values in mm).
  struct TO_Struct_FollowingError {
    bool EnableMonitoring = true;  // RES; chosen: TRUE
    double MinValue = 2.0;         // DIR; chosen: 2 mm below MinVelocity
    // DIR; chosen: 10 mm at maximum velocity: twice the 5 mm lag of 500 mm/s at Kv 50 without precontrol
    double MaxValue = 10.0;
    double MinVelocity = 10.0;                 // DIR; chosen: 10 mm/s
    double WarningLevel = 90.0;                // DIR, %; chosen: 90 %
    double AdditionalSetpointDelayTime = 0.0;  // DIR; chosen: 0 s (dynamic filter off)
  } FollowingError;

  // ---- §3.25 PositioningMonitoring (man. §10.3.26) ----
  struct TO_Struct_PositionMonitoring {
    double ToleranceTime = 1.0;  // DIR; chosen: 1 s
    double MinDwellTime = 0.01;  // DIR; chosen: 10 ms (spec 04 §3.25: 0 ... 20 ms for dynamic tasks)
    double Window = 0.01;        // DIR, 0.001...; chosen: 10 µm
  } PositioningMonitoring;

  // ---- §3.26 StandstillSignal (man. §10.3.27) ----
  TO_Struct_StandstillSignal StandstillSignal;

  // ---- §4.1 StatusPositioning (man. §10.3.28), RON ----
  struct TO_Struct_StatusPositioning {
    double Distance = 0.0;
    double TargetPosition = 0.0;
    std::int32_t TargetPositionModuloCycle = 0;
    double FollowingError = 0.0;
    double SetpointExecutionTime = 0.0;
    double SuperimposedDistance = 0.0;
  } StatusPositioning;

  // ---- §4.2 StatusDrive (man. §10.3.29), RON ----
  TO_Struct_StatusDrive StatusDrive;

  // ---- §4.3 StatusServo (man. §10.3.30), RON ----
  struct TO_Struct_StatusServo {
    double BalancedPosition = 0.0;
    double ControlDifference = 0.0;
    double PositionAfterDynamicFilter = 0.0;
  } StatusServo;

  // ---- §4.4 StatusProvidedLeadingValue (man. §10.3.31), RON ----
  TO_Struct_StatusProvidedLeadingValue StatusProvidedLeadingValue;

  // ---- §4.5 StatusSensor[1..4] (man. §10.3.32): Array [1..4] OF TO_Struct_StatusSensor, RON ----
  std::array<TO_Struct_StatusSensor, 4> StatusSensor;

  // ---- §4.6 StatusExtrapolation (man. §10.3.33), RON ----
  TO_Struct_StatusExtrapolation StatusExtrapolation;

  // ---- §5.5 StatusKinematicsMotion (man. §10.3.34), DWORD, RON; bits: StatusKinematicsMotionBit ----
  std::uint32_t StatusKinematicsMotion = 0;

  // ---- §4.7 StatusTorqueData (man. §10.3.35), RON; all 6 members ----
  struct TO_Struct_StatusTorqueData {
    std::int32_t CommandAdditiveTorqueActive = 0;
    std::int32_t CommandTorqueRangeActive = 0;
    double ActualTorque = 0.0;
    double ActualForce = 0.0;
    double TotalTorqueAdditive = 0.0;
    double TotalForceAdditive = 0.0;
  } StatusTorqueData;

  // ---- §4.8 StatusMotionIn (man. §10.3.36), RON; S7-1500T functions ----
  struct TO_Struct_StatusMotionIn {
    std::int32_t FunctionState = static_cast<std::int32_t>(MotionInFunctionState::kNone);
    std::uint16_t ActualSuperimposingAxis = 0;  // DB_ANY, 0 = no MC_MotionInSuperimposedAxes job
    std::uint32_t StatusWord = 0;               // DWORD; bits: StatusMotionInBit
  } StatusMotionIn;

  // §4.9 StatusInterpreterMotion, §5 bit words and §4.10 ErrorDetail (man. §10.3.37 ... §10.3.42):
  // AxisStatusWords
};

}  // namespace tomc::techobjects
