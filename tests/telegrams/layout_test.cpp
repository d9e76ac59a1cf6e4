// Telegram layouts against spec 06 §2 (every table) and §2.15 (length summary).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/layout.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams {
namespace {

using enum Signal;
constexpr auto S = Direction::kSetpoint;
constexpr auto A = Direction::kActual;

struct ExpectedField {
  Signal signal;
  int offset;
};

struct ExpectedLayout {
  int telegram;
  Direction direction;
  int words;  // spec 06 §2.15
  int bytes;  // spec 06 §2.15
  std::vector<ExpectedField> fields;
};

std::string label(const ExpectedLayout& e) {
  return "telegram " + std::to_string(e.telegram) + " " + std::string(to_string(e.direction));
}

// Transcribed from the spec 06 §2 tables (W/Off columns); PZD order.
const std::vector<ExpectedLayout>& spec_layouts() {
  static const std::vector<ExpectedLayout> kLayouts = {
      // §2.1 telegram 1, PZD-2/2
      {1, S, 2, 4, {{STW1, 0}, {NSOLL_A, 2}}},
      {1, A, 2, 4, {{ZSW1, 0}, {NIST_A, 2}}},
      // §2.2 telegram 2, PZD-4/4
      {2, S, 4, 8, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}}},
      {2, A, 4, 8, {{ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}}},
      // §2.3 telegram 3, PZD-5/9
      {3, S, 5, 10, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}}},
      {3, A, 9, 18, {{ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}, {G1_ZSW, 8}, {G1_XIST1, 10}, {G1_XIST2, 14}}},
      // §2.4 telegram 4, PZD-6/14
      {4, S, 6, 12, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}, {G2_STW, 10}}},
      {4,
       A,
       14,
       28,
       {{ZSW1, 0},
        {NIST_B, 2},
        {ZSW2, 6},
        {G1_ZSW, 8},
        {G1_XIST1, 10},
        {G1_XIST2, 14},
        {G2_ZSW, 18},
        {G2_XIST1, 20},
        {G2_XIST2, 24}}},
      // §2.5 telegram 5, PZD-9/9
      {5, S, 9, 18, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}, {XERR, 10}, {KPC, 14}}},
      {5, A, 9, 18, {{ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}, {G1_ZSW, 8}, {G1_XIST1, 10}, {G1_XIST2, 14}}},
      // §2.6 telegram 6, PZD-10/14 (actual identical to telegram 4)
      {6, S, 10, 20, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}, {G2_STW, 10}, {XERR, 12}, {KPC, 16}}},
      {6,
       A,
       14,
       28,
       {{ZSW1, 0},
        {NIST_B, 2},
        {ZSW2, 6},
        {G1_ZSW, 8},
        {G1_XIST1, 10},
        {G1_XIST2, 14},
        {G2_ZSW, 18},
        {G2_XIST1, 20},
        {G2_XIST2, 24}}},
      // §2.12 telegram 81, PZD-2/6
      {81, S, 2, 4, {{STW2_ENC, 0}, {G1_STW, 2}}},
      {81, A, 6, 12, {{ZSW2_ENC, 0}, {G1_ZSW, 2}, {G1_XIST1, 4}, {G1_XIST2, 8}}},
      // §2.13 telegram 83, PZD-2/8 (NIST_B default offset 12)
      {83, S, 2, 4, {{STW2_ENC, 0}, {G1_STW, 2}}},
      {83, A, 8, 16, {{ZSW2_ENC, 0}, {G1_ZSW, 2}, {G1_XIST1, 4}, {G1_XIST2, 8}, {NIST_B, 12}}},
      // §2.7 telegram 102, PZD-6/10
      {102, S, 6, 12, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}}},
      {102,
       A,
       10,
       20,
       {{ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}, {MELDW, 8}, {G1_ZSW, 10}, {G1_XIST1, 12}, {G1_XIST2, 16}}},
      // §2.8 telegram 103, PZD-7/15
      {103, S, 7, 14, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}, {G2_STW, 12}}},
      {103,
       A,
       15,
       30,
       {{ZSW1, 0},
        {NIST_B, 2},
        {ZSW2, 6},
        {MELDW, 8},
        {G1_ZSW, 10},
        {G1_XIST1, 12},
        {G1_XIST2, 16},
        {G2_ZSW, 20},
        {G2_XIST1, 22},
        {G2_XIST2, 26}}},
      // §2.10 telegram 105, PZD-10/10
      {105,
       S,
       10,
       20,
       {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}, {XERR, 12}, {KPC, 16}}},
      {105,
       A,
       10,
       20,
       {{ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}, {MELDW, 8}, {G1_ZSW, 10}, {G1_XIST1, 12}, {G1_XIST2, 16}}},
      // §2.11 telegram 106, PZD-11/15 (actual identical to telegram 103)
      {106,
       S,
       11,
       22,
       {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}, {G2_STW, 12}, {XERR, 14}, {KPC, 18}}},
      {106,
       A,
       15,
       30,
       {{ZSW1, 0},
        {NIST_B, 2},
        {ZSW2, 6},
        {MELDW, 8},
        {G1_ZSW, 10},
        {G1_XIST1, 12},
        {G1_XIST2, 16},
        {G2_ZSW, 20},
        {G2_XIST1, 22},
        {G2_XIST2, 26}}},
      // §2.14 telegram 750, PZD-3/1
      {750, S, 3, 6, {{M_ADD1, 0}, {M_LIMIT_POS, 2}, {M_LIMIT_NEG, 4}}},
      {750, A, 1, 2, {{M_ACT, 0}}},
  };
  return kLayouts;
}

