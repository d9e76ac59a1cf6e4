// One technology object and its simulated drive from JSON (machine.hpp, docs/scenarios.md).
#include "tomc/scenario/machine.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "cam_elements.hpp"
#include "json_reader.hpp"
#include "legacy_parameters.hpp"
#if TOMC_WITH_COMEDI
#include "tomc/drives/comedi_analog_drive.hpp"
#endif
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/motion/axis_units.hpp"
#include "tomc/telegrams/encoder.hpp"

namespace tomc::scenario {

namespace to = tomc::techobjects;
using detail::ObjectReader;

namespace {

// The cam types are the last four, in the order of techobjects::CamVariant.
constexpr std::array<std::string_view, 8> kToTypeNames{
    "TO_SpeedAxis", "TO_PositioningAxis", "TO_SynchronousAxis", "TO_ExternalEncoder",
    "TO_Cam",       "TO_Cam_10k",         "TO_Cam_600Seg",      "TO_Cam_6kSeg"};
constexpr std::size_t kFirstCamType = 4;
constexpr std::array<std::string_view, 5> kPlannedToTypeNames{
    "TO_OutputCam", "TO_CamTrack", "TO_MeasuringInput", "TO_Kinematics", "TO_LeadingAxisProxy"};
constexpr std::array<TechnologyObjectKind, 8> kToKinds{TechnologyObjectKind::kSpeedAxis,
                                                       TechnologyObjectKind::kPositioningAxis,
                                                       TechnologyObjectKind::kSynchronousAxis,
                                                       TechnologyObjectKind::kExternalEncoder,
                                                       TechnologyObjectKind::kCam,
                                                       TechnologyObjectKind::kCam,
                                                       TechnologyObjectKind::kCam,
                                                       TechnologyObjectKind::kCam};

std::string list_of(std::span<const std::string_view> names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

// The simulated drive of a positioning/synchronous axis follows the TO's mechanics unless the file says
// otherwise (docs/scenarios.md): gear, load units per revolution, encoder 1 resolution.
void drive_like_axis(const to::PositioningAxisData& d, drives::SimulatedDriveParameters& p) {
  p.reference_speed_rpm = d.Actor.DriveParameter.ReferenceSpeed;
  p.reference_torque_nm = d.Actor.DriveParameter.ReferenceTorque;
  p.gear_motor_revolutions = d.LoadGear.Numerator;
  p.gear_load_revolutions = d.LoadGear.Denominator;
  const auto units = to::axis_unit_factors(d.Units.LengthUnit, d.Units.VelocityUnit);
  p.load_units_per_revolution =
      d.Properties.MotionType == 0 ? d.Mechanics.LeadScrew * units.leadscrew : units.units_per_revolution;
  const auto& s1 = d.Sensor[0];
  p.encoder1.steps_per_revolution = s1.Parameter.StepsPerRevolution;
  p.encoder1.fine_resolution_xist1 = static_cast<std::uint8_t>(s1.Parameter.FineResolutionXist1);
  p.encoder1.fine_resolution_xist2 = static_cast<std::uint8_t>(s1.Parameter.FineResolutionXist2);
}

// The incremental encoder of an analog or stepper drive on the card's counter: ×4 what the TO's encoder 1
// counts per revolution (StepsPerRevolution · 2^FineResolutionXist1).
drives::io::QuadratureEncoderParameters counter_encoder(const drives::SimulatedDriveParameters& p) {
  drives::io::QuadratureEncoderParameters e;
  const double counts =
      telegrams::counts_per_revolution(p.encoder1.steps_per_revolution, p.encoder1.fine_resolution_xist1);
  e.lines_per_revolution = static_cast<std::uint32_t>(std::max(1.0, counts / 4.0));
  e.width_bits = p.encoder1.xist1_width_bits;
  e.count_at_power_on = p.encoder1.xist1_at_power_on;
  e.zero_mark_offset_revolutions = p.encoder1.reference_mark_offset_revolutions;
  return e;
}

// The simulated servo amplifier of an analog drive: the simulated drive's motor, load and machine.
// Without an enable output the amplifier's enable input is not wired: it runs whenever it is ready.
drives::io::SimulatedServoAmplifierParameters analog_amplifier(const DriveSettings& drive,
                                                               bool enable_output) {
  const auto& p = drive.parameters;
  const auto& a = *drive.analog;
  drives::io::SimulatedServoAmplifierParameters amp;
  amp.mechanics = p;
  amp.dac = a.dac;
  amp.rpm_per_volt = a.amplifier_rpm_per_volt > 0.0 ? a.amplifier_rpm_per_volt
                                                    : p.reference_speed_rpm / a.volts_at_reference;
  amp.input_offset_volts = a.amplifier_offset_volts;
  amp.ready_delay_s = a.ready_delay_s;
  amp.enable_wired = enable_output;
  amp.encoder_shaft = p.encoder1.shaft;
  amp.encoder = counter_encoder(p);
  return amp;
}

// The telegram-3 side of either actor, wired to the simulated hardware's default channels (the servo
// amplifier and the stepper motor use the same ones for enable, ready and counter).
void actor_base(const DriveSettings& drive, bool enable_output, bool ready_input,
                drives::ActorParameters& actor) {
  const auto& p = drive.parameters;
  const drives::io::SimulatedServoAmplifierParameters wiring;
  actor.servo_cycle_s = p.servo_cycle_s;
  actor.reference_speed_rpm = p.reference_speed_rpm;
  if (enable_output) actor.enable_output = wiring.enable_input;
  if (ready_input) actor.ready_input = wiring.ready_output;
  actor.counter = wiring.counter;
  actor.counter_width_bits = p.encoder1.xist1_width_bits;
  // NIST_B is the motor speed: a load-side encoder turns 1/ratio revolutions per motor revolution (a linear
  // scale counts 2^FineResolutionXist1 per Resolution of load travel).
  const double ratio = p.gear_motor_revolutions / p.gear_load_revolutions;
  const auto& e = p.encoder1;
  if (e.linear) {
    actor.counts_per_revolution =
        p.load_units_per_revolution / e.resolution * std::ldexp(1.0, e.fine_resolution_xist1) / ratio;
  } else {
    actor.counts_per_revolution =
        telegrams::counts_per_revolution(e.steps_per_revolution, e.fine_resolution_xist1) /
        (e.shaft == drives::SimulatedEncoderParameters::Shaft::kLoad ? ratio : 1.0);
  }
  actor.standstill_threshold_rpm = p.standstill_threshold_rpm;
}

drives::AnalogDriveParameters analog_actor(const DriveSettings& drive, bool enable_output, bool ready_input) {
  const auto& a = *drive.analog;
  drives::AnalogDriveParameters actor;
  actor_base(drive, enable_output, ready_input, actor);
  // With an encoder_telegram the position comes from that 81/83 encoder (the drive's encoder1), not the card.
  if (drive.encoder_telegram != 0) actor.feedback = drives::PositionFeedback::kSeparateEncoder;
  actor.volts_at_reference = a.volts_at_reference;
  actor.overdrive_percent = a.overdrive_percent;
  actor.offset_volts = a.offset_volts;
  actor.dac = a.dac;
  actor.analog_output = drives::io::SimulatedServoAmplifierParameters{}.speed_input;
  return actor;
}

// A drive with "analog": {"comedi": {...}}: the analog actor on a real DAQ card (decision A21). The card is
// opened here, so a missing device is a configuration error naming the file; nullptr after a problem.
to::DeviceIo* add_comedi_drive(const DriveSettings& drive, bool enable_output, bool ready_input,
                               const std::string& path, to::Runtime& runtime, Problems& problems) {
  const ComediSettings& c = *drive.analog->comedi;
  const std::string at = path + ".analog.comedi";
  const std::size_t before = problems.size();
  if (drive.encoder_telegram != 0) {
    problems.add(path + ".encoder_telegram",
                 "a separate 81/83 encoder is simulated: with \"comedi\" the position is the card's counter");
  }
  // The card's wiring and the TO's Actor.Interface must agree (spec 01 §3.12: both are optional).
  const auto wiring = [&](const char* key, bool wired, bool given, const char* variable) {
    if (wired && !given) {
      problems.add(at + "." + key, std::string("missing: the TO's ") + variable + " is TRUE");
    } else if (!wired && given) {
      problems.add(at + "." + key,
                   std::string("the TO's ") + variable + " is FALSE (set it TRUE or remove the channel)");
    }
  };
  wiring("enable_output", enable_output, c.enable_output.has_value(), "Actor.Interface.EnableDriveOutput");
  wiring("ready_input", ready_input, c.ready_input.has_value(), "Actor.Interface.DriveReadyInput");
  if (problems.size() != before) return nullptr;
#if TOMC_WITH_COMEDI
  drives::io::ComediIoParameters card;
  card.device_file = c.device_file;
  card.analog_outputs = {c.analog_output};
  if (c.enable_output) card.digital_outputs = {*c.enable_output};
  if (c.ready_input) card.digital_inputs = {*c.ready_input};
  card.counters = {c.counter};
  card.counter_width_bits = c.counter_width_bits;
  drives::AnalogDriveParameters actor = analog_actor(drive, enable_output, ready_input);
  actor.analog_output = c.analog_output;
  actor.enable_output = c.enable_output;
  actor.ready_input = c.ready_input;
  actor.counter = c.counter;
  actor.counter_width_bits = c.counter_width_bits;
  try {
    return &runtime.add_device(std::make_unique<drives::ComediAnalogDrive>(card, actor));
  } catch (const std::runtime_error& e) {
    problems.add(at + ".device", e.what());
  }
#else
  (void)runtime;
  problems.add(at,
               "this tomc is built without the comedi backend (configure with -DTOMC_WITH_COMEDI=ON, "
               "which needs Debian's libcomedi-dev)");
#endif
  return nullptr;
}

// The simulated stepper driver and motor (decision A12) on the simulated drive's gear, load and machine. With
// "feedback": "pulses" the counter is the PTO's pulse count, so the TO's encoder 1 counts motor steps; with
// "encoder" it is the incremental encoder of encoder 1.
drives::io::SimulatedStepperMotorParameters stepper_motor(const DriveSettings& drive, bool enable_output) {
  const auto& p = drive.parameters;
  const auto& st = *drive.stepper;
  drives::io::SimulatedStepperMotorParameters m;
  m.mechanics = p;
  m.feedback = st.encoder_feedback ? drives::io::SimulatedStepperMotorParameters::Feedback::kEncoder
                                   : drives::io::SimulatedStepperMotorParameters::Feedback::kPulseCount;
  m.pulse_counter_width_bits = p.encoder1.xist1_width_bits;
  m.steps_per_revolution = st.steps_per_revolution;
  m.pull_in_rate_hz = st.pull_in_rate_hz;
  m.pull_out_rate_hz = st.pull_out_rate_hz;
  m.max_acceleration_hz_per_s = st.max_acceleration_hz_per_s;
  m.enable_wired = enable_output;
  m.ready_delay_s = st.ready_delay_s;
  m.encoder_shaft = p.encoder1.shaft;
  m.encoder = counter_encoder(p);
  return m;
}

drives::StepperDriveParameters stepper_actor(const DriveSettings& drive, bool enable_output,
                                             bool ready_input) {
  const auto& st = *drive.stepper;
  drives::StepperDriveParameters actor;
  actor_base(drive, enable_output, ready_input, actor);
  actor.steps_per_revolution = st.steps_per_revolution;
  if (!st.encoder_feedback) actor.counts_per_revolution = st.steps_per_revolution;  // the pulse count
  actor.max_frequency_hz = st.max_frequency_hz;
  actor.pulse_output = drives::io::SimulatedStepperMotorParameters{}.pulse_input;
  return actor;
}

// "SuperimposingAxes": ["<axis defined before>", ...]: the possible superimposing axes of a positioning or
// synchronous axis for MC_MotionInSuperimposedAxes (seed 004 §6.14.3.2, decision U10).
std::vector<to::PositioningAxis*> load_superimposing_axes(ObjectReader& r,
                                                          std::span<const MachineObject> existing,
                                                          Problems& problems) {
  std::vector<to::PositioningAxis*> out;
  const Json* v = r.get("SuperimposingAxes");
  if (v == nullptr) return out;
  const std::string path = r.path_of("SuperimposingAxes");
  if (!v->is_array()) {
    problems.add(path, "expected an array of axis names");
    return out;
  }
  for (std::size_t i = 0; i < v->size(); ++i) {
    const std::string at = path + "[" + std::to_string(i) + "]";
    const auto name = detail::read_string((*v)[i], at, problems);
    if (!name) continue;
    const auto it = std::find_if(existing.begin(), existing.end(),
                                 [&](const MachineObject& o) { return o.name == *name; });
    if (it == existing.end()) {
      problems.add(at, "'" + *name +
                           "' is not a technology object defined before this one (a superimposing axis must "
                           "come first in technology_objects)");
    } else if (it->built && it->positioning_axis == nullptr) {
      problems.add(at, "'" + *name + "' is a " + std::string(it->type_name()) +
                           ", which cannot be a superimposing axis (positioning or synchronous axes only)");
    } else if (std::find(out.begin(), out.end(), it->positioning_axis) != out.end()) {
      problems.add(at, "'" + *name + "' is named twice");
    } else if (out.size() == to::SuperimposingAxisTable::kCapacity) {
      problems.add(at, "more than " + std::to_string(to::SuperimposingAxisTable::kCapacity) +
                           " possible superimposing axes");
    } else if (it->built) {
      out.push_back(it->positioning_axis);
    }
  }
  return out;
}

// "LeadingValueInterconnections": [ {"Leader": "<TO defined before>", "Coupling": "Setpoint" | "ActualValue"
// | "Delayed", "LeadingValueReversalTolerance": <≥ 0>} ] (spec 07 §1.2, §1.5, §1.6, O-15).
std::vector<to::LeadingValueInterconnection> load_interconnections(ObjectReader& r, std::string_view follower,
                                                                   std::span<const MachineObject> existing,
                                                                   Problems& problems) {
  std::vector<to::LeadingValueInterconnection> out;
  const Json* v = r.get("LeadingValueInterconnections");
  if (v == nullptr) return out;
  const std::string path = r.path_of("LeadingValueInterconnections");
  if (!v->is_array()) {
    problems.add(path, "expected an array of {\"Leader\": ..., \"Coupling\": ...}");
    return out;
  }
  for (std::size_t i = 0; i < v->size(); ++i) {
    ObjectReader e((*v)[i], path + "[" + std::to_string(i) + "]", problems);
    if (!e.valid()) continue;
    to::LeadingValueInterconnection c;
    const MachineObject* leader = nullptr;
    if (const Json* l = e.get("Leader", true)) {
      if (auto name = detail::read_string(*l, e.path_of("Leader"), problems)) {
        const auto it = std::find_if(existing.begin(), existing.end(),
                                     [&](const MachineObject& o) { return o.name == *name; });
        if (it == existing.end()) {
          problems.add(e.path_of("Leader"),
                       "'" + *name +
                           "' is not a technology object defined before this one (a leading "
                           "value must come first in technology_objects)");
        } else if (it->built && it->leading_value_source() == nullptr) {
          problems.add(e.path_of("Leader"), "'" + *name + "' is a " + std::string(it->type_name()) +
                                                ", which cannot be a leading value (spec 07 §1.2)");
        } else if (it->built) {
          leader = &*it;
          c.object = it->object;
          c.source = const_cast<to::LeadingValueSource*>(it->leading_value_source());
        }
      }
    }
    if (const Json* k = e.get("Coupling")) {
      if (auto choice = detail::read_choice(*k, e.path_of("Coupling"), {"Setpoint", "ActualValue", "Delayed"},
                                            problems)) {
        constexpr std::array kCouplings{to::LeadingValueCoupling::kSetpoint,
                                        to::LeadingValueCoupling::kActualValue,
                                        to::LeadingValueCoupling::kDelayed};
        c.coupling = kCouplings[static_cast<std::size_t>(*choice)];
      }
    }
    // Only an axis keeps the history of its setpoint (decision C26): refused at this key, before the TO's
    // own refusal at emplace() would become a problem of the follower's whole `config`.
    if (c.coupling == to::LeadingValueCoupling::kDelayed && leader != nullptr &&
        leader->positioning_axis == nullptr) {
      problems.add(e.path_of("Coupling"), "'" + std::string(follower) + "' cannot couple \"Delayed\" to '" +
                                              leader->name + "', a " + std::string(leader->type_name()) +
                                              " (only a positioning or synchronous axis can, decision C26)");
      c.source = nullptr;
    }
    // A tomc extension for the V10 setting (spec 07 §1.6, decision C27), in the leader's length unit.
    double tolerance = 0.0;
    // Stored as a float: at most 1e9 (a length), so the conversion is defined.
    e.real("LeadingValueReversalTolerance", tolerance, detail::Range{0.0, 1.0e9, false});
    c.reversal_tolerance = static_cast<float>(tolerance);
    e.finish();
    if (c.source != nullptr) out.push_back(c);
  }
  return out;
}

}  // namespace

std::string_view MachineObject::type_name() const noexcept {
  if (cam != nullptr) return to::type_name(cam->variant());
  return kToTypeNames[static_cast<std::size_t>(std::find(kToKinds.begin(), kToKinds.end(), kind) -
                                               kToKinds.begin())];
}

const to::VariableInfo* MachineObject::find_variable(std::string_view path) const noexcept {
  switch (kind) {
    case TechnologyObjectKind::kSpeedAxis:
      return to::find_speed_axis_variable(path);
    case TechnologyObjectKind::kPositioningAxis:
    case TechnologyObjectKind::kSynchronousAxis:
      return to::find_positioning_axis_variable(path);
    case TechnologyObjectKind::kExternalEncoder:
      return to::find_external_encoder_variable(path);
    case TechnologyObjectKind::kCam:
      return to::find_cam_variable(path);
  }
  return nullptr;
}

std::optional<to::BitReference> MachineObject::find_bit(std::string_view path) const noexcept {
  switch (kind) {
    case TechnologyObjectKind::kSpeedAxis:
      return to::find_speed_axis_bit(path);
    case TechnologyObjectKind::kPositioningAxis:
    case TechnologyObjectKind::kSynchronousAxis:
      return to::find_positioning_axis_bit(path);
    case TechnologyObjectKind::kExternalEncoder:
      return to::find_external_encoder_bit(path);
    case TechnologyObjectKind::kCam:
      return to::find_cam_bit(path);
  }
  return std::nullopt;
}

std::function<double()> MachineObject::reader(const to::VariableInfo* info,
                                              std::optional<to::BitReference> bit) const {
  const auto read = [info, bit](const auto& data) {
    return bit ? (bit->read(data) ? 1.0 : 0.0) : info->read(data);
  };
  switch (kind) {
    case TechnologyObjectKind::kSpeedAxis:
      return [a = speed_axis, read] { return read(a->data()); };
    case TechnologyObjectKind::kPositioningAxis:
    case TechnologyObjectKind::kSynchronousAxis:
      return [a = positioning_axis, read] { return read(a->data()); };
    case TechnologyObjectKind::kExternalEncoder:
      return [a = external_encoder, read] { return read(a->data()); };
    case TechnologyObjectKind::kCam:
      return [a = cam, read] { return read(a->data()); };
  }
  return [] { return std::numeric_limits<double>::quiet_NaN(); };
}

double MachineObject::read(std::string_view path) const noexcept {
  if (synchronous_axis != nullptr) return synchronous_axis->read(path);
  if (positioning_axis != nullptr) return positioning_axis->read(path);
  if (speed_axis != nullptr) return speed_axis->read(path);
  if (external_encoder != nullptr) return external_encoder->read(path);
  if (cam != nullptr) return cam->read(path);
  return std::numeric_limits<double>::quiet_NaN();
}

to::WriteResult MachineObject::write(std::string_view variable, double value) const noexcept {
  if (speed_axis != nullptr) return speed_axis->write(variable, value);
  if (positioning_axis != nullptr) return positioning_axis->write(variable, value);
  if (cam != nullptr) return cam->write(variable, value);
  return external_encoder->write(variable, value);
}

bool MachineObject::inject_alarm(std::uint32_t number, std::uint32_t additional,
                                 to::AlarmReaction reaction) const noexcept {
  if (speed_axis != nullptr) return speed_axis->inject_alarm(number, additional, reaction);
  if (positioning_axis != nullptr) return positioning_axis->inject_alarm(number, additional, reaction);
  if (cam != nullptr) return false;  // a cam has no technology alarms of its own
  return external_encoder->inject_alarm(number, additional, reaction);
}

const to::AlarmList& MachineObject::alarms() const noexcept {
  if (speed_axis != nullptr) return speed_axis->alarms();
  if (positioning_axis != nullptr) return positioning_axis->alarms();
  if (cam != nullptr) {
    static const to::AlarmList kNone;  // a cam raises none
    return kNone;
  }
  return external_encoder->alarms();
}

const to::LeadingValueSource* MachineObject::leading_value_source() const noexcept {
  if (positioning_axis != nullptr) return positioning_axis;
  if (external_encoder != nullptr) return external_encoder;
  return nullptr;
}

bool is_identifier(std::string_view name) noexcept {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::optional<MachineObject> load_technology_object(const Json& value, const std::string& path,
                                                    double cycle_time_s, to::Runtime& runtime,
                                                    std::span<const MachineObject> existing,
                                                    Problems& problems, std::string_view tool,
                                                    GatewayLinks* gateways,
                                                    const std::filesystem::path& directory) {
  // A "legacy" parameter set (JOINT, H3) becomes config and drive keys first (legacy_parameters.hpp).
  bool legacy_ok = true;
  Json expanded;
  const Json* source = &value;
  if (value.is_object() && value.contains("legacy")) {
    if (auto x = detail::with_legacy_expanded(value, path, cycle_time_s, problems)) {
      expanded = std::move(*x);
    } else {
      expanded = value;
      expanded.erase("legacy");
      // The legacy set would have given the drive: a placeholder keeps "drive: missing" from following the
      // legacy problems (the TO is not built).
      if (!expanded.contains("drive")) expanded["drive"] = Json{{"adapter", "analog"}, {"telegram", 3}};
      legacy_ok = false;
    }
    source = &expanded;
  }
  ObjectReader r(*source, path, problems);
  if (!r.valid()) return std::nullopt;
  MachineObject entry;
  if (const Json* v = r.get("name", true)) {
    if (auto name = detail::read_string(*v, r.path_of("name"), problems)) {
      const bool duplicate = std::any_of(existing.begin(), existing.end(),
                                         [&](const MachineObject& o) { return o.name == *name; });
      if (!is_identifier(*name)) {
        problems.add(r.path_of("name"),
                     "'" + *name + "' is not a name (letters, digits, _; not starting with a digit)");
      } else if (duplicate) {
        problems.add(r.path_of("name"), "'" + *name + "' is defined twice");
      } else {
        entry.name = *name;
      }
    }
  }
  std::optional<TechnologyObjectKind> kind;
  to::CamVariant cam_variant = to::CamVariant::kCam;
  if (const Json* v = r.get("type", true)) {
    if (auto t = detail::read_string(*v, r.path_of("type"), problems)) {
      const auto it = std::find(kToTypeNames.begin(), kToTypeNames.end(), *t);
      const std::string supported = list_of(std::span<const std::string_view>(kToTypeNames));
      if (it == kToTypeNames.end()) {
        // Technology objects of the S7-1500T manuals that tomc does not model yet get their own message, so
        // a user knows the name is right and only the support is missing.
        const bool planned = std::find(kPlannedToTypeNames.begin(), kPlannedToTypeNames.end(), *t) !=
                             kPlannedToTypeNames.end();
        problems.add(r.path_of("type"),
                     planned ? *t + " is not yet supported by tomc (supported: " + supported + ")"
                             : "unknown technology object type '" + *t + "' (one of " + supported + ")");
      } else {
        const auto index = static_cast<std::size_t>(it - kToTypeNames.begin());
        kind = kToKinds[index];
        if (index >= kFirstCamType) cam_variant = static_cast<to::CamVariant>(index - kFirstCamType);
      }
    }
  }
  const std::size_t before = problems.size();
  to::SpeedAxisData speed_data;
  to::PositioningAxisData positioning_data;
  to::ExternalEncoderData encoder_data;
  std::vector<to::LeadingValueInterconnection> interconnections;
  std::vector<to::PositioningAxis*> superimposing_axes;
  std::unique_ptr<to::CamData> cam_settings;
  detail::CamElements cam_elements;
  DriveSettings drive;
  bool has_drive = false;
  if (kind) {
    bool needs_drive = true;
    const Json* config = r.get("config");
    // The simulated drive is parameterised like the TO unless the file says otherwise (p2000 =
    // ReferenceSpeed, p2003 = ReferenceTorque, the mechanics of the load), as automatic data adaption would
    // do; a mismatch must be asked for explicitly.
    auto& p = drive.parameters;
    switch (*kind) {
      case TechnologyObjectKind::kSpeedAxis:
        if (config != nullptr) load_speed_axis_config(*config, r.path_of("config"), speed_data, problems);
        p.reference_speed_rpm = speed_data.Actor.DriveParameter.ReferenceSpeed;
        p.reference_torque_nm = speed_data.Actor.DriveParameter.ReferenceTorque;
        needs_drive = speed_data.VirtualAxis.Mode != to::kModeOn && speed_data.Simulation.Mode != to::kModeOn;
        break;
      case TechnologyObjectKind::kSynchronousAxis:
        interconnections = load_interconnections(r, entry.name, existing, problems);
        [[fallthrough]];
      case TechnologyObjectKind::kPositioningAxis:
        superimposing_axes = load_superimposing_axes(r, existing, problems);
        if (config != nullptr)
          load_positioning_axis_config(
              *config, r.path_of("config"), positioning_data, problems,
              *kind == TechnologyObjectKind::kSynchronousAxis ? "TO_SynchronousAxis" : "TO_PositioningAxis");
        drive_like_axis(positioning_data, p);
        needs_drive = positioning_data.VirtualAxis.Mode != to::kModeOn &&
                      positioning_data.Simulation.Mode != to::kModeOn;
        break;
      case TechnologyObjectKind::kExternalEncoder: {
        if (config != nullptr)
          load_external_encoder_config(*config, r.path_of("config"), encoder_data, problems);
        const auto& d = encoder_data;
        p.gear_motor_revolutions = d.LoadGear.Numerator;
        p.gear_load_revolutions = d.LoadGear.Denominator;
        const auto units = to::axis_unit_factors(d.Units.LengthUnit, d.Units.VelocityUnit);
        p.load_units_per_revolution = d.Properties.MotionType == 0 ? d.Mechanics.LeadScrew * units.leadscrew
                                                                   : units.units_per_revolution;
        p.encoder1.steps_per_revolution = d.Sensor.Parameter.StepsPerRevolution;
        p.encoder1.fine_resolution_xist1 = static_cast<std::uint8_t>(d.Sensor.Parameter.FineResolutionXist1);
        p.encoder1.fine_resolution_xist2 = static_cast<std::uint8_t>(d.Sensor.Parameter.FineResolutionXist2);
        drive.encoder_telegram = 81;  // an encoder-only device unless the file says otherwise
        break;
      }
      case TechnologyObjectKind::kCam:
        cam_settings = std::make_unique<to::CamData>(to::CamVariant::kCam);  // only its scalar variables
        if (config != nullptr)
          load_cam_config(*config, r.path_of("config"), *cam_settings, problems, to::type_name(cam_variant));
        cam_elements = detail::load_cam_elements(r, cam_variant, directory, problems);
        needs_drive = false;
        break;
    }
    entry.kind = *kind;
    if (*kind == TechnologyObjectKind::kCam && r.has("drive")) {
      r.get("drive");
      problems.add(r.path_of("drive"), "a cam has no drive (it is a transfer function, spec 07 §3.1)");
    } else if (const Json* v = r.get("drive")) {
      load_drive(*v, r.path_of("drive"), cycle_time_s, drive, problems);
      has_drive = true;
    } else if (needs_drive) {
      problems.add(r.path_of("drive"),
                   "missing (a " + std::string(entry.type_name()) +
                       (*kind == TechnologyObjectKind::kExternalEncoder
                            ? " needs a device with encoder telegram 81 or 83)"
                            : " needs a drive unless VirtualAxis.Mode or Simulation.Mode is 1)"));
    }
  } else {
    // The type is unusable, so its config cannot be checked; still accept the keys to avoid noise.
    r.get("config");
    r.get("drive");
    r.get("LeadingValueInterconnections");
    r.get("SuperimposingAxes");
    for (const char* key : {"Points", "Segments", "MotionLaws", "Interpolate"})
      r.get(key);
  }
  if (kind && *kind != TechnologyObjectKind::kSynchronousAxis &&
      *kind != TechnologyObjectKind::kPositioningAxis && r.has("SuperimposingAxes")) {
    r.get("SuperimposingAxes");
    problems.add(r.path_of("SuperimposingAxes"),
                 "only a positioning or synchronous axis has superimposing axes (seed 004 §6.14.3.2)");
  }
  if (kind && *kind != TechnologyObjectKind::kSynchronousAxis && r.has("LeadingValueInterconnections")) {
    r.get("LeadingValueInterconnections");
    problems.add(r.path_of("LeadingValueInterconnections"), "only a TO_SynchronousAxis has leading values");
  }
  r.finish();
  if (!entry.name.empty() && kind && problems.size() == before && legacy_ok) {
    drives::SimulatedDrive* drive_ptr = nullptr;
    to::DeviceIo* io = nullptr;
    if (has_drive && drive.gateway) {
      if (gateways == nullptr) {
        problems.add(r.path_of("drive") + ".adapter",
                     "a gateway drive is not available in " + std::string(tool));
        return entry.name.empty() ? std::nullopt : std::optional<MachineObject>(std::move(entry));
      }
      try {
        io = &runtime.add_device(gateways->make_drive(*drive.gateway, drive.device_config(), cycle_time_s));
      } catch (const std::exception& e) {
        problems.add(r.path_of("drive") + ".adapter", e.what());
        return entry.name.empty() ? std::nullopt : std::optional<MachineObject>(std::move(entry));
      }
    } else if (has_drive && drive.analog) {
      const auto& itf = *kind == TechnologyObjectKind::kSpeedAxis ? speed_data.Actor.Interface
                                                                  : positioning_data.Actor.Interface;
      // The S7 shows the analog setpoint interface in Actor.Type (RON, set by the configuration).
      speed_data.Actor.Type = static_cast<std::int32_t>(to::ActorType::kAnalogOutput);
      positioning_data.Actor.Type = static_cast<std::int32_t>(to::ActorType::kAnalogOutput);
      if (drive.analog->comedi) {
        // A real DAQ card (add_comedi_drive): opened now, so a missing card is a configuration error.
        io = add_comedi_drive(drive, itf.EnableDriveOutput, itf.DriveReadyInput, r.path_of("drive"), runtime,
                              problems);
        if (io == nullptr)
          return entry.name.empty() ? std::nullopt : std::optional<MachineObject>(std::move(entry));
      }
      std::optional<drives::SeparateEncoderParameters> encoder;
      if (drive.encoder_telegram != 0) encoder = {drive.encoder_telegram, drive.parameters.encoder1};
      if (io == nullptr) {
        auto owned = std::make_unique<drives::SimulatedAnalogDrive>(
            analog_amplifier(drive, itf.EnableDriveOutput),
            analog_actor(drive, itf.EnableDriveOutput, itf.DriveReadyInput), encoder);
        entry.mechanics = &owned->hardware().mechanics();
        entry.analog_drive = owned.get();
        // The separate 81/83 encoder is a simulated PROFIdrive encoder device: encoder_error goes there.
        drive_ptr = owned->separate_encoder();
        io = &runtime.add_device(std::move(owned));
      }
    } else if (has_drive && drive.stepper) {
      // A PTO module is a telegram-3 drive to the S7 (spec 01 §3.11): Actor.Type stays 1.
      const auto& itf = *kind == TechnologyObjectKind::kSpeedAxis ? speed_data.Actor.Interface
                                                                  : positioning_data.Actor.Interface;
      const auto& e = drive.parameters.encoder1;
      const double counts = telegrams::counts_per_revolution(e.steps_per_revolution, e.fine_resolution_xist1);
      if (*kind != TechnologyObjectKind::kSpeedAxis && !drive.stepper->encoder_feedback &&
          std::fabs(counts - drive.stepper->steps_per_revolution) > 1e-9) {
        problems.add(r.path_of("drive") + ".stepper.steps_per_revolution",
                     format_number(drive.stepper->steps_per_revolution) +
                         ": with \"feedback\": \"pulses\" the TO's encoder counts motor steps (Sensor[1] "
                         "StepsPerRevolution · 2^FineResolutionXist1 = " +
                         format_number(counts) + ")");
        return entry.name.empty() ? std::nullopt : std::optional<MachineObject>(std::move(entry));
      }
      auto owned = std::make_unique<drives::SimulatedStepperDrive>(
          stepper_motor(drive, itf.EnableDriveOutput),
          stepper_actor(drive, itf.EnableDriveOutput, itf.DriveReadyInput));
      entry.mechanics = &owned->hardware().mechanics();
      entry.stepper_drive = owned.get();
      io = &runtime.add_device(std::move(owned));
    } else if (has_drive) {
      auto owned = std::make_unique<drives::SimulatedDrive>(drive.device_config(), drive.parameters);
      entry.mechanics = &owned->mechanics();
      owned->set_external_speed(drive.external_speed);
      drive_ptr = owned.get();
      io = &runtime.add_device(std::move(owned));
    }
    try {
      switch (*kind) {
        case TechnologyObjectKind::kSpeedAxis:
          entry.speed_axis = &runtime.emplace<to::SpeedAxis>(entry.name, io, speed_data);
          entry.object = entry.speed_axis;
          break;
        case TechnologyObjectKind::kPositioningAxis:
          entry.positioning_axis = &runtime.emplace<to::PositioningAxis>(entry.name, io, positioning_data);
          entry.object = entry.positioning_axis;
          break;
        case TechnologyObjectKind::kSynchronousAxis:
          entry.synchronous_axis =
              &runtime.emplace<to::SynchronousAxis>(entry.name, io, positioning_data, interconnections);
          entry.positioning_axis = entry.synchronous_axis;
          entry.object = entry.synchronous_axis;
          break;
        case TechnologyObjectKind::kExternalEncoder:
          entry.external_encoder = &runtime.emplace<to::ExternalEncoder>(entry.name, io, encoder_data);
          entry.object = entry.external_encoder;
          break;
        case TechnologyObjectKind::kCam:
          // Its number (StatusSynchronizedMotion.ActualCam): the 1-based place in the file (decision C8).
          entry.cam = &runtime.emplace<to::Cam>(entry.name, cam_variant,
                                                static_cast<std::uint16_t>(existing.size() + 1));
          entry.object = entry.cam;
          (void)entry.cam->write("InterpolationSettings.InterpolationMode",
                                 cam_settings->InterpolationSettings.InterpolationMode);
          (void)entry.cam->write("InterpolationSettings.BoundaryConditions",
                                 cam_settings->InterpolationSettings.BoundaryConditions);
          detail::apply_cam_elements(cam_elements, *entry.cam, path, problems);
          break;
      }
      for (to::PositioningAxis* superimposing : superimposing_axes)
        entry.positioning_axis->add_possible_superimposing_axis(*superimposing);
      entry.drive = drive_ptr;
      entry.built = true;
    } catch (const std::invalid_argument& e) {
      // Cross-checks of the TO (units against the motion type, the encoder's telegram, ...), named by path.
      problems.add(r.path_of("config"), e.what());
    }
  }
  if (entry.name.empty()) return std::nullopt;
  return entry;
}

void wire_machine_inputs(to::Runtime& runtime, std::span<const MachineObject> objects) {
  std::vector<std::pair<to::PositioningAxis*, const drives::MotorLoad*>> wired;
  std::vector<std::pair<to::ExternalEncoder*, const drives::MotorLoad*>> encoders;
  for (const auto& o : objects) {
    if (o.positioning_axis != nullptr && o.mechanics != nullptr)
      wired.emplace_back(o.positioning_axis, o.mechanics);
    if (o.external_encoder != nullptr && o.mechanics != nullptr)
      encoders.emplace_back(o.external_encoder, o.mechanics);
  }
  if (wired.empty() && encoders.empty()) return;
  runtime.set_pre_servo([wired = std::move(wired), encoders = std::move(encoders)](to::Runtime&) {
    for (const auto& [axis, drive] : wired) {
      const drives::MachineInputs in = drive->machine_inputs();
      const auto& hw = axis->data().PositionLimits_HW;
      auto& image = axis->digital_inputs();
      image.MinSwitch = in.negative_limit_switch == hw.MinSwitchLevel;
      image.MaxSwitch = in.positive_limit_switch == hw.MaxSwitchLevel;
      image.HomingInput = in.reference_cam;
    }
    for (const auto& [encoder, drive] : encoders)
      encoder->digital_inputs().HomingInput = drive->machine_inputs().reference_cam;
  });
}

}  // namespace tomc::scenario
