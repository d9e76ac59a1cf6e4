#pragma once
// An analog or stepper drive as `tomc sim` and `tomc demo` build it: the actor (analog_drive.hpp,
// stepper_drive.hpp) on its simulated hardware (simulated_servo_amplifier.hpp, simulated_stepper_motor.hpp),
// owned together so that the hardware outlives the actor. To the TO it is the actor: a drive on telegram 3,
// or on telegram 2 beside a separately connected encoder on telegram 81/83 (slot kEncoder1) that measures the
// same machine (spec 01 §3.3 "drive and encoder in separate telegrams", §3.12; docs/analog-drives.md).

#include <optional>
#include <stdexcept>

#include "tomc/drives/analog_drive.hpp"
#include "tomc/drives/io/simulated_servo_amplifier.hpp"
#include "tomc/drives/io/simulated_stepper_motor.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/drives/stepper_drive.hpp"

namespace tomc::drives {

// The separate encoder: a simulated PROFIdrive encoder device (SimulatedDrive without a drive telegram) on
// the actor's machine (the hardware's mechanics: gear, load units, cycle, sign-of-life settings), its shaft
// following the machine's load.
struct SeparateEncoderParameters {
  std::uint16_t telegram = 83;           // 81 or 83
  SimulatedEncoderParameters encoder{};  // shaft, resolution, reference marks, XIST1 width
};

namespace detail {
// The separate encoder of a SimulatedActorDrive (simulated_actor_drive.cpp): moves the encoder device to the
// machine's load position, exchanges its telegram, and tells the actor its count and whether it works.
class SeparateEncoder {
 public:
  SeparateEncoder(const SeparateEncoderParameters& parameters, const SimulatedDriveParameters& mechanics);
  // Between the actor's sample() and answer(): this cycle's 81/83 frame into actual[kEncoder1].
  void exchange(double load_position, Telegram3Actor& actor, DeviceFrames& actual) noexcept;
  void write_setpoint(const DeviceFrames& setpoint) noexcept { device_.write_setpoint(setpoint); }
  SimulatedDrive& device() noexcept { return device_; }
  const SimulatedDrive& device() const noexcept { return device_; }

 private:
  double servo_cycle_s_;
  SimulatedDrive device_;
  const telegrams::TelegramCodec* codec_ = &telegrams::TelegramCodec::empty();
  DeviceFrames frames_{};
};
// Throws std::invalid_argument when the actor's feedback and the presence of a separate encoder disagree.
void check_separate_encoder(const ActorParameters& actor, const std::optional<SeparateEncoderParameters>& e);
}  // namespace detail

template <class Hardware, class HardwareParameters, class Actor, class ActorParameters>
class SimulatedActorDrive final : public DriveAdapter {
 public:
  // `encoder` must be given exactly when `actor.feedback` is PositionFeedback::kSeparateEncoder.
  SimulatedActorDrive(const HardwareParameters& hardware, const ActorParameters& actor,
                      const std::optional<SeparateEncoderParameters>& encoder = std::nullopt)
      : hardware_(hardware), actor_(hardware_, actor), config_(actor_.config()) {
    detail::check_separate_encoder(actor, encoder);
    if (encoder) {
      encoder_.emplace(*encoder, hardware_.parameters().mechanics);
      config_.encoder_telegrams[0] = encoder->telegram;
    }
  }

  const DeviceConfig& config() const noexcept override { return config_; }
  bool read_actual(DeviceFrames& actual) noexcept override {
    actor_.sample();
    if (encoder_) encoder_->exchange(hardware_.mechanics().load_position(), actor_, actual);
    return actor_.answer(actual);
  }
  void write_setpoint(const DeviceFrames& setpoint) noexcept override {
    actor_.write_setpoint(setpoint);
    if (encoder_) encoder_->write_setpoint(setpoint);
  }
  LinkHealth link_health() const noexcept override { return actor_.link_health(); }

  Hardware& hardware() noexcept { return hardware_; }
  const Hardware& hardware() const noexcept { return hardware_; }
  Actor& actor() noexcept { return actor_; }
  const Actor& actor() const noexcept { return actor_; }
  // The separate 81/83 encoder device (fault injection, observation); nullptr with the counter.
  SimulatedDrive* separate_encoder() noexcept { return encoder_ ? &encoder_->device() : nullptr; }
  const SimulatedDrive* separate_encoder() const noexcept { return encoder_ ? &encoder_->device() : nullptr; }

 private:
  Hardware hardware_;  // first: the actor holds a reference to it
  Actor actor_;
  DeviceConfig config_;
  std::optional<detail::SeparateEncoder> encoder_;
};

using SimulatedAnalogDrive =
    SimulatedActorDrive<io::SimulatedServoAmplifier, io::SimulatedServoAmplifierParameters, AnalogDrive,
                        AnalogDriveParameters>;
using SimulatedStepperDrive =
    SimulatedActorDrive<io::SimulatedStepperMotor, io::SimulatedStepperMotorParameters, StepperDrive,
                        StepperDriveParameters>;

}  // namespace tomc::drives
