// Telegram layouts, spec 06 §2.1–§2.15. One row per telegram and direction: (signal, byte offset) in PZD
// order.
#include "tomc/telegrams/layout.hpp"

#include <algorithm>
#include <initializer_list>

#include "layout_table.hpp"

namespace tomc::telegrams {
using detail::kLayouts;
using detail::kSupported;

bool TelegramLayout::carries(Signal signal) const noexcept {
  return offset_of(signal) >= 0;
}

int TelegramLayout::offset_of(Signal signal) const noexcept {
  for (const auto& f : fields()) {
    if (f.signal == signal) return f.offset;
  }
  return -1;
}

std::span<const std::uint16_t> supported_telegrams() noexcept {
  return kSupported;
}

bool is_drive_telegram(int telegram) noexcept {
  return (telegram >= 1 && telegram <= 6) || telegram == 102 || telegram == 103 || telegram == 105 ||
         telegram == 106;
}
bool is_encoder_telegram(int telegram) noexcept {
  return telegram == 81 || telegram == 83;
}
bool is_supplementary_telegram(int telegram) noexcept {
  return telegram == 750;
}

Result<TelegramLayout> find_layout(int telegram, Direction direction) noexcept {
  if (telegram == 104) return TelegramError::kTelegram104NotDefined;
  const auto* it = std::find_if(std::begin(kLayouts), std::end(kLayouts), [&](const TelegramLayout& l) {
    return l.telegram == telegram && l.direction == direction;
  });
  if (it == std::end(kLayouts)) return TelegramError::kUnknownTelegram;
  return *it;
}

}  // namespace tomc::telegrams
