#include "tomc/techobjects/drive/encoder_channel.hpp"

#include <algorithm>

#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/encoder.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

bool carries(std::uint16_t telegram, tg::Signal signal) {
  if (telegram == 0) return false;
  const auto codec = tg::TelegramCodec::create(telegram, tg::Direction::kActual);
  return static_cast<bool>(codec) && codec->carries(signal);
}

}  // namespace

std::optional<EncoderSource> find_encoder_source(const drives::DeviceConfig& device, std::uint32_t number,
                                                 std::span<const EncoderSource> taken) {
  const auto free = [&](EncoderSource s) { return std::find(taken.begin(), taken.end(), s) == taken.end(); };
  if (number == 2) {
    if (carries(device.drive_telegram, tg::Signal::G2_XIST1) && free(EncoderSource::kDriveG2)) {
      return EncoderSource::kDriveG2;
    }
  } else if (carries(device.drive_telegram, tg::Signal::G1_XIST1) && free(EncoderSource::kDriveG1)) {
    return EncoderSource::kDriveG1;
  }
  if (carries(device.encoder_telegrams[0], tg::Signal::G1_XIST1) && free(EncoderSource::kEncoderG1)) {
    return EncoderSource::kEncoderG1;
  }
  if (carries(device.encoder_telegrams[1], tg::Signal::G1_XIST1) && free(EncoderSource::kEncoder2G1)) {
    return EncoderSource::kEncoder2G1;
  }
  return std::nullopt;
}

void EncoderChannel::read(const DriveConnection& drive, bool fresh) noexcept {
  const tg::ActualSignals& a = source_ == EncoderSource::kEncoderG1    ? drive.encoder_actual(0)
                               : source_ == EncoderSource::kEncoder2G1 ? drive.encoder_actual(1)
                                                                       : drive.drive_actual();
  const bool g2 = source_ == EncoderSource::kDriveG2;
  const tg::EncoderStatusWord zsw = g2 ? a.G2_ZSW : a.G1_ZSW;
  const std::uint32_t xist2 = g2 ? a.G2_XIST2 : a.G1_XIST2;
  error_ = zsw.test(tg::EncoderStatusBit::kEncoderError);
  error_code_ = error_ ? xist2 : 0;
  if (!fresh || error_) return;
  EncoderSample sample;
  sample.xist1 = g2 ? a.G2_XIST1 : a.G1_XIST1;
  if (chain_.absolute_type() && zsw.test(tg::EncoderStatusBit::kAbsoluteValueTransmitted)) {
    sample.xist2_absolute = xist2;
  }
  if (velocity_from_nist_) sample.nist_b = a.NIST_B;
  chain_.update(sample);
  // Reference mark: "value 1 available" after the mark was crossed; the read request's answer in Gx_XIST2 is
  // the Gx_XIST1 value at the mark (spec 06 §6.2, TV23), relative to this cycle's Gx_XIST1 in the counter's
  // width.
  const bool available = zsw.test(tg::EncoderStatusBit::kValue1Available);
  if (mark_ == MarkState::kArmed && available) {
    mark_ = MarkState::kReading;
    read_sent_ = false;
  } else if (mark_ == MarkState::kReading && read_sent_ && available) {
    const std::uint8_t width = chain_.xist1_width();
    const std::uint64_t modulus = std::uint64_t{1} << width;
    auto delta =
        static_cast<std::int64_t>((static_cast<std::uint64_t>(xist2) - sample.xist1) & (modulus - 1));
    if (delta >= static_cast<std::int64_t>(modulus / 2)) delta -= static_cast<std::int64_t>(modulus);
    mark_position_ = chain_.continuous_position() + static_cast<double>(delta) * chain_.units_per_count();
    mark_ = MarkState::kCaptured;
  }
}

tg::EncoderControlWord EncoderChannel::control_word() noexcept {
  auto& stw = control_;
  // Low byte: reference-mark search (function 1, command 1), then the read request (command 2).
  std::uint16_t request = 0;
  if (mark_ == MarkState::kArmed) request = tg::encoder_request::reference_mark_search();
  if (mark_ == MarkState::kReading) {
    request = tg::encoder_request::read_reference_mark();
    read_sent_ = true;
  }
  stw = tg::EncoderControlWord{static_cast<std::uint16_t>((stw.value() & 0xFF00u) | request)};
  stw.set(tg::EncoderControlBit::kRequestAbsoluteValue, chain_.absolute_type());
  stw.set(tg::EncoderControlBit::kAcknowledgeEncoderError, acknowledge_cycles_ > 0);
  if (acknowledge_cycles_ > 0) --acknowledge_cycles_;
  return stw;
}

}  // namespace tomc::techobjects
