#pragma once
// The gateway simulator behind `tomc gateway-sim` (docs/gateway.md "Gateway simulator"): simulated PROFIdrive
// drives — the same model as the embedded default — served over the DDS contract exactly as a real gateway
// would serve real drives, with fault injection (drop, delay, stop, restart, drive faults, disconnects) from
// the configuration, the command line or the command topic.
//
// Clocking: the drives are stepped once per setpoint sample of the controller being served, like drives in
// isochronous mode follow the controller's clock, so a controller in lock-step sees exactly what the embedded
// simulated drive gives. When no setpoint arrives for `watchdog`, the gateway's own clock steps them each
// cycle_time without setpoints: they run into their setpoint timeout, as real drives whose controller died.

#include <cstdint>
#include <memory>

#include "tomc/scenario/gateway_sim_config.hpp"

namespace tomc::gateway_sim {

struct SimulatorCounters {
  std::uint64_t incarnation = 0;
  std::uint64_t controller = 0;  // the controller being served, 0 = none
  std::uint64_t setpoints_applied = 0;
  std::uint64_t setpoint_gaps = 0;
  std::uint64_t setpoints_rejected = 0;
  std::uint64_t answers_published = 0;
  std::uint64_t answers_dropped = 0;
  std::uint64_t idle_steps = 0;  // steps of the gateway's own clock (no controller)
  std::uint64_t commands = 0;
};

class GatewaySimulator {
 public:
  // Creates the drives and the DDS entities (loopback-only) and starts serving. Throws std::runtime_error
  // when Fast DDS refuses, std::invalid_argument for an unusable configuration.
  explicit GatewaySimulator(const scenario::GatewaySimConfig& config);
  ~GatewaySimulator();  // stops the threads and deletes the participant
  GatewaySimulator(const GatewaySimulator&) = delete;
  GatewaySimulator& operator=(const GatewaySimulator&) = delete;

  SimulatorCounters counters() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tomc::gateway_sim
