// Leading and following value offsets on TO_SynchronousAxis: MC_PhasingAbsolute/Relative and
// MC_OffsetAbsolute/Relative against spec 07 §8 (PH-1, PH-2, OF-1, OF-2), §4.1–§4.2, §6.6 and the S5/S6
// columns and rows of the §9.19.2 matrix (spec 07 §5.1). Set-up of §8 (gearing_fixture.hpp): cycle 1 ms,
// leader L and follower F virtual, linear mm, F homed at 0, L configured as F's leading value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "gearing_fixture.hpp"
#include "tomc/instructions/mc_leading_value_additive.hpp"
#include "tomc/instructions/mc_phasing.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace {

using namespace tomc;
using techobjects::StatusWord2Bit;
using techobjects::StatusWordBit;
using techobjects::SynchronousAxis;
using tomc::testing::GearingMachine;
using tomc::testing::virtual_linear;
namespace eid = techobjects::error_id;

// The §8 machine plus one instance of each phasing/offset instruction, called every cycle after the others.
struct ShiftMachine : GearingMachine {
  explicit ShiftMachine(const std::function<void(techobjects::Runtime&)>& add = {},
                        float reversal_tolerance = 0.0F)
      : GearingMachine(virtual_linear(), virtual_linear(), add, {}, reversal_tolerance) {
    user = [this] {
      phasing_rel(*F);
      phasing_abs(*F);
      offset_rel(*F);
      offset_abs(*F);
      additive(*F);
      if (extra) extra();
    };
  }
  // MC_GearIn ratio/1 at rest: InGear at once (GI-1).
  void geared(int ratio) {
    gear.RatioNumerator = ratio;
    gear.Execute = true;
    run(2);
    ASSERT_TRUE(gear.InGear);
  }
  void leader_at(double v) {
    move_L.Velocity = v;
    move_L.Acceleration = move_L.Deceleration = 10000.0;
    move_L.Execute = false;
    run(1);
    move_L.Execute = true;
    ASSERT_GT(run_until([&] { return move_L.InVelocity; }, 2000), 0);
  }
  // PhasingRelative(10, V 100, A/D 1000, the given jerk) by dynamic parameters (profile 0), executed.
  instructions::MC_PhasingRelative<SynchronousAxis>& phasing_by_dynamics(double jerk) {
    phasing_rel.Master = leader_axis;
    phasing_rel.PhaseShift = 10.0;
    phasing_rel.ProfileReference = 0;
    phasing_rel.Velocity = 100.0;
    phasing_rel.Acceleration = phasing_rel.Deceleration = 1000.0;
    phasing_rel.Jerk = jerk;
    phasing_rel.Execute = true;
    return phasing_rel;
  }
  const techobjects::StatusSynchronizedMotion& sync() const { return F->synchronized_motion(); }
  bool bit(StatusWordBit b) const { return techobjects::test(f().StatusWord, b); }
  bool bit(StatusWord2Bit b) const { return techobjects::test(f().StatusWord2, b); }

  instructions::MC_PhasingRelative<SynchronousAxis> phasing_rel;
  instructions::MC_PhasingAbsolute<SynchronousAxis> phasing_abs;
  instructions::MC_OffsetRelative<SynchronousAxis> offset_rel;
  instructions::MC_OffsetAbsolute<SynchronousAxis> offset_abs;
  instructions::MC_LeadingValueAdditive<SynchronousAxis> additive;
  std::function<void()> extra;
};

