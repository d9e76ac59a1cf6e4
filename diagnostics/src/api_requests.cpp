// Request bodies of the web API (api.hpp): untrusted bytes -> commands, or one line saying what is wrong.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tomc/diagnostics/api.hpp"

namespace tomc::diagnostics::api {

namespace {

// Deepest bracket nesting outside strings, stopping early above `limit`: checked before parsing, so that a
// body like "[[[[...]]]]" never reaches the parser.
int nesting_depth(std::string_view s, int limit) {
  int depth = 0;
  int deepest = 0;
  bool in_string = false;
  bool escape = false;
  for (const char c : s) {
    if (in_string) {
      if (escape) {
        escape = false;
      } else if (c == '\\') {
        escape = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) return deepest;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

std::string_view kind_of(const Json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  return "an object";
}

// Typed access to the members of one request object; every key read is "known", unknown() names the rest.
class Fields {
 public:
  explicit Fields(const Json& object) : object_(object) {}

  const Json* get(std::string_view key) {
    known_.emplace_back(key);
    const auto it = object_.find(std::string(key));
    return it == object_.end() ? nullptr : &*it;
  }
  std::optional<double> number(std::string_view key, bool required, std::string& problem) {
    const Json* v = get(key);
    if (v == nullptr) {
      if (required) problem = std::string(key) + ": missing";
      return std::nullopt;
    }
    if (!v->is_number()) {
      problem = std::string(key) + ": expected a number, got " + std::string(kind_of(*v));
      return std::nullopt;
    }
    const double d = v->get<double>();
    if (!std::isfinite(d)) {
      problem = std::string(key) + ": not a finite number";
      return std::nullopt;
    }
    return d;
  }
  std::optional<std::int64_t> integer(std::string_view key, std::int64_t minimum, std::int64_t maximum,
                                      bool required, std::string& problem) {
    const auto d = number(key, required, problem);
    if (!d) return std::nullopt;
    if (std::floor(*d) != *d || *d < static_cast<double>(minimum) || *d > static_cast<double>(maximum)) {
      problem = std::string(key) + ": expected an integer " + std::to_string(minimum) + " .. " +
                std::to_string(maximum);
      return std::nullopt;
    }
    return static_cast<std::int64_t>(*d);
  }
  std::optional<bool> boolean(std::string_view key, bool required, std::string& problem) {
    const Json* v = get(key);
    if (v == nullptr) {
      if (required) problem = std::string(key) + ": missing";
      return std::nullopt;
    }
    if (!v->is_boolean()) {
      problem = std::string(key) + ": expected true or false, got " + std::string(kind_of(*v));
      return std::nullopt;
    }
    return v->get<bool>();
  }
  std::optional<std::string> string(std::string_view key, bool required, std::string& problem) {
    const Json* v = get(key);
    if (v == nullptr) {
      if (required) problem = std::string(key) + ": missing";
      return std::nullopt;
    }
    if (!v->is_string()) {
      problem = std::string(key) + ": expected a string, got " + std::string(kind_of(*v));
      return std::nullopt;
    }
    return v->get<std::string>();
  }
  // The first key nobody asked for ("" when none): a typo must not be ignored silently.
  std::string unknown() const {
    for (const auto& item : object_.items()) {
      if (std::find(known_.begin(), known_.end(), item.key()) == known_.end()) return item.key();
    }
    return {};
  }

 private:
  const Json& object_;
  std::vector<std::string> known_;
};

struct CommandName {
  std::string_view name;
  PanelCommandKind kind;
};
constexpr CommandName kCommands[] = {
    {"take", PanelCommandKind::kTake},
    {"give_back", PanelCommandKind::kGiveBack},
    {"lifebeat", PanelCommandKind::kLifebeat},
    {"enable", PanelCommandKind::kEnable},
    {"disable", PanelCommandKind::kDisable},
    {"jog", PanelCommandKind::kJog},
    {"velocity", PanelCommandKind::kMoveVelocity},
    {"stop", PanelCommandKind::kStop},
    {"acknowledge", PanelCommandKind::kAcknowledge},
    {"dynamics", PanelCommandKind::kSetDynamics},
    {"adapt", PanelCommandKind::kSetAdapt},
    {"home", PanelCommandKind::kHome},
    {"move_absolute", PanelCommandKind::kMoveAbsolute},
    {"move_relative", PanelCommandKind::kMoveRelative},
};

// Key names shown to users may come from the request: printable ASCII only, and short.
std::string printable(std::string_view s) {
  std::string out;
  for (const char c : s.substr(0, 40))
    out += (c >= 0x20 && c < 0x7F) ? c : '?';
  return out;
}

}  // namespace

std::variant<Json, std::string> parse_object(std::string_view body) {
  if (body.size() > kMaxBodyBytes) return std::string("body larger than 64 KiB");
  if (nesting_depth(body, kMaxJsonDepth) > kMaxJsonDepth) return std::string("JSON nested too deeply");
  Json json = Json::parse(body.begin(), body.end(), nullptr, false);
  if (json.is_discarded()) return std::string("malformed JSON");
  if (!json.is_object()) return "expected a JSON object, got " + std::string(kind_of(json));
  return json;
}

std::string to_text(const Json& json) {
  return json.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string hex_error_id(std::uint16_t error_id) {
  char text[12];
  std::snprintf(text, sizeof text, "16#%04X", static_cast<unsigned>(error_id));
  return text;
}

std::string session_text(std::uint64_t session) {
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(session));
  return text;
}

std::optional<std::uint64_t> parse_session(std::string_view text) noexcept {
  if (text.empty() || text.size() > 16) return std::nullopt;
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 16);
  if (error != std::errc{} || end != text.data() + text.size() || value == 0) return std::nullopt;
  return value;
}

std::variant<PanelCommand, std::string> parse_panel_command(std::string_view body) {
  auto parsed = parse_object(body);
  if (auto* e = std::get_if<std::string>(&parsed)) return *e;
  const Json& json = std::get<Json>(parsed);
  Fields f(json);
  std::string problem;
  PanelCommand c;
  const auto name = f.string("command", true, problem);
  if (!name) return problem;
  const auto* known = std::find_if(std::begin(kCommands), std::end(kCommands),
                                   [&](const CommandName& k) { return k.name == *name; });
  if (known == std::end(kCommands)) {
    std::string list;
    for (const auto& k : kCommands)
      list += (list.empty() ? "" : ", ") + std::string(k.name);
    return "command: '" + printable(*name) + "' is not a command (" + list + ")";
  }
  c.kind = known->kind;
  const auto session = f.string("session", true, problem);
  if (!session) return problem;
  const auto key = parse_session(*session);
  if (!key) return std::string("session: expected 1 to 16 hexadecimal digits, not all zero");
  c.session = *key;

  switch (c.kind) {
    case PanelCommandKind::kTake: {
      const auto lifebeat = f.number("lifebeat_s", false, problem);
      if (!problem.empty()) return problem;
      c.value = lifebeat.value_or(0.0);
      break;
    }
    case PanelCommandKind::kJog: {
      const auto d = f.integer("direction", -1, 1, true, problem);
      if (!d) return problem;
      c.direction = static_cast<std::int32_t>(*d);
      break;
    }
    case PanelCommandKind::kMoveVelocity: {
      const auto d = f.integer("direction", -1, 1, true, problem);
      if (!d) return problem;
      if (*d == 0) return std::string("direction: 1 (forwards) or -1 (backwards)");
      c.direction = static_cast<std::int32_t>(*d);
      break;
    }
    case PanelCommandKind::kStop: {
      const auto maximum = f.boolean("maximum", false, problem);
      if (!problem.empty()) return problem;
      c.mode = maximum.value_or(false) ? 1 : 0;
      break;
    }
    case PanelCommandKind::kSetDynamics: {
      const auto v = f.number("velocity", true, problem);
      const auto a = problem.empty() ? f.number("acceleration", true, problem) : std::nullopt;
      const auto d = problem.empty() ? f.number("deceleration", true, problem) : std::nullopt;
      const auto j = problem.empty() ? f.number("jerk", true, problem) : std::nullopt;
      if (!problem.empty()) return problem;
      c.dynamics = PanelDynamics{*v, *a, *d, *j};
      break;
    }
    case PanelCommandKind::kSetAdapt: {
      const auto p = f.number("percent", true, problem);
      if (!p) return problem;
      c.value = *p;
      break;
    }
    case PanelCommandKind::kHome: {
      const auto mode = f.string("mode", true, problem);
      if (!mode) return problem;
      if (*mode == "active") {
        c.mode = 3;  // MC_Home Mode 3 (spec 02 §9.4)
      } else if (*mode == "set") {
        c.mode = 0;  // MC_Home Mode 0, "set actual position"
      } else {
        return std::string("mode: 'active' (active homing) or 'set' (set actual position)");
      }
      const auto p = f.number("position", true, problem);
      if (!p) return problem;
      c.value = *p;
      break;
    }
    case PanelCommandKind::kMoveAbsolute: {
      const auto p = f.number("position", true, problem);
      if (!p) return problem;
      c.value = *p;
      const auto d = f.integer("direction", -1, 1, false, problem);
      if (!problem.empty()) return problem;
      c.direction = static_cast<std::int32_t>(d.value_or(0));
      break;
    }
    case PanelCommandKind::kMoveRelative: {
      const auto p = f.number("distance", true, problem);
      if (!p) return problem;
      c.value = *p;
      const auto d = f.integer("direction", -1, 1, false, problem);
      if (!problem.empty()) return problem;
      if (d.value_or(1) == 0) return std::string("direction: 1 or -1");
      c.direction = static_cast<std::int32_t>(d.value_or(1));
      break;
    }
    case PanelCommandKind::kGiveBack:
    case PanelCommandKind::kLifebeat:
    case PanelCommandKind::kEnable:
    case PanelCommandKind::kDisable:
    case PanelCommandKind::kAcknowledge:
      break;
  }
  if (const std::string extra = f.unknown(); !extra.empty()) {
    return "'" + printable(extra) + "' is not a parameter of '" + std::string(known->name) + "'";
  }
  return c;
}

std::variant<TraceRequest, std::string> parse_trace_request(std::string_view body) {
  auto parsed = parse_object(body);
  if (auto* e = std::get_if<std::string>(&parsed)) return *e;
  const Json& json = std::get<Json>(parsed);
  Fields f(json);
  std::string problem;
  TraceRequest r;
  const Json* channels = f.get("channels");
  if (channels == nullptr) return std::string("channels: missing");
  if (!channels->is_array())
    return "channels: expected an array of signal names, got " + std::string(kind_of(*channels));
  if (channels->empty() || channels->size() > kMaxTraceChannels) {
    return "channels: between 1 and " + std::to_string(kMaxTraceChannels) + " signals";
  }
  for (std::size_t i = 0; i < channels->size(); ++i) {
    const Json& c = (*channels)[i];
    if (!c.is_string() || c.get_ref<const std::string&>().empty() ||
        c.get_ref<const std::string&>().size() > 200) {
      return "channels[" + std::to_string(i) + "]: expected a signal name '<TO>.<path>'";
    }
    r.channels.push_back(c.get<std::string>());
  }
  if (const Json* t = f.get("trigger")) {
    if (!t->is_object()) return "trigger: expected an object, got " + std::string(kind_of(*t));
    Fields tf(*t);
    const auto kind = tf.string("kind", true, problem);
    if (!kind) return "trigger." + problem;
    constexpr std::pair<std::string_view, TriggerKind> kKinds[] = {{"immediate", TriggerKind::kImmediate},
                                                                   {"rising", TriggerKind::kRisingEdge},
                                                                   {"falling", TriggerKind::kFallingEdge},
                                                                   {"above", TriggerKind::kAbove},
                                                                   {"below", TriggerKind::kBelow}};
    const auto* k =
        std::find_if(std::begin(kKinds), std::end(kKinds), [&](const auto& p) { return p.first == *kind; });
    if (k == std::end(kKinds)) return std::string("trigger.kind: immediate, rising, falling, above or below");
    r.trigger = k->second;
    if (r.trigger != TriggerKind::kImmediate) {
      const auto signal = tf.string("signal", true, problem);
      if (!signal) return "trigger." + problem;
      if (signal->empty() || signal->size() > 200)
        return std::string("trigger.signal: expected '<TO>.<path>'");
      r.trigger_signal = *signal;
    }
    if (r.trigger == TriggerKind::kAbove || r.trigger == TriggerKind::kBelow) {
      const auto threshold = tf.number("threshold", true, problem);
      if (!threshold) return "trigger." + problem;
      r.threshold = *threshold;
    }
    if (const std::string extra = tf.unknown(); !extra.empty()) {
      return "trigger: '" + printable(extra) + "' is not a parameter of a '" + std::string(k->first) +
             "' trigger";
    }
  }
  const auto pre = f.integer("pre_samples", 0, kMaxTraceSamples, false, problem);
  if (!problem.empty()) return problem;
  const auto post = f.integer("post_samples", 1, kMaxTraceSamples, false, problem);
  if (!problem.empty()) return problem;
  const auto decimation = f.integer("decimation", 1, kMaxTraceDecimation, false, problem);
  if (!problem.empty()) return problem;
  r.pre_samples = static_cast<std::uint32_t>(pre.value_or(0));
  r.post_samples = static_cast<std::uint32_t>(post.value_or(1000));
  r.decimation = static_cast<std::uint32_t>(decimation.value_or(1));
  if (static_cast<std::uint64_t>(r.pre_samples) + r.post_samples > kMaxTraceSamples) {
    return "pre_samples + post_samples: at most " + std::to_string(kMaxTraceSamples);
  }
  if (const std::string extra = f.unknown(); !extra.empty()) {
    return "'" + printable(extra) + "' is not a parameter of a trace";
  }
  return r;
}

std::variant<bool, std::string> parse_switch(std::string_view body) {
  auto parsed = parse_object(body);
  if (auto* e = std::get_if<std::string>(&parsed)) return *e;
  Fields f(std::get<Json>(parsed));
  std::string problem;
  const auto on = f.boolean("on", true, problem);
  if (!on) return problem;
  if (const std::string extra = f.unknown(); !extra.empty())
    return "'" + printable(extra) + "' is not a parameter";
  return *on;
}

namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// The snapshot value of a data-block variable by its path; nullopt without a snapshot or such a variable.
std::optional<double> value_of(std::span<const techobjects::VariableInfo> variables,
                               std::span<const double> values, std::string_view path) {
  for (std::size_t i = 0; i < variables.size() && i < values.size(); ++i) {
    if (variables[i].path == path) return values[i];
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_panel_ranges(const PanelCommand& c,
                                              std::span<const techobjects::VariableInfo> variables,
                                              std::span<const double> values) {
  constexpr double kRange = 1.0e12;  // LREAL positions and dynamics of the data block (spec 04 §0.2)
  const auto limit = [&](std::string_view path) { return value_of(variables, values, path); };
  const auto within_range = [&](std::string_view key, double v) -> std::optional<std::string> {
    if (std::abs(v) > kRange) return std::string(key) + ": " + number_text(v) + " outside -1.0E12 .. 1.0E12";
    return std::nullopt;
  };
  switch (c.kind) {
    case PanelCommandKind::kTake:
      if (c.value != 0.0 && !(c.value >= AxisPanel::kMinLifebeatS && c.value <= AxisPanel::kMaxLifebeatS))
        return "lifebeat_s: " + number_text(c.value) + " outside 0.1 .. 60 s (0: the default 1.5 s)";
      return std::nullopt;
    case PanelCommandKind::kSetDynamics: {
      struct Field {
        const char* key;
        double value;
        const char* limit;
      };
      const Field fields[] = {{"velocity", c.dynamics.velocity, "DynamicLimits.MaxVelocity"},
                              {"acceleration", c.dynamics.acceleration, "DynamicLimits.MaxAcceleration"},
                              {"deceleration", c.dynamics.deceleration, "DynamicLimits.MaxDeceleration"},
                              {"jerk", c.dynamics.jerk, "DynamicLimits.MaxJerk"}};
      for (const Field& f : fields) {
        const bool jerk = std::string_view(f.key) == "jerk";
        if (jerk ? f.value < 0.0 : f.value <= 0.0)
          return std::string(f.key) + ": " + number_text(f.value) + (jerk ? " below 0" : " not above 0");
        if (auto problem = within_range(f.key, f.value)) return problem;
        const auto max = limit(f.limit);
        if (max && (!jerk || *max > 0.0) && f.value > *max) {
          return std::string(f.key) + ": " + number_text(f.value) + " above the axis' " + f.limit + " " +
                 number_text(*max);
        }
      }
      return std::nullopt;
    }
    case PanelCommandKind::kHome:
    case PanelCommandKind::kMoveAbsolute: {
      if (auto problem = within_range("position", c.value)) return problem;
      if (limit("Modulo.Enable").value_or(0.0) != 0.0) {
        const double start = limit("Modulo.StartValue").value_or(0.0);
        const double length = limit("Modulo.Length").value_or(0.0);
        if (length > 0.0 && !(c.value >= start && c.value < start + length)) {
          return "position: " + number_text(c.value) + " outside the modulo range " + number_text(start) +
                 " .. " + number_text(start + length) + " (Modulo.StartValue, Modulo.Length)";
        }
      } else if (c.kind == PanelCommandKind::kMoveAbsolute &&
                 limit("PositionLimits_SW.Active").value_or(0.0) != 0.0) {
        const auto lo = limit("PositionLimits_SW.MinPosition");
        const auto hi = limit("PositionLimits_SW.MaxPosition");
        if (lo && hi && !(c.value >= *lo && c.value <= *hi)) {
          return "position: " + number_text(c.value) + " outside the software limits " + number_text(*lo) +
                 " .. " + number_text(*hi) + " (PositionLimits_SW)";
        }
      }
      return std::nullopt;
    }
    case PanelCommandKind::kMoveRelative:
      return within_range("distance", c.value);
    default:
      return std::nullopt;
  }
}

}  // namespace tomc::diagnostics::api
