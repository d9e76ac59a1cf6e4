// The participant limited to one configured interface (loopback by default) and the contract's QoS
// (participant.hpp, network.hpp, docs/gateway.md).
#include "tomc/drives/dds/participant.hpp"

#include <algorithm>
#include <stdexcept>

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <fastrtps/xmlparser/XMLProfileManager.h>
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

// Reliable writers announce their samples every 50 ms instead of Fast DDS's 3 s: a status or command sample
// lost before the reader had fully matched is repaired within a few cycles of the watchdog, not seconds later
// (TOOLCHAIN §11.6).
void fast_repair(fdds::DataWriterQos& qos) {
  qos.reliable_writer_qos().times.heartbeatPeriod = eprosima::fastrtps::Duration_t(0, 50'000'000);
}

// The contract's data representation (docs/gateway.md §3): writers write XCDR1 and readers accept it, stated
// in the QoS so that a peer that offers or requests only XCDR2 does not match — and the discovery data says
// why (gateway_link.cpp diagnose()).
void xcdr1(fdds::DataRepresentationQosPolicy& policy) {
  policy.m_value.clear();
  policy.m_value.push_back(fdds::XCDR_DATA_REPRESENTATION);
}

bool same_ipv4(const Locator_t& l, const std::string& address) {
  return l.kind == LOCATOR_KIND_UDPv4 && IPLocator::toIPv4string(l) == address;
}

// A UDPv4 locator that is "any address" (the transport then uses its whitelisted interface) or the address.
bool is_own_or_any(const Locator_t& l, const std::string& address) {
  return l.kind == LOCATOR_KIND_UDPv4 && (IPLocator::isAny(l) || same_ipv4(l, address));
}

constexpr const char* kDiscoveryMulticast = "239.255.0.1";  // the RTPS default SPDP multicast group

}  // namespace

std::string check_domain(int domain) {
  if (domain < 0 || domain > kMaxDomainId) {
    return "domain " + std::to_string(domain) + " out of range 0.." + std::to_string(kMaxDomainId) +
           " (UDP ports 7400 + 250 x domain must stay below 65536)";
  }
  return {};
}

fdds::DomainParticipantQos participant_qos(const std::string& name, int domain,
                                           const ResolvedNetwork& network) {
  // Built from the code defaults, not from get_default_participant_qos(): an XML profile in the environment
  // (FASTRTPS_DEFAULT_PROFILES_FILE, ./DEFAULT_FASTRTPS_PROFILES.xml) cannot change the transports.
  fdds::DomainParticipantQos qos;
  qos.name(name);
  qos.transport().use_builtin_transports = false;
  auto udp = std::make_shared<UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.emplace_back(network.address);
  // Default 4: with unicast discovery only participant ids 0..3 were found.
  udp->maxInitialPeersRange = static_cast<std::uint32_t>(kProbedParticipantIds);
  qos.transport().user_transports.push_back(udp);

  auto& builtin = qos.wire_protocol().builtin;
  builtin.metatrafficUnicastLocatorList.clear();
  builtin.metatrafficMulticastLocatorList.clear();
  builtin.initialPeersList.clear();
  Locator_t any;  // UDPv4, address 0, port 0: a non-empty list keeps Fast DDS from adding multicast locators
  any.kind = LOCATOR_KIND_UDPv4;
  builtin.metatrafficUnicastLocatorList.push_back(any);
  for (const std::string& address : network.peers) {
    Locator_t peer;  // port 0: the well-known discovery ports of every participant id
    peer.kind = LOCATOR_KIND_UDPv4;
    IPLocator::setIPv4(peer, address);
    builtin.initialPeersList.push_back(peer);
  }
  if (network.multicast_discovery) {
    Locator_t group;
    IPLocator::createLocator(LOCATOR_KIND_UDPv4, kDiscoveryMulticast,
                             rtps_ports(domain, 0).discovery_multicast, group);
    builtin.metatrafficMulticastLocatorList.push_back(group);
    builtin.initialPeersList.push_back(group);
  }
  qos.wire_protocol().default_multicast_locator_list.clear();
  return qos;
}

fdds::DomainParticipantQos loopback_participant_qos(const std::string& name) {
  return participant_qos(name, 0, loopback_network());
}

