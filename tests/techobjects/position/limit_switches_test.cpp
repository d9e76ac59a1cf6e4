// Travel-range limit monitors (spec 02 §4, spec 04 §3.16, §3.17, §8 rules 5-6).
#include "tomc/techobjects/position/limit_switches.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace {

using namespace tomc::techobjects::limits;
using tomc::techobjects::PositioningAxisData;

// spec 02 §11 defaults: T_s = 4 ms, MaxDeceleration 10000 mm/s², MaxJerk 1.0E6 mm/s³.
constexpr double kCycle = 0.004;
constexpr double kMaxDecel = 10000.0;
constexpr double kMaxJerk = 1.0E6;
constexpr double kInf = std::numeric_limits<double>::infinity();

static_assert(noexcept(std::declval<SoftwareLimitMonitor&>().update(SoftwareLimitInput{})));
static_assert(noexcept(std::declval<HardwareLimitMonitor&>().update(HardwareLimitInput{})));
static_assert(std::is_trivially_copyable_v<SoftwareLimitMonitor>);
static_assert(std::is_trivially_copyable_v<HardwareLimitMonitor>);

SoftwareLimitConfig sw_config(double lo, double hi, std::int32_t reached = 0, std::int32_t exceeded = 0) {
  SoftwareLimitConfig c;
  c.active = true;
  c.min_position = lo;
  c.max_position = hi;
  c.limit_reached_behavior = reached;
  c.limit_exceeded_behavior = exceeded;
  return c;
}

SoftwareLimitConfig modulo_config(double lo, double hi) {
  SoftwareLimitConfig c = sw_config(lo, hi);
  c.modulo_enable = true;
  c.modulo_start = 0.0;
  c.modulo_length = 360.0;
  return c;
}

SoftwareLimitInput sw_input(double position, double velocity, bool homed = true) {
  SoftwareLimitInput in;
  in.position = position;
  in.velocity = velocity;
  in.homed = homed;
  in.stop_deceleration = kMaxDecel;
  in.stop_jerk = 0.0;
  in.cycle_time = kCycle;
  return in;
}

// ---- reaction codes -------------------------------------------------------------------------------

// spec 02 §1.3, §4.5, spec 04 §3.16: 533 → 0: max dynamics (2), 1: current dynamics (1); following /
// kinematics axis always 2. 534 → 0: remove enable (4), 1: emergency stop, keep enable (3).
TEST(SwLimitReaction, ReachedAndExceededReactionCodes) {
  struct Row {
    std::int32_t behavior;
    bool following;
    std::int32_t reached;
    std::int32_t exceeded;
  };
  constexpr std::array kRows{Row{0, false, 2, 4}, Row{1, false, 1, 3}, Row{0, true, 2, 4},
                             Row{1, true, 2, 3}};
  for (const Row& row : kRows) {
    EXPECT_EQ(sw_limit_reached_reaction(row.behavior, row.following), row.reached) << row.behavior;
    EXPECT_EQ(sw_limit_exceeded_reaction(row.behavior), row.exceeded) << row.behavior;
  }
}

// spec 02 §4.2, spec 04 §3.17: passable switch always disables (4); non-passable per ApproachBehavior.
TEST(HwLimitReaction, PerModeAndApproachBehavior) {
  struct Row {
    std::int32_t mode;
    std::int32_t approach;
    std::int32_t reaction;
  };
  constexpr std::array kRows{Row{0, 0, 4}, Row{0, 1, 3}, Row{1, 0, 4}, Row{1, 1, 4}};
  for (const Row& row : kRows) {
    HardwareLimitConfig c;
    c.mode = row.mode;
    c.approach_behavior = row.approach;
    EXPECT_EQ(hw_limit_reaction(c), row.reaction) << row.mode << "/" << row.approach;
  }
}

// spec 04 §3.16, §3.17: the config structs are filled from the DB members.
TEST(LimitConfig, FilledFromPositioningAxisData) {
  PositioningAxisData db;
  db.PositionLimits_SW.Active = true;
  db.PositionLimits_SW.MinPosition = -12.5;
  db.PositionLimits_SW.MaxPosition = 400.0;
  db.PositionLimits_SW.LimitReachedBehavior = 1;
  db.PositionLimits_SW.LimitExceededBehavior = 1;
  db.Modulo.Enable = true;
  db.Modulo.StartValue = -180.0;
  db.Modulo.Length = 360.0;
  const SoftwareLimitConfig sw = software_limit_config(db.PositionLimits_SW, db.Modulo);
  EXPECT_TRUE(sw.active);
  EXPECT_EQ(sw.min_position, -12.5);
  EXPECT_EQ(sw.max_position, 400.0);
  EXPECT_EQ(sw.limit_reached_behavior, 1);
  EXPECT_EQ(sw.limit_exceeded_behavior, 1);
  EXPECT_TRUE(sw.modulo_enable);
  EXPECT_EQ(sw.modulo_start, -180.0);
  EXPECT_EQ(sw.modulo_length, 360.0);

  db.PositionLimits_HW.Active = true;
  db.PositionLimits_HW.MinSwitchLevel = true;
  db.PositionLimits_HW.MaxSwitchLevel = false;
  db.PositionLimits_HW.Mode = 1;
  db.PositionLimits_HW.ApproachBehavior = 1;
  const HardwareLimitConfig hw = hardware_limit_config(db.PositionLimits_HW);
  EXPECT_TRUE(hw.active);
  EXPECT_TRUE(hw.min_switch_level);
  EXPECT_FALSE(hw.max_switch_level);
  EXPECT_EQ(hw.mode, 1);
  EXPECT_EQ(hw.approach_behavior, 1);
}