// PH-1 (spec 07 §8; §4.1 profile 0, §6.6): GearIn 2/1, L at rest. PhasingRelative(10, V 100, A/D 1000, J 0):
// the follower's extra travel r·Δφ = 20 as a trapezoid 0.1 s + 0.1 s + 0.1 s = 0.300 s; StartPhasing and
// StatusWord.X24 while it runs; Done with CoveredPhaseShift = PhaseShift = 10. A following
// PhasingAbsolute(10) has nothing to do: Done, no motion.
TEST(PhasingOffset, PH1PhasingByDynamicParameters) {
  ShiftMachine m;
  m.geared(2);
  auto& p = m.phasing_by_dynamics(0.0);
  m.run(1);
  EXPECT_TRUE(p.Busy);
  EXPECT_TRUE(p.StartPhasing);
  double peak_velocity = 0.0;
  int x24_cycles = 0;
  m.extra = [&] {
    peak_velocity = std::max(peak_velocity, std::fabs(m.f().Velocity));
    x24_cycles += m.bit(StatusWordBit::kPhasingCommand) ? 1 : 0;
  };
  const int cycles = 1 + m.run_until([&] { return p.Done; }, 1000);
  EXPECT_NEAR(cycles, 300, 2);
  EXPECT_NEAR(x24_cycles, 299, 2);
  EXPECT_NEAR(peak_velocity, 100.0, 1e-6);  // the job's Velocity, the follower's extra travel
  EXPECT_NEAR(m.f().Position, 20.0, 1e-9);
  EXPECT_NEAR(p.CoveredPhaseShift, 10.0, 1e-12);
  EXPECT_NEAR(m.sync().PhaseShift, 10.0, 1e-12);
  EXPECT_NEAR(m.F->read("StatusSynchronizedMotion.FunctionLeadingValue.Position"), 10.0, 1e-12);
  EXPECT_FALSE(m.bit(StatusWordBit::kPhasingCommand));
  EXPECT_TRUE(m.gear.InGear);
  // The shifted gear line: L +5 -> F = 2·(5 + 10) = 30.
  m.move_rel_L.Distance = 5.0;
  m.move_rel_L.Velocity = 50.0;
  m.move_rel_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_rel_L.Done; }, 2000), 0);
  EXPECT_NEAR(m.f().Position, 30.0, 1e-9);
  // PhasingAbsolute to the value reached: Done in its call, no motion.
  auto& a = m.phasing_abs;
  a.Master = m.leader_axis;
  a.PhaseShift = 10.0;
  a.ProfileReference = 0;
  a.Execute = true;
  m.run(1);
  EXPECT_TRUE(a.Done);
  EXPECT_NEAR(a.AbsolutePhaseShift, 10.0, 1e-12);
  EXPECT_NEAR(m.f().Position, 30.0, 1e-9);
  // PhasingAbsolute(4): back by 6, the follower by 12.
  a.Execute = false;
  m.run(1);
  a.PhaseShift = 4.0;
  a.Velocity = 100.0;
  a.Acceleration = a.Deceleration = 1000.0;
  a.Jerk = 0.0;
  a.Execute = true;
  ASSERT_GT(m.run_until([&] { return a.Done; }, 1000), 0);
  EXPECT_NEAR(a.AbsolutePhaseShift, 4.0, 1e-12);
  EXPECT_NEAR(m.f().Position, 18.0, 1e-9);
}

// Spec 07 §4.1 profile 0 with a jerk limit (the 7-segment rest-to-rest travel the job keeps, decision C17):
// GearIn 2/1, PhasingRelative(10, V 100, A/D 1000, J 100,000): the follower's extra travel 20 as an S-curve,
// jerk ramps 0.01 s, acceleration phases 0.11 s (v = a²/j + a·0.09 = 100) covering 5.5 each, cruise
// 9 / 100 = 0.09 s: 0.31 s = 310 cycles. Half way (0.155 s, the symmetric midpoint) the phase shift is 5.
TEST(PhasingOffset, PhasingProfile0WithJerkIsTheSevenSegmentSCurve) {
  ShiftMachine m;
  m.geared(2);
  auto& p = m.phasing_by_dynamics(100000.0);
  double peak_velocity = 0.0;
  double peak_acceleration = 0.0;
  m.extra = [&] {
    peak_velocity = std::max(peak_velocity, std::fabs(m.f().Velocity));
    peak_acceleration = std::max(peak_acceleration, std::fabs(m.f().Acceleration));
  };
  m.run(1);  // the call's cycle (as PH-1); the travel starts in the next MC_Interpolator
  m.run(155);
  EXPECT_NEAR(m.sync().PhaseShift, 5.0, 1e-9);
  EXPECT_NEAR(m.f().Position, 10.0, 1e-9);
  const int cycles = 1 + 155 + m.run_until([&] { return p.Done; }, 1000);
  EXPECT_NEAR(cycles, 310, 1);
  EXPECT_NEAR(peak_velocity, 100.0, 1e-6);
  EXPECT_NEAR(peak_acceleration, 1000.0, 1e-6);
  EXPECT_NEAR(m.f().Position, 20.0, 1e-9);
  EXPECT_NEAR(p.CoveredPhaseShift, 10.0, 1e-12);
}

