// MC_PositionProfile on the positioning axis (spec 03 §4.7, seed 004 §6.8.4 and §9.7), cycle by cycle on the
// simulated drive (positioning_axis_fixture.hpp: 1 ms cycles, DynamicDefaults 100 mm/s and 1000 mm/s²,
// trapezoid). A job submitted in the user program of cycle k moves from the interpolator of cycle k+1, so the
// profile time after cycle k+n is StartTime + n ms.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "profile_motion_in_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace {

using namespace tomc;
using techobjects::StatusWord2Bit;
using techobjects::StatusWordBit;
using techobjects::TimePositionProfile;
using tomc::testing::ProfileMachine;
using tomc::testing::ramp_profile;
namespace eid = techobjects::error_id;
using Profile = instructions::MC_PositionProfile<techobjects::PositioningAxis>;

// The profile's own shape: a monotone cubic through the points, at rest at both ends, never past a point.
// Decision L1 (a monotone piecewise cubic with Fritsch–Butland slopes, velocity 0 at both ends).
TEST(TimePositionProfile, MonotoneCubicThroughThePointsAtRestAtTheEnds) {
  const TimePositionProfile p = ramp_profile();
  for (int i = 0; i < 4; ++i) {
    const auto s = techobjects::evaluate(p, p.Point[i].Time);
    EXPECT_NEAR(s.position, p.Point[i].Position, 1e-12) << i;
  }
  EXPECT_EQ(techobjects::evaluate(p, 0.0).velocity, 0.0);
  EXPECT_EQ(techobjects::evaluate(p, 0.5).velocity, 0.0);
  double last = -1.0;
  for (int k = 0; k <= 500; ++k) {  // monotone data: monotone profile
    const double y = techobjects::evaluate(p, k * 0.001).position;
    EXPECT_GE(y, last - 1e-12) << k;
    last = y;
  }
  // Velocity continuous at the inner points (left and right limits agree).
  for (int i = 1; i < 3; ++i) {
    const double t = p.Point[i].Time;
    EXPECT_NEAR(techobjects::evaluate(p, t - 1e-9).velocity, techobjects::evaluate(p, t + 1e-9).velocity,
                1e-4);
  }
  // Fritsch–Butland velocity at point 1: slopes 50 and 100 mm/s, h 0.1 and 0.3 s -> 1.2 / (0.7/50 + 0.5/100).
  EXPECT_NEAR(techobjects::evaluate(p, 0.1).velocity, 1.2 / (0.7 / 50.0 + 0.5 / 100.0), 1e-9);
  const auto d = techobjects::max_dynamics(p, 0.0);
  double v_seen = 0.0;
  double a_seen = 0.0;
  for (int k = 0; k <= 50000; ++k) {
    const auto s = techobjects::evaluate(p, k * 1e-5);
    v_seen = std::max(v_seen, std::fabs(s.velocity));
    a_seen = std::max(a_seen, std::fabs(s.acceleration));
  }
  EXPECT_NEAR(d.velocity, v_seen, 1e-3);
  EXPECT_GE(d.acceleration, a_seen - 1e-9);
  EXPECT_LE(d.acceleration, a_seen + 1.0);
}

// seed 004 §6.8.4: an axis at rest that is "ready to follow the profile directly" (relative, StartTime at the
// profile's start at rest) shows OnProfile at once; the setpoint is the profile shifted to the start
// position; the axis stops at the profile's end and Done follows after the positioning window (spec 03 §3.5).
TEST(PositionProfile, RelativeFromRestFollowsTheProfileAtOnce) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  m.run(5);
  const double x0 = m.db().Position;
  const TimePositionProfile p = ramp_profile();
  m.profile.TimePosition = &p;
  m.profile.Execute = true;
  m.run(1);  // cycle 1: the edge (the status words show it from the interpolator of cycle 2)
  ASSERT_TRUE(m.profile.Busy);
  EXPECT_TRUE(m.profile.Active);
  EXPECT_FALSE(m.x9());
  for (int n = 1; n <= 499; ++n) {  // cycle 1+n: profile time n ms
    m.run(1);
    ASSERT_NEAR(m.db().Position, x0 + techobjects::evaluate(p, n * 0.001).position, 1e-9) << n;
    ASSERT_TRUE(m.x9() && m.x10()) << n;
  }
  m.run(1);  // cycle 501: the end of the profile, at rest
  EXPECT_NEAR(m.db().Position, x0 + 40.0, 1e-9);
  EXPECT_EQ(m.db().Velocity, 0.0);
  EXPECT_FALSE(m.x10());
  EXPECT_TRUE(m.x9());  // until Done
  const int done = m.run_until([&] { return m.profile.Done; }, 200);
  EXPECT_GT(done, 10);  // MinDwellTime 10 ms
  EXPECT_FALSE(m.x9());
  EXPECT_NEAR(m.db().ActualPosition, x0 + 40.0, m.db().PositioningMonitoring.Window);
}

