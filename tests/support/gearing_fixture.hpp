#pragma once
// The common set-up of spec 07 §8: cycle 1 ms; leader L a virtual TO_PositioningAxis (linear, mm), follower F
// a virtual TO_SynchronousAxis homed at 0 with L as its possible leading value (setpoint coupling). F's
// limits: MaxVelocity 1000, MaxAcceleration/Deceleration 10000; its defaults: Velocity 500,
// Acceleration/Deceleration 5000, Jerk 0. Unlike §8, MaxJerk is 0 (no jerk limit) so that the synchronization
// ramps are the trapezoids the scenarios compute (decision S3: MaxJerk > 0 would cap jerk-0 jobs).
#include <functional>
#include <memory>

#include "tomc/instructions/mc_cam_in.hpp"
#include "tomc/instructions/mc_cam_out.hpp"
#include "tomc/instructions/mc_gear_in.hpp"
#include "tomc/instructions/mc_gear_in_pos.hpp"
#include "tomc/instructions/mc_gear_in_velocity.hpp"
#include "tomc/instructions/mc_gear_out.hpp"
#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_move_relative.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_stop.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::testing {

using techobjects::PositioningAxis;
using techobjects::SynchronousAxis;

inline techobjects::PositioningAxisData virtual_linear() {
  techobjects::PositioningAxisData d;
  d.VirtualAxis.Mode = techobjects::kModeOn;
  d.DynamicLimits.MaxVelocity = 1000.0;
  d.DynamicLimits.Velocity = 1000.0;
  d.DynamicLimits.MaxAcceleration = 10000.0;
  d.DynamicLimits.MaxDeceleration = 10000.0;
  d.DynamicLimits.MaxJerk = 0.0;
  d.DynamicDefaults.Velocity = 500.0;
  d.DynamicDefaults.Acceleration = 5000.0;
  d.DynamicDefaults.Deceleration = 5000.0;
  d.DynamicDefaults.Jerk = 0.0;
  d.DynamicDefaults.EmergencyDeceleration = 20000.0;
  return d;
}

inline techobjects::PositioningAxisData virtual_rotary_modulo() {
  auto d = virtual_linear();
  d.Properties.MotionType = static_cast<std::int32_t>(techobjects::PropertiesMotionType::kRotary);
  d.Units.LengthUnit = techobjects::unit_code::kDegree;
  d.Units.VelocityUnit = techobjects::unit_code::kDegreePerSecond;
  d.Modulo.Enable = true;
  d.Modulo.Length = 360.0;
  return d;
}

struct GearingMachine {
  // `add` adds further TOs (cams) before the runtime starts; `follower_device` gives F a drive (a real,
  // non-virtual follower), nullptr by default; `reversal_tolerance` is both interconnections' leading value
  // reversal tolerance (decision C27).
  explicit GearingMachine(
      techobjects::PositioningAxisData leader = virtual_linear(),
      techobjects::PositioningAxisData follower = virtual_linear(),
      const std::function<void(techobjects::Runtime&)>& add = {},
      const std::function<techobjects::DeviceIo*(techobjects::Runtime&)>& follower_device = {},
      float reversal_tolerance = 0.0F)
      : runtime(techobjects::RuntimeConfig{0.001, 1, 1}) {
    // The follower is added first: the runtime still runs the leader first (leaders()).
    L = std::make_unique<PositioningAxis>("L", nullptr, leader);
    L2 = std::make_unique<PositioningAxis>("L2", nullptr, leader);
    F = &runtime.emplace<SynchronousAxis>(
        "F", follower_device ? follower_device(runtime) : nullptr, follower,
        std::vector<techobjects::LeadingValueInterconnection>{
            {L.get(), L.get(), techobjects::LeadingValueCoupling::kSetpoint, reversal_tolerance},
            {L2.get(), L2.get(), techobjects::LeadingValueCoupling::kSetpoint, reversal_tolerance}});
    leader_axis = L.get();
    leader2_axis = L2.get();
    runtime.add_technology_object(std::move(L));
    runtime.add_technology_object(std::move(L2));
    gear.Master = leader_axis;
    gear2.Master = leader2_axis;
    gear_pos.Master = leader_axis;
    gear_velocity.Master = leader_axis;
    cam_in.Master = cam_in2.Master = leader_axis;
    if (add) add(runtime);
    runtime.set_user_program([this](techobjects::Runtime&) {
      power_L(*leader_axis);
      power_L2(*leader2_axis);
      move_L(*leader_axis);
      move_rel_L(*leader_axis);
      power_F(*F);
      home_F(*F);
      gear(*F);
      gear2(*F);
      gear_pos(*F);
      gear_velocity(*F);
      gear_out(*F);
      cam_out(*F);
      cam_in(*F);
      cam_in2(*F);
      move_F(*F);
      move_abs_F(*F);
      halt_F(*F);
      stop_F(*F);
      if (user) user();
    });
    runtime.start();
    power_L.Enable = power_L2.Enable = power_F.Enable = true;
    run(3);
    home_F.Mode = 0;
    home_F.Execute = true;
    run(1);
    home_F.Execute = false;
    run(1);
  }
  void run(int cycles) {
    for (int i = 0; i < cycles; ++i)
      runtime.step();
  }
  template <typename P>
  int run_until(P done, int limit) {
    for (int i = 1; i <= limit; ++i) {
      runtime.step();
      if (done()) return i;
    }
    return -1;
  }
  const techobjects::PositioningAxisData& f() const { return F->data(); }
  const techobjects::PositioningAxisData& l() const { return leader_axis->data(); }

  techobjects::Runtime runtime;
  std::unique_ptr<PositioningAxis> L;
  std::unique_ptr<PositioningAxis> L2;
  PositioningAxis* leader_axis = nullptr;
  PositioningAxis* leader2_axis = nullptr;
  SynchronousAxis* F = nullptr;
  instructions::MC_Power<PositioningAxis> power_L;
  instructions::MC_Power<PositioningAxis> power_L2;
  instructions::MC_MoveVelocity<PositioningAxis> move_L;
  instructions::MC_MoveRelative<PositioningAxis> move_rel_L;
  instructions::MC_Power<SynchronousAxis> power_F;
  instructions::MC_Home<SynchronousAxis> home_F;
  instructions::MC_GearIn<SynchronousAxis> gear;
  instructions::MC_GearIn<SynchronousAxis> gear2;
  instructions::MC_GearInPos<SynchronousAxis> gear_pos;
  instructions::MC_GearInVelocity<SynchronousAxis> gear_velocity;
  instructions::MC_GearOut<SynchronousAxis> gear_out;
  instructions::MC_CamIn<SynchronousAxis> cam_in;
  instructions::MC_CamIn<SynchronousAxis> cam_in2;
  instructions::MC_CamOut<SynchronousAxis> cam_out;
  instructions::MC_MoveVelocity<SynchronousAxis> move_F;
  instructions::MC_MoveAbsolute<SynchronousAxis> move_abs_F;
  instructions::MC_Halt<SynchronousAxis> halt_F;
  instructions::MC_Stop<SynchronousAxis> stop_F;
  std::function<void()> user;
};

}  // namespace tomc::testing
