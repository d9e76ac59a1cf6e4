// The gateway link's network settings (issue 16, docs/gateway.md §11): interface by name or address, unicast
// peers, multicast only when asked for; a wrong or missing interface or address is a configuration error
// that names it — in the C++ API, in scenario files, in the gateway simulator's file and on its command line.
// Nothing here sends a packet: the QoS is built and checked, the files are loaded.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include "build_paths.hpp"
#include "tomc/drives/dds/gateway_link.hpp"
#include "tomc/drives/dds/network.hpp"
#include "tomc/drives/dds/participant.hpp"
#include "tomc/scenario/gateway_sim_config.hpp"
#include "tomc/scenario/scenario.hpp"

#ifndef TOMC_BINARY
#error "TOMC_BINARY must name build/bin/tomc"
#endif

namespace {

using namespace tomc::drives::dds;
using eprosima::fastdds::rtps::UDPv4TransportDescriptor;
using eprosima::fastrtps::rtps::IPLocator;

// An interface name no host has, and an address from TEST-NET-3 (RFC 5737) that is on no interface here.
constexpr const char* kNoSuchInterface = "tomcnosuch0";
constexpr const char* kForeignAddress = "203.0.113.77";

NetworkSettings settings(const std::string& interface, std::vector<std::string> peers = {}) {
  NetworkSettings s;
  s.interface = interface;
  s.peers = std::move(peers);
  return s;
}

std::string all_problems(const std::vector<NetworkProblem>& problems) {
  std::string s;
  for (const auto& p : problems)
    s += p.setting + ": " + p.message + "\n";
  return s;
}

// Decisions N1, G11 (127.0.0.1 by default); docs/gateway.md §11.
TEST(NetworkSettings, DefaultIsLoopbackWithPeer127001) {
  ResolvedNetwork r;
  ASSERT_EQ(all_problems(resolve_network({}, true, r)), "");
  EXPECT_EQ(r.address, "127.0.0.1");
  EXPECT_TRUE(r.loopback());
  EXPECT_EQ(r.peers, std::vector<std::string>{"127.0.0.1"});
  EXPECT_FALSE(r.multicast_discovery);
}

// Decision N1 (interface by name or IPv4 address of this host).
TEST(NetworkSettings, InterfaceByNameOrByAddress) {
  ResolvedNetwork by_name;
  ASSERT_EQ(all_problems(resolve_network(settings("lo"), true, by_name)), "");
  EXPECT_EQ(by_name.address, "127.0.0.1");
  ResolvedNetwork by_address;
  ASSERT_EQ(all_problems(resolve_network(settings("127.0.0.1", {"127.0.0.1"}), true, by_address)), "");
  EXPECT_EQ(by_address.interface_name, by_name.interface_name);
}

// Decision N2 (checked against the host's interfaces at configuration time, named).
TEST(NetworkSettings, WrongInterfaceOrAddressIsNamed) {
  ResolvedNetwork r;
  auto p = resolve_network(settings(kNoSuchInterface, {"10.1.2.3"}), true, r);
  ASSERT_EQ(p.size(), 1u) << all_problems(p);
  EXPECT_EQ(p[0].setting, "interface");
  EXPECT_NE(p[0].message.find(std::string("'") + kNoSuchInterface +
                              "' is neither an IPv4 address nor an interface"),
            std::string::npos)
      << p[0].message;
  EXPECT_TRUE(r.address.empty());

  p = resolve_network(settings(kForeignAddress, {"10.1.2.3"}), true, r);
  ASSERT_EQ(p.size(), 1u) << all_problems(p);
  EXPECT_EQ(p[0].setting, "interface");
  EXPECT_EQ(p[0].message,
            std::string(kForeignAddress) + " is not an IPv4 address of an interface of this host");
}

// Decision N1 (unicast peers); docs/gateway.md §11.
TEST(NetworkSettings, PeersAreUnicastIPv4AddressesReachableThroughTheInterface) {
  ResolvedNetwork r;
  const auto p = resolve_network(
      settings("", {"gateway.local", "239.255.0.1", "0.0.0.0", "10.0.0.2", "127.0.0.1"}), true, r);
  ASSERT_EQ(p.size(), 4u) << all_problems(p);
  EXPECT_EQ(p[0].setting, "peers[0]");
  EXPECT_EQ(p[0].message, "'gateway.local' is not an IPv4 address (a.b.c.d)");
  EXPECT_EQ(p[1].setting, "peers[1]");
  EXPECT_EQ(p[1].message, "239.255.0.1 is a multicast address; peers are unicast addresses");
  EXPECT_EQ(p[2].setting, "peers[2]");
  EXPECT_EQ(p[3].setting, "peers[3]");
  EXPECT_EQ(p[3].message, "10.0.0.2 cannot be reached through the loopback interface (set \"interface\")");
}

// A controller must know where its gateway is; a gateway may wait to be contacted.
// Decisions N1, N4 (a gateway may wait to be contacted; a controller may not).
TEST(NetworkSettings, ControllerOnARealInterfaceNeedsAPeer) {
  // Any non-loopback interface of this host with an IPv4 address will do; without one the rule cannot be
  // reached and the test says so.
  std::string address;
  for (const char* candidate : {"eth0", "ens3", "enp0s3"}) {
    ResolvedNetwork r;
    if (resolve_network(settings(candidate, {"10.9.9.9"}), true, r).empty() && !r.loopback()) {
      address = r.address;
      break;
    }
  }
  if (address.empty())
    GTEST_SKIP() << "no non-loopback interface with an IPv4 address found (eth0, ens3, enp0s3)";
  ResolvedNetwork r;
  auto p = resolve_network(settings(address), true, r);
  ASSERT_EQ(p.size(), 1u) << all_problems(p);
  EXPECT_EQ(p[0].setting, "peers");
  EXPECT_NE(p[0].message.find("the gateway's unicast address(es) must be given"), std::string::npos);
  EXPECT_EQ(all_problems(resolve_network(settings(address), false, r)), "");
  EXPECT_TRUE(r.peers.empty());
  p = resolve_network(settings(address, {"127.0.0.1"}), false, r);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].message.find("is a loopback address"), std::string::npos);
}

