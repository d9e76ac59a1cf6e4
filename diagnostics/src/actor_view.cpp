// The analog or stepper actor of an axis as the page shows it (actor_view.hpp).
#include "tomc/diagnostics/actor_view.hpp"

namespace tomc::diagnostics {

std::string_view to_string(ActorKind kind) noexcept {
  switch (kind) {
    case ActorKind::kNone:
      return "none";
    case ActorKind::kAnalog:
      return "analog";
    case ActorKind::kStepper:
      return "stepper";
  }
  return "?";
}

namespace {

void read_common(const drives::Telegram3Actor& actor, ActorSnapshot& out) noexcept {
  out.enable_output = actor.enable_output();
  out.ready_input = actor.ready_input();
  out.counter = actor.counter_value();
  out.measured_speed_rpm = actor.measured_speed_rpm();
  out.drive_state = static_cast<std::uint8_t>(actor.state());
  out.fault = actor.active_fault();
  out.encoder_fault = actor.encoder_fault();
}

}  // namespace

void ActorSource::read(ActorSnapshot& out) const noexcept {
  out.kind = kind();
  if (analog_ != nullptr) {
    read_common(*analog_, out);
    out.output_volts = analog_->output_volts();
    out.output_code = analog_->output_code();
    const double reference = analog_->parameters().volts_at_reference;
    out.output_percent = reference != 0.0 ? out.output_volts / reference * 100.0 : 0.0;
  } else if (stepper_ != nullptr) {
    read_common(*stepper_, out);
    out.pulse_frequency_hz = stepper_->pulse_frequency_hz();
  }
}

}  // namespace tomc::diagnostics
