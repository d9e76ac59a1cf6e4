// Camming on TO_SynchronousAxis: MC_CamIn / MC_CamOut against the scenarios of spec 07 §8 (CM-1 … CM-6)
// and the synchronization profiles of §3.4 with their numbers. Set-up of §8 (gearing_fixture.hpp); the cams
// of §8 "Camming":
//   C   points (0,0), (180,100), (360,0), linear interpolation
//   C2  points (0,0), (360,100): a line
//   C3  one segment on [0, 360], y = 100·(10ξ³ − 15ξ⁴ + 6ξ⁵), ξ = x/360 (zero slope at both ends)
//   C4  points (0,0), (180,50), (360,0): C' of CM-5
#include <gtest/gtest.h>

#include <cmath>

#include "gearing_fixture.hpp"
#include "tomc/instructions/mc_interpolate_cam.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace {

using namespace tomc;
using techobjects::Cam;
using techobjects::StatusWordBit;
using tomc::testing::GearingMachine;
using tomc::testing::virtual_linear;
using tomc::testing::virtual_rotary_modulo;
namespace eid = techobjects::error_id;

struct Cams {
  Cam* C = nullptr;
  Cam* C2 = nullptr;
  Cam* C3 = nullptr;
  Cam* C4 = nullptr;
};

Cam& points_cam(techobjects::Runtime& r, const char* name, std::uint16_t number,
                std::initializer_list<techobjects::TO_Cam_Struct_PointData> points) {
  Cam& c = r.emplace<Cam>(name, techobjects::CamVariant::kCam, number);
  std::size_t i = 1;
  for (const auto& p : points)
    EXPECT_TRUE(c.write_point(i++, p, true));
  return c;
}

// The cams live in a base constructed before the machine (whose constructor adds them).
struct CamsHolder {
  Cams cams;
};

// A machine of spec 07 §8 with the cams above.
struct CammingMachine : CamsHolder, GearingMachine {
  explicit CammingMachine(techobjects::PositioningAxisData leader = virtual_rotary_modulo(),
                          techobjects::PositioningAxisData follower = virtual_rotary_modulo())
      : GearingMachine(leader, follower, [this](techobjects::Runtime& r) {
          cams.C = &points_cam(r, "C", 11, {{0.0, 0.0}, {180.0, 100.0}, {360.0, 0.0}});
          cams.C2 = &points_cam(r, "C2", 12, {{0.0, 0.0}, {360.0, 100.0}});
          Cam& c3 = r.emplace<Cam>("C3", techobjects::CamVariant::kCam, 13);
          techobjects::TO_Cam_Struct_SegmentData s;
          s.xmin = 0.0;
          s.xmax = 360.0;
          s.a3 = 1000.0 / std::pow(360.0, 3);
          s.a4 = -1500.0 / std::pow(360.0, 4);
          s.a5 = 600.0 / std::pow(360.0, 5);
          EXPECT_TRUE(c3.write_segment(1, s, true));
          cams.C3 = &c3;
          cams.C4 = &points_cam(r, "C4", 14, {{0.0, 0.0}, {180.0, 50.0}, {360.0, 0.0}});
        }) {
    // MC_InterpolateCam once the runtime runs (its start loads the cams' start values).
    for (Cam* c : {cams.C, cams.C2, cams.C3, cams.C4})
      EXPECT_TRUE(c->interpolate_cam().accepted());
  }
  const techobjects::StatusSynchronizedMotion& sync() const { return F->synchronized_motion(); }
  // The first MC_CamIn instance with the inputs every case sets: the cam, SyncProfileReference and
  // ApplicationMode (spec 07 §3.4); the case sets the rest and Execute.
  instructions::MC_CamIn<techobjects::SynchronousAxis>& cam_in_with(Cam* cam, std::int32_t profile,
                                                                    std::int32_t mode) {
    cam_in.Cam = cam;
    cam_in.SyncProfileReference = profile;
    cam_in.ApplicationMode = mode;
    return cam_in;
  }
  // The leader moves `distance` at `velocity` (MC_MoveRelative, acceleration 10000); returns when done.
  void leader_moves(double distance, double velocity = 100.0) {
    move_rel_L.Execute = false;
    run(1);
    move_rel_L.Distance = distance;
    move_rel_L.Velocity = velocity;
    move_rel_L.Acceleration = move_rel_L.Deceleration = 10000.0;
    move_rel_L.Execute = true;
    ASSERT_GT(run_until([&] { return move_rel_L.Done; }, 100000), 0);
  }
  void leader_velocity(double v) {
    move_L.Execute = false;
    run(1);
    move_L.Velocity = v;
    move_L.Acceleration = move_L.Deceleration = 10000.0;
    move_L.Execute = true;
    ASSERT_GT(run_until([&] { return move_L.InVelocity; }, 2000), 0);
  }
  void follower_to(double position) {
    move_abs_F.Position = position;
    move_abs_F.Velocity = 500.0;
    move_abs_F.Execute = true;
    ASSERT_GT(run_until([&] { return move_abs_F.Done; }, 2000), 0);
    move_abs_F.Execute = false;
    run(1);
  }
};

bool bit(const techobjects::PositioningAxisData& d, StatusWordBit b) {
  return techobjects::test(d.StatusWord, b);
}

