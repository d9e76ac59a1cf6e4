#pragma once
// What the page shows of an axis on an analog or stepper actor (issue 20; spec 01 §3.11, §3.12): instead of
// PROFIdrive words, the signals at the terminals — the analog output (% of U_100%, volts, DAC code) or the
// pulse train (Hz), the enable output, the ready input, the counter — and the actor's drive state and fault.
// Read in the cycle with the TO's snapshot (the actor runs in MC_Servo of the same thread): plain copies.

#include <cstdint>

#include "tomc/drives/analog_drive.hpp"
#include "tomc/drives/stepper_drive.hpp"

namespace tomc::diagnostics {

enum class ActorKind : std::uint8_t { kNone, kAnalog, kStepper };
std::string_view to_string(ActorKind kind) noexcept;  // "none", "analog", "stepper"

struct ActorSnapshot {
  ActorKind kind = ActorKind::kNone;
  double output_percent = 0.0;      // analog: output / U_100% (100 % = reference speed, up to the overdrive)
  double output_volts = 0.0;        // analog: commanded, before quantisation
  std::int32_t output_code = 0;     // analog: the DAC code written
  double pulse_frequency_hz = 0.0;  // stepper: the PTO's rate (signed: direction)
  bool enable_output = false;
  bool ready_input = false;
  std::int64_t counter = 0;  // the ×4 encoder count or the PTO's pulse count (continuous)
  double measured_speed_rpm = 0.0;
  std::uint8_t drive_state = 0;  // telegrams::DriveState (S1..S5)
  std::uint32_t fault = 0;       // the actor's fault (20001 ready lost, 20002 ...), 0: none
  bool encoder_fault = false;
};

// The actor of one axis: set once before the cycle runs; read() is the cycle's copy.
class ActorSource {
 public:
  ActorSource() = default;
  explicit ActorSource(const drives::AnalogDrive& analog) noexcept : analog_(&analog) {}
  explicit ActorSource(const drives::StepperDrive& stepper) noexcept : stepper_(&stepper) {}
  ActorKind kind() const noexcept {
    return analog_ != nullptr    ? ActorKind::kAnalog
           : stepper_ != nullptr ? ActorKind::kStepper
                                 : ActorKind::kNone;
  }
  void read(ActorSnapshot& out) const noexcept;

 private:
  const drives::AnalogDrive* analog_ = nullptr;
  const drives::StepperDrive* stepper_ = nullptr;
};

}  // namespace tomc::diagnostics
