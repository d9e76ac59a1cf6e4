#pragma once
// A PROFIdrive drive that exists only in software but speaks the telegrams byte for byte (issue 3, spec 06
// §4–§9): state machine S1..S5 with OFF1/OFF2/OFF3 and faults, a motor and load model behind a speed loop,
// encoders with reference marks and measuring, torque limits, DSC, sign-of-life, the simulated machine's
// position-based inputs, and fault injection. docs/simulated-drive.md documents every parameter.

#include <array>
#include <cstdint>
#include <optional>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/encoder.hpp"
#include "tomc/telegrams/sign_of_life.hpp"
#include "tomc/telegrams/signals.hpp"

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

// SINAMICS fault numbers the model raises itself.
inline constexpr std::uint32_t kFaultSignOfLife = 1912;       // clock-cycle synchronism: sign-of-life failure
inline constexpr std::uint32_t kFaultSetpointTimeout = 8501;  // PROFINET setpoint timeout (link loss)
inline constexpr std::uint32_t kFaultMotorEncoder = 31110;    // motor encoder error: no speed feedback
inline constexpr std::uint32_t kFaultNoControlByPlc = 7220;   // STW1.10 dropped while switched on

class SimulatedDrive final : public DriveAdapter {
 public:
  SimulatedDrive(const DeviceConfig& config, const SimulatedDriveParameters& parameters);

  const DeviceConfig& config() const noexcept override { return config_; }
  bool read_actual(DeviceFrames& actual) noexcept override;
  void write_setpoint(const DeviceFrames& setpoint) noexcept override;
  LinkHealth link_health() const noexcept override { return health_; }

  // ---- fault injection (each can be cleared again) ----
  void inject_fault(std::uint32_t code, SimulatedDriveParameters::FaultReaction reaction) noexcept;
  void clear_injected_fault() noexcept { injected_fault_ = 0; }
  void inject_encoder_error(int encoder, std::uint16_t code) noexcept;  // encoder 1 or 2
  void clear_encoder_error(int encoder) noexcept;
  void freeze_sign_of_life(bool frozen) noexcept { sign_of_life_frozen_ = frozen; }
  void set_link_lost(bool lost) noexcept { link_lost_ = lost; }
  // The machine's fixed stops give way (a broken stop, a workpiece that yields): the load passes them.
  void break_fixed_stops(bool broken) noexcept { fixed_stops_broken_ = broken; }

  // ---- simulation control ----
  // Power cycle: the mechanics keep their position, the electronics restart (incremental encoders lose it).
  void power_cycle() noexcept;
  // Encoder-only devices: speed of the measured shaft (load units per second).
  void set_external_speed(double load_units_per_second) noexcept { external_speed_ = load_units_per_second; }

  // ---- observation (for tests, diagnostics and the simulated machine's inputs) ----
  telegrams::DriveState state() const noexcept { return state_; }
  std::uint32_t active_fault() const noexcept { return fault_code_; }
  double motor_speed_rpm() const noexcept;
  double motor_torque_nm() const noexcept { return torque_; }
  double load_position() const noexcept { return load_position_; }
  // Backlash: where the motor stands relative to the load, −backlash/2 ... +backlash/2 (+: in contact pushing
  // positive). 0 without backlash.
  double backlash_offset() const noexcept { return gap_; }
  double load_speed() const noexcept;  // load units per second
  MachineInputs machine_inputs() const noexcept;
  const SimulatedDriveParameters& parameters() const noexcept { return p_; }

 private:
  struct EncoderState {
    bool present = false;
    std::uint16_t control = 0;  // last Gx_STW
    std::uint16_t status = 0;   // Gx_ZSW being reported
    std::uint32_t xist2 = 0;
    std::uint32_t captured = 0;  // reference mark / measured value (XIST1 format)
    bool capture_valid = false;
    std::uint16_t error_code = 0;           // present cause (injected or detected), 0 = none
    std::uint16_t reported_error_code = 0;  // shown in XIST2 while the error bit is set
    double revolutions_at_power_on = 0.0;   // shaft revolutions where XIST1 started counting
    std::uint32_t xist1_at_power_on = 0;
  };

