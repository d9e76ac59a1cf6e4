#pragma once
// MC_MoveVelocity (spec 03 §4.8): no Done; InVelocity while the setpoint speed is reached and constant; Busy
// until another job replaces it.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_MoveVelocity {
  bool Execute = false;
  double Velocity = 100.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int16_t Direction = 0;
  bool Current = false;
  bool PositionControlled = true;  // ignored on a speed axis
  bool InVelocity = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return axis.move_velocity(techobjects::MoveVelocityInputs{
              Velocity, Acceleration, Deceleration, Jerk, Direction, Current, PositionControlled});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    const auto& o = handshake_.outputs();
    InVelocity = o.Busy && handshake_.last_status().in_velocity;
    Busy = o.Busy;
    CommandAborted = o.CommandAborted;
    Error = o.Error;
    ErrorID = o.ErrorID;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