// CM-1 (spec 07 §8; §3.3, §3.4 profile 2): direct synchronous setting, cyclic, SlaveScaling 2.
TEST(Camming, CM1DirectSynchronousSettingCyclic) {
  CammingMachine m;
  m.follower_to(10.0);
  auto& c = m.cam_in_with(m.cams.C, 2, 1);
  c.MasterSyncPosition = 0.0;
  c.SlaveScaling = 2.0;
  c.Execute = true;
  m.run(1);
  EXPECT_TRUE(c.InSync);  // at once
  m.run(1);               // the status of the next MC_Interpolator
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronous));
  EXPECT_EQ(m.sync().FunctionState, 3);
  EXPECT_EQ(m.sync().ActualCam, 11);
  EXPECT_DOUBLE_EQ(m.sync().SlaveOffset, 10.0);
  EXPECT_DOUBLE_EQ(m.sync().MasterOffset, 0.0);
  EXPECT_DOUBLE_EQ(m.sync().SlaveScaling, 2.0);
  EXPECT_DOUBLE_EQ(m.F->read("StatusSynchronizedMotion.Offset"), 10.0);
  // The cam is in use (StatusWord.X0): MC_InterpolateCam is refused (CM-4, 16#80AB).
  EXPECT_EQ(m.cams.C->read("StatusWord.X0"), 1.0);
  EXPECT_EQ(m.cams.C->interpolate_cam().error_id, eid::kCamInUse);
  m.leader_moves(90.0);
  EXPECT_NEAR(m.f().Position, 2.0 * 50.0 + 10.0, 1e-9);  // F = 2·f(90) + 10 = 110
  // To unwrapped 360: one period, F = 10 again, EndOfProfile for one call.
  int ends = 0;
  m.user = [&] { ends += c.EndOfProfile ? 1 : 0; };
  m.leader_moves(270.0);
  EXPECT_NEAR(m.f().Position, 10.0, 1e-9);
  EXPECT_EQ(ends, 1);
  m.leader_moves(90.0);  // unwrapped 450
  EXPECT_NEAR(m.f().Position, 110.0, 1e-9);
  EXPECT_EQ(ends, 1);
  EXPECT_TRUE(c.InSync);
  EXPECT_TRUE(c.Busy);
}

// CM-2 (§3.3 "cyclic appending"): a line 0…100 over 360, F linear: F = 200 at 720, 250 at 900.
TEST(Camming, CM2CyclicAppending) {
  CammingMachine m(virtual_rotary_modulo(), virtual_linear());
  auto& c = m.cam_in_with(m.cams.C2, 2, 2);
  c.Execute = true;
  m.run(1);
  ASSERT_TRUE(c.InSync);
  m.leader_moves(720.0, 360.0);
  EXPECT_NEAR(m.f().Position, 200.0, 1e-9);
  m.leader_moves(180.0, 360.0);
  EXPECT_NEAR(m.f().Position, 250.0, 1e-9);
}

// CM-3 (§3.3 "not cyclic", O-10): the cam end ends the synchronous operation; F holds 100.
TEST(Camming, CM3NonCyclicEnd) {
  CammingMachine m(virtual_rotary_modulo(), virtual_linear());
  auto& c = m.cam_in_with(m.cams.C3, 2, 0);
  c.Execute = true;
  m.run(1);
  ASSERT_TRUE(c.InSync);
  bool end_seen = false;
  m.user = [&] { end_seen = end_seen || c.EndOfProfile; };
  m.leader_moves(180.0);
  EXPECT_NEAR(m.f().Position, 50.0, 1e-9);  // ξ = 1/2: 100·(10/8 − 15/16 + 6/32) = 50
  EXPECT_TRUE(c.Busy);
  m.leader_moves(200.0);  // past 360
  EXPECT_TRUE(end_seen);
  EXPECT_TRUE(c.EndOfProfile);  // held while Execute is TRUE (O-10)
  EXPECT_FALSE(c.Busy);
  EXPECT_FALSE(c.InSync);
  EXPECT_FALSE(c.Error);
  EXPECT_FALSE(bit(m.f(), StatusWordBit::kSynchronous));
  EXPECT_EQ(m.sync().FunctionState, 0);
  EXPECT_NEAR(m.f().Position, 100.0, 1e-9);
  EXPECT_EQ(m.cams.C3->read("StatusWord.X0"), 0.0);  // released
  EXPECT_TRUE(m.cams.C3->interpolate_cam().accepted());
}

// CM-4 (§1.10): the parameter errors; a running camming is not affected.
TEST(Camming, CM4ParameterErrors) {
  CammingMachine m;
  struct Case {
    const char* what;
    void (*set)(instructions::MC_CamIn<techobjects::SynchronousAxis>&);
    std::uint16_t error_id;
  };
  const Case cases[] = {
      {"MasterSyncPosition 400", [](auto& c) { c.MasterSyncPosition = 400.0; }, eid::kOutsideCam},
      {"MasterScaling 0", [](auto& c) { c.MasterScaling = 0.0; }, eid::kInvalidMasterScaling},
      {"MasterStartDistance 0, profile 1", [](auto& c) { c.MasterStartDistance = 0.0; },
       eid::kInvalidMasterStartDistance},
      {"ApplicationMode 3", [](auto& c) { c.ApplicationMode = 3; }, eid::kInvalidApplicationMode},
      {"SyncProfileReference 7", [](auto& c) { c.SyncProfileReference = 7; },
       eid::kInvalidSyncProfileReference},
      {"profile 5 without camming", [](auto& c) { c.SyncProfileReference = 5; }, eid::kNoActiveCamming},
      {"MasterOffset NaN", [](auto& c) { c.MasterOffset = std::nan(""); }, eid::kInvalidMasterOffset},
  };
  for (const Case& k : cases) {
    auto& c = m.cam_in2;
    c = {};
    c.Master = m.leader_axis;
    c.Cam = m.cams.C;
    c.SyncProfileReference = 1;
    c.MasterStartDistance = 90.0;
    k.set(c);
    c.Execute = true;
    m.run(1);
    EXPECT_TRUE(c.Error) << k.what;
    EXPECT_EQ(c.ErrorID, k.error_id) << k.what;
    c.Execute = false;
    m.run(1);
  }
  EXPECT_EQ(m.cams.C->read("StatusWord.X0"), 0.0);  // no rejected job holds the cam
}

