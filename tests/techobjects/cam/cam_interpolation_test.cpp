// TO_Cam interpolation (spec 07 §3.1–§3.3) against closed forms: segments reproduced, quintic transitions,
// natural and periodic cubic splines, the B-spline ("Bézier") mode, the VDI 2143 motion laws, the boundary
// rules (overlaps, points under segments), scaling and shifting.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/cam/vdi2143.hpp"

namespace {

using namespace tomc::techobjects;
namespace eid = tomc::techobjects::error_id;

constexpr double kPi = std::numbers::pi;

void set_points(Cam& cam, const std::vector<TO_Cam_Struct_PointData>& points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    ASSERT_TRUE(cam.write_point(i + 1, points[i], true));
}

void set_mode(Cam& cam, CamInterpolationMode mode, CamBoundaryConditions bc = CamBoundaryConditions::kNone) {
  ASSERT_TRUE(cam.write("InterpolationSettings.InterpolationMode", static_cast<double>(mode)).ok());
  ASSERT_TRUE(cam.write("InterpolationSettings.BoundaryConditions", static_cast<double>(bc)).ok());
}

// Deterministic "random" points with rising x (a linear congruential generator, no std::random state).
std::vector<TO_Cam_Struct_PointData> scattered_points(std::size_t n, std::uint32_t seed) {
  std::vector<TO_Cam_Struct_PointData> p;
  double x = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    seed = seed * 1664525u + 1013904223u;
    const double r1 = static_cast<double>(seed >> 8) / 16777216.0;
    seed = seed * 1664525u + 1013904223u;
    const double r2 = static_cast<double>(seed >> 8) / 16777216.0;
    p.push_back({x, 100.0 * (r2 - 0.5)});
    x += 0.5 + 9.5 * r1;  // intervals 0.5 ... 10
  }
  return p;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::max(1.0, std::abs(b));
}

// spec 07 §3.1: a segment is y = a6·x⁶ + … + a0 + b0·sin(b1·x + b2) with absolute x (O-7); the cam
// reproduces it to rounding over its whole range.
TEST(CamInterpolation, SegmentPolynomialOfDegreeSixWithSineReproduced) {
  Cam cam("Cam1");
  TO_Cam_Struct_SegmentData s;
  s.xmin = -2.0;
  s.xmax = 3.0;
  s.a0 = 1.5;
  s.a1 = -0.25;
  s.a2 = 0.75;
  s.a3 = -0.125;
  s.a4 = 0.0625;
  s.a5 = -0.03125;
  s.a6 = 0.015625;
  s.sineAmplitude = 0.4;
  s.sinePeriod = 2.0;
  s.sinePhase = 0.3;
  ASSERT_TRUE(cam.write_segment(1, s, true));
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  EXPECT_EQ(cam.data().StatusCam.StartLeadingValue, -2.0);
  EXPECT_EQ(cam.data().StatusCam.EndLeadingValue, 3.0);
  for (int i = 0; i <= 500; ++i) {
    const double x = -2.0 + 5.0 * i / 500.0;
    const std::array<double, 7> a{s.a0, s.a1, s.a2, s.a3, s.a4, s.a5, s.a6};
    double y = 0.0, dy = 0.0, ddy = 0.0;
    for (int k = 0; k < 7; ++k) {
      y += a[k] * std::pow(x, k);
      if (k >= 1) dy += k * a[k] * std::pow(x, k - 1);
      if (k >= 2) ddy += k * (k - 1) * a[k] * std::pow(x, k - 2);
    }
    y += 0.4 * std::sin(2.0 * x + 0.3);
    dy += 0.8 * std::cos(2.0 * x + 0.3);
    ddy -= 1.6 * std::sin(2.0 * x + 0.3);
    const CamValue v = cam.profile().evaluate(x);
    EXPECT_LT(relative(v.y, y), 1e-13) << x;
    EXPECT_LT(relative(v.dy, dy), 1e-13) << x;
    EXPECT_LT(relative(v.ddy, ddy), 1e-13) << x;
  }
}