std::string network_violations(const fdds::DomainParticipantQos& qos, const ResolvedNetwork& network) {
  std::string out;
  const std::string& address = network.address;
  if (qos.transport().use_builtin_transports)
    out += "builtin transports enabled (UDPv4 on every interface)\n";
  if (qos.transport().user_transports.empty()) out += "no user transport\n";
  for (const auto& t : qos.transport().user_transports) {
    if (const auto* udp = dynamic_cast<const UDPv4TransportDescriptor*>(t.get())) {
      if (udp->interfaceWhiteList.size() != 1 || udp->interfaceWhiteList.front() != address) {
        out += "UDPv4 transport not whitelisted to exactly " + address + "\n";
      }
    } else if (dynamic_cast<const SharedMemTransportDescriptor*>(t.get()) == nullptr) {
      out += "a transport that is neither UDPv4 on " + address + " nor shared memory\n";
    }
  }
  const auto& builtin = qos.wire_protocol().builtin;
  if (builtin.metatrafficUnicastLocatorList.empty()) {
    out += "empty metatraffic unicast locator list (Fast DDS then adds multicast discovery)\n";
  }
  for (const Locator_t& l : builtin.metatrafficMulticastLocatorList) {
    if (!network.multicast_discovery || l.kind != LOCATOR_KIND_UDPv4 ||
        IPLocator::toIPv4string(l) != kDiscoveryMulticast) {
      out += "metatraffic multicast locators\n";
    }
  }
  if (!qos.wire_protocol().default_multicast_locator_list.empty()) out += "default multicast locators\n";
  for (const Locator_t& l : builtin.metatrafficUnicastLocatorList) {
    if (!is_own_or_any(l, address))
      out += "metatraffic unicast: a locator that is not UDPv4 on " + address + "\n";
  }
  for (const Locator_t& l : qos.wire_protocol().default_unicast_locator_list) {
    if (!is_own_or_any(l, address))
      out += "default unicast: a locator that is not UDPv4 on " + address + "\n";
  }
  for (const Locator_t& l : builtin.initialPeersList) {
    const bool listed = std::any_of(network.peers.begin(), network.peers.end(),
                                    [&](const std::string& p) { return same_ipv4(l, p); });
    const bool group = network.multicast_discovery && l.kind == LOCATOR_KIND_UDPv4 &&
                       IPLocator::toIPv4string(l) == kDiscoveryMulticast;
    if (!listed && !group) out += "initial peers: a locator that is not a configured peer\n";
  }
  return out;
}

std::string loopback_violations(const fdds::DomainParticipantQos& qos) {
  return network_violations(qos, loopback_network());
}

fdds::DataWriterQos cyclic_writer_qos() {
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = fdds::BEST_EFFORT_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  qos.data_sharing().off();  // /dev/shm segments would outlive a killed process (TOOLCHAIN §11.7)
  xcdr1(qos.representation());
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
  xcdr1(qos.type_consistency().representation);
  return qos;
}

fdds::DataWriterQos status_writer_qos() {
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  qos.data_sharing().off();
  xcdr1(qos.representation());
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
  xcdr1(qos.type_consistency().representation);
  return qos;
}

fdds::DataWriterQos command_writer_qos() {
  fdds::DataWriterQos qos = fdds::DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 16;
  qos.data_sharing().off();
  xcdr1(qos.representation());
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
  xcdr1(qos.type_consistency().representation);
  return qos;
}

Participant::Participant(int domain, const std::string& name, const std::string& partition,
                         const ResolvedNetwork& network, fdds::DomainParticipantListener* listener) {
  if (const auto problem = check_domain(domain); !problem.empty()) throw std::runtime_error(problem);
  if (network.address.empty()) throw std::invalid_argument("DDS participant: no interface address");
  const fdds::DomainParticipantQos qos = participant_qos(name, domain, network);
  if (const auto leaks = network_violations(qos, network); !leaks.empty()) {
    throw std::logic_error("DDS participant QoS is not limited to " + network.address + ":\n" + leaks);
  }
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  // No intra-process delivery: with it, Fast DDS 2.9 lets a participant's discovery writer keep a raw pointer
  // to the discovery reader of another participant of this process after that one was deleted, and a crash
  // follows when the survivor deletes an endpoint before the deletion reached it (issue 22, decision V10;
  // fixed upstream in eProsima/Fast-DDS#5034, not in Debian's 2.9). Participants of one process then exchange
  // through the loopback transport like separate processes. The default XML profiles are loaded first so
  // that a <library_settings> in them cannot turn it back on.
  factory->load_profiles();
  eprosima::fastrtps::LibrarySettingsAttributes library;
  library.intraprocess_delivery = eprosima::fastrtps::INTRAPROCESS_OFF;
  eprosima::fastrtps::xmlparser::XMLProfileManager::library_settings(library);
  // No status callbacks at participant level (the readers have their own listeners); discovery callbacks
  // reach `listener` regardless of the mask.
  participant_ = factory->create_participant(static_cast<fdds::DomainId_t>(domain), qos, listener,
                                             fdds::StatusMask::none());
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
