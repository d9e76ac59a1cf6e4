// Real-time discipline of the backlash compensation and the dynamic filter (issue 5): a positioning axis with
// both active, reversing every move on a drive with backlash, allocates nothing after start(). A counting
// global operator new over 200,000 cycles (20,000 under the sanitizers); its own binary, so that the counter
// sees only this test.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "counting_allocator.hpp"
#include "positioning_axis_fixture.hpp"

namespace {

using namespace tomc;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 20'000;
#else
constexpr int kCycles = 200'000;
#endif

// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path); spec 01 §5.9 and spec 02 §7.6 exercised; 40
// cycles per crossing from decision P25's play at Backlash.Velocity.
TEST(BacklashFilterAllocation, ReversingAxisWithBacklashAndFilterAllocatesNothing) {
  auto d = tomc::testing::linear_axis_data();
  d.Sensor[0].Backlash.Enable = true;
  d.Sensor[0].Backlash.Size = 0.2;
  d.Sensor[0].Backlash.Velocity = 5.0;
  d.SetpointFilter.DynamicFilter.Mode = 2;  // the longest loops: two 16-cycle averages and a dead time
  d.SetpointFilter.DynamicFilter.T1 = 0.016;
  d.SetpointFilter.DynamicFilter.T2 = 0.0155;
  d.SetpointFilter.DynamicFilter.Tt = 0.0125;
  d.FollowingError.AdditionalSetpointDelayTime = 0.028;
  auto p = tomc::testing::linear_drive();
  p.backlash = 0.2;
  tomc::testing::PositioningAxisMachine m(d, p);
  ASSERT_GT(m.enable(), 0);

  int moves = 0;
  int passing_cycles = 0;
  bool start = true;
  m.user = [&] {
    if (techobjects::test(m.db().StatusWord2, techobjects::StatusWord2Bit::kPassingBacklash))
      ++passing_cycles;
    if (m.move_relative.Done || start) {  // every move reverses the previous one
      m.move_relative.Execute = false;
      m.move_relative.Distance = (moves % 2 == 0) ? 2.0 : -2.0;
      start = false;
      ++moves;
    } else {
      m.move_relative.Execute = true;
    }
  };
  m.run(2);

  const auto before = tomc::testing::allocation_count();
  m.run(kCycles);
  const auto allocated = tomc::testing::allocation_count() - before;
  EXPECT_EQ(allocated, 0u) << "allocations in " << kCycles << " cycles";
  // The cycle did the work in question: many reversals, each crossing the backlash, no alarm.
  EXPECT_GT(moves, kCycles / 400);
  EXPECT_GT(passing_cycles, moves * 20);  // 0.2 mm at 5 mm/s = 40 cycles per reversal after the first
  EXPECT_TRUE(m.axis->dynamic_filter().active());
  EXPECT_EQ(m.db().ErrorWord, 0u);
}

}  // namespace
