#pragma once
// The configuration file of the gateway simulator, `tomc gateway-sim --config FILE` (docs/gateway.md
// "Gateway simulator"). Each device is a simulated PROFIdrive drive described by the same `drive` object as
// in scenario files, so a scenario's drive moves into the gateway unchanged:
//
//   { "gateway": "gw1", "domain": 42, "cycle_time": 0.001,
//     "devices": [ { "name": "axis1", "drive": { "telegram": 3 } } ] }

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tomc/drives/dds/network.hpp"
#include "tomc/scenario/config.hpp"

namespace tomc::scenario {

struct GatewaySimDevice {
  std::string name;  // the device name controllers address
  telegrams::ByteOrder byte_order = telegrams::ByteOrder::kBig;
  DriveSettings drive;
  drives::DeviceConfig device_config() const;  // telegrams and byte order
};

struct GatewaySimConfig {
  std::string gateway = "gateway";
  int domain = 0;
  std::string partition;
  // "interface", "peers" (the controllers' addresses, optional), "multicast_discovery": loopback by default.
  drives::dds::NetworkSettings network;
  double cycle_time = 0.001;  // the gateway's own clock (its PROFINET send clock)
  // A controller silent this long is gone: the gateway's clock drives the drives without setpoints (they then
  // run into their setpoint timeout) and another controller may take over.
  double watchdog = 0.05;
  std::vector<GatewaySimDevice> devices;
  // Fault injection from the start (also on the command line).
  std::uint32_t drop_every = 0;  // drop every n-th answer; 0 = none
  std::uint32_t delay_us = 0;    // publish every answer this late
};

// Every problem with its JSON path, as the scenario loader does.
void load_gateway_sim_config(const Json& document, GatewaySimConfig& config, Problems& problems);
// Reads and parses the file; problems include "cannot read" and malformed JSON.
void load_gateway_sim_config_file(const std::filesystem::path& file, GatewaySimConfig& config,
                                  Problems& problems);

}  // namespace tomc::scenario
