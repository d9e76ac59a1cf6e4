// Every test vector of spec 06 §11 (TV01..TV26), one test each, with the exact bytes/values of the table.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "test_helpers.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/control_words.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/encoder.hpp"
#include "tomc/telegrams/normalisation.hpp"
#include "tomc/telegrams/sign_of_life.hpp"

namespace tomc::telegrams {
namespace {

using test::bytes;
using test::hex;

constexpr double kRefSpeed = 3000.0;  // spec 06 §11: n_ref = 3000 rpm unless stated

TelegramCodec codec(int telegram, Direction direction) {
  auto c = TelegramCodec::create(telegram, direction);
  EXPECT_TRUE(c.ok()) << "telegram " << telegram << ": " << describe(c.error());
  return c.value();
}

std::vector<std::byte> encode(int telegram, const SetpointSignals& values) {
  const auto c = codec(telegram, Direction::kSetpoint);
  std::vector<std::byte> frame(c.frame_size(), std::byte{0xAA});
  EXPECT_EQ(c.encode(values, frame), TelegramError::kNone);
  return frame;
}

ActualSignals decode_actual(int telegram, const std::vector<std::byte>& frame) {
  const auto c = codec(telegram, Direction::kActual);
  ActualSignals values;
  EXPECT_EQ(c.decode(frame, values), TelegramError::kNone);
  return values;
}

Stw2 stw2_with_sign_of_life(std::uint16_t ls, std::uint16_t other_bits = 0) {
  Stw2 stw2{other_bits};
  stw2.set_field(kSignOfLifeField, ls);
  return stw2;
}

// spec 06 §11 TV01 — §2.1 layout of telegram 1, §1.2 N2 normalisation
TEST(TestVectors, TV01_Telegram1SetpointRun1500rpm) {
  SetpointSignals s;
  s.STW1 = Stw1{0x047F};
  s.NSOLL_A = speed_to_n2(1500.0, kRefSpeed);
  EXPECT_EQ(s.NSOLL_A, 0x2000);
  EXPECT_EQ(hex(encode(1, s)), "04 7F 20 00");
}

// spec 06 §11 TV02 — §2.1, §1.2 N2 of a negative speed
TEST(TestVectors, TV02_Telegram1SetpointNegative750rpm) {
  SetpointSignals s;
  s.STW1 = Stw1{0x047E};
  s.NSOLL_A = speed_to_n2(-750.0, kRefSpeed);
  EXPECT_EQ(s.NSOLL_A, -4096);
  EXPECT_EQ(hex(encode(1, s)), "04 7E F0 00");
}

// spec 06 §11 TV03 — §2.2 layout of telegram 2, §1.2 N4, §3.3 master sign-of-life in STW2.12-15
TEST(TestVectors, TV03_Telegram2SetpointWithSignOfLife1) {
  SetpointSignals s;
  s.STW1 = Stw1{0x047F};
  s.NSOLL_B = speed_to_n4(1500.0, kRefSpeed);
  s.STW2 = stw2_with_sign_of_life(1);
  EXPECT_EQ(hex(encode(2, s)), "04 7F 20 00 00 00 10 00");
}

// spec 06 §11 TV04 — §2.3 layout of telegram 3 (10 setpoint bytes)
TEST(TestVectors, TV04_Telegram3Setpoint) {
  SetpointSignals s;
  s.STW1 = Stw1{0x047F};
  s.NSOLL_B = speed_to_n4(1500.0, kRefSpeed);
  s.STW2 = stw2_with_sign_of_life(5);
  s.G1_STW = EncoderControlWord{0};
  const auto frame = encode(3, s);
  EXPECT_EQ(frame.size(), 10u);
  EXPECT_EQ(hex(frame), "04 7F 20 00 00 00 50 00 00 00");
}

// spec 06 §11 TV05 — §2.3 actual layout, §4.2 decode rule, §1.2 N4 decode, §6.2 XIST2 not valid
TEST(TestVectors, TV05_Telegram3ActualDecode) {
  const auto a = decode_actual(3, bytes({0x02, 0x37, 0xE0, 0x00, 0x00, 0x00, 0x60, 0x00, 0x00, 0x00, 0x00,
                                         0x40, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(a.ZSW1.value(), 0x0237);
  EXPECT_EQ(decode_zsw1(a.ZSW1.value()).state, DriveState::kS4Operation);
  EXPECT_EQ(static_cast<std::uint32_t>(a.NIST_B), 0xE0000000u);
  EXPECT_DOUBLE_EQ(n4_to_speed(a.NIST_B, kRefSpeed), -1500.0);
  EXPECT_EQ(a.ZSW2.field(kSignOfLifeField), 6);
  EXPECT_EQ(a.G1_ZSW.value(), 0);
  EXPECT_EQ(a.G1_XIST1, 0x00400000u);
  EXPECT_EQ(a.G1_XIST1, 4194304u);
  EXPECT_EQ(a.G1_XIST2, 0u);
  EXPECT_FALSE(a.G1_ZSW.test(EncoderStatusBit::kAbsoluteValueTransmitted));
  EXPECT_EQ(xist2_content(EncoderControlWord{0}, a.G1_ZSW), Xist2Content::kNotValid);
}

// spec 06 §11 TV06 — §1.2 N4 decoding
TEST(TestVectors, TV06_NistBDecode) {
  const double speed = n4_to_speed(static_cast<std::int32_t>(0x0CCCCCCD), kRefSpeed);
  EXPECT_NEAR(speed, 600.0000006, 1e-7);
  EXPECT_GT(speed, 600.0);
  EXPECT_NEAR(n4_to_speed(static_cast<std::int32_t>(0x0CCCCCCD), 1.0), 0.2000000002, 1e-10);
}

// spec 06 §11 TV07 — §1.2 N4 of -100 %
TEST(TestVectors, TV07_NsollBMinus100Percent) {
  SetpointSignals s;
  s.NSOLL_B = speed_to_n4(-3000.0, kRefSpeed);
  EXPECT_EQ(static_cast<std::uint32_t>(s.NSOLL_B), 0xC0000000u);
  const auto frame = encode(2, s);
  EXPECT_EQ(hex(std::span<const std::byte>(frame).subspan(2, 4)), "C0 00 00 00");
}

// spec 06 §11 TV08 — §1.2 saturation of N4 at +200 % and decoding of 0x80000000
TEST(TestVectors, TV08_NsollBSaturation) {
  for (const double n : {7000.0, 6000.0}) {
    SetpointSignals s;
    s.NSOLL_B = speed_to_n4(n, kRefSpeed);
    EXPECT_EQ(static_cast<std::uint32_t>(s.NSOLL_B), 0x7FFFFFFFu) << n;
    const auto frame = encode(2, s);
    EXPECT_EQ(hex(std::span<const std::byte>(frame).subspan(2, 4)), "7F FF FF FF") << n;
  }
  EXPECT_DOUBLE_EQ(n4_to_speed(static_cast<std::int32_t>(0x80000000u), kRefSpeed), -6000.0);
}

// spec 06 §11 TV09 — §2.7 layout of telegram 102, §9 MOMRED
TEST(TestVectors, TV09_Telegram102Setpoint) {
  constexpr double kRefTorque = 10.0;
  SetpointSignals s;
  s.STW1 = Stw1{0x047F};
  s.NSOLL_B = speed_to_n4(1500.0, kRefSpeed);
  s.STW2 = stw2_with_sign_of_life(3);
  s.MOMRED = momred_from_torque_limit(0.25 * kRefTorque, kRefTorque);
  EXPECT_EQ(s.MOMRED, 0x3000);
  s.G1_STW = EncoderControlWord{0};
  const auto frame = encode(102, s);
  EXPECT_EQ(frame.size(), 12u);
  EXPECT_EQ(hex(frame), "04 7F 20 00 00 00 30 00 30 00 00 00");
}

// spec 06 §11 TV10 — §2.10 layout of telegram 105, §7 XERR and KPC
TEST(TestVectors, TV10_Telegram105Setpoint) {
  SetpointSignals s;
  s.STW1 = Stw1{0x047F};
  s.NSOLL_B = speed_to_n4(1500.0, kRefSpeed);
  s.STW2 = stw2_with_sign_of_life(1);
  s.MOMRED = 0;
  s.G1_STW = EncoderControlWord{0};
  s.XERR = xerr_from_counts(-1234.0);
  s.KPC = kpc_from_kv(500.0);
  EXPECT_EQ(s.KPC, 500000);
  EXPECT_EQ(s.KPC, 0x0007A120);
  const auto frame = encode(105, s);
  EXPECT_EQ(frame.size(), 20u);
  EXPECT_EQ(hex(frame), "04 7F 20 00 00 00 10 00 00 00 00 00 FF FF FB 2E 00 07 A1 20");
}

// spec 06 §11 TV11 — §7 KPC rounding rule (not Siemens' truncated 0x000A2C2A)
TEST(TestVectors, TV11_KpcRounding) {
  const double kv = 40.0 * 1000.0 / 60.0;  // 40 (1000/min) in 1/s
  const std::int32_t kpc = kpc_from_kv(kv);
  EXPECT_EQ(kpc, 666667);
  EXPECT_NE(kpc, 0x000A2C2A);
  SetpointSignals s;
  s.KPC = kpc;
  const auto frame = encode(5, s);
  EXPECT_EQ(hex(std::span<const std::byte>(frame).subspan(14, 4)), "00 0A 2C 2B");
}

// spec 06 §11 TV12 — §7 XERR in encoder-1 counts
TEST(TestVectors, TV12_XerrFromFollowingError) {
  const double counts_per_rev = counts_per_revolution(2048, 11);
  EXPECT_DOUBLE_EQ(counts_per_rev, 4194304.0);
  const double following_error_mm = 1.0;
  const double leadscrew_mm_per_rev = 10.0;
  const std::int32_t xerr = xerr_from_counts(following_error_mm / leadscrew_mm_per_rev * counts_per_rev);
  EXPECT_EQ(xerr, 419430);
  SetpointSignals s;
  s.XERR = xerr;
  const auto frame = encode(105, s);
  EXPECT_EQ(hex(std::span<const std::byte>(frame).subspan(12, 4)), "00 06 66 66");
}

// spec 06 §11 TV13 — §2.10 actual layout of 105, §3.5 MELDW, §6.2 absolute value in XIST2
TEST(TestVectors, TV13_Telegram105ActualDecode) {
  const auto a = decode_actual(105, bytes({0x02, 0x37, 0x10, 0x00, 0x00, 0x00, 0x20, 0x00, 0x30, 0x00,
                                           0x20, 0x00, 0x12, 0x34, 0x56, 0x78, 0x01, 0x00, 0x00, 0x00}));
  EXPECT_EQ(decode_zsw1(a.ZSW1.value()).state, DriveState::kS4Operation);
  EXPECT_EQ(a.NIST_B, 0x10000000);
  EXPECT_DOUBLE_EQ(n4_to_speed(a.NIST_B, kRefSpeed), 750.0);
  EXPECT_EQ(a.ZSW2.field(kSignOfLifeField), 2);
  EXPECT_EQ(a.MELDW.value(), 0x3000);
  EXPECT_TRUE(a.MELDW.test(MeldwBit::kDriveReady));
  EXPECT_TRUE(a.MELDW.test(MeldwBit::kPulsesEnabled));
  EXPECT_FALSE(a.MELDW.test(MeldwBit::kControllerEnable));
  EXPECT_EQ(a.G1_ZSW.value(), 0x2000);
  EXPECT_EQ(xist2_content(EncoderControlWord{encoder_request::absolute_value()}, a.G1_ZSW),
            Xist2Content::kAbsoluteValue);
  EXPECT_EQ(a.G1_XIST1, 0x12345678u);
  EXPECT_EQ(a.G1_XIST2, 0x01000000u);
}

// spec 06 §11 TV14 — §2.14 layout of 750, §8 default limits = +/- reference torque
TEST(TestVectors, TV14_Telegram750DefaultSetpoint) {
  constexpr double kRefTorque = 10.0;
  SetpointSignals s;
  s.M_ADD1 = 0;
  s.M_LIMIT_POS = torque_to_n2(kRefTorque, kRefTorque);
  s.M_LIMIT_NEG = torque_to_n2(-kRefTorque, kRefTorque);
  EXPECT_EQ(hex(encode(750, s)), "00 00 40 00 C0 00");
}

// spec 06 §11 TV15 — §8 N2 scaling of telegram 750 setpoints
TEST(TestVectors, TV15_Telegram750Setpoint) {
  constexpr double kRefTorque = 10.0;
  SetpointSignals s;
  s.M_ADD1 = torque_to_n2(2.5, kRefTorque);
  s.M_LIMIT_POS = torque_to_n2(5.0, kRefTorque);
  s.M_LIMIT_NEG = torque_to_n2(-5.0, kRefTorque);
  EXPECT_EQ(hex(encode(750, s)), "10 00 20 00 E0 00");
}

// spec 06 §11 TV16 — §8 M_ACT decode
TEST(TestVectors, TV16_Telegram750ActualDecode) {
  const auto a = decode_actual(750, bytes({0xF8, 0x00}));
  EXPECT_EQ(a.M_ACT, -2048);
  EXPECT_DOUBLE_EQ(n2_to_torque(a.M_ACT, 10.0), -1.25);
}

// spec 06 §11 TV17 — §5.1 master sign-of-life 1..15, never 0, in STW2.12-15
TEST(TestVectors, TV17_MasterSignOfLifeWrap) {
  SignOfLifeGenerator generator;
  generator.reset(13);
  EXPECT_EQ(generator.next(), 13);  // the start value
  const std::uint16_t expected_counters[] = {14, 15, 1, 2};
  const std::uint16_t expected_stw2[] = {0xE100, 0xF100, 0x1100, 0x2100};
  for (int i = 0; i < 4; ++i) {
    const std::uint8_t ls = generator.next();
    EXPECT_EQ(ls, expected_counters[i]) << "increment " << i + 1;
    Stw2 stw2{0x0100};
    EXPECT_TRUE(stw2.test(Stw2Bit::kTravelToFixedStop));
    stw2.set_field(kSignOfLifeField, ls);
    EXPECT_EQ(stw2.value(), expected_stw2[i]) << "increment " << i + 1;
    EXPECT_NE(stw2.value(), 0x0100);
  }
}

// spec 06 §11 TV18 — §5.2 [OUR CHOICE] controller-side monitor, "keep own expectation" variant
TEST(TestVectors, TV18_SlaveSignOfLifeMonitorTrip) {
  SignOfLifeMonitor monitor(SignOfLifeMonitorConfig{.tolerance = 1, .step = 1});
  const std::uint8_t received[] = {3, 4, 4, 5};
  const std::uint32_t counter_after[] = {0, 0, 10, 20};
  const SignOfLifeStatus status_after[] = {SignOfLifeStatus::kOk, SignOfLifeStatus::kOk,
                                           SignOfLifeStatus::kOk, SignOfLifeStatus::kFailed};
  for (int cycle = 0; cycle < 4; ++cycle) {
    EXPECT_EQ(monitor.check(received[cycle]), status_after[cycle]) << "cycle " << cycle + 1;
    EXPECT_EQ(monitor.error_counter(), counter_after[cycle]) << "cycle " << cycle + 1;
  }
}

// spec 06 §11 TV19 — §6.1 32-bit XIST1 wrap in both directions
TEST(TestVectors, TV19_Xist1Wrap32) {
  EXPECT_EQ(xist1_delta(0xFFFFFF00u, 0x00000100u), 512);
  EXPECT_EQ(xist1_delta(0x00000100u, 0xFFFFFF00u), -512);
  EXPECT_EQ(xist1_delta(0xFFFFFF00u, 0x00000100u, 32), 512);
}

// spec 06 §11 TV20 — §6.1 16-bit counter (BehaviorGx_XIST1 = 0)
TEST(TestVectors, TV20_Xist1Wrap16) {
  EXPECT_EQ(xist1_delta(0xFFF0u, 0x0010u, 16), 32);
}

// spec 06 §11 TV21 — §6.1 position computation
TEST(TestVectors, TV21_PositionFromCounts) {
  IncrementalCount count;
  count.update(0x7FF00000u);
  EXPECT_EQ(count.update(0x7FF00000u + 1048576u), 1048576);
  const double counts_per_rev = counts_per_revolution(2048, 11);
  EXPECT_DOUBLE_EQ(counts_per_rev, 4194304.0);
  const double revolutions = static_cast<double>(count.counts()) / counts_per_rev;
  EXPECT_DOUBLE_EQ(revolutions, 0.25);
  EXPECT_DOUBLE_EQ(revolutions * 10.0, 2.5);
}

// spec 06 §11 TV22 — §6.2 error code in XIST2, §6.4 code 0x0001
TEST(TestVectors, TV22_EncoderErrorInXist2) {
  const EncoderStatusWord g1_zsw{0x8000};
  const std::uint32_t g1_xist2 = 0x00000001;
  EXPECT_TRUE(g1_zsw.test(EncoderStatusBit::kEncoderError));
  EXPECT_EQ(xist2_content(EncoderControlWord{0}, g1_zsw), Xist2Content::kErrorCode);
  EXPECT_EQ(encoder_error_code(g1_xist2), kEncoderErrorSensorGroup);
  EXPECT_EQ(kEncoderErrorSensorGroup, 0x0001);
  EXPECT_NE(describe_encoder_error(encoder_error_code(g1_xist2)).find("sensor group error"),
            std::string_view::npos);
}

// spec 06 §11 TV23 — §6.3 G1_STW handshake words, big-endian in telegram 81 (§2.12)
TEST(TestVectors, TV23_EncoderRequestWords) {
  const std::uint16_t words[] = {
      encoder_request::reference_mark_search(), encoder_request::read_reference_mark(),
      encoder_request::flying_measurement(),    encoder_request::read_measured_value(),
      encoder_request::absolute_value(),        encoder_request::acknowledge_error(),
  };
  const char* expected[] = {"00 11", "00 21", "00 91", "00 A1", "20 00", "80 00"};
  for (int i = 0; i < 6; ++i) {
    SetpointSignals s;
    s.G1_STW = EncoderControlWord{words[i]};
    const auto frame = encode(81, s);
    EXPECT_EQ(hex(std::span<const std::byte>(frame).subspan(2, 2)), expected[i]) << "request " << i;
  }
}

// spec 06 §11 TV24 — §4.2 ZSW1 decoding rule
TEST(TestVectors, TV24_Zsw1StateDecode) {
  struct Row {
    std::uint16_t zsw1;
    DriveState state;
    bool control_ok;
  };
  const Row rows[] = {
      {0x0270, DriveState::kS1SwitchingOnInhibited, true},
      {0x0231, DriveState::kS2ReadyForSwitchingOn, true},
      {0x0233, DriveState::kS3SwitchedOn, true},
      {0x0237, DriveState::kS4Operation, true},
      {0x0213, DriveState::kS5bQuickStop, true},  // bit 5 = 0 => quick stop
      {0x0248, DriveState::kFault, true},
      {0x0037, DriveState::kS4Operation, false},  // bit 9 = 0
  };
  for (const auto& row : rows) {
    const DriveStatus status = decode_zsw1(row.zsw1);
    EXPECT_EQ(status.state, row.state) << std::hex << row.zsw1;
    EXPECT_EQ(status.control_requested, row.control_ok) << std::hex << row.zsw1;
  }
  EXPECT_TRUE(decode_zsw1(0x0213).quick_stop_active);
  EXPECT_FALSE(decode_zsw1(0x0233).quick_stop_active);
}

// spec 06 §11 TV25 — §2.12/§2.13 layouts of 81/83, §3.8 ZSW2_ENC, §6.2 absolute value, §1.2 N4
TEST(TestVectors, TV25_EncoderTelegrams81And83) {
  const auto t81 =
      decode_actual(81, bytes({0x12, 0x00, 0x00, 0x00, 0x00, 0xAB, 0xCD, 0xEF, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(t81.ZSW2_ENC.value(), 0x1200);
  EXPECT_TRUE(t81.ZSW2_ENC.test(Zsw2EncBit::kControlRequested));
  EXPECT_FALSE(t81.ZSW2_ENC.test(Zsw2EncBit::kFaultPresent));
  EXPECT_EQ(t81.ZSW2_ENC.field(kSignOfLifeField), 1);
  EXPECT_EQ(t81.G1_ZSW.value(), 0);
  EXPECT_EQ(t81.G1_XIST1, 0x00ABCDEFu);
  EXPECT_EQ(t81.G1_XIST2, 0u);

  const auto t83 = decode_actual(83, bytes({0x12, 0x00, 0x20, 0x00, 0x00, 0xAB, 0xCD, 0xEF, 0x00, 0x12, 0x34,
                                            0x56, 0x06, 0x66, 0x66, 0x66}));
  EXPECT_TRUE(t83.G1_ZSW.test(EncoderStatusBit::kAbsoluteValueTransmitted));
  EXPECT_EQ(xist2_content(EncoderControlWord{encoder_request::absolute_value()}, t83.G1_ZSW),
            Xist2Content::kAbsoluteValue);
  EXPECT_EQ(t83.G1_XIST1, 0x00ABCDEFu);
  EXPECT_EQ(t83.G1_XIST2, 0x00123456u);
  EXPECT_EQ(t83.NIST_B, 0x06666666);
  EXPECT_NEAR(n4_to_speed(t83.NIST_B, 1.0), 0.09999999963, 1e-11);
  EXPECT_NEAR(n4_to_speed(t83.NIST_B, kRefSpeed), 299.9999989, 1e-7);
  EXPECT_EQ(speed_to_n4(300.0, kRefSpeed), 0x06666666);  // the N4 encoding of exactly 10 %
}

// spec 06 §11 TV26 — §4.1/§4.2/§4.3 fault acknowledge sequence, controller (Stw1Sequencer) against a drive
// simulated with next_drive_state + zsw1_for; the fault reaction masks STW1 bits 0..2 (§4.1 "Fault").
TEST(TestVectors, TV26_FaultAcknowledgeSequence) {
  DriveState state = DriveState::kS1SwitchingOnInhibited;
  bool fault = true;
  std::uint16_t previous_stw1 = 0x047E;
  auto drive_cycle = [&](std::uint16_t stw1) {
    const bool ack_edge = (stw1 & 0x0080u) != 0 && (previous_stw1 & 0x0080u) == 0;
    previous_stw1 = stw1;
    if (fault && ack_edge) {
      fault = false;  // the acknowledge leaves the drive in switching-on inhibited (§4.1)
      state = DriveState::kS1SwitchingOnInhibited;
    } else {
      const std::uint16_t effective = fault ? static_cast<std::uint16_t>(stw1 & ~0x0007u) : stw1;
      state = next_drive_state(state, effective, false);
    }
    const std::uint16_t effective = fault ? static_cast<std::uint16_t>(stw1 & ~0x0007u) : stw1;
    return zsw1_for(state, effective, true, fault, false);
  };

  std::uint16_t zsw1 = drive_cycle(0x047E);
  ASSERT_EQ(zsw1, 0x0248);

  Stw1Sequencer sequencer;
  sequencer.request_acknowledge();
  const std::uint16_t expected_stw1[] = {0x04FE, 0x047E, 0x047F, 0x047F};
  const std::uint16_t expected_zsw1[] = {0x0270, 0x0231, 0x0233, 0x0237};
  for (int cycle = 0; cycle < 4; ++cycle) {
    const std::uint16_t stw1 = sequencer.next(zsw1, DriveRequest::kOperate);
    EXPECT_EQ(stw1, expected_stw1[cycle]) << "cycle " << cycle;
    zsw1 = drive_cycle(stw1);
    EXPECT_EQ(zsw1, expected_zsw1[cycle]) << "cycle " << cycle;
  }
  EXPECT_EQ(decode_zsw1(zsw1).state, DriveState::kS4Operation);
  // Steady state: the sequencer keeps the run word.
  EXPECT_EQ(sequencer.next(zsw1, DriveRequest::kOperate), 0x047F);
}

}  // namespace
}  // namespace tomc::telegrams
