// Simulated drive, PROFIdrive general state machine (spec 06 §4.1 transitions, §4.2 ZSW1 per state, §4.3
// canonical STW1 words): every transition with the exact STW1 sent and the exact ZSW1 answered.
//
// ZSW1 bit 8 ("speed setpoint/actual deviation within tolerance", spec 06 §3.2, p2163) is a standard bit the
// drive sets in S4 while |n_set - n_act| < p2163. The "typical" S4 word 0x0237 of §4.2 assumes bit 8 = 0
// ("bits 8 and 10-15 = 0"); at standstill with n_set = 0 the deviation is 0, so the exact S4 word is 0x0337.
// S4 with bit 8 = 0 (0x0237) is checked separately during a hard acceleration.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "drive_harness.hpp"

namespace tomc::drives::test {
namespace {

using enum tg::DriveState;

constexpr std::uint16_t kS4AtSetpoint = 0x0337;  // §4.2 0x0237 + §3.2 bit 8 (deviation within tolerance)

struct Step {
  std::uint16_t stw1;
  std::uint16_t zsw1;
  tg::DriveState state;
  const char* what;
};

void run_steps(Harness& h, const std::vector<Step>& steps) {
  for (const auto& s : steps) {
    h.stw1(s.stw1);
    ASSERT_TRUE(h.cycle());
    EXPECT_EQ(hex16(h.zsw1()), hex16(s.zsw1)) << s.what << " (STW1 " << hex16(s.stw1) << ")";
    EXPECT_EQ(h.drive.state(), s.state) << s.what << ": " << tg::to_string(h.drive.state());
    // The controller's reading (spec 06 §4.2 rule): S5a reads as S3; S0 idle (bit 6) reads as S1.
    if (s.state != kS0NotReady) {
      EXPECT_EQ(tg::decode_zsw1(h.zsw1()).state, s.state == kS5aRampStop ? kS3SwitchedOn : s.state) << s.what;
    }
  }
}

// spec 06 §4.2: ZSW1 = 0x0000 before the first cyclic setpoint frame; §4.1 S0 -> S1 -> S2 -> S3 -> S4 with
// 0x047E / 0x047F (§4.3), one transition per drive cycle.
TEST(DriveStateMachineSim, PowerUpWords) {
  Harness h(drive_config(1), {});
  ASSERT_TRUE(h.cycle_without_setpoint());
  EXPECT_EQ(hex16(h.zsw1()), "0x0000");  // spec 06 §4.2 "S0 power-on (no cyclic data yet)"
  EXPECT_EQ(h.drive.state(), kS0NotReady);
  ASSERT_TRUE(h.cycle_without_setpoint());
  EXPECT_EQ(hex16(h.zsw1()), "0x0000");
  run_steps(h, {
                   {0x047E, 0x0270, kS1SwitchingOnInhibited, "S0 -> S1 (first cyclic data, STW1.10 = 1)"},
                   {0x047E, 0x0231, kS2ReadyForSwitchingOn, "S1 -> S2 (bit0 = 0, bit1 = bit2 = 1)"},
                   {0x047F, 0x0233, kS3SwitchedOn, "S2 -> S3 (bit0 = 1)"},
                   {0x047F, kS4AtSetpoint, kS4Operation, "S3 -> S4 (bit3 = 1)"},
                   {0x047F, kS4AtSetpoint, kS4Operation, "S4 stays"},
                   {0x0477, 0x0233, kS3SwitchedOn, "S4 -> S3 pulse inhibit (bit3 = 0)"},
                   {0x0477, 0x0233, kS3SwitchedOn, "S3 stays while bit3 = 0"},
                   {0x047F, kS4AtSetpoint, kS4Operation, "S3 -> S4"},
                   {0x047C, 0x0260, kS1SwitchingOnInhibited, "S4 -> S1 OFF2 coast (ZSW1.4 = 0)"},
                   {0x047C, 0x0260, kS1SwitchingOnInhibited, "S1 stays while OFF2"},
                   {0x047E, 0x0231, kS2ReadyForSwitchingOn, "S1 -> S2 after OFF2 released"},
               });
}

// spec 06 §4.1 "S0 ... while STW1.10 = 0" and §4.2 "S0 idle: 0x0240 + bits 4/5 mirroring STW1.1/STW1.2".
TEST(DriveStateMachineSim, NoControlByPlcStaysInS0Idle) {
  Harness h(drive_config(1), {});
  run_steps(h, {
                   {0x0000, 0x0240, kS0NotReady, "S0 idle, no PLC control"},
                   {0x0002, 0x0250, kS0NotReady, "S0 idle, ZSW1.4 mirrors STW1.1"},
                   {0x007E, 0x0270, kS0NotReady, "S0 idle, ZSW1.4/5 mirror STW1.1/2"},
                   {0x047E, 0x0270, kS1SwitchingOnInhibited, "S0 -> S1 with STW1.10"},
               });
}

struct TransitionCase {
  const char* name;
  std::vector<Step> steps;  // after power-up to S2 at standstill
};

// Every row of the spec 06 §4.1 table that can be reached at standstill (S5a/S5b end in the next cycle
// because the speed is already below p1226).
TEST(DriveStateMachineSim, EveryTransitionAtStandstill) {
  const std::vector<TransitionCase> cases = {
      {"S1 stays while ON is still set (S1 is left only with bit0 = 0)",
       {{0x047C, 0x0260, kS1SwitchingOnInhibited, "S2 -> S1 (OFF2)"},
        {0x047F, 0x0270, kS1SwitchingOnInhibited, "S1 stays, bit0 = 1"},
        {0x047E, 0x0231, kS2ReadyForSwitchingOn, "S1 -> S2"}}},
      {"S2 -> S1 on OFF2", {{0x047C, 0x0260, kS1SwitchingOnInhibited, "S2 -> S1, bit1 = 0"}}},
      {"S2 -> S1 on OFF3", {{0x047A, 0x0250, kS1SwitchingOnInhibited, "S2 -> S1, bit2 = 0 (ZSW1.5 = 0)"}}},
      {"S3 -> S2 on OFF1",
       {{0x0477, 0x0233, kS3SwitchedOn, "S2 -> S3 without enable operation"},
        {0x0476, 0x0231, kS2ReadyForSwitchingOn, "S3 -> S2, bit0 = 0"}}},
      {"S3 -> S1 on OFF2",
       {{0x0477, 0x0233, kS3SwitchedOn, "S2 -> S3"},
        {0x0475, 0x0260, kS1SwitchingOnInhibited, "S3 -> S1, bit1 = 0"}}},
      {"S3 -> S1 on OFF3",
       {{0x0477, 0x0233, kS3SwitchedOn, "S2 -> S3"},
        {0x0473, 0x0250, kS1SwitchingOnInhibited, "S3 -> S1, bit2 = 0"}}},
      {"S4 -> S5a -> S2 (OFF1, standstill reached)",
       {{0x047F, 0x0233, kS3SwitchedOn, "S2 -> S3"},
        {0x047F, kS4AtSetpoint, kS4Operation, "S3 -> S4"},
        {0x047E, 0x0233, kS5aRampStop, "S4 -> S5a (ZSW1.2 = 0 during the ramp)"},
        {0x047E, 0x0231, kS2ReadyForSwitchingOn, "S5a -> S2 at standstill"}}},
      {"S4 -> S5b -> S1 (OFF3, standstill reached)",
       {{0x047F, 0x0233, kS3SwitchedOn, "S2 -> S3"},
        {0x047F, kS4AtSetpoint, kS4Operation, "S3 -> S4"},
        {0x047B, 0x0213, kS5bQuickStop, "S4 -> S5b (ZSW1.5 = 0)"},
        {0x047B, 0x0250, kS1SwitchingOnInhibited, "S5b -> S1 at standstill"},
        {0x047E, 0x0231, kS2ReadyForSwitchingOn, "S1 -> S2 (spec 06 §4.3: then send 0x047E)"}}},
      {"S4 -> S1 on OFF2",
       {{0x047F, 0x0233, kS3SwitchedOn, "S2 -> S3"},
        {0x047F, kS4AtSetpoint, kS4Operation, "S3 -> S4"},
        {0x047D, 0x0260, kS1SwitchingOnInhibited, "S4 -> S1, bit1 = 0 with ON still set"}}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    Harness h(drive_config(1), {});
    run_steps(h, {{0x047E, 0x0270, kS1SwitchingOnInhibited, "S0 -> S1"},
                  {0x047E, 0x0231, kS2ReadyForSwitchingOn, "S1 -> S2"}});
    run_steps(h, c.steps);
  }
}

// The transitions out of S5a/S5b need a running motor (spec 06 §4.1: OFF1 is interruptible, OFF3 is not).
TEST(DriveStateMachineSim, TransitionsOutOfRampStops) {
  const std::vector<TransitionCase> cases = {
      {"S5a -> S4 (ON again: OFF1 interruptible)",
       {{0x047E, 0x0233, kS5aRampStop, "S4 -> S5a"}, {0x047F, kS4AtSetpoint, kS4Operation, "S5a -> S4"}}},
      {"S5a -> S5b (OFF3)",
       {{0x047E, 0x0233, kS5aRampStop, "S4 -> S5a"},
        {0x047A, 0x0213, kS5bQuickStop, "S5a -> S5b (ZSW1.5 = 0)"}}},
      {"S5a -> S1 (OFF2)",
       {{0x047E, 0x0233, kS5aRampStop, "S4 -> S5a"}, {0x047C, 0x0260, kS1SwitchingOnInhibited, "S5a -> S1"}}},
      {"S5a -> S2 (enable operation withdrawn)",
       {{0x047E, 0x0233, kS5aRampStop, "S4 -> S5a"}, {0x0476, 0x0231, kS2ReadyForSwitchingOn, "S5a -> S2"}}},
      {"S5b stays with ON and OFF3 released (quick stop not interruptible)",
       {{0x047B, 0x0213, kS5bQuickStop, "S4 -> S5b"},
        {0x047F, 0x0213, kS5bQuickStop, "S5b stays, ZSW1.5 = 0 while in S5b"}}},
      {"S5b -> S1 (OFF2)",
       {{0x047B, 0x0213, kS5bQuickStop, "S4 -> S5b"},
        {0x0479, 0x0240, kS1SwitchingOnInhibited, "S5b -> S1, ZSW1.4 = ZSW1.5 = 0"}}},
      {"S5b -> S1 (enable operation withdrawn)",
       {{0x047B, 0x0213, kS5bQuickStop, "S4 -> S5b"},
        {0x0473, 0x0250, kS1SwitchingOnInhibited, "S5b -> S1"}}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    Harness h(drive_config(1), {});
    h.run_at_speed(3000.0);
    ASSERT_NEAR(h.nist_rpm(), 3000.0, 0.5);
    ASSERT_EQ(hex16(h.zsw1()), hex16(kS4AtSetpoint));
    run_steps(h, c.steps);
  }
}

// spec 06 §3.2 bit 8: cleared while |n_set - n_act| >= p2163 (90 rpm), so S4 reads exactly 0x0237 then.
TEST(DriveStateMachineSim, S4WithoutBit8DuringHardAcceleration) {
  Harness h(drive_config(1), {});
  h.power_up_to_s4();
  h.speed_rpm(3000.0);
  ASSERT_TRUE(h.cycle());
  // After one cycle the speed is at most a/J * 1 ms = 4 Nm / 3e-4 kgm^2 * 1 ms = 127 rpm: far from 3000.
  EXPECT_LT(h.nist_rpm(), 130.0);
  EXPECT_EQ(hex16(h.zsw1()), "0x0237");
  const int cycles = h.run_until([&] { return (h.zsw1() & 0x0100u) != 0; }, 1000);
  EXPECT_GT(h.nist_rpm(), 3000.0 - h.params().speed_deviation_tolerance_rpm);
  EXPECT_LT(cycles, 1000);
  EXPECT_EQ(hex16(h.zsw1()), hex16(kS4AtSetpoint));
}

}  // namespace
}  // namespace tomc::drives::test