  void apply_setpoints() noexcept;
  void update_state_machine() noexcept;
  void integrate(double dt) noexcept;
  void update_encoders(double previous_load_position, double previous_motor_revolutions) noexcept;
  void update_encoder(int index, double previous_shaft, double shaft, double previous_load,
                      double load) noexcept;
  void encode_actuals(DeviceFrames& actual) noexcept;
  double shaft_revolutions(const SimulatedEncoderParameters& e, double motor_revolutions,
                           double load_position) const noexcept;
  std::uint32_t xist1_of(int index, double shaft) const noexcept;
  void raise_fault(std::uint32_t code, SimulatedDriveParameters::FaultReaction reaction) noexcept;
  bool has_fault() const noexcept { return fault_code_ != 0; }
  double speed_setpoint_rpm() const noexcept;
  double torque_limit_positive() const noexcept;
  double torque_limit_negative() const noexcept;

  DeviceConfig config_;
  SimulatedDriveParameters p_;
  std::array<telegrams::TelegramCodec, kSlotCount> setpoint_codecs_{};
  std::array<telegrams::TelegramCodec, kSlotCount> actual_codecs_{};

  // received setpoints
  DeviceFrames setpoint_frames_{};
  telegrams::SetpointSignals drive_sp_{};
  telegrams::SetpointSignals supplementary_sp_{};
  std::array<telegrams::SetpointSignals, 2> encoder_sp_{};
  bool cyclic_data_ = false;     // a setpoint frame has arrived since power-on
  bool fresh_setpoint_ = false;  // written since the last read_actual
  std::uint32_t missed_setpoints_ = 0;
  std::uint16_t previous_stw1_ = 0;

  // drive state
  telegrams::DriveState state_ = telegrams::DriveState::kS0NotReady;
  std::uint32_t fault_code_ = 0;
  SimulatedDriveParameters::FaultReaction fault_reaction_ = SimulatedDriveParameters::FaultReaction::kOff2;
  std::uint32_t injected_fault_ = 0;
  SimulatedDriveParameters::FaultReaction injected_reaction_ = SimulatedDriveParameters::FaultReaction::kOff2;
  bool pulses_enabled_ = false;
  double ramp_setpoint_rpm_ = 0.0;  // ramp-function generator output during OFF1/OFF3
  telegrams::SignOfLifeMonitor master_monitor_{};
  telegrams::SignOfLifeGenerator slave_sign_of_life_{};
  std::uint8_t slave_counter_ = 0;
  bool sign_of_life_frozen_ = false;
  bool link_lost_ = false;
  bool fixed_stops_broken_ = false;

  // mechanics (motor side in rad/s, load in load units)
  double omega_ = 0.0;  // motor speed, rad/s
  double motor_revolutions_ = 0.0;
  double load_position_ = 0.0;
  double torque_ = 0.0;          // motor torque, Nm
  double stall_integral_ = 0.0;  // speed-controller integral while blocked at a fixed stop
  double gap_ = 0.0;             // backlash: motor position − load position (load units), ±backlash/2
  double load_speed_ = 0.0;      // with backlash: the load's speed in the last substep (load units/s)
  bool blocked_ = false;
  double external_speed_ = 0.0;
  double dsc_xist1_at_sample_ = 0.0;  // G1 counts at the cycle start (DSC reference)
  double motor_revolutions_at_sample_ = 0.0;

  std::array<EncoderState, 2> encoders_{};
  LinkHealth health_{};

  // Resolved once at construction so that a cycle does no layout look-ups or transcendental set-up.
  struct Resolved {
    bool nsoll_b = false;
    bool stw2 = false;
    bool momred = false;
    bool g1_stw = false;
    bool g2_stw = false;
    bool dsc = false;
    bool supplementary = false;
    double ratio = 1.0;                     // motor revolutions per load revolution
    double inertia = 0.0;                   // at the motor shaft
    double lag = 0.0;                       // 1 - exp(-dt/T) of the speed loop per substep
    double dt = 0.0;                        // substep
    std::array<double, 2> xist1_scale{};    // counts per shaft revolution (linear: per step)
    std::array<double, 2> xist1_modulus{};  // 2^width
    double dsc_counts_to_motor_revolutions = 0.0;
  } r_{};
  // Per cycle: the speed setpoint and torque limits from this cycle's telegrams.
  double cycle_speed_setpoint_rpm_ = 0.0;
  double cycle_torque_limit_positive_ = 0.0;
  double cycle_torque_limit_negative_ = 0.0;
};

}  // namespace tomc::drives
