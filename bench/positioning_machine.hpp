#pragma once
// The machine the positioning-axis benchmarks measure (issue 5): N TO_PositioningAxis with the default data
// block of positioning_axis_data.hpp (mm, 10 mm leadscrew, jerk-limited: MaxJerk 1e5 mm/s³), each either on
// its own simulated PROFIdrive drive (telegram 3, the codec running as in the runtime) or virtual (no drive).
// A user program of MC_Power, MC_Home and two MC_MoveAbsolute per axis runs every cycle.
//
// Workloads:
//   steady  — one long positioning move per axis, measured while it cruises (the profile is sampled, nothing
//             is planned);
//   replan  — a new MC_MoveAbsolute (BufferMode 0) every `period` cycles per axis, each to a target 100 mm
//             ahead of the setpoint: PositionProfile::plan from a moving state, in the user program's
//             instruction call.
//
// The axes are registered through one TechnologyObject (AxisGroup) whose servo()/interpolate() run every
// axis' MC_Servo/MC_Interpolator: benchmarks time just these (the TO with its telegram codec, without the
// drive model), callgrind counts them through the extern "C" functions the workloads name.
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "axis_group.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::bench {

using techobjects::PositioningAxis;

using AxisGroup = AxisGroupOf<PositioningAxis>;

struct AxisProgram {
  instructions::MC_Power<PositioningAxis> power;
  instructions::MC_Home<PositioningAxis> home;
  instructions::MC_MoveAbsolute<PositioningAxis> move[2];
};

class PositioningMachine {
 public:
  // period 0: steady motion; n > 0: a new MC_MoveAbsolute every n cycles.
  PositioningMachine(int axes, bool with_drive, int period)
      : runtime_(techobjects::RuntimeConfig{0.001, 1, 1}), period_(period) {
    auto group = std::make_unique<AxisGroup>("AxisGroup");
    group_ = group.get();
    const techobjects::PositioningAxisData data;  // the default data block
    for (int i = 0; i < axes; ++i) {
      techobjects::DeviceIo* io = nullptr;
      if (with_drive) {
        drives::DeviceConfig device;
        device.drive_telegram = 3;
        drives::SimulatedDriveParameters p;
        p.load_units_per_revolution = 10.0;  // the 10 mm leadscrew of the data block
        io = &runtime_.add_device(std::make_unique<drives::SimulatedDrive>(device, p));
      }
      auto d = data;
      if (!with_drive) d.VirtualAxis.Mode = techobjects::kModeOn;
      group_->axes.push_back(std::make_unique<PositioningAxis>("Axis" + std::to_string(i + 1), io, d));
    }
    runtime_.add_technology_object(std::move(group));
    programs_.resize(static_cast<std::size_t>(axes));
    runtime_.set_user_program([this](techobjects::Runtime&) { user_program(); });
    runtime_.start();
    for (auto& p : programs_) {
      p.power.Enable = true;
      p.home.Mode = 0;
      p.home.Position = 0.0;
      p.move[0].Velocity = 200.0;
      p.move[1].Velocity = 200.0;
    }
    for (int k = 0; k < 300; ++k)  // enabled, homed, and (steady) the long move at its cruise velocity
      runtime_.step();
    for (std::size_t i = 0; i < programs_.size(); ++i) {
      if (!programs_[i].power.Status || !(std::fabs(group_->axes[i]->setpoint().velocity) > 0.0)) {
        throw std::runtime_error("positioning machine: axis not enabled and moving after set-up");
      }
    }
  }

  void step() noexcept { runtime_.step(); }
  AxisGroup& group() noexcept { return *group_; }
  techobjects::Runtime& runtime() noexcept { return runtime_; }
  const std::vector<AxisProgram>& programs() const noexcept { return programs_; }
  // The user program, exposed so that a callgrind workload can run it inside its counted function.
  void set_user_program_hook(void (*hook)(PositioningMachine&)) noexcept { hook_ = hook; }
  void user_program() noexcept {
    if (hook_ != nullptr) {
      hook_(*this);
    } else {
      run_user_program();
    }
  }
  void run_user_program() noexcept {
    const auto cycle = runtime_.clock().servo_cycles;
    for (std::size_t i = 0; i < programs_.size(); ++i) {
      auto& p = programs_[i];
      auto& axis = *group_->axes[i];
      p.power(axis);
      p.home.Execute = p.power.Status && cycle < 20;
      p.home(axis);
      if (period_ == 0 || cycle < 150) {
        // One long move (steady: until the end of the run; replan: at cruise before the replanning starts).
        p.move[0].Position = 1.0e9;
        p.move[0].Execute = (axis.data().StatusWord & 0x20u) != 0;  // homed (StatusWord.X5)
        p.move[0](axis);
        continue;
      }
      // Replanning: every `period` cycles a rising edge on the instance whose turn it is.
      const auto n = static_cast<std::uint64_t>(period_);
      const std::size_t which = (cycle / n) % 2;
      auto& next = p.move[which];
      auto& other = p.move[1 - which];
      if (cycle % n == 0) {
        next.Position = axis.setpoint().position + 100.0 + static_cast<double>(cycle % 7);
        next.Execute = true;
        other.Execute = false;
      }
      p.move[0](axis);
      p.move[1](axis);
    }
  }

 private:
  techobjects::Runtime runtime_;
  AxisGroup* group_ = nullptr;
  std::vector<AxisProgram> programs_;
  int period_ = 0;
  void (*hook_)(PositioningMachine&) = nullptr;
};

}  // namespace tomc::bench
