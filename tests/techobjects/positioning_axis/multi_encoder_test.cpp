// Several encoders on one positioning axis (S7-1500T): spec 01 §3.8 (seed 004 §6.2.4.5), MC_SetSensor
// (spec 03 §4.12, §6 priority, T44; spec 01 §12 test 16), MC_Home with Sensor (spec 02 §5.10), spec 04
// Sensor[n] / StatusSensor[n] / OperativeSensor. Simulated drive on telegram 4: G1 = the motor encoder
// (Sensor[1]), G2 = a load-side encoder (Sensor[2]); load gear 1:1, leadscrew 10 mm, so both read the same
// position (one count = 10 mm / 2048 / 2^11 = 2.4 nm). 1 ms servo = interpolator cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_set_sensor.hpp"
#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"

namespace {

using tomc::instructions::MC_SetSensor;
using tomc::techobjects::PositioningAxis;
using tomc::techobjects::PositioningAxisData;
using tomc::techobjects::StatusWordBit;
namespace error_id = tomc::techobjects::error_id;
namespace tt = tomc::techobjects;

constexpr double kCount = 10.0 / (2048.0 * 2048.0);  // mm per Gx_XIST1 count

PositioningAxisData two_encoder_data() {
  auto d = tomc::testing::linear_axis_data();
  d.Sensor[1].Existent = true;
  d.Sensor[1].Interface.Number = 2;  // G2 of telegram 4
  d.Sensor[1].MountingMode = static_cast<std::int32_t>(tt::SensorMountingMode::kLoadSide);
  return d;
}

bool homed(const PositioningAxis& axis) {
  return (axis.data().StatusWord >> static_cast<unsigned>(StatusWordBit::kHomingDone)) & 1u;
}

std::uint32_t additional_value(const PositioningAxis& axis, std::uint32_t number) {
  for (const auto& a : axis.alarms().alarms())
    if (a.number == number) return a.additional_value;
  return 0;
}

struct TwoEncoderAxis : tomc::testing::PositioningAxisMachine {
  // with_drive = false: a virtual or simulated axis (VirtualAxis.Mode / Simulation.Mode in `d`).
  explicit TwoEncoderAxis(PositioningAxisData d = two_encoder_data(), bool with_drive = true)
      : PositioningAxisMachine(d, tomc::testing::linear_drive(), 4, with_drive) {
    user = [this] { set_sensor(*axis); };
  }
  // One MC_SetSensor call (rising edge, one cycle, falling edge); returns the ErrorID (0: Done).
  std::uint16_t switch_to(std::int16_t sensor, std::int32_t mode, std::int16_t reference = 1) {
    set_sensor.Sensor = sensor;
    set_sensor.Mode = mode;
    set_sensor.ReferenceSensor = reference;
    set_sensor.Execute = true;
    run(1);
    const std::uint16_t result = set_sensor.Done ? 0 : set_sensor.ErrorID == 0 ? 0xFFFF : set_sensor.ErrorID;
    set_sensor.Execute = false;
    run(1);
    return result;
  }
  // MC_Home Mode 13 on encoder `sensor` (spec 02 §5.10); returns the ErrorID (0: Done).
  std::uint16_t adjust(std::int32_t sensor, double position) {
    home.Mode = 13;
    home.Sensor = sensor;
    home.Position = position;
    home.Execute = true;
    run(1);
    const std::uint16_t result = home.Done ? 0 : home.ErrorID;
    home.Execute = false;
    run(1);
    return result;
  }
  int move_to(double position) {
    move_absolute.Position = position;
    move_absolute.Velocity = 50.0;
    move_absolute.Execute = true;
    const int cycles = run_until([&] { return move_absolute.Done; }, 10000);
    move_absolute.Execute = false;
    run(1);
    return cycles;
  }
  MC_SetSensor<PositioningAxis> set_sensor;
};

// Spec 01 §3.8: "actual values of all used encoders are continuously updated": the load-side encoder follows
// the motor encoder in every servo cycle of a 100 mm move (no backlash, gear 1:1: within two counts).
TEST(MultipleEncoders, EveryEncoderIsReadEveryServoCycle) {
  TwoEncoderAxis m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  m.move_absolute.Position = 100.0;
  m.move_absolute.Velocity = 50.0;
  m.move_absolute.Execute = true;
  double largest = 0.0;
  int cycles = 0;
  for (; cycles < 5000 && !m.move_absolute.Done; ++cycles) {
    m.run(1);
    const auto& s = m.db().StatusSensor;
    largest = std::max(largest, std::fabs(s[1].Position - s[0].Position));
    ASSERT_EQ(s[1].State, static_cast<std::int32_t>(tt::SensorState::VALID)) << "cycle " << cycles;
    ASSERT_NEAR(s[1].Velocity, s[0].Velocity, 1e-3) << "cycle " << cycles;
  }
  ASSERT_TRUE(m.move_absolute.Done);
  EXPECT_GT(cycles, 2000);  // 100 mm at 50 mm/s: 2 s plus the ramps
  EXPECT_LE(largest, 2 * kCount);
  EXPECT_NEAR(m.db().StatusSensor[0].Position, m.db().ActualPosition, 1e-12);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 100.0, 0.01);
}

