// Sign-of-life counter and monitor, spec 06 §5 (and TV17/TV18 of §11).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tomc/telegrams/sign_of_life.hpp"

namespace tomc::telegrams {
namespace {

// spec 06 §5.1: 1 ... 15, then 1 again; 0 is never used.
TEST(SignOfLifeCounter, AdvanceWrapsFifteenToOne) {
  for (int v = 1; v <= 14; ++v)
    EXPECT_EQ(advance_sign_of_life(static_cast<std::uint8_t>(v)), v + 1) << v;
  EXPECT_EQ(advance_sign_of_life(15), 1);
  EXPECT_EQ(advance_sign_of_life(0), 1);  // not started: first value is 1
}

// spec 06 §5.1 [OUR CHOICE]: k steps per application cycle, mod 15 skipping 0.
TEST(SignOfLifeCounter, AdvanceByStep) {
  EXPECT_EQ(advance_sign_of_life(1, 2), 3);
  EXPECT_EQ(advance_sign_of_life(13, 2), 15);
  EXPECT_EQ(advance_sign_of_life(14, 2), 1);
  EXPECT_EQ(advance_sign_of_life(15, 2), 2);
  EXPECT_EQ(advance_sign_of_life(15, 14), 14);
  EXPECT_EQ(advance_sign_of_life(1, 14), 15);
  for (int step = 1; step <= 14; ++step) {
    for (int v = 1; v <= 15; ++v) {
      const int next = advance_sign_of_life(static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(step));
      EXPECT_EQ(next, (v - 1 + step) % 15 + 1) << v << " + " << step;
      EXPECT_NE(next, 0);
    }
  }
}

// spec 06 §5.1: the generator counts 1..15, wraps to 1 and never emits 0.
TEST(SignOfLifeGenerator, CountsAndNeverEmitsZero) {
  SignOfLifeGenerator generator;
  EXPECT_EQ(generator.current(), 0);  // nothing sent yet
  std::uint8_t previous = generator.next();
  EXPECT_EQ(previous, 1);
  for (int i = 0; i < 100; ++i) {
    const std::uint8_t v = generator.next();
    EXPECT_NE(v, 0);
    EXPECT_LE(v, 15);
    EXPECT_EQ(v, previous == 15 ? 1 : previous + 1);
    EXPECT_EQ(generator.current(), v);
    previous = v;
  }
}

// spec 06 §5.1 (the counter runs 1…15 and 0 is never used), decision T18 (the controller's counter starts at
// 1).
TEST(SignOfLifeGenerator, ResetToStartValue) {
  SignOfLifeGenerator generator;
  generator.reset(15);
  EXPECT_EQ(generator.next(), 15);
  EXPECT_EQ(generator.next(), 1);  // 15 -> 1, never 0
  generator.reset(0);              // 0 is no valid start: starts at 1
  EXPECT_EQ(generator.next(), 1);
  generator.reset(16);
  EXPECT_EQ(generator.next(), 1);
  generator.reset(7);
  EXPECT_EQ(generator.current(), 0);
  EXPECT_EQ(generator.next(), 7);
  EXPECT_EQ(generator.next(), 8);
}

// Feeds a monitor a list of received values; returns the status after each.
std::vector<SignOfLifeStatus> feed(SignOfLifeMonitor& monitor, const std::vector<int>& values) {
  std::vector<SignOfLifeStatus> out;
  for (const int v : values)
    out.push_back(monitor.check(static_cast<std::uint8_t>(v)));
  return out;
}

// spec 06 §5.1 Requirement: zeros mean "not synchronised / not supported" and never a fault.
TEST(SignOfLifeMonitor, ZerosAreNotSynchronisedWithoutFault) {
  SignOfLifeMonitor monitor;
  EXPECT_EQ(monitor.status(), SignOfLifeStatus::kNotSynchronised);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(monitor.check(0), SignOfLifeStatus::kNotSynchronised);
    EXPECT_EQ(monitor.error_counter(), 0u);
  }
  // The first non-zero value synchronises.
  EXPECT_EQ(monitor.check(9), SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.expected(), 10);
  EXPECT_EQ(monitor.check(10), SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.error_counter(), 0u);
}

// spec 06 §5.2: a correct partner counting 1..15,1.. never raises the error counter.
TEST(SignOfLifeMonitor, CorrectPartnerAcrossWrap) {
  SignOfLifeMonitor monitor;
  std::uint8_t v = 12;
  for (int i = 0; i < 60; ++i) {
    EXPECT_EQ(monitor.check(v), SignOfLifeStatus::kOk) << i;
    EXPECT_EQ(monitor.error_counter(), 0u);
    v = v == 15 ? 1 : static_cast<std::uint8_t>(v + 1);
  }
}

// spec 06 §5.2 [OUR CHOICE]: the monitor trips in exactly the cycle where the counter first exceeds
// 10 * tolerance (consecutive errors: after tolerance + 1 errors).
TEST(SignOfLifeMonitor, TripsExactlyWhenCounterExceedsTenTimesTolerance) {
  for (const std::uint16_t tolerance : {1, 2, 3, 5, 10}) {
    SCOPED_TRACE(tolerance);
    SignOfLifeMonitor monitor(SignOfLifeMonitorConfig{.tolerance = tolerance, .step = 1});
    ASSERT_EQ(monitor.check(1), SignOfLifeStatus::kOk);  // synchronise, expects 2 next
    for (int error = 1; error <= tolerance + 1; ++error) {
      const auto status = monitor.check(1);  // stuck partner: always wrong
      EXPECT_EQ(monitor.error_counter(), 10u * static_cast<unsigned>(error));
      if (error <= tolerance) {
        EXPECT_EQ(status, SignOfLifeStatus::kOk)
            << "error " << error << " counter " << monitor.error_counter();
      } else {
        EXPECT_EQ(status, SignOfLifeStatus::kFailed) << "error " << error;
      }
    }
  }
}

// spec 06 §5.2: +10 per error, -1 (floor 0) per correct value; with tolerance 1 an error followed by 9
// correct values leaves 1, so a second error trips (11 > 10); after 10 correct values (0) it does not (10).
TEST(SignOfLifeMonitor, LeakyCounterEdges) {
  {
    SignOfLifeMonitor monitor(SignOfLifeMonitorConfig{.tolerance = 1, .step = 1});
    // values: 1 sync; 5 wrong (expected 2); then 3..11 correct (9 values); then wrong.
    feed(monitor, {1, 5});
    EXPECT_EQ(monitor.error_counter(), 10u);
    feed(monitor, {3, 4, 5, 6, 7, 8, 9, 10, 11});
    EXPECT_EQ(monitor.error_counter(), 1u);
    EXPECT_EQ(monitor.status(), SignOfLifeStatus::kOk);
    EXPECT_EQ(monitor.check(1), SignOfLifeStatus::kFailed);  // expected 12
    EXPECT_EQ(monitor.error_counter(), 11u);
  }
  {
    SignOfLifeMonitor monitor(SignOfLifeMonitorConfig{.tolerance = 1, .step = 1});
    feed(monitor, {1, 5, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
    EXPECT_EQ(monitor.error_counter(), 0u);
    EXPECT_EQ(monitor.check(1), SignOfLifeStatus::kOk);  // expected 13
    EXPECT_EQ(monitor.error_counter(), 10u);
    EXPECT_EQ(monitor.check(14), SignOfLifeStatus::kOk);  // correct again
    EXPECT_EQ(monitor.error_counter(), 9u);
  }
  {
    // The floor is 0: correct values never make the counter negative/wrap.
    SignOfLifeMonitor monitor;
    feed(monitor, {4, 5, 6, 7});
    EXPECT_EQ(monitor.error_counter(), 0u);
  }
}

// spec 06 §5.2: default tolerance 1 = one isolated wrong value tolerated.
TEST(SignOfLifeMonitor, SingleIsolatedWrongValueToleratedWithToleranceOne) {
  SignOfLifeMonitor monitor;
  EXPECT_EQ(monitor.config().tolerance, 1);
  EXPECT_EQ(monitor.config().step, 1);
  const auto statuses = feed(monitor, {1, 2, 3, 9, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 1, 2});
  for (const auto s : statuses)
    EXPECT_EQ(s, SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.error_counter(), 0u);  // 10 - 13 correct values, floored at 0
}

// spec 06 §5.2: slave value 0 while synchronised counts as an error.
TEST(SignOfLifeMonitor, ZeroAfterSynchronisationIsAnError) {
  SignOfLifeMonitor monitor;
  feed(monitor, {7, 8});
  EXPECT_EQ(monitor.check(0), SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.error_counter(), 10u);
  EXPECT_EQ(monitor.check(0), SignOfLifeStatus::kFailed);
}

// spec 06 §5.2: tolerance 0 -> the first wrong value trips (10 > 0).
TEST(SignOfLifeMonitor, ToleranceZeroTripsOnFirstError) {
  SignOfLifeMonitor monitor(SignOfLifeMonitorConfig{.tolerance = 0, .step = 1});
  EXPECT_EQ(monitor.check(3), SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.check(4), SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.check(6), SignOfLifeStatus::kFailed);
}

// spec 06 §5.2: 0xFFFF switches monitoring off (as p0925 = 65535).
TEST(SignOfLifeMonitor, ToleranceFFFFSwitchesMonitoringOff) {
  SignOfLifeMonitor monitor(SignOfLifeMonitorConfig{.tolerance = 0xFFFF, .step = 1});
  EXPECT_EQ(monitor.check(0), SignOfLifeStatus::kNotSynchronised);
  for (int i = 0; i < 100000; ++i) {
    const auto s = monitor.check(static_cast<std::uint8_t>(1 + (i * 7) % 15));  // garbage sequence
    ASSERT_NE(s, SignOfLifeStatus::kFailed) << i;
  }
  EXPECT_NE(monitor.check(0), SignOfLifeStatus::kFailed);
}

// spec 06 §5.1 [OUR CHOICE]: T_MAPC = 2 T_DP -> the partner advances by 2 per check.
TEST(SignOfLifeMonitor, StepTwo) {
  SignOfLifeMonitor monitor(SignOfLifeMonitorConfig{.tolerance = 1, .step = 2});
  const auto statuses = feed(monitor, {11, 13, 15, 2, 4, 6, 8, 10, 12, 14, 1, 3});
  for (const auto s : statuses)
    EXPECT_EQ(s, SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.error_counter(), 0u);
  EXPECT_EQ(monitor.expected(), 5);
  // A partner advancing by 1 is wrong for this monitor.
  SignOfLifeMonitor slow(SignOfLifeMonitorConfig{.tolerance = 1, .step = 2});
  EXPECT_EQ(slow.check(1), SignOfLifeStatus::kOk);
  EXPECT_EQ(slow.check(2), SignOfLifeStatus::kOk);
  EXPECT_EQ(slow.error_counter(), 10u);
  EXPECT_EQ(slow.check(3), SignOfLifeStatus::kFailed);
}

// spec 06 §5.2: the failure is latched until reset(); reset returns to "not synchronised".
TEST(SignOfLifeMonitor, FailureLatchedUntilReset) {
  SignOfLifeMonitor monitor;
  feed(monitor, {1, 5, 5});
  ASSERT_EQ(monitor.status(), SignOfLifeStatus::kFailed);
  // Correct values afterwards (expected runs on: 4, 5, ...) do not clear it.
  for (const int v : {4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}) {
    EXPECT_EQ(monitor.check(static_cast<std::uint8_t>(v)), SignOfLifeStatus::kFailed);
  }
  EXPECT_EQ(monitor.status(), SignOfLifeStatus::kFailed);
  monitor.reset();
  EXPECT_EQ(monitor.status(), SignOfLifeStatus::kNotSynchronised);
  EXPECT_EQ(monitor.error_counter(), 0u);
  EXPECT_EQ(monitor.expected(), 0);
  EXPECT_EQ(monitor.check(0), SignOfLifeStatus::kNotSynchronised);
  EXPECT_EQ(monitor.check(8), SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.check(9), SignOfLifeStatus::kOk);
  EXPECT_EQ(monitor.error_counter(), 0u);
}

// spec 06 §11 TV18 / §5.2: the monitor keeps its own expectation; a partner that slipped one cycle keeps
// mismatching and trips. A resynchronising monitor would not.
TEST(SignOfLifeMonitor, KeepsOwnExpectationAfterMismatch) {
  SignOfLifeMonitor monitor;
  feed(monitor, {3, 4, 4});
  EXPECT_EQ(monitor.expected(), 6);  // not 5 (= received + 1)
  EXPECT_EQ(monitor.check(5), SignOfLifeStatus::kFailed);
}

// Generator and monitor agree with each other over many wraps.
// spec 06 §5.1 (+1 per cycle, 15 → 1) and §5.2 (an expected value never counts as an error).
TEST(SignOfLifeMonitor, GeneratorFeedsMonitorWithoutErrors) {
  for (std::uint8_t start = 1; start <= 15; ++start) {
    SignOfLifeGenerator generator;
    generator.reset(start);
    SignOfLifeMonitor monitor;
    for (int i = 0; i < 50; ++i)
      ASSERT_EQ(monitor.check(generator.next()), SignOfLifeStatus::kOk);
    EXPECT_EQ(monitor.error_counter(), 0u);
  }
}

}  // namespace
}  // namespace tomc::telegrams
