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

namespace {

using namespace tomc::techobjects;
using namespace tomc::instructions;

TEST(CamAllocation, EvaluationAndReadInstructionsAllocateNothing) {
  for (const auto mode : {0.0, 1.0, 2.0}) {
    Cam cam("Cam10k", CamVariant::kCam10k);
    ASSERT_TRUE(cam.write("InterpolationSettings.InterpolationMode", mode).ok());
    for (std::size_t i = 1; i <= 10000; ++i)
      ASSERT_TRUE(cam.write_point(i, {0.1 * static_cast<double>(i), static_cast<double>(i % 7)}, true));
    ASSERT_TRUE(cam.interpolate_cam().accepted());
    MC_GetCamFollowingValue following;
    MC_GetCamLeadingValue leading;
    double sum = 0.0;
    const std::uint64_t before = tomc::testing::allocation_count();
    for (int cycle = 0; cycle < 2000; ++cycle) {
      const double x = 0.1 + 0.49 * cycle;
      sum += cam.profile().evaluate(x).y;
      sum += following_value(cam.profile(), 3.0 * x, {0.0, 1.0, 3.0, 2.0}).value.dy;
      following.Execute = (cycle % 2) == 0;
      following.LeadingValue = x;
      following(cam);
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

}  // namespace