// spec 07 §3.2 [IMPL]: a transition matches position, velocity and acceleration at both ends with a quintic.
// Two segments cut from one quintic leave a gap that only that quintic closes: the transition is it.
TEST(CamInterpolation, QuinticTransitionReproducesTheQuinticItBridges) {
  const std::array<double, 6> q{2.0, -1.0, 0.5, 0.02, -0.003, 0.0001};  // y = Σ q_k x^k
  Cam cam("Cam1");
  TO_Cam_Struct_SegmentData left{
      .xmin = 0.0, .xmax = 4.0, .a0 = q[0], .a1 = q[1], .a2 = q[2], .a3 = q[3], .a4 = q[4], .a5 = q[5]};
  TO_Cam_Struct_SegmentData right = left;
  right.xmin = 9.0;
  right.xmax = 12.0;
  ASSERT_TRUE(cam.write_segment(1, left, true));
  ASSERT_TRUE(cam.write_segment(2, right, true));
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  ASSERT_EQ(cam.profile().pieces().size(), 3u);  // segment, transition [4, 9], segment
  EXPECT_EQ(cam.profile().pieces()[1].x0, 4.0);
  EXPECT_EQ(cam.profile().pieces()[1].x1, 9.0);
  for (int i = 0; i <= 100; ++i) {
    const double x = 4.0 + 5.0 * i / 100.0;
    double y = 0.0;
    for (int k = 5; k >= 0; --k)
      y = y * x + q[static_cast<std::size_t>(k)];
    EXPECT_LT(relative(cam.profile().evaluate(x).y, y), 1e-11) << x;
  }
  EXPECT_LT(cam.profile().continuity().max_step[2], 1e-9);
}

// A gap below 1e-4 is closed by joining the elements (SYNC8 "Boundary conditions"), no transition.
// spec 07 §3.1 (boundary rules: gaps), §3.2; decision C4 (gaps of 1e-4 or more get a transition).
TEST(CamInterpolation, GapBelowTheToleranceIsJoined) {
  Cam cam("Cam1");
  ASSERT_TRUE(cam.write_segment(1, {.xmin = 0.0, .xmax = 1.0, .a1 = 1.0}, true));
  ASSERT_TRUE(cam.write_segment(2, {.xmin = 1.00005, .xmax = 2.0, .a1 = 1.0}, true));
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  ASSERT_EQ(cam.profile().pieces().size(), 2u);
  EXPECT_EQ(cam.profile().pieces()[1].x0, 1.0);
}

// Every mode reproduces a straight line through its points exactly (linear, spline, B-spline: the Greville
// control polygon of a line is the line).
// spec 07 §3.2 (InterpolationMode 0, 1, 2); decision C4.
TEST(CamInterpolation, EveryModeReproducesAStraightLine) {
  for (const auto mode : {CamInterpolationMode::kLinear, CamInterpolationMode::kCubicSpline,
                          CamInterpolationMode::kBezierSpline}) {
    Cam cam("Cam1");
    set_mode(cam, mode);
    std::vector<TO_Cam_Struct_PointData> pts;
    for (double x : {0.0, 1.0, 2.5, 7.0, 7.5, 12.0})
      pts.push_back({x, 3.0 * x - 4.0});
    set_points(cam, pts);
    ASSERT_TRUE(cam.interpolate_cam().accepted());
    for (int i = 0; i <= 240; ++i) {
      const double x = 12.0 * i / 240.0;
      const CamValue v = cam.profile().evaluate(x);
      EXPECT_NEAR(v.y, 3.0 * x - 4.0, 1e-12) << static_cast<int>(mode) << " " << x;
      EXPECT_NEAR(v.dy, 3.0, 1e-12);
      EXPECT_NEAR(v.ddy, 0.0, 1e-11);
    }
  }
}

// Natural cubic spline through (0,0), (1,1), (2,0): M1 = −3, s(u) = 1.5u − 0.5u³ on [0, 1] (closed form).
// spec 07 §3.2 (cubic spline interpolation), decision C4 (natural spline: M = 0 at the ends).
TEST(CamInterpolation, NaturalCubicSplineClosedForm) {
  Cam cam("Cam1");
  set_mode(cam, CamInterpolationMode::kCubicSpline);
  set_points(cam, {{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}});
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  EXPECT_NEAR(cam.profile().evaluate(0.5).y, 0.6875, 1e-15);
  EXPECT_NEAR(cam.profile().evaluate(1.0).ddy, -3.0, 1e-14);
  EXPECT_NEAR(cam.profile().evaluate(0.0).ddy, 0.0, 1e-15);   // natural ends
  EXPECT_NEAR(cam.profile().evaluate(1.5).y, 0.6875, 1e-15);  // symmetric
}

