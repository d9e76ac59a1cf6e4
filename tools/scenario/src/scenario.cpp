// The scenario engine (scenario.hpp, docs/scenarios.md). Loading validates everything before the first cycle:
// a scenario that starts runs to its end, so a typo at cycle 2900 of a long file costs no waiting.
#include "tomc/scenario/scenario.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <functional>
#include <limits>
#include <ostream>
#include <span>
#include <sstream>

#include "instances.hpp"
#include "json_reader.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/scenario/machine.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/motion/axis_units.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/retentive_store.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::scenario {
namespace {

namespace to = tomc::techobjects;
using detail::Instance;
using detail::ObjectReader;
using Reaction = drives::SimulatedDriveParameters::FaultReaction;

constexpr std::int64_t kMaxCycles = 1'000'000'000;  // 11.6 days at 1 ms: far beyond any test, still finite
constexpr double kDefaultTolerance = 1e-9;

std::string list_of(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

std::string list_of(std::span<const std::string_view> names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

// %.17g: every real of the trace reads back as the same double.
std::string format_real(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

enum class Format : std::uint8_t { kBool, kInteger, kReal };

Format format_of(to::VariableType type) {
  if (type == to::VariableType::kBool) return Format::kBool;
  if (type == to::VariableType::kLreal) return Format::kReal;
  return Format::kInteger;
}

Format format_of(detail::ParameterType type) {
  switch (type) {
    case detail::ParameterType::kBool:
      return Format::kBool;
    case detail::ParameterType::kLreal:
      return Format::kReal;
    case detail::ParameterType::kInt:
    case detail::ParameterType::kDint:
    case detail::ParameterType::kWord:
    case detail::ParameterType::kTechnologyObject:
    case detail::ParameterType::kCam:
    case detail::ParameterType::kTimePosition:
      break;
  }
  return Format::kInteger;
}

std::string format_value(double value, Format format) {
  switch (format) {
    case Format::kBool:
      return value != 0.0 ? "1" : "0";
    case Format::kInteger:
      return std::to_string(static_cast<long long>(value));
    case Format::kReal:
      break;
  }
  return format_real(value);
}

// What the simulated drive shows beyond the telegram, as "<TO>.drive.<name>" (an extension of the contract's
// trace names: the spec tests need the drive's own view, e.g. its state after an OFF1).
struct DriveObservable {
  std::string_view name;
  Format format;
  double (*read)(const drives::SimulatedDrive&) noexcept;
};
constexpr std::array<DriveObservable, 6> kDriveObservables{{
    {"state", Format::kInteger,
     [](const drives::SimulatedDrive& d) noexcept { return static_cast<double>(d.state()); }},
    {"active_fault", Format::kInteger,
     [](const drives::SimulatedDrive& d) noexcept { return static_cast<double>(d.active_fault()); }},
    {"motor_speed_rpm", Format::kReal,
     [](const drives::SimulatedDrive& d) noexcept { return d.motor_speed_rpm(); }},
    {"motor_torque_nm", Format::kReal,
     [](const drives::SimulatedDrive& d) noexcept { return d.motor_torque_nm(); }},
    {"load_position", Format::kReal,
     [](const drives::SimulatedDrive& d) noexcept { return d.load_position(); }},
    {"load_speed", Format::kReal, [](const drives::SimulatedDrive& d) noexcept { return d.load_speed(); }},
}};

// What the analog actor and its amplifier show, as "<TO>.analog.<name>", and what the stepper actor and its
// motor show, as "<TO>.stepper.<name>" (docs/analog-drives.md): the signals the diagnostics show instead of
// telegram words for such an axis.
template <class Drive>
struct ActorObservable {
  std::string_view name;
  Format format;
  double (*read)(const Drive&) noexcept;
};
using AnalogObservable = ActorObservable<drives::SimulatedAnalogDrive>;
using StepperObservable = ActorObservable<drives::SimulatedStepperDrive>;
constexpr std::array<AnalogObservable, 11> kAnalogObservables{{
    {"offset_volts", Format::kReal,
     [](const drives::SimulatedAnalogDrive& d) noexcept { return d.actor().parameters().offset_volts; }},
    {"TarOffs.ValOf", Format::kInteger,
     [](const drives::SimulatedAnalogDrive& d) noexcept {
       return static_cast<double>(d.actor().offset_calibration_status().ValOf);
     }},
    {"TarOffs.EndTr", Format::kBool,
     [](const drives::SimulatedAnalogDrive& d) noexcept {
       return d.actor().offset_calibration_status().EndTr ? 1.0 : 0.0;
     }},
    {"TarOffs.Error", Format::kInteger,
     [](const drives::SimulatedAnalogDrive& d) noexcept {
       return static_cast<double>(d.actor().offset_calibration_status().Error);
     }},
    {"output_volts", Format::kReal,
     [](const drives::SimulatedAnalogDrive& d) noexcept { return d.actor().output_volts(); }},
    {"output_code", Format::kInteger,
     [](const drives::SimulatedAnalogDrive& d) noexcept {
       return static_cast<double>(d.actor().output_code());
     }},
    {"enable_output", Format::kBool,
     [](const drives::SimulatedAnalogDrive& d) noexcept { return d.actor().enable_output() ? 1.0 : 0.0; }},
    {"ready_input", Format::kBool,
     [](const drives::SimulatedAnalogDrive& d) noexcept { return d.actor().ready_input() ? 1.0 : 0.0; }},
    {"counter", Format::kInteger,
     [](const drives::SimulatedAnalogDrive& d) noexcept {
       return static_cast<double>(d.actor().counter_value());
     }},
    {"active_fault", Format::kInteger,
     [](const drives::SimulatedAnalogDrive& d) noexcept {
       return static_cast<double>(d.actor().active_fault());
     }},
    {"load_position", Format::kReal,
     [](const drives::SimulatedAnalogDrive& d) noexcept { return d.hardware().mechanics().load_position(); }},
}};
constexpr std::array<StepperObservable, 10> kStepperObservables{{
    {"pulse_frequency_hz", Format::kReal,
     [](const drives::SimulatedStepperDrive& d) noexcept { return d.actor().pulse_frequency_hz(); }},
    {"enable_output", Format::kBool,
     [](const drives::SimulatedStepperDrive& d) noexcept { return d.actor().enable_output() ? 1.0 : 0.0; }},
    {"ready_input", Format::kBool,
     [](const drives::SimulatedStepperDrive& d) noexcept { return d.actor().ready_input() ? 1.0 : 0.0; }},
    {"counter", Format::kInteger,
     [](const drives::SimulatedStepperDrive& d) noexcept {
       return static_cast<double>(d.actor().counter_value());
     }},
    {"active_fault", Format::kInteger,
     [](const drives::SimulatedStepperDrive& d) noexcept {
       return static_cast<double>(d.actor().active_fault());
     }},
    {"pulses_sent", Format::kInteger,
     [](const drives::SimulatedStepperDrive& d) noexcept {
       return static_cast<double>(d.hardware().pulses_sent());
     }},
    {"rotor_steps", Format::kInteger,
     [](const drives::SimulatedStepperDrive& d) noexcept {
       return static_cast<double>(d.hardware().rotor_steps());
     }},
    {"lost_steps", Format::kInteger,
     [](const drives::SimulatedStepperDrive& d) noexcept {
       return static_cast<double>(d.hardware().lost_steps());
     }},
    {"in_step", Format::kBool,
     [](const drives::SimulatedStepperDrive& d) noexcept { return d.hardware().in_step() ? 1.0 : 0.0; }},
    {"load_position", Format::kReal,
     [](const drives::SimulatedStepperDrive& d) noexcept {
       return d.hardware().mechanics().load_position();
     }},
}};

// "<TO>.<kind>.<observable>" of an actor drive (analog or stepper); nullopt and a problem when the TO has no
// such drive or the name is unknown.
template <class Drive, std::size_t N>
std::optional<std::function<double()>> actor_observable(const std::array<ActorObservable<Drive>, N>& table,
                                                        const Drive* drive, std::string_view kind,
                                                        std::string_view head, std::string_view observable,
                                                        const std::string& path, Format& format,
                                                        Problems& problems) {
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const ActorObservable<Drive>& d) { return d.name == observable; });
  if (drive == nullptr || it == table.end()) {
    std::string names;
    for (const auto& d : table)
      names += (names.empty() ? "" : ", ") + std::string(d.name);
    problems.add(path, drive == nullptr
                           ? "'" + std::string(head) + "' has no " + std::string(kind) + " drive"
                           : "'" + std::string(observable) + "' is not " + (kind == "analog" ? "an " : "a ") +
                                 std::string(kind) + " drive value (" + names + ")");
    return std::nullopt;
  }
  format = it->format;
  return [drive, read = it->read] { return read(*drive); };
}

using TechnologyObjectEntry = MachineObject;

struct InstanceEntry {
  std::string name;
  std::string instruction;
  std::string defined_at;  // JSON path of the first event
  std::size_t axis = 0;
  std::string axis_name;
  bool cpu_wide = false;         // no Axis input (MC_SaveAbsoluteEncoderData)
  std::unique_ptr<Instance> fb;  // nullptr: unknown instruction (already reported)
};

enum class FaultKind : std::uint8_t {
  kDriveFault,
  kEncoderError,
  kSignOfLifeFreeze,
  kLinkLoss,
  kTechnologyAlarm,
  kFixedStopBreak,
  kAmplifierFault,     // analog/stepper drive: the servo amplifier or stepper driver faults, its ready drops
  kEncoderSignalLost,  // analog drive: the encoder on the card's counter is unplugged (count stands, signal
                       // lost)
  kSafeTorqueOff,      // Safety Integrated STO selected in the drive (alarm 421)
  kSafeStop1,          // Safety Integrated SS1 selected in the drive (alarm 550, then 421)
};
constexpr std::array<std::string_view, 10> kFaultNames{
    "drive_fault",      "encoder_error",   "sign_of_life_freeze", "link_loss",       "technology_alarm",
    "fixed_stop_break", "amplifier_fault", "encoder_signal_lost", "safe_torque_off", "safe_stop_1"};

struct SetItem {
  std::size_t to = 0;
  std::string variable;
  std::string path;  // JSON path, for a (never expected) refusal at run time
  double value = 0.0;
  // "<TO>.analog.TarOffs.En" / ".Reset": an input of the analog actor's offset calibration, not a TO
  // variable.
  enum class Target : std::uint8_t { kVariable, kTarOffsEn, kTarOffsReset };
  Target target = Target::kVariable;
};

struct Event {
  enum class Kind : std::uint8_t { kInstance, kSet, kInject, kClear };
  std::uint64_t cycle = 0;
  Kind kind = Kind::kInstance;
  // kInstance
  std::size_t instance = 0;
  std::vector<std::pair<std::size_t, double>> inputs;
  std::vector<std::pair<std::size_t, std::size_t>> object_inputs;   // (parameter, technology object index)
  std::vector<std::pair<std::size_t, std::size_t>> profile_inputs;  // (parameter, index into profiles)
  // kSet
  std::vector<SetItem> sets;
  // kInject, kClear
  std::size_t target = 0;
  FaultKind fault = FaultKind::kDriveFault;
  std::uint32_t code = 0;
  Reaction reaction = Reaction::kOff2;
  int encoder = 1;
  // kTechnologyAlarm: the alarm's reaction (0..5) and additional value
  std::int32_t alarm_reaction = 0;
  std::uint32_t additional_value = 0;
};

struct Column {
  std::string name;
  Format format = Format::kReal;
  std::function<double()> read;
};

struct Expectation {
  std::size_t index = 0;  // position in "expect"
  std::uint64_t cycle = 0;
  double tolerance = kDefaultTolerance;
  std::vector<std::pair<Column, double>> values;
};

}  // namespace

struct Scenario::Impl {
  double cycle_time = 0.001;
  std::uint64_t cycles = 0;
  std::unique_ptr<to::Runtime> runtime;
  // Drives behind a Fast DDS gateway (gateway_adapter.hpp); empty with simulated drives only.
  GatewayLinks gateways;
  std::vector<TechnologyObjectEntry> objects;
  std::vector<std::array<bool, 2>> tar_offs_inputs;  // per object: TarOffs En, Reset as last set
  std::vector<InstanceEntry> instances;
  std::vector<Event> events;
  // MC_PositionProfile.TimePosition of the timeline: the user's profile structures (a deque: stable
  // addresses).
  std::deque<to::TimePositionProfile> profiles;
  std::vector<Column> trace;
  std::vector<Expectation> expectations;       // sorted by cycle
  std::unique_ptr<to::RetentiveStore> retain;  // "retain_file": absolute-encoder adjustments across runs
  std::string retain_report;                   // what restoring it found (for the CLI's summary)
  Problems problems;
  std::filesystem::path directory;  // files named by the document are relative to it
  // A broken technology_objects or timeline array makes every later reference to its names fail; those
  // follow-up problems would only bury the real one, so they are not reported.
  bool objects_broken = false;
  bool timeline_broken = false;

