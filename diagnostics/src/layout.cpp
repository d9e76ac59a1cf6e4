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
// The jobs of seed 004 ch. 9 that the manual's §8.2 page predates (issue 18): superimposed motion, torque on
// telegram 750, MC_PositionProfile and MotionIn, each by the status bit or DINT the data block has for it
// (spec 04 §5.1, §5.2, §4.7, §4.8).
constexpr std::array<LayoutItem, 10> kPositioningJobs{{
    {"MC_MoveSuperimposed (StatusWord.X23)", "StatusWord.X23"},
    {"MC_HaltSuperimposed (StatusWord2.X7)", "StatusWord2.X7"},
    {"MC_PositionProfile (StatusWord2.X9)", "StatusWord2.X9"},
    {"On profile (StatusWord2.X10)", "StatusWord2.X10"},
    {"MotionIn (StatusWord.X31)", "StatusWord.X31"},
    {"MC_MotionInSuperimposed (StatusWord2.X6)", "StatusWord2.X6"},
    {"MotionIn on several axes (StatusWord2.X8)", "StatusWord2.X8"},
    {"Torque limiting job (StatusWord.X26)", "StatusWord.X26"},
    {"Additive torque active", "StatusTorqueData.CommandAdditiveTorqueActive=1"},
    {"Torque range active", "StatusTorqueData.CommandTorqueRangeActive=1"},
}};
constexpr std::array<LayoutItem, 5> kPositioningJobValues{{
    {"Superimposed distance", "StatusPositioning.SuperimposedDistance", true},
    {"Actual torque", "StatusTorqueData.ActualTorque", true},
    {"Total additive torque", "StatusTorqueData.TotalTorqueAdditive", true},
    {"MotionIn function state", "StatusMotionIn.FunctionState", true},
    {"MotionIn status word", "StatusMotionIn.StatusWord", true},
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
constexpr std::array<LayoutArea, 10> kPositioningLayout{{
    {"status", "Axis status", kPositioningStatus},
    {"status", "Limit switch status", kPositioningLimitSwitches},
    {"status", "Motion status", kPositioningMotion},
    {"status", "Superimposed, torque, profile and MotionIn jobs", kPositioningJobs},
    {"status", "Warnings", kAxisWarnings},
    {"status", "Errors", kPositioningErrors},
    {"motion", "Setpoints", kPositioningSetpoints},
    {"motion", "Actual values", kPositioningActual},
    {"motion", "Superimposed motion and torque", kPositioningJobValues},
    {"motion", "Dynamic limits", kDynamicLimits},
}};

// ---- TO_SynchronousAxis: the positioning axis' page plus synchronous operation (issue 19; spec 07 §1.9,
// spec 04 §5.1/§5.2 bits of Y; the manual's §8.2 page shows these only in its synchronous-operation view)
// ----
constexpr std::array<LayoutItem, 14> kSynchronousStatus{{
    {"Synchronizing (StatusWord.X21)", "StatusWord.X21"},
    {"Synchronous (StatusWord.X22)", "StatusWord.X22"},
    {"Desynchronizing (StatusWord2.X1)", "StatusWord2.X1"},
    {"Gearing active",
     "StatusSynchronizedMotion.FunctionState=1 | StatusSynchronizedMotion.FunctionState=2 | "
     "StatusSynchronizedMotion.FunctionState=6 | StatusSynchronizedMotion.FunctionState=4"},
    {"Camming active", "StatusSynchronizedMotion.FunctionState=3 | StatusSynchronizedMotion.FunctionState=5"},
    {"Synchronous job waiting", "!StatusSynchronizedMotion.WaitingFunctionState=0"},
    {"Phasing (StatusWord.X24)", "StatusWord.X24"},
    {"Phasing waiting (StatusWord2.X3)", "StatusWord2.X3"},
    {"Offset (StatusWord2.X4)", "StatusWord2.X4"},
    {"Offset waiting (StatusWord2.X5)", "StatusWord2.X5"},
    {"Leading value additive", "StatusSynchronizedMotion.StatusWord.X4"},
    {"Synchronous motion simulation", "StatusSynchronizedMotion.StatusWord.X3"},
    {"Dynamic limit exceeded (velocity, acceleration, deceleration)",
     "StatusSynchronizedMotion.StatusWord.X0 | StatusSynchronizedMotion.StatusWord.X1 | "
     "StatusSynchronizedMotion.StatusWord.X2"},
    {"Synchronous operation error (ErrorWord.X14)", "ErrorWord.X14"},
}};
// Leader-side positions are in the leading axis' units (spec 07 §1.2: no conversion), so units.cpp gives
// them none; velocities and accelerations of the leading value are the follower's (decision C16).
constexpr std::array<LayoutItem, 6> kSynchronousLeading{{
    {"Leading axis (ActualMaster)", "StatusSynchronizedMotion.ActualMaster", true},
    {"Effective leading value position", "StatusSynchronizedMotion.EffectiveLeadingValue.Position", true},
    {"Effective leading value velocity", "StatusSynchronizedMotion.EffectiveLeadingValue.Velocity", true},
    {"Effective leading value acceleration", "StatusSynchronizedMotion.EffectiveLeadingValue.Acceleration",
     true},
    {"Phase shift", "StatusSynchronizedMotion.PhaseShift", true},
    {"Function leading value position", "StatusSynchronizedMotion.FunctionLeadingValue.Position", true},
}};
constexpr std::array<LayoutItem, 10> kSynchronousFollowing{{
    {"Active function (FunctionState)", "StatusSynchronizedMotion.FunctionState", true},
    {"Waiting function (WaitingFunctionState)", "StatusSynchronizedMotion.WaitingFunctionState", true},
    {"Active cam (ActualCam)", "StatusSynchronizedMotion.ActualCam", true},
    {"Function following value position", "StatusSynchronizedMotion.FunctionFollowingValue.Position", true},
    {"Function following value velocity", "StatusSynchronizedMotion.FunctionFollowingValue.Velocity", true},
    {"Function following value acceleration", "StatusSynchronizedMotion.FunctionFollowingValue.Acceleration",
     true},
    {"Offset", "StatusSynchronizedMotion.Offset", true},
    {"Master offset", "StatusSynchronizedMotion.MasterOffset", true},
    {"Master scaling", "StatusSynchronizedMotion.MasterScaling", true},
    {"Slave offset", "StatusSynchronizedMotion.SlaveOffset", true},
}};
constexpr std::array<LayoutArea, 13> kSynchronousLayout{{
    {"status", "Axis status", kPositioningStatus},
    {"status", "Limit switch status", kPositioningLimitSwitches},
    {"status", "Motion status", kPositioningMotion},
    {"status", "Synchronous operation", kSynchronousStatus},
    {"status", "Superimposed, torque, profile and MotionIn jobs", kPositioningJobs},
    {"status", "Warnings", kAxisWarnings},
    {"status", "Errors", kPositioningErrors},
    {"motion", "Leading value", kSynchronousLeading},
    {"motion", "Following value", kSynchronousFollowing},
    {"motion", "Setpoints", kPositioningSetpoints},
    {"motion", "Actual values", kPositioningActual},
    {"motion", "Superimposed motion and torque", kPositioningJobValues},
    {"motion", "Dynamic limits", kDynamicLimits},
}};

// ---- TO_Cam (spec 07 §3.1): its status word and definition range; the plot is cam_plot.hpp ----
constexpr std::array<LayoutItem, 6> kCamStatus{{
    {"Interpolated (StatusWord.X5)", "StatusWord.X5"},
    {"In use by camming (StatusWord.X0)", "StatusWord.X0"},
    {"Cam data changed since interpolation (StatusWord.X4)", "StatusWord.X4"},
    {"Error", "StatusWord.X1"},
    {"Interpolation running (StatusWord.X6)", "StatusWord.X6"},
    {"MC_CopyCamData active (StatusWord.X7)", "StatusWord.X7"},
}};
constexpr std::array<LayoutItem, 4> kCamRange{{
    {"Start leading value", "StatusCam.StartLeadingValue", true},
    {"End leading value", "StatusCam.EndLeadingValue", true},
    {"Valid points", "StatusCam.NumberOfValidPoints", true},
    {"Valid segments", "StatusCam.NumberOfValidSegments", true},
}};
constexpr std::array<LayoutArea, 2> kCamLayout{{
    {"status", "Cam status", kCamStatus},
    {"motion", "Definition range", kCamRange},
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
      return kPositioningLayout;
    case to::TechnologyObjectType::kSynchronousAxis:
      return kSynchronousLayout;
    case to::TechnologyObjectType::kExternalEncoder:
      return kEncoderLayout;
    case to::TechnologyObjectType::kCam:
      return kCamLayout;
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