// docs/gateway.md §11 (the RTPS ports of a domain).
TEST(NetworkSettings, RtpsPortFormula) {
  const RtpsPorts p = rtps_ports(42, 3);
  EXPECT_EQ(p.discovery_multicast, 7400u + 250u * 42u);
  EXPECT_EQ(p.discovery_unicast, 7400u + 250u * 42u + 10u + 2u * 3u);
  EXPECT_EQ(p.user_multicast, 7400u + 250u * 42u + 1u);
  EXPECT_EQ(p.user_unicast, 7400u + 250u * 42u + 11u + 2u * 3u);
}

// The QoS of a participant on another interface: one UDPv4 transport on that address, the configured peers
// as initial peers, no multicast; the checker objects to anything else.
// Decision N5 (network_violations: the QoS checked against the settings).
TEST(NetworkSettings, QosOnAnInterfaceIsUnicastToTheConfiguredPeersOnly) {
  const ResolvedNetwork net{"veth-c", "10.216.0.1", {"10.216.0.2"}, false};
  const auto qos = participant_qos("test", 7, net);
  EXPECT_EQ(network_violations(qos, net), "");
  ASSERT_EQ(qos.transport().user_transports.size(), 1u);
  const auto* udp = dynamic_cast<const UDPv4TransportDescriptor*>(qos.transport().user_transports[0].get());
  ASSERT_NE(udp, nullptr);
  EXPECT_EQ(udp->interfaceWhiteList, std::vector<std::string>{"10.216.0.1"});
  EXPECT_EQ(udp->maxInitialPeersRange, static_cast<std::uint32_t>(kProbedParticipantIds));
  const auto& builtin = qos.wire_protocol().builtin;
  ASSERT_EQ(builtin.initialPeersList.size(), 1u);
  EXPECT_EQ(IPLocator::toIPv4string(*builtin.initialPeersList.begin()), "10.216.0.2");
  EXPECT_EQ(builtin.initialPeersList.begin()->port, 0u);  // every participant id's well-known port
  EXPECT_TRUE(builtin.metatrafficMulticastLocatorList.empty());
  EXPECT_TRUE(qos.wire_protocol().default_multicast_locator_list.empty());
  // Not loopback-only, and a QoS for another network is refused for this one.
  EXPECT_NE(loopback_violations(qos), "");
  EXPECT_NE(network_violations(loopback_participant_qos("x"), net), "");
  // A peer nobody configured is refused.
  auto widened = qos;
  eprosima::fastrtps::rtps::Locator_t other;
  IPLocator::createLocator(LOCATOR_KIND_UDPv4, "10.216.0.9", 0, other);
  widened.wire_protocol().builtin.initialPeersList.push_back(other);
  EXPECT_NE(network_violations(widened, net), "");
}

