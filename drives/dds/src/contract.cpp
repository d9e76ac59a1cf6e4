// Frames <-> contract samples (contract.hpp).
#include "tomc/drives/dds/contract.hpp"

#include <cstring>

#include "tomc/telegrams/layout.hpp"

namespace tomc::drives::dds {

namespace tg = tomc::telegrams;

gateway::ByteOrder to_contract(tg::ByteOrder order) noexcept {
  switch (order) {
    case tg::ByteOrder::kBig:
      return gateway::BYTE_ORDER_BIG;
    case tg::ByteOrder::kLittleBytes:
      return gateway::BYTE_ORDER_LITTLE_BYTES;
    case tg::ByteOrder::kSwappedWords:
      return gateway::BYTE_ORDER_SWAPPED_WORDS;
    case tg::ByteOrder::kLittle:
      return gateway::BYTE_ORDER_LITTLE;
  }
  return gateway::BYTE_ORDER_BIG;
}

std::optional<tg::ByteOrder> from_contract(gateway::ByteOrder order) noexcept {
  switch (order) {
    case gateway::BYTE_ORDER_BIG:
      return tg::ByteOrder::kBig;
    case gateway::BYTE_ORDER_LITTLE_BYTES:
      return tg::ByteOrder::kLittleBytes;
    case gateway::BYTE_ORDER_SWAPPED_WORDS:
      return tg::ByteOrder::kSwappedWords;
    case gateway::BYTE_ORDER_LITTLE:
      return tg::ByteOrder::kLittle;
  }
  return std::nullopt;  // a value outside the enum, from a malformed sample
}

std::array<std::uint16_t, kSlotCount> slot_telegrams(const DeviceConfig& config) noexcept {
  std::array<std::uint16_t, kSlotCount> t{};
  for (std::size_t i = 0; i < kSlotCount; ++i)
    t[i] = config.telegram(static_cast<Slot>(i));
  return t;
}

const char* slot_name(std::size_t slot) noexcept {
  static constexpr const char* kNames[] = {"drive", "supplementary", "encoder1", "encoder2"};
  return slot < kSlotCount ? kNames[slot] : "?";
}

void fill(const DeviceConfig& config, const DeviceFrames& frames,
          std::array<gateway::Telegram, kSlotCount>& slots) noexcept {
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    const auto number = config.telegram(static_cast<Slot>(i));
    const Frame& f = frames.slots[i];
    slots[i].number(number);
    auto& pzd = slots[i].pzd();
    const std::size_t length = number == 0 ? 0 : f.length;
    pzd.resize(length);  // within the capacity reserved at set-up: no allocation
    if (length != 0) std::memcpy(pzd.data(), f.bytes.data(), length);
  }
}

namespace {

// The first difference as codes, so that the cyclic check and the message share one rule.
struct Difference {
  enum Kind : std::uint8_t { kNone, kByteOrder, kTelegram, kLength } kind = kNone;
  std::size_t slot = 0;
  std::size_t expected = 0;
  std::size_t got = 0;
};

Difference compare(const DeviceConfig& config, tg::Direction direction, gateway::ByteOrder byte_order,
                   const std::array<gateway::Telegram, kSlotCount>& slots) noexcept {
  const auto order = from_contract(byte_order);
  if (!order || *order != config.codec.byte_order) {
    return {Difference::kByteOrder, 0, static_cast<std::size_t>(config.codec.byte_order),
            static_cast<std::size_t>(byte_order)};
  }
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    const std::uint16_t expected = config.telegram(static_cast<Slot>(i));
    if (slots[i].number() != expected) return {Difference::kTelegram, i, expected, slots[i].number()};
    std::size_t length = 0;
    if (expected != 0) {
      const auto layout = tg::find_layout(expected, direction);
      length = layout ? layout->length : 0;
    }
    if (slots[i].pzd().size() != length) return {Difference::kLength, i, length, slots[i].pzd().size()};
  }
  return {};
}

}  // namespace

bool matches(const DeviceConfig& config, tg::Direction direction, gateway::ByteOrder byte_order,
             const std::array<gateway::Telegram, kSlotCount>& slots) noexcept {
  return compare(config, direction, byte_order, slots).kind == Difference::kNone;
}

std::string mismatch(const DeviceConfig& config, tg::Direction direction, gateway::ByteOrder byte_order,
                     const std::array<gateway::Telegram, kSlotCount>& slots) {
  const Difference d = compare(config, direction, byte_order, slots);
  switch (d.kind) {
    case Difference::kNone:
      return {};
    case Difference::kByteOrder: {
      const auto got = from_contract(byte_order);
      return "byte order " +
             (got ? std::string(tg::to_string(*got)) : "invalid (" + std::to_string(d.got) + ")") +
             ", expected " + std::string(tg::to_string(config.codec.byte_order));
    }
    case Difference::kTelegram:
      return std::string("slot ") + slot_name(d.slot) + ": telegram " + std::to_string(d.got) +
             ", expected " + std::to_string(d.expected);
    case Difference::kLength:
      return std::string("slot ") + slot_name(d.slot) + ": " + std::to_string(d.got) +
             " PZD bytes, expected " + std::to_string(d.expected);
  }
  return "?";
}

void extract(const std::array<gateway::Telegram, kSlotCount>& slots, DeviceFrames& frames) noexcept {
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    const auto& pzd = slots[i].pzd();
    const std::size_t length = pzd.size() <= tg::kMaxFrameBytes ? pzd.size() : 0;
    frames.slots[i].length = static_cast<std::uint8_t>(length);
    if (length != 0) std::memcpy(frames.slots[i].bytes.data(), pzd.data(), length);
  }
}

}  // namespace tomc::drives::dds
