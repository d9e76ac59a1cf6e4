#pragma once
// Cursors over caller-provided bytes for the PROFINET codecs: big-endian by default (PNIO blocks, DCP and RT
// frames are network order), little-endian on request (the NDR fields of DCE/RPC follow the sender's data
// representation). The first failure sticks: later reads return 0 and later writes are dropped, so a codec
// checks once at the end instead of after every field.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>

#include "tomc/profinet/error.hpp"

namespace tomc::profinet {

class WireReader {
 public:
  explicit WireReader(std::span<const std::uint8_t> bytes) noexcept : bytes_(bytes) {}

  std::uint8_t u8() noexcept { return take(1) ? bytes_[position_ - 1] : 0; }
  std::uint16_t u16(bool little_endian = false) noexcept {
    if (!take(2)) return 0;
    const auto* p = &bytes_[position_ - 2];
    return little_endian ? static_cast<std::uint16_t>(p[0] | (p[1] << 8))
                         : static_cast<std::uint16_t>((p[0] << 8) | p[1]);
  }
  std::uint32_t u32(bool little_endian = false) noexcept {
    const std::uint32_t first = u16(little_endian);
    const std::uint32_t second = u16(little_endian);
    return little_endian ? (second << 16) | first : (first << 16) | second;
  }
  // Copies n bytes into out (which must hold n); on failure out is left as it was.
  void bytes(std::uint8_t* out, std::size_t n) noexcept {
    if (take(n) && n != 0) std::memcpy(out, &bytes_[position_ - n], n);
  }
  std::span<const std::uint8_t> view(std::size_t n) noexcept {
    if (!take(n)) return {};
    return bytes_.subspan(position_ - n, n);
  }
  void skip(std::size_t n) noexcept { (void)take(n); }
  void fail(ProfinetError error) noexcept {
    if (error_ == ProfinetError::kNone) error_ = error;
  }

  std::size_t position() const noexcept { return position_; }
  std::size_t remaining() const noexcept { return bytes_.size() - position_; }
  ProfinetError error() const noexcept { return error_; }
  bool ok() const noexcept { return error_ == ProfinetError::kNone; }

 private:
  bool take(std::size_t n) noexcept {
    if (error_ != ProfinetError::kNone) return false;
    if (n > bytes_.size() - position_) {
      error_ = ProfinetError::kTruncated;
      return false;
    }
    position_ += n;
    return true;
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t position_ = 0;
  ProfinetError error_ = ProfinetError::kNone;
};

class WireWriter {
 public:
  explicit WireWriter(std::span<std::uint8_t> bytes) noexcept : bytes_(bytes) {}

  void u8(std::uint8_t value) noexcept {
    if (take(1)) bytes_[position_ - 1] = value;
  }
  void u16(std::uint16_t value, bool little_endian = false) noexcept {
    if (!take(2)) return;
    auto* p = &bytes_[position_ - 2];
    p[little_endian ? 1 : 0] = static_cast<std::uint8_t>(value >> 8);
    p[little_endian ? 0 : 1] = static_cast<std::uint8_t>(value);
  }
  void u32(std::uint32_t value, bool little_endian = false) noexcept {
    u16(static_cast<std::uint16_t>(little_endian ? value : value >> 16), little_endian);
    u16(static_cast<std::uint16_t>(little_endian ? value >> 16 : value), little_endian);
  }
  void bytes(std::span<const std::uint8_t> data) noexcept {
    if (take(data.size()) && !data.empty())
      std::memcpy(&bytes_[position_ - data.size()], data.data(), data.size());
  }
  void text(std::string_view value) noexcept {
    bytes({reinterpret_cast<const std::uint8_t*>(value.data()), value.size()});
  }
  void zeros(std::size_t n) noexcept {
    if (take(n) && n != 0) std::memset(&bytes_[position_ - n], 0, n);
  }
  // Overwrites a big-endian u16 written earlier (block and data lengths known only at the end).
  void patch_u16(std::size_t at, std::uint16_t value, bool little_endian = false) noexcept {
    if (error_ != ProfinetError::kNone || at + 2 > position_) return;
    bytes_[at + (little_endian ? 1 : 0)] = static_cast<std::uint8_t>(value >> 8);
    bytes_[at + (little_endian ? 0 : 1)] = static_cast<std::uint8_t>(value);
  }
  void patch_u32(std::size_t at, std::uint32_t value, bool little_endian = false) noexcept {
    patch_u16(at + (little_endian ? 2 : 0), static_cast<std::uint16_t>(value >> 16), little_endian);
    patch_u16(at + (little_endian ? 0 : 2), static_cast<std::uint16_t>(value), little_endian);
  }

  std::size_t position() const noexcept { return position_; }
  ProfinetError error() const noexcept { return error_; }
  bool ok() const noexcept { return error_ == ProfinetError::kNone; }
  std::span<std::uint8_t> written() const noexcept { return bytes_.first(position_); }

 private:
  bool take(std::size_t n) noexcept {
    if (error_ != ProfinetError::kNone) return false;
    if (n > bytes_.size() - position_) {
      error_ = ProfinetError::kBufferTooSmall;
      return false;
    }
    position_ += n;
    return true;
  }

  std::span<std::uint8_t> bytes_;
  std::size_t position_ = 0;
  ProfinetError error_ = ProfinetError::kNone;
};

}  // namespace tomc::profinet
