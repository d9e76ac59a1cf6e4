// The axis control panel through Diagnostics, on a speed axis with the simulated drive (spec 02 §9.2-§9.4,
// §11 scenario 50; seed 004 §7.2-§7.4). Units: velocity 1/min, accelerations 1/s² (revolutions); limits of
// diagnostics_axis_data(): MaxVelocity 3000 1/min, MaxAcceleration 100 1/s², MaxDeceleration 200 1/s², no
// jerk limit. Cycle 1 ms. A command posted before step() k is taken by the post-interpolator hook of cycle k;
// the panel's instructions are called there, so its jobs move the axis from the interpolator of cycle k+1.
#include <gtest/gtest.h>

#include <cmath>

#include "diagnostics_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using diagnostics::PanelAnswer;
using diagnostics::PanelCommandKind;
using tomc::testing::DiagnosticsMachine;
namespace eid = techobjects::error_id;

constexpr std::uint64_t kSession = 0x1234;

bool status_bit(const techobjects::SpeedAxis& axis, techobjects::StatusWordBit bit) {
  return techobjects::test(axis.data().StatusWord, bit);
}

// Takes control priority and enables the axis. The lifebeat monitoring time is long (10 s) unless a test
// is about the lifebeat.
void take_and_enable(DiagnosticsMachine& m, double lifebeat_s = 10.0) {
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kTake, 0, lifebeat_s), PanelAnswer::kAccepted);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kEnable), PanelAnswer::kAccepted);
  ASSERT_GT(m.run_until([&] { return status_bit(*m.axes[0], techobjects::StatusWordBit::kEnable); }, 100), 0);
}

// spec 02 §9.2: "TO disabled by the program (MC_Power.Enable = FALSE)" is the precondition of taking over.
TEST(AxisControlPanel, TakeIsRefusedWhileTheProgramEnablesTheAxis) {
  DiagnosticsMachine m;
  m.programs[0]->power.Enable = true;
  ASSERT_GT(m.run_until([&] { return m.programs[0]->power.Status; }, 100), 0);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kTake), PanelAnswer::kProgramControlsAxis);
  EXPECT_FALSE(m.axes[0]->control_priority().held());
  m.programs[0]->move.Velocity = 600.0;
  m.programs[0]->run = true;
  m.run(200);
  // Released by the program, but still stopping (10 rev/s at 200 1/s²: 50 ms): refused until the TO is
  // disabled.
  m.programs[0]->power.Enable = false;
  m.programs[0]->power.StopMode = 2;
  m.run(1);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kTake), PanelAnswer::kProgramControlsAxis);
  ASSERT_GT(m.run_until([&] { return m.axes[0]->program_released(); }, 100), 0);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kTake), PanelAnswer::kAccepted);
  EXPECT_TRUE(m.axes[0]->control_priority().held());
}

// Master control has one holder: another session is refused, and cannot command the axis.
// spec 02 §9.2 (one holder of control priority), decision W4 (lifebeat 0.1…60 s).
TEST(AxisControlPanel, OnlyOneHolder) {
  DiagnosticsMachine m;
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kTake), PanelAnswer::kAccepted);
  EXPECT_EQ(m.command(0, kSession + 1, PanelCommandKind::kTake), PanelAnswer::kHeldByOtherSession);
  EXPECT_EQ(m.command(0, kSession + 1, PanelCommandKind::kEnable), PanelAnswer::kNotHolder);
  EXPECT_EQ(m.command(0, kSession + 1, PanelCommandKind::kLifebeat), PanelAnswer::kNotHolder);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kTake), PanelAnswer::kAccepted);  // the holder again
  EXPECT_EQ(m.command(0, 0, PanelCommandKind::kTake), PanelAnswer::kInvalidValue);     // no session key
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kTake, 0, 0.05),
            PanelAnswer::kInvalidValue);  // lifebeat
}