// Decisions N1, N5 (multicast only when asked for).
TEST(NetworkSettings, MulticastDiscoveryOnlyWhenAskedFor) {
  ResolvedNetwork net{"veth-c", "10.216.0.1", {"10.216.0.2"}, false};
  const auto plain = participant_qos("test", 7, net);
  net.multicast_discovery = true;
  const auto qos = participant_qos("test", 7, net);
  EXPECT_EQ(network_violations(qos, net), "");
  const auto& builtin = qos.wire_protocol().builtin;
  ASSERT_EQ(builtin.metatrafficMulticastLocatorList.size(), 1u);
  const auto& group = *builtin.metatrafficMulticastLocatorList.begin();
  EXPECT_EQ(IPLocator::toIPv4string(group), "239.255.0.1");
  EXPECT_EQ(group.port, rtps_ports(7, 0).discovery_multicast);
  // The multicast QoS fails the check of a network that did not ask for it.
  net.multicast_discovery = false;
  EXPECT_NE(network_violations(qos, net), "");
  EXPECT_EQ(network_violations(plain, net), "");
}

// Decision N2.
TEST(NetworkSettings, GatewayLinkRefusesAWrongInterfaceNamingIt) {
  GatewayLinkConfig config;
  config.domain = 160;
  config.network.interface = kNoSuchInterface;
  config.network.peers = {"10.1.2.3"};
  try {
    GatewayLink::create(config);
    FAIL() << "created a link on a missing interface";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(std::string("gateway link: interface: '") + kNoSuchInterface + "'"),
              std::string::npos)
        << e.what();
  }
}