  // run state
  std::uint64_t cycle = 0;
  std::size_t next_event = 0;
  std::vector<std::size_t> created;  // instances in creation order: the user program calls them in this order
  std::vector<bool> is_created;
  std::vector<std::string> runtime_errors;
  bool aborted = false;  // a `set` was refused: stop after this cycle
  bool ran = false;

  // ---- loading ----
  void load(const Json& document);
  void load_technology_object(const Json& value, const std::string& path);
  // MC_PositionProfile.TimePosition: [[time, position], ...] into a new profile; its index in `profiles`.
  std::optional<std::size_t> read_time_position(const Json& value, const std::string& path);
  void load_event(const Json& value, const std::string& path, std::optional<std::uint64_t>& previous_cycle);
  void load_instance_event(ObjectReader& r, Event& event);
  void load_set_event(ObjectReader& r, Event& event);
  void load_fault_event(ObjectReader& r, Event& event, bool inject);
  std::optional<std::size_t> find_object(std::string_view name) const;
  std::optional<std::size_t> find_instance(std::string_view name) const;
  std::optional<Column> resolve(std::string_view name, const std::string& path);
  std::optional<Column> resolve_alarm(const TechnologyObjectEntry& entry, std::string_view alarm,
                                      const std::string& path, Column column);
  std::optional<std::uint64_t> read_cycle(ObjectReader& r);

