// Cost of one application cycle per simulated drive (issue 3): the runtime with N simulated PROFIdrive
// drives, each driven by a small speed-commanding technology object through a DriveConnection; and the
// simulated drive alone (setpoint in, one model cycle, actual frames out); the analog actor on its simulated
// amplifier and the PID regulator (issue 20).
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "../tests/support/speed_command_object.hpp"
#include "tomc/drives/simulated_actor_drive.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/position/pid_regulator.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace {

using namespace tomc;

void BM_ApplicationCycle(benchmark::State& state) {
  const auto drives = static_cast<int>(state.range(0));
  techobjects::Runtime rt(techobjects::RuntimeConfig{0.001, 1, 1});
  for (int i = 0; i < drives; ++i) {
    drives::DeviceConfig device;
    device.drive_telegram = 105;
    auto& io =
        rt.add_device(std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
    rt.emplace<testing::SpeedCommandObject>(io, techobjects::DriveConnectionConfig{}, 1000.0, 0.5);
  }
  rt.start();
  for (int i = 0; i < 20; ++i)
    rt.step();  // enabled and moving
  for (auto _ : state)
    rt.step();
  state.SetItemsProcessed(state.iterations() * drives);
  state.counters["ns_per_drive"] =
      benchmark::Counter(static_cast<double>(state.iterations() * drives),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// One drive cycle as the TO's drive connection sees it: setpoint frame in, one cycle of the drive, actual
// frames out (STW1 0x047E/0x047F to S4 first, then a constant speed setpoint).
template <class Drive>
void run_drive_cycle(benchmark::State& state, Drive& drive) {
  const drives::DeviceConfig device = drive.config();
  auto setpoint = drives::make_frames(device, telegrams::Direction::kSetpoint);
  auto actual = drives::make_frames(device, telegrams::Direction::kActual);
  const auto codec =
      telegrams::TelegramCodec::create(device.drive_telegram, telegrams::Direction::kSetpoint).value();
  telegrams::SetpointSignals sp;
  sp.STW1 = telegrams::Stw1{0x047E};
  for (int i = 0; i < 4; ++i) {  // S0 -> S4
    if (i == 2) sp.STW1 = telegrams::Stw1{0x047F};
    (void)codec.encode(sp, setpoint[drives::Slot::kDrive].view());
    drive.write_setpoint(setpoint);
    drive.read_actual(actual);
  }
  sp.NSOLL_B = 0x10000000;
  sp.NSOLL_A = 0x1000;
  std::uint8_t life = 1;
  for (auto _ : state) {
    sp.STW2.set_field(telegrams::kSignOfLifeField, life);
    life = static_cast<std::uint8_t>(life == 15 ? 1 : life + 1);
    (void)codec.encode(sp, setpoint[drives::Slot::kDrive].view());
    drive.write_setpoint(setpoint);
    benchmark::DoNotOptimize(drive.read_actual(actual));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_SimulatedDriveCycle(benchmark::State& state) {
  drives::DeviceConfig device;
  device.drive_telegram = static_cast<std::uint16_t>(state.range(0));
  drives::SimulatedDrive drive(device, drives::SimulatedDriveParameters{});
  run_drive_cycle(state, drive);
}

// The analog actor on its simulated servo amplifier (issue 20), with enable output and ready input.
void BM_AnalogDriveCycle(benchmark::State& state) {
  drives::io::SimulatedServoAmplifierParameters amplifier;
  drives::AnalogDriveParameters actor;
  actor.enable_output = amplifier.enable_input;
  actor.ready_input = amplifier.ready_output;
  actor.counts_per_revolution = 4.0 * amplifier.encoder.lines_per_revolution;
  drives::SimulatedAnalogDrive drive(amplifier, actor);
  run_drive_cycle(state, drive);
}

// The stepper actor on its simulated PTO and stepper motor (issue 20), encoder feedback, enable and ready;
// the motor pulls in at the 20 kHz of the run_drive_cycle setpoint (750 1/min), so it runs in step.
void BM_StepperDriveCycle(benchmark::State& state) {
  drives::io::SimulatedStepperMotorParameters motor;
  motor.feedback = drives::io::SimulatedStepperMotorParameters::Feedback::kEncoder;
  motor.pull_in_rate_hz = 25000.0;
  drives::StepperDriveParameters actor;
  actor.enable_output = motor.enable_input;
  actor.ready_input = motor.ready_output;
  actor.counts_per_revolution = 4.0 * motor.encoder.lines_per_revolution;
  drives::SimulatedStepperDrive drive(motor, actor);
  run_drive_cycle(state, drive);
}

// The PID option of the position controller (issue 20): one update with P, I (clamped) and D.
void BM_PidRegulatorUpdate(benchmark::State& state) {
  techobjects::PidGains gains;
  gains.IntegralTime = 0.1;
  gains.DerivativeTime = 0.002;
  gains.DerivativeCycles = 4;
  gains.IntegralLimit = 50.0;
  gains.OutputLimit = 500.0;
  techobjects::PidRegulator pid;
  (void)pid.configure(gains, 0.001);
  double e = 0.0;
  for (auto _ : state) {
    e = e > 1.0 ? -1.0 : e + 0.001;
    benchmark::DoNotOptimize(pid.update(e));
  }
  state.SetItemsProcessed(state.iterations());
}

// Speed axes (TO_SpeedAxis + MC_Power + MC_MoveVelocity in the user program) on simulated drives, steady
// motion.
void BM_SpeedAxisCycle(benchmark::State& state) {
  const auto axes = static_cast<int>(state.range(0));
  techobjects::Runtime rt(techobjects::RuntimeConfig{0.001, 1, 1});
  struct Program {
    techobjects::SpeedAxis* axis;
    instructions::MC_Power<techobjects::SpeedAxis> power;
    instructions::MC_MoveVelocity<techobjects::SpeedAxis> move;
  };
  std::vector<Program> programs(static_cast<std::size_t>(axes));
  for (auto& p : programs) {
    drives::DeviceConfig device;
    device.drive_telegram = 105;
    auto& io =
        rt.add_device(std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
    p.axis = &rt.emplace<techobjects::SpeedAxis>("Axis", &io, techobjects::SpeedAxisData{});
    p.power.Enable = true;
    p.move.Velocity = 1500.0;
  }
  rt.set_user_program([&](techobjects::Runtime&) {
    for (auto& p : programs) {
      p.power(*p.axis);
      p.move.Execute = p.power.Status;
      p.move(*p.axis);
    }
  });
  rt.start();
  for (int i = 0; i < 2000; ++i)
    rt.step();
  for (auto _ : state)
    rt.step();
  state.counters["ns_per_axis"] =
      benchmark::Counter(static_cast<double>(state.iterations() * axes),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_SpeedAxisCycle)->Arg(1)->Arg(16)->Arg(256);
BENCHMARK(BM_ApplicationCycle)->Arg(1)->Arg(16)->Arg(256)->Arg(4096);
BENCHMARK(BM_SimulatedDriveCycle)->Arg(1)->Arg(3)->Arg(105)->Arg(106);
BENCHMARK(BM_AnalogDriveCycle);
BENCHMARK(BM_StepperDriveCycle);
BENCHMARK(BM_PidRegulatorUpdate);