const Signal kAllSignals[] = {STW1,     NSOLL_A,  NSOLL_B,  STW2,     G1_STW,      G2_STW,      XERR,
                              KPC,      MOMRED,   STW2_ENC, M_ADD1,   M_LIMIT_POS, M_LIMIT_NEG, ZSW1,
                              NIST_A,   NIST_B,   ZSW2,     G1_ZSW,   G1_XIST1,    G1_XIST2,    G2_ZSW,
                              G2_XIST1, G2_XIST2, MELDW,    ZSW2_ENC, M_ACT};

// spec 06 §2.1–§2.14: every signal at the offset of the tables, in PZD order, and nothing else.
TEST(Layout, EveryTelegramAndDirectionMatchesSpecTables) {
  for (const auto& e : spec_layouts()) {
    SCOPED_TRACE(label(e));
    const auto layout = find_layout(e.telegram, e.direction);
    ASSERT_TRUE(layout.ok()) << describe(layout.error());
    EXPECT_EQ(layout->telegram, e.telegram);
    EXPECT_EQ(layout->direction, e.direction);
    ASSERT_EQ(layout->fields().size(), e.fields.size());
    for (std::size_t i = 0; i < e.fields.size(); ++i) {
      EXPECT_EQ(layout->fields()[i].signal, e.fields[i].signal) << "field " << i;
      EXPECT_EQ(layout->fields()[i].offset, e.fields[i].offset) << name(e.fields[i].signal);
      EXPECT_EQ(layout->offset_of(e.fields[i].signal), e.fields[i].offset) << name(e.fields[i].signal);
      EXPECT_TRUE(layout->carries(e.fields[i].signal)) << name(e.fields[i].signal);
    }
    for (const Signal s : kAllSignals) {
      const bool listed = std::any_of(e.fields.begin(), e.fields.end(),
                                      [&](const ExpectedField& f) { return f.signal == s; });
      if (!listed) {
        EXPECT_FALSE(layout->carries(s)) << name(s);
        EXPECT_EQ(layout->offset_of(s), -1) << name(s);
      }
    }
  }
}

// spec 06 §2.15: setpoint/actual words and bytes; the signals fill each frame without gap (the §2 tables
// list a signal in every PZD).
TEST(Layout, LengthsMatchSpecSummaryAndFieldsFillTheFrame) {
  for (const auto& e : spec_layouts()) {
    SCOPED_TRACE(label(e));
    const auto layout = find_layout(e.telegram, e.direction);
    ASSERT_TRUE(layout.ok());
    EXPECT_EQ(layout->length, e.bytes);
    EXPECT_EQ(e.words * 2, e.bytes);
    int covered = 0;
    int next_offset = 0;
    for (const auto& f : layout->fields()) {
      EXPECT_EQ(f.offset, next_offset) << name(f.signal);
      const int size = info(f.signal).bits / 8;
      next_offset = f.offset + size;
      covered += size;
    }
    EXPECT_EQ(covered, e.bytes);

    const auto codec = TelegramCodec::create(e.telegram, e.direction);
    ASSERT_TRUE(codec.ok());
    EXPECT_EQ(codec->frame_size(), static_cast<std::size_t>(e.bytes));
    EXPECT_EQ(codec->telegram(), e.telegram);
    EXPECT_EQ(codec->direction(), e.direction);
    EXPECT_EQ(codec->byte_order(), ByteOrder::kBig);  // spec 06 §1.1 default
  }
}

// spec 06 §2.15: the largest frame is 30 bytes (103/106 actual).
TEST(Layout, MaxFrameBytesIs30) {
  EXPECT_EQ(kMaxFrameBytes, 30u);
}

