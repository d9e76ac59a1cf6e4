#pragma once
// The simulated backend of the hardware I/O layer: a servo amplifier with a ±10 V speed input, an enable
// input and a ready output, turning the shared motor and load model (motor_load.hpp), with an incremental
// encoder on a counter input of the "card" (quadrature_counter.hpp). Seen from the controller it is a card:
// an analog output, a digital output (to the amplifier's enable), a digital input (its ready) and a counter.
// One sample_inputs() is one servo cycle of the amplifier: the outputs written last cycle act during it.

#include "tomc/drives/io/quadrature_counter.hpp"
#include "tomc/drives/io/simulated_driver_card.hpp"
#include "tomc/drives/motor_load.hpp"
#include "tomc/drives/simulated_drive_parameters.hpp"

namespace tomc::drives::io {

// Where the amplifier is wired on the card (the actor's channels must match): DriverWiring's enable, ready,
// counter (the encoder), and the speed input.
struct SimulatedServoAmplifierParameters : DriverWiring {
  Channel speed_input{0, 0};  // analog output of the card -> amplifier speed input
  DacFormat dac{};            // the card's analog output

  // The amplifier: its speed loop is the motor/load model's (speed_loop_time_constant_s).
  double rpm_per_volt = 300.0;      // motor speed per volt at the input (3000 1/min at 10 V)
  double input_offset_volts = 0.0;  // drift: the motor turns at 0 V command (what TarOffs compensates)
  SimulatedEncoderParameters::Shaft encoder_shaft = SimulatedEncoderParameters::Shaft::kMotor;
  QuadratureEncoderParameters encoder{};
  // Motor, load and machine (MotorLoad); also servo_cycle_s, substeps, max_speed_rpm and torque_limit_nm.
  SimulatedDriveParameters mechanics{};
};

// Power off or an amplifier fault (set_power, set_fault): not ready, and the motor coasts.
class SimulatedServoAmplifier final : public SimulatedDriverCard {
 public:
  explicit SimulatedServoAmplifier(const SimulatedServoAmplifierParameters& parameters);

  IoStatus sample_inputs() noexcept override;
  void arm_zero_mark(Channel channel) noexcept override;
  void set_analog_output(Channel channel, std::int32_t code) noexcept override;
  void set_pulse_frequency(Channel, double) noexcept override {}  // no pulse input on a servo amplifier

  // ---- simulation control ----
  // Unplug (false) or plug in the encoder on the counter: the count stands while unplugged and the card
  // reports the lost signal (CounterSample::signal_lost).
  void set_encoder_connected(bool connected) noexcept { counter_.set_connected(connected); }

  // ---- observation ----
  double input_volts() const noexcept { return applied_volts_; }
  const MotorLoad& mechanics() const noexcept { return mechanics_; }
  const SimulatedServoAmplifierParameters& parameters() const noexcept { return p_; }

 private:
  void latch_outputs() noexcept override { written_code_ = pending_code_; }
  double encoder_shaft_revolutions() const noexcept;

  SimulatedServoAmplifierParameters p_;
  MotorLoad mechanics_;
  QuadratureCounter counter_;
  // the analog output of the card as written (acts in the next cycle) and as applied (this cycle)
  std::int32_t pending_code_ = 0;
  std::int32_t written_code_ = 0;
  double applied_volts_ = 0.0;
  bool armed_request_ = false;
};

}  // namespace tomc::drives::io
