// `tomc demo [--config FILE] [--port N] [--bind ADDR] [--token T | --generate-token] [--seconds S]`: a
// simulated machine run in real time with its diagnostics page (README's first command, via scripts/demo).
// The machine is a JSON file in the scenario format's `technology_objects` (docs/scenarios.md), plus the
// demo's program and the page's settings (docs/diagnostics.md "tomc demo"); without --config the built-in
// examples/demo_machine.json is used.
#include <signal.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli_error.hpp"
#include "commands.hpp"
#include "demo_faults.hpp"
#include "demo_program.hpp"
#include "free_runner.hpp"
#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/diagnostics/server.hpp"
#include "tomc/scenario/gateway_adapter.hpp"
#include "tomc/scenario/machine.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace tomc::cli {

namespace {

constexpr std::string_view kDemoUsage =
    "usage: tomc demo [--config FILE] [--port N] [--bind ADDRESS] [--allow-host NAME]...\n"
    "                 [--token TOKEN | --generate-token]\n"
    "                 [--seconds S] [--gateway DOMAIN [--gateway-partition P]\n"
    "                 [--gateway-interface IF --gateway-peer ADDRESS...]]\n"
    "                 [--free-running] [--inject-faults N]\n"
    "\n"
    "Runs a simulated machine in real time with a user program that moves its axes in a loop, and serves "
    "the\n"
    "diagnostics page (status, telegrams, alarms, axis control panel, traces) at the printed URL.\n"
    "\n"
    "  --config FILE      the machine: cycle_time, technology_objects as in tomc sim (docs/scenarios.md),\n"
    "                     optional program and diagnostics sections (docs/diagnostics.md); default: the\n"
    "                     built-in demo machine (examples/demo_machine.json)\n"
    "  --port N           TCP port, 0 = any free port (default 8080 or the config's)\n"
    "  --bind ADDRESS     listen address (default 127.0.0.1: this machine only); beyond loopback the token\n"
    "                     travels in clear: a trusted network or a TLS proxy only\n"
    "  --allow-host NAME  also answer requests for this Host (e.g. the machine's name or address when\n"
    "                     bound to 0.0.0.0); repeatable\n"
    "  --token TOKEN      allow control actions to a page that presents TOKEN (default: read-only)\n"
    "  --generate-token   make a random token and print it in the URL\n"
    "  --seconds S        stop after S seconds (default: run until Ctrl-C)\n"
    "  --gateway DOMAIN   every drive through the Fast DDS gateway on DOMAIN (0..232), each TO's device\n"
    "                     named like the TO (e.g. tomc gateway-sim; docs/gateway.md)\n"
    "  --gateway-partition P  the gateway's DDS partition (default: none)\n"
    "  --gateway-interface IF  the network interface (name or IPv4 address of this host) to the gateway\n"
    "                     (default: loopback)\n"
    "  --gateway-peer ADDRESS  the gateway's IPv4 unicast address (repeatable; needed with an interface)\n"
    "  --free-running     step the cycles back to back instead of in real time (the machine's clock is\n"
    "                     virtual: the soak's 10^8 cycles in hours, not days); not with a gateway drive\n"
    "  --inject-faults N  every N cycles a fault on the next simulated drive in turn (drive fault, encoder\n"
    "                     error, frozen sign-of-life; cleared after 20 cycles, acknowledged by the program)\n"
    "\n"
    "exit status: 0 stopped normally, 1 could not serve (e.g. port in use), 2 bad command line or config.\n";

struct DemoOptions {
  std::optional<std::string> config;
  std::optional<int> port;
  std::optional<std::string> bind;
  std::vector<std::string> allowed_hosts;
  std::optional<std::string> token;
  bool generate_token = false;
  std::optional<double> seconds;
  std::optional<int> gateway_domain;
  std::string gateway_partition;
  std::optional<std::string> gateway_interface;
  std::vector<std::string> gateway_peers;
  bool free_running = false;
  std::optional<std::uint64_t> fault_period_cycles;
  bool help = false;
};

std::string value_of(std::span<const std::string_view> args, std::size_t& i, std::string_view option) {
  const std::string_view a = args[i];
  const std::string prefix = std::string(option) + "=";
  if (a.starts_with(prefix)) return std::string(a.substr(prefix.size()));
  if (i + 1 >= args.size()) throw UsageError("demo: " + std::string(option) + " needs a value");
  return std::string(args[++i]);
}

template <typename T>
T number_of(const std::string& text, std::string_view option) {
  std::istringstream in(text);
  T value{};
  if (!(in >> value) || !in.eof())
    throw UsageError("demo: " + std::string(option) + ": '" + text + "' is not a number");
  return value;
}

bool is_option(std::string_view a, std::string_view option) {
  return a == option || (a.starts_with(option) && a.size() > option.size() && a[option.size()] == '=');
}

DemoOptions parse_demo_options(std::span<const std::string_view> args) {
  DemoOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view a = args[i];
    if (a == "--help" || a == "-h") {
      o.help = true;
    } else if (is_option(a, "--config")) {
      o.config = value_of(args, i, "--config");
    } else if (is_option(a, "--port")) {
      const int port = number_of<int>(value_of(args, i, "--port"), "--port");
      if (port < 0 || port > 65535) throw UsageError("demo: --port: 0 .. 65535");
      o.port = port;
    } else if (is_option(a, "--bind")) {
      o.bind = value_of(args, i, "--bind");
    } else if (is_option(a, "--allow-host")) {
      o.allowed_hosts.emplace_back(value_of(args, i, "--allow-host"));
      if (o.allowed_hosts.back().empty()) throw UsageError("demo: --allow-host: empty");
    } else if (is_option(a, "--token")) {
      o.token = value_of(args, i, "--token");
      if (o.token->empty()) throw UsageError("demo: --token: empty");
    } else if (a == "--generate-token") {
      o.generate_token = true;
    } else if (is_option(a, "--seconds")) {
      const double s = number_of<double>(value_of(args, i, "--seconds"), "--seconds");
      if (!(s > 0.0) || !std::isfinite(s)) throw UsageError("demo: --seconds: a positive number");
      o.seconds = s;
    } else if (a == "--free-running") {
      o.free_running = true;
    } else if (is_option(a, "--inject-faults")) {
      const auto n = number_of<std::int64_t>(value_of(args, i, "--inject-faults"), "--inject-faults");
      if (n < 2 * static_cast<std::int64_t>(DemoFaultInjector::kHoldCycles))
        throw UsageError("demo: --inject-faults: a period of at least 40 cycles");
      o.fault_period_cycles = static_cast<std::uint64_t>(n);
    } else if (is_option(a, "--gateway-interface")) {
      o.gateway_interface = value_of(args, i, "--gateway-interface");
    } else if (is_option(a, "--gateway-peer")) {
      o.gateway_peers.push_back(value_of(args, i, "--gateway-peer"));
    } else if (is_option(a, "--gateway-partition")) {
      o.gateway_partition = value_of(args, i, "--gateway-partition");
    } else if (is_option(a, "--gateway")) {
      const int domain = number_of<int>(value_of(args, i, "--gateway"), "--gateway");
      if (domain < 0 || domain > 232) throw UsageError("demo: --gateway: a DDS domain 0 .. 232");
      o.gateway_domain = domain;
    } else {
      throw UsageError("demo: unknown argument '" + std::string(a) + "' (try: tomc demo --help)");
    }
  }
  if (o.token && o.generate_token) throw UsageError("demo: --token and --generate-token exclude each other");
  if (!o.gateway_partition.empty() && !o.gateway_domain)
    throw UsageError("demo: --gateway-partition needs --gateway");
  if ((o.gateway_interface || !o.gateway_peers.empty()) && !o.gateway_domain)
    throw UsageError("demo: --gateway-interface and --gateway-peer need --gateway");
  if (o.free_running && o.gateway_domain)
    throw UsageError("demo: --free-running: a gateway drive runs in real time (not with --gateway)");
  return o;
}

