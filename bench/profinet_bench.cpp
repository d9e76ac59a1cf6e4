// The controller's cyclic PROFINET frame handling per device and cycle (profinet_devices.hpp), for 1, 4 and
// 16 devices; docs/performance.md "PROFINET frame codecs".
#include <benchmark/benchmark.h>

#include <vector>

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

}  // namespace

BENCHMARK_MAIN();
