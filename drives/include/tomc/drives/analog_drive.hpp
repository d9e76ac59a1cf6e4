#pragma once
// The analog drive actor (spec 01 §3.12, seed 004 §6.2.7/§6.5.1): a ±10 V speed setpoint on an analog
// output, an optional enable output and ready input, and an incremental encoder on a counter, all through the
// hardware I/O layer. Towards the technology object it is a drive on telegram 3 (DriveAdapter), exactly as
// the S7 puts its analog actor behind a telegram-3-like interface: no TO code knows which actor is behind the
// drive connection. docs/analog-drives.md describes every rule.

#include <cstdint>
#include <optional>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc/drives/io/hardware_io.hpp"
#include "tomc/drives/io/quadrature_counter.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/sign_of_life.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::drives {

struct AnalogDriveParameters {
  double servo_cycle_s = 0.001;
  double reference_speed_rpm = 3000.0;  // <TO>.Actor.DriveParameter.ReferenceSpeed: 100 % output
  double volts_at_reference = 10.0;     // U_100%
  double overdrive_percent = 117.0;     // |output| <= this % of U_100% (spec 01 §3.12 "≈ ±117 %")
  double offset_volts = 0.0;            // added to the output while the axis is enabled (TarOffs)
  io::DacFormat dac{};
  io::Channel analog_output{0, 0};           // <TO>.Actor.Interface.AddressOut
  std::optional<io::Channel> enable_output;  // <TO>.Actor.Interface.EnableDriveOutput (optional)
  std::optional<io::Channel> ready_input;    // <TO>.Actor.Interface.DriveReadyInput (optional)
  io::Channel counter{4, 0};
  std::uint8_t counter_width_bits = 32;
  double counts_per_revolution = 10000.0;  // counts per motor revolution (NIST_B); ×4 of the lines
  double standstill_threshold_rpm = 20.0;  // stop reactions end (enable off) below this measured speed
};

// Fault numbers the actor shows while ZSW1.3 is set (the TO raises its drive-fault alarm 401).
inline constexpr std::uint32_t kFaultDriveReadyLost = 20001;  // ready input dropped while enabled (rule 2)
inline constexpr std::uint32_t kFaultIo = 20002;              // the I/O card failed a read or write

class AnalogDrive final : public DriveAdapter {
 public:
  // `hardware` must outlive the actor. Telegram 3 facing the TO.
  AnalogDrive(io::HardwareIo& hardware, const AnalogDriveParameters& parameters);

  const DeviceConfig& config() const noexcept override { return config_; }
  bool read_actual(DeviceFrames& actual) noexcept override;
  void write_setpoint(const DeviceFrames& setpoint) noexcept override;
  LinkHealth link_health() const noexcept override { return health_; }

  // Analog offset auto-calibration result (TarOffs): added to the output from the next cycle.
  void set_offset_volts(double volts) noexcept { p_.offset_volts = volts; }

  // ---- observation (diagnostics, tests) ----
  telegrams::DriveState state() const noexcept { return state_; }
  std::uint32_t active_fault() const noexcept { return fault_; }
  double output_volts() const noexcept { return output_volts_; }  // commanded, before quantisation
  std::int32_t output_code() const noexcept { return output_code_; }
  bool enable_output() const noexcept { return enable_; }
  bool ready_input() const noexcept { return ready_; }
  std::int64_t counter_value() const noexcept { return extension_.value(); }
  double measured_speed_rpm() const noexcept { return speed_rpm_; }
  const AnalogDriveParameters& parameters() const noexcept { return p_; }

 private:
  void update_state(std::uint16_t stw1) noexcept;
  void update_encoder(std::uint16_t control, telegrams::ActualSignals& a) noexcept;
  void compose_outputs() noexcept;

  io::HardwareIo* hw_;
  AnalogDriveParameters p_;
  DeviceConfig config_{};
  telegrams::TelegramCodec setpoint_codec_{};
  telegrams::TelegramCodec actual_codec_{};
  DeviceFrames setpoint_frames_{};
  bool fresh_setpoint_ = false;
  bool cyclic_data_ = false;
  telegrams::SetpointSignals sp_{};
  std::uint16_t previous_stw1_ = 0;

  telegrams::DriveState state_ = telegrams::DriveState::kS1SwitchingOnInhibited;
  std::uint32_t fault_ = 0;
  bool ready_ = false;
  bool io_ok_ = true;
  bool enable_ = false;
  double output_volts_ = 0.0;
  std::int32_t output_code_ = 0;

  io::CounterExtension extension_;
  std::int64_t previous_count_ = 0;
  double speed_rpm_ = 0.0;
  std::uint16_t encoder_status_ = 0;
  std::int64_t latched_ = 0;
  std::uint16_t previous_encoder_command_ = 0;

  telegrams::SignOfLifeGenerator sign_of_life_{};
  std::uint8_t slave_counter_ = 0;
  LinkHealth health_{};
};

}  // namespace tomc::drives
