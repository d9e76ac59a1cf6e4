// Fixed workload for callgrind: 16 devices' cyclic frame handling (profinet_devices.hpp) for kCycles
// cycles; scripts/bench divides the instructions of profinet_cyclic() by cycles and units (devices).
#include <cstdio>
#include <vector>

#include "profinet_devices.hpp"

constexpr int kCycles = 20000;
constexpr int kDevices = 16;

extern "C" __attribute__((noinline)) std::size_t profinet_cyclic(
    std::vector<tomc::bench::ProfinetDevice>& devices) {
  std::size_t sent = 0;
  for (auto& device : devices) {
    std::size_t bytes = 0;
    if (device.cycle(bytes)) sent += bytes;
  }
  return sent;
}

int main() {
  std::vector<tomc::bench::ProfinetDevice> devices;
  for (int i = 0; i < kDevices; ++i)
    devices.emplace_back(static_cast<std::uint16_t>(i));
  std::size_t total = 0;
  for (int i = 0; i < kCycles; ++i)
    total += profinet_cyclic(devices);
  std::printf("cycles=%d units=%d bytes=%zu\n", kCycles, kDevices, total);
  return 0;
}
