#pragma once
// Byte order of the PZD image on one connection (spec 06 §1.1).
// PROFINET itself is big-endian; a gateway may present the image swapped, so the order is chosen per
// connection.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace tomc::telegrams {

enum class ByteOrder : std::uint8_t {
  kBig,           // PROFIdrive/PROFINET: 32-bit signals high word first, every word high byte first
  kLittleBytes,   // every 16-bit word low byte first; 32-bit signals keep the high word first
  kSwappedWords,  // 32-bit signals low word first; every word high byte first
  kLittle,        // fully little-endian (both swaps), e.g. Festo edcon over Modbus / EtherNet/IP
};

std::string_view to_string(ByteOrder order) noexcept;
// Accepts "big", "little-bytes", "swapped-words", "little".
std::optional<ByteOrder> parse_byte_order(std::string_view text) noexcept;

inline std::uint16_t read_word(const std::byte* p, ByteOrder order) noexcept {
  const auto b0 = static_cast<std::uint16_t>(p[0]);
  const auto b1 = static_cast<std::uint16_t>(p[1]);
  const bool low_byte_first = order == ByteOrder::kLittleBytes || order == ByteOrder::kLittle;
  return low_byte_first ? static_cast<std::uint16_t>(b0 | (b1 << 8))
                        : static_cast<std::uint16_t>((b0 << 8) | b1);
}

inline void write_word(std::byte* p, std::uint16_t value, ByteOrder order) noexcept {
  const bool low_byte_first = order == ByteOrder::kLittleBytes || order == ByteOrder::kLittle;
  const auto high = static_cast<std::byte>(value >> 8);
  const auto low = static_cast<std::byte>(value & 0xFFu);
  p[0] = low_byte_first ? low : high;
  p[1] = low_byte_first ? high : low;
}

inline std::uint32_t read_double_word(const std::byte* p, ByteOrder order) noexcept {
  const bool low_word_first = order == ByteOrder::kSwappedWords || order == ByteOrder::kLittle;
  const std::uint32_t first = read_word(p, order);
  const std::uint32_t second = read_word(p + 2, order);
  return low_word_first ? (second << 16) | first : (first << 16) | second;
}

inline void write_double_word(std::byte* p, std::uint32_t value, ByteOrder order) noexcept {
  const bool low_word_first = order == ByteOrder::kSwappedWords || order == ByteOrder::kLittle;
  const auto high = static_cast<std::uint16_t>(value >> 16);
  const auto low = static_cast<std::uint16_t>(value & 0xFFFFu);
  write_word(p, low_word_first ? low : high, order);
  write_word(p + 2, low_word_first ? high : low, order);
}

}  // namespace tomc::telegrams
