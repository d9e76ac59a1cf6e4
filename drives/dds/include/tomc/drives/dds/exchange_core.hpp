#pragma once
// The gateway adapter without Fast DDS: the device table, the hand-over between the three threads involved,
// and the controller's rules of the contract (docs/gateway.md "What the controller does").
//
//   cyclic thread    read_actual() / write_setpoint() per device, once per servo cycle: no lock, no
//                    allocation, no waiting. The last device's write_setpoint() publishes the cycle's
//                    setpoint frames (a triple buffer) and wakes the sender thread (a futex wake, never a
//                    wait).
//   sender thread    take_setpoints(): newest setpoint frames -> the DDS sample it then writes.
//   listener thread  route(): a received ActualCycle -> per device, a triple buffer of the newest answer.
//
// GatewayLink adds the DDS entities and the sender thread; tests drive this class directly.

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/drives/dds/latest_value.hpp"
#include "tomc/drives/drive_adapter.hpp"
#include "tomc_gateway.h"

namespace tomc::drives::dds {

struct ExchangeOptions {
  std::uint64_t controller = 1;             // id of this controller run, non-zero (GatewayLink draws it)
  std::uint32_t cycle_time_ns = 1'000'000;  // announced in every SetpointCycle
  // An answer counts as fresh in cycle c when it answers the setpoint of cycle c-1-k with k <= this. 0 = only
  // the previous cycle's (lock-step); 1 (default) also tolerates an answer one cycle late on a real-time
  // link.
  std::uint32_t max_answer_age_cycles = 1;
};

// What the adapter counts for one device beyond LinkHealth (any thread may read it).
struct GatewayDeviceCounters {
  std::uint64_t answers = 0;   // answers routed to the device
  std::uint64_t stale = 0;     // answers taken in a cycle but too old, or for another or no controller
  std::uint64_t rejected = 0;  // answers whose telegrams, lengths or byte order differ from the configuration
  std::uint64_t restarts = 0;  // gateway restarts (a new ActualCycle.incarnation) seen by the cyclic side
  // Answers to this controller's setpoints whose drive telegram carries ZSW2, and how often the drive's
  // sign-of-life in it (bits 12..15, spec 06 §5) changed between two of them: a drive in isochronous mode
  // counts it every cycle; one that never changes is flagged by GatewayLink::diagnose().
  std::uint64_t sign_of_life_answers = 0;
  std::uint64_t sign_of_life_changes = 0;
  // How often this controller's master sign-of-life (STW2 bits 12..15) changed between two cycles sent: 0
  // when the controller does not run the device isochronously, and then the drive need not count either.
  std::uint64_t master_sign_of_life_changes = 0;
};

struct ExchangeStatistics {
  std::uint64_t cycles_sent = 0;
  std::uint64_t cycles_answered = 0;    // newest cycle every device has answered, + 1 (0 = none)
  std::uint64_t samples_received = 0;   // ActualCycle samples routed
  std::uint64_t samples_rejected = 0;   // wrong contract version, too many devices, duplicate or old sequence
  std::uint64_t answers_lost = 0;       // gaps in a gateway's ActualCycle.sequence
  std::uint64_t foreign_devices = 0;    // answer entries for devices this controller does not have
  std::uint64_t incomplete_cycles = 0;  // cycles in which not every device wrote its setpoint
  // Round trip of a cycle: from the cyclic thread publishing the cycle's setpoints to the listener having
  // routed the last device's answer to them. Microseconds.
  std::uint64_t round_trips = 0;
  double round_trip_median_us = 0.0;
  double round_trip_p99_us = 0.0;
  double round_trip_max_us = 0.0;
};

class ExchangeCore {
 public:
  explicit ExchangeCore(ExchangeOptions options);
  ExchangeCore(const ExchangeCore&) = delete;
  ExchangeCore& operator=(const ExchangeCore&) = delete;

