#pragma once
// The machine the gearing and camming benchmarks measure (issues 9, 19): one leader, a TO_PositioningAxis on
// its simulated PROFIdrive drive (telegram 3) running MC_MoveVelocity at 100 mm/s, and N TO_SynchronousAxis
// followers, each on its own simulated drive (telegram 3, the codec running as in the runtime), either geared
// 1:1 with MC_GearIn or cammed with MC_CamIn (one shared TO_Cam: a cubic spline through 37 points of
// 10·sin(2π·x/360) mm, equal end slopes; direct synchronous setting, cyclic), setpoint coupling, measured in
// steady synchronous travel (InGear/InSync: the gear line or the cam is evaluated every cycle, nothing is
// planned). Data blocks: the default (mm, 10 mm leadscrew, MaxJerk 1e5 mm/s³). A user program of MC_Power and
// MC_GearIn/MC_CamIn per follower (MC_Power and MC_MoveVelocity for the leader) runs every cycle.
//
// The followers are registered through one TechnologyObject (FollowerGroup) whose servo()/interpolate() run
// every follower's MC_Servo/MC_Interpolator and which names the leader as its leading value, so that the
// runtime evaluates the leader first (spec 07 §6.1): benchmarks time just the followers (TO with telegram
// codec, without the drive models), callgrind counts them through the extern "C" function the workload names.
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "axis_group.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_cam_in.hpp"
#include "tomc/instructions/mc_gear_in.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::bench {

using techobjects::PositioningAxis;
using techobjects::SynchronousAxis;

using FollowerGroup = AxisGroupOf<SynchronousAxis>;  // names the leader (spec 07 §6.1)

struct FollowerProgram {
  instructions::MC_Power<SynchronousAxis> power;
  instructions::MC_GearIn<SynchronousAxis> gear;
  instructions::MC_CamIn<SynchronousAxis> cam;
  instructions::MC_Home<SynchronousAxis> home;  // camming needs a homed follower (spec 07 §3.4)
  bool synchronous() const noexcept { return gear.InGear || cam.InSync; }
};

// The synchronous function every follower runs.
enum class Function { kGearing, kCamming };

class GearingMachine {
 public:
  explicit GearingMachine(int followers, Function function = Function::kGearing)
      : runtime_(techobjects::RuntimeConfig{0.001, 1, 1}), function_(function) {
    const techobjects::PositioningAxisData data;  // the default data block
    auto drive = [&]() -> techobjects::DeviceIo& {
      drives::DeviceConfig device;
      device.drive_telegram = 3;
      drives::SimulatedDriveParameters p;
      p.load_units_per_revolution = 10.0;  // the 10 mm leadscrew of the data block
      return runtime_.add_device(std::make_unique<drives::SimulatedDrive>(device, p));
    };
    leader_ = &runtime_.emplace<PositioningAxis>("Leader", &drive(), data);
    auto group = std::make_unique<FollowerGroup>("FollowerGroup", leader_);
    group_ = group.get();
    for (int i = 0; i < followers; ++i) {
      group_->axes.push_back(std::make_unique<SynchronousAxis>(
          "Follower", &drive(), data,
          std::vector<techobjects::LeadingValueInterconnection>{
              {leader_, leader_, techobjects::LeadingValueCoupling::kSetpoint}}));
    }
    runtime_.add_technology_object(std::move(group));
    cam_ = &runtime_.emplace<techobjects::Cam>("Cam");
    for (int i = 0; i <= 36; ++i) {
      const double x = 10.0 * i;
      (void)cam_->write_point(static_cast<std::size_t>(i + 1), {x, 10.0 * std::sin(2.0 * M_PI * x / 360.0)},
                              true);
    }
    (void)cam_->write("InterpolationSettings.InterpolationMode", 1.0);
    (void)cam_->write("InterpolationSettings.BoundaryConditions", 1.0);
    programs_.resize(static_cast<std::size_t>(followers));
    runtime_.set_user_program([this](techobjects::Runtime&) { user_program(); });
    runtime_.start();
    if (!cam_->interpolate_cam().accepted()) throw std::runtime_error("gearing machine: the cam");
    power_.Enable = true;
    move_.Velocity = 100.0;
    for (auto& p : programs_) {
      p.power.Enable = true;
      p.gear.Master = leader_;
      p.cam.Master = leader_;
      p.cam.Cam = cam_;
      p.cam.SyncProfileReference = 2;
      p.cam.ApplicationMode = 1;
    }
    // Enabled, the leader at its velocity, every follower InGear / InSync (on the moving leader).
    for (int k = 0; k < 1000; ++k)
      runtime_.step();
    for (std::size_t i = 0; i < programs_.size(); ++i) {
      const auto& f = *group_->axes[i];
      const double slope =
          function_ == Function::kGearing
              ? 1.0
              : f.synchronized_motion().FunctionFollowingValue.Velocity / leader_->setpoint().velocity;
      if (!programs_[i].synchronous() ||
          std::fabs(f.setpoint().velocity - slope * leader_->setpoint().velocity) > 1e-9 ||
          (function_ == Function::kCamming && f.synchronized_motion().FunctionState != 3)) {
        throw std::runtime_error("gearing machine: a follower is not in synchronous travel after set-up");
      }
    }
  }

  void step() noexcept { runtime_.step(); }
  FollowerGroup& group() noexcept { return *group_; }
  const PositioningAxis& leader() const noexcept { return *leader_; }
  const std::vector<FollowerProgram>& programs() const noexcept { return programs_; }

 private:
  void user_program() noexcept {
    power_(*leader_);
    move_.Execute = power_.Status;
    move_(*leader_);
    for (std::size_t i = 0; i < programs_.size(); ++i) {
      auto& p = programs_[i];
      auto& f = *group_->axes[i];
      p.power(f);
      const bool start = p.power.Status && move_.InVelocity;
      if (function_ == Function::kGearing) {
        p.gear.Execute = start;
        p.gear(f);
      } else {
        p.home.Mode = 0;  // direct homing: the position stays, the axis is homed
        p.home.Execute = p.power.Status;
        p.home(f);
        p.cam.Execute = start && p.home.Done;
        p.cam(f);
      }
    }
  }

  techobjects::Runtime runtime_;
  Function function_;
  techobjects::Cam* cam_ = nullptr;
  PositioningAxis* leader_ = nullptr;
  FollowerGroup* group_ = nullptr;
  instructions::MC_Power<PositioningAxis> power_;
  instructions::MC_MoveVelocity<PositioningAxis> move_;
  std::vector<FollowerProgram> programs_;
};

}  // namespace tomc::bench
