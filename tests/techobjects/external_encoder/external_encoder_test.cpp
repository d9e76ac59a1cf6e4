// TO_ExternalEncoder on an encoder-only simulated device (telegram 81/83) whose shaft turns at a set speed
// (spec 01 §2.4, §5.3; spec 02 §5.1, §5.7; spec 03 §4.1 [AMB-1], §4.15; spec 04 §5, §8).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/instructions/mc_write_parameter.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace {

using namespace tomc;
using techobjects::ExternalEncoder;
using techobjects::StatusWordBit;

struct EncoderMachine {
  explicit EncoderMachine(std::uint16_t telegram = 81, techobjects::ExternalEncoderData data = {})
      : runtime(techobjects::RuntimeConfig{0.001, 1, 1}) {
    drives::DeviceConfig device;
    device.encoder_telegrams[0] = telegram;
    drives::SimulatedDriveParameters p;
    p.load_units_per_revolution = 360.0;
    p.encoder1.shaft = drives::SimulatedEncoderParameters::Shaft::kLoad;
    auto owned = std::make_unique<drives::SimulatedDrive>(device, p);
    drive = owned.get();
    auto& io = runtime.add_device(std::move(owned));
    encoder = &runtime.emplace<ExternalEncoder>("Encoder1", &io, data);
    runtime.set_user_program([this](techobjects::Runtime&) {
      power(*encoder);
      reset(*encoder);
      home(*encoder);
      write_parameter(*encoder);
    });
    runtime.start();
  }
  void run(int n) {
    for (int i = 0; i < n; ++i)
      runtime.step();
  }
  const techobjects::ExternalEncoderData& db() const { return encoder->data(); }
  techobjects::Runtime runtime;
  drives::SimulatedDrive* drive = nullptr;
  ExternalEncoder* encoder = nullptr;
  instructions::MC_Power<ExternalEncoder> power;
  instructions::MC_Reset<ExternalEncoder> reset;
  instructions::MC_Home<ExternalEncoder> home;
  instructions::MC_WriteParameter<ExternalEncoder> write_parameter;
};

// spec 01 §2.4, §5.3: a shaft at 90 °/s reads 90 °/s; after 5 s the modulo position is 450 - 360 = 90° in
// cycle 1 (spec 12 scenario 4: wrap and counter).
TEST(ExternalEncoder, PositionVelocityAndModuloFromTelegram81) {
  for (const std::uint16_t telegram : {81, 83}) {
    EncoderMachine m(telegram);
    m.run(10);
    EXPECT_EQ(m.db().StatusSensor.State, static_cast<std::int32_t>(techobjects::SensorState::VALID));
    m.drive->set_external_speed(90.0);
    m.run(5000);
    // Differentiated counts: one count per 1 ms cycle is 360° / (2048 x 2^11) / 0.001 s = 0.086 °/s.
    EXPECT_NEAR(m.db().ActualVelocity, 90.0, 0.09) << telegram;
    EXPECT_NEAR(m.db().ActualPosition, 90.0, 0.2) << telegram;
    EXPECT_EQ(m.db().ActualModuloCycle, 1) << telegram;
    EXPECT_FALSE(techobjects::test(m.db().StatusWord, StatusWordBit::kStandstill));
    m.drive->set_external_speed(-90.0);
    m.run(2000);
    EXPECT_NEAR(m.db().ActualPosition, 270.0, 0.4) << telegram;  // 90 - 180 wraps back into cycle 0
    EXPECT_EQ(m.db().ActualModuloCycle, 0) << telegram;
  }
}

// spec 03 §4.1 [AMB-1] (decision E1): MC_Power enables the external encoder once its values are valid;
// StatusWord.X0; standstill X7 with the shaft at rest.
TEST(ExternalEncoder, PowerEnablesAndStandstillIsShown) {
  EncoderMachine m;
  m.power.Enable = true;
  m.run(20);
  EXPECT_TRUE(m.power.Status);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kEnable));
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kStandstill));
  m.power.Enable = false;
  m.run(2);  // the interpolator of the next cycle disables
  EXPECT_FALSE(m.power.Status);
  EXPECT_FALSE(m.power.Busy);
}

