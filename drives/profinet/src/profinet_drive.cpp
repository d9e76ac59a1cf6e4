#include "tomc/drives/profinet_drive.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "tomc/profinet/parameter_access.hpp"

namespace tomc::drives {

namespace {

std::uint16_t frame_bytes(std::uint16_t telegram, telegrams::Direction direction) {
  const auto codec = telegrams::TelegramCodec::create(telegram, direction);
  return codec ? static_cast<std::uint16_t>(codec->frame_size()) : 0;
}

profinet::ExpectedSubmodule telegram_submodule(std::uint16_t subslot, std::uint16_t telegram) {
  return {subslot, telegram_submodule_ident(telegram), profinet::SubmoduleDirection::kInputOutput,
          frame_bytes(telegram, telegrams::Direction::kActual),
          frame_bytes(telegram, telegrams::Direction::kSetpoint)};
}

profinet::DeviceIdentity with_modules(profinet::DeviceIdentity identity, const DeviceConfig& config) {
  identity.modules.clear();
  for (const profinet::ExpectedModule& module : profidrive_modules(config)) {
    profinet::DeviceModule real{module.slot, module.ident, {}};
    for (const profinet::ExpectedSubmodule& sub : module.submodules) {
      real.submodules.push_back({sub.subslot, sub.ident, sub.direction, sub.input_length, sub.output_length});
    }
    identity.modules.push_back(real);
  }
  return identity;
}

}  // namespace

std::vector<profinet::ExpectedModule> profidrive_modules(const DeviceConfig& config) {
  std::vector<profinet::ExpectedModule> modules{
      {0, 0, kDapIdent, {{1, kDapIdent, profinet::SubmoduleDirection::kNoIo, 0, 0}}}};
  if (config.drive_telegram != 0) {
    profinet::ExpectedModule drive{0, kDriveObjectSlot, kDriveObjectIdent, {}};
    drive.submodules.push_back(telegram_submodule(kTelegramSubslot, config.drive_telegram));
    if (config.supplementary_telegram != 0)
      drive.submodules.push_back(telegram_submodule(kSupplementarySubslot, config.supplementary_telegram));
    modules.push_back(std::move(drive));
  }
  for (const Slot slot : {Slot::kEncoder1, Slot::kEncoder2}) {
    if (config.telegram(slot) == 0) continue;
    const TelegramPlace place = telegram_place(config, slot);
    modules.push_back(
        {0, place.slot, kEncoderObjectIdent, {telegram_submodule(place.subslot, config.telegram(slot))}});
  }
  return modules;
}

std::vector<profinet::ExpectedModule> profidrive_modules(std::uint16_t telegram) {
  DeviceConfig config;
  config.drive_telegram = telegram;
  return profidrive_modules(config);
}

ProfinetDrive::ProfinetDrive(profinet::DeviceIdentity identity, const DeviceConfig& config,
                             const SimulatedDriveParameters& parameters)
    : device_(with_modules(std::move(identity), config)),
      drive_(config, parameters),
      setpoint_(make_frames(config, telegrams::Direction::kSetpoint)),
      actual_(make_frames(config, telegrams::Direction::kActual)),
      config_(config) {
  for (std::size_t s = 0; s < kSlotCount; ++s)
    places_[s] = telegram_place(config, static_cast<Slot>(s));
  master_slot_ = static_cast<std::size_t>(config.drive_telegram != 0 ? Slot::kDrive : Slot::kEncoder1);
  if (auto codec = telegrams::TelegramCodec::create(config.telegram(static_cast<Slot>(master_slot_)),
                                                    telegrams::Direction::kSetpoint, config.codec)) {
    master_codec_ = *codec;
  }
  telegram_ = config.drive_telegram;
  reference_speed_rpm_ = parameters.reference_speed_rpm;
  namespace pn = profinet;
  // The telegram of the object in `slot` (p0922): the drive object's, an encoder object's; 0 = no object.
  const auto object_telegram = [this](std::uint16_t slot) -> std::uint16_t {
    if (slot == kDriveObjectSlot && config_.drive_telegram != 0) return telegram_;
    for (const Slot s : {Slot::kEncoder1, Slot::kEncoder2}) {
      if (places_[static_cast<std::size_t>(s)].slot == slot) return config_.telegram(s);
    }
    return 0;
  };
  // PNIOStatus of a refused record access: ErrorCode 0xDF (write) / 0xDE (read), ErrorDecode 0x80 (PNIORW),
  // ErrorCode1 0xB0 (access: invalid index) or 0xB8 (invalid parameter / no request pending).
  device_.set_write_handler([this, object_telegram](const pn::RecordHeader& header,
                                                    std::span<const std::uint8_t> data) {
    const std::uint16_t telegram = object_telegram(header.slot);
    if (telegram == 0 || header.index != pn::kParameterAccessIndex)
      return pn::PnioStatus{0xDF, 0x80, 0xB0, 0x00};
    const auto request = pn::decode_parameter_request(data);
    if (!request) return pn::PnioStatus{0xDF, 0x80, 0xB8, 0x00};
    pn::ParameterResponse response{request->reference, pn::parameter_response_id::kReadOk, request->axis, {}};
    for (const pn::ParameterAddress& p : request->parameters) {
      if (p.attribute == 0x10 && p.number == 922) {
        response.parameters.push_back({pn::parameter_format::kUnsigned16, {telegram}});
      } else if (p.attribute == 0x10 && p.number == 2000) {
        response.parameters.push_back(
            {pn::parameter_format::kFloatingPoint,
             {std::bit_cast<std::uint32_t>(static_cast<float>(reference_speed_rpm_))}});
      } else {
        response.id = pn::parameter_response_id::kReadError;
        response.parameters.push_back({pn::parameter_format::kError, {0}});
      }
    }
    parameter_response_ = pn::encode(response);
    return pn::PnioStatus{};
  });
  device_.set_read_handler(
      [this, object_telegram](const pn::RecordHeader& header, std::vector<std::uint8_t>& data) {
        if (object_telegram(header.slot) == 0 || header.index != pn::kParameterAccessIndex)
          return pn::PnioStatus{0xDE, 0x80, 0xB0, 0x00};
        if (parameter_response_.empty()) return pn::PnioStatus{0xDE, 0x80, 0xB8, 0x00};
        data = std::move(parameter_response_);
        parameter_response_.clear();
        return pn::PnioStatus{};
      });
}

bool ProfinetDrive::outputs_valid() const noexcept {
  if (device_.state() != profinet::ArState::kRunning) return false;
  for (const TelegramPlace& p : places_) {
    if (p.slot != 0 && device_.output_iops(p.slot, p.subslot) != profinet::kIoxsGood) return false;
  }
  return true;
}

bool ProfinetDrive::follow_controller() noexcept {
  const TelegramPlace place = places_[master_slot_];
  const auto received = device_.output_data(place.slot, place.subslot);
  const telegrams::Signal signal = master_slot_ == static_cast<std::size_t>(Slot::kDrive)
                                       ? telegrams::Signal::STW2
                                       : telegrams::Signal::STW2_ENC;
  if (device_.state() != profinet::ArState::kRunning || received.size() != master_codec_.frame_size() ||
      !master_codec_.carries(signal)) {
    return false;
  }
  telegrams::SetpointSignals signals{};
  if (master_codec_.decode(std::as_bytes(received), signals) != telegrams::TelegramError::kNone) return false;
  const auto master = static_cast<std::uint8_t>(signal == telegrams::Signal::STW2
                                                    ? signals.STW2.field(telegrams::kSignOfLifeField)
                                                    : signals.STW2_ENC.field(telegrams::kSignOfLifeField));
  if (master == 0 || master == master_sign_of_life_) return false;
  master_sign_of_life_ = master;
  cycle();
  return true;
}

void ProfinetDrive::cycle() noexcept {
  if (outputs_valid()) {
    bool complete = true;
    for (std::size_t s = 0; s < kSlotCount; ++s) {
      if (places_[s].slot == 0) continue;
      const auto received = device_.output_data(places_[s].slot, places_[s].subslot);
      Frame& setpoint = setpoint_.slots[s];
      if (received.size() != setpoint.length) {
        complete = false;
        continue;
      }
      std::memcpy(setpoint.bytes.data(), received.data(), received.size());
    }
    if (complete) drive_.write_setpoint(setpoint_);
  }
  if (drive_.read_actual(actual_)) {
    for (std::size_t s = 0; s < kSlotCount; ++s) {
      if (places_[s].slot == 0) continue;
      const auto input = device_.input_data(places_[s].slot, places_[s].subslot);
      const Frame& actual = actual_.slots[s];
      if (input.size() == actual.length) std::memcpy(input.data(), actual.bytes.data(), input.size());
    }
  }
}

}  // namespace tomc::drives
