#include "tomc/drives/drive_adapter.hpp"

#include "tomc/telegrams/layout.hpp"

namespace tomc::drives {

namespace tg = tomc::telegrams;

std::uint16_t DeviceConfig::telegram(Slot s) const noexcept {
  switch (s) {
    case Slot::kDrive:
      return drive_telegram;
    case Slot::kSupplementary:
      return supplementary_telegram;
    case Slot::kEncoder1:
      return encoder_telegrams[0];
    case Slot::kEncoder2:
      return encoder_telegrams[1];
  }
  return 0;
}

std::string validate(const DeviceConfig& c) {
  auto describe = [](int telegram) {
    const auto layout = tg::find_layout(telegram, tg::Direction::kSetpoint);
    return layout ? std::string() : std::string(tg::describe(layout.error()));
  };
  if (c.drive_telegram != 0 && !tg::is_drive_telegram(c.drive_telegram)) {
    const auto why = describe(c.drive_telegram);
    return "drive_telegram: " + std::to_string(c.drive_telegram) + " is not a drive telegram" +
           (why.empty() ? std::string() : " (" + why + ")");
  }
  if (c.supplementary_telegram != 0 && c.supplementary_telegram != 750) {
    return "supplementary_telegram: " + std::to_string(c.supplementary_telegram) + " is not 750";
  }
  if (c.supplementary_telegram != 0 && c.drive_telegram == 0) {
    return "supplementary_telegram: telegram 750 needs a drive telegram (spec 06 §2.14)";
  }
  for (std::size_t i = 0; i < c.encoder_telegrams.size(); ++i) {
    const auto t = c.encoder_telegrams[i];
    if (t != 0 && !tg::is_encoder_telegram(t)) {
      return "encoder_telegrams[" + std::to_string(i) + "]: " + std::to_string(t) + " is not 81 or 83";
    }
  }
  if (c.drive_telegram == 0 && c.encoder_telegrams[0] == 0 && c.encoder_telegrams[1] == 0) {
    return "device: no telegram configured";
  }
  const auto codec = tg::TelegramCodec::create(83, tg::Direction::kActual, c.codec);
  if (!codec) return "codec: " + std::string(tg::describe(codec.error()));
  return {};
}

DeviceCodecs::DeviceCodecs() noexcept {
  setpoint.fill(&tg::TelegramCodec::empty());
  actual.fill(&tg::TelegramCodec::empty());
}

DeviceCodecs::DeviceCodecs(const DeviceConfig& config) noexcept : DeviceCodecs() {
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    const auto t = config.telegram(static_cast<Slot>(i));
    if (t == 0) continue;
    if (auto c = tg::TelegramCodec::shared(t, tg::Direction::kSetpoint, config.codec))
      setpoint[i] = c.value();
    if (auto c = tg::TelegramCodec::shared(t, tg::Direction::kActual, config.codec)) actual[i] = c.value();
  }
}

DeviceFrames make_frames(const DeviceConfig& config, tg::Direction direction) {
  DeviceFrames frames;
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    const auto t = config.telegram(static_cast<Slot>(i));
    if (t == 0) continue;
    const auto layout = tg::find_layout(t, direction);
    if (layout) frames.slots[i].length = layout->length;
  }
  return frames;
}

}  // namespace tomc::drives
