// Fixed workload for callgrind: one application cycle (Runtime::step) with 16 simulated drives, each driven
// by a speed-commanding TO through a DriveConnection. scripts/bench reports instructions per drive and cycle.
#include <cstdio>
#include <memory>

#include "../tests/support/speed_command_object.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

using namespace tomc;

constexpr int kCycles = 20000;
constexpr int kDrives = 16;

extern "C" __attribute__((noinline)) void runtime_cycle(techobjects::Runtime& rt) {
  rt.step();
}

int main() {
  techobjects::Runtime rt(techobjects::RuntimeConfig{0.001, 1, 1});
  for (int i = 0; i < kDrives; ++i) {
    drives::DeviceConfig device;
    device.drive_telegram = 105;
    auto& io =
        rt.add_device(std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
    rt.emplace<testing::SpeedCommandObject>(io, techobjects::DriveConnectionConfig{}, 1000.0, 0.5);
  }
  rt.start();
  for (int i = 0; i < kCycles; ++i)
    runtime_cycle(rt);
  std::printf("cycles=%d units=%d\n", kCycles, kDrives);
  return 0;
}
