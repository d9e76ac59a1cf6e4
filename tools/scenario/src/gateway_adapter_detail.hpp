#pragma once
// Internal: the part of the dds_gateway adapter's loading that config.cpp's load_drive() calls.
#include "json_reader.hpp"
#include "tomc/drives/dds/network.hpp"

namespace tomc::scenario::detail {

// With the dds_gateway adapter: every key of `drive` besides adapter, telegram and supplementary_telegram is
// a simulated-drive parameter, which belongs to the gateway's configuration; each is reported.
void reject_simulated_drive_keys(const Json& drive, ObjectReader& reader, Problems& problems);

// The network keys of a dds_gateway adapter or a gateway simulator's file: "interface" (a name or an IPv4
// address of this host), "peers" (an array of IPv4 unicast addresses), "multicast_discovery" (false). Checks
// them against this host's interfaces (drives::dds::resolve_network); every problem names its JSON path.
// `require_peers`: a controller on an interface other than loopback must name the gateway's address.
void read_network(ObjectReader& reader, drives::dds::NetworkSettings& network, bool require_peers,
                  Problems& problems);

}  // namespace tomc::scenario::detail