// spec 02 §1.2: StatusWord.X15..X18, ErrorWord.X8/X9, WarningWord.X8/X9.
TEST(LimitStatusBits, BitPositions) {
  LimitStatusBits a;
  a.sw_limit_min_active = true;
  a.sw_limit_error = true;
  a.sw_limit_max_warning = true;
  LimitStatusBits b;
  b.hw_limit_max_active = true;
  b.hw_limit_error = true;
  const LimitStatusBits m = merge(a, b);
  EXPECT_EQ(m.status_word(), (1U << 15) | (1U << 18));
  EXPECT_EQ(m.error_word(), (1U << 8) | (1U << 9));
  EXPECT_EQ(m.warning_word(), 1U << 9);
  LimitStatusBits c;
  c.sw_limit_max_active = c.hw_limit_min_active = c.sw_limit_min_warning = true;
  EXPECT_EQ(c.status_word(), (1U << 16) | (1U << 17));
  EXPECT_EQ(c.warning_word(), 1U << 8);
}

// ---- effective limits (modulo rule) -----------------------------------------------------------------

// spec 02 §4.5, spec 04 §8 rule 5, spec 02 §11 scenario 30.
TEST(SwLimitEffective, ModuloRules) {
  struct Row {
    const char* name;
    SoftwareLimitConfig config;
    bool monitored;
    double lo;
    double hi;
  };
  SoftwareLimitConfig inactive = sw_config(-10.0, 10.0);
  inactive.active = false;
  const std::array rows{
      Row{"linear", sw_config(-1000.0, 1000.0), true, -1000.0, 1000.0},
      Row{"inactive", inactive, false, 0.0, 0.0},
      Row{"min >= max", sw_config(5.0, 5.0), false, 0.0, 0.0},
      Row{"modulo both outside", modulo_config(-50.0, 400.0), false, 0.0, 0.0},
      Row{"modulo min inside → max = boundary", modulo_config(10.0, 400.0), true, 10.0, 360.0},
      Row{"modulo max inside → min = boundary", modulo_config(-50.0, 300.0), true, 0.0, 300.0},
      Row{"modulo both inside", modulo_config(10.0, 300.0), true, 10.0, 300.0},
  };
  for (const Row& row : rows) {
    const EffectiveSoftwareLimits e = effective_software_limits(row.config);
    EXPECT_EQ(e.monitored, row.monitored) << row.name;
    if (row.monitored) {
      EXPECT_DOUBLE_EQ(e.min_position, row.lo) << row.name;
      EXPECT_DOUBLE_EQ(e.max_position, row.hi) << row.name;
    }
  }
}

// ---- braking distance / look-ahead ---------------------------------------------------------------

// spec 02 §4.5 (stop AT the limit with the current dynamic values); spec 02 §3.5 ramps.
TEST(BrakingDistance, ClosedForms) {
  struct Row {
    const char* name;
    double v, a, d, j, expected;
  };
  const double t_tri = std::sqrt(10.0 / kMaxJerk);
  const std::array rows{
      Row{"no jerk: v²/2D", 100.0, 0.0, 1000.0, 0.0, 5.0},
      Row{"no jerk, accelerating (jerk unlimited)", 100.0, 500.0, 1000.0, kInf, 5.0},
      Row{"trapezoid: v²/2D + vD/2J", 1000.0, 0.0, kMaxDecel, kMaxJerk, 50.0 + 5.0},
      Row{"triangle: v·sqrt(v/J)", 10.0, 0.0, kMaxDecel, kMaxJerk, 10.0 * t_tri},
      Row{"standstill", 0.0, 0.0, kMaxDecel, kMaxJerk, 0.0},
      Row{"no deceleration", 1.0, 0.0, 0.0, 0.0, kInf},
  };
  for (const Row& row : rows) {
    const double d = braking_distance(row.v, row.a, row.d, row.j);
    if (std::isinf(row.expected)) {
      EXPECT_TRUE(std::isinf(d)) << row.name;
    } else {
      EXPECT_NEAR(d, row.expected, 1e-9 * std::max(1.0, row.expected)) << row.name;
    }
  }
  // Still accelerating → longer; already decelerating → shorter (jerk-limited).
  const double base = braking_distance(500.0, 0.0, kMaxDecel, kMaxJerk);
  EXPECT_GT(braking_distance(500.0, 5000.0, kMaxDecel, kMaxJerk), base);
  EXPECT_LT(braking_distance(500.0, -5000.0, kMaxDecel, kMaxJerk), base);
}

