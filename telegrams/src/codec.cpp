// Table-driven frame codec: walks the telegram's fields and moves each between the value struct and the bytes.
#include "tomc/telegrams/codec.hpp"

namespace tomc::telegrams {

Result<TelegramCodec> TelegramCodec::create(int telegram, Direction direction, CodecOptions options) noexcept {
  auto layout = find_layout(telegram, direction);
  if (!layout) return layout.error();
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
  return codec;
}

template <typename Values>
TelegramError TelegramCodec::encode_fields(const Values& values, std::span<std::byte> frame,
                                           Direction expected) const noexcept {
  if (layout_.length == 0) return TelegramError::kUnknownTelegram;
  if (layout_.direction != expected) return TelegramError::kWrongDirection;
  if (frame.size() != layout_.length) return TelegramError::kFrameLengthMismatch;
  for (const auto& f : layout_.fields()) {
    std::byte* p = frame.data() + f.offset;
    if (info(f.signal).bits == 32) {
      write_double_word(p, values.raw(f.signal), options_.byte_order);
    } else {
      write_word(p, static_cast<std::uint16_t>(values.raw(f.signal)), options_.byte_order);
    }
  }
  return TelegramError::kNone;
}

template <typename Values>
TelegramError TelegramCodec::decode_fields(std::span<const std::byte> frame, Values& values,
                                           Direction expected) const noexcept {
  if (layout_.length == 0) return TelegramError::kUnknownTelegram;
  if (layout_.direction != expected) return TelegramError::kWrongDirection;
  if (frame.size() != layout_.length) return TelegramError::kFrameLengthMismatch;
  for (const auto& f : layout_.fields()) {
    const std::byte* p = frame.data() + f.offset;
    const std::uint32_t raw =
        info(f.signal).bits == 32 ? read_double_word(p, options_.byte_order) : read_word(p, options_.byte_order);
    values.set_raw(f.signal, raw);
  }
  return TelegramError::kNone;
}

TelegramError TelegramCodec::encode(const SetpointSignals& values, std::span<std::byte> frame) const noexcept {
  return encode_fields(values, frame, Direction::kSetpoint);
}
TelegramError TelegramCodec::encode(const ActualSignals& values, std::span<std::byte> frame) const noexcept {
  return encode_fields(values, frame, Direction::kActual);
}
TelegramError TelegramCodec::decode(std::span<const std::byte> frame, SetpointSignals& values) const noexcept {
  return decode_fields(frame, values, Direction::kSetpoint);
}
TelegramError TelegramCodec::decode(std::span<const std::byte> frame, ActualSignals& values) const noexcept {
  return decode_fields(frame, values, Direction::kActual);
}

}  // namespace tomc::telegrams
