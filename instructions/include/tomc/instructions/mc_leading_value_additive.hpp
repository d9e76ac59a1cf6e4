#pragma once
// MC_LeadingValueAdditive (spec 07 §4.3): Enable-level instruction. While Enable is TRUE, Position, Velocity
// and Acceleration are added to the follower's leading value at once (taken on every call); Busy while they
// are. Enable = FALSE removes them; another instance's start ends this one (Busy FALSE, §9.19.2 S7 "A").
// Error/ErrorID of a refused start are shown while Enable stays TRUE; a Position, Velocity or Acceleration
// that is not finite shows Error/16#8118 while it lasts and keeps the last values (decision C19). MC_Reset
// with Restart ends the job (Busy FALSE).
#include <cstdint>

#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_LeadingValueAdditive {
  bool Enable = false;
  double Position = 0.0;
  double Velocity = 0.0;
  double Acceleration = 0.0;
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    const techobjects::LeadingValueAdditiveValues values{Position, Velocity, Acceleration};
    if (Enable && !last_enable_) {
      const techobjects::Submission s = axis.additive_start(values);
      job_ = s.accepted() ? s.id : 0;
      Error = !s.accepted();
      ErrorID = s.error_id;
    } else if (Enable && job_ != 0) {
      // Values that are not finite: Error with 16#8118 while they are, the last valid ones stay in effect.
      ErrorID = axis.additive_update(job_, values);
      Error = ErrorID != 0;
    } else if (!Enable) {
      axis.additive_end(job_);
      job_ = 0;
      Error = false;
      ErrorID = 0;
    }
    last_enable_ = Enable;
    Busy = axis.additive_busy(job_);
  }

 private:
  techobjects::JobId job_ = 0;
  bool last_enable_ = false;
};

}  // namespace tomc::instructions
