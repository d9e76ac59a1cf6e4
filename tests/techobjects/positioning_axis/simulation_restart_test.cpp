// A restart with a changed Simulation.Mode (decision B8): Simulation.Mode is RES ("can be changed while the
// user program runs", seed 004 §6.1.7; RES in §10.3.2 and spec 04 §3.1), so a start value written before
// MC_Reset Restart = TRUE (spec 03 §4.2) decides whether the axis uses its drive after the restart;
// VirtualAxis.Mode is RON ("only by a new download in CPU STOP", §6.1.5, spec 04 §3.2). The simulated
// drive is on telegram 3 (linear_drive(): 10 mm per load revolution); 1 ms servo = interpolator cycle. Its
// own executable: the cycles of every restart are counted by the global operator new (no allocation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "counting_allocator.hpp"
#include "positioning_axis_fixture.hpp"
#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/telegrams/drive_state.hpp"

namespace {

using tomc::techobjects::PositioningAxisData;
using tomc::techobjects::StatusWordBit;
using tomc::testing::PositioningAxisMachine;
namespace tt = tomc::techobjects;
namespace tg = tomc::telegrams;

bool status_bit(const PositioningAxisMachine& m, StatusWordBit bit) {
  return tt::test(m.db().StatusWord, bit);
}

bool config_fault(const PositioningAxisMachine& m) {
  return (m.db().ErrorWord >> static_cast<unsigned>(tt::ErrorWordBit::kConfigFault)) & 1u;
}

std::uint32_t alarm_102(const PositioningAxisMachine& m) {  // its additional value; 0: not pending
  for (const auto& a : m.axis->alarms().alarms())
    if (a.number == tt::kAlarmConfiguration) return a.additional_value;
  return 0;
}

// MC_Power Enable = FALSE until the TO is disabled, then MC_Reset Restart = TRUE (spec 03 §4.2: a restart
// needs a disabled TO). The restart's cycles allocate nothing. Returns whether MC_Reset was Done.
bool restart(PositioningAxisMachine& m) {
  m.power.Enable = false;
  EXPECT_GT(m.run_until([&] { return !m.power.Busy; }, 2000), 0);
  m.reset.Restart = true;
  m.reset.Execute = true;
  const auto before = tomc::testing::allocation_count();
  m.run(2);
  const auto allocations = tomc::testing::allocation_count() - before;
  const bool done = m.reset.Done;
  m.reset.Execute = false;
  m.reset.Restart = false;
  m.run(1);
  EXPECT_EQ(allocations, 0u);
  return done;
}

// MC_MoveRelative by `distance` at 50 mm/s; the cycles until Done (-1: not within 10 s).
int move_by(PositioningAxisMachine& m, double distance) {
  m.move_relative.Distance = distance;
  m.move_relative.Velocity = 50.0;
  m.move_relative.Execute = true;
  const auto before = tomc::testing::allocation_count();
  const int cycles = m.run_until([&] { return m.move_relative.Done; }, 10000);
  EXPECT_EQ(tomc::testing::allocation_count(), before);
  m.move_relative.Execute = false;
  m.run(1);
  return cycles;
}

PositioningAxisData simulated_data() {
  auto d = tomc::testing::linear_axis_data();
  d.Simulation.Mode = tt::kModeOn;
  return d;
}

// 0 -> 1: seed 004 §6.1.7 "an axis in simulation outputs no setpoint to the drive and reads no encoder
// value; the actual values are generated from the setpoints with a delay". After the restart the axis
// enables without the drive (§6.1.7 table: MC_Power "enabled immediately, without waiting for the drive"),
// StatusWord.X25 AxisSimulation is set (spec 04 §5.1), and a 20 mm move reaches 20 mm in the data block while
// the drive stays switched off (OFF1, never S4) where it was, its link running on without a fault.
TEST(SimulationRestart, RealToSimulatedStopsCommandingTheDrive) {
  PositioningAxisMachine m;
  ASSERT_GT(m.enable(), 1);  // through the drive's state machine: more than the call's cycle
  ASSERT_TRUE(m.home_at(0.0));
  ASSERT_GT(move_by(m, 10.0), 0);
  EXPECT_NEAR(m.drive->load_position(), 10.0, 0.01);
  EXPECT_FALSE(status_bit(m, StatusWordBit::kAxisSimulation));

  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 1).ok());
  EXPECT_TRUE(status_bit(m, StatusWordBit::kOnlineStartValuesChanged));  // spec 04 §0.2: waits for a restart
  EXPECT_EQ(m.db().Simulation.Mode, 0u);
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(m.db().Simulation.Mode, 1u);
  EXPECT_FALSE(status_bit(m, StatusWordBit::kOnlineStartValuesChanged));
  EXPECT_TRUE(status_bit(m, StatusWordBit::kAxisSimulation));
  EXPECT_EQ(m.axis->drive(), nullptr);  // no drive in use
  EXPECT_EQ(alarm_102(m), 0u);

  // Enabled in the interpolator cycle after the call (the drive is not asked); StatusDrive.InOperation
  // follows in the next MC_Servo.
  EXPECT_EQ(m.enable(), 2);
  ASSERT_TRUE(m.home_at(0.0));  // an incremental encoder lost its reference with the restart (spec 04 §8)
  EXPECT_TRUE(m.db().StatusDrive.InOperation);
  EXPECT_NE(m.drive->state(), tg::DriveState::kS4Operation);
  EXPECT_EQ(m.drive->motor_speed_rpm(), 0.0);  // switched off and at rest since the disable
  const double drive_position = m.drive->load_position();
  double farthest = 0.0;
  m.move_relative.Distance = 20.0;
  m.move_relative.Velocity = 50.0;
  m.move_relative.Execute = true;
  for (int i = 0; i < 10000 && !m.move_relative.Done; ++i) {
    m.run(1);
    farthest = std::max(farthest, m.db().ActualPosition);
    ASSERT_NE(m.drive->state(), tg::DriveState::kS4Operation) << "cycle " << i;
    ASSERT_EQ(m.db().VelocitySetpoint, 0.0);  // no setpoint output (spec 01 §2.5 table)
  }
  ASSERT_TRUE(m.move_relative.Done);
  EXPECT_NEAR(m.db().ActualPosition, 20.0, 1e-9);
  EXPECT_NEAR(farthest, 20.0, 1e-9);
  EXPECT_NEAR(m.drive->load_position(), drive_position, 1e-12);  // the drive did not move
  EXPECT_EQ(m.drive->motor_speed_rpm(), 0.0);
  EXPECT_EQ(m.drive->active_fault(), 0u);  // its sign-of-life went on: no communication fault
  EXPECT_TRUE(m.axis->alarms().alarms().empty());
}

