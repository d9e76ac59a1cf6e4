#pragma once
// The stepper actor (spec 01 §3.11, seed 004 §6.2.6): a PTO module (TM PTO 2x24V / TM PTO 4) that the S7
// connects through telegram 3. The speed setpoint NSOLL_B becomes a pulse frequency on a pulse-train output
// (step and direction), with the optional enable output and ready input of the analog actor; the position
// comes from the module's count of the pulses it sent or from an encoder on its counter input. The
// control-difference quantisation that keeps a stepper from hunting around its target is the TO's
// (PositionControl.ControlDifferenceQuantization, position_control.hpp). docs/analog-drives.md.

#include "tomc/drives/telegram3_actor.hpp"

namespace tomc::drives {

struct StepperDriveParameters : ActorParameters {
  double steps_per_revolution = 1600.0;  // motor steps per revolution: 100 % = ReferenceSpeed of these
  double max_frequency_hz = 200000.0;    // the PTO's output range; the frequency is clamped to ± it
  io::Channel pulse_output{5, 0};        // <TO>.Actor.Interface.AddressOut of the PTO channel
};

class StepperDrive final : public Telegram3Actor {
 public:
  // `hardware` must outlive the actor. Telegram 3 facing the TO.
  StepperDrive(io::HardwareIo& hardware, const StepperDriveParameters& parameters);

  // ---- observation (diagnostics, tests) ----
  double pulse_frequency_hz() const noexcept { return frequency_hz_; }
  const StepperDriveParameters& parameters() const noexcept { return p_; }

 private:
  void set_speed_output(bool enabled, double speed) noexcept override;

  StepperDriveParameters p_;
  double frequency_hz_ = 0.0;
};

}  // namespace tomc::drives
