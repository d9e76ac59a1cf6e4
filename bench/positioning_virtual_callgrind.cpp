// Fixed workload for callgrind: MC_Servo + MC_Interpolator of one virtual TO_PositioningAxis (no drive) in
// steady motion (a long MC_MoveAbsolute at its cruise velocity). scripts/bench: instructions per axis-cycle.
#include <cstdio>

#include "positioning_machine.hpp"

constexpr int kCycles = 20000;
constexpr int kAxes = 1;

extern "C" __attribute__((noinline, noipa)) void positioning_virtual(
    tomc::bench::AxisGroup& group, const tomc::techobjects::CycleClock& clock, int phase) {
  group.run(clock, phase);
}

int main() {
  tomc::bench::PositioningMachine m(kAxes, false, 0);
  m.group().hook = positioning_virtual;
  for (int i = 0; i < kCycles; ++i)
    m.step();
  std::printf("cycles=%d units=%d velocity=%g\n", kCycles, kAxes, m.group().axes[0]->data().Velocity);
  return 0;
}
