// Real-time discipline of MC_TorqueLimiting (torque limiting and fixed-stop detection): an axis that drives
// into a fixed stop, clamps, is released and changes limit and mode, in a loop, allocates nothing after
// start(). The same for the telegram-750 jobs (MC_TorqueAdditive, MC_TorqueRange, torque precontrol). A
// counting global operator new over 200,000 cycles (20,000 under the sanitizers); its own binary, so that the
// counter sees only these tests.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "counting_allocator.hpp"
#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_torque_additive.hpp"
#include "tomc/instructions/mc_torque_limiting.hpp"
#include "tomc/instructions/mc_torque_range.hpp"

namespace {

using namespace tomc;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 20'000;
#else
constexpr int kCycles = 200'000;
#endif

// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), over spec 01 §8.10/§8.11 (torque limiting,
// fixed-stop clamping).
TEST(TorqueLimitingAllocation, ClampReleaseAndLimitChangesAllocateNothing) {
  auto p = tomc::testing::linear_drive();
  p.machine.positive_fixed_stop = 32.0;
  p.machine.negative_fixed_stop = -32.0;
  tomc::testing::PositioningAxisMachine m(tomc::testing::linear_axis_data(), p, 105);
  instructions::MC_TorqueLimiting<techobjects::PositioningAxis> torque;
  m.user = [&] { torque(*m.axis); };
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  torque.Enable = true;
  torque.Mode = 1;
  torque.Limit = 0.5;
  long clamps = 0, releases = 0, limitations = 0;
  bool was_clamped = false, was_limited = false;
  double direction = 1.0;
  const auto before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < kCycles; ++cycle) {
    // Into the stop at 40 mm/s, alternately the positive and the negative one; when clamped, away to 0.
    if (!m.move_velocity.Busy && !m.move_absolute.Busy && !torque.InClamping) {
      m.move_velocity.Velocity = 40.0;
      m.move_velocity.Direction = direction > 0.0 ? 1 : 2;
      m.move_velocity.Execute = true;
    }
    if (torque.InClamping && !m.move_absolute.Busy) {
      m.move_velocity.Execute = false;
      m.move_absolute.Position = 0.0;
      m.move_absolute.Velocity = 40.0;
      m.move_absolute.Execute = true;
      direction = -direction;
      torque.Limit = torque.Limit > 0.4 ? 0.3 : 0.5;  // a new clamping torque without an edge
    }
    if (m.move_absolute.Done) m.move_absolute.Execute = false;
    m.run(1);
    if (torque.InClamping && !was_clamped) ++clamps;
    if (!torque.InClamping && was_clamped) ++releases;
    if (torque.InLimitation && !was_limited) ++limitations;
    was_clamped = torque.InClamping;
    was_limited = torque.InLimitation;
  }
  const auto allocated = tomc::testing::allocation_count() - before;
  EXPECT_EQ(allocated, 0u) << "allocations in " << kCycles << " cycles";
  EXPECT_EQ(m.db().ErrorDetail.Number, 0u);
  EXPECT_FALSE(torque.Error);
  // The loop did what it is about: clampings at both stops, each released again.
  EXPECT_GE(clamps, kCycles / 10000) << "releases " << releases << " limitations " << limitations;
  EXPECT_GE(releases, clamps - 1);
  EXPECT_GE(limitations, clamps);
}

// Positioning back and forth with torque precontrol on, while MC_TorqueAdditive and MC_TorqueRange are
// switched on and off and their values change, and MC_TorqueLimiting is tried against MC_TorqueRange (the
// exclusion's error path): nothing allocates.
// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), over spec 01 §8.12/§8.13 (MC_TorqueAdditive,
// MC_TorqueRange) and spec 02 §7.5.
TEST(TorqueLimitingAllocation, TelegramSevenFiftyJobsAllocateNothing) {
  auto d = tomc::testing::linear_axis_data();
  d.TorquePreControl.Mode = 1;
  tomc::testing::PositioningAxisMachine m(d, tomc::testing::linear_drive(), 105, true, 750);
  instructions::MC_TorqueAdditive<techobjects::PositioningAxis> additive;
  instructions::MC_TorqueRange<techobjects::PositioningAxis> range;
  instructions::MC_TorqueLimiting<techobjects::PositioningAxis> limiting;
  m.user = [&] {
    additive(*m.axis);
    range(*m.axis);
    limiting(*m.axis);
  };
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  long moves = 0, exclusions = 0, nonzero_torque = 0;
  const auto before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < kCycles; ++cycle) {
    if (m.move_absolute.Done || !m.move_absolute.Busy) {
      m.move_absolute.Execute = false;
      m.run(1);
      m.move_absolute.Position = (moves % 2 == 0) ? 20.0 : 0.0;
      m.move_absolute.Velocity = 100.0;
      m.move_absolute.Execute = true;
      ++moves;
    }
    const int phase = cycle % 500;
    additive.Enable = phase < 300;
    additive.Value = 0.001 * (cycle % 97);
    range.Enable = phase >= 100 && phase < 400;
    range.UpperLimit = 3.0 + 0.001 * (cycle % 89);
    range.LowerLimit = -3.0;
    limiting.Enable = phase >= 200 && phase < 250;  // rejected: MC_TorqueRange limits
    m.run(1);
    if (limiting.Error) ++exclusions;
    if (m.axis->drive()->supplementary_setpoint().M_ADD1 != 0) ++nonzero_torque;
  }
  const auto allocated = tomc::testing::allocation_count() - before;
  EXPECT_EQ(allocated, 0u) << "allocations in " << kCycles << " cycles";
  EXPECT_EQ(m.db().ErrorDetail.Number, 0u);
  EXPECT_FALSE(additive.Error);
  EXPECT_FALSE(range.Error);
  EXPECT_GE(moves, kCycles / 1000) << "the loop positioned";
  EXPECT_GE(exclusions, kCycles / 20) << "the exclusion was exercised";
  EXPECT_GE(nonzero_torque, kCycles / 2) << "M_ADD1 was sent";
}

}  // namespace
