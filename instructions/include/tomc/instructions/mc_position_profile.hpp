#pragma once
// MC_PositionProfile (spec 03 §4.7, seed 004 §9.7): moves the axis along a time-position profile, relative
// (ProfileReference 0) or absolute (1), after a transition profile with the given dynamics where the axis is
// not ready to follow it. TimePosition is the profile, x = time: a TO_Cam as in the manual, or tomc's point
// structure (decision L1): `fb.TimePosition = &cam;` or `= &points;`. It must outlive the job.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/motion/time_position_source.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_PositionProfile {
  techobjects::TimePositionSource TimePosition{};
  bool Execute = false;
  std::int32_t BufferMode = 0;
  double StartTime = 0.0;
  std::int32_t ProfileReference = 0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
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
          return axis.position_profile(
              techobjects::PositionProfileInputs{TimePosition, StartTime, ProfileReference, Velocity,
                                                 Acceleration, Deceleration, Jerk, BufferMode});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
    Active = handshake_.outputs().Active;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