// spec 06 §2: the supported set; §2.15 rows.
TEST(Layout, SupportedTelegramsAreExactlyTheSpecList) {
  const std::vector<std::uint16_t> expected = {1, 2, 3, 4, 5, 6, 81, 83, 102, 103, 105, 106, 750};
  const auto supported = supported_telegrams();
  EXPECT_EQ(std::vector<std::uint16_t>(supported.begin(), supported.end()), expected);
  for (const int t : {1, 2, 3, 4, 5, 6, 102, 103, 105, 106}) {
    EXPECT_TRUE(is_drive_telegram(t)) << t;
    EXPECT_FALSE(is_encoder_telegram(t)) << t;
    EXPECT_FALSE(is_supplementary_telegram(t)) << t;
  }
  for (const int t : {81, 83}) {
    EXPECT_FALSE(is_drive_telegram(t)) << t;
    EXPECT_TRUE(is_encoder_telegram(t)) << t;
    EXPECT_FALSE(is_supplementary_telegram(t)) << t;
  }
  EXPECT_FALSE(is_drive_telegram(750));
  EXPECT_FALSE(is_encoder_telegram(750));
  EXPECT_TRUE(is_supplementary_telegram(750));
  for (const int t : {0, 7, 20, 82, 104, 107, 111, 749}) {
    EXPECT_FALSE(is_drive_telegram(t) || is_encoder_telegram(t) || is_supplementary_telegram(t)) << t;
  }
}

// spec 06 §2.9 and §10.10: telegram 104 is rejected at configuration time with its own error.
TEST(Layout, Telegram104IsRejected) {
  for (const Direction d : {S, A}) {
    const auto layout = find_layout(104, d);
    EXPECT_FALSE(layout.ok());
    EXPECT_EQ(layout.error(), TelegramError::kTelegram104NotDefined);
    const auto codec = TelegramCodec::create(104, d);
    EXPECT_FALSE(codec.ok());
    EXPECT_EQ(codec.error(), TelegramError::kTelegram104NotDefined);
  }
}

// spec 06 §2: anything not in the supported list is unknown.
TEST(Layout, UnknownTelegramsAreRejected) {
  for (const int t : {-1, 0, 7, 8, 9, 20, 80, 82, 84, 101, 107, 110, 111, 390, 391, 749, 751, 65536 + 1}) {
    for (const Direction d : {S, A}) {
      const auto layout = find_layout(t, d);
      EXPECT_EQ(layout.error(), TelegramError::kUnknownTelegram) << t;
      const auto codec = TelegramCodec::create(t, d);
      EXPECT_EQ(codec.error(), TelegramError::kUnknownTelegram) << t;
    }
  }
}

// spec 06 §2.13: NIST_B offset of telegram 83 configurable (default 12); XIST1 and XIST2 keep their order in
// the other two 32-bit slots.
TEST(Layout, Telegram83NistBOffsetOption) {
  struct Row {
    std::uint8_t nist_b;
    int xist1;
    int xist2;
  };
  for (const Row row : {Row{4, 8, 12}, Row{8, 4, 12}, Row{12, 4, 8}}) {
    SCOPED_TRACE("NIST_B offset " + std::to_string(row.nist_b));
    const auto codec = TelegramCodec::create(83, A, CodecOptions{.telegram83_nist_b_offset = row.nist_b});
    ASSERT_TRUE(codec.ok()) << describe(codec.error());
    EXPECT_EQ(codec->frame_size(), 16u);
    EXPECT_EQ(codec->layout().offset_of(ZSW2_ENC), 0);
    EXPECT_EQ(codec->layout().offset_of(G1_ZSW), 2);
    EXPECT_EQ(codec->layout().offset_of(NIST_B), row.nist_b);
    EXPECT_EQ(codec->layout().offset_of(G1_XIST1), row.xist1);
    EXPECT_EQ(codec->layout().offset_of(G1_XIST2), row.xist2);

    // The decode follows the moved offsets.
    std::vector<std::byte> frame(16, std::byte{0});
    frame[static_cast<std::size_t>(row.nist_b)] = std::byte{0x11};
    frame[static_cast<std::size_t>(row.xist1)] = std::byte{0x22};
    frame[static_cast<std::size_t>(row.xist2)] = std::byte{0x33};
    ActualSignals a;
    ASSERT_EQ(codec->decode(frame, a), TelegramError::kNone);
    EXPECT_EQ(a.NIST_B, 0x11000000);
    EXPECT_EQ(a.G1_XIST1, 0x22000000u);
    EXPECT_EQ(a.G1_XIST2, 0x33000000u);
  }
  EXPECT_EQ(CodecOptions{}.telegram83_nist_b_offset, 12);
  for (const std::uint8_t bad : {0, 1, 2, 3, 5, 6, 10, 14, 16, 255}) {
    const auto codec = TelegramCodec::create(83, A, CodecOptions{.telegram83_nist_b_offset = bad});
    EXPECT_FALSE(codec.ok()) << int{bad};
    EXPECT_EQ(codec.error(), TelegramError::kInvalidOption) << int{bad};
  }
}

