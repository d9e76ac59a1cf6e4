#pragma once
// The gateway's side of the contract (docs/gateway.md §5), shared by every gateway tomc has — the simulator
// (`tomc gateway-sim`) and the PROFINET gateway (`tomc gateway`) — so that both decide the same way which
// setpoint samples they apply: one controller at a time (G1), version, size, controller and cycle checks with
// gap counting (G2), probes (G9), the watchdog that releases a silent controller (G6), and the counters and
// identity (G5) that GatewayStatus and ActualCycle carry. Not thread-safe: the caller serialises its calls.

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include "tomc/drives/dds/network.hpp"
#include "tomc/drives/dds/participant.hpp"
#include "tomc_gateway.h"

namespace tomc::drives::dds {

// A random non-zero 64-bit id (a gateway's incarnation, a controller's run).
std::uint64_t random_id();

struct SessionCounters {
  std::uint64_t setpoints_applied = 0;
  std::uint64_t setpoint_gaps = 0;
  std::uint64_t setpoints_rejected = 0;
  std::uint64_t answers_published = 0;
};

class SetpointSession {
 public:
  using Clock = std::chrono::steady_clock;
  enum class Verdict : std::uint8_t {
    kRejected,  // counted in setpoints_rejected (G1, G2, G9)
    kProbe,     // answer at once for `controller`, apply nothing (G9)
    kApply,     // apply the sample's device entries (G3) and answer (G4)
  };
  struct Decision {
    Verdict verdict = Verdict::kRejected;
    std::uint64_t gap = 0;  // missing cycle numbers before this sample (kApply)
    bool released = false;  // the previous controller was released first: forget its setpoints
  };

  explicit SetpointSession(std::chrono::nanoseconds watchdog) : watchdog_(watchdog) {}

  Decision accept(const gateway::SetpointCycle& sample, Clock::time_point now);
  // G6: no setpoint applied for the watchdog time (or never).
  bool silent(Clock::time_point now) const noexcept { return !ever_ || now - last_setpoint_ >= watchdog_; }
  // Forgets the served controller (G6); the next one may take over.
  void release() noexcept;
  // A new run of the gateway (G5): new incarnation, sequence numbers from 1, no controller.
  void restart();

  std::uint64_t controller() const noexcept { return owner_; }
  std::uint64_t incarnation() const noexcept { return incarnation_; }
  // The next ActualCycle's sequence number; every answer takes one, also one that is then not sent (G5).
  std::uint64_t next_sequence() noexcept { return ++sequence_; }
  SessionCounters& counters() noexcept { return counters_; }
  const SessionCounters& counters() const noexcept { return counters_; }

  // The header fields of GatewayStatus and ActualCycle from this session.
  void fill_status(gateway::GatewayStatus& status, const std::string& gateway, std::uint32_t cycle_time_ns,
                   std::uint64_t command_number) const;
  void fill_answer(gateway::ActualCycle& answer, const std::string& gateway, std::uint64_t sequence,
                   std::uint64_t controller) const;

 private:
  std::chrono::nanoseconds watchdog_;
  std::uint64_t incarnation_ = random_id();
  std::uint64_t sequence_ = 0;
  std::uint64_t owner_ = 0;
  bool have_cycle_ = false;
  std::uint64_t last_cycle_ = 0;
  bool ever_ = false;
  Clock::time_point last_setpoint_{};
  SessionCounters counters_{};
};

// A DataReaderListener that takes every sample into one reused Sample (no allocation once its sequences have
// grown) and hands the valid ones to `handler`. Fast DDS calls it from its listener thread.
template <typename Sample, typename Handler>
class TakingListener final : public eprosima::fastdds::dds::DataReaderListener {
 public:
  explicit TakingListener(Handler handler) : handler_(std::move(handler)) {}
  void on_data_available(eprosima::fastdds::dds::DataReader* reader) override {
    std::lock_guard<std::mutex> lock(mutex_);
    eprosima::fastdds::dds::SampleInfo info;
    while (reader->take_next_sample(&sample_, &info) == ReturnCode_t::RETCODE_OK) {
      if (info.valid_data) handler_(sample_);
    }
  }

 private:
  Handler handler_;
  std::mutex mutex_;
  Sample sample_;
};

template <typename Sample, typename Handler>
std::unique_ptr<eprosima::fastdds::dds::DataReaderListener> make_taking_listener(Handler handler) {
  return std::make_unique<TakingListener<Sample, Handler>>(std::move(handler));
}

// The DDS entities of a gateway: its participant on the configured network (without peers it answers the
// controllers that contact it, §11), the actual and status writers and the setpoint reader with the QoS of
// §3. Throws std::runtime_error (naming `who`) when the network or Fast DDS refuses.
class GatewayEndpoints {
 public:
  GatewayEndpoints(int domain, const std::string& participant_name, const std::string& partition,
                   const NetworkSettings& network, const std::string& who);
  // The setpoint reader, its samples to `listener` (which must outlive this object).
  void read_setpoints(eprosima::fastdds::dds::DataReaderListener* listener);
  eprosima::fastdds::dds::DataWriter& actual_writer() noexcept { return *actual_writer_; }
  eprosima::fastdds::dds::DataWriter& status_writer() noexcept { return *status_writer_; }
  Participant& participant() noexcept { return *participant_; }

 private:
  std::string who_;
  eprosima::fastdds::dds::TypeSupport setpoint_type_;
  eprosima::fastdds::dds::TypeSupport actual_type_;
  eprosima::fastdds::dds::TypeSupport status_type_;
  std::unique_ptr<Participant> participant_;
  eprosima::fastdds::dds::DataWriter* actual_writer_ = nullptr;
  eprosima::fastdds::dds::DataWriter* status_writer_ = nullptr;
};

// Sizes `answer` for `devices` entries whose PZD vectors hold any telegram: filling it later does not
// allocate.
void reserve_answer(gateway::ActualCycle& answer, std::size_t devices);

}  // namespace tomc::drives::dds