// OF-1 (spec 07 §8; §4.2 profile 1, §6.6): GearIn 1/1, L at +100 mm/s. OffsetRelative(10, OffsetDistance 90):
// StartOffset and StatusWord2.X4 while L covers 90 (0.9 s); half way (ξ = 1/2, S = 1/2) F − L = 5; at the
// end F − L = 10, Done, Offset = 10; the follower's velocity has no step (S' and S'' are 0 at both ends).
TEST(PhasingOffset, OF1FollowingValueOffsetOverADistance) {
  ShiftMachine m;
  m.geared(1);
  m.leader_at(100.0);
  auto& o = m.offset_rel;
  o.Offset = 10.0;
  o.ProfileReference = 1;
  o.OffsetDistance = 90.0;
  o.Execute = true;
  m.run(1);
  const double l0 = m.l().Position;
  EXPECT_TRUE(o.StartOffset);
  double largest_velocity_step = 0.0;
  double last_v = m.f().Velocity;
  bool half_seen = false;
  m.extra = [&] {
    largest_velocity_step = std::max(largest_velocity_step, std::fabs(m.f().Velocity - last_v));
    last_v = m.f().Velocity;
    if (!half_seen && m.l().Position - l0 >= 45.0 - 1e-9) {
      half_seen = true;
      EXPECT_NEAR(m.f().Position - m.l().Position, 5.0, 1e-6);
      EXPECT_TRUE(m.bit(StatusWord2Bit::kOffsetCommand));
    }
  };
  const int cycles = m.run_until([&] { return o.Done; }, 2000);
  EXPECT_NEAR(cycles, 900, 2);
  EXPECT_TRUE(half_seen);
  EXPECT_NEAR(m.f().Position - m.l().Position, 10.0, 1e-6);
  EXPECT_NEAR(o.CoveredOffset, 10.0, 1e-12);
  EXPECT_NEAR(m.sync().Offset, 10.0, 1e-12);
  EXPECT_FALSE(m.bit(StatusWord2Bit::kOffsetCommand));
  // Peak offset velocity Δo·S'(1/2)·v/L = 10·1.875·100/90 = 20.8 mm/s, reached smoothly: per cycle the
  // velocity changes by at most Δo·max|S''|·v²/L²·T = 10·5.77·100²/90²·0.001 = 0.071 mm/s.
  EXPECT_LT(largest_velocity_step, 0.075);
  // FunctionFollowingValue is before the offset (spec 07 §1.9).
  m.run(1);
  EXPECT_NEAR(m.sync().FunctionFollowingValue.Position, m.f().Position - 10.0, 1e-9);
}

// spec 07 §8 OF-1, reversal: the leading value reverses mid-offset -> Error 16#808C; the part covered stays.
TEST(PhasingOffset, OF1ReversalCancelsWithError808C) {
  ShiftMachine m;
  m.geared(1);
  m.leader_at(100.0);
  auto& o = m.offset_rel;
  o.Offset = 10.0;
  o.OffsetDistance = 90.0;
  o.Execute = true;
  m.run(450);  // half way
  m.leader_at(-100.0);
  EXPECT_TRUE(o.Error);
  EXPECT_EQ(o.ErrorID, eid::kLeadingValueReversed);
  EXPECT_GT(m.sync().Offset, 4.0);
  EXPECT_LT(m.sync().Offset, 6.0);
  EXPECT_TRUE(m.gear.InGear);
  const double offset = m.sync().Offset;
  m.run(100);
  EXPECT_NEAR(m.f().Position - m.l().Position, offset, 1e-9);
}

