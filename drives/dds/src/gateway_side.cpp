// The gateway's side of the contract (gateway_side.hpp, docs/gateway.md §5).
#include "tomc/drives/dds/gateway_side.hpp"

#include <unistd.h>

#include <random>

#include <stdexcept>

#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/type_support.hpp"

namespace tomc::drives::dds {

std::uint64_t random_id() {
  std::random_device device;
  std::uint64_t id = (static_cast<std::uint64_t>(device()) << 32) ^ device();
  id ^= static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) *
        0x9E3779B97F4A7C15ULL;
  id ^= static_cast<std::uint64_t>(::getpid()) << 17;
  return id == 0 ? 1 : id;
}

SetpointSession::Decision SetpointSession::accept(const gateway::SetpointCycle& sample,
                                                  Clock::time_point now) {
  Decision d;
  if (sample.contract_version() != kContractVersion || sample.devices().size() > kMaxDevices ||
      sample.controller() == 0) {
    ++counters_.setpoints_rejected;
    return d;
  }
  const bool other = owner_ != 0 && sample.controller() != owner_;
  if (sample.devices().empty()) {
    // G9: answered if this controller could be served; it does not take the gateway nor refresh the watchdog.
    if (other && !silent(now)) {
      ++counters_.setpoints_rejected;
      return d;
    }
    d.verdict = Verdict::kProbe;
    return d;
  }
  if (other) {
    // G1: another controller only after the served one has been silent for the watchdog time.
    if (!silent(now)) {
      ++counters_.setpoints_rejected;
      return d;
    }
    release();
    d.released = true;
  }
  if (owner_ == 0) owner_ = sample.controller();
  if (have_cycle_) {
    if (sample.cycle() <= last_cycle_) {  // G2: old or duplicated
      ++counters_.setpoints_rejected;
      return d;
    }
    d.gap = sample.cycle() - last_cycle_ - 1;
    counters_.setpoint_gaps += d.gap;
  }
  have_cycle_ = true;
  last_cycle_ = sample.cycle();
  last_setpoint_ = now;
  ever_ = true;
  ++counters_.setpoints_applied;
  d.verdict = Verdict::kApply;
  return d;
}

void SetpointSession::release() noexcept {
  owner_ = 0;
  have_cycle_ = false;
}

void SetpointSession::restart() {
  incarnation_ = random_id();
  sequence_ = 0;
  release();
  ever_ = false;
}

void SetpointSession::fill_status(gateway::GatewayStatus& status, const std::string& gateway,
                                  std::uint32_t cycle_time_ns, std::uint64_t command_number) const {
  status.contract_version(kContractVersion);
  status.gateway(gateway);
  status.incarnation(incarnation_);
  status.controller(owner_);
  status.cycle_time_ns(cycle_time_ns);
  status.setpoints_applied(counters_.setpoints_applied);
  status.setpoint_gaps(counters_.setpoint_gaps);
  status.setpoints_rejected(counters_.setpoints_rejected);
  status.answers_published(counters_.answers_published);
  status.command_number(command_number);
}

void SetpointSession::fill_answer(gateway::ActualCycle& answer, const std::string& gateway,
                                  std::uint64_t sequence, std::uint64_t controller) const {
  answer.contract_version(kContractVersion);
  answer.gateway(gateway);
  answer.incarnation(incarnation_);
  answer.sequence_number(sequence);
  answer.controller(controller);
}

GatewayEndpoints::GatewayEndpoints(int domain, const std::string& participant_name,
                                   const std::string& partition, const NetworkSettings& network,
                                   const std::string& who)
    : who_(who),
      setpoint_type_(new SetpointCycleType()),
      actual_type_(new ActualCycleType()),
      status_type_(new GatewayStatusType()) {
  participant_ = std::make_unique<Participant>(domain, participant_name, partition,
                                               resolve_network_or_throw(network, false));
  Participant& p = *participant_;
  actual_writer_ = p.publisher().create_datawriter(&p.topic(kActualTopic, actual_type_), cyclic_writer_qos());
  status_writer_ = p.publisher().create_datawriter(&p.topic(kStatusTopic, status_type_), status_writer_qos());
  if (actual_writer_ == nullptr || status_writer_ == nullptr) {
    throw std::runtime_error(who_ + ": Fast DDS could not create the writers");
  }
}

void GatewayEndpoints::read_setpoints(eprosima::fastdds::dds::DataReaderListener* listener) {
  Participant& p = *participant_;
  if (p.subscriber().create_datareader(&p.topic(kSetpointTopic, setpoint_type_), cyclic_reader_qos(),
                                       listener) == nullptr) {
    throw std::runtime_error(who_ + ": Fast DDS could not create the setpoint reader");
  }
}

void reserve_answer(gateway::ActualCycle& answer, std::size_t devices) {
  answer.devices().resize(devices);
  for (auto& e : answer.devices()) {
    for (auto& s : e.slots())
      s.pzd().reserve(telegrams::kMaxFrameBytes);
  }
}

}  // namespace tomc::drives::dds
