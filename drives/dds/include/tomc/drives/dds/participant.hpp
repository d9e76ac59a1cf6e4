#pragma once
// Every DDS participant tomc creates — the gateway adapter's, the gateway simulator's, the tests' — comes
// from here, so that none of them can send anything but unicast on the one configured interface: loopback
// by default (TOOLCHAIN.md §5: with default settings Fast DDS sends multicast out of every interface), or
// the interface and peers of a NetworkSettings (network.hpp). The per-topic QoS of the contract is here too,
// so both sides of the contract use the same (docs/gateway.md "QoS").
//
// This header includes Fast DDS: only the DDS adapter, the gateway simulator and their tests include it.

#include <memory>
#include <string>

#include "tomc/drives/dds/network.hpp"

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

namespace tomc::drives::dds {

// UDP ports are 7400 + 250 × domain + offsets: domain ids above 232 do not fit.
inline constexpr int kMaxDomainId = 232;
// Empty if `domain` is usable, else why not.
std::string check_domain(int domain);

inline constexpr const char* kSetpointTopic = "tomc/gateway/setpoint";
inline constexpr const char* kActualTopic = "tomc/gateway/actual";
inline constexpr const char* kStatusTopic = "tomc/gateway/status";
inline constexpr const char* kCommandTopic = "tomc/gateway/command";

// The participant QoS of every tomc participant on `network`: no builtin transports (so no shared memory and
// no multicast discovery), one UDPv4 transport whitelisted to the network's one address, unicast metatraffic
// locators (a non-empty list keeps Fast DDS from adding its multicast ones) and discovery by unicast to the
// well-known ports of the peers for participant ids 0..kProbedParticipantIds-1. Only when the network asks
// for multicast discovery: SPDP multicast to 239.255.0.1 on port 7400 + 250 × domain as well.
eprosima::fastdds::dds::DomainParticipantQos participant_qos(const std::string& name, int domain,
                                                             const ResolvedNetwork& network);
// participant_qos() on loopback_network(): 127.0.0.1 only.
eprosima::fastdds::dds::DomainParticipantQos loopback_participant_qos(const std::string& name);

// Empty when `qos` can send nothing but unicast on `network`'s address to its peers (and multicast discovery
// only if it asks for it); else each reason, one per line. The factory below refuses a QoS that fails it.
std::string network_violations(const eprosima::fastdds::dds::DomainParticipantQos& qos,
                               const ResolvedNetwork& network);
// network_violations() against loopback_network(): the check of the loopback test.
std::string loopback_violations(const eprosima::fastdds::dds::DomainParticipantQos& qos);

// QoS of the cyclic topics (setpoint, actual): best effort, volatile, keep last 1, no data sharing. A late or
// lost sample is never repeated: the next cycle's sample supersedes it (docs/gateway.md "QoS").
eprosima::fastdds::dds::DataWriterQos cyclic_writer_qos();
eprosima::fastdds::dds::DataReaderQos cyclic_reader_qos();
// QoS of the status topic: reliable, transient local, keep last 1 — a controller that starts later gets the
// gateway's newest status.
eprosima::fastdds::dds::DataWriterQos status_writer_qos();
eprosima::fastdds::dds::DataReaderQos status_reader_qos();
// QoS of the simulator's command topic: reliable, volatile (a restarted simulator must not replay old
// commands), keep last 16.
eprosima::fastdds::dds::DataWriterQos command_writer_qos();
eprosima::fastdds::dds::DataReaderQos command_reader_qos();

// A participant with participant_qos() on `network` (loopback by default), one publisher and one subscriber
// in `partition` ("" = the default partition; the partition is a Publisher and Subscriber QoS). Controller
// and gateway must use the same domain and partition. Deleting it deletes every entity it contains.
// Construction throws std::runtime_error when Fast DDS refuses.
class Participant {
 public:
  // `listener` (optional) gets the participant's discovery callbacks (remote participants and endpoints).
  Participant(int domain, const std::string& name, const std::string& partition,
              const ResolvedNetwork& network = loopback_network(),
              eprosima::fastdds::dds::DomainParticipantListener* listener = nullptr);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  eprosima::fastdds::dds::DomainParticipant& get() noexcept { return *participant_; }
  eprosima::fastdds::dds::Publisher& publisher() noexcept { return *publisher_; }
  eprosima::fastdds::dds::Subscriber& subscriber() noexcept { return *subscriber_; }
  // The topic `name` of `type`, registering the type on first use.
  eprosima::fastdds::dds::Topic& topic(const std::string& name, eprosima::fastdds::dds::TypeSupport type);

 private:
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
};

}  // namespace tomc::drives::dds
