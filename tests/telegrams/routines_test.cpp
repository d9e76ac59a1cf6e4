// The telegram-specific codec routines (decision O4) against the generic per-field loop they replace in the
// cycle: for every telegram of spec 06 §2 × direction × byte order (§1.1) × NIST_B offset of telegram 83
// (§2.13), the same bytes out of random values and the same values out of random bytes; and malformed frames
// (every wrong length, the other direction's struct, an empty codec) refused with the same error and nothing
// written.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "test_helpers.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/layout.hpp"

namespace tomc::telegrams {
namespace {

// The signal lists, byte orders and random values of the round-trip tests (test_helpers.hpp).
using namespace test;  // NOLINT(google-build-using-namespace): test helpers only

constexpr std::uint8_t kNistBOffsets[] = {4, 8, 12};  // spec 06 §2.13

std::vector<std::byte> random_frame(std::mt19937& rng, std::size_t size) {
  std::vector<std::byte> frame(size);
  for (auto& b : frame)
    b = static_cast<std::byte>(rng() & 0xFFu);
  return frame;
}

// Own: the value struct of the codec's direction; Other: the other one (refused with kWrongDirection).
// malformed: also every wrong length and the other direction's struct (once per layout is enough: the checks
// are the codec's own, not the routine's).
template <typename Own, typename Other, std::size_t N, std::size_t M>
void same_as_reference(const TelegramCodec& codec, const Signal (&own)[N], const Signal (&other)[M],
                       std::mt19937& rng, bool malformed) {
  for (int iteration = 0; iteration < 16; ++iteration) {
    const Own values = random_values<Own>(rng, own);
    // Encode into a frame of random bytes: the routine writes exactly the bytes the loop writes.
    const auto start = random_frame(rng, codec.frame_size());
    auto fast = start;
    auto reference = start;
    ASSERT_EQ(codec.encode(values, fast), TelegramError::kNone);
    ASSERT_EQ(codec.encode_reference(values, reference), TelegramError::kNone);
    ASSERT_EQ(hex(fast), hex(reference));
    // Decode random bytes over random values: every carried signal read, every other one left as it was.
    const auto frame = random_frame(rng, codec.frame_size());
    const Own sentinel = random_values<Own>(rng, own);
    Own fast_values = sentinel;
    Own reference_values = sentinel;
    ASSERT_EQ(codec.decode(frame, fast_values), TelegramError::kNone);
    ASSERT_EQ(codec.decode_reference(frame, reference_values), TelegramError::kNone);
    ASSERT_EQ(fast_values, reference_values) << hex(frame);
  }
  if (!malformed) return;
  // Every wrong length up to two bytes beyond the longest frame: the same error, nothing written or read.
  for (std::size_t size = 0; size <= kMaxFrameBytes + 2; ++size) {
    if (size == codec.frame_size()) continue;
    const auto start = random_frame(rng, size);
    auto fast = start;
    auto reference = start;
    const Own values = random_values<Own>(rng, own);
    EXPECT_EQ(codec.encode(values, fast), TelegramError::kFrameLengthMismatch) << size;
    EXPECT_EQ(codec.encode_reference(values, reference), TelegramError::kFrameLengthMismatch) << size;
    EXPECT_EQ(fast, start);
    EXPECT_EQ(reference, start);
    Own fast_values = values;
    Own reference_values = values;
    EXPECT_EQ(codec.decode(start, fast_values), TelegramError::kFrameLengthMismatch) << size;
    EXPECT_EQ(codec.decode_reference(start, reference_values), TelegramError::kFrameLengthMismatch) << size;
    EXPECT_EQ(fast_values, values);
    EXPECT_EQ(reference_values, values);
  }
  // The other direction's struct, in a frame of the right length.
  const auto start = random_frame(rng, codec.frame_size());
  auto frame = start;
  const Other wrong = random_values<Other>(rng, other);
  Other wrong_fast = wrong;
  Other wrong_reference = wrong;
  EXPECT_EQ(codec.encode(wrong, frame), TelegramError::kWrongDirection);
  EXPECT_EQ(codec.encode_reference(wrong, frame), TelegramError::kWrongDirection);
  EXPECT_EQ(frame, start);
  EXPECT_EQ(codec.decode(start, wrong_fast), TelegramError::kWrongDirection);
  EXPECT_EQ(codec.decode_reference(start, wrong_reference), TelegramError::kWrongDirection);
  EXPECT_EQ(wrong_fast, wrong);
  EXPECT_EQ(wrong_reference, wrong);
}

void check_codec(const TelegramCodec& codec, std::mt19937& rng, bool malformed) {
  if (codec.direction() == Direction::kSetpoint) {
    same_as_reference<SetpointSignals, ActualSignals>(codec, kSetpointSignals, kActualSignals, rng,
                                                      malformed);
  } else {
    same_as_reference<ActualSignals, SetpointSignals>(codec, kActualSignals, kSetpointSignals, rng,
                                                      malformed);
  }
}

// Table: every (telegram, direction, byte order, NIST_B offset) create() accepts — 13 telegrams × 2 × 4 × 3,
// the offset changing only telegram 83's actual frame — once as created and once from the shared table the
// drive connections use.
// Decision O4 (one unrolled routine per layout × byte order × NIST_B offset, same bytes as the table loop),
// decisions T2 and T6 (the byte orders and offsets).
TEST(TelegramRoutines, SameBytesAndValuesAsTheReferenceLoop) {
  std::mt19937 rng(0x0A23u);  // fixed seed: reproducible
  int codecs = 0;
  for (const std::uint16_t telegram : supported_telegrams()) {
    for (const Direction direction : {Direction::kSetpoint, Direction::kActual}) {
      for (const ByteOrder order : kAllOrders) {
        for (const std::uint8_t nist : kNistBOffsets) {
          SCOPED_TRACE("telegram " + std::to_string(telegram) + " " + std::string(to_string(direction)) +
                       " " + std::string(to_string(order)) + " NIST_B@" + std::to_string(nist));
          const CodecOptions options{.byte_order = order, .telegram83_nist_b_offset = nist};
          const auto created = TelegramCodec::create(telegram, direction, options);
          ASSERT_TRUE(created.ok());
          check_codec(*created, rng, true);
          const auto shared = TelegramCodec::shared(telegram, direction, options);
          ASSERT_TRUE(shared.ok());
          check_codec(**shared, rng, false);
          ++codecs;
        }
      }
    }
  }
  EXPECT_EQ(codecs, 13 * 2 * 4 * 3);
}

// spec 06 §2.13: the three NIST_B offsets give three different actual frames of telegram 83 (the routine is
// chosen by the offset, not by the telegram alone), each equal to the reference.
TEST(TelegramRoutines, Telegram83NistBOffsetSelectsTheRoutine) {
  ActualSignals values;
  values.ZSW2_ENC = Zsw2Enc{0x1234};
  values.G1_ZSW = EncoderStatusWord{0x5678};
  values.G1_XIST1 = 0x11111111u;
  values.G1_XIST2 = 0x22222222u;
  values.NIST_B = 0x33333333;
  const char* expected[] = {
      "12 34 56 78 33 33 33 33 11 11 11 11 22 22 22 22",  // NIST_B at 4
      "12 34 56 78 11 11 11 11 33 33 33 33 22 22 22 22",  // NIST_B at 8
      "12 34 56 78 11 11 11 11 22 22 22 22 33 33 33 33",  // NIST_B at 12 (default)
  };
  for (std::size_t n = 0; n < std::size(kNistBOffsets); ++n) {
    const auto codec = TelegramCodec::create(83, Direction::kActual,
                                             CodecOptions{.telegram83_nist_b_offset = kNistBOffsets[n]});
    ASSERT_TRUE(codec.ok());
    std::vector<std::byte> frame(16);
    ASSERT_EQ(codec->encode(values, frame), TelegramError::kNone);
    EXPECT_EQ(hex(frame), expected[n]);
  }
}

// A codec without a telegram refuses everything on both paths; telegram 104 and an invalid option are
// refused at create(), before any routine is chosen.
// Decision T11 (telegram 104 refused at create()), decision T6 (NIST_B offset only 4, 8 or 12), decision T2
// (the four byte orders), decision O4.
TEST(TelegramRoutines, EmptyCodecAndInvalidConfigurationAreRefused) {
  const TelegramCodec& empty = TelegramCodec::empty();
  std::vector<std::byte> frame(4, std::byte{0x5A});
  SetpointSignals sp;
  ActualSignals ac;
  EXPECT_EQ(empty.encode(sp, frame), TelegramError::kUnknownTelegram);
  EXPECT_EQ(empty.encode_reference(sp, frame), TelegramError::kUnknownTelegram);
  EXPECT_EQ(empty.decode(frame, ac), TelegramError::kUnknownTelegram);
  EXPECT_EQ(empty.decode_reference(frame, ac), TelegramError::kUnknownTelegram);
  EXPECT_EQ(frame, std::vector<std::byte>(4, std::byte{0x5A}));
  EXPECT_EQ(TelegramCodec::create(104, Direction::kSetpoint).error(), TelegramError::kTelegram104NotDefined);
  EXPECT_EQ(
      TelegramCodec::create(83, Direction::kActual, CodecOptions{.telegram83_nist_b_offset = 6}).error(),
      TelegramError::kInvalidOption);
  EXPECT_EQ(
      TelegramCodec::create(3, Direction::kSetpoint, CodecOptions{.byte_order = static_cast<ByteOrder>(4)})
          .error(),
      TelegramError::kInvalidOption);
}

}  // namespace
}  // namespace tomc::telegrams
