#pragma once
// `tomc gateway` (docs/profinet-gateway.md): the gateway side of the DDS contract (docs/gateway.md) in front
// of a PROFINET IO controller. Each configured device is one AR with one PROFINET IO device; its telegram
// submodule's data are the contract device's drive telegram, passed through unchanged (G10).
//
// Threads: the cyclic thread (RealTimeRunner at send clock × reduction ratio) receives the input and alarm
// frames, answers the setpoint it applied one cycle earlier, applies the newest setpoint, sends the output
// frames and runs the data-hold watchdogs — nothing else: no DDS, no lock, no allocation. Fast DDS's listener
// thread checks each SetpointCycle (G1-G3, G9) and hands it over through a lock-free triple buffer; a sender
// thread writes the answers and the status; the start-up thread brings every device without an AR up
// (DCP, Connect, records, PrmEnd, ApplicationReady) and hands it to the cyclic thread.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tomc/scenario/profinet_gateway_config.hpp"

namespace tomc::profinet_gateway {

// The name of the gateway's cyclic thread (pthread_setname_np, at most 15 characters).
inline constexpr const char* kCyclicThreadName = "tomc-pn-cyclic";

struct GatewayDeviceStatus {
  std::string name;
  bool exchanging = false;        // the AR runs and the cyclic thread exchanges with the device
  std::uint32_t ars = 0;          // ARs established so far
  std::uint32_t alarms = 0;       // alarms received and acknowledged
  float reference_speed_rpm = 0;  // p2000 read at start-up (0: not checked)
  std::string detail;             // the last start-up problem or module difference; "" when none
  std::string last_alarm;         // "alarm 2 acknowledged: diagnosis, slot 1 subslot 2, USI 0x8000"; "" none
};

struct GatewayCounters {
  std::uint64_t setpoints_applied = 0;
  std::uint64_t setpoint_gaps = 0;
  std::uint64_t setpoints_rejected = 0;
  std::uint64_t answers_published = 0;
  std::uint64_t cycles = 0;    // of the cyclic thread
  std::uint64_t overruns = 0;  // cycles that ended after the next one was due
  // The cyclic thread's start latency (cycle start minus deadline, RealTimeRunner), µs: its wake-up latency,
  // or with "wake_margin_us" what the margin did not absorb.
  double wake_up_p99_us = 0.0;
  double wake_up_max_us = 0.0;
  double spin_mean_us = 0.0;       // with "wake_margin_us": CPU spun per cycle
  std::uint64_t late_wakeups = 0;  // with "wake_margin_us": cycles woken after their send time
};

class ProfinetGateway {
 public:
  // Opens the sockets on config.interface (CAP_NET_RAW), the DDS participant, and starts the threads.
  // std::runtime_error naming the setting when the host refuses (no such interface, address not on it, ...).
  explicit ProfinetGateway(const scenario::ProfinetGatewayConfig& config);
  ~ProfinetGateway();  // stops the cyclic thread, releases every AR, deletes the participant
  ProfinetGateway(const ProfinetGateway&) = delete;
  ProfinetGateway& operator=(const ProfinetGateway&) = delete;

  GatewayCounters counters() const;
  std::vector<GatewayDeviceStatus> devices() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tomc::profinet_gateway
