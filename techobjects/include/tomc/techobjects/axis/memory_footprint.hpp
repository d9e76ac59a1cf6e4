#pragma once
// What a technology object takes in memory: the object plus the heap it owns (issue 14, docs/performance.md
// "Memory per axis"; tests/techobjects/positioning_axis/memory_test.cpp guards the 8 KiB of DEVELOPERS.md).
#include <cstddef>
#include <string>

namespace tomc::techobjects {

// The heap a std::string owns beyond the object (0 while the short-string buffer holds it).
inline std::size_t string_heap_bytes(const std::string& s) noexcept {
  const std::string empty;
  return s.capacity() > empty.capacity() ? s.capacity() + 1 : 0;
}

}  // namespace tomc::techobjects
