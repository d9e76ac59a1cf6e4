// The cam instructions (spec 07 §3.2, §3.6) through their PLCopen handshake: MC_InterpolateCam,
// MC_GetCamFollowingValue, MC_GetCamFollowingValueCyclic, MC_GetCamLeadingValue, MC_CopyCamData; and the
// cam's data-block table.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "tomc/instructions/mc_copy_cam_data.hpp"
#include "tomc/instructions/mc_get_cam_value.hpp"
#include "tomc/instructions/mc_interpolate_cam.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace {

using namespace tomc::techobjects;
using namespace tomc::instructions;
namespace eid = tomc::techobjects::error_id;

// Cam C of spec 07 §8 with following values 0…1: (0,0), (180,1), (360,0), linear.
void triangle(Cam& cam) {
  cam.write_point(1, {0.0, 0.0}, true);
  cam.write_point(2, {180.0, 1.0}, true);
  cam.write_point(3, {360.0, 0.0}, true);
}

// MC_InterpolateCam: Done on the edge call, StatusWord.X5 Interpolated, X4 CamDataChanged cleared, the range
// in StatusCam; 16#80AB while a follower uses the cam (spec 07 §3.2, §8 CM-4), the old profile staying.
TEST(CamInstructions, InterpolateCamHandshakeAndInUse) {
  Cam cam("C");
  triangle(cam);
  EXPECT_EQ(cam.read("StatusWord.X4"), 1.0);  // CamDataChanged
  EXPECT_EQ(cam.read("StatusWord.X5"), 0.0);
  MC_InterpolateCam fb;
  fb.Execute = true;
  fb(cam);
  EXPECT_TRUE(fb.Done);
  EXPECT_FALSE(fb.Busy);
  EXPECT_FALSE(fb.Error);
  EXPECT_EQ(cam.read("StatusWord.X5"), 1.0);
  EXPECT_EQ(cam.read("StatusWord.X4"), 0.0);
  EXPECT_EQ(cam.read("StatusCam.StartLeadingValue"), 0.0);
  EXPECT_EQ(cam.read("StatusCam.EndLeadingValue"), 360.0);
  EXPECT_EQ(cam.read("StatusCam.NumberOfValidPoints"), 3.0);
  fb(cam);
  EXPECT_TRUE(fb.Done);  // stays while Execute stays TRUE (spec 03 §3.2 E5)
  fb.Execute = false;
  fb(cam);
  EXPECT_FALSE(fb.Done);

  cam.acquire();  // MC_CamIn uses the cam
  EXPECT_EQ(cam.read("StatusWord.X0"), 1.0);
  cam.write_point(4, {720.0, 0.0}, true);
  fb.Execute = true;
  fb(cam);
  EXPECT_TRUE(fb.Error);
  EXPECT_EQ(fb.ErrorID, eid::kCamInUse);
  EXPECT_EQ(cam.profile().end(), 360.0);  // the cam in use is untouched
  EXPECT_EQ(cam.read("StatusWord.X5"), 1.0);
  cam.release();
  EXPECT_EQ(cam.read("StatusWord.X0"), 0.0);
  fb.Execute = false;
  fb(cam);
  fb.Execute = true;
  fb(cam);
  EXPECT_TRUE(fb.Done);
  EXPECT_EQ(cam.profile().end(), 720.0);
}

