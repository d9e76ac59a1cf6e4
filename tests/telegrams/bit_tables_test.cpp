// Named bits and bit groups of the control/status words against the spec 06 §3 tables.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "tomc/telegrams/control_words.hpp"
#include "tomc/telegrams/signals.hpp"
#include "tomc/telegrams/word_fields.hpp"

namespace tomc::telegrams {
namespace {

using enum Signal;

struct ExpectedField {
  std::string name;
  int first_bit;
  int width;
  std::uint16_t mask;  // the "Mask" column of the spec table
};

void expect_fields(Signal signal, const std::vector<ExpectedField>& expected) {
  SCOPED_TRACE(std::string(name(signal)));
  const auto fields = word_fields(signal);
  ASSERT_EQ(fields.size(), expected.size());
  std::uint16_t seen = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(fields[i].name, expected[i].name) << "field " << i;
    EXPECT_EQ(fields[i].field.first_bit, expected[i].first_bit) << expected[i].name;
    EXPECT_EQ(fields[i].field.width, expected[i].width) << expected[i].name;
    EXPECT_EQ(fields[i].field.mask(), expected[i].mask) << expected[i].name;
    EXPECT_EQ(seen & fields[i].field.mask(), 0) << expected[i].name << " overlaps another field";
    seen = static_cast<std::uint16_t>(seen | fields[i].field.mask());
  }
}

// spec 06 §3.1 STW1
TEST(BitTables, Stw1) {
  expect_fields(STW1, {{"On", 0, 1, 0x0001},
                       {"NoCoastStop", 1, 1, 0x0002},
                       {"NoQuickStop", 2, 1, 0x0004},
                       {"EnableOperation", 3, 1, 0x0008},
                       {"EnableRampFunctionGenerator", 4, 1, 0x0010},
                       {"UnfreezeRampFunctionGenerator", 5, 1, 0x0020},
                       {"EnableSetpoint", 6, 1, 0x0040},
                       {"AcknowledgeFault", 7, 1, 0x0080},
                       {"Jog1", 8, 1, 0x0100},
                       {"Jog2", 9, 1, 0x0200},
                       {"ControlByPlc", 10, 1, 0x0400},
                       {"DriveSpecific11", 11, 1, 0x0800},
                       {"DriveSpecific12", 12, 1, 0x1000},
                       {"DriveSpecific13", 13, 1, 0x2000},
                       {"DriveSpecific14", 14, 1, 0x4000},
                       {"DriveSpecific15", 15, 1, 0x8000}});
  EXPECT_EQ(static_cast<int>(Stw1Bit::kOn), 0);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kNoCoastStop), 1);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kNoQuickStop), 2);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kEnableOperation), 3);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kEnableRampFunctionGenerator), 4);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kUnfreezeRampFunctionGenerator), 5);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kEnableSetpoint), 6);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kAcknowledgeFault), 7);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kJog1), 8);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kJog2), 9);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kControlByPlc), 10);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kDriveSpecific11), 11);
  EXPECT_EQ(static_cast<int>(Stw1Bit::kDriveSpecific15), 15);
}

// spec 06 §3.2 ZSW1
TEST(BitTables, Zsw1) {
  expect_fields(ZSW1, {{"ReadyToSwitchOn", 0, 1, 0x0001},
                       {"Ready", 1, 1, 0x0002},
                       {"OperationEnabled", 2, 1, 0x0004},
                       {"FaultPresent", 3, 1, 0x0008},
                       {"NoCoastStopActive", 4, 1, 0x0010},
                       {"NoQuickStopActive", 5, 1, 0x0020},
                       {"SwitchingOnInhibited", 6, 1, 0x0040},
                       {"WarningPresent", 7, 1, 0x0080},
                       {"SpeedDeviationWithinTolerance", 8, 1, 0x0100},
                       {"ControlRequested", 9, 1, 0x0200},
                       {"ComparisonValueReached", 10, 1, 0x0400},
                       {"DriveSpecific11", 11, 1, 0x0800},
                       {"DriveSpecific12", 12, 1, 0x1000},
                       {"DriveSpecific13", 13, 1, 0x2000},
                       {"DriveSpecific14", 14, 1, 0x4000},
                       {"DriveSpecific15", 15, 1, 0x8000}});
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kReadyToSwitchOn), 0);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kReady), 1);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kOperationEnabled), 2);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kFaultPresent), 3);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kNoCoastStopActive), 4);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kNoQuickStopActive), 5);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kSwitchingOnInhibited), 6);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kWarningPresent), 7);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kSpeedDeviationWithinTolerance), 8);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kControlRequested), 9);
  EXPECT_EQ(static_cast<int>(Zsw1Bit::kComparisonValueReached), 10);
}

