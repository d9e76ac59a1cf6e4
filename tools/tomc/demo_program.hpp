#pragma once
// The user program of `tomc demo`: a PLC-style loop per axis that runs it through a list of velocities, each
// held for a dwell time, forever. A program switch "<axis>.automatic" (shown on the page) takes the axis out
// of the loop: the program then disables it (MC_Power.Enable = FALSE), which is what the axis control panel
// needs before it can take master control (spec 02 §9.2). Errors are acknowledged after a few seconds so that
// the demo recovers from faults injected while it runs. Runs in the cycle: noexcept, no allocation.

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/runtime.hpp"
#include "tomc/techobjects/speed_axis.hpp"

namespace tomc::cli {

struct DemoSequence {
  std::vector<double> velocities;  // in the axis' velocity unit; 0 = MC_Halt
  double dwell_s = 3.0;
};

class DemoAxisProgram {
 public:
  static constexpr double kAcknowledgeAfterS = 5.0;

  DemoAxisProgram(techobjects::SpeedAxis& axis, DemoSequence sequence);
  std::atomic<bool>& automatic() noexcept { return automatic_; }
  const DemoSequence& sequence() const noexcept { return sequence_; }
  void operator()(const techobjects::CycleClock& clock) noexcept;

 private:
  void start_step(std::size_t step) noexcept;

  techobjects::SpeedAxis& axis_;
  DemoSequence sequence_;
  std::atomic<bool> automatic_{true};
  instructions::MC_Power<techobjects::SpeedAxis> power_;
  instructions::MC_MoveVelocity<techobjects::SpeedAxis> move_;
  instructions::MC_Halt<techobjects::SpeedAxis> halt_;
  instructions::MC_Reset<techobjects::SpeedAxis> reset_;
  std::size_t step_ = 0;
  double step_time_s_ = 0.0;
  double error_time_s_ = 0.0;
  bool running_ = false;
};

}  // namespace tomc::cli
