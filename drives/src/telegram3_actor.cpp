// The telegram-3 side of the analog and stepper actors (telegram3_actor.hpp). read_actual(): sample the card,
// supervise the ready input, answer in telegram 3. write_setpoint(): one evaluation of STW1 (with the
// ready-input rules), the enable output and the derived class's output stage, the zero-mark latch, out to the
// card. No allocation, no locks, no exceptions.
#include "tomc/drives/telegram3_actor.hpp"

#include <algorithm>
#include <cmath>

#include "tomc/telegrams/control_words.hpp"
#include "tomc/telegrams/encoder.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace tomc::drives {

namespace tg = tomc::telegrams;

namespace {

constexpr std::uint16_t kTelegram = 3;

bool enabled_state(tg::DriveState s) noexcept {
  return s == tg::DriveState::kS4Operation || s == tg::DriveState::kS5aRampStop ||
         s == tg::DriveState::kS5bQuickStop;
}
bool switched_on(tg::DriveState s) noexcept {
  return s == tg::DriveState::kS3SwitchedOn || enabled_state(s);
}

}  // namespace

Telegram3Actor::Telegram3Actor(io::HardwareIo& hardware, const ActorParameters& parameters)
    : hw_(&hardware), base_(parameters), extension_(parameters.counter_width_bits) {
  config_.drive_telegram = kTelegram;
  if (auto c = tg::TelegramCodec::shared(kTelegram, tg::Direction::kSetpoint, config_.codec))
    setpoint_codec_ = c.value();
  if (auto c = tg::TelegramCodec::shared(kTelegram, tg::Direction::kActual, config_.codec))
    actual_codec_ = c.value();
  setpoint_frames_ = make_frames(config_, tg::Direction::kSetpoint);
  sign_of_life_.reset(1);
}

// ---------------------------------------------------------------------------------------------------------
// Start of MC_Servo

bool Telegram3Actor::read_actual(DeviceFrames& actual) noexcept {
  const io::IoStatus status = hw_->sample_inputs();
  io_ok_ = status == io::IoStatus::kOk;
  if (!io_ok_ && fault_ == 0) fault_ = kFaultIo;
  ready_ = base_.ready_input ? hw_->digital_input(*base_.ready_input) : true;
  const io::CounterSample sample = hw_->counter(base_.counter);
  const std::int64_t count = extension_.update(sample.count);
  if (health_.exchanges == 0) previous_count_ = count;
  speed_rpm_ =
      static_cast<double>(count - previous_count_) / base_.counts_per_revolution / base_.servo_cycle_s * 60.0;
  previous_count_ = count;
  if ((encoder_status_ & 0x0001u) != 0 && sample.latched && (encoder_status_ & 0x0010u) == 0) {
    latched_ = extension_.extend(sample.latched_count);
    encoder_status_ |= 0x0010u;  // value 1 available
  }

  // Ready-input rule 2 (spec 01 §3.12): ready lost on a switched-on axis disables it with an error, at once.
  if (base_.ready_input && !ready_ && switched_on(state_) && fault_ == 0) fault_ = kFaultDriveReadyLost;
  if (fault_ != 0 && state_ != tg::DriveState::kS1SwitchingOnInhibited) {
    state_ = tg::DriveState::kS1SwitchingOnInhibited;
    drive_outputs();
    (void)hw_->write_outputs();
  }
  if (cyclic_data_) slave_counter_ = sign_of_life_.next();

  ++health_.exchanges;
  health_.up = true;
  health_.consecutive_missed = 0;

  tg::ActualSignals a;
  const bool fault = fault_ != 0;
  std::uint16_t zsw1 = tg::zsw1_for(state_, sp_.STW1.value(), cyclic_data_, fault, false);
  if (fault) zsw1 &= static_cast<std::uint16_t>(~0x0030u);  // as the simulated drive (decision R3)
  a.ZSW1 = tg::Zsw1{zsw1};
  a.NIST_B = tg::speed_to_n4(speed_rpm_, base_.reference_speed_rpm);
  a.ZSW2.set(tg::Zsw2Bit::kPulsesEnabled, enable_);
  a.ZSW2.set_field(tg::kSignOfLifeField, slave_counter_);
  update_encoder(sp_.G1_STW.value(), a);
  a.G1_XIST1 = static_cast<std::uint32_t>(static_cast<std::uint64_t>(count));
  (void)actual_codec_->encode(a, actual[Slot::kDrive].view());
  return true;
}