// spec 02 §4.5, spec 02 §11 scenario 28: the stop triggered by the look-ahead ends exactly at the limit
// and needs no more than the configured deceleration; it is not triggered a cycle too early.
TEST(StopAtLimitLookAhead, StopsExactlyAtTheLimit) {
  struct Row {
    double velocity;
    double limit;
    double jerk;
  };
  constexpr std::array kRows{Row{1000.0, 400.0, 0.0},      Row{-1000.0, -400.0, 0.0},
                             Row{250.0, 400.0, 0.0},       Row{-777.0, -300.0, 0.0},
                             Row{1000.0, 400.0, kMaxJerk}, Row{-60.0, -2.0, kMaxJerk}};
  for (const Row& row : kRows) {
    double p = 0.0;
    int cycles = 0;
    StopLookAhead la;
    while (!(la = stop_at_limit_look_ahead(p, row.velocity, 0.0, row.limit, kMaxDecel, row.jerk, kCycle))
                .stop_now &&
           cycles < 100000) {
      p += row.velocity * kCycle;
      ++cycles;
    }
    ASSERT_TRUE(la.stop_now) << row.limit;
    ASSERT_GT(cycles, 0) << row.limit;
    const double speed = std::fabs(row.velocity);
    const double needed = braking_distance(speed, 0.0, kMaxDecel, row.jerk);
    // The stop fits now (with at most the configured deceleration) ...
    EXPECT_LE(needed, la.remaining_distance + 1e-9) << row.limit;
    if (row.jerk == 0.0) {
      EXPECT_LE(speed * speed / (2.0 * la.remaining_distance), kMaxDecel * (1.0 + 1e-9)) << row.limit;
    }
    // ... but one cycle later it would not have fitted any more.
    EXPECT_LT(la.remaining_distance - speed * kCycle, needed) << row.limit;
    EXPECT_NEAR(p + std::copysign(la.remaining_distance, row.velocity), row.limit, 1e-9);
  }
}

// ---- software limit monitor ------------------------------------------------------------------------

struct SwRun {
  SoftwareLimitResult first;  // first cycle that raised an alarm
  double stop_position = 0.0;
  double final_position = 0.0;
  int alarms = 0;
};

// Moves at `velocity` from `start` until the monitor raises an alarm, then brakes (without jerk) so that
// the setpoint ends at the stop position (spec 02 §4.5 "stop at the SW limit position").
SwRun run_towards_limit(SoftwareLimitMonitor& m, double start, double velocity) {
  SwRun run;
  double p = start;
  double v = velocity;
  double decel = 0.0;
  bool stopping = false;
  for (int i = 0; i < 100000; ++i) {
    const SoftwareLimitResult r = m.update(sw_input(p, v));
    if (r.alarm.raised()) {
      if (run.alarms == 0) run.first = r;
      ++run.alarms;
    }
    if (r.stop_now && !stopping) {
      stopping = true;
      run.stop_position = r.stop_position;
      decel = v * v / (2.0 * std::fabs(r.stop_position - p));
    }
    if (stopping) {
      const double dv = std::min(std::fabs(v), decel * kCycle);
      const double v_next = v > 0 ? v - dv : v + dv;
      p += (v + v_next) / 2.0 * kCycle;
      v = v_next;
      if (v == 0.0) {
        p = run.stop_position;  // the profile generator lands exactly on its target
        const SoftwareLimitResult last = m.update(sw_input(p, 0.0));
        if (last.alarm.raised()) ++run.alarms;
        break;
      }
    } else {
      p += v * kCycle;
    }
  }
  run.final_position = p;
  return run;
}