// spec 02 §5.7, spec 01 §2.4.1: direct homing sets the actual position (Mode 0) or shifts it (Mode 1); the
// modulo counter follows the shorter way; X5 HomingDone.
TEST(ExternalEncoder, DirectHoming) {
  EncoderMachine m;
  m.run(10);
  m.home.Mode = 0;
  m.home.Position = 30.0;
  m.home.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.home.Done);
  EXPECT_NEAR(m.db().ActualPosition, 30.0, 1e-9);
  EXPECT_DOUBLE_EQ(m.home.ReferenceMarkPosition, 30.0);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));
  m.home.Execute = false;
  m.run(1);
  m.home.Mode = 1;
  m.home.Position = -60.0;  // 30 - 60 = -30 = 330° in the cycle before
  m.home.Execute = true;
  m.run(1);
  EXPECT_NEAR(m.db().ActualPosition, 330.0, 1e-9);
  EXPECT_EQ(m.db().ActualModuloCycle, -1);
  m.home.Execute = false;
  m.run(1);
  m.home.Mode = 3;  // active homing needs an axis
  m.home.Execute = true;
  m.run(1);
  EXPECT_EQ(m.home.ErrorID, techobjects::error_id::kHomingModeNotAvailable);
}

// spec 02 §5.12, spec 04 §8 rule 8: an encoder error raises the sensor alarm (ErrorWord.X5,
// ErrorDetail.Reaction 10) and an incremental encoder loses HomingDone; MC_Reset acknowledges once the error
// is gone.
TEST(ExternalEncoder, EncoderErrorRaisesTheSensorAlarmAndResetsHomed) {
  EncoderMachine m;
  m.power.Enable = true;
  m.run(10);
  m.home.Execute = true;
  m.run(2);
  ASSERT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));
  m.drive->inject_encoder_error(1, 0x0101);
  m.run(3);
  EXPECT_TRUE(m.encoder->alarms().pending(techobjects::kAlarmSensorFault));
  EXPECT_TRUE(techobjects::test(m.db().ErrorWord, techobjects::ErrorWordBit::kSensorFault));
  EXPECT_EQ(m.db().ErrorDetail.Reaction,
            static_cast<std::int32_t>(techobjects::ExternalEncoderReaction::kRemoveEnable));
  EXPECT_FALSE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));
  EXPECT_FALSE(m.power.Status);
  m.drive->clear_encoder_error(1);
  m.reset.Execute = true;
  m.run(30);
  EXPECT_FALSE(m.encoder->alarms().pending(techobjects::kAlarmSensorFault));
  EXPECT_EQ(m.db().ErrorWord, 0u);
  EXPECT_TRUE(m.power.Status);
}

// spec 06 §5.2 on ZSW2_ENC (telegram 83): a frozen encoder sign-of-life trips at the second wrong value, and
// the external encoder says so with alarm 406 (as the axes do) instead of only dropping
// StatusSensor.CommunicationOK; its value is invalid, the enable removed (reaction 10). Found by the
// fault-matrix property (issue 22).
TEST(ExternalEncoder, SignOfLifeFailureRaisesAnAlarm) {
  EncoderMachine m(83);
  m.power.Enable = true;
  m.run(20);
  ASSERT_TRUE(m.power.Status);
  m.drive->freeze_sign_of_life(true);
  m.run(1);  // first wrong value: error counter 10, tolerated
  EXPECT_FALSE(m.encoder->alarms().pending(techobjects::kAlarmDriveSignOfLife));
  m.run(1);  // second: 20 > 10
  EXPECT_TRUE(m.encoder->alarms().pending(techobjects::kAlarmDriveSignOfLife));
  EXPECT_FALSE(m.db().StatusSensor.CommunicationOK);
  EXPECT_EQ(m.db().ErrorDetail.Reaction,
            static_cast<std::int32_t>(techobjects::ExternalEncoderReaction::kRemoveEnable));
  EXPECT_FALSE(m.encoder->leading_value(techobjects::LeadingValueCoupling::kActualValue).valid);
  m.drive->freeze_sign_of_life(false);
  m.reset.Execute = true;
  m.run(30);
  EXPECT_EQ(m.encoder->alarms().alarms().size(), 0u);
  EXPECT_TRUE(m.db().StatusSensor.CommunicationOK);
  EXPECT_TRUE(m.power.Status);
}

