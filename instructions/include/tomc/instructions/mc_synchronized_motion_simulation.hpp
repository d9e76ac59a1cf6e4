#pragma once
// MC_SynchronizedMotionSimulation (spec 07 §4.4): Enable-level instruction. Enable's rising edge puts the
// follower's synchronous operation (Synchronous, leader and follower at standstill) into simulation:
// InSimulation and Busy TRUE; the follower is free for single-axis jobs, disabling and MC_Stop while the
// gearing or camming goes on computing. Enable = FALSE ends it as soon as the follower can take the
// synchronous setpoint over (enabled, no MC_Stop): until then every call tries again and shows why not in
// Error/ErrorID; Enable TRUE again meanwhile keeps the simulation. A TO restart ends it (InSimulation FALSE).
#include <cstdint>

#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_SynchronizedMotionSimulation {
  bool Enable = false;
  bool InSimulation = false;
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    if (Enable && !last_enable_ && job_ != 0) {
      Error = false;  // Enable again before the end could happen: the simulation goes on
      ErrorID = 0;
    } else if (Enable && !last_enable_) {
      const techobjects::Submission s = axis.simulation_start();
      job_ = s.accepted() ? s.id : 0;
      Error = !s.accepted();
      ErrorID = s.error_id;
    } else if (!Enable) {
      ErrorID = axis.simulation_end(job_);
      Error = ErrorID != 0;
    }
    last_enable_ = Enable;
    InSimulation = axis.in_simulation(job_);
    if (!InSimulation) job_ = 0;
    Busy = InSimulation;
  }

 private:
  techobjects::JobId job_ = 0;
  bool last_enable_ = false;
};

}  // namespace tomc::instructions
