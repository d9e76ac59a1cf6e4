// The diagnostics hub between the cycle and the web server (diagnostics.hpp).
#include "tomc/diagnostics/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "tomc/diagnostics/positioning_panel.hpp"
#include "tomc/diagnostics/synchronous_view.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::diagnostics {

namespace to = tomc::techobjects;

std::string_view to_string(PanelAnswer answer) noexcept {
  switch (answer) {
    case PanelAnswer::kAccepted:
      return "accepted";
    case PanelAnswer::kNotSupported:
      return "this axis' control panel has no such function";
    case PanelAnswer::kProgramControlsAxis:
      return "the user program has not released the axis (MC_Power.Enable = TRUE or the axis is enabled)";
    case PanelAnswer::kHeldByOtherSession:
      return "another page holds control priority over this axis";
    case PanelAnswer::kNotHolder:
      return "this page does not hold control priority over this axis";
    case PanelAnswer::kGivingBack:
      return "control priority is being returned to the user program";
    case PanelAnswer::kInvalidValue:
      return "a value is out of range";
    case PanelAnswer::kUnknownObject:
      return "no such technology object";
    case PanelAnswer::kNoPanel:
      return "this technology object has no axis control panel";
    case PanelAnswer::kQueueFull:
      return "the command queue to the cycle is full";
    case PanelAnswer::kNoAnswer:
      return "the cycle did not answer (is the runtime running?)";
  }
  return "?";
}

std::string_view to_string(PanelCommandKind kind) noexcept {
  switch (kind) {
    case PanelCommandKind::kTake:
      return "take";
    case PanelCommandKind::kGiveBack:
      return "give_back";
    case PanelCommandKind::kLifebeat:
      return "lifebeat";
    case PanelCommandKind::kEnable:
      return "enable";
    case PanelCommandKind::kDisable:
      return "disable";
    case PanelCommandKind::kJog:
      return "jog";
    case PanelCommandKind::kMoveVelocity:
      return "velocity";
    case PanelCommandKind::kStop:
      return "stop";
    case PanelCommandKind::kAcknowledge:
      return "acknowledge";
    case PanelCommandKind::kSetDynamics:
      return "dynamics";
    case PanelCommandKind::kSetAdapt:
      return "adapt";
    case PanelCommandKind::kHome:
      return "home";
    case PanelCommandKind::kMoveAbsolute:
      return "move_absolute";
    case PanelCommandKind::kMoveRelative:
      return "move_relative";
  }
  return "?";
}

std::string_view to_string(PanelMotion motion) noexcept {
  switch (motion) {
    case PanelMotion::kNone:
      return "none";
    case PanelMotion::kJogForward:
      return "jog forwards";
    case PanelMotion::kJogBackward:
      return "jog backwards";
    case PanelMotion::kVelocityForward:
      return "velocity forwards";
    case PanelMotion::kVelocityBackward:
      return "velocity backwards";
    case PanelMotion::kStopping:
      return "stopping";
    case PanelMotion::kHoming:
      return "homing";
    case PanelMotion::kPositioning:
      return "positioning";
  }
  return "?";
}

Diagnostics::Diagnostics(DiagnosticsConfig config) : config_(config), recorder_(config.trace_ring_rows) {
  if (config_.publish_period_cycles == 0) throw std::invalid_argument("publish_period_cycles must be >= 1");
  for (auto& a : answers_)
    a.store(0, std::memory_order_relaxed);
}

Diagnostics::~Diagnostics() = default;

// ---------------------------------------------------------------------------------------------------------
// Set-up

void Diagnostics::add(to::SpeedAxis& axis) {
  add(std::make_unique<TechnologyObjectView<to::SpeedAxis>>(axis),
      std::make_unique<BasicAxisPanel<to::SpeedAxis>>(axis));
}

void Diagnostics::add(to::PositioningAxis& axis) {
  add(std::make_unique<TechnologyObjectView<to::PositioningAxis>>(axis),
      std::make_unique<PositioningAxisPanel>(axis));
}

void Diagnostics::add(to::SynchronousAxis& axis) {
  add(std::make_unique<SynchronousAxisView>(axis), std::make_unique<PositioningAxisPanel>(axis));
}

void Diagnostics::add(const to::Cam& cam) {
  add(std::make_unique<CamView>(cam), nullptr);
}

