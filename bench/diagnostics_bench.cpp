// What the web diagnostics cost the cycle (issue 7 target: page at 10 Hz plus a 32-channel trace <= 1 % of
// the cycle): Diagnostics::cycle() — the post-interpolator hook that runs the control panels, publishes
// snapshots and records the trace — on a machine of 4 speed axes with their simulated drives, and the whole
// application cycle with and without it. The reader's side (poll(): taking snapshots, draining the trace
// ring) runs outside the timed region, as it runs on the web server's thread.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "positioning_machine.hpp"
#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace {

using namespace tomc;

constexpr int kAxes = 4;

struct Machine {
  explicit Machine(std::uint32_t publish_period, bool with_diagnostics)
      : runtime(techobjects::RuntimeConfig{0.001, 1, 1}),
        diagnostics(diagnostics::DiagnosticsConfig{publish_period, 8192, 100}) {
    for (int i = 0; i < kAxes; ++i) {
      drives::DeviceConfig device;
      device.drive_telegram = 105;
      auto& io = runtime.add_device(
          std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
      axes.push_back(&runtime.emplace<techobjects::SpeedAxis>("Axis" + std::to_string(i + 1), &io,
                                                              techobjects::SpeedAxisData{}));
      diagnostics.add(*axes.back());
    }
    power.resize(kAxes);
    move.resize(kAxes);
    for (auto& m : move)
      m.Velocity = 1500.0;
    runtime.set_user_program([this](techobjects::Runtime&) {
      for (int i = 0; i < kAxes; ++i) {
        power[i].Enable = true;
        power[i](*axes[i]);
        move[i].Execute = power[i].Status;
        move[i](*axes[i]);
      }
    });
    if (with_diagnostics) diagnostics.attach(runtime);
    runtime.start();
    for (int i = 0; i < 2000; ++i)
      runtime.step();  // enabled and at speed
  }
  // 32 channels: 8 signals of each axis (values, words, bits, telegram words).
  void start_trace() {
    diagnostics::TraceRequest r;
    for (int a = 1; a <= kAxes; ++a) {
      for (const char* p : {"Velocity", "ActualSpeed", "VelocitySetpoint", "StatusWord", "StatusWord.X12",
                            "ErrorWord", "telegram.drive.NIST_B", "telegram.drive.ZSW1"})
        r.channels.push_back("Axis" + std::to_string(a) + "." + p);
    }
    r.post_samples = diagnostics::kMaxTraceSamples;
    if (!diagnostics.start_trace(r).empty()) std::abort();
    runtime.step();  // the cycle takes the setup
  }
  // The web server's side, between timed stretches: snapshots, trace rows, a new recording when one is full.
  void reader() {
    diagnostics.poll();
    const bool done = diagnostics.read([](const diagnostics::Diagnostics::State& s) {
      return s.trace.state == diagnostics::TraceCapture::State::kComplete;
    });
    if (done) start_trace();
  }

  techobjects::Runtime runtime;
  diagnostics::Diagnostics diagnostics;
  std::vector<techobjects::SpeedAxis*> axes;
  std::vector<instructions::MC_Power<techobjects::SpeedAxis>> power;
  std::vector<instructions::MC_MoveVelocity<techobjects::SpeedAxis>> move;
};

// Diagnostics::cycle() alone. range(0): publish period (cycles); range(1): 1 = a 32-channel trace records.
void BM_DiagnosticsCycle(benchmark::State& state) {
  Machine m(static_cast<std::uint32_t>(state.range(0)), true);
  if (state.range(1) != 0) m.start_trace();
  techobjects::CycleClock clock = m.runtime.clock();
  std::uint64_t n = 0;
  for (auto _ : state) {
    m.diagnostics.cycle(clock);
    ++clock.servo_cycles;
    if (++n % 20 == 0) {  // the server polls every 20 ms
      state.PauseTiming();
      m.reader();
      state.ResumeTiming();
    }
  }
  m.diagnostics.poll();
  const auto lost = m.diagnostics.read([](const diagnostics::Diagnostics::State& s) { return s.trace.lost; });
  state.counters["lost"] = static_cast<double>(lost);
}

// The whole application cycle of the 4 axes, without (0) and with (1) diagnostics publishing every 10 cycles
// and a 32-channel trace.
void BM_ApplicationCycle(benchmark::State& state) {
  const bool with = state.range(0) != 0;
  Machine m(10, with);
  if (with) m.start_trace();
  std::uint64_t n = 0;
  for (auto _ : state) {
    m.runtime.step();
    if (with && ++n % 20 == 0) {
      state.PauseTiming();
      m.reader();
      state.ResumeTiming();
    }
  }
}

// Diagnostics::cycle() of 4 positioning axes (issue 21: a positioning axis reflects ~610 variables, a speed
// axis 80) on simulated drives in steady motion, with a 32-channel trace of the values an engineer scopes
// while commissioning. range(0): publish period (cycles). The axes move in their own runtime (its step is
// timed too: the published values change as in a real cycle); the diagnostics are attached to a second
// runtime that never runs and are called right after each step. Diagnostics' cost = this benchmark minus
// BM_PositioningRuntimeStep.
void BM_DiagnosticsCyclePositioning(benchmark::State& state) {
  bench::PositioningMachine m(kAxes, true, 0);
  diagnostics::Diagnostics d(
      diagnostics::DiagnosticsConfig{static_cast<std::uint32_t>(state.range(0)), 8192, 100});
  for (auto& axis : m.group().axes)
    d.add(*axis);
  techobjects::Runtime idle(techobjects::RuntimeConfig{0.001, 1, 1});
  d.attach(idle);
  // 32 channels: 8 of each axis.
  diagnostics::TraceRequest r;
  for (int a = 1; a <= kAxes; ++a) {
    for (const char* p : {"ActualPosition", "ActualVelocity", "Position", "StatusPositioning.FollowingError",
                          "StatusWord", "StatusWord.X7", "telegram.drive.NIST_B", "telegram.drive.G1_XIST1"})
      r.channels.push_back("Axis" + std::to_string(a) + "." + p);
  }
  r.post_samples = diagnostics::kMaxTraceSamples;
  if (!d.start_trace(r).empty()) std::abort();
  techobjects::CycleClock clock = m.runtime().clock();
  std::uint64_t n = 0;
  for (auto _ : state) {
    m.step();  // the axes move: the published values change
    d.cycle(clock);
    ++clock.servo_cycles;
    if (++n % 20 == 0) {
      state.PauseTiming();
      d.poll();
      const bool done = d.read([](const diagnostics::Diagnostics::State& s) {
        return s.trace.state == diagnostics::TraceCapture::State::kComplete;
      });
      if (done && !d.start_trace(r).empty()) std::abort();
      state.ResumeTiming();
    }
  }
}

// The same machine's runtime step alone: what the diagnostics' share is measured against.
void BM_PositioningRuntimeStep(benchmark::State& state) {
  bench::PositioningMachine m(kAxes, true, 0);
  for (auto _ : state)
    m.step();
}

}  // namespace

BENCHMARK(BM_DiagnosticsCyclePositioning)->Arg(10)->Arg(1);
BENCHMARK(BM_PositioningRuntimeStep);
BENCHMARK(BM_DiagnosticsCycle)->Args({10, 0})->Args({1, 0})->Args({10, 1})->Args({1, 1});
BENCHMARK(BM_ApplicationCycle)->Arg(0)->Arg(1);
