// Fixed workload for callgrind: one servo cycle of the dynamic filter in its most expensive configuration
// (Mode 2: two moving averages over 16 servo cycles and a 16-cycle dead time; position, velocity and
// acceleration), and of the backlash compensation while a motor reverses through its backlash.
#include <cstdio>

#include "tomc/techobjects/position/backlash.hpp"
#include "tomc/techobjects/position/dynamic_filter.hpp"

using namespace tomc;

constexpr int kCycles = 20000;

extern "C" __attribute__((noinline)) double setpoint_path(techobjects::DynamicFilter& f,
                                                          techobjects::BacklashCompensation& b, int k) {
  const double v = (k / 400) % 2 == 0 ? 100.0 : -100.0;
  const techobjects::MotionState out = f.update(techobjects::MotionState{0.1 * k, v, 0.0}, true);
  return out.position + b.update(techobjects::BacklashInput{out.position, true, true, out.velocity});
}

int main() {
  techobjects::DynamicFilter f;
  (void)f.configure(techobjects::DynamicFilterConfig{2, 0.016, 0.0155, 0.016, 0.001});
  techobjects::BacklashCompensation b;
  (void)b.configure(techobjects::BacklashConfig{true, 0.2, 5.0, 0.001});
  double sum = 0.0;
  for (int k = 0; k < kCycles; ++k)
    sum += setpoint_path(f, b, k);
  std::printf("cycles=%d units=1 checksum=%g\n", kCycles, sum);
  return 0;
}