  // ---- running ----
  void user_program() noexcept;
  void apply(const Event& event) noexcept;
};

// ---------------------------------------------------------------------------------------------------------
// Loading

std::optional<std::size_t> Scenario::Impl::find_object(std::string_view name) const {
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].name == name) return i;
  }
  return std::nullopt;
}

std::optional<std::size_t> Scenario::Impl::find_instance(std::string_view name) const {
  for (std::size_t i = 0; i < instances.size(); ++i) {
    if (instances[i].name == name) return i;
  }
  return std::nullopt;
}

std::optional<std::uint64_t> Scenario::Impl::read_cycle(ObjectReader& r) {
  const Json* v = r.get("cycle", true);
  if (v == nullptr || cycles == 0) return std::nullopt;  // cycles == 0: already reported, range unknown
  const auto c =
      detail::read_integer(*v, r.path_of("cycle"), 0, static_cast<std::int64_t>(cycles) - 1, false, problems);
  if (!c) return std::nullopt;
  return static_cast<std::uint64_t>(*c);
}

void Scenario::Impl::load(const Json& document) {
  ObjectReader root(document, "", problems);
  if (!root.valid()) return;

  if (const Json* v = root.get("cycle_time", true)) {
    if (auto d = detail::read_number(*v, "cycle_time", problems)) {
      if (*d > 0.0) {
        cycle_time = *d;
      } else {
        problems.add("cycle_time", detail::out_of_range_message(*d, detail::kPositive));
      }
    }
  }
  if (const Json* v = root.get("cycles", true)) {
    if (auto c = detail::read_integer(*v, "cycles", 1, kMaxCycles, false, problems)) {
      cycles = static_cast<std::uint64_t>(*c);
    }
  }
  runtime = std::make_unique<to::Runtime>(to::RuntimeConfig{cycle_time, 1, 1});

  if (const Json* v = root.get("technology_objects", true)) {
    if (!v->is_array() || v->empty()) {
      problems.add("technology_objects",
                   "expected a non-empty array of technology objects, got " +
                       std::string(v->is_array() ? "an empty array" : detail::type_name(*v)));
      objects_broken = true;
    } else {
      for (std::size_t i = 0; i < v->size(); ++i) {
        load_technology_object((*v)[i], "technology_objects[" + std::to_string(i) + "]");
      }
    }
  }

  // The retentive memory of absolute-encoder adjustments (spec 02 §5.9): restored before the first cycle,
  // written whenever an adjustment changes (docs/scenarios.md "retain_file"). Before the timeline: its
  // MC_SaveAbsoluteEncoderData works on it.
  if (const Json* v = root.get("retain_file")) {
    if (auto path = detail::read_string(*v, "retain_file", problems)) {
      if (path->empty()) {
        problems.add("retain_file", "expected a file name");
      } else {
        retain = std::make_unique<to::RetentiveStore>(*path);
      }
    }
  }

  if (const Json* v = root.get("timeline")) {
    if (!v->is_array()) {
      problems.add("timeline", "expected an array of events, got " + std::string(detail::type_name(*v)));
      timeline_broken = true;
    } else {
      std::optional<std::uint64_t> previous;
      for (std::size_t i = 0; i < v->size(); ++i) {
        load_event((*v)[i], "timeline[" + std::to_string(i) + "]", previous);
      }
    }
  }

  if (const Json* v = root.get("trace")) {
    if (!v->is_array()) {
      problems.add("trace", "expected an array of trace names, got " + std::string(detail::type_name(*v)));
    } else {
      for (std::size_t i = 0; i < v->size(); ++i) {
        const std::string path = "trace[" + std::to_string(i) + "]";
        const auto name = detail::read_string((*v)[i], path, problems);
        if (!name) continue;
        const bool duplicate =
            std::any_of(trace.begin(), trace.end(), [&](const Column& c) { return c.name == *name; });
        if (duplicate) {
          problems.add(path, "'" + *name + "' is traced twice");
          continue;
        }
        if (auto column = resolve(*name, path)) trace.push_back(std::move(*column));
      }
    }
  }

  if (const Json* v = root.get("expect")) {
    if (!v->is_array()) {
      problems.add("expect", "expected an array of expectations, got " + std::string(detail::type_name(*v)));
    } else {
      for (std::size_t i = 0; i < v->size(); ++i) {
        ObjectReader r((*v)[i], "expect[" + std::to_string(i) + "]", problems);
        if (!r.valid()) continue;
        Expectation e;
        e.index = i;
        const auto cycle = read_cycle(r);
        r.real("tolerance", e.tolerance, detail::kNonNegative);
        if (const Json* values = r.get("values", true)) {
          ObjectReader vr(*values, r.path_of("values"), problems);
          if (vr.valid() && values->empty()) problems.add(vr.path(), "expected at least one trace name");
          if (vr.valid()) {
            for (const auto& [name, expected] : values->items()) {
              vr.get(name);  // every key is a trace name: none is "unknown" to the reader
              const std::string path = vr.path_of(name);
              auto column = resolve(name, path);
              std::optional<double> number;
              if (expected.is_boolean()) {
                number = expected.get<bool>() ? 1.0 : 0.0;  // "move1.Done": true reads naturally
              } else {
                number = detail::read_number(expected, path, problems);
              }
              if (column && number) e.values.emplace_back(std::move(*column), *number);
            }
          }
        }
        r.finish();
        if (cycle) {
          e.cycle = *cycle;
          expectations.push_back(std::move(e));
        }
      }
      std::stable_sort(expectations.begin(), expectations.end(),
                       [](const Expectation& a, const Expectation& b) { return a.cycle < b.cycle; });
    }
  }
  root.finish();
}

