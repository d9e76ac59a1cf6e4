// `tomc gateway-sim`: simulated PROFIdrive drives behind the DDS gateway contract, as a separate process
// (docs/gateway.md "Gateway simulator"), and `--send` to inject a fault into a running one.
#include <unistd.h>

#include <charconv>
#include <iostream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cli_error.hpp"
#include "commands.hpp"
#include "stop_signals.hpp"
#include "tomc/gateway_sim/commander.hpp"
#include "tomc/gateway_sim/gateway_simulator.hpp"
#include "tomc/scenario/gateway_sim_config.hpp"

namespace tomc::cli {
namespace {

constexpr std::string_view kGatewaySimUsage =
    "usage: tomc gateway-sim --config FILE [--domain N] [--partition NAME] [--name GATEWAY]\n"
    "                        [--interface IF] [--peer ADDRESS]... [--drop-every K] [--delay-us D]\n"
    "       tomc gateway-sim --send COMMAND [--value N] [--device NAME] --domain N [--partition NAME]\n"
    "                        [--name GATEWAY] [--interface IF --peer ADDRESS]\n"
    "\n"
    "Serves the simulated drives of FILE (docs/gateway.md) over Fast DDS until SIGINT/SIGTERM, on loopback\n"
    "unless an interface is given. The options override the file: DDS domain and partition, the gateway's\n"
    "name, the interface (a name or an IPv4 address of this host) and the controllers' unicast addresses\n"
    "(--peer, repeatable; optional for the simulator, which answers every controller that contacts it; the\n"
    "simulator's address for --send), drop every K-th answer, publish every answer D microseconds late.\n"
    "\n"
    "--send injects a fault into a running simulator and waits until it reports it applied. COMMAND is\n"
    "drop-answers (--value: how many; 18446744073709551615 = until resume), delay-answers (--value: us),\n"
    "stop, resume, restart (--value: ms of silence), drive-fault (--device, --value: fault number, 0 "
    "clears),\n"
    "disconnect or connect (--device).\n"
    "\n"
    "exit status: 0 stopped by a signal (or command applied), 1 the command was not confirmed,\n"
    "2 bad command line or configuration (one line per problem, each naming its JSON path).\n";

struct Options {
  std::optional<std::string> config;
  std::optional<int> domain;
  std::optional<std::string> partition;
  std::optional<std::string> name;
  std::optional<std::string> interface;
  std::vector<std::string> peers;
  std::optional<std::uint32_t> drop_every;
  std::optional<std::uint32_t> delay_us;
  std::optional<gateway_sim::Command> send;
  std::uint64_t value = 0;
  std::string device;
  bool help = false;
};

template <typename T>
T parse_number(std::string_view option, std::string_view text, T minimum, T maximum) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < minimum || value > maximum) {
    throw UsageError("gateway-sim: " + std::string(option) + ": '" + std::string(text) +
                     "' is not an integer " + std::to_string(minimum) + ".." + std::to_string(maximum));
  }
  return value;
}

Options parse_options(std::span<const std::string_view> args) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view a = args[i];
    auto next = [&]() -> std::string_view {
      if (i + 1 >= args.size()) throw UsageError("gateway-sim: " + std::string(a) + " needs a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h") {
      o.help = true;
    } else if (a == "--config") {
      o.config = std::string(next());
    } else if (a == "--domain") {
      o.domain = parse_number<int>(a, next(), 0, 232);
    } else if (a == "--partition") {
      o.partition = std::string(next());
    } else if (a == "--name") {
      o.name = std::string(next());
    } else if (a == "--interface") {
      o.interface = std::string(next());
    } else if (a == "--peer") {
      o.peers.emplace_back(next());
    } else if (a == "--drop-every") {
      o.drop_every = parse_number<std::uint32_t>(a, next(), 0, 1'000'000);
    } else if (a == "--delay-us") {
      o.delay_us = parse_number<std::uint32_t>(a, next(), 0, 10'000'000);
    } else if (a == "--send") {
      const std::string_view c = next();
      o.send = gateway_sim::parse_command(c);
      if (!o.send) throw UsageError("gateway-sim: --send: unknown command '" + std::string(c) + "'");
    } else if (a == "--value") {
      o.value = parse_number<std::uint64_t>(a, next(), 0, UINT64_MAX);
    } else if (a == "--device") {
      o.device = std::string(next());
    } else {
      throw UsageError("gateway-sim: unknown argument '" + std::string(a) +
                       "' (try: tomc gateway-sim --help)");
    }
  }
  return o;
}