// Cubic spline ("C splines", spec 07 §3.2): through every point, continuous in position, velocity and
// acceleration to 1e-9 at every point; natural ends without BoundaryConditions, equal first and second
// derivatives at start and end with BoundaryConditions = 1 (spec 07 §3.1, §3.3 cyclic use).
TEST(CamInterpolation, CubicSplineContinuityNaturalAndPeriodic) {
  for (const auto bc : {CamBoundaryConditions::kNone, CamBoundaryConditions::kEqualFirstDerivative}) {
    for (const std::size_t n : {3u, 4u, 17u, 1000u}) {
      Cam cam("Cam1");
      set_mode(cam, CamInterpolationMode::kCubicSpline, bc);
      const auto pts = scattered_points(n, 7u + static_cast<std::uint32_t>(n));
      set_points(cam, pts);
      ASSERT_TRUE(cam.interpolate_cam().accepted()) << n;
      ASSERT_EQ(cam.profile().pieces().size(), n - 1);
      for (const auto& p : pts)
        EXPECT_NEAR(cam.profile().evaluate(p.x).y, p.y, 1e-9);
      const CamContinuity& c = cam.profile().continuity();
      EXPECT_LT(c.max_step[0], 1e-9) << n;
      EXPECT_LT(c.max_step[1], 1e-9) << n;
      EXPECT_LT(c.max_step[2], 1e-9) << n;
      const CamValue start = cam.profile().evaluate(pts.front().x);
      const CamValue end = cam.profile().evaluate(pts.back().x);
      if (bc == CamBoundaryConditions::kNone) {
        EXPECT_NEAR(start.ddy, 0.0, 1e-9);
        EXPECT_NEAR(end.ddy, 0.0, 1e-9);
      } else {
        EXPECT_NEAR(c.end_minus_start[1], 0.0, 1e-9) << n;
        EXPECT_NEAR(c.end_minus_start[2], 0.0, 1e-9) << n;
        EXPECT_NEAR(end.dy, start.dy, 1e-9);
      }
    }
  }
}

// A cyclic cam from points: sin over one period with BoundaryConditions = 1 is C² across the period end too,
// and close to sin (spline error O(h⁴)).
// spec 07 §3.2 (cubic spline, BoundaryConditions 1); decision C4.
TEST(CamInterpolation, PeriodicSplineOfASineIsCloseToTheSine) {
  Cam cam("Cam1");
  set_mode(cam, CamInterpolationMode::kCubicSpline, CamBoundaryConditions::kEqualFirstDerivative);
  std::vector<TO_Cam_Struct_PointData> pts;
  for (int i = 0; i <= 36; ++i)
    pts.push_back({10.0 * i, std::sin(kPi * i / 18.0)});
  set_points(cam, pts);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  for (int i = 0; i <= 3600; ++i) {
    const double x = 0.1 * i;
    EXPECT_NEAR(cam.profile().evaluate(x).y, std::sin(x * kPi / 180.0), 2e-5) << x;
  }
  EXPECT_NEAR(cam.profile().evaluate(0.0).dy, kPi / 180.0, 1e-5);
}

// "Bézier spline" (spec 07 §3.2: shaped by the points without passing through them all, range not
// enlarged): the B-spline of decisions C4 starts and ends at the end points, stays inside the range of the
// points and is C² to 1e-9.
TEST(CamInterpolation, BezierSplineStaysInRangeAndIsC2) {
  Cam cam("Cam1");
  set_mode(cam, CamInterpolationMode::kBezierSpline);
  const auto pts = scattered_points(40, 99u);
  set_points(cam, pts);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  const auto [lo, hi] =
      std::minmax_element(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.y < b.y; });
  for (int i = 0; i <= 10000; ++i) {
    const double x = pts.front().x + (pts.back().x - pts.front().x) * i / 10000.0;
    const double y = cam.profile().evaluate(x).y;
    EXPECT_GE(y, lo->y - 1e-9);
    EXPECT_LE(y, hi->y + 1e-9);
  }
  EXPECT_NEAR(cam.profile().evaluate(pts.front().x).y, pts.front().y, 1e-12);
  EXPECT_NEAR(cam.profile().evaluate(pts.back().x).y, pts.back().y, 1e-12);
  const CamContinuity& c = cam.profile().continuity();
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_LT(c.max_step[k], 1e-9) << k;
  // Not an interpolation: some inner point is missed (the spline smooths).
  EXPECT_TRUE(std::any_of(pts.begin() + 1, pts.end() - 1, [&](const auto& p) {
    return std::abs(cam.profile().evaluate(p.x).y - p.y) > 1e-3;
  }));
}

