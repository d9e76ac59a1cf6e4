// The analog drive actor's output stage (analog_drive.hpp): the speed setpoint as a clamped voltage plus the
// offset, quantised by the DAC. No allocation, no locks, no exceptions.
#include "tomc/drives/analog_drive.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::drives {

AnalogDrive::AnalogDrive(io::HardwareIo& hardware, const AnalogDriveParameters& parameters)
    : Telegram3Actor(hardware, parameters), p_(parameters) {
  // Outputs safe from the start: 0 V, enable off.
  drive_outputs();
  (void)hardware.write_outputs();
}

void AnalogDrive::offset_calibration(bool enable, bool reset) noexcept {
  const bool rising = enable && !calibration_enable_;
  calibration_enable_ = enable;
  if (!enable) {
    calibration_state_ = Calibration::kIdle;
    calibration_.EndTr = false;
    return;
  }
  if (!rising) return;
  calibration_.Error = 0;
  calibration_.EndTr = false;
  if (reset) {  // "Reset Offset": Reset TRUE, then En
    p_.offset_volts = 0.0;
    finish_calibration(0);
    return;
  }
  calibration_state_ = Calibration::kWaitingForStandstill;
  calibration_cycles_ = 0;
  // "If the encoder is not connected or does not work the calibration ends at once" (seed 000 TarOffs).
  if (encoder_fault()) finish_calibration(kErrorCalibrationNoEncoder);
}

void AnalogDrive::finish_calibration(std::uint32_t error) noexcept {
  calibration_.Error = error;
  calibration_.ValOf = io::dac_code(p_.offset_volts, p_.dac);
  calibration_.EndTr = true;
  calibration_state_ = Calibration::kFinished;
}

// TarOffs [derived, spec 05a §3.1: "integrated standstill command = offset, stored as a DAC bias"]: while the
// TO holds the axis at standstill, its command is what cancels the amplifier's drift; its mean over
// calibration_measure_s, added to the offset, becomes the new offset.
void AnalogDrive::calibrate(bool enabled, double speed) noexcept {
  if (calibration_state_ != Calibration::kWaitingForStandstill &&
      calibration_state_ != Calibration::kMeasuring) {
    return;
  }
  // The encoder failed while waiting or measuring: what was measured is not a standstill command.
  if (encoder_fault()) {
    finish_calibration(kErrorCalibrationNoEncoder);
    return;
  }
  const bool standstill = enabled && state() == telegrams::DriveState::kS4Operation &&
                          std::fabs(measured_speed_rpm()) < p_.standstill_threshold_rpm;
  if (!standstill) {  // "not finished until the axis stands still"; motion restarts the wait
    calibration_state_ = Calibration::kWaitingForStandstill;
    calibration_cycles_ = 0;
    return;
  }
  ++calibration_cycles_;
  if (calibration_state_ == Calibration::kWaitingForStandstill) {
    if (static_cast<double>(calibration_cycles_) * p_.servo_cycle_s >= p_.calibration_settle_s) {
      calibration_state_ = Calibration::kMeasuring;
      calibration_cycles_ = 0;
      calibration_sum_volts_ = 0.0;
    }
    return;
  }
  calibration_sum_volts_ += speed * p_.volts_at_reference;
  if (static_cast<double>(calibration_cycles_) * p_.servo_cycle_s < p_.calibration_measure_s) return;
  const double offset = p_.offset_volts + calibration_sum_volts_ / static_cast<double>(calibration_cycles_);
  // Error 11 (seed 000): more than 1 % of the DAC's maximum value; the offset in use stays.
  const bool excessive = std::fabs(offset) > 0.01 * p_.dac.full_scale_volts;
  if (!excessive) p_.offset_volts = offset;
  finish_calibration(excessive ? kErrorOffsetExcessive : 0);
}

void AnalogDrive::set_speed_output(bool enabled, double speed) noexcept {
  calibrate(enabled, speed);
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
