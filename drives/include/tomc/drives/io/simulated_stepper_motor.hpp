#pragma once
// The simulated backend of a stepper axis: a PTO channel (pulse train, step and direction) into a stepper
// driver with an enable input and a ready output, a stepper motor that follows the pulses step by step as
// long as it can, and the position feedback on a counter of the "card": either the PTO's own count of the
// pulses it sent (a TM PTO without encoder) or an incremental encoder on the motor or load shaft
// (quadrature_counter.hpp). The load turns the shared motor/load model's machine (limit switches, cams).
// One sample_inputs() is one servo cycle: the outputs written last cycle act during it (decision R2).
//
// Lost steps, a model tomc chose (spec 01 §3.11 and seed 004 §6.2.6 say nothing about the motor; decision
// A12): the rotor follows the pulses while it is in step. It falls out of step (stalls) when the pulse rate
// exceeds pull_out_rate_hz, or when above the start-stop rate pull_in_rate_hz the rate steps by more than
// max_acceleration_hz_per_s × the servo cycle (the PTO changes its rate once per cycle); a stalled rotor
// stands while the pulses keep coming (every one is a lost step) and falls back into step once the pulse rate
// is at or below pull_in_rate_hz.

#include <cstdint>

#include "tomc/drives/io/quadrature_counter.hpp"
#include "tomc/drives/io/simulated_driver_card.hpp"
#include "tomc/drives/motor_load.hpp"
#include "tomc/drives/simulated_drive_parameters.hpp"

namespace tomc::drives::io {

// Where the driver is wired on the card (the actor's channels must match): DriverWiring's enable, ready and
// counter (the PTO's pulse count or the encoder), and the pulse input.
struct SimulatedStepperMotorParameters : DriverWiring {
  Channel pulse_input{5, 0};  // PTO channel of the card -> driver step/direction

  enum class Feedback : std::uint8_t { kPulseCount, kEncoder };
  Feedback feedback = Feedback::kPulseCount;
  std::uint8_t pulse_counter_width_bits = 32;  // the PTO's pulse counter register

  double steps_per_revolution = 1600.0;         // motor steps (full steps × microsteps) per revolution
  double pull_in_rate_hz = 2000.0;              // start-stop rate: followed from standstill at once
  double pull_out_rate_hz = 40000.0;            // the highest rate the motor follows with its load
  double max_acceleration_hz_per_s = 400000.0;  // the fastest rate change above pull_in it follows
  SimulatedEncoderParameters::Shaft encoder_shaft = SimulatedEncoderParameters::Shaft::kMotor;
  QuadratureEncoderParameters encoder{};  // Feedback::kEncoder
  // Gear, load units and machine of the shared model (MotorLoad), servo_cycle_s and substeps.
  SimulatedDriveParameters mechanics{};
};

// A driver fault (set_fault): not ready, no holding torque, pulses ignored until cleared.
class SimulatedStepperMotor final : public SimulatedDriverCard {
 public:
  explicit SimulatedStepperMotor(const SimulatedStepperMotorParameters& parameters);

  IoStatus sample_inputs() noexcept override;
  void arm_zero_mark(Channel channel) noexcept override;
  void set_analog_output(Channel, std::int32_t) noexcept override {}  // no analog input on a stepper driver
  void set_pulse_frequency(Channel channel, double hertz) noexcept override;

  // ---- observation ----
  double pulse_frequency_hz() const noexcept { return applied_hz_; }
  std::int64_t pulses_sent() const noexcept { return pulses_; }       // by the PTO, signed
  std::int64_t rotor_steps() const noexcept { return rotor_steps_; }  // where the rotor is
  std::int64_t lost_steps() const noexcept { return lost_steps_; }    // pulses the rotor did not follow
  bool in_step() const noexcept { return in_step_; }
  std::uint32_t stalls() const noexcept { return stalls_; }  // times the rotor fell out of step
  const MotorLoad& mechanics() const noexcept { return mechanics_; }
  const SimulatedStepperMotorParameters& parameters() const noexcept { return p_; }

 private:
  void latch_outputs() noexcept override { written_hz_ = pending_hz_; }
  double rotor_revolutions() const noexcept {
    return static_cast<double>(rotor_steps_) / p_.steps_per_revolution;
  }
  double encoder_shaft_revolutions() const noexcept;
  CounterSample feedback() const noexcept;
  void check_step(double hertz, double cycle_s) noexcept;
  void follow(std::int64_t pulses) noexcept;

  SimulatedStepperMotorParameters p_;
  MotorLoad mechanics_;
  QuadratureCounter encoder_;
  double pending_hz_ = 0.0;
  double written_hz_ = 0.0;
  double applied_hz_ = 0.0;
  double phase_ = 0.0;  // the PTO's fractional pulse
  std::int64_t pulses_ = 0;
  std::int64_t rotor_steps_ = 0;
  std::int64_t lost_steps_ = 0;
  double rotor_rate_hz_ = 0.0;  // the step rate the rotor follows (0 when stalled or disabled)
  bool in_step_ = true;
  std::uint32_t stalls_ = 0;
};

}  // namespace tomc::drives::io