// MC_GetCamLeadingValue, the manual's example (spec 07 §3.6): following value 0.5 with approach 225 →
// direction 1: 270, direction 2: 90, direction 3: 270. An approach value that is itself a solution is
// returned only by direction 3.
TEST(CamInstructions, GetCamLeadingValueManualExample) {
  Cam cam("C");
  triangle(cam);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  struct Row {
    double approach;
    std::int32_t direction;
    double value;
    std::uint16_t error;
  };
  const std::array<Row, 9> rows{{
      {225.0, 1, 270.0, 0},
      {225.0, 2, 90.0, 0},
      {225.0, 3, 270.0, 0},
      {90.0, 3, 90.0, 0},
      {90.0, 1, 270.0, 0},
      {90.0, 2, 0.0, eid::kCamEndReached},  // nothing below 90 before the cam starts
      {300.0, 1, 0.0, eid::kCamEndReached},
      {225.0, 4, 0.0, eid::kInvalidApproachDirection},
      {225.0, 0, 0.0, eid::kInvalidApproachDirection},
  }};
  for (const Row& r : rows) {
    MC_GetCamLeadingValue fb;
    fb.FollowingValue = 0.5;
    fb.ApproachLeadingValue = r.approach;
    fb.ApproachDirection = r.direction;
    fb.Execute = true;
    fb(cam);
    EXPECT_EQ(fb.Done, r.error == 0) << r.approach << " " << r.direction;
    EXPECT_EQ(fb.ErrorID, r.error) << r.approach << " " << r.direction;
    EXPECT_NEAR(fb.Value, r.value, 1e-9) << r.approach << " " << r.direction;
  }
  // No solution at all (16#8063), the approach value not a number (16#8062), SlaveScaling 0 (16#8024).
  MC_GetCamLeadingValue fb;
  fb.Execute = true;
  fb.FollowingValue = 2.0;
  fb.ApproachLeadingValue = 100.0;
  fb(cam);
  EXPECT_EQ(fb.ErrorID, eid::kNoLeadingValue);
  MC_GetCamLeadingValue nan_fb;
  nan_fb.Execute = true;
  nan_fb.ApproachLeadingValue = std::nan("");
  nan_fb(cam);
  EXPECT_EQ(nan_fb.ErrorID, eid::kInvalidApproachValue);
  MC_GetCamLeadingValue zero_fb;
  zero_fb.Execute = true;
  zero_fb.SlaveScaling = 0.0;
  zero_fb(cam);
  EXPECT_EQ(zero_fb.ErrorID, eid::kInvalidSlaveScaling);
}

// The approach value refers to the scaled and shifted leading values (spec 07 §3.6); a touching root (the
// maximum of a smooth cam) is found too.
TEST(CamInstructions, GetCamLeadingValueScaledAndAtAMaximum) {
  Cam cam("Sine");
  ASSERT_TRUE(cam.write_segment(1,
                                {.xmin = 0.0,
                                 .xmax = 360.0,
                                 .a0 = 0.5,
                                 .sineAmplitude = -0.5,
                                 .sinePeriod = std::numbers::pi / 180.0,
                                 .sinePhase = std::numbers::pi / 2.0},
                                true));  // 0.5 − 0.5·cos(x°): 0 … 1 … 0
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  MC_GetCamLeadingValue fb;
  fb.Execute = true;
  fb.FollowingValue = 1.0;  // only at the maximum, x = 180
  fb.ApproachLeadingValue = 0.0;
  fb.ApproachDirection = 1;
  fb(cam);
  ASSERT_TRUE(fb.Done) << fb.ErrorID;
  EXPECT_NEAR(fb.Value, 180.0, 1e-3);  // a tangent root: the position is found to √tolerance
  // MasterOffset 1000, MasterScaling 2, SlaveScaling 10, SlaveOffset 5: y = 10 at u = 90 → x = 1180.
  MC_GetCamLeadingValue scaled;
  scaled.Execute = true;
  scaled.FollowingValue = 10.0;
  scaled.MasterOffset = 1000.0;
  scaled.MasterScaling = 2.0;
  scaled.SlaveScaling = 10.0;
  scaled.SlaveOffset = 5.0;
  scaled.ApproachLeadingValue = 1000.0;
  scaled.ApproachDirection = 1;
  scaled(cam);
  ASSERT_TRUE(scaled.Done) << scaled.ErrorID;
  EXPECT_NEAR(scaled.Value, 1180.0, 1e-9);
}

