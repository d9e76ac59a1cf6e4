#pragma once
// The Fast DDS gateway adapter as a drive's `adapter` in a configuration file (docs/scenarios.md, "drive"):
//
//   "adapter": { "type": "dds_gateway", "domain": 42, "device": "axis1" }
//   "adapter": { "type": "dds_gateway", "domain": 42, "device": "axis1",
//                "interface": "eth1", "peers": ["192.168.10.20"] }        // a gateway on another host
//
// instead of the embedded simulated drive, and the links that build the adapters from such settings — the
// function an embedding program or `tomc demo --gateway` uses (docs/gateway.md "Using it").

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "tomc/drives/dds/network.hpp"
#include "tomc/drives/drive_adapter.hpp"
#include "tomc/telegrams/byte_order.hpp"

namespace tomc::drives::dds {
class GatewayLink;
}

namespace tomc::scenario {

class Problems;

struct GatewayAdapterSettings {
  int domain = 0;
  std::string partition;
  std::string device;  // the device's name at the gateway
  // "interface", "peers", "multicast_discovery": loopback unless given (docs/gateway.md §11).
  drives::dds::NetworkSettings network;
  telegrams::ByteOrder byte_order = telegrams::ByteOrder::kBig;
  std::uint32_t max_answer_age_cycles = 1;
  double connect_timeout_s = 5.0;  // how long to wait for the gateway before the first cycle
  double answer_timeout_s = 0.01;  // lock-step: how long to wait for each cycle's answers
};

// Reads the `adapter` object (its "type" is "dds_gateway"); every problem with its JSON path.
void load_gateway_adapter(const nlohmann::ordered_json& adapter, std::string_view path,
                          GatewayAdapterSettings& settings, Problems& problems);

// The gateway links of one program: one DDS participant per (domain, partition, network), shared by its
// devices.
class GatewayLinks {
 public:
  GatewayLinks();
  ~GatewayLinks();
  GatewayLinks(const GatewayLinks&) = delete;
  GatewayLinks& operator=(const GatewayLinks&) = delete;

  // The adapter for one device (set-up; add it to the runtime). Throws std::invalid_argument (bad settings,
  // duplicate device) or std::runtime_error (Fast DDS refused).
  std::unique_ptr<drives::DriveAdapter> make_drive(const GatewayAdapterSettings& settings,
                                                   const drives::DeviceConfig& device, double cycle_time_s);
  bool empty() const noexcept { return links_.empty(); }

  // Before the first cycle: waits for the gateways (at most the largest connect_timeout_s); one line per
  // device that is not answering, "<device>: <why>". Empty = every device answers.
  std::vector<std::string> connect();
  // Lock-step pacing between two cycles: waits until every link's devices answered the cycle just sent, at
  // most answer_timeout_s per link. A missing answer is not an error here: the TOs see it as a missed cycle.
  void wait_for_answers();

  const std::vector<std::shared_ptr<drives::dds::GatewayLink>>& links() const noexcept { return links_; }

 private:
  std::vector<std::shared_ptr<drives::dds::GatewayLink>> links_;
  std::vector<double> answer_timeouts_s_;
  double connect_timeout_s_ = 0.0;
};

}  // namespace tomc::scenario
