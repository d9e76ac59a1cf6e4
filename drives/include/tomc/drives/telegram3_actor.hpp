#pragma once
// What the analog actor (analog_drive.hpp) and the stepper actor (stepper_drive.hpp) share: towards the
// technology object a drive on telegram 3 (spec 01 §3.11, §3.12: the S7 connects both through telegram 3),
// towards the hardware I/O layer an optional enable output, an optional ready input with the three rules of
// spec 01 §3.12, and the position from a counter (×4 encoder or the pulse count of a PTO module). The output
// stage that turns the speed setpoint into a signal (volts, pulse frequency) is the derived class's.
// docs/analog-drives.md describes every rule.

#include <cstdint>
#include <optional>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc/drives/io/hardware_io.hpp"
#include "tomc/drives/io/quadrature_counter.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/sign_of_life.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::drives {

struct ActorParameters {
  double servo_cycle_s = 0.001;
  double reference_speed_rpm = 3000.0;       // <TO>.Actor.DriveParameter.ReferenceSpeed: 100 % output
  std::optional<io::Channel> enable_output;  // <TO>.Actor.Interface.EnableDriveOutput (optional)
  std::optional<io::Channel> ready_input;    // <TO>.Actor.Interface.DriveReadyInput (optional)
  io::Channel counter{4, 0};
  std::uint8_t counter_width_bits = 32;
  double counts_per_revolution = 10000.0;  // counts per motor revolution (NIST_B); ×4 of the lines
  double standstill_threshold_rpm = 20.0;  // stop reactions end (enable off) below this measured speed
};

// Fault numbers an actor shows while ZSW1.3 is set (the TO raises its drive-fault alarm 401).
inline constexpr std::uint32_t kFaultDriveReadyLost = 20001;  // ready input dropped while enabled (rule 2)
inline constexpr std::uint32_t kFaultIo = 20002;              // the I/O card failed a read or write

class Telegram3Actor : public DriveAdapter {
 public:
  const DeviceConfig& config() const noexcept override { return config_; }
  bool read_actual(DeviceFrames& actual) noexcept override;
  void write_setpoint(const DeviceFrames& setpoint) noexcept override;
  LinkHealth link_health() const noexcept override { return health_; }

  // ---- observation (diagnostics, tests) ----
  telegrams::DriveState state() const noexcept { return state_; }
  std::uint32_t active_fault() const noexcept { return fault_; }
  bool enable_output() const noexcept { return enable_; }
  bool ready_input() const noexcept { return ready_; }
  std::int64_t counter_value() const noexcept { return extension_.value(); }
  double measured_speed_rpm() const noexcept { return speed_rpm_; }

 protected:
  // `hardware` must outlive the actor. The derived constructor calls drive_outputs() once its own members
  // exist, so that the outputs are safe (0, enable off) from the start.
  Telegram3Actor(io::HardwareIo& hardware, const ActorParameters& parameters);
  ~Telegram3Actor() override = default;
  Telegram3Actor(const Telegram3Actor&) = delete;
  Telegram3Actor& operator=(const Telegram3Actor&) = delete;

  // The output stage, once per write_setpoint() and when a fault disables the actor: `enabled` = the
  // enable output (S4, or S5 until standstill, no fault); `speed` = the speed setpoint as a fraction of the
  // reference speed (0 outside S4 with STW1.4 and STW1.6; S5 brakes with 0). Writes its output channel
  // only; write_outputs() follows.
  virtual void set_speed_output(bool enabled, double speed) noexcept = 0;
  // Compose the enable output and the output stage for the current state.
  void drive_outputs() noexcept;
  io::HardwareIo& hardware() noexcept { return *hw_; }

 private:
  void update_state(std::uint16_t stw1) noexcept;
  void update_encoder(std::uint16_t control, telegrams::ActualSignals& a) noexcept;

  io::HardwareIo* hw_;
  ActorParameters base_;
  DeviceConfig config_{};
  const telegrams::TelegramCodec* setpoint_codec_ = &telegrams::TelegramCodec::empty();
  const telegrams::TelegramCodec* actual_codec_ = &telegrams::TelegramCodec::empty();
  DeviceFrames setpoint_frames_{};
  bool cyclic_data_ = false;
  telegrams::SetpointSignals sp_{};
  std::uint16_t previous_stw1_ = 0;

  telegrams::DriveState state_ = telegrams::DriveState::kS1SwitchingOnInhibited;
  std::uint32_t fault_ = 0;
  bool ready_ = false;
  bool io_ok_ = true;
  bool enable_ = false;

  io::CounterExtension extension_;
  std::int64_t previous_count_ = 0;
  double speed_rpm_ = 0.0;
  std::uint16_t encoder_status_ = 0;
  std::int64_t latched_ = 0;

  telegrams::SignOfLifeGenerator sign_of_life_{};
  std::uint8_t slave_counter_ = 0;
  LinkHealth health_{};
};

}  // namespace tomc::drives
