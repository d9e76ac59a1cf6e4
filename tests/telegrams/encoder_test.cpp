// Encoder actual values, spec 06 §6: XIST1 deltas (§6.1), XIST2 content (§6.2), G1_STW requests (§6.3),
// error codes (§6.4), absolute range (§6.2).
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <random>
#include <set>
#include <string>

#include "tomc/telegrams/control_words.hpp"
#include "tomc/telegrams/encoder.hpp"

namespace tomc::telegrams {
namespace {

// spec 06 §11 TV19/TV20 and §6.1.
TEST(Xist1Delta, SpecVectorsAndSimpleCases) {
  EXPECT_EQ(xist1_delta(0xFFFFFF00u, 0x00000100u), 512);   // TV19
  EXPECT_EQ(xist1_delta(0x00000100u, 0xFFFFFF00u), -512);  // TV19 reverse
  EXPECT_EQ(xist1_delta(0xFFF0u, 0x0010u, 16), 32);        // TV20
  EXPECT_EQ(xist1_delta(0x0010u, 0xFFF0u, 16), -32);
  EXPECT_EQ(xist1_delta(0xFFFFFFFFu, 0x00000000u), 1);  // overflow 0xFFFFFFFF -> 0 ([TR])
  EXPECT_EQ(xist1_delta(0x00000000u, 0xFFFFFFFFu), -1);
  EXPECT_EQ(xist1_delta(1000u, 1000u), 0);
  EXPECT_EQ(xist1_delta(0u, 0x7FFFFFFFu), 0x7FFFFFFF);  // largest forward move < 2^31
  EXPECT_EQ(xist1_delta(0x7FFFFFFFu, 0u), -0x7FFFFFFF);
  EXPECT_EQ(xist1_delta(0x0FFFu, 0x0000u, 12), 1);
  EXPECT_EQ(xist1_delta(0x0u, 0x7FFu, 12), 0x7FF);
  EXPECT_EQ(xist1_delta(0x7FFu, 0x0u, 12), -0x7FF);
}

// spec 06 §6.1: d = (new - old) mod 2^W "sign-extended from W bits": a difference of exactly 2^(W-1) has the
// sign bit set and is -2^(W-1) (outside the valid movement range, but defined by the rule).
TEST(Xist1Delta, SignExtensionAtHalfRange) {
  EXPECT_EQ(xist1_delta(0x00000000u, 0x80000000u), -2147483648LL);
  EXPECT_EQ(xist1_delta(0x80000000u, 0x00000000u), -2147483648LL);
  EXPECT_EQ(xist1_delta(0x0000u, 0x8000u, 16), -32768);
  EXPECT_EQ(xist1_delta(0x0u, 0x1u, 1), -1);
  EXPECT_EQ(xist1_delta(0x0u, 0x7FFFu, 16), 32767);
}

// spec 06 §6.1 (BehaviorGx_XIST1 = 0): only the configured width is evaluated; bits above it are ignored.
TEST(Xist1Delta, NarrowWidthIgnoresHigherBits) {
  EXPECT_EQ(xist1_delta(0xABCDFFF0u, 0x12340010u, 16), 32);
  EXPECT_EQ(xist1_delta(0xFFFF0010u, 0x0000FFF0u, 16), -32);
  EXPECT_EQ(xist1_delta(0xFFFFFFFFu, 0x00000001u, 1), 0);  // width 1: only bit 0 counts
  EXPECT_EQ(xist1_delta(0x80000001u, 0x00000001u, 31), 0);
}

// spec 06 §6.1 property: for every width W in 1..32 and every true movement |d| < 2^(W-1), the delta between
// prev and (prev + d) mod 2^W is d. The reference is computed with 64-bit arithmetic.
TEST(Xist1Delta, RandomPropertyAllWidths) {
  std::mt19937_64 rng(0xE1C0DE5u);
  for (int width = 1; width <= 32; ++width) {
    SCOPED_TRACE("width " + std::to_string(width));
    const std::int64_t modulus = std::int64_t{1} << width;
    const std::int64_t half = modulus / 2;
    for (int i = 0; i < 2000; ++i) {
      const std::int64_t prev = static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(modulus));
      // true movement in (-2^(W-1), 2^(W-1)); for W = 1 that is only 0
      const std::int64_t span = 2 * half - 1;
      std::int64_t d = static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(span)) - (half - 1);
      if (i < 4) d = std::array<std::int64_t, 4>{0, half - 1, -(half - 1), (half > 1) ? 1 : 0}[i];
      const std::int64_t current = ((prev + d) % modulus + modulus) % modulus;
      // Random garbage above the width must not matter.
      const std::uint64_t garbage_prev = width < 32 ? (rng() << width) : 0;
      const std::uint64_t garbage_cur = width < 32 ? (rng() << width) : 0;
      const auto p32 = static_cast<std::uint32_t>(static_cast<std::uint64_t>(prev) | garbage_prev);
      const auto c32 = static_cast<std::uint32_t>(static_cast<std::uint64_t>(current) | garbage_cur);
      ASSERT_EQ(xist1_delta(p32, c32, static_cast<std::uint8_t>(width)), d)
          << "prev " << prev << " current " << current;
    }
  }
}

