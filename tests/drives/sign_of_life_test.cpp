// Simulated drive, sign-of-life (spec 06 §5): the drive monitors the master counter in STW2.12-15 (p0925
// tolerance, leaky counter +10 / -1, fault above 10 * tolerance, §5.2) and sends its own counter in
// ZSW2.12-15, which the controller monitors with telegrams::SignOfLifeMonitor. With tolerance t a frozen
// counter is detected at the (t + 1)-th bad cycle on both sides.
#include <gtest/gtest.h>

#include "drive_harness.hpp"

namespace tomc::drives::test {
namespace {

class SignOfLifeTolerance : public ::testing::TestWithParam<std::uint16_t> {};

// Drive side: the controller's master LS stops advancing; ZSW1.3 with F01912 appears in the answer to the
// (tolerance + 1)-th frozen cycle, with the communication fault reaction (OFF3 by default).
// spec 06 §5.2 (drive side: +10 per wrong master value, fault above 10 × p0925), decision R7 (F01912 with
// the communication fault reaction, OFF3).
TEST_P(SignOfLifeTolerance, DriveDetectsFrozenMasterCounter) {
  const std::uint16_t tolerance = GetParam();
  SimulatedDriveParameters p;
  p.sign_of_life_tolerance = tolerance;
  Harness h(drive_config(3), p);
  h.run_at_speed(1000.0, 100);  // 104 cycles with a running counter (wraps 15 -> 1 several times)
  ASSERT_EQ(h.drive.active_fault(), 0u);
  ASSERT_EQ(hex16(h.zsw1()), "0x0337");
  h.freeze_master = true;
  for (int bad = 1; bad <= tolerance; ++bad) {
    ASSERT_TRUE(h.cycle());
    EXPECT_EQ(h.zsw1() & 0x0008u, 0u) << "bad cycle " << bad << " is tolerated";
  }
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(h.zsw1() & 0x0008u, 0x0008u) << "fault at bad cycle " << tolerance + 1;
  EXPECT_EQ(h.drive.active_fault(), kFaultSignOfLife);
  EXPECT_EQ(h.drive.state(), tg::DriveState::kS5bQuickStop);  // communication_fault_reaction = OFF3
}

// Controller side: the drive's slave LS freezes; a monitor with the same tolerance trips at bad cycle t + 1.
TEST_P(SignOfLifeTolerance, ControllerDetectsFrozenSlaveCounter) {
  const std::uint16_t tolerance = GetParam();
  Harness h(drive_config(3), {});
  tg::SignOfLifeMonitor monitor(tg::SignOfLifeMonitorConfig{tolerance, 1});
  h.stw1(0x047E);
  for (int k = 0; k < 40; ++k) {
    ASSERT_TRUE(h.cycle());
    ASSERT_NE(h.slave_sign_of_life(), 0) << "spec 06 §5.1: 0 is never used once running";
    ASSERT_EQ(monitor.check(h.slave_sign_of_life()), tg::SignOfLifeStatus::kOk) << "cycle " << k;
  }
  h.drive.freeze_sign_of_life(true);
  for (int bad = 1; bad <= tolerance; ++bad) {
    ASSERT_TRUE(h.cycle());
    EXPECT_EQ(monitor.check(h.slave_sign_of_life()), tg::SignOfLifeStatus::kOk) << "bad cycle " << bad;
  }
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(monitor.check(h.slave_sign_of_life()), tg::SignOfLifeStatus::kFailed);
  EXPECT_EQ(h.drive.active_fault(), 0u) << "the drive's own monitoring is not affected";
}

INSTANTIATE_TEST_SUITE_P(Tolerances, SignOfLifeTolerance, ::testing::Values(1, 2, 3));

// The slave counter counts 1..15, then 1 again (spec 06 §5.1), +1 per drive cycle.
TEST(SignOfLifeSim, SlaveCounterSequence) {
  Harness h(drive_config(2), {});
  h.stw1(0x047E);
  std::uint8_t expected = 1;
  for (int k = 0; k < 40; ++k) {
    ASSERT_TRUE(h.cycle());
    EXPECT_EQ(h.slave_sign_of_life(), expected) << "cycle " << k;
    expected = expected == 15 ? 1 : static_cast<std::uint8_t>(expected + 1);
  }
}

// An isolated error is tolerated (tolerance 1) and decays (-1 per good cycle): a second isolated error ten
// good cycles later is tolerated as well, a second one within fewer cycles trips.
// spec 06 §5.2 (leaky counter, −1 per good value) and §11 TV18 (the expectation runs on after a bad value).
TEST(SignOfLifeSim, IsolatedErrorsAreTolerated) {
  Harness h(drive_config(3), {});
  h.run_at_speed(500.0, 50);
  auto skip_one = [&] {
    h.freeze_master = true;
    ASSERT_TRUE(h.cycle());
    h.freeze_master = false;
  };
  // The drive's expectation runs on after a bad value (TV18), so the controller skips the missed step.
  skip_one();             // error counter 10: not above 10 * 1
  (void)h.master.next();  // make up for the missed step: back in step with the drive's expectation
  EXPECT_EQ(h.drive.active_fault(), 0u);
  h.run(10);   // ten good cycles: 10 -> 0
  skip_one();  // 0 + 10 = 10: tolerated again
  (void)h.master.next();
  EXPECT_EQ(h.drive.active_fault(), 0u) << "the first error had fully decayed";
  h.run(5);    // 10 -> 5
  skip_one();  // 5 + 10 = 15 > 10: trips
  EXPECT_EQ(h.drive.active_fault(), kFaultSignOfLife) << "second error only five cycles later";
}

// Telegram 1 has no STW2/ZSW2: never a sign-of-life fault, however long it runs.
// spec 06 §2.1 (telegram 1 has no STW2/ZSW2) and §5.1 (the sign-of-life lives there).
TEST(SignOfLifeSim, Telegram1NeverFaults) {
  Harness h(drive_config(1), {});
  h.run_at_speed(1000.0, 3000);
  EXPECT_EQ(h.drive.active_fault(), 0u);
  EXPECT_EQ(hex16(h.zsw1()), "0x0337");
}

// spec 06 §5.1: a controller that sends 0 (not synchronised / not supported) is no error; neither is an RT
// (non-isochronous) drive, which sends slave LS 0.
TEST(SignOfLifeSim, ZeroMasterCounterAndNonIsochronousAreNoError) {
  {
    Harness h(drive_config(3), {});
    h.freeze_master = true;  // STW2.12-15 stays 0
    h.run_at_speed(1000.0, 500);
    EXPECT_EQ(h.drive.active_fault(), 0u);
  }
  {
    SimulatedDriveParameters p;
    p.isochronous = false;
    Harness h(drive_config(3), p);
    h.run_at_speed(1000.0, 50);
    h.freeze_master = true;
    h.run(50);
    EXPECT_EQ(h.drive.active_fault(), 0u);
    EXPECT_EQ(h.slave_sign_of_life(), 0);
  }
}

// After a sign-of-life fault the acknowledge resynchronises the monitor (spec 06 §5.2: the drive restarts
// synchronisation); the drive can be switched on again.
TEST(SignOfLifeSim, AcknowledgeAfterSignOfLifeFault) {
  Harness h(drive_config(3), {});
  h.run_at_speed(0.0, 10);
  h.freeze_master = true;
  h.run(2);
  ASSERT_EQ(h.drive.active_fault(), kFaultSignOfLife);
  h.freeze_master = false;
  h.stw1(0x047E);
  h.run(3);
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  h.stw1(0x04FE);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0270");
  h.stw1(0x047E);
  h.run(1);
  h.stw1(0x047F);
  h.run(20);
  EXPECT_EQ(h.drive.active_fault(), 0u);
  EXPECT_EQ(hex16(h.zsw1()), "0x0337");
}

}  // namespace
}  // namespace tomc::drives::test
