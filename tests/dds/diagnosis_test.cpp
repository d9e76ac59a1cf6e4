// Diagnosis a commissioning engineer can act on (issue 16, docs/gateway.md §8): "no gateway has announced
// itself" is a different report from "a DDS participant was discovered, but its endpoints do not match"
// (type name, partition, data representation, reliability/durability), and the latter names the difference.
// In one process on loopback: a GatewayLink and a hand-made "gateway" participant whose endpoints are wrong
// in one way each. And a drive whose sign-of-life never starts counting (a drive not in isochronous mode
// behind `tomc gateway-sim`) is flagged, while a counting one is not.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>

#include "gateway_process.hpp"
#include "tomc/drives/dds/gateway_link.hpp"
#include "tomc/drives/dds/participant.hpp"
#include "tomc/drives/dds/type_support.hpp"
#include "tomc/telegrams/layout.hpp"

namespace {

using namespace tomc::drives::dds;
namespace fdds = eprosima::fastdds::dds;

std::string partition() {
  return "tomc-diag-" + std::to_string(::getpid());
}

// Polls the link's report for device "axis1" until `done` holds or 5 s pass.
DeviceReport report_when(GatewayLink& link, const std::function<bool(const DeviceReport&)>& done) {
  DeviceReport r;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  do {
    r = link.diagnose().at(0);
    if (done(r)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  } while (std::chrono::steady_clock::now() < deadline);
  return r;
}

std::shared_ptr<GatewayLink> make_link(int domain) {
  GatewayLinkConfig config;
  config.domain = domain;
  config.partition = partition();
  auto link = GatewayLink::create(config);
  tomc::drives::DeviceConfig device;
  device.drive_telegram = 3;
  auto drive = link->make_drive("axis1", device);
  (void)drive;  // the report is per device; the adapter itself is not used here
  return link;
}

// Decision N7 ("no gateway" named with the domain and what discovery saw).
TEST(Diagnosis, NobodyOnTheDomainIsNoGateway) {
  auto link = make_link(163);
  const DeviceReport r = link->diagnose().at(0);
  EXPECT_EQ(r.diagnosis, DeviceDiagnosis::kNoGateway) << r.text;
  EXPECT_NE(r.text.find("no gateway has announced itself on DDS domain 163"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("no other DDS participant discovered"), std::string::npos) << r.text;
}

// A participant with nothing on the contract's topics is not a gateway: still "no gateway", naming it.
// Decision N7 (only endpoints on tomc/gateway/* make a gateway).
TEST(Diagnosis, AParticipantWithoutContractEndpointsIsStillNoGateway) {
  auto link = make_link(164);
  Participant other(164, "some other application", partition());
  const DeviceReport r = report_when(
      *link, [](const DeviceReport& x) { return x.text.find("discovered:") != std::string::npos; });
  EXPECT_EQ(r.diagnosis, DeviceDiagnosis::kNoGateway) << r.text;
  EXPECT_NE(
      r.text.find(
          "discovered: 'some other application'; none publishes tomc/gateway/status in this partition)"),
      std::string::npos)
      << r.text;
}

struct BadGateway {
  explicit BadGateway(int domain, const std::string& partition_name = partition())
      : participant(domain, "bad gateway", partition_name) {}
  Participant participant;
};

bool mismatched(const DeviceReport& r) {
  return r.diagnosis == DeviceDiagnosis::kEndpointMismatch;
}

// (Fast DDS 2.9 does not announce a writer's data representation, so the XCDR2 case of the same check is
// only reachable from another vendor's DDS; this is the writer side with a QoS Fast DDS does announce.)
// Decision N7 (durability compared), docs/gateway.md §3 (status: transient-local).
TEST(Diagnosis, AVolatileStatusWriterIsAnEndpointMismatch) {
  auto link = make_link(165);
  BadGateway gw(165);
  fdds::TypeSupport type(new GatewayStatusType());
  auto qos = status_writer_qos();
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  auto* writer = gw.participant.publisher().create_datawriter(&gw.participant.topic(kStatusTopic, type), qos);
  ASSERT_NE(writer, nullptr);
  const DeviceReport r = report_when(*link, mismatched);
  EXPECT_EQ(r.diagnosis, DeviceDiagnosis::kEndpointMismatch) << r.text;
  EXPECT_EQ(
      r.text,
      "DDS participant 'bad gateway' was discovered, but its endpoints do not match this controller's: its "
      "writer of tomc/gateway/status is volatile; the contract requires transient-local durability");
  EXPECT_STREQ(to_string(r.diagnosis), "endpoints do not match");
}

// Decision N7 (reliability compared), decision G3 (cyclic topics best effort).
TEST(Diagnosis, SetpointReaderAskingForReliableIsAnEndpointMismatch) {
  auto link = make_link(166);
  BadGateway gw(166);
  fdds::TypeSupport type(new SetpointCycleType());
  auto qos = cyclic_reader_qos();
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  ASSERT_NE(gw.participant.subscriber().create_datareader(&gw.participant.topic(kSetpointTopic, type), qos),
            nullptr);
  const DeviceReport r = report_when(*link, mismatched);
  EXPECT_EQ(r.diagnosis, DeviceDiagnosis::kEndpointMismatch) << r.text;
  EXPECT_NE(
      r.text.find(
          "its reader of tomc/gateway/setpoint requests reliable; the contract's writer is best effort"),
      std::string::npos)
      << r.text;
}

// Decision N7 (type name compared), docs/gateway.md §1 (the contract's type names).
TEST(Diagnosis, AnotherTypeNameIsAnEndpointMismatch) {
  auto link = make_link(167);
  BadGateway gw(167);
  auto* generated = new SetpointCycleType();
  generated->setName("gateway::Setpoints");
  fdds::TypeSupport type(generated);
  ASSERT_NE(gw.participant.subscriber().create_datareader(&gw.participant.topic(kSetpointTopic, type),
                                                          cyclic_reader_qos()),
            nullptr);
  const DeviceReport r = report_when(*link, mismatched);
  EXPECT_EQ(r.diagnosis, DeviceDiagnosis::kEndpointMismatch) << r.text;
  EXPECT_NE(
      r.text.find("its reader of tomc/gateway/setpoint has type 'gateway::Setpoints', the contract's is "
                  "'tomc::gateway::SetpointCycle'"),
      std::string::npos)
      << r.text;
}

// A gateway in another partition is another controller/gateway pair sharing the domain (docs/gateway.md §1),
// not a mismatch: "no gateway" in this partition, naming where gateways are.
TEST(Diagnosis, AGatewayInAnotherPartitionIsNoGatewayHere) {
  auto link = make_link(168);
  BadGateway gw(168, "elsewhere");
  fdds::TypeSupport type(new GatewayStatusType());
  ASSERT_NE(gw.participant.publisher().create_datawriter(&gw.participant.topic(kStatusTopic, type),
                                                         status_writer_qos()),
            nullptr);
  const DeviceReport r = report_when(
      *link, [](const DeviceReport& x) { return x.text.find("other partitions") != std::string::npos; });
  EXPECT_EQ(r.diagnosis, DeviceDiagnosis::kNoGateway) << r.text;
  EXPECT_NE(
      r.text.find("none publishes tomc/gateway/status in this partition); gateways in other partitions: "
                  "'bad gateway' in partition 'elsewhere'"),
      std::string::npos)
      << r.text;
}

// Drives `cycles` cycles of device axis1 (telegram 3) through `link`, with a counting master sign-of-life in
// STW2 as a controller in isochronous mode sends it (or STW2 0 without `count`); returns the device's report
// afterwards.
DeviceReport run_cycles(GatewayLink& link, DdsGatewayDrive& drive, int cycles, bool count) {
  namespace tg = tomc::telegrams;
  const auto layout = tg::find_layout(3, tg::Direction::kSetpoint);
  const auto stw2 = static_cast<std::size_t>(layout.value().offset_of(tg::Signal::STW2));
  auto actual = tomc::drives::make_frames(drive.config(), tg::Direction::kActual);
  auto setpoint = tomc::drives::make_frames(drive.config(), tg::Direction::kSetpoint);
  for (int cycle = 0; cycle < cycles; ++cycle) {
    (void)drive.read_actual(actual);
    setpoint[tomc::drives::Slot::kDrive].bytes[stw2] =
        static_cast<std::byte>(count ? ((cycle % 15) + 1) << 4 : 0);
    drive.write_setpoint(setpoint);
    // Lock-step: returns as soon as the answer is in; the bound stays below the gateway's 1 s watchdog. 200
    // ms was exceeded often enough on a busy machine to miss the 90 answers expected of 100 cycles.
    link.wait_for_answers(std::chrono::milliseconds(800));
  }
  return link.diagnose().at(0);
}

void sign_of_life_case(int domain, bool controller_counts, bool isochronous, DeviceDiagnosis expected) {
  const auto dir = tomc::testing::test_directory("sol" + std::to_string(domain));
  tomc::testing::GatewayProcess gateway(
      dir,
      R"({ "gateway": "gw1", "domain": )" + std::to_string(domain) +
          R"(, "cycle_time": 0.001, "watchdog": 1.0, "devices": [ { "name": "axis1", "drive": { "telegram": 3, "isochronous": )" +
          (isochronous ? "true" : "false") + " } } ] }");
  GatewayLinkConfig config;
  config.domain = domain;
  config.partition = tomc::testing::test_partition();
  config.max_answer_age_cycles = 0;
  auto link = GatewayLink::create(config);
  tomc::drives::DeviceConfig device;
  device.drive_telegram = 3;
  auto drive = link->make_drive("axis1", device);
  const auto reports = link->connect(std::chrono::seconds(10));
  ASSERT_EQ(reports.at(0).diagnosis, DeviceDiagnosis::kAnswering) << reports.at(0).text << gateway.log();
  const DeviceReport r = run_cycles(*link, *drive, 100, controller_counts);
  EXPECT_EQ(r.diagnosis, expected) << r.text;
  const auto counters = drive->counters();
  EXPECT_GE(counters.sign_of_life_answers, 90u);
  if (expected == DeviceDiagnosis::kSignOfLifeNotCounting) {
    EXPECT_EQ(counters.sign_of_life_changes, 0u);
    EXPECT_NE(
        r.text.find("'axis1' answers, but the drive's sign-of-life (ZSW2 bits 12..15) has not counted in"),
        std::string::npos)
        << r.text;
  } else if (isochronous) {
    EXPECT_GE(counters.sign_of_life_changes, 80u);
  }
  std::filesystem::remove_all(dir);
}

// Decision N8 (kSignOfLifeNotCounting after 32 answers without a change while ours counts).
TEST(Diagnosis, ASignOfLifeThatNeverCountsIsFlagged) {
  sign_of_life_case(169, true, false, DeviceDiagnosis::kSignOfLifeNotCounting);
}

// Decision N8 (a counting drive sign-of-life is not flagged).
TEST(Diagnosis, ACountingSignOfLifeIsNotFlagged) {
  sign_of_life_case(170, true, true, DeviceDiagnosis::kAnswering);
}

// Without isochronous operation neither side counts: nothing to flag.
// Decision N8 (only while the controller's own STW2 sign-of-life counts), spec 06 §5.1 (RT operation: 0
// accepted).
TEST(Diagnosis, NoSignOfLifeOnEitherSideIsNotFlagged) {
  sign_of_life_case(173, false, false, DeviceDiagnosis::kAnswering);
}

}  // namespace
