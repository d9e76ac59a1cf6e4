// Codec round trips for every telegram, both directions and all byte orders (spec 06 §1.1, §2), and the
// codec's error returns.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "test_helpers.hpp"
#include "tomc/telegrams/byte_order.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/layout.hpp"

namespace tomc::telegrams {
namespace {

using test::hex;
using test::kActualSignals;
using test::kAllOrders;
using test::kSetpointSignals;
using test::random_values;

std::string trace(int telegram, Direction d, ByteOrder o) {
  return "telegram " + std::to_string(telegram) + " " + std::string(to_string(d)) + " " +
         std::string(to_string(o));
}

template <typename Values, std::size_t N>
void round_trip(int telegram, Direction direction, const Signal (&signals)[N], std::mt19937& rng) {
  for (const ByteOrder order : kAllOrders) {
    SCOPED_TRACE(trace(telegram, direction, order));
    const auto codec = TelegramCodec::create(telegram, direction, CodecOptions{.byte_order = order});
    ASSERT_TRUE(codec.ok());
    EXPECT_EQ(codec->byte_order(), order);
    for (int iteration = 0; iteration < 200; ++iteration) {
      const auto source = random_values<Values>(rng, signals);
      const auto sentinel = random_values<Values>(rng, signals);
      std::vector<std::byte> frame(codec->frame_size());
      ASSERT_EQ(codec->encode(source, frame), TelegramError::kNone);
      Values decoded = sentinel;
      ASSERT_EQ(codec->decode(frame, decoded), TelegramError::kNone);
      for (const Signal s : signals) {
        if (codec->carries(s)) {
          ASSERT_EQ(decoded.raw(s), source.raw(s)) << name(s);
        } else {
          ASSERT_EQ(decoded.raw(s), sentinel.raw(s)) << name(s) << " is not carried and must stay untouched";
        }
      }
      // Encoding the decoded values gives the same bytes again.
      std::vector<std::byte> again(codec->frame_size());
      ASSERT_EQ(codec->encode(decoded, again), TelegramError::kNone);
      ASSERT_EQ(again, frame);
    }
  }
}

// spec 06 §2 (all telegrams) × §1.1 (all byte orders): encode then decode returns exactly the carried
// signals.
TEST(RoundTrip, EveryTelegramBothDirectionsAllByteOrders) {
  std::mt19937 rng(0x5EED0106u);  // fixed seed: reproducible
  for (const std::uint16_t telegram : supported_telegrams()) {
    round_trip<SetpointSignals>(telegram, Direction::kSetpoint, kSetpointSignals, rng);
    round_trip<ActualSignals>(telegram, Direction::kActual, kActualSignals, rng);
  }
}

// spec 06 §2.13: telegram 83 with each NIST_B offset, all byte orders.
TEST(RoundTrip, Telegram83AllNistBOffsets) {
  std::mt19937 rng(83u);
  for (const std::uint8_t offset : {4, 8, 12}) {
    for (const ByteOrder order : kAllOrders) {
      SCOPED_TRACE(trace(83, Direction::kActual, order) + " NIST_B@" + std::to_string(offset));
      const auto codec = TelegramCodec::create(
          83, Direction::kActual, CodecOptions{.byte_order = order, .telegram83_nist_b_offset = offset});
      ASSERT_TRUE(codec.ok());
      for (int i = 0; i < 50; ++i) {
        const auto source = random_values<ActualSignals>(rng, kActualSignals);
        std::vector<std::byte> frame(16);
        ASSERT_EQ(codec->encode(source, frame), TelegramError::kNone);
        ActualSignals decoded;
        ASSERT_EQ(codec->decode(frame, decoded), TelegramError::kNone);
        EXPECT_EQ(decoded.NIST_B, source.NIST_B);
        EXPECT_EQ(decoded.G1_XIST1, source.G1_XIST1);
        EXPECT_EQ(decoded.G1_XIST2, source.G1_XIST2);
        EXPECT_EQ(decoded.G1_ZSW, source.G1_ZSW);
        EXPECT_EQ(decoded.ZSW2_ENC, source.ZSW2_ENC);
      }
    }
  }
}

// spec 06 §1.1: explicit byte patterns of each order for one 16-bit and one 32-bit signal (telegram 2
// setpoint: STW1 at 0, NSOLL_B at 2, STW2 at 6).
TEST(RoundTrip, ExplicitBytePatternsPerOrder) {
  struct Row {
    ByteOrder order;
    const char* bytes;
  };
  const Row rows[] = {
      {ByteOrder::kBig, "04 7F 12 34 56 78 A1 B2"},           // high word first, high byte first
      {ByteOrder::kLittleBytes, "7F 04 34 12 78 56 B2 A1"},   // each word low byte first, high word first
      {ByteOrder::kSwappedWords, "04 7F 56 78 12 34 A1 B2"},  // low word first, each word high byte first
      {ByteOrder::kLittle, "7F 04 78 56 34 12 B2 A1"},        // fully little-endian
  };
  SetpointSignals s;
  s.STW1 = Stw1{0x047F};
  s.NSOLL_B = 0x12345678;
  s.STW2 = Stw2{0xA1B2};
  for (const auto& row : rows) {
    SCOPED_TRACE(std::string(to_string(row.order)));
    const auto codec = TelegramCodec::create(2, Direction::kSetpoint, CodecOptions{.byte_order = row.order});
    ASSERT_TRUE(codec.ok());
    std::vector<std::byte> frame(8);
    ASSERT_EQ(codec->encode(s, frame), TelegramError::kNone);
    EXPECT_EQ(hex(frame), row.bytes);
    SetpointSignals back;
    ASSERT_EQ(codec->decode(frame, back), TelegramError::kNone);
    EXPECT_EQ(back.STW1.value(), 0x047F);
    EXPECT_EQ(back.NSOLL_B, 0x12345678);
    EXPECT_EQ(back.STW2.value(), 0xA1B2);
  }
}

// spec 06 §1.1: the low-level word helpers.
TEST(RoundTrip, WordHelpers) {
  std::byte buf[4] = {};
  write_word(buf, 0xBEEF, ByteOrder::kBig);
  EXPECT_EQ(hex(std::span<const std::byte>(buf, 2)), "BE EF");
  EXPECT_EQ(read_word(buf, ByteOrder::kBig), 0xBEEF);
  EXPECT_EQ(read_word(buf, ByteOrder::kLittleBytes), 0xEFBE);
  write_double_word(buf, 0xDEADBEEFu, ByteOrder::kSwappedWords);
  EXPECT_EQ(hex(std::span<const std::byte>(buf, 4)), "BE EF DE AD");
  EXPECT_EQ(read_double_word(buf, ByteOrder::kSwappedWords), 0xDEADBEEFu);
  EXPECT_EQ(read_double_word(buf, ByteOrder::kBig), 0xBEEFDEADu);
}

// spec 06 §1.1: the per-connection configuration names.
TEST(RoundTrip, ByteOrderNames) {
  EXPECT_EQ(parse_byte_order("big"), ByteOrder::kBig);
  EXPECT_EQ(parse_byte_order("little-bytes"), ByteOrder::kLittleBytes);
  EXPECT_EQ(parse_byte_order("swapped-words"), ByteOrder::kSwappedWords);
  EXPECT_EQ(parse_byte_order("little"), ByteOrder::kLittle);
  EXPECT_FALSE(parse_byte_order("Big").has_value());
  EXPECT_FALSE(parse_byte_order("").has_value());
  for (const ByteOrder o : kAllOrders)
    EXPECT_EQ(parse_byte_order(to_string(o)), o);
}

// A frame of the wrong length is refused and nothing is read or written.
// spec 06 §2.15 (the length of each telegram and direction).
TEST(CodecErrors, WrongFrameLength) {
  for (const std::uint16_t telegram : supported_telegrams()) {
    SCOPED_TRACE("telegram " + std::to_string(telegram));
    const auto sp = TelegramCodec::create(telegram, Direction::kSetpoint);
    const auto ac = TelegramCodec::create(telegram, Direction::kActual);
    ASSERT_TRUE(sp.ok());
    ASSERT_TRUE(ac.ok());
    for (const std::size_t size : {std::size_t{0}, sp->frame_size() - 1, sp->frame_size() + 1}) {
      std::vector<std::byte> frame(size, std::byte{0x5A});
      SetpointSignals values;
      values.STW1 = Stw1{0x1234};
      values.M_ADD1 = 7;
      EXPECT_EQ(sp->encode(values, frame), TelegramError::kFrameLengthMismatch) << size;
      EXPECT_EQ(frame, std::vector<std::byte>(size, std::byte{0x5A}));
      const SetpointSignals before = values;
      EXPECT_EQ(sp->decode(frame, values), TelegramError::kFrameLengthMismatch) << size;
      EXPECT_EQ(values, before);
    }
    for (const std::size_t size : {std::size_t{0}, ac->frame_size() - 1, ac->frame_size() + 1}) {
      std::vector<std::byte> frame(size, std::byte{0x5A});
      ActualSignals values;
      values.ZSW1 = Zsw1{0x0237};
      values.M_ACT = -3;
      EXPECT_EQ(ac->encode(values, frame), TelegramError::kFrameLengthMismatch) << size;
      EXPECT_EQ(frame, std::vector<std::byte>(size, std::byte{0x5A}));
      const ActualSignals before = values;
      EXPECT_EQ(ac->decode(frame, values), TelegramError::kFrameLengthMismatch) << size;
      EXPECT_EQ(values, before);
    }
  }
}

// Values of the other direction are refused (setpoint struct with an actual codec and vice versa).
// spec 06 §2 (each telegram's setpoint and actual layouts are distinct).
TEST(CodecErrors, WrongDirection) {
  for (const std::uint16_t telegram : supported_telegrams()) {
    SCOPED_TRACE("telegram " + std::to_string(telegram));
    const auto sp = TelegramCodec::create(telegram, Direction::kSetpoint);
    const auto ac = TelegramCodec::create(telegram, Direction::kActual);
    ASSERT_TRUE(sp.ok());
    ASSERT_TRUE(ac.ok());
    {
      std::vector<std::byte> frame(sp->frame_size(), std::byte{0x5A});
      ActualSignals values;
      values.ZSW1 = Zsw1{0x0237};
      const ActualSignals before = values;
      EXPECT_EQ(sp->encode(values, frame), TelegramError::kWrongDirection);
      EXPECT_EQ(sp->decode(frame, values), TelegramError::kWrongDirection);
      EXPECT_EQ(values, before);
      EXPECT_EQ(frame, std::vector<std::byte>(sp->frame_size(), std::byte{0x5A}));
    }
    {
      std::vector<std::byte> frame(ac->frame_size(), std::byte{0x5A});
      SetpointSignals values;
      values.STW1 = Stw1{0x047F};
      const SetpointSignals before = values;
      EXPECT_EQ(ac->encode(values, frame), TelegramError::kWrongDirection);
      EXPECT_EQ(ac->decode(frame, values), TelegramError::kWrongDirection);
      EXPECT_EQ(values, before);
      EXPECT_EQ(frame, std::vector<std::byte>(ac->frame_size(), std::byte{0x5A}));
    }
  }
}

// A default-constructed codec is empty and refuses everything.
// Project decision P2 (errors are values, Result<T>: a codec without a telegram answers kUnknownTelegram,
// never writes).
TEST(CodecErrors, EmptyCodec) {
  const TelegramCodec codec;
  EXPECT_EQ(codec.frame_size(), 0u);
  std::vector<std::byte> frame;
  SetpointSignals s;
  ActualSignals a;
  EXPECT_EQ(codec.encode(s, frame), TelegramError::kUnknownTelegram);
  EXPECT_EQ(codec.decode(frame, s), TelegramError::kUnknownTelegram);
  EXPECT_EQ(codec.encode(a, frame), TelegramError::kUnknownTelegram);
  EXPECT_EQ(codec.decode(frame, a), TelegramError::kUnknownTelegram);
}

// The shared codec table (decision U1) answers every input create() accepts with a codec that encodes the
// same bytes, one address per distinct codec, and create()'s error for every input it rejects.
TEST(SharedCodec, SameFramesAsCreateForEveryTelegramOrderAndNistBOffset) {
  std::mt19937 rng(0x5A4EDu);
  for (const std::uint16_t telegram : supported_telegrams()) {
    for (const ByteOrder order : kAllOrders) {
      for (const std::uint8_t nist : {4, 8, 12}) {
        const CodecOptions options{.byte_order = order, .telegram83_nist_b_offset = nist};
        SCOPED_TRACE(trace(telegram, Direction::kActual, order) + " NIST_B@" + std::to_string(nist));
        const auto own_sp = TelegramCodec::create(telegram, Direction::kSetpoint, options);
        const auto own_act = TelegramCodec::create(telegram, Direction::kActual, options);
        const auto shared_sp = TelegramCodec::shared(telegram, Direction::kSetpoint, options);
        const auto shared_act = TelegramCodec::shared(telegram, Direction::kActual, options);
        ASSERT_TRUE(own_sp.ok() && own_act.ok() && shared_sp.ok() && shared_act.ok());
        EXPECT_EQ(shared_sp.value(), TelegramCodec::shared(telegram, Direction::kSetpoint, options).value());
        ASSERT_EQ((*shared_sp)->frame_size(), own_sp->frame_size());
        ASSERT_EQ((*shared_act)->frame_size(), own_act->frame_size());
        EXPECT_EQ((*shared_act)->byte_order(), order);
        const auto sp = random_values<SetpointSignals>(rng, kSetpointSignals);
        const auto act = random_values<ActualSignals>(rng, kActualSignals);
        std::vector<std::byte> a(own_sp->frame_size()), b(a.size()), c(own_act->frame_size()), d(c.size());
        ASSERT_EQ(own_sp->encode(sp, a), TelegramError::kNone);
        ASSERT_EQ((*shared_sp)->encode(sp, b), TelegramError::kNone);
        EXPECT_EQ(a, b);
        ASSERT_EQ(own_act->encode(act, c), TelegramError::kNone);
        ASSERT_EQ((*shared_act)->encode(act, d), TelegramError::kNone);
        EXPECT_EQ(c, d);
      }
    }
  }
  // Telegram 83's three NIST_B layouts are three codecs.
  const auto at4 = TelegramCodec::shared(83, Direction::kActual, CodecOptions{.telegram83_nist_b_offset = 4});
  const auto at12 =
      TelegramCodec::shared(83, Direction::kActual, CodecOptions{.telegram83_nist_b_offset = 12});
  ASSERT_TRUE(at4.ok() && at12.ok());
  EXPECT_NE(at4.value(), at12.value());
  EXPECT_EQ((*at4)->layout().offset_of(Signal::NIST_B), 4);
  EXPECT_EQ((*at12)->layout().offset_of(Signal::NIST_B), 12);
}

// spec 06 §2.9 (telegram 104 not defined); §2 (the supported telegrams).
TEST(SharedCodec, RejectsWhatCreateRejects) {
  EXPECT_EQ(TelegramCodec::shared(104, Direction::kSetpoint).error(), TelegramError::kTelegram104NotDefined);
  EXPECT_EQ(TelegramCodec::shared(7, Direction::kActual).error(), TelegramError::kUnknownTelegram);
  EXPECT_EQ(
      TelegramCodec::shared(83, Direction::kActual, CodecOptions{.telegram83_nist_b_offset = 6}).error(),
      TelegramCodec::create(83, Direction::kActual, CodecOptions{.telegram83_nist_b_offset = 6}).error());
  EXPECT_EQ(
      TelegramCodec::shared(3, Direction::kSetpoint, CodecOptions{.byte_order = static_cast<ByteOrder>(9)})
          .error(),
      TelegramError::kInvalidOption);
  EXPECT_EQ(TelegramCodec::empty().frame_size(), 0u);
}

// Every error has its own description (for messages).
// Decision T11 (each refusal has its own error so the message says why); the texts themselves are tomc's own.
TEST(CodecErrors, Descriptions) {
  EXPECT_EQ(describe(TelegramError::kNone), "no error");
  const TelegramError all[] = {TelegramError::kNone,
                               TelegramError::kUnknownTelegram,
                               TelegramError::kTelegram104NotDefined,
                               TelegramError::kFrameLengthMismatch,
                               TelegramError::kWrongDirection,
                               TelegramError::kInvalidOption};
  for (const auto a : all) {
    for (const auto b : all) {
      if (a != b) {
        EXPECT_NE(describe(a), describe(b));
      }
    }
  }
}

}  // namespace
}  // namespace tomc::telegrams
