#pragma once
// The parameters of the simulated machine axis: drive, motor, load, encoders and the machine's switches and
// stops (docs/simulated-drive.md documents every one). The simulated PROFIdrive drive uses all of them; the
// simulated servo amplifier of an analog drive uses the motor, load and machine ones (MotorLoad).

#include <cstdint>
#include <optional>

namespace tomc::drives {

// Where an encoder sits and how it counts.
struct SimulatedEncoderParameters {
  enum class Shaft : std::uint8_t { kMotor, kLoad };
  Shaft shaft = Shaft::kMotor;
  bool linear = false;        // a linear scale on the load: counts from load units, not revolutions
  double resolution = 0.001;  // linear only: load units per step (Sensor.Parameter.Resolution)
  std::uint32_t steps_per_revolution = 2048;  // p979[2]
  std::uint8_t fine_resolution_xist1 = 11;    // p0418, counts = steps * 2^fine
  std::uint8_t fine_resolution_xist2 = 9;  // p0419, absolute value / reference marks use fine1 (spec 06 §6.2)
  std::uint32_t determinable_revolutions = 4096;  // 0 = incremental, 1 = single-turn, >1 multi-turn absolute
  std::uint8_t xist1_width_bits = 32;             // counter width of XIST1
  std::uint32_t xist1_at_power_on = 0;            // incremental: counter value at power-on
  double reference_mark_interval_revolutions = 1.0;  // a zero mark every N revolutions of the shaft
  double reference_mark_offset_revolutions = 0.25;   // first mark at this shaft angle
  double absolute_offset_revolutions = 0.0;          // shaft revolutions at which the absolute value reads 0
  double nist_reference_speed =
      3000.0;  // telegram 83 NIST_B: 100 % = this shaft speed in rpm (linear: load units/s)
};

// A switch or cam of the simulated machine, active while the load position is inside [from, to].
struct PositionWindow {
  double from = 0.0;
  double to = 0.0;
  bool contains(double x) const noexcept { return x >= from && x <= to; }
};

struct SimulatedMachineParameters {
  // Position-based digital inputs (load units). Limit switches are active beyond their position.
  std::optional<double> negative_limit_switch;  // active at load position <= this
  std::optional<double> positive_limit_switch;  // active at load position >= this
  std::optional<PositionWindow> reference_cam;
  std::optional<PositionWindow> probe1;  // measuring input 1 of the drive (G_STW functions 1/2)
  std::optional<PositionWindow> probe2;  // measuring input 2 (functions 3/4)
  // Mechanical end stops: the load cannot pass them; the motor torque rises to its limit.
  std::optional<double> negative_fixed_stop;
  std::optional<double> positive_fixed_stop;
};

struct SimulatedDriveParameters {
  // Cycle
  double servo_cycle_s = 0.001;
  std::uint32_t substeps = 4;  // model integration steps per servo cycle (drive speed-loop clock)

  // Drive (SINAMICS parameter numbers in brackets)
  double reference_speed_rpm = 3000.0;          // p2000
  double max_speed_rpm = 6000.0;                // p1082
  double reference_torque_nm = 4.0;             // p2003
  double torque_limit_nm = 4.0;                 // p1520/p1521 (symmetric)
  double off1_ramp_down_time_s = 1.0;           // p1121, from max speed to 0
  double off3_ramp_down_time_s = 0.2;           // p1135
  double standstill_threshold_rpm = 20.0;       // p1226
  double speed_deviation_tolerance_rpm = 90.0;  // p2163, ZSW1.8 / MELDW.8
  std::uint16_t sign_of_life_tolerance = 1;     // p0925; 0xFFFF = no monitoring
  bool isochronous = true;                      // generates and monitors sign-of-life (telegrams with STW2)
  std::uint32_t setpoint_timeout_cycles = 20;   // link loss this long -> fault F08501
  enum class FaultReaction : std::uint8_t { kOff1, kOff2, kOff3 };
  FaultReaction communication_fault_reaction = FaultReaction::kOff3;

  // Motor and load
  double speed_loop_time_constant_s = 0.002;  // closed speed loop as a first-order lag
  double motor_inertia_kgm2 = 1.0e-4;
  double load_inertia_kgm2 = 2.0e-4;              // at the load shaft
  double viscous_friction_nm_per_rad_s = 1.0e-4;  // at the motor shaft
  double coulomb_friction_nm = 0.02;              // at the motor shaft
  double gear_motor_revolutions = 1.0;            // gear: motor revolutions ...
  double gear_load_revolutions = 1.0;             // ... per load revolutions
  double load_units_per_revolution = 360.0;       // degrees (rotary) or leadscrew pitch in mm (linear)
  double initial_load_position = 0.0;             // load units
  // Backlash between motor and load (load units, >= 0): after a reversal the motor crosses this dead band
  // before the load moves.
  double backlash = 0.0;
  // Where the motor stands in it at power-on: motor − load in load units, limited to ±backlash/2 (0: middle,
  // +backlash/2: in contact pushing positive).
  double initial_backlash_offset = 0.0;

  SimulatedEncoderParameters encoder1{};  // G1: motor encoder by default
  SimulatedEncoderParameters encoder2{SimulatedEncoderParameters::Shaft::kLoad};  // G2 / separate encoder
  SimulatedMachineParameters machine{};
};

// Inputs of the simulated machine that a PLC would read from its own input modules.
struct MachineInputs {
  bool negative_limit_switch = false;
  bool positive_limit_switch = false;
  bool reference_cam = false;
  bool probe1 = false;
  bool probe2 = false;
  bool at_fixed_stop = false;
};

}  // namespace tomc::drives