// spec 02 §4.5 (533 approach, 534 passed), spec 02 §1.3, spec 04 §7: both sides, both behaviours.
TEST(SwLimitMonitor, ReachedOnBothSidesStopsAtTheLimit) {
  struct Row {
    const char* name;
    double velocity;
    std::int32_t reached_behavior;
    LimitSide side;
    std::int32_t reaction;
    double limit;
    std::uint32_t status;
    std::uint32_t warning;
  };
  const std::array rows{
      Row{"max, behaviour 0", 1000.0, 0, LimitSide::kMax, 2, 400.0, 1U << 16, 1U << 9},
      Row{"max, behaviour 1", 1000.0, 1, LimitSide::kMax, 1, 400.0, 1U << 16, 1U << 9},
      Row{"min, behaviour 0", -1000.0, 0, LimitSide::kMin, 2, -300.0, 1U << 15, 1U << 8},
      Row{"min, behaviour 1", -500.0, 1, LimitSide::kMin, 1, -300.0, 1U << 15, 1U << 8},
  };
  for (const Row& row : rows) {
    SoftwareLimitMonitor m(sw_config(-300.0, 400.0, row.reached_behavior));
    const SwRun run = run_towards_limit(m, 0.0, row.velocity);
    EXPECT_EQ(run.first.alarm, (LimitAlarmEvent{kAlarmSwLimitReached, row.reaction, row.side})) << row.name;
    EXPECT_TRUE(run.first.stop_now) << row.name;
    EXPECT_EQ(run.alarms, 1) << row.name << ": no 534 when the stop ends at the limit";
    EXPECT_DOUBLE_EQ(run.final_position, row.limit) << row.name;
    const LimitStatusBits b = m.bits();
    EXPECT_EQ(b.status_word(), row.status) << row.name;
    EXPECT_EQ(b.error_word(), 1U << 8) << row.name;
    EXPECT_EQ(b.warning_word(), row.warning) << row.name;
  }
}

// spec 02 §4.5: passing the limit (e.g. the setpoint jumps over it) → 534 per LimitExceededBehavior.
TEST(SwLimitMonitor, ExceededOnBothSides) {
  struct Row {
    const char* name;
    double position;
    std::int32_t exceeded_behavior;
    LimitSide side;
    std::int32_t reaction;
    std::uint32_t status;
  };
  const std::array rows{
      Row{"max, disable", 400.5, 0, LimitSide::kMax, 4, 1U << 16},
      Row{"max, emergency stop", 401.0, 1, LimitSide::kMax, 3, 1U << 16},
      Row{"min, disable", -300.5, 0, LimitSide::kMin, 4, 1U << 15},
      Row{"min, emergency stop", -1000.0, 1, LimitSide::kMin, 3, 1U << 15},
  };
  for (const Row& row : rows) {
    SoftwareLimitMonitor m(sw_config(-300.0, 400.0, 0, row.exceeded_behavior));
    EXPECT_FALSE(m.update(sw_input(0.0, 0.0)).alarm.raised()) << row.name;
    const SoftwareLimitResult r = m.update(sw_input(row.position, 0.0));
    EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmSwLimitExceeded, row.reaction, row.side})) << row.name;
    EXPECT_EQ(r.bits.status_word(), row.status) << row.name;
    EXPECT_EQ(r.bits.error_word(), 1U << 8) << row.name;
    EXPECT_EQ(r.bits.warning_word(), 0U) << row.name << ": WarningWord only for 533 (spec 04 §7)";
    // The reaction brakes further outwards: no second alarm while unacknowledged.
    const double outwards = row.side == LimitSide::kMax ? 1.0 : -1.0;
    EXPECT_FALSE(m.update(sw_input(row.position + outwards, outwards)).alarm.raised()) << row.name;
  }
}

// spec 02 §4.5, spec 04 §3.16, scenario 29: a following / kinematics axis always stops with max dynamics.
TEST(SwLimitMonitor, FollowingAxisIgnoresLimitReachedBehavior) {
  SoftwareLimitMonitor m(sw_config(-300.0, 400.0, /*reached=*/1));
  SoftwareLimitInput in = sw_input(399.0, 500.0);
  in.following_axis = true;
  in.stop_jerk = kMaxJerk;
  const SoftwareLimitResult r = m.update(in);
  EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmSwLimitReached, 2, LimitSide::kMax}));
  EXPECT_DOUBLE_EQ(r.stop_position, 400.0);
}

// spec 02 §4.5: a 533 stop that overshoots the limit escalates to 534.
TEST(SwLimitMonitor, ReachedEscalatesToExceeded) {
  SoftwareLimitMonitor m(sw_config(-300.0, 400.0));
  double p = 0.0;
  SoftwareLimitResult r;
  while (!(r = m.update(sw_input(p, 1000.0))).stop_now)
    p += 1000.0 * kCycle;
  EXPECT_EQ(r.alarm.alarm, kAlarmSwLimitReached);
  const SoftwareLimitResult over = m.update(sw_input(400.2, 10.0));
  EXPECT_EQ(over.alarm, (LimitAlarmEvent{kAlarmSwLimitExceeded, 4, LimitSide::kMax}));
}

