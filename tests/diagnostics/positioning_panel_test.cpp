// The axis control panel of TO_PositioningAxis (PositioningAxisPanel; spec 02 §9.2-§9.4, seed 004 §7.2-§7.7):
// the speed axis' functions plus homing (MC_Home Mode 3 active, Mode 0 set position) and positioning
// (MC_MoveAbsolute, MC_MoveRelative) with the panel's dynamics; the user program's jobs are rejected with
// 16#8012 meanwhile; bad values are refused, errors of the TO reach the page; the lifebeat stops the axis and
// returns master control (16#8013).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "positioning_panel_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using diagnostics::PanelAnswer;
using diagnostics::PanelCommandKind;
using diagnostics::PanelMotion;
using techobjects::StatusWordBit;
using tomc::testing::PositioningDiagnosticsMachine;
namespace eid = techobjects::error_id;

// Takes master control and enables the axis through the panel.
void take_and_enable(PositioningDiagnosticsMachine& m, double lifebeat_s = 60.0) {
  ASSERT_EQ(m.command(PanelCommandKind::kTake, 0, lifebeat_s), PanelAnswer::kAccepted);
  ASSERT_EQ(m.command(PanelCommandKind::kEnable), PanelAnswer::kAccepted);
  ASSERT_GT(m.run_until([&] { return m.status_bit(StatusWordBit::kEnable); }, 500), 0);
}

// Decisions W10 and W17 (the positioning axis' panel: homing Mode 3/0, absolute and relative positioning),
// spec 02 §9.4.
TEST(PositioningAxisPanel, CapabilitiesAndInstructions) {
  PositioningDiagnosticsMachine m;
  const auto* panel = m.diagnostics.panel(0);
  ASSERT_NE(panel, nullptr);
  using namespace diagnostics::capability;
  for (const std::uint32_t c : {kEnable, kJog, kVelocity, kStop, kAcknowledge, kAdaptVelocity, kHomeActive,
                                kHomeSetPosition, kMoveAbsolute, kMoveRelative})
    EXPECT_NE(panel->capabilities() & c, 0u) << c;
  ASSERT_EQ(panel->instruction_names().size(), 8u);
  EXPECT_EQ(panel->instruction_names()[5], "MC_Home");
  EXPECT_EQ(panel->instruction_names()[6], "MC_MoveAbsolute");
  EXPECT_EQ(panel->instruction_names()[7], "MC_MoveRelative");
}

// spec 02 §9.2 precondition (decision W1): refused while the user program has the axis enabled.
TEST(PositioningAxisPanel, TakeIsRefusedWhileTheProgramControlsTheAxis) {
  PositioningDiagnosticsMachine m;
  m.power.Enable = true;
  ASSERT_GT(m.run_until([&] { return m.power.Status; }, 500), 0);
  EXPECT_EQ(m.command(PanelCommandKind::kTake), PanelAnswer::kProgramControlsAxis);
  m.power.Enable = false;
  ASSERT_GT(m.run_until([&] { return m.axis->program_released(); }, 2000), 0);
  EXPECT_EQ(m.command(PanelCommandKind::kTake), PanelAnswer::kAccepted);
  m.run(1);
  EXPECT_TRUE(m.status_bit(StatusWordBit::kControlPanelActive));
}

