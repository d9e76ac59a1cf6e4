#pragma once
// A PROFIdrive drive that exists only in software but speaks the telegrams byte for byte (issue 3, spec 06
// §4–§9): state machine S1..S5 with OFF1/OFF2/OFF3 and faults, a motor and load model behind a speed loop,
// encoders with reference marks and measuring, torque limits, DSC, sign-of-life, the simulated machine's
// position-based inputs, and fault injection. docs/simulated-drive.md documents every parameter.

#include <array>
#include <cstdint>
#include <optional>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc/drives/motor_load.hpp"
#include "tomc/drives/simulated_drive_parameters.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/encoder.hpp"
#include "tomc/telegrams/sign_of_life.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::drives {

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
  void break_fixed_stops(bool broken) noexcept { mechanics_.break_fixed_stops(broken); }

  // ---- Safety Integrated functions selected in the drive (spec 01 §4, seed 004 §6.3.1) ----
  // The drive's own stop reaction, which the TO sees only in ZSW1: STO coasts at once (OFF2: ZSW1.4 = 0,
  // switching on inhibited); SS1 brakes on the OFF3 ramp (ZSW1.5 = 0) and then switches the torque off (STO).
  // Deselected, the drive waits in S1 for a new switch-on (STW1.0 0 -> 1).
  enum class SafetyFunction : std::uint8_t { kNone, kSto, kSs1 };
  void select_safety_function(SafetyFunction function) noexcept { safety_ = function; }
  bool safe_torque_off() const noexcept { return safe_torque_off_; }

  // ---- simulation control ----
  // Power cycle: the mechanics keep their position, the electronics restart (incremental encoders lose it).
  void power_cycle() noexcept;
  // Encoder-only devices: speed of the measured shaft (load units per second).
  void set_external_speed(double load_units_per_second) noexcept { external_speed_ = load_units_per_second; }
  // p2000 changed through parameter access (the PROFINET emulator): NSOLL/NIST scale with it from the next
  // cycle on, as a drive's do.
  void set_reference_speed_rpm(double rpm) noexcept { p_.reference_speed_rpm = rpm; }
  // The setpoint monitoring set by a start-up record (the PROFINET emulator's DAP record 0x0100).
  void set_setpoint_timeout_cycles(std::uint32_t cycles) noexcept { p_.setpoint_timeout_cycles = cycles; }

  // ---- observation (for tests, diagnostics and the simulated machine's inputs) ----
  telegrams::DriveState state() const noexcept { return state_; }
  std::uint32_t active_fault() const noexcept { return fault_code_; }
  double motor_speed_rpm() const noexcept;
  double motor_torque_nm() const noexcept { return mechanics_.motor_torque_nm(); }
  double load_position() const noexcept { return mechanics_.load_position(); }
  // Backlash: where the motor stands relative to the load, −backlash/2 ... +backlash/2 (+: in contact pushing
  // positive). 0 without backlash.
  double backlash_offset() const noexcept { return mechanics_.backlash_offset(); }
  double load_speed() const noexcept;  // load units per second
  MachineInputs machine_inputs() const noexcept;
  const SimulatedDriveParameters& parameters() const noexcept { return p_; }
  const MotorLoad& mechanics() const noexcept { return mechanics_; }

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
  MotorLoad mechanics_;  // after p_: built from it
  DeviceCodecs codecs_;

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
  SafetyFunction safety_ = SafetyFunction::kNone;
  bool safe_torque_off_ = false;    // STO in effect (selected, or SS1 after its ramp)
  double ramp_setpoint_rpm_ = 0.0;  // ramp-function generator output during OFF1/OFF3
  telegrams::SignOfLifeMonitor master_monitor_{};
  telegrams::SignOfLifeGenerator slave_sign_of_life_{};
  std::uint8_t slave_counter_ = 0;
  bool sign_of_life_frozen_ = false;
  bool link_lost_ = false;

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
