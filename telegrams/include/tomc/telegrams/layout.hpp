#pragma once
// Word positions of every supported telegram in both directions, exactly as spec 06 §2.

#include <array>
#include <cstdint>
#include <span>

#include "tomc/telegrams/error.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams {

inline constexpr std::size_t kMaxFrameBytes = 30;  // telegrams 103/106 actual (spec 06 §2.15)
inline constexpr std::size_t kMaxFieldsPerFrame = 10;

struct FieldLayout {
  Signal signal;
  std::uint8_t offset;  // byte offset in the frame; PZD number = offset / 2 + 1
};

struct TelegramLayout {
  std::uint16_t telegram = 0;
  Direction direction = Direction::kSetpoint;
  std::uint8_t length = 0;  // bytes
  std::uint8_t field_count = 0;
  std::array<FieldLayout, kMaxFieldsPerFrame> field_table{};

  std::span<const FieldLayout> fields() const noexcept { return {field_table.data(), field_count}; }
  bool carries(Signal signal) const noexcept;
  // Byte offset of a signal, or -1 when the telegram does not carry it.
  int offset_of(Signal signal) const noexcept;
};

// The telegram numbers of spec 06 §2, ascending.
std::span<const std::uint16_t> supported_telegrams() noexcept;

// Encoder-only telegrams (81, 83) and the supplementary telegram 750 are not drive telegrams.
bool is_drive_telegram(int telegram) noexcept;
bool is_encoder_telegram(int telegram) noexcept;
bool is_supplementary_telegram(int telegram) noexcept;

// The standard layout; kTelegram104NotDefined for 104, kUnknownTelegram for anything else not supported.
Result<TelegramLayout> find_layout(int telegram, Direction direction) noexcept;

}  // namespace tomc::telegrams
