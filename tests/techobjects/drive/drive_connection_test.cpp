// The axis side of the PROFIdrive link against the simulated drive, cycle by cycle: enable sequence
// (spec 06 §4.3), speed setpoint, StatusDrive.CommunicationOK and its causes (seed L11468), sign-of-life in
// both directions (spec 06 §5), link loss and fault acknowledge (TV26).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace {

namespace tg = tomc::telegrams;
using namespace tomc::techobjects;
using tomc::drives::DeviceConfig;
using tomc::drives::SimulatedDrive;
using tomc::drives::SimulatedDriveParameters;

class ConnectionObject final : public TechnologyObject {
 public:
  ConnectionObject(DeviceIo& io, const DriveConnectionConfig& config) : connection(io, config) {}
  std::string_view name() const noexcept override { return "connection"; }
  void servo(const CycleClock&) noexcept override {
    connection.read();
    zsw1_seen.push_back(connection.drive_actual().ZSW1.value());
    connection.write(command);
    stw1_sent.push_back(connection.drive_setpoint().STW1.value());
  }
  void interpolate(const CycleClock&) noexcept override {}
  DriveConnection connection;
  ServoCommand command;
  std::vector<std::uint16_t> zsw1_seen;
  std::vector<std::uint16_t> stw1_sent;
};

struct Machine {
  explicit Machine(std::uint16_t telegram, SimulatedDriveParameters p = {}, DriveConnectionConfig c = {})
      : runtime(RuntimeConfig{p.servo_cycle_s, 1, 1}) {
    DeviceConfig device;
    device.drive_telegram = telegram;
    auto owned = std::make_unique<SimulatedDrive>(device, p);
    drive = owned.get();
    auto& io = runtime.add_device(std::move(owned));
    object = &runtime.emplace<ConnectionObject>(io, c);
    runtime.start();
  }
  DriveConnection& connection() { return object->connection; }
  void run(int cycles) {
    for (int i = 0; i < cycles; ++i)
      runtime.step();
  }
  // Runs until the predicate holds; returns the number of cycles, or -1 after `limit`.
  template <typename Predicate>
  int run_until(Predicate done, int limit) {
    for (int i = 1; i <= limit; ++i) {
      runtime.step();
      if (done()) return i;
    }
    return -1;
  }
  Runtime runtime;
  SimulatedDrive* drive = nullptr;
  ConnectionObject* object = nullptr;
};

// spec 06 §4.3: 0x047E until S2, then 0x047F; the drive answers S0 -> S1 -> S2 -> S3 -> S4, one step per
// cycle. In S4 the simulated drive also sets ZSW1.8 (speed setpoint/actual deviation within tolerance) as a
// SINAMICS does, so S4 at standstill reads 0x0337 where spec 06 §4.2 shows 0x0237 with bit 8 left out.
TEST(DriveConnection, EnableSequenceWordByWord) {
  Machine m(3);
  m.connection().request(tg::DriveRequest::kOperate);
  const int cycles = m.run_until([&] { return m.connection().in_operation(); }, 50);
  EXPECT_EQ(cycles, 5);
  const std::vector<std::uint16_t> zsw1 = {0x0000, 0x0270, 0x0231, 0x0233, 0x0337};
  const std::vector<std::uint16_t> stw1 = {0x047E, 0x047E, 0x047F, 0x047F, 0x047F};
  EXPECT_EQ(m.object->zsw1_seen, zsw1);
  EXPECT_EQ(m.object->stw1_sent, stw1);
  EXPECT_TRUE(m.connection().communication_ok());
  EXPECT_EQ(m.drive->state(), tg::DriveState::kS4Operation);
}

// Before cyclic data the drive does not request control: CommunicationOK = FALSE (seed L11468).
// Decision R9 (CommunicationOK FALSE while ZSW1.9 "control requested" is 0).
TEST(DriveConnection, NotControlledBeforeTheDriveAnswers) {
  Machine m(2);
  m.run(1);
  EXPECT_FALSE(m.connection().communication_ok());
  EXPECT_EQ(m.connection().communication_fault(), CommunicationFault::kNotControlled);
  m.run(1);
  EXPECT_TRUE(m.connection().communication_ok());
}