// The points as the user's program would fill the structure; their order, count >= 2 and finiteness are the
// instruction's to check (its ErrorIDs), so only the shape and the capacity are the loader's.
std::optional<std::size_t> Scenario::Impl::read_time_position(const Json& value, const std::string& path) {
  if (!value.is_array()) {
    problems.add(path, "expected an array of [time, position] pairs");
    return std::nullopt;
  }
  if (value.size() > to::kMaxTimePositionPoints) {
    problems.add(path, std::to_string(value.size()) + " points, at most " +
                           std::to_string(to::kMaxTimePositionPoints) + " fit the profile structure");
    return std::nullopt;
  }
  to::TimePositionProfile profile;
  bool ok = true;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = path + "[" + std::to_string(i) + "]";
    const Json& p = value[i];
    if (!p.is_array() || p.size() != 2) {
      problems.add(at, "expected [time, position]");
      ok = false;
      continue;
    }
    const auto t = detail::read_number(p[0], at + "[0]", problems);
    const auto y = detail::read_number(p[1], at + "[1]", problems);
    if (!t || !y) {
      ok = false;
      continue;
    }
    profile.Point[i] = {*t, *y};
  }
  if (!ok) return std::nullopt;
  profile.NumberOfPoints = static_cast<std::int32_t>(value.size());
  profiles.push_back(profile);
  return profiles.size() - 1;
}

void Scenario::Impl::load_technology_object(const Json& value, const std::string& path) {
  if (auto entry = scenario::load_technology_object(value, path, cycle_time, *runtime, objects, problems,
                                                    "tomc sim", &gateways, directory)) {
    objects.push_back(std::move(*entry));
    tar_offs_inputs.push_back({false, false});
  }
}

void Scenario::Impl::load_event(const Json& value, const std::string& path,
                                std::optional<std::uint64_t>& previous_cycle) {
  ObjectReader r(value, path, problems);
  if (!r.valid()) return;
  Event event;
  const auto cycle = read_cycle(r);
  if (cycle) {
    if (previous_cycle && *cycle < *previous_cycle) {
      problems.add(r.path_of("cycle"), std::to_string(*cycle) + " is before the previous event's cycle " +
                                           std::to_string(*previous_cycle) +
                                           " (events must be in time order)");
    }
    previous_cycle = *cycle;
    event.cycle = *cycle;
  }
  std::vector<std::string_view> kinds;
  for (std::string_view k : {"instance", "set", "inject", "clear"}) {
    if (r.has(k)) kinds.push_back(k);
  }
  if (kinds.size() != 1) {
    problems.add(path, kinds.empty() ? "an event needs one of 'instance', 'set', 'inject', 'clear'"
                                     : "an event does one thing: it has both '" + std::string(kinds[0]) +
                                           "' and '" + std::string(kinds[1]) + "'");
    r.get("instance");
    r.get("instruction");
    r.get("axis");
    r.get("inputs");
    r.get("set");
    r.get("inject");
    r.get("clear");
    r.finish();
    return;
  }
  const std::size_t before = problems.size();
  if (kinds[0] == "instance") {
    event.kind = Event::Kind::kInstance;
    load_instance_event(r, event);
  } else if (kinds[0] == "set") {
    event.kind = Event::Kind::kSet;
    load_set_event(r, event);
  } else {
    const bool inject = kinds[0] == "inject";
    event.kind = inject ? Event::Kind::kInject : Event::Kind::kClear;
    load_fault_event(r, event, inject);
  }
  r.finish();
  if (cycle && problems.size() == before) events.push_back(std::move(event));
}

