#pragma once
// The MotionIn instructions (spec 03 §4.17, class M of §3.1, §3.3 L4): MC_MotionInVelocity,
// MC_MotionInPosition, MC_MotionInSuperimposed, MC_MotionInSuperimposedAxes. The rising edge of Enable starts
// the job, the inputs are the axis' (superimposed) setpoints on every call while Enable = TRUE (no profile,
// no dynamic limits), the falling edge ends it. No Done output; CommandAborted or Error end the job and stay
// shown until Enable falls.
#include <cstdint>

#include "tomc/techobjects/axis/job.hpp"
#include "tomc/techobjects/axis/job_inputs.hpp"
#include "tomc/techobjects/synchronous/leading_value.hpp"

namespace tomc::instructions {

namespace detail {

// The Enable handshake both MotionIn instructions share. `submit(running)` passes the inputs to the axis
// (running = 0 at the rising edge).
class MotionInHandshake {
 public:
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  template <typename Axis, typename Submit>
  void call(Axis& axis, bool enable, Submit submit) noexcept {
    if (enable && !last_enable_) {  // rising edge: a new job, the outputs of the last one cleared
      CommandAborted = false;
      Error = false;
      ErrorID = 0;
      take(submit(0));
    } else if (enable && job_ != 0) {
      const techobjects::JobStatus status = axis.job_status(job_);
      if (status.state == techobjects::JobState::kActive) {
        take(submit(job_));
      } else {
        job_ = 0;
        CommandAborted = status.state != techobjects::JobState::kError;
        Error = !CommandAborted;
        ErrorID = Error ? status.error_id : 0;
      }
    } else if (!enable && last_enable_) {  // falling edge: the job ends, every output clears
      if (job_ != 0) axis.end_motion_in(job_);
      job_ = 0;
      CommandAborted = false;
      Error = false;
      ErrorID = 0;
    }
    last_enable_ = enable;
    Busy = job_ != 0;
  }
  // The outputs on the instruction (Busy, CommandAborted, Error, ErrorID).
  template <typename FB>
  void show(FB& fb) const noexcept {
    fb.Busy = Busy;
    fb.CommandAborted = CommandAborted;
    fb.Error = Error;
    fb.ErrorID = ErrorID;
  }

 private:
  void take(const techobjects::Submission& s) noexcept {
    job_ = s.id;
    if (s.error_id != 0) {
      Error = true;
      ErrorID = s.error_id;
    }
  }
  techobjects::JobId job_ = 0;
  bool last_enable_ = false;
};

}  // namespace detail

template <typename Axis>
struct MC_MotionInVelocity {
  bool Enable = false;
  double Velocity = 0.0;
  double Acceleration = 0.0;
  bool PositionControlled = true;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(axis, Enable, [&](techobjects::JobId running) {
      return axis.motion_in_velocity(
          running, techobjects::MotionInVelocityInputs{Velocity, Acceleration, PositionControlled});
    });
    handshake_.show(*this);
  }

 private:
  detail::MotionInHandshake handshake_;
};

template <typename Axis>
struct MC_MotionInPosition {
  bool Enable = false;
  double Position = 0.0;
  double Velocity = 0.0;
  double Acceleration = 0.0;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(axis, Enable, [&](techobjects::JobId running) {
      return axis.motion_in_position(running,
                                     techobjects::MotionInPositionInputs{Position, Velocity, Acceleration});
    });
    handshake_.show(*this);
  }

 private:
  detail::MotionInHandshake handshake_;
};

// MC_MotionInSuperimposed (spec 03 §4.17.3): Distance is the absolute superimposition (x = x_base +
// Distance), VelocityDiff and AccelerationDiff its velocity and acceleration; StatusWord2.X6 while active.
template <typename Axis>
struct MC_MotionInSuperimposed {
  bool Enable = false;
  double Distance = 0.0;
  double VelocityDiff = 0.0;
  double AccelerationDiff = 0.0;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(axis, Enable, [&](techobjects::JobId running) {
      return axis.motion_in_superimposed(
          running, techobjects::MotionInSuperimposedInputs{Distance, VelocityDiff, AccelerationDiff});
    });
    handshake_.show(*this);
  }

 private:
  detail::MotionInHandshake handshake_;
};

// MC_MotionInSuperimposedAxes (spec 03 §4.17.4): adds the setpoints of SuperimposingAxis — one of Axis'
// configured possible superimposing axes — to Axis' base motion in the same cycle; StatusWord2.X8 while
// active. The instance is called with Axis; SuperimposingAxis is an input as in the manual.
template <typename Axis>
struct MC_MotionInSuperimposedAxes {
  const techobjects::LeadingValueSource* SuperimposingAxis = nullptr;
  bool Enable = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(axis, Enable, [&](techobjects::JobId running) {
      return axis.motion_in_superimposed_axes(running, SuperimposingAxis);
    });
    handshake_.show(*this);
  }

 private:
  detail::MotionInHandshake handshake_;
};

}  // namespace tomc::instructions