// seed 004 §6.2.4.5 "single encoders may stop as long as they take no part in position control": an error
// of encoder 2 is alarm 433 (no reaction; additional value 2 * 65536 + the Gx_XIST2 code, decision B2), the
// move goes on; encoder 1's error stays alarm 431 with its remove-enable reaction.
TEST(MultipleEncoders, AnErrorOfAnEncoderOutsideTheLoopDoesNotStopTheAxis) {
  TwoEncoderAxis m;
  ASSERT_GT(m.enable(), 0);
  m.move_velocity.Velocity = 20.0;
  m.move_velocity.Execute = true;
  m.run(300);
  ASSERT_TRUE(m.move_velocity.InVelocity);
  m.drive->inject_encoder_error(2, 0x0003);
  m.run(5);
  EXPECT_TRUE(m.axis->alarms().pending(tt::kAlarmAdditionalSensorFault));
  EXPECT_EQ(additional_value(*m.axis, tt::kAlarmAdditionalSensorFault), 2u * 65536u + 3u);
  EXPECT_FALSE(m.axis->alarms().pending(tt::kAlarmSensorFault));
  EXPECT_TRUE(m.db().StatusSensor[1].Error);
  EXPECT_EQ(m.db().StatusSensor[1].State, static_cast<std::int32_t>(tt::SensorState::WAITING_FOR_VALID));
  EXPECT_FALSE(m.db().StatusSensor[0].Error);
  // Encoder 2 cannot become operative nor give its position while it fails (decision B4).
  EXPECT_EQ(m.switch_to(2, 0), error_id::kEncoderNotValid);
  EXPECT_EQ(m.switch_to(1, 3, 2), error_id::kEncoderNotValid);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  m.run(100);
  EXPECT_TRUE(m.power.Status);
  EXPECT_TRUE(m.move_velocity.InVelocity);
  EXPECT_NEAR(m.db().ActualVelocity, 20.0, 0.2);
  // The cause gone, MC_Reset acknowledges the alarm and the encoder (Gx_STW.15): valid again.
  m.drive->clear_encoder_error(2);
  m.reset.Execute = true;
  m.run(20);
  m.reset.Execute = false;
  m.run(1);
  EXPECT_FALSE(m.axis->alarms().pending(tt::kAlarmAdditionalSensorFault));
  EXPECT_FALSE(m.db().StatusSensor[1].Error);
  EXPECT_EQ(m.db().StatusSensor[1].State, static_cast<std::int32_t>(tt::SensorState::VALID));
}

// Spec 01 §12 test 16: encoder 1 at 100.000 mm, encoder 2 at 100.400 mm (MC_Home Mode 13 on encoder 2,
// spec 02 §5.10: only that encoder moves). MC_SetSensor Mode 0: ActualPosition stays 100.000 (no jump),
// OperativeSensor 2, homing status unchanged; the next move is measured by encoder 2.
TEST(MultipleEncoders, SetSensorMode0SwitchesWithoutAJump) {
  TwoEncoderAxis m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  EXPECT_EQ(m.adjust(2, 0.4), 0);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 0.4, 1e-9);
  EXPECT_NEAR(m.db().ActualPosition, 0.0, 1e-6);  // the axis' position did not move
  EXPECT_EQ(m.db().StatusSensor[1].Adjusted, 1);
  ASSERT_GT(m.move_to(100.0), 0);
  m.run(200);
  const double before = m.db().ActualPosition;
  EXPECT_NEAR(before, 100.0, 0.001);
  EXPECT_NEAR(m.db().StatusSensor[1].Position - m.db().StatusSensor[0].Position, 0.4, 1e-6);
  ASSERT_TRUE(homed(*m.axis));

  EXPECT_EQ(m.switch_to(2, 0), 0);
  EXPECT_EQ(m.db().OperativeSensor, 2u);
  EXPECT_NEAR(m.db().ActualPosition, before, 1e-6);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, before, 1e-6);
  EXPECT_TRUE(homed(*m.axis));
  m.run(200);
  EXPECT_NEAR(m.db().ActualPosition, before, 1e-3);  // no compensating motion
  ASSERT_GT(m.move_to(110.0), 0);
  m.run(200);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 110.0, 0.001);
  EXPECT_NEAR(m.db().StatusSensor[0].Position, 110.0 - (before - 100.0) - 0.0, 0.002);
}

