// Fixed workload for callgrind: one whole application cycle (Runtime::step) with one TO_PositioningAxis in
// steady motion on its simulated drive (telegram 3): MC_Servo, MC_Interpolator, the user program and the
// drive model. scripts/bench: instructions per cycle.
#include <cstdio>

#include "positioning_machine.hpp"

constexpr int kCycles = 20000;
constexpr int kAxes = 1;

extern "C" __attribute__((noinline, noipa)) void positioning_step(tomc::bench::PositioningMachine& m) {
  m.step();
}

int main() {
  tomc::bench::PositioningMachine m(kAxes, true, 0);
  for (int i = 0; i < kCycles; ++i)
    positioning_step(m);
  std::printf("cycles=%d units=%d velocity=%g\n", kCycles, kAxes, m.group().axes[0]->data().Velocity);
  return 0;
}