// spec 06 §6.1: 64-bit accumulation of deltas; the first sample only sets the reference.
TEST(IncrementalCount, AccumulatesAcrossWraps) {
  IncrementalCount count;
  EXPECT_EQ(count.update(0xFFFFFF00u), 0);  // first sample: reference only
  EXPECT_EQ(count.counts(), 0);
  EXPECT_EQ(count.update(0x00000100u), 512);
  EXPECT_EQ(count.counts(), 512);
  EXPECT_EQ(count.update(0xFFFFFF00u), -512);
  EXPECT_EQ(count.counts(), 0);
  // Keep moving forward 2^30 per cycle: the 64-bit count passes far beyond 2^32.
  std::uint32_t x = 0xFFFFFF00u;
  for (int i = 0; i < 40; ++i) {
    x += 0x40000000u;
    EXPECT_EQ(count.update(x), 0x40000000);
  }
  EXPECT_EQ(count.counts(), 40LL * 0x40000000LL);
  // And back below zero.
  for (int i = 0; i < 80; ++i) {
    x -= 0x40000000u;
    count.update(x);
  }
  EXPECT_EQ(count.counts(), -40LL * 0x40000000LL);
}

// spec 06 §6.1 and §11 TV20 (16-bit XIST1 wrap: +32), decision T21 (width a parameter); set_counts/restart
// are tomc's own (homing sets the count, an encoder fault takes a new reference).
TEST(IncrementalCount, NarrowWidthSetCountsAndRestart) {
  IncrementalCount count(16);
  count.update(0xFFF0u);
  EXPECT_EQ(count.update(0x0010u), 32);  // TV20 through the accumulator
  EXPECT_EQ(count.counts(), 32);
  count.set_counts(1000);
  EXPECT_EQ(count.counts(), 1000);
  EXPECT_EQ(count.update(0x0020u), 16);
  EXPECT_EQ(count.counts(), 1016);
  count.restart();  // e.g. after an encoder fault: the next sample is a new reference
  EXPECT_EQ(count.update(0x8000u), 0);
  EXPECT_EQ(count.counts(), 1016);
  EXPECT_EQ(count.update(0x8001u), 1);
  EXPECT_EQ(count.counts(), 1017);
}

// spec 06 §6.1: counts_per_rev = StepsPerRevolution * 2^FineResolutionXist1; TV21.
TEST(IncrementalCount, CountsPerRevolutionAndTv21) {
  EXPECT_DOUBLE_EQ(counts_per_revolution(2048, 11), 4194304.0);
  EXPECT_DOUBLE_EQ(counts_per_revolution(1, 0), 1.0);
  EXPECT_DOUBLE_EQ(counts_per_revolution(1u << 20, 31), 2251799813685248.0);
  EXPECT_DOUBLE_EQ(1048576.0 / counts_per_revolution(2048, 11) * 10.0, 2.5);
}

