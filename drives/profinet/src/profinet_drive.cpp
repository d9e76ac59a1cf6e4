#include "tomc/drives/profinet_drive.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>

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
  // PNIOStatus of a refused record access: ErrorCode 0xDF (write) / 0xDE (read), ErrorDecode 0x80 (PNIORW),
  // ErrorCode1 0xB0 (access: invalid index) or 0xB8 (invalid parameter / no request pending).
  device_.set_write_handler([this](const pn::RecordHeader& header, std::span<const std::uint8_t> data) {
    if (header.slot == 0 && header.subslot == 1 && header.index == kMonitoringRecordIndex)
      return write_monitoring_record(data);
    if (object_telegram(header.slot) == 0 || header.index != pn::kParameterAccessIndex)
      return pn::PnioStatus{0xDF, 0x80, 0xB0, 0x00};
    const auto request = pn::decode_parameter_request(data);
    if (!request) return pn::PnioStatus{0xDF, 0x80, 0xB8, 0x00};
    const pn::ParameterResponse response = request->id == pn::parameter_request_id::kChange
                                               ? change_parameters(*request, header.slot)
                                               : read_parameters(*request, header.slot);
    parameter_response_ = pn::encode(response);
    return pn::PnioStatus{};
  });
  device_.set_read_handler([this](const pn::RecordHeader& header, std::vector<std::uint8_t>& data) {
    if (header.slot == 0 && header.subslot == 1 && header.index == kMonitoringRecordIndex) {
      const auto cycles = static_cast<std::uint16_t>(drive_.parameters().setpoint_timeout_cycles);
      data = {0x00, 0x01, static_cast<std::uint8_t>(cycles >> 8), static_cast<std::uint8_t>(cycles)};
      return pn::PnioStatus{};
    }
    if (object_telegram(header.slot) == 0 || header.index != pn::kParameterAccessIndex)
      return pn::PnioStatus{0xDE, 0x80, 0xB0, 0x00};
    if (parameter_response_.empty()) return pn::PnioStatus{0xDE, 0x80, 0xB8, 0x00};
    data = std::move(parameter_response_);
    parameter_response_.clear();
    return pn::PnioStatus{};
  });
}

// The DAP's ParameterRecordDataItem (GSDML file, Index 256, decision I34): 4 bytes, version 0x0001 then the
// setpoint timeout in cycles (Unsigned16, 1..1000; F08501 after it). PNIOStatus DF 80 B1 (write length error)
// for another length, DF 80 B8 (invalid parameter) for another version or a value out of range.
profinet::PnioStatus ProfinetDrive::write_monitoring_record(std::span<const std::uint8_t> data) {
  if (data.size() != 4) return profinet::PnioStatus{0xDF, 0x80, 0xB1, 0x00};
  const auto version = static_cast<std::uint16_t>(data[0] << 8 | data[1]);
  const auto cycles = static_cast<std::uint16_t>(data[2] << 8 | data[3]);
  if (version != 1 || cycles < 1 || cycles > 1000) return profinet::PnioStatus{0xDF, 0x80, 0xB8, 0x00};
  drive_.set_setpoint_timeout_cycles(cycles);
  ++monitoring_records_;
  return profinet::PnioStatus{};
}

std::uint16_t ProfinetDrive::object_telegram(std::uint16_t slot) const noexcept {
  if (slot == kDriveObjectSlot && config_.drive_telegram != 0) return telegram_;
  for (const Slot s : {Slot::kEncoder1, Slot::kEncoder2}) {
    if (places_[static_cast<std::size_t>(s)].slot == slot) return config_.telegram(s);
  }
  return 0;
}

profinet::ParameterResponse ProfinetDrive::read_parameters(const profinet::ParameterRequest& request,
                                                           std::uint16_t slot) const {
  namespace pn = profinet;
  pn::ParameterResponse response{request.reference, pn::parameter_response_id::kReadOk, request.axis, {}};
  for (const pn::ParameterAddress& p : request.parameters) {
    if (p.attribute == 0x10 && p.number == 922) {
      response.parameters.push_back({pn::parameter_format::kUnsigned16, {object_telegram(slot)}});
    } else if (p.attribute == 0x10 && p.number == 2000) {
      response.parameters.push_back(
          {pn::parameter_format::kFloatingPoint,
           {std::bit_cast<std::uint32_t>(static_cast<float>(reference_speed_rpm_))}});
    } else {
      response.id = pn::parameter_response_id::kReadError;
      response.parameters.push_back(
          {pn::parameter_format::kError, {pn::parameter_error::kImpermissibleNumber}});
    }
  }
  return response;
}

// A change request (PROFIdrive base mode, request ID 0x02; decision I33): p2000 of the drive object takes a
// FloatingPoint value within SINAMICS' range 6..210000 rpm; p0922 is read-only here (the emulated drive's
// telegram is fixed by its submodules); any other number does not exist. Every parameter is executed or
// refused on its own; one refusal makes the answer kChangeError with a kZero value per executed parameter and
// a kError value per refused one, as the profile's multi-parameter change response.
profinet::ParameterResponse ProfinetDrive::change_parameters(const profinet::ParameterRequest& request,
                                                             std::uint16_t slot) {
  namespace pn = profinet;
  constexpr double kMinReferenceSpeed = 6.0;  // p2000's limits (SINAMICS S120 list manual)
  constexpr double kMaxReferenceSpeed = 210000.0;
  pn::ParameterResponse response{request.reference, pn::parameter_response_id::kChangeOk, request.axis, {}};
  for (std::size_t k = 0; k < request.parameters.size(); ++k) {
    const pn::ParameterAddress& p = request.parameters[k];
    const pn::ParameterValue& v = request.values.at(k);  // the decoder gives one value per address
    std::optional<std::uint16_t> error;
    if (p.attribute != 0x10) {
      error = pn::parameter_error::kAddressImpermissible;
    } else if (p.number == 922) {
      error = pn::parameter_error::kNotChangeable;
    } else if (p.number != 2000) {
      error = pn::parameter_error::kImpermissibleNumber;
    } else if (slot != kDriveObjectSlot || config_.drive_telegram == 0) {
      error = pn::parameter_error::kNotChangeable;  // an encoder object's reference speed is the drive's
    } else if (p.subindex != 0) {
      error = pn::parameter_error::kFaultySubindex;
    } else if (v.values.size() != 1) {
      error = pn::parameter_error::kValuesInconsistent;
    } else if (v.format != pn::parameter_format::kFloatingPoint) {
      error = pn::parameter_error::kIncorrectDataType;
    } else {
      const double rpm = std::bit_cast<float>(v.values.front());
      if (!(rpm >= kMinReferenceSpeed && rpm <= kMaxReferenceSpeed)) {  // NaN too
        error = pn::parameter_error::kLimitExceeded;
      } else {
        reference_speed_rpm_ = rpm;
        drive_.set_reference_speed_rpm(rpm);
      }
    }
    if (error) {
      response.id = pn::parameter_response_id::kChangeError;
      response.parameters.push_back({pn::parameter_format::kError, {*error}});
    } else {
      response.parameters.push_back({pn::parameter_format::kZero, {}});
    }
  }
  return response;
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
