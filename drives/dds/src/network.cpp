// The gateway link's network settings, checked against this host's interfaces (network.hpp).
#include "tomc/drives/dds/network.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>

#include <algorithm>
#include <stdexcept>

namespace tomc::drives::dds {

namespace {

struct HostInterface {
  std::string name;
  std::vector<std::string> addresses;  // IPv4, dotted
  bool loopback = false;
  bool running = false;  // up, with carrier: Fast DDS ignores an interface that is not (see below)
};

std::vector<HostInterface> host_interfaces() {
  std::vector<HostInterface> out;
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) != 0) return out;
  for (ifaddrs* i = list; i != nullptr; i = i->ifa_next) {
    if (i->ifa_name == nullptr) continue;
    auto it =
        std::find_if(out.begin(), out.end(), [&](const HostInterface& h) { return h.name == i->ifa_name; });
    if (it == out.end()) {
      out.push_back(HostInterface{i->ifa_name,
                                  {},
                                  (i->ifa_flags & IFF_LOOPBACK) != 0,
                                  (i->ifa_flags & IFF_UP) != 0 && (i->ifa_flags & IFF_RUNNING) != 0});
      it = out.end() - 1;
    }
    if (i->ifa_addr != nullptr && i->ifa_addr->sa_family == AF_INET) {
      char text[INET_ADDRSTRLEN] = {};
      const auto* in = reinterpret_cast<const sockaddr_in*>(i->ifa_addr);
      if (::inet_ntop(AF_INET, &in->sin_addr, text, sizeof text) != nullptr) it->addresses.emplace_back(text);
    }
  }
  ::freeifaddrs(list);
  return out;
}

// The address in host byte order, if `text` is a dotted IPv4 address.
bool parse_ipv4(const std::string& text, std::uint32_t& address) {
  in_addr a{};
  if (::inet_pton(AF_INET, text.c_str(), &a) != 1) return false;
  address = ntohl(a.s_addr);
  return true;
}

std::string names_of(const std::vector<HostInterface>& interfaces) {
  std::string s;
  for (const auto& i : interfaces)
    s += (s.empty() ? "" : ", ") + i.name;
  return s.empty() ? "none" : s;
}

// Fast DDS 2.9 drops a whitelisted address whose interface is not up and running when the participant is
// created, and never looks again: the participant would never send or receive. Said here, at start-up.
std::string not_running(const std::string& name, const std::string& address) {
  return "interface '" + name + "' (" + address + ") is down or has no link (carrier); DDS cannot use it";
}

}  // namespace

bool ResolvedNetwork::loopback() const noexcept {
  return address.rfind("127.", 0) == 0;
}

ResolvedNetwork loopback_network() {
  return ResolvedNetwork{"lo", "127.0.0.1", {"127.0.0.1"}, false};
}

std::vector<NetworkProblem> resolve_network(const NetworkSettings& settings, bool require_peers,
                                            ResolvedNetwork& out) {
  std::vector<NetworkProblem> problems;
  out = ResolvedNetwork{};
  out.multicast_discovery = settings.multicast_discovery;
  const auto interfaces = host_interfaces();

  const std::string wanted = settings.interface.empty() ? std::string("127.0.0.1") : settings.interface;
  std::uint32_t numeric = 0;
  if (parse_ipv4(wanted, numeric)) {
    for (const auto& i : interfaces) {
      if (std::find(i.addresses.begin(), i.addresses.end(), wanted) != i.addresses.end()) {
        out.interface_name = i.name;
        out.address = wanted;
        if (!i.running) problems.push_back({"interface", not_running(i.name, wanted)});
      }
    }
    if (out.address.empty()) {
      problems.push_back({"interface", wanted + " is not an IPv4 address of an interface of this host"});
    }
  } else {
    const auto it = std::find_if(interfaces.begin(), interfaces.end(),
                                 [&](const HostInterface& h) { return h.name == wanted; });
    if (it == interfaces.end()) {
      problems.push_back({"interface", "'" + wanted +
                                           "' is neither an IPv4 address nor an interface of this " +
                                           "host (interfaces: " + names_of(interfaces) + ")"});
    } else if (it->addresses.empty()) {
      problems.push_back({"interface", "interface '" + wanted + "' has no IPv4 address"});
    } else if (!it->running) {
      problems.push_back({"interface", not_running(it->name, it->addresses.front())});
    } else {
      out.interface_name = it->name;
      out.address = it->addresses.front();
    }
  }

  const bool loopback = out.address.empty() ? settings.interface.empty() : out.loopback();
  for (std::size_t i = 0; i < settings.peers.size(); ++i) {
    const std::string setting = "peers[" + std::to_string(i) + "]";
    const std::string& peer = settings.peers[i];
    std::uint32_t a = 0;
    if (!parse_ipv4(peer, a)) {
      problems.push_back({setting, "'" + peer + "' is not an IPv4 address (a.b.c.d)"});
    } else if ((a >> 28) == 0xE) {
      problems.push_back({setting, peer + " is a multicast address; peers are unicast addresses"});
    } else if (a == 0 || a == 0xFFFFFFFFu) {
      problems.push_back({setting, peer + " is not a unicast address of a host"});
    } else if (loopback && (a >> 24) != 127) {
      problems.push_back(
          {setting, peer + " cannot be reached through the loopback interface (set \"interface\")"});
    } else if (!loopback && (a >> 24) == 127) {
      problems.push_back(
          {setting, peer + " is a loopback address, not reachable through interface '" + wanted + "'"});
    } else if (std::find(out.peers.begin(), out.peers.end(), peer) == out.peers.end()) {
      out.peers.push_back(peer);
    }
  }
  if (settings.peers.empty()) {
    if (loopback) {
      out.peers.emplace_back("127.0.0.1");
    } else if (require_peers && !settings.multicast_discovery) {
      problems.push_back({"peers", "no peer address: with interface '" + wanted +
                                       "' the gateway's unicast address(es) must be given"});
    }
  }
  if (!problems.empty()) out = ResolvedNetwork{};
  return problems;
}

ResolvedNetwork resolve_network_or_throw(const NetworkSettings& settings, bool require_peers) {
  ResolvedNetwork out;
  const auto problems = resolve_network(settings, require_peers, out);
  if (!problems.empty()) {
    std::string text;
    for (const auto& p : problems)
      text += (text.empty() ? "" : "; ") + p.setting + ": " + p.message;
    throw std::invalid_argument(text);
  }
  return out;
}

RtpsPorts rtps_ports(int domain, int participant_id) noexcept {
  const auto base = static_cast<std::uint32_t>(7400 + 250 * domain);
  const auto id = static_cast<std::uint32_t>(2 * participant_id);
  return RtpsPorts{base + 0, base + 10 + id, base + 1, base + 11 + id};
}

}  // namespace tomc::drives::dds