// CM-5 (§3.4 profile 5): the switch waits for the end of the running cam, then C' takes over without a
// position step; the old job is aborted.
TEST(Camming, CM5SwitchAtTheEndOfTheCam) {
  CammingMachine m;
  m.follower_to(10.0);
  auto& c = m.cam_in_with(m.cams.C, 2, 1);
  c.SlaveScaling = 2.0;
  c.Execute = true;
  m.run(1);
  ASSERT_TRUE(c.InSync);
  m.leader_moves(90.0);
  auto& n = m.cam_in2;
  n.Cam = m.cams.C4;
  n.SyncProfileReference = 5;
  n.MasterSyncPosition = 0.0;
  n.ApplicationMode = 1;
  n.Execute = true;
  m.run(2);
  EXPECT_TRUE(n.Busy);
  EXPECT_FALSE(n.InSync);
  EXPECT_EQ(m.sync().WaitingFunctionState, 3);
  EXPECT_TRUE(c.InSync);
  EXPECT_EQ(m.cams.C4->read("StatusWord.X0"), 1.0);  // held by the waiting job
  double largest_step = 0.0;
  double last = m.F->setpoint().position;
  m.user = [&] {
    largest_step = std::max(largest_step, std::fabs(m.F->setpoint().position - last));
    last = m.F->setpoint().position;
  };
  m.leader_moves(360.0);  // through the end of C at unwrapped 360
  EXPECT_TRUE(c.CommandAborted);
  EXPECT_TRUE(n.InSync);
  EXPECT_EQ(m.sync().ActualCam, 14);
  EXPECT_EQ(m.sync().WaitingFunctionState, 0);
  EXPECT_EQ(m.cams.C->read("StatusWord.X0"), 0.0);
  // No position step: at most one cycle's travel of the faster cam (2·100/180 per degree at 0.1°/cycle).
  EXPECT_LT(largest_step, 2.0 * (100.0 / 180.0) * 0.1 + 1e-9);
  // From the end of C (unwrapped 360, F = 10) on, F follows C4 (slope 50/180): at 450, 10 + 25.
  EXPECT_NEAR(m.f().Position, 10.0 + 50.0 * 90.0 / 180.0, 1e-6);
}

// CM-6 (§3.4 profile 6, MCI8 function chart): leader at 270 moving +100°/s, MasterSyncPosition 180,
// MasterStartDistance 180: StartSync at once, InSync at 90 (next revolution), MasterOffset −90.
TEST(Camming, CM6ProfileSixAutomaticMasterOffset) {
  CammingMachine m;
  m.leader_moves(270.0);
  m.leader_velocity(100.0);
  auto& c = m.cam_in_with(m.cams.C, 6, 1);
  c.MasterSyncPosition = 180.0;
  c.MasterStartDistance = 180.0;
  c.Execute = true;
  // StartSync in the first MC_Interpolator after the call (the leader moves).
  ASSERT_EQ(m.run_until([&] { return c.StartSync; }, 5), 2);
  const double start = m.l().Position;  // ≈ 270.2
  m.run(1);
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kSynchronizing));
  EXPECT_EQ(m.sync().FunctionState, 3);
  // MasterOffset = (start + 180) − 0·1 − 180, shown in the leader's range: start + 180 ≡ start − 180 ≈ −89.8.
  EXPECT_NEAR(m.sync().MasterOffset, start - 360.0, 1e-9);
  ASSERT_GT(m.run_until([&] { return c.InSync; }, 3000), 0);
  // 180° of leader travel at 0.1°/cycle from where the job started (±1 cycle): at ≈ 90.
  const double travelled = std::fmod(m.l().Position - start + 360.0, 360.0);
  EXPECT_NEAR(travelled, 180.0, 0.1 + 1e-9);
  // Synchronous: F = f(x − MasterOffset) on C (f(180) = 100 at the synchronous point).
  m.run(100);
  const double u = std::fmod(m.l().Position - m.sync().MasterOffset + 720.0, 360.0);
  const double f = u <= 180.0 ? u * 100.0 / 180.0 : (360.0 - u) * 100.0 / 180.0;
  EXPECT_NEAR(m.f().Position, f, 1e-6);
}

