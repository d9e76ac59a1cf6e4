// Responses of the web API (api.hpp): what Diagnostics collected, as JSON and CSV.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tomc/diagnostics/api.hpp"
#include "tomc/diagnostics/synchronous_view.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/word_fields.hpp"

namespace tomc::diagnostics::api {

namespace to = tomc::techobjects;
namespace tg = tomc::telegrams;

namespace {

constexpr std::pair<std::uint32_t, std::string_view> kCapabilityNames[] = {
    {capability::kEnable, "enable"},
    {capability::kJog, "jog"},
    {capability::kVelocity, "velocity"},
    {capability::kStop, "stop"},
    {capability::kAcknowledge, "acknowledge"},
    {capability::kAdaptVelocity, "adapt"},
    {capability::kHomeActive, "home_active"},
    {capability::kHomeSetPosition, "home_set"},
    {capability::kMoveAbsolute, "move_absolute"},
    {capability::kMoveRelative, "move_relative"},
};

Json capabilities(std::uint32_t mask) {
  Json list = Json::array();
  for (const auto& [bit, name] : kCapabilityNames) {
    if ((mask & bit) != 0) list.push_back(name);
  }
  return list;
}

std::string_view class_name(to::AlarmClass c) {
  switch (c) {
    case to::AlarmClass::kWarning:
      return "W";
    case to::AlarmClass::kAcknowledge:
      return "F";
    case to::AlarmClass::kRestart:
      return "R";
  }
  return "?";
}

// A number for JSON: NaN and infinities become null (JSON has neither).
Json number(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

// When a pending alarm was raised by the wall clock: the time of its "raised" event in the history (D9);
// null if the history no longer holds it.
Json raised_unix_s(const Diagnostics::ObjectState& o, const to::PendingAlarm& a) {
  for (std::size_t e = o.history.size(); e-- > 0;) {
    const to::AlarmEvent& event = o.history[e];
    if (event.kind == to::AlarmEvent::Kind::kRaised && event.number == a.number &&
        event.cycle == a.raised_cycle)
      return number(o.history_unix_s[e]);
  }
  return nullptr;
}

Json alarm_json(const to::PendingAlarm& a, const Diagnostics::ObjectState& o) {
  const to::AlarmDefinition* d = to::find_alarm(a.number);
  return Json{{"number", a.number},
              {"unix_s", raised_unix_s(o, a)},
              {"additional_value", a.additional_value},
              {"class", class_name(a.alarm_class)},
              {"reaction", static_cast<int>(a.reaction)},
              {"reaction_text", to::to_string(a.reaction)},
              {"text", d == nullptr ? std::string_view("?") : d->text},
              {"cycle", a.raised_cycle}};
}

Json event_json(const to::AlarmEvent& e, double unix_s) {
  const to::AlarmDefinition* d = to::find_alarm(e.number);
  return Json{{"sequence", e.sequence},
              {"cycle", e.cycle},
              {"unix_s", number(unix_s)},
              {"kind", e.kind == to::AlarmEvent::Kind::kRaised ? "raised" : "acknowledged"},
              {"number", e.number},
              {"additional_value", e.additional_value},
              {"reaction", static_cast<int>(e.reaction)},
              {"reaction_text", to::to_string(e.reaction)},
              {"text", d == nullptr ? std::string_view("?") : d->text}};
}

Json panel_json(const AxisPanel& panel, const PanelStatus& s) {
  Json instructions = Json::array();
  const auto names = panel.instruction_names();
  for (std::size_t i = 0; i < names.size() && i < s.instructions.size(); ++i) {
    const InstructionOutputs& o = s.instructions[i];
    instructions.push_back(Json{{"name", names[i]},
                                {"busy", o.busy},
                                {"done", o.done},
                                {"active", o.active},
                                {"error", o.error},
                                {"error_id", hex_error_id(o.error_id)}});
  }
  return Json{{"held", s.held},
              {"giving_back", s.giving_back},
              {"lifebeat_s", number(s.lifebeat_s)},
              {"lifebeat_age_s", number(s.lifebeat_age_s)},
              {"dynamics",
               {{"velocity", number(s.dynamics.velocity)},
                {"acceleration", number(s.dynamics.acceleration)},
                {"deceleration", number(s.dynamics.deceleration)},
                {"jerk", number(s.dynamics.jerk)}}},
              {"adapt_percent", number(s.adapt_percent)},
              {"motion", to_string(s.motion)},
              {"error_id", hex_error_id(s.error_id)},
              {"error_text", s.error_id == 0 ? std::string_view() : to::error_id::describe(s.error_id)},
              {"error_cycle", s.error_cycle},
              {"instructions", std::move(instructions)}};
}

std::string_view trace_state(TraceCapture::State s) {
  return to_string(s);
}

// What the page names instead of numbers on a synchronous axis (issue 19 "Page"): the leading axis of
// ActualMaster, the functions of FunctionState / WaitingFunctionState, the cam of ActualCam.
Json synchronous_json(const Diagnostics& diagnostics, const ObjectView& view, const ObjectSnapshot& s) {
  const auto table = view.variables();
  auto value = [&](std::string_view path) {
    const to::VariableInfo* v = to::find_variable(table, path);
    return v == nullptr ? 0.0 : s.values[static_cast<std::size_t>(v - table.data())];
  };
  const auto master = static_cast<std::size_t>(value("StatusSynchronizedMotion.ActualMaster"));
  const std::vector<std::string> leaders = view.leading_value_names();
  Json leader = master >= 1 && master <= leaders.size() ? Json(leaders[master - 1]) : Json(nullptr);
  const auto cam_number = static_cast<std::uint32_t>(value("StatusSynchronizedMotion.ActualCam"));
  Json cam = nullptr;
  for (std::size_t i = 0; cam_number != 0 && i < diagnostics.object_count(); ++i) {
    const to::Cam* c = diagnostics.view(i).cam();
    if (c != nullptr && c->number() == cam_number) cam = diagnostics.view(i).name();
  }
  return Json{
      {"leader", std::move(leader)},
      {"function",
       function_state_name(static_cast<std::int32_t>(value("StatusSynchronizedMotion.FunctionState")))},
      {"waiting", function_state_name(
                      static_cast<std::int32_t>(value("StatusSynchronizedMotion.WaitingFunctionState")))},
      {"cam", std::move(cam)}};
}

// The terminals of an analog or stepper actor (issue 20), shown instead of telegram words.
Json actor_json(const ActorSnapshot& a) {
  Json j{{"kind", to_string(a.kind)},
         {"enable_output", a.enable_output},
         {"ready_input", a.ready_input},
         {"counter", a.counter},
         {"measured_speed_rpm", number(a.measured_speed_rpm)},
         {"drive_state", tg::to_string(static_cast<tg::DriveState>(a.drive_state))},
         {"fault", a.fault},
         {"encoder_fault", a.encoder_fault}};
  if (a.kind == ActorKind::kAnalog) {
    j["output_percent"] = number(a.output_percent);
    j["output_volts"] = number(a.output_volts);
    j["output_code"] = a.output_code;
  } else {
    j["pulse_frequency_hz"] = number(a.pulse_frequency_hz);
  }
  return j;
}

}  // namespace

Json cam_plot(const CamPlot& plot) {
  return Json{{"start", plot.start},       {"end", plot.end},
              {"revision", plot.revision}, {"samples", plot.leading.size()},
              {"leading", plot.leading},   {"position", plot.position},
              {"velocity", plot.velocity}, {"acceleration", plot.acceleration}};
}

Json describe_objects(const Diagnostics& diagnostics) {
  Json objects = Json::array();
  for (std::size_t i = 0; i < diagnostics.object_count(); ++i) {
    const ObjectView& view = diagnostics.view(i);
    Json layout = Json::array();
    const ObjectUnits& units = diagnostics.units(i);
    const auto table = view.variables();
    auto unit_of = [&](std::string_view path) -> std::string_view {
      const to::VariableInfo* v = to::find_variable(table, path);
      return v == nullptr ? std::string_view() : units.symbol(quantity_of(*v));
    };
    for (const LayoutArea& area : diagnostics_layout(view.type())) {
      Json items = Json::array();
      for (const LayoutItem& item : area.items)
        items.push_back(Json{{"label", item.label},
                             {"source", item.source},
                             {"value", item.value},
                             {"unit", item.value ? unit_of(item.source) : std::string_view()}});
      layout.push_back(Json{{"page", area.page}, {"title", area.title}, {"items", std::move(items)}});
    }
    Json telegram = Json::array();
    for (const TelegramChannel& c : view.telegram_channels()) {
      Json fields = Json::array();
      for (const tg::NamedField& f : tg::word_fields(c.signal))
        fields.push_back(Json{{"name", f.name}, {"first_bit", f.field.first_bit}, {"width", f.field.width}});
      const tg::SignalInfo& info = tg::info(c.signal);
      telegram.push_back(
          Json{{"slot", slot_name(c.slot)},
               {"direction", tg::to_string(c.direction)},
               {"signal", info.name},
               {"bits", info.bits},
               {"signed", info.kind == tg::SignalKind::kNormalised || info.kind == tg::SignalKind::kSigned},
               {"normalised", info.kind == tg::SignalKind::kNormalised},
               {"fields", std::move(fields)}});
    }
    Json telegrams = Json::object();
    if (const to::DriveConnection* d = view.drive()) {
      const drives::DeviceConfig& device = d->device_config();
      telegrams = Json{{"drive", device.drive_telegram},
                       {"supplementary", device.supplementary_telegram},
                       {"encoder1", device.encoder_telegrams[0]},
                       {"encoder2", device.encoder_telegrams[1]}};
    }
    const AxisPanel* panel = diagnostics.panel(i);
    objects.push_back(
        Json{{"name", view.name()},
             {"type", type_name(view.type())},
             {"panel", panel != nullptr},
             {"capabilities", capabilities(panel == nullptr ? 0 : panel->capabilities())},
             {"instructions", panel == nullptr ? Json::array() : Json(panel->instruction_names())},
             {"layout", std::move(layout)},
             {"telegrams", std::move(telegrams)},
             {"telegram", std::move(telegram)},
             {"units",
              {{"position", units.position},
               {"velocity", units.velocity},
               {"acceleration", units.acceleration},
               {"jerk", units.jerk}}},
             {"reference_speed", diagnostics.reference_speed(i)},
             {"variable_count", view.variables().size()},
             // A synchronous axis: its leading values, StatusSynchronizedMotion.ActualMaster n is the n-th.
             {"actor", to_string(diagnostics.actor_kind(i))},
             {"leading_values", view.leading_value_names()},
             // A cam: the number a follower's StatusSynchronizedMotion.ActualCam shows (decision C8).
             {"cam_number", view.cam() != nullptr ? Json(view.cam()->number()) : Json(nullptr)}});
  }
  Json switches = Json::array();
  for (const ProgramSwitch& s : diagnostics.switches())
    switches.push_back(Json{{"name", s.name}, {"description", s.description}});
  return Json{{"servo_cycle_s", diagnostics.servo_cycle_s()},
              {"objects", std::move(objects)},
              {"switches", std::move(switches)},
              {"trace_limits",
               {{"channels", kMaxTraceChannels},
                {"samples", kMaxTraceSamples},
                {"decimation", kMaxTraceDecimation}}}};
}

Json status(const Diagnostics& diagnostics, const Diagnostics::State& state, std::size_t history_events) {
  Json objects = Json::array();
  std::uint64_t cycle = 0;
  for (std::size_t i = 0; i < diagnostics.object_count() && i < state.objects.size(); ++i) {
    const Diagnostics::ObjectState& o = state.objects[i];
    const ObjectView& view = diagnostics.view(i);
    const ObjectSnapshot& s = o.snapshot;
    cycle = std::max(cycle, s.cycle);
    const auto table = view.variables();
    auto value_of = [&](std::string_view path) -> Json {
      const to::VariableInfo* v = to::find_variable(table, path);
      if (v == nullptr || !o.valid) return nullptr;
      return number(s.values[static_cast<std::size_t>(v - table.data())]);
    };
    Json words = Json::object();
    for (const char* w : {"StatusWord", "StatusWord2", "ErrorWord", "WarningWord"}) {
      if (to::find_variable(table, w) != nullptr) words[w] = value_of(w);
    }
    Json items = Json::array();
    for (const ResolvedItem& item : diagnostics.layout_items(i))
      items.push_back(o.valid ? number(item.evaluate(s.values)) : Json(nullptr));
    Json alarms = Json::array();
    for (std::uint32_t a = 0; a < s.alarm_count; ++a)
      alarms.push_back(alarm_json(s.alarms[a], o));
    Json history = Json::array();
    const std::size_t first = o.history.size() > history_events ? o.history.size() - history_events : 0;
    for (std::size_t e = first; e < o.history.size(); ++e)
      history.push_back(event_json(o.history[e], o.history_unix_s[e]));
    const AxisPanel* panel = diagnostics.panel(i);
    Json object = Json{
        {"name", view.name()},
        {"valid", o.valid},
        {"cycle", s.cycle},
        {"words", std::move(words)},
        // The positions the TO derives from each encoder's XIST (telegram page: XIST as counts and
        // position); null for a TO without them (a speed axis).
        {"encoder_positions",
         to::find_variable(table, "StatusSensor.Position") != nullptr
             ? Json::array({value_of("StatusSensor.Position"), nullptr})
             : Json::array({value_of("StatusSensor[1].Position"), value_of("StatusSensor[2].Position")})},
        {"error_detail",
         {{"number", value_of("ErrorDetail.Number")}, {"reaction", value_of("ErrorDetail.Reaction")}}},
        {"items", std::move(items)},
        {"telegram", o.valid ? Json(s.words) : Json::array()},
        {"alarms", std::move(alarms)},
        {"history", std::move(history)},
        {"history_lost", o.history_lost},
        {"panel", panel != nullptr && o.valid ? panel_json(*panel, s.panel) : Json(nullptr)}};
    if (view.type() == to::TechnologyObjectType::kSynchronousAxis && o.valid)
      object["synchronous"] = synchronous_json(diagnostics, view, s);
    if (view.cam() != nullptr) object["revision"] = s.revision;
    if (s.actor.kind != ActorKind::kNone && o.valid) object["actor"] = actor_json(s.actor);
    objects.push_back(std::move(object));
  }
  Json switches = Json::array();
  for (const ProgramSwitch& sw : diagnostics.switches())
    switches.push_back(Json{{"name", sw.name}, {"on", sw.flag->load(std::memory_order_relaxed)}});
  const TraceCapture& t = state.trace;
  return Json{{"cycle", cycle},
              {"time_s", static_cast<double>(cycle) * diagnostics.servo_cycle_s()},
              {"objects", std::move(objects)},
              {"switches", std::move(switches)},
              {"trace",
               {{"state", trace_state(t.state)},
                {"generation", t.generation},
                {"rows", t.rows()},
                {"lost", t.lost},
                {"expected_rows", t.pre_samples + t.post_samples}}}};
}

Json variables(const Diagnostics& diagnostics, const Diagnostics::State& state, std::size_t object) {
  const ObjectView& view = diagnostics.view(object);
  const Diagnostics::ObjectState& o = state.objects[object];
  Json list = Json::array();
  const auto table = view.variables();
  const ObjectUnits& units = diagnostics.units(object);
  for (std::size_t i = 0; i < table.size(); ++i) {
    const to::VariableInfo& v = table[i];
    list.push_back(Json{{"path", v.path},
                        {"type", to::to_string(v.type)},
                        {"unit", units.symbol(quantity_of(v))},
                        {"access", to::to_string(v.access)},
                        {"status", v.role == to::VariableRole::kStatus},
                        {"value", o.valid ? number(o.snapshot.values[i]) : Json(nullptr)}});
  }
  return Json{{"name", view.name()}, {"cycle", o.snapshot.cycle}, {"variables", std::move(list)}};
}

Json alarms(const Diagnostics& diagnostics, const Diagnostics::State& state, std::size_t object) {
  const Diagnostics::ObjectState& o = state.objects[object];
  Json pending = Json::array();
  for (std::uint32_t a = 0; a < o.snapshot.alarm_count; ++a)
    pending.push_back(alarm_json(o.snapshot.alarms[a], o));
  Json history = Json::array();
  for (std::size_t e = 0; e < o.history.size(); ++e)
    history.push_back(event_json(o.history[e], o.history_unix_s[e]));
  return Json{{"name", diagnostics.view(object).name()},
              {"pending", std::move(pending)},
              {"history", std::move(history)},
              {"history_lost", o.history_lost}};
}

Json trace(const TraceCapture& c, std::size_t max_points) {
  const std::size_t rows = c.rows();
  const std::size_t width = c.channels.size();
  // Evenly picked rows for display; the trigger row is always one of them.
  std::vector<std::size_t> picked;
  if (rows <= max_points || max_points < 2) {
    for (std::size_t i = 0; i < rows; ++i)
      picked.push_back(i);
  } else {
    for (std::size_t k = 0; k < max_points; ++k)
      picked.push_back(k * (rows - 1) / (max_points - 1));
    if (c.trigger_row < rows) picked.push_back(c.trigger_row);
    std::sort(picked.begin(), picked.end());
    picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
  }
  const double t0 = c.trigger_row < rows ? static_cast<double>(c.cycles[c.trigger_row])
                                         : (rows > 0 ? static_cast<double>(c.cycles[0]) : 0.0);
  const double cycle_s = c.decimation == 0 ? c.sample_period_s : c.sample_period_s / c.decimation;
  Json time = Json::array();
  Json series = Json::array();
  for (std::size_t ch = 0; ch < width; ++ch)
    series.push_back(Json::array());
  for (const std::size_t r : picked) {
    time.push_back((static_cast<double>(c.cycles[r]) - t0) * cycle_s);
    for (std::size_t ch = 0; ch < width; ++ch)
      series[ch].push_back(number(c.values[r * width + ch]));
  }
  return Json{{"state", trace_state(c.state)},
              {"generation", c.generation},
              {"channels", c.channels},
              {"trigger", c.trigger_description},
              {"pre_samples", c.pre_samples},
              {"post_samples", c.post_samples},
              {"decimation", c.decimation},
              {"sample_period_s", c.sample_period_s},
              {"rows", rows},
              {"lost", c.lost},
              {"trigger_cycle", c.trigger_row < rows ? Json(c.cycles[c.trigger_row]) : Json(nullptr)},
              {"time_s", std::move(time)},
              {"values", std::move(series)}};
}

std::string trace_csv(const TraceCapture& c) {
  std::string out = "cycle,time";
  for (const auto& name : c.channels) {
    out += ',';
    // Channel names are "<TO>.<path>"; quote them only if a user managed to put a comma or quote in one.
    if (name.find_first_of(",\"\n\r") == std::string::npos) {
      out += name;
    } else {
      out += '"';
      for (const char ch : name)
        out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
      out += '"';
    }
  }
  out += '\n';
  const std::size_t rows = c.rows();
  const std::size_t width = c.channels.size();
  const double cycle_s = c.decimation == 0 ? c.sample_period_s : c.sample_period_s / c.decimation;
  const double t0 = c.trigger_row < rows ? static_cast<double>(c.cycles[c.trigger_row])
                                         : (rows > 0 ? static_cast<double>(c.cycles[0]) : 0.0);
  char buffer[40];
  for (std::size_t r = 0; r < rows; ++r) {
    out += std::to_string(c.cycles[r]);
    std::snprintf(buffer, sizeof buffer, ",%.9g", (static_cast<double>(c.cycles[r]) - t0) * cycle_s);
    out += buffer;
    for (std::size_t ch = 0; ch < width; ++ch) {
      std::snprintf(buffer, sizeof buffer, ",%.17g", c.values[r * width + ch]);  // reads back exactly
      out += buffer;
    }
    out += '\n';
  }
  return out;
}

}  // namespace tomc::diagnostics::api