std::string random_token() {
  std::random_device device;  // /dev/urandom on Linux
  std::string token;
  for (int i = 0; i < 4; ++i) {
    char part[9];
    std::snprintf(part, sizeof part, "%08x", static_cast<unsigned>(device()));
    token += part;
  }
  return token;
}

// ---- the configuration file ----

using Json = scenario::Json;

struct DemoConfig {
  double cycle_time_s = 0.001;
  std::vector<scenario::MachineObject> objects;
  std::vector<std::pair<std::string, DemoSequence>> sequences;       // speed axes, by object name
  std::vector<std::pair<std::string, DemoPositioning>> positioning;  // positioning axes, by object name
  std::vector<std::pair<std::string, DemoCamming>> camming;          // synchronous axes with a cam

  diagnostics::ServerOptions server;
  diagnostics::DiagnosticsConfig diagnostics;
};

std::string kind_of(const Json& v) {
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "a boolean";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  return "null";
}

void only_keys(const Json& object, const std::string& path, std::initializer_list<std::string_view> keys,
               scenario::Problems& problems) {
  for (const auto& item : object.items()) {
    if (item.key() == "comment") continue;
    if (std::find(keys.begin(), keys.end(), item.key()) == keys.end()) {
      std::string list;
      for (auto k : keys)
        list += (list.empty() ? "" : ", ") + std::string(k);
      problems.add(scenario::join_path(path, item.key()), "unknown key (known: " + list + ")");
    }
  }
}