// MC_GetCamFollowingValue: value and derivatives (spec 07 §3.6) with the errors 16#8064 (outside the cam),
// 16#8023 (MasterScaling 0) and tomc's 16#8150 (not interpolated).
TEST(CamInstructions, GetCamFollowingValue) {
  Cam cam("C");
  triangle(cam);
  MC_GetCamFollowingValue fb;
  fb.Execute = true;
  fb.LeadingValue = 90.0;
  fb(cam);
  EXPECT_EQ(fb.ErrorID, eid::kCamNotInterpolated);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  fb.Execute = false;
  fb(cam);
  fb.Execute = true;
  fb.SlaveScaling = 2.0;
  fb.SlaveOffset = 10.0;
  fb(cam);
  ASSERT_TRUE(fb.Done);
  EXPECT_NEAR(fb.Value, 11.0, 1e-12);
  EXPECT_NEAR(fb.FirstDerivative, 2.0 / 180.0, 1e-15);
  EXPECT_NEAR(fb.SecondDerivative, 0.0, 1e-15);
  fb.Execute = false;
  fb(cam);
  EXPECT_FALSE(fb.Done);
  EXPECT_EQ(fb.Value, 0.0);  // the result is shown with Done only
  struct Row {
    double leading;
    double master_scaling;
    std::uint16_t error;
  };
  for (const Row& r : {Row{360.5, 1.0, eid::kNoFollowingValue}, Row{-0.5, 1.0, eid::kNoFollowingValue},
                       Row{std::nan(""), 1.0, eid::kNoFollowingValue},
                       Row{90.0, 0.0, eid::kInvalidMasterScaling}, Row{360.0, 1.0, 0}, Row{0.0, 1.0, 0}}) {
    MC_GetCamFollowingValue g;
    g.Execute = true;
    g.LeadingValue = r.leading;
    g.MasterScaling = r.master_scaling;
    g(cam);
    EXPECT_EQ(g.ErrorID, r.error) << r.leading;
  }
}

