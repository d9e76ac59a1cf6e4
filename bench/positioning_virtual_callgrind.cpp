// Fixed workload for callgrind: MC_Servo + MC_Interpolator of one virtual TO_PositioningAxis (no drive) in
// steady motion (a long MC_MoveAbsolute at its cruise velocity). scripts/bench: instructions per axis-cycle.
#include <cstdio>

#include "positioning_machine.hpp"
#include "touched_bytes.hpp"

constexpr int kCycles = 20000;
constexpr int kAxes = 1;

extern "C" __attribute__((noinline, noipa)) void positioning_virtual(
    tomc::bench::AxisGroup& group, const tomc::techobjects::CycleClock& clock, int phase) {
  group.run(clock, phase);
}

int main(int argc, char** argv) {  // argument `touched`: bench/touched_bytes.py
  const bool touched = tomc::bench::touched_mode(argc, argv);
  tomc::bench::PositioningMachine m(kAxes, false, 0);
  m.group().hook = touched ? tomc::bench::touched_phase<tomc::bench::AxisGroup> : positioning_virtual;
  tomc::bench::touched_object(touched, m.group().axes[0].get(), sizeof(tomc::techobjects::PositioningAxis));
  const int cycles = touched ? tomc::bench::kTouchedCycles : kCycles;
  for (int i = 0; i < cycles; ++i)
    m.step();
  // The axis' state after the run, every digit: two builds of the same code (with and without link-time
  // optimisation, decision P27) must print the same line.
  const auto& d = m.group().axes[0]->data();
  std::printf("cycles=%d units=%d velocity=%g position=%.17g actual=%.17g following_error=%.17g status=%u\n",
              cycles, kAxes, d.Velocity, d.Position, d.ActualPosition, d.StatusPositioning.FollowingError,
              static_cast<unsigned>(d.StatusWord));
  return 0;
}
