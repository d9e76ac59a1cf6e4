// The diagnostics pages per TO type, as spec 04 §9.1 (speed axis), §9.2 (positioning/synchronous axis) and
// §9.3 (external encoder) list them (seed 004 §8.1-§8.3). S7-1500 flavour: one encoder indicator (encoder 1);
// the S7-1500T pages repeat it for encoders 2..4.
#include "tomc/diagnostics/layout.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>

namespace tomc::diagnostics {

namespace to = tomc::techobjects;

namespace {

// ---- spec 04 §9.1, TO_SpeedAxis ----
constexpr std::array<LayoutItem, 7> kSpeedAxisStatus{{
    {"Simulation active", "StatusWord.X25 | VirtualAxis.Mode=1"},
    {"Enabled", "StatusWord.X0"},
    {"Error", "StatusWord.X1"},
    {"Restart active", "StatusWord.X2"},
    {"Axis control panel active", "StatusWord.X4"},
    {"Drive ready", "StatusDrive.InOperation"},
    {"Restart required", "StatusWord.X3"},
}};
constexpr std::array<LayoutItem, 8> kSpeedAxisMotion{{
    {"Done (no job active)", "StatusWord.X6"},
    {"Jog", "StatusWord.X9"},
    {"Speed setpoint job", "StatusWord.X10"},
    {"Constant speed", "StatusWord.X12"},
    {"Accelerating", "StatusWord.X13"},
    {"Decelerating", "StatusWord.X14"},
    {"Torque limiting active", "StatusWord.X27"},
    {"Stop job active", "StatusWord2.X0"},
}};
constexpr std::array<LayoutItem, 3> kAxisWarnings{{
    {"Configuration", "WarningWord.X1"},
    {"Job rejected", "WarningWord.X3"},
    {"Dynamic limitation", "WarningWord.X6"},
}};
constexpr std::array<LayoutItem, 8> kSpeedAxisErrors{{
    {"System", "ErrorWord.X0"},
    {"Configuration", "ErrorWord.X1"},
    {"User program", "ErrorWord.X2"},
    {"Drive", "ErrorWord.X4"},
    {"Data exchange", "ErrorWord.X7"},
    {"I/O", "ErrorWord.X13"},
    {"Job rejected", "ErrorWord.X3"},
    {"Dynamic limitation", "ErrorWord.X6"},
}};
constexpr std::array<LayoutItem, 2> kSpeedAxisSetpoints{{
    {"Speed setpoint", "Velocity", true},
    {"Speed override (%)", "Override.Velocity", true},
}};
constexpr std::array<LayoutItem, 2> kSpeedAxisActual{{
    {"Load-side speed", "Velocity", true},  // as the manual prints it (spec 04 §9.1)
    {"Motor-shaft speed", "ActualSpeed", true},
}};
constexpr std::array<LayoutItem, 4> kDynamicLimits{{
    {"Velocity", "DynamicLimits.MaxVelocity", true},
    {"Acceleration", "DynamicLimits.MaxAcceleration", true},
    {"Deceleration", "DynamicLimits.MaxDeceleration", true},
    {"Jerk", "DynamicLimits.MaxJerk", true},
}};
constexpr std::array<LayoutArea, 7> kSpeedAxisLayout{{
    {"status", "Axis status", kSpeedAxisStatus},
    {"status", "Motion status", kSpeedAxisMotion},
    {"status", "Warnings", kAxisWarnings},
    {"status", "Errors", kSpeedAxisErrors},
    {"motion", "Setpoints", kSpeedAxisSetpoints},
    {"motion", "Actual values", kSpeedAxisActual},
    {"motion", "Dynamic limits", kDynamicLimits},
}};

// ---- spec 04 §9.2, TO_PositioningAxis / TO_SynchronousAxis ----
constexpr std::array<LayoutItem, 12> kPositioningStatus{{
    {"Simulation active", "StatusWord.X25 | VirtualAxis.Mode=1"},
    {"Enabled", "StatusWord.X0"},
    {"Position-controlled operation", "!StatusWord.X28"},
    {"Homed", "StatusWord.X5"},
    {"Error", "StatusWord.X1"},
    {"Restart active", "StatusWord.X2"},
    {"Axis control panel active", "StatusWord.X4"},
    {"Drive ready", "StatusDrive.InOperation"},
    {"Encoder actual values valid", "StatusSensor[1].State=2"},
    {"Encoder referenced", "StatusSensor[1].Adjusted"},
    {"Restart required", "StatusWord.X3"},
    {"Active encoder", "OperativeSensor", true},
}};
constexpr std::array<LayoutItem, 4> kPositioningLimitSwitches{{
    {"Negative software limit switch reached", "StatusWord.X15"},
    {"Positive software limit switch reached", "StatusWord.X16"},
    {"Negative hardware limit switch approached or passed", "StatusWord.X17"},
    {"Positive hardware limit switch approached or passed", "StatusWord.X18"},
}};
constexpr std::array<LayoutItem, 12> kPositioningMotion{{
    {"Done (no job active)", "StatusWord.X6"},
    {"Homing job", "StatusWord.X11"},
    {"Jog", "StatusWord.X9"},
    {"Velocity setpoint job", "StatusWord.X10"},
    {"Positioning job", "StatusWord.X8 | StatusWord2.X9"},
    {"Constant velocity", "StatusWord.X12"},
    {"Standstill", "StatusWord.X7"},
    {"Accelerating", "StatusWord.X13"},
    {"Decelerating", "StatusWord.X14"},
    {"Torque limiting active", "StatusWord.X27"},
    {"Stop job active", "StatusWord2.X0"},
    {"Superimposed motion", "StatusWord.X23 | StatusWord2.X6 | StatusWord2.X8 | StatusWord2.X7"},
}};
constexpr std::array<LayoutItem, 16> kPositioningErrors{{
    {"System", "ErrorWord.X0"},
    {"Configuration", "ErrorWord.X1"},
    {"User program", "ErrorWord.X2"},
    {"Drive", "ErrorWord.X4"},
    {"Encoder", "StatusSensor[1].Error"},  // the page uses StatusSensor, not ErrorWord.X5 (spec 04 §9.2)
    {"Data exchange", "ErrorWord.X7"},
    {"I/O", "ErrorWord.X13"},
    {"Job rejected", "ErrorWord.X3"},
    {"Homing", "ErrorWord.X10"},
    {"Positioning", "ErrorWord.X12"},
    {"Dynamic limitation", "ErrorWord.X6"},
    {"Following error", "ErrorWord.X11"},
    {"Software limit switch", "ErrorWord.X8"},
    {"Hardware limit switch", "ErrorWord.X9"},
    {"Adaptation", "ErrorWord.X15"},
    {"Superimposition", "ErrorWord.X16"},
}};
constexpr std::array<LayoutItem, 4> kPositioningSetpoints{{
    {"Target position", "StatusPositioning.TargetPosition", true},
    {"Setpoint position", "Position", true},
    {"Setpoint velocity", "Velocity", true},
    {"Velocity override (%)", "Override.Velocity", true},
}};
constexpr std::array<LayoutItem, 4> kPositioningActual{{
    {"Operative encoder", "OperativeSensor", true},
    {"Actual position", "ActualPosition", true},
    {"Actual velocity", "ActualVelocity", true},
    {"Following error", "StatusPositioning.FollowingError", true},
}};
constexpr std::array<LayoutArea, 8> kPositioningLayout{{
    {"status", "Axis status", kPositioningStatus},
    {"status", "Limit switch status", kPositioningLimitSwitches},
    {"status", "Motion status", kPositioningMotion},
    {"status", "Warnings", kAxisWarnings},
    {"status", "Errors", kPositioningErrors},
    {"motion", "Setpoints", kPositioningSetpoints},
    {"motion", "Actual values", kPositioningActual},
    {"motion", "Dynamic limits", kDynamicLimits},
}};

// ---- spec 04 §9.3, TO_ExternalEncoder (no "Warnings" area) ----
constexpr std::array<LayoutItem, 7> kEncoderStatus{{
    {"Encoder enabled", "StatusWord.X0"},
    {"Homed", "StatusWord.X5"},
    {"Error", "StatusWord.X1"},
    {"Restart active", "StatusWord.X2"},
    {"Encoder actual values valid", "StatusSensor.State=2"},
    {"Encoder referenced", "StatusSensor.Adjusted"},
    {"Restart required", "StatusWord.X3"},
}};
constexpr std::array<LayoutItem, 3> kEncoderMotion{{
    {"Done (no job except MC_Power)", "StatusWord.X6"},
    {"Homing job", "StatusWord.X11"},
    {"Standstill", "StatusWord.X7"},
}};
constexpr std::array<LayoutItem, 6> kEncoderErrors{{
    {"System", "ErrorWord.X0"},
    {"Configuration", "ErrorWord.X1"},
    {"User program", "ErrorWord.X2"},
    {"Encoder", "ErrorWord.X5"},
    {"Data exchange", "ErrorWord.X7"},
    {"Adaptation", "ErrorWord.X15"},
}};
constexpr std::array<LayoutItem, 2> kEncoderActual{{
    {"Actual position", "ActualPosition", true},
    {"Actual velocity", "ActualVelocity", true},
}};
constexpr std::array<LayoutArea, 4> kEncoderLayout{{
    {"status", "Encoder status", kEncoderStatus},
    {"status", "Motion status", kEncoderMotion},
    {"status", "Errors", kEncoderErrors},
    {"motion", "Actual values", kEncoderActual},
}};

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ')
    s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ')
    s.remove_suffix(1);
  return s;
}

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// A variable or bit path -> (row, bit).
std::optional<ResolvedCondition> resolve_path(std::string_view path,
                                              std::span<const to::VariableInfo> table) {
  if (const to::VariableInfo* v = to::find_variable(table, path)) {
    return ResolvedCondition{static_cast<std::size_t>(v - table.data()), -1, false, false, 0.0};
  }
  if (const auto bit = to::find_bit(table, path)) {
    return ResolvedCondition{static_cast<std::size_t>(bit->word - table.data()), bit->bit, false, false, 0.0};
  }
  return std::nullopt;
}

bool truthy(double value, int bit) noexcept {
  if (bit < 0) return value != 0.0 && !std::isnan(value);
  if (!(value >= 0.0 && value < 4294967296.0)) return false;
  return ((static_cast<std::uint32_t>(value) >> bit) & 1u) != 0;
}

}  // namespace

