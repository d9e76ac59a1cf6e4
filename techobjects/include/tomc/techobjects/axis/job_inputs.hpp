#pragma once
// The types every axis TO shares with the instructions that call it (one home, issue 14): the inputs of the
// motion jobs as the user gives them (spec 03 §4; negative dynamics = the DynamicDefaults, spec 03 §2.1),
// MC_Power's outputs, the result of a data-block write, and the digital inputs an axis reads besides its
// telegrams.

#include <cstdint>

#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/motion/time_position_source.hpp"

namespace tomc::techobjects {

// Inputs of the motion instructions, as the user gives them (negative = default, spec 03 §2.1).
struct MoveVelocityInputs {
  double Velocity = 100.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t Direction = 0;  // 0 sign of Velocity, 1 positive, 2 negative
  bool Current = false;
  bool PositionControlled = true;  // positioning/synchronous axes (spec 02 §2.1); ignored on a speed axis
};
struct HaltInputs {
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool AbortAcceleration = false;
  std::int32_t Mode = 0;
};
struct StopInputs {
  std::int32_t Mode = 0;  // 0 emergency, 2 max dynamics, 3 given dynamics; 1 invalid
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool AbortAcceleration = false;
};
struct JogInputs {
  bool JogForward = false;
  bool JogBackward = false;
  double Velocity = 100.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool PositionControlled = true;  // positioning/synchronous axes (spec 02 §2.5); ignored on a speed axis
};

// The result of writing a data-block variable from user code.
struct WriteResult {
  bool found = false;
  AccessError access = AccessError::kNone;
  ValueError value = ValueError::kNone;
  bool ok() const noexcept { return found && access == AccessError::kNone && value == ValueError::kNone; }
};

// What MC_Power shows (spec 03 §4.1, §3.3 L1/L2).
struct PowerState {
  bool Status = false;
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;
};

// Inputs of MC_MoveAbsolute (spec 03 §4.5); negative dynamics = DynamicDefaults.
struct MoveAbsoluteInputs {
  double Position = 0.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t Direction = 1;   // modulo only: 1 positive, 2 negative, 3 shortest path
  std::int32_t BufferMode = 0;  // 0 abort, 1 append
};
// Inputs of MC_MoveRelative (spec 03 §4.6).
struct MoveRelativeInputs {
  double Distance = 0.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t BufferMode = 0;
};
// Inputs of MC_PositionProfile (spec 03 §4.7): the dynamics are those of the transition profile.
struct PositionProfileInputs {
  TimePositionSource TimePosition{};  // a TO_Cam or the user's points; must outlive the job
  double StartTime = 0.0;
  std::int32_t ProfileReference = 0;  // 0 relative, 1 absolute
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t BufferMode = 0;
};
// Inputs of MC_MotionInVelocity / MC_MotionInPosition (spec 03 §4.17), taken every cycle while Enable = TRUE.
struct MotionInVelocityInputs {
  double Velocity = 0.0;
  double Acceleration = 0.0;
  bool PositionControlled = true;
};
struct MotionInPositionInputs {
  double Position = 0.0;
  double Velocity = 0.0;
  double Acceleration = 0.0;
};
// Inputs of MC_MotionInSuperimposed (spec 03 §4.17.3), taken every cycle while Enable = TRUE: Distance is the
// absolute value of the superimposition (seed 004 §6.14.3: x_set = x_base + Distance).
struct MotionInSuperimposedInputs {
  double Distance = 0.0;
  double VelocityDiff = 0.0;
  double AccelerationDiff = 0.0;
};
// Inputs of MC_MoveSuperimposed (spec 03 §4.10).
struct MoveSuperimposedInputs {
  double Distance = 0.0;
  double VelocityDiff = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
};
// Inputs of MC_HaltSuperimposed (spec 03 §4.11).
struct HaltSuperimposedInputs {
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool AbortAcceleration = false;
};
// Inputs of MC_SetSensor (spec 03 §4.12); Sensor and ReferenceSensor are INT in the manual (AMB-26).
struct SetSensorInputs {
  std::int16_t Sensor = 1;
  std::int32_t Mode = 0;  // 0 switch + take over the position, 1 switch only, 2/3 take over without switch
  std::int16_t ReferenceSensor = 1;
};
// Inputs of MC_Home (spec 03 §4.3).
struct HomeInputs {
  double Position = 0.0;
  std::int32_t Mode = 0;
  std::int32_t Sensor = 0;
};

// The process-image inputs an axis reads besides its telegrams (spec 02 §4.4, §5.3): the hardware limit
// switches and the homing digital input. The integrator (or the scenario engine, from the simulated machine)
// writes them before MC_Servo, e.g. in the MC_PreServo hook, as a PLC's "TPA OB Servo" process image.
struct AxisDigitalInputs {
  bool MinSwitch = false;    // level of PositionLimits_HW.MinSwitchAddress
  bool MaxSwitch = false;    // level of PositionLimits_HW.MaxSwitchAddress
  bool HomingInput = false;  // level of Sensor[n].ActiveHoming/PassiveHoming.DigitalInputAddress
};

}  // namespace tomc::techobjects
