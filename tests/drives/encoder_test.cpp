// Simulated drive, encoder actual values (spec 06 §6): XIST1 counts (§6.1), its 32-bit wrap (TV19), the
// multiplexed XIST2 (§6.2) with reference mark, measured value and absolute value, the G_STW -> G_ZSW
// handshakes (§6.3) and encoder errors (§6.4) on G1/G2 of a drive telegram and on separate encoder telegrams
// 81/83.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "drive_harness.hpp"
#include "tomc/telegrams/encoder.hpp"

namespace tomc::drives::test {
namespace {

// 2048 steps * 2^11 fine resolution (p979[2], p0418) = 4 194 304 counts per revolution.
double cpr(const SimulatedEncoderParameters& e) {
  return tg::counts_per_revolution(e.steps_per_revolution, e.fine_resolution_xist1);
}

// spec 06 §6.1: ΔXIST1 per cycle = n/60 * cycle * steps * 2^fine; the counter is an integer, so +-1.
TEST(EncoderSim, Xist1CountsForConstantSpeed) {
  SimulatedDriveParameters p;
  Harness h(drive_config(3), p);
  const double n = 1500.0;
  h.run_at_speed(n, 300);
  ASSERT_NEAR(h.nist_rpm(), n, 0.01);
  const double per_cycle = n / 60.0 * p.servo_cycle_s * cpr(p.encoder1);  // 104 857.6
  ASSERT_DOUBLE_EQ(per_cycle, 104857.6);
  std::uint32_t previous = h.actual.G1_XIST1;
  std::int64_t total = 0;
  for (int k = 0; k < 100; ++k) {
    ASSERT_TRUE(h.cycle());
    const auto d = tg::xist1_delta(previous, h.actual.G1_XIST1);
    EXPECT_NEAR(static_cast<double>(d), per_cycle, 1.0) << "cycle " << k;
    total += d;
    previous = h.actual.G1_XIST1;
  }
  EXPECT_NEAR(static_cast<double>(total), 100 * per_cycle, 1.0);
}

// The counts of an absolute motor encoder are its position: XIST1 = floor(revolutions * counts/rev).
// spec 06 §6.1 (XIST1 of an absolute encoder within its range), docs/simulated-drive.md "One cycle" step 4.
TEST(EncoderSim, Xist1OfAbsoluteEncoderIsThePosition) {
  SimulatedDriveParameters p;
  p.initial_load_position = 900.0;  // 2.5 revolutions, gear 1:1, 360 degrees per revolution
  Harness h(drive_config(3), p);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(h.actual.G1_XIST1, static_cast<std::uint32_t>(2.5 * cpr(p.encoder1)));
}

struct WrapCase {
  const char* name;
  std::uint32_t power_on;
  double rpm;
};

class Xist1Wrap : public ::testing::TestWithParam<WrapCase> {};

// TV19: an incremental encoder starting at 0xFFFFFF00 wraps through 0 (and one starting at 0x100 going
// backwards wraps below 0); xist1_delta over the wrap still gives the true movement.
// spec 06 §6.1 and §11 TV19 (32-bit wrap: Δ = ±512 counts).
TEST_P(Xist1Wrap, DeltaAcrossWrapIsTheMovement) {
  const auto& c = GetParam();
  SimulatedDriveParameters p;
  p.encoder1.determinable_revolutions = 0;  // incremental
  p.encoder1.xist1_at_power_on = c.power_on;
  Harness h(drive_config(3), p);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(h.actual.G1_XIST1, c.power_on);  // at rest: the power-on value
  h.power_up_to_s4();
  h.speed_rpm(c.rpm);
  std::uint32_t previous = h.actual.G1_XIST1;
  ASSERT_EQ(previous, c.power_on);
  std::int64_t accumulated = 0;
  bool wrapped = false;
  for (int k = 0; k < 50; ++k) {
    ASSERT_TRUE(h.cycle());
    const std::uint32_t now = h.actual.G1_XIST1;
    const auto d = tg::xist1_delta(previous, now);
    if ((c.rpm > 0.0 && now < previous) || (c.rpm < 0.0 && now > previous)) {
      wrapped = true;
      EXPECT_EQ(d > 0, c.rpm > 0.0) << "delta across the wrap has the sign of the motion";
    }
    accumulated += d;
    previous = now;
  }
  EXPECT_TRUE(wrapped);
  // True movement from the mechanics: the load position (degrees, gear 1:1) since power-on at 0.
  const double expected = h.drive.load_position() / 360.0 * cpr(p.encoder1);
  EXPECT_NEAR(static_cast<double>(accumulated), expected, 1.0);
  EXPECT_GT(std::fabs(expected), 256.0);  // more than the distance to the wrap
}

INSTANTIATE_TEST_SUITE_P(Tv19, Xist1Wrap,
                         ::testing::Values(WrapCase{"Forward", 0xFFFFFF00u, 300.0},
                                           WrapCase{"Backward", 0x00000100u, -300.0}),
                         [](const auto& info) { return std::string(info.param.name); });

// spec 06 §6.3: G1_STW 0x0011 starts the reference-mark search (G1_ZSW.0); the mark found sets G1_ZSW.4;
// 0x0021 reads it: XIST2 = mark position in XIST1 format (§6.2, p0418 fine bits); 0x0000 ends the function.
struct MarkCase {
  const char* name;
  std::uint32_t determinable_revolutions;
  std::uint32_t xist1_at_power_on;
};

class ReferenceMark : public ::testing::TestWithParam<MarkCase> {};

// spec 06 §6.3 (reference-mark search: G1_STW 0x0011, G1_ZSW 0x0001 then 0x0011, XIST2 the captured value).
TEST_P(ReferenceMark, CapturesExactMarkPosition) {
  const auto& c = GetParam();
  SimulatedDriveParameters p;
  p.initial_load_position = 36.0;  // 0.1 revolution; first mark at 0.25 revolution (offset 0.25, every 1 rev)
  p.encoder1.determinable_revolutions = c.determinable_revolutions;
  p.encoder1.xist1_at_power_on = c.xist1_at_power_on;
  Harness h(drive_config(3), p);
  const double counts = cpr(p.encoder1);
  // Absolute: XIST1 = revolutions * cpr. Incremental: power-on value + (revolutions - 0.1) * cpr.
  const double mark_rev = p.encoder1.reference_mark_offset_revolutions;
  const auto expected_mark = static_cast<std::uint32_t>(
      c.determinable_revolutions != 0 ? std::floor(mark_rev * counts)
                                      : std::floor(c.xist1_at_power_on + (mark_rev - 0.1) * counts));
  h.power_up_to_s4();
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x0011};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0001");  // function 1 active, no value yet
  h.speed_rpm(60.0);                                    // 1 rev/s: the mark is 0.15 rev away, ~150 ms
  std::uint32_t before = h.actual.G1_XIST1;
  const int found = h.run_until(
      [&] {
        if ((h.actual.G1_ZSW.value() & 0x0010u) == 0) before = h.actual.G1_XIST1;
        return (h.actual.G1_ZSW.value() & 0x0010u) != 0;
      },
      1000);
  ASSERT_LE(found, 1000);
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0011");
  // The mark lies between XIST1 before and after the cycle in which it was crossed.
  EXPECT_LE(tg::xist1_delta(before, expected_mark), tg::xist1_delta(before, h.actual.G1_XIST1));
  EXPECT_GE(tg::xist1_delta(before, expected_mark), 0);
  EXPECT_EQ(h.actual.G1_XIST2, 0u) << "value not requested yet";
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x0021};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0011");
  EXPECT_EQ(h.actual.G1_XIST2, expected_mark);
  EXPECT_EQ(tg::xist2_content(h.drive_sp.G1_STW, h.actual.G1_ZSW), tg::Xist2Content::kReferenceMark);
  // Further marks (every revolution) do not overwrite the value already available.
  h.run(1500);
  EXPECT_EQ(h.actual.G1_XIST2, expected_mark);
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x0000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0000");
  EXPECT_EQ(h.actual.G1_XIST2, 0u);
}

