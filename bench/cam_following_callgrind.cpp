// Fixed workload for callgrind: the per-cycle cam work of one follower (issue 19) — the camming synchronous
// function (scaling, cyclic application mode, evaluation with both derivatives) on a 1,000-point cubic-spline
// TO_Cam, the leading value advancing 0.1° per cycle over several periods. scripts/bench: instructions per
// cycle.
#include <cmath>
#include <cstdio>

#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/cam/cam_synchronous_function.hpp"

constexpr int kCycles = 20000;

extern "C" __attribute__((noinline, noipa)) double cam_following(tomc::techobjects::CamSynchronousFunction& f,
                                                                 double leading) {
  return f.evaluate(leading, 100.0, 0.0).position;
}

int main() {
  using namespace tomc::techobjects;
  Cam cam("C");
  (void)cam.write("InterpolationSettings.InterpolationMode", 1.0);
  (void)cam.write("InterpolationSettings.BoundaryConditions", 1.0);
  for (int i = 0; i < 1000; ++i) {
    const double x = 360.0 * i / 999.0;
    (void)cam.write_point(static_cast<std::size_t>(i + 1),
                          {x, 50.0 * (1.0 - std::cos(x * 3.14159265358979 / 180.0))}, true);
  }
  if (!cam.interpolate_cam().accepted()) return 1;
  CamSynchronousFunction f;
  f.start(cam.profile(), {0.0, 10.0, 1.0, 2.0}, CamApplicationMode::kCyclic);
  double sum = 0.0;
  for (int i = 0; i < kCycles; ++i)
    sum += cam_following(f, 0.1 * i);
  std::printf("cycles=%d units=1 sum=%g\n", kCycles, sum);
  return 0;
}
