// Embedding tomc in a C++ program: one positioning axis (10 mm leadscrew) on the simulated PROFIdrive drive
// with telegram 3, a user program with MC_Power, MC_Home (set position 0) and MC_MoveAbsolute to 100 mm, run
// in real time by RealTimeRunner (1 ms cycle). Exits 0 once the move is Done at 100 mm.
//   build/bin/embed_positioning_axis
// Against an installed tomc: find_package(tomc CONFIG REQUIRED COMPONENTS core), link tomc::core
// (docs/embedding.md).
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <thread>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

using namespace tomc;

int main() {
  // Set-up (may allocate): the drive, the TO with its data block's start values, the user program.
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig device;
  device.drive_telegram = 3;  // STW1/STW2, NSOLL_B, G1_STW, ZSW1/ZSW2, NIST_B, G1_ZSW, G1_XIST1/2
  drives::SimulatedDriveParameters drive;
  drive.load_units_per_revolution = 10.0;  // the axis' default mechanics: 10 mm per revolution
  auto& io = runtime.add_device(std::make_unique<drives::SimulatedDrive>(device, drive));
  techobjects::PositioningAxisData start_values;
  start_values.DynamicLimits.MaxJerk = 0.0;  // trapezoid profiles
  auto& axis = runtime.emplace<techobjects::PositioningAxis>("Slide", &io, start_values);

  instructions::MC_Power<techobjects::PositioningAxis> power;
  instructions::MC_Home<techobjects::PositioningAxis> home;
  instructions::MC_MoveAbsolute<techobjects::PositioningAxis> move;
  power.Enable = true;
  home.Mode = 0;  // set the actual position to home.Position (0 mm)
  move.Position = 100.0;
  std::atomic<bool> finished{false};
  runtime.set_user_program([&](techobjects::Runtime&) {
    power(axis);
    home.Execute = power.Status;
    home(axis);
    move.Execute = home.Done;
    move(axis);
    if (move.Done || move.Error) finished.store(true, std::memory_order_release);
  });
  runtime.start();  // from here on the cycle allocates nothing

  techobjects::RealTimeRunner runner(
      techobjects::RealTimeRunnerConfig{std::chrono::milliseconds(1), 0, false}, [&] { runtime.step(); });
  runner.start();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!finished.load(std::memory_order_acquire) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  runner.stop();  // the cycle's data may be read in this thread from here on

  const auto stats = runner.statistics();
  const auto& db = axis.data();
  std::printf("cycles %llu, overruns %llu, wake-up jitter median %.0f us, p99 %.0f us, max %.0f us\n",
              static_cast<unsigned long long>(stats.cycles), static_cast<unsigned long long>(stats.overruns),
              stats.jitter_median_us, stats.jitter_p99_us, stats.jitter_max_us);
  std::printf("Slide: Done %d, Error %d (16#%04X), Position %.3f mm, ActualPosition %.3f mm\n",
              move.Done ? 1 : 0, move.Error ? 1 : 0, move.ErrorID, db.Position, db.ActualPosition);
  return move.Done && std::abs(db.Position - 100.0) < 1e-6 ? 0 : 1;
}
