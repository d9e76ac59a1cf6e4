#pragma once
// Between tomc's frames and the contract's samples (idl/tomc_gateway.idl, docs/gateway.md): byte order, the
// slot order, and the check that a received device entry carries exactly the telegrams a device is configured
// with. Both sides of the contract use these, so the controller and the gateway simulator agree by
// construction.

#include <cstdint>
#include <optional>
#include <string>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc_gateway.h"

namespace tomc::drives::dds {

inline constexpr std::uint32_t kContractVersion = gateway::GATEWAY_CONTRACT_VERSION;
inline constexpr std::size_t kMaxDevices = gateway::MAX_DEVICES_PER_SAMPLE;
inline constexpr std::size_t kMaxNameLength = 63;  // string<63> in the IDL

gateway::ByteOrder to_contract(telegrams::ByteOrder order) noexcept;
std::optional<telegrams::ByteOrder> from_contract(gateway::ByteOrder order) noexcept;

// The telegram numbers of the four slots, in the contract's slot order (SLOT_DRIVE ... SLOT_ENCODER2).
std::array<std::uint16_t, kSlotCount> slot_telegrams(const DeviceConfig& config) noexcept;

// Copies the used slots of `frames` into `slots` (number and PZD bytes); unused slots get number 0 and no
// bytes. The vectors keep their capacity: filling the same sample again does not allocate.
void fill(const DeviceConfig& config, const DeviceFrames& frames,
          std::array<gateway::Telegram, kSlotCount>& slots) noexcept;

// Empty when `slots` (in `byte_order`) carries exactly the telegrams of `config` in `direction` with the
// telegram's length, else the first difference ("slot drive: telegram 2, expected 3"). Then the entry must
// not be used: bytes of another telegram or byte order read as wrong values.
std::string mismatch(const DeviceConfig& config, telegrams::Direction direction,
                     gateway::ByteOrder byte_order, const std::array<gateway::Telegram, kSlotCount>& slots);
// The same check without building a message: for the cyclic paths.
bool matches(const DeviceConfig& config, telegrams::Direction direction, gateway::ByteOrder byte_order,
             const std::array<gateway::Telegram, kSlotCount>& slots) noexcept;

// Copies a checked entry into frames (lengths as configured). Call only when matches() holds.
void extract(const std::array<gateway::Telegram, kSlotCount>& slots, DeviceFrames& frames) noexcept;

// "drive", "supplementary", "encoder1", "encoder2".
const char* slot_name(std::size_t slot) noexcept;

}  // namespace tomc::drives::dds