// Spec 01 §5.9: backlash compensation corrects the motor encoder's actual value (Sensor[1], motor shaft,
// 0.2 mm). After MC_SetSensor Mode 0 to the load-side encoder 2 nothing is added on a reversal: at rest after
// moving back, ActualPosition is encoder 2's position and StatusWord2.X2 (passing backlash) never shows
// (decision B4; before, the start-up encoder's 0.2 mm went on being added to encoder 2).
TEST(MultipleEncoders, BacklashCompensationOnlyWhileItsEncoderClosesTheLoop) {
  auto d = two_encoder_data();
  d.Sensor[0].Backlash.Enable = true;
  d.Sensor[0].Backlash.Size = 0.2;
  TwoEncoderAxis m(d);
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  ASSERT_GT(m.move_to(50.0), 0);
  m.run(100);
  ASSERT_EQ(m.switch_to(2, 0), 0);
  ASSERT_EQ(m.db().OperativeSensor, 2u);
  bool passing = false;
  m.move_absolute.Position = 20.0;
  m.move_absolute.Velocity = 50.0;
  m.move_absolute.Execute = true;
  for (int k = 0; k < 5000 && !m.move_absolute.Done; ++k) {
    m.run(1);
    passing = passing || tt::test(m.db().StatusWord2, tt::StatusWord2Bit::kPassingBacklash);
  }
  ASSERT_TRUE(m.move_absolute.Done);
  m.run(200);
  EXPECT_FALSE(passing);
  EXPECT_NEAR(m.db().ActualPosition, m.db().StatusSensor[1].Position, 1e-9);
  EXPECT_NEAR(m.db().ActualPosition, 20.0, 0.01);
}

// Spec 01 §3.8 Mode 1: the difference D = p_old - p_new reaches ActualPosition as D·exp(-t/T), T =
// SmoothingTimeByChangeDifference = 10 ms; position control then moves the load by -0.4 mm until encoder 2
// reads the setpoint (spec 03 §4.12 "compensating motion").
TEST(MultipleEncoders, SetSensorMode1SmoothsTheDifferenceAndCompensates) {
  auto d = two_encoder_data();
  d.PositionControl.SmoothingTimeByChangeDifference = 0.010;
  TwoEncoderAxis m(d);
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(100.0));
  ASSERT_EQ(m.adjust(2, 100.4), 0);
  m.run(100);
  const double p_old = m.db().ActualPosition;
  ASSERT_NEAR(p_old, 100.0, 1e-6);

  m.set_sensor.Sensor = 2;
  m.set_sensor.Mode = 1;
  m.set_sensor.Execute = true;
  m.run(1);  // the user program switches; the next MC_Servo shows the first smoothed step
  ASSERT_TRUE(m.set_sensor.Done);
  double previous = m.db().ActualPosition;
  double largest_step = 0.0;
  for (int i = 1; i <= 1500; ++i) {
    m.run(1);
    if (i == 1) {
      // 100.4 - 0.4·exp(-1 ms / 10 ms) = 100.038, the controller has not moved the load yet
      EXPECT_NEAR(m.db().ActualPosition, 100.4 - 0.4 * std::exp(-0.1), 0.002);
    }
    largest_step = std::max(largest_step, std::fabs(m.db().ActualPosition - previous));
    previous = m.db().ActualPosition;
  }
  EXPECT_LT(largest_step, 0.05);  // never the 0.4 mm step
  EXPECT_EQ(m.db().OperativeSensor, 2u);
  EXPECT_NEAR(m.db().ActualPosition, 100.0, 0.002);
  EXPECT_NEAR(m.db().StatusSensor[0].Position, 99.6, 0.002);  // the load moved
  EXPECT_TRUE(m.power.Status);
}

