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

// ---- positioning axis ----

DemoPositioningProgram::DemoPositioningProgram(techobjects::PositioningAxis& axis, DemoPositioning plan)
    : axis_(axis), plan_(std::move(plan)) {
  power_.StartMode = 1;
  power_.StopMode = 2;  // leaving the loop stops with maximum dynamics, then disables
  home_.Mode = static_cast<std::int16_t>(plan_.home_mode);
  home_.Position = plan_.home_position;
  absolute_.Velocity = relative_.Velocity = plan_.velocity;
  absolute_.Direction = 3;  // a modulo axis takes the shortest way (ignored on a linear axis)
  relative_.Distance = plan_.distance;
}

// A new job needs a rising Execute edge: one call with FALSE, then TRUE stays until the next job.
void DemoPositioningProgram::start_home() noexcept {
  end_jobs();
  home_.Execute = true;
  step_ = Step::kHoming;
  step_time_s_ = 0.0;
}

void DemoPositioningProgram::start_move() noexcept {
  end_jobs();
  if (plan_.distance != 0.0) {
    relative_.Execute = true;
  } else if (!plan_.positions.empty()) {
    absolute_.Position = plan_.positions[target_ % plan_.positions.size()];
    absolute_.Execute = true;
  }
  step_ = Step::kMoving;
  step_time_s_ = 0.0;
}

void DemoPositioningProgram::end_jobs() noexcept {
  home_.Execute = absolute_.Execute = relative_.Execute = false;
  home_(axis_);
  absolute_(axis_);
  relative_(axis_);
}

void DemoPositioningProgram::operator()(const techobjects::CycleClock& clock) noexcept {
  const double dt = clock.servo_cycle_s;  // the demo's user program runs every servo cycle
  const bool automatic = automatic_.load(std::memory_order_relaxed);
  power_.Enable = automatic;
  power_(axis_);
  const bool enabled = automatic && power_.Status;
  step_time_s_ += dt;
  if (!enabled) {
    if (step_ != Step::kDisabled) end_jobs();
    step_ = Step::kDisabled;
  } else {
    const bool homed = techobjects::test(axis_.data().StatusWord, techobjects::StatusWordBit::kHomingDone);
    const bool relative = plan_.distance != 0.0;
    const bool move_done = relative ? relative_.Done : absolute_.Done;
    const bool move_failed =
        relative ? relative_.Error || relative_.CommandAborted : absolute_.Error || absolute_.CommandAborted;
    switch (step_) {
      case Step::kDisabled:
        if (homed) {
          start_move();
        } else {
          start_home();
        }
        break;
      case Step::kHoming:
        if (home_.Done) {
          start_move();
        } else if (home_.Error || home_.CommandAborted) {
          step_ = Step::kFault;
          step_time_s_ = 0.0;
        }
        break;
      case Step::kMoving:
        if (move_done) {
          ++moves_;
          ++target_;
          step_ = Step::kDwell;
          step_time_s_ = 0.0;
        } else if (move_failed) {
          step_ = Step::kFault;
          step_time_s_ = 0.0;
        }
        break;
      case Step::kDwell:
        if (step_time_s_ >= plan_.dwell_s) start_move();
        break;
      case Step::kFault:
        // A refused or aborted job: start again (homing if needed) after a second without a pending error.
        if (step_time_s_ >= 1.0 &&
            !techobjects::test(axis_.data().StatusWord, techobjects::StatusWordBit::kError)) {
          end_jobs();
          step_ = Step::kDisabled;
        }
        break;
    }
  }
  home_(axis_);
  absolute_(axis_);
  relative_(axis_);
  const bool error = techobjects::test(axis_.data().StatusWord, techobjects::StatusWordBit::kError);
  error_time_s_ = automatic && error ? error_time_s_ + dt : 0.0;
  reset_.Execute = error_time_s_ >= kAcknowledgeAfterS;
  if (reset_.Execute) error_time_s_ = 0.0;
  reset_(axis_);
}

// ---- synchronous axis camming ----

DemoCammingProgram::DemoCammingProgram(techobjects::SynchronousAxis& axis, techobjects::Cam& cam,
                                       std::int32_t application_mode)
    : axis_(axis) {
  power_.StartMode = 1;
  power_.StopMode = 2;
  home_.Mode = 0;
  cam_in_.Master = axis.interconnections().empty() ? nullptr : axis.interconnections().front().source;
  cam_in_.Cam = &cam;
  cam_in_.SyncProfileReference = 2;  // direct synchronous setting (spec 07 §3.4): no travel to the cam
  cam_in_.ApplicationMode = application_mode;
}

void DemoCammingProgram::operator()(const techobjects::CycleClock& clock) noexcept {
  const double dt = clock.servo_cycle_s;
  const bool automatic = automatic_.load(std::memory_order_relaxed);
  power_.Enable = automatic;
  power_(axis_);
  const bool enabled = automatic && power_.Status;
  step_time_s_ += dt;
  if (!enabled) {
    step_ = Step::kDisabled;
    home_.Execute = cam_in_.Execute = false;
  } else {
    switch (step_) {
      case Step::kDisabled:
        home_.Execute = true;  // a rising edge: Execute was FALSE while disabled
        step_ = Step::kHoming;
        break;
      case Step::kHoming:
        if (home_.Done) {
          home_.Execute = false;
          cam_in_.Execute = true;
          step_ = Step::kCamming;
        } else if (home_.Error || home_.CommandAborted) {
          step_ = Step::kFault;
          step_time_s_ = 0.0;
        }
        break;
      case Step::kCamming:
        // The cam job runs for ever (cyclic); a refused or aborted one is started again.
        if (cam_in_.Error || cam_in_.CommandAborted || !cam_in_.Busy) {
          step_ = Step::kFault;
          step_time_s_ = 0.0;
        }
        break;
      case Step::kFault:
        home_.Execute = cam_in_.Execute = false;
        if (step_time_s_ >= 1.0 &&
            !techobjects::test(axis_.data().StatusWord, techobjects::StatusWordBit::kError))
          step_ = Step::kDisabled;
        break;
    }
  }
  home_(axis_);
  cam_in_(axis_);
  const bool error = techobjects::test(axis_.data().StatusWord, techobjects::StatusWordBit::kError);
  error_time_s_ = automatic && error ? error_time_s_ + dt : 0.0;
  reset_.Execute = error_time_s_ >= kAcknowledgeAfterS;
  if (reset_.Execute) error_time_s_ = 0.0;
  reset_(axis_);
}

// ---- external encoder ----

DemoEncoderProgram::DemoEncoderProgram(techobjects::ExternalEncoder& encoder) : encoder_(encoder) {
  power_.Enable = true;
}

void DemoEncoderProgram::operator()(const techobjects::CycleClock& clock) noexcept {
  power_(encoder_);
  const bool error = techobjects::test(encoder_.data().StatusWord, techobjects::StatusWordBit::kError);
  error_time_s_ = error ? error_time_s_ + clock.servo_cycle_s : 0.0;
  reset_.Execute = error_time_s_ >= kAcknowledgeAfterS;
  if (reset_.Execute) error_time_s_ = 0.0;
  reset_(encoder_);
}

}  // namespace tomc::cli