// spec 06 §0.1 and §1.2: data types and widths of every signal.
TEST(Layout, SignalInfoMatchesSpecDataTypes) {
  struct Row {
    Signal signal;
    const char* name;
    Direction direction;
    int bits;
    SignalKind kind;
  };
  const Row rows[] = {
      {STW1, "STW1", S, 16, SignalKind::kWord},
      {NSOLL_A, "NSOLL_A", S, 16, SignalKind::kNormalised},  // N2
      {NSOLL_B, "NSOLL_B", S, 32, SignalKind::kNormalised},  // N4
      {STW2, "STW2", S, 16, SignalKind::kWord},
      {G1_STW, "G1_STW", S, 16, SignalKind::kWord},
      {G2_STW, "G2_STW", S, 16, SignalKind::kWord},
      {XERR, "XERR", S, 32, SignalKind::kSigned},        // I32
      {KPC, "KPC", S, 32, SignalKind::kSigned},          // I32
      {MOMRED, "MOMRED", S, 16, SignalKind::kUnsigned},  // U16
      {STW2_ENC, "STW2_ENC", S, 16, SignalKind::kWord},
      {M_ADD1, "M_ADD1", S, 16, SignalKind::kNormalised},  // N2
      {M_LIMIT_POS, "M_LIMIT_POS", S, 16, SignalKind::kNormalised},
      {M_LIMIT_NEG, "M_LIMIT_NEG", S, 16, SignalKind::kNormalised},
      {ZSW1, "ZSW1", A, 16, SignalKind::kWord},
      {NIST_A, "NIST_A", A, 16, SignalKind::kNormalised},
      {NIST_B, "NIST_B", A, 32, SignalKind::kNormalised},
      {ZSW2, "ZSW2", A, 16, SignalKind::kWord},
      {G1_ZSW, "G1_ZSW", A, 16, SignalKind::kWord},
      {G1_XIST1, "G1_XIST1", A, 32, SignalKind::kUnsigned},  // U32
      {G1_XIST2, "G1_XIST2", A, 32, SignalKind::kUnsigned},
      {G2_ZSW, "G2_ZSW", A, 16, SignalKind::kWord},
      {G2_XIST1, "G2_XIST1", A, 32, SignalKind::kUnsigned},
      {G2_XIST2, "G2_XIST2", A, 32, SignalKind::kUnsigned},
      {MELDW, "MELDW", A, 16, SignalKind::kWord},
      {ZSW2_ENC, "ZSW2_ENC", A, 16, SignalKind::kWord},
      {M_ACT, "M_ACT", A, 16, SignalKind::kNormalised},
  };
  ASSERT_EQ(std::size(rows), kSignalCount);
  for (const auto& row : rows) {
    const auto& i = info(row.signal);
    EXPECT_EQ(i.signal, row.signal) << row.name;
    EXPECT_EQ(i.name, row.name);
    EXPECT_EQ(i.direction, row.direction) << row.name;
    EXPECT_EQ(i.bits, row.bits) << row.name;
    EXPECT_EQ(i.kind, row.kind) << row.name;
    EXPECT_EQ(parse_signal(row.name), row.signal) << row.name;
  }
  EXPECT_EQ(parse_signal("M_ADD"), M_ADD1);
  EXPECT_FALSE(parse_signal("stw1").has_value());
  EXPECT_FALSE(parse_signal("STW3").has_value());
}

// spec 06 §1.2: raw ranges (N2 0x8000..0x7FFF, N4 0x80000000..0x7FFFFFFF, U16/U32 unsigned).
TEST(Layout, RawRanges) {
  EXPECT_EQ(raw_minimum(NSOLL_A), -32768);
  EXPECT_EQ(raw_maximum(NSOLL_A), 32767);
  EXPECT_EQ(raw_minimum(NIST_B), -2147483648LL);
  EXPECT_EQ(raw_maximum(NIST_B), 2147483647LL);
  EXPECT_EQ(raw_minimum(XERR), -2147483648LL);
  EXPECT_EQ(raw_maximum(KPC), 2147483647LL);
  EXPECT_EQ(raw_minimum(MOMRED), 0);
  EXPECT_EQ(raw_maximum(MOMRED), 65535);
  EXPECT_EQ(raw_minimum(G1_XIST1), 0);
  EXPECT_EQ(raw_maximum(G1_XIST1), 4294967295LL);
  EXPECT_EQ(raw_minimum(STW1), 0);
  EXPECT_EQ(raw_maximum(ZSW1), 65535);
  EXPECT_EQ(raw_minimum(M_LIMIT_NEG), -32768);
  EXPECT_EQ(raw_maximum(M_ACT), 32767);
}

}  // namespace
}  // namespace tomc::telegrams
