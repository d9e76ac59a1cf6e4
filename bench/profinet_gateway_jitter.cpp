// 16 emulated PROFINET drives at 1 ms through one gateway (issue 17 "Performance"; docs/performance.md
// "PROFINET gateway, 16 devices"). An opt-in program, not a test: it needs root (network namespaces) and runs
// for seconds. The set-up of GatewayNetns.FourDrivesAtOneMillisecondThroughOneGateway with N devices: two
// namespaces made here, N veth pairs whose gateway ends are ports of a bridge (the gateway's interface), each
// namespace checked to hold only lo, the bridge and its own veth ends; the gateway (tomc::profinet_gateway)
// in this process, N emulated drives (ProfinetDrive behind the sockets, one thread each), and unless
// --no-sim `tomc sim`'s runtime moving N positioning axes through DDS (MC_Power, MC_MoveVelocity 20 mm/s).
//
// Measured: the send jitter on the wire — dumpcap captures the bridge, tshark gives each output frame's time,
// and per device the interval between consecutive output frames minus the send clock — its p50/p99/p99.9/
// max over all devices; and the cyclic thread's wake-up latency from its RealTimeRunner (p99, max), its
// overruns, the ARs lost and the setpoints applied.
//
//   sudo build/bin/profinet_gateway_jitter [--devices 16] [--seconds 5] [--fifo 0] [--watchdog-factor 20]
//                                          [--wake-margin-us 0] [--no-sim]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "gateway_hosts.hpp"
#include "in_process_gateway.hpp"
#include "netns_hosts.hpp"
#include "tomc/gateway/profinet_gateway.hpp"

namespace gh = tomc::profinet::gateway_hosts;
namespace pn = tomc::profinet;
namespace sc = tomc::scenario;

