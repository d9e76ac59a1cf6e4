#pragma once
// Which network a DDS participant of the gateway link uses (docs/gateway.md §11 "The network"): the interface
// (by name or by one of its IPv4 addresses), the unicast addresses of the other side, and whether multicast
// discovery is allowed. The default is loopback: interface 127.0.0.1, peer 127.0.0.1, no multicast. Discovery
// is by unicast to the listed peers only; multicast is never used unless `multicast_discovery` asks for it.
//
// resolve_network() checks the settings against this host's interfaces, so a wrong or missing interface or
// address is a configuration error that names it, before any DDS entity exists. This header does not include
// Fast DDS.

#include <cstdint>
#include <string>
#include <vector>

namespace tomc::drives::dds {

struct NetworkSettings {
  // "" = loopback. Else an interface name ("eth1") or an IPv4 address of this host ("192.168.10.5").
  std::string interface;
  // IPv4 unicast addresses of the other side (the gateway's for a controller, the controllers' for a
  // gateway). Empty with the loopback interface = 127.0.0.1. A controller on another interface must list
  // the gateway; a gateway may leave it empty and then only answers controllers that contact it.
  std::vector<std::string> peers;
  // Also announce by multicast (SPDP to 239.255.0.1, port 7400 + 250 × domain) on the interface. Off unless
  // asked for: tomc never needs it.
  bool multicast_discovery = false;
};

// The settings checked against this host: the one address the transport is bound to and the peers.
struct ResolvedNetwork {
  std::string interface_name;  // e.g. "lo", "eth1"
  std::string address;         // IPv4 address of that interface, e.g. "127.0.0.1"
  std::vector<std::string> peers;
  bool multicast_discovery = false;
  bool loopback() const noexcept;  // address in 127/8
};

// The default: interface lo at 127.0.0.1, peer 127.0.0.1, no multicast (what resolve_network({}) gives).
ResolvedNetwork loopback_network();

// One problem of a NetworkSettings: which setting ("interface", "peers[1]", "peers") and what is wrong.
struct NetworkProblem {
  std::string setting;
  std::string message;
};

// Resolves `settings` on this host into `out`. Returns every problem; `out` is only valid when there is none.
// `require_peers`: an interface other than loopback needs at least one peer (a controller must know where the
// gateway is).
std::vector<NetworkProblem> resolve_network(const NetworkSettings& settings, bool require_peers,
                                            ResolvedNetwork& out);
// The same, throwing std::invalid_argument with every problem ("interface: 'eth7' is not ...").
ResolvedNetwork resolve_network_or_throw(const NetworkSettings& settings, bool require_peers);

// The UDP ports of the RTPS specification (DDSI-RTPS 2.x §9.6.1.1) with its default parameters
// PB = 7400, DG = 250, PG = 2, d0 = 0, d1 = 10, d2 = 1, d3 = 11: the ones a peer sends to.
struct RtpsPorts {
  std::uint32_t discovery_multicast;  // PB + DG × domain + d0
  std::uint32_t discovery_unicast;    // PB + DG × domain + d1 + PG × participant_id
  std::uint32_t user_multicast;       // PB + DG × domain + d2
  std::uint32_t user_unicast;         // PB + DG × domain + d3 + PG × participant_id
};
RtpsPorts rtps_ports(int domain, int participant_id) noexcept;
// Participant ids 0 .. kProbedParticipantIds-1 get discovery sent to each peer (Fast DDS's
// maxInitialPeersRange): up to this many participants per host and domain find each other.
inline constexpr int kProbedParticipantIds = 32;

}  // namespace tomc::drives::dds