void Diagnostics::add(to::ExternalEncoder& encoder) {
  add(std::make_unique<TechnologyObjectView<to::ExternalEncoder>>(encoder), nullptr);
}

void Diagnostics::add(std::unique_ptr<ObjectView> view, std::unique_ptr<AxisPanel> panel) {
  if (attached_) throw std::logic_error("Diagnostics::add: already attached to the runtime");
  if (!view) throw std::invalid_argument("Diagnostics::add: no view");
  if (find_object(view->name())) {
    throw std::invalid_argument("Diagnostics::add: '" + std::string(view->name()) + "' is added twice");
  }
  auto object = std::make_unique<Object>();
  const auto table = view->variables();
  for (const LayoutArea& area : diagnostics_layout(view->type())) {
    for (const LayoutItem& item : area.items) {
      std::string problem;
      auto resolved = resolve(item, table, &problem);
      // The layouts are tested against every table (layout_test.cpp); this guards a table change.
      if (!resolved)
        throw std::logic_error("diagnostics layout of " + std::string(view->name()) + ": " + problem);
      object->items.push_back(std::move(*resolved));
    }
  }
  const std::size_t words = view->telegram_channels().size();
  object->buffer.for_each([&](ObjectSnapshot& s) {
    s.values.assign(table.size(), 0.0);
    s.words.assign(words, 0);
  });
  object->view = std::move(view);
  object->panel = std::move(panel);
  objects_.push_back(std::move(object));
}

void Diagnostics::set_actor(std::string_view object, ActorSource actor) {
  if (attached_) throw std::logic_error("Diagnostics::set_actor: already attached to the runtime");
  const auto i = find_object(object);
  if (!i) throw std::invalid_argument("Diagnostics::set_actor: no object '" + std::string(object) + "'");
  objects_[*i]->actor = actor;
}

void Diagnostics::add_switch(std::string name, std::string description, std::atomic<bool>& flag) {
  if (attached_) throw std::logic_error("Diagnostics::add_switch: already attached to the runtime");
  switches_.push_back(ProgramSwitch{std::move(name), std::move(description), &flag});
}

void Diagnostics::attach(to::Runtime& runtime) {
  if (attached_) throw std::logic_error("Diagnostics::attach: attached twice");
  servo_cycle_s_ = runtime.config().servo_cycle_s;
  std::lock_guard lock(mutex_);
  state_.objects.resize(objects_.size());
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    // Staggered over the publish period so that no cycle copies every object.
    objects_[i]->publish_slot =
        (i * config_.publish_period_cycles / objects_.size()) % config_.publish_period_cycles;
    state_.objects[i].snapshot.values.assign(objects_[i]->view->variables().size(), 0.0);
    state_.objects[i].snapshot.words.assign(objects_[i]->view->telegram_channels().size(), 0);
    // Configuration, fixed after download: read once here, before the cycle runs.
    const ObjectView& view = *objects_[i]->view;
    objects_[i]->units = object_units(view.variables(), view.data_block());
    if (const to::VariableInfo* v =
            to::find_variable(view.variables(), "Actor.DriveParameter.ReferenceSpeed"))
      objects_[i]->reference_speed = v->read_fn(view.data_block());
  }
  runtime.set_post_interpolator([this](to::Runtime& rt) { cycle(rt.clock()); });
  attached_ = true;
}

