#pragma once
// Real drives behind a gateway that owns the PROFINET IO controller, reached over Fast DDS (docs/gateway.md).
//
//   auto link = GatewayLink::create({.domain = 42});
//   runtime.add_device(link->make_drive("axis1", device_config));   // one DdsGatewayDrive per device
//   for (const auto& r : link->connect(std::chrono::seconds(5))) ...  // before the first cycle
//   runtime.start(); ... runtime.step();                             // real time, or lock-step:
//   link->wait_for_answers(timeout);                                 //   between two steps
//
// One GatewayLink is one DDS participant for all devices of this controller on one domain (and partition);
// each cycle it sends one SetpointCycle sample with every device's setpoint frames and routes the gateway's
// ActualCycle answers to the devices. The cyclic thread never blocks on DDS: DdsGatewayDrive's read_actual()
// and write_setpoint() only touch lock-free buffers, a sender thread writes the sample, Fast DDS's listener
// thread routes the answers (exchange_core.hpp). This header does not include Fast DDS.

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tomc/drives/dds/exchange_core.hpp"
#include "tomc/drives/dds/network.hpp"
#include "tomc/drives/drive_adapter.hpp"

namespace tomc::drives::dds {

struct GatewayLinkConfig {
  int domain = 0;           // DDS domain id, 0..232; controller and gateway must use the same
  std::string partition;    // DDS partition, "" = default; controller and gateway must use the same
  NetworkSettings network;  // interface and the gateway's address(es); default loopback (network.hpp)
  std::string participant_name = "tomc controller";
  double cycle_time_s = 0.001;              // the servo cycle, announced to the gateway
  std::uint32_t max_answer_age_cycles = 1;  // ExchangeOptions::max_answer_age_cycles
};

// Why a device does or does not get answers, for the commissioning engineer (diagnose(), connect()).
enum class DeviceDiagnosis : std::uint8_t {
  kAnswering,              // fresh answers arrive
  kSignOfLifeNotCounting,  // fresh answers arrive, but the drive's sign-of-life (ZSW2) has never counted
  kNoGateway,              // no gateway has announced itself on the domain/partition
  kEndpointMismatch,  // a DDS participant was discovered, but its endpoints on the contract's topics do not
                      // match this controller's (type name, partition, data representation, QoS)
  kNotServed,         // gateways are there, none serves a device of this name
  kConfigMismatch,    // a gateway serves it with other telegrams, lengths or byte order
  kDisconnected,      // the gateway serves it but has no cyclic exchange with the device
  kOtherController,   // the gateway is serving another controller
  kSilent,  // the gateway serves it but its answers are missing or stale (stopped, restarting, late)
};
const char* to_string(DeviceDiagnosis diagnosis) noexcept;

struct DeviceReport {
  std::string device;
  DeviceDiagnosis diagnosis = DeviceDiagnosis::kSilent;
  std::string text;  // one line, e.g. "gateway 'gw1' does not serve 'axis9' (it serves: axis1, axis2)"
};

class DdsGatewayDrive;

class GatewayLink : public std::enable_shared_from_this<GatewayLink> {
 public:
  // Creates the participant and entities (unicast on the configured interface only, participant.hpp). Throws
  // std::invalid_argument for a bad configuration (naming a wrong or missing interface or peer address) and
  // std::runtime_error when Fast DDS refuses.
  static std::shared_ptr<GatewayLink> create(const GatewayLinkConfig& config);
  ~GatewayLink();
  GatewayLink(const GatewayLink&) = delete;
  GatewayLink& operator=(const GatewayLink&) = delete;

  // ---- set-up ----
  // The adapter of one device; add it to the runtime. Every adapter of a link must be added to the same
  // runtime (each cycle's sample is sent once every device has written). Throws std::invalid_argument (bad or
  // duplicate name, invalid configuration, after start()).
  std::unique_ptr<DdsGatewayDrive> make_drive(const std::string& device, const DeviceConfig& config);
  // Fixes the device table and starts the sender thread and the listeners. connect() calls it.
  void start();
  // Before the first cycle: starts the link and waits until every device has heard from a gateway, at most
  // `timeout`. Returns one report per device; all kAnswering means ready.
  std::vector<DeviceReport> connect(std::chrono::milliseconds timeout);

  // ---- between cycles (lock-step operation, tests; never from inside Runtime::step()) ----
  // Waits until every device has answered the setpoints of the last cycle sent, at most `timeout`.
  bool wait_for_answers(std::chrono::nanoseconds timeout);

  // ---- any thread ----
  std::vector<DeviceReport> diagnose() const;
  ExchangeStatistics statistics() const;
  const GatewayLinkConfig& config() const noexcept;
  std::uint64_t controller_id() const noexcept;
  ExchangeCore& core() noexcept;
  // Gateways whose status was received: name, incarnation, served device names (for diagnostics and tests).
  struct GatewayDevice {
    std::string name;
    std::string state;  // "connected", "faulted", "disconnected", "configuration mismatch"
    std::uint32_t fault = 0;
    std::string detail;
  };
  struct GatewayInfo {
    std::string name;
    std::uint64_t incarnation = 0;
    std::uint64_t controller = 0;
    std::uint64_t command_number = 0;
    std::vector<GatewayDevice> devices;
  };
  std::vector<GatewayInfo> gateways() const;

 private:
  struct Impl;
  explicit GatewayLink(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// The DriveAdapter of one device behind the gateway. read_actual() hands out the newest answer if it answers
// this controller's setpoint of the previous cycle (or at most max_answer_age_cycles older); otherwise it
// returns false and the TO's link supervision counts the cycle as missed. Never blocks, never allocates.
class DdsGatewayDrive final : public DriveAdapter {
 public:
  DdsGatewayDrive(std::shared_ptr<GatewayLink> link, std::size_t index);

  const DeviceConfig& config() const noexcept override { return config_; }
  bool read_actual(DeviceFrames& actual) noexcept override { return core_->read_actual(index_, actual); }
  void write_setpoint(const DeviceFrames& setpoint) noexcept override {
    core_->write_setpoint(index_, setpoint);
  }
  LinkHealth link_health() const noexcept override { return core_->link_health(index_); }

  const std::string& device() const { return core_->device_name(index_); }
  GatewayDeviceCounters counters() const noexcept { return core_->counters(index_); }
  GatewayLink& link() noexcept { return *link_; }

 private:
  std::shared_ptr<GatewayLink> link_;  // keeps the participant alive as long as the runtime holds the adapter
  ExchangeCore* core_;
  std::size_t index_;
  DeviceConfig config_;
};

}  // namespace tomc::drives::dds
