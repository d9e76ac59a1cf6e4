#pragma once
// Encodes and decodes one telegram of one direction into caller-provided bytes. No allocation, no
// exceptions: every outcome is a TelegramError. Configure once (create), then call per cycle.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "tomc/telegrams/byte_order.hpp"
#include "tomc/telegrams/error.hpp"
#include "tomc/telegrams/layout.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams {

struct CodecOptions {
  ByteOrder byte_order = ByteOrder::kBig;
  // Telegram 83: byte offset of NIST_B in the actual frame, 4, 8 or 12 (default 12, spec 06 §2.13
  // [UNCONFIRMED]). G1_XIST1 and G1_XIST2 keep their order in the remaining 32-bit slots.
  std::uint8_t telegram83_nist_b_offset = 12;
};

class TelegramCodec {
 public:
  TelegramCodec() noexcept = default;  // empty codec: length 0, every call fails with kUnknownTelegram
  static Result<TelegramCodec> create(int telegram, Direction direction, CodecOptions options = {}) noexcept;
  // The same codec from a process-wide table of every valid (telegram, direction, options), built once on
  // first use: a technology object keeps a pointer (8 bytes) instead of a copy (58 bytes) per slot and
  // direction, and thousands of axes share a few cache lines of layouts (issue 18 memory, decision U1).
  // Configuration-time call (the first one builds the table); never fails for a create()-valid input.
  static Result<const TelegramCodec*> shared(int telegram, Direction direction,
                                             CodecOptions options = {}) noexcept;
  // A codec of length 0 (every call fails with kUnknownTelegram): what an unused slot points to.
  static const TelegramCodec& empty() noexcept;

  const TelegramLayout& layout() const noexcept { return layout_; }
  int telegram() const noexcept { return layout_.telegram; }
  Direction direction() const noexcept { return layout_.direction; }
  std::size_t frame_size() const noexcept { return layout_.length; }
  ByteOrder byte_order() const noexcept { return options_.byte_order; }
  bool carries(Signal signal) const noexcept { return layout_.carries(signal); }

  // The frame must be exactly frame_size() bytes; signals the telegram does not carry are left untouched.
  TelegramError encode(const SetpointSignals& values, std::span<std::byte> frame) const noexcept;
  TelegramError encode(const ActualSignals& values, std::span<std::byte> frame) const noexcept;
  TelegramError decode(std::span<const std::byte> frame, SetpointSignals& values) const noexcept;
  TelegramError decode(std::span<const std::byte> frame, ActualSignals& values) const noexcept;

 private:
  // The layout resolved once at create(): where each signal sits in the frame and in the value struct, so the
  // per-cycle loop is a few loads and stores (docs/performance.md).
  struct CompiledField {
    std::uint8_t frame_offset;
    std::uint8_t value_offset;  // offsetof the member in SetpointSignals / ActualSignals
    std::uint8_t bytes;         // 2 or 4
  };
  void compile() noexcept;
  TelegramError check(std::size_t frame_size, Direction expected) const noexcept;

  TelegramLayout layout_{};
  CodecOptions options_{};
  std::array<CompiledField, kMaxFieldsPerFrame> compiled_{};
};

}  // namespace tomc::telegrams