std::optional<double> positive_number(const Json& v, const std::string& path, scenario::Problems& problems) {
  if (!v.is_number() || !(v.get<double>() > 0.0)) {
    problems.add(path, "expected a number > 0, got " +
                           (v.is_number() ? scenario::format_number(v.get<double>()) : kind_of(v)));
    return std::nullopt;
  }
  return v.get<double>();
}

// program.<speed axis>: {"velocities": [...], "dwell_s": s}
void load_speed_program(const Json& entry, const std::string& path, const std::string& name,
                        DemoConfig& config, scenario::Problems& problems) {
  only_keys(entry, path, {"velocities", "dwell_s"}, problems);
  DemoSequence sequence;
  if (const auto v = entry.find("velocities"); v != entry.end()) {
    if (!v->is_array() || v->empty() || v->size() > 100) {
      problems.add(scenario::join_path(path, "velocities"), "expected an array of 1 .. 100 numbers");
    } else {
      for (std::size_t i = 0; i < v->size(); ++i) {
        if (!(*v)[i].is_number()) {
          problems.add(scenario::join_path(path, "velocities") + "[" + std::to_string(i) + "]",
                       "expected a number");
        } else {
          sequence.velocities.push_back((*v)[i].get<double>());
        }
      }
    }
  }
  if (const auto d = entry.find("dwell_s"); d != entry.end()) {
    if (const auto s = positive_number(*d, scenario::join_path(path, "dwell_s"), problems))
      sequence.dwell_s = *s;
  }
  config.sequences.emplace_back(name, std::move(sequence));
}

// The default loop of a positioning axis without a "program" entry: homing by setting the position 0; a
// modulo axis turns in quarter turns, a linear axis moves between 10 % and 90 % of its software limits (0 and
// 100 of its length unit without them).
DemoPositioning default_positioning(const techobjects::PositioningAxis& axis) {
  const auto& d = axis.data();
  DemoPositioning plan;
  if (d.Modulo.Enable) {
    plan.distance = d.Modulo.Length / 4.0;
  } else if (d.PositionLimits_SW.Active) {
    const double span = d.PositionLimits_SW.MaxPosition - d.PositionLimits_SW.MinPosition;
    plan.positions = {d.PositionLimits_SW.MinPosition + 0.1 * span,
                      d.PositionLimits_SW.MinPosition + 0.9 * span};
  } else {
    plan.positions = {0.0, 100.0};
  }
  return plan;
}

