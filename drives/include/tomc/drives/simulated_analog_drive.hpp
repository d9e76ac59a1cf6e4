#pragma once
// An analog drive as `tomc sim` and `tomc demo` build it: the analog actor (analog_drive.hpp) on the
// simulated servo amplifier (simulated_servo_amplifier.hpp), owned together so that the amplifier outlives
// the actor. To the TO it is the actor: a drive on telegram 3.

#include "tomc/drives/analog_drive.hpp"
#include "tomc/drives/io/simulated_servo_amplifier.hpp"

namespace tomc::drives {

class SimulatedAnalogDrive final : public DriveAdapter {
 public:
  SimulatedAnalogDrive(const io::SimulatedServoAmplifierParameters& amplifier,
                       const AnalogDriveParameters& actor)
      : amplifier_(amplifier), actor_(amplifier_, actor) {}

  const DeviceConfig& config() const noexcept override { return actor_.config(); }
  bool read_actual(DeviceFrames& actual) noexcept override { return actor_.read_actual(actual); }
  void write_setpoint(const DeviceFrames& setpoint) noexcept override { actor_.write_setpoint(setpoint); }
  LinkHealth link_health() const noexcept override { return actor_.link_health(); }

  io::SimulatedServoAmplifier& amplifier() noexcept { return amplifier_; }
  const io::SimulatedServoAmplifier& amplifier() const noexcept { return amplifier_; }
  AnalogDrive& actor() noexcept { return actor_; }
  const AnalogDrive& actor() const noexcept { return actor_; }

 private:
  io::SimulatedServoAmplifier amplifier_;  // first: the actor holds a reference to it
  AnalogDrive actor_;
};

}  // namespace tomc::drives