// Decision H11 (seed 004 §6.11: Adjusted = "encoder referenced"; only an absolute encoder keeps it): an
// incremental encoder referenced by Mode 13 loses Adjusted with HomingDone when it reports an error.
TEST(ExternalEncoder, EncoderErrorResetsAdjustedOfAnIncrementalEncoder) {
  EncoderMachine m;
  m.power.Enable = true;
  m.run(10);
  m.home.Mode = 13;
  m.home.Position = 42.0;
  m.home.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.home.Done);
  ASSERT_EQ(m.db().StatusSensor.Adjusted, 1);
  m.drive->inject_encoder_error(1, 0x0101);
  m.run(3);
  EXPECT_FALSE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));
  EXPECT_EQ(m.db().StatusSensor.Adjusted, 0);
}

// spec 03 §4.15: 1010/1011/1012 are accepted on E (after restart); 1000 and 1020 belong to axes.
TEST(ExternalEncoder, WriteParameter) {
  EncoderMachine m;
  m.write_parameter.ParameterNumber = 1010;
  m.write_parameter.Value = 0.000125;
  m.write_parameter.Execute = true;
  m.run(1);
  EXPECT_TRUE(m.write_parameter.Done);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kOnlineStartValuesChanged));
  m.write_parameter.Execute = false;
  m.run(1);
  m.write_parameter.ParameterNumber = 1020;
  m.write_parameter.Execute = true;
  m.run(1);
  EXPECT_EQ(m.write_parameter.ErrorID, techobjects::error_id::kInvalidParameterNumber);
}

// spec 03 §4.15 ("after restart"), spec 07 §1.4: T_i written with MC_WriteParameter 1010 takes effect at the
// MC_Reset Restart and enters Extrapolation.LeadingAxisDependentTime = T_i + T_ipo + T1 + T2, as on the
// positioning axis. Before issue 14 the value was stored where nothing read it, and the encoder left T_i out.
TEST(ExternalEncoder, WrittenTiTakesEffectAtRestartInTheExtrapolation) {
  EncoderMachine m;
  m.run(2);
  EXPECT_DOUBLE_EQ(m.db().Extrapolation.LeadingAxisDependentTime, 0.001);  // T_i 0 + T_ipo 1 ms
  m.write_parameter.ParameterNumber = 1010;
  m.write_parameter.Value = 0.000125;
  m.write_parameter.Execute = true;
  m.run(2);
  ASSERT_TRUE(m.write_parameter.Done);
  EXPECT_DOUBLE_EQ(m.encoder->communication_times().Ti, 0.0);  // not before the restart
  EXPECT_DOUBLE_EQ(m.db().Extrapolation.LeadingAxisDependentTime, 0.001);
  m.reset.Restart = true;
  m.reset.Execute = true;
  m.run(3);
  ASSERT_TRUE(m.reset.Done);
  EXPECT_DOUBLE_EQ(m.encoder->communication_times().Ti, 0.000125);
  EXPECT_DOUBLE_EQ(m.db().Extrapolation.LeadingAxisDependentTime, 0.000125 + 0.001);
}

// spec 04 §3.8: Extrapolation.PositionFilter.T1 is DIR: written from the user program it enters the
// leading-axis time at once (as on the positioning axis).
TEST(ExternalEncoder, ExtrapolationWritesTakeEffectAtOnce) {
  EncoderMachine m;
  m.run(2);
  ASSERT_TRUE(m.encoder->write("Extrapolation.PositionFilter.T1", 0.004).ok());
  EXPECT_DOUBLE_EQ(m.db().Extrapolation.LeadingAxisDependentTime, 0.001 + 0.004);
}

