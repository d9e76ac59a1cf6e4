#include "tomc/drives/profinet_drive.hpp"

#include <algorithm>
#include <cstring>

namespace tomc::drives {

namespace {

std::uint16_t frame_bytes(std::uint16_t telegram, telegrams::Direction direction) {
  const auto codec = telegrams::TelegramCodec::create(telegram, direction);
  return codec ? static_cast<std::uint16_t>(codec->frame_size()) : 0;
}

profinet::DeviceIdentity with_modules(profinet::DeviceIdentity identity, std::uint16_t telegram) {
  identity.modules.clear();
  for (const profinet::ExpectedModule& module : profidrive_modules(telegram)) {
    profinet::DeviceModule real{module.slot, module.ident, {}};
    for (const profinet::ExpectedSubmodule& sub : module.submodules) {
      real.submodules.push_back({sub.subslot, sub.ident, sub.direction, sub.input_length, sub.output_length});
    }
    identity.modules.push_back(real);
  }
  return identity;
}

}  // namespace

std::vector<profinet::ExpectedModule> profidrive_modules(std::uint16_t telegram) {
  return {{0, 0, kDapIdent, {{1, kDapIdent, profinet::SubmoduleDirection::kNoIo, 0, 0}}},
          {0,
           kDriveObjectSlot,
           kDriveObjectIdent,
           {{kTelegramSubslot, telegram_submodule_ident(telegram), profinet::SubmoduleDirection::kInputOutput,
             frame_bytes(telegram, telegrams::Direction::kActual),
             frame_bytes(telegram, telegrams::Direction::kSetpoint)}}}};
}

ProfinetDrive::ProfinetDrive(profinet::DeviceIdentity identity, const DeviceConfig& config,
                             const SimulatedDriveParameters& parameters)
    : device_(with_modules(std::move(identity), config.drive_telegram)),
      drive_(config, parameters),
      setpoint_(make_frames(config, telegrams::Direction::kSetpoint)),
      actual_(make_frames(config, telegrams::Direction::kActual)) {
  if (auto codec = telegrams::TelegramCodec::create(config.drive_telegram, telegrams::Direction::kSetpoint,
                                                    config.codec)) {
    setpoint_codec_ = *codec;
  }
}

bool ProfinetDrive::follow_controller() noexcept {
  const auto received = device_.output_data(kDriveObjectSlot, kTelegramSubslot);
  if (device_.state() != profinet::ArState::kRunning || received.size() != setpoint_codec_.frame_size() ||
      !setpoint_codec_.carries(telegrams::Signal::STW2)) {
    return false;
  }
  telegrams::SetpointSignals signals{};
  if (setpoint_codec_.decode(std::as_bytes(received), signals) != telegrams::TelegramError::kNone)
    return false;
  const auto master = static_cast<std::uint8_t>(signals.STW2.field(telegrams::kSignOfLifeField));
  if (master == 0 || master == master_sign_of_life_) return false;
  master_sign_of_life_ = master;
  cycle();
  return true;
}

void ProfinetDrive::cycle() noexcept {
  const auto received = device_.output_data(kDriveObjectSlot, kTelegramSubslot);
  Frame& setpoint = setpoint_[Slot::kDrive];
  if (device_.state() == profinet::ArState::kRunning &&
      device_.output_iops(kDriveObjectSlot, kTelegramSubslot) == profinet::kIoxsGood &&
      received.size() == setpoint.length) {
    std::memcpy(setpoint.bytes.data(), received.data(), received.size());
    drive_.write_setpoint(setpoint_);
  }
  if (drive_.read_actual(actual_)) {
    const auto input = device_.input_data(kDriveObjectSlot, kTelegramSubslot);
    const Frame& actual = actual_[Slot::kDrive];
    if (input.size() == actual.length) std::memcpy(input.data(), actual.bytes.data(), input.size());
  }
}

}  // namespace tomc::drives