// spec 02 §4.5, spec 04 §8 rule 5, scenario 27: not homed → no SW monitoring; Active = FALSE → none.
TEST(SwLimitMonitor, NotHomedOrInactiveNoMonitoring) {
  SoftwareLimitMonitor m(sw_config(-300.0, 400.0));
  for (double p : {0.0, 399.0, 400.0, 1000.0, -5000.0}) {
    const SoftwareLimitResult r = m.update(sw_input(p, 1000.0, /*homed=*/false));
    EXPECT_FALSE(r.alarm.raised()) << p;
    EXPECT_FALSE(r.stop_now) << p;
    EXPECT_EQ(r.bits, LimitStatusBits{}) << p;
  }
  SoftwareLimitConfig off = sw_config(-300.0, 400.0);
  off.active = false;
  SoftwareLimitMonitor inactive(off);
  EXPECT_FALSE(inactive.update(sw_input(1000.0, 1000.0)).alarm.raised());
  // Losing the homed state clears the latched state.
  SoftwareLimitMonitor latched(sw_config(-300.0, 400.0));
  latched.update(sw_input(0.0, 0.0));
  EXPECT_TRUE(latched.update(sw_input(500.0, 0.0)).alarm.raised());
  EXPECT_EQ(latched.update(sw_input(500.0, 0.0, false)).bits, LimitStatusBits{});
}

// spec 02 §4.5 (moving clear), spec 04 §8 rule 5: after acknowledging, only back towards the work area;
// the other direction re-triggers 533.
TEST(SwLimitMonitor, MovingClearAfterAcknowledge) {
  SoftwareLimitMonitor m(sw_config(-300.0, 400.0));
  const SwRun run = run_towards_limit(m, 0.0, 1000.0);
  ASSERT_DOUBLE_EQ(run.final_position, 400.0);
  EXPECT_FALSE(m.motion_allowed(-1.0)) << "not acknowledged";
  EXPECT_FALSE(m.motion_allowed(1.0));
  m.acknowledge();
  EXPECT_TRUE(m.motion_allowed(-1.0));
  EXPECT_FALSE(m.motion_allowed(1.0));
  EXPECT_EQ(m.update(sw_input(400.0, 0.0)).bits.status_word(), 1U << 16) << "X16 stays at the limit";
  // Wrong direction: re-triggers 533 at once, stop at the limit.
  const SoftwareLimitResult again = m.update(sw_input(400.0, 10.0));
  EXPECT_EQ(again.alarm, (LimitAlarmEvent{kAlarmSwLimitReached, 2, LimitSide::kMax}));
  EXPECT_TRUE(again.stop_now);
  EXPECT_DOUBLE_EQ(again.stop_position, 400.0);
  m.acknowledge();
  // Towards the work area: no alarm, X16 resets once inside.
  SoftwareLimitResult r = m.update(sw_input(400.0, -10.0));
  EXPECT_FALSE(r.alarm.raised());
  r = m.update(sw_input(399.96, -10.0));
  EXPECT_FALSE(r.alarm.raised());
  EXPECT_EQ(r.bits, LimitStatusBits{});
  EXPECT_TRUE(m.motion_allowed(1.0));
}

// spec 02 §4.5: outside the valid range (e.g. after homing) the current position acts as the active SW
// limit until the axis is back inside; passing it against the free-move direction raises 533/534.
TEST(SwLimitMonitor, OutsideAfterHomingPositionIsTheLimit) {
  SoftwareLimitMonitor m(sw_config(-300.0, 400.0));
  SoftwareLimitResult r = m.update(sw_input(600.0, 0.0, false));
  EXPECT_EQ(r.bits, LimitStatusBits{});
  r = m.update(sw_input(600.0, 0.0, true));  // homed now
  EXPECT_FALSE(r.alarm.raised());
  EXPECT_EQ(r.bits.status_word(), 1U << 16);
  EXPECT_EQ(r.bits.error_word(), 0U);
  EXPECT_TRUE(m.motion_allowed(-1.0));
  EXPECT_FALSE(m.motion_allowed(1.0));
  // Moving back towards the work area: allowed, the active limit follows.
  r = m.update(sw_input(590.0, -100.0));
  EXPECT_FALSE(r.alarm.raised());
  // Outwards again: look-ahead stops at the active limit (590) with 533.
  r = m.update(sw_input(590.0, 100.0));
  EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmSwLimitReached, 2, LimitSide::kMax}));
  EXPECT_DOUBLE_EQ(r.stop_position, 590.0);
  m.acknowledge();
  // Passed outwards after acknowledgement: 534.
  r = m.update(sw_input(595.0, 0.0));
  EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmSwLimitExceeded, 4, LimitSide::kMax}));
  m.acknowledge();
  // Back inside: configured limits apply again.
  r = m.update(sw_input(100.0, -10.0));
  EXPECT_EQ(r.bits, LimitStatusBits{});
}