// program.<synchronous axis>: {"cam": "<TO_Cam>", "application_mode": 0|1|2}: MC_CamIn to its first leading
// value instead of the positioning loop.
void load_camming_program(const Json& entry, const std::string& path, const std::string& name,
                          DemoConfig& config, scenario::Problems& problems) {
  only_keys(entry, path, {"cam", "application_mode"}, problems);
  DemoCamming plan;
  const Json& cam = entry.at("cam");
  const auto is_cam = [&](const scenario::MachineObject& o) {
    return cam.is_string() && o.name == cam.get<std::string>() && o.cam != nullptr;
  };
  if (std::none_of(config.objects.begin(), config.objects.end(), is_cam)) {
    problems.add(scenario::join_path(path, "cam"), "expected the name of a TO_Cam of this machine");
  } else {
    plan.cam = cam.get<std::string>();
  }
  if (const auto m = entry.find("application_mode"); m != entry.end()) {
    if (!m->is_number_integer() || m->get<std::int64_t>() < 0 || m->get<std::int64_t>() > 2) {
      problems.add(scenario::join_path(path, "application_mode"),
                   "expected 0 (not cyclic), 1 (cyclic) or 2 (cyclic appending)");
    } else {
      plan.application_mode = static_cast<std::int32_t>(m->get<std::int64_t>());
    }
  }
  config.camming.emplace_back(name, std::move(plan));
}

// program.<positioning axis>: {"home_mode": 0|3, "home_position": x, "positions": [...] | "distance": d,
// "velocity": v, "dwell_s": s}
void load_positioning_program(const Json& entry, const std::string& path, const std::string& name,
                              const techobjects::PositioningAxis* axis, DemoConfig& config,
                              scenario::Problems& problems) {
  only_keys(entry, path, {"home_mode", "home_position", "positions", "distance", "velocity", "dwell_s"},
            problems);
  DemoPositioning plan = axis != nullptr ? default_positioning(*axis) : DemoPositioning{};
  const auto number = [&](const char* key, double& out) {
    const auto v = entry.find(key);
    if (v == entry.end()) return false;
    if (!v->is_number() || !std::isfinite(v->get<double>())) {
      problems.add(scenario::join_path(path, key), "expected a number, got " + kind_of(*v));
      return false;
    }
    out = v->get<double>();
    return true;
  };
  if (const auto m = entry.find("home_mode"); m != entry.end()) {
    if (!m->is_number_integer() || (m->get<std::int64_t>() != 0 && m->get<std::int64_t>() != 3)) {
      problems.add(scenario::join_path(path, "home_mode"), "expected 0 (set position) or 3 (active homing)");
    } else {
      plan.home_mode = m->get<std::int32_t>();
    }
  }
  number("home_position", plan.home_position);
  const bool has_positions = entry.contains("positions");
  if (has_positions) {
    plan.positions.clear();
    plan.distance = 0.0;
    const Json& v = entry["positions"];
    if (!v.is_array() || v.empty() || v.size() > 100) {
      problems.add(scenario::join_path(path, "positions"), "expected an array of 1 .. 100 numbers");
    } else {
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (!v[i].is_number()) {
          problems.add(scenario::join_path(path, "positions") + "[" + std::to_string(i) + "]",
                       "expected a number");
        } else {
          plan.positions.push_back(v[i].get<double>());
        }
      }
    }
  }
  double distance = 0.0;
  if (number("distance", distance)) {
    if (has_positions) {
      problems.add(scenario::join_path(path, "distance"), "either positions or distance, not both");
    } else if (distance == 0.0) {
      problems.add(scenario::join_path(path, "distance"), "expected a distance other than 0");
    } else {
      plan.positions.clear();
      plan.distance = distance;
    }
  }
  if (const auto v = entry.find("velocity"); v != entry.end()) {
    if (const auto x = positive_number(*v, scenario::join_path(path, "velocity"), problems))
      plan.velocity = *x;
  }
  if (const auto d = entry.find("dwell_s"); d != entry.end()) {
    if (const auto x = positive_number(*d, scenario::join_path(path, "dwell_s"), problems)) plan.dwell_s = *x;
  }
  config.positioning.emplace_back(name, std::move(plan));
}