// Boundary rules (SYNC8 "Show elements used > Boundary conditions"): a later segment over an earlier one is
// used over its whole range and the earlier one continues after it; a segment wins over points in its
// range; for points with the same x the later one wins.
// spec 07 §3.1 (boundary rules of the elements).
TEST(CamInterpolation, OverlapsAndPointsUnderSegments) {
  Cam cam("Cam1");
  ASSERT_TRUE(cam.write_segment(1, {.xmin = 0.0, .xmax = 100.0, .a0 = 1.0}, true));
  ASSERT_TRUE(cam.write_segment(2, {.xmin = 40.0, .xmax = 60.0, .a0 = 2.0}, true));
  set_points(cam, {{50.0, 9.0}, {120.0, 1.0}, {150.0, 5.0}, {150.0, 1.0}});
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  EXPECT_EQ(cam.profile().evaluate(20.0).y, 1.0);
  EXPECT_EQ(cam.profile().evaluate(50.0).y, 2.0);            // segment 2, not the point (50, 9)
  EXPECT_EQ(cam.profile().evaluate(80.0).y, 1.0);            // segment 1 continues after segment 2
  EXPECT_NEAR(cam.profile().evaluate(135.0).y, 1.0, 1e-12);  // (150, 5) replaced by (150, 1)
  EXPECT_EQ(cam.data().StatusCam.NumberOfValidPoints, 4u);
  EXPECT_EQ(cam.data().StatusCam.NumberOfValidSegments, 2u);
  // pieces: seg1 [0,40], seg2 [40,60], seg1 [60,100], transition [100,120], line [120,150]
  ASSERT_EQ(cam.profile().pieces().size(), 5u);
  EXPECT_EQ(cam.data().StatusCam.EndLeadingValue, 150.0);
}

// The manual's errors of MC_InterpolateCam (spec 07 §3.2, §8 CM-4; docs/errors.md).
TEST(CamInterpolation, ErrorsOfInterpolateCam) {
  struct Case {
    const char* what;
    std::vector<TO_Cam_Struct_PointData> points;
    std::vector<TO_Cam_Struct_SegmentData> segments;
    std::uint16_t error;
    CamDefect defect;
    std::uint32_t element;
  };
  const double nan = std::nan("");
  const std::vector<Case> cases{
      {"empty", {}, {}, eid::kCamEmpty, CamDefect::kEmpty, 0},
      {"single point (CM-4)", {{10.0, 1.0}}, {}, eid::kCamInvalid, CamDefect::kSinglePoint, 0},
      {"points out of order",
       {{0.0, 0.0}, {10.0, 1.0}, {5.0, 2.0}},
       {},
       eid::kCamInvalid,
       CamDefect::kPointsNotAscending,
       3},
      {"segment xmin = xmax",
       {},
       {{.xmin = 5.0, .xmax = 5.0}},
       eid::kCamInvalid,
       CamDefect::kSegmentRange,
       1},
      {"segment xmin > xmax",
       {},
       {{.xmin = 0.0, .xmax = 1.0}, {.xmin = 6.0, .xmax = 5.0}},
       eid::kCamInvalid,
       CamDefect::kSegmentRange,
       2},
      {"point not finite", {{0.0, 0.0}, {nan, 1.0}}, {}, eid::kCamInvalid, CamDefect::kNotFinite, 2},
  };
  for (const Case& c : cases) {
    Cam cam("Cam1");
    set_points(cam, c.points);
    for (std::size_t i = 0; i < c.segments.size(); ++i)
      ASSERT_TRUE(cam.write_segment(i + 1, c.segments[i], true));
    const Submission s = cam.interpolate_cam();
    EXPECT_FALSE(s.accepted()) << c.what;
    EXPECT_EQ(s.error_id, c.error) << c.what;
    EXPECT_EQ(cam.last_interpolation().defect, c.defect) << c.what;
    EXPECT_EQ(cam.last_interpolation().element, c.element) << c.what;
    EXPECT_FALSE(cam.interpolated()) << c.what;
    EXPECT_TRUE(cam.profile().empty()) << c.what;
  }
}