// The V10 leading value reversal tolerance (spec 07 §1.6 [OPEN], tomc extension; decision C27) at its edge:
// GearIn 1/1 at rest, OffsetRelative(10, OffsetDistance 90); L moves +20, back by `back`, forward +10 and
// back by `back` again. Moving back by at most the tolerance from the farthest value (20, then 29.5) keeps
// the offset job; 0.001 more cancels it with 16#808C (tolerance 0: any reversal does).
TEST(PhasingOffset, ReversalToleranceOfTheOffsetAtItsEdge) {
  struct Row {
    float tolerance;
    double back;
    bool cancelled;
  };
  for (const Row& r : {Row{0.5F, 0.5, false}, Row{0.5F, 0.501, true}, Row{0.0F, 0.001, true}}) {
    ShiftMachine m({}, r.tolerance);
    m.geared(1);
    auto& o = m.offset_rel;
    o.Offset = 10.0;
    o.OffsetDistance = 90.0;
    o.Execute = true;
    m.run(1);
    ASSERT_TRUE(o.StartOffset);
    const auto move_leader = [&](double distance) {
      m.move_rel_L.Distance = distance;
      m.move_rel_L.Execute = false;
      m.run(1);
      m.move_rel_L.Execute = true;
      ASSERT_GT(m.run_until([&] { return m.move_rel_L.Done || o.Error; }, 2000), 0);
    };
    for (const double distance : {20.0, -r.back, 10.0, -r.back}) {
      move_leader(distance);
      if (o.Error) break;
    }
    EXPECT_EQ(o.Error, r.cancelled) << r.tolerance << " " << r.back;
    EXPECT_EQ(o.ErrorID, r.cancelled ? eid::kLeadingValueReversed : 0) << r.tolerance << " " << r.back;
    if (r.cancelled) {  // in the first move back, as soon as it went beyond the tolerance
      EXPECT_LT(m.l().Position, 20.0 - r.tolerance);
      EXPECT_GE(m.l().Position, 20.0 - r.back - 1e-9);
    } else {  // both moves back kept the job: it goes on from the farthest value, 29.5
      EXPECT_NEAR(m.l().Position, 29.0, 1e-12);
      EXPECT_TRUE(o.Busy);
      EXPECT_FALSE(o.Done);
    }
    EXPECT_TRUE(m.gear.InGear);
  }
}

// OF-2 (spec 07 §8; §1.8): offsets and phase shift are reset when the synchronous operation is overridden.
TEST(PhasingOffset, OF2ResetOnOverride) {
  ShiftMachine m;
  m.geared(1);
  auto& p = m.phasing_rel;
  p.PhaseShift = 10.0;
  p.Velocity = 100.0;
  p.Acceleration = p.Deceleration = 1000.0;
  p.Jerk = 0.0;
  p.Execute = true;
  ASSERT_GT(m.run_until([&] { return p.Done; }, 1000), 0);
  m.leader_at(100.0);
  auto& o = m.offset_abs;
  o.Offset = 10.0;
  o.OffsetDistance = 50.0;
  o.Execute = true;
  ASSERT_GT(m.run_until([&] { return o.Done; }, 1000), 0);
  EXPECT_NEAR(o.AbsoluteOffset, 10.0, 1e-12);
  EXPECT_NEAR(m.f().Position - m.l().Position, 20.0, 1e-6);  // φ 10 at ratio 1 plus o 10
  m.halt_F.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.gear.CommandAborted);
  EXPECT_EQ(m.sync().PhaseShift, 0.0);
  EXPECT_EQ(m.sync().Offset, 0.0);
  m.gear.Execute = false;
  m.run(1);
  m.gear.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.gear.InGear; }, 2000), 0);
  EXPECT_EQ(m.sync().PhaseShift, 0.0);
  EXPECT_EQ(m.sync().Offset, 0.0);
}