// A device without an encoder telegram is a configuration error naming the variable.
// spec 01 §3.1/§3.3 (an external encoder is one encoder, read only through an encoder telegram),
// ARCHITECTURE-GUIDE §6 (the error names its variable).
TEST(ExternalEncoder, DeviceWithoutEncoderTelegramIsRejected) {
  techobjects::Runtime runtime(techobjects::RuntimeConfig{});
  drives::DeviceConfig device;
  device.drive_telegram = 1;
  auto& io = runtime.add_device(
      std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
  EXPECT_THROW(
      {
        try {
          ExternalEncoder e("E", &io, techobjects::ExternalEncoderData{});
        } catch (const std::invalid_argument& ex) {
          EXPECT_NE(std::string(ex.what()).find("E.Sensor.Interface"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
}

}  // namespace

namespace {

using namespace tomc;
using techobjects::StatusWordBit;

// spec 02 §5.6, §5.1 (EE: passive modes 2, 8, 10): the shaft turns at 90 °/s; the encoder's zero mark is at
// 0.25 rev = 90° of each turn. Mode 10 assigns Homing.HomePosition (30°) at the mark while the user's motion
// turns the shaft; X11 while searching, X5 and Done at the mark.
TEST(ExternalEncoderHoming, PassiveZeroMark) {
  techobjects::ExternalEncoderData d;
  d.Homing.HomePosition = 30.0;
  d.Sensor.PassiveHoming.Direction = 0;  // positive
  EncoderMachine m(81, d);
  m.power.Enable = true;
  m.run(10);
  m.home.Mode = 10;
  m.home.Execute = true;
  m.run(2);
  EXPECT_TRUE(m.home.Busy);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingCommand));
  m.drive->set_external_speed(90.0);
  int cycles = 0;
  for (; cycles < 3000 && !m.home.Done; ++cycles)
    m.run(1);
  ASSERT_TRUE(m.home.Done);
  EXPECT_NEAR(cycles, 1000, 5);  // 90° at 90 °/s
  // The position at the mark (90° of the shaft) is 30°: now 30° + the travel since.
  EXPECT_NEAR(m.db().ActualPosition - (m.drive->load_position() - 90.0), 30.0, 0.2);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));
  EXPECT_EQ(m.db().StatusSensor.Adjusted, 1);
}

// spec 02 §5.6: passive homing needs an enabled encoder.
TEST(ExternalEncoderHoming, PassiveNeedsEnable) {
  EncoderMachine m;
  m.run(10);
  m.home.Mode = 8;
  m.home.Execute = true;
  m.run(1);
  EXPECT_EQ(m.home.ErrorID, techobjects::error_id::kAxisNotEnabled);
}

// spec 02 §5.9: Mode 7 on an absolute external encoder is retentive: a new runtime restoring the data shows
// the same position; Mode 13 is for incremental encoders only.
TEST(ExternalEncoderHoming, AbsoluteAdjustmentIsRetentive) {
  techobjects::ExternalEncoderData d;
  d.Sensor.Type = static_cast<std::int32_t>(techobjects::SensorEncoderType::ABSOLUTE);
  d.Sensor.Parameter.DeterminableRevolutions = 4096;
  d.Modulo.Enable = false;
  techobjects::RetainedEncoderData retained;
  {
    EncoderMachine m(81, d);
    m.run(10);
    m.drive->set_external_speed(36.0);
    m.run(1000);
    m.drive->set_external_speed(0.0);
    m.run(5);
    m.home.Mode = 7;
    m.home.Position = 1000.0;
    m.home.Execute = true;
    m.run(1);
    ASSERT_TRUE(m.home.Done);
    EXPECT_DOUBLE_EQ(m.db().ActualPosition, 1000.0);
    retained = m.encoder->retained();
    ASSERT_TRUE(retained.valid);
    m.home.Execute = false;
    m.run(1);
    m.home.Mode = 13;
    m.home.Execute = true;
    m.run(1);
    EXPECT_EQ(m.home.ErrorID, techobjects::error_id::kHomingModeNotAvailable);
  }
  // The same shaft position (36°) after a restart: a device whose shaft starts there.
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig device;
  device.encoder_telegrams[0] = 81;
  drives::SimulatedDriveParameters p;
  p.load_units_per_revolution = 360.0;
  p.encoder1.shaft = drives::SimulatedEncoderParameters::Shaft::kLoad;
  p.initial_load_position = 36.0;
  auto& io = runtime.add_device(std::make_unique<drives::SimulatedDrive>(device, p));
  auto& e = runtime.emplace<ExternalEncoder>("Encoder1", &io, d);
  e.restore_retained(retained);
  runtime.start();
  for (int i = 0; i < 20; ++i)
    runtime.step();
  EXPECT_NEAR(e.data().ActualPosition, 1000.0, 0.01);
  EXPECT_TRUE(techobjects::test(e.data().StatusWord, StatusWordBit::kHomingDone));
}

// spec 02 §5.1: an adjusted absolute encoder stays adjusted until new encoder settings are downloaded;
// MC_Reset with Restart = TRUE is not such a download, so Adjusted and the position stay (spec 02 §5.12).
TEST(ExternalEncoderHoming, RestartKeepsAdjustedOfAnAbsoluteEncoder) {
  techobjects::ExternalEncoderData d;
  d.Sensor.Type = static_cast<std::int32_t>(techobjects::SensorEncoderType::ABSOLUTE);
  d.Sensor.Parameter.DeterminableRevolutions = 4096;
  d.Modulo.Enable = false;
  EncoderMachine m(81, d);
  m.run(10);
  m.home.Mode = 7;
  m.home.Position = 500.0;
  m.home.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.home.Done);
  ASSERT_EQ(m.db().StatusSensor.Adjusted, 1);
  m.reset.Restart = true;
  m.reset.Execute = true;
  m.run(3);
  ASSERT_TRUE(m.reset.Done);
  EXPECT_EQ(m.db().StatusSensor.Adjusted, 1);
  EXPECT_NEAR(m.db().ActualPosition, 500.0, 0.01);
  EXPECT_TRUE(techobjects::test(m.db().StatusWord, StatusWordBit::kHomingDone));
}

// Decision H10 (spec 03 §6.1 row MC_Home Mode 9: 'A' against passive homing; spec 02 §5.6): Mode 9 aborts a
// passive Mode 2 job also when the encoder is homed (Mode 2 keeps "homed"); the mark then changes nothing.
TEST(ExternalEncoderHoming, Mode9AbortsPassiveMode2OnAHomedEncoder) {
  EncoderMachine m;
  m.power.Enable = true;
  m.run(10);
  m.home.Mode = 0;
  m.home.Position = 0.0;
  m.home.Execute = true;
  m.run(1);
  ASSERT_TRUE(m.home.Done);
  m.home.Execute = false;
  m.run(1);
  instructions::MC_Home<ExternalEncoder> passive;
  instructions::MC_Home<ExternalEncoder> abort_passive;
  passive.Mode = 2;
  passive.Position = 200.0;
  passive.Execute = true;
  passive(*m.encoder);
  m.run(1);
  passive(*m.encoder);
  ASSERT_TRUE(passive.Busy);
  abort_passive.Mode = 9;
  abort_passive.Execute = true;
  abort_passive(*m.encoder);
  m.run(1);
  abort_passive(*m.encoder);
  passive(*m.encoder);
  EXPECT_TRUE(abort_passive.Done);
  EXPECT_TRUE(passive.CommandAborted);
  EXPECT_FALSE(passive.Busy);
  m.drive->set_external_speed(90.0);
  m.run(1500);  // the zero mark at 90° passes
  passive(*m.encoder);
  EXPECT_FALSE(passive.Done);
  EXPECT_NEAR(m.db().ActualPosition, m.drive->load_position(), 0.2);  // still the Mode 0 coordinates
}

// Decision H8 (seed 004 §6.1.4: the home position decides the modulo counter): passive Mode 2 to 180° while
// the shaft turns at 90 °/s: the mark is evaluated a little after the shaft passed it, so the present
// position is above 180 (upper half), but the home position 180 is on the inclusive boundary: counter 0.
TEST(ExternalEncoderHoming, PassiveHomingCounterFollowsTheHomePosition) {
  techobjects::ExternalEncoderData d;
  d.Sensor.PassiveHoming.Direction = 0;  // positive
  EncoderMachine m(81, d);
  ASSERT_TRUE(m.db().Modulo.Enable);
  m.power.Enable = true;
  m.run(10);
  m.home.Mode = 2;
  m.home.Position = 180.0;
  m.home.Execute = true;
  m.run(2);
  m.drive->set_external_speed(90.0);
  for (int i = 0; i < 3000 && !m.home.Done; ++i)
    m.run(1);
  ASSERT_TRUE(m.home.Done);
  // Boundary inclusive: home 180 -> counter 0 although the position is already past 180 at the mark report.
  EXPECT_GT(m.db().ActualPosition, 180.0);
  EXPECT_EQ(m.db().ActualModuloCycle, 0);
}

}  // namespace