// The speed setpoint goes out as NSOLL_B (N4 of the reference speed) and comes back as NIST_B.
TEST(DriveConnection, SpeedSetpointIsFollowed) {
  Machine m(2);
  m.connection().request(tg::DriveRequest::kOperate);
  m.run(5);
  ASSERT_TRUE(m.connection().in_operation());
  m.object->command.speed_rpm = 1500.0;
  m.run(1);
  EXPECT_EQ(m.connection().drive_setpoint().NSOLL_B, 0x20000000);  // spec 06 TV03: 1500 of 3000 rpm
  // First-order speed loop, T = 2 ms, one cycle of transport delay: after 40 ms within 0.1 %.
  m.run(40);
  EXPECT_NEAR(m.connection().actual_speed_rpm(), 1500.0, 1.5);
  EXPECT_NEAR(m.drive->motor_speed_rpm(), 1500.0, 1.5);
}

// spec 06 §5.2 with tolerance 1: the second wrong slave value trips; CommunicationOK drops in that cycle.
TEST(DriveConnection, FrozenDriveSignOfLifeTripsInToleranceCycles) {
  Machine m(3);
  m.connection().request(tg::DriveRequest::kOperate);
  m.run(10);
  ASSERT_TRUE(m.connection().communication_ok());
  m.drive->freeze_sign_of_life(true);
  m.run(1);  // the frozen value repeats once: first error, counter 10, not above 10
  EXPECT_TRUE(m.connection().communication_ok());
  m.run(1);  // second error: counter 20 > 10
  EXPECT_EQ(m.connection().communication_fault(), CommunicationFault::kSignOfLifeFailed);
  EXPECT_FALSE(m.connection().in_operation());
  // Repaired and acknowledged: the monitor resynchronises.
  m.drive->freeze_sign_of_life(false);
  m.connection().acknowledge();
  m.run(2);
  EXPECT_TRUE(m.connection().communication_ok());
}

// Telegram 1 carries no STW2/ZSW2: there is no sign-of-life to check, so none fails.
// spec 06 §2.1 (telegram 1 is STW1/NSOLL_A and ZSW1/NIST_A: no STW2/ZSW2) and §5.1 (the sign-of-life lives
// in STW2/ZSW2).
TEST(DriveConnection, TelegramOneHasNoSignOfLife) {
  Machine m(1);
  m.connection().request(tg::DriveRequest::kOperate);
  m.run(10);
  m.drive->freeze_sign_of_life(true);
  m.run(10);
  EXPECT_TRUE(m.connection().in_operation());
}

// Link loss: CommunicationOK drops once more cycles than the tolerance have no fresh frame; the drive itself
// faults after its setpoint timeout (F08501, OFF3); after the link returns, acknowledge recovers (TV26).
// Decision R9 (more than link_loss_tolerance_cycles without a fresh frame), decision R7 (F08501 setpoint
// timeout, OFF3), spec 06 §11 TV26 (acknowledge).
TEST(DriveConnection, LinkLossAndRecovery) {
  SimulatedDriveParameters p;
  p.setpoint_timeout_cycles = 20;
  DriveConnectionConfig c;
  c.link_loss_tolerance_cycles = 3;
  Machine m(3, p, c);
  m.connection().request(tg::DriveRequest::kOperate);
  m.run(10);
  ASSERT_TRUE(m.connection().in_operation());
  m.drive->set_link_lost(true);
  m.run(3);
  EXPECT_TRUE(m.connection().communication_ok());  // 3 missed = the tolerance
  m.run(1);
  EXPECT_EQ(m.connection().communication_fault(), CommunicationFault::kLinkLost);
  // The setpoint of the last good cycle still arrived; 20 missed setpoints later the drive faults.
  m.run(16);
  EXPECT_EQ(m.drive->active_fault(), 0u);
  m.run(1);
  EXPECT_EQ(m.drive->active_fault(), tomc::drives::kFaultSetpointTimeout);
  m.drive->set_link_lost(false);
  m.run(2);
  EXPECT_EQ(m.connection().communication_fault(), CommunicationFault::kDriveFault);
  m.connection().acknowledge();
  const int cycles = m.run_until([&] { return m.connection().in_operation(); }, 100);
  EXPECT_GT(cycles, 0);
  EXPECT_EQ(m.drive->active_fault(), 0u);
}

