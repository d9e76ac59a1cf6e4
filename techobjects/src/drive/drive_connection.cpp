#include "tomc/techobjects/drive/drive_connection.hpp"

#include <algorithm>

#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;
using drives::Slot;

std::string_view to_string(CommunicationFault fault) noexcept {
  switch (fault) {
    case CommunicationFault::kNone:
      return "none";
    case CommunicationFault::kLinkLost:
      return "link lost";
    case CommunicationFault::kNotControlled:
      return "drive does not request control (ZSW1.9 = 0)";
    case CommunicationFault::kDriveFault:
      return "drive fault (ZSW1.3)";
    case CommunicationFault::kSignOfLifeFailed:
      return "drive sign-of-life failed";
  }
  return "?";
}

DriveConnection::DriveConnection(DeviceIo& device, const DriveConnectionConfig& config)
    : device_(&device),
      config_(config),
      codecs_(device.adapter->config()),
      slave_monitor_(config.sign_of_life),
      peer_restarts_(device.adapter->link_health().peer_restarts) {
  // Without MC_TorqueRange the TO sends the reference torque as limits (spec 06 §8, TV14).
  supplementary_sp_.M_LIMIT_POS = 0x4000;
  supplementary_sp_.M_LIMIT_NEG = static_cast<std::int16_t>(-0x4000);
  // The TO owns STW1 bits 0..7 and 10; 4..6 held at 1 (spec 06 §3.1).
  drive_sp_.STW1 = tg::Stw1{tg::stw1_for(tg::DriveCommand::kIdle)};
  for (auto& e : encoder_sp_)
    e.STW2_ENC.set(tg::Stw2EncBit::kControlByPlc);
  const auto& drive_actual = codecs_(tg::Direction::kActual, Slot::kDrive);
  has_nist_b_ = drive_actual.carries(tg::Signal::NIST_B);
  has_zsw2_ = drive_actual.carries(tg::Signal::ZSW2);
  for (std::size_t i = 0; i < drives::kSlotCount; ++i) {
    if (codecs_.actual[i]->frame_size() != 0) actual_slots_ |= static_cast<std::uint8_t>(1u << i);
    if (codecs_.setpoint[i]->frame_size() != 0) setpoint_slots_ |= static_cast<std::uint8_t>(1u << i);
  }
}

void DriveConnection::restart(const DriveConnectionConfig& config) noexcept {
  const auto sign_of_life = config_.sign_of_life;
  config_ = config;
  config_.sign_of_life = sign_of_life;  // the running monitor keeps its configuration and expectation
  drive_sp_.STW1 = tg::Stw1{static_cast<std::uint16_t>(drive_sp_.STW1.value() & 0x04FFu)};
  drive_sp_.STW2 = tg::Stw2{static_cast<std::uint16_t>(drive_sp_.STW2.value() & 0xF000u)};
  request_ = tg::DriveRequest::kOff;
  speed_setpoint_rpm_ = 0.0;
  fixed_stop_sent_ = false;
}

void DriveConnection::set_user_control_bits(std::uint16_t stw1, std::uint16_t stw1_mask, std::uint16_t stw2,
                                            std::uint16_t stw2_mask) noexcept {
  drive_sp_.STW1 =
      tg::Stw1{static_cast<std::uint16_t>((drive_sp_.STW1.value() & ~stw1_mask) | (stw1 & stw1_mask))};
  drive_sp_.STW2 =
      tg::Stw2{static_cast<std::uint16_t>((drive_sp_.STW2.value() & ~stw2_mask) | (stw2 & stw2_mask))};
}

void DriveConnection::acknowledge() noexcept {
  sequencer_.request_acknowledge();
  slave_monitor_.reset();
}

