// Fixed workload for callgrind: one application cycle of a TO_SpeedAxis on its simulated PROFIdrive drive
// (telegram 105) in steady motion under MC_MoveVelocity, user program included.
#include <cstdio>
#include <memory>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

using namespace tomc;

constexpr int kCycles = 20000;

extern "C" __attribute__((noinline)) void speed_axis_cycle(techobjects::Runtime& rt) {
  rt.step();
}

int main() {
  techobjects::Runtime rt(techobjects::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig device;
  device.drive_telegram = 105;
  auto& io =
      rt.add_device(std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
  auto& axis = rt.emplace<techobjects::SpeedAxis>("Axis1", &io, techobjects::SpeedAxisData{});
  instructions::MC_Power<techobjects::SpeedAxis> power;
  instructions::MC_MoveVelocity<techobjects::SpeedAxis> move;
  power.Enable = true;
  move.Velocity = 1500.0;
  rt.set_user_program([&](techobjects::Runtime&) {
    power(axis);
    move.Execute = power.Status;
    move(axis);
  });
  rt.start();
  for (int i = 0; i < 2000; ++i)
    rt.step();  // enabled and at speed: steady motion from here
  for (int i = 0; i < kCycles; ++i)
    speed_axis_cycle(rt);
  std::printf("cycles=%d units=1 invelocity=%d\n", kCycles, move.InVelocity ? 1 : 0);
  return 0;
}