// spec 06 §3.3 STW2 (bits 5-6, 9-10 reserved)
TEST(BitTables, Stw2) {
  expect_fields(STW2, {{"DriveDataSetSelection", 0, 5, 0x001F},
                       {"ParkingAxisSelection", 7, 1, 0x0080},
                       {"TravelToFixedStop", 8, 1, 0x0100},
                       {"MotorSwitchoverFinished", 11, 1, 0x0800},
                       {"SignOfLife", 12, 4, 0xF000}});
  EXPECT_EQ(static_cast<int>(Stw2Bit::kParkingAxisSelection), 7);
  EXPECT_EQ(static_cast<int>(Stw2Bit::kTravelToFixedStop), 8);
  EXPECT_EQ(static_cast<int>(Stw2Bit::kMotorSwitchoverFinished), 11);
  EXPECT_EQ(kDriveDataSetSelectionField.mask(), 0x001F);
  EXPECT_EQ(kSignOfLifeField.mask(), 0xF000);
}

// spec 06 §3.4 ZSW2 (bit 9 reserved)
TEST(BitTables, Zsw2) {
  expect_fields(ZSW2, {{"DriveDataSetEffective", 0, 5, 0x001F},
                       {"AlarmClass", 5, 2, 0x0060},
                       {"ParkingAxisActive", 7, 1, 0x0080},
                       {"TravelToFixedStopActive", 8, 1, 0x0100},
                       {"PulsesEnabled", 10, 1, 0x0400},
                       {"MotorDataSetChangeoverActive", 11, 1, 0x0800},
                       {"SignOfLife", 12, 4, 0xF000}});
  EXPECT_EQ(static_cast<int>(Zsw2Bit::kParkingAxisActive), 7);
  EXPECT_EQ(static_cast<int>(Zsw2Bit::kTravelToFixedStopActive), 8);
  EXPECT_EQ(static_cast<int>(Zsw2Bit::kPulsesEnabled), 10);
  EXPECT_EQ(static_cast<int>(Zsw2Bit::kMotorDataSetChangeoverActive), 11);
  EXPECT_EQ(kDriveDataSetEffectiveField.mask(), 0x001F);
  EXPECT_EQ(kAlarmClassField.mask(), 0x0060);
}

// spec 06 §3.5 MELDW (bits 4-5, 9-10, 14-15 reserved)
TEST(BitTables, Meldw) {
  expect_fields(MELDW, {{"RampFunctionCompleted", 0, 1, 0x0001},
                        {"TorqueUtilisationBelowThreshold", 1, 1, 0x0002},
                        {"SpeedBelowStandstillThreshold", 2, 1, 0x0004},
                        {"SpeedAtOrBelowThreshold2", 3, 1, 0x0008},
                        {"NoMotorOverTemperatureAlarm", 6, 1, 0x0040},
                        {"NoPowerUnitOverloadAlarm", 7, 1, 0x0080},
                        {"SpeedDeviationWithinTolerance", 8, 1, 0x0100},
                        {"ControllerEnable", 11, 1, 0x0800},
                        {"DriveReady", 12, 1, 0x1000},
                        {"PulsesEnabled", 13, 1, 0x2000}});
  EXPECT_EQ(static_cast<int>(MeldwBit::kRampFunctionCompleted), 0);
  EXPECT_EQ(static_cast<int>(MeldwBit::kTorqueUtilisationBelowThreshold), 1);
  EXPECT_EQ(static_cast<int>(MeldwBit::kSpeedBelowStandstillThreshold), 2);
  EXPECT_EQ(static_cast<int>(MeldwBit::kSpeedAtOrBelowThreshold2), 3);
  EXPECT_EQ(static_cast<int>(MeldwBit::kNoMotorOverTemperatureAlarm), 6);
  EXPECT_EQ(static_cast<int>(MeldwBit::kNoPowerUnitOverloadAlarm), 7);
  EXPECT_EQ(static_cast<int>(MeldwBit::kSpeedDeviationWithinTolerance), 8);
  EXPECT_EQ(static_cast<int>(MeldwBit::kControllerEnable), 11);
  EXPECT_EQ(static_cast<int>(MeldwBit::kDriveReady), 12);
  EXPECT_EQ(static_cast<int>(MeldwBit::kPulsesEnabled), 13);
}

