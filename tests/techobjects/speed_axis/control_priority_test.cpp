// Control priority of the axis control panel on TO_SpeedAxis (spec 02 §9.2, §9.3, §11 scenario 50; seed 004
// §7.2, §7.4): while the panel holds it the user program's jobs are rejected with 16#8012, StatusWord.X4 is
// TRUE, the panel's own calls (inside a PanelCall) get through, and Override.Velocity has no effect.
#include <gtest/gtest.h>

#include "speed_axis_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::ControlPriority;
using techobjects::SpeedAxis;
using tomc::testing::SpeedAxisMachine;
namespace eid = techobjects::error_id;

techobjects::SpeedAxisData trapezoid_data() {
  techobjects::SpeedAxisData d;
  d.DynamicLimits.MaxJerk = 0.0;
  return d;
}

// The panel's own instances, called after the program's (the fixture's `user` hook) inside a PanelCall.
struct Panel {
  instructions::MC_Power<SpeedAxis> power;
  instructions::MC_MoveVelocity<SpeedAxis> move;
  instructions::MC_Reset<SpeedAxis> reset;
  void attach(SpeedAxisMachine& m) {
    m.user = [this, &m] {
      if (!m.axis->control_priority().held()) return;
      ControlPriority::PanelCall call(m.axis->control_priority());
      power(*m.axis);
      move(*m.axis);
      reset(*m.axis);
    };
  }
};

bool control_panel_active(const SpeedAxisMachine& m) {
  return techobjects::test(m.axis->data().StatusWord, techobjects::StatusWordBit::kControlPanelActive);
}

// spec 02 §9.2 precondition: the TO is disabled by the program (MC_Power.Enable = FALSE).
TEST(ControlPriority, ProgramReleasesTheAxisOnlyWhenDisabled) {
  SpeedAxisMachine m(2, trapezoid_data());
  m.run(2);
  EXPECT_TRUE(m.axis->program_released());
  ASSERT_GT(m.enable(), 0);
  EXPECT_FALSE(m.axis->program_released());
  m.power.Enable = false;
  m.run(1);
  // StopMode 0 ramps from standstill at once; the TO is disabled at the end of that interpolator cycle.
  const int cycles = m.run_until([&] { return m.axis->program_released(); }, 50);
  EXPECT_GT(cycles, 0);
}

// spec 02 §9.2 and §11 scenario 50: jobs from the user program are rejected with 16#8012 and StatusWord.X4
// is TRUE while the panel holds priority; the panel's jobs run; after it gives priority back the program's
// jobs are accepted again.
TEST(ControlPriority, ProgramJobsAreRejectedWhilePanelHoldsPriority) {
  SpeedAxisMachine m(2, trapezoid_data());
  Panel panel;
  panel.attach(m);
  m.run(2);
  ASSERT_TRUE(m.axis->program_released());
  m.axis->control_priority().grant();
  m.run(1);
  EXPECT_TRUE(control_panel_active(m));

  // The program tries to enable and to move: both rejected with 16#8012, the axis stays disabled.
  m.power.Enable = true;
  m.move.Execute = true;
  m.move.Velocity = 600.0;
  m.run(20);
  EXPECT_TRUE(m.power.Error);
  EXPECT_EQ(m.power.ErrorID, eid::kControlPanelActive);
  EXPECT_TRUE(m.move.Error);
  EXPECT_EQ(m.move.ErrorID, eid::kControlPanelActive);
  EXPECT_FALSE(techobjects::test(m.axis->data().StatusWord, techobjects::StatusWordBit::kEnable));
  // MC_Reset and MC_Halt of the program too.
  m.reset.Execute = true;
  m.halt.Execute = true;
  m.run(1);
  EXPECT_EQ(m.reset.ErrorID, eid::kControlPanelActive);
  EXPECT_EQ(m.halt.ErrorID, eid::kControlPanelActive);
  // A jog input of the program: rejected; no input: no job and no error (MC_MoveJog is level-controlled).
  m.jog.JogForward = true;
  m.run(1);
  EXPECT_TRUE(m.jog.Error);
  EXPECT_EQ(m.jog.ErrorID, eid::kControlPanelActive);
  m.jog.JogForward = false;
  m.power.Enable = false;
  m.move.Execute = false;
  m.reset.Execute = false;
  m.halt.Execute = false;
  m.run(1);
  EXPECT_FALSE(m.jog.Error);
  EXPECT_FALSE(m.power.Error);  // Enable = FALSE is no job

  // The panel enables and moves the axis: 600 1/min at the default 10 1/s² takes 1 s.
  panel.power.Enable = true;
  panel.power.StopMode = 2;
  ASSERT_GT(m.run_until([&] { return panel.power.Status; }, 100), 0);
  panel.move.Velocity = 600.0;
  panel.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return panel.move.InVelocity; }, 2000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 600.0);

  // The panel stops and disables, then gives priority back: the program's jobs are accepted again.
  panel.move.Execute = false;
  panel.power.Enable = false;
  ASSERT_GT(m.run_until([&] { return m.axis->program_released(); }, 2000), 0);
  m.axis->control_priority().give_back();
  m.run(1);
  EXPECT_FALSE(control_panel_active(m));
  ASSERT_GT(m.enable(), 0);
  EXPECT_FALSE(m.power.Error);
  m.move.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.move.Busy);
  EXPECT_FALSE(m.move.Error);
}

// spec 02 §9.3, seed 004 §7.4: <TO>.Override.Velocity is ineffective while the panel is active.
TEST(ControlPriority, OverrideIsIneffectiveForThePanel) {
  SpeedAxisMachine m(2, trapezoid_data());
  Panel panel;
  panel.attach(m);
  m.run(2);
  ASSERT_TRUE(m.axis->write("Override.Velocity", 50.0).ok());
  m.axis->control_priority().grant();
  panel.power.Enable = true;
  ASSERT_GT(m.run_until([&] { return panel.power.Status; }, 100), 0);
  panel.move.Velocity = 300.0;
  panel.move.Execute = true;
  ASSERT_GT(m.run_until([&] { return panel.move.InVelocity; }, 2000), 0);
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 300.0);  // not 150: the 50 % override does not act
}

}  // namespace