// PH-2 and the requirements (spec 07 §4.1, §4.2, §1.10): the ErrorIDs of a rejected phasing / offset job;
// a running job is not affected.
TEST(PhasingOffset, PH2RequirementsAndExclusion) {
  ShiftMachine m;
  // No synchronous operation: 16#8075.
  m.offset_rel.Offset = 1.0;
  m.offset_rel.OffsetDistance = 10.0;
  m.offset_rel.Execute = true;
  m.run(1);
  EXPECT_EQ(m.offset_rel.ErrorID, eid::kNoSynchronousOperation);
  m.offset_rel.Execute = false;
  m.run(1);
  // Synchronizing, not yet synchronous (GearIn to a moving leader): 16#80A9.
  m.leader_at(100.0);
  m.gear.Acceleration = m.gear.Deceleration = 1000.0;
  m.gear.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear.Busy);
  ASSERT_FALSE(m.gear.InGear);
  m.phasing_rel.PhaseShift = 1.0;
  m.phasing_rel.Execute = true;
  m.run(1);
  EXPECT_EQ(m.phasing_rel.ErrorID, eid::kNotSynchronous);
  m.phasing_rel.Execute = false;
  ASSERT_GT(m.run_until([&] { return m.gear.InGear; }, 1000), 0);
  // An offset running: a phasing job is refused with 16#808A, the offset goes on (§9.19.2 Phasing × S6 "N").
  m.offset_rel.OffsetDistance = 100.0;
  m.offset_rel.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.offset_rel.Busy);
  m.phasing_rel.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.phasing_rel.Error);
  EXPECT_EQ(m.phasing_rel.ErrorID, eid::kPhasingAndOffsetExclusive);
  EXPECT_TRUE(m.offset_rel.Busy);
  m.phasing_rel.Execute = false;
  // Parameter errors.
  struct Case {
    const char* what;
    std::function<void(instructions::MC_PhasingRelative<SynchronousAxis>&)> set;
    std::uint16_t error_id;
  };
  const Case cases[] = {
      {"ProfileReference 3", [](auto& p) { p.ProfileReference = 3; }, eid::kInvalidProfileReference},
      {"PhaseShift NaN", [](auto& p) { p.PhaseShift = std::nan(""); }, eid::kInvalidPhaseShift},
      {"PhasingDistance 0", [](auto& p) { p.ProfileReference = 1; }, eid::kInvalidPhasingDistance},
      {"StartPosition inf",
       [](auto& p) {
         p.ProfileReference = 2;
         p.PhasingDistance = 1.0;
         p.StartPosition = INFINITY;
       },
       eid::kInvalidStartPosition},
      {"Direction 4",
       [](auto& p) {
         p.ProfileReference = 1;
         p.PhasingDistance = 1.0;
         p.Direction = 4;
       },
       eid::kInvalidDirection},
  };
  for (const Case& k : cases) {
    auto& p = m.phasing_rel;
    p = {};
    k.set(p);
    p.Execute = true;
    m.run(1);
    EXPECT_TRUE(p.Error) << k.what;
    EXPECT_EQ(p.ErrorID, k.error_id) << k.what;
    p.Execute = false;
    m.run(1);
  }
  EXPECT_TRUE(m.offset_rel.Busy);
}

// spec 07 §8 PH-2 and GV-2: phasing profile 0 only in gearing (16#80A8); nothing during MC_GearInVelocity
// (16#8079).
TEST(PhasingOffset, PH2ProfileZeroOnlyInGearingNothingInVelocityGearing) {
  techobjects::Cam* cam = nullptr;
  ShiftMachine m([&](techobjects::Runtime& r) {
    cam = &r.emplace<techobjects::Cam>("C", techobjects::CamVariant::kCam, 11);
    (void)cam->write_point(1, {0.0, 0.0}, true);
    (void)cam->write_point(2, {360.0, 100.0}, true);
  });
  ASSERT_TRUE(cam->interpolate_cam().accepted());
  m.cam_in.Cam = cam;
  m.cam_in.SyncProfileReference = 2;
  m.cam_in.ApplicationMode = 2;
  m.cam_in.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.cam_in.InSync);
  m.phasing_rel.PhaseShift = 1.0;
  m.phasing_rel.ProfileReference = 0;
  m.phasing_rel.Execute = true;
  m.run(1);
  EXPECT_EQ(m.phasing_rel.ErrorID, eid::kPhasingProfileNeedsGearing);
  m.phasing_rel.Execute = false;
  m.gear_velocity.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.gear_velocity.Busy);
  m.offset_abs.Offset = 1.0;
  m.offset_abs.OffsetDistance = 1.0;
  m.offset_abs.Execute = true;
  m.run(1);
  EXPECT_EQ(m.offset_abs.ErrorID, eid::kVelocityGearingActive);
}