  // ---- set-up ----
  // Throws std::invalid_argument for a bad name (empty, longer than 63, duplicate), an invalid configuration,
  // more than MAX_DEVICES devices, or after freeze().
  std::size_t add_device(const std::string& name, const DeviceConfig& config);
  void freeze();  // sizes every buffer; from here on the device table is fixed
  bool frozen() const noexcept { return frozen_; }
  std::size_t device_count() const noexcept { return devices_.size(); }
  const std::string& device_name(std::size_t device) const { return devices_.at(device)->name; }
  const DeviceConfig& device_config(std::size_t device) const { return devices_.at(device)->config; }
  const ExchangeOptions& options() const noexcept { return options_; }

  // ---- cyclic thread ----
  bool read_actual(std::size_t device, DeviceFrames& actual) noexcept;
  void write_setpoint(std::size_t device, const DeviceFrames& setpoint) noexcept;
  LinkHealth link_health(std::size_t device) const noexcept { return devices_[device]->health; }

  // ---- sender thread ----
  // Incremented and notified each time a cycle's setpoints are published; the sender waits on it.
  std::atomic<std::uint32_t>& setpoint_signal() noexcept { return setpoint_signal_; }
  // A probe (docs/gateway.md G9): a SetpointCycle without devices that a gateway answers at once.
  void prepare_probe(gateway::SetpointCycle& sample) const;
  // Set-up of the sender's sample: device names, byte orders, telegram numbers, reserved PZD capacity.
  void prepare_sample(gateway::SetpointCycle& sample) const;
  // Copies the newest published setpoints into a prepared sample; false if none is new since the last call.
  bool take_setpoints(gateway::SetpointCycle& sample) noexcept;

  // ---- listener thread(s) ----
  // Routes one received sample: checks it, hands each entry for one of our devices to that device's cyclic
  // side. `now_ns` is steady_clock time (for the round-trip statistics). Never throws.
  void route(const gateway::ActualCycle& sample, std::int64_t now_ns) noexcept;

  // ---- any thread ----
  std::uint64_t cycles_sent() const noexcept { return cycles_sent_.load(std::memory_order_acquire); }
  // Blocks the calling thread (never the cyclic one in a real-time set-up) until every device has answered
  // the setpoints of every cycle sent so far, or `timeout` passed. For lock-step operation and tests.
  bool wait_for_answers(std::chrono::nanoseconds timeout);
  // Blocks until every device has received an answer addressed to this controller (to a probe or a cycle):
  // setpoints reach the gateway and its answers come back.
  bool wait_until_heard(std::chrono::nanoseconds timeout);
  GatewayDeviceCounters counters(std::size_t device) const noexcept;
  // Whether the device had an answer addressed to this controller (to a probe or a cycle).
  bool heard_by_us(std::size_t device) const noexcept { return devices_[device]->heard_by_us.load(); }
  // Answers of the device's own controller routed so far for cycle c are in cycles (c+1); 0 = none.
  std::uint64_t answered_through(std::size_t device) const noexcept {
    return devices_[device]->answered.load(std::memory_order_acquire);
  }
  // The cycle (count of cycles sent) of the device's newest fresh answer, + 1; 0 = never fresh.
  std::uint64_t last_fresh(std::size_t device) const noexcept {
    return devices_[device]->last_fresh.load(std::memory_order_relaxed);
  }
  // The newest mismatch the listener found for the device ("slot drive: telegram 2, expected 3"), or "".
  std::string last_mismatch(std::size_t device) const;
  ExchangeStatistics statistics() const;
  // Starts the round-trip statistics afresh (e.g. after a warm-up); the other counters keep counting.
  void reset_round_trips() noexcept;