// spec 06 §3.6 G1_STW / G2_STW (bits 8-10 reserved)
TEST(BitTables, EncoderControlWord) {
  const std::vector<ExpectedField> expected = {{"Function1", 0, 1, 0x0001},
                                               {"Function2", 1, 1, 0x0002},
                                               {"Function3", 2, 1, 0x0004},
                                               {"Function4", 3, 1, 0x0008},
                                               {"Command", 4, 3, 0x0070},
                                               {"MeasurementMode", 7, 1, 0x0080},
                                               {"HomePositionShift", 11, 1, 0x0800},
                                               {"RequestSetHomePosition", 12, 1, 0x1000},
                                               {"RequestAbsoluteValue", 13, 1, 0x2000},
                                               {"RequestParkEncoder", 14, 1, 0x4000},
                                               {"AcknowledgeEncoderError", 15, 1, 0x8000}};
  expect_fields(G1_STW, expected);
  expect_fields(G2_STW, expected);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kFunction1), 0);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kFunction2), 1);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kFunction3), 2);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kFunction4), 3);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kMeasurementMode), 7);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kHomePositionShift), 11);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kRequestSetHomePosition), 12);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kRequestAbsoluteValue), 13);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kRequestParkEncoder), 14);
  EXPECT_EQ(static_cast<int>(EncoderControlBit::kAcknowledgeEncoderError), 15);
  EXPECT_EQ(kEncoderFunctionsField.mask(), 0x000F);
  EXPECT_EQ(kEncoderCommandField.mask(), 0x0070);
  // Command values 0..3 (§3.6).
  EXPECT_EQ(static_cast<int>(EncoderCommand::kNone), 0);
  EXPECT_EQ(static_cast<int>(EncoderCommand::kActivate), 1);
  EXPECT_EQ(static_cast<int>(EncoderCommand::kReadValue), 2);
  EXPECT_EQ(static_cast<int>(EncoderCommand::kCancel), 3);
}

// spec 06 §3.7 G1_ZSW / G2_ZSW (bit 10 reserved)
TEST(BitTables, EncoderStatusWord) {
  const std::vector<ExpectedField> expected = {{"Function1Active", 0, 1, 0x0001},
                                               {"Function2Active", 1, 1, 0x0002},
                                               {"Function3Active", 2, 1, 0x0004},
                                               {"Function4Active", 3, 1, 0x0008},
                                               {"Value1Available", 4, 1, 0x0010},
                                               {"Value2Available", 5, 1, 0x0020},
                                               {"Value3Available", 6, 1, 0x0040},
                                               {"Value4Available", 7, 1, 0x0080},
                                               {"Probe1Deflected", 8, 1, 0x0100},
                                               {"Probe2Deflected", 9, 1, 0x0200},
                                               {"EncoderFaultAcknowledgeActive", 11, 1, 0x0800},
                                               {"HomePositionSetExecuted", 12, 1, 0x1000},
                                               {"AbsoluteValueTransmitted", 13, 1, 0x2000},
                                               {"ParkingEncoderActive", 14, 1, 0x4000},
                                               {"EncoderError", 15, 1, 0x8000}};
  expect_fields(G1_ZSW, expected);
  expect_fields(G2_ZSW, expected);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kFunction1Active), 0);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kFunction4Active), 3);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kValue1Available), 4);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kValue4Available), 7);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kProbe1Deflected), 8);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kProbe2Deflected), 9);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kEncoderFaultAcknowledgeActive), 11);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kHomePositionSetExecuted), 12);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kAbsoluteValueTransmitted), 13);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kParkingEncoderActive), 14);
  EXPECT_EQ(static_cast<int>(EncoderStatusBit::kEncoderError), 15);
  EXPECT_EQ(kEncoderFunctionsActiveField.mask(), 0x000F);
  EXPECT_EQ(kEncoderValuesAvailableField.mask(), 0x00F0);
}

// spec 06 §3.8 STW2_ENC / ZSW2_ENC
TEST(BitTables, EncoderTelegramWords) {
  expect_fields(
      STW2_ENC,
      {{"AcknowledgeFault", 7, 1, 0x0080}, {"ControlByPlc", 10, 1, 0x0400}, {"SignOfLife", 12, 4, 0xF000}});
  expect_fields(ZSW2_ENC, {{"FaultPresent", 3, 1, 0x0008},
                           {"WarningPresent", 7, 1, 0x0080},
                           {"ControlRequested", 9, 1, 0x0200},
                           {"SignOfLife", 12, 4, 0xF000}});
  EXPECT_EQ(static_cast<int>(Stw2EncBit::kAcknowledgeFault), 7);
  EXPECT_EQ(static_cast<int>(Stw2EncBit::kControlByPlc), 10);
  EXPECT_EQ(static_cast<int>(Zsw2EncBit::kFaultPresent), 3);
  EXPECT_EQ(static_cast<int>(Zsw2EncBit::kWarningPresent), 7);
  EXPECT_EQ(static_cast<int>(Zsw2EncBit::kControlRequested), 9);
}

