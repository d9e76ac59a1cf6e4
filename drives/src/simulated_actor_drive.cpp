// The separate 81/83 encoder of a simulated analog or stepper drive (simulated_actor_drive.hpp). No
// allocation, no locks, no exceptions in exchange().
#include "tomc/drives/simulated_actor_drive.hpp"

#include <string>

#include "tomc/telegrams/encoder.hpp"

namespace tomc::drives::detail {

namespace tg = tomc::telegrams;

namespace {
DeviceConfig encoder_device(std::uint16_t telegram) {
  DeviceConfig c;
  c.encoder_telegrams[0] = telegram;
  return c;
}
SimulatedDriveParameters encoder_on(const SimulatedDriveParameters& mechanics,
                                    const SimulatedEncoderParameters& encoder) {
  SimulatedDriveParameters p = mechanics;
  p.encoder1 = encoder;  // an encoder-only device answers its encoder telegram with encoder 1
  return p;
}
}  // namespace

void check_separate_encoder(const ActorParameters& actor, const std::optional<SeparateEncoderParameters>& e) {
  const bool separate = actor.feedback == PositionFeedback::kSeparateEncoder;
  if (separate != e.has_value()) {
    throw std::invalid_argument(separate
                                    ? "the actor's position comes from a separate encoder, but none is given"
                                    : "a separate encoder is given, but the actor reads its counter");
  }
  if (e && e->telegram != 81 && e->telegram != 83) {
    throw std::invalid_argument("separate encoder telegram " + std::to_string(e->telegram) +
                                " is not 81 or 83");
  }
}

SeparateEncoder::SeparateEncoder(const SeparateEncoderParameters& parameters,
                                 const SimulatedDriveParameters& mechanics)
    : servo_cycle_s_(mechanics.servo_cycle_s),
      device_(encoder_device(parameters.telegram), encoder_on(mechanics, parameters.encoder)) {
  if (auto c = tg::TelegramCodec::shared(parameters.telegram, tg::Direction::kActual)) codec_ = c.value();
  frames_ = make_frames(device_.config(), tg::Direction::kActual);
}

void SeparateEncoder::exchange(double load_position, Telegram3Actor& actor, DeviceFrames& actual) noexcept {
  // The encoder device integrates a speed over the cycle: the one that lands it on the machine's load
  // position (no drift: the difference is taken against where it is).
  device_.set_external_speed((load_position - device_.load_position()) / servo_cycle_s_);
  if (device_.read_actual(frames_)) actual[Slot::kEncoder1] = frames_[Slot::kEncoder1];
  tg::ActualSignals a;
  (void)codec_->decode(actual[Slot::kEncoder1].view(), a);
  actor.separate_encoder_count(a.G1_XIST1, !a.G1_ZSW.test(tg::EncoderStatusBit::kEncoderError));
}

}  // namespace tomc::drives::detail
