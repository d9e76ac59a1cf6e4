// Straight-line codec routines: each layout of layout_table.hpp is resolved into (frame offset, value offset,
// width) triples at compile time and unrolled, so a telegram 3 actual frame is six fixed loads, byte swaps
// and stores with no per-field loop, width test or byte-order switch in the cycle (decision O4).
#include "routines.hpp"

#include <array>
#include <cstddef>
#include <iterator>
#include <utility>

#include "field_moves.hpp"
#include "layout_table.hpp"

namespace tomc::telegrams::detail {
namespace {

constexpr std::size_t kLayoutCount = std::size(kLayouts);
constexpr std::size_t kByteOrders = static_cast<std::size_t>(ByteOrder::kLittle) + 1;
constexpr std::array<std::uint8_t, 3> kNistBOffsets{4, 8, 12};  // spec 06 §2.13

// The NIST_B offset the layout is built with: telegram 83's actual frame has three, every other layout one.
constexpr std::uint8_t nist_b_of(std::size_t layout, std::size_t n) {
  const TelegramLayout& l = kLayouts[layout];
  return l.telegram == 83 && l.direction == Direction::kActual ? kNistBOffsets[n] : 0;
}

template <std::size_t kLayout, std::uint8_t kNistB>
constexpr auto compiled_fields() {
  constexpr TelegramLayout layout = with_nist_b_offset(kLayouts[kLayout], kNistB);
  std::array<CompiledField, layout.field_count> fields{};
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const FieldLayout& f = layout.field_table[i];
    fields[i] = CompiledField{f.offset, value_offset(f.signal), wire_bytes(f.signal)};
  }
  return fields;
}

template <ByteOrder kOrder, std::size_t kLayout, std::uint8_t kNistB>
void encode_fixed(const void* values, std::byte* frame) noexcept {
  static constexpr auto kFields = compiled_fields<kLayout, kNistB>();
  const auto* base = static_cast<const unsigned char*>(values);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (encode_field<kOrder>(kFields[I], base, frame), ...);
  }
  (std::make_index_sequence<kFields.size()>{});
}

template <ByteOrder kOrder, std::size_t kLayout, std::uint8_t kNistB>
void decode_fixed(const std::byte* frame, void* values) noexcept {
  static constexpr auto kFields = compiled_fields<kLayout, kNistB>();
  auto* base = static_cast<unsigned char*>(values);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (decode_field<kOrder>(kFields[I], frame, base), ...);
  }
  (std::make_index_sequence<kFields.size()>{});
}

using NistRow = std::array<Routines, kNistBOffsets.size()>;
using LayoutRow = std::array<NistRow, kByteOrders>;

template <std::size_t kLayout, std::size_t kOrder>
constexpr NistRow nist_row() {
  constexpr auto order = static_cast<ByteOrder>(kOrder);
  return [&]<std::size_t... N>(std::index_sequence<N...>) {
    return NistRow{Routines{&encode_fixed<order, kLayout, nist_b_of(kLayout, N)>,
                            &decode_fixed<order, kLayout, nist_b_of(kLayout, N)>}...};
  }
  (std::make_index_sequence<kNistBOffsets.size()>{});
}

template <std::size_t kLayout>
constexpr LayoutRow layout_row() {
  return [&]<std::size_t... O>(std::index_sequence<O...>) {
    return LayoutRow{nist_row<kLayout, O>()...};
  }
  (std::make_index_sequence<kByteOrders>{});
}

constexpr auto kRoutines = []<std::size_t... L>(std::index_sequence<L...>) {
  return std::array<LayoutRow, kLayoutCount>{layout_row<L>()...};
}
(std::make_index_sequence<kLayoutCount>{});

}  // namespace

Routines find_routines(int telegram, Direction direction, ByteOrder order,
                       std::uint8_t nist_b_offset) noexcept {
  const auto o = static_cast<std::size_t>(order);
  if (o >= kByteOrders) return {};
  for (std::size_t l = 0; l < kLayoutCount; ++l) {
    if (kLayouts[l].telegram != telegram || kLayouts[l].direction != direction) continue;
    std::size_t n = 0;
    while (n + 1 < kNistBOffsets.size() && kNistBOffsets[n] != nist_b_offset)
      ++n;
    return kRoutines[l][o][n];
  }
  return {};
}

}  // namespace tomc::telegrams::detail
