// Frame codec: at create() the layout is resolved into (frame offset, value offset, width) triples, which the
// reference loop walks, and the telegram-specific routine of the layout is chosen (routines.cpp), which the
// cycle calls.
#include "tomc/telegrams/codec.hpp"

#include <cstddef>
#include <cstring>

#include "field_moves.hpp"
#include "layout_table.hpp"
#include "routines.hpp"

namespace tomc::telegrams {
namespace {

using detail::CompiledField;

template <ByteOrder kOrder>
void encode_loop(const CompiledField* fields, std::size_t count, const void* values,
                 std::byte* frame) noexcept {
  const auto* base = static_cast<const unsigned char*>(values);
  for (std::size_t i = 0; i < count; ++i)
    detail::encode_field<kOrder>(fields[i], base, frame);
}

template <ByteOrder kOrder>
void decode_loop(const CompiledField* fields, std::size_t count, const std::byte* frame,
                 void* values) noexcept {
  auto* base = static_cast<unsigned char*>(values);
  for (std::size_t i = 0; i < count; ++i)
    detail::decode_field<kOrder>(fields[i], frame, base);
}

void encode_any(ByteOrder order, const CompiledField* fields, std::size_t count, const void* values,
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

void decode_any(ByteOrder order, const CompiledField* fields, std::size_t count, const std::byte* frame,
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
    codec.layout_ = detail::with_nist_b_offset(codec.layout_, nist);
  }
  const detail::Routines routines =
      detail::find_routines(telegram, direction, options.byte_order, options.telegram83_nist_b_offset);
  if (routines.encode == nullptr || routines.decode == nullptr) return TelegramError::kUnknownTelegram;
  codec.encode_ = routines.encode;
  codec.decode_ = routines.decode;
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
    compiled_[i] = CompiledField{f.offset, detail::value_offset(f.signal),
                                 static_cast<std::uint8_t>(info(f.signal).bits / 8)};
  }
}

TelegramError TelegramCodec::encode_reference(const SetpointSignals& values,
                                              std::span<std::byte> frame) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kSetpoint);
  if (e == TelegramError::kNone)
    encode_any(options_.byte_order, compiled_.data(), layout_.field_count, &values, frame.data());
  return e;
}

TelegramError TelegramCodec::encode_reference(const ActualSignals& values,
                                              std::span<std::byte> frame) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kActual);
  if (e == TelegramError::kNone)
    encode_any(options_.byte_order, compiled_.data(), layout_.field_count, &values, frame.data());
  return e;
}

TelegramError TelegramCodec::decode_reference(std::span<const std::byte> frame,
                                              SetpointSignals& values) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kSetpoint);
  if (e == TelegramError::kNone)
    decode_any(options_.byte_order, compiled_.data(), layout_.field_count, frame.data(), &values);
  return e;
}

TelegramError TelegramCodec::decode_reference(std::span<const std::byte> frame,
                                              ActualSignals& values) const noexcept {
  const TelegramError e = check(frame.size(), Direction::kActual);
  if (e == TelegramError::kNone)
    decode_any(options_.byte_order, compiled_.data(), layout_.field_count, frame.data(), &values);
  return e;
}

}  // namespace tomc::telegrams