// 1 -> 0: a simulated axis built with a drive keeps it (decision B8); after the restart the drive is used
// again: MC_Power waits for its state machine (spec 01 §6), the actual values come from its encoder — the
// restart loses the reference (spec 04 §8 rule 8, HomingDone reset), and the incremental encoder's count starts
// at 0 then (tomc's own: the drive's encoder, not the simulated 30 mm) — and a 10 mm move moves the drive's load
// by 10 mm.
TEST(SimulationRestart, SimulatedToRealUsesTheDriveAgain) {
  PositioningAxisMachine m(simulated_data());
  EXPECT_EQ(m.enable(), 2);
  ASSERT_TRUE(m.home_at(0.0));
  ASSERT_GT(move_by(m, 30.0), 0);
  EXPECT_NEAR(m.db().ActualPosition, 30.0, 1e-9);
  EXPECT_NEAR(m.drive->load_position(), 0.0, 1e-12);  // never commanded
  EXPECT_NE(m.drive->state(), tg::DriveState::kS4Operation);

  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 0).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(m.db().Simulation.Mode, 0u);
  EXPECT_FALSE(status_bit(m, StatusWordBit::kAxisSimulation));
  ASSERT_NE(m.axis->drive(), nullptr);
  EXPECT_NEAR(m.db().ActualPosition, 0.0, 1e-9);
  EXPECT_FALSE(status_bit(m, StatusWordBit::kHomingDone));

  const int cycles = m.enable();
  EXPECT_GT(cycles, 2);  // S1 -> S2 -> S3 -> S4 with the drive's answers
  EXPECT_EQ(m.drive->state(), tg::DriveState::kS4Operation);
  m.move_relative.Distance = 10.0;
  m.move_relative.Velocity = 50.0;
  m.move_relative.Execute = true;
  double fastest_command = 0.0;  // the speed setpoint to the drive, in the velocity unit (mm/s)
  for (int i = 0; i < 10000 && !m.move_relative.Done; ++i) {
    m.run(1);
    fastest_command = std::max(fastest_command, m.db().VelocitySetpoint);
  }
  ASSERT_TRUE(m.move_relative.Done);
  EXPECT_NEAR(fastest_command, 50.0, 5.0);  // Kv and precontrol around the programmed 50 mm/s
  m.run(200);
  EXPECT_NEAR(m.drive->load_position(), 10.0, 0.01);
  EXPECT_NEAR(m.db().ActualPosition, m.drive->load_position(), 0.01);
  EXPECT_NEAR(m.db().ActualPosition, 10.0, 0.01);
  EXPECT_TRUE(m.axis->alarms().alarms().empty());  // the link stayed up through the simulation
}

