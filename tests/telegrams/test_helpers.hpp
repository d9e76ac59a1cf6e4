#pragma once
// Small helpers shared by the telegram tests: hex byte strings as written in spec 06 §11.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

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

}  // namespace tomc::telegrams::test
