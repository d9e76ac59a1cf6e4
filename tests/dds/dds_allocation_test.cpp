// Real-time discipline of the gateway adapter (issue 8): Runtime::step() with speed axes on DdsGatewayDrive
// adapters allocates nothing, while the DDS threads (sender, listener) do their work beside it. A counting
// global operator new counts only on the thread that runs the cycle.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "gateway_process.hpp"
#include "selective_counting_new.hpp"
#include "tomc/drives/dds/gateway_link.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace {
thread_local bool t_counting = false;
std::atomic<std::uint64_t> g_allocations{0};
}  // namespace

void tomc::testing::count_allocation() noexcept {
  if (t_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
}

namespace {

using namespace tomc;
using techobjects::SpeedAxis;

// tomc's own: proves the per-thread counter counts, so the zero of the cycle test can fail.
TEST(GatewayAllocation, CountingAllocatorCountsThisThread) {
  t_counting = true;
  const auto before = g_allocations.load();
  void* p = ::operator new(16);  // an explicit call: the compiler may not elide it
  t_counting = false;
  ::operator delete(p);
  EXPECT_EQ(g_allocations.load(), before + 1);
}

// 4 speed axes behind the gateway simulator, moving: 2000 cycles of Runtime::step() without one allocation.
// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), decisions G4/G5 (sender thread and triple
// buffers), docs/gateway.md §6 C6.
TEST(GatewayAllocation, CycleWithGatewayDrivesDoesNotAllocate) {
  const int domain = 150;
  std::vector<std::pair<std::string, int>> devices = {{"a1", 2}, {"a2", 3}, {"a3", 105}, {"a4", 1}};
  tomc::testing::GatewayProcess gateway(tomc::testing::test_directory("alloc"),
                                        tomc::testing::gateway_config(domain, devices));
  drives::dds::GatewayLinkConfig config;
  config.domain = domain;
  config.partition = tomc::testing::test_partition();
  auto link = drives::dds::GatewayLink::create(config);
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  struct Axis {
    SpeedAxis* axis = nullptr;
    instructions::MC_Power<SpeedAxis> power;
    instructions::MC_MoveVelocity<SpeedAxis> move;
  };
  std::vector<std::unique_ptr<Axis>> axes;
  for (const auto& [name, telegram] : devices) {
    drives::DeviceConfig dc;
    dc.drive_telegram = static_cast<std::uint16_t>(telegram);
    auto& io = runtime.add_device(link->make_drive(name, dc));
    auto a = std::make_unique<Axis>();
    a->axis = &runtime.emplace<SpeedAxis>(name, &io, techobjects::SpeedAxisData{});
    a->power.Enable = true;
    a->move.Velocity = 600.0;
    a->move.Acceleration = 100.0;
    a->move.Deceleration = 100.0;
    axes.push_back(std::move(a));
  }
  runtime.set_user_program([&](techobjects::Runtime&) {
    for (auto& a : axes) {
      a->power(*a->axis);
      a->move.Execute = a->power.Status;
      a->move(*a->axis);
    }
  });
  for (const auto& r : link->connect(std::chrono::seconds(10)))
    ASSERT_EQ(r.diagnosis, drives::dds::DeviceDiagnosis::kAnswering) << r.text;
  runtime.start();
  for (int i = 0; i < 5; ++i) {  // warm-up outside the count
    runtime.step();
    link->wait_for_answers(std::chrono::milliseconds(50));
  }
  std::uint64_t counted = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto before = g_allocations.load();
    t_counting = true;
    runtime.step();
    t_counting = false;
    counted += g_allocations.load() - before;
    link->wait_for_answers(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(counted, 0u);
  for (const auto& a : axes) {
    EXPECT_TRUE(a->move.InVelocity) << a->axis->name();
    EXPECT_TRUE(a->axis->data().StatusDrive.CommunicationOK) << a->axis->name();
  }
}

}  // namespace