void DriveConnection::read() noexcept {
  if (device_ == nullptr) return;
  bool fresh = device_->fresh;
  // A restarted link partner (a gateway with a new incarnation) broke the exchange even when frames keep
  // coming: this cycle counts as beyond the link-loss tolerance, so the TO raises its communication alarm
  // (docs/gateway.md); the next fresh frame resynchronises as after any gap.
  const std::uint32_t restarts = device_->adapter->link_health().peer_restarts;
  if (restarts != peer_restarts_) {
    peer_restarts_ = restarts;
    fresh = false;
    missed_ = std::max(missed_, config_.link_loss_tolerance_cycles);
  }
  if (fresh) {
    // After a gap the drive's counter has moved on: resynchronise; the gap is the link supervision's
    // business.
    if (missed_ != 0) slave_monitor_.reset();
    missed_ = 0;
    ever_fresh_ = true;
    auto decode = [&](Slot s, tg::ActualSignals& into) {
      const auto i = static_cast<std::size_t>(s);
      if ((actual_slots_ & (1u << i)) != 0)
        (void)codecs_.actual[i]->decode(device_->actual.slots[i].view(), into);
    };
    decode(Slot::kDrive, drive_act_);
    decode(Slot::kSupplementary, supplementary_act_);
    decode(Slot::kEncoder1, encoder_act_[0]);
    decode(Slot::kEncoder2, encoder_act_[1]);
  } else if (missed_ < UINT32_MAX) {
    ++missed_;
  }

  const bool has_drive = (actual_slots_ & (1u << static_cast<unsigned>(Slot::kDrive))) != 0;
  if (has_drive) {
    status_ = tg::decode_zsw1(drive_act_.ZSW1.value());
    actual_speed_rpm_ = has_nist_b_ ? tg::n4_to_speed(drive_act_.NIST_B, config_.reference_speed_rpm)
                                    : tg::n2_to_speed(drive_act_.NIST_A, config_.reference_speed_rpm);
  }

  // Slave sign-of-life, once per fresh frame (spec 06 §5.2): ZSW2 of the drive or ZSW2_ENC of an encoder.
  if (config_.isochronous && fresh) {
    if (has_zsw2_) {
      (void)slave_monitor_.check(static_cast<std::uint8_t>(drive_act_.ZSW2.field(tg::kSignOfLifeField)));
    } else if (!has_drive && (actual_slots_ & (1u << static_cast<unsigned>(Slot::kEncoder1))) != 0) {
      (void)slave_monitor_.check(
          static_cast<std::uint8_t>(encoder_act_[0].ZSW2_ENC.field(tg::kSignOfLifeField)));
    }
  }

  // StatusDrive.CommunicationOK (seed L11468): link, control requested, no fault, sign-of-life.
  if (!ever_fresh_ || missed_ > config_.link_loss_tolerance_cycles) {
    communication_fault_ = CommunicationFault::kLinkLost;
  } else if (has_drive && !status_.control_requested) {
    communication_fault_ = CommunicationFault::kNotControlled;
  } else if (has_drive && status_.state == tg::DriveState::kFault) {
    communication_fault_ = CommunicationFault::kDriveFault;
  } else if (!has_drive && !encoder_act_[0].ZSW2_ENC.test(tg::Zsw2EncBit::kControlRequested)) {
    communication_fault_ = CommunicationFault::kNotControlled;
  } else if (slave_monitor_.status() == tg::SignOfLifeStatus::kFailed) {
    communication_fault_ = CommunicationFault::kSignOfLifeFailed;
  } else {
    communication_fault_ = CommunicationFault::kNone;
  }
}

void DriveConnection::set_encoder_control(EncoderSource source, tg::EncoderControlWord word) noexcept {
  switch (source) {
    case EncoderSource::kDriveG1:
      drive_sp_.G1_STW = word;
      break;
    case EncoderSource::kDriveG2:
      drive_sp_.G2_STW = word;
      break;
    case EncoderSource::kEncoderG1:
      encoder_sp_[0].G1_STW = word;
      break;
    case EncoderSource::kEncoder2G1:
      encoder_sp_[1].G1_STW = word;
      break;
  }
}

void DriveConnection::write(const ServoCommand& command) noexcept {
  if (device_ == nullptr) return;
  speed_setpoint_rpm_ = command.speed_rpm;
  drive_sp_.XERR = command.xerr;
  drive_sp_.KPC = command.kpc;
  drive_sp_.MOMRED = command.momred;
  if (command.travel_to_fixed_stop != fixed_stop_sent_) {  // on change only: the bit is also the user's
    drive_sp_.STW2.set(tg::Stw2Bit::kTravelToFixedStop, command.travel_to_fixed_stop);
    fixed_stop_sent_ = command.travel_to_fixed_stop;
  }
  set_encoder_control(command.encoder, command.encoder_control);
  const std::uint8_t master = config_.isochronous ? master_.next() : 0;
  if ((setpoint_slots_ & (1u << static_cast<unsigned>(Slot::kDrive))) != 0) {
    // STW1: the TO's bits 0..7 and 10 from the sequencer, the user's bits (8, 9, 11..15) kept.
    const std::uint16_t owned = 0x04FF;
    const std::uint16_t stw1 = sequencer_.next(drive_act_.ZSW1.value(), request_);
    drive_sp_.STW1 = tg::Stw1{static_cast<std::uint16_t>((drive_sp_.STW1.value() & ~owned) | (stw1 & owned))};
    drive_sp_.STW2.set_field(tg::kSignOfLifeField, master);
    // Setpoints only count in S4; before, the drive ignores them (spec 01 §6.2) - send them anyway.
    if (has_nist_b_) {  // telegram 1 carries NSOLL_A/NIST_A, all others NSOLL_B/NIST_B
      drive_sp_.NSOLL_B = tg::speed_to_n4(speed_setpoint_rpm_, config_.reference_speed_rpm);
    } else {
      drive_sp_.NSOLL_A = tg::speed_to_n2(speed_setpoint_rpm_, config_.reference_speed_rpm);
    }
  }
  for (auto& e : encoder_sp_)
    e.STW2_ENC.set_field(tg::kSignOfLifeField, master);
  auto encode = [&](Slot s, const tg::SetpointSignals& from) {
    const auto i = static_cast<std::size_t>(s);
    if ((setpoint_slots_ & (1u << i)) != 0)
      (void)codecs_.setpoint[i]->encode(from, device_->setpoint.slots[i].view());
  };
  encode(Slot::kDrive, drive_sp_);
  encode(Slot::kSupplementary, supplementary_sp_);
  encode(Slot::kEncoder1, encoder_sp_[0]);
  encode(Slot::kEncoder2, encoder_sp_[1]);
}

}  // namespace tomc::techobjects
