#pragma once
// A simulated PROFIdrive drive behind a PROFINET IO device: the device emulator of the PROFINET tests
// (docs/profinet-gateway.md). The device has a DAP (slot 0, subslot 1) and a drive object (slot 1) whose
// telegram submodule (subslot 2) carries the drive's setpoint and actual telegram; the telegram number is in
// the submodule's ident, so a controller configured for another telegram gets a ModuleDiffBlock.

#include <vector>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/profinet/io_device.hpp"
#include "tomc/telegrams/codec.hpp"

namespace tomc::drives {

inline constexpr std::uint32_t kDapIdent = 0x00000001;
inline constexpr std::uint32_t kDriveObjectIdent = 0x00000100;
inline constexpr std::uint16_t kDriveObjectSlot = 1;
inline constexpr std::uint16_t kTelegramSubslot = 2;
constexpr std::uint32_t telegram_submodule_ident(std::uint16_t telegram) noexcept {
  return 0x00010000u + telegram;
}

// The modules a controller expects for a drive on `telegram` (the same the emulator has).
std::vector<profinet::ExpectedModule> profidrive_modules(std::uint16_t telegram);

class ProfinetDrive {
 public:
  // identity: name, IP, MAC, IDs; its modules are replaced by the drive's. config.drive_telegram only (no
  // supplementary or encoder telegrams behind PROFINET yet). The drive object answers PROFIdrive base-mode
  // parameter requests (record index 0xB02E, any subslot of its slot) for p0922 (the telegram, Unsigned16)
  // and p2000 (the reference speed, FloatingPoint); any other parameter gets error value 0 (impermissible
  // parameter number).
  ProfinetDrive(profinet::DeviceIdentity identity, const DeviceConfig& config,
                const SimulatedDriveParameters& parameters);
  ProfinetDrive(const ProfinetDrive&) = delete;  // the record handlers refer to this object
  ProfinetDrive& operator=(const ProfinetDrive&) = delete;

  profinet::IoDevice& device() noexcept { return device_; }
  // p0922 as the drive answers it (default: its telegram). A drive reconfigured to another telegram without
  // changing its GSDML module answers the new number, which the gateway's start-up check must refuse.
  void set_p0922(std::uint16_t telegram) noexcept { telegram_ = telegram; }
  SimulatedDrive& drive() noexcept { return drive_; }

  // One drive cycle: while the AR runs and the controller's provider state (IOPS) is GOOD, the received
  // setpoint telegram goes to the drive (otherwise the drive gets none and ends in F08501 after its timeout,
  // as a real one); the drive's actual telegram goes into the input image. No allocation.
  void cycle() noexcept;
  // Isochronous operation: the drive application runs once per master application cycle, i.e. when the
  // controller's sign-of-life in STW2 (bits 12-15, spec 06 §5) has advanced since the last cycle. Call it for
  // every received output frame; it runs cycle() and returns true then. Telegrams without STW2, or a
  // controller that does not count (0), never advance it: such a drive runs cycle() on its own clock.
  bool follow_controller() noexcept;

 private:
  profinet::IoDevice device_;
  SimulatedDrive drive_;
  DeviceFrames setpoint_;
  DeviceFrames actual_;
  telegrams::TelegramCodec setpoint_codec_;
  std::uint8_t master_sign_of_life_ = 0;
  std::uint16_t telegram_ = 0;
  double reference_speed_rpm_ = 0.0;
  std::vector<std::uint8_t> parameter_response_;  // the answer to the last parameter request, read once
};

}  // namespace tomc::drives
