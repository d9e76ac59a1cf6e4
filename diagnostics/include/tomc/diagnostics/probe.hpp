#pragma once
// A value the cycle reads without looking anything up: a read function and the object it reads, resolved
// once from a path before recording starts (trace channels and triggers, diagnostics areas). Reading is a
// function call; no allocation, no locks.

#include <cstdint>

namespace tomc::diagnostics {

struct Probe {
  double (*read)(const void* object) noexcept = nullptr;
  const void* object = nullptr;
  std::int8_t bit = -1;  // >= 0: that bit of an unsigned word (BYTE/WORD/DWORD, a telegram word)

  bool valid() const noexcept { return read != nullptr; }
  double value() const noexcept {
    const double v = read(object);
    if (bit < 0) return v;
    // Words are unsigned integers below 2^32; anything else (NaN: wrong data block) reads as FALSE.
    if (!(v >= 0.0 && v < 4294967296.0)) return 0.0;
    return ((static_cast<std::uint32_t>(v) >> bit) & 1u) != 0 ? 1.0 : 0.0;
  }
};

}  // namespace tomc::diagnostics
