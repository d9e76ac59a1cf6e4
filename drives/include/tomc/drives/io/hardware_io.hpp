#pragma once
// The hardware I/O layer under the analog and stepper actors (issue 20): analog outputs, digital inputs and
// outputs, pulse-train outputs and counters, addressed as a Linux DAQ card addresses them (subdevice,
// channel). Two backends: the simulated servo amplifier (simulated_servo_amplifier.hpp, the default), the
// simulated stepper motor (simulated_stepper_motor.hpp) and, not built yet, a comedi card. Called from
// MC_Servo: every function is noexcept and allocation-free.

#include <cstdint>

namespace tomc::drives::io {

// One channel of a card. The simulated backend knows its channels by the same addresses.
struct Channel {
  std::uint16_t subdevice = 0;
  std::uint16_t channel = 0;
  friend bool operator==(const Channel&, const Channel&) = default;
};

// A bipolar DAC: `bits` including the sign, codes −2^(bits−1) … 2^(bits−1)−1 over ±full_scale_volts. The
// default is the S7 analog value format of a 16-bit output module: code 27648 = 10 V, so that the overdrive
// range ends at 32511 = 11.759 V (spec 01 §3.12 "≈ ±117 %").
struct DacFormat {
  std::uint8_t bits = 16;                              // 8..16 (12-bit + sign = 13)
  double full_scale_volts = 10.0 * 32768.0 / 27648.0;  // the voltage of code 2^(bits−1)
};

// Volts -> DAC code: rounded to the nearest step, saturated to the code range.
std::int32_t dac_code(double volts, const DacFormat& format) noexcept;
// DAC code -> volts the amplifier sees.
double dac_volts(std::int32_t code, const DacFormat& format) noexcept;
// The smallest voltage step.
double dac_step_volts(const DacFormat& format) noexcept;

// A counter channel as read in one cycle: the raw count (modulo 2^width of the counter) and the zero-mark
// latch (a one-shot capture of the count at the next zero mark, armed by arm_zero_mark()).
struct CounterSample {
  std::uint32_t count = 0;
  std::uint32_t latched_count = 0;
  bool latched = false;
  // The card's encoder-signal supervision (wire break, missing line-driver signals, as a TM PosInput's
  // "encoder signal fault"): no encoder connected, or one that stopped working; the count does not follow.
  bool signal_lost = false;
};

enum class IoStatus : std::uint8_t { kOk, kReadFailed, kWriteFailed, kDeviceLost };
const char* to_string(IoStatus status) noexcept;

class HardwareIo {
 public:
  virtual ~HardwareIo() = default;

  // Start of MC_Servo: sample every input of this cycle. A failure keeps the last good values and is
  // reported; the actor raises its fault (docs/analog-drives.md).
  virtual IoStatus sample_inputs() noexcept = 0;
  virtual bool digital_input(Channel channel) const noexcept = 0;
  virtual CounterSample counter(Channel channel) const noexcept = 0;
  // Arms the one-shot zero-mark latch of a counter (H3 SetIP, TM PosInput "latch on N"); the next zero mark
  // captures the count, shown by counter().latched until the next arm.
  virtual void arm_zero_mark(Channel channel) noexcept = 0;

  // Outputs of this cycle, sent to the hardware by write_outputs() at the end of MC_Servo.
  virtual void set_analog_output(Channel channel, std::int32_t code) noexcept = 0;
  virtual void set_digital_output(Channel channel, bool value) noexcept = 0;
  // A pulse-train output (PTO: step and direction): pulses per second, the sign is the direction. The
  // module keeps the fractional pulse between cycles, so a frequency held for T seconds gives f·T pulses.
  virtual void set_pulse_frequency(Channel channel, double hertz) noexcept = 0;
  virtual IoStatus write_outputs() noexcept = 0;
};

}  // namespace tomc::drives::io