 private:
  // The newest answer for one device, as the listener hands it to the cyclic thread.
  struct Answer {
    std::uint64_t incarnation = 0;
    std::uint64_t controller = 0;
    std::uint64_t setpoint_cycle = 0;
    bool has_setpoint = false;
    DeviceFrames frames{};
  };
  struct Device {
    std::string name;
    DeviceConfig config;
    gateway::ByteOrder byte_order = gateway::BYTE_ORDER_BIG;
    LatestValue<Answer> answers;
    // cyclic thread only
    LinkHealth health{};
    std::uint64_t incarnation = 0;
    std::uint64_t written_in = 0;  // cycles_sent + 1 when written in the current cycle
    // shared counters
    std::atomic<std::uint64_t> answer_count{0};
    std::atomic<std::uint64_t> stale{0};
    std::atomic<std::uint64_t> rejected{0};
    std::atomic<std::uint64_t> restarts{0};
    std::atomic<std::uint64_t> answered{0};
    std::atomic<std::uint64_t> last_fresh{0};
    std::atomic<bool> heard_by_us{false};
    std::atomic<std::uint64_t> sign_of_life_answers{0};
    std::atomic<std::uint64_t> sign_of_life_changes{0};
    std::atomic<std::uint64_t> master_sign_of_life_changes{0};
    int stw2_offset = -1;           // byte offset of STW2 in the drive's setpoint telegram; -1: not carried
    int master_sign_of_life = -1;   // sender thread only: the last one sent, -1 = none yet
    int zsw2_offset = -1;           // byte offset of ZSW2 in the drive's actual telegram; -1: not carried
    std::uint8_t sign_of_life = 0;  // guarded by route_mutex_: the last one seen
    std::string mismatch;           // guarded by route_mutex_
  };
  struct SetpointBatch {
    std::uint64_t cycle = 0;
    std::vector<DeviceFrames> devices;
  };
  struct GatewaySequence {
    std::string name;
    std::uint64_t incarnation = 0;
    std::uint64_t sequence = 0;
  };
  static constexpr std::size_t kFlushRing = 64;
  static constexpr std::size_t kRoundTripBuckets = 20'000;  // 1 us each; the last one collects the rest

  bool is_current(const Answer& answer, std::uint64_t sent) const noexcept;
  void flush() noexcept;
  std::size_t find(std::string_view name) const noexcept;
  void record_round_trip(std::uint64_t cycle, std::int64_t now_ns) noexcept;

  ExchangeOptions options_;
  bool frozen_ = false;
  std::vector<std::unique_ptr<Device>> devices_;
  std::vector<std::pair<std::string, std::size_t>> by_name_;  // sorted, for the listener's look-up

  // cyclic -> sender
  LatestValue<SetpointBatch> batches_;
  std::atomic<std::uint32_t> setpoint_signal_{0};
  std::atomic<std::uint64_t> cycles_sent_{0};
  std::size_t written_count_ = 0;  // cyclic thread only
  std::atomic<std::uint64_t> incomplete_cycles_{0};
  std::array<std::atomic<std::int64_t>, kFlushRing> flush_ns_{};
  std::array<std::atomic<std::uint64_t>, kFlushRing> flush_cycle_{};

  // listener side
  mutable std::mutex route_mutex_;  // the listener's own: Fast DDS may call it from more than one thread
  std::vector<GatewaySequence> gateways_;
  std::atomic<std::uint64_t> samples_received_{0};
  std::atomic<std::uint64_t> samples_rejected_{0};
  std::atomic<std::uint64_t> answers_lost_{0};
  std::atomic<std::uint64_t> foreign_devices_{0};
  std::atomic<std::uint64_t> completed_{0};  // min over devices of `answered`
  std::atomic<std::uint64_t> heard_{0};      // devices with an answer addressed to this controller
  std::unique_ptr<std::array<std::atomic<std::uint32_t>, kRoundTripBuckets>> round_trip_histogram_;
  std::atomic<std::uint64_t> round_trips_{0};
  std::atomic<std::int64_t> round_trip_max_ns_{0};

  // waiters (never the cyclic thread)
  std::mutex wait_mutex_;
  std::condition_variable answered_cv_;
};

}  // namespace tomc::drives::dds
