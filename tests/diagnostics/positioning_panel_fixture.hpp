#pragma once
// A positioning axis with its diagnostics, for the panel tests: the default slide of
// positioning_axis_data.hpp (mm, 10 mm per motor revolution, telegram 3 with the motor encoder's zero mark
// for active homing) on the simulated PROFIdrive drive, a user program with MC_Power and MC_MoveAbsolute,
// Diagnostics attached (publish every cycle). Stepped by hand unless a test runs it in real time.
#include <memory>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::testing {

struct PositioningDiagnosticsMachine {
  explicit PositioningDiagnosticsMachine(diagnostics::DiagnosticsConfig config = {1, 4096, 500})
      : runtime(techobjects::RuntimeConfig{0.001, 1, 1}), diagnostics(config) {
    drives::DeviceConfig device;
    device.drive_telegram = 3;
    drives::SimulatedDriveParameters parameters;
    parameters.load_units_per_revolution = 10.0;
    auto owned = std::make_unique<drives::SimulatedDrive>(device, parameters);
    drive = owned.get();
    auto& io = runtime.add_device(std::move(owned));
    techobjects::PositioningAxisData data;
    data.DynamicLimits.MaxJerk = 0.0;  // trapezoids: round numbers
    axis = &runtime.emplace<techobjects::PositioningAxis>("Slide", &io, data);
    diagnostics.add(*axis);
    runtime.set_user_program([this](techobjects::Runtime&) {
      power(*axis);
      move(*axis);
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
  diagnostics::PanelAnswer command(diagnostics::PanelCommandKind kind, std::int32_t direction = 0,
                                   double value = 0.0, std::int32_t mode = 0, std::uint64_t session = 7) {
    diagnostics::PanelCommand c;
    c.session = session;
    c.kind = kind;
    c.direction = direction;
    c.value = value;
    c.mode = mode;
    const std::uint64_t request = diagnostics.post(c);
    if (request == 0) return diagnostics::PanelAnswer::kQueueFull;
    runtime.step();
    return diagnostics.answer_of(request).value_or(diagnostics::PanelAnswer::kNoAnswer);
  }
  diagnostics::PanelStatus panel() {
    diagnostics.poll();
    return diagnostics.read(
        [](const diagnostics::Diagnostics::State& s) { return s.objects[0].snapshot.panel; });
  }
  bool status_bit(techobjects::StatusWordBit bit) const {
    return techobjects::test(axis->data().StatusWord, bit);
  }

  techobjects::Runtime runtime;
  diagnostics::Diagnostics diagnostics;
  drives::SimulatedDrive* drive = nullptr;
  techobjects::PositioningAxis* axis = nullptr;
  instructions::MC_Power<techobjects::PositioningAxis> power;
  instructions::MC_MoveAbsolute<techobjects::PositioningAxis> move;
};

}  // namespace tomc::testing