// Profile 1 (§3.4, §6.4): in advance over MasterStartDistance: StartSync at x_sync − 100, InSync at x_sync
// with the follower on the cam; a linear leader already too close is refused (16#8034, O-11).
TEST(Camming, ProfileOneInAdvanceOverDistance) {
  CammingMachine m(virtual_linear(), virtual_linear());
  m.leader_velocity(100.0);
  auto& c = m.cam_in_with(m.cams.C2, 1, 2);  // C2 is a line: appending continues it before x_sync
  c.MasterOffset = m.l().Position + 150.0;  // x_sync = 0·1 + MasterOffset + 0
  c.SlaveOffset = 50.0;
  c.MasterStartDistance = 100.0;
  const double x_sync = c.MasterOffset;
  c.Execute = true;
  m.run(2);
  EXPECT_TRUE(c.Busy);
  EXPECT_FALSE(c.StartSync);
  EXPECT_EQ(m.sync().WaitingFunctionState, 3);
  ASSERT_GT(m.run_until([&] { return c.StartSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, x_sync - 100.0, 0.1 + 1e-9);
  ASSERT_GT(m.run_until([&] { return c.InSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, x_sync, 0.1 + 1e-9);
  m.run(360);  // 36 mm further: F = 50 + 100·36/360 plus one cycle's share
  EXPECT_NEAR(m.f().Position, 50.0 + 100.0 * (m.l().Position - x_sync) / 360.0, 1e-6);
  EXPECT_NEAR(m.f().Velocity, 100.0 * 100.0 / 360.0, 1e-6);

  auto& late = m.cam_in2;
  late.Cam = m.cams.C2;
  late.SyncProfileReference = 1;
  late.MasterOffset = m.l().Position + 50.0;
  late.MasterStartDistance = 100.0;
  late.Execute = true;
  m.run(1);
  EXPECT_EQ(late.ErrorID, eid::kInvalidMasterSyncPosition);
  EXPECT_TRUE(c.InSync);
}

// SyncDirection on a modulo follower (spec 07 §3.4 SyncDirection, §6.1 item 3; decision Y3 [IMPL]): cam C
// (cyclic) synchronized over 100 deg of leader travel (profile 1) to its point u = 0, y = 0. Without the
// synchronization the follower would be at its position − f(260) = −55.6 deg relative; from there the
// occurrence of y = 0 (k·360) is chosen: 1 the next one above, 2 the one below, 3 the nearer. Table: follower
// start, SyncDirection, the follower's travel until InSync (unwrapped, summed per cycle).
TEST(Camming, SyncDirectionOnAModuloFollower) {
  struct Case {
    double start;
    std::int32_t direction;
    double travel;
  };
  for (const Case k : {Case{300.0, 1, 60.0}, Case{300.0, 2, -300.0}, Case{300.0, 3, 60.0},
                       Case{100.0, 3, -100.0}, Case{100.0, 1, 260.0}, Case{100.0, 2, -100.0}}) {
    CammingMachine m;
    m.follower_to(k.start);
    m.leader_velocity(100.0);
    auto& c = m.cam_in_with(m.cams.C, 1, 1);
    c.MasterOffset = m.l().Position + 150.0;  // the synchronous point 150 deg ahead (cam u = 0)
    c.MasterStartDistance = 100.0;
    c.SyncDirection = k.direction;
    double travel = 0.0;
    double last = m.f().Position;
    m.user = [&] {
      travel += std::remainder(m.f().Position - last, 360.0);
      last = m.f().Position;
    };
    c.Execute = true;
    ASSERT_GT(m.run_until([&] { return c.InSync; }, 5000), 0) << k.start << " " << k.direction;
    EXPECT_NEAR(travel, k.travel, 1e-6) << k.start << " " << k.direction;
    EXPECT_NEAR(std::remainder(m.f().Position, 360.0), 0.0, 1e-6);
  }
}

// Profile 3 (§3.4): subsequent synchronization: starts at x_sync, synchronous at x_sync +
// MasterStartDistance.
TEST(Camming, ProfileThreeSubsequent) {
  CammingMachine m(virtual_linear(), virtual_linear());
  m.leader_velocity(100.0);
  auto& c = m.cam_in_with(m.cams.C2, 3, 2);
  c.MasterOffset = m.l().Position + 50.0;
  c.MasterStartDistance = 60.0;
  const double x_sync = c.MasterOffset;
  c.Execute = true;
  ASSERT_GT(m.run_until([&] { return c.StartSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, x_sync, 0.1 + 1e-9);
  ASSERT_GT(m.run_until([&] { return c.InSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, x_sync + 60.0, 0.1 + 1e-9);
  EXPECT_NEAR(m.f().Position, 100.0 * (m.l().Position - x_sync) / 360.0, 1e-6);
}

// Profile 4 (§3.4): pending while the leader stands, then synchronous after MasterStartDistance from where
// the leader started; a non-cyclic cam the leader is outside of is refused (16#80AD).
TEST(Camming, ProfileFourFromTheCurrentLeaderPosition) {
  CammingMachine m(virtual_linear(), virtual_linear());
  auto& c = m.cam_in_with(m.cams.C2, 4, 0);
  c.MasterStartDistance = 40.0;
  c.Execute = true;
  m.run(5);
  EXPECT_TRUE(c.Busy) << c.ErrorID;
  EXPECT_FALSE(c.StartSync);
  EXPECT_EQ(m.sync().WaitingFunctionState, 3);
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = m.move_L.Deceleration = 10000.0;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return c.StartSync; }, 100), 0);
  ASSERT_GT(m.run_until([&] { return c.InSync; }, 3000), 0);
  EXPECT_NEAR(m.l().Position, 40.0, 0.1 + 1e-9);
  EXPECT_NEAR(m.f().Position, 100.0 * m.l().Position / 360.0, 1e-6);

  auto& out = m.cam_in2;
  out.Cam = m.cams.C2;
  out.SyncProfileReference = 4;
  out.MasterStartDistance = 40.0;
  out.MasterOffset = 1000.0;  // the leader (≈ 40) is before the cam [1000, 1360]
  out.Execute = true;
  m.run(1);
  EXPECT_EQ(out.ErrorID, eid::kOutsideCam);
}

// Profile 0 (§6.5): in advance with dynamic parameters: synchronous at x_sync on the cam, within the job's
// Velocity and Acceleration on the way.
TEST(Camming, ProfileZeroDynamicParameters) {
  CammingMachine m(virtual_linear(), virtual_linear());
  m.leader_velocity(100.0);
  auto& c = m.cam_in_with(m.cams.C2, 0, 2);
  c.MasterOffset = m.l().Position + 300.0;
  c.SlaveOffset = 20.0;
  c.Velocity = 200.0;
  c.Acceleration = c.Deceleration = 500.0;
  c.Jerk = 0.0;
  const double x_sync = c.MasterOffset;
  c.Execute = true;
  double peak_v = 0.0;
  double peak_a = 0.0;
  m.user = [&] {
    if (c.StartSync) {
      peak_v = std::max(peak_v, std::fabs(m.f().Velocity));
      peak_a = std::max(peak_a, std::fabs(m.f().Acceleration));
    }
  };
  ASSERT_GT(m.run_until([&] { return c.InSync; }, 6000), 0);
  EXPECT_NEAR(m.l().Position, x_sync, 0.1 + 1e-9);
  EXPECT_NEAR(m.f().Position, 20.0 + 100.0 * (m.l().Position - x_sync) / 360.0, 1e-6);
  EXPECT_LE(peak_v, 200.0);
  EXPECT_LE(peak_a, 500.0);
}

// MC_CamIn profile 0 whose synchronous velocity equals the job's Velocity synchronizes (spec 07 §3.4 "dynamic
// limits are as for MC_GearInPos", §2.2 profile 0, §6.8: only MaxVelocity 1000 decides; decision C23). C2
// scaled by SlaveScaling 3.6 is a line of slope 1; the leader at 100 mm/s, Velocity 100: InSync at
// x_sync = MasterOffset + 180 with F = 180 and 100 mm/s, about 9,800 cycles after the job, the blend within
// 100 mm/s and no alarm 501. Before, the job stayed pending for ever (the 98 % reserve on the end velocity).
TEST(Camming, ProfileZeroSynchronizesWhenTheSynchronousVelocityIsTheJobVelocity) {
  CammingMachine m(virtual_linear(), virtual_linear());
  m.leader_velocity(100.0);
  auto& c = m.cam_in_with(m.cams.C2, 0, 0);
  c.SlaveScaling = 3.6;
  c.MasterSyncPosition = 180.0;
  c.MasterOffset = m.l().Position + 800.0;
  c.SlaveOffset = 0.0;
  c.Velocity = 100.0;
  c.Acceleration = c.Deceleration = 5000.0;
  c.Jerk = 0.0;
  const double x_sync = c.MasterOffset + c.MasterSyncPosition;
  c.Execute = true;
  m.run(1);
  ASSERT_TRUE(c.Busy) << std::hex << c.ErrorID;
  double v_max = 0.0;
  int cycles = 1;
  for (; cycles < 12000 && !c.InSync; ++cycles) {
    m.run(1);
    v_max = std::max(v_max, std::fabs(m.F->setpoint().velocity));
  }
  ASSERT_TRUE(c.InSync) << "never synchronized";
  EXPECT_NEAR(cycles, 9800, 20);
  EXPECT_NEAR(m.l().Position, x_sync, 0.1 + 1e-9);
  EXPECT_NEAR(m.F->setpoint().velocity, 100.0, 1e-6);
  EXPECT_NEAR(m.F->setpoint().position - (m.l().Position - x_sync), 180.0, 1e-6);
  EXPECT_LE(v_max, 100.0 * (1.0 + 1e-9));
  EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
}

// Profile 0 and the follower's DynamicLimits (spec 07 §3.4 "dynamic limits are as for MC_GearInPos",
// §6.5, §6.8 table; SYNC8 "in advance using dynamic parameters", decision C23). Cam C3 compressed tenfold
// (MasterScaling 0.1), the synchronous point at its steepest curvature ξ = 0.2113 (MasterSyncPosition
// 7.607 mm): slope 100·S'(ξ)/36 = 2.314, curvature 100·S''(ξ)/36² = 0.4452/mm, so at a leader of 100 mm/s
// the cam itself asks 231.4 mm/s and 4,452 mm/s² there. F: MaxAcceleration 2000, MaxDeceleration 1500,
// MaxJerk 1e6. The job's Velocity 5000, Acceleration 3000, Jerk 2e6 exceed them: alarms 501, 502, 503 and
// the job runs with 1000 / 2000 / 1e6. The synchronization holds them at every cycle (before decision C23
// the blend onto the cam itself passed the cam's 4,452 mm/s² through); InSync when the leader reaches
// x_sync = MasterOffset + 7.607, 2,076 cycles after the job at 100 mm/s; from there the follower is on the
// cam with its own acceleration, indicated by StatusSynchronizedMotion.StatusWord.X1 (synchronous travel).
TEST(Camming, ProfileZeroHoldsTheDynamicLimitsOnACurvedCam) {
  auto f = virtual_linear();
  f.DynamicLimits.MaxAcceleration = 2000.0;
  f.DynamicLimits.MaxDeceleration = 1500.0;
  f.DynamicLimits.MaxJerk = 1.0e6;
  CammingMachine m(virtual_linear(), f);
  m.leader_velocity(100.0);
  auto& c = m.cam_in;
  const double xi = 0.2113;  // S''(ξ) = 60ξ − 180ξ² + 120ξ³ is largest at ξ = (3 − √3)/6
  c.Cam = m.cams.C3;
  c.SyncProfileReference = 0;
  c.MasterScaling = 0.1;
  c.MasterSyncPosition = 0.1 * 360.0 * xi;
  c.MasterOffset = m.l().Position + 200.0;
  c.SlaveOffset = 50.0;
  c.ApplicationMode = 0;
  c.Velocity = 5000.0;
  c.Acceleration = 3000.0;
  c.Deceleration = 1000.0;
  c.Jerk = 2.0e6;
  const double x_sync = c.MasterOffset + c.MasterSyncPosition;
  c.Execute = true;
  m.run(1);
  ASSERT_TRUE(c.Busy) << std::hex << c.ErrorID;
  for (auto n : {techobjects::kAlarmDynamicsLimitedVelocity, techobjects::kAlarmDynamicsLimitedAcceleration,
                 techobjects::kAlarmDynamicsLimitedJerk}) {
    EXPECT_TRUE(m.F->alarms().pending(n)) << n;
  }
  double peak_v = 0.0, peak_acc = 0.0, peak_dec = 0.0, peak_jerk = 0.0, x_start = 0.0;
  double previous_a = m.F->setpoint().acceleration;
  int cycles = 1;
  bool synchronizing = false;
  for (; cycles < 4000 && !c.InSync; ++cycles) {
    m.run(1);
    const auto& sp = m.F->setpoint();
    if (c.StartSync && !c.InSync) {
      if (!synchronizing) x_start = m.l().Position;
      synchronizing = true;
      peak_v = std::max(peak_v, std::fabs(sp.velocity));
      (sp.acceleration * sp.velocity < 0.0 ? peak_dec : peak_acc) =
          std::max(sp.acceleration * sp.velocity < 0.0 ? peak_dec : peak_acc, std::fabs(sp.acceleration));
      peak_jerk = std::max(peak_jerk, std::fabs(sp.acceleration - previous_a) / 0.001);
    }
    previous_a = sp.acceleration;
  }
  ASSERT_TRUE(c.InSync);
  ASSERT_TRUE(synchronizing);
  EXPECT_NEAR(cycles, 2076, 2);
  EXPECT_NEAR(m.l().Position, x_sync, 0.1 + 1e-9);
  EXPECT_GT(x_sync - x_start, 10.0);  // a synchronization length (31.5 mm), not a step
  EXPECT_LE(peak_v, 1000.0);
  EXPECT_LE(peak_acc, 2000.0);
  EXPECT_LE(peak_dec, 1000.0);  // the job's Deceleration (below MaxDeceleration: no alarm for it)
  EXPECT_LE(peak_jerk, 1.0e6 * (1.0 + 1e-6));
  EXPECT_GT(peak_acc, 1000.0);  // and not needlessly slow
  // On the cam from the synchronous point: y = f((x − MO)/MS) + SO with the cam's own acceleration.
  m.run(1);
  const double u = (m.l().Position - c.MasterOffset) / 0.1;
  const auto cam = m.cams.C3->profile().evaluate(u);
  EXPECT_NEAR(m.F->setpoint().position, cam.y + 50.0, 1e-6);
  EXPECT_NEAR(m.F->setpoint().velocity, cam.dy * 100.0 / 0.1, 1e-6);
  EXPECT_NEAR(m.F->setpoint().acceleration, cam.ddy * 1.0e4 / 0.01, 1e-3);
  EXPECT_NEAR(m.F->setpoint().acceleration, 4452.0, 5.0);
  EXPECT_EQ(m.sync().StatusWord & 2u, 2u);  // X1 MaxAccelerationExceeded: indicated, not limited
}

// Profile 0 over the next modulo pass (spec 07 §3.4 profile 0, §6.5; decision Y12 as for MC_GearInPos): a
// modulo leader at 100 deg/s, the synchronous point 1 deg ahead — closer than the synchronization length
// (>= 100²/1000 = 10 deg), so its start lies behind the leader. The job waits for the next pass (the cam
// moves with its synchronous point, 360 deg on), synchronizes without a step (at most Velocity per cycle) and
// is InSync on cam C's rising flank, F = (100/180)·(L − synchronous point) in the modulo ranges.
TEST(Camming, ProfileZeroOverTheNextModuloPass) {
  CammingMachine m;
  m.leader_velocity(100.0);
  auto& c = m.cam_in_with(m.cams.C, 0, 1);
  c.MasterOffset = m.l().Position + 1.0;
  c.Velocity = 500.0;
  c.Acceleration = c.Deceleration = 1000.0;
  c.Jerk = 0.0;
  c.Execute = true;
  double previous = m.F->setpoint().position;
  int cycles = 0;
  for (; cycles < 8000 && !c.InSync; ++cycles) {
    m.run(1);
    ASSERT_FALSE(c.Error) << cycles;
    ASSERT_LE(std::fabs(m.F->setpoint().position - previous), 0.5 + 1e-6) << cycles;
    previous = m.F->setpoint().position;
  }
  ASSERT_TRUE(c.InSync);
  EXPECT_NEAR(cycles, 3610, 2);  // InSync at the synchronous point of the next pass: 361 deg at 100 deg/s
  const double u = std::remainder(m.l().Position - c.MasterOffset, 360.0);
  EXPECT_GE(u, -1e-9);
  EXPECT_NEAR(std::remainder(m.f().Position - 100.0 / 180.0 * u, 360.0), 0.0, 1e-6);
}

// MC_CamOut (§3.5): profile 0 stops the follower at SlavePosition (FunctionState 5, the camming aborted at
// the start of desynchronization); the wrong family is refused both ways (16#8078, 16#8077).
TEST(Camming, CamOutAndTheFamilies) {
  CammingMachine m(virtual_linear(), virtual_linear());
  auto& o = m.cam_out;
  o.SyncProfileReference = 0;
  o.Execute = true;
  m.run(1);
  EXPECT_EQ(o.ErrorID, eid::kNoCamming);
  o.Execute = false;
  m.gear.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear.InGear);
  o.Execute = true;
  m.run(1);
  EXPECT_EQ(o.ErrorID, eid::kNoCamming);  // a gearing is not a camming
  o.Execute = false;

  auto& c = m.cam_in_with(m.cams.C2, 2, 2);
  c.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.gear.CommandAborted);  // an active CamIn aborts MC_GearIn (§9.19.2 R "active" x S1)
  ASSERT_TRUE(c.InSync);
  m.gear_out.SyncProfileReference = 0;
  m.gear_out.Execute = true;
  m.run(1);
  EXPECT_EQ(m.gear_out.ErrorID, eid::kNoGearing);
  m.leader_velocity(360.0);  // F at 100 mm/s on C2
  o.SlavePosition = 500.0;
  o.Deceleration = 1000.0;
  o.Jerk = 0.0;
  o.Execute = true;
  m.run(2);
  EXPECT_TRUE(o.Busy);
  EXPECT_EQ(m.sync().WaitingFunctionState, 5);
  ASSERT_GT(m.run_until([&] { return o.StartSyncOut; }, 10000), 0);
  EXPECT_TRUE(c.CommandAborted);
  EXPECT_EQ(m.sync().FunctionState, 5);
  EXPECT_EQ(m.cams.C2->read("StatusWord.X0"), 0.0);
  ASSERT_GT(m.run_until([&] { return o.Done; }, 10000), 0);
  EXPECT_NEAR(m.f().Position, 500.0, 1e-6);
  m.run(20);  // the standstill signal's minimum dwell time, as in GP-5
  EXPECT_TRUE(bit(m.f(), StatusWordBit::kStandstill));
}

// §9.19.2: MC_Halt ends an active camming (CommandAborted) and releases the cam.
TEST(Camming, OverrideByHaltReleasesTheCam) {
  CammingMachine m;
  auto& c = m.cam_in_with(m.cams.C, 2, 1);
  c.Execute = true;
  m.run(1);
  ASSERT_TRUE(c.InSync);
  m.halt_F.Execute = true;
  m.run(2);
  EXPECT_TRUE(c.CommandAborted);
  EXPECT_EQ(m.sync().FunctionState, 0);
  EXPECT_EQ(m.sync().ActualCam, 0);
  EXPECT_EQ(m.cams.C->read("StatusWord.X0"), 0.0);
}

// §3.2: camming with a cam that is not interpolated raises alarm 612 (remove enable) and the job ends with
// 16#8001 (decision C8).
TEST(Camming, CamNotInterpolatedRaises612) {
  CammingMachine m;
  // A change after MC_InterpolateCam (StatusWord.X4 CamDataChanged): the cam must be interpolated again.
  ASSERT_TRUE(m.cams.C->write_point(4, {400.0, 0.0}, true));
  ASSERT_EQ(m.cams.C->read("StatusWord.X4"), 1.0);
  auto& c = m.cam_in;
  c.Cam = m.cams.C;
  c.SyncProfileReference = 2;
  c.Execute = true;
  m.run(1);
  EXPECT_EQ(c.ErrorID, eid::kAbortedByAlarmReaction);
  EXPECT_TRUE(m.F->alarms().pending(techobjects::kAlarmCamNotInterpolated));
}

// §6.8: in synchronous travel the configured limits only indicate (StatusSynchronizedMotion.StatusWord.X0),
// no alarm 501 and no limiting: C scaled by 20 has slope 20·100/180 = 11.1, so L at 100 gives F 1,111 >
// 1,000.
TEST(Camming, SynchronousTravelIndicatesTheLimits) {
  CammingMachine m(virtual_linear(), virtual_linear());
  auto& c = m.cam_in_with(m.cams.C, 2, 1);
  c.SlaveScaling = 20.0;
  c.Execute = true;
  m.run(2);
  ASSERT_TRUE(c.InSync);
  m.leader_moves(60.0);  // L on the rising flank at 100 mm/s
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = m.move_L.Deceleration = 10000.0;
  m.move_L.Execute = true;
  m.run(100);
  EXPECT_NEAR(m.f().Velocity, 20.0 * 100.0 / 180.0 * 100.0, 1e-6);
  EXPECT_EQ(m.F->read("StatusSynchronizedMotion.StatusWord.X0"), 1.0);
  EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  EXPECT_TRUE(c.InSync);
}

// §3.4 "the leading value must not reverse during synchronization": alarm 608 (stop with maximum dynamics).
TEST(Camming, LeaderReversalDuringSynchronizationRaises608) {
  CammingMachine m(virtual_linear(), virtual_linear());
  m.leader_velocity(100.0);
  auto& c = m.cam_in_with(m.cams.C2, 4, 2);
  c.MasterStartDistance = 100.0;
  c.Execute = true;
  ASSERT_GT(m.run_until([&] { return c.StartSync; }, 10), 0);
  m.run(200);  // half way
  m.move_L.Execute = false;
  m.run(1);
  m.move_L.Velocity = -100.0;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.F->alarms().pending(techobjects::kAlarmSynchronizationError); }, 100),
            0);
  m.run(2);
  EXPECT_TRUE(c.Error || c.CommandAborted);
  EXPECT_FALSE(c.InSync);
  EXPECT_EQ(m.cams.C2->read("StatusWord.X0"), 0.0);
}

}  // namespace

