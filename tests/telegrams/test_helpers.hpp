#pragma once
// Small helpers shared by the telegram tests: hex byte strings as written in spec 06 §11, every byte order
// and signal, and value structs filled with random wire bits.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "tomc/telegrams/byte_order.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams::test {

inline std::vector<std::byte> bytes(std::initializer_list<unsigned> values) {
  std::vector<std::byte> out;
  out.reserve(values.size());
  for (unsigned v : values)
    out.push_back(static_cast<std::byte>(v));
  return out;
}

// "04 7F 20 00" style, upper case, for readable failure messages.
inline std::string hex(std::span<const std::byte> data) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string out;
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (i != 0) out.push_back(' ');
    const auto b = static_cast<unsigned>(data[i]);
    out.push_back(kDigits[b >> 4]);
    out.push_back(kDigits[b & 0xFu]);
  }
  return out;
}

inline std::string hex(const std::vector<std::byte>& data) {
  return hex(std::span<const std::byte>(data));
}

inline constexpr ByteOrder kAllOrders[] = {ByteOrder::kBig, ByteOrder::kLittleBytes, ByteOrder::kSwappedWords,
                                           ByteOrder::kLittle};

inline constexpr Signal kSetpointSignals[] = {
    Signal::STW1,   Signal::NSOLL_A,     Signal::NSOLL_B,    Signal::STW2,   Signal::G1_STW,
    Signal::G2_STW, Signal::XERR,        Signal::KPC,        Signal::MOMRED, Signal::STW2_ENC,
    Signal::M_ADD1, Signal::M_LIMIT_POS, Signal::M_LIMIT_NEG};
inline constexpr Signal kActualSignals[] = {
    Signal::ZSW1,     Signal::NIST_A,   Signal::NIST_B, Signal::ZSW2,     Signal::G1_ZSW,
    Signal::G1_XIST1, Signal::G1_XIST2, Signal::G2_ZSW, Signal::G2_XIST1, Signal::G2_XIST2,
    Signal::MELDW,    Signal::ZSW2_ENC, Signal::M_ACT};

inline std::uint32_t random_raw(std::mt19937& rng, Signal s) {
  const std::uint32_t v = rng();
  return info(s).bits == 16 ? (v & 0xFFFFu) : v;
}

template <typename Values, std::size_t N>
Values random_values(std::mt19937& rng, const Signal (&signals)[N]) {
  Values v;
  for (const Signal s : signals)
    v.set_raw(s, random_raw(rng, s));
  return v;
}

}  // namespace tomc::telegrams::test
