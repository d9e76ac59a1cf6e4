// The DDS side of the gateway adapter: participant, writer, readers, the sender thread and the diagnosis
// (gateway_link.hpp, docs/gateway.md).
#include "tomc/drives/dds/gateway_link.hpp"

#include <unistd.h>

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <random>
#include <stdexcept>
#include <thread>

#include <fastdds/rtps/builtin/data/ReaderProxyData.h>
#include <fastdds/rtps/builtin/data/WriterProxyData.h>
#include <fastdds/rtps/participant/ParticipantDiscoveryInfo.h>
#include <fastdds/rtps/reader/ReaderDiscoveryInfo.h>
#include <fastdds/rtps/writer/WriterDiscoveryInfo.h>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/participant.hpp"
#include "tomc/drives/dds/type_support.hpp"

namespace tomc::drives::dds {

namespace fdds = eprosima::fastdds::dds;

namespace {

std::int64_t steady_now_ns() noexcept {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

std::uint64_t random_id() {
  std::random_device device;
  std::uint64_t id = (static_cast<std::uint64_t>(device()) << 32) ^ device();
  id ^= static_cast<std::uint64_t>(steady_now_ns()) * 0x9E3779B97F4A7C15ULL;
  id ^= static_cast<std::uint64_t>(::getpid());
  return id == 0 ? 1 : id;
}

// Answers to the controller's setpoints after which a drive sign-of-life that never changed is flagged: a
// counting drive changes it every cycle; 32 covers the drive's start-up (it may begin counting only after it
// has synchronised to the controller's sign-of-life, spec 06 §5).
constexpr std::uint64_t kSignOfLifeWindow = 32;

std::string quoted_list(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

class ActualListener final : public fdds::DataReaderListener {
 public:
  explicit ActualListener(ExchangeCore& core) : core_(core) {}
  void on_data_available(fdds::DataReader* reader) override {
    std::lock_guard<std::mutex> lock(mutex_);  // one sample buffer; Fast DDS may call from several threads
    fdds::SampleInfo info;
    while (reader->take_next_sample(&sample_, &info) == ReturnCode_t::RETCODE_OK) {
      if (info.valid_data) core_.route(sample_, steady_now_ns());
    }
  }

 private:
  ExchangeCore& core_;
  std::mutex mutex_;
  gateway::ActualCycle sample_;
};

class StatusListener final : public fdds::DataReaderListener {
 public:
  void on_data_available(fdds::DataReader* reader) override {
    gateway::GatewayStatus status;
    fdds::SampleInfo info;
    while (reader->take_next_sample(&status, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data || status.contract_version() != kContractVersion) continue;
      std::lock_guard<std::mutex> lock(mutex);
      auto it = std::find_if(statuses.begin(), statuses.end(), [&](const gateway::GatewayStatus& s) {
        return s.gateway() == status.gateway().c_str();
      });
      if (it == statuses.end()) {
        statuses.push_back(status);
      } else {
        *it = status;
      }
    }
  }
  mutable std::mutex mutex;
  std::vector<gateway::GatewayStatus> statuses;  // newest per gateway name
};

// What discovery tells about the other participants on the domain: which exist, and which endpoints they have
// on the contract's topics, with the properties that decide whether they match this controller's
// (docs/gateway.md §1, §3). diagnose() uses it to tell "no gateway" from "a gateway whose endpoints do not
// match".
class DiscoveryListener final : public fdds::DomainParticipantListener {
 public:
  using GuidPrefix = eprosima::fastrtps::rtps::GuidPrefix_t;
  struct Remote {
    GuidPrefix prefix;
    std::string name;
  };
  struct Endpoint {
    eprosima::fastrtps::rtps::GUID_t guid;
    bool reader = false;
    std::string topic;
    std::string type;
    bool reliable = false;
    bool transient_local = false;  // TRANSIENT_LOCAL or stronger
    std::vector<std::string> partitions;
    std::vector<fdds::DataRepresentationId_t> representations;
  };

  void on_participant_discovery(fdds::DomainParticipant* participant,
                                eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override {
    using Status = eprosima::fastrtps::rtps::ParticipantDiscoveryInfo;
    const GuidPrefix prefix = info.info.m_guid.guidPrefix;
    if (participant != nullptr && prefix == participant->guid().guidPrefix) return;
    std::lock_guard<std::mutex> lock(mutex);
    auto it =
        std::find_if(remotes.begin(), remotes.end(), [&](const Remote& r) { return r.prefix == prefix; });
    if (info.status == Status::DISCOVERED_PARTICIPANT || info.status == Status::CHANGED_QOS_PARTICIPANT) {
      if (it == remotes.end()) {
        std::string name = info.info.m_participantName.to_string();
        remotes.push_back(Remote{prefix, name.empty() ? std::string("(unnamed)") : name});
      }
    } else if (it != remotes.end()) {
      remotes.erase(it);
      endpoints.erase(std::remove_if(endpoints.begin(), endpoints.end(),
                                     [&](const Endpoint& e) { return e.guid.guidPrefix == prefix; }),
                      endpoints.end());
    }
  }

  void on_subscriber_discovery(fdds::DomainParticipant* participant,
                               eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override {
    using Status = eprosima::fastrtps::rtps::ReaderDiscoveryInfo;
    const auto& d = info.info;
    Endpoint e{d.guid(),
               true,
               d.topicName().to_string(),
               d.typeName().to_string(),
               d.m_qos.m_reliability.kind == fdds::RELIABLE_RELIABILITY_QOS,
               d.m_qos.m_durability.kind != fdds::VOLATILE_DURABILITY_QOS,
               d.m_qos.m_partition.names(),
               d.m_qos.representation.m_value};
    update(participant, std::move(e),
           info.status == Status::DISCOVERED_READER || info.status == Status::CHANGED_QOS_READER);
  }

  void on_publisher_discovery(fdds::DomainParticipant* participant,
                              eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override {
    using Status = eprosima::fastrtps::rtps::WriterDiscoveryInfo;
    const auto& d = info.info;
    Endpoint e{d.guid(),
               false,
               d.topicName().to_string(),
               d.typeName().to_string(),
               d.m_qos.m_reliability.kind == fdds::RELIABLE_RELIABILITY_QOS,
               d.m_qos.m_durability.kind != fdds::VOLATILE_DURABILITY_QOS,
               d.m_qos.m_partition.names(),
               d.m_qos.representation.m_value};
    update(participant, std::move(e),
           info.status == Status::DISCOVERED_WRITER || info.status == Status::CHANGED_QOS_WRITER);
  }

  mutable std::mutex mutex;
  std::vector<Remote> remotes;
  std::vector<Endpoint> endpoints;  // remote endpoints on topics "tomc/gateway/..."

 private:
  void update(fdds::DomainParticipant* participant, Endpoint e, bool present) {
    if (participant != nullptr && e.guid.guidPrefix == participant->guid().guidPrefix) return;
    if (e.topic.rfind("tomc/gateway/", 0) != 0) return;
    std::lock_guard<std::mutex> lock(mutex);
    auto it =
        std::find_if(endpoints.begin(), endpoints.end(), [&](const Endpoint& x) { return x.guid == e.guid; });
    if (it != endpoints.end()) endpoints.erase(it);
    if (present) endpoints.push_back(std::move(e));
  }
};

// Whether two partition lists match (DDS: the empty list is the default partition ""; names may be
// fnmatch-style wildcards on either side).
bool partitions_match(std::vector<std::string> a, std::vector<std::string> b) {
  if (a.empty()) a.emplace_back();
  if (b.empty()) b.emplace_back();
  for (const auto& x : a) {
    for (const auto& y : b) {
      if (x == y || ::fnmatch(x.c_str(), y.c_str(), 0) == 0 || ::fnmatch(y.c_str(), x.c_str(), 0) == 0)
        return true;
    }
  }
  return false;
}

std::string partition_text(const std::vector<std::string>& names) {
  if (names.empty()) return "the default partition";
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "'" : ", '") + n + "'";
  return "partition " + s;
}

// Why a remote endpoint does not match this controller's endpoint of the same topic; "" when it matches or is
// not one this controller pairs with (its own kind on the same topic, or the simulator's command topic).
std::string endpoint_mismatch(const DiscoveryListener::Endpoint& e, const std::string& partition) {
  struct Local {
    const char* topic;
    bool remote_is_reader;  // the remote side of this controller's endpoint
    const char* type;
    bool reliable;  // this controller's endpoint
    bool transient_local;
  };
  static constexpr Local kLocals[] = {
      {kSetpointTopic, true, "tomc::gateway::SetpointCycle", false, false},
      {kActualTopic, false, "tomc::gateway::ActualCycle", false, false},
      {kStatusTopic, false, "tomc::gateway::GatewayStatus", true, true},
  };
  const Local* local = nullptr;
  for (const auto& l : kLocals) {
    if (e.topic == l.topic && e.reader == l.remote_is_reader) local = &l;
  }
  if (local == nullptr) return {};
  // Another partition is another controller/gateway pair sharing the domain (§1): not this link's business
  // (a gateway that is only there is named in the "no gateway" text instead).
  std::vector<std::string> ours;
  if (!partition.empty()) ours.push_back(partition);
  if (!partitions_match(e.partitions, ours)) return {};
  const std::string what = std::string("its ") + (e.reader ? "reader of " : "writer of ") + e.topic;
  if (e.type != local->type) {
    return what + " has type '" + e.type + "', the contract's is '" + local->type + "'";
  }
  if (e.reader) {
    // The remote reader requests; this controller's writer offers (best effort, volatile, XCDR1).
    if (e.reliable && !local->reliable)
      return what + " requests reliable; the contract's writer is best effort";
    if (e.transient_local && !local->transient_local) {
      return what + " requests transient-local durability; the contract's writer is volatile";
    }
    if (!e.representations.empty() && std::find(e.representations.begin(), e.representations.end(),
                                                fdds::XCDR_DATA_REPRESENTATION) == e.representations.end()) {
      return what + " does not accept XCDR1 (data representation), which the contract requires";
    }
  } else {
    if (local->reliable && !e.reliable) return what + " is best effort; the contract requires reliable";
    if (local->transient_local && !e.transient_local) {
      return what + " is volatile; the contract requires transient-local durability";
    }
    if (!e.representations.empty() && e.representations.front() != fdds::XCDR_DATA_REPRESENTATION) {
      return what + " writes " +
             (e.representations.front() == fdds::XCDR2_DATA_REPRESENTATION ? "XCDR2"
                                                                           : "another representation") +
             " (data representation); the contract requires XCDR1";
    }
  }
  return {};
}

}  // namespace

const char* to_string(DeviceDiagnosis diagnosis) noexcept {
  switch (diagnosis) {
    case DeviceDiagnosis::kAnswering:
      return "answering";
    case DeviceDiagnosis::kSignOfLifeNotCounting:
      return "sign-of-life not counting";
    case DeviceDiagnosis::kNoGateway:
      return "no gateway";
    case DeviceDiagnosis::kEndpointMismatch:
      return "endpoints do not match";
    case DeviceDiagnosis::kNotServed:
      return "not served";
    case DeviceDiagnosis::kConfigMismatch:
      return "configuration mismatch";
    case DeviceDiagnosis::kDisconnected:
      return "disconnected";
    case DeviceDiagnosis::kOtherController:
      return "other controller";
    case DeviceDiagnosis::kSilent:
      return "silent";
  }
  return "?";
}

struct GatewayLink::Impl {
  GatewayLinkConfig config;
  ResolvedNetwork network;
  std::unique_ptr<ExchangeCore> core;
  // The listeners before the participant: members are destroyed in reverse order, entities first.
  std::unique_ptr<ActualListener> actual_listener;
  StatusListener status_listener;
  DiscoveryListener discovery_listener;
  std::unique_ptr<Participant> participant;
  fdds::TypeSupport setpoint_type{new SetpointCycleType()};
  fdds::TypeSupport actual_type{new ActualCycleType()};
  fdds::TypeSupport status_type{new GatewayStatusType()};
  fdds::DataWriter* setpoint_writer = nullptr;
  fdds::DataReader* actual_reader = nullptr;
  fdds::DataReader* status_reader = nullptr;

  std::mutex start_mutex;
  bool started = false;
  std::thread sender;
  std::atomic<bool> stop{false};
  gateway::SetpointCycle sample;  // the sender thread's
  std::atomic<std::uint64_t> write_failures{0};

  // "" when no discovered endpoint contradicts this controller's, else the first contradiction, naming the
  // participant: "gateway participant 'gw' discovered, but its reader of tomc/gateway/setpoint ...".
  std::string endpoint_problem() const {
    std::lock_guard<std::mutex> lock(discovery_listener.mutex);
    for (const auto& e : discovery_listener.endpoints) {
      const std::string why = endpoint_mismatch(e, config.partition);
      if (why.empty()) continue;
      std::string name = "?";
      for (const auto& r : discovery_listener.remotes) {
        if (r.prefix == e.guid.guidPrefix) name = r.name;
      }
      return "DDS participant '" + name +
             "' was discovered, but its endpoints do not match this controller's: " + why;
    }
    return {};
  }
  // Status writers in other partitions than this controller's, for "no gateway" texts: "'gw2' in partition
  // 'line2'".
  std::vector<std::string> gateways_elsewhere() const {
    std::lock_guard<std::mutex> lock(discovery_listener.mutex);
    std::vector<std::string> ours;
    if (!config.partition.empty()) ours.push_back(config.partition);
    std::vector<std::string> out;
    for (const auto& e : discovery_listener.endpoints) {
      if (e.reader || e.topic != kStatusTopic || partitions_match(e.partitions, ours)) continue;
      std::string name = "?";
      for (const auto& r : discovery_listener.remotes) {
        if (r.prefix == e.guid.guidPrefix) name = r.name;
      }
      out.push_back("'" + name + "' in " + partition_text(e.partitions));
    }
    return out;
  }
  // The discovered participants' names, for "no gateway" texts.
  std::vector<std::string> remote_names() const {
    std::lock_guard<std::mutex> lock(discovery_listener.mutex);
    std::vector<std::string> names;
    for (const auto& r : discovery_listener.remotes)
      names.push_back("'" + r.name + "'");
    return names;
  }
  // " via 10.0.0.1 (eth1) to peer(s) 10.0.0.2" or "" on loopback.
  std::string network_text() const {
    if (network.loopback() && network.peers == std::vector<std::string>{"127.0.0.1"}) return {};
    std::string peers;
    for (const auto& p : network.peers)
      peers += (peers.empty() ? "" : ", ") + p;
    return " via " + network.address + " (" + network.interface_name + ") to peer(s) " +
           (peers.empty() ? "none" : peers);
  }

  void sender_loop() noexcept {
    auto& signal = core->setpoint_signal();
    std::uint32_t seen = signal.load(std::memory_order_acquire);
    for (;;) {
      signal.wait(seen, std::memory_order_acquire);
      seen = signal.load(std::memory_order_acquire);
      if (stop.load(std::memory_order_acquire)) return;
      if (core->take_setpoints(sample) && !setpoint_writer->write(&sample)) write_failures.fetch_add(1);
    }
  }
};

std::shared_ptr<GatewayLink> GatewayLink::create(const GatewayLinkConfig& config) {
  if (const auto problem = check_domain(config.domain); !problem.empty())
    throw std::invalid_argument(problem);
  if (!(config.cycle_time_s > 0.0) || config.cycle_time_s > 4.0) {
    throw std::invalid_argument("gateway link: cycle time must be > 0 and <= 4 s");
  }
  ResolvedNetwork network;
  try {
    network = resolve_network_or_throw(config.network, true);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("gateway link: ") + e.what());
  }
  auto impl = std::make_unique<Impl>();
  impl->config = config;
  impl->network = network;
  ExchangeOptions options;
  options.controller = random_id();
  options.cycle_time_ns = static_cast<std::uint32_t>(std::llround(config.cycle_time_s * 1e9));
  options.max_answer_age_cycles = config.max_answer_age_cycles;
  impl->core = std::make_unique<ExchangeCore>(options);
  impl->participant = std::make_unique<Participant>(config.domain, config.participant_name, config.partition,
                                                    network, &impl->discovery_listener);
  Participant& p = *impl->participant;
  // The status reader listens from the start: diagnose() can say which gateways are there before connect().
  impl->status_reader = p.subscriber().create_datareader(&p.topic(kStatusTopic, impl->status_type),
                                                         status_reader_qos(), &impl->status_listener);
  impl->setpoint_writer =
      p.publisher().create_datawriter(&p.topic(kSetpointTopic, impl->setpoint_type), cyclic_writer_qos());
  if (impl->status_reader == nullptr || impl->setpoint_writer == nullptr) {
    throw std::runtime_error("Fast DDS could not create the gateway link's status reader / setpoint writer");
  }
  return std::shared_ptr<GatewayLink>(new GatewayLink(std::move(impl)));
}

GatewayLink::GatewayLink(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

GatewayLink::~GatewayLink() {
  if (impl_->sender.joinable()) {
    impl_->stop.store(true, std::memory_order_release);
    impl_->core->setpoint_signal().fetch_add(1, std::memory_order_release);
    impl_->core->setpoint_signal().notify_all();
    impl_->sender.join();
  }
  // Entities (and their listeners' calls) end before the listeners and the core go away.
  impl_->participant.reset();
}

std::unique_ptr<DdsGatewayDrive> GatewayLink::make_drive(const std::string& device,
                                                         const DeviceConfig& config) {
  std::lock_guard<std::mutex> lock(impl_->start_mutex);
  if (impl_->started) throw std::invalid_argument("gateway link: devices are added before start()/connect()");
  const std::size_t index = impl_->core->add_device(device, config);
  return std::make_unique<DdsGatewayDrive>(shared_from_this(), index);
}

void GatewayLink::start() {
  std::lock_guard<std::mutex> lock(impl_->start_mutex);
  if (impl_->started) return;
  Impl& m = *impl_;
  m.core->freeze();
  m.core->prepare_sample(m.sample);
  Participant& p = *m.participant;
  m.actual_listener = std::make_unique<ActualListener>(*m.core);
  m.actual_reader = p.subscriber().create_datareader(&p.topic(kActualTopic, m.actual_type),
                                                     cyclic_reader_qos(), m.actual_listener.get());
  if (m.actual_reader == nullptr)
    throw std::runtime_error("Fast DDS could not create the actual-value reader");
  m.sender = std::thread([&m] { m.sender_loop(); });
  m.started = true;
}

std::vector<DeviceReport> GatewayLink::connect(std::chrono::milliseconds timeout) {
  start();
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  // Probes until every device has an answer addressed to this controller: then setpoints reach the gateway
  // (its reader has matched this writer, which an idle answer alone would not show) and its answers come
  // back. The runtime has not started: nothing else writes.
  gateway::SetpointCycle probe;
  impl_->core->prepare_probe(probe);
  for (;;) {
    impl_->setpoint_writer->write(&probe);
    if (impl_->core->wait_until_heard(std::chrono::milliseconds(5))) break;
    // Stop waiting early when every silent device has a definite reason that waiting will not change.
    const auto reports = diagnose();
    // Reasons from a gateway's status need that status; an endpoint that cannot match (from discovery data)
    // is definite without one.
    const bool have_status = !gateways().empty();
    bool settled = true;
    for (std::size_t i = 0; i < reports.size() && settled; ++i) {
      const DeviceDiagnosis d = reports[i].diagnosis;
      settled = impl_->core->heard_by_us(i) || d == DeviceDiagnosis::kEndpointMismatch ||
                (have_status && (d == DeviceDiagnosis::kNotServed || d == DeviceDiagnosis::kConfigMismatch ||
                                 d == DeviceDiagnosis::kOtherController));
    }
    if (settled || std::chrono::steady_clock::now() >= deadline) break;
  }
  return diagnose();
}

bool GatewayLink::wait_for_answers(std::chrono::nanoseconds timeout) {
  return impl_->core->wait_for_answers(timeout);
}

std::vector<DeviceReport> GatewayLink::diagnose() const {
  const ExchangeCore& core = *impl_->core;
  std::vector<gateway::GatewayStatus> statuses;
  {
    std::lock_guard<std::mutex> lock(impl_->status_listener.mutex);
    statuses = impl_->status_listener.statuses;
  }
  const std::uint64_t sent = core.cycles_sent();
  const std::uint64_t ours = core.options().controller;
  const std::string endpoint_problem = impl_->endpoint_problem();
  std::vector<DeviceReport> reports;
  for (std::size_t i = 0; i < core.device_count(); ++i) {
    DeviceReport r;
    r.device = core.device_name(i);
    const DeviceConfig& mine = core.device_config(i);
    const GatewayDeviceCounters counters = core.counters(i);
    const std::uint64_t fresh = core.last_fresh(i);
    const bool answering = sent == 0
                               ? counters.answers > 0 && core.last_mismatch(i).empty()
                               : fresh != 0 && sent + 1 - fresh <= core.options().max_answer_age_cycles + 2;
    // The gateway(s) that list this device.
    const gateway::GatewayStatus* serving = nullptr;
    const gateway::DeviceDescription* description = nullptr;
    for (const auto& s : statuses) {
      for (const auto& d : s.devices()) {
        if (d.device() == r.device) {
          serving = &s;
          description = &d;
        }
      }
    }
    std::string configured_difference;
    if (description != nullptr) {
      const auto telegrams = slot_telegrams(mine);
      for (std::size_t slot = 0; slot < kSlotCount && configured_difference.empty(); ++slot) {
        if (description->telegrams()[slot] != telegrams[slot]) {
          configured_difference = std::string("slot ") + slot_name(slot) + ": the gateway has telegram " +
                                  std::to_string(description->telegrams()[slot]) + ", this controller " +
                                  std::to_string(telegrams[slot]);
        }
      }
      if (configured_difference.empty() && description->byte_order() != to_contract(mine.codec.byte_order)) {
        configured_difference = "the gateway's byte order differs from this controller's";
      }
    }
    const std::string mismatch = core.last_mismatch(i);
    if (answering && counters.master_sign_of_life_changes > 0 &&
        counters.sign_of_life_answers >= kSignOfLifeWindow && counters.sign_of_life_changes == 0) {
      // The controller counts its sign-of-life (isochronous operation) but the drive's never changed. The
      // TO's sign-of-life monitor takes only zeros for "not yet sending" and raises no alarm: said here
      // (docs/gateway.md G10).
      r.diagnosis = DeviceDiagnosis::kSignOfLifeNotCounting;
      r.text = "'" + r.device +
               "' answers, but the drive's sign-of-life (ZSW2 bits 12..15) has not counted in " +
               std::to_string(counters.sign_of_life_answers) +
               " answers: the drive is not in isochronous mode, or the gateway does not pass ZSW2 through";
    } else if (answering) {
      r.diagnosis = DeviceDiagnosis::kAnswering;
      r.text = "'" + r.device + "' answers" +
               (serving ? " through gateway '" + serving->gateway().to_string() + "'" : "");
    } else if (!configured_difference.empty() || !mismatch.empty() ||
               (description != nullptr && description->state() == gateway::DEVICE_CONFIG_MISMATCH)) {
      r.diagnosis = DeviceDiagnosis::kConfigMismatch;
      r.text = "'" + r.device + "': " +
               (!configured_difference.empty()
                    ? "gateway '" + serving->gateway().to_string() + "': " + configured_difference
                : !mismatch.empty() ? mismatch
                                    : "gateway '" + serving->gateway().to_string() +
                                          "': " + description->detail().to_string());
    } else if (!endpoint_problem.empty() && (statuses.empty() || serving != nullptr)) {
      // Discovered, but type, partition, representation or QoS keep its endpoints from matching ours.
      r.diagnosis = DeviceDiagnosis::kEndpointMismatch;
      r.text = endpoint_problem;
    } else if (statuses.empty()) {
      r.diagnosis = DeviceDiagnosis::kNoGateway;
      const auto names = impl_->remote_names();
      r.text = "no gateway has announced itself on DDS domain " + std::to_string(impl_->config.domain) +
               (impl_->config.partition.empty() ? "" : " partition '" + impl_->config.partition + "'") +
               impl_->network_text() +
               (names.empty() ? " (no other DDS participant discovered)"
                              : " (discovered: " + quoted_list(names) + "; none publishes " + kStatusTopic +
                                    " in this partition)");
      if (const auto elsewhere = impl_->gateways_elsewhere(); !elsewhere.empty()) {
        r.text += "; gateways in other partitions: " + quoted_list(elsewhere);
      }
    } else if (serving == nullptr) {
      r.diagnosis = DeviceDiagnosis::kNotServed;
      std::string served;
      for (const auto& s : statuses) {
        std::vector<std::string> names;
        for (const auto& d : s.devices())
          names.push_back(d.device().to_string());
        served += (served.empty() ? "" : "; ") + std::string("gateway '") + s.gateway().to_string() +
                  "' serves: " + quoted_list(names);
      }
      r.text = "no gateway serves '" + r.device + "' (" + served + ")";
    } else if (description->state() == gateway::DEVICE_DISCONNECTED) {
      r.diagnosis = DeviceDiagnosis::kDisconnected;
      r.text = "gateway '" + serving->gateway().to_string() + "' has no cyclic exchange with '" + r.device +
               "'" + (description->detail().size() == 0 ? "" : ": " + description->detail().to_string());
    } else if (serving->controller() != 0 && serving->controller() != ours) {
      r.diagnosis = DeviceDiagnosis::kOtherController;
      r.text = "gateway '" + serving->gateway().to_string() + "' serves another controller";
    } else {
      r.diagnosis = DeviceDiagnosis::kSilent;
      r.text = "gateway '" + serving->gateway().to_string() + "' serves '" + r.device +
               "' but no current answer arrives (" + std::to_string(counters.answers) + " answers, " +
               std::to_string(counters.stale) + " stale, " + std::to_string(counters.restarts) +
               " gateway restarts)";
    }
    reports.push_back(std::move(r));
  }
  return reports;
}

ExchangeStatistics GatewayLink::statistics() const {
  return impl_->core->statistics();
}
const GatewayLinkConfig& GatewayLink::config() const noexcept {
  return impl_->config;
}
std::uint64_t GatewayLink::controller_id() const noexcept {
  return impl_->core->options().controller;
}
ExchangeCore& GatewayLink::core() noexcept {
  return *impl_->core;
}

std::vector<GatewayLink::GatewayInfo> GatewayLink::gateways() const {
  std::lock_guard<std::mutex> lock(impl_->status_listener.mutex);
  std::vector<GatewayInfo> out;
  for (const auto& s : impl_->status_listener.statuses) {
    GatewayInfo g;
    g.name = s.gateway().to_string();
    g.incarnation = s.incarnation();
    g.controller = s.controller();
    g.command_number = s.command_number();
    for (const auto& d : s.devices()) {
      static constexpr const char* kStates[] = {"connected", "faulted", "disconnected",
                                                "configuration mismatch"};
      const auto state = static_cast<std::size_t>(d.state());
      g.devices.push_back(GatewayDevice{d.device().to_string(), state < 4 ? kStates[state] : "invalid",
                                        d.fault(), d.detail().to_string()});
    }
    out.push_back(std::move(g));
  }
  return out;
}

DdsGatewayDrive::DdsGatewayDrive(std::shared_ptr<GatewayLink> link, std::size_t index)
    : link_(std::move(link)), core_(&link_->core()), index_(index), config_(core_->device_config(index)) {}

}  // namespace tomc::drives::dds
