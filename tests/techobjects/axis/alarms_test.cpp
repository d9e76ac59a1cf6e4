// Technology alarms: classes and acknowledgement (spec 01 §7, spec 04 §0.5), ErrorDetail priority, the log.
#include <gtest/gtest.h>

#include <vector>

#include "tomc/techobjects/axis/alarms.hpp"

namespace {

using namespace tomc::techobjects;

// spec 02 §1.3 / spec 04 §7: the manual's alarms carry their stated reactions.
TEST(Alarms, DefinitionsCarryTheManualsReactions) {
  const struct {
    std::uint32_t number;
    AlarmReaction reaction;
    AlarmClass alarm_class;
  } expected[] = {
      {421, AlarmReaction::kRemoveEnable, AlarmClass::kAcknowledge},
      {501, AlarmReaction::kNone, AlarmClass::kWarning},
      {502, AlarmReaction::kNone, AlarmClass::kWarning},
      {503, AlarmReaction::kNone, AlarmClass::kWarning},
      {521, AlarmReaction::kRemoveEnable, AlarmClass::kAcknowledge},
      {522, AlarmReaction::kNone, AlarmClass::kWarning},
      {541, AlarmReaction::kRemoveEnable, AlarmClass::kAcknowledge},
      {550, AlarmReaction::kFollowSetpoint, AlarmClass::kAcknowledge},
      {412, AlarmReaction::kRemoveEnable, AlarmClass::kAcknowledge},
  };
  for (const auto& e : expected) {
    const auto* d = find_alarm(e.number);
    ASSERT_NE(d, nullptr) << e.number;
    EXPECT_EQ(d->reaction, e.reaction) << e.number;
    EXPECT_EQ(d->alarm_class, e.alarm_class) << e.number;
    EXPECT_FALSE(d->text.empty());
  }
  EXPECT_EQ(find_alarm(999), nullptr);
}

// spec 01 §7 (acknowledgement with MC_Reset), spec 04 §0.5 (alarm classes).
TEST(Alarms, RaiseOnceAndAcknowledge) {
  AlarmList list;
  EXPECT_TRUE(list.raise(kAlarmFollowingErrorWarning, 0, 10));
  EXPECT_TRUE(list.any_warning());
  EXPECT_FALSE(list.any_error());
  EXPECT_TRUE(list.raise(kAlarmFollowingError, 0, 11));
  EXPECT_TRUE(list.raise(kAlarmFollowingError, 7, 12));  // already pending: kept once, first record wins
  EXPECT_EQ(list.alarms().size(), 2u);
  EXPECT_TRUE(list.any_error());
  EXPECT_EQ(list.strongest_reaction(), AlarmReaction::kRemoveEnable);
  EXPECT_FALSE(list.raise(12345, 0, 13));  // unknown number
  // spec 01 §7: MC_Reset (Restart = FALSE) acknowledges W and F alarms.
  EXPECT_EQ(list.acknowledge(false, 20), 2u);
  EXPECT_TRUE(list.alarms().empty());
  EXPECT_EQ(list.strongest_reaction(), AlarmReaction::kNone);
  EXPECT_EQ(list.error_detail(), nullptr);
}

// ErrorDetail shows the highest-priority pending alarm: strongest reaction, then the oldest.
// spec 02 §1.1 (ErrorDetail.Reaction), spec 04 §0.5 (alarm classes).
TEST(Alarms, ErrorDetailPriority) {
  AlarmList list;
  list.raise(kAlarmSoftwareLimitReached, 0, 1);     // reaction 2
  list.raise(kAlarmDynamicsLimitedVelocity, 0, 2);  // warning
  ASSERT_NE(list.error_detail(), nullptr);
  EXPECT_EQ(list.error_detail()->number, kAlarmSoftwareLimitReached);
  list.raise(kAlarmPositioning, 1, 3);  // remove enable
  EXPECT_EQ(list.error_detail()->number, kAlarmPositioning);
  EXPECT_EQ(list.error_detail()->additional_value, 1u);
  list.raise(kAlarmFollowingError, 0, 4);  // also remove enable, newer
  EXPECT_EQ(list.error_detail()->number, kAlarmPositioning);
  // A reaction given at raise time (configurable alarms) is the one that counts.
  AlarmList configured;
  configured.raise(kAlarmSoftwareLimitExceeded, 0, AlarmReaction::kStopEmergencyRamp, 5);
  EXPECT_EQ(configured.strongest_reaction(), AlarmReaction::kStopEmergencyRamp);
}

// Decision M1 (a TO keeps its 16 pending alarms).
TEST(Alarms, ListCapacityIsBounded) {
  AlarmList list;
  std::size_t raised = 0;
  for (const auto& d : alarm_definitions())
    raised += list.raise(d.number, 0, 1) ? 1 : 0;
  EXPECT_EQ(raised, std::min(alarm_definitions().size(), AlarmList::kCapacity));
}

// Decision M1 (one alarm ring per runtime, 1,024 events).
TEST(Alarms, LogKeepsTheHistoryAndCountsLosses) {
  AlarmLog runtime_log;  // the runtime's (Runtime::add_technology_object attaches it)
  AlarmList list;
  list.attach(runtime_log, 1);
  list.raise(kAlarmDriveFault, 0, 100);
  list.acknowledge(false, 150);
  std::vector<AlarmEvent> out(8);
  const auto n = list.log().copy_since(0, out);
  ASSERT_EQ(n, 2u);
  EXPECT_EQ(out[0].kind, AlarmEvent::Kind::kRaised);
  EXPECT_EQ(out[0].cycle, 100u);
  EXPECT_EQ(out[1].kind, AlarmEvent::Kind::kAcknowledged);
  EXPECT_EQ(out[1].sequence, 2u);
  EXPECT_EQ(list.log().copy_since(2, out), 0u);

  AlarmLog log;
  for (std::uint64_t i = 0; i < AlarmLog::kCapacity + 10; ++i)
    log.append(AlarmEvent{0, i, AlarmEvent::Kind::kRaised, 401, 0, {}});
  EXPECT_EQ(log.last_sequence(), AlarmLog::kCapacity + 10);
  EXPECT_EQ(log.lost_before(), 11u);
  std::vector<AlarmEvent> all(AlarmLog::kCapacity + 10);
  const auto copied = log.copy_since(0, all);
  EXPECT_EQ(copied, AlarmLog::kCapacity);
  EXPECT_EQ(all[0].sequence, 11u);
  EXPECT_EQ(all[0].cycle, 10u);
}

// One log per runtime: each TO sees its own events, numbered 1, 2, ... as before (issue 14), and an
// unattached list still counts its events.
TEST(Alarms, OneLogPerRuntimeShowsEachListItsOwnEvents) {
  AlarmLog runtime_log;
  AlarmList a;
  AlarmList b;
  a.attach(runtime_log, 1);
  b.attach(runtime_log, 2);
  a.raise(kAlarmDriveFault, 7, 10);
  b.raise(kAlarmFollowingError, 0, 11);
  b.acknowledge(false, 12);
  a.raise(kAlarmSensorFault, 3, 13);
  EXPECT_EQ(runtime_log.last_sequence(), 4u);
  std::vector<AlarmEvent> out(8);
  ASSERT_EQ(a.log().last_sequence(), 2u);
  ASSERT_EQ(a.log().copy_since(0, out), 2u);
  EXPECT_EQ(out[0].number, kAlarmDriveFault);
  EXPECT_EQ(out[0].sequence, 1u);
  EXPECT_EQ(out[1].number, kAlarmSensorFault);
  EXPECT_EQ(out[1].sequence, 2u);
  ASSERT_EQ(a.log().copy_since(1, out), 1u);
  EXPECT_EQ(out[0].number, kAlarmSensorFault);
  ASSERT_EQ(b.log().copy_since(0, out), 2u);
  EXPECT_EQ(out[0].kind, AlarmEvent::Kind::kRaised);
  EXPECT_EQ(out[1].kind, AlarmEvent::Kind::kAcknowledged);
  EXPECT_EQ(out[1].cycle, 12u);
  // A full copy buffer takes the oldest first.
  std::vector<AlarmEvent> one(1);
  ASSERT_EQ(a.log().copy_since(0, one), 1u);
  EXPECT_EQ(one[0].sequence, 1u);

  AlarmList alone;
  alone.raise(kAlarmDriveFault, 0, 1);
  EXPECT_EQ(alone.log().last_sequence(), 1u);
  EXPECT_EQ(alone.log().copy_since(0, out), 0u);
}

// Events of a TO overwritten by the other TOs' events are lost, never shown wrong.
// Decision M1 (a TO's view of the shared ring).
TEST(Alarms, ViewOfAnOverwrittenHistoryShowsWhatIsKept) {
  AlarmLog runtime_log;
  AlarmList quiet;
  AlarmList busy;
  quiet.attach(runtime_log, 1);
  busy.attach(runtime_log, 2);
  quiet.raise(kAlarmDriveFault, 0, 1);
  for (std::uint64_t i = 0; i < AlarmLog::kCapacity; ++i) {
    busy.raise(kAlarmFollowingError, 0, 2 + i);
    busy.acknowledge(false, 2 + i);
  }
  std::vector<AlarmEvent> out(4);
  EXPECT_EQ(quiet.log().last_sequence(), 1u);
  EXPECT_EQ(quiet.log().copy_since(0, out), 0u);
  ASSERT_EQ(busy.log().copy_since(2 * AlarmLog::kCapacity - 2, out), 2u);
  EXPECT_EQ(out[1].sequence, 2 * AlarmLog::kCapacity);
}

}  // namespace
