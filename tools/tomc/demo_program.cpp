// The demo's user program (demo_program.hpp).
#include "demo_program.hpp"

namespace tomc::cli {

DemoAxisProgram::DemoAxisProgram(techobjects::SpeedAxis& axis, DemoSequence sequence)
    : axis_(axis), sequence_(std::move(sequence)) {
  power_.StartMode = 1;
  power_.StopMode = 2;  // leaving the loop stops with maximum dynamics, then disables
}

void DemoAxisProgram::start_step(std::size_t step) noexcept {
  step_ = step;
  step_time_s_ = 0.0;
  const double v = sequence_.velocities.empty() ? 0.0 : sequence_.velocities[step_];
  // A new job needs a rising Execute edge: one call with FALSE, then TRUE stays until the next step.
  move_.Execute = false;
  halt_.Execute = false;
  move_(axis_);
  halt_(axis_);
  if (v != 0.0) {
    move_.Velocity = v;
    move_.Execute = true;
  } else {
    halt_.Execute = true;
  }
}

void DemoAxisProgram::operator()(const techobjects::CycleClock& clock) noexcept {
  const double dt = clock.servo_cycle_s;  // the demo's user program runs every servo cycle
  const bool automatic = automatic_.load(std::memory_order_relaxed);
  power_.Enable = automatic;
  power_(axis_);
  const bool enabled = automatic && power_.Status;
  if (enabled && !running_) start_step(0);
  if (!enabled) {
    move_.Execute = false;
    halt_.Execute = false;
  }
  running_ = enabled;
  if (enabled) {
    step_time_s_ += dt;
    if (step_time_s_ >= sequence_.dwell_s && !sequence_.velocities.empty())
      start_step((step_ + 1) % sequence_.velocities.size());
  }
  move_(axis_);
  halt_(axis_);
  // Acknowledge a pending error after a while (the page shows it meanwhile).
  const bool error = techobjects::test(axis_.data().StatusWord, techobjects::StatusWordBit::kError);
  error_time_s_ = automatic && error ? error_time_s_ + dt : 0.0;
  reset_.Execute = error_time_s_ >= kAcknowledgeAfterS;
  if (reset_.Execute) error_time_s_ = 0.0;
  reset_(axis_);
}

}  // namespace tomc::cli