// spec 06 §6.3 / TV23 and the G1_STW bit layout of §3.6.
TEST(EncoderRequest, HandshakeWords) {
  EXPECT_EQ(encoder_request::reference_mark_search(), 0x0011);
  EXPECT_EQ(encoder_request::read_reference_mark(), 0x0021);
  EXPECT_EQ(encoder_request::flying_measurement(), 0x0091);
  EXPECT_EQ(encoder_request::read_measured_value(), 0x00A1);
  EXPECT_EQ(encoder_request::cancel(0x1, false), 0x0031);
  EXPECT_EQ(encoder_request::cancel(0x1, true), 0x00B1);
  EXPECT_EQ(encoder_request::absolute_value(), 0x2000);
  EXPECT_EQ(encoder_request::park(), 0x4000);
  EXPECT_EQ(encoder_request::acknowledge_error(), 0x8000);
  // Other functions (§3.6): mark 2 / probe 1 falling = function 2, probe 2 rising = function 3.
  EXPECT_EQ(encoder_request::reference_mark_search(0x2), 0x0012);
  EXPECT_EQ(encoder_request::flying_measurement(0x4), 0x0094);
  EXPECT_EQ(encoder_request::read_measured_value(0x8), 0x00A8);
  EXPECT_EQ(encoder_request::flying_measurement(0xF), 0x009F);
  // Only bits 0..3 select functions; higher bits of the mask never leak into the command.
  EXPECT_EQ(encoder_request::reference_mark_search(0xF1), 0x0011);
  const EncoderControlWord w{encoder_request::read_measured_value()};
  EXPECT_EQ(w.field(kEncoderCommandField), static_cast<std::uint16_t>(EncoderCommand::kReadValue));
  EXPECT_TRUE(w.test(EncoderControlBit::kMeasurementMode));
  EXPECT_TRUE(w.test(EncoderControlBit::kFunction1));
}

