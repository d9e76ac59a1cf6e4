// `tomc gateway --config FILE`: the DDS gateway contract served by a PROFINET IO controller for real drives
// (docs/profinet-gateway.md).
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>

#include "cli_error.hpp"
#include "commands.hpp"
#include "stop_signals.hpp"
#include "tomc/gateway/commissioning.hpp"
#include "tomc/gateway/profinet_gateway.hpp"
#include "tomc/scenario/profinet_gateway_config.hpp"

namespace tomc::cli {
namespace {

constexpr std::string_view kGatewayUsage =
    "usage: tomc gateway --config FILE\n"
    "       tomc gateway --identify --interface IF [--wait-ms MS]\n"
    "       tomc gateway --set-name NAME --mac MAC --interface IF [--temporary]\n"
    "                    [--ip A.B.C.D [--netmask A.B.C.D] [--gateway A.B.C.D]]\n"
    "\n"
    "A PROFINET IO controller (RT_CLASS_1) for the devices of FILE, served to tomc over the DDS gateway\n"
    "contract (docs/gateway.md, docs/profinet-gateway.md), until SIGINT/SIGTERM. Needs CAP_NET_RAW for the\n"
    "raw socket on the file's profinet.interface.\n"
    "\n"
    "Commissioning (DCP, before any AR): --identify lists every station on IF that answers an Identify All\n"
    "within MS milliseconds (default 1000; name of station, MAC, IP suite, VendorID/DeviceID); --set-name\n"
    "gives the device with MAC (aa:bb:cc:dd:ee:ff) the name of station NAME, kept across power cycles\n"
    "unless --temporary; with --ip also its IP suite (netmask default 255.255.255.0, gateway default none).\n"
    "\n"
    "exit status: 0 stopped by a signal (--identify, --set-name: done), 1 the host refused (interface,\n"
    "address, DDS) or the device did not take the name, 2 bad command line or configuration (one line per\n"
    "problem, each naming its JSON path).\n";

// --identify and --set-name (decision I32).
// The IP suite of --ip/--netmask/--gateway (decision I37): nullopt without --ip.
struct IpSuiteText {
  std::optional<std::string> ip, netmask, gateway;
  bool any() const noexcept { return ip || netmask || gateway; }
};

std::optional<profinet::IpSuite> ip_suite(const IpSuiteText& text) {
  if (!text.ip) {
    if (text.any()) throw UsageError("gateway: --netmask and --gateway go with --ip");
    return std::nullopt;
  }
  const auto parse = [](const char* option, const std::string& value) {
    const auto address = profinet::parse_ipv4(value);
    if (!address)
      throw UsageError(std::string("gateway: ") + option + " '" + value +
                       "' is not an IPv4 address (a.b.c.d)");
    return *address;
  };
  profinet::IpSuite suite{parse("--ip", *text.ip), {255, 255, 255, 0}, {}};
  if (text.netmask) suite.netmask = parse("--netmask", *text.netmask);
  if (text.gateway) suite.gateway = parse("--gateway", *text.gateway);
  return suite;
}

std::string dotted(const profinet::Ipv4Address& a) {
  return std::to_string(a[0]) + "." + std::to_string(a[1]) + "." + std::to_string(a[2]) + "." +
         std::to_string(a[3]);
}

int commissioning_command(const std::string& interface, const std::optional<std::string>& name,
                          const std::optional<std::string>& mac_text, bool permanent,
                          std::optional<int> wait_ms_given, const IpSuiteText& ip_text, std::ostream& out) {
  if (interface.empty()) throw UsageError("gateway: missing --interface IF (try: tomc gateway --help)");
  std::optional<profinet::MacAddress> mac;
  if (name) {
    if (const std::string why = scenario::station_name_problem(*name); !why.empty())
      throw UsageError("gateway: --set-name " + why);
    if (!mac_text) throw UsageError("gateway: --set-name needs --mac MAC (try: tomc gateway --identify)");
    mac = profinet::parse_mac(*mac_text);
    if (!mac) throw UsageError("gateway: --mac '" + *mac_text + "' is not a MAC address (aa:bb:cc:dd:ee:ff)");
  } else if (mac_text || !permanent || ip_text.any()) {
    throw UsageError("gateway: --mac, --temporary and --ip/--netmask/--gateway go with --set-name");
  }
  const std::optional<profinet::IpSuite> ip = ip_suite(ip_text);
  if (name && wait_ms_given)
    throw UsageError("gateway: --wait-ms goes with --identify (--set-name waits 500 ms)");
  const int wait_ms = wait_ms_given.value_or(1000);
  if (wait_ms < 10 || wait_ms > 60'000) throw UsageError("gateway: --wait-ms out of range 10..60000");
  try {
    if (!name) {
      const auto stations = profinet_gateway::identify_all(interface, std::chrono::milliseconds(wait_ms));
      out << "gateway: " << stations.size() << " station(s) on " << interface << " answered DCP Identify All"
          << std::endl;
      for (const profinet::DcpStation& station : stations)
        out << "  " << profinet::describe(station) << '\n';
      return 0;
    }
    if (const std::string why = profinet_gateway::set_name_of_station(interface, *mac, *name, permanent,
                                                                      std::chrono::milliseconds(500), ip);
        !why.empty()) {
      std::cerr << "tomc: gateway: " << *mac_text << ": " << why << '\n';
      return 1;
    }
    out << "gateway: " << profinet::to_string(*mac) << " is now '" << *name << "'"
        << (ip ? " at " + dotted(ip->address) + "/" + dotted(ip->netmask) +
                     (ip->gateway != profinet::Ipv4Address{} ? " via " + dotted(ip->gateway) : "")
               : "")
        << (permanent ? "" : " (temporary)") << std::endl;
    return 0;
  } catch (const std::runtime_error& e) {  // the host refused the raw socket
    std::cerr << "tomc: gateway: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace

int gateway_command(std::span<const std::string_view> args, std::ostream& out) {
  std::optional<std::string> file;
  bool identify = false;
  std::optional<std::string> name;
  std::optional<std::string> mac;
  std::string interface;
  bool permanent = true;
  std::optional<int> wait_ms;
  IpSuiteText ip;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool has_value = i + 1 < args.size();
    if (args[i] == "--help" || args[i] == "-h") {
      out << kGatewayUsage;
      return 0;
    }
    if (args[i] == "--config" && has_value) {
      file = std::string(args[++i]);
    } else if (args[i] == "--identify") {
      identify = true;
    } else if (args[i] == "--set-name" && has_value) {
      name = std::string(args[++i]);
    } else if (args[i] == "--mac" && has_value) {
      mac = std::string(args[++i]);
    } else if (args[i] == "--interface" && has_value) {
      interface = std::string(args[++i]);
    } else if (args[i] == "--wait-ms" && has_value) {
      try {
        wait_ms = std::stoi(std::string(args[++i]));
      } catch (const std::exception&) {
        throw UsageError("gateway: --wait-ms '" + std::string(args[i]) + "' is not a number of milliseconds");
      }
    } else if (args[i] == "--ip" && has_value) {
      ip.ip = std::string(args[++i]);
    } else if (args[i] == "--netmask" && has_value) {
      ip.netmask = std::string(args[++i]);
    } else if (args[i] == "--gateway" && has_value) {
      ip.gateway = std::string(args[++i]);
    } else if (args[i] == "--temporary") {
      permanent = false;
    } else {
      throw UsageError("gateway: unknown argument '" + std::string(args[i]) + "' (try: tomc gateway --help)");
    }
  }
  if (static_cast<int>(file.has_value()) + static_cast<int>(identify) + static_cast<int>(name.has_value()) >
      1)
    throw UsageError("gateway: --config, --identify and --set-name exclude each other");
  if (identify || name) return commissioning_command(interface, name, mac, permanent, wait_ms, ip, out);
  if (!interface.empty() || mac || !permanent || wait_ms || ip.any())
    throw UsageError(
        "gateway: --interface, --mac, --temporary, --ip, --netmask, --gateway and --wait-ms go with "
        "--identify "
        "or --set-name");
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
