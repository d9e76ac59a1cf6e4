// The generic view of a technology object (object_view.hpp): its reflection table, telegram words and probes.
#include "tomc/diagnostics/object_view.hpp"

#include <charconv>

#include "tomc/diagnostics/synchronous_view.hpp"
#include "tomc/techobjects/cam/cam_data.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/telegrams/layout.hpp"

namespace tomc::diagnostics {

namespace to = tomc::techobjects;
namespace tg = tomc::telegrams;

std::span<const to::VariableInfo> variables_of(to::TechnologyObjectType type) noexcept {
  switch (type) {
    case to::TechnologyObjectType::kSpeedAxis:
      return to::speed_axis_variables();
    case to::TechnologyObjectType::kPositioningAxis:
      return to::positioning_axis_variables();
    case to::TechnologyObjectType::kSynchronousAxis:
      return synchronous_axis_variables();
    case to::TechnologyObjectType::kExternalEncoder:
      return to::external_encoder_variables();
    case to::TechnologyObjectType::kCam:
      return to::cam_variables();
  }
  return {};
}

std::string_view type_name(to::TechnologyObjectType type) noexcept {
  switch (type) {
    case to::TechnologyObjectType::kSpeedAxis:
      return "TO_SpeedAxis";
    case to::TechnologyObjectType::kPositioningAxis:
      return "TO_PositioningAxis";
    case to::TechnologyObjectType::kSynchronousAxis:
      return "TO_SynchronousAxis";
    case to::TechnologyObjectType::kExternalEncoder:
      return "TO_ExternalEncoder";
    case to::TechnologyObjectType::kCam:
      return "TO_Cam";
  }
  return "?";
}

std::string_view slot_name(drives::Slot slot) noexcept {
  switch (slot) {
    case drives::Slot::kDrive:
      return "drive";
    case drives::Slot::kSupplementary:
      return "supplementary";
    case drives::Slot::kEncoder1:
      return "encoder1";
    case drives::Slot::kEncoder2:
      return "encoder2";
  }
  return "?";
}

void ObjectView::resolve_telegrams() {
  channels_.clear();
  const to::DriveConnection* d = drive();
  if (d != nullptr) {
    const drives::DeviceConfig& device = d->device_config();
    for (const drives::Slot slot : {drives::Slot::kDrive, drives::Slot::kSupplementary,
                                    drives::Slot::kEncoder1, drives::Slot::kEncoder2}) {
      const std::uint16_t telegram = device.telegram(slot);
      if (telegram == 0) continue;
      // Actual words first: they are what a commissioning engineer looks at (ZSW1, NIST, Gx_XIST1 ...).
      for (const tg::Direction direction : {tg::Direction::kActual, tg::Direction::kSetpoint}) {
        const auto layout = tg::find_layout(telegram, direction);
        if (!layout) continue;
        for (const tg::FieldLayout& field : layout->fields())
          channels_.push_back(TelegramChannel{slot, direction, field.signal});
      }
    }
  }
  sources_ = std::make_unique<TelegramSource[]>(channels_.size());
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    const TelegramChannel& c = channels_[i];
    const bool actual = c.direction == tg::Direction::kActual;
    TelegramSource& s = sources_[i];
    s.signal = c.signal;
    s.actual = nullptr;
    s.setpoint = nullptr;
    switch (c.slot) {
      case drives::Slot::kDrive:
        if (actual)
          s.actual = &d->drive_actual();
        else
          s.setpoint = &d->drive_setpoint();
        break;
      case drives::Slot::kSupplementary:
        if (actual)
          s.actual = &d->supplementary_actual();
        else
          s.setpoint = &d->supplementary_setpoint();
        break;
      case drives::Slot::kEncoder1:
        if (actual)
          s.actual = &d->encoder_actual(0);
        else
          s.setpoint = &d->encoder_setpoint(0);
        break;
      case drives::Slot::kEncoder2:
        if (actual)
          s.actual = &d->encoder_actual(1);
        else
          s.setpoint = &d->encoder_setpoint(1);
        break;
    }
  }
}

std::uint32_t ObjectView::telegram_word(std::size_t i) const noexcept {
  return i < channels_.size() ? sources_[i].read() : 0;
}

namespace {

// "X<n>" with n = 0..31, no leading zeros (as parse_bit_path of the data blocks).
std::optional<std::uint8_t> parse_bit_suffix(std::string_view text) {
  if (text.size() < 2 || text.size() > 3 || text[0] != 'X') return std::nullopt;
  if (text.size() == 3 && text[1] == '0') return std::nullopt;
  unsigned n = 0;
  const auto [end, error] = std::from_chars(text.data() + 1, text.data() + text.size(), n);
  if (error != std::errc{} || end != text.data() + text.size() || n > 31) return std::nullopt;
  return static_cast<std::uint8_t>(n);
}

}  // namespace

std::optional<Probe> ObjectView::probe(std::string_view path) const {
  const auto table = variables();
  if (const to::VariableInfo* v = to::find_variable(table, path)) {
    return Probe{v->read_fn, source_of(*v), -1};
  }
  if (const auto bit = to::find_bit(table, path)) {
    return Probe{bit->word->read_fn, source_of(*bit->word), static_cast<std::int8_t>(bit->bit)};
  }
  constexpr std::string_view kTelegram = "telegram.";
  if (!path.starts_with(kTelegram)) return std::nullopt;
  std::string_view rest = path.substr(kTelegram.size());
  const auto dot = rest.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  const std::string_view slot = rest.substr(0, dot);
  rest = rest.substr(dot + 1);
  std::int8_t bit = -1;
  if (const auto bit_dot = rest.find('.'); bit_dot != std::string_view::npos) {
    const auto n = parse_bit_suffix(rest.substr(bit_dot + 1));
    if (!n) return std::nullopt;
    bit = static_cast<std::int8_t>(*n);
    rest = rest.substr(0, bit_dot);
  }
  const auto signal = tg::parse_signal(rest);
  if (!signal) return std::nullopt;
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    const TelegramChannel& c = channels_[i];
    if (slot_name(c.slot) != slot || c.signal != *signal) continue;
    if (bit >= 0 && bit >= static_cast<std::int8_t>(tg::info(c.signal).bits)) return std::nullopt;
    constexpr auto read = [](const void* object) noexcept -> double {
      return static_cast<double>(static_cast<const TelegramSource*>(object)->read());
    };
    return Probe{read, &sources_[i], bit};
  }
  return std::nullopt;
}

}  // namespace tomc::diagnostics
