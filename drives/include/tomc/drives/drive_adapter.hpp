#pragma once
// The one interface between technology objects and drives (ARCHITECTURE-GUIDE §5): raw PROFIdrive frames,
// exchanged once per servo cycle. A simulated drive and a real one behind a gateway look identical here.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "tomc/telegrams/codec.hpp"

namespace tomc::drives {

// The telegrams of one device as a technology object connects them (spec 01 §3.3): the drive telegram, the
// supplementary torque telegram 750, and up to two separately connected encoder telegrams (81/83).
enum class Slot : std::uint8_t { kDrive, kSupplementary, kEncoder1, kEncoder2 };
inline constexpr std::size_t kSlotCount = 4;

struct Frame {
  std::array<std::byte, telegrams::kMaxFrameBytes> bytes{};
  std::uint8_t length = 0;  // 0 = slot not used

  std::span<std::byte> view() noexcept { return {bytes.data(), length}; }
  std::span<const std::byte> view() const noexcept { return {bytes.data(), length}; }
};

struct DeviceFrames {
  std::array<Frame, kSlotCount> slots{};
  Frame& operator[](Slot s) noexcept { return slots[static_cast<std::size_t>(s)]; }
  const Frame& operator[](Slot s) const noexcept { return slots[static_cast<std::size_t>(s)]; }
};

struct DeviceConfig {
  std::uint16_t drive_telegram = 0;                  // 1..6, 102, 103, 105, 106; 0 = encoder-only device
  std::uint16_t supplementary_telegram = 0;          // 0 or 750
  std::array<std::uint16_t, 2> encoder_telegrams{};  // 0, 81 or 83 each
  telegrams::CodecOptions codec{};

  std::uint16_t telegram(Slot s) const noexcept;
};

// The shared codecs of a device's slots (TelegramCodec::shared), one per direction; an unused slot (or a
// telegram the codec rejects: validate() names it) holds TelegramCodec::empty(), whose frame_size() is 0.
// Both ends of the link use it: the technology object's DriveConnection and the simulated drives.
struct DeviceCodecs {
  std::array<const telegrams::TelegramCodec*, kSlotCount> setpoint{};
  std::array<const telegrams::TelegramCodec*, kSlotCount> actual{};

  DeviceCodecs() noexcept;  // every slot unused
  explicit DeviceCodecs(const DeviceConfig& config) noexcept;
  const telegrams::TelegramCodec& operator()(telegrams::Direction d, Slot s) const noexcept {
    return *(d == telegrams::Direction::kSetpoint ? setpoint : actual)[static_cast<std::size_t>(s)];
  }
};

// Empty when the configuration is usable, else one line naming the problem (e.g. "drive_telegram: 104 ...").
std::string validate(const DeviceConfig& config);

// Frames sized for the configured telegrams (length set per slot, bytes zero).
DeviceFrames make_frames(const DeviceConfig& config, telegrams::Direction direction);

struct LinkHealth {
  bool up = false;                       // a fresh actual frame arrived within the adapter's tolerance
  std::uint32_t consecutive_missed = 0;  // servo cycles in a row without a fresh actual frame
  std::uint64_t missed_total = 0;
  std::uint64_t exchanges = 0;
  // Restarts of the link partner seen so far (e.g. a gateway that came back with a new incarnation): the
  // exchange was broken even if no cycle went without a frame, and the drive connection treats it as a link
  // loss (docs/gateway.md).
  std::uint32_t peer_restarts = 0;
};

class DriveAdapter {
 public:
  virtual ~DriveAdapter() = default;

  virtual const DeviceConfig& config() const noexcept = 0;
  // Start of MC_Servo. Copies the newest actual frames into `actual` and returns true; returns false and
  // leaves `actual` unchanged when nothing fresh arrived for this cycle.
  virtual bool read_actual(DeviceFrames& actual) noexcept = 0;
  // End of MC_Servo: this cycle's setpoint frames.
  virtual void write_setpoint(const DeviceFrames& setpoint) noexcept = 0;
  virtual LinkHealth link_health() const noexcept = 0;
};

}  // namespace tomc::drives
