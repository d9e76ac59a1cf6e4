#pragma once
// The standard telegram layouts of spec 06 §2 as constant data, shared by find_layout() (layout.cpp) and the
// telegram-specific codec routines (routines.cpp), which unroll each layout at compile time (decision O4).
// Private to the telegrams library.

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>

#include "tomc/telegrams/layout.hpp"

namespace tomc::telegrams::detail {

using enum Signal;
constexpr auto S = Direction::kSetpoint;
constexpr auto A = Direction::kActual;

constexpr TelegramLayout make(std::uint16_t telegram, Direction direction, std::uint8_t length,
                              std::initializer_list<FieldLayout> fields) {
  TelegramLayout layout{};
  layout.telegram = telegram;
  layout.direction = direction;
  layout.length = length;
  for (const auto& f : fields)
    layout.field_table[layout.field_count++] = f;
  return layout;
}

// Actual frames shared by several telegrams.
constexpr std::initializer_list<FieldLayout> kTwoEncoderActual = {  // telegrams 4 and 6, §2.4
    {ZSW1, 0},      {NIST_B, 2},  {ZSW2, 6},      {G1_ZSW, 8},   {G1_XIST1, 10},
    {G1_XIST2, 14}, {G2_ZSW, 18}, {G2_XIST1, 20}, {G2_XIST2, 24}};
constexpr std::initializer_list<FieldLayout> kTwoEncoderMeldwActual = {  // telegrams 103 and 106, §2.8
    {ZSW1, 0},      {NIST_B, 2},    {ZSW2, 6},    {MELDW, 8},     {G1_ZSW, 10},
    {G1_XIST1, 12}, {G1_XIST2, 16}, {G2_ZSW, 20}, {G2_XIST1, 22}, {G2_XIST2, 26}};
constexpr std::initializer_list<FieldLayout> kOneEncoderMeldwActual = {  // telegrams 102 and 105, §2.7
    {ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}, {MELDW, 8}, {G1_ZSW, 10}, {G1_XIST1, 12}, {G1_XIST2, 16}};
constexpr std::initializer_list<FieldLayout> kOneEncoderActual = {  // telegrams 3 and 5, §2.3
    {ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}, {G1_ZSW, 8}, {G1_XIST1, 10}, {G1_XIST2, 14}};

inline constexpr TelegramLayout kLayouts[] = {
    // §2.1 telegram 1, PZD-2/2
    make(1, S, 4, {{STW1, 0}, {NSOLL_A, 2}}),
    make(1, A, 4, {{ZSW1, 0}, {NIST_A, 2}}),
    // §2.2 telegram 2, PZD-4/4
    make(2, S, 8, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}}),
    make(2, A, 8, {{ZSW1, 0}, {NIST_B, 2}, {ZSW2, 6}}),
    // §2.3 telegram 3, PZD-5/9
    make(3, S, 10, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}}),
    make(3, A, 18, kOneEncoderActual),
    // §2.4 telegram 4, PZD-6/14
    make(4, S, 12, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}, {G2_STW, 10}}),
    make(4, A, 28, kTwoEncoderActual),
    // §2.5 telegram 5, PZD-9/9 (DSC)
    make(5, S, 18, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}, {XERR, 10}, {KPC, 14}}),
    make(5, A, 18, kOneEncoderActual),
    // §2.6 telegram 6, PZD-10/14 (DSC, two encoders) [UNCONFIRMED order, see docs/decisions.md]
    make(6, S, 20, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {G1_STW, 8}, {G2_STW, 10}, {XERR, 12}, {KPC, 16}}),
    make(6, A, 28, kTwoEncoderActual),
    // §2.12 telegram 81, encoder PZD-2/6
    make(81, S, 4, {{STW2_ENC, 0}, {G1_STW, 2}}),
    make(81, A, 12, {{ZSW2_ENC, 0}, {G1_ZSW, 2}, {G1_XIST1, 4}, {G1_XIST2, 8}}),
    // §2.13 telegram 83, encoder with speed PZD-2/8 (NIST_B offset configurable, see codec)
    make(83, S, 4, {{STW2_ENC, 0}, {G1_STW, 2}}),
    make(83, A, 16, {{ZSW2_ENC, 0}, {G1_ZSW, 2}, {G1_XIST1, 4}, {G1_XIST2, 8}, {NIST_B, 12}}),
    // §2.7 telegram 102, PZD-6/10 (torque reduction)
    make(102, S, 12, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}}),
    make(102, A, 20, kOneEncoderMeldwActual),
    // §2.8 telegram 103, PZD-7/15
    make(103, S, 14, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}, {G2_STW, 12}}),
    make(103, A, 30, kTwoEncoderMeldwActual),
    // §2.10 telegram 105, PZD-10/10 (torque reduction + DSC)
    make(105, S, 20, {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}, {XERR, 12}, {KPC, 16}}),
    make(105, A, 20, kOneEncoderMeldwActual),
    // §2.11 telegram 106, PZD-11/15 [UNCONFIRMED order, see docs/decisions.md]
    make(
        106, S, 22,
        {{STW1, 0}, {NSOLL_B, 2}, {STW2, 6}, {MOMRED, 8}, {G1_STW, 10}, {G2_STW, 12}, {XERR, 14}, {KPC, 18}}),
    make(106, A, 30, kTwoEncoderMeldwActual),
    // §2.14 telegram 750, supplementary torque telegram PZD-3/1
    make(750, S, 6, {{M_ADD1, 0}, {M_LIMIT_POS, 2}, {M_LIMIT_NEG, 4}}),
    make(750, A, 2, {{M_ACT, 0}}),
};