// Mode 1 with SmoothingTimeByChangeDifference = 0: the difference is a control deviation at once.
// spec 01 §3.8 (MC_SetSensor Mode 1: no position transfer, the difference smoothed with
// SmoothingTimeByChangeDifference, here 0).
TEST(MultipleEncoders, SetSensorMode1WithoutSmoothingJumps) {
  TwoEncoderAxis m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(100.0));
  ASSERT_EQ(m.adjust(2, 100.4), 0);
  m.run(100);
  m.set_sensor.Sensor = 2;
  m.set_sensor.Mode = 1;
  m.set_sensor.Execute = true;
  m.run(2);
  EXPECT_NEAR(m.db().ActualPosition, 100.4, 0.002);
  m.set_sensor.Execute = false;
  m.run(1500);
  EXPECT_NEAR(m.db().ActualPosition, 100.0, 0.002);
  EXPECT_NEAR(m.db().StatusSensor[0].Position, 99.6, 0.002);
}

// Modes 2 and 3 prepare a switch without one (spec 03 §4.12): 2 gives encoder 2 the axis' position, 3 gives
// encoder 1 (the operative one) encoder 2's, with the setpoint moving along (no motion, decision B4).
TEST(MultipleEncoders, SetSensorModes2And3TransferWithoutSwitching) {
  TwoEncoderAxis m;
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(50.0));
  ASSERT_EQ(m.adjust(2, 52.0), 0);
  EXPECT_EQ(m.switch_to(2, 2), 0);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 50.0, 1e-6);
  ASSERT_EQ(m.adjust(2, 53.0), 0);
  EXPECT_EQ(m.switch_to(1, 3, 2), 0);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  EXPECT_NEAR(m.db().ActualPosition, 53.0, 1e-6);
  EXPECT_NEAR(m.db().Position, 53.0, 1e-6);
  m.run(300);
  EXPECT_NEAR(m.db().ActualPosition, 53.0, 1e-3);
  EXPECT_NEAR(m.drive->load_position(), 0.0, 1e-3);  // nothing moved (direct homing at 50 mm moved none)
}

// Prerequisites and priority (spec 03 §4.12, §6, T44): an encoder that is not configured 16#811B, Mode 4
// 16#8114, while MC_Home runs 16#811C (the homing goes on); during MC_MoveVelocity Done, and the move stays
// Busy. MC_Home with Sensor: Mode 13 only (16#811A otherwise).
TEST(MultipleEncoders, SetSensorPrerequisitesAndPriority) {
  TwoEncoderAxis m;
  ASSERT_GT(m.enable(), 0);
  EXPECT_EQ(m.switch_to(3, 0), error_id::kSensorNotConfigured);
  EXPECT_EQ(m.switch_to(0, 0), error_id::kSensorNotConfigured);
  EXPECT_EQ(m.switch_to(2, 3, 4), error_id::kSensorNotConfigured);
  EXPECT_EQ(m.switch_to(2, 4), error_id::kInvalidMode);
  EXPECT_EQ(m.db().OperativeSensor, 1u);

  m.home.Mode = 3;
  m.home.Sensor = 0;
  m.home.Position = 0.0;
  m.home.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.home.Busy);
  EXPECT_EQ(m.switch_to(2, 0), error_id::kSensorSwitchBlocked);
  EXPECT_TRUE(m.home.Busy);
  EXPECT_FALSE(m.home.CommandAborted);
  m.home.Execute = false;
  m.halt.Execute = true;  // end the homing
  m.run(500);
  m.halt.Execute = false;
  m.run(1);

  m.move_velocity.Velocity = 10.0;
  m.move_velocity.Execute = true;
  m.run(100);
  ASSERT_TRUE(m.move_velocity.Busy);
  EXPECT_EQ(m.switch_to(2, 0), 0);
  EXPECT_TRUE(m.move_velocity.Busy);
  EXPECT_FALSE(m.move_velocity.CommandAborted);
  EXPECT_EQ(m.db().OperativeSensor, 2u);
  EXPECT_EQ(m.switch_to(1, 0), 0);
  EXPECT_TRUE(m.move_velocity.Busy);
  m.move_velocity.Execute = false;

  m.home.Execute = false;
  m.run(1);
  m.home.Mode = 0;
  m.home.Sensor = 2;
  m.home.Execute = true;
  m.run(1);
  EXPECT_EQ(m.home.ErrorID, error_id::kInvalidSensor);
}

