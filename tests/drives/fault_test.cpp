// Simulated drive, faults and acknowledge (spec 06 §3.1 bit 7, §3.2 bit 3, §4.1 "Fault", §4.3, TV24, TV26):
// a fault forces its reaction (OFF1/OFF2/OFF3) by masking STW1, ZSW1.3 is set until acknowledged, the drive
// ends switched-on inhibited (0x0248); the acknowledge is a 0 -> 1 edge of STW1.7 and only works once the
// cause is gone.
#include <gtest/gtest.h>

#include <cmath>

#include "drive_harness.hpp"

namespace tomc::drives::test {
namespace {

constexpr std::uint32_t kInjected = 7900;  // any drive fault number

struct FaultCase {
  const char* name;
  Reaction reaction;
  tg::DriveState reacting;  // state while the fault reaction runs
  double ramp_time_s;       // 0 = coasting
};

class FaultReaction : public ::testing::TestWithParam<FaultCase> {};

TEST_P(FaultReaction, StopsThenAcknowledgeRecovers) {
  const auto& c = GetParam();
  SimulatedDriveParameters p;
  Harness h(drive_config(1), p);
  const double n0 = 3000.0;
  h.run_at_speed(n0);
  ASSERT_EQ(hex16(h.zsw1()), "0x0337");

  h.drive.inject_fault(kInjected, c.reaction);
  ASSERT_TRUE(h.cycle());
  // ZSW1.3 in the very cycle the fault appears (spec 06 §3.2); the controller reads FAULT (§4.2 rule).
  EXPECT_TRUE((h.zsw1() & 0x0008u) != 0) << hex16(h.zsw1());
  EXPECT_EQ(tg::decode_zsw1(h.zsw1()).state, tg::DriveState::kFault);
  EXPECT_EQ(h.drive.active_fault(), kInjected);
  EXPECT_EQ(h.drive.state(), c.reacting);

  // The stop behaviour of the reaction, with the controller still sending 0x047F.
  const int stop_cycles =
      h.run_until([&] { return h.drive.state() == tg::DriveState::kS1SwitchingOnInhibited; }, 2000);
  if (c.ramp_time_s > 0.0) {
    // Same ramp as the commanded OFF1/OFF3 (stop_test.cpp): (n0 - p1226) / a plus the lag, to a few cycles.
    const double a = p.max_speed_rpm / c.ramp_time_s;
    const double lag = a * p.speed_loop_time_constant_s;
    const double t = lag < p.standstill_threshold_rpm
                         ? (n0 + lag - p.standstill_threshold_rpm) / a
                         : n0 / a + p.speed_loop_time_constant_s * std::log(lag / p.standstill_threshold_rpm);
    EXPECT_NEAR(stop_cycles, std::ceil(t / p.servo_cycle_s), 3) << c.name;
    EXPECT_LT(std::fabs(h.nist_rpm()), p.standstill_threshold_rpm);
  } else {
    // OFF2: pulses off in the fault cycle already (S1 at once), the motor coasts: after 1 ms it has lost only
    // the friction deceleration (B w + Tc) / J = (0.0314 + 0.02) / 3e-4 = 171 rad/s^2 -> 1.6 rpm per ms.
    EXPECT_EQ(stop_cycles, 1);
    EXPECT_NEAR(h.nist_rpm(), n0 - 2 * 1.637, 0.5);
    EXPECT_EQ(h.drive.motor_torque_nm(), 0.0);
  }

  // Let the motor come to rest (OFF2 coasts for ~2.8 s) so that S4 later reads 0x0337 (n_set = n_act = 0).
  const int rest = h.run_until([&] { return h.nist_rpm() == 0.0; }, 4000);
  EXPECT_LE(rest, 4000);
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");

  // Final word with 0x047E: 0x0248 (fault, switching on inhibited, control requested; TV24/TV26).
  h.stw1(0x047E);
  h.run(3);
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");

  // Acknowledge while the cause is still present: nothing happens.
  h.stw1(0x04FE);
  h.run(2);
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  EXPECT_EQ(h.drive.active_fault(), kInjected);
  h.stw1(0x047E);
  h.run(2);
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  // Switching on is inhibited while the fault is present.
  h.stw1(0x047F);
  h.run(3);
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  h.stw1(0x047E);
  h.run(1);

  // Cause gone: TV26. 0x04FE (edge of bit 7) -> fault cleared, S1 (0x0270); 0x047E -> S2 (0x0231);
  // 0x047F -> S3 (0x0233) -> S4 (0x0337 = 0x0237 + bit 8 at standstill with n_set = 0).
  h.drive.clear_injected_fault();
  h.speed_rpm(0.0);
  h.stw1(0x04FE);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0270");
  EXPECT_EQ(h.drive.active_fault(), 0u);
  h.stw1(0x047E);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0231");
  h.stw1(0x047F);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0233");
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0337");
}

INSTANTIATE_TEST_SUITE_P(
    Reactions, FaultReaction,
    ::testing::Values(FaultCase{"OFF1", Reaction::kOff1, tg::DriveState::kS5aRampStop, 1.0},
                      FaultCase{"OFF2", Reaction::kOff2, tg::DriveState::kS1SwitchingOnInhibited, 0.0},
                      FaultCase{"OFF3", Reaction::kOff3, tg::DriveState::kS5bQuickStop, 0.2}),
    [](const auto& info) { return std::string(info.param.name); });

// The acknowledge is an edge: holding bit 7 from before the cause went away does not acknowledge.
// spec 06 §4.1 and §11 TV26 (acknowledge on a 0 → 1 edge of STW1.7: 0x0248 → 0x0270), decisions R3 and R4.
TEST(FaultAcknowledgeSim, NeedsRisingEdgeOfBit7) {
  Harness h(drive_config(1), {});
  h.power_up_to_s4();
  h.drive.inject_fault(kInjected, Reaction::kOff2);
  h.stw1(0x04FE);
  h.run(3);
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  h.drive.clear_injected_fault();
  h.run(3);  // bit 7 still 1: no edge
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  EXPECT_EQ(h.drive.active_fault(), kInjected);
  h.stw1(0x047E);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0248");
  h.stw1(0x04FE);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.zsw1()), "0x0270");
}

// A motor-encoder error (G1 on the motor shaft, spec 06 §6.4) takes away the speed feedback: drive fault with
// OFF2 reaction; it can be acknowledged only after the encoder error is gone and acknowledged.
TEST(FaultAcknowledgeSim, MotorEncoderErrorFaultsTheDrive) {
  Harness h(drive_config(3), {});
  h.run_at_speed(1000.0);
  h.drive.inject_encoder_error(1, tg::kEncoderErrorSensorGroup);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(h.drive.active_fault(), kFaultMotorEncoder);
  EXPECT_EQ(h.drive.state(), tg::DriveState::kS1SwitchingOnInhibited);
  h.stw1(0x047E);
  h.run(2);
  h.stw1(0x04FE);
  h.run(2);
  EXPECT_EQ(h.drive.active_fault(), kFaultMotorEncoder) << "encoder cause still present";
  h.drive.clear_encoder_error(1);
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x8000};
  h.stw1(0x047E);
  h.run(2);
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x0000};
  h.run(1);
  EXPECT_EQ(h.actual.G1_ZSW.value() & 0x8000u, 0u);
  h.stw1(0x04FE);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(h.drive.active_fault(), 0u);
  EXPECT_EQ(hex16(h.zsw1()), "0x0270");
}

}  // namespace
}  // namespace tomc::drives::test
