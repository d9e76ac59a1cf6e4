// Fixed workload for callgrind: MC_Servo + MC_Interpolator of 16 TO_SynchronousAxis followers, each on its
// simulated drive (telegram 3, codec included), geared 1:1 with MC_GearIn to one leader at 100 mm/s, in
// steady synchronous travel (gearing_machine.hpp); with the argument `camming`, cammed with MC_CamIn on the
// machine's cyclic spline cam instead. The leader, the drive models and the user program run outside the
// counted function. scripts/bench: instructions per follower and cycle.
#include <cstdio>
#include <string_view>

#include "gearing_machine.hpp"

constexpr int kCycles = 10000;
constexpr int kFollowers = 16;

extern "C" __attribute__((noinline, noipa)) void gearing_cycle(tomc::bench::FollowerGroup& group,
                                                               const tomc::techobjects::CycleClock& clock,
                                                               int phase) {
  group.run(clock, phase);
}

int main(int argc, char** argv) {
  const bool camming = argc > 1 && std::string_view(argv[1]) == "camming";
  tomc::bench::GearingMachine m(kFollowers,
                                camming ? tomc::bench::Function::kCamming : tomc::bench::Function::kGearing);
  m.group().hook = gearing_cycle;
  for (int i = 0; i < kCycles; ++i)
    m.step();
  std::printf("cycles=%d units=%d in_gear=%d velocity=%g\n", kCycles, kFollowers,
              m.programs().back().synchronous() ? 1 : 0, m.group().axes.back()->data().Velocity);
  return 0;
}