// MC_CamOut profile 5 (spec 07 §3.5, §5.1 footnote 8): it cancels a pending MC_CamIn only (CommandAborted,
// the cam free again) and is Done; against an active camming it is Done and the camming goes on.
TEST(Camming, CamOutProfileFiveCancelsOnlyAPendingCamIn) {
  CammingMachine m;
  auto& c = m.cam_in_with(m.cams.C, 1, 1);
  c.MasterSyncPosition = 180.0;
  c.MasterStartDistance = 90.0;
  c.Execute = true;
  m.run(2);
  ASSERT_TRUE(c.Busy);
  ASSERT_FALSE(c.StartSync);
  EXPECT_EQ(m.sync().WaitingFunctionState, 3);
  auto& out = m.cam_out;
  out.SyncProfileReference = 5;
  out.Execute = true;
  m.run(1);
  EXPECT_TRUE(out.Done);
  EXPECT_TRUE(c.CommandAborted);
  m.run(1);
  EXPECT_EQ(m.sync().WaitingFunctionState, 0);
  EXPECT_EQ(m.cams.C->read("StatusWord.X0"), 0.0);
  // Active (direct setting, profile 2): CamOut profile 5 is Done, the camming continues.
  out.Execute = false;
  c.Execute = false;
  m.run(1);
  c.SyncProfileReference = 2;
  c.MasterSyncPosition = 0.0;
  c.Execute = true;
  m.run(1);
  ASSERT_TRUE(c.InSync);
  out.Execute = true;
  m.run(1);
  EXPECT_TRUE(out.Done);
  EXPECT_TRUE(c.InSync);
  EXPECT_FALSE(c.CommandAborted);
  m.leader_moves(90.0);
  EXPECT_NEAR(m.f().Position, 50.0, 1e-9);  // f(90) of C
}