std::optional<std::size_t> Diagnostics::find_object(std::string_view name) const noexcept {
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (objects_[i]->view->name() == name) return i;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------------------
// The cycle

void Diagnostics::answer(std::uint64_t request, PanelAnswer answer) noexcept {
  answers_[request % answers_.size()].store((request << 8) | static_cast<std::uint64_t>(answer),
                                            std::memory_order_release);
}

void Diagnostics::cycle(const to::CycleClock& clock) noexcept {
  // 1. Panel commands: a bounded number per cycle, so a flood of requests cannot stretch the cycle.
  PanelCommand c;
  for (int i = 0; i < 16 && commands_.pop(c); ++i) {
    PanelAnswer a = PanelAnswer::kUnknownObject;
    if (c.object < objects_.size()) {
      AxisPanel* panel = objects_[c.object]->panel.get();
      a = panel == nullptr ? PanelAnswer::kNoPanel : panel->command(c);
    }
    answer(c.request, a);
  }
  // 2. Panels: lifebeat monitoring and their instruction calls.
  for (auto& o : objects_) {
    if (o->panel) o->panel->cycle(clock);
  }
  // 3. Snapshots, each object in its own slot of the publish period.
  const std::uint64_t slot = clock.servo_cycles % config_.publish_period_cycles;
  for (auto& o : objects_) {
    if (o->publish_slot == slot) publish(*o, clock.servo_cycles);
  }
  // 4. Trace.
  recorder_.sample(clock.servo_cycles);
}

void Diagnostics::publish(Object& object, std::uint64_t cycle) noexcept {
  ObjectSnapshot& s = object.buffer.back();
  const ObjectView& view = *object.view;
  s.cycle = cycle;
  s.revision = view.revision();
  object.actor.read(s.actor);
  const auto table = view.variables();
  // ObjectView::source_of() without its virtual calls per row (a positioning axis has ~610 rows).
  const void* data = view.data_block();
  const void* extension = view.extension_block();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const to::VariableInfo& row = table[i];
    s.values[i] = row.read_fn(row.owner == to::TechnologyObjectType::kSynchronousAxis ? extension : data);
  }
  for (std::size_t i = 0; i < s.words.size(); ++i)
    s.words[i] = view.telegram_word(i);
  s.alarm_count = 0;
  s.event_count = 0;
  if (const to::AlarmList* alarms = view.alarms()) {
    for (const to::PendingAlarm& a : alarms->alarms())
      s.alarms[s.alarm_count++] = a;
    const to::AlarmLogView log = alarms->log();
    const std::uint64_t last = log.last_sequence();
    const std::uint64_t after = last > kEventsPerSnapshot ? last - kEventsPerSnapshot : 0;
    s.event_count = static_cast<std::uint32_t>(log.copy_since(after, s.events));
  }
  if (object.panel) {
    object.panel->status(s.panel);
  } else {
    s.panel = PanelStatus{};
  }
  object.buffer.publish();
}

// ---------------------------------------------------------------------------------------------------------
// The other side

std::uint64_t Diagnostics::post(PanelCommand command) noexcept {
  if (command.object >= objects_.size() || !objects_[command.object]->panel) return 0;
  command.request = next_request_.fetch_add(1, std::memory_order_relaxed);
  return commands_.push(command) ? command.request : 0;
}

std::optional<PanelAnswer> Diagnostics::answer_of(std::uint64_t request) const noexcept {
  const std::uint64_t word = answers_[request % answers_.size()].load(std::memory_order_acquire);
  if ((word >> 8) != request) return std::nullopt;
  return static_cast<PanelAnswer>(word & 0xFF);
}

PanelAnswer Diagnostics::command(PanelCommand command, std::chrono::milliseconds timeout) {
  if (command.object >= objects_.size()) return PanelAnswer::kUnknownObject;
  if (!objects_[command.object]->panel) return PanelAnswer::kNoPanel;
  const std::uint64_t request = post(command);
  if (request == 0) return PanelAnswer::kQueueFull;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (const auto a = answer_of(request)) return *a;
    if (std::chrono::steady_clock::now() >= deadline) return PanelAnswer::kNoAnswer;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

bool Diagnostics::set_switch(std::string_view name, bool on) {
  for (auto& s : switches_) {
    if (s.name == name) {
      s.flag->store(on, std::memory_order_relaxed);
      return true;
    }
  }
  return false;
}

void Diagnostics::poll() {
  std::lock_guard lock(mutex_);
  ++state_.polls;
  const double now_unix_s =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    Object& o = *objects_[i];
    if (!o.buffer.update()) continue;
    ObjectState& st = state_.objects[i];
    st.snapshot = o.buffer.front();
    st.valid = true;
    const ObjectSnapshot& s = st.snapshot;
    // Alarm history: append the events newer than the last one kept; a gap means events were overwritten
    // before a poll saw them (more than kEventsPerSnapshot between two polls) and is counted.
    for (std::uint32_t e = 0; e < s.event_count; ++e) {
      const to::AlarmEvent& event = s.events[e];
      if (event.sequence <= st.last_sequence) continue;
      st.history_lost += event.sequence - st.last_sequence - 1;
      st.last_sequence = event.sequence;
      st.history.push_back(event);
      const double age_s =
          s.cycle >= event.cycle ? static_cast<double>(s.cycle - event.cycle) * servo_cycle_s_ : 0.0;
      st.history_unix_s.push_back(now_unix_s - age_s);
      while (st.history.size() > config_.alarm_history) {
        st.history.pop_front();
        st.history_unix_s.pop_front();
      }
    }
  }
  // The trace: progress before the drain decides completion (every row of a finished recording is in the ring
  // by then), progress after it classifies the rows by the trigger.
  TraceCapture& capture = state_.trace;
  const TraceRecorder::Progress before = recorder_.progress();
  recorder_.drain(drained_);
  const TraceRecorder::Progress after = recorder_.progress();
  capture.absorb(drained_, after);
  if (before.generation == capture.generation) {
    if (before.phase == TracePhase::kDone) capture.finish(false);
    if (before.phase == TracePhase::kStopped) capture.finish(true);
  }
}