// spec 02 §9.3, seed 004 §7.4: on taking over, the panel dynamics are 10 % of the velocity and acceleration
// limits and 100 % of deceleration and jerk; "Adapt velocity" starts at 100 %.
TEST(AxisControlPanel, DefaultDynamicsAreTenAndHundredPercentOfTheLimits) {
  DiagnosticsMachine m;
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kTake), PanelAnswer::kAccepted);
  m.run(1);
  const auto s = m.snapshot(0);
  EXPECT_TRUE(s.panel.held);
  EXPECT_EQ(s.panel.session, kSession);
  EXPECT_DOUBLE_EQ(s.panel.dynamics.velocity, 300.0);
  EXPECT_DOUBLE_EQ(s.panel.dynamics.acceleration, 10.0);
  EXPECT_DOUBLE_EQ(s.panel.dynamics.deceleration, 200.0);
  EXPECT_DOUBLE_EQ(s.panel.dynamics.jerk, 0.0);
  EXPECT_DOUBLE_EQ(s.panel.adapt_percent, 100.0);
  EXPECT_DOUBLE_EQ(s.panel.lifebeat_s, diagnostics::AxisPanel::kDefaultLifebeatS);
  EXPECT_TRUE(status_bit(*m.axes[0], techobjects::StatusWordBit::kControlPanelActive));  // StatusWord.X4
}

// Jog forwards at the panel velocity (300 1/min = 5 rev/s at 10 1/s²: 500 cycles), "Adapt velocity" 50 %
// halves it live (spec 02 §9.3: 100 x 50 % = 50), releasing stops the axis with the panel deceleration.
TEST(AxisControlPanel, JogWithAdaptVelocity) {
  DiagnosticsMachine m;
  take_and_enable(m);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kJog, +1), PanelAnswer::kAccepted);
  const int cycles = m.run_until([&] { return m.axes[0]->data().Velocity >= 300.0 - 1e-9; }, 1000);
  EXPECT_NEAR(cycles, 500, 2);
  EXPECT_TRUE(status_bit(*m.axes[0], techobjects::StatusWordBit::kJogCommand));
  // A lifebeat keeps the panel; adapt velocity 50 %: the jog velocity follows (braking at 200 1/s²).
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kLifebeat), PanelAnswer::kAccepted);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kSetAdapt, 0, 50.0), PanelAnswer::kAccepted);
  m.run(100);
  EXPECT_DOUBLE_EQ(m.axes[0]->data().Velocity, 150.0);
  // Release: 150 1/min = 2.5 rev/s at 200 1/s² stops in 12.5 ms.
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kJog, 0), PanelAnswer::kAccepted);
  m.run(20);
  EXPECT_DOUBLE_EQ(m.axes[0]->data().Velocity, 0.0);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kSetAdapt, 0, 0.5), PanelAnswer::kInvalidValue);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kSetAdapt, 0, 201.0), PanelAnswer::kInvalidValue);
}

// spec 02 §9.3: Override.Velocity is ineffective while the panel is active.
TEST(AxisControlPanel, OverrideHasNoEffectOnThePanel) {
  DiagnosticsMachine m;
  ASSERT_TRUE(m.axes[0]->write("Override.Velocity", 20.0).ok());
  take_and_enable(m);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kMoveVelocity, -1), PanelAnswer::kAccepted);
  m.run(600);
  EXPECT_DOUBLE_EQ(m.axes[0]->data().Velocity, -300.0);
}

// spec 02 §9.2 and §11 scenario 50: a job of the user program is rejected with 16#8012 while the panel
// holds priority.
TEST(AxisControlPanel, ProgramJobsAreRejectedWith8012) {
  DiagnosticsMachine m;
  take_and_enable(m);
  m.programs[0]->move.Velocity = 600.0;
  m.programs[0]->run = true;
  m.run(1);
  EXPECT_TRUE(m.programs[0]->move.Error);
  EXPECT_EQ(m.programs[0]->move.ErrorID, eid::kControlPanelActive);
  m.programs[0]->power.Enable = true;
  m.run(1);
  EXPECT_EQ(m.programs[0]->power.ErrorID, eid::kControlPanelActive);
}

