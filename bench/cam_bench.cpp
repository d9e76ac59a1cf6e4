// TO_Cam (issue 19), Google Benchmark:
//   BM_InterpolateCam/points/mode — one MC_InterpolateCam of a cam of `points` valid points (16 and 1,000 on
//   a
//       TO_Cam, 10,000 on a TO_Cam_10k) in mode 0 linear, 1 cubic spline (Eigen sparse LDLᵀ), 2 B-spline;
//   BM_CamFollowingValue/points — what a follower does per cycle with the cam: the scaled following value
//       and its two derivatives at a leading value that advances like a leader at constant speed (cyclic);
//   BM_CamSynchronousFunction/points — the camming synchronous function (spec 07 §6.2: scaling, cyclic
//       application mode, value and both derivatives) at a leading value that advances over several periods;
//   BM_GetCamLeadingValue/points — one MC_GetCamLeadingValue search over the whole cam (not cyclic).
// Figures and commands: docs/performance.md "Cams (issue 19)".
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/cam/cam_synchronous_function.hpp"

namespace {

using namespace tomc::techobjects;

std::unique_ptr<Cam> make_cam(std::int64_t points, std::int64_t mode) {
  auto cam = std::make_unique<Cam>("C", points > 1000 ? CamVariant::kCam10k : CamVariant::kCam);
  (void)cam->write("InterpolationSettings.InterpolationMode", static_cast<double>(mode));
  for (std::int64_t i = 0; i < points; ++i) {
    const double x = 360.0 * static_cast<double>(i) / static_cast<double>(points - 1);
    (void)cam->write_point(static_cast<std::size_t>(i + 1),
                           {x, 50.0 * (1.0 - std::cos(x * 3.14159265358979 / 180.0))}, true);
  }
  return cam;
}

void BM_InterpolateCam(benchmark::State& state) {
  auto cam = make_cam(state.range(0), state.range(1));
  for (auto _ : state) {
    const Submission s = cam->interpolate_cam();
    benchmark::DoNotOptimize(s);
    if (!s.accepted()) state.SkipWithError("interpolation failed");
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_CamFollowingValue(benchmark::State& state) {
  auto cam = make_cam(state.range(0), 1);
  if (!cam->interpolate_cam().accepted()) state.SkipWithError("interpolation failed");
  const CamScaling scaling{0.0, 10.0, 1.0, 2.0};
  double leading = 0.0;
  for (auto _ : state) {
    leading += 0.1;  // 100 °/s at 1 ms
    if (leading > 360.0) leading -= 360.0;
    const CamLookup r = following_value(cam->profile(), leading, scaling);
    benchmark::DoNotOptimize(r);
  }
}

void BM_CamSynchronousFunction(benchmark::State& state) {
  auto cam = make_cam(state.range(0), 1);
  if (!cam->interpolate_cam().accepted()) state.SkipWithError("interpolation failed");
  CamSynchronousFunction f;
  f.start(cam->profile(), CamScaling{0.0, 10.0, 1.0, 2.0}, CamApplicationMode::kCyclic);
  double leading = 0.0;
  for (auto _ : state) {
    leading += 0.1;
    const CamFollowingValue v = f.evaluate(leading, 100.0, 0.0);
    benchmark::DoNotOptimize(v);
  }
}

void BM_GetCamLeadingValue(benchmark::State& state) {
  auto cam = make_cam(state.range(0), 1);
  if (!cam->interpolate_cam().accepted()) state.SkipWithError("interpolation failed");
  for (auto _ : state) {
    const CamLookup r = cam->get_leading_value(50.0, 0.0, 1, CamScaling{});
    benchmark::DoNotOptimize(r);
    if (r.error_id != 0) state.SkipWithError("no leading value");
  }
}

}  // namespace

BENCHMARK(BM_InterpolateCam)
    ->ArgsProduct({{16, 1000, 10000}, {0, 1, 2}})
    ->ArgNames({"points", "mode"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CamFollowingValue)->Arg(16)->Arg(1000)->Arg(10000)->ArgName("points");
BENCHMARK(BM_CamSynchronousFunction)->Arg(16)->Arg(1000)->Arg(10000)->ArgName("points");
BENCHMARK(BM_GetCamLeadingValue)
    ->Arg(16)
    ->Arg(1000)
    ->Arg(10000)
    ->ArgName("points")
    ->Unit(benchmark::kMicrosecond);
