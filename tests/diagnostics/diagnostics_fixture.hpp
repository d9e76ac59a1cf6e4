#pragma once
// A small machine for the diagnostics tests: speed axes on simulated PROFIdrive drives, a user program with
// an MC_Power and an MC_MoveVelocity per axis, and Diagnostics attached to the runtime. Stepped by hand, so
// that every test is deterministic and counts cycles.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::testing {

struct AxisProgram {
  bool run = false;  // MC_MoveVelocity.Execute = run AND MC_Power.Status
  instructions::MC_Power<techobjects::SpeedAxis> power;
  instructions::MC_MoveVelocity<techobjects::SpeedAxis> move;
};

// Trapezoid profiles (MaxJerk 0) with round numbers: 3000 1/min = 50 rev/s, 100 1/s² up, 200 1/s² down.
inline techobjects::SpeedAxisData diagnostics_axis_data() {
  techobjects::SpeedAxisData d;
  d.DynamicLimits.MaxVelocity = 3000.0;
  d.DynamicLimits.MaxAcceleration = 100.0;
  d.DynamicLimits.MaxDeceleration = 200.0;
  d.DynamicLimits.MaxJerk = 0.0;
  return d;
}

struct DiagnosticsMachine {
  explicit DiagnosticsMachine(std::size_t axis_count = 1,
                              diagnostics::DiagnosticsConfig config = {1, 4096, 500},
                              std::uint16_t telegram = 3)
      : runtime(techobjects::RuntimeConfig{0.001, 1, 1}), diagnostics(config) {
    for (std::size_t i = 0; i < axis_count; ++i) {
      drives::DeviceConfig device;
      device.drive_telegram = telegram;
      auto owned = std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{});
      drives.push_back(owned.get());
      auto& io = runtime.add_device(std::move(owned));
      axes.push_back(&runtime.emplace<techobjects::SpeedAxis>("Axis" + std::to_string(i + 1), &io,
                                                              diagnostics_axis_data()));
      programs.push_back(std::make_unique<AxisProgram>());
      diagnostics.add(*axes.back());
    }
    runtime.set_user_program([this](techobjects::Runtime&) {
      for (std::size_t i = 0; i < axes.size(); ++i) {
        programs[i]->power(*axes[i]);
        programs[i]->move.Execute = programs[i]->run && programs[i]->power.Status;
        programs[i]->move(*axes[i]);
      }
    });
    diagnostics.attach(runtime);
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
  // Posts a command and steps until the cycle answered it (the cycle takes it in its next post-interpolator
  // hook, so one step suffices).
  diagnostics::PanelAnswer command(diagnostics::PanelCommand c) {
    const std::uint64_t request = diagnostics.post(c);
    if (request == 0) return diagnostics::PanelAnswer::kQueueFull;
    runtime.step();
    return diagnostics.answer_of(request).value_or(diagnostics::PanelAnswer::kNoAnswer);
  }
  diagnostics::PanelAnswer command(std::uint32_t object, std::uint64_t session,
                                   diagnostics::PanelCommandKind kind, std::int32_t direction = 0,
                                   double value = 0.0) {
    diagnostics::PanelCommand c;
    c.object = object;
    c.session = session;
    c.kind = kind;
    c.direction = direction;
    c.value = value;
    return command(c);
  }
  diagnostics::ObjectSnapshot snapshot(std::size_t object) {
    diagnostics.poll();
    return diagnostics.read(
        [&](const diagnostics::Diagnostics::State& s) { return s.objects[object].snapshot; });
  }

  techobjects::Runtime runtime;
  diagnostics::Diagnostics diagnostics;
  std::vector<drives::SimulatedDrive*> drives;
  std::vector<techobjects::SpeedAxis*> axes;
  std::vector<std::unique_ptr<AxisProgram>> programs;
};

}  // namespace tomc::testing