inline constexpr std::uint16_t kSupported[] = {1, 2, 3, 4, 5, 6, 81, 83, 102, 103, 105, 106, 750};

// Width on the wire (spec 06 §1.2: N4, I32 and the XIST counts are 32-bit; every other signal 16-bit).
constexpr std::uint8_t wire_bytes(Signal s) {
  return (s == NSOLL_B || s == NIST_B || s == XERR || s == KPC || s == G1_XIST1 || s == G1_XIST2 ||
          s == G2_XIST1 || s == G2_XIST2)
             ? 4
             : 2;
}

// Every field lies inside its frame, none overlaps another, and every field is of its table's direction.
constexpr bool layouts_are_consistent() {
  for (const auto& layout : kLayouts) {
    if (layout.length > kMaxFrameBytes) return false;
    std::uint32_t used = 0;
    for (std::size_t i = 0; i < layout.field_count; ++i) {
      const auto& f = layout.field_table[i];
      const std::uint32_t bytes = wire_bytes(f.signal);
      if (f.offset % 2 != 0 || f.offset + bytes > layout.length) return false;
      const std::uint32_t mask = ((1u << bytes) - 1u) << f.offset;
      if ((used & mask) != 0) return false;
      used |= mask;
      const bool setpoint_signal = f.signal <= M_LIMIT_NEG;
      if (setpoint_signal != (layout.direction == S)) return false;
    }
  }
  return true;
}
static_assert(layouts_are_consistent());

// Telegram 83's actual frame with NIST_B at byte 4, 8 or 12 (spec 06 §2.13): G1_XIST1 then G1_XIST2 take the
// other two 32-bit slots in order. Any other layout, or another offset, is returned unchanged.
constexpr TelegramLayout with_nist_b_offset(TelegramLayout layout, std::uint8_t nist) {
  if (layout.telegram != 83 || layout.direction != A || (nist != 4 && nist != 8 && nist != 12)) return layout;
  std::uint8_t slot = 4;
  for (auto& f : layout.field_table) {
    if (f.signal == G1_XIST1 || f.signal == G1_XIST2) {
      if (slot == nist) slot += 4;
      f.offset = slot;
      slot += 4;
    } else if (f.signal == NIST_B) {
      f.offset = nist;
    }
  }
  return layout;
}

}  // namespace tomc::telegrams::detail