// MC_Reset with Restart: the start-up encoder (PositionControl.InitialOperativeSensor) is operative again.
// spec 04 §3.20 (PositionControl.InitialOperativeSensor: the encoder after a TO restart), spec 01 §3.8.
TEST(MultipleEncoders, RestartReturnsToTheStartUpEncoder) {
  TwoEncoderAxis m;
  EXPECT_EQ(m.switch_to(2, 1), 0);
  EXPECT_EQ(m.db().OperativeSensor, 2u);
  m.reset.Restart = true;
  m.reset.Execute = true;
  m.run(3);
  m.reset.Execute = false;
  m.run(1);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  EXPECT_EQ(m.axis->operative_encoder().source(), tt::EncoderSource::kDriveG1);
  ASSERT_EQ(m.axis->additional_encoders().all().size(), 1u);
  EXPECT_EQ(m.axis->additional_encoders().all()[0].number, 2u);
}

// Start-up with InitialOperativeSensor = 2: the load encoder closes the loop from the first cycle.
// spec 04 §3.20 (InitialOperativeSensor 1…4, RES), spec 01 §3.8 (exactly one encoder closes the loop).
TEST(MultipleEncoders, InitialOperativeSensorTwo) {
  auto d = two_encoder_data();
  d.PositionControl.InitialOperativeSensor = 2;
  TwoEncoderAxis m(d);
  EXPECT_EQ(m.db().OperativeSensor, 2u);
  EXPECT_EQ(m.axis->operative_encoder().source(), tt::EncoderSource::kDriveG2);
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  ASSERT_GT(m.move_to(20.0), 0);
  EXPECT_NEAR(m.db().StatusSensor[0].Position, 20.0, 0.01);
}

