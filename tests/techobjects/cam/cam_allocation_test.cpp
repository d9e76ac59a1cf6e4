// Real-time discipline of the cam (spec 07 §3; DEVELOPERS.md): what a follower does every cycle with an
// interpolated cam — evaluating it, scaled lookups, the read instructions, use counting — allocates nothing,
// for every interpolation mode and the largest variant. MC_InterpolateCam itself allocates (decisions C2) and
// runs before the counted part.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "counting_allocator.hpp"
#include "tomc/instructions/mc_get_cam_value.hpp"
#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/cam/cam_synchronous_function.hpp"

namespace {

using namespace tomc::techobjects;
using namespace tomc::instructions;

// spec 07 §3.6 (the read instructions); decision C2 (only MC_InterpolateCam allocates).
TEST(CamAllocation, EvaluationAndReadInstructionsAllocateNothing) {
  for (const auto mode : {0.0, 1.0, 2.0}) {
    Cam cam("Cam10k", CamVariant::kCam10k);
    ASSERT_TRUE(cam.write("InterpolationSettings.InterpolationMode", mode).ok());
    for (std::size_t i = 1; i <= 10000; ++i)
      ASSERT_TRUE(cam.write_point(i, {0.1 * static_cast<double>(i), static_cast<double>(i % 7)}, true));
    ASSERT_TRUE(cam.interpolate_cam().accepted());
    MC_GetCamFollowingValue following;
    MC_GetCamLeadingValue leading;
    MC_GetCamFollowingValueCyclic cyclic;
    cyclic.Enable = true;
    double sum = 0.0;
    const std::uint64_t before = tomc::testing::allocation_count();
    for (int cycle = 0; cycle < 2000; ++cycle) {
      const double x = 0.1 + 0.49 * cycle;
      sum += cam.profile().evaluate(x).y;
      sum += following_value(cam.profile(), 3.0 * x, {0.0, 1.0, 3.0, 2.0}).value.dy;
      following.Execute = (cycle % 2) == 0;
      following.LeadingValue = x;
      following(cam);
      cyclic.LeadingValue = 2.0 * x;  // leaves the cam (0.1…1,000) halfway: the error path too
      cyclic(cam);
      sum += cyclic.Value;
      leading.Execute = (cycle % 400) == 0;  // a search over all 10,000 pieces
      leading.FollowingValue = 3.5;
      leading.ApproachLeadingValue = x;
      leading(cam);
      cam.acquire();
      cam.release();
    }
    EXPECT_EQ(tomc::testing::allocation_count(), before) << mode;
    EXPECT_TRUE(std::isfinite(sum));
  }
}

// Camming's synchronous function switching between cams every 100 cycles (as MC_CamIn profile 5 would at the
// end of a cam) and between application modes: no allocation.
// spec 07 §3.4 (MC_CamIn profile 5), §3.3 (application modes); decision C10.
TEST(CamAllocation, SynchronousFunctionWithCamSwitchingAllocatesNothing) {
  Cam a("A");
  Cam b("B", CamVariant::kCam10k);
  ASSERT_TRUE(b.write("InterpolationSettings.InterpolationMode", 1.0).ok());
  for (std::size_t i = 1; i <= 1000; ++i)
    ASSERT_TRUE(a.write_point(i, {0.36 * static_cast<double>(i - 1), static_cast<double>(i % 5)}, true));
  for (std::size_t i = 1; i <= 10000; ++i)
    ASSERT_TRUE(b.write_point(i, {0.036 * static_cast<double>(i - 1), static_cast<double>(i % 11)}, true));
  ASSERT_TRUE(a.interpolate_cam().accepted());
  ASSERT_TRUE(b.interpolate_cam().accepted());
  CamSynchronousFunction f;
  double sum = 0.0;
  const std::uint64_t before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < 20000; ++cycle) {
    if (cycle % 100 == 0) {
      Cam& next = (cycle / 100) % 2 == 0 ? a : b;
      const auto mode = static_cast<CamApplicationMode>((cycle / 100) % 3);
      if (f.active()) ((cycle / 100) % 2 == 0 ? b : a).release();
      next.acquire();
      f.start(next.profile(), {0.0, 1.0, 1.0, 2.0}, mode);
    }
    const CamFollowingValue v = f.evaluate(0.7 * cycle, 700.0, 0.0);
    sum += v.position + v.velocity + v.acceleration;
  }
  EXPECT_EQ(tomc::testing::allocation_count(), before);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