// seed 004 §9.7.2 "absolute profile": a transition profile with the job's dynamics to the profile's absolute
// start (X9 TRUE, X10 FALSE), then the profile. 100 mm at 100 mm/s and 1000 mm/s² = 1100 cycles.
TEST(PositionProfile, AbsoluteRunsATransitionToTheStartPoint) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  TimePositionProfile p;
  p.NumberOfPoints = 3;
  p.Point[0] = {0.0, 100.0};
  p.Point[1] = {0.2, 110.0};
  p.Point[2] = {0.4, 120.0};
  m.profile.TimePosition = &p;
  m.profile.ProfileReference = 1;
  m.profile.Velocity = 100.0;
  m.profile.Execute = true;
  m.run(1);
  int on_profile_at = -1;
  for (int k = 2; k <= 1200 && on_profile_at < 0; ++k) {
    m.run(1);
    EXPECT_TRUE(m.x9());
    if (m.x10()) on_profile_at = k;
    EXPECT_LE(m.db().Velocity, 100.0 + 1e-9);
  }
  EXPECT_EQ(on_profile_at, 1 + 1100);
  EXPECT_NEAR(m.db().Position, 100.0, 1e-9);
  m.run(400);  // cycle 1501: the end at 120 mm
  EXPECT_NEAR(m.db().Position, 120.0, 1e-9);
  EXPECT_GT(m.run_until([&] { return m.profile.Done; }, 200), 0);
}

// seed 004 §6.8.4: the transition of a relative profile brings the velocity to the profile's (here 0 at its
// start) with the job's deceleration; "its length gives the start position of the profile". MoveVelocity at
// 50 mm/s braked at 1000 mm/s²: 50 cycles, 1.25 mm.
TEST(PositionProfile, RelativeFromMotionBrakesThenStartsWhereTheTransitionEnds) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 50.0;
  m.move_velocity.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_velocity.InVelocity; }, 200), 0);
  m.run(10);
  const TimePositionProfile p = ramp_profile();
  m.profile.TimePosition = &p;
  m.profile.Execute = true;
  const double x_edge = m.db().Position;
  m.run(1);
  m.run(1);  // MC_MoveVelocity, called before MC_PositionProfile, shows the abort one cycle later
  EXPECT_TRUE(m.move_velocity.CommandAborted);  // §9.19.1 R4 x C3 = A
  EXPECT_TRUE(m.x9());
  EXPECT_FALSE(m.x10());
  const int on = m.run_until([&] { return m.x10(); }, 100);
  EXPECT_EQ(2 + on, 1 + 50);
  // The edge cycle's interpolator still moved 0.05 mm at 50 mm/s; then 1.25 mm of braking.
  const double start = x_edge + 0.05 + 50.0 * 0.05 / 2.0;
  EXPECT_NEAR(m.db().Position, start, 1e-6);
  m.run(500);
  EXPECT_NEAR(m.db().Position, start + 40.0, 1e-6);
}

// seed 004 §9.7.2 "relative profile" ③ and §6.8.3: BufferMode 1 stays pending (Busy, not Active) until the
// running profile is Done, then starts in that cycle from its end; StartTime 0.25 s of the same profile adds
// the rest of it. The appended job starts at rest and the profile moves at 0.25 s: a velocity transition.
TEST(PositionProfile, BufferMode1AppendsBehindARunningProfile) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  const double x0 = m.db().Position;
  const TimePositionProfile p = ramp_profile();
  m.profile.TimePosition = &p;
  m.profile.Execute = true;
  m.run(1);
  m.profile2.TimePosition = &p;
  m.profile2.BufferMode = 1;
  m.profile2.StartTime = 0.25;
  m.profile2.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.profile2.Busy);
  EXPECT_FALSE(m.profile2.Active);
  EXPECT_TRUE(m.profile.Active);
  const int first_done = m.run_until([&] { return m.profile.Done; }, 700);
  ASSERT_GT(first_done, 0);
  EXPECT_TRUE(m.profile2.Active);  // the same cycle (spec 03 §3.7 T-E)
  // The appended job covers its transition (0 -> v(0.25 s) at 1000 mm/s²: v²/2000) and the rest of the
  // profile.
  const auto at = techobjects::evaluate(p, 0.25);
  ASSERT_GT(m.run_until([&] { return m.profile2.Done; }, 1000), 0);
  EXPECT_NEAR(m.db().Position, x0 + 40.0 + at.velocity * at.velocity / 2000.0 + (40.0 - at.position), 1e-6);
  EXPECT_FALSE(m.profile.CommandAborted);
}

