#pragma once
// MC_MoveJog (spec 03 §3.4 J1..J5, §4.9): level-controlled jogging.
#include <cstdint>

#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_MoveJog {
  bool JogForward = false;
  bool JogBackward = false;
  double Velocity = 100.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool PositionControlled = true;  // ignored on a speed axis
  bool InVelocity = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    const bool any = JogForward || JogBackward;
    // A final flag (Error, CommandAborted) stays while an input is held and clears when both are FALSE (J4).
    if (Error || CommandAborted) {
      if (any) return;
      Error = false;
      ErrorID = 0;
      CommandAborted = false;
    }
    if (job_ != 0) {
      const auto status = axis.job_status(job_);
      if (status.state == techobjects::JobState::kAborted ||
          status.state == techobjects::JobState::kUnknown) {
        finish(any, true, 0);  // aborted by another job: no new jog until the inputs were released
        return;
      }
      if (status.state == techobjects::JobState::kError) {
        finish(any, false, status.error_id);
        return;
      }
      if (status.state == techobjects::JobState::kDone) job_ = 0;  // J2: at standstill after release
    }
    const techobjects::Submission s =
        axis.jog(job_, techobjects::JogInputs{JogForward, JogBackward, Velocity, Acceleration, Deceleration,
                                              Jerk, PositionControlled});
    if (!s.accepted()) {
      job_ = 0;
      Busy = false;
      InVelocity = false;
      if (s.error_id != 0) {
        Error = true;
        ErrorID = s.error_id;
      }
      return;
    }
    job_ = s.id;
    const auto status = axis.job_status(job_);
    Busy = status.state == techobjects::JobState::kActive;
    InVelocity = Busy && status.in_velocity;
    if (!Busy) job_ = 0;
  }

 private:
  // The final flag shows for at least this call; it is held while an input stays TRUE.
  void finish(bool, bool aborted, std::uint16_t error_id) noexcept {
    job_ = 0;
    Busy = false;
    InVelocity = false;
    CommandAborted = aborted;
    Error = !aborted;
    ErrorID = Error ? error_id : 0;
  }
  techobjects::JobId job_ = 0;
};

}  // namespace tomc::instructions