// Set position (MC_Home Mode 0), absolute and relative positioning with the panel velocity (10 % of
// MaxVelocity = 50 mm/s, seed 004 §7.4); the program's MC_MoveAbsolute is rejected with 16#8012 meanwhile.
TEST(PositioningAxisPanel, SetPositionThenMoveAbsoluteAndRelative) {
  PositioningDiagnosticsMachine m;
  take_and_enable(m);
  // Not homed yet: the TO refuses the absolute move; its ErrorID reaches the page.
  ASSERT_EQ(m.command(PanelCommandKind::kMoveAbsolute, 0, 10.0), PanelAnswer::kAccepted);
  m.run(2);
  auto s = m.panel();
  EXPECT_EQ(s.error_id, eid::kAxisNotHomed);  // Error itself shows for one call: Execute falls at once
  EXPECT_FALSE(s.instructions[6].busy);
  EXPECT_EQ(s.motion, PanelMotion::kNone);

  ASSERT_EQ(m.command(PanelCommandKind::kHome, 0, 25.0, 0), PanelAnswer::kAccepted);
  m.run(2);
  EXPECT_TRUE(m.status_bit(StatusWordBit::kHomingDone));
  EXPECT_NEAR(m.axis->data().ActualPosition, 25.0, 1e-6);
  EXPECT_FALSE(m.panel().instructions[5].busy);

  ASSERT_EQ(m.command(PanelCommandKind::kMoveAbsolute, 0, 100.0), PanelAnswer::kAccepted);
  m.run(50);
  s = m.panel();
  EXPECT_EQ(s.motion, PanelMotion::kPositioning);
  EXPECT_TRUE(s.instructions[6].busy);
  EXPECT_TRUE(m.status_bit(StatusWordBit::kPositioningCommand));
  // The user program meanwhile: rejected with 16#8012.
  m.move.Position = 0.0;
  m.move.Execute = true;
  m.run(1);
  EXPECT_EQ(m.move.ErrorID, eid::kControlPanelActive);
  m.move.Execute = false;
  m.run(100);
  EXPECT_NEAR(m.axis->data().Velocity, 50.0, 1e-9);  // the panel velocity
  ASSERT_GT(m.run_until([&] { return !m.panel().instructions[6].busy; }, 5000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Position, 100.0);
  EXPECT_EQ(m.panel().motion, PanelMotion::kNone);

  // Relative, backwards (direction -1 travels the distance the other way).
  ASSERT_EQ(m.command(PanelCommandKind::kMoveRelative, -1, 30.0), PanelAnswer::kAccepted);
  ASSERT_GT(m.run_until([&] { return !m.panel().instructions[7].busy; }, 5000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Position, 70.0);
  m.run(500);
  EXPECT_NEAR(m.axis->data().ActualPosition, 70.0, 0.05);
}

// Active homing (MC_Home Mode 3) with the default configuration: the motor encoder's zero mark.
// spec 02 §9.4 (panel homing), decision W17 (MC_Home Mode 3, the configured active homing).
TEST(PositioningAxisPanel, ActiveHoming) {
  PositioningDiagnosticsMachine m;
  take_and_enable(m);
  ASSERT_EQ(m.command(PanelCommandKind::kHome, 0, 5.0, 3), PanelAnswer::kAccepted);
  m.run(5);
  EXPECT_EQ(m.panel().motion, PanelMotion::kHoming);
  EXPECT_TRUE(m.status_bit(StatusWordBit::kHomingCommand));
  ASSERT_GT(m.run_until([&] { return !m.panel().instructions[5].busy; }, 20000), 0);
  EXPECT_TRUE(m.status_bit(StatusWordBit::kHomingDone));
  EXPECT_DOUBLE_EQ(m.axis->data().Position, 5.0);
  EXPECT_EQ(m.panel().motion, PanelMotion::kNone);
  EXPECT_EQ(m.panel().error_id, 0);
}

// Values out of range are refused before they reach an instruction; STOP ends a positioning job.
// Decision D6 (panel values range-checked before posting), docs/diagnostics.md "Axis control panel" (STOP
// aborts a positioning job).
TEST(PositioningAxisPanel, BadValuesAreRefusedAndStopEndsPositioning) {
  PositioningDiagnosticsMachine m;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Not the holder: refused before anything else.
  EXPECT_EQ(m.command(PanelCommandKind::kMoveAbsolute, 0, 10.0), PanelAnswer::kNotHolder);
  take_and_enable(m);
  EXPECT_EQ(m.command(PanelCommandKind::kHome, 0, 0.0, 5), PanelAnswer::kInvalidValue);
  EXPECT_EQ(m.command(PanelCommandKind::kHome, 0, nan, 0), PanelAnswer::kInvalidValue);
  EXPECT_EQ(m.command(PanelCommandKind::kMoveAbsolute, 0, std::numeric_limits<double>::infinity()),
            PanelAnswer::kInvalidValue);
  EXPECT_EQ(m.command(PanelCommandKind::kMoveAbsolute, 2, 10.0), PanelAnswer::kInvalidValue);
  EXPECT_EQ(m.command(PanelCommandKind::kMoveRelative, 0, 10.0), PanelAnswer::kInvalidValue);
  EXPECT_EQ(m.command(PanelCommandKind::kMoveRelative, 1, nan), PanelAnswer::kInvalidValue);
  EXPECT_FALSE(m.status_bit(StatusWordBit::kHomingDone));

  ASSERT_EQ(m.command(PanelCommandKind::kMoveRelative, 1, 1000.0), PanelAnswer::kAccepted);
  m.run(300);
  EXPECT_GT(m.axis->data().Velocity, 0.0);
  ASSERT_EQ(m.command(PanelCommandKind::kStop), PanelAnswer::kAccepted);
  ASSERT_GT(m.run_until([&] { return m.axis->data().Velocity == 0.0; }, 2000), 0);
  const auto s = m.panel();
  EXPECT_FALSE(s.instructions[7].busy);
  EXPECT_EQ(s.motion, PanelMotion::kNone);
  EXPECT_TRUE(m.status_bit(StatusWordBit::kEnable));
}

// spec 02 §9.2 table "Online connection lost": no lifebeat for the monitoring time while positioning -> the
// axis stops with maximum deceleration and is disabled, 16#8013, control priority back to the program.
TEST(PositioningAxisPanel, LifebeatLossStopsPositioningAndReturnsMasterControl) {
  PositioningDiagnosticsMachine m;
  take_and_enable(m, 0.5);
  ASSERT_EQ(m.command(PanelCommandKind::kHome, 0, 0.0, 0), PanelAnswer::kAccepted);
  ASSERT_EQ(m.command(PanelCommandKind::kMoveAbsolute, 0, 1000.0), PanelAnswer::kAccepted);
  m.run(200);
  EXPECT_GT(m.axis->data().Velocity, 0.0);
  ASSERT_GT(m.run_until([&] { return !m.panel().held; }, 2000), 0);
  const auto s = m.panel();
  EXPECT_EQ(s.error_id, eid::kLifebeatExpired);
  EXPECT_TRUE(m.axis->program_released());
  EXPECT_FALSE(m.status_bit(StatusWordBit::kEnable));
  EXPECT_FALSE(m.axis->control_priority().held());
  EXPECT_LT(m.axis->data().Position, 1000.0);
  m.run(2);
  EXPECT_FALSE(m.status_bit(StatusWordBit::kControlPanelActive));
  // The user program has the axis again.
  m.power.Enable = true;
  ASSERT_GT(m.run_until([&] { return m.power.Status; }, 500), 0);
  EXPECT_FALSE(m.power.Error);
}

}  // namespace