// spec 03 §3.2 E7 / T08: invalid inputs are rejected in the edge cycle: Error, an ErrorID, no motion.
TEST(PositionProfile, InvalidProfilesAndInputsAreRejectedWithTheirErrorId) {
  struct Case {
    std::string name;
    std::function<void(TimePositionProfile&, Profile&)> change;
    std::uint16_t error_id;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Case> cases = {
      {"no profile", [](TimePositionProfile&, Profile& f) { f.TimePosition = nullptr; },
       eid::kInvalidTimePositionProfile},
      {"one point", [](TimePositionProfile& p, Profile&) { p.NumberOfPoints = 1; },
       eid::kInvalidTimePositionProfile},
      {"too many points", [](TimePositionProfile& p, Profile&) { p.NumberOfPoints = 129; },
       eid::kInvalidTimePositionProfile},
      {"negative count", [](TimePositionProfile& p, Profile&) { p.NumberOfPoints = -3; },
       eid::kInvalidTimePositionProfile},
      {"times out of order", [](TimePositionProfile& p, Profile&) { p.Point[2].Time = 0.05; },
       eid::kTimePositionOutOfOrder},
      {"equal times", [](TimePositionProfile& p, Profile&) { p.Point[2].Time = p.Point[1].Time; },
       eid::kTimePositionOutOfOrder},
      {"NaN position", [nan](TimePositionProfile& p, Profile&) { p.Point[1].Position = nan; },
       eid::kTimePositionNotFinite},
      {"infinite time", [inf](TimePositionProfile& p, Profile&) { p.Point[3].Time = inf; },
       eid::kTimePositionNotFinite},
      {"StartTime at the end", [](TimePositionProfile&, Profile& f) { f.StartTime = 0.5; },
       eid::kInvalidStartTime},
      {"StartTime before the start", [](TimePositionProfile&, Profile& f) { f.StartTime = -0.1; },
       eid::kInvalidStartTime},
      {"StartTime NaN", [nan](TimePositionProfile&, Profile& f) { f.StartTime = nan; },
       eid::kInvalidStartTime},
      {"ProfileReference 2", [](TimePositionProfile&, Profile& f) { f.ProfileReference = 2; },
       eid::kInvalidPositionProfileReference},
      {"BufferMode 2", [](TimePositionProfile&, Profile& f) { f.BufferMode = 2; }, eid::kInvalidBufferMode},
      {"Velocity 0", [](TimePositionProfile&, Profile& f) { f.Velocity = 0.0; }, eid::kInvalidVelocity},
      {"Acceleration 0", [](TimePositionProfile&, Profile& f) { f.Acceleration = 0.0; },
       eid::kInvalidAcceleration},
      {"absolute, not homed", [](TimePositionProfile&, Profile& f) { f.ProfileReference = 1; },
       eid::kAxisNotHomed},
  };
  for (const auto& c : cases) {
    ProfileMachine m;
    ASSERT_GT(m.enable(), 0);
    TimePositionProfile p = ramp_profile();
    m.profile.TimePosition = &p;
    c.change(p, m.profile);
    m.profile.Execute = true;
    const double x0 = m.db().Position;
    m.run(1);
    EXPECT_TRUE(m.profile.Error) << c.name;
    EXPECT_FALSE(m.profile.Busy) << c.name;
    EXPECT_EQ(m.profile.ErrorID, c.error_id) << c.name;
    m.run(20);
    EXPECT_EQ(m.db().Position, x0) << c.name;
    EXPECT_FALSE(m.x9()) << c.name;
  }
}

// Decision L3: an absolute profile that moves at StartTime cannot be joined from elsewhere: 16#8185 before
// the matrix aborts anything (the running MoveVelocity continues).
TEST(PositionProfile, AbsoluteProfileMovingAtStartTimeIsRejectedUnlessTheAxisIsOnIt) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_velocity.Velocity = 20.0;
  m.move_velocity.Execute = true;
  m.run(10);
  const TimePositionProfile p = ramp_profile();
  m.profile.TimePosition = &p;
  m.profile.ProfileReference = 1;
  m.profile.StartTime = 0.25;
  m.profile.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.profile.Error);
  EXPECT_EQ(m.profile.ErrorID, eid::kProfileStartNotReachable);
  EXPECT_TRUE(m.move_velocity.Busy);
  EXPECT_FALSE(m.move_velocity.CommandAborted);
}

