#pragma once
// MC_MoveRelative (spec 03 §4.6): move by Distance from the setpoint position at the job's start (for an
// appended job: from the end of the job before it). Homing is not required.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_MoveRelative {
  bool Execute = false;
  double Distance = 0.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t BufferMode = 0;
  bool Done = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return axis.move_relative(techobjects::MoveRelativeInputs{Distance, Velocity, Acceleration,
                                                                    Deceleration, Jerk, BufferMode});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
    Active = handshake_.outputs().Active;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