std::vector<std::string> Diagnostics::start_trace(const TraceRequest& request) {
  std::vector<std::string> problems;
  TraceSetup setup;
  auto resolve_probe = [&](const std::string& name, const std::string& where) -> std::optional<Probe> {
    const auto dot = name.find('.');
    const auto object =
        dot == std::string::npos ? std::nullopt : find_object(std::string_view(name).substr(0, dot));
    if (!object) {
      problems.push_back(where + ": '" + name + "' names no technology object ('<TO>.<path>')");
      return std::nullopt;
    }
    auto probe = objects_[*object]->view->probe(std::string_view(name).substr(dot + 1));
    if (!probe) problems.push_back(where + ": '" + name + "' is not a variable, bit or telegram word");
    return probe;
  };
  if (request.channels.empty() || request.channels.size() > kMaxTraceChannels) {
    problems.push_back("channels: between 1 and " + std::to_string(kMaxTraceChannels) + " signals, got " +
                       std::to_string(request.channels.size()));
  }
  for (std::size_t i = 0; i < request.channels.size() && i < kMaxTraceChannels; ++i) {
    if (auto p = resolve_probe(request.channels[i], "channels[" + std::to_string(i) + "]")) {
      setup.channels[setup.channel_count++] = *p;
    }
  }
  setup.trigger = request.trigger;
  setup.threshold = request.threshold;
  if (request.trigger != TriggerKind::kImmediate) {
    if (auto p = resolve_probe(request.trigger_signal, "trigger.signal")) setup.trigger_probe = *p;
  }
  if (!std::isfinite(request.threshold)) problems.push_back("trigger.threshold: not a finite number");
  if (request.post_samples < 1) problems.push_back("post_samples: at least 1");
  if (static_cast<std::uint64_t>(request.pre_samples) + request.post_samples > kMaxTraceSamples) {
    problems.push_back("pre_samples + post_samples: at most " + std::to_string(kMaxTraceSamples));
  }
  if (request.decimation < 1 || request.decimation > kMaxTraceDecimation) {
    problems.push_back("decimation: 1 .. " + std::to_string(kMaxTraceDecimation));
  }
  setup.decimation = request.decimation;
  setup.post_samples = request.post_samples;
  if (!problems.empty()) return problems;

  std::lock_guard lock(mutex_);
  const std::uint32_t generation = recorder_.submit(setup);
  if (generation == 0) return {"the cycle has not yet taken the previous trace (is the runtime running?)"};
  TraceCapture capture;
  capture.state = TraceCapture::State::kWaitingForTrigger;
  capture.generation = generation;
  capture.channels = request.channels;
  capture.trigger_description =
      request.trigger == TriggerKind::kImmediate
          ? "immediate"
          : std::string(to_string(request.trigger)) + " " + request.trigger_signal +
                (request.trigger == TriggerKind::kAbove || request.trigger == TriggerKind::kBelow
                     ? " " + std::to_string(request.threshold)
                     : "");
  capture.pre_samples = request.pre_samples;
  capture.post_samples = request.post_samples;
  capture.decimation = request.decimation;
  capture.sample_period_s = servo_cycle_s_ * request.decimation;
  capture.cycles.reserve(request.pre_samples + request.post_samples);
  capture.values.reserve(static_cast<std::size_t>(request.pre_samples + request.post_samples) *
                         request.channels.size());
  state_.trace = std::move(capture);
  return {};
}

void Diagnostics::stop_trace() {
  std::lock_guard lock(mutex_);
  if (state_.trace.generation != 0) recorder_.stop(state_.trace.generation);
}

}  // namespace tomc::diagnostics
