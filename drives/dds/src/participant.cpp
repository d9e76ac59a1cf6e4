// The loopback-only participant and the contract's QoS (participant.hpp, docs/gateway.md).
#include "tomc/drives/dds/participant.hpp"

#include <stdexcept>

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/qos/PublisherQos.hpp>
#include <fastdds/dds/subscriber/qos/SubscriberQos.hpp>

namespace tomc::drives::dds {

namespace fdds = eprosima::fastdds::dds;
using eprosima::fastdds::rtps::SharedMemTransportDescriptor;
using eprosima::fastdds::rtps::UDPv4TransportDescriptor;
using eprosima::fastrtps::rtps::IPLocator;
using eprosima::fastrtps::rtps::Locator_t;
using eprosima::fastrtps::rtps::LocatorList_t;

namespace {

constexpr const char* kLoopback = "127.0.0.1";

// Reliable writers announce their samples every 50 ms instead of Fast DDS's 3 s: a status or command sample
// lost before the reader had fully matched is repaired within a few cycles of the watchdog, not seconds later
// (TOOLCHAIN §11.6).
void fast_repair(fdds::DataWriterQos& qos) {
  qos.reliable_writer_qos().times.heartbeatPeriod = eprosima::fastrtps::Duration_t(0, 50'000'000);
}

// A UDPv4 locator that is "any address" (the transport then uses its whitelisted interfaces) or on 127/8.
bool is_loopback_or_any(const Locator_t& l) {
  if (l.kind != LOCATOR_KIND_UDPv4) return false;
  return IPLocator::isAny(l) || l.address[12] == 127;
}

void check_list(const LocatorList_t& list, const char* what, std::string& out) {
  for (const Locator_t& l : list) {
    if (!is_loopback_or_any(l)) out += std::string(what) + ": a locator that is not UDPv4 on 127.0.0.1\n";
  }
}

}  // namespace

std::string check_domain(int domain) {
  if (domain < 0 || domain > kMaxDomainId) {
    return "domain " + std::to_string(domain) + " out of range 0.." + std::to_string(kMaxDomainId) +
           " (UDP ports 7400 + 250 x domain must stay below 65536)";
  }
  return {};
}

fdds::DomainParticipantQos loopback_participant_qos(const std::string& name) {
  // Built from the code defaults, not from get_default_participant_qos(): an XML profile in the environment
  // (FASTRTPS_DEFAULT_PROFILES_FILE, ./DEFAULT_FASTRTPS_PROFILES.xml) cannot change the transports.
  fdds::DomainParticipantQos qos;
  qos.name(name);
  qos.transport().use_builtin_transports = false;
  auto udp = std::make_shared<UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.emplace_back(kLoopback);
  udp->maxInitialPeersRange = 32;  // default 4: with unicast discovery only participant ids 0..3 were found
  qos.transport().user_transports.push_back(udp);

  auto& builtin = qos.wire_protocol().builtin;
  builtin.metatrafficUnicastLocatorList.clear();
  builtin.metatrafficMulticastLocatorList.clear();
  builtin.initialPeersList.clear();
  Locator_t any;  // UDPv4, address 0, port 0: a non-empty list keeps Fast DDS from adding multicast locators
  any.kind = LOCATOR_KIND_UDPv4;
  builtin.metatrafficUnicastLocatorList.push_back(any);
  Locator_t peer;  // port 0: the well-known discovery ports of every participant id
  peer.kind = LOCATOR_KIND_UDPv4;
  IPLocator::setIPv4(peer, 127, 0, 0, 1);
  builtin.initialPeersList.push_back(peer);
  qos.wire_protocol().default_multicast_locator_list.clear();
  return qos;
}

std::string loopback_violations(const fdds::DomainParticipantQos& qos) {
  std::string out;
  if (qos.transport().use_builtin_transports)
    out += "builtin transports enabled (UDPv4 on every interface)\n";
  if (qos.transport().user_transports.empty()) out += "no user transport\n";
  for (const auto& t : qos.transport().user_transports) {
    if (const auto* udp = dynamic_cast<const UDPv4TransportDescriptor*>(t.get())) {
      if (udp->interfaceWhiteList.size() != 1 || udp->interfaceWhiteList.front() != kLoopback) {
        out += "UDPv4 transport not whitelisted to exactly 127.0.0.1\n";
      }
    } else if (dynamic_cast<const SharedMemTransportDescriptor*>(t.get()) == nullptr) {
      out += "a transport that is neither UDPv4 on 127.0.0.1 nor shared memory\n";
    }
  }
  const auto& builtin = qos.wire_protocol().builtin;
  if (builtin.metatrafficUnicastLocatorList.empty()) {
    out += "empty metatraffic unicast locator list (Fast DDS then adds multicast discovery)\n";
  }
  if (!builtin.metatrafficMulticastLocatorList.empty()) out += "metatraffic multicast locators\n";
  if (!qos.wire_protocol().default_multicast_locator_list.empty()) out += "default multicast locators\n";
  check_list(builtin.metatrafficUnicastLocatorList, "metatraffic unicast", out);
  check_list(builtin.initialPeersList, "initial peers", out);
  check_list(qos.wire_protocol().default_unicast_locator_list, "default unicast", out);
  return out;
}

fdds::DataWriterQos cyclic_writer_qos() {
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  qos.data_sharing().off();  // /dev/shm segments would outlive a killed process (TOOLCHAIN §11.7)
  return qos;
}

fdds::DataReaderQos cyclic_reader_qos() {
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  // More than 1: answers of two gateways may arrive between two takes of the listener; each is routed.
  qos.history().depth = 4;
  qos.data_sharing().off();
  return qos;
}

fdds::DataWriterQos status_writer_qos() {
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  qos.data_sharing().off();
  fast_repair(qos);
  return qos;
}

fdds::DataReaderQos status_reader_qos() {
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 4;
  qos.data_sharing().off();
  return qos;
}

fdds::DataWriterQos command_writer_qos() {
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 16;
  qos.data_sharing().off();
  fast_repair(qos);
  return qos;
}

fdds::DataReaderQos command_reader_qos() {
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 16;
  qos.data_sharing().off();
  return qos;
}

Participant::Participant(int domain, const std::string& name, const std::string& partition) {
  if (const auto problem = check_domain(domain); !problem.empty()) throw std::runtime_error(problem);
  const fdds::DomainParticipantQos qos = loopback_participant_qos(name);
  if (const auto leaks = loopback_violations(qos); !leaks.empty()) {
    throw std::logic_error("DDS participant QoS is not loopback-only:\n" + leaks);
  }
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  participant_ = factory->create_participant(static_cast<fdds::DomainId_t>(domain), qos);
  if (participant_ == nullptr) {
    throw std::runtime_error("Fast DDS could not create a participant on domain " + std::to_string(domain));
  }
  fdds::PublisherQos pq = fdds::PUBLISHER_QOS_DEFAULT;
  fdds::SubscriberQos sq = fdds::SUBSCRIBER_QOS_DEFAULT;
  if (!partition.empty()) {
    pq.partition().push_back(partition.c_str());
    sq.partition().push_back(partition.c_str());
  }
  publisher_ = participant_->create_publisher(pq);
  subscriber_ = participant_->create_subscriber(sq);
  if (publisher_ == nullptr || subscriber_ == nullptr) {
    participant_->delete_contained_entities();
    factory->delete_participant(participant_);
    throw std::runtime_error("Fast DDS could not create a publisher/subscriber on domain " +
                             std::to_string(domain));
  }
}

Participant::~Participant() {
  participant_->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

fdds::Topic& Participant::topic(const std::string& name, fdds::TypeSupport type) {
  if (participant_->find_type(type.get_type_name()).empty()) {
    if (type.register_type(participant_) != ReturnCode_t::RETCODE_OK) {
      throw std::runtime_error("Fast DDS could not register type " + type.get_type_name());
    }
  }
  if (auto* existing = dynamic_cast<fdds::Topic*>(participant_->lookup_topicdescription(name)))
    return *existing;
  fdds::Topic* t = participant_->create_topic(name, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  if (t == nullptr) throw std::runtime_error("Fast DDS could not create topic " + name);
  return *t;
}

}  // namespace tomc::drives::dds