void Scenario::Impl::load_instance_event(ObjectReader& r, Event& event) {
  const auto name = detail::read_string(*r.get("instance"), r.path_of("instance"), problems);
  std::optional<std::string> instruction;
  std::optional<std::string> axis;
  const Json* inputs = r.get("inputs");
  if (const Json* v = r.get("instruction"))
    instruction = detail::read_string(*v, r.path_of("instruction"), problems);
  if (const Json* v = r.get("axis")) axis = detail::read_string(*v, r.path_of("axis"), problems);
  if (!name) return;
  if (!is_identifier(*name)) {
    problems.add(r.path_of("instance"),
                 "'" + *name + "' is not a name (letters, digits, _; not starting with a digit)");
    return;
  }
  auto index = find_instance(*name);
  if (!index && instruction && *instruction == detail::kSaveAbsoluteEncoderData) {
    // No Axis input: it backs up every TO's adjustment in the retentive store (spec 03 §4.16).
    InstanceEntry entry;
    entry.name = *name;
    entry.instruction = *instruction;
    entry.defined_at = r.path();
    entry.cpu_wide = true;
    if (axis) {
      problems.add(r.path_of("axis"),
                   *instruction +
                       " has no Axis input: it backs up the absolute-encoder adjustment of "
                       "every technology object (spec 03 §4.16)");
    } else if (!retain) {
      problems.add(r.path_of("instruction"),
                   *instruction + " needs \"retain_file\": the retentive store it writes (spec 02 §5.9)");
    } else {
      entry.fb = detail::make_save_absolute_encoder_data(*retain);
    }
    instances.push_back(std::move(entry));
    index = instances.size() - 1;
  } else if (!index) {
    // First mention: it creates the instance, so it must say what and on which axis.
    bool complete = true;
    if (!r.has("instruction")) {
      problems.add(r.path_of("instruction"),
                   "missing (the first event of instance '" + *name + "' must give instruction and axis)");
      complete = false;
    }
    if (!r.has("axis")) {
      problems.add(r.path_of("axis"),
                   "missing (the first event of instance '" + *name + "' must give instruction and axis)");
      complete = false;
    }
    if (!complete || !instruction || !axis) return;
    if (find_object(*name)) {
      problems.add(r.path_of("instance"), "'" + *name + "' is already the name of a technology object");
      return;
    }
    const auto to_index = find_object(*axis);
    if (!to_index && !objects_broken) {
      std::vector<std::string> names;
      for (const auto& o : objects)
        names.push_back(o.name);
      problems.add(r.path_of("axis"),
                   "unknown technology object '" + *axis + "' (defined: " + list_of(names) + ")");
    }
    // Recorded even with an unknown axis (the scenario will not run then), so that later events and trace
    // names of this instance do not report follow-up problems.
    InstanceEntry entry;
    entry.name = *name;
    entry.instruction = *instruction;
    entry.defined_at = r.path();
    entry.axis = to_index.value_or(0);
    entry.axis_name = *axis;
    if (to_index && objects[*to_index].built) {
      const TechnologyObjectEntry& object = objects[*to_index];
      entry.fb = detail::make_instance(*instruction, object.kind);
      if (!entry.fb) {
        const std::string supported = list_of(detail::instructions_for(object.kind));
        bool other_type = false;
        for (auto kind : {TechnologyObjectKind::kSpeedAxis, TechnologyObjectKind::kPositioningAxis,
                          TechnologyObjectKind::kSynchronousAxis, TechnologyObjectKind::kExternalEncoder,
                          TechnologyObjectKind::kCam}) {
          const auto names = detail::instructions_for(kind);
          other_type = other_type || std::find(names.begin(), names.end(), *instruction) != names.end();
        }
        problems.add(r.path_of("instruction"),
                     other_type
                         ? *instruction + " is not an instruction of " + std::string(object.type_name()) +
                               " " + object.name + " (spec 01 §1.3; its instructions: " + supported + ")"
                     : detail::is_planned_instruction(*instruction)
                         ? *instruction + " is not yet supported by tomc sim (supported: " + supported + ")"
                         : "unknown instruction '" + *instruction + "' (supported: " + supported + ")");
      }
    }
    // Recorded even when unusable, so later events of the same instance do not report it again.
    instances.push_back(std::move(entry));
    index = instances.size() - 1;
  } else {
    const InstanceEntry& existing = instances[*index];
    if (instruction && *instruction != existing.instruction) {
      problems.add(r.path_of("instruction"), "instance '" + *name + "' is an " + existing.instruction + " (" +
                                                 existing.defined_at + "); one name denotes one instance");
    }
    if (axis && *axis != existing.axis_name) {
      problems.add(r.path_of("axis"), "instance '" + *name + "' works on " + existing.axis_name + " (" +
                                          existing.defined_at + "), not " + *axis);
    }
  }
  event.instance = *index;
  const InstanceEntry& entry = instances[*index];
  if (inputs == nullptr || !entry.fb) return;
  ObjectReader ir(*inputs, r.path_of("inputs"), problems);
  if (!ir.valid()) return;
  for (const auto& [key, value] : inputs->items()) {
    ir.get(key);  // checked here against the instruction's parameters, with a better message than finish()
    const std::string path = ir.path_of(key);
    const auto parameter = entry.fb->find(key);
    std::string input_names;
    for (const auto& p : entry.fb->parameters()) {
      if (p.input) input_names += (input_names.empty() ? "" : ", ") + std::string(p.name);
    }
    if (!parameter) {
      if (key == "comment") continue;
      problems.add(path, "unknown input of " + entry.instruction + " (inputs: " + input_names + ")");
      continue;
    }
    const auto& info = entry.fb->parameters()[*parameter];
    if (!info.input) {
      problems.add(path,
                   "'" + key + "' is an output of " + entry.instruction + " (inputs: " + input_names + ")");
      continue;
    }
    std::optional<double> number;
    switch (info.type) {
      case detail::ParameterType::kBool:
        if (auto b = detail::read_bool(value, path, problems)) number = *b ? 1.0 : 0.0;
        break;
      case detail::ParameterType::kInt:
        if (auto i = detail::read_integer(value, path, -32768, 32767, false, problems))
          number = static_cast<double>(*i);
        break;
      case detail::ParameterType::kDint:
        if (auto i = detail::read_integer(value, path, std::numeric_limits<std::int32_t>::min(),
                                          std::numeric_limits<std::int32_t>::max(), false, problems)) {
          number = static_cast<double>(*i);
        }
        break;
      case detail::ParameterType::kWord:
        if (auto i = detail::read_integer(value, path, 0, 65535, true, problems))
          number = static_cast<double>(*i);
        break;
      case detail::ParameterType::kLreal:
        number = detail::read_number(value, path, problems);
        break;
      case detail::ParameterType::kTimePosition:
        if (value.is_string()) {
          // The manual's form: a TO_Cam of the scenario, x = time (spec 03 §4.7, decision L8).
          const std::string target = value.get<std::string>();
          const auto index = find_object(target);
          if (!index) {
            if (!objects_broken) problems.add(path, "unknown technology object '" + target + "'");
          } else if (objects[*index].built && objects[*index].cam == nullptr) {
            problems.add(path, "'" + target + "' is a " + std::string(objects[*index].type_name()) +
                                   ", not a cam (TimePosition is a TO_Cam or [[time, position], ...])");
          } else {
            event.object_inputs.emplace_back(*parameter, *index);
          }
        } else if (auto index = read_time_position(value, path)) {
          event.profile_inputs.emplace_back(*parameter, *index);
        }
        break;
      case detail::ParameterType::kTechnologyObject:
      case detail::ParameterType::kCam: {
        // A TO by name: a leading value of the scenario (MC_GearIn.Master, spec 07 §1.2) or a cam of it
        // (MC_CamIn.Cam, spec 07 §3.4).
        const bool cam = info.type == detail::ParameterType::kCam;
        if (auto target = detail::read_string(value, path, problems)) {
          const auto index = find_object(*target);
          if (!index) {
            if (!objects_broken) problems.add(path, "unknown technology object '" + *target + "'");
          } else if (objects[*index].built && (cam ? objects[*index].cam == nullptr
                                                   : objects[*index].leading_value_source() == nullptr)) {
            problems.add(path, "'" + *target + "' is a " + std::string(objects[*index].type_name()) +
                                   (cam ? ", not a cam" : ", which cannot be a leading value"));
          } else {
            event.object_inputs.emplace_back(*parameter, *index);
          }
        }
        break;
      }
    }
    if (number) event.inputs.emplace_back(*parameter, *number);
  }
}

void Scenario::Impl::load_set_event(ObjectReader& r, Event& event) {
  const Json* set = r.get("set");
  ObjectReader sr(*set, r.path_of("set"), problems);
  if (!sr.valid()) return;
  if (set->empty()) problems.add(sr.path(), "expected at least one '<TO>.<variable>' to write");
  for (const auto& [key, value] : set->items()) {
    sr.get(key);
    const std::string path = sr.path_of(key);
    const auto dot = key.find('.');
    const auto to_index = find_object(key.substr(0, dot));
    if (dot != std::string::npos && !to_index && objects_broken) continue;
    if (dot == std::string::npos || !to_index) {
      problems.add(path, "expected '<technology object>.<variable path>', e.g. 'Axis1.Override.Velocity'");
      continue;
    }
    if (!objects[*to_index].built) continue;  // its definition was already reported
    const std::string variable = key.substr(dot + 1);
    if (variable == "analog.TarOffs.En" || variable == "analog.TarOffs.Reset") {
      if (objects[*to_index].analog_drive == nullptr) {
        problems.add(path, objects[*to_index].name + " has no analog drive (\"adapter\": \"analog\")");
      } else if (!value.is_boolean()) {
        problems.add(path, "expected true or false");
      } else {
        event.sets.push_back(
            SetItem{*to_index, variable, path, value.get<bool>() ? 1.0 : 0.0,
                    variable.ends_with("En") ? SetItem::Target::kTarOffsEn : SetItem::Target::kTarOffsReset});
      }
      continue;
    }
    const to::VariableInfo* info = objects[*to_index].find_variable(variable);
    if (info == nullptr) {
      problems.add(path, "unknown variable of " + std::string(objects[*to_index].type_name()) + " " +
                             objects[*to_index].name);
      continue;
    }
    // The same rule user code obeys (spec 04 §0.2): DIR and CAL only.
    const to::AccessError access = to::check_write_access(*info, to::WriteContext::kUserProgram);
    if (access != to::AccessError::kNone) {
      problems.add(path, "the user program cannot write it: " + std::string(to::to_string(access)));
      continue;
    }
    if (auto number = detail::read_variable_value(*info, value, path, problems)) {
      event.sets.push_back(SetItem{*to_index, variable, path, *number});
    }
  }
}

