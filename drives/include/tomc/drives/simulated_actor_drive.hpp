#pragma once
// An analog or stepper drive as `tomc sim` and `tomc demo` build it: the actor (analog_drive.hpp,
// stepper_drive.hpp) on its simulated hardware (simulated_servo_amplifier.hpp, simulated_stepper_motor.hpp),
// owned together so that the hardware outlives the actor. To the TO it is the actor: a drive on telegram 3.

#include "tomc/drives/analog_drive.hpp"
#include "tomc/drives/io/simulated_servo_amplifier.hpp"
#include "tomc/drives/io/simulated_stepper_motor.hpp"
#include "tomc/drives/stepper_drive.hpp"

namespace tomc::drives {

template <class Hardware, class HardwareParameters, class Actor, class ActorParameters>
class SimulatedActorDrive final : public DriveAdapter {
 public:
  SimulatedActorDrive(const HardwareParameters& hardware, const ActorParameters& actor)
      : hardware_(hardware), actor_(hardware_, actor) {}

  const DeviceConfig& config() const noexcept override { return actor_.config(); }
  bool read_actual(DeviceFrames& actual) noexcept override { return actor_.read_actual(actual); }
  void write_setpoint(const DeviceFrames& setpoint) noexcept override { actor_.write_setpoint(setpoint); }
  LinkHealth link_health() const noexcept override { return actor_.link_health(); }

  Hardware& hardware() noexcept { return hardware_; }
  const Hardware& hardware() const noexcept { return hardware_; }
  Actor& actor() noexcept { return actor_; }
  const Actor& actor() const noexcept { return actor_; }

 private:
  Hardware hardware_;  // first: the actor holds a reference to it
  Actor actor_;
};

using SimulatedAnalogDrive =
    SimulatedActorDrive<io::SimulatedServoAmplifier, io::SimulatedServoAmplifierParameters, AnalogDrive,
                        AnalogDriveParameters>;
using SimulatedStepperDrive =
    SimulatedActorDrive<io::SimulatedStepperMotor, io::SimulatedStepperMotorParameters, StepperDrive,
                        StepperDriveParameters>;

}  // namespace tomc::drives