// Bug (issue 19): a cam interpolated during set-up, before Runtime::start(), must still count as
// interpolated afterwards — MC_CamIn used to answer 16#80AC (spec 07 §3.2: interpolate after download).
TEST(Camming, CamInterpolatedBeforeTheRuntimeStartsIsUsable) {
  Cam* early = nullptr;
  GearingMachine m(virtual_rotary_modulo(), virtual_rotary_modulo(), [&](techobjects::Runtime& r) {
    early = &points_cam(r, "E", 21, {{0.0, 0.0}, {180.0, 100.0}, {360.0, 0.0}});
    EXPECT_TRUE(early->interpolate_cam().accepted());
  });
  EXPECT_EQ(early->read("StatusWord.X5"), 1.0);  // Interpolated
  EXPECT_EQ(early->read("StatusCam.EndLeadingValue"), 360.0);
  auto& c = m.cam_in;
  c.Cam = early;
  c.SyncProfileReference = 2;
  c.ApplicationMode = 1;
  c.Execute = true;
  m.run(1);
  EXPECT_FALSE(c.Error) << std::hex << c.ErrorID;
  EXPECT_TRUE(c.InSync);
}

// Decision C20 (spec 07 §3.4: Velocity/Acceleration/Deceleration/Jerk are profile 0's only): a
// distance profile ignores them — an Acceleration above MaxAcceleration raises no alarm 502 and an
// Acceleration of 0.0 is not refused (16#8111); profile 0 still checks them. Found by
// camming_property_test.cpp (alarm 502 in synchronous travel from a profile-3 job's unused Acceleration).
TEST(Camming, DynamicParametersAreProfileZerosOnly) {
  CammingMachine m(virtual_linear(), virtual_linear());
  auto& c = m.cam_in_with(m.cams.C2, 3, 2);
  c.MasterOffset = 100.0;
  c.MasterStartDistance = 50.0;
  c.Acceleration = 20000.0;  // MaxAcceleration 10000
  c.Deceleration = 0.0;      // illegal where it is used
  c.Jerk = std::nan("");
  c.Execute = true;
  m.run(1);
  EXPECT_TRUE(c.Busy) << std::hex << c.ErrorID;
  EXPECT_FALSE(m.F->alarms().pending(techobjects::kAlarmDynamicsLimitedAcceleration));
  auto& p0 = m.cam_in2;
  p0.Cam = m.cams.C2;
  p0.SyncProfileReference = 0;
  p0.MasterOffset = 400.0;
  p0.ApplicationMode = 2;
  p0.Deceleration = 0.0;
  p0.Execute = true;
  m.run(1);
  EXPECT_EQ(p0.ErrorID, eid::kInvalidDeceleration);
}