// Phasing over a leading value distance during camming (spec 07 §4.1 profile 1, §6.6): cam C2 a line 0…100
// over 0…360 (slope 5/18), cyclic appending, set directly at L = F = 0; L at +100 mm/s. PhasingRelative(36,
// PhasingDistance 180): after L covered 180 the function leading value is L + 36 and F = (L + 36)·5/18.
TEST(PhasingOffset, PhasingOverADistanceDuringCamming) {
  techobjects::Cam* cam = nullptr;
  ShiftMachine m([&](techobjects::Runtime& r) {
    cam = &r.emplace<techobjects::Cam>("C2", techobjects::CamVariant::kCam, 12);
    (void)cam->write_point(1, {0.0, 0.0}, true);
    (void)cam->write_point(2, {360.0, 100.0}, true);
  });
  ASSERT_TRUE(cam->interpolate_cam().accepted());
  m.cam_in.Cam = cam;
  m.cam_in.SyncProfileReference = 2;
  m.cam_in.ApplicationMode = 2;
  m.cam_in.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.cam_in.InSync);
  m.leader_at(100.0);
  auto& p = m.phasing_rel;
  p.ProfileReference = 1;
  p.PhaseShift = 36.0;
  p.PhasingDistance = 180.0;
  p.Execute = true;
  m.run(1);
  const double l0 = m.l().Position;
  ASSERT_GT(m.run_until([&] { return p.Done; }, 3000), 0);
  EXPECT_NEAR(m.l().Position - l0, 180.0, 0.1 + 1e-9);  // within the cycle's travel
  m.run(1);
  EXPECT_NEAR(m.sync().FunctionLeadingValue.Position, m.l().Position + 36.0, 1e-9);
  EXPECT_NEAR(m.f().Position, (m.l().Position + 36.0) * 100.0 / 360.0, 1e-9);
  EXPECT_NEAR(p.CoveredPhaseShift, 36.0, 1e-12);
}

// Profile 2 (spec 07 §4.2, §6.6): the offset waits (StatusWord2.X5, no StartOffset) until the effective
// leading value crosses StartPosition, then runs over OffsetDistance from there; profile 5 cancels a waiting
// job only.
TEST(PhasingOffset, ProfileTwoWaitsForStartPositionProfileFiveCancels) {
  ShiftMachine m;
  m.geared(1);
  m.leader_at(100.0);
  auto& o = m.offset_rel;
  o.ProfileReference = 2;
  o.Offset = 4.0;
  o.OffsetDistance = 20.0;
  o.StartPosition = m.l().Position + 30.1;  // 30 mm ahead when the job is called in the next cycle
  o.Execute = true;
  m.run(2);  // the status words follow in the next MC_Interpolator
  EXPECT_TRUE(o.Busy);
  EXPECT_FALSE(o.StartOffset);
  EXPECT_TRUE(m.bit(StatusWord2Bit::kOffsetCommandWaiting));
  EXPECT_FALSE(m.bit(StatusWord2Bit::kOffsetCommand));
  const int until_start = m.run_until([&] { return o.StartOffset; }, 1000);
  EXPECT_NEAR(until_start + 1, 300, 2);
  const int until_done = m.run_until([&] { return o.Done; }, 1000);
  EXPECT_NEAR(until_done, 200, 2);
  EXPECT_NEAR(m.f().Position - m.l().Position, 4.0, 1e-6);
  // A waiting job is cancelled by profile 5 (CommandAborted), the cancelling job is Done.
  auto& w = m.offset_abs;
  w.ProfileReference = 2;
  w.Offset = 0.0;
  w.OffsetDistance = 20.0;
  w.StartPosition = m.l().Position + 500.0;
  w.Execute = true;
  m.run(1);
  ASSERT_TRUE(w.Busy);
  o.Execute = false;
  m.run(1);
  o.ProfileReference = 5;
  o.Execute = true;
  m.run(1);
  EXPECT_TRUE(o.Done);
  EXPECT_TRUE(w.CommandAborted);
  m.run(1);
  EXPECT_FALSE(m.bit(StatusWord2Bit::kOffsetCommandWaiting));
  EXPECT_NEAR(m.sync().Offset, 4.0, 1e-12);
}

