#pragma once
// The telegram-specific codec routines (decision O4): one straight-line encode and decode per standard
// layout, byte order and (telegram 83 actual) NIST_B offset, unrolled at compile time from layout_table.hpp.
// Private to the telegrams library; TelegramCodec::create() picks one, the cycle calls it through one
// pointer.

#include <cstdint>

#include "tomc/telegrams/byte_order.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams::detail {

struct Routines {
  EncodeRoutine encode = nullptr;
  DecodeRoutine decode = nullptr;
};

// Both null when (telegram, direction) is not a standard layout. `nist_b_offset` only matters for telegram
// 83's actual frame (4, 8 or 12; create() has checked it).
Routines find_routines(int telegram, Direction direction, ByteOrder order,
                       std::uint8_t nist_b_offset) noexcept;

}  // namespace tomc::telegrams::detail