// Reads the file into a runtime: cycle_time and technology_objects as tomc sim reads them, then the optional
// "program" and "diagnostics" sections.
void load_demo_config(const Json& root, std::unique_ptr<techobjects::Runtime>& runtime, DemoConfig& config,
                      scenario::GatewayLinks& gateways, scenario::Problems& problems) {
  if (!root.is_object()) {
    problems.add("", "expected a JSON object, got " + kind_of(root));
    return;
  }
  only_keys(root, "", {"cycle_time", "technology_objects", "program", "diagnostics"}, problems);
  if (const auto it = root.find("cycle_time"); it != root.end()) {
    if (const auto t = positive_number(*it, "cycle_time", problems)) {
      if (*t < 1e-4 || *t > 0.1) {
        problems.add("cycle_time", scenario::format_number(*t) +
                                       " out of range 0.0001 .. 0.1 s (the demo runs in real time)");
      } else {
        config.cycle_time_s = *t;
      }
    }
  }
  runtime = std::make_unique<techobjects::Runtime>(techobjects::RuntimeConfig{config.cycle_time_s, 1, 1});
  const auto objects = root.find("technology_objects");
  if (objects == root.end() || !objects->is_array() || objects->empty()) {
    problems.add("technology_objects", "expected a non-empty array of technology objects");
  } else {
    for (std::size_t i = 0; i < objects->size(); ++i) {
      if (auto o = scenario::load_technology_object(
              (*objects)[i], "technology_objects[" + std::to_string(i) + "]", config.cycle_time_s, *runtime,
              config.objects, problems, "tomc demo", &gateways)) {
        config.objects.push_back(std::move(*o));
      }
    }
    // Hardware limit switches and homing inputs of the simulated machine, as in tomc sim.
    if (problems.empty()) scenario::wire_machine_inputs(*runtime, config.objects);
  }
  if (const auto program = root.find("program"); program != root.end()) {
    if (!program->is_object()) {
      problems.add("program", "expected an object '<axis>': {\"velocities\": [...], \"dwell_s\": s}");
    } else {
      for (const auto& [name, entry] : program->items()) {
        if (name == "comment") continue;
        const std::string path = scenario::join_path("program", name);
        const bool known = std::any_of(config.objects.begin(), config.objects.end(),
                                       [&](const scenario::MachineObject& o) { return o.name == name; });
        if (!known) {
          problems.add(path, "no technology object of that name");
          continue;
        }
        if (!entry.is_object()) {
          problems.add(path, "expected an object, got " + kind_of(entry));
          continue;
        }
        const auto object = std::find_if(config.objects.begin(), config.objects.end(),
                                         [&](const scenario::MachineObject& o) { return o.name == name; });
        // By kind: a definition with problems has no object, but its program is still checked.
        using Kind = scenario::TechnologyObjectKind;
        if (object->kind == Kind::kSpeedAxis) {
          load_speed_program(entry, path, name, config, problems);
        } else if (object->kind == Kind::kSynchronousAxis && entry.contains("cam")) {
          load_camming_program(entry, path, name, config, problems);
        } else if (object->kind == Kind::kPositioningAxis || object->kind == Kind::kSynchronousAxis) {
          load_positioning_program(entry, path, name, object->positioning_axis, config, problems);
        } else if (object->kind == Kind::kCam) {
          problems.add(path, "a cam has no program (it is read by its followers)");
        } else {
          problems.add(path, "an external encoder has no program (it is enabled and read)");
        }
      }
    }
  }
  if (const auto d = root.find("diagnostics"); d != root.end()) {
    if (!d->is_object()) {
      problems.add("diagnostics", "expected an object");
    } else {
      only_keys(*d, "diagnostics",
                {"bind", "allowed_hosts", "port", "token", "publish_period_cycles", "event_period_s",
                 "export_priority"},
                problems);
      if (const auto v = d->find("bind"); v != d->end()) {
        if (!v->is_string() || v->get<std::string>().empty()) {
          problems.add("diagnostics.bind", "expected an address such as \"127.0.0.1\"");
        } else {
          config.server.bind_address = v->get<std::string>();
        }
      }
      if (const auto v = d->find("allowed_hosts"); v != d->end()) {
        bool ok = v->is_array();
        for (std::size_t i = 0; ok && i < v->size(); ++i)
          ok = (*v)[i].is_string() && !(*v)[i].get<std::string>().empty();
        if (!ok) {
          problems.add("diagnostics.allowed_hosts", "expected an array of host names, e.g. [\"plc7.local\"]");
        } else {
          config.server.allowed_hosts = v->get<std::vector<std::string>>();
        }
      }
      if (const auto v = d->find("port"); v != d->end()) {
        if (!v->is_number_integer() || v->get<std::int64_t>() < 0 || v->get<std::int64_t>() > 65535) {
          problems.add("diagnostics.port", "expected an integer 0 .. 65535 (0: any free port)");
        } else {
          config.server.port = v->get<int>();
        }
      }
      if (const auto v = d->find("token"); v != d->end()) {
        if (!v->is_string() || v->get<std::string>().empty()) {
          problems.add("diagnostics.token", "expected a non-empty string");
        } else {
          config.server.token = v->get<std::string>();
        }
      }
      if (const auto v = d->find("publish_period_cycles"); v != d->end()) {
        if (!v->is_number_integer() || v->get<std::int64_t>() < 1 || v->get<std::int64_t>() > 10000) {
          problems.add("diagnostics.publish_period_cycles", "expected an integer 1 .. 10000");
        } else {
          config.diagnostics.publish_period_cycles = v->get<std::uint32_t>();
        }
      }
      if (const auto v = d->find("event_period_s"); v != d->end()) {
        if (!v->is_number() || v->get<double>() < 0.02 || v->get<double>() > 10.0) {
          problems.add("diagnostics.event_period_s", "expected a number 0.02 .. 10 (s)");
        } else {
          config.server.event_period = std::chrono::milliseconds(std::lround(v->get<double>() * 1000.0));
        }
      }
      if (const auto v = d->find("export_priority"); v != d->end()) {
        using Priority = diagnostics::http::ServerLimits::ExportPriority;
        if (v->is_string() && (*v == "idle" || *v == "normal")) {
          config.server.limits.export_priority = *v == "idle" ? Priority::kIdle : Priority::kNormal;
        } else {
          problems.add("diagnostics.export_priority", "expected \"idle\" (default) or \"normal\"");
        }
      }
    }
  }
}

