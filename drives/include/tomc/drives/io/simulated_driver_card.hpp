#pragma once
// What the simulated servo amplifier (simulated_servo_amplifier.hpp) and the simulated stepper driver
// (simulated_stepper_motor.hpp) share, seen from the card: the driver's enable input on a digital output of
// the card, its ready output on a digital input (mains on, no fault, after ready_delay_s), the position
// counter, a card failure to inject, and the outputs written in cycle k acting during cycle k+1 (R2).

#include "tomc/drives/io/hardware_io.hpp"

namespace tomc::drives::io {

struct DriverWiring {
  Channel enable_input{2, 0};  // digital output of the card -> driver enable
  Channel ready_output{3, 0};  // driver ready -> digital input of the card
  Channel counter{4, 0};       // position feedback -> counter of the card
  bool enable_wired = true;    // false: the driver runs whenever it is ready
  double ready_delay_s = 0.02;
};

class SimulatedDriverCard : public HardwareIo {
 public:
  bool digital_input(Channel channel) const noexcept final {
    return channel == wiring_.ready_output && ready_sample_;
  }
  CounterSample counter(Channel channel) const noexcept final {
    return channel == wiring_.counter ? sample_ : CounterSample{};
  }
  void set_digital_output(Channel channel, bool value) noexcept final {
    if (channel == wiring_.enable_input) pending_enable_ = value;
  }
  IoStatus write_outputs() noexcept final {
    if (io_failure_ != IoStatus::kOk) return io_failure_;  // nothing reaches the driver
    written_enable_ = pending_enable_;
    latch_outputs();
    return IoStatus::kOk;
  }

  // ---- simulation control ----
  // The driver's power section (mains); off: not ready, no torque.
  void set_power(bool on) noexcept {
    if (on && !powered_) powered_for_s_ = 0.0;
    powered_ = on;
  }
  // A driver fault (overcurrent, overtemperature, ...): not ready, no torque until cleared.
  void set_fault(bool fault) noexcept { fault_ = fault; }
  // A card that fails: every read/write reports `status` until cleared with kOk.
  void inject_io_failure(IoStatus status) noexcept { io_failure_ = status; }

  // ---- observation ----
  bool ready() const noexcept { return powered_ && !fault_ && powered_for_s_ >= wiring_.ready_delay_s; }
  bool enabled() const noexcept { return applied_enable_; }

 protected:
  // Powered since before the controller started.
  explicit SimulatedDriverCard(const DriverWiring& wiring) noexcept
      : wiring_(wiring), powered_for_s_(wiring.ready_delay_s) {}

  // write_outputs(): the derived class's own outputs, pending -> written.
  virtual void latch_outputs() noexcept = 0;
  // Start of sample_inputs(): the enable written last cycle applies.
  void apply_enable() noexcept { applied_enable_ = written_enable_ || !wiring_.enable_wired; }
  void power_for(double dt) noexcept {
    if (powered_) powered_for_s_ += dt;
  }
  // End of sample_inputs(): this cycle's counter and ready signal, unless the card fails (the values of the
  // last good sample stay).
  IoStatus finish_sample(const CounterSample& sample) noexcept {
    if (io_failure_ != IoStatus::kOk) return io_failure_;
    sample_ = sample;
    ready_sample_ = ready();
    return IoStatus::kOk;
  }

 private:
  DriverWiring wiring_;
  bool pending_enable_ = false;
  bool written_enable_ = false;
  bool applied_enable_ = false;
  bool powered_ = true;
  double powered_for_s_ = 0.0;
  bool fault_ = false;
  IoStatus io_failure_ = IoStatus::kOk;
  CounterSample sample_{};
  bool ready_sample_ = false;
};

}  // namespace tomc::drives::io