// Frames that do not arrive are the link monitor's business (up to link_loss_tolerance_cycles ride through,
// R9), not sign-of-life errors (spec 06 §5.2): the drive counts on while its frames are lost, and the monitor
// resynchronises on the first fresh frame after the gap, so gaps of 1, 2 and 3 cycles, three times each,
// leave CommunicationOK and the drive in operation (a monitor that kept its expectation over the gap would
// see every later frame 1-3 ahead and raise 406).
TEST(DriveConnection, ShortFrameGapsAreNoSignOfLifeErrors) {
  for (int gap = 1; gap <= 3; ++gap) {
    SCOPED_TRACE(gap);
    DriveConnectionConfig c;
    c.link_loss_tolerance_cycles = 3;
    Machine m(3, {}, c);
    m.connection().request(tg::DriveRequest::kOperate);
    m.run(10);
    ASSERT_TRUE(m.connection().in_operation());
    for (int repeat = 0; repeat < 3; ++repeat) {  // three gaps, 15 cycles apart
      m.drive->set_link_lost(true);
      m.run(gap);
      m.drive->set_link_lost(false);
      m.run(15);
      EXPECT_TRUE(m.connection().communication_ok());
      EXPECT_NE(m.connection().communication_fault(), CommunicationFault::kSignOfLifeFailed);
    }
    EXPECT_TRUE(m.connection().in_operation());
  }
}

// spec 06 TV26 through the connection: fault 0x0248 -> 0x04FE once -> 0x047E -> 0x0270 -> 0x0231 -> 0x047F.
TEST(DriveConnection, FaultAcknowledgeSequence) {
  Machine m(2);
  m.connection().request(tg::DriveRequest::kOperate);
  m.run(10);
  m.drive->inject_fault(7860, SimulatedDriveParameters::FaultReaction::kOff2);
  m.run(3);
  EXPECT_EQ(m.connection().communication_fault(), CommunicationFault::kDriveFault);
  EXPECT_EQ(m.connection().drive_actual().ZSW1.value(), 0x0248);
  // Acknowledge while the cause is present: nothing changes.
  m.connection().acknowledge();
  m.run(3);
  EXPECT_EQ(m.connection().drive_actual().ZSW1.value(), 0x0248);
  m.drive->clear_injected_fault();
  m.object->zsw1_seen.clear();
  m.object->stw1_sent.clear();
  m.connection().acknowledge();
  m.run(5);
  const std::vector<std::uint16_t> stw1 = {0x04FE, 0x047E, 0x047F, 0x047F, 0x047F};
  const std::vector<std::uint16_t> zsw1 = {0x0248, 0x0270, 0x0231, 0x0233, 0x0337};
  EXPECT_EQ(m.object->stw1_sent, stw1);
  EXPECT_EQ(m.object->zsw1_seen, zsw1);
  EXPECT_TRUE(m.connection().in_operation());
}

// A link partner that restarted (LinkHealth::peer_restarts, e.g. a gateway with a new incarnation,
// docs/gateway.md) is a link loss in the cycle it is seen, although frames keep arriving; the next fresh
// frame recovers the link.
class RestartingLink final : public tomc::drives::DriveAdapter {
 public:
  RestartingLink(const DeviceConfig& c, const SimulatedDriveParameters& p) : drive(c, p) {}
  const DeviceConfig& config() const noexcept override { return drive.config(); }
  bool read_actual(tomc::drives::DeviceFrames& a) noexcept override { return drive.read_actual(a); }
  void write_setpoint(const tomc::drives::DeviceFrames& s) noexcept override { drive.write_setpoint(s); }
  tomc::drives::LinkHealth link_health() const noexcept override {
    auto h = drive.link_health();
    h.peer_restarts = restarts;
    return h;
  }
  SimulatedDrive drive;
  std::uint32_t restarts = 0;
};

// Decision G6 (a peer restart faster than the link tolerance is still a link loss, counted beyond the
// tolerance).
TEST(DriveConnection, PeerRestartIsALinkLoss) {
  Runtime runtime(RuntimeConfig{0.001, 1, 1});
  DeviceConfig device;
  device.drive_telegram = 3;
  auto owned = std::make_unique<RestartingLink>(device, SimulatedDriveParameters{});
  RestartingLink* link = owned.get();
  auto& io = runtime.add_device(std::move(owned));
  DriveConnectionConfig c;
  c.link_loss_tolerance_cycles = 3;
  auto& object = runtime.emplace<ConnectionObject>(io, c);
  runtime.start();
  object.connection.request(tg::DriveRequest::kOperate);
  for (int i = 0; i < 10; ++i)
    runtime.step();
  ASSERT_TRUE(object.connection.communication_ok());
  link->restarts = 1;
  runtime.step();
  EXPECT_EQ(object.connection.communication_fault(), CommunicationFault::kLinkLost);
  EXPECT_GT(object.connection.cycles_without_fresh_frame(), c.link_loss_tolerance_cycles);
  runtime.step();
  EXPECT_TRUE(object.connection.communication_ok());
  EXPECT_EQ(object.connection.cycles_without_fresh_frame(), 0u);
}

}  // namespace