// --gateway: every TO's drive becomes the device of the same name behind the gateway, with the telegrams the
// file gives (the drive model's parameters belong to the gateway's configuration, docs/gateway.md).
void route_drives_through_gateway(Json& root, const DemoOptions& o) {
  const int domain = *o.gateway_domain;
  const std::string& partition = o.gateway_partition;
  const auto objects = root.find("technology_objects");
  if (objects == root.end() || !objects->is_array()) return;  // reported by the loader
  for (auto& object : *objects) {
    if (!object.is_object() || !object.contains("drive") || !object["drive"].is_object()) continue;
    const Json& old = object["drive"];
    Json drive = Json::object();
    Json adapter = {{"type", "dds_gateway"}, {"domain", domain}, {"device", object.value("name", "")}};
    if (!partition.empty()) adapter["partition"] = partition;
    // Checked by the adapter loader like a file's: a wrong interface or peer is named there.
    if (o.gateway_interface) adapter["interface"] = *o.gateway_interface;
    if (!o.gateway_peers.empty()) adapter["peers"] = o.gateway_peers;
    drive["adapter"] = adapter;
    for (const char* key : {"telegram", "supplementary_telegram", "encoder_telegram"}) {
      if (old.contains(key)) drive[key] = old[key];
    }
    object["drive"] = drive;
  }
}

// The default sequence of an axis without a "program" entry: half and a quarter of its velocity limit
// forwards, a quarter backwards, stop.
DemoSequence default_sequence(const techobjects::SpeedAxis& axis) {
  const double v = axis.data().DynamicLimits.MaxVelocity;
  return DemoSequence{{0.5 * v, 0.25 * v, -0.25 * v, 0.0}, 3.0};
}

}  // namespace