// Run at the panel velocity and stop with the panel deceleration (MC_Halt): 300 1/min = 5 rev/s at 200 1/s²
// is standstill after 25 ms.
// spec 02 §9.3 (the panel's velocity and dynamics), docs/diagnostics.md "Axis control panel" (STOP: MC_Halt
// with the panel deceleration).
TEST(AxisControlPanel, VelocityAndStop) {
  DiagnosticsMachine m;
  take_and_enable(m);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kMoveVelocity, +1), PanelAnswer::kAccepted);
  m.run(600);
  ASSERT_DOUBLE_EQ(m.axes[0]->data().Velocity, 300.0);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kStop), PanelAnswer::kAccepted);
  const int cycles = m.run_until([&] { return m.axes[0]->data().Velocity == 0.0; }, 100);
  EXPECT_NEAR(cycles, 25, 2);
  m.run(2);
  const auto s = m.snapshot(0);
  EXPECT_EQ(s.panel.motion, diagnostics::PanelMotion::kNone);
  EXPECT_TRUE(s.panel.instructions[3].done || !s.panel.instructions[3].busy);  // MC_Halt ended
  EXPECT_FALSE(s.panel.instructions[3].error);
  // New dynamics: velocity 600 at 20 1/s² (10 rev/s: 500 cycles).
  diagnostics::PanelCommand c;
  c.object = 0;
  c.session = kSession;
  c.kind = PanelCommandKind::kSetDynamics;
  c.dynamics = {600.0, 20.0, 200.0, 0.0};
  ASSERT_EQ(m.command(c), PanelAnswer::kAccepted);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kMoveVelocity, +1), PanelAnswer::kAccepted);
  EXPECT_NEAR(m.run_until([&] { return m.axes[0]->data().Velocity >= 600.0 - 1e-9; }, 1000), 500, 2);
  c.dynamics = {600.0, 0.0, 200.0, 0.0};
  EXPECT_EQ(m.command(c), PanelAnswer::kInvalidValue);
}

// spec 02 §9.2 table, §11 scenario 50: with a 1000 ms lifebeat and no lifebeat any more, the axis is stopped
// with maximum deceleration once more than 1000 ms passed, 16#8013 is reported and control priority returns
// to the user program when the axis is disabled (MC_Power StopMode 2: MaxDeceleration 200 1/s², 25 ms from
// 300 1/min).
TEST(AxisControlPanel, LifebeatLossStopsTheAxisAndReturnsPriority) {
  DiagnosticsMachine m;
  take_and_enable(m, 1.0);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kJog, +1), PanelAnswer::kAccepted);
  m.run(600);
  ASSERT_DOUBLE_EQ(m.axes[0]->data().Velocity, 300.0);
  // The last lifebeat: taken in cycle c (the command's step).
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kLifebeat), PanelAnswer::kAccepted);
  m.run(1000);  // c+1 .. c+1000: 1000 ms since the lifebeat, not more
  EXPECT_TRUE(m.axes[0]->control_priority().held());
  EXPECT_DOUBLE_EQ(m.axes[0]->data().Velocity, 300.0);
  EXPECT_EQ(m.snapshot(0).panel.error_id, 0);
  m.run(1);  // c+1001: the panel disables with StopMode 2; braking from the next interpolator cycle
  EXPECT_EQ(m.snapshot(0).panel.error_id, eid::kLifebeatExpired);
  EXPECT_TRUE(m.snapshot(0).panel.giving_back);
  const int stop = m.run_until([&] { return m.axes[0]->data().Velocity == 0.0; }, 100);
  EXPECT_NEAR(stop, 25, 2);
  // Disabled, then control priority returns to the user program.
  ASSERT_GT(m.run_until([&] { return !m.axes[0]->control_priority().held(); }, 100), 0);
  EXPECT_FALSE(status_bit(*m.axes[0], techobjects::StatusWordBit::kEnable));
  m.run(1);
  EXPECT_FALSE(status_bit(*m.axes[0], techobjects::StatusWordBit::kControlPanelActive));
  const auto s = m.snapshot(0);
  EXPECT_FALSE(s.panel.held);
  EXPECT_EQ(s.panel.error_id, eid::kLifebeatExpired);
  // The old holder is not a holder any more; the program enables the axis again.
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kEnable), PanelAnswer::kNotHolder);
  m.programs[0]->power.Enable = true;
  ASSERT_GT(m.run_until([&] { return m.programs[0]->power.Status; }, 100), 0);
  EXPECT_FALSE(m.programs[0]->power.Error);
}