// MC_GetCamFollowingValueCyclic (spec 07 §3.6; MCI8 V8 "Cyclically read the following value"): while Enable
// holds, every call reads the cam at that call's LeadingValue (the result in the same application cycle), for
// a cam of known closed form: one segment y = x² on [0, 10]. With MasterOffset 100, MasterScaling 2,
// SlaveScaling 3, SlaveOffset 5 (spec 07 §3.3: y = SS·f((x − MO)/MS) + SO) the leading value x reads
// u = (x − 100)/2, Value = 3u² + 5, FirstDerivative = 3·2u/2 = 3u, SecondDerivative = 3·2/4 = 1.5.
// Two instances on one cam; the errors of MC_GetCamFollowingValue while they last (decision C25).
TEST(CamInstructions, GetCamFollowingValueCyclic) {
  Cam cam("Parabola");
  ASSERT_TRUE(cam.write_segment(1, {.xmin = 0.0, .xmax = 10.0, .a2 = 1.0}, true));
  MC_GetCamFollowingValueCyclic a;
  a.Enable = true;
  a.LeadingValue = 3.0;
  a(cam);  // not interpolated: tomc's 16#8150, as MC_GetCamFollowingValue
  EXPECT_TRUE(a.Busy);
  EXPECT_FALSE(a.Valid);
  EXPECT_TRUE(a.Error);
  EXPECT_EQ(a.ErrorID, eid::kCamNotInterpolated);
  ASSERT_TRUE(cam.interpolate_cam().accepted());

  a.MasterOffset = 100.0;
  a.MasterScaling = 2.0;
  a.SlaveScaling = 3.0;
  a.SlaveOffset = 5.0;
  MC_GetCamFollowingValueCyclic b;  // unscaled, on the same cam
  b.Enable = true;
  // One row per application cycle: the leading value changes every call and so does the result.
  struct Cycle {
    double leading;  // of instance a (scaled); b reads u itself
    double u;
  };
  for (const Cycle& c : {Cycle{100.0, 0.0}, Cycle{106.0, 3.0}, Cycle{107.0, 3.5}, Cycle{115.0, 7.5},
                         Cycle{120.0, 10.0}, Cycle{101.0, 0.5}}) {
    a.LeadingValue = c.leading;
    b.LeadingValue = c.u;
    a(cam);
    b(cam);
    ASSERT_TRUE(a.Valid && a.Busy && !a.Error) << c.leading << " " << a.ErrorID;
    EXPECT_NEAR(a.Value, 3.0 * c.u * c.u + 5.0, 1e-12) << c.leading;
    EXPECT_NEAR(a.FirstDerivative, 3.0 * c.u, 1e-12) << c.leading;
    EXPECT_NEAR(a.SecondDerivative, 1.5, 1e-12) << c.leading;
    ASSERT_TRUE(b.Valid) << c.u;
    EXPECT_NEAR(b.Value, c.u * c.u, 1e-12) << c.u;
    EXPECT_NEAR(b.FirstDerivative, 2.0 * c.u, 1e-12) << c.u;
    EXPECT_NEAR(b.SecondDerivative, 2.0, 1e-12) << c.u;
  }

  // Outside the scaled cam (u = 10.5): 16#8064 while it lasts, Busy stays, the values are not shown; back
  // inside, the next call is valid again without a new Enable edge.
  a.LeadingValue = 121.0;
  a(cam);
  EXPECT_TRUE(a.Busy);
  EXPECT_FALSE(a.Valid);
  EXPECT_TRUE(a.Error);
  EXPECT_EQ(a.ErrorID, eid::kNoFollowingValue);
  EXPECT_EQ(a.Value, 0.0);
  a.LeadingValue = 104.0;
  a(cam);
  ASSERT_TRUE(a.Valid);
  EXPECT_FALSE(a.Error);
  EXPECT_EQ(a.ErrorID, 0);
  EXPECT_NEAR(a.Value, 17.0, 1e-12);
  a.MasterScaling = 0.0;  // 16#8023
  a(cam);
  EXPECT_EQ(a.ErrorID, eid::kInvalidMasterScaling);
  EXPECT_FALSE(a.Valid);
  b(cam);  // the other instance is not affected
  EXPECT_TRUE(b.Valid);

  // Enable FALSE: nothing is read, every output is reset.
  a.Enable = false;
  a(cam);
  EXPECT_FALSE(a.Busy || a.Valid || a.Error);
  EXPECT_EQ(a.ErrorID, 0);
  EXPECT_EQ(a.Value, 0.0);
  EXPECT_EQ(a.FirstDerivative, 0.0);
  EXPECT_EQ(a.SecondDerivative, 0.0);
  // A cyclic read does not use the cam (StatusWord.X0): MC_InterpolateCam stays possible meanwhile.
  EXPECT_EQ(cam.users(), 0u);
  EXPECT_TRUE(cam.interpolate_cam().accepted());
  b(cam);
  EXPECT_TRUE(b.Valid);
}

