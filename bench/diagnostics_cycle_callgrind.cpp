// Fixed workload for callgrind: Diagnostics::cycle() (the post-interpolator hook: control panels, snapshots
// every 10 cycles per object, a 32-channel trace) on 4 speed axes with simulated drives in steady motion.
// Only diagnostics_cycle is counted; the reader's poll() runs outside it every 20 cycles, as on the server.
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

using namespace tomc;

constexpr int kCycles = 20000;
constexpr int kAxes = 4;

extern "C" __attribute__((noinline)) void diagnostics_cycle(diagnostics::Diagnostics& d,
                                                            const techobjects::CycleClock& clock) {
  d.cycle(clock);
}

int main() {
  techobjects::Runtime rt(techobjects::RuntimeConfig{0.001, 1, 1});
  diagnostics::Diagnostics d(diagnostics::DiagnosticsConfig{10, 8192, 100});
  std::vector<techobjects::SpeedAxis*> axes;
  std::vector<instructions::MC_Power<techobjects::SpeedAxis>> power(kAxes);
  std::vector<instructions::MC_MoveVelocity<techobjects::SpeedAxis>> move(kAxes);
  for (int i = 0; i < kAxes; ++i) {
    drives::DeviceConfig device;
    device.drive_telegram = 105;
    auto& io =
        rt.add_device(std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
    axes.push_back(&rt.emplace<techobjects::SpeedAxis>("Axis" + std::to_string(i + 1), &io,
                                                       techobjects::SpeedAxisData{}));
    d.add(*axes.back());
    power[i].Enable = true;
    move[i].Velocity = 1500.0;
  }
  rt.set_user_program([&](techobjects::Runtime&) {
    for (int i = 0; i < kAxes; ++i) {
      power[i](*axes[i]);
      move[i].Execute = power[i].Status;
      move[i](*axes[i]);
    }
  });
  d.attach(rt);
  rt.set_post_interpolator([&](techobjects::Runtime& r) { diagnostics_cycle(d, r.clock()); });  // counted
  rt.start();
  for (int i = 0; i < 2000; ++i)
    rt.step();
  diagnostics::TraceRequest trace;
  for (int a = 1; a <= kAxes; ++a) {
    for (const char* p : {"Velocity", "ActualSpeed", "VelocitySetpoint", "StatusWord", "StatusWord.X12",
                          "ErrorWord", "telegram.drive.NIST_B", "telegram.drive.ZSW1"})
      trace.channels.push_back("Axis" + std::to_string(a) + "." + p);
  }
  trace.post_samples = kCycles + 1000;
  if (!d.start_trace(trace).empty()) return 1;
  for (int i = 0; i < kCycles; ++i) {
    rt.step();
    if (i % 20 == 0) d.poll();
  }
  d.poll();
  const auto rows = d.read([](const diagnostics::Diagnostics::State& s) { return s.trace.rows(); });
  std::printf("cycles=%d units=1 trace_rows=%zu\n", kCycles, rows);
  return rows >= static_cast<std::size_t>(kCycles) - 1 ? 0 : 1;
}