// Give back (seed 004 §7.8): disable, then priority returns; while it is being returned only lifebeats count.
TEST(AxisControlPanel, GiveBackDisablesFirst) {
  DiagnosticsMachine m;
  take_and_enable(m);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kMoveVelocity, +1), PanelAnswer::kAccepted);
  m.run(600);
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kGiveBack), PanelAnswer::kAccepted);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kEnable), PanelAnswer::kGivingBack);
  ASSERT_GT(m.run_until([&] { return !m.axes[0]->control_priority().held(); }, 200), 0);
  EXPECT_DOUBLE_EQ(m.axes[0]->data().Velocity, 0.0);
  EXPECT_TRUE(m.axes[0]->program_released());
  EXPECT_EQ(m.snapshot(0).panel.error_id, 0);  // a normal give-back is no error
}

// Acknowledge (MC_Reset from the panel) clears a technology alarm; the program's MC_Reset could not.
// docs/diagnostics.md "Axis control panel" (acknowledge: the panel's MC_Reset), decision D10.
TEST(AxisControlPanel, AcknowledgeClearsAlarms) {
  DiagnosticsMachine m;
  take_and_enable(m);
  ASSERT_TRUE(m.axes[0]->inject_alarm(techobjects::kAlarmDynamicsLimitedVelocity, 0,
                                      techobjects::AlarmReaction::kNone));
  m.run(1);
  ASSERT_TRUE(m.axes[0]->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kAcknowledge), PanelAnswer::kAccepted);
  m.run(2);
  EXPECT_FALSE(m.axes[0]->alarms().pending(techobjects::kAlarmDynamicsLimitedVelocity));
  // The alarm history on the reader's side has "raised" and "acknowledged".
  m.run(2);
  m.diagnostics.poll();
  const auto history =
      m.diagnostics.read([](const diagnostics::Diagnostics::State& s) { return s.objects[0].history; });
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[0].kind, techobjects::AlarmEvent::Kind::kRaised);
  EXPECT_EQ(history[1].kind, techobjects::AlarmEvent::Kind::kAcknowledged);
  EXPECT_EQ(history[1].number, techobjects::kAlarmDynamicsLimitedVelocity);
}

// Commands for an object without a panel or an unknown object are answered without reaching a panel.
// Decision W10 (panel functions by capability: homing and positioning only on axes that implement them).
TEST(AxisControlPanel, PositionFunctionsAreNotSupportedOnASpeedAxis) {
  DiagnosticsMachine m;
  ASSERT_EQ(m.command(0, kSession, PanelCommandKind::kTake), PanelAnswer::kAccepted);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kHome, 0, 0.0), PanelAnswer::kNotSupported);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kMoveAbsolute, 0, 10.0), PanelAnswer::kNotSupported);
  EXPECT_EQ(m.command(0, kSession, PanelCommandKind::kMoveRelative, 0, 10.0), PanelAnswer::kNotSupported);
  const std::uint32_t caps = m.snapshot(0).panel.capabilities;
  EXPECT_NE(caps & diagnostics::capability::kJog, 0u);
  EXPECT_EQ(caps & diagnostics::capability::kMoveAbsolute, 0u);
  diagnostics::PanelCommand c;
  c.object = 7;
  EXPECT_EQ(m.diagnostics.command(c), PanelAnswer::kUnknownObject);
}

}  // namespace
