// The simulated servo amplifier behind the analog actor (simulated_servo_amplifier.hpp).
#include "tomc/drives/io/simulated_servo_amplifier.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::drives::io {

SimulatedServoAmplifier::SimulatedServoAmplifier(const SimulatedServoAmplifierParameters& parameters)
    : p_(parameters), mechanics_(p_.mechanics) {
  if (p_.mechanics.substeps == 0) p_.mechanics.substeps = 1;
  counter_ = QuadratureCounter(p_.counter, encoder_shaft_revolutions());
  powered_for_s_ = p_.ready_delay_s;  // powered since before the controller started
  sample_ = counter_.sample();
  ready_sample_ = ready();
}

double SimulatedServoAmplifier::encoder_shaft_revolutions() const noexcept {
  if (p_.encoder_shaft == SimulatedEncoderParameters::Shaft::kMotor) return mechanics_.motor_revolutions();
  return mechanics_.load_position() / p_.mechanics.load_units_per_revolution;
}

bool SimulatedServoAmplifier::ready() const noexcept {
  return powered_ && !fault_ && powered_for_s_ >= p_.ready_delay_s;
}

void SimulatedServoAmplifier::set_power(bool on) noexcept {
  if (on && !powered_) powered_for_s_ = 0.0;
  powered_ = on;
}

IoStatus SimulatedServoAmplifier::sample_inputs() noexcept {
  // This cycle of the amplifier runs with last cycle's outputs (like the drive's transport delay, R2).
  applied_volts_ = dac_volts(written_code_, p_.dac);
  applied_enable_ = written_enable_ || !p_.enable_wired;
  if (armed_request_) {
    counter_.arm_zero_mark();
    armed_request_ = false;
  }
  const double dt = p_.mechanics.servo_cycle_s / static_cast<double>(p_.mechanics.substeps);
  for (std::uint32_t i = 0; i < p_.mechanics.substeps; ++i) {
    if (powered_) powered_for_s_ += dt;
    MotorLoadCommand command;
    command.torque_enabled = applied_enable_ && ready();
    command.reference_rpm = std::clamp((applied_volts_ + p_.input_offset_volts) * p_.rpm_per_volt,
                                       -p_.mechanics.max_speed_rpm, p_.mechanics.max_speed_rpm);
    command.torque_limit_positive = p_.mechanics.torque_limit_nm;
    command.torque_limit_negative = -p_.mechanics.torque_limit_nm;
    mechanics_.step(command, dt);
    counter_.update(encoder_shaft_revolutions());
  }
  if (io_failure_ != IoStatus::kOk) return io_failure_;  // the values of the last good sample stay
  sample_ = counter_.sample();
  ready_sample_ = ready();
  return IoStatus::kOk;
}

bool SimulatedServoAmplifier::digital_input(Channel channel) const noexcept {
  return channel == p_.ready_output && ready_sample_;
}

CounterSample SimulatedServoAmplifier::counter(Channel channel) const noexcept {
  return channel == p_.encoder ? sample_ : CounterSample{};
}

void SimulatedServoAmplifier::arm_zero_mark(Channel channel) noexcept {
  if (channel == p_.encoder) armed_request_ = true;
}

void SimulatedServoAmplifier::set_analog_output(Channel channel, std::int32_t code) noexcept {
  if (channel == p_.speed_input) pending_code_ = code;
}

void SimulatedServoAmplifier::set_digital_output(Channel channel, bool value) noexcept {
  if (channel == p_.enable_input) pending_enable_ = value;
}

IoStatus SimulatedServoAmplifier::write_outputs() noexcept {
  if (io_failure_ != IoStatus::kOk) return io_failure_;  // nothing reaches the amplifier
  written_code_ = pending_code_;
  written_enable_ = pending_enable_;
  return IoStatus::kOk;
}

}  // namespace tomc::drives::io
