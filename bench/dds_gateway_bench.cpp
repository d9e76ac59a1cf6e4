// The Fast DDS gateway exchange (issue 8, docs/performance.md): a `tomc gateway-sim` process with 1, 16 or 64
// simulated drives (telegram 105 + 750) and this process as the controller, on loopback.
//
// Per cycle the benchmark runs the adapters' cyclic part — read_actual() and write_setpoint() of every
// device, what Runtime::step() calls — and times only that (manual time: the cost on the cyclic thread). Then
// it waits for the gateway's answer. Counters:
//   rtt_*_us   round trip of one cycle's exchange: from the cyclic thread publishing the cycle's setpoints to
//              the listener having routed the last device's answer (ExchangeCore's histogram, 1 us buckets)
//   missed     cycles whose answer did not arrive within 50 ms
// Two pacings: back to back (the next cycle as soon as the answer is in), and paced by a 1 ms clock as a real
// controller runs (the processes sleep between cycles, so wake-up latencies are part of the round trip).
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <thread>

#include "../tests/dds/gateway_process.hpp"
#include "tomc/drives/dds/gateway_link.hpp"
#include "tomc/telegrams/layout.hpp"

namespace {

using namespace tomc;
using Clock = std::chrono::steady_clock;

constexpr int kCycles = 5000;

// One simulator process per drive count, started on first use and stopped at exit.
tomc::testing::GatewayProcess& gateway_for(int drives, int domain) {
  static std::map<int, std::unique_ptr<tomc::testing::GatewayProcess>> processes;
  auto& p = processes[drives];
  if (!p) {
    std::ostringstream devices;
    for (int i = 0; i < drives; ++i) {
      devices << (i ? ", " : "") << "{ \"name\": \"d" << i
              << "\", \"drive\": { \"telegram\": 105, \"supplementary_telegram\": 750 } }";
    }
    const std::string config = "{ \"gateway\": \"bench\", \"domain\": " + std::to_string(domain) +
                               ", \"devices\": [" + devices.str() + "] }";
    p = std::make_unique<tomc::testing::GatewayProcess>(
        tomc::testing::test_directory("bench" + std::to_string(drives)), config);
  }
  return *p;
}

// The controller side, one link per drive count, kept across repetitions: a new controller would have to wait
// for the gateway's watchdog to release the previous one (docs/gateway.md G1).
struct Controller {
  std::shared_ptr<drives::dds::GatewayLink> link;
  std::vector<std::unique_ptr<drives::dds::DdsGatewayDrive>> adapters;
  std::vector<drives::DeviceFrames> actual;
  std::vector<drives::DeviceFrames> setpoint;
  std::string problem;  // non-empty: the gateway did not answer
};

Controller& controller_for(int drives, int domain) {
  static std::map<int, std::unique_ptr<Controller>> controllers;
  auto& c = controllers[drives];
  if (c) return *c;
  gateway_for(drives, domain);
  c = std::make_unique<Controller>();
  drives::dds::GatewayLinkConfig config;
  config.domain = domain;
  config.partition = tomc::testing::test_partition();
  c->link = drives::dds::GatewayLink::create(config);
  drives::DeviceConfig dc;
  dc.drive_telegram = 105;
  dc.supplementary_telegram = 750;
  for (int i = 0; i < drives; ++i) {
    c->adapters.push_back(c->link->make_drive("d" + std::to_string(i), dc));
    c->actual.push_back(drives::make_frames(dc, telegrams::Direction::kActual));
    c->setpoint.push_back(drives::make_frames(dc, telegrams::Direction::kSetpoint));
  }
  for (const auto& r : c->link->connect(std::chrono::seconds(20))) {
    if (r.diagnosis != drives::dds::DeviceDiagnosis::kAnswering) c->problem = r.text;
  }
  return *c;
}

void BM_GatewayCycle(benchmark::State& state) {
  const int drives = static_cast<int>(state.range(0));
  const bool paced = state.range(1) != 0;
  Controller& c = controller_for(drives, 190 + drives % 40);
  if (!c.problem.empty()) {
    state.SkipWithError(c.problem.c_str());
    for (auto _ : state) {  // Google Benchmark 1.7 needs the iterations run even when skipped
    }
    return;
  }
  auto& link = c.link;
  auto& adapters = c.adapters;
  auto& actual = c.actual;
  auto& setpoint = c.setpoint;
  std::uint64_t missed = 0;
  auto next = Clock::now();
  int warm_up = 50;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    for (int i = 0; i < drives; ++i)
      benchmark::DoNotOptimize(adapters[i]->read_actual(actual[i]));
    for (int i = 0; i < drives; ++i)
      adapters[i]->write_setpoint(setpoint[i]);
    const auto t1 = Clock::now();
    state.SetIterationTime(std::chrono::duration<double>(t1 - t0).count());
    if (!link->wait_for_answers(std::chrono::milliseconds(50)) && warm_up <= 0) ++missed;
    if (--warm_up == 0) link->core().reset_round_trips();  // the first cycles include the gateway's take-over
    if (paced) {
      next += std::chrono::milliseconds(1);
      std::this_thread::sleep_until(next);
    }
  }
  const auto s = link->statistics();
  state.counters["rtt_median_us"] = s.round_trip_median_us;
  state.counters["rtt_p99_us"] = s.round_trip_p99_us;
  state.counters["rtt_max_us"] = s.round_trip_max_us;
  state.counters["missed"] = static_cast<double>(missed);
  state.counters["drives"] = drives;
}

BENCHMARK(BM_GatewayCycle)
    ->ArgNames({"drives", "paced_1ms"})
    ->Args({1, 0})
    ->Args({16, 0})
    ->Args({64, 0})
    ->Args({1, 1})
    ->Args({16, 1})
    ->Args({64, 1})
    ->Iterations(kCycles)
    ->UseManualTime()
    ->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
