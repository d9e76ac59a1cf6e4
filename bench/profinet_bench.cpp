// The controller's cyclic PROFINET frame handling per device and cycle, for 1, 4 and 16 devices: the bare
// codecs (profinet_devices.hpp) and the IoController calls of the gateway's cyclic thread
// (profinet_controllers.hpp); docs/performance.md "PROFINET frame codecs".
#include <benchmark/benchmark.h>

#include <vector>

#include "profinet_controllers.hpp"
#include "profinet_devices.hpp"

namespace {

void BM_ProfinetCyclicFrames(benchmark::State& state) {
  std::vector<tomc::bench::ProfinetDevice> devices;
  for (std::int64_t i = 0; i < state.range(0); ++i)
    devices.emplace_back(static_cast<std::uint16_t>(i));
  for (auto _ : state) {
    for (auto& device : devices) {
      std::size_t sent = 0;
      benchmark::DoNotOptimize(device.cycle(sent));
      benchmark::DoNotOptimize(sent);
    }
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));  // items: device-cycles
}
BENCHMARK(BM_ProfinetCyclicFrames)->Arg(1)->Arg(4)->Arg(16);

void BM_GatewayCyclicControllers(benchmark::State& state) {
  tomc::bench::ProfinetControllers controllers(static_cast<int>(state.range(0)));
  if (!controllers.ready()) return state.SkipWithError("the in-memory start-up failed");
  std::uint64_t now_us = 1'000'000;
  for (auto _ : state) {
    now_us += 1000;
    benchmark::DoNotOptimize(controllers.cycle(now_us));
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));  // items: device-cycles
}
BENCHMARK(BM_GatewayCyclicControllers)->Arg(1)->Arg(4)->Arg(16);

}  // namespace

BENCHMARK_MAIN();