// Signals that are not words have no named fields.
// spec 06 §3 (bit tables exist only for the control/status words; the §2 setpoints and actual values are
// numbers), decision T28.
TEST(BitTables, NonWordSignalsHaveNoFields) {
  for (const Signal s : {NSOLL_A, NSOLL_B, XERR, KPC, MOMRED, M_ADD1, M_LIMIT_POS, M_LIMIT_NEG, NIST_A,
                         NIST_B, G1_XIST1, G1_XIST2, G2_XIST1, G2_XIST2, M_ACT}) {
    EXPECT_TRUE(word_fields(s).empty()) << name(s);
  }
}

// spec 06 §0.1: bit 0 = LSB; 0x047F = STW1 bits 0..6 and 10.
TEST(WordTemplate, TestReadsTheSpecExample) {
  const Stw1 stw1{0x047F};
  for (int b = 0; b < 16; ++b) {
    const bool expected = (b <= 6) || b == 10;
    EXPECT_EQ(stw1.test(static_cast<Stw1Bit>(b)), expected) << "bit " << b;
  }
}

TEST(WordTemplate, SetAndClearBuildTheCanonicalWords) {
  // spec 06 §4.3: 0x047E = bits 1-6 and 10; 0x047B = 0,1,3-6,10.
  Stw1 w;
  EXPECT_EQ(w.value(), 0);
  w.set(Stw1Bit::kNoCoastStop)
      .set(Stw1Bit::kNoQuickStop)
      .set(Stw1Bit::kEnableOperation)
      .set(Stw1Bit::kEnableRampFunctionGenerator)
      .set(Stw1Bit::kUnfreezeRampFunctionGenerator)
      .set(Stw1Bit::kEnableSetpoint)
      .set(Stw1Bit::kControlByPlc);
  EXPECT_EQ(w.value(), 0x047E);
  w.set(Stw1Bit::kOn);
  EXPECT_EQ(w.value(), 0x047F);
  w.set(Stw1Bit::kNoQuickStop, false);
  EXPECT_EQ(w.value(), 0x047B);
  w.set(Stw1Bit::kNoQuickStop, false);  // clearing twice is idempotent
  EXPECT_EQ(w.value(), 0x047B);
  w.set(Stw1Bit::kDriveSpecific15);
  EXPECT_EQ(w.value(), 0x847B);
  EXPECT_TRUE(w.test(Stw1Bit::kDriveSpecific15));
  w.set(Stw1Bit::kDriveSpecific15, false);
  EXPECT_EQ(w.value(), 0x047B);
  EXPECT_EQ(Stw1{0x047B}, w);
  EXPECT_FALSE(Stw1{0x047F} == w);
}

TEST(WordTemplate, FieldAndSetField) {
  Stw2 stw2{0x0FFF};
  EXPECT_EQ(stw2.field(kSignOfLifeField), 0);
  stw2.set_field(kSignOfLifeField, 0xA);
  EXPECT_EQ(stw2.value(), 0xAFFF);
  EXPECT_EQ(stw2.field(kSignOfLifeField), 0xA);
  EXPECT_EQ(stw2.field(kDriveDataSetSelectionField), 0x1F);
  // A value wider than the field is cut to the field and never spills into other bits.
  stw2.set_field(kSignOfLifeField, 0x1F3);
  EXPECT_EQ(stw2.value(), 0x3FFF);
  Stw2 dds{0xFFFF};
  dds.set_field(kDriveDataSetSelectionField, 0x25);
  EXPECT_EQ(dds.value(), 0xFFE5);
  EXPECT_EQ(dds.field(kDriveDataSetSelectionField), 0x05);

  EncoderControlWord g1;
  g1.set_field(kEncoderCommandField, static_cast<std::uint16_t>(EncoderCommand::kReadValue));
  g1.set_field(kEncoderFunctionsField, 0x1);
  EXPECT_EQ(g1.value(), 0x0021);  // spec 06 §6.3 "read reference mark"
  Zsw2 zsw2{0x0060};
  EXPECT_EQ(zsw2.field(kAlarmClassField), 3);
  EXPECT_EQ((BitField{0, 16}.mask()), 0xFFFF);
  EXPECT_EQ((BitField{15, 1}.mask()), 0x8000);
}

}  // namespace
}  // namespace tomc::telegrams