// spec 02 §4.5 modulo, spec 04 §8 rule 5, spec 02 §11 scenario 30.
TEST(SwLimitMonitor, ModuloCases) {
  {  // both outside the modulo range: no monitoring at all
    SoftwareLimitMonitor m(modulo_config(-50.0, 400.0));
    for (double p = 0.0; p < 360.0; p += 7.5)
      EXPECT_FALSE(m.update(sw_input(p, 1000.0)).alarm.raised()) << p;
  }
  {  // min inside, max → 360: the stop ends at the boundary (shown as 0), no 534 there
    SoftwareLimitMonitor m(modulo_config(10.0, 400.0));
    const SwRun run = run_towards_limit(m, 200.0, 1000.0);
    EXPECT_EQ(run.first.alarm, (LimitAlarmEvent{kAlarmSwLimitReached, 2, LimitSide::kMax}));
    EXPECT_DOUBLE_EQ(run.stop_position, 360.0);
    const SoftwareLimitResult wrapped = m.update(sw_input(0.0, 0.0));  // 360 ≡ 0
    EXPECT_FALSE(wrapped.alarm.raised());
    EXPECT_EQ(wrapped.bits.status_word(), 1U << 16);
    m.acknowledge();
    EXPECT_FALSE(m.update(sw_input(359.0, -10.0)).alarm.raised());
    EXPECT_EQ(m.bits(), LimitStatusBits{});
  }
  {  // both inside: entering the forbidden zone over the top is 534 Max, from below 534 Min
    SoftwareLimitMonitor up(modulo_config(10.0, 300.0));
    up.update(sw_input(290.0, 0.0));
    EXPECT_EQ(up.update(sw_input(305.0, 0.0)).alarm,
              (LimitAlarmEvent{kAlarmSwLimitExceeded, 4, LimitSide::kMax}));
    // Braking on past the modulo boundary: still the Max side (5 ≡ 365), no new alarm.
    const SoftwareLimitResult past = up.update(sw_input(5.0, 100.0));
    EXPECT_FALSE(past.alarm.raised());
    EXPECT_EQ(past.bits.status_word(), 1U << 16);
    SoftwareLimitMonitor down(modulo_config(10.0, 300.0));
    down.update(sw_input(20.0, 0.0));
    EXPECT_EQ(down.update(sw_input(5.0, -100.0)).alarm,
              (LimitAlarmEvent{kAlarmSwLimitExceeded, 4, LimitSide::kMin}));
  }
  {  // the monitored position is the modulo position: 700 ≡ 340 lies inside [0, 350]
    SoftwareLimitMonitor m(modulo_config(-50.0, 350.0));
    EXPECT_FALSE(m.update(sw_input(700.0, 0.0)).alarm.raised());
    EXPECT_EQ(m.bits(), LimitStatusBits{});
  }
}

// ---- hardware limit monitor ------------------------------------------------------------------------

HardwareLimitConfig hw_config(std::int32_t mode, std::int32_t approach = 0) {
  HardwareLimitConfig c;
  c.active = true;
  c.min_switch_level = true;  // high-active, so "input TRUE" = on the switch in these tests
  c.max_switch_level = true;
  c.mode = mode;
  c.approach_behavior = approach;
  return c;
}

HardwareLimitInput hw_input(bool min_on, bool max_on, double position, double velocity) {
  HardwareLimitInput in;
  in.min_switch_input = min_on;
  in.max_switch_input = max_on;
  in.position = position;
  in.velocity = velocity;
  return in;
}

// spec 02 §4.1, §4.2: passable vs non-passable, both sides; position stored only for passable switches.
TEST(HwLimitMonitor, ApproachPassableAndNonPassable) {
  struct Row {
    const char* name;
    std::int32_t mode;
    std::int32_t approach;
    LimitSide side;
    std::int32_t reaction;
    bool stored;
    std::uint32_t status;
  };
  const std::array rows{
      Row{"non-passable max, disable", 0, 0, LimitSide::kMax, 4, false, 1U << 18},
      Row{"non-passable min, emergency stop", 0, 1, LimitSide::kMin, 3, false, 1U << 17},
      Row{"passable max", 1, 1, LimitSide::kMax, 4, true, 1U << 18},
      Row{"passable min", 1, 0, LimitSide::kMin, 4, true, 1U << 17},
  };
  for (const Row& row : rows) {
    HardwareLimitMonitor m(hw_config(row.mode, row.approach));
    const double v = row.side == LimitSide::kMax ? 100.0 : -100.0;
    EXPECT_FALSE(m.update(hw_input(false, false, 0.0, v)).alarm.raised()) << row.name;
    const bool max = row.side == LimitSide::kMax;
    const HardwareLimitResult r = m.update(hw_input(!max, max, 500.0, v));
    EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmHwLimitApproached, row.reaction, row.side})) << row.name;
    EXPECT_EQ(r.bits.status_word(), row.status) << row.name;
    EXPECT_EQ(r.bits.error_word(), 1U << 9) << row.name;
    EXPECT_FALSE(r.deactivation_required) << row.name;
    EXPECT_EQ(m.detection_position_stored(), row.stored) << row.name;
    if (row.stored) {
      EXPECT_EQ(m.detection_position(), 500.0) << row.name;
    }
    // Held: no repeated alarm while braking on.
    EXPECT_FALSE(m.update(hw_input(!max, max, 501.0, v)).alarm.raised()) << row.name;
  }
}

