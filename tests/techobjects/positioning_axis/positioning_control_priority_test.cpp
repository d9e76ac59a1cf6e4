// Control priority of the axis control panel on TO_PositioningAxis and TO_SynchronousAxis (spec 02 §9.2,
// §9.3, §11 scenario 50; seed 004 §7.2, §7.4; decisions W1, W2): while the panel holds it every job of the
// user program is rejected with 16#8012 (MC_Power only with Enable = TRUE, MC_MoveJog only with an input
// set), StatusWord.X4 ControlPanelActive is TRUE, the panel's own calls (inside a PanelCall) get through,
// Override.Velocity has no effect, and after the panel gives priority back the program's jobs run again.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "gearing_fixture.hpp"
#include "positioning_axis_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using techobjects::ControlPriority;
using tomc::testing::PositioningAxisMachine;
namespace eid = techobjects::error_id;

// The panel's own instances, called after the program's (the fixture's `user` hook) inside a PanelCall.
struct Panel {
  instructions::MC_Power<techobjects::PositioningAxis> power;
  instructions::MC_Home<techobjects::PositioningAxis> home;
  instructions::MC_MoveAbsolute<techobjects::PositioningAxis> move_absolute;
  void attach(PositioningAxisMachine& m) {
    m.user = [this, &m] {
      if (!m.axis->control_priority().held()) return;
      ControlPriority::PanelCall call(m.axis->control_priority());
      power(*m.axis);
      home(*m.axis);
      move_absolute(*m.axis);
    };
  }
};

bool control_panel_active(const techobjects::PositioningAxisData& db) {
  return techobjects::test(db.StatusWord, techobjects::StatusWordBit::kControlPanelActive);
}

bool constant_velocity(const techobjects::PositioningAxisData& db) {
  return techobjects::test(db.StatusWord, techobjects::StatusWordBit::kConstantVelocity);
}

// spec 02 §9.2 precondition (decision W1): the TO is disabled by the program (MC_Power.Enable = FALSE).
TEST(PositioningControlPriority, ProgramReleasesTheAxisOnlyWhenDisabled) {
  PositioningAxisMachine m;
  m.run(2);
  EXPECT_TRUE(m.axis->program_released());
  ASSERT_GT(m.enable(), 0);
  EXPECT_FALSE(m.axis->program_released());
  m.power.Enable = false;
  EXPECT_GT(m.run_until([&] { return m.axis->program_released(); }, 200), 0);
}

// spec 02 §9.2 ("Motion Control jobs of the user program are rejected with 16#8012") and §11 scenario 50:
// one row per job of the user program; each is rejected with 16#8012 while the panel holds priority.
struct ProgramJob {
  const char* instruction;
  std::function<void(PositioningAxisMachine&, bool)> set;  // start (true) or end (false) the job
  std::function<std::uint16_t(const PositioningAxisMachine&)> error_id;
};

std::vector<ProgramJob> program_jobs() {
  using M = PositioningAxisMachine;
  return {
      {"MC_Power (Enable = TRUE)", [](M& m, bool on) { m.power.Enable = on; },
       [](const M& m) { return m.power.ErrorID; }},
      {"MC_Reset", [](M& m, bool on) { m.reset.Execute = on; }, [](const M& m) { return m.reset.ErrorID; }},
      {"MC_Home", [](M& m, bool on) { m.home.Execute = on; }, [](const M& m) { return m.home.ErrorID; }},
      {"MC_MoveAbsolute",
       [](M& m, bool on) {
         m.move_absolute.Position = 10.0;
         m.move_absolute.Execute = on;
       },
       [](const M& m) { return m.move_absolute.ErrorID; }},
      {"MC_MoveRelative",
       [](M& m, bool on) {
         m.move_relative.Distance = 10.0;
         m.move_relative.Execute = on;
       },
       [](const M& m) { return m.move_relative.ErrorID; }},
      {"MC_MoveVelocity",
       [](M& m, bool on) {
         m.move_velocity.Velocity = 10.0;
         m.move_velocity.Execute = on;
       },
       [](const M& m) { return m.move_velocity.ErrorID; }},
      {"MC_Halt", [](M& m, bool on) { m.halt.Execute = on; }, [](const M& m) { return m.halt.ErrorID; }},
      {"MC_Stop", [](M& m, bool on) { m.stop.Execute = on; }, [](const M& m) { return m.stop.ErrorID; }},
      {"MC_MoveJog (JogForward)", [](M& m, bool on) { m.jog.JogForward = on; },
       [](const M& m) { return m.jog.ErrorID; }},
      {"MC_WriteParameter",
       [](M& m, bool on) {
         m.write_parameter.ParameterNumber = 1000;
         m.write_parameter.Value = 1.0;
         m.write_parameter.Execute = on;
       },
       [](const M& m) { return m.write_parameter.ErrorID; }},
  };
}