INSTANTIATE_TEST_SUITE_P(Encoders, ReferenceMark,
                         ::testing::Values(MarkCase{"Absolute", 4096, 0}, MarkCase{"Incremental", 0, 5000}),
                         [](const auto& info) { return std::string(info.param.name); });

// spec 06 §6.3 flying measurement, probe 1 rising edge: 0x0091 -> G1_ZSW.0; the probe edge sets G1_ZSW.4 and
// G1_ZSW.8 mirrors the probe; 0x00A1 reads XIST2 = XIST1 at the edge (interpolated within the cycle).
TEST(EncoderSim, FlyingMeasurementOnProbe1) {
  SimulatedDriveParameters p;
  p.machine.probe1 = PositionWindow{100.0, 120.0};  // load degrees, gear 1:1: motor revolution 100/360
  Harness h(drive_config(3), p);
  h.power_up_to_s4();
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x0091};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0001");
  h.speed_rpm(30.0);  // 180 degrees/s: 0.18 degree per cycle
  const int found = h.run_until([&] { return (h.actual.G1_ZSW.value() & 0x0010u) != 0; }, 2000);
  ASSERT_LE(found, 2000);
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0111");  // active, value 1 available, probe 1 deflected
  EXPECT_TRUE(h.drive.machine_inputs().probe1);
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x00A1};
  ASSERT_TRUE(h.cycle());
  const double expected = 100.0 / 360.0 * cpr(p.encoder1);  // 1 165 084.4
  EXPECT_NEAR(static_cast<double>(h.actual.G1_XIST2), expected, 1.0);
  EXPECT_EQ(tg::xist2_content(h.drive_sp.G1_STW, h.actual.G1_ZSW), tg::Xist2Content::kMeasuredValue);
  // Leaving the window clears G1_ZSW.8; the value stays available.
  h.run_until([&] { return !h.drive.machine_inputs().probe1; }, 2000);
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0011");
  EXPECT_NEAR(static_cast<double>(h.actual.G1_XIST2), expected, 1.0);
}

