// Following-error monitoring (spec 02 §6.2), positioning monitoring (§6.1) and standstill signal (§6.3).
#include "tomc/techobjects/position/position_monitoring.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace tomc::techobjects {
namespace {

static_assert(noexcept(std::declval<PositioningMonitor&>().update(0.0)));
static_assert(noexcept(std::declval<StandstillSignal&>().update(0.0)));
static_assert(noexcept(std::declval<const FollowingErrorMonitor&>().check(0.0, 0.0)));

// ---- §6.2 following-error monitoring ----

FollowingErrorMonitoringConfig fe_config() {
  FollowingErrorMonitoringConfig c;
  c.MinValue = 2.0;
  c.MaxValue = 10.0;
  c.MinVelocity = 10.0;
  c.MaxVelocity = 500.0;
  c.WarningLevel = 90.0;
  return c;
}

// spec 02 §6.2 (following-error monitoring: the characteristic, 522 warning, 521 error).
TEST(FollowingErrorMonitor, PermittedErrorCharacteristic) {
  const FollowingErrorMonitor m(fe_config());
  EXPECT_DOUBLE_EQ(m.permitted(0.0), 2.0);
  EXPECT_DOUBLE_EQ(m.permitted(5.0), 2.0);
  EXPECT_DOUBLE_EQ(m.permitted(10.0), 2.0);  // |v| <= MinVelocity
  EXPECT_DOUBLE_EQ(m.permitted(-10.0), 2.0);
  EXPECT_DOUBLE_EQ(m.permitted(255.0), 6.0);  // 2 + 8·245/490
  EXPECT_DOUBLE_EQ(m.permitted(-255.0), 6.0);
  EXPECT_DOUBLE_EQ(m.permitted(132.5), 4.0);  // 2 + 8·122.5/490
  EXPECT_DOUBLE_EQ(m.permitted(500.0), 10.0);
  EXPECT_DOUBLE_EQ(m.permitted(800.0), 10.0);  // clamped above v_max
}

// spec 02 §6.2 (following-error monitoring: the characteristic, 522 warning, 521 error).
TEST(FollowingErrorMonitor, DegenerateVelocityRange) {
  auto c = fe_config();
  c.MaxVelocity = 10.0;  // = MinVelocity
  const FollowingErrorMonitor m(c);
  EXPECT_DOUBLE_EQ(m.permitted(10.0), 2.0);
  EXPECT_DOUBLE_EQ(m.permitted(10.5), 10.0);
}

// spec 02 §6.2 (following-error monitoring: the characteristic, 522 warning, 521 error).
TEST(FollowingErrorMonitor, WarningAndErrorThresholds) {
  auto c = fe_config();
  c.MinValue = 100.0;  // the spec example: FE_max = 100 mm, WarningLevel 90 % -> warning from 90 mm
  c.MaxValue = 200.0;
  const FollowingErrorMonitor m(c);
  EXPECT_EQ(m.check(89.99, 0.0).alarm, FollowingErrorAlarm::kNone);
  EXPECT_EQ(m.check(90.0, 0.0).alarm, FollowingErrorAlarm::kWarning522);  // >= warning level
  EXPECT_EQ(m.check(-95.0, 0.0).alarm, FollowingErrorAlarm::kWarning522);
  EXPECT_EQ(m.check(100.0, 0.0).alarm, FollowingErrorAlarm::kWarning522);  // not yet > FE_max
  EXPECT_EQ(m.check(100.001, 0.0).alarm, FollowingErrorAlarm::kError521);
  EXPECT_EQ(m.check(-100.001, 0.0).alarm, FollowingErrorAlarm::kError521);
  const auto r = m.check(0.0, 0.0);
  EXPECT_DOUBLE_EQ(r.permitted, 100.0);
  EXPECT_DOUBLE_EQ(r.warning_threshold, 90.0);
  // velocity-dependent: at v_max the limit is 200 (warning from 180), at standstill 100
  EXPECT_EQ(m.check(150.0, 500.0).alarm, FollowingErrorAlarm::kNone);
  EXPECT_EQ(m.check(150.0, 0.0).alarm, FollowingErrorAlarm::kError521);
  EXPECT_EQ(m.check(std::nan(""), 0.0).alarm, FollowingErrorAlarm::kError521);
}

// spec 02 §6.2 (following-error monitoring: the characteristic, 522 warning, 521 error).
TEST(FollowingErrorMonitor, DisabledMonitoringReportsNothing) {
  auto c = fe_config();
  c.EnableMonitoring = false;
  const FollowingErrorMonitor m(c);
  const auto r = m.check(1000.0, 0.0);
  EXPECT_EQ(r.alarm, FollowingErrorAlarm::kNone);
  EXPECT_DOUBLE_EQ(r.permitted, 2.0);
}

// ---- §6.1 positioning monitoring ----

PositioningMonitoringConfig pm_config(double tolerance, double dwell) {
  return PositioningMonitoringConfig{0.01, tolerance, dwell, 0.001};
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, InactiveUntilStarted) {
  PositioningMonitor m(pm_config(0.01, 0.005));
  EXPECT_EQ(m.update(0.0).outcome, PositioningOutcome::kInactive);
  m.start(5.0);
  EXPECT_EQ(m.status().outcome, PositioningOutcome::kInProgress);
  m.cancel();
  EXPECT_EQ(m.update(5.0).outcome, PositioningOutcome::kInactive);
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, DoneExactlyMinDwellTimeAfterArrival) {
  PositioningMonitor m(pm_config(0.01, 0.005));  // 10 cycles tolerance, 5 cycles dwell
  EXPECT_EQ(m.dwell_cycles(), 5u);
  m.start(10.0);
  // cycles 0..2 outside, arrival in cycle 3 -> Done in cycle 3 + 5 = 8
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(m.update(9.9).outcome, PositioningOutcome::kInProgress) << k;
  for (int k = 3; k < 8; ++k)
    EXPECT_EQ(m.update(10.005).outcome, PositioningOutcome::kInProgress) << k;
  const auto s = m.update(9.995);
  EXPECT_EQ(s.outcome, PositioningOutcome::kDone);
  EXPECT_EQ(s.additional_value, 0u);
  EXPECT_EQ(m.update(50.0).outcome, PositioningOutcome::kDone);  // latched until the next start
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, WindowBoundaryCountsAsInside) {
  PositioningMonitor m(PositioningMonitoringConfig{0.5, 0.01, 0.0, 0.001});
  m.start(2.0);
  EXPECT_EQ(m.update(2.5).outcome, PositioningOutcome::kDone);  // MinDwellTime 0: Done in the entry cycle
  m.start(2.0);
  EXPECT_EQ(m.update(1.5).outcome, PositioningOutcome::kDone);
  m.start(2.0);
  EXPECT_EQ(m.update(2.5001).outcome, PositioningOutcome::kInProgress);
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, Alarm541TargetNotReachedAfterToleranceTime) {
  PositioningMonitor m(pm_config(0.01, 0.005));
  EXPECT_EQ(m.tolerance_cycles(), 10u);
  m.start(10.0);
  // now − t0 = 0 ... 10 ms: still allowed; 11 ms > ToleranceTime: alarm 541/1
  for (int k = 0; k <= 10; ++k)
    EXPECT_EQ(m.update(0.0).outcome, PositioningOutcome::kInProgress) << k;
  const auto s = m.update(0.0);
  EXPECT_EQ(s.outcome, PositioningOutcome::kFault);
  EXPECT_EQ(s.additional_value, kPositioningTargetNotReached);
  EXPECT_EQ(m.update(10.0).outcome, PositioningOutcome::kFault);  // latched
  EXPECT_EQ(kPositioningAlarm, 541u);
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, EnteringExactlyAtToleranceTimeIsInTime) {
  PositioningMonitor m(pm_config(0.01, 0.005));
  m.start(10.0);
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(m.update(0.0).outcome, PositioningOutcome::kInProgress) << k;
  for (int k = 10; k < 15; ++k)
    EXPECT_EQ(m.update(10.0).outcome, PositioningOutcome::kInProgress) << k;
  EXPECT_EQ(m.update(10.0).outcome, PositioningOutcome::kDone);  // cycle 15 = 10 + 5
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, FractionalToleranceTimeRoundsToFirstCycleBeyond) {
  PositioningMonitor m(PositioningMonitoringConfig{0.01, 0.0025, 0.0, 0.001});
  m.start(1.0);
  for (int k = 0; k <= 2; ++k)
    EXPECT_EQ(m.update(0.0).outcome, PositioningOutcome::kInProgress) << k;
  EXPECT_EQ(m.update(0.0).outcome, PositioningOutcome::kFault);  // 3 ms > 2.5 ms
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, Alarm541TargetLeftDuringDwell) {
  PositioningMonitor m(pm_config(0.01, 0.005));
  m.start(10.0);
  EXPECT_EQ(m.update(10.0).outcome, PositioningOutcome::kInProgress);  // entry in cycle 0
  for (int k = 1; k < 4; ++k)
    EXPECT_EQ(m.update(10.0).outcome, PositioningOutcome::kInProgress) << k;
  const auto s = m.update(10.02);  // left in cycle 4, one cycle before Done
  EXPECT_EQ(s.outcome, PositioningOutcome::kFault);
  EXPECT_EQ(s.additional_value, kPositioningTargetLeft);
  // a new start() restarts the monitoring
  m.start(10.02);
  EXPECT_EQ(m.update(10.02).outcome, PositioningOutcome::kInProgress);
}

// spec 02 §6.1 (positioning monitoring: window, MinDwellTime, ToleranceTime, alarm 541).
TEST(PositioningMonitor, TimesAreConvertedWithoutRoundingSlip) {
  PositioningMonitor m(PositioningMonitoringConfig{0.01, 0.3, 0.01, 0.001});
  EXPECT_EQ(m.tolerance_cycles(), 300u);
  EXPECT_EQ(m.dwell_cycles(), 10u);
  EXPECT_FALSE(m.configure(PositioningMonitoringConfig{0.01, 0.3, 0.01, 0.0}));
  EXPECT_FALSE(m.configure(PositioningMonitoringConfig{-0.01, 0.3, 0.01, 0.001}));
  EXPECT_EQ(m.dwell_cycles(), 10u);
}

// ---- §6.3 standstill signal ----

// spec 02 §6.3 (standstill signal: window, MinDwellTime).
TEST(StandstillSignal, SetAfterMinDwellTime) {
  StandstillSignal s(StandstillSignalConfig{1.0, 0.01, 0.001});
  EXPECT_EQ(s.dwell_cycles(), 10u);
  EXPECT_FALSE(s.update(5.0));
  // the first cycle below the threshold counts as one cycle of dwell: X7 in the 10th cycle below
  for (int k = 1; k < 10; ++k)
    EXPECT_FALSE(s.update(k % 2 == 0 ? 0.5 : -1.0)) << k;
  EXPECT_TRUE(s.update(0.0));
  EXPECT_TRUE(s.standstill());
}

// spec 02 §6.3 (standstill signal: window, MinDwellTime).
TEST(StandstillSignal, ZeroDwellTimeSetsInFirstCycle) {
  StandstillSignal s(StandstillSignalConfig{1.0, 0.0, 0.001});
  EXPECT_TRUE(s.update(0.9));
}

// spec 02 §6.3 (standstill signal: window, MinDwellTime).
TEST(StandstillSignal, HysteresisWhenLeaving) {
  StandstillSignal s(StandstillSignalConfig{1.0, 0.002, 0.001});
  s.update(0.0);
  ASSERT_TRUE(s.update(0.0));
  EXPECT_TRUE(s.update(1.05));   // above the threshold but within the 10 % hysteresis
  EXPECT_TRUE(s.update(-1.1));   // exactly threshold·1.1: still held
  EXPECT_FALSE(s.update(1.11));  // beyond the hysteresis: left
  EXPECT_FALSE(s.update(0.5));   // dwell restarts
  EXPECT_TRUE(s.update(0.5));
}

// spec 02 §6.3 (standstill signal: window, MinDwellTime).
TEST(StandstillSignal, HysteresisBandHoldsTheDwellTimer) {
  StandstillSignal s(StandstillSignalConfig{1.0, 0.01, 0.001});
  for (int k = 0; k < 5; ++k)
    EXPECT_FALSE(s.update(0.0));
  EXPECT_FALSE(s.update(1.05));  // in the band: neither counts nor resets
  for (int k = 0; k < 4; ++k)
    EXPECT_FALSE(s.update(0.0));
  EXPECT_TRUE(s.update(0.0));  // 10th cycle below
  s.reset();
  EXPECT_FALSE(s.standstill());
  for (int k = 0; k < 5; ++k)
    EXPECT_FALSE(s.update(0.0));
  EXPECT_FALSE(s.update(2.0));  // leaving resets the timer
  for (int k = 0; k < 9; ++k)
    EXPECT_FALSE(s.update(0.0));
  EXPECT_TRUE(s.update(0.0));
}

}  // namespace
}  // namespace tomc::techobjects
