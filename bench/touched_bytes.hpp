#pragma once
// Data touched per axis-cycle (issue 23): a callgrind workload run with the argument `touched` routes its
// phases through touched_phase(), which brackets the counted function with two stores to a marker.
// bench/touched_bytes.py runs the program under valgrind's lackey (--trace-mem=yes) and counts the distinct
// bytes and 64-byte cache lines loaded or stored between the markers of the last cycle (MC_Servo +
// MC_Interpolator), split into stack and the rest (the TO, its codec, its frames).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::bench {

// Each store opens or closes a counted phase; its address is printed for the script.
inline volatile std::uint64_t touched_marker = 0;

constexpr int kTouchedCycles = 8;  // after the machine's set-up: the last of these is the measured cycle

// True with the argument `touched`; then the marker's address goes to stdout first (the script reads it
// there).
inline bool touched_mode(int argc, char** argv) noexcept {
  if (argc < 2 || std::string_view(argv[1]) != "touched") return false;
  std::printf("marker=%p\n", static_cast<const volatile void*>(&touched_marker));
  std::fflush(stdout);
  return true;
}

// The first axis' object, for the script's split of the lines inside and outside it (decision O4: which of
// the TO's own members the cycle touches). Printed only in touched mode.
inline void touched_object(bool touched, const void* object, std::size_t size) noexcept {
  if (!touched) return;
  std::printf("object=%p size=%zu\n", object, size);
  std::fflush(stdout);
}

template <typename Group>
void touched_phase(Group& group, const techobjects::CycleClock& clock, int phase) noexcept {
  touched_marker = touched_marker + 1;  // open
  group.run(clock, phase);
  touched_marker = touched_marker + 1;  // close
}

}  // namespace tomc::bench
