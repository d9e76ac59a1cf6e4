#pragma once
// MC_MoveSuperimposed (spec 03 §4.10, seed 004 §6.7.10): a relative move added on top of the running base
// motion of a positioning or synchronous axis; the base motion goes on unchanged.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_MoveSuperimposed {
  bool Execute = false;
  double Distance = 0.0;
  double VelocityDiff = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return axis.move_superimposed(
              techobjects::MoveSuperimposedInputs{Distance, VelocityDiff, Acceleration, Deceleration, Jerk});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