// Virtual <-> real: VirtualAxis.Mode is RON (seed 004 §6.1.5 "only by a new download in CPU STOP"): its
// start value cannot be written, so no restart turns a virtual axis into a real one or back. Simulation.Mode
// on a virtual axis changes nothing of its behaviour ("virtual" wins, spec 04 §3.2): after a restart with 1
// the actual value is still the setpoint one servo cycle later (§6.1.5), not the simulated control loop's
// delay, and there is no alarm.
TEST(SimulationRestart, VirtualAxisStaysVirtual) {
  auto d = tomc::testing::linear_axis_data();
  d.VirtualAxis.Mode = tt::kModeOn;
  PositioningAxisMachine m(d, tomc::testing::linear_drive(), 3, false);
  EXPECT_EQ(m.axis->write_start_value("VirtualAxis.Mode", 0).access, tt::AccessError::kReadOnly);
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 1).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(m.db().VirtualAxis.Mode, 1u);
  EXPECT_EQ(alarm_102(m), 0u);
  EXPECT_EQ(m.enable(), 2);
  ASSERT_TRUE(m.home_at(0.0));
  m.move_relative.Distance = 20.0;
  m.move_relative.Velocity = 50.0;
  m.move_relative.Execute = true;
  double previous_setpoint = m.db().Position;
  for (int i = 0; i < 10000 && !m.move_relative.Done; ++i) {
    m.run(1);
    ASSERT_NEAR(m.db().ActualPosition, previous_setpoint, 1e-12) << "cycle " << i;
    previous_setpoint = m.db().Position;
  }
  ASSERT_TRUE(m.move_relative.Done);

  // A virtual axis built with a drive never commands it: the drive is not even kept.
  PositioningAxisMachine with_drive(d);
  EXPECT_EQ(with_drive.axis->drive(), nullptr);
  EXPECT_EQ(with_drive.enable(), 2);
  with_drive.run(100);
  EXPECT_NE(with_drive.drive->state(), tg::DriveState::kS4Operation);
}

