#pragma once
// A simulated PROFIdrive drive behind a PROFINET IO device: the device emulator of the PROFINET tests
// (docs/profinet-gateway.md). The device has a DAP (slot 0, subslot 1), a drive object (slot 1) whose
// telegram submodule (subslot 2) carries the drive telegram and, with telegram 750, a supplementary telegram
// submodule (subslot 3), and an encoder object per separately connected encoder (telegram 81/83 in its
// subslot 2; slot 2 and 3 behind a drive object, slot 1 and 2 in an encoder-only device). Every telegram
// submodule's ident is 0x10000 + telegram, so a controller configured for another telegram gets a
// ModuleDiffBlock.

#include <array>
#include <vector>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/drives/telegram_place.hpp"
#include "tomc/profinet/io_device.hpp"
#include "tomc/profinet/parameter_access.hpp"
#include "tomc/telegrams/codec.hpp"

namespace tomc::drives {

inline constexpr std::uint32_t kDapIdent = 0x00000001;
inline constexpr std::uint32_t kDriveObjectIdent = 0x00000100;
inline constexpr std::uint32_t kEncoderObjectIdent = 0x00000200;
// The DAP submodule's parameter record (its GSDML ParameterRecordDataItem, decision I34): version 0x0001 and
// the drive's setpoint timeout in cycles (Unsigned16, default 20).
inline constexpr std::uint16_t kMonitoringRecordIndex = 0x0100;
constexpr std::uint32_t telegram_submodule_ident(std::uint16_t telegram) noexcept {
  return 0x00010000u + telegram;
}

// The modules a controller expects for the emulated device of `config` (the same the emulator has); the
// second form for a drive telegram alone.
std::vector<profinet::ExpectedModule> profidrive_modules(const DeviceConfig& config);
std::vector<profinet::ExpectedModule> profidrive_modules(std::uint16_t telegram);

class ProfinetDrive {
 public:
  // identity: name, IP, MAC, IDs; its modules are replaced by the device's (profidrive_modules(config)).
  // Each object answers PROFIdrive base-mode parameter requests (record index 0xB02E, any subslot of its
  // slot) for p0922 (its telegram, Unsigned16: the drive telegram of the drive object, the encoder telegram
  // of an encoder object) and p2000 (the reference speed, FloatingPoint); any other parameter gets error
  // value 0 (impermissible parameter number). Change requests: p2000 of the drive object (6..210000 rpm,
  // else error 0x02; the drive's speed scaling follows it), p0922 refused as read-only (error 0x01).
  // The DAP submodule (slot 0, subslot 1) takes record kMonitoringRecordIndex (write_monitoring_record).
  ProfinetDrive(profinet::DeviceIdentity identity, const DeviceConfig& config,
                const SimulatedDriveParameters& parameters);
  ProfinetDrive(const ProfinetDrive&) = delete;  // the record handlers refer to this object
  ProfinetDrive& operator=(const ProfinetDrive&) = delete;

  profinet::IoDevice& device() noexcept { return device_; }
  // p0922 as the drive object answers it (default: its telegram). A drive reconfigured to another telegram
  // without changing its GSDML module answers the new number, which the gateway's start-up check must refuse.
  void set_p0922(std::uint16_t telegram) noexcept { telegram_ = telegram; }
  SimulatedDrive& drive() noexcept { return drive_; }
  // How many monitoring records (kMonitoringRecordIndex) the device took.
  int monitoring_records() const noexcept { return monitoring_records_; }
  // The submodule that carries the master sign-of-life: the drive telegram's, or encoder 1's in an
  // encoder-only device.
  TelegramPlace master_place() const noexcept { return places_[master_slot_]; }
  // The AR runs and the controller's provider state (IOPS) of every telegram submodule is GOOD.
  bool outputs_valid() const noexcept;

  // One drive cycle: while outputs_valid(), the received setpoint telegrams go to the drive (otherwise the
  // drive gets none and ends in F08501 after its timeout, as a real one); the drive's actual telegrams go
  // into the input image. No allocation.
  void cycle() noexcept;
  // Isochronous operation: the drive application runs once per master application cycle, i.e. when the
  // controller's sign-of-life (STW2 or STW2_ENC bits 12-15, spec 06 §5) has advanced since the last cycle.
  // Call it for every received output frame; it runs cycle() and returns true then. Telegrams without it, or
  // a controller that does not count (0), never advance it: such a drive runs cycle() on its own clock.
  bool follow_controller() noexcept;

 private:
  profinet::PnioStatus write_monitoring_record(std::span<const std::uint8_t> data);
  std::uint16_t object_telegram(std::uint16_t slot) const noexcept;  // p0922 of the object in slot; 0: none
  profinet::ParameterResponse read_parameters(const profinet::ParameterRequest& request,
                                              std::uint16_t slot) const;
  profinet::ParameterResponse change_parameters(const profinet::ParameterRequest& request,
                                                std::uint16_t slot);

  profinet::IoDevice device_;
  SimulatedDrive drive_;
  DeviceFrames setpoint_;
  DeviceFrames actual_;
  std::array<TelegramPlace, kSlotCount> places_{};
  std::size_t master_slot_ = 0;
  telegrams::TelegramCodec master_codec_;  // setpoint codec of the master slot
  std::uint8_t master_sign_of_life_ = 0;
  std::uint16_t telegram_ = 0;
  DeviceConfig config_;
  double reference_speed_rpm_ = 0.0;
  std::vector<std::uint8_t> parameter_response_;  // the answer to the last parameter request, read once
  int monitoring_records_ = 0;
};

}  // namespace tomc::drives