namespace {

struct Options {
  int devices = 16;
  int seconds = 5;
  int fifo = 0;
  int watchdog_factor = 20;  // decision I7: the device threads are not real-time
  int wake_margin_us = 0;    // the cyclic thread wakes this early and spins to the send time (decision I25)
  bool sim = true;
};

double percentile(std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size()))) - 1;
  return sorted[std::min(k, sorted.size() - 1)];
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&] { return i + 1 < argc ? std::atoi(argv[++i]) : 0; };
    if (a == "--devices")
      o.devices = next();
    else if (a == "--seconds")
      o.seconds = next();
    else if (a == "--fifo")
      o.fifo = next();
    else if (a == "--watchdog-factor")
      o.watchdog_factor = next();
    else if (a == "--wake-margin-us")
      o.wake_margin_us = next();
    else if (a == "--no-sim")
      o.sim = false;
    else {
      std::fprintf(stderr, "unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  if (o.devices < 1 || o.devices > 64 || o.seconds < 1 || o.wake_margin_us < 0 || o.wake_margin_us > 500) {
    std::fprintf(stderr, "--devices 1..64, --seconds >= 1, --wake-margin-us 0..500\n");
    return 2;
  }
  pn::testing::Namespaces hosts("tomc17j", "tomc17k");
  if (const std::string why = gh::make_bridged_hosts(hosts, o.devices); !why.empty()) {
    std::fprintf(stderr, "%s\n", why.c_str());
    return 1;
  }
  if (!gh::bridged_interfaces_only(hosts, o.devices)) {
    std::fprintf(stderr, "the namespaces hold other interfaces: nothing sent\n");
    return 1;
  }
  if (!pn::testing::Capture::available()) {
    std::fprintf(stderr, "tshark/dumpcap are not installed (scripts/setup)\n");
    return 1;
  }
  pn::testing::Capture capture(
      hosts.first, "pn-g",
      std::filesystem::temp_directory_path() / ("tomc17-jitter-" + std::to_string(::getpid()) + ".pcap"));
  std::vector<std::unique_ptr<gh::DeviceHost>> drives;
  for (int k = 0; k < o.devices; ++k)
    drives.push_back(std::make_unique<gh::DeviceHost>(hosts.second, gh::bridged_device(k)));

  sc::ProfinetGatewayConfig config;
  config.gateway = "gw-pn";
  config.domain = gh::kDomain;
  config.partition = "tomc-test-" + std::to_string(::getpid());
  config.watchdog = 0.5;
  config.interface = "pn-g";
  config.ip = {10, 218, 0, 1};
  config.watchdog_factor = static_cast<std::uint16_t>(o.watchdog_factor);
  config.fifo_priority = o.fifo;
  config.wake_margin_us = o.wake_margin_us;
  for (int k = 0; k < o.devices; ++k) {
    const gh::DeviceOptions d = gh::bridged_device(k);
    sc::ProfinetDeviceConfig device;
    device.name = "axis" + std::to_string(k + 1);
    device.name_of_station = d.name_of_station;
    device.ip = d.ip;
    device.telegram = 3;
    config.devices.push_back(device);
  }
  std::string error;
  auto gateway = pn::testing::gateway_in(hosts.first, config, error);
  if (!error.empty()) {
    std::fprintf(stderr, "gateway: %s\n", error.c_str());
    return 1;
  }
  // Every AR up (bounded), then the measured run.
  const auto all_up = [&] {
    for (const auto& d : gateway->devices()) {
      if (!d.exchanging) return false;
    }
    return true;
  };
  for (int i = 0; i < 2000 && !all_up(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  if (!all_up()) {
    std::fprintf(stderr, "not every device came up within 20 s\n");
    return 1;
  }
  const auto before = gateway->counters();
  std::string summary = "no sim";
  if (o.sim) {
    std::string failure;
    const auto rows = gh::run(
        gh::velocity_scenario(o.devices, 1000 * o.seconds), hosts.first,
        [](int, const std::vector<double>&) {}, failure);
    int moving = 0;
    for (int k = 0; k < o.devices && !rows.empty(); ++k) {
      const std::size_t column = 2 + 3 * static_cast<std::size_t>(k);
      moving += std::abs(rows.back()[column] - 20.0) < 0.5 && rows.back()[column + 1] == 0.0 ? 1 : 0;
    }
    summary = std::to_string(rows.size()) + " sim cycles, " + std::to_string(moving) + " of " +
              std::to_string(o.devices) + " axes at 20 mm/s without alarm" +
              (failure.empty() ? "" : " (" + failure + ")");
  } else {
    std::this_thread::sleep_for(std::chrono::seconds(o.seconds));
  }
  const auto after = gateway->counters();
  int ars = 0;
  for (const auto& d : gateway->devices())
    ars += static_cast<int>(d.ars);
  gateway.reset();
  capture.stop();

  // Each output frame's time on the bridge, per FrameID (device k sends 0x8001 + 2k, decision I9).
  const std::string mac = [&] {
    const std::string link = pn::testing::output_of("ip -n " + hosts.first + " -o link show dev pn-g");
    const auto at = link.find("link/ether ");
    return at == std::string::npos ? std::string{} : link.substr(at + 11, 17);
  }();
  std::istringstream lines(pn::testing::output_of("tshark -n -r " + capture.file().string() +
                                                  " -Y 'eth.src == " + mac +
                                                  " && pn_rt.frame_id >= 0x8001 && pn_rt.frame_id < 0x8100' "
                                                  "-T fields -e frame.time_epoch -e pn_rt.frame_id"
                                                  " 2>/dev/null"));
  std::map<int, std::vector<double>> times;  // µs since the first frame
  double first = -1.0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream cells(line);
    std::string seconds;
    int frame_id = 0;
    cells >> seconds >> frame_id;
    const auto dot = seconds.find('.');
    if (dot == std::string::npos) continue;
    // Integer seconds and nanoseconds apart: a double of the epoch in µs would lose the sub-µs part.
    const double t = static_cast<double>(std::stoll(seconds.substr(0, dot)) % 100000) * 1e6 +
                     std::stod("0" + seconds.substr(dot)) * 1e6;
    if (first < 0) first = t;
    times[frame_id].push_back(t - first);
  }
  const double period_us = config.cycle_time() * 1e6;
  std::vector<double> jitter;
  for (const auto& [id, t] : times) {
    for (std::size_t i = 1; i < t.size(); ++i)
      jitter.push_back(std::abs(t[i] - t[i - 1] - period_us));
  }
  std::sort(jitter.begin(), jitter.end());
  std::printf(
      "%d devices, send clock %.0f us, %d s, fifo %d: %zu output frames of %zu FrameIDs captured\n"
      "send jitter |interval - send clock| (us): p50 %.1f, p99 %.1f, p99.9 %.1f, max %.1f\n"
      "cyclic thread: %llu cycles, %llu overruns, start latency p99 %.0f us, max %.0f us (whole run); wake "
      "margin %d us: %.0f us spun per cycle, %llu late wake-ups\n"
      "%d ARs for %d devices (%d lost), %llu setpoints applied; %s\n",
      o.devices, period_us, o.seconds, o.fifo, jitter.size() + times.size(), times.size(),
      percentile(jitter, 0.5), percentile(jitter, 0.99), percentile(jitter, 0.999),
      jitter.empty() ? 0.0 : jitter.back(), static_cast<unsigned long long>(after.cycles - before.cycles),
      static_cast<unsigned long long>(after.overruns - before.overruns), after.wake_up_p99_us,
      after.wake_up_max_us, o.wake_margin_us, after.spin_mean_us,
      static_cast<unsigned long long>(after.late_wakeups), ars, o.devices, ars - o.devices,
      static_cast<unsigned long long>(after.setpoints_applied - before.setpoints_applied), summary.c_str());
  return times.size() == static_cast<std::size_t>(o.devices) ? 0 : 1;
}