// spec 02 §9.2 (seed 004 §7.2: while the panel holds control priority, program jobs get 16#8012).
TEST(PositioningControlPriority, ProgramJobsAreRejectedWith8012WhilePanelHoldsPriority) {
  for (const ProgramJob& job : program_jobs()) {
    SCOPED_TRACE(job.instruction);
    PositioningAxisMachine m;
    m.run(2);
    ASSERT_TRUE(m.axis->program_released());
    m.axis->control_priority().grant();
    job.set(m, true);
    m.run(2);
    EXPECT_EQ(job.error_id(m), eid::kControlPanelActive);
    EXPECT_FALSE(techobjects::test(m.db().StatusWord, techobjects::StatusWordBit::kEnable));
    EXPECT_FALSE(techobjects::test(m.db().StatusWord, techobjects::StatusWordBit::kHomingDone));
  }
}

// Decision W2: MC_Power with Enable = FALSE and MC_MoveJog without an input are no jobs: no error.
TEST(PositioningControlPriority, NoJobNoError) {
  PositioningAxisMachine m;
  m.run(2);
  m.axis->control_priority().grant();
  m.run(5);
  EXPECT_FALSE(m.power.Error);
  EXPECT_FALSE(m.jog.Error);
}

// StatusWord.X4 follows the panel's priority (spec 04 StatusWord table, [App]).
TEST(PositioningControlPriority, StatusWordX4ShowsThePanel) {
  PositioningAxisMachine m;
  m.run(2);
  EXPECT_FALSE(control_panel_active(m.db()));
  m.axis->control_priority().grant();
  m.run(1);
  EXPECT_TRUE(control_panel_active(m.db()));
  EXPECT_DOUBLE_EQ(m.axis->read("StatusWord.X4"), 1.0);
  m.axis->control_priority().give_back();
  m.run(1);
  EXPECT_FALSE(control_panel_active(m.db()));
}

// The panel's own jobs get through; Override.Velocity has no effect on them (spec 02 §9.3, seed 004 §7.4);
// after the give-back the program's jobs are accepted again and the override acts again.
TEST(PositioningControlPriority, PanelMovesTheAxisOverrideIneffectiveReleaseReturnsControl) {
  PositioningAxisMachine m;
  Panel panel;
  panel.attach(m);
  m.run(2);
  ASSERT_TRUE(m.axis->write("Override.Velocity", 50.0).ok());
  m.axis->control_priority().grant();
  panel.power.Enable = true;
  panel.power.StopMode = 2;
  ASSERT_GT(m.run_until([&] { return panel.power.Status; }, 200), 0);
  panel.home.Mode = 0;
  panel.home.Position = 0.0;
  panel.home.Execute = true;
  ASSERT_GT(m.run_until([&] { return panel.home.Done; }, 10), 0);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, techobjects::StatusWordBit::kHomingDone));
  panel.move_absolute.Position = 1000.0;
  panel.move_absolute.Velocity = 20.0;
  panel.move_absolute.Execute = true;
  // At the constant-velocity phase the setpoint velocity is the job's, not 50 % of it.
  ASSERT_GT(m.run_until([&] { return constant_velocity(m.db()) && m.db().Velocity != 0.0; }, 5000), 0);
  EXPECT_NEAR(m.db().Velocity, 20.0, 1e-9);
  panel.move_absolute.Execute = false;
  panel.power.Enable = false;
  ASSERT_GT(m.run_until([&] { return m.axis->program_released(); }, 5000), 0);
  m.axis->control_priority().give_back();

  // Back with the user program: MC_Power and a positioning job are accepted, the override acts.
  ASSERT_GT(m.enable(), 0);
  EXPECT_FALSE(m.power.Error);
  m.move_absolute.Position = m.db().Position - 1000.0;
  m.move_absolute.Velocity = 20.0;
  m.move_absolute.Execute = true;
  ASSERT_GT(m.run_until([&] { return constant_velocity(m.db()) && m.db().Velocity != 0.0; }, 5000), 0);
  EXPECT_FALSE(m.move_absolute.Error);
  EXPECT_NEAR(m.db().Velocity, -10.0, 1e-9);
}

// The synchronous axis inherits the hook; its gearing jobs are rejected too (spec 02 §9.2: "SA, PA, SyA").
TEST(PositioningControlPriority, SynchronousAxisGearingIsRejectedWhilePanelHoldsPriority) {
  tomc::testing::GearingMachine m;
  m.power_F.Enable = false;
  ASSERT_GT(m.run_until([&] { return m.F->program_released(); }, 1000), 0);
  m.F->control_priority().grant();
  m.run(1);
  EXPECT_TRUE(control_panel_active(m.f()));
  m.gear.Execute = true;
  m.gear_velocity.Execute = true;
  m.gear_pos.Execute = true;
  m.gear_out.Execute = true;
  m.power_F.Enable = true;
  m.run(2);
  EXPECT_EQ(m.gear.ErrorID, eid::kControlPanelActive);
  EXPECT_EQ(m.gear_velocity.ErrorID, eid::kControlPanelActive);
  EXPECT_EQ(m.gear_pos.ErrorID, eid::kControlPanelActive);
  EXPECT_EQ(m.gear_out.ErrorID, eid::kControlPanelActive);
  EXPECT_EQ(m.power_F.ErrorID, eid::kControlPanelActive);
}

}  // namespace