// spec 06 §6.2/§6.3: G1_STW 0x2000 -> G1_ZSW.13, XIST2 = revolutions * steps * 2^p0419 (modulo the range);
// a power cycle keeps the mechanics and therefore the absolute value; an incremental encoder (G2 here)
// restarts its XIST1 at its power-on value and never acknowledges the absolute-value request.
TEST(EncoderSim, AbsoluteValueSurvivesPowerCycleIncrementalRestarts) {
  SimulatedDriveParameters p;
  p.initial_load_position = 900.0;  // 2.5 revolutions
  p.encoder2.determinable_revolutions = 0;
  p.encoder2.xist1_at_power_on = 0x1000;
  Harness h(drive_config(4), p);
  const double abs_cpr =
      tg::counts_per_revolution(p.encoder1.steps_per_revolution, p.encoder1.fine_resolution_xist2);
  ASSERT_DOUBLE_EQ(abs_cpr, 2048.0 * 512.0);
  h.drive_sp.G1_STW = tg::EncoderControlWord{0x2000};
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x2000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x2000");
  EXPECT_EQ(h.actual.G1_XIST2, static_cast<std::uint32_t>(2.5 * abs_cpr));  // 2 621 440
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x0000") << "incremental: no absolute value";
  EXPECT_EQ(h.actual.G2_XIST2, 0u);
  EXPECT_EQ(h.actual.G2_XIST1, 0x1000u);

  // Move by about +1.2 revolutions and stop.
  h.power_up_to_s4();
  h.speed_rpm(120.0);
  h.run(600);
  h.speed_rpm(0.0);
  h.run(200);
  ASSERT_EQ(h.nist_rpm(), 0.0);
  const double rev = h.drive.load_position() / 360.0;
  ASSERT_GT(rev, 3.6);
  const auto abs_before = h.actual.G1_XIST2;
  const auto xist1_before = h.actual.G1_XIST1;
  EXPECT_EQ(abs_before, static_cast<std::uint32_t>(std::floor(rev * abs_cpr)));
  EXPECT_NEAR(static_cast<double>(h.actual.G2_XIST1), 0x1000 + (rev - 2.5) * cpr(p.encoder2), 1.0);

  h.drive.power_cycle();
  ASSERT_TRUE(h.cycle_without_setpoint());
  EXPECT_EQ(hex16(h.zsw1()), "0x0000");
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x2000");
  EXPECT_EQ(h.actual.G1_XIST2, abs_before);
  EXPECT_EQ(h.actual.G1_XIST1, xist1_before);
  EXPECT_EQ(h.actual.G2_XIST1, 0x1000u) << "incremental XIST1 restarts at its power-on value";

  // Multi-turn range: the absolute value wraps at determinable_revolutions (spec 06 §6.2 absolute range).
  EXPECT_EQ(tg::absolute_range_counts(2048, 9, 4096), static_cast<std::uint64_t>(4096 * abs_cpr));
}