// Configuration: an existing encoder that no telegram of the device carries is named with its path.
// Decision B3 (which telegram carries Sensor[n]), ARCHITECTURE-GUIDE §6 (the error names its path).
TEST(MultipleEncoders, AnEncoderWithoutTelegramIsAConfigurationError) {
  try {
    tomc::testing::PositioningAxisMachine m(two_encoder_data(), tomc::testing::linear_drive(), 3);
    FAIL() << "telegram 3 carries one encoder only";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Sensor[2].Interface.Number"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------------------------------------
// Virtual and simulated axes with several encoders (decision B7)

// A simulated axis whose encoder 2 is a linear scale on the load: 0.01 mm per count (Resolution 0.01 mm, no
// fine resolution), counting backwards (InverseDirection) — mechanics unlike encoder 1's 2.4 nm counts.
PositioningAxisData simulated_two_encoder_data() {
  auto d = two_encoder_data();
  d.Simulation.Mode = tt::kModeOn;
  auto& s = d.Sensor[1];
  s.System = static_cast<std::int32_t>(tt::SensorMeasuringSystem::LINEAR);
  s.Parameter.Resolution = 0.01;
  s.Parameter.FineResolutionXist1 = 0;
  s.Parameter.FineResolutionXist2 = 0;
  s.InverseDirection = true;
  return d;
}

bool on_grid(double position, double step) {
  return std::fabs(position / step - std::round(position / step)) < 1e-6;
}

// Seed 004 §6.2.4.5 "Simulazione" ("simulating the axis simulates every encoder configured as used"; "every
// used encoder delivers actual values continuously") and §6.1.7/§6.1.8 (the simulated actual value lags the
// setpoint by T_t): in every servo cycle of a 100 mm move encoder 2 shows the simulated actual value through
// its own mechanics — on its 0.01 mm grid, within one of its counts — and its velocity within one count per
// servo cycle (10 mm/s); after the move it shows exactly 100 mm (no drift over 10,000 counts).
TEST(MultipleEncoders, SimulatedAxisSimulatesEveryUsedEncoder) {
  TwoEncoderAxis m(simulated_two_encoder_data(), false);
  ASSERT_EQ(m.axis->additional_encoders().all().size(), 1u);
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  EXPECT_EQ(m.db().StatusSensor[1].State, static_cast<std::int32_t>(tt::SensorState::VALID));
  EXPECT_EQ(m.db().StatusSensor[1].Position, 0.0);
  m.move_absolute.Position = 100.0;
  m.move_absolute.Velocity = 50.0;
  m.move_absolute.Execute = true;
  double largest = 0.0;
  double fastest = 0.0;
  int cycles = 0;
  for (; cycles < 5000 && !m.move_absolute.Done; ++cycles) {
    m.run(1);
    const auto& s = m.db().StatusSensor[1];
    ASSERT_EQ(s.State, static_cast<std::int32_t>(tt::SensorState::VALID)) << "cycle " << cycles;
    ASSERT_TRUE(on_grid(s.Position, 0.01)) << s.Position;
    largest = std::max(largest, std::fabs(s.Position - m.db().ActualPosition));
    ASSERT_NEAR(s.Velocity, m.db().ActualVelocity, 10.0 + 1e-6) << "cycle " << cycles;
    fastest = std::max(fastest, s.Velocity);
  }
  ASSERT_TRUE(m.move_absolute.Done);
  EXPECT_GT(cycles, 2000);  // 100 mm at 50 mm/s
  EXPECT_LE(largest, 0.01 + 1e-9);
  EXPECT_GT(largest, 0.0);  // its own grid: not the axis' value passed through
  EXPECT_NEAR(fastest, 50.0, 10.0 + 1e-6);
  m.run(100);
  EXPECT_NEAR(m.db().ActualPosition, 100.0, 1e-9);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 100.0, 1e-9);
  EXPECT_EQ(m.db().StatusSensor[1].Velocity, 0.0);
}

// Seed 004 §6.1.7: "to use a technology object in simulation, encoder 1 must be used for position control"
// (decision B7): MC_SetSensor Mode 0/1 to encoder 2 is 16#811D and encoder 1 stays; Modes 2 and 3 prepare as
// on a real axis; MC_Home Mode 13 with Sensor = 2 adjusts encoder 2 alone (spec 02 §5.10, decision B5), and
// the encoder keeps that offset while the simulated load moves.
TEST(MultipleEncoders, SimulatedAxisKeepsEncoderOneInTheLoop) {
  TwoEncoderAxis m(simulated_two_encoder_data(), false);
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  EXPECT_EQ(m.switch_to(2, 0), error_id::kSensorSwitchSimulated);
  EXPECT_EQ(m.switch_to(2, 1), error_id::kSensorSwitchSimulated);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
  EXPECT_EQ(m.switch_to(1, 0), 0);  // onto encoder 1: nothing to switch
  EXPECT_EQ(m.adjust(2, 30.0), 0);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 30.0, 1e-9);
  EXPECT_EQ(m.db().StatusSensor[1].Adjusted, 1);
  EXPECT_NEAR(m.db().ActualPosition, 0.0, 1e-9);
  ASSERT_GT(m.move_to(10.0), 0);
  m.run(100);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 40.0, 1e-9);
  // Mode 3: encoder 2's 40 mm to the operative encoder 1: the axis takes it over without motion.
  EXPECT_EQ(m.switch_to(1, 3, 2), 0);
  EXPECT_NEAR(m.db().ActualPosition, 40.0, 1e-9);
  EXPECT_NEAR(m.db().Position, 40.0, 1e-9);
  EXPECT_EQ(m.db().ActualVelocity, 0.0);
  // Mode 2: the axis' position to encoder 2, after encoder 2 was adjusted elsewhere.
  EXPECT_EQ(m.adjust(2, -5.0), 0);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, -5.0, 1e-9);
  EXPECT_EQ(m.switch_to(2, 2), 0);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 40.0, 1e-9);
  EXPECT_EQ(m.db().OperativeSensor, 1u);
}

// Seed 004 §6.1.7: a simulated axis with encoder 2 as start-up encoder is a configuration error naming the
// variable.
TEST(MultipleEncoders, SimulatedAxisStartsWithEncoderOne) {
  auto d = simulated_two_encoder_data();
  d.PositionControl.InitialOperativeSensor = 2;
  try {
    TwoEncoderAxis m(d, false);
    FAIL() << "a simulated axis closes the loop on encoder 1";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("PositionControl.InitialOperativeSensor"), std::string::npos)
        << e.what();
  }
}