// The network options over `network` (the file's, or loopback): every problem names its option.
drives::dds::NetworkSettings network_of(const Options& o, drives::dds::NetworkSettings network,
                                        bool require_peers) {
  if (o.interface) network.interface = *o.interface;
  if (!o.peers.empty()) network.peers = o.peers;
  drives::dds::ResolvedNetwork resolved;
  const auto problems = drives::dds::resolve_network(network, require_peers, resolved);
  if (!problems.empty()) {
    const auto& p = problems.front();
    const std::string option = p.setting == "interface" ? "--interface" : "--peer";
    throw UsageError("gateway-sim: " + option + ": " + p.message);
  }
  return network;
}

int send(const Options& o, std::ostream& out) {
  if (!o.domain) throw UsageError("gateway-sim: --send needs --domain");
  if (o.config) throw UsageError("gateway-sim: --send talks to a running simulator; --config is not used");
  gateway_sim::GatewayCommander commander(*o.domain, o.partition.value_or(""), network_of(o, {}, true));
  const std::string gateway = o.name.value_or("");
  if (!commander.send(gateway, *o.send, o.value, o.device)) {
    std::cerr << "tomc: gateway-sim: no gateway simulator" << (gateway.empty() ? "" : " '" + gateway + "'")
              << " on domain " << *o.domain << " confirmed " << gateway_sim::to_string(*o.send) << '\n';
    return 1;
  }
  out << "gateway-sim: " << gateway_sim::to_string(*o.send) << " applied\n";
  return 0;
}

}  // namespace

int gateway_sim_command(std::span<const std::string_view> args, std::ostream& out) {
  const Options o = parse_options(args);
  if (o.help) {
    out << kGatewaySimUsage;
    return 0;
  }
  if (o.send) return send(o, out);
  if (!o.config) throw UsageError("gateway-sim: missing --config FILE (try: tomc gateway-sim --help)");

  scenario::GatewaySimConfig config;
  scenario::Problems problems;
  scenario::load_gateway_sim_config_file(*o.config, config, problems);
  if (!problems.empty()) {
    for (const auto& line : problems.lines())
      std::cerr << "tomc: " << *o.config << ": " << line << '\n';
    return kExitBadInput;
  }
  if (o.domain) config.domain = *o.domain;
  if (o.partition) config.partition = *o.partition;
  if (o.name) {
    if (o.name->empty() || o.name->size() > 63) throw UsageError("gateway-sim: --name: 1..63 characters");
    config.gateway = *o.name;
  }
  if (o.interface || !o.peers.empty()) config.network = network_of(o, config.network, false);
  if (o.drop_every) config.drop_every = *o.drop_every;
  if (o.delay_us) config.delay_us = *o.delay_us;

  const sigset_t signals = block_stop_signals();  // before any DDS thread exists (stop_signals.hpp)
  {
    gateway_sim::GatewaySimulator simulator(config);
    std::string names;
    for (const auto& d : config.devices)
      names += (names.empty() ? "" : ", ") + d.name;
    out << "gateway-sim: '" << config.gateway << "' serves " << names << " on DDS domain " << config.domain
        << (config.partition.empty() ? "" : " partition '" + config.partition + "'") << " via "
        << (config.network.interface.empty() ? std::string("loopback") : config.network.interface)
        << ", cycle " << config.cycle_time * 1000.0 << " ms, pid " << ::getpid() << std::endl;
    const int signal_number = wait_for_stop_signal(signals);
    const auto c = simulator.counters();
    out << "gateway-sim: stopped by signal " << signal_number << " after " << c.setpoints_applied
        << " setpoints applied, " << c.answers_published << " answers, " << c.setpoint_gaps
        << " setpoint gaps, " << c.setpoints_rejected << " rejected" << std::endl;
  }
  return 0;
}

}  // namespace tomc::cli