void Scenario::Impl::load_fault_event(ObjectReader& r, Event& event, bool inject) {
  const std::string key = inject ? "inject" : "clear";
  ObjectReader fr(*r.get(key), r.path_of(key), problems);
  if (!fr.valid()) return;
  bool target_found = false;
  if (const Json* v = fr.get("target", true)) {
    if (auto target = detail::read_string(*v, fr.path_of("target"), problems)) {
      const auto index = find_object(*target);
      if (!index) {
        if (!objects_broken)
          problems.add(fr.path_of("target"), "unknown technology object '" + *target + "'");
      } else {
        event.target = *index;
        target_found = true;
      }
    }
  }
  std::optional<std::size_t> fault;
  if (const Json* v = fr.get("fault", true)) {
    fault = detail::read_choice(*v, fr.path_of("fault"), {kFaultNames.begin(), kFaultNames.end()}, problems);
  }
  if (fault) {
    event.fault = static_cast<FaultKind>(*fault);
    // Every fault but a technology alarm is one of the simulated drive's; amplifier_fault is the analog or
    // stepper drive's.
    const bool analog_fault = event.fault == FaultKind::kAmplifierFault;
    if (target_found && event.fault == FaultKind::kEncoderSignalLost && objects[event.target].built &&
        (objects[event.target].analog_drive == nullptr ||
         objects[event.target].analog_drive->separate_encoder() != nullptr)) {
      problems.add(fr.path_of("target"),
                   objects[event.target].name +
                       " has no analog drive with an encoder on its counter (a separate "
                       "81/83 encoder fails with encoder_error)");
    } else if (target_found && event.fault != FaultKind::kTechnologyAlarm &&
               event.fault != FaultKind::kEncoderSignalLost && objects[event.target].built &&
               (analog_fault ? objects[event.target].analog_drive == nullptr &&
                                   objects[event.target].stepper_drive == nullptr
                             : objects[event.target].drive == nullptr)) {
      problems.add(
          fr.path_of("target"),
          objects[event.target].name +
              (analog_fault ? " has no analog or stepper drive (\"adapter\": \"analog\" or \"stepper\")"
                            : " has no simulated drive to inject faults into"));
    }
    switch (event.fault) {
      case FaultKind::kDriveFault:
        if (inject) {
          // 7860 = SINAMICS F07860 "external fault 1", whose default reaction is OFF2.
          std::int64_t code = 7860;
          fr.integer("code", code, 1, 4294967295LL);
          event.code = static_cast<std::uint32_t>(code);
          if (const Json* v = fr.get("reaction")) {
            if (auto c =
                    detail::read_choice(*v, fr.path_of("reaction"), {"OFF1", "OFF2", "OFF3"}, problems)) {
              event.reaction = std::array{Reaction::kOff1, Reaction::kOff2, Reaction::kOff3}[*c];
            }
          }
        }
        break;
      case FaultKind::kEncoderError:
        fr.integer("encoder", event.encoder, 1, 2);
        if (inject) {
          std::int64_t code = 0x0001;  // spec 06 §6.4: sensor group error
          fr.integer("code", code, 1, 65535, true);
          event.code = static_cast<std::uint32_t>(code);
        }
        break;
      case FaultKind::kSignOfLifeFreeze:
      case FaultKind::kLinkLoss:
      case FaultKind::kFixedStopBreak:
      case FaultKind::kAmplifierFault:
      case FaultKind::kEncoderSignalLost:
      case FaultKind::kSafeTorqueOff:
      case FaultKind::kSafeStop1:
        break;
      case FaultKind::kTechnologyAlarm: {
        // A technology alarm as if its cause had occurred (SpeedAxis::inject_alarm); it ends by MC_Reset.
        if (!inject) {
          problems.add(fr.path_of("fault"), "a technology alarm is acknowledged with MC_Reset, not cleared");
          break;
        }
        std::int64_t number = 0;
        fr.integer("alarm", number, 1, 4294967295LL, false, true);
        const auto* definition = to::find_alarm(static_cast<std::uint32_t>(number));
        if (number != 0 && definition == nullptr) {
          problems.add(fr.path_of("alarm"),
                       "alarm " + std::to_string(number) + " is not defined (docs/errors.md)");
        }
        event.code = static_cast<std::uint32_t>(number);
        std::int64_t reaction = definition != nullptr ? static_cast<std::int64_t>(definition->reaction) : 0;
        fr.integer("reaction", reaction, 0, 5);
        event.alarm_reaction = static_cast<std::int32_t>(reaction);
        std::int64_t additional = 0;
        fr.integer("additional_value", additional, 0, 4294967295LL);
        event.additional_value = static_cast<std::uint32_t>(additional);
        break;
      }
    }
  }
  fr.finish();
}

// "<TO>.alarm.<number>": 1 while that technology alarm is pending on the TO, else 0; "<TO>.alarm.<number>.
// additional_value": its additional value (0 while not pending) — what the data block's ErrorDetail does not
// show (e.g. the cause of alarm 560, decision H3).
std::optional<Column> Scenario::Impl::resolve_alarm(const TechnologyObjectEntry& entry,
                                                    std::string_view alarm, const std::string& path,
                                                    Column column) {
  constexpr std::string_view kAdditional = ".additional_value";
  const bool additional = alarm.ends_with(kAdditional);
  const std::string_view digits = additional ? alarm.substr(0, alarm.size() - kAdditional.size()) : alarm;
  std::uint32_t number = 0;
  const bool numeric = !digits.empty() && digits.size() <= 9 &&
                       std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (numeric) {
    for (char c : digits)
      number = number * 10 + static_cast<std::uint32_t>(c - '0');
  }
  if (!numeric || to::find_alarm(number) == nullptr) {
    problems.add(path, numeric ? "alarm " + std::string(digits) + " is not defined (docs/errors.md)"
                               : "'alarm." + std::string(alarm) +
                                     "' is not an alarm trace name ('alarm.<number>' or "
                                     "'alarm.<number>.additional_value')");
    return std::nullopt;
  }
  const to::AlarmList* list = &entry.alarms();
  if (additional) {
    column.format = Format::kInteger;
    column.read = [list, number] {
      for (const auto& a : list->alarms()) {
        if (a.number == number) return static_cast<double>(a.additional_value);
      }
      return 0.0;
    };
  } else {
    column.format = Format::kBool;
    column.read = [list, number] { return list->pending(number) ? 1.0 : 0.0; };
  }
  return column;
}

