// The analog drive actor's output stage (analog_drive.hpp): the speed setpoint as a clamped voltage plus the
// offset, quantised by the DAC. No allocation, no locks, no exceptions.
#include "tomc/drives/analog_drive.hpp"

#include <algorithm>

namespace tomc::drives {

AnalogDrive::AnalogDrive(io::HardwareIo& hardware, const AnalogDriveParameters& parameters)
    : Telegram3Actor(hardware, parameters), p_(parameters) {
  // Outputs safe from the start: 0 V, enable off.
  drive_outputs();
  (void)hardware.write_outputs();
}

void AnalogDrive::set_speed_output(bool enabled, double speed) noexcept {
  double volts = 0.0;
  if (enabled) {
    // spec 01 §3.12: U = clamp(n/ReferenceSpeed, ±overdrive) · U_100% (+ the offset, also in S5).
    const double limit = p_.overdrive_percent / 100.0;
    volts = std::clamp(speed, -limit, limit) * p_.volts_at_reference + p_.offset_volts;
  }
  output_volts_ = volts;
  output_code_ = io::dac_code(volts, p_.dac);
  hardware().set_analog_output(p_.analog_output, output_code_);
}

}  // namespace tomc::drives
