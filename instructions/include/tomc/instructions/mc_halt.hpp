#pragma once
// MC_Halt (spec 03 §4.4): decelerate to standstill; later motion jobs stay allowed.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_Halt {
  bool Execute = false;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool AbortAcceleration = false;
  std::int32_t Mode = 0;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return axis.halt(techobjects::HaltInputs{Deceleration, Jerk, AbortAcceleration, Mode});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