// seed 004 §6.8.4 "dynamic limits while following the profile": a profile faster than MaxVelocity raises 501;
// the setpoint stays within MaxVelocity and MaxAcceleration/MaxDeceleration with OnProfile FALSE while it is
// limited, catches up with the profile's end and the job is Done there.
TEST(PositionProfile, ProfileBeyondTheDynamicLimitsIsFollowedWithinThemAndRaises501) {
  auto data = tomc::testing::linear_axis_data();
  data.DynamicLimits.MaxVelocity = 80.0;
  data.DynamicLimits.Velocity = 80.0;
  data.DynamicDefaults.Velocity = 50.0;
  ProfileMachine m(data);
  ASSERT_GT(m.enable(), 0);
  const double x0 = m.db().Position;
  const TimePositionProfile p = ramp_profile();  // peak about 100 mm/s
  m.profile.TimePosition = &p;
  m.profile.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.axis->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  int limited_at = -1;
  int back_at = -1;
  double last_v = 0.0;
  for (int k = 2; k <= 1000 && !m.profile.Done; ++k) {
    m.run(1);
    ASSERT_LE(std::fabs(m.db().Velocity), 80.0 + 1e-9) << k;
    const double a = (m.db().Velocity - last_v) / 0.001;
    ASSERT_LE(std::fabs(a), 5000.0 * (1.0 + 1e-6)) << k;
    last_v = m.db().Velocity;
    if (limited_at < 0 && m.x9() && !m.x10()) limited_at = k;
    if (limited_at > 0 && back_at < 0 && m.x10()) back_at = k;
  }
  EXPECT_GT(limited_at, 1);  // on the profile first: it starts slowly
  EXPECT_TRUE(m.profile.Done);
  EXPECT_NEAR(m.db().Position, x0 + 40.0, 1e-9);
}

// Direct homing during the absolute transition (MC_Home Mode 1 shifts the coordinates by 10 mm, spec 02
// §5.7): the transition and the profile move with the axis, so the setpoint never steps (found by the
// property test: before, the profile kept the old coordinates and the setpoint jumped by the shift).
TEST(PositionProfile, DirectHomingDuringTheTransitionMovesTheProfileWithTheAxis) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  TimePositionProfile p;
  p.NumberOfPoints = 3;
  p.Point[0] = {0.0, 50.0};
  p.Point[1] = {0.2, 60.0};
  p.Point[2] = {0.4, 70.0};
  m.profile.TimePosition = &p;
  m.profile.ProfileReference = 1;
  m.profile.Execute = true;
  m.run(100);  // in the transition
  m.home.Mode = 1;
  m.home.Position = 10.0;
  m.home.Execute = true;
  m.run(1);
  m.home.Execute = false;
  double last = m.axis->setpoint().position;
  for (int k = 0; k < 1500 && !m.profile.Done; ++k) {
    m.run(1);
    const double x = m.axis->setpoint().position;
    ASSERT_LE(std::fabs(x - last), 100.0 * 0.001 + 1e-9) << k;  // at most DynamicDefaults.Velocity x 1 ms
    last = x;
  }
  EXPECT_TRUE(m.profile.Done);
  EXPECT_NEAR(m.db().Position, 70.0 + 10.0, 1e-9);
}

// ---- TimePosition as the manual has it: a TO_Cam, x = time in s, y = position (spec 03 §4.7, decision L8)
// ----

// One polynomial segment y(t) = h (3t² − 2t³) on [0, 1] s: at rest at both ends, peak 1.5 h mm/s at 0.5 s.
void cubic_cam(techobjects::Cam& cam, double height) {
  techobjects::TO_Cam_Struct_SegmentData s;
  s.xmin = 0.0;
  s.xmax = 1.0;
  s.a2 = 3.0 * height;
  s.a3 = -2.0 * height;
  ASSERT_TRUE(cam.write_segment(1, s, true));
}
double cubic(double height, double t) {
  return height * (3.0 * t * t - 2.0 * t * t * t);
}
double cubic_velocity(double height, double t) {
  return height * (6.0 * t - 6.0 * t * t);
}

