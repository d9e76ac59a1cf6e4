#pragma once
// The simulated backend of the hardware I/O layer: a servo amplifier with a ±10 V speed input, an enable
// input and a ready output, turning the shared motor and load model (motor_load.hpp), with an incremental
// encoder on a counter input of the "card" (quadrature_counter.hpp). Seen from the controller it is a card:
// an analog output, a digital output (to the amplifier's enable), a digital input (its ready) and a counter.
// One sample_inputs() is one servo cycle of the amplifier: the outputs written last cycle act during it.

#include "tomc/drives/io/hardware_io.hpp"
#include "tomc/drives/io/quadrature_counter.hpp"
#include "tomc/drives/motor_load.hpp"
#include "tomc/drives/simulated_drive_parameters.hpp"

namespace tomc::drives::io {

struct SimulatedServoAmplifierParameters {
  // Where the amplifier is wired on the card (the actor's channels must match).
  Channel speed_input{0, 0};   // analog output of the card -> amplifier speed input
  Channel enable_input{2, 0};  // digital output of the card -> amplifier enable
  Channel ready_output{3, 0};  // amplifier ready -> digital input of the card
  Channel encoder{4, 0};       // encoder -> counter of the card
  DacFormat dac{};             // the card's analog output

  // The amplifier: its speed loop is the motor/load model's (speed_loop_time_constant_s).
  double rpm_per_volt = 300.0;      // motor speed per volt at the input (3000 1/min at 10 V)
  double input_offset_volts = 0.0;  // drift: the motor turns at 0 V command (what TarOffs compensates)
  bool enable_wired = true;         // false: the amplifier runs whenever it is ready
  double ready_delay_s = 0.02;      // power-on -> ready
  SimulatedEncoderParameters::Shaft encoder_shaft = SimulatedEncoderParameters::Shaft::kMotor;
  QuadratureEncoderParameters counter{};
  // Motor, load and machine (MotorLoad); also servo_cycle_s, substeps, max_speed_rpm and torque_limit_nm.
  SimulatedDriveParameters mechanics{};
};

class SimulatedServoAmplifier final : public HardwareIo {
 public:
  explicit SimulatedServoAmplifier(const SimulatedServoAmplifierParameters& parameters);

  IoStatus sample_inputs() noexcept override;
  bool digital_input(Channel channel) const noexcept override;
  CounterSample counter(Channel channel) const noexcept override;
  void arm_zero_mark(Channel channel) noexcept override;
  void set_analog_output(Channel channel, std::int32_t code) noexcept override;
  void set_digital_output(Channel channel, bool value) noexcept override;
  IoStatus write_outputs() noexcept override;

  // ---- simulation control ----
  // The amplifier's power section (mains); off: not ready, the motor coasts.
  void set_power(bool on) noexcept;
  // An amplifier fault (overcurrent, ...): not ready and the motor coasts until cleared.
  void set_fault(bool fault) noexcept { fault_ = fault; }
  // A card that fails: every read/write reports `status` until cleared with kOk.
  void inject_io_failure(IoStatus status) noexcept { io_failure_ = status; }

  // ---- observation ----
  double input_volts() const noexcept { return applied_volts_; }
  bool enabled() const noexcept { return applied_enable_; }
  bool ready() const noexcept;
  const MotorLoad& mechanics() const noexcept { return mechanics_; }
  const SimulatedServoAmplifierParameters& parameters() const noexcept { return p_; }

 private:
  double encoder_shaft_revolutions() const noexcept;

  SimulatedServoAmplifierParameters p_;
  MotorLoad mechanics_;
  QuadratureCounter counter_;
  // outputs of the card as written (act in the next cycle) and as applied (this cycle)
  std::int32_t pending_code_ = 0;
  bool pending_enable_ = false;
  std::int32_t written_code_ = 0;
  bool written_enable_ = false;
  double applied_volts_ = 0.0;
  bool applied_enable_ = false;
  bool armed_request_ = false;
  bool powered_ = true;
  double powered_for_s_ = 0.0;
  bool fault_ = false;
  IoStatus io_failure_ = IoStatus::kOk;
  CounterSample sample_{};
  bool ready_sample_ = false;
};

}  // namespace tomc::drives::io