int demo_command(std::span<const std::string_view> args, std::ostream& out) {
  const DemoOptions o = parse_demo_options(args);
  if (o.help) {
    out << kDemoUsage;
    return 0;
  }
  // The configuration: the user's file or the built-in demo machine.
  std::string text;
  std::string source = "built-in demo machine";
  if (o.config) {
    std::ifstream in(*o.config, std::ios::binary);
    if (!in) throw UsageError("demo: cannot read '" + *o.config + "': " + std::strerror(errno));
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
    source = *o.config;
  } else {
    text = std::string(demo_machine_json());
  }
  Json root = Json::parse(text, nullptr, false);
  if (root.is_discarded()) throw UsageError("demo: " + source + ": malformed JSON");
  if (o.gateway_domain) route_drives_through_gateway(root, o);
  DemoConfig config;
  std::unique_ptr<techobjects::Runtime> runtime;
  scenario::Problems problems;
  scenario::GatewayLinks gateways;  // outlives the runtime's drives that use it
  load_demo_config(root, runtime, config, gateways, problems);
  if (!problems.empty()) {
    for (const auto& line : problems.lines())
      std::cerr << "tomc: " << source << ": " << line << '\n';
    return kExitBadInput;
  }

  // The machine: every TO on the page with its panel, the demo program per TO, an "automatic" switch per
  // axis.
  diagnostics::Diagnostics diagnostics(config.diagnostics);
  std::vector<std::unique_ptr<DemoProgram>> programs;
  const auto camming_of = [&config](const std::string& name) -> const DemoCamming* {
    for (const auto& [axis, plan] : config.camming) {
      if (axis == name) return &plan;
    }
    return nullptr;
  };
  for (const scenario::MachineObject& object : config.objects) {
    if (object.speed_axis != nullptr) {
      diagnostics.add(*object.speed_axis);
      DemoSequence sequence = default_sequence(*object.speed_axis);
      for (const auto& [name, s] : config.sequences) {
        if (name != object.name) continue;
        if (!s.velocities.empty()) sequence.velocities = s.velocities;
        sequence.dwell_s = s.dwell_s;
      }
      programs.push_back(std::make_unique<DemoAxisProgram>(*object.speed_axis, std::move(sequence)));
    } else if (object.cam != nullptr) {
      diagnostics.add(*object.cam);  // the page's cam plot; read by its followers: no program
      continue;
    } else if (object.positioning_axis != nullptr && object.synchronous_axis != nullptr &&
               camming_of(object.name) != nullptr) {
      diagnostics.add(*object.synchronous_axis);
      techobjects::Cam* cam = nullptr;
      for (const scenario::MachineObject& o : config.objects) {
        if (o.name == camming_of(object.name)->cam) cam = o.cam;
      }
      programs.push_back(std::make_unique<DemoCammingProgram>(*object.synchronous_axis, *cam,
                                                              camming_of(object.name)->application_mode));
    } else if (object.positioning_axis != nullptr) {  // also a synchronous axis: its own view
      if (object.synchronous_axis != nullptr) {
        diagnostics.add(*object.synchronous_axis);
      } else {
        diagnostics.add(*object.positioning_axis);
      }
      DemoPositioning plan = default_positioning(*object.positioning_axis);
      for (const auto& [name, p] : config.positioning) {
        if (name == object.name) plan = p;
      }
      programs.push_back(std::make_unique<DemoPositioningProgram>(*object.positioning_axis, std::move(plan)));
    } else if (object.external_encoder != nullptr) {
      diagnostics.add(*object.external_encoder);
      programs.push_back(std::make_unique<DemoEncoderProgram>(*object.external_encoder));
    } else {
      continue;
    }
    if (auto* automatic = programs.back()->automatic()) {
      diagnostics.add_switch(object.name + ".automatic",
                             "the demo program runs " + object.name +
                                 " in its loop; switch off to release the axis for the control panel",
                             *automatic);
    }
  }
  // Axes on analog or stepper actors: the page shows the actor's terminals instead of telegram words.
  for (const scenario::MachineObject& object : config.objects) {
    if (object.analog_drive != nullptr)
      diagnostics.set_actor(object.name, diagnostics::ActorSource(object.analog_drive->actor()));
    if (object.stepper_drive != nullptr)
      diagnostics.set_actor(object.name, diagnostics::ActorSource(object.stepper_drive->actor()));
  }
  runtime->set_user_program([&programs](techobjects::Runtime& rt) {
    for (auto& p : programs)
      (*p)(rt.clock());
  });
  diagnostics.attach(*runtime);
  runtime->start();

  // Signals are taken synchronously by this thread: block them before any other thread starts.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  if (o.free_running && !gateways.empty()) {
    std::cerr << "tomc: demo: --free-running: " << source
              << " has a gateway drive, which runs in real time\n";
    return kExitBadInput;
  }
  std::vector<drives::SimulatedDrive*> simulated;
  for (const auto& object : config.objects) {
    if (object.drive != nullptr) simulated.push_back(object.drive);
  }
  DemoFaultInjector faults(
      o.fault_period_cycles ? std::move(simulated) : std::vector<drives::SimulatedDrive*>{},
      o.fault_period_cycles.value_or(0));
  // The cycle: the faults due before this step, then the step (one thread, so the drives need no lock);
  // without --inject-faults the real-time cycle is the step alone.
  std::uint64_t steps = 0;
  techobjects::RealTimeRunner::Cycle cycle = [&runtime] { runtime->step(); };
  if (o.fault_period_cycles) {
    cycle = [&runtime, &faults, &steps] {
      faults(steps++);
      runtime->step();
    };
  }
  techobjects::RealTimeRunner runner(
      techobjects::RealTimeRunnerConfig{std::chrono::nanoseconds(std::llround(config.cycle_time_s * 1e9)), 0,
                                        false},
      std::move(cycle));
  FreeRunner free_runner([&runtime, &faults](std::uint64_t cycle) {
    faults(cycle);
    runtime->step();
  });

  diagnostics::ServerOptions server_options = config.server;
  if (o.port) server_options.port = *o.port;
  if (o.bind) server_options.bind_address = *o.bind;
  server_options.allowed_hosts.insert(server_options.allowed_hosts.end(), o.allowed_hosts.begin(),
                                      o.allowed_hosts.end());
  if (o.token) server_options.token = *o.token;
  if (o.generate_token) server_options.token = random_token();
  server_options.title = "tomc demo";
  server_options.runner_statistics = [&] {
    return o.free_running ? free_runner.statistics() : runner.statistics();
  };
  diagnostics::Server server(diagnostics, server_options);
  try {
    server.start();
  } catch (const std::runtime_error& e) {
    std::cerr << "tomc: demo: " << e.what() << '\n';
    return 1;
  }
  if (!gateways.empty()) {
    for (const auto& warning : gateways.connect())
      std::cerr << "tomc: demo: warning: " << warning << '\n';
  }
  if (o.free_running)
    free_runner.start();
  else
    runner.start();

  out << "tomc demo: " << source << ", cycle " << config.cycle_time_s * 1000.0 << " ms"
      << (o.free_running ? " (free-running: virtual time)" : "") << ":";
  for (const auto& object : config.objects)
    out << ' ' << object.name;
  out << '\n';
  const std::string url = server.url();
  if (server_options.token.empty()) {
    out << "tomc demo: diagnostics page (read-only; --generate-token allows control) at " << url << '\n';
  } else if (o.generate_token) {
    out << "tomc demo: diagnostics page at " << url << "#token=" << server_options.token << '\n';
  } else {
    out << "tomc demo: diagnostics page at " << url << " (control actions need the token)\n";
  }
  out << "tomc demo: Ctrl-C stops" << std::endl;

  // Until Ctrl-C / SIGTERM, or the given number of seconds.
  const auto deadline = o.seconds
                            ? std::chrono::steady_clock::now() + std::chrono::duration<double>(*o.seconds)
                            : std::chrono::steady_clock::time_point::max();
  for (;;) {
    timespec wait{0, 200'000'000};
    if (sigtimedwait(&stop_signals, nullptr, &wait) > 0) break;
    if (std::chrono::steady_clock::now() >= deadline) break;
  }
  server.stop();
  runner.stop();
  free_runner.stop();
  const auto stats = o.free_running ? free_runner.statistics() : runner.statistics();
  out << "tomc demo: stopped after " << stats.cycles << " cycles (" << stats.overruns << " overruns)\n";
  return 0;
}

}  // namespace tomc::cli
