// What the cycle publishes (diagnostics.hpp): data-block values through the reflection table, the telegram
// words of the drive telegram with their probes, the alarm history, staggered publishing, program switches.
#include <gtest/gtest.h>

#include <chrono>
#include <set>

#include "diagnostics_fixture.hpp"
#include "tomc/telegrams/layout.hpp"

namespace {

using namespace tomc;
using tomc::testing::DiagnosticsMachine;
namespace tg = tomc::telegrams;

// ARCHITECTURE-GUIDE §3 (data blocks are data: a snapshot is the data block of the cycle it was published
// in).
TEST(Snapshots, ValuesAreTheDataBlock) {
  DiagnosticsMachine m;
  m.programs[0]->power.Enable = true;
  m.programs[0]->move.Velocity = 900.0;
  m.programs[0]->run = true;
  m.run(57);  // mid-ramp: the velocity changes every cycle
  const auto s = m.snapshot(0);
  const auto table = m.diagnostics.view(0).variables();
  ASSERT_EQ(s.values.size(), table.size());
  EXPECT_EQ(s.cycle, m.runtime.clock().servo_cycles - 1);  // published in the last cycle run
  for (std::size_t i = 0; i < table.size(); ++i)
    EXPECT_EQ(s.values[i], table[i].read(m.axes[0]->data())) << table[i].path;
  EXPECT_GT(m.axes[0]->data().Velocity, 0.0);
}

// spec 06 §2 telegram 3: actual ZSW1, NIST_B, ZSW2, G1_ZSW, G1_XIST1, G1_XIST2; setpoint STW1, NSOLL_B, STW2,
// G1_STW. The snapshot holds the words the drive connection exchanged in that cycle.
TEST(Snapshots, TelegramWords) {
  DiagnosticsMachine m;
  m.programs[0]->power.Enable = true;
  m.run(30);
  const auto& view = m.diagnostics.view(0);
  std::vector<tg::Signal> actual;
  std::vector<tg::Signal> setpoint;
  for (const auto& c : view.telegram_channels()) {
    EXPECT_EQ(c.slot, drives::Slot::kDrive);
    (c.direction == tg::Direction::kActual ? actual : setpoint).push_back(c.signal);
  }
  using S = tg::Signal;
  EXPECT_EQ(actual, (std::vector<S>{S::ZSW1, S::NIST_B, S::ZSW2, S::G1_ZSW, S::G1_XIST1, S::G1_XIST2}));
  EXPECT_EQ(setpoint, (std::vector<S>{S::STW1, S::NSOLL_B, S::STW2, S::G1_STW}));
  const auto s = m.snapshot(0);
  const auto* drive = m.axes[0]->drive();
  ASSERT_NE(drive, nullptr);
  for (std::size_t i = 0; i < view.telegram_channels().size(); ++i) {
    const auto& c = view.telegram_channels()[i];
    const std::uint32_t expected = c.direction == tg::Direction::kActual
                                       ? drive->drive_actual().raw(c.signal)
                                       : drive->drive_setpoint().raw(c.signal);
    EXPECT_EQ(s.words[i], expected) << tg::name(c.signal);
  }
  // Enabled: ZSW1 shows "operation enabled" (bit 2).
  EXPECT_TRUE(drive->drive_actual().ZSW1.test(tg::Zsw1Bit::kOperationEnabled));
}

// docs/diagnostics.md "Traces" (signals: data-block paths, bits of words, telegram words and bits; anything
// else refused).
TEST(Snapshots, Probes) {
  DiagnosticsMachine m;
  m.programs[0]->power.Enable = true;
  m.run(30);
  const auto& view = m.diagnostics.view(0);
  const auto* drive = m.axes[0]->drive();
  const auto enabled = view.probe("StatusWord.X0");
  const auto zsw1 = view.probe("telegram.drive.ZSW1");
  const auto operation = view.probe("telegram.drive.ZSW1.X2");
  const auto velocity = view.probe("Velocity");
  ASSERT_TRUE(enabled && zsw1 && operation && velocity);
  EXPECT_EQ(enabled->value(), 1.0);
  EXPECT_EQ(zsw1->value(), static_cast<double>(drive->drive_actual().ZSW1.value()));
  EXPECT_EQ(operation->value(), 1.0);
  EXPECT_EQ(velocity->value(), m.axes[0]->data().Velocity);
  for (const char* unknown :
       {"NoSuchVariable", "StatusWord.X32", "telegram.drive.G2_XIST1", "telegram.encoder1.G1_XIST1",
        "telegram.drive.ZSW1.X16", "telegram.drive.ZSW1.X01", "telegram.drive", "telegram.drive.",
        "telegram.drive.NOPE", "Velocity.X1"}) {
    EXPECT_FALSE(view.probe(unknown).has_value()) << unknown;
  }
}

// Four objects, period 8: each object is published once per 8 cycles, in its own cycle of the period.
// Decision W12 (each TO published every publish_period_cycles, staggered).
TEST(Snapshots, PublishingIsStaggered) {
  DiagnosticsMachine m(4, diagnostics::DiagnosticsConfig{8, 256, 100});
  std::vector<std::set<std::uint64_t>> seen(4);
  for (int i = 0; i < 64; ++i) {
    m.run(1);
    m.diagnostics.poll();
    m.diagnostics.read([&](const diagnostics::Diagnostics::State& s) {
      for (std::size_t o = 0; o < 4; ++o) {
        if (s.objects[o].valid) seen[o].insert(s.objects[o].snapshot.cycle);
      }
      return 0;
    });
  }
  for (std::size_t o = 0; o < 4; ++o) {
    EXPECT_EQ(seen[o].size(), 8u) << o;
    for (const std::uint64_t c : seen[o])
      EXPECT_EQ(c % 8, o * 2) << o;
  }
}

// Every event reaches the history while the reader polls often enough; events overwritten in between are
// counted, not invented.
// Decision M1 (the bounded alarm ring); tomc's own: events the reader missed are counted as lost, never
// invented.
TEST(Snapshots, AlarmHistoryCountsWhatItMissed) {
  DiagnosticsMachine m;
  auto& axis = *m.axes[0];
  for (int i = 0; i < 40; ++i) {
    ASSERT_TRUE(axis.inject_alarm(techobjects::kAlarmDynamicsLimitedVelocity, static_cast<std::uint32_t>(i),
                                  techobjects::AlarmReaction::kNone));
    ASSERT_TRUE(axis.reset(false).accepted());
    m.run(1);  // the interpolator acknowledges: "raised" and "acknowledged", 80 events
  }
  m.run(1);
  m.diagnostics.poll();
  const auto state =
      m.diagnostics.read([](const diagnostics::Diagnostics::State& s) { return s.objects[0]; });
  ASSERT_EQ(state.history.size(), diagnostics::kEventsPerSnapshot);
  EXPECT_EQ(state.history.back().sequence, 80u);
  EXPECT_EQ(state.history.front().sequence, 80u - diagnostics::kEventsPerSnapshot + 1);
  EXPECT_EQ(state.history_lost, 80u - diagnostics::kEventsPerSnapshot);
  EXPECT_EQ(state.history.back().kind, techobjects::AlarmEvent::Kind::kAcknowledged);
  EXPECT_EQ(state.history.back().additional_value, 39u);
  // Polled every cycle, nothing is lost.
  DiagnosticsMachine n;
  for (int i = 0; i < 40; ++i) {
    ASSERT_TRUE(n.axes[0]->inject_alarm(techobjects::kAlarmDynamicsLimitedVelocity, 0,
                                        techobjects::AlarmReaction::kNone));
    ASSERT_TRUE(n.axes[0]->reset(false).accepted());
    n.run(1);
    n.diagnostics.poll();
  }
  n.run(1);
  n.diagnostics.poll();
  const auto full = n.diagnostics.read([](const diagnostics::Diagnostics::State& s) { return s.objects[0]; });
  EXPECT_EQ(full.history.size(), 80u);
  EXPECT_EQ(full.history_lost, 0u);
}

// Issue 22 (the soak's "alarm history bounded", docs/reliability.md §7): the reader keeps the newest
// DiagnosticsConfig::alarm_history events per object, each with its wall-clock time; what it drops at the
// front was read, so it is not counted as lost.
TEST(Snapshots, AlarmHistoryKeepsTheNewestUpToItsBound) {
  DiagnosticsMachine m(1, diagnostics::DiagnosticsConfig{1, 4096, 50});
  for (int i = 0; i < 40; ++i) {  // 80 events ("raised", "acknowledged"), polled every cycle
    ASSERT_TRUE(m.axes[0]->inject_alarm(techobjects::kAlarmDynamicsLimitedVelocity,
                                        static_cast<std::uint32_t>(i), techobjects::AlarmReaction::kNone));
    ASSERT_TRUE(m.axes[0]->reset(false).accepted());
    m.run(1);
    m.diagnostics.poll();
  }
  m.run(1);
  m.diagnostics.poll();
  const auto state =
      m.diagnostics.read([](const diagnostics::Diagnostics::State& s) { return s.objects[0]; });
  ASSERT_EQ(state.history.size(), 50u);
  EXPECT_EQ(state.history_unix_s.size(), 50u);
  EXPECT_EQ(state.history.front().sequence, 31u);
  EXPECT_EQ(state.history.back().sequence, 80u);
  EXPECT_EQ(state.history.back().additional_value, 39u);
  EXPECT_EQ(state.history_lost, 0u);
}

// Issue 21: every event of the history has its wall-clock time, dated back from the newest snapshot's cycle
// (the cycle runs in real time): an event 500 cycles of 1 ms before the snapshot happened 0.5 s before the
// poll; events are in time order.
TEST(Snapshots, AlarmHistoryHasWallClockTime) {
  DiagnosticsMachine m;
  ASSERT_TRUE(m.axes[0]->inject_alarm(techobjects::kAlarmDynamicsLimitedVelocity, 7,
                                      techobjects::AlarmReaction::kNone));
  m.run(1);
  const std::uint64_t raised = m.runtime.clock().servo_cycles - 1;
  m.run(500);
  const double before =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  m.diagnostics.poll();
  const double after =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  const auto state =
      m.diagnostics.read([](const diagnostics::Diagnostics::State& s) { return s.objects[0]; });
  ASSERT_EQ(state.history.size(), 1u);
  ASSERT_EQ(state.history_unix_s.size(), 1u);
  EXPECT_EQ(state.history[0].cycle, raised);
  const double age_s = static_cast<double>(state.snapshot.cycle - raised) * 0.001;
  EXPECT_GE(age_s, 0.49);  // published at most one publish period (10 cycles) before the last cycle
  EXPECT_GE(state.history_unix_s[0], before - age_s - 1e-6);
  EXPECT_LE(state.history_unix_s[0], after - age_s + 1e-6);
}

// Decision W15 (the program switch <axis>.automatic that releases an axis to the panel).
TEST(Snapshots, ProgramSwitches) {
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  diagnostics::Diagnostics d;
  std::atomic<bool> automatic{true};
  d.add_switch("Axis1.automatic", "run Axis1 in the demo loop", automatic);
  d.attach(runtime);
  EXPECT_TRUE(d.set_switch("Axis1.automatic", false));
  EXPECT_FALSE(automatic.load());
  EXPECT_FALSE(d.set_switch("Axis2.automatic", true));
  ASSERT_EQ(d.switches().size(), 1u);
  EXPECT_EQ(d.switches()[0].description, "run Axis1 in the demo loop");
  EXPECT_THROW(d.add_switch("late", "", automatic), std::logic_error);
}

}  // namespace