// spec 06 §6.3/§6.4 on G2 of telegram 4: G2_ZSW.15 with the code in G2_XIST2; G2_STW 0x8000 shows G2_ZSW.11;
// the error is cleared only by an acknowledge after the cause is gone. G2 (load encoder) does not fault the
// drive.
TEST(EncoderSim, ErrorOnG2OfTelegram4) {
  Harness h(drive_config(4), {});
  h.power_up_to_s4();
  h.drive.inject_encoder_error(2, tg::kEncoderErrorZeroMarkMonitoring);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x8000");
  EXPECT_EQ(tg::encoder_error_code(h.actual.G2_XIST2), tg::kEncoderErrorZeroMarkMonitoring);
  EXPECT_EQ(tg::xist2_content(h.drive_sp.G2_STW, h.actual.G2_ZSW), tg::Xist2Content::kErrorCode);
  EXPECT_EQ(hex16(h.actual.G1_ZSW.value()), "0x0000");
  EXPECT_EQ(h.drive.active_fault(), 0u);
  EXPECT_EQ(hex16(h.zsw1()), "0x0337");

  // Acknowledge while the cause is present: bit 11 shows the acknowledge, the error stays.
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x8000};
  h.run(2);
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x8800");
  EXPECT_EQ(tg::encoder_error_code(h.actual.G2_XIST2), tg::kEncoderErrorZeroMarkMonitoring);
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x0000};
  h.run(1);
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x8000");

  // Cause gone: the error bit stays until the acknowledge.
  h.drive.clear_encoder_error(2);
  h.run(3);
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x8000");
  EXPECT_EQ(tg::encoder_error_code(h.actual.G2_XIST2), tg::kEncoderErrorZeroMarkMonitoring);
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x8000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x0800");
  EXPECT_EQ(h.actual.G2_XIST2, 0u);
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x0000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x0000");
}

// spec 06 §6.3: a command value > 3 drives the encoder into its error state (0x0F01, §6.4); once the invalid
// command is withdrawn the error can be acknowledged.
TEST(EncoderSim, InvalidCommandReportsCommandError) {
  Harness h(drive_config(4), {});
  h.power_up_to_s4();
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x0041};  // command 4
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(h.actual.G2_ZSW.value() & 0x8000u, 0x8000u);
  EXPECT_EQ(tg::encoder_error_code(h.actual.G2_XIST2), tg::kEncoderErrorCommandNotSupported);
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x0000};
  h.run(2);
  EXPECT_EQ(h.actual.G2_ZSW.value() & 0x8000u, 0x8000u) << "latched until acknowledged";
  h.drive_sp.G2_STW = tg::EncoderControlWord{0x8000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(h.actual.G2_ZSW.value()), "0x0800");
}

