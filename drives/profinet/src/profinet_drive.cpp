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
  telegram_ = config.drive_telegram;
  reference_speed_rpm_ = parameters.reference_speed_rpm;
  namespace pn = profinet;
  // PNIOStatus of a refused record access: ErrorCode 0xDF (write) / 0xDE (read), ErrorDecode 0x80 (PNIORW),
  // ErrorCode1 0xB0 (access: invalid index) or 0xB8 (invalid parameter / no request pending).
  device_.set_write_handler([this](const pn::RecordHeader& header, std::span<const std::uint8_t> data) {
    if (header.slot != kDriveObjectSlot || header.index != pn::kParameterAccessIndex)
      return pn::PnioStatus{0xDF, 0x80, 0xB0, 0x00};
    const auto request = pn::decode_parameter_request(data);
    if (!request) return pn::PnioStatus{0xDF, 0x80, 0xB8, 0x00};
    pn::ParameterResponse response{request->reference, pn::parameter_response_id::kReadOk, request->axis, {}};
    for (const pn::ParameterAddress& p : request->parameters) {
      if (p.attribute == 0x10 && p.number == 922) {
        response.parameters.push_back({pn::parameter_format::kUnsigned16, {telegram_}});
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
  device_.set_read_handler([this](const pn::RecordHeader& header, std::vector<std::uint8_t>& data) {
    if (header.slot != kDriveObjectSlot || header.index != pn::kParameterAccessIndex)
      return pn::PnioStatus{0xDE, 0x80, 0xB0, 0x00};
    if (parameter_response_.empty()) return pn::PnioStatus{0xDE, 0x80, 0xB8, 0x00};
    data = std::move(parameter_response_);
    parameter_response_.clear();
    return pn::PnioStatus{};
  });
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
