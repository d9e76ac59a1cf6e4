#pragma once
// Encodes and decodes one telegram of one direction into caller-provided bytes. No allocation, no
// exceptions: every outcome is a TelegramError. Configure once (create), then call per cycle: create()
// chooses a straight-line routine for the telegram's layout and byte order (decision O4); the generic
// per-field loop stays as the reference it is tested against.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "tomc/telegrams/byte_order.hpp"
#include "tomc/telegrams/error.hpp"
#include "tomc/telegrams/layout.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams {

namespace detail {
// A layout unrolled at compile time (routines.cpp): `values` is the SetpointSignals or ActualSignals of the
// layout's direction, `frame` has the layout's length.
using EncodeRoutine = void (*)(const void* values, std::byte* frame) noexcept;
using DecodeRoutine = void (*)(const std::byte* frame, void* values) noexcept;
// A signal resolved at configuration: where it sits in the frame and in the value struct, and its width.
struct CompiledField {
  std::uint8_t frame_offset;
  std::uint8_t value_offset;  // offsetof the member in SetpointSignals / ActualSignals
  std::uint8_t bytes;         // 2 or 4
};
}  // namespace detail

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
  // first use: a technology object keeps a pointer (8 bytes) instead of a copy (layout, routines) per slot
  // and direction, and thousands of axes share a few cache lines of layouts (issue 18 memory, decision U1).
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
  TelegramError encode(const SetpointSignals& values, std::span<std::byte> frame) const noexcept {
    return run(&values, frame, Direction::kSetpoint);
  }
  TelegramError encode(const ActualSignals& values, std::span<std::byte> frame) const noexcept {
    return run(&values, frame, Direction::kActual);
  }
  TelegramError decode(std::span<const std::byte> frame, SetpointSignals& values) const noexcept {
    return run(frame, &values, Direction::kSetpoint);
  }
  TelegramError decode(std::span<const std::byte> frame, ActualSignals& values) const noexcept {
    return run(frame, &values, Direction::kActual);
  }

  // The same through the generic per-field loop over the compiled layout: the reference the telegram-specific
  // routines are tested against (tests/telegrams/routines_test.cpp). Not for the cycle.
  TelegramError encode_reference(const SetpointSignals& values, std::span<std::byte> frame) const noexcept;
  TelegramError encode_reference(const ActualSignals& values, std::span<std::byte> frame) const noexcept;
  TelegramError decode_reference(std::span<const std::byte> frame, SetpointSignals& values) const noexcept;
  TelegramError decode_reference(std::span<const std::byte> frame, ActualSignals& values) const noexcept;

 private:
  // The layout resolved once at create(), walked by the reference loop.
  void compile() noexcept;
  // Refuses an empty codec, the other direction's struct and a frame of another length, in this order.
  TelegramError check(std::size_t frame_size, Direction expected) const noexcept {
    if (layout_.length == 0) return TelegramError::kUnknownTelegram;
    if (layout_.direction != expected) return TelegramError::kWrongDirection;
    if (frame_size != layout_.length) return TelegramError::kFrameLengthMismatch;
    return TelegramError::kNone;
  }
  TelegramError run(const void* values, std::span<std::byte> frame, Direction expected) const noexcept {
    const TelegramError e = check(frame.size(), expected);
    if (e == TelegramError::kNone) encode_(values, frame.data());
    return e;
  }
  TelegramError run(std::span<const std::byte> frame, void* values, Direction expected) const noexcept {
    const TelegramError e = check(frame.size(), expected);
    if (e == TelegramError::kNone) decode_(frame.data(), values);
    return e;
  }

  // Member order (decision P28): what a cycle's encode()/decode() reads (the routine, then the layout's
  // direction and length) lies in the first 24 bytes, one cache line; the rest is configuration.
  // The routines: set by create() for every valid layout; never called while the length is 0 (check() first).
  detail::EncodeRoutine encode_ = nullptr;
  detail::DecodeRoutine decode_ = nullptr;
  TelegramLayout layout_{};
  CodecOptions options_{};
  std::array<detail::CompiledField, kMaxFieldsPerFrame> compiled_{};
};

}  // namespace tomc::telegrams