// Decision C21 (spec 07 §3.3 not cyclic, §3.4 profile 4, §1.10 16#80AD): profile 4 becomes synchronous
// MasterStartDistance after where the leader starts; beyond the end of a non-cyclic cam the job would be
// synchronous outside the cam and end at once with a jump to f(End). It ends with 16#80AD when the leader
// starts instead, the cam free, the follower where it was. Found by camming_property_test.cpp (an 87 mm
// step).
TEST(Camming, ProfileFourSynchronousPointBeyondANonCyclicCam) {
  CammingMachine m(virtual_linear(), virtual_linear());
  auto& c = m.cam_in;
  c.Cam = m.cams.C2;  // [0, 360]
  c.SyncProfileReference = 4;
  c.MasterOffset = 0.0;
  c.MasterStartDistance = 400.0;  // the leader at 0 + 400 > 360
  c.ApplicationMode = 0;
  c.Execute = true;
  m.run(3);
  ASSERT_TRUE(c.Busy) << std::hex << c.ErrorID;  // pending while the leader stands (WaitingFunctionState 3)
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = m.move_L.Deceleration = 10000.0;
  m.move_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return c.Error; }, 10), 0);
  EXPECT_EQ(c.ErrorID, eid::kOutsideCam);
  EXPECT_FALSE(c.StartSync);
  EXPECT_EQ(m.sync().WaitingFunctionState, 0);
  EXPECT_EQ(m.cams.C2->read("StatusWord.X0"), 0.0);
  EXPECT_NEAR(m.f().Position, 0.0, 1e-12);
  // Within the cam the same job synchronizes (ProfileFourFromTheCurrentLeaderPosition does so from 0 + 40).
  c.Execute = false;
  m.run(1);
  c.MasterStartDistance = 100.0;
  c.Execute = true;
  ASSERT_GT(m.run_until([&] { return c.InSync; }, 3000), 0);
  EXPECT_NEAR(m.f().Position, 100.0 * m.l().Position / 360.0, 1e-6);
}