// The relative job on an interpolated cam from rest follows it at once: the setpoint is the cam's polynomial,
// cycle by cycle, shifted to the start position; OnProfile while it does; Done at the end (40 mm).
// Decision L8 (a TO_Cam as TimePosition: x = time, y = position), spec 03 §4.7 (OnProfile,
// StatusWord2.X10).
TEST(PositionProfile, FollowsATimePositionCamCycleByCycle) {
  ProfileMachine m;
  ASSERT_GT(m.enable(), 0);
  m.run(5);
  const double x0 = m.db().Position;
  techobjects::Cam cam("Cam_1");
  cubic_cam(cam, 40.0);
  ASSERT_TRUE(cam.interpolate_cam().accepted());
  m.profile.TimePosition = &cam;
  m.profile.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.profile.Busy) << m.profile.ErrorID;
  for (int n = 1; n <= 999; ++n) {  // cycle 1+n: cam time n ms
    m.run(1);
    const double t = n * 0.001;
    ASSERT_NEAR(m.db().Position, x0 + cubic(40.0, t), 1e-9) << n;
    ASSERT_NEAR(m.db().Velocity, cubic_velocity(40.0, t), 1e-9) << n;
    ASSERT_TRUE(m.x9() && m.x10()) << n;
  }
  m.run(1);
  EXPECT_NEAR(m.db().Position, x0 + 40.0, 1e-9);
  EXPECT_EQ(m.db().Velocity, 0.0);
  EXPECT_GT(m.run_until([&] { return m.profile.Done; }, 200), 0);
  EXPECT_FALSE(m.axis->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
}

// A cam not interpolated: 16#8150 (as MC_CamIn); StartTime outside [first, last) of the cam: 16#8183; a cam
// that does not end at rest: 16#8187. A cam
// faster than DynamicLimits.MaxVelocity (peak 60 mm/s, limit 50): 501 once the axis reaches the excess, the
// setpoint within the limit, and the job still ends at the cam's end position.
// Decision L8 (16#8150 not interpolated, 16#8183 StartTime, 16#8187 not at rest), decision L4 (501 and the
// setpoint within MaxVelocity).
TEST(PositionProfile, TimePositionCamErrorsAndLimits) {
  auto data = tomc::testing::linear_axis_data();
  data.DynamicLimits.MaxVelocity = 50.0;
  data.DynamicLimits.Velocity = 50.0;
  data.DynamicDefaults.Velocity = 50.0;
  ProfileMachine m(data);
  ASSERT_GT(m.enable(), 0);
  techobjects::Cam raw("Raw");
  cubic_cam(raw, 40.0);
  const auto submit = [&](const techobjects::Cam& cam, double start_time) {
    m.profile.Execute = false;
    m.run(1);
    m.profile.TimePosition = &cam;
    m.profile.StartTime = start_time;
    m.profile.Execute = true;
    m.run(1);
  };
  submit(raw, 0.0);
  EXPECT_TRUE(m.profile.Error);
  EXPECT_EQ(m.profile.ErrorID, eid::kCamNotInterpolated);
  ASSERT_TRUE(raw.interpolate_cam().accepted());
  for (const double outside : {-0.1, 1.0, std::numeric_limits<double>::quiet_NaN()}) {
    submit(raw, outside);
    EXPECT_TRUE(m.profile.Error) << outside;
    EXPECT_EQ(m.profile.ErrorID, eid::kInvalidStartTime) << outside;
  }
  // A cam still moving at its end (y = 10 t): the axis would stop with a step of 10 mm/s: 16#8187.
  techobjects::Cam moving("Moving");
  techobjects::TO_Cam_Struct_SegmentData ramp;
  ramp.xmin = 0.0;
  ramp.xmax = 1.0;
  ramp.a1 = 10.0;
  ASSERT_TRUE(moving.write_segment(1, ramp, true));
  ASSERT_TRUE(moving.interpolate_cam().accepted());
  submit(moving, 0.0);
  EXPECT_TRUE(m.profile.Error);
  EXPECT_EQ(m.profile.ErrorID, eid::kProfileNotAtRestAtEnd);
  const double x0 = m.db().Position;
  submit(raw, 0.0);
  ASSERT_TRUE(m.profile.Busy) << m.profile.ErrorID;
  bool saw501 = false;
  for (int k = 0; k < 3000 && !m.profile.Done; ++k) {
    m.run(1);
    ASSERT_LE(std::fabs(m.db().Velocity), 50.0 + 1e-9) << k;
    saw501 = saw501 || m.axis->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity);
  }
  EXPECT_TRUE(m.profile.Done);
  EXPECT_TRUE(saw501);
  EXPECT_NEAR(m.db().Position, x0 + 40.0, 1e-9);
}

}  // namespace