// Seed 004 §6.1.7 "to use a technology object in simulation, encoder 1 must be used for position control"
// at a restart (decision B8): Simulation.Mode 1 with InitialOperativeSensor 2 is alarm 102 (additional value
// 2, ErrorWord.X1 ConfigFault, class R, reaction "remove enable"); neither value is taken over — the axis
// stays on its drive with encoder 1, StatusWord.X3 stays TRUE — it cannot be enabled, an MC_Reset without
// restart does not clear it, and a restart with InitialOperativeSensor 1 applies the simulation and clears
// it.
TEST(SimulationRestart, EncoderOneRuleIsARestartError) {
  auto d = tomc::testing::linear_axis_data();
  d.Sensor[1].Existent = true;
  d.Sensor[1].Interface.Number = 2;  // G2 of telegram 4
  PositioningAxisMachine m(d, tomc::testing::linear_drive(), 4);
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 1).ok());
  ASSERT_TRUE(m.axis->write_start_value("PositionControl.InitialOperativeSensor", 2).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(alarm_102(m), tt::kConfigurationSimulationEncoder);
  EXPECT_EQ(m.db().ErrorDetail.Number, tt::kAlarmConfiguration);
  EXPECT_EQ(m.db().ErrorDetail.Reaction, static_cast<std::int32_t>(tt::AlarmReaction::kRemoveEnable));
  EXPECT_TRUE(config_fault(m));
  EXPECT_TRUE(status_bit(m, StatusWordBit::kError));
  EXPECT_TRUE(status_bit(m, StatusWordBit::kOnlineStartValuesChanged));
  EXPECT_EQ(m.db().Simulation.Mode, 0u);
  EXPECT_EQ(m.db().PositionControl.InitialOperativeSensor, 1u);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  EXPECT_NE(m.axis->drive(), nullptr);
  // Remove enable: MC_Power stays without Status, the drive is not switched on.
  m.power.Enable = true;
  m.run(300);
  EXPECT_FALSE(m.power.Status);
  EXPECT_NE(m.drive->state(), tg::DriveState::kS4Operation);
  m.power.Enable = false;
  m.run(5);
  // Class R: an acknowledgement alone leaves it.
  m.reset.Execute = true;
  m.run(2);
  m.reset.Execute = false;
  m.run(1);
  EXPECT_EQ(alarm_102(m), tt::kConfigurationSimulationEncoder);

  ASSERT_TRUE(m.axis->write_start_value("PositionControl.InitialOperativeSensor", 1).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(alarm_102(m), 0u);
  EXPECT_FALSE(config_fault(m));
  EXPECT_FALSE(status_bit(m, StatusWordBit::kOnlineStartValuesChanged));
  EXPECT_EQ(m.db().Simulation.Mode, 1u);
  EXPECT_TRUE(status_bit(m, StatusWordBit::kAxisSimulation));
  EXPECT_EQ(m.axis->drive(), nullptr);
  EXPECT_EQ(m.enable(), 2);
}

// Seed 004 §6.1.7 "at the end of the simulation a valid drive and encoder integration must be present": an
// axis built without a drive cannot leave the simulation; the restart is alarm 102 with additional value 1,
// Simulation.Mode stays 1 in the work memory (the axis stays simulated, StatusWord.X25) until the start value
// is 1 again.
TEST(SimulationRestart, EndingTheSimulationWithoutADriveIsARestartError) {
  PositioningAxisMachine m(simulated_data(), tomc::testing::linear_drive(), 3, false);
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 0).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(alarm_102(m), tt::kConfigurationNoDrive);
  EXPECT_TRUE(config_fault(m));
  EXPECT_EQ(m.db().Simulation.Mode, 1u);
  EXPECT_TRUE(status_bit(m, StatusWordBit::kAxisSimulation));
  EXPECT_TRUE(status_bit(m, StatusWordBit::kOnlineStartValuesChanged));
  m.power.Enable = true;
  m.run(50);
  EXPECT_FALSE(m.power.Status);
  // A second restart with the same start value finds the same error (nothing was taken over).
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(alarm_102(m), tt::kConfigurationNoDrive);
  ASSERT_TRUE(m.axis->write_start_value("Simulation.Mode", 1).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(alarm_102(m), 0u);
  EXPECT_FALSE(status_bit(m, StatusWordBit::kOnlineStartValuesChanged));
  EXPECT_EQ(m.enable(), 2);
}

// Spec 04 §3.20: InitialOperativeSensor is the encoder used after a restart; one whose Sensor[n].Existent is
// FALSE is alarm 102 with additional value 3, and the start-up encoder in force stays (never an axis whose
// operative encoder has no configuration).
TEST(SimulationRestart, StartUpEncoderThatDoesNotExistIsARestartError) {
  PositioningAxisMachine m;
  ASSERT_TRUE(m.axis->write_start_value("PositionControl.InitialOperativeSensor", 3).ok());
  ASSERT_TRUE(restart(m));
  EXPECT_EQ(alarm_102(m), tt::kConfigurationNoSuchEncoder);
  EXPECT_EQ(m.db().PositionControl.InitialOperativeSensor, 1u);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  EXPECT_EQ(m.axis->retained_of_sensor(1), &m.axis->retained());
}

}  // namespace
