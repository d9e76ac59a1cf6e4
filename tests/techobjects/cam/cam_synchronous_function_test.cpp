// The synchronous function of camming (spec 07 §3.3, §6.2) against the numbers of the spec 07 §8 camming
// scenarios CM-1 (cyclic), CM-2 (cyclic appending), CM-3 (not cyclic), with the derivatives checked against
// the motion of the leading value.
#include <gtest/gtest.h>

#include <cmath>

#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/cam/cam_synchronous_function.hpp"
#include "tomc/techobjects/cam/vdi2143.hpp"

namespace {

using namespace tomc::techobjects;

// Cam C of spec 07 §8: (0,0), (180,100), (360,0), linear.
void cam_c(Cam& cam) {
  cam.write_point(1, {0.0, 0.0}, true);
  cam.write_point(2, {180.0, 100.0}, true);
  cam.write_point(3, {360.0, 0.0}, true);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
}

// CM-1 (ApplicationMode 1, SlaveScaling 2, SlaveOffset 10 from the direct synchronous setting at F = 10):
// L = 90 → F = 2·50 + 10 = 110; at L = 360 (unwrapped, one period) F = 10 and EndOfProfile; at 450 F = 110.
// spec 07 §8 CM-1; §3.3 (scaling, ApplicationMode 1 cyclic).
TEST(CamSynchronousFunction, Cm1Cyclic) {
  Cam cam("C");
  cam_c(cam);
  CamSynchronousFunction f;
  f.start(cam.profile(), {0.0, 10.0, 1.0, 2.0}, CamApplicationMode::kCyclic);
  struct Row {
    double leader;
    double follower;
    bool end_of_profile;
  };
  for (const Row& r :
       {Row{0.0, 10.0, false}, Row{90.0, 110.0, false}, Row{359.9, 10.0 + 2.0 * 0.1 * 100.0 / 180.0, false},
        Row{360.0, 10.0, true}, Row{450.0, 110.0, false}, Row{720.0, 10.0, true}}) {
    const CamFollowingValue v = f.evaluate(r.leader, 100.0, 0.0);
    EXPECT_NEAR(v.position, r.follower, 1e-9) << r.leader;
    EXPECT_EQ(v.end_of_profile, r.end_of_profile) << r.leader;
    EXPECT_FALSE(v.ended);
  }
  // Velocity: 2·(100/180)·v on the rising half, the negative on the falling half (v = 100 °/s).
  EXPECT_NEAR(f.evaluate(450.0 + 1.0, 100.0, 0.0).velocity, 2.0 * 100.0 / 180.0 * 100.0, 1e-9);
  EXPECT_NEAR(f.evaluate(630.0, 100.0, 0.0).velocity, -2.0 * 100.0 / 180.0 * 100.0, 1e-9);
}

// CM-2: C2 = line (0,0)…(360,100), ApplicationMode 2: F = 200 at unwrapped 720, 250 at 900.
// spec 07 §8 CM-2 (ApplicationMode 2, cyclic appending), §3.3.
TEST(CamSynchronousFunction, Cm2CyclicAppending) {
  Cam cam("C2");
  cam.write_point(1, {0.0, 0.0}, true);
  cam.write_point(2, {360.0, 100.0}, true);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  CamSynchronousFunction f;
  f.start(cam.profile(), {}, CamApplicationMode::kCyclicAppending);
  EXPECT_NEAR(f.evaluate(720.0, 0.0, 0.0).position, 200.0, 1e-9);
  EXPECT_NEAR(f.evaluate(900.0, 0.0, 0.0).position, 250.0, 1e-9);
  EXPECT_EQ(f.evaluate(900.0, 0.0, 0.0).period, 2);
  EXPECT_NEAR(f.evaluate(-90.0, 0.0, 0.0).position, -25.0, 1e-9);  // backwards: one period less
}

// CM-3: C3 = 100·(10ξ³ − 15ξ⁴ + 6ξ⁵) on [0, 360], not cyclic: past 360 the operation ends with F = 100.
// spec 07 §8 CM-3 (non-cyclic end, F holds 100), decision C11.
TEST(CamSynchronousFunction, Cm3NotCyclicEnds) {
  std::array<TO_Cam_Struct_SegmentData, kMaxLawSegments> law{};
  ASSERT_EQ(motion_law_segments(MotionLaw::kPolynomial5, 0.0, 0.0, 360.0, 100.0, law), 1u);
  Cam cam("C3");
  cam.write_segment(1, law[0], true);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  CamSynchronousFunction f;
  f.start(cam.profile(), {}, CamApplicationMode::kNotCyclic);
  EXPECT_NEAR(f.evaluate(180.0, 100.0, 0.0).position, 50.0, 1e-9);
  const CamFollowingValue at_end = f.evaluate(360.0, 100.0, 0.0);
  EXPECT_FALSE(at_end.ended);
  EXPECT_NEAR(at_end.velocity, 0.0, 1e-9);  // zero slope at both ends (the law's purpose)
  const CamFollowingValue past = f.evaluate(360.1, 100.0, 0.0);
  EXPECT_TRUE(past.ended);
  EXPECT_TRUE(past.end_of_profile);
  EXPECT_NEAR(past.position, 100.0, 1e-9);
  EXPECT_EQ(past.velocity, 0.0);
}

// The derivatives are those of the following value over time: with a leader at v = 120 °/s and
// a = 50 °/s², the follower's velocity and acceleration match central differences of its position
// (MasterScaling 1.5, SlaveScaling −0.8, a spline cam).
// spec 07 §6.2 (the synchronous function: following value and its derivatives).
TEST(CamSynchronousFunction, DerivativesFollowTheLeaderMotion) {
  Cam cam("Spline");
  ASSERT_TRUE(cam.write("InterpolationSettings.InterpolationMode", 1.0).ok());
  ASSERT_TRUE(cam.write("InterpolationSettings.BoundaryConditions", 1.0).ok());
  const double ys[] = {0.0, 20.0, 35.0, 10.0, -5.0, 0.0};
  for (int i = 0; i < 6; ++i)
    cam.write_point(static_cast<std::size_t>(i + 1), {72.0 * i, ys[i]}, true);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  CamSynchronousFunction f;
  f.start(cam.profile(), {30.0, 5.0, 1.5, -0.8}, CamApplicationMode::kCyclic);
  const auto leader = [](double t) { return 100.0 + 120.0 * t + 25.0 * t * t; };
  const double dt = 1e-4;
  for (double t = 0.0; t < 8.0; t += 0.37) {
    const double v = 120.0 + 50.0 * t;
    const CamFollowingValue now = f.evaluate(leader(t), v, 50.0);
    const double before = f.evaluate(leader(t - dt), 0.0, 0.0).position;
    const double after = f.evaluate(leader(t + dt), 0.0, 0.0).position;
    EXPECT_NEAR(now.velocity, (after - before) / (2.0 * dt), 1e-4 * (1.0 + std::abs(now.velocity))) << t;
    EXPECT_NEAR(now.acceleration, (after - 2.0 * now.position + before) / (dt * dt),
                2e-2 * (1.0 + std::abs(now.acceleration)))
        << t;
  }
}

}  // namespace
