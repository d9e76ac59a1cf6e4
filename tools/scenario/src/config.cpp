// The TO configuration and simulated-drive loaders (config.hpp). The TO side is driven entirely by the
// reflection table, so a variable added to the data block is configurable without touching this file.
#include "tomc/scenario/config.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "gateway_adapter_detail.hpp"
#include "json_reader.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/telegrams/layout.hpp"

namespace tomc::scenario {
namespace {

namespace to = tomc::techobjects;
using detail::ObjectReader;
using detail::Range;

std::string lowercase(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

// A near miss ("dynamiclimits.maxvelocity", "MaxVelocity") is most often a typo of one real path.
std::string suggestion_for(std::string_view key, std::span<const to::VariableInfo> table) {
  const std::string lower = lowercase(key);
  std::string tail_match;
  int tail_matches = 0;
  for (const auto& v : table) {
    if (lowercase(v.path) == lower) return " (did you mean '" + std::string(v.path) + "'?)";
    const auto dot = v.path.rfind('.');
    const std::string_view tail = dot == std::string_view::npos ? v.path : v.path.substr(dot + 1);
    if (lowercase(tail) == lower) {
      tail_match = v.path;
      ++tail_matches;
    }
  }
  if (tail_matches == 1) return " (did you mean '" + tail_match + "'?)";
  return {};
}

std::string permitted_list(const to::VariableInfo& info) {
  std::string list;
  for (double v : info.allowed_values)
    list += (list.empty() ? "" : ", ") + format_number(v);
  return list;
}

}  // namespace

drives::DeviceConfig DriveSettings::device_config() const {
  drives::DeviceConfig c;
  c.drive_telegram = telegram;
  c.supplementary_telegram = supplementary_telegram;
  c.encoder_telegrams[0] = encoder_telegram;
  return c;
}

namespace {

// Every key of `config` is a data-block path of `table`; the reflection table decides type, range and access.
template <typename Data>
void load_config(const Json& config, std::string_view path, std::string_view type_name,
                 std::span<const to::VariableInfo> table, const to::VariableInfo* (*find)(std::string_view),
                 Data& data, Problems& problems) {
  if (!config.is_object()) {
    problems.add(path,
                 "expected an object of data-block paths, got " + std::string(detail::type_name(config)));
    return;
  }
  const std::string of = "not a variable of " + std::string(type_name);
  for (const auto& [key, value] : config.items()) {
    if (key == "comment") continue;
    const std::string at = join_path(path, key);
    const to::VariableInfo* info = find(key);
    if (info == nullptr) {
      if (key == "LeadingValueInterconnections") {
        // Not a data-block variable but the TO's interconnections (decision Y2): say where it belongs.
        const std::string_view parent = path.substr(0, path.rfind('.'));
        problems.add(at, type_name == "TO_SynchronousAxis"
                             ? "not a variable of TO_SynchronousAxis: LeadingValueInterconnections belongs "
                               "beside 'config', at " +
                                   std::string(parent) + ".LeadingValueInterconnections"
                             : "not a variable of " + std::string(type_name) +
                                   ": only a TO_SynchronousAxis has LeadingValueInterconnections (beside "
                                   "its 'config')");
      } else if (value.is_object()) {
        // {"DynamicLimits": {"MaxVelocity": ...}}: the format wants the full path as one key.
        problems.add(at, of + "; keys are full data-block paths such as '" + key + "." +
                             (value.empty() ? std::string("...") : value.begin().key()) + "'");
      } else {
        problems.add(at, "unknown variable of " + std::string(type_name) + suggestion_for(key, table));
      }
      continue;
    }
    const to::AccessError access = to::check_write_access(*info, to::WriteContext::kConfiguration);
    if (access != to::AccessError::kNone) {
      problems.add(at, "cannot be configured: " + std::string(to::to_string(access)));
      continue;
    }
    if (const auto number = detail::read_variable_value(*info, value, at, problems)) {
      // Cannot fail: read_variable_value ran the same check_value.
      static_cast<void>(info->write(data, *number));
    }
  }
}

}  // namespace

void load_speed_axis_config(const Json& config, std::string_view path, to::SpeedAxisData& data,
                            Problems& problems) {
  load_config(config, path, "TO_SpeedAxis", to::speed_axis_variables(), &to::find_speed_axis_variable, data,
              problems);
}

void load_positioning_axis_config(const Json& config, std::string_view path, to::PositioningAxisData& data,
                                  Problems& problems, std::string_view type_name) {
  load_config(config, path, type_name, to::positioning_axis_variables(), &to::find_positioning_axis_variable,
              data, problems);
}

void load_external_encoder_config(const Json& config, std::string_view path, to::ExternalEncoderData& data,
                                  Problems& problems) {
  load_config(config, path, "TO_ExternalEncoder", to::external_encoder_variables(),
              &to::find_external_encoder_variable, data, problems);
}

void load_cam_config(const Json& config, std::string_view path, to::CamData& data, Problems& problems,
                     std::string_view type_name) {
  load_config(config, path, type_name, to::cam_variables(), &to::find_cam_variable, data, problems);
}

namespace detail {

std::optional<double> read_variable_value(const to::VariableInfo& info, const Json& value,
                                          std::string_view at, Problems& problems) {
  const std::string type(to::to_string(info.type));
  double number = 0.0;
  if (info.type == to::VariableType::kBool) {
    if (!value.is_boolean()) {
      problems.add(at, "expected true or false (BOOL), got " + std::string(type_name(value)));
      return std::nullopt;
    }
    number = value.get<bool>() ? 1.0 : 0.0;
  } else if (value.is_number()) {
    number = value.get<double>();
  } else if (value.is_string() && to::bit_width(info.type) != 0) {
    const auto hex = parse_hex_literal(value.get_ref<const std::string&>());
    if (!hex) {
      problems.add(at,
                   "'" + value.get<std::string>() + "' is not a " + type + " literal such as 16#7 or 0x7");
      return std::nullopt;
    }
    number = static_cast<double>(*hex);
  } else {
    problems.add(at, "expected " +
                         std::string(info.type == to::VariableType::kLreal ? "a number" : "an integer") +
                         " (" + type + "), got " + std::string(type_name(value)));
    return std::nullopt;
  }
  switch (to::check_value(info, number)) {
    case to::ValueError::kNone:
      return number;
    case to::ValueError::kNotInteger:
      problems.add(at, format_number(number) + " is not an integer (" + type + ")");
      break;
    case to::ValueError::kOutOfRange:
      problems.add(at, format_number(number) + " out of range " + format_number(info.minimum) + ".." +
                           format_number(info.maximum));
      break;
    case to::ValueError::kNotAllowed:
      problems.add(at, format_number(number) + " is not a permitted value (" + permitted_list(info) + ")");
      break;
    case to::ValueError::kNotANumber:
    case to::ValueError::kNotBoolean:
    case to::ValueError::kWrongDataBlock:
      // Not reachable from JSON (no NaN in JSON; BOOL checked above; one table per TO type), but a message
      // beats silence if the table ever changes.
      problems.add(at, std::string(to::to_string(to::check_value(info, number))));
      break;
  }
  return std::nullopt;
}

}  // namespace detail

namespace {

using Reaction = drives::SimulatedDriveParameters::FaultReaction;
constexpr std::int64_t kUint32Max = 4294967295LL;

void load_encoder(const Json& value, const std::string& path, drives::SimulatedEncoderParameters& e,
                  Problems& problems) {
  ObjectReader r(value, path, problems);
  if (const Json* v = r.get("shaft")) {
    if (auto c = detail::read_choice(*v, r.path_of("shaft"), {"motor", "load"}, problems)) {
      e.shaft = *c == 0 ? drives::SimulatedEncoderParameters::Shaft::kMotor
                        : drives::SimulatedEncoderParameters::Shaft::kLoad;
    }
  }
  r.boolean("linear", e.linear);
  r.real("resolution", e.resolution, detail::kPositive);
  r.integer("steps_per_revolution", e.steps_per_revolution, 1, kUint32Max);
  r.integer("fine_resolution_xist1", e.fine_resolution_xist1, 0, 31);
  r.integer("fine_resolution_xist2", e.fine_resolution_xist2, 0, 31);
  r.integer("determinable_revolutions", e.determinable_revolutions, 0, kUint32Max);
  r.integer("xist1_width_bits", e.xist1_width_bits, 1, 32);
  r.integer("xist1_at_power_on", e.xist1_at_power_on, 0, kUint32Max, true);
  r.real("reference_mark_interval_revolutions", e.reference_mark_interval_revolutions, detail::kPositive);
  r.real("reference_mark_offset_revolutions", e.reference_mark_offset_revolutions);
  r.real("absolute_offset_revolutions", e.absolute_offset_revolutions);
  r.real("nist_reference_speed", e.nist_reference_speed, detail::kPositive);
  r.finish();
}

void load_window(ObjectReader& parent, std::string_view key, std::optional<drives::PositionWindow>& target,
                 Problems& problems) {
  const Json* v = parent.get(key);
  if (v == nullptr) return;
  if (v->is_null()) {
    target.reset();
    return;
  }
  ObjectReader r(*v, parent.path_of(key), problems);
  if (!r.valid()) return;
  drives::PositionWindow w;
  const std::size_t before = problems.size();
  r.real("from", w.from, detail::kAnyNumber, true);
  r.real("to", w.to, detail::kAnyNumber, true);
  r.finish();
  if (problems.size() != before) return;
  if (w.from > w.to) {
    problems.add(r.path(),
                 "from (" + format_number(w.from) + ") is greater than to (" + format_number(w.to) + ")");
    return;
  }
  target = w;
}

void load_machine(const Json& value, const std::string& path, drives::SimulatedMachineParameters& m,
                  Problems& problems) {
  ObjectReader r(value, path, problems);
  r.optional_real("negative_limit_switch", m.negative_limit_switch);
  r.optional_real("positive_limit_switch", m.positive_limit_switch);
  load_window(r, "reference_cam", m.reference_cam, problems);
  load_window(r, "probe1", m.probe1, problems);
  load_window(r, "probe2", m.probe2, problems);
  r.optional_real("negative_fixed_stop", m.negative_fixed_stop);
  r.optional_real("positive_fixed_stop", m.positive_fixed_stop);
  r.finish();
  if (m.negative_fixed_stop && m.positive_fixed_stop && *m.negative_fixed_stop >= *m.positive_fixed_stop) {
    problems.add(path, "negative_fixed_stop (" + format_number(*m.negative_fixed_stop) +
                           ") must be below positive_fixed_stop (" + format_number(*m.positive_fixed_stop) +
                           ")");
  }
}

// {"subdevice": s, "channel": c} of a comedi card.
void load_channel(ObjectReader& parent, std::string_view key, drives::io::Channel& channel,
                  Problems& problems) {
  if (const Json* v = parent.get(key, true)) {
    ObjectReader r(*v, parent.path_of(key), problems);
    r.integer("subdevice", channel.subdevice, 0, 65535, false, true);
    r.integer("channel", channel.channel, 0, 65535, false, true);
    r.finish();
  }
}

void load_comedi(const Json& value, const std::string& path, ComediSettings& c, Problems& problems) {
  ObjectReader r(value, path, problems);
  if (!r.valid()) return;
  if (const Json* v = r.get("device", true)) {
    if (auto file = detail::read_string(*v, r.path_of("device"), problems)) {
      if (file->empty()) {
        problems.add(r.path_of("device"), "expected the card's device file, e.g. \"/dev/comedi0\"");
      } else {
        c.device_file = *file;
      }
    }
  }
  load_channel(r, "analog_output", c.analog_output, problems);
  load_channel(r, "counter", c.counter, problems);
  // Optional: needed when the TO's Actor.Interface wires them (checked where the drive is built).
  if (r.has("enable_output")) load_channel(r, "enable_output", c.enable_output.emplace(), problems);
  if (r.has("ready_input")) load_channel(r, "ready_input", c.ready_input.emplace(), problems);
  r.integer("counter_width_bits", c.counter_width_bits, 8, 32);
  r.finish();
}

void load_analog(const Json& value, const std::string& path, AnalogSettings& a, Problems& problems) {
  ObjectReader r(value, path, problems);
  r.real("volts_at_reference", a.volts_at_reference, detail::kPositive);
  r.real("overdrive_percent", a.overdrive_percent, detail::Range{100.0, 200.0});
  r.real("offset_volts", a.offset_volts);
  r.integer("dac_bits", a.dac.bits, 8, 16);
  r.real("dac_full_scale_volts", a.dac.full_scale_volts, detail::kPositive);
  r.real("amplifier_rpm_per_volt", a.amplifier_rpm_per_volt, detail::kNonNegative);
  r.real("amplifier_offset_volts", a.amplifier_offset_volts);
  r.real("ready_delay_s", a.ready_delay_s, detail::kNonNegative);
  if (const Json* v = r.get("comedi")) {
    load_comedi(*v, r.path_of("comedi"), a.comedi.emplace(), problems);
    // The simulated amplifier's keys describe hardware a real card replaces.
    for (const char* key : {"amplifier_rpm_per_volt", "amplifier_offset_volts", "ready_delay_s"}) {
      if (r.has(key)) {
        problems.add(r.path_of(key),
                     "a key of the simulated servo amplifier: with \"comedi\" the amplifier is the real one");
      }
    }
  }
  r.finish();
  if (a.volts_at_reference * a.overdrive_percent / 100.0 > a.dac.full_scale_volts * (1.0 + 1e-9)) {
    problems.add(path,
                 "the overdrive range (" + format_number(a.volts_at_reference * a.overdrive_percent / 100.0) +
                     " V) exceeds the DAC's full scale (" + format_number(a.dac.full_scale_volts) + " V)");
  }
}

void load_stepper(const Json& value, const std::string& path, StepperSettings& st, Problems& problems) {
  ObjectReader r(value, path, problems);
  r.real("steps_per_revolution", st.steps_per_revolution, detail::kPositive);
  r.real("max_frequency_hz", st.max_frequency_hz, detail::kPositive);
  if (const Json* v = r.get("feedback")) {
    if (auto f = detail::read_choice(*v, r.path_of("feedback"), {"pulses", "encoder"}, problems)) {
      st.encoder_feedback = *f == 1;
    }
  }
  r.real("pull_in_rate_hz", st.pull_in_rate_hz, detail::kNonNegative);
  r.real("pull_out_rate_hz", st.pull_out_rate_hz, detail::kPositive);
  r.real("max_acceleration_hz_per_s", st.max_acceleration_hz_per_s, detail::kPositive);
  r.real("ready_delay_s", st.ready_delay_s, detail::kNonNegative);
  r.finish();
  if (st.pull_in_rate_hz > st.pull_out_rate_hz) {
    problems.add(path, "pull_in_rate_hz (" + format_number(st.pull_in_rate_hz) +
                           ") must not exceed pull_out_rate_hz (" + format_number(st.pull_out_rate_hz) + ")");
  }
}

}  // namespace

void load_drive(const Json& drive, std::string_view path, double cycle_time_s, DriveSettings& settings,
                Problems& problems) {
  ObjectReader r(drive, std::string(path), problems);
  if (!r.valid()) return;
  if (const Json* v = r.get("adapter")) {
    if (v->is_object()) {
      // The Fast DDS gateway (gateway_adapter.cpp): the drive model lives in the gateway, not here.
      settings.gateway.emplace();
      settings.adapter = "dds_gateway";
      load_gateway_adapter(*v, r.path_of("adapter"), *settings.gateway, problems);
    } else if (auto a = detail::read_string(*v, r.path_of("adapter"), problems)) {
      if (*a == "dds" || *a == "dds_gateway") {
        problems.add(r.path_of("adapter"),
                     "the gateway adapter is an object: {\"type\": \"dds_gateway\", \"domain\": 0, "
                     "\"device\": \"<name at the gateway>\"}");
      } else if (*a != "simulated" && *a != "analog" && *a != "stepper") {
        problems.add(
            r.path_of("adapter"),
            "'" + *a + "' is not an adapter ('simulated', 'analog', 'stepper', or a dds_gateway object)");
      } else {
        settings.adapter = *a;
        if (*a == "analog") settings.analog.emplace();
        if (*a == "stepper") settings.stepper.emplace();
      }
    }
  }
  // A drive telegram, or (an encoder-only device, e.g. for TO_ExternalEncoder) an encoder telegram, or both.
  if (const Json* v = r.get("encoder_telegram")) {
    if (auto t = detail::read_integer(*v, r.path_of("encoder_telegram"), 0, 65535, false, problems)) {
      if (*t != 0 && *t != 81 && *t != 83) {
        problems.add(r.path_of("encoder_telegram"),
                     std::to_string(*t) + " is not an encoder telegram (81, 83)");
      } else {
        settings.encoder_telegram = static_cast<std::uint16_t>(*t);
      }
    }
  }
  if (const Json* v = r.get("telegram", !r.has("encoder_telegram"))) {
    if (auto t = detail::read_integer(*v, r.path_of("telegram"), 0, 65535, false, problems)) {
      if (!telegrams::is_drive_telegram(static_cast<int>(*t))) {
        problems.add(r.path_of("telegram"),
                     std::to_string(*t) + " is not a drive telegram (1, 2, 3, 4, 5, 6, 102, 103, 105, 106)");
      } else {
        settings.telegram = static_cast<std::uint16_t>(*t);
      }
    }
  }
  // An encoder-only device measures a shaft that something else turns (docs/simulated-drive.md): its speed.
  if (const Json* v = r.get("external_speed")) {
    if (auto speed = detail::read_number(*v, r.path_of("external_speed"), problems)) {
      if (r.has("telegram")) {
        problems.add(r.path_of("external_speed"),
                     "only for an encoder-only device (no drive telegram): a drive turns its own shaft");
      } else {
        settings.external_speed = *speed;
      }
    }
  }
  if (const Json* v = r.get("supplementary_telegram")) {
    if (auto t = detail::read_integer(*v, r.path_of("supplementary_telegram"), 0, 65535, false, problems)) {
      if (*t != 0 && *t != 750) {
        problems.add(r.path_of("supplementary_telegram"), std::to_string(*t) + " is not 0 or 750");
      } else {
        settings.supplementary_telegram = static_cast<std::uint16_t>(*t);
      }
    }
  }

  if (settings.gateway) {
    detail::reject_simulated_drive_keys(drive, r, problems);
    r.finish();
    return;
  }
  auto& p = settings.parameters;
  p.servo_cycle_s = cycle_time_s;
  if (const Json* v = r.get("servo_cycle_s")) {
    if (auto d = detail::read_number(*v, r.path_of("servo_cycle_s"), problems); d && *d != cycle_time_s) {
      problems.add(r.path_of("servo_cycle_s"), format_number(*d) + " differs from cycle_time " +
                                                   format_number(cycle_time_s) +
                                                   " (the drive runs in the MC_Servo cycle; leave it out)");
    }
  }
  r.integer("substeps", p.substeps, 1, 1000);
  r.real("reference_speed_rpm", p.reference_speed_rpm, detail::kPositive);
  r.real("max_speed_rpm", p.max_speed_rpm, detail::kPositive);
  r.real("reference_torque_nm", p.reference_torque_nm, detail::kPositive);
  r.real("torque_limit_nm", p.torque_limit_nm, detail::kNonNegative);
  r.real("off1_ramp_down_time_s", p.off1_ramp_down_time_s, detail::kPositive);
  r.real("off3_ramp_down_time_s", p.off3_ramp_down_time_s, detail::kPositive);
  r.real("standstill_threshold_rpm", p.standstill_threshold_rpm, detail::kNonNegative);
  r.real("speed_deviation_tolerance_rpm", p.speed_deviation_tolerance_rpm, detail::kNonNegative);
  r.integer("sign_of_life_tolerance", p.sign_of_life_tolerance, 0, 65535, true);
  r.boolean("isochronous", p.isochronous);
  r.integer("setpoint_timeout_cycles", p.setpoint_timeout_cycles, 1, kUint32Max);
  if (const Json* v = r.get("communication_fault_reaction")) {
    if (auto c = detail::read_choice(*v, r.path_of("communication_fault_reaction"), {"OFF1", "OFF2", "OFF3"},
                                     problems)) {
      p.communication_fault_reaction = std::array{Reaction::kOff1, Reaction::kOff2, Reaction::kOff3}[*c];
    }
  }
  r.real("speed_loop_time_constant_s", p.speed_loop_time_constant_s, detail::kPositive);
  r.real("motor_inertia_kgm2", p.motor_inertia_kgm2, detail::kPositive);
  r.real("load_inertia_kgm2", p.load_inertia_kgm2, detail::kNonNegative);
  r.real("viscous_friction_nm_per_rad_s", p.viscous_friction_nm_per_rad_s, detail::kNonNegative);
  r.real("coulomb_friction_nm", p.coulomb_friction_nm, detail::kNonNegative);
  r.real("gear_motor_revolutions", p.gear_motor_revolutions, detail::kPositive);
  r.real("gear_load_revolutions", p.gear_load_revolutions, detail::kPositive);
  r.real("load_units_per_revolution", p.load_units_per_revolution, detail::kPositive);
  r.real("initial_load_position", p.initial_load_position);
  r.real("backlash", p.backlash, detail::kNonNegative);
  r.real("initial_backlash_offset", p.initial_backlash_offset);
  if (const Json* v = r.get("encoder1")) load_encoder(*v, r.path_of("encoder1"), p.encoder1, problems);
  if (const Json* v = r.get("encoder2")) load_encoder(*v, r.path_of("encoder2"), p.encoder2, problems);
  if (const Json* v = r.get("machine")) load_machine(*v, r.path_of("machine"), p.machine, problems);
  if (const Json* v = r.get("analog")) {
    if (!settings.analog) {
      problems.add(r.path_of("analog"), "only with \"adapter\": \"analog\"");
    } else {
      load_analog(*v, r.path_of("analog"), *settings.analog, problems);
    }
  }
  if (const Json* v = r.get("stepper")) {
    if (!settings.stepper) {
      problems.add(r.path_of("stepper"), "only with \"adapter\": \"stepper\"");
    } else {
      load_stepper(*v, r.path_of("stepper"), *settings.stepper, problems);
    }
  }
  // The analog and the stepper actor are telegram-3 drives to the TO (spec 01 §3.11, §3.12: the S7 puts them
  // behind the same interface), with the position on the card's counter; the analog actor may instead have a
  // separately connected 81/83 encoder, and then it is a telegram-2 drive (spec 01 §3.3 "1 + 81/83").
  if (settings.analog || settings.stepper) {
    const std::string actor = settings.analog ? "the analog actor" : "the stepper actor";
    const bool separate = settings.analog && settings.encoder_telegram != 0;
    if (separate && settings.telegram != 2) {
      problems.add(r.path_of("telegram"),
                   std::to_string(settings.telegram) +
                       ": with a separate encoder (encoder_telegram) the analog actor is a telegram-2 drive "
                       "(write 2; telegram 3 carries the counter as its encoder)");
    } else if (!separate && settings.telegram != 0 && settings.telegram != 3) {
      problems.add(r.path_of("telegram"),
                   std::to_string(settings.telegram) + ": " + actor +
                       " is a telegram-3 drive to the TO (write 3" +
                       (settings.analog ? ", or 2 with an encoder_telegram 81/83)" : ")"));
    }
    if (settings.supplementary_telegram != 0) {
      problems.add(r.path_of("supplementary_telegram"), actor + " has no telegram 750");
    }
    if (settings.stepper && settings.encoder_telegram != 0) {
      problems.add(r.path_of("encoder_telegram"), actor + " reads its position from the counter");
    }
  }
  r.finish();
}

}  // namespace tomc::scenario
