// Physical value <-> wire value conversions: spec 06 §1.2 (N2/N4 [OUR CHOICE] rounding and saturation),
// §7 (XERR, KPC), §8 (telegram 750 torques), §9 (MOMRED).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "tomc/telegrams/normalisation.hpp"

namespace tomc::telegrams {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// spec 06 §1.2: 0x4000 = 100 % (N2), 0x40000000 = 100 % (N4).
TEST(Normalisation, HundredPercent) {
  EXPECT_EQ(kN2Hundred, 16384.0);
  EXPECT_EQ(kN4Hundred, 1073741824.0);
  EXPECT_EQ(speed_to_n2(3000.0, 3000.0), 0x4000);
  EXPECT_EQ(speed_to_n2(-3000.0, 3000.0), -0x4000);
  EXPECT_EQ(speed_to_n4(3000.0, 3000.0), 0x40000000);
  EXPECT_EQ(speed_to_n4(-3000.0, 3000.0), -0x40000000);
  EXPECT_EQ(speed_to_n2(0.0, 3000.0), 0);
  EXPECT_EQ(speed_to_n4(0.0, 3000.0), 0);
  EXPECT_DOUBLE_EQ(n2_to_speed(0x4000, 3000.0), 3000.0);
  EXPECT_DOUBLE_EQ(n4_to_speed(0x40000000, 3000.0), 3000.0);
}

// spec 06 §1.2: N2 range -200 % (0x8000) ... +199.994 % (0x7FFF); saturation at both edges.
TEST(Normalisation, N2SaturationEdges) {
  // reference 16384 makes one raw step = one unit.
  EXPECT_EQ(speed_to_n2(32767.0, 16384.0), 32767);
  EXPECT_EQ(speed_to_n2(32767.4, 16384.0), 32767);
  EXPECT_EQ(speed_to_n2(32767.5, 16384.0), 32767);  // would round to 32768: saturates
  EXPECT_EQ(speed_to_n2(32768.0, 16384.0), 32767);
  EXPECT_EQ(speed_to_n2(1e12, 16384.0), 32767);
  EXPECT_EQ(speed_to_n2(-32768.0, 16384.0), -32768);
  EXPECT_EQ(speed_to_n2(-32768.4, 16384.0), -32768);
  EXPECT_EQ(speed_to_n2(-32768.5, 16384.0), -32768);  // would round to -32769: saturates
  EXPECT_EQ(speed_to_n2(-1e12, 16384.0), -32768);
  EXPECT_EQ(speed_to_n2(6000.0, 3000.0), 32767);    // exactly +200 % is not representable
  EXPECT_EQ(speed_to_n2(-6000.0, 3000.0), -32768);  // exactly -200 % is 0x8000
  EXPECT_DOUBLE_EQ(n2_to_speed(-32768, 3000.0), -6000.0);
  EXPECT_DOUBLE_EQ(n2_to_speed(32767, 16384.0), 32767.0);
}

// spec 06 §1.2: N4 range 0x80000000 ... 0x7FFFFFFF.
TEST(Normalisation, N4SaturationEdges) {
  EXPECT_EQ(speed_to_n4(2147483647.0, kN4Hundred), 2147483647);
  EXPECT_EQ(speed_to_n4(2147483647.25, kN4Hundred), 2147483647);
  EXPECT_EQ(speed_to_n4(2147483647.5, kN4Hundred), 2147483647);  // would round to 2^31: saturates
  EXPECT_EQ(speed_to_n4(2147483648.0, kN4Hundred), 2147483647);
  EXPECT_EQ(speed_to_n4(-2147483648.0, kN4Hundred), -2147483647 - 1);
  EXPECT_EQ(speed_to_n4(-2147483648.5, kN4Hundred), -2147483647 - 1);
  EXPECT_EQ(speed_to_n4(-1e300, kN4Hundred), -2147483647 - 1);
  EXPECT_EQ(speed_to_n4(1e300, kN4Hundred), 2147483647);
  EXPECT_EQ(speed_to_n4(-6000.0, 3000.0), -2147483647 - 1);  // -200 % = 0x80000000
  EXPECT_EQ(speed_to_n4(-7000.0, 3000.0), -2147483647 - 1);
}

// spec 06 §1.2 [OUR CHOICE]: round half away from zero (not to even, not truncation).
TEST(Normalisation, RoundHalfAwayFromZero) {
  // N2 with reference 16384: raw = speed.
  EXPECT_EQ(speed_to_n2(0.5, 16384.0), 1);
  EXPECT_EQ(speed_to_n2(-0.5, 16384.0), -1);
  EXPECT_EQ(speed_to_n2(1.5, 16384.0), 2);
  EXPECT_EQ(speed_to_n2(2.5, 16384.0), 3);  // half-to-even would give 2
  EXPECT_EQ(speed_to_n2(-2.5, 16384.0), -3);
  EXPECT_EQ(speed_to_n2(2.4999, 16384.0), 2);
  EXPECT_EQ(speed_to_n2(-2.4999, 16384.0), -2);
  EXPECT_EQ(speed_to_n2(0.49, 16384.0), 0);
  EXPECT_EQ(speed_to_n2(-0.49, 16384.0), 0);
  // N4 with reference 2^30: raw = speed.
  EXPECT_EQ(speed_to_n4(0.5, kN4Hundred), 1);
  EXPECT_EQ(speed_to_n4(-0.5, kN4Hundred), -1);
  EXPECT_EQ(speed_to_n4(4.5, kN4Hundred), 5);  // half-to-even would give 4
  EXPECT_EQ(speed_to_n4(-4.5, kN4Hundred), -5);
  EXPECT_EQ(speed_to_n4(1000000.5, kN4Hundred), 1000001);
  // 10 % of 2^30 = 107374182.4 -> 107374182 (TV25), 0.6 -> up.
  EXPECT_EQ(speed_to_n4(300.0, 3000.0), 107374182);
  EXPECT_EQ(speed_to_n4(-300.0, 3000.0), -107374182);
  EXPECT_EQ(speed_to_n2(1.0, 3.0), 5461);   // 5461.33
  EXPECT_EQ(speed_to_n2(2.0, 3.0), 10923);  // 10922.67
  EXPECT_EQ(speed_to_n2(-2.0, 3.0), -10923);
}

// Header contract (normalisation.hpp): NaN gives 0; a reference <= 0 or non-finite gives 0.
// Decision T3 (a NaN value or a reference not finite or not > 0 gives 0, never a full-scale setpoint).
TEST(Normalisation, NaNAndBadReferenceGiveZero) {
  EXPECT_EQ(speed_to_n2(kNaN, 3000.0), 0);
  EXPECT_EQ(speed_to_n4(kNaN, 3000.0), 0);
  EXPECT_EQ(torque_to_n2(kNaN, 10.0), 0);
  for (const double bad_reference : {0.0, -0.0, -3000.0, kNaN, kInf, -kInf}) {
    EXPECT_EQ(speed_to_n2(1500.0, bad_reference), 0) << bad_reference;
    EXPECT_EQ(speed_to_n4(1500.0, bad_reference), 0) << bad_reference;
    EXPECT_EQ(speed_to_n4(-1500.0, bad_reference), 0) << bad_reference;
    EXPECT_EQ(torque_to_n2(5.0, bad_reference), 0) << bad_reference;
    EXPECT_EQ(momred_from_torque_limit(5.0, bad_reference), 0) << bad_reference;
  }
  EXPECT_EQ(kpc_from_kv(kNaN), 0);
  EXPECT_EQ(xerr_from_counts(kNaN), 0);
  EXPECT_EQ(momred_from_reduction_percent(kNaN), 0);
  EXPECT_EQ(momred_from_torque_limit(kNaN, 10.0), 0);
}

// Header contract (normalisation.hpp): "A non-finite value gives 0 (never a random setpoint)".
// Decision T3 (a non-finite value can never become a full-scale setpoint).
TEST(Normalisation, InfiniteValueGivesZero) {
  for (const double v : {kInf, -kInf}) {
    EXPECT_EQ(speed_to_n2(v, 3000.0), 0) << v;
    EXPECT_EQ(speed_to_n4(v, 3000.0), 0) << v;
    EXPECT_EQ(torque_to_n2(v, 10.0), 0) << v;
    EXPECT_EQ(kpc_from_kv(v), 0) << v;
    EXPECT_EQ(xerr_from_counts(v), 0) << v;
  }
}

// spec 06 §8: telegram 750 torques are N2 of the reference torque (TV14/TV15/TV16).
TEST(Normalisation, Torque750) {
  EXPECT_EQ(torque_to_n2(10.0, 10.0), 0x4000);
  EXPECT_EQ(static_cast<std::uint16_t>(torque_to_n2(-10.0, 10.0)), 0xC000);
  EXPECT_EQ(torque_to_n2(2.5, 10.0), 0x1000);
  EXPECT_EQ(static_cast<std::uint16_t>(torque_to_n2(-5.0, 10.0)), 0xE000);
  EXPECT_EQ(torque_to_n2(25.0, 10.0), 32767);  // saturated to int16
  EXPECT_EQ(torque_to_n2(-25.0, 10.0), -32768);
  EXPECT_DOUBLE_EQ(n2_to_torque(-2048, 10.0), -1.25);
  EXPECT_DOUBLE_EQ(n2_to_torque(0x4000, 10.0), 10.0);
}

// spec 06 §9 [OUR CHOICE]: MOMRED = round(16384 * (1 - clamp(T_limit, 0, T_ref) / T_ref)), 0x4000 = 100 %.
TEST(Normalisation, Momred) {
  constexpr double kRef = 10.0;
  EXPECT_EQ(momred_from_torque_limit(10.0, kRef), 0);      // no reduction
  EXPECT_EQ(momred_from_torque_limit(2.5, kRef), 0x3000);  // TV09: 25 % limit = 75 % reduction
  EXPECT_EQ(momred_from_torque_limit(5.0, kRef), 0x2000);
  EXPECT_EQ(momred_from_torque_limit(0.0, kRef), 0x4000);        // full reduction
  EXPECT_EQ(momred_from_torque_limit(25.0, kRef), 0);            // clamped to T_ref
  EXPECT_EQ(momred_from_torque_limit(-3.0, kRef), 0x4000);       // clamped to 0
  EXPECT_EQ(momred_from_torque_limit(10.0 / 3.0, kRef), 10923);  // 10922.67 rounds up

  EXPECT_EQ(momred_from_reduction_percent(0.0), 0);
  EXPECT_EQ(momred_from_reduction_percent(75.0), 0x3000);
  EXPECT_EQ(momred_from_reduction_percent(100.0), 0x4000);
  EXPECT_EQ(momred_from_reduction_percent(150.0), 0x4000);  // clamped to 100 %
  EXPECT_EQ(momred_from_reduction_percent(-5.0), 0);        // clamped to 0 %
  EXPECT_EQ(momred_from_reduction_percent(1.0), 164);       // 163.84 -> 164 ([FESTO] round)

  EXPECT_DOUBLE_EQ(torque_limit_from_momred(0, kRef), 10.0);
  EXPECT_DOUBLE_EQ(torque_limit_from_momred(0x3000, kRef), 2.5);
  EXPECT_DOUBLE_EQ(torque_limit_from_momred(0x4000, kRef), 0.0);
  EXPECT_DOUBLE_EQ(torque_limit_from_momred(0xFFFF, kRef), 0.0);  // beyond 0x4000: not meaningful, 100 %
}

// spec 06 §7 [OUR CHOICE]: KPC = round(Kv * 1000), unit 0.001 1/s, saturated to int32; TV10, TV11.
TEST(Normalisation, Kpc) {
  EXPECT_EQ(kpc_from_kv(500.0), 500000);                 // TV10
  EXPECT_EQ(kpc_from_kv(40.0 * 1000.0 / 60.0), 666667);  // TV11, not the truncated 666666
  EXPECT_EQ(kpc_from_kv(1.0), 1000);                     // value 1000 = 1 1/s
  EXPECT_EQ(kpc_from_kv(0.0), 0);                        // KPC = 0 deactivates DSC
  EXPECT_EQ(kpc_from_kv(666.6664), 666666);
  EXPECT_EQ(kpc_from_kv(2147480.0), 2147480000);  // TO upper limit of Kv (seed L12280)
  EXPECT_EQ(kpc_from_kv(3e6), 2147483647);        // saturated
  EXPECT_EQ(kpc_from_kv(-3e6), -2147483647 - 1);
  EXPECT_DOUBLE_EQ(kv_from_kpc(666667), 666.667);
  EXPECT_DOUBLE_EQ(kv_from_kpc(500000), 500.0);
}

// spec 06 §7: XERR in encoder-1 counts, rounded (half away from zero), saturated to int32; TV10, TV12.
TEST(Normalisation, Xerr) {
  EXPECT_EQ(xerr_from_counts(-1234.0), -1234);
  EXPECT_EQ(static_cast<std::uint32_t>(xerr_from_counts(-1234.0)), 0xFFFFFB2Eu);
  EXPECT_EQ(xerr_from_counts(1.0 / 10.0 * 4194304.0), 419430);  // TV12: 419430.4
  EXPECT_EQ(xerr_from_counts(419430.6), 419431);
  EXPECT_EQ(xerr_from_counts(2.5), 3);
  EXPECT_EQ(xerr_from_counts(-2.5), -3);
  EXPECT_EQ(xerr_from_counts(2147483647.0), 2147483647);
  EXPECT_EQ(xerr_from_counts(2147483647.5), 2147483647);
  EXPECT_EQ(xerr_from_counts(5e9), 2147483647);
  EXPECT_EQ(xerr_from_counts(-2147483648.0), -2147483647 - 1);
  EXPECT_EQ(xerr_from_counts(-5e9), -2147483647 - 1);
}

// Decode then encode of every N2 raw value gives the raw value back (no drift through the physical unit).
// spec 06 §1.2 (N2 = value / reference · 2^14), decision T3 (round half away from zero makes decode → encode
// exact).
TEST(Normalisation, N2DecodeEncodeIsIdentity) {
  for (int raw = -32768; raw <= 32767; ++raw) {
    const auto r = static_cast<std::int16_t>(raw);
    ASSERT_EQ(speed_to_n2(n2_to_speed(r, 3000.0), 3000.0), r) << raw;
  }
}

}  // namespace
}  // namespace tomc::telegrams