std::optional<Column> Scenario::Impl::resolve(std::string_view name, const std::string& path) {
  const auto dot = name.find('.');
  if (dot == std::string_view::npos) {
    problems.add(path, "'" + std::string(name) +
                           "' is not a trace name ('<TO>.<variable>' or '<instance>.<parameter>')");
    return std::nullopt;
  }
  const std::string_view head = name.substr(0, dot);
  const std::string_view rest = name.substr(dot + 1);
  Column column;
  column.name = std::string(name);
  if (const auto o = find_object(head)) {
    const TechnologyObjectEntry& entry = objects[*o];
    if (!entry.built) return std::nullopt;  // already reported
    if (rest.starts_with("drive.")) {
      const std::string_view observable = rest.substr(6);
      const auto it = std::find_if(kDriveObservables.begin(), kDriveObservables.end(),
                                   [&](const DriveObservable& d) { return d.name == observable; });
      if (entry.drive == nullptr || it == kDriveObservables.end()) {
        std::string names;
        for (const auto& d : kDriveObservables)
          names += (names.empty() ? "" : ", ") + std::string(d.name);
        problems.add(path, entry.drive == nullptr
                               ? "'" + std::string(head) + "' has no simulated drive"
                               : "'" + std::string(observable) + "' is not a drive value (" + names + ")");
        return std::nullopt;
      }
      const drives::SimulatedDrive* drive = entry.drive;
      column.format = it->format;
      column.read = [drive, read = it->read] { return read(*drive); };
      return column;
    }
    if (rest.starts_with("analog.") || rest.starts_with("stepper.")) {
      const bool analog = rest.starts_with("analog.");
      auto read = analog ? actor_observable(kAnalogObservables, entry.analog_drive, "analog", head,
                                            rest.substr(7), path, column.format, problems)
                         : actor_observable(kStepperObservables, entry.stepper_drive, "stepper", head,
                                            rest.substr(8), path, column.format, problems);
      if (!read) return std::nullopt;
      column.read = std::move(*read);
      return column;
    }
    if (rest.starts_with("alarm.")) return resolve_alarm(entry, rest.substr(6), path, std::move(column));
    if (const to::VariableInfo* info = entry.find_variable(rest)) {
      column.format = format_of(info->type);
      column.read = entry.reader(info, std::nullopt);
      return column;
    }
    if (const auto bit = entry.find_bit(rest)) {
      column.format = Format::kBool;
      column.read = entry.reader(nullptr, bit);
      return column;
    }
    // A synchronous axis' StatusSynchronizedMotion.* (spec 07 §1.9) is not in the positioning axis' variable
    // table: read it through SynchronousAxis::read.
    if (entry.synchronous_axis != nullptr) {
      if (const auto type = entry.synchronous_axis->synchronized_motion_type(rest)) {
        column.format = format_of(*type);
        column.read = [axis = entry.synchronous_axis, path = std::string(rest)] { return axis->read(path); };
        return column;
      }
    }
    problems.add(path, "'" + std::string(rest) + "' is not a variable of " + std::string(entry.type_name()) +
                           " " + entry.name);
    return std::nullopt;
  }
  if (const auto i = find_instance(head)) {
    const InstanceEntry& entry = instances[*i];
    if (!entry.fb) return std::nullopt;  // unknown instruction, already reported
    const auto parameter = entry.fb->find(rest);
    if (!parameter) {
      std::string names;
      for (const auto& p : entry.fb->parameters())
        names += (names.empty() ? "" : ", ") + std::string(p.name);
      problems.add(path, "'" + std::string(rest) + "' is not a parameter of " + entry.instruction + " (" +
                             names + ")");
      return std::nullopt;
    }
    const Instance* fb = entry.fb.get();
    if (fb->parameters()[*parameter].type == detail::ParameterType::kTechnologyObject ||
        fb->parameters()[*parameter].type == detail::ParameterType::kCam ||
        fb->parameters()[*parameter].type == detail::ParameterType::kTimePosition) {
      problems.add(path, "'" + std::string(rest) + "' names a technology object; it cannot be traced");
      return std::nullopt;
    }
    column.format = format_of(fb->parameters()[*parameter].type);
    column.read = [fb, p = *parameter] { return fb->get(p); };
    return column;
  }
  if (!objects_broken && !timeline_broken) {
    problems.add(
        path, "'" + std::string(head) + "' is neither a technology object nor an instance of the timeline");
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------------------------------
// Running

void Scenario::Impl::apply(const Event& event) noexcept {
  switch (event.kind) {
    case Event::Kind::kInstance: {
      if (!is_created[event.instance]) {
        is_created[event.instance] = true;
        created.push_back(event.instance);  // reserved at start: no allocation
      }
      Instance& fb = *instances[event.instance].fb;
      for (const auto& [parameter, value] : event.inputs)
        fb.set(parameter, value);
      for (const auto& [parameter, object] : event.object_inputs)
        fb.set_object(parameter, objects[object]);
      for (const auto& [parameter, profile] : event.profile_inputs)
        fb.set_profile(parameter, &profiles[profile]);
      break;
    }
    case Event::Kind::kSet:
      for (const SetItem& s : event.sets) {
        if (s.target != SetItem::Target::kVariable) {
          // TarOffs inputs (docs/analog-drives.md): the actor sees En and Reset together, as the legacy
          // block.
          auto& inputs = tar_offs_inputs[s.to];
          inputs[s.target == SetItem::Target::kTarOffsEn ? 0 : 1] = s.value != 0.0;
          objects[s.to].analog_drive->actor().offset_calibration(inputs[0], inputs[1]);
          continue;
        }
        const to::WriteResult result = objects[s.to].write(s.variable, s.value);
        if (!result.ok()) {
          // Validated at load time with the same rules; if the TO ever disagrees the run must not go on
          // quietly.
          try {
            runtime_errors.push_back(s.path + ": refused at cycle " + std::to_string(cycle) + ": " +
                                     std::string(result.access != to::AccessError::kNone
                                                     ? to::to_string(result.access)
                                                     : to::to_string(result.value)));
          } catch (...) {
            runtime_errors.clear();  // out of memory while reporting: still stop the run below
          }
          aborted = true;
        }
      }
      break;
    case Event::Kind::kInject:
    case Event::Kind::kClear: {
      if (event.fault == FaultKind::kTechnologyAlarm) {
        (void)objects[event.target].inject_alarm(event.code, event.additional_value,
                                                 static_cast<to::AlarmReaction>(event.alarm_reaction));
        break;
      }
      if (event.fault == FaultKind::kAmplifierFault) {
        const bool on = event.kind == Event::Kind::kInject;
        if (auto* analog = objects[event.target].analog_drive) analog->hardware().set_fault(on);
        if (auto* stepper = objects[event.target].stepper_drive) stepper->hardware().set_fault(on);
        break;
      }
      if (event.fault == FaultKind::kEncoderSignalLost) {
        objects[event.target].analog_drive->hardware().set_encoder_connected(event.kind !=
                                                                             Event::Kind::kInject);
        break;
      }
      drives::SimulatedDrive& d = *objects[event.target].drive;
      const bool on = event.kind == Event::Kind::kInject;
      switch (event.fault) {
        case FaultKind::kDriveFault:
          if (on) {
            d.inject_fault(event.code, event.reaction);
          } else {
            d.clear_injected_fault();
          }
          break;
        case FaultKind::kEncoderError:
          if (on) {
            d.inject_encoder_error(event.encoder, static_cast<std::uint16_t>(event.code));
          } else {
            d.clear_encoder_error(event.encoder);
          }
          break;
        case FaultKind::kSignOfLifeFreeze:
          d.freeze_sign_of_life(on);
          break;
        case FaultKind::kLinkLoss:
          d.set_link_lost(on);
          break;
        case FaultKind::kFixedStopBreak:
          d.break_fixed_stops(on);
          break;
        case FaultKind::kSafeTorqueOff:
        case FaultKind::kSafeStop1: {
          using Safety = drives::SimulatedDrive::SafetyFunction;
          const Safety selected = event.fault == FaultKind::kSafeTorqueOff ? Safety::kSto : Safety::kSs1;
          d.select_safety_function(on ? selected : Safety::kNone);
          break;
        }
        case FaultKind::kTechnologyAlarm:
        case FaultKind::kAmplifierFault:
        case FaultKind::kEncoderSignalLost:
          break;  // handled above
      }
      break;
    }
  }
}

void Scenario::Impl::user_program() noexcept {
  // Events of this cycle first ("just before the user program"), then every created instance once, in
  // creation order, on its axis — the order in which a PLC program would call its FB instances.
  while (next_event < events.size() && events[next_event].cycle == cycle)
    apply(events[next_event++]);
  for (std::size_t i : created)
    instances[i].fb->call(instances[i].cpu_wide ? nullptr : objects[instances[i].axis].object);
}

// ---------------------------------------------------------------------------------------------------------

Scenario::Scenario(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Scenario::~Scenario() = default;

LoadResult Scenario::load(const Json& document, const std::filesystem::path& directory) {
  auto impl = std::make_unique<Impl>();
  impl->directory = directory;
  impl->load(document);
  LoadResult result;
  if (!impl->problems.empty()) {
    result.problems = impl->problems.lines();
    return result;
  }
  impl->is_created.assign(impl->instances.size(), false);
  impl->created.reserve(impl->instances.size());
  Impl* self = impl.get();
  impl->runtime->set_user_program([self](to::Runtime&) { self->user_program(); });
  wire_machine_inputs(*impl->runtime, impl->objects);
  if (impl->retain) {
    for (const auto& o : impl->objects) {
      if (o.positioning_axis != nullptr) impl->retain->attach(*o.positioning_axis);
      if (o.external_encoder != nullptr) impl->retain->attach(*o.external_encoder);
    }
    const to::RetainFile file = impl->retain->restore();
    impl->retain_report = std::string(impl->retain->file().string()) + ": " +
                          std::string(to::to_string(file.status)) +
                          (file.message.empty() ? "" : " (" + file.message + ")");
    impl->runtime->set_post_servo([store = impl->retain.get()](to::Runtime&) { store->cycle(); });
  }
  impl->runtime->start();
  result.scenario.reset(new Scenario(std::move(impl)));
  return result;
}

LoadResult Scenario::load_text(std::string_view text, std::string_view source,
                               const std::filesystem::path& directory) {
  Json document;
  try {
    document = Json::parse(text);
  } catch (const Json::parse_error& e) {
    // nlohmann prefixes "[json.exception.parse_error.101] "; the user needs only line, column and cause.
    std::string what = e.what();
    if (const auto close = what.find("] ");
        what.starts_with("[json.exception") && close != std::string::npos) {
      what.erase(0, close + 2);
    }
    LoadResult result;
    result.problems.push_back(std::string(source) + ": malformed JSON: " + what);
    return result;
  }
  return load(document, directory);
}

LoadResult Scenario::load_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    LoadResult result;
    result.problems.push_back(file.string() + ": cannot read: " + std::strerror(errno));
    return result;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return load_text(text.str(), file.string(), file.parent_path());
}

double Scenario::cycle_time() const noexcept {
  return impl_->cycle_time;
}
std::uint64_t Scenario::cycles() const noexcept {
  return impl_->cycles;
}

std::string Scenario::trace_header() const {
  std::string header = "cycle,time";
  for (const Column& c : impl_->trace)
    header += "," + c.name;
  return header;
}

RunResult Scenario::run(std::ostream* trace) {
  Impl& s = *impl_;
  RunResult result;
  if (s.ran) {
    result.runtime_errors.push_back("a scenario runs once: load it again to rerun it");
    return result;
  }
  s.ran = true;
  if (trace != nullptr) *trace << trace_header() << '\n';
  auto next_expectation = s.expectations.begin();
  std::string row;
  if (!s.gateways.empty()) result.warnings = s.gateways.connect();
  for (s.cycle = 0; s.cycle < s.cycles; ++s.cycle) {
    s.runtime->step();
    // Drives behind a gateway: lock-step, each cycle's answers (or their timeout) before the next cycle.
    if (!s.gateways.empty()) s.gateways.wait_for_answers();
    ++result.cycles_run;
    // Single-threaded: the store writes a pending snapshot between cycles, outside Runtime::step().
    if (s.retain) (void)s.retain->service();
    if (trace != nullptr) {
      // The time column in its shortest exact form: 0.003, not 0.0030000000000000001.
      row = std::to_string(s.cycle) + "," + format_number(static_cast<double>(s.cycle) * s.cycle_time);
      for (const Column& c : s.trace) {
        row += ',';
        row += format_value(c.read(), c.format);
      }
      *trace << row << '\n';
    }
    for (; next_expectation != s.expectations.end() && next_expectation->cycle == s.cycle;
         ++next_expectation) {
      for (const auto& [column, expected] : next_expectation->values) {
        ++result.expectations_checked;
        const double actual = column.read();
        if (!(std::fabs(actual - expected) <= next_expectation->tolerance)) {
          result.failed_expectations.push_back(
              "expect[" + std::to_string(next_expectation->index) + "] (cycle " + std::to_string(s.cycle) +
              "): " + column.name + " = " + format_number(actual) + ", expected " + format_number(expected) +
              " (tolerance " + format_number(next_expectation->tolerance) + ")");
        }
      }
    }
    if (s.aborted) break;
  }
  if (s.retain) {
    // The end of the run is a power-down: what the retentive memory holds reaches the file.
    s.retain->cycle();
    (void)s.retain->service();
  }
  result.runtime_errors.insert(result.runtime_errors.end(), s.runtime_errors.begin(), s.runtime_errors.end());
  return result;
}

}  // namespace tomc::scenario