void Telegram3Actor::update_encoder(std::uint16_t control, tg::ActualSignals& a) noexcept {
  const tg::EncoderControlWord stw{control};
  const std::uint16_t functions = stw.field(tg::kEncoderFunctionsField);
  const std::uint16_t command = stw.field(tg::kEncoderCommandField);
  std::uint16_t status = encoder_status_;
  std::uint16_t error = 0;
  // The counter has one zero-mark latch: reference mark 1 (function 1) only; no probe inputs, no absolute
  // value (an incremental encoder).
  if (command > 3 ||
      (functions != 0 && (stw.test(tg::EncoderControlBit::kMeasurementMode) || (functions & 0x000Eu) != 0))) {
    error = tg::kEncoderErrorCommandNotSupported;
  }
  if (error == 0) {
    if (command == 1 && (functions & 0x0001u) != 0 && (status & 0x0001u) == 0) {
      status = static_cast<std::uint16_t>((status & ~0x0011u) | 0x0001u);  // active, nothing available
      hw_->arm_zero_mark(base_.counter);
    } else if (command == 3 || (functions & 0x0001u) == 0) {
      status &= static_cast<std::uint16_t>(~0x0011u);
    }
  }
  status = static_cast<std::uint16_t>(status & 0x00FFu);
  if (stw.test(tg::EncoderControlBit::kRequestParkEncoder)) status |= 0x4000u;
  if (stw.test(tg::EncoderControlBit::kAcknowledgeEncoderError)) status |= 0x0800u;
  // An error stays shown until acknowledged with Gx_STW.15 once its cause is gone (spec 06 §6.3).
  const bool latched_error =
      (encoder_status_ & 0x8000u) != 0 && !stw.test(tg::EncoderControlBit::kAcknowledgeEncoderError);
  std::uint32_t xist2 = 0;
  if (error != 0 || latched_error) {
    status |= 0x8000u;
    xist2 = tg::kEncoderErrorCommandNotSupported;
  } else if (command == 2 && (status & 0x0010u) != 0) {
    xist2 = static_cast<std::uint32_t>(static_cast<std::uint64_t>(latched_));
  }
  encoder_status_ = status;
  a.G1_ZSW = tg::EncoderStatusWord{status};
  a.G1_XIST2 = xist2;
}

// ---------------------------------------------------------------------------------------------------------
// End of MC_Servo

void Telegram3Actor::write_setpoint(const DeviceFrames& setpoint) noexcept {
  const auto& frame = setpoint[Slot::kDrive];
  if (frame.length == setpoint_frames_[Slot::kDrive].length) {
    (void)setpoint_codec_->decode(frame.view(), sp_);
    cyclic_data_ = true;
  }
  update_state(sp_.STW1.value());
  drive_outputs();
  if (hw_->write_outputs() != io::IoStatus::kOk) {
    io_ok_ = false;
    if (fault_ == 0) fault_ = kFaultIo;
  }
}

void Telegram3Actor::update_state(std::uint16_t stw1) noexcept {
  // Acknowledge: a 0 -> 1 edge of STW1.7 clears the fault once its cause is gone.
  const bool edge = (stw1 & 0x0080u) != 0 && (previous_stw1_ & 0x0080u) == 0;
  previous_stw1_ = stw1;
  if (fault_ != 0) {
    const bool cause_present =
        (fault_ == kFaultDriveReadyLost && base_.ready_input && !ready_) || (fault_ == kFaultIo && !io_ok_);
    if (edge && !cause_present) fault_ = 0;
    state_ = tg::DriveState::kS1SwitchingOnInhibited;
    return;  // one state evaluation per cycle: the next transition comes next cycle (decision R4)
  }
  if (!cyclic_data_) return;
  std::uint16_t effective = stw1;
  // Ready-input rule 1: not switched on before the ready signal is present (OFF2 holds it in S1).
  if (base_.ready_input && !ready_) effective &= static_cast<std::uint16_t>(~0x0002u);
  const bool standstill = std::fabs(speed_rpm_) < base_.standstill_threshold_rpm;
  state_ = tg::next_drive_state(state_, effective, standstill);
}

void Telegram3Actor::drive_outputs() noexcept {
  // Rule 3 and the stop reactions: the enable output follows the state (S4, and S5 until standstill).
  enable_ = fault_ == 0 && enabled_state(state_);
  double speed = 0.0;
  if (enable_ && state_ == tg::DriveState::kS4Operation &&
      sp_.STW1.test(tg::Stw1Bit::kEnableRampFunctionGenerator) &&
      sp_.STW1.test(tg::Stw1Bit::kEnableSetpoint)) {
    speed = tg::n4_to_speed(sp_.NSOLL_B, base_.reference_speed_rpm) / base_.reference_speed_rpm;
  }
  // S5: zero speed, the drive brakes with its own loop (spec 02 §5 "Analog drive").
  set_speed_output(enable_, speed);
  if (base_.enable_output) hw_->set_digital_output(*base_.enable_output, enable_);
}

}  // namespace tomc::drives
