#pragma once
// MC_Stop (spec 03 §4.13): stop and block new motion jobs while Execute = TRUE.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_Stop {
  bool Execute = false;
  std::int32_t Mode = 0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool AbortAcceleration = false;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return axis.stop(techobjects::StopInputs{Mode, Deceleration, Jerk, AbortAcceleration});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    // The lock follows the Execute level of the accepted job, also after Done (spec 03 §4.13 implementation
    // rule).
    axis.stop_execute(handshake_.job(), Execute);
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
