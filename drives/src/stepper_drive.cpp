// The stepper actor's output stage (stepper_drive.hpp): speed setpoint -> pulse frequency. No allocation, no
// locks, no exceptions.
#include "tomc/drives/stepper_drive.hpp"

#include <algorithm>

namespace tomc::drives {

StepperDrive::StepperDrive(io::HardwareIo& hardware, const StepperDriveParameters& parameters)
    : Telegram3Actor(hardware, parameters), p_(parameters) {
  // Outputs safe from the start: no pulses, enable off.
  drive_outputs();
  (void)hardware.write_outputs();
}

void StepperDrive::set_speed_output(bool enabled, double speed) noexcept {
  // f = n/ReferenceSpeed · ReferenceSpeed/60 · steps per revolution; S5 and disabled: no pulses (a stepper
  // stops on the spot, its stop ramp is the TO's).
  const double hertz = enabled ? speed * p_.reference_speed_rpm / 60.0 * p_.steps_per_revolution : 0.0;
  frequency_hz_ = std::clamp(hertz, -p_.max_frequency_hz, p_.max_frequency_hz);
  hardware().set_pulse_frequency(p_.pulse_output, frequency_hz_);
}

}  // namespace tomc::drives
