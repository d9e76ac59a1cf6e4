#pragma once
// A speed axis on the simulated PROFIdrive drive with a user program calling MC_* instances, as a PLC runs
// it: one Runtime::step() = MC_Servo, MC_Interpolator, user program.
#include <functional>
#include <memory>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_move_jog.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/instructions/mc_set_axis_stw.hpp"
#include "tomc/instructions/mc_stop.hpp"
#include "tomc/instructions/mc_write_parameter.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::testing {

using techobjects::SpeedAxis;

struct SpeedAxisMachine {
  explicit SpeedAxisMachine(std::uint16_t telegram = 2, techobjects::SpeedAxisData data = {},
                            drives::SimulatedDriveParameters drive_parameters = {}, bool with_drive = true,
                            std::uint16_t supplementary = 0)
      : runtime(techobjects::RuntimeConfig{drive_parameters.servo_cycle_s, 1, 1}) {
    techobjects::DeviceIo* io = nullptr;
    if (with_drive) {
      drives::DeviceConfig device;
      device.drive_telegram = telegram;
      device.supplementary_telegram = supplementary;  // 0 or 750 (torque data)
      auto owned = std::make_unique<drives::SimulatedDrive>(device, drive_parameters);
      drive = owned.get();
      io = &runtime.add_device(std::move(owned));
    }
    axis = &runtime.emplace<SpeedAxis>("Axis1", io, data);
    runtime.set_user_program([this](techobjects::Runtime&) {
      power(*axis);
      reset(*axis);
      move(*axis);
      move2(*axis);
      halt(*axis);
      stop(*axis);
      jog(*axis);
      set_stw(*axis);
      write_parameter(*axis);
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
  // Enables the axis and returns the cycles it took.
  int enable() {
    power.Enable = true;
    return run_until([&] { return power.Status; }, 100);
  }

  techobjects::Runtime runtime;
  drives::SimulatedDrive* drive = nullptr;
  SpeedAxis* axis = nullptr;
  instructions::MC_Power<SpeedAxis> power;
  instructions::MC_Reset<SpeedAxis> reset;
  instructions::MC_MoveVelocity<SpeedAxis> move;
  instructions::MC_MoveVelocity<SpeedAxis> move2;
  instructions::MC_Halt<SpeedAxis> halt;
  instructions::MC_Stop<SpeedAxis> stop;
  instructions::MC_MoveJog<SpeedAxis> jog;
  instructions::MC_SetAxisSTW<SpeedAxis> set_stw;
  instructions::MC_WriteParameter<SpeedAxis> write_parameter;
  std::function<void()> user;
};

}  // namespace tomc::testing