// spec 02 §4.4: MinSwitchLevel / MaxSwitchLevel FALSE = low-active, TRUE = high-active.
TEST(HwLimitMonitor, SwitchLevelPolarity) {
  struct Row {
    bool level;
    bool input;
    bool alarm;
  };
  constexpr std::array kRows{Row{false, false, true}, Row{false, true, false}, Row{true, true, true},
                             Row{true, false, false}};
  for (const Row& row : kRows) {
    HardwareLimitConfig c = hw_config(0);
    c.max_switch_level = row.level;
    c.min_switch_level = !row.level;
    HardwareLimitMonitor m(c);
    // The min switch stays at its inactive level (input == level of max → inactive for min).
    const HardwareLimitResult r = m.update(hw_input(row.level, row.input, 0.0, 10.0));
    EXPECT_EQ(r.alarm.raised(), row.alarm) << row.level << "/" << row.input;
    if (row.alarm) {
      EXPECT_EQ(r.alarm.side, LimitSide::kMax);
    }
  }
}

// spec 02 §4.3 passable, spec 04 §8 rule 6, scenario 23: X18 resets only when the stored detection
// position is passed back, even though the input went inactive earlier; moving clear after MC_Reset only.
TEST(HwLimitMonitor, PassableMovingClear) {
  HardwareLimitMonitor m(hw_config(1));
  m.update(hw_input(false, false, 490.0, 100.0));
  EXPECT_EQ(m.update(hw_input(false, true, 500.0, 100.0)).alarm.alarm, kAlarmHwLimitApproached);
  m.update(hw_input(false, false, 503.0, 0.0));  // passed the switch, stopped at 503
  EXPECT_FALSE(m.motion_allowed(-1.0)) << "before MC_Reset";
  m.acknowledge();
  EXPECT_TRUE(m.motion_allowed(-1.0));
  EXPECT_FALSE(m.motion_allowed(1.0));
  struct Step {
    bool input;
    double position;
    bool x18;
  };
  constexpr std::array kSteps{Step{false, 503.0, true}, Step{true, 502.0, true}, Step{false, 500.5, true},
                              Step{false, 500.0, true}, Step{false, 499.9, false}};
  for (const Step& s : kSteps) {
    const HardwareLimitResult r = m.update(hw_input(false, s.input, s.position, -10.0));
    EXPECT_FALSE(r.alarm.raised()) << s.position;
    EXPECT_EQ(r.bits.hw_limit_max_active, s.x18) << s.position;
    EXPECT_FALSE(r.bits.hw_limit_error) << s.position;
  }
  EXPECT_FALSE(m.detection_position_stored());
  // Re-armed normally afterwards.
  EXPECT_EQ(m.update(hw_input(false, true, 500.0, 10.0)).alarm.alarm, kAlarmHwLimitApproached);
}

// spec 02 §4.3 non-passable, spec 04 §8 rule 6, scenario 24: X17 resets when the input is no longer at
// its active level; the axis stays enabled with ApproachBehavior 1 (reaction 3).
TEST(HwLimitMonitor, NonPassableMovingClear) {
  HardwareLimitMonitor m(hw_config(0, 1));
  m.update(hw_input(false, false, -10.0, -50.0));
  const HardwareLimitResult hit = m.update(hw_input(true, false, -20.0, -50.0));
  EXPECT_EQ(hit.alarm, (LimitAlarmEvent{kAlarmHwLimitApproached, 3, LimitSide::kMin}));
  EXPECT_FALSE(m.detection_position_stored());
  m.acknowledge();
  EXPECT_TRUE(m.motion_allowed(1.0));
  EXPECT_FALSE(m.motion_allowed(-1.0));
  HardwareLimitResult r = m.update(hw_input(true, false, -22.0, 10.0));
  EXPECT_TRUE(r.bits.hw_limit_min_active);
  r = m.update(hw_input(false, false, -21.0, 10.0));
  EXPECT_FALSE(r.alarm.raised());
  EXPECT_EQ(r.bits, LimitStatusBits{});
}

// spec 02 §4.3 step 4, scenario 25: moving against the free-move direction before leaving the switch
// re-arms the monitoring: 531 again.
TEST(HwLimitMonitor, WrongDirectionRetriggers) {
  for (std::int32_t mode : {0, 1}) {
    HardwareLimitMonitor m(hw_config(mode));
    m.update(hw_input(false, false, 490.0, 100.0));
    m.update(hw_input(false, true, 500.0, 100.0));
    m.update(hw_input(false, mode == 0, 503.0, 0.0));
    m.acknowledge();
    const HardwareLimitResult r = m.update(hw_input(false, mode == 0, 503.5, 5.0));
    EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmHwLimitApproached, 4, LimitSide::kMax})) << mode;
    EXPECT_TRUE(r.bits.hw_limit_error) << mode;
    if (mode == 1) {
      EXPECT_EQ(m.detection_position(), 500.0) << "the original detection position is kept";
    }
  }
}

