#pragma once
// Moving one signal between its value struct and the frame bytes: shared by the generic per-field loop of
// the codec (codec.cpp) and the telegram-specific routines (routines.cpp). Private to the telegrams library.

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "tomc/telegrams/byte_order.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams::detail {

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

template <ByteOrder kOrder>
[[gnu::always_inline]] inline void encode_field(const CompiledField& f, const unsigned char* values,
                                                std::byte* frame) noexcept {
  if (f.bytes == 4) {
    std::uint32_t v;
    std::memcpy(&v, values + f.value_offset, sizeof v);
    write_double_word(frame + f.frame_offset, v, kOrder);
  } else {
    std::uint16_t v;
    std::memcpy(&v, values + f.value_offset, sizeof v);
    write_word(frame + f.frame_offset, v, kOrder);
  }
}

template <ByteOrder kOrder>
[[gnu::always_inline]] inline void decode_field(const CompiledField& f, const std::byte* frame,
                                                unsigned char* values) noexcept {
  if (f.bytes == 4) {
    const std::uint32_t v = read_double_word(frame + f.frame_offset, kOrder);
    std::memcpy(values + f.value_offset, &v, sizeof v);
  } else {
    const std::uint16_t v = read_word(frame + f.frame_offset, kOrder);
    std::memcpy(values + f.value_offset, &v, sizeof v);
  }
}

}  // namespace tomc::telegrams::detail