std::string problems_of(const std::string& adapter_keys) {
  const auto result = tomc::scenario::Scenario::load_text(
      R"({ "cycle_time": 0.001, "cycles": 10, "technology_objects": [ { "name": "A", "type": "TO_SpeedAxis",
        "drive": { "telegram": 2, "adapter": { "type": "dds_gateway", "domain": 160, "device": "a", )" +
          adapter_keys + R"( } } } ] })",
      "s.json");
  std::string all;
  for (const auto& line : result.problems)
    all += line + "\n";
  return all;
}

// Decision N2; docs/scenarios.md "`drive`: adapter, telegram and the simulated machine".
TEST(NetworkSettings, ScenarioAdapterNetworkProblemsNameTheirPaths) {
  const std::string prefix = "technology_objects[0].drive.adapter.";
  EXPECT_EQ(problems_of(R"("interface": "lo", "peers": ["127.0.0.1"])"), "");
  std::string all =
      problems_of(std::string(R"("interface": ")") + kNoSuchInterface + R"(", "peers": ["10.0.0.2"])");
  EXPECT_NE(all.find(prefix + "interface: '" + kNoSuchInterface + "' is neither"), std::string::npos) << all;
  all = problems_of(R"("peers": ["10.0.0", 5], "multicast_discovery": "yes")");
  EXPECT_NE(all.find(prefix + "peers[1]: expected a string"), std::string::npos) << all;
  EXPECT_NE(all.find(prefix + "multicast_discovery:"), std::string::npos) << all;
  all = problems_of(R"("peers": ["10.0.0", "224.0.0.1"])");
  EXPECT_NE(all.find(prefix + "peers[0]: '10.0.0' is not an IPv4 address (a.b.c.d)"), std::string::npos)
      << all;
  EXPECT_NE(all.find(prefix + "peers[1]: 224.0.0.1 is a multicast address"), std::string::npos) << all;
  all = problems_of(std::string(R"("interface": ")") + kForeignAddress + R"(")");
  EXPECT_NE(all.find(prefix + "interface: " + kForeignAddress +
                     " is not an IPv4 address of an interface of this host"),
            std::string::npos)
      << all;
  all = problems_of(R"("peers": "10.0.0.2")");
  EXPECT_NE(all.find(prefix + "peers: expected an array of IPv4 addresses, got a string"), std::string::npos)
      << all;
}

// Decision N2; docs/gateway.md §9 (the gateway simulator's file).
TEST(NetworkSettings, GatewaySimFileNetworkProblemsNameTheirPaths) {
  tomc::scenario::GatewaySimConfig config;
  tomc::scenario::Problems problems;
  tomc::scenario::load_gateway_sim_config(
      tomc::scenario::Json::parse(
          std::string(R"({ "gateway": "gw", "domain": 1, "interface": ")") + kNoSuchInterface +
          R"(", "peers": ["x"], "devices": [ { "name": "a", "drive": { "telegram": 2 } } ] })"),
      config, problems);
  std::string all;
  for (const auto& line : problems.lines())
    all += line + "\n";
  EXPECT_NE(all.find(std::string("interface: '") + kNoSuchInterface + "' is neither"), std::string::npos)
      << all;
  EXPECT_NE(all.find("peers[0]: 'x' is not an IPv4 address"), std::string::npos) << all;

  // Loopback by default, by name, and no peers needed for the gateway.
  tomc::scenario::GatewaySimConfig ok;
  tomc::scenario::Problems none;
  tomc::scenario::load_gateway_sim_config(
      tomc::scenario::Json::parse(
          R"({ "gateway": "gw", "domain": 1, "interface": "lo", "devices": [ { "name": "a", "drive": { "telegram": 2 } } ] })"),
      ok, none);
  EXPECT_TRUE(none.empty()) << none.lines().front();
  EXPECT_EQ(ok.network.interface, "lo");
}

// A number beyond a double is nlohmann's out_of_range.406, not a parse_error: the gateway-sim and PROFINET
// gateway files (one reader) report it as malformed JSON instead of ending the program (reliability.md §2).
TEST(NetworkSettings, GatewaySimFileWithANumberBeyondADoubleIsMalformed) {
  const auto file =
      std::filesystem::temp_directory_path() / ("tomc-overflow-" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << R"({ "gateway": "gw", "domain": 7777e5777755555555555555555555552777 })";
  tomc::scenario::GatewaySimConfig config;
  tomc::scenario::Problems problems;
  tomc::scenario::load_gateway_sim_config_file(file, config, problems);
  std::filesystem::remove(file);
  ASSERT_EQ(problems.lines().size(), 1u);
  EXPECT_NE(problems.lines().front().find("malformed JSON: number overflow"), std::string::npos)
      << problems.lines().front();
}

int run_tomc(const std::string& arguments, std::string& err) {
  const auto dir = std::filesystem::temp_directory_path() / ("tomc-net-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto err_file = dir / "err.txt";
  const int raw = std::system(
      (std::string(TOMC_BINARY) + " " + arguments + " >/dev/null 2>" + err_file.string()).c_str());
  std::ifstream in(err_file);
  err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  std::filesystem::remove_all(dir);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// The command lines refuse a wrong interface or peer before any DDS traffic, naming the option.
// Decision N2; docs/gateway.md §10 (using it: the command lines).
TEST(NetworkSettings, CommandLinesNameAWrongInterfaceOrPeer) {
  const auto dir = std::filesystem::temp_directory_path() / ("tomc-netcli-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto config = dir / "gw.json";
  std::ofstream(config)
      << R"({ "gateway": "gw", "domain": 161, "devices": [ { "name": "a", "drive": { "telegram": 2 } } ] })";
  std::string err;
  EXPECT_EQ(run_tomc("gateway-sim --config " + config.string() + " --interface " + kNoSuchInterface, err), 2);
  EXPECT_NE(err.find(std::string("gateway-sim: --interface: '") + kNoSuchInterface + "' is neither"),
            std::string::npos)
      << err;
  EXPECT_EQ(run_tomc("gateway-sim --config " + config.string() + " --peer 239.1.2.3", err), 2);
  EXPECT_NE(err.find("gateway-sim: --peer: 239.1.2.3 is a multicast address"), std::string::npos) << err;
  EXPECT_EQ(run_tomc("gateway-sim --send stop --domain 161 --interface lo --peer 10.1.1.1", err), 2);
  EXPECT_NE(err.find("--peer: 10.1.1.1 cannot be reached through the loopback interface"), std::string::npos)
      << err;
  EXPECT_EQ(run_tomc("demo --gateway-interface lo", err), 2);
  EXPECT_NE(err.find("--gateway-interface and --gateway-peer need --gateway"), std::string::npos) << err;
  EXPECT_EQ(run_tomc(std::string("demo --seconds 0.1 --port 0 --gateway 161 --gateway-interface ") +
                         kNoSuchInterface + " --gateway-peer 10.1.1.1",
                     err),
            2);
  EXPECT_NE(err.find(std::string("drive.adapter.interface: '") + kNoSuchInterface + "' is neither"),
            std::string::npos)
      << err;
  std::filesystem::remove_all(dir);
}

}  // namespace
