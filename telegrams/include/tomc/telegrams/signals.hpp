#pragma once
// The PROFIdrive signals carried by the supported telegrams (spec 06 §1.2, §2), with the identifiers the
// manuals use, and the two value structs a connection exchanges each cycle.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "tomc/telegrams/control_words.hpp"

namespace tomc::telegrams {

enum class Direction : std::uint8_t {
  kSetpoint,  // controller -> drive (PLC output)
  kActual,    // drive -> controller (PLC input)
};

std::string_view to_string(Direction direction) noexcept;
std::optional<Direction> parse_direction(std::string_view text) noexcept;

enum class Signal : std::uint8_t {
  // setpoint direction
  STW1,
  NSOLL_A,
  NSOLL_B,
  STW2,
  G1_STW,
  G2_STW,
  XERR,
  KPC,
  MOMRED,
  STW2_ENC,
  M_ADD1,
  M_LIMIT_POS,
  M_LIMIT_NEG,
  // actual direction
  ZSW1,
  NIST_A,
  NIST_B,
  ZSW2,
  G1_ZSW,
  G1_XIST1,
  G1_XIST2,
  G2_ZSW,
  G2_XIST1,
  G2_XIST2,
  MELDW,
  ZSW2_ENC,
  M_ACT,
};
inline constexpr std::size_t kSignalCount = static_cast<std::size_t>(Signal::M_ACT) + 1;

enum class SignalKind : std::uint8_t {
  kWord,        // V2 bit string (control/status word); named bits in control_words.hpp
  kNormalised,  // N2/N4 signed normalised value (0x4000 / 0x40000000 = 100 %)
  kSigned,      // I32 (XERR, KPC)
  kUnsigned,    // U16/U32 (MOMRED, XIST1/XIST2 counts)
};

struct SignalInfo {
  Signal signal;
  std::string_view name;
  Direction direction;
  std::uint8_t bits;  // 16 or 32
  SignalKind kind;
};

const SignalInfo& info(Signal signal) noexcept;
inline std::string_view name(Signal signal) noexcept {
  return info(signal).name;
}
// Exact identifier, case-sensitive; "M_ADD" is accepted for M_ADD1.
std::optional<Signal> parse_signal(std::string_view text) noexcept;

// Raw minimum/maximum of a signal's wire value, as a signed 64-bit number (for range checks of user input).
std::int64_t raw_minimum(Signal signal) noexcept;
std::int64_t raw_maximum(Signal signal) noexcept;

// Everything the controller may send; a telegram carries a subset (see TelegramLayout). Members ordered so
// that no 32-bit value leaves a hole (32 bytes instead of 36; an axis holds six of each struct, decision M9);
// the codecs address them by offsetof (field_moves.hpp), never by position.
struct SetpointSignals {
  Stw1 STW1;
  std::int16_t NSOLL_A = 0;
  std::int32_t NSOLL_B = 0;
  Stw2 STW2;
  EncoderControlWord G1_STW;
  EncoderControlWord G2_STW;
  Stw2Enc STW2_ENC;
  std::int32_t XERR = 0;
  std::int32_t KPC = 0;
  std::uint16_t MOMRED = 0;
  std::int16_t M_ADD1 = 0;
  std::int16_t M_LIMIT_POS = 0;
  std::int16_t M_LIMIT_NEG = 0;

  // The wire value of a setpoint signal, zero-extended (signed values as their two's-complement bits).
  std::uint32_t raw(Signal signal) const noexcept;
  // Sets a setpoint signal from its wire bits; actual-direction signals are ignored.
  void set_raw(Signal signal, std::uint32_t value) noexcept;
  friend bool operator==(const SetpointSignals&, const SetpointSignals&) = default;
};

// Everything a drive or encoder may report (36 bytes, no hole: decision M9).
struct ActualSignals {
  Zsw1 ZSW1;
  std::int16_t NIST_A = 0;
  std::int32_t NIST_B = 0;
  Zsw2 ZSW2;
  EncoderStatusWord G1_ZSW;
  std::uint32_t G1_XIST1 = 0;
  std::uint32_t G1_XIST2 = 0;
  EncoderStatusWord G2_ZSW;
  Zsw2Enc ZSW2_ENC;
  std::uint32_t G2_XIST1 = 0;
  std::uint32_t G2_XIST2 = 0;
  Meldw MELDW;
  std::int16_t M_ACT = 0;

  std::uint32_t raw(Signal signal) const noexcept;
  void set_raw(Signal signal, std::uint32_t value) noexcept;
  friend bool operator==(const ActualSignals&, const ActualSignals&) = default;
};

}  // namespace tomc::telegrams