std::span<const LayoutArea> diagnostics_layout(to::TechnologyObjectType type) noexcept {
  switch (type) {
    case to::TechnologyObjectType::kSpeedAxis:
      return kSpeedAxisLayout;
    case to::TechnologyObjectType::kPositioningAxis:
    case to::TechnologyObjectType::kSynchronousAxis:
      return kPositioningLayout;
    case to::TechnologyObjectType::kExternalEncoder:
      return kEncoderLayout;
    case to::TechnologyObjectType::kCam:  // no axis panel for a cam
      return {};
  }
  return {};
}

double ResolvedItem::evaluate(std::span<const double> values) const noexcept {
  if (value) return variable < values.size() ? values[variable] : std::nan("");
  for (const ResolvedCondition& c : any_of) {
    if (c.variable >= values.size()) continue;
    const double v = values[c.variable];
    bool on = c.compare ? v == c.equals : truthy(v, c.bit);
    if (c.negate) on = !on;
    if (on) return 1.0;
  }
  return 0.0;
}

std::optional<ResolvedItem> resolve(const LayoutItem& item, std::span<const to::VariableInfo> table,
                                    std::string* problem) {
  auto fail = [&](std::string_view part) -> std::optional<ResolvedItem> {
    if (problem != nullptr)
      *problem = std::string(item.label) + ": '" + std::string(part) + "' does not resolve";
    return std::nullopt;
  };
  ResolvedItem resolved;
  resolved.value = item.value;
  if (item.value) {
    const auto c = resolve_path(trim(item.source), table);
    if (!c || c->bit >= 0) return fail(item.source);
    resolved.variable = c->variable;
    return resolved;
  }
  std::string_view rest = item.source;
  while (!rest.empty()) {
    const auto bar = rest.find('|');
    std::string_view part = trim(rest.substr(0, bar));
    rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
    const bool negate = part.starts_with('!');
    if (negate) part.remove_prefix(1);
    std::optional<double> equals;
    if (const auto eq = part.find('='); eq != std::string_view::npos) {
      equals = parse_number(part.substr(eq + 1));
      if (!equals) return fail(part);
      part = part.substr(0, eq);
    }
    auto c = resolve_path(part, table);
    if (!c) return fail(part);
    c->negate = negate;
    if (equals) {
      if (c->bit >= 0) return fail(part);
      c->compare = true;
      c->equals = *equals;
    }
    resolved.any_of.push_back(*c);
  }
  if (resolved.any_of.empty()) return fail(item.source);
  return resolved;
}

}  // namespace tomc::diagnostics
