// Embedding tomc in a program of your own: one speed axis on the simulated PROFIdrive drive, a user program
// with MC_Power and MC_MoveVelocity, run in real time by RealTimeRunner (1 ms cycle) for the given seconds.
//   build/bin/embed_speed_axis [seconds]
// Replace the SimulatedDrive by another DriveAdapter (e.g. the gateway adapter) and nothing else changes.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

using namespace tomc;

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 2.0;

  // Set-up (may allocate): the drive, the technology object with its start values, the user program.
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig device;
  device.drive_telegram = 2;  // PROFIdrive standard telegram 2: STW1/STW2, NSOLL_B, ZSW1/ZSW2, NIST_B
  auto& io = runtime.add_device(
      std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
  techobjects::SpeedAxisData
      start_values;  // the data block's start values, as TIA Portal would download them
  start_values.DynamicDefaults.Acceleration = 20.0;  // 1/s²
  auto& axis = runtime.emplace<techobjects::SpeedAxis>("Conveyor", &io, start_values);

  instructions::MC_Power<techobjects::SpeedAxis> power;
  instructions::MC_MoveVelocity<techobjects::SpeedAxis> move;
  power.Enable = true;
  move.Velocity = 600.0;  // 1/min
  runtime.set_user_program([&](techobjects::Runtime&) {
    power(axis);
    move.Execute = power.Status;
    move(axis);
  });
  runtime.start();  // from here on the cycle allocates nothing

  techobjects::RealTimeRunner runner(
      techobjects::RealTimeRunnerConfig{std::chrono::milliseconds(1), 0, false}, [&] { runtime.step(); });
  runner.start();
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  runner.stop();

  const auto stats = runner.statistics();
  const auto& db = axis.data();
  std::printf("cycles %llu, overruns %llu, wake-up jitter median %.0f us, p99 %.0f us, max %.0f us\n",
              static_cast<unsigned long long>(stats.cycles), static_cast<unsigned long long>(stats.overruns),
              stats.jitter_median_us, stats.jitter_p99_us, stats.jitter_max_us);
  std::printf(
      "Conveyor: enabled %d, InVelocity %d, Velocity %.1f 1/min, ActualSpeed %.1f 1/min, ErrorDetail %u\n",
      power.Status ? 1 : 0, move.InVelocity ? 1 : 0, db.Velocity, db.ActualSpeed, db.ErrorDetail.Number);
  return power.Status && move.InVelocity ? 0 : 1;
}