struct SeparateEncoderCase {
  const char* name;
  std::uint16_t telegram;
};

class SeparateEncoder : public ::testing::TestWithParam<SeparateEncoderCase> {};

// Encoder-only device with telegram 81/83 (spec 06 §2.12/§2.13, §3.8): ZSW2_ENC.3 and G1_ZSW.15 with the code
// in XIST2; acknowledge with G1_STW 0x8000 (G1_ZSW.11); error cleared only after the cause is gone.
TEST_P(SeparateEncoder, ErrorReportingAndAcknowledge) {
  const auto& c = GetParam();
  SimulatedDriveParameters p;
  p.encoder1.shaft = SimulatedEncoderParameters::Shaft::kLoad;
  Harness h(drive_config(0, 0, {c.telegram, 0}), p);
  h.drive.set_external_speed(360.0);  // 1 load revolution per second
  h.run(10);
  auto& a = h.encoder_actual[0];
  auto& sp = h.encoder[0];
  EXPECT_TRUE(a.ZSW2_ENC.test(tg::Zsw2EncBit::kControlRequested));
  EXPECT_FALSE(a.ZSW2_ENC.test(tg::Zsw2EncBit::kFaultPresent));
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x0000");
  if (c.telegram == 83) {
    // NIST_B: 60 rpm of the measured shaft at nist_reference_speed 3000 rpm = 2 % = 0.02 * 2^30.
    EXPECT_EQ(a.NIST_B, tg::speed_to_n4(60.0, p.encoder1.nist_reference_speed));
  }
  // XIST1 counts the external motion: 1 rev/s * 1 ms * 4 194 304 = 4194.3 counts per cycle.
  const auto before = a.G1_XIST1;
  ASSERT_TRUE(h.cycle());
  EXPECT_NEAR(static_cast<double>(tg::xist1_delta(before, a.G1_XIST1)), 4194.304, 1.0);

  h.drive.inject_encoder_error(1, tg::kEncoderErrorSensorGroup);
  ASSERT_TRUE(h.cycle());
  EXPECT_TRUE(a.ZSW2_ENC.test(tg::Zsw2EncBit::kFaultPresent));
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x8000");
  EXPECT_EQ(tg::encoder_error_code(a.G1_XIST2), tg::kEncoderErrorSensorGroup);
  sp.G1_STW = tg::EncoderControlWord{0x8000};
  h.run(2);
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x8800") << "acknowledge shown, cause still present";
  sp.G1_STW = tg::EncoderControlWord{0x0000};
  h.drive.clear_encoder_error(1);
  h.run(2);
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x8000") << "latched until acknowledged";
  sp.G1_STW = tg::EncoderControlWord{0x8000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x0800");
  EXPECT_FALSE(a.ZSW2_ENC.test(tg::Zsw2EncBit::kFaultPresent));
  sp.G1_STW = tg::EncoderControlWord{0x0000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x0000");

  // spec 06 §3.8: without STW2_ENC.10 (control by PLC) G1_STW is disabled and XIST2 is not output.
  sp.G1_STW = tg::EncoderControlWord{0x2000};
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x2000");
  EXPECT_NE(a.G1_XIST2, 0u);
  sp.STW2_ENC.set(tg::Stw2EncBit::kControlByPlc, false);
  ASSERT_TRUE(h.cycle());
  EXPECT_EQ(hex16(a.G1_ZSW.value()), "0x0000");
  EXPECT_EQ(a.G1_XIST2, 0u);
}

INSTANTIATE_TEST_SUITE_P(Telegrams, SeparateEncoder,
                         ::testing::Values(SeparateEncoderCase{"T81", 81}, SeparateEncoderCase{"T83", 83}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace tomc::drives::test
