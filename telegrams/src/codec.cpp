// Table-driven frame codec: at create() the layout is resolved into (frame offset, value offset, width)
// triples; encode/decode then move each signal between the value struct and the bytes.
#include "tomc/telegrams/codec.hpp"

#include <cstddef>
#include <cstring>

namespace tomc::telegrams {
namespace {

// Where each signal lives in its value struct. Both structs are standard-layout (Word<> has one uint16_t).
constexpr std::uint8_t value_offset(Signal s) noexcept {
  switch (s) {
    case Signal::STW1:
      return offsetof(SetpointSignals, STW1);
    case Signal::NSOLL_A:
      return offsetof(SetpointSignals, NSOLL_A);
    case Signal::NSOLL_B:
      return offsetof(SetpointSignals, NSOLL_B);
    case Signal::STW2:
      return offsetof(SetpointSignals, STW2);
    case Signal::G1_STW:
      return offsetof(SetpointSignals, G1_STW);
    case Signal::G2_STW:
      return offsetof(SetpointSignals, G2_STW);
    case Signal::XERR:
      return offsetof(SetpointSignals, XERR);
    case Signal::KPC:
      return offsetof(SetpointSignals, KPC);
    case Signal::MOMRED:
      return offsetof(SetpointSignals, MOMRED);
    case Signal::STW2_ENC:
      return offsetof(SetpointSignals, STW2_ENC);
    case Signal::M_ADD1:
      return offsetof(SetpointSignals, M_ADD1);
    case Signal::M_LIMIT_POS:
      return offsetof(SetpointSignals, M_LIMIT_POS);
    case Signal::M_LIMIT_NEG:
      return offsetof(SetpointSignals, M_LIMIT_NEG);
    case Signal::ZSW1:
      return offsetof(ActualSignals, ZSW1);
    case Signal::NIST_A:
      return offsetof(ActualSignals, NIST_A);
    case Signal::NIST_B:
      return offsetof(ActualSignals, NIST_B);
    case Signal::ZSW2:
      return offsetof(ActualSignals, ZSW2);
    case Signal::G1_ZSW:
      return offsetof(ActualSignals, G1_ZSW);
    case Signal::G1_XIST1:
      return offsetof(ActualSignals, G1_XIST1);
    case Signal::G1_XIST2:
      return offsetof(ActualSignals, G1_XIST2);
    case Signal::G2_ZSW:
      return offsetof(ActualSignals, G2_ZSW);
    case Signal::G2_XIST1:
      return offsetof(ActualSignals, G2_XIST1);
    case Signal::G2_XIST2:
      return offsetof(ActualSignals, G2_XIST2);
    case Signal::MELDW:
      return offsetof(ActualSignals, MELDW);
    case Signal::ZSW2_ENC:
      return offsetof(ActualSignals, ZSW2_ENC);
    case Signal::M_ACT:
      return offsetof(ActualSignals, M_ACT);
  }
  return 0;
}

static_assert(sizeof(Stw1) == 2 && sizeof(EncoderStatusWord) == 2, "words are plain 16-bit values");

template <ByteOrder kOrder, typename Field>
void encode_loop(const Field* fields, std::size_t count, const void* values, std::byte* frame) noexcept {
  const auto* base = static_cast<const unsigned char*>(values);
  for (std::size_t i = 0; i < count; ++i) {
    const Field& f = fields[i];
    if (f.bytes == 4) {
      std::uint32_t v;
      std::memcpy(&v, base + f.value_offset, sizeof v);
      write_double_word(frame + f.frame_offset, v, kOrder);
    } else {
      std::uint16_t v;
      std::memcpy(&v, base + f.value_offset, sizeof v);
      write_word(frame + f.frame_offset, v, kOrder);
    }
  }
}

template <ByteOrder kOrder, typename Field>
void decode_loop(const Field* fields, std::size_t count, const std::byte* frame, void* values) noexcept {
  auto* base = static_cast<unsigned char*>(values);
  for (std::size_t i = 0; i < count; ++i) {
    const Field& f = fields[i];
    if (f.bytes == 4) {
      const std::uint32_t v = read_double_word(frame + f.frame_offset, kOrder);
      std::memcpy(base + f.value_offset, &v, sizeof v);
    } else {
      const std::uint16_t v = read_word(frame + f.frame_offset, kOrder);
      std::memcpy(base + f.value_offset, &v, sizeof v);
    }
  }
}

template <typename Field>
void encode_any(ByteOrder order, const Field* fields, std::size_t count, const void* values,
                std::byte* frame) noexcept {
  switch (order) {
    case ByteOrder::kBig:
      encode_loop<ByteOrder::kBig>(fields, count, values, frame);
      break;
    case ByteOrder::kLittleBytes:
      encode_loop<ByteOrder::kLittleBytes>(fields, count, values, frame);
      break;
    case ByteOrder::kSwappedWords:
      encode_loop<ByteOrder::kSwappedWords>(fields, count, values, frame);
      break;
    case ByteOrder::kLittle:
      encode_loop<ByteOrder::kLittle>(fields, count, values, frame);
      break;
  }
}

template <typename Field>
void decode_any(ByteOrder order, const Field* fields, std::size_t count, const std::byte* frame,
                void* values) noexcept {
  switch (order) {
    case ByteOrder::kBig:
      decode_loop<ByteOrder::kBig>(fields, count, frame, values);
      break;
    case ByteOrder::kLittleBytes:
      decode_loop<ByteOrder::kLittleBytes>(fields, count, frame, values);
      break;
    case ByteOrder::kSwappedWords:
      decode_loop<ByteOrder::kSwappedWords>(fields, count, frame, values);
      break;
    case ByteOrder::kLittle:
      decode_loop<ByteOrder::kLittle>(fields, count, frame, values);
      break;
  }
}

}  // namespace

Result<TelegramCodec> TelegramCodec::create(int telegram, Direction direction,
                                            CodecOptions options) noexcept {
  auto layout = find_layout(telegram, direction);
  if (!layout) return layout.error();
  if (static_cast<unsigned>(options.byte_order) > static_cast<unsigned>(ByteOrder::kLittle)) {
    return TelegramError::kInvalidOption;
  }
  TelegramCodec codec;
  codec.layout_ = layout.value();
  codec.options_ = options;
  if (telegram == 83 && direction == Direction::kActual) {
    // spec 06 §2.13: NIST_B at 4, 8 or 12; XIST1 then XIST2 take the other two 32-bit slots in order.
    const std::uint8_t nist = options.telegram83_nist_b_offset;
    if (nist != 4 && nist != 8 && nist != 12) return TelegramError::kInvalidOption;
    std::uint8_t slot = 4;
    for (auto& f : codec.layout_.field_table) {
      if (f.signal == Signal::G1_XIST1 || f.signal == Signal::G1_XIST2) {
        if (slot == nist) slot += 4;
        f.offset = slot;
        slot += 4;
      } else if (f.signal == Signal::NIST_B) {
        f.offset = nist;
      }
    }
  }
  codec.compile();
  return codec;
}

namespace {

constexpr std::array<std::uint8_t, 3> kNistBOffsets{4, 8, 12};  // spec 06 §2.13
constexpr std::size_t kByteOrders = static_cast<std::size_t>(ByteOrder::kLittle) + 1;
constexpr std::size_t kMaxTelegrams = 16;
// Per telegram and byte order: the setpoint codec, then the actual codec for each NIST_B offset (only
// telegram 83's actual frame depends on it; the others repeat the same layout).
constexpr std::size_t kCodecsPerOrder = 1 + kNistBOffsets.size();

struct SharedCodecTable {
  std::array<std::uint16_t, kMaxTelegrams> telegram{};
  std::size_t count = 0;
  std::array<std::array<std::array<TelegramCodec, kCodecsPerOrder>, kByteOrders>, kMaxTelegrams> codec{};
};

const SharedCodecTable& shared_codecs() noexcept {
  static const SharedCodecTable table = [] {
    SharedCodecTable t;
    for (const std::uint16_t number : supported_telegrams()) {
      if (t.count == kMaxTelegrams) break;  // guarded by a test: every supported telegram is in the table
      auto& row = t.codec[t.count];
      t.telegram[t.count++] = number;
      for (std::size_t order = 0; order < kByteOrders; ++order) {
        CodecOptions options;
        options.byte_order = static_cast<ByteOrder>(order);
        if (auto c = TelegramCodec::create(number, Direction::kSetpoint, options)) row[order][0] = c.value();
        for (std::size_t n = 0; n < kNistBOffsets.size(); ++n) {
          options.telegram83_nist_b_offset = kNistBOffsets[n];
          if (auto c = TelegramCodec::create(number, Direction::kActual, options))
            row[order][1 + n] = c.value();
        }
      }
    }
    return t;
  }();
  return table;
}

}  // namespace

Result<const TelegramCodec*> TelegramCodec::shared(int telegram, Direction direction,
                                                   CodecOptions options) noexcept {
  // create() decides validity and the error; the table only answers for what it accepts.
  if (auto checked = create(telegram, direction, options); !checked) return checked.error();
  const auto& table = shared_codecs();
  for (std::size_t i = 0; i < table.count; ++i) {
    if (table.telegram[i] != telegram) continue;
    const auto& row = table.codec[i][static_cast<std::size_t>(options.byte_order)];
    if (direction == Direction::kSetpoint) return &row[0];
    for (std::size_t n = 0; n < kNistBOffsets.size(); ++n) {
      if (kNistBOffsets[n] == options.telegram83_nist_b_offset) return &row[1 + n];
    }
    return &row[kNistBOffsets.size()];  // not telegram 83 (create() checked its offset): one layout
  }
  return TelegramError::kUnknownTelegram;  // unreachable while the table holds every supported telegram
}

const TelegramCodec& TelegramCodec::empty() noexcept {
  static const TelegramCodec codec;
  return codec;
}

void TelegramCodec::compile() noexcept {
  for (std::size_t i = 0; i < layout_.field_count; ++i) {
    const FieldLayout& f = layout_.field_table[i];
    compiled_[i] =
        CompiledField{f.offset, value_offset(f.signal), static_cast<std::uint8_t>(info(f.signal).bits / 8)};
  }
}

TelegramError TelegramCodec::check(std::size_t frame_size, Direction expected) const noexcept {
  if (layout_.length == 0) return TelegramError::kUnknownTelegram;
  if (layout_.direction != expected) return TelegramError::kWrongDirection;
  if (frame_size != layout_.length) return TelegramError::kFrameLengthMismatch;
  return TelegramError::kNone;
}

TelegramError TelegramCodec::encode(const SetpointSignals& values,
                                    std::span<std::byte> frame) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kSetpoint);
  if (e == TelegramError::kNone)
    encode_any(options_.byte_order, compiled_.data(), layout_.field_count, &values, frame.data());
  return e;
}

TelegramError TelegramCodec::encode(const ActualSignals& values, std::span<std::byte> frame) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kActual);
  if (e == TelegramError::kNone)
    encode_any(options_.byte_order, compiled_.data(), layout_.field_count, &values, frame.data());
  return e;
}

TelegramError TelegramCodec::decode(std::span<const std::byte> frame,
                                    SetpointSignals& values) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kSetpoint);
  if (e == TelegramError::kNone)
    decode_any(options_.byte_order, compiled_.data(), layout_.field_count, frame.data(), &values);
  return e;
}

TelegramError TelegramCodec::decode(std::span<const std::byte> frame, ActualSignals& values) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kActual);
  if (e == TelegramError::kNone)
    decode_any(options_.byte_order, compiled_.data(), layout_.field_count, frame.data(), &values);
  return e;
}

}  // namespace tomc::telegrams
