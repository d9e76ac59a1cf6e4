#pragma once
// MC_HaltSuperimposed (spec 03 §4.11): brakes the superimposed motion to standstill; the base motion is not
// affected. Without a superimposed motion it is Done at once.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_HaltSuperimposed {
  bool Execute = false;
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
          return axis.halt_superimposed(
              techobjects::HaltSuperimposedInputs{Deceleration, Jerk, AbortAcceleration});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