// MC_CopyCamData (spec 07 §3.6): Mode 0 invalidates every element first, Mode 1 keeps them; the copied
// elements become valid; the result counts after the next MC_InterpolateCam; ranges are checked.
TEST(CamInstructions, CopyCamData) {
  Cam cam("C");
  triangle(cam);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  const std::vector<TO_Cam_Struct_PointData> points{{-5.0, 0.0}, {0.0, 1.0}, {10.0, 2.0}, {20.0, 0.0}};
  MC_CopyCamData copy;
  copy.Mode = 0;
  copy.StartPointCam = 1;
  copy.StartPointArray = 1;  // skip (-5, 0)
  copy.NumberOfPoints = 3;
  copy.ArrayOfPoints = points;
  copy.Execute = true;
  copy(cam);
  ASSERT_TRUE(copy.Done) << copy.ErrorID;
  EXPECT_EQ(cam.read("StatusWord.X4"), 1.0);
  EXPECT_EQ(cam.profile().end(), 360.0);  // used only after the next MC_InterpolateCam
  EXPECT_EQ(cam.data().StatusCam.NumberOfValidPoints, 3u);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  EXPECT_EQ(cam.data().StatusCam.StartLeadingValue, 0.0);
  EXPECT_EQ(cam.data().StatusCam.EndLeadingValue, 20.0);
  EXPECT_NEAR(cam.profile().evaluate(5.0).y, 1.5, 1e-12);

  // Mode 1 appends point 4 and a segment, keeping points 1…3.
  const std::array<TO_Cam_Struct_SegmentData, 1> segments{{{.xmin = 30.0, .xmax = 40.0, .a0 = 0.0}}};
  MC_CopyCamData append;
  append.Mode = 1;
  append.StartPointCam = 4;
  append.NumberOfPoints = 1;
  append.ArrayOfPoints = std::span(points).subspan(3);
  append.NumberOfSegments = 1;
  append.ArrayOfSegments = segments;
  append.Execute = true;
  append(cam);
  ASSERT_TRUE(append.Done) << append.ErrorID;
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  EXPECT_EQ(cam.data().StatusCam.NumberOfValidPoints, 4u);  // point 4 = (20, 0) again: the later one wins
  EXPECT_EQ(cam.data().StatusCam.EndLeadingValue, 40.0);

  struct Row {
    std::int32_t mode, start_cam, start_array, count;
    std::uint16_t error;
  };
  for (const Row& r :
       {Row{2, 1, 0, 1, eid::kInvalidMode}, Row{0, 0, 0, 1, eid::kInvalidCamElementRange},
        Row{0, 1000, 0, 2, eid::kInvalidCamElementRange}, Row{0, 1, 3, 2, eid::kInvalidCamElementRange},
        Row{0, 1, 0, -1, eid::kInvalidCamElementRange}, Row{0, 999, 2, 2, 0}}) {
    MC_CopyCamData c;
    c.Mode = r.mode;
    c.StartPointCam = r.start_cam;
    c.StartPointArray = r.start_array;
    c.NumberOfPoints = r.count;
    c.ArrayOfPoints = points;
    c.Execute = true;
    c(cam);
    EXPECT_EQ(c.ErrorID, r.error) << r.mode << " " << r.start_cam << " " << r.start_array << " " << r.count;
  }
}

// The data-block table of the cam (spec 07 §3.1): InterpolationSettings are CAL with their ranges, the
// status variables are read-only.
TEST(CamInstructions, DataBlockTable) {
  Cam cam("C");
  EXPECT_TRUE(cam.write("InterpolationSettings.InterpolationMode", 2.0).ok());
  EXPECT_EQ(cam.data().InterpolationSettings.InterpolationMode, 2);
  EXPECT_EQ(cam.write("InterpolationSettings.InterpolationMode", 3.0).value, ValueError::kOutOfRange);
  EXPECT_EQ(cam.write("InterpolationSettings.BoundaryConditions", 0.5).value, ValueError::kNotInteger);
  EXPECT_EQ(cam.write("StatusCam.EndLeadingValue", 1.0).access, AccessError::kStatusVariable);
  EXPECT_EQ(cam.write("StatusWord", 1.0).access, AccessError::kStatusVariable);
  EXPECT_FALSE(cam.write("Point[1].x", 1.0).found);  // elements through write_point / MC_CopyCamData
  EXPECT_TRUE(std::isnan(cam.read("NoSuchVariable")));
  const VariableInfo* reaction = find_cam_variable("ErrorDetail.Reaction");
  ASSERT_NE(reaction, nullptr);
  EXPECT_EQ(check_value(*reaction, 9.0), ValueError::kNone);
  EXPECT_EQ(check_value(*reaction, 4.0), ValueError::kNotAllowed);
  EXPECT_EQ(cam_variables().size(), 11u);
  for (const VariableInfo& v : cam_variables())
    EXPECT_EQ(v.owner, TechnologyObjectType::kCam) << v.path;
}

}  // namespace
