#pragma once
// Internal: the part of the dds_gateway adapter's loading that config.cpp's load_drive() calls.
#include <filesystem>
#include <string>
#include <vector>

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

// The keys every gateway's file has (`tomc gateway-sim`, `tomc gateway`): "gateway" (its name), "domain",
// "partition", the network keys above (controllers optional), "watchdog" (s).
void read_gateway_side(ObjectReader& root, std::string& gateway, int& domain, std::string& partition,
                       drives::dds::NetworkSettings& network, double& watchdog, Problems& problems);
// "devices": a non-empty array of at most the contract's 128 devices; false (with the problem) otherwise.
bool check_gateway_devices(const Json& devices, Problems& problems);
// A gateway device's "name" (1..63 characters, not one of `taken`) and "byte_order".
void read_gateway_device(ObjectReader& r, const std::vector<std::string>& taken, std::string& name,
                         telegrams::ByteOrder& byte_order, Problems& problems);
// Reads and parses a JSON file; false with the problem ("cannot read", malformed JSON) named by the file.
bool read_json_file(const std::filesystem::path& file, Json& document, Problems& problems);

}  // namespace tomc::scenario::detail