// spec 02 §4.4: Active = FALSE (MC_WriteParameter 1000) disables both switches at once; activating it on
// a switch raises 531.
TEST(HwLimitMonitor, ActiveFalse) {
  HardwareLimitConfig c = hw_config(0);
  c.active = false;
  HardwareLimitMonitor m(c);
  for (int i = 0; i < 3; ++i) {
    const HardwareLimitResult r = m.update(hw_input(true, true, 0.0, 10.0));
    EXPECT_FALSE(r.alarm.raised());
    EXPECT_EQ(r.bits, LimitStatusBits{});
  }
  m.set_active(true);
  EXPECT_EQ(m.update(hw_input(false, true, 0.0, 0.0)).alarm.alarm, kAlarmHwLimitApproached);
  m.set_active(false);  // effective immediately: latched state and bits cleared
  EXPECT_EQ(m.bits(), LimitStatusBits{});
  EXPECT_TRUE(m.motion_allowed(1.0));
}

// spec 02 §4.3 special case, spec 04 §8 rule 6: both switches active (or reversed polarity) → 531, no
// moving clear until PositionLimits_HW.Active = FALSE via MC_WriteParameter 1000.
TEST(HwLimitMonitor, BothSwitchesActiveOrReversedPolarity) {
  HardwareLimitMonitor m(hw_config(0, 1));
  m.update(hw_input(false, false, 0.0, 0.0));
  HardwareLimitResult r = m.update(hw_input(true, true, 0.0, 0.0));
  EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmHwLimitApproached, 3, LimitSide::kBoth}));
  EXPECT_TRUE(r.deactivation_required);
  EXPECT_EQ(r.bits.status_word(), (1U << 17) | (1U << 18));
  m.acknowledge();
  EXPECT_FALSE(m.motion_allowed(1.0));
  EXPECT_FALSE(m.motion_allowed(-1.0));
  r = m.update(hw_input(false, false, 0.0, 0.0));
  EXPECT_TRUE(r.deactivation_required) << "stays until Active = FALSE";
  m.set_active(false);
  EXPECT_FALSE(m.update(hw_input(true, true, 0.0, 10.0)).alarm.raised());
  EXPECT_TRUE(m.motion_allowed(1.0));

  // Reversed polarity: the negative switch responds while moving positive.
  HardwareLimitMonitor rev(hw_config(1));
  rev.update(hw_input(false, false, 0.0, 50.0));
  r = rev.update(hw_input(true, false, 100.0, 50.0));
  EXPECT_EQ(r.alarm.side, LimitSide::kMin);
  EXPECT_TRUE(r.deactivation_required);
  rev.acknowledge();
  EXPECT_FALSE(rev.motion_allowed(1.0));
  EXPECT_FALSE(rev.motion_allowed(-1.0));
}

// spec 02 §4.2 ("does not distinguish approaching and passing"): a switch bouncing right after it was
// moved clear of raises 531 again, but is not taken for reversed polarity.
TEST(HwLimitMonitor, BounceAfterMovingClearIsNotReversedPolarity) {
  HardwareLimitMonitor m(hw_config(0));
  m.update(hw_input(false, false, -10.0, -50.0));
  m.update(hw_input(true, false, -20.0, -50.0));
  m.acknowledge();
  EXPECT_FALSE(m.update(hw_input(false, false, -19.0, 10.0)).bits.hw_limit_min_active);
  const HardwareLimitResult r = m.update(hw_input(true, false, -18.9, 10.0));
  EXPECT_EQ(r.alarm, (LimitAlarmEvent{kAlarmHwLimitApproached, 4, LimitSide::kMin}));
  EXPECT_FALSE(r.deactivation_required);
  m.acknowledge();
  EXPECT_TRUE(m.motion_allowed(1.0));
}

// spec 02 §4.2, spec 04 §8 rule 6, scenario 26: reversal cam during active homing → no 531.
TEST(HwLimitMonitor, HomingReversalCamNoAlarm) {
  HardwareLimitMonitor m(hw_config(0));
  HardwareLimitInput in = hw_input(false, true, 800.0, 20.0);
  in.homing_reversal = true;
  const HardwareLimitResult r = m.update(in);
  EXPECT_FALSE(r.alarm.raised());
  EXPECT_EQ(r.reversal_cam, LimitSide::kMax);
  EXPECT_EQ(r.bits, LimitStatusBits{});
}

}  // namespace