// Seed 004 §6.1.8 / spec 01 §2.7: a simulated absolute encoder comes up at "the fixed simulated incremental
// value of 240 increments" plus its AbsEncoderOffset. The manual's example on encoder 2: a rotary axis, all
// ratios 1, 2048 increments per revolution, offset 137.812°: 240/2048 · 360° + 137.812° = 179.9995°
// (printed "= 180°"); the encoder is adjusted.
TEST(MultipleEncoders, SimulatedAbsoluteEncoderComesUpAtTwoHundredFortyIncrements) {
  auto d = two_encoder_data();
  d.Simulation.Mode = tt::kModeOn;
  d.Properties.MotionType = static_cast<std::int32_t>(tt::PropertiesMotionType::kRotary);
  d.Units.LengthUnit = tt::unit_code::kDegree;
  d.Units.VelocityUnit = tt::unit_code::kDegreePerSecond;
  d.Sensor[1].MountingMode = static_cast<std::int32_t>(tt::SensorMountingMode::kMotorShaft);
  d.Sensor[1].Type = static_cast<std::int32_t>(tt::SensorEncoderType::ABSOLUTE);
  d.Sensor[1].Parameter.DeterminableRevolutions = 4096;
  TwoEncoderAxis m(d, false);
  tt::RetainedEncoderData retained;
  retained.adopt(137.812, 0, 0);
  m.axis->restore_retained(2, retained);
  m.run(2);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 240.0 / 2048.0 * 360.0 + 137.812, 1e-9);
  EXPECT_NEAR(m.db().StatusSensor[1].Position, 180.0, 0.001);
  EXPECT_EQ(m.db().StatusSensor[1].Adjusted, 1);
  EXPECT_NEAR(m.db().StatusSensor[1].AbsEncoderOffset, 137.812, 1e-12);
  EXPECT_EQ(m.db().StatusSensor[1].State, static_cast<std::int32_t>(tt::SensorState::VALID));
}

// Seed 004 §6.1.5/§6.1.6 (V8.0+): a virtual axis reads no encoder value; its actual values are its setpoints
// one servo cycle later and StatusSensor.Adjusted is 1 — in every used encoder (decision B7). MC_SetSensor
// switches which Sensor[n] applies without moving anything; MC_Home Mode 13 on one encoder is 16#811A (an
// encoder that shows the setpoint cannot be adjusted alone).
TEST(MultipleEncoders, VirtualAxisShowsItsSetpointsInEveryUsedEncoder) {
  auto d = two_encoder_data();
  d.VirtualAxis.Mode = tt::kModeOn;
  TwoEncoderAxis m(d, false);
  ASSERT_GT(m.enable(), 0);
  ASSERT_TRUE(m.home_at(0.0));
  EXPECT_EQ(m.db().StatusSensor[1].Adjusted, 1);
  m.move_relative.Distance = 20.0;
  m.move_relative.Velocity = 50.0;
  m.move_relative.Execute = true;
  double previous_setpoint = m.db().Position;
  int cycles = 0;
  for (; cycles < 3000 && !m.move_relative.Done; ++cycles) {
    m.run(1);
    const auto& s = m.db().StatusSensor[1];
    ASSERT_EQ(s.Position, m.db().ActualPosition) << "cycle " << cycles;
    ASSERT_EQ(s.Velocity, m.db().ActualVelocity) << "cycle " << cycles;
    ASSERT_NEAR(s.Position, previous_setpoint, 1e-12) << "cycle " << cycles;  // one servo cycle later
    ASSERT_EQ(s.State, static_cast<std::int32_t>(tt::SensorState::VALID));
    previous_setpoint = m.db().Position;
  }
  ASSERT_TRUE(m.move_relative.Done);
  EXPECT_EQ(m.switch_to(2, 1), 0);
  EXPECT_EQ(m.db().OperativeSensor, 2u);
  m.run(10);
  EXPECT_NEAR(m.db().ActualPosition, 20.0, 1e-9);
  EXPECT_EQ(m.db().StatusSensor[0].Position, m.db().ActualPosition);
  EXPECT_EQ(m.db().StatusSensor[0].Adjusted, 1);
  EXPECT_EQ(m.switch_to(1, 3, 2), 0);
  EXPECT_NEAR(m.db().ActualPosition, 20.0, 1e-9);
  EXPECT_EQ(m.adjust(1, 5.0), error_id::kInvalidSensor);
  EXPECT_NEAR(m.db().StatusSensor[0].Position, 20.0, 1e-9);
}

}  // namespace
