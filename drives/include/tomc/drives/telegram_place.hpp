#pragma once
// Where a PROFIdrive device carries the telegram of each contract slot (docs/gateway.md §2): the layout of
// the emulated drive (drives/profinet) and the default of `tomc gateway`'s file (one function for both). The
// drive object is in slot 1 with the drive telegram in subslot 2 and telegram 750 in subslot 3; an encoder
// object per separately connected encoder follows it (slots 2 and 3), or starts at slot 1 in an encoder-only
// device; an encoder's telegram is in its subslot 2.

#include <cstdint>

#include "tomc/drives/drive_adapter.hpp"

namespace tomc::drives {

inline constexpr std::uint16_t kDriveObjectSlot = 1;
inline constexpr std::uint16_t kTelegramSubslot = 2;
inline constexpr std::uint16_t kSupplementarySubslot = 3;

struct TelegramPlace {
  std::uint16_t slot = 0;
  std::uint16_t subslot = 0;
  friend bool operator==(const TelegramPlace&, const TelegramPlace&) = default;
};

// Slot 0 when the configuration has no telegram in `slot`.
inline TelegramPlace telegram_place(const DeviceConfig& config, Slot slot) noexcept {
  if (config.telegram(slot) == 0) return {};
  const auto first_encoder = static_cast<std::uint16_t>(config.drive_telegram != 0 ? 2 : 1);
  switch (slot) {
    case Slot::kDrive:
      return {kDriveObjectSlot, kTelegramSubslot};
    case Slot::kSupplementary:
      return {kDriveObjectSlot, kSupplementarySubslot};
    case Slot::kEncoder1:
      return {first_encoder, kTelegramSubslot};
    case Slot::kEncoder2:
      return {static_cast<std::uint16_t>(first_encoder + 1), kTelegramSubslot};
  }
  return {};
}

}  // namespace tomc::drives