// Invalid points are ignored: one valid point among invalid ones is still a single point.
// spec 07 §3.1 (only valid elements are interpolated).
TEST(CamInterpolation, InvalidElementsAreIgnored) {
  Cam cam("Cam1");
  ASSERT_TRUE(cam.write_point(1, {0.0, 0.0}, true));
  ASSERT_TRUE(cam.write_point(2, {1.0, 5.0}, false));
  EXPECT_EQ(cam.interpolate_cam().error_id, eid::kCamInvalid);
  ASSERT_TRUE(cam.write_point(3, {2.0, 4.0}, true));
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  EXPECT_DOUBLE_EQ(cam.profile().evaluate(1.0).y, 2.0);
}

// The size variants (spec 07 §3.1, O-8): arrays sized at configuration; a TO_Cam_10k takes 10,000 points.
TEST(CamInterpolation, SizeVariants) {
  struct Row {
    CamVariant variant;
    std::size_t points;
    std::size_t segments;
    const char* name;
  };
  for (const Row& r :
       {Row{CamVariant::kCam, 1000, 50, "TO_Cam"}, Row{CamVariant::kCam10k, 10000, 50, "TO_Cam_10k"},
        Row{CamVariant::kCam600Seg, 1000, 600, "TO_Cam_600Seg"},
        Row{CamVariant::kCam6kSeg, 10000, 6000, "TO_Cam_6kSeg"}}) {
    Cam cam("Cam1", r.variant);
    EXPECT_EQ(cam.data().Point.size(), r.points);
    EXPECT_EQ(cam.data().Segment.size(), r.segments);
    EXPECT_EQ(type_name(r.variant), r.name);
    EXPECT_TRUE(cam.write_point(r.points, {1.0, 1.0}, true));
    EXPECT_FALSE(cam.write_point(r.points + 1, {1.0, 1.0}, true));
    EXPECT_FALSE(cam.write_point(0, {1.0, 1.0}, true));
    EXPECT_FALSE(cam.write_segment(r.segments + 1, {}, true));
  }
  Cam big("Cam10k", CamVariant::kCam10k);
  set_mode(big, CamInterpolationMode::kCubicSpline);
  set_points(big, scattered_points(10000, 3u));
  ASSERT_TRUE(big.interpolate_cam().accepted());
  EXPECT_EQ(big.profile().pieces().size(), 9999u);
  EXPECT_LT(big.profile().continuity().max_step[2], 1e-9);
}