// The S5 (phasing) column of §9.19.2 as behaviour (spec 07 §5.1): each new job against a running
// MC_PhasingRelative over a long distance — A: the phasing ends with CommandAborted; N: the new job is
// refused and the phasing goes on; "-": both go on.
TEST(PhasingOffset, OverrideMatrixColumnS5Phasing) {
  struct Row {
    const char* new_job;
    std::function<void(ShiftMachine&)> start;
    std::function<bool(ShiftMachine&)> new_job_error;
    char cell;
  };
  const Row rows[] = {
      {"MC_Halt", [](ShiftMachine& m) { m.halt_F.Execute = true; },
       [](ShiftMachine& m) { return m.halt_F.Error; }, 'A'},
      {"MC_MoveAbsolute BufferMode 1",
       [](ShiftMachine& m) {
         m.move_abs_F.BufferMode = 1;
         m.move_abs_F.Execute = true;
       },
       [](ShiftMachine& m) { return m.move_abs_F.Error; }, 'N'},
      {"MC_MoveVelocity", [](ShiftMachine& m) { m.move_F.Execute = true; },
       [](ShiftMachine& m) { return m.move_F.Error; }, 'A'},
      {"MC_Stop", [](ShiftMachine& m) { m.stop_F.Execute = true; },
       [](ShiftMachine& m) { return m.stop_F.Error; }, 'A'},
      {"MC_GearIn", [](ShiftMachine& m) { m.gear2.Execute = true; },
       [](ShiftMachine& m) { return m.gear2.Error; }, 'A'},
      {"MC_PhasingAbsolute",
       [](ShiftMachine& m) {
         m.phasing_abs.ProfileReference = 1;
         m.phasing_abs.PhasingDistance = 10.0;
         m.phasing_abs.PhaseShift = 3.0;
         m.phasing_abs.Execute = true;
       },
       [](ShiftMachine& m) { return m.phasing_abs.Error; }, 'A'},
      {"MC_OffsetRelative",
       [](ShiftMachine& m) {
         m.offset_rel.OffsetDistance = 10.0;
         m.offset_rel.Offset = 1.0;
         m.offset_rel.Execute = true;
       },
       [](ShiftMachine& m) { return m.offset_rel.Error; }, 'N'},
      {"MC_GearOut pending",
       [](ShiftMachine& m) {
         m.gear_out.SyncProfileReference = 1;
         m.gear_out.MasterStopDistance = 10.0;
         m.gear_out.SlavePosition = 1e6;
         m.gear_out.Execute = true;
       },
       [](ShiftMachine& m) { return m.gear_out.Error; }, '-'},
  };
  for (const Row& r : rows) {
    ShiftMachine m;
    m.geared(1);
    m.leader_at(10.0);
    auto& p = m.phasing_rel;
    p.ProfileReference = 1;
    p.PhaseShift = 5.0;
    p.PhasingDistance = 1000.0;
    p.Execute = true;
    m.run(2);
    ASSERT_TRUE(p.Busy) << r.new_job;
    r.start(m);
    m.run(2);
    EXPECT_EQ(p.CommandAborted, r.cell == 'A') << r.new_job;
    EXPECT_EQ(p.Busy, r.cell != 'A') << r.new_job;
    EXPECT_EQ(r.new_job_error(m), r.cell == 'N') << r.new_job;
  }
}

