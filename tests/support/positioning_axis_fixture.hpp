#pragma once
// A positioning axis on the simulated PROFIdrive drive with a user program calling MC_* instances, as a PLC
// runs it: one Runtime::step() = MC_Servo, MC_Interpolator, user program. The simulated machine's limit
// switches are copied into the axis' digital inputs in the MC_PreServo hook (a PLC's servo process image).
#include <functional>
#include <memory>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_halt_superimposed.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_move_jog.hpp"
#include "tomc/instructions/mc_move_relative.hpp"
#include "tomc/instructions/mc_move_superimposed.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/instructions/mc_stop.hpp"
#include "tomc/instructions/mc_write_parameter.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::testing {

using techobjects::PositioningAxis;

// The default linear axis of positioning_axis_data.hpp (mm, 10 mm/rev leadscrew, 2048-step motor encoder)
// with trapezoid profiles (no jerk limit) unless a test asks otherwise.
inline techobjects::PositioningAxisData linear_axis_data() {
  techobjects::PositioningAxisData d;
  d.DynamicLimits.MaxJerk = 0.0;
  return d;
}

// The simulated drive matching linear_axis_data(): load units are mm, one load revolution = 10 mm.
inline drives::SimulatedDriveParameters linear_drive() {
  drives::SimulatedDriveParameters p;
  p.load_units_per_revolution = 10.0;
  return p;
}

struct PositioningAxisMachine {
  explicit PositioningAxisMachine(techobjects::PositioningAxisData data = linear_axis_data(),
                                  drives::SimulatedDriveParameters drive_parameters = linear_drive(),
                                  std::uint16_t telegram = 3, bool with_drive = true)
      : runtime(techobjects::RuntimeConfig{drive_parameters.servo_cycle_s, 1, 1}) {
    techobjects::DeviceIo* io = nullptr;
    if (with_drive) {
      drives::DeviceConfig device;
      device.drive_telegram = telegram;
      auto owned = std::make_unique<drives::SimulatedDrive>(device, drive_parameters);
      drive = owned.get();
      io = &runtime.add_device(std::move(owned));
    }
    axis = &runtime.emplace<PositioningAxis>("Axis1", io, data);
    runtime.set_pre_servo([this](techobjects::Runtime&) {
      if (drive == nullptr) return;
      const auto in = drive->machine_inputs();
      // The wired level: a switch shows its configured active level while actuated (low-active by default,
      // PositionLimits_HW.*SwitchLevel = FALSE: a normally closed contact reads FALSE on the switch).
      const auto& hw = axis->data().PositionLimits_HW;
      axis->digital_inputs().MinSwitch = in.negative_limit_switch == hw.MinSwitchLevel;
      axis->digital_inputs().MaxSwitch = in.positive_limit_switch == hw.MaxSwitchLevel;
      axis->digital_inputs().HomingInput = in.reference_cam;
    });
    runtime.set_user_program([this](techobjects::Runtime&) {
      power(*axis);
      reset(*axis);
      home(*axis);
      move_absolute(*axis);
      move_absolute2(*axis);
      move_relative(*axis);
      move_relative2(*axis);
      move_velocity(*axis);
      halt(*axis);
      stop(*axis);
      jog(*axis);
      write_parameter(*axis);
      move_superimposed(*axis);
      halt_superimposed(*axis);
      if (user) user();
    });
    runtime.start();
  }
  void run(int cycles) {
    for (int i = 0; i < cycles; ++i)
      runtime.step();
  }
  template <typename Predicate>
  int run_until(Predicate done, int limit) {
    for (int i = 1; i <= limit; ++i) {
      runtime.step();
      if (done()) return i;
    }
    return -1;
  }
  int enable() {
    power.Enable = true;
    return run_until([&] { return power.Status; }, 200);
  }
  // MC_Home Mode 0 (direct homing, absolute) at `position`; returns when Done.
  bool home_at(double position) {
    home.Mode = 0;
    home.Position = position;
    home.Execute = true;
    run(1);
    const bool done = home.Done;
    home.Execute = false;
    run(1);
    return done;
  }
  const techobjects::PositioningAxisData& db() const { return axis->data(); }

  techobjects::Runtime runtime;
  drives::SimulatedDrive* drive = nullptr;
  PositioningAxis* axis = nullptr;
  instructions::MC_Power<PositioningAxis> power;
  instructions::MC_Reset<PositioningAxis> reset;
  instructions::MC_Home<PositioningAxis> home;
  instructions::MC_MoveAbsolute<PositioningAxis> move_absolute;
  instructions::MC_MoveAbsolute<PositioningAxis> move_absolute2;
  instructions::MC_MoveRelative<PositioningAxis> move_relative;
  instructions::MC_MoveRelative<PositioningAxis> move_relative2;
  instructions::MC_MoveVelocity<PositioningAxis> move_velocity;
  instructions::MC_Halt<PositioningAxis> halt;
  instructions::MC_Stop<PositioningAxis> stop;
  instructions::MC_MoveJog<PositioningAxis> jog;
  instructions::MC_WriteParameter<PositioningAxis> write_parameter;
  instructions::MC_MoveSuperimposed<PositioningAxis> move_superimposed;
  instructions::MC_HaltSuperimposed<PositioningAxis> halt_superimposed;
  std::function<void()> user;
};

}  // namespace tomc::testing
