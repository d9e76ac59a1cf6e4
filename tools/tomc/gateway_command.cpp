// `tomc gateway --config FILE`: the DDS gateway contract served by a PROFINET IO controller for real drives
// (docs/profinet-gateway.md).
#include <unistd.h>

#include <iostream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>

#include "cli_error.hpp"
#include "commands.hpp"
#include "stop_signals.hpp"
#include "tomc/gateway/profinet_gateway.hpp"
#include "tomc/scenario/profinet_gateway_config.hpp"

namespace tomc::cli {
namespace {

constexpr std::string_view kGatewayUsage =
    "usage: tomc gateway --config FILE\n"
    "\n"
    "A PROFINET IO controller (RT_CLASS_1) for the devices of FILE, served to tomc over the DDS gateway\n"
    "contract (docs/gateway.md, docs/profinet-gateway.md), until SIGINT/SIGTERM. Needs CAP_NET_RAW for the\n"
    "raw socket on the file's profinet.interface.\n"
    "\n"
    "exit status: 0 stopped by a signal, 1 the host refused (interface, address, DDS),\n"
    "2 bad command line or configuration (one line per problem, each naming its JSON path).\n";

}  // namespace

int gateway_command(std::span<const std::string_view> args, std::ostream& out) {
  std::optional<std::string> file;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--help" || args[i] == "-h") {
      out << kGatewayUsage;
      return 0;
    }
    if (args[i] == "--config" && i + 1 < args.size()) {
      file = std::string(args[++i]);
    } else {
      throw UsageError("gateway: unknown argument '" + std::string(args[i]) + "' (try: tomc gateway --help)");
    }
  }
  if (!file) throw UsageError("gateway: missing --config FILE (try: tomc gateway --help)");
  scenario::ProfinetGatewayConfig config;
  scenario::Problems problems;
  scenario::load_profinet_gateway_config_file(*file, config, problems);
  if (!problems.empty()) {
    for (const auto& line : problems.lines())
      std::cerr << "tomc: " << *file << ": " << line << '\n';
    return kExitBadInput;
  }
  const sigset_t signals = block_stop_signals();
  try {
    profinet_gateway::ProfinetGateway gateway(config);
    out << "gateway: '" << config.gateway << "' serves " << config.devices.size() << " PROFINET device(s) on "
        << config.interface << " (send clock " << config.cycle_time() * 1000.0 << " ms) on DDS domain "
        << config.domain << ", pid " << ::getpid() << std::endl;
    const int signal_number = wait_for_stop_signal(signals);
    const auto c = gateway.counters();
    out << "gateway: stopped by signal " << signal_number << " after " << c.cycles << " cycles ("
        << c.overruns << " overruns), " << c.setpoints_applied << " setpoints applied, "
        << c.answers_published << " answers" << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "tomc: gateway: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace tomc::cli
