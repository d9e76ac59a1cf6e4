// The simulated servo amplifier behind the analog actor (simulated_servo_amplifier.hpp).
#include "tomc/drives/io/simulated_servo_amplifier.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::drives::io {

SimulatedServoAmplifier::SimulatedServoAmplifier(const SimulatedServoAmplifierParameters& parameters)
    : SimulatedDriverCard(parameters), p_(parameters), mechanics_(p_.mechanics) {
  if (p_.mechanics.substeps == 0) p_.mechanics.substeps = 1;
  counter_ = QuadratureCounter(p_.encoder, encoder_shaft_revolutions());
  (void)finish_sample(counter_.sample());
}

double SimulatedServoAmplifier::encoder_shaft_revolutions() const noexcept {
  if (p_.encoder_shaft == SimulatedEncoderParameters::Shaft::kMotor) return mechanics_.motor_revolutions();
  return mechanics_.load_position() / p_.mechanics.load_units_per_revolution;
}

IoStatus SimulatedServoAmplifier::sample_inputs() noexcept {
  // This cycle of the amplifier runs with last cycle's outputs (like the drive's transport delay, R2).
  applied_volts_ = dac_volts(written_code_, p_.dac);
  apply_enable();
  if (armed_request_) {
    counter_.arm_zero_mark();
    armed_request_ = false;
  }
  const double dt = p_.mechanics.servo_cycle_s / static_cast<double>(p_.mechanics.substeps);
  for (std::uint32_t i = 0; i < p_.mechanics.substeps; ++i) {
    power_for(dt);
    MotorLoadCommand command;
    command.torque_enabled = enabled() && ready();
    command.reference_rpm = std::clamp((applied_volts_ + p_.input_offset_volts) * p_.rpm_per_volt,
                                       -p_.mechanics.max_speed_rpm, p_.mechanics.max_speed_rpm);
    command.torque_limit_positive = p_.mechanics.torque_limit_nm;
    command.torque_limit_negative = -p_.mechanics.torque_limit_nm;
    mechanics_.step(command, dt);
    counter_.update(encoder_shaft_revolutions());
  }
  return finish_sample(counter_.sample());
}

void SimulatedServoAmplifier::arm_zero_mark(Channel channel) noexcept {
  if (channel == p_.counter) armed_request_ = true;
}

void SimulatedServoAmplifier::set_analog_output(Channel channel, std::int32_t code) noexcept {
  if (channel == p_.speed_input) pending_code_ = code;
}

}  // namespace tomc::drives::io
