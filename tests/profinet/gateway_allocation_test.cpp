// Real-time discipline of `tomc gateway` (docs/profinet-gateway.md, decision I10): its cyclic thread
// (receive input and alarm frames, acknowledge alarms, publish answers, apply setpoints, send output frames,
// data-hold watchdogs) allocates nothing while a controller moves an axis through it and the device sends
// alarms. The gateway runs in this process (tomc::profinet_gateway) in a network namespace made by the test;
// a counting global operator new counts only on the thread named kCyclicThreadName, so the Fast DDS, start-up
// and test threads beside it do not count. Its own executable: the operator new replaces the process's.
#include <gtest/gtest.h>

#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "gateway_hosts.hpp"
#include "in_process_gateway.hpp"
#include "selective_counting_new.hpp"
#include "tomc/gateway/profinet_gateway.hpp"

namespace {

std::atomic<std::uint64_t> g_cyclic_allocations{0};
std::atomic<pid_t> g_counted_thread{0};  // the kernel thread id whose allocations count

// The thread id is read once per thread: the count costs the other threads (Fast DDS, the scenario) nothing
// that could slow the exchange.
pid_t this_thread_id() noexcept {
  static thread_local const pid_t id = static_cast<pid_t>(::syscall(SYS_gettid));
  return id;
}

// The thread of this process named `name` (/proc/self/task/*/comm), waiting up to 2 s for it; 0 if none.
pid_t thread_named(const std::string& name) {
  for (int i = 0; i < 200; ++i) {
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
      std::string comm;
      std::getline(std::ifstream(task.path() / "comm"), comm);
      if (comm == name) return static_cast<pid_t>(std::stoi(task.path().filename().string()));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return 0;
}

}  // namespace

void tomc::testing::count_allocation() noexcept {
  if (this_thread_id() == g_counted_thread.load(std::memory_order_relaxed))
    g_cyclic_allocations.fetch_add(1, std::memory_order_relaxed);
}

namespace gh = tomc::profinet::gateway_hosts;
namespace pn = tomc::profinet;
namespace sc = tomc::scenario;

// The counter sees a thread of that name allocate (so the zero below can fail).
// tomc's own: proves the counter sees the cyclic thread by name, so the zero of the cycle test can fail.
TEST(ProfinetGatewayAllocation, TheCounterSeesTheCyclicThread) {
  const std::uint64_t before = g_cyclic_allocations.load();
  std::atomic<bool> named{false};
  std::atomic<bool> counted{false};
  std::thread thread([&] {
    ::pthread_setname_np(::pthread_self(), tomc::profinet_gateway::kCyclicThreadName);
    named = true;
    while (!counted.load())
      std::this_thread::yield();
    auto* volatile p = new int(7);
    delete p;
  });
  while (!named.load())
    std::this_thread::yield();
  g_counted_thread = thread_named(tomc::profinet_gateway::kCyclicThreadName);
  counted = true;
  thread.join();
  g_counted_thread = 0;
  EXPECT_EQ(g_cyclic_allocations.load() - before, 1u);
}

TEST(ProfinetGatewayAllocation, TheCyclicThreadAllocatesNothing) {
  pn::testing::Namespaces hosts("tomc17a", "tomc17b");
  if (const std::string why = gh::make_hosts(hosts); !why.empty()) GTEST_SKIP() << why;
  ASSERT_TRUE(gh::own_interfaces_only(hosts));
  sc::ProfinetGatewayConfig config;
  config.gateway = "gw-pn";
  config.domain = gh::kDomain + 1;  // beside gateway_test.cpp's runs under ctest -j
  config.partition = "tomc-test-" + std::to_string(::getpid());
  config.watchdog = 0.5;
  config.interface = "pn-g";
  config.ip = {10, 218, 0, 1};
  config.watchdog_factor = 20;  // decision I7
  sc::ProfinetDeviceConfig device;
  device.name = "axis1";
  device.name_of_station = "drive-1";
  device.ip = {10, 218, 0, 2};
  device.telegram = 3;
  config.devices.push_back(device);

  gh::DeviceHost drive(hosts.second);
  std::string error;
  auto gateway = pn::testing::gateway_in(hosts.first, config, error);
  ASSERT_EQ(error, "");
  g_counted_thread = thread_named(tomc::profinet_gateway::kCyclicThreadName);
  ASSERT_NE(g_counted_thread.load(), 0) << "no thread named " << tomc::profinet_gateway::kCyclicThreadName;
  // The whole run counts: start-up hand-over, the move (setpoints applied, answers published), a diagnosis
  // and a process alarm acknowledged, the idle answers after the controller has gone.
  const std::uint64_t before = g_cyclic_allocations.load();
  gh::Json doc = gh::scenario(true, 300, 0);
  doc["technology_objects"][0]["drive"]["adapter"]["domain"] = config.domain;
  std::string failure;
  const auto rows = gh::run(
      doc, hosts.first,
      [&](int cycle, const std::vector<double>&) {
        if (cycle == 100) drive.send_alarm(pn::alarm_type::kDiagnosis);
        if (cycle == 150) drive.send_alarm(pn::alarm_type::kProcess);
      },
      failure);
  ASSERT_EQ(failure, "");
  for (int i = 0; i < 100 && drive.alarm_acks() < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // idle answers
  const std::uint64_t allocations = g_cyclic_allocations.load() - before;
  g_counted_thread = 0;
  const auto counters = gateway->counters();
  const auto status = gateway->devices();
  gateway.reset();
  ASSERT_EQ(rows.size(), 300u);
  // The cyclic thread applied the controller's setpoints and answered them. (Whether the axis reaches its
  // target is the business of GatewayNetns: under a load of 10-13 on two cores a late answer here may stop it
  // with alarm 405, which changes nothing for the count.)
  EXPECT_EQ(drive.alarm_acks(), 2);
  ASSERT_EQ(status.size(), 1u);
  EXPECT_EQ(status[0].alarms, 2u);
  EXPECT_GE(counters.setpoints_applied, 250u);
  EXPECT_GE(counters.answers_published, 250u);
  EXPECT_GE(counters.cycles, 300u);
  EXPECT_EQ(allocations, 0u) << "over " << counters.cycles << " cycles of the gateway";
  std::printf("gateway: %llu cycles, %llu setpoints applied, %llu allocations on the cyclic thread\n",
              static_cast<unsigned long long>(counters.cycles),
              static_cast<unsigned long long>(counters.setpoints_applied),
              static_cast<unsigned long long>(allocations));
}
