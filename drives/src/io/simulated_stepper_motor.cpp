// The simulated stepper driver and motor behind the stepper actor (simulated_stepper_motor.hpp).
#include "tomc/drives/io/simulated_stepper_motor.hpp"

#include <cmath>

namespace tomc::drives::io {

SimulatedStepperMotor::SimulatedStepperMotor(const SimulatedStepperMotorParameters& parameters)
    : SimulatedDriverCard(parameters), p_(parameters), mechanics_(p_.mechanics) {
  if (p_.mechanics.substeps == 0) p_.mechanics.substeps = 1;
  rotor_steps_ = std::llround(mechanics_.motor_revolutions() * p_.steps_per_revolution);
  encoder_ = QuadratureCounter(p_.encoder, encoder_shaft_revolutions());
  (void)finish_sample(feedback());
}

CounterSample SimulatedStepperMotor::feedback() const noexcept {
  if (p_.feedback == SimulatedStepperMotorParameters::Feedback::kEncoder) return encoder_.sample();
  // The PTO's count of the pulses it sent, in a register of pulse_counter_width_bits.
  const int width = p_.pulse_counter_width_bits >= 32 ? 32 : p_.pulse_counter_width_bits;
  const std::uint64_t mask = (std::uint64_t{1} << width) - 1u;
  CounterSample sample;
  sample.count = static_cast<std::uint32_t>(static_cast<std::uint64_t>(pulses_) & mask);
  return sample;
}

double SimulatedStepperMotor::encoder_shaft_revolutions() const noexcept {
  if (p_.encoder_shaft == SimulatedEncoderParameters::Shaft::kMotor) return rotor_revolutions();
  return rotor_revolutions() / mechanics_.ratio();
}

void SimulatedStepperMotor::check_step(double hertz, double cycle_s) noexcept {
  // The PTO changes its rate once per cycle: the rotor sees a rate step of (hertz − its rate).
  const double rate = std::fabs(hertz);
  if (!enabled() || !ready()) {
    rotor_rate_hz_ = 0.0;
    in_step_ = true;  // energised again at standstill, it holds the step it stands on
    return;
  }
  if (in_step_) {
    const bool too_fast = rate > p_.pull_out_rate_hz;
    const bool too_steep =
        rate > p_.pull_in_rate_hz &&
        std::fabs(hertz - rotor_rate_hz_) > p_.max_acceleration_hz_per_s * cycle_s * (1.0 + 1e-9);
    if (too_fast || too_steep) {
      in_step_ = false;
      ++stalls_;
    }
  } else if (rate <= p_.pull_in_rate_hz) {
    in_step_ = true;  // slow enough to pull in again, from wherever the rotor stands
  }
  rotor_rate_hz_ = in_step_ ? hertz : 0.0;
}

void SimulatedStepperMotor::follow(std::int64_t pulses) noexcept {
  // Without current in the windings (disabled, not ready) pulses are ignored; a stalled rotor stands.
  if (in_step_ && enabled() && ready()) {
    rotor_steps_ += pulses;
  } else {
    lost_steps_ += pulses < 0 ? -pulses : pulses;
  }
}

IoStatus SimulatedStepperMotor::sample_inputs() noexcept {
  // This cycle runs with last cycle's outputs (like the drive's transport delay, R2).
  applied_hz_ = written_hz_;
  apply_enable();
  check_step(applied_hz_, p_.mechanics.servo_cycle_s);
  const double dt = p_.mechanics.servo_cycle_s / static_cast<double>(p_.mechanics.substeps);
  for (std::uint32_t i = 0; i < p_.mechanics.substeps; ++i) {
    power_for(dt);
    // The PTO: whole pulses, the fraction carried to the next step.
    phase_ += applied_hz_ * dt;
    const double whole = std::trunc(phase_);
    phase_ -= whole;
    const auto pulses = static_cast<std::int64_t>(whole);
    pulses_ += pulses;
    const double before = mechanics_.load_position();
    follow(pulses);
    const double load = rotor_revolutions() / mechanics_.ratio() * p_.mechanics.load_units_per_revolution;
    mechanics_.move_externally((load - before) / dt, dt);
    encoder_.update(encoder_shaft_revolutions());
  }
  return finish_sample(feedback());
}

void SimulatedStepperMotor::arm_zero_mark(Channel channel) noexcept {
  // Only an encoder has a zero mark; the pulse count has none (the latch never fires).
  if (channel == p_.counter && p_.feedback == SimulatedStepperMotorParameters::Feedback::kEncoder) {
    encoder_.arm_zero_mark();
  }
}

void SimulatedStepperMotor::set_pulse_frequency(Channel channel, double hertz) noexcept {
  if (channel == p_.pulse_input) pending_hz_ = std::isfinite(hertz) ? hertz : 0.0;
}

}  // namespace tomc::drives::io
