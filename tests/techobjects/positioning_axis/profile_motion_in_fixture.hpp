#pragma once
// The positioning-axis machine of positioning_axis_fixture.hpp whose user program also calls two
// MC_PositionProfile and the two MotionIn instances (after the fixture's own instances, in this order).
#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_motion_in.hpp"
#include "tomc/instructions/mc_position_profile.hpp"
#include "tomc/techobjects/motion/time_position_profile.hpp"

namespace tomc::testing {

// Ramp up in 0.1 s, cruise, ramp down: 40 mm in 0.5 s, peak near 118 mm/s.
inline techobjects::TimePositionProfile ramp_profile() {
  techobjects::TimePositionProfile p;
  p.NumberOfPoints = 4;
  p.Point[0] = {0.0, 0.0};
  p.Point[1] = {0.1, 5.0};
  p.Point[2] = {0.4, 35.0};
  p.Point[3] = {0.5, 40.0};
  return p;
}

struct ProfileMachine : PositioningAxisMachine {
  explicit ProfileMachine(techobjects::PositioningAxisData data = linear_axis_data(),
                          drives::SimulatedDriveParameters drive_parameters = linear_drive(),
                          bool with_drive = true, std::uint16_t telegram = 3)
      : PositioningAxisMachine(data, drive_parameters, telegram, with_drive) {
    user = [this] {
      profile(*axis);
      profile2(*axis);
      motion_in_velocity(*axis);
      motion_in_position(*axis);
    };
  }
  bool x9() const {
    return techobjects::test(db().StatusWord2, techobjects::StatusWord2Bit::kPositionProfileCommand);
  }
  bool x10() const { return techobjects::test(db().StatusWord2, techobjects::StatusWord2Bit::kOnProfile); }

  instructions::MC_PositionProfile<PositioningAxis> profile;
  instructions::MC_PositionProfile<PositioningAxis> profile2;
  instructions::MC_MotionInVelocity<PositioningAxis> motion_in_velocity;
  instructions::MC_MotionInPosition<PositioningAxis> motion_in_position;
};

}  // namespace tomc::testing
