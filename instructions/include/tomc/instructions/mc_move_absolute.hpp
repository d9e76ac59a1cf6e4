#pragma once
// MC_MoveAbsolute (spec 03 §4.5): position to an absolute target; Done once the target is reached and the
// positioning window's dwell time has passed; Active FALSE while appended (BufferMode 1) and pending.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_MoveAbsolute {
  bool Execute = false;
  double Position = 0.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t BufferMode = 0;
  std::int16_t Direction = 1;
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
          return axis.move_absolute(techobjects::MoveAbsoluteInputs{
              Position, Velocity, Acceleration, Deceleration, Jerk, Direction, BufferMode});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
    Active = handshake_.outputs().Active;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