// LV-1 (spec 07 §8; §4.3, §1.8): GearIn 1/1 InGear with L at rest at 100. MC_LeadingValueAdditive(Position
// 0.5): in the next cycle EffectiveLeadingValue = 100.5 and F jumps +0.5 (no ramp), StatusSynchronizedMotion.
// StatusWord.X4. MC_Halt on F aborts the gearing, the additive job stays Busy; MC_Stop too. Enable = FALSE:
// X4 FALSE, EffectiveLeadingValue 100. A second instance's start ends the first (§9.19.2 S7 "A").
TEST(PhasingOffset, LV1AdditiveLeadingValue) {
  ShiftMachine m;
  m.move_rel_L.Distance = 100.0;
  m.move_rel_L.Velocity = 500.0;
  m.move_rel_L.Execute = true;
  ASSERT_GT(m.run_until([&] { return m.move_rel_L.Done; }, 2000), 0);
  m.geared(1);
  const double f0 = m.f().Position;
  m.additive.Position = 0.5;
  m.additive.Enable = true;
  m.run(1);
  EXPECT_TRUE(m.additive.Busy);
  m.run(1);
  EXPECT_NEAR(m.sync().EffectiveLeadingValue.Position, 100.5, 1e-12);
  EXPECT_NEAR(m.f().Position - f0, 0.5, 1e-12);  // at once
  EXPECT_EQ(m.F->read("StatusSynchronizedMotion.StatusWord.X4"), 1.0);
  m.halt_F.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.gear.CommandAborted);
  EXPECT_TRUE(m.additive.Busy);
  m.stop_F.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.additive.Busy);
  m.additive.Enable = false;
  m.run(2);
  EXPECT_FALSE(m.additive.Busy);
  EXPECT_EQ(m.F->read("StatusSynchronizedMotion.StatusWord.X4"), 0.0);
  EXPECT_NEAR(m.sync().EffectiveLeadingValue.Position, 100.0, 1e-12);
  // Another instance ends the running one; a value that is not finite at the start is refused.
  instructions::MC_LeadingValueAdditive<SynchronousAxis> second;
  m.extra = [&] { second(*m.F); };
  m.additive.Enable = true;
  m.run(1);
  ASSERT_TRUE(m.additive.Busy);
  second.Position = 1.0;
  second.Enable = true;
  m.run(2);
  EXPECT_TRUE(second.Busy);
  EXPECT_FALSE(m.additive.Busy);
  EXPECT_NEAR(m.sync().EffectiveLeadingValue.Position, 101.0, 1e-12);
  second.Enable = false;
  m.run(1);
  second.Position = NAN;
  second.Enable = true;
  m.run(1);
  EXPECT_TRUE(second.Error);
  EXPECT_FALSE(second.Busy);
}

// Spec 07 §4.3, decision C19: a Position that is not finite answers with Error/16#8118 while it lasts and
// keeps the last value (no step, no silent NaN: MotionIn ends its job instead, which here would drop the
// additive value, itself a step); a finite value again clears the error. MC_Reset with Restart = TRUE ends
// the job (§4.3 "aborted only by another MC_LeadingValueAdditive and by MC_Reset with Restart = TRUE").
TEST(PhasingOffset, AdditiveNotFiniteAnswersWithAnErrorAndRestartEndsIt) {
  ShiftMachine m;
  instructions::MC_Reset<SynchronousAxis> reset;
  m.extra = [&] { reset(*m.F); };
  m.geared(1);
  m.additive.Enable = true;
  m.additive.Position = 0.5;
  m.run(2);
  EXPECT_NEAR(m.f().Position, 0.5, 1e-12);
  m.additive.Position = std::nan("");
  m.run(3);
  EXPECT_TRUE(m.additive.Busy);
  EXPECT_TRUE(m.additive.Error);
  EXPECT_EQ(m.additive.ErrorID, eid::kInvalidPosition);  // 16#8118
  EXPECT_NEAR(m.f().Position, 0.5, 1e-12);
  m.additive.Position = 0.25;
  m.run(2);
  EXPECT_FALSE(m.additive.Error);
  EXPECT_NEAR(m.f().Position, 0.25, 1e-12);
  m.power_F.Enable = false;
  m.run(3);
  EXPECT_TRUE(m.additive.Busy);  // disabling does not end it
  reset.Restart = true;
  reset.Execute = true;
  ASSERT_GT(m.run_until([&] { return reset.Done; }, 10), 0);
  m.run(1);
  EXPECT_FALSE(m.additive.Busy);
  EXPECT_FALSE(m.additive.Error);
}

}  // namespace
