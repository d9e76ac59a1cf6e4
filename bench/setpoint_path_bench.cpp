// Cost of the dynamic filter (spec 02 §7.6) and the backlash compensation (spec 01 §5.9) per servo cycle, as
// components and inside a positioning axis on its simulated drive (issue 5).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_relative.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/position/backlash.hpp"
#include "tomc/techobjects/position/dynamic_filter.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace {

using namespace tomc;

// 0: PT2 + dead time (Mode 1, T1 5 ms, T2 3 ms, Tt 2.5 ms); 1: the longest loops, two moving averages over
// 16 cycles and a 16-cycle dead time (Mode 2); at T_s = 1 ms.
void BM_DynamicFilter(benchmark::State& state) {
  techobjects::DynamicFilter f;
  const bool worst = state.range(0) == 1;
  (void)f.configure(worst ? techobjects::DynamicFilterConfig{2, 0.016, 0.0155, 0.016, 0.001}
                          : techobjects::DynamicFilterConfig{1, 0.005, 0.003, 0.0025, 0.001});
  double x = 0.0;
  for (auto _ : state) {
    x += 0.1;
    benchmark::DoNotOptimize(f.update(techobjects::MotionState{x, 100.0, 0.0}, true));
  }
}

// A motor reversing every 400 cycles through a 0.2 mm backlash crossed at 5 mm/s.
void BM_Backlash(benchmark::State& state) {
  techobjects::BacklashCompensation b;
  (void)b.configure(techobjects::BacklashConfig{true, 0.2, 5.0, 0.001});
  double motor = 0.0;
  std::uint32_t k = 0;
  for (auto _ : state) {
    const double v = (k++ / 400) % 2 == 0 ? 100.0 : -100.0;
    motor += v * 0.001;
    benchmark::DoNotOptimize(b.update(techobjects::BacklashInput{motor, true, true, v}));
  }
}

// TO_PositioningAxis + MC_Power + MC_MoveRelative (±2 mm, every move reversing) on a simulated drive with
// telegram 3; range(0) = 1 with backlash compensation and the Mode 2 filter of the allocation test.
void BM_PositioningAxisReversing(benchmark::State& state) {
  techobjects::PositioningAxisData d;
  d.DynamicLimits.MaxJerk = 0.0;
  drives::SimulatedDriveParameters p;
  p.load_units_per_revolution = 10.0;
  p.backlash = 0.2;
  if (state.range(0) == 1) {
    d.Sensor[0].Backlash.Enable = true;
    d.Sensor[0].Backlash.Size = 0.2;
    d.Sensor[0].Backlash.Velocity = 5.0;
    d.SetpointFilter.DynamicFilter = {2, 0.016, 0.0155, 0.0125};
    d.FollowingError.AdditionalSetpointDelayTime = 0.028;
  }
  techobjects::Runtime rt(techobjects::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig device;
  device.drive_telegram = 3;
  auto& io = rt.add_device(std::make_unique<drives::SimulatedDrive>(device, p));
  auto& axis = rt.emplace<techobjects::PositioningAxis>("Axis1", &io, d);
  instructions::MC_Power<techobjects::PositioningAxis> power;
  instructions::MC_MoveRelative<techobjects::PositioningAxis> move;
  power.Enable = true;
  int moves = 0;
  rt.set_user_program([&](techobjects::Runtime&) {
    power(axis);
    if (move.Done || !move.Busy) {
      move.Execute = !move.Execute && power.Status;
      if (move.Execute) move.Distance = (moves++ % 2 == 0) ? 2.0 : -2.0;
    }
    move(axis);
  });
  rt.start();
  for (int i = 0; i < 100; ++i)
    rt.step();
  for (auto _ : state)
    rt.step();
  state.counters["moves"] = moves;
}

}  // namespace

BENCHMARK(BM_DynamicFilter)->Arg(0)->Arg(1);
BENCHMARK(BM_Backlash);
BENCHMARK(BM_PositioningAxisReversing)->Arg(0)->Arg(1);
