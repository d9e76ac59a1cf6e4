// Fixed workload for callgrind: one TO_PositioningAxis on its simulated drive (telegram 3) that gets a new
// MC_MoveAbsolute every cycle while it moves, so PositionProfile::plan runs from a moving state in every
// cycle. Counted: MC_Servo + MC_Interpolator and the user program (MC_Power, MC_Home, 2 x MC_MoveAbsolute:
// the instruction call is where the job is planned); not the drive model. scripts/bench: per axis-cycle.
#include <cstdio>

#include "positioning_machine.hpp"

constexpr int kCycles = 20000;
constexpr int kAxes = 1;

extern "C" __attribute__((noinline, noipa)) void positioning_replan(
    void* object, const tomc::techobjects::CycleClock* clock, int phase) {
  if (phase == 2) {
    static_cast<tomc::bench::PositioningMachine*>(object)->run_user_program();
  } else {
    static_cast<tomc::bench::AxisGroup*>(object)->run(*clock, phase);
  }
}

int main() {
  tomc::bench::PositioningMachine m(kAxes, true, 1);
  m.group().hook = [](tomc::bench::AxisGroup& g, const tomc::techobjects::CycleClock& c, int phase) {
    positioning_replan(&g, &c, phase);
  };
  m.set_user_program_hook(
      [](tomc::bench::PositioningMachine& machine) { positioning_replan(&machine, nullptr, 2); });
  for (int i = 0; i < kCycles; ++i)
    m.step();
  std::printf("cycles=%d units=%d velocity=%g\n", kCycles, kAxes, m.group().axes[0]->data().Velocity);
  return 0;
}