// VDI 2143 motion laws (spec 07 §3.2) as segments from (x0, y0) = (100, 10) to (x1, y1) = (190, 55): the end
// points, the boundary velocities, the value at the middle and the characteristic values C_v = max|y'|·L/h
// and C_a = max|y''|·L²/h of the normalized law (VDI 2143 table).
TEST(CamInterpolation, Vdi2143MotionLaws) {
  struct Law {
    MotionLaw law;
    std::size_t segments;
    double end_slope;  // y' at both ends, normalized (·L/h)
    double middle;     // y at ξ = 1/2, normalized
    double cv;
    double ca;
  };
  const std::array<Law, 6> laws{{
      {MotionLaw::kLine, 1, 1.0, 0.5, 1.0, 0.0},
      {MotionLaw::kQuadraticParabola, 2, 0.0, 0.5, 2.0, 4.0},
      {MotionLaw::kSimpleSine, 1, 0.0, 0.5, kPi / 2.0, kPi * kPi / 2.0},
      {MotionLaw::kInclinedSine, 1, 0.0, 0.5, 2.0, 2.0 * kPi},
      {MotionLaw::kPolynomial5, 1, 0.0, 0.5, 1.875, 10.0 / std::sqrt(3.0)},
      {MotionLaw::kModifiedSine, 3, 0.0, 0.5, 4.0 * kPi / (4.0 + kPi), 4.0 * kPi * kPi / (4.0 + kPi)},
  }};
  const double x0 = 100.0, y0 = 10.0, x1 = 190.0, y1 = 55.0, l = x1 - x0, h = y1 - y0;
  for (const Law& law : laws) {
    std::array<TO_Cam_Struct_SegmentData, kMaxLawSegments> out{};
    const std::size_t n = motion_law_segments(law.law, x0, y0, x1, y1, out);
    ASSERT_EQ(n, law.segments) << static_cast<int>(law.law);
    Cam cam("Cam1");
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_TRUE(cam.write_segment(i + 1, out[i], true));
    ASSERT_TRUE(cam.interpolate_cam().accepted());
    const CamProfile& p = cam.profile();
    EXPECT_NEAR(p.evaluate(x0).y, y0, 1e-9);
    EXPECT_NEAR(p.evaluate(x1).y, y1, 1e-9);
    EXPECT_NEAR(p.evaluate(x0).dy * l / h, law.end_slope, 1e-9);
    EXPECT_NEAR(p.evaluate(x1).dy * l / h, law.end_slope, 1e-9);
    EXPECT_NEAR((p.evaluate(x0 + 0.5 * l).y - y0) / h, law.middle, 1e-9);
    double cv = 0.0, ca = 0.0;
    for (int i = 0; i <= 90000; ++i) {
      const CamValue v = p.evaluate(x0 + l * i / 90000.0);
      cv = std::max(cv, std::abs(v.dy) * l / h);
      ca = std::max(ca, std::abs(v.ddy) * l * l / h);
    }
    EXPECT_NEAR(cv, law.cv, 1e-6) << static_cast<int>(law.law);
    EXPECT_NEAR(ca, law.ca, 1e-6) << static_cast<int>(law.law);
    // Position and velocity continuous at the inner joins; acceleration too except the parabola (a step).
    EXPECT_LT(p.continuity().max_step[0], 1e-9);
    EXPECT_LT(p.continuity().max_step[1], 1e-9);
    if (law.law != MotionLaw::kQuadraticParabola) {
      EXPECT_LT(p.continuity().max_step[2] * l * l / h, 1e-6);
    }
  }
  std::array<TO_Cam_Struct_SegmentData, 1> one{};
  EXPECT_EQ(motion_law_segments(MotionLaw::kModifiedSine, x0, y0, x1, y1, one), 0u);  // out too small
  EXPECT_EQ(motion_law_segments(MotionLaw::kLine, x1, y0, x0, y1, one), 0u);          // x1 <= x0
}

// The hinted search finds the same piece as the binary search, for every hint, at joins and inside pieces.
// tomc's own: the piece hint of the synchronous function must not change the result (docs/performance.md,
// Cams (issue 19)).
TEST(CamInterpolation, HintedFindAgreesWithBinarySearch) {
  Cam cam("Cam1");
  set_points(cam, scattered_points(50, 11u));
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  const CamProfile& p = cam.profile();
  for (const CamPiece& piece : p.pieces()) {
    for (const double x : {piece.x0, 0.5 * (piece.x0 + piece.x1), piece.x1}) {
      for (std::size_t hint = 0; hint < p.pieces().size() + 2; ++hint)
        ASSERT_EQ(p.find(x, hint), p.find(x)) << x << " " << hint;
    }
  }
}

// Scaling and shifting (spec 07 §3.3): y = SlaveScaling·f((x − MasterOffset)/MasterScaling) + SlaveOffset.
// Cam C of spec 07 §8: (0,0), (180,100), (360,0), linear. CM-1 numbers: SS 2, SO 10, L = 90 → 110.
TEST(CamInterpolation, ScalingAndShifting) {
  Cam cam("C");
  set_points(cam, {{0.0, 0.0}, {180.0, 100.0}, {360.0, 0.0}});
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  CamLookup r = following_value(cam.profile(), 90.0, {0.0, 10.0, 1.0, 2.0});
  EXPECT_EQ(r.error_id, 0);
  EXPECT_DOUBLE_EQ(r.value.y, 110.0);
  EXPECT_DOUBLE_EQ(r.value.dy, 2.0 * 100.0 / 180.0);
  // MasterScaling 2, MasterOffset 30: x = 30 + 2·90 = 210 reads f(90) = 50; the slope halves.
  r = following_value(cam.profile(), 210.0, {30.0, 0.0, 2.0, 1.0});
  EXPECT_DOUBLE_EQ(r.value.y, 50.0);
  EXPECT_DOUBLE_EQ(r.value.dy, 100.0 / 180.0 / 2.0);
  // A negative MasterScaling mirrors the cam: x = −90 reads f(90).
  r = following_value(cam.profile(), -90.0, {0.0, 0.0, -1.0, 1.0});
  EXPECT_DOUBLE_EQ(r.value.y, 50.0);
  EXPECT_DOUBLE_EQ(r.value.dy, -100.0 / 180.0);
}

}  // namespace