// spec 06 §6.2: every row of the XIST2 content table.
TEST(Xist2Content, EveryCaseOfTheSpecTable) {
  using C = Xist2Content;
  struct Row {
    std::uint16_t g1_stw;
    std::uint16_t g1_zsw;
    Xist2Content content;
    const char* what;
  };
  const Row rows[] = {
      // bit 15: error code, whatever else is set (TV22)
      {0x0000, 0x8000, C::kErrorCode, "encoder error"},
      {0x2000, 0xA000, C::kErrorCode, "error beats absolute value"},
      {0x0021, 0x8010, C::kErrorCode, "error beats value available"},
      // value 1..4 available after "read value" (command 2)
      {0x0021, 0x0010, C::kReferenceMark, "read reference mark 1, value 1 available"},
      {0x0022, 0x0020, C::kReferenceMark, "read reference mark 2, value 2 available"},
      {0x00A1, 0x0110, C::kMeasuredValue, "read measured value, probe 1, value 1 available"},
      {0x00A4, 0x0040, C::kMeasuredValue, "read measured value, function 3"},
      {0x00A8, 0x0080, C::kMeasuredValue, "read measured value, function 4"},
      // a running function with a value available, but no "read value" yet: XIST2 not valid
      {0x0011, 0x0011, C::kNotValid, "search active, value available, command 1"},
      {0x0091, 0x0111, C::kNotValid, "measurement active, command 1"},
      {0x0031, 0x0010, C::kNotValid, "cancel"},
      {0x0021, 0x0001, C::kNotValid, "read requested, no value available yet"},
      // bit 13: absolute value (TV13, TV25)
      {0x2000, 0x2000, C::kAbsoluteValue, "absolute value requested and transmitted"},
      {0x0000, 0x2000, C::kAbsoluteValue, "absolute value transmitted"},
      {0x2000, 0x0000, C::kNotValid, "absolute value requested, not yet acknowledged"},
      // a reference/measured value read interrupts the cyclic absolute value though bit 13 stays set
      {0x2021, 0x2010, C::kReferenceMark, "read value while absolute transmission"},
      {0x20A1, 0x2010, C::kMeasuredValue, "read measured value while absolute transmission"},
      // none of the above
      {0x0000, 0x0000, C::kNotValid, "nothing (TV05)"},
      {0x4000, 0x4000, C::kNotValid, "parking"},
      {0x8000, 0x0800, C::kNotValid, "acknowledge active, no error"},
  };
  for (const auto& row : rows) {
    EXPECT_EQ(xist2_content(EncoderControlWord{row.g1_stw}, EncoderStatusWord{row.g1_zsw}), row.content)
        << row.what << " got "
        << to_string(xist2_content(EncoderControlWord{row.g1_stw}, EncoderStatusWord{row.g1_zsw}));
  }
  EXPECT_EQ(to_string(C::kNotValid), "not valid");
  EXPECT_EQ(to_string(C::kErrorCode), "error code");
  EXPECT_EQ(to_string(C::kReferenceMark), "reference mark");
  EXPECT_EQ(to_string(C::kMeasuredValue), "measured value");
  EXPECT_EQ(to_string(C::kAbsoluteValue), "absolute value");
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// spec 06 §6.4: every code and its meaning; other codes are unknown.
TEST(EncoderErrors, EveryCodeOfTheSpecTable) {
  struct Row {
    std::uint16_t code;
    std::uint16_t constant;
    const char* meaning;  // key phrase of the §6.4 "Meaning" column
  };
  const Row rows[] = {
      {0x0001, kEncoderErrorSensorGroup, "sensor group error"},
      {0x0002, kEncoderErrorZeroMarkMonitoring, "zero-mark monitoring"},
      {0x0003, kEncoderErrorAbortParking, "abort parking sensor"},
      {0x0004, kEncoderErrorAbortReferenceSearch, "abort reference value search"},
      {0x0005, kEncoderErrorAbortReferenceRetrieval, "abort reference value retrieval"},
      {0x0006, kEncoderErrorAbortFlyingMeasurement, "abort measurement on the fly"},
      {0x0007, kEncoderErrorAbortMeasuredValueRetrieval, "abort measured value retrieval"},
      {0x0008, kEncoderErrorAbortAbsoluteValue, "abort absolute value transmission"},
      {0x000A, kEncoderErrorAbortAbsoluteValueAlt, "abort absolute value transmission"},
      {0x0F01, kEncoderErrorCommandNotSupported, "command not supported"},
      {0x0F02, kEncoderErrorMasterSignOfLife, "master sign-of-life"},
      {0x1001, kEncoderErrorManufacturer, "manufacturer-specific"},
  };
  std::set<std::string_view> descriptions;
  for (const auto& row : rows) {
    EXPECT_EQ(row.constant, row.code);
    const std::string_view d = describe_encoder_error(row.code);
    EXPECT_NE(lower(d).find(row.meaning), std::string::npos) << std::hex << row.code << ": " << d;
    EXPECT_NE(d, "unknown encoder error code") << std::hex << row.code;
    descriptions.insert(d);
  }
  EXPECT_EQ(descriptions.size(), 11u);  // 0x0008 and 0x000A share one meaning
  for (const std::uint16_t unknown : {0x0000, 0x0009, 0x000B, 0x0F00, 0x0F03, 0x1000, 0x1002, 0xFFFF}) {
    EXPECT_EQ(describe_encoder_error(unknown), "unknown encoder error code") << std::hex << unknown;
  }
}

// spec 06 §6.4 / [TR]: the 16-bit code is in bits 0..15 of XIST2.
TEST(EncoderErrors, CodeFromLowBitsOfXist2) {
  EXPECT_EQ(encoder_error_code(0x00000001u), 0x0001);
  EXPECT_EQ(encoder_error_code(0xABCD0F02u), 0x0F02);
  EXPECT_EQ(encoder_error_code(0x00011001u), 0x1001);
}

// spec 06 §6.2: absolute range = StepsPerRevolution * 2^FineResolutionXist2 * DeterminableRevolutions.
TEST(EncoderAbsoluteRange, Formula) {
  EXPECT_EQ(absolute_range_counts(2048, 9, 4096), 2048ull * 512ull * 4096ull);  // multi-turn
  EXPECT_EQ(absolute_range_counts(2048, 9, 4096), 4294967296ull);               // beyond 32 bits
  EXPECT_EQ(absolute_range_counts(8192, 0, 1), 8192ull);                        // single-turn
  EXPECT_EQ(absolute_range_counts(2048, 11, 1), 4194304ull);
  EXPECT_EQ(absolute_range_counts(2048, 9, 0), 0ull);  // incremental
  EXPECT_EQ(absolute_range_counts(0xFFFFFFFFu, 31, 1), 0xFFFFFFFFull << 31);
  EXPECT_EQ(absolute_range_counts(1, 31, 0xFFFFFFFFu), 0xFFFFFFFFull << 31);
}

}  // namespace
}  // namespace tomc::telegrams
