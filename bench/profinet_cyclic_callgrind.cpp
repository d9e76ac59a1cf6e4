// Fixed workload for callgrind: 16 devices' cyclic frame handling for kCycles cycles, the bare codecs
// (profinet_devices.hpp, profinet_cyclic()) and the gateway's IoController calls (profinet_controllers.hpp,
// gateway_cyclic()); scripts/bench divides the instructions of each by cycles and units (devices).
#include <cstdio>
#include <vector>

#include "profinet_controllers.hpp"
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

extern "C" __attribute__((noinline)) std::size_t gateway_cyclic(tomc::bench::ProfinetControllers& controllers,
                                                                std::uint64_t now_us) {
  return controllers.cycle(now_us);
}

int main() {
  std::vector<tomc::bench::ProfinetDevice> devices;
  for (int i = 0; i < kDevices; ++i)
    devices.emplace_back(static_cast<std::uint16_t>(i));
  std::size_t total = 0;
  for (int i = 0; i < kCycles; ++i)
    total += profinet_cyclic(devices);
  tomc::bench::ProfinetControllers controllers(kDevices);
  if (!controllers.ready()) return 1;
  std::size_t gateway_total = 0;
  for (int i = 0; i < kCycles; ++i)
    gateway_total += gateway_cyclic(controllers, 1'000'000 + 1000 * static_cast<std::uint64_t>(i));
  std::printf("cycles=%d units=%d bytes=%zu gateway_bytes=%zu\n", kCycles, kDevices, total, gateway_total);
  return 0;
}
