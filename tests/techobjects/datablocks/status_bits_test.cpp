// The bit words of all TO types against the bit tables of spec 04 §5. Each row is one line of the spec table:
// bit number, manual name and the S / P/Y / E columns ("-" = reserved for that TO type).
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "tomc/techobjects/datablocks/status_bits.hpp"

namespace tomc::techobjects {
namespace {

constexpr auto S = TechnologyObjectType::kSpeedAxis;
constexpr auto P = TechnologyObjectType::kPositioningAxis;
constexpr auto Y = TechnologyObjectType::kSynchronousAxis;
constexpr auto E = TechnologyObjectType::kExternalEncoder;

template <typename Bit>
struct Row {
  Bit bit;
  int number;
  std::string name;
  bool s;
  bool py;
  bool e;
  bool y_only = false;  // a synchronous-axis bit of spec 07 §1.9, reserved on P
};

// Holds an enum against a spec table: numbers, names, per-TO availability, and that the enum has no extra
// bits.
template <typename Bit, std::size_t N>
void expect_table(const std::vector<Row<Bit>>& rows, const std::array<Bit, N>& all_bits,
                  std::uint32_t (*mask)(TechnologyObjectType)) {
  std::uint32_t s_mask = 0, py_mask = 0, y_mask = 0, e_mask = 0;
  std::set<int> numbers;
  for (const auto& row : rows) {
    SCOPED_TRACE(row.name);
    EXPECT_EQ(static_cast<int>(row.bit), row.number);
    EXPECT_EQ(name(row.bit), row.name);
    EXPECT_EQ(defined_on(S, row.bit), row.s);
    EXPECT_EQ(defined_on(P, row.bit), row.py);
    EXPECT_EQ(defined_on(Y, row.bit), row.py || row.y_only);  // Y has all P variables (spec 04 §0.1)
    EXPECT_EQ(defined_on(E, row.bit), row.e);
    EXPECT_TRUE(numbers.insert(row.number).second) << "bit listed twice";
    const auto m = std::uint32_t{1} << row.number;
    if (row.s) s_mask |= m;
    if (row.py) py_mask |= m;
    if (row.py || row.y_only) y_mask |= m;
    if (row.e) e_mask |= m;
  }
  // The mask has no bit the table calls reserved.
  EXPECT_EQ(mask(S), s_mask);
  EXPECT_EQ(mask(P), py_mask);
  EXPECT_EQ(mask(Y), y_mask);
  EXPECT_EQ(mask(E), e_mask);
  // Every enumerator is a row of the table, in bit order.
  ASSERT_EQ(all_bits.size(), rows.size());
  for (std::size_t i = 0; i < N; ++i)
    EXPECT_EQ(static_cast<int>(all_bits[i]), rows[i].number) << i;
}

// spec 04 §5.1 (man. §10.2.15, §10.3.38, §10.4.15); bits 19-22 and 24 are reserved on S, P, E; Y uses 21, 22
// and 24 (spec 07 §1.9)
TEST(StatusBits, StatusWord) {
  using enum StatusWordBit;
  const std::vector<Row<StatusWordBit>> rows = {
      {kEnable, 0, "Enable", true, true, true},
      {kError, 1, "Error", true, true, true},
      {kRestartActive, 2, "RestartActive", true, true, true},
      {kOnlineStartValuesChanged, 3, "OnlineStartValuesChanged", true, true, true},
      {kControlPanelActive, 4, "ControlPanelActive", true, true, false},
      {kHomingDone, 5, "HomingDone", false, true, true},
      {kDone, 6, "Done", true, true, true},
      {kStandstill, 7, "Standstill", false, true, true},
      {kPositioningCommand, 8, "PositioningCommand", false, true, false},
      {kJogCommand, 9, "JogCommand", true, true, false},
      {kVelocityCommand, 10, "VelocityCommand", true, true, false},
      {kHomingCommand, 11, "HomingCommand", false, true, true},
      {kConstantVelocity, 12, "ConstantVelocity", true, true, false},
      {kAccelerating, 13, "Accelerating", true, true, false},
      {kDecelerating, 14, "Decelerating", true, true, false},
      {kSWLimitMinActive, 15, "SWLimitMinActive", false, true, false},
      {kSWLimitMaxActive, 16, "SWLimitMaxActive", false, true, false},
      {kHWLimitMinActive, 17, "HWLimitMinActive", false, true, false},
      {kHWLimitMaxActive, 18, "HWLimitMaxActive", false, true, false},
      {kSynchronizing, 21, "Synchronizing", false, false, false, true},  // spec 07 §1.9
      {kSynchronous, 22, "Synchronous", false, false, false, true},      // spec 07 §1.9
      {kMoveSuperimposedCommand, 23, "MoveSuperimposedCommand", false, true, false},
      {kPhasingCommand, 24, "PhasingCommand", false, false, false, true},  // spec 07 §1.9
      {kAxisSimulation, 25, "AxisSimulation", true, true, false},
      {kTorqueLimitingCommand, 26, "TorqueLimitingCommand", true, true, false},
      {kInLimitation, 27, "InLimitation", true, true, false},
      {kNonPositionControlled, 28, "NonPositionControlled", false, true, false},
      {kKinematicsMotionCommand, 29, "KinematicsMotionCommand", false, true, false},
      {kInClamping, 30, "InClamping", false, true, false},
      {kMotionInCommand, 31, "MotionInCommand", false, true, false},
  };
  expect_table(rows, kStatusWordBits, &status_word_mask);
}

// spec 04 §5.2 (man. §10.2.16, §10.3.39); not present on E
TEST(StatusBits, StatusWord2) {
  using enum StatusWord2Bit;
  const std::vector<Row<StatusWord2Bit>> rows = {
      {kStopCommand, 0, "StopCommand", true, true, false},
      {kDesynchronizingCommand, 1, "DesynchronizingCommand", false, false, false, true},  // spec 07 §1.9
      {kPassingBacklash, 2, "PassingBacklash", false, true, false},
      {kPhasingCommandWaiting, 3, "PhasingCommandWaiting", false, false, false, true},  // spec 07 §1.9
      {kOffsetCommand, 4, "OffsetCommand", false, false, false, true},                  // spec 07 §1.9
      {kOffsetCommandWaiting, 5, "OffsetCommandWaiting", false, false, false, true},    // spec 07 §1.9
      {kMotionInSuperimposedCommand, 6, "MotionInSuperimposedCommand", false, true, false},
      {kHaltSuperimposedCommand, 7, "HaltSuperimposedCommand", false, true, false},
      {kMotionInSuperimposedAxesCommand, 8, "MotionInSuperimposedAxesCommand", false, true, false},
      {kPositionProfileCommand, 9, "PositionProfileCommand", false, true, false},
      {kOnProfile, 10, "OnProfile", false, true, false},
  };
  expect_table(rows, kStatusWord2Bits, &status_word2_mask);
  EXPECT_EQ(status_word2_mask(S), 0x1u);  // spec 04 §5.2: "S declares bits 1...31 reserved"
}

// spec 04 §5.3 (man. §10.2.17, §10.3.40, §10.4.16); bits 14 and 17-31 reserved
TEST(StatusBits, ErrorWord) {
  using enum ErrorWordBit;
  const std::vector<Row<ErrorWordBit>> rows = {
      {kSystemFault, 0, "SystemFault", true, true, true},
      {kConfigFault, 1, "ConfigFault", true, true, true},
      {kUserFault, 2, "UserFault", true, true, true},
      {kCommandNotAccepted, 3, "CommandNotAccepted", true, true, true},
      {kDriveFault, 4, "DriveFault", true, true, false},
      {kSensorFault, 5, "SensorFault", false, true, true},
      {kDynamicError, 6, "DynamicError", true, true, false},
      {kCommunicationFault, 7, "CommunicationFault", true, true, true},
      {kSWLimit, 8, "SWLimit", false, true, false},
      {kHWLimit, 9, "HWLimit", false, true, false},
      {kHomingError, 10, "HomingError", false, true, true},
      {kFollowingErrorFault, 11, "FollowingErrorFault", false, true, false},
      {kPositioningFault, 12, "PositioningFault", false, true, false},
      {kPeripheralError, 13, "PeripheralError", true, true, true},
      {kSynchronousError, 14, "SynchronousError", false, false, false, true},  // spec 07 §1.9
      {kAdaptionError, 15, "AdaptionError", true, true, true},
      {kSuperimposingError, 16, "SuperimposingError", false, true, false},
  };
  expect_table(rows, kErrorWordBits, &error_word_mask);
  // "HomingFault" in man. ch. 6 and 8 is the same bit (spec 04 §5.3, §14 item 4).
  EXPECT_EQ(ErrorWordBit::kHomingFault, ErrorWordBit::kHomingError);
}

// spec 04 §5.4 (man. §10.2.19, §10.3.42, §10.4.18); bits 14 and 17-31 reserved
TEST(StatusBits, WarningWord) {
  using enum WarningWordBit;
  const std::vector<Row<WarningWordBit>> rows = {
      {kSystemWarning, 0, "SystemWarning", true, true, true},
      {kConfigWarning, 1, "ConfigWarning", true, true, true},
      {kUserWarning, 2, "UserWarning", true, true, true},
      {kCommandNotAccepted, 3, "CommandNotAccepted", true, true, true},
      {kDriveWarning, 4, "DriveWarning", true, true, false},
      {kSensorWarning, 5, "SensorWarning", false, true, true},
      {kDynamicWarning, 6, "DynamicWarning", true, true, false},
      {kCommunicationWarning, 7, "CommunicationWarning", true, true, true},
      {kSWLimitMin, 8, "SWLimitMin", false, true, false},
      {kSWLimitMax, 9, "SWLimitMax", false, true, false},
      {kHomingWarning, 10, "HomingWarning", false, true, true},
      {kFollowingErrorWarning, 11, "FollowingErrorWarning", false, true, false},
      {kPositioningWarning, 12, "PositioningWarning", false, true, false},
      {kPeripheralWarning, 13, "PeripheralWarning", true, true, true},
      {kSynchronousWarning, 14, "SynchronousWarning", false, false, false, true},  // spec 07 §1.9
      {kAdaptionWarning, 15, "AdaptionWarning", true, true, true},
      {kSuperimposingWarning, 16, "SuperimposingWarning", false, true, false},
  };
  expect_table(rows, kWarningWordBits, &warning_word_mask);
}

// spec 04 §5.5 and §4.8/§4.9: the small status words
TEST(StatusBits, OtherStatusWords) {
  EXPECT_EQ(static_cast<int>(StatusKinematicsMotionBit::kMaxVelocityExceeded), 0);
  EXPECT_EQ(static_cast<int>(StatusKinematicsMotionBit::kMaxAccelerationExceeded), 1);
  EXPECT_EQ(static_cast<int>(StatusKinematicsMotionBit::kMaxDecelerationExceeded), 2);
  EXPECT_EQ(static_cast<int>(StatusMotionInBit::kMaxVelocityExceeded), 0);
  EXPECT_EQ(static_cast<int>(StatusInterpreterMotionBit::kControlledByInterpreter), 0);
  EXPECT_EQ(static_cast<int>(StatusInterpreterMotionBit::kMotionByInterpreter), 1);
  EXPECT_EQ(static_cast<int>(StatusSynchronizedMotionBit::kMaxVelocityExceeded), 0);
  EXPECT_EQ(static_cast<int>(StatusSynchronizedMotionBit::kMaxAccelerationExceeded), 1);
  EXPECT_EQ(static_cast<int>(StatusSynchronizedMotionBit::kMaxDecelerationExceeded), 2);
  EXPECT_EQ(static_cast<int>(StatusSynchronizedMotionBit::kInSimulation), 3);                 // spec 07 §1.9
  EXPECT_EQ(static_cast<int>(StatusSynchronizedMotionBit::kLeadingValueAdditiveCommand), 4);  // spec 07 §1.9
}

// The speed-axis diagnostics page (spec 04 §9.1) reads only bits the S columns define.
TEST(StatusBits, SpeedAxisDiagnosticsUsesDefinedBits) {
  for (auto bit :
       {StatusWordBit::kEnable, StatusWordBit::kError, StatusWordBit::kRestartActive,
        StatusWordBit::kControlPanelActive, StatusWordBit::kOnlineStartValuesChanged, StatusWordBit::kDone,
        StatusWordBit::kJogCommand, StatusWordBit::kVelocityCommand, StatusWordBit::kConstantVelocity,
        StatusWordBit::kAccelerating, StatusWordBit::kDecelerating, StatusWordBit::kInLimitation}) {
    EXPECT_TRUE(defined_on(S, bit)) << name(bit);
  }
  for (auto bit :
       {ErrorWordBit::kSystemFault, ErrorWordBit::kConfigFault, ErrorWordBit::kUserFault,
        ErrorWordBit::kDriveFault, ErrorWordBit::kCommunicationFault, ErrorWordBit::kPeripheralError,
        ErrorWordBit::kCommandNotAccepted, ErrorWordBit::kDynamicError}) {
    EXPECT_TRUE(defined_on(S, bit)) << name(bit);
  }
  for (auto bit : {WarningWordBit::kConfigWarning, WarningWordBit::kCommandNotAccepted,
                   WarningWordBit::kDynamicWarning}) {
    EXPECT_TRUE(defined_on(S, bit)) << name(bit);
  }
  EXPECT_FALSE(defined_on(S, StatusWordBit::kStandstill));  // "Not available on S" (spec 04 §5.1)
  EXPECT_FALSE(defined_on(S, StatusWordBit::kHomingDone));
}

// spec 04 §5.1 (StatusWord X0 Enable, X5 HomingDone, X31 MotionInCommand) and §5.3 (ErrorWord X0
// SystemFault, X15 AdaptionError).
TEST(BitWord32, SetTestReset) {
  StatusWordBits word;
  EXPECT_EQ(word.value(), 0u);
  word.set(StatusWordBit::kHomingDone);
  EXPECT_EQ(word.value(), 0x20u);
  EXPECT_TRUE(word.test(StatusWordBit::kHomingDone));
  EXPECT_FALSE(word.test(StatusWordBit::kDone));
  word.set(StatusWordBit::kMotionInCommand).set(StatusWordBit::kEnable);
  EXPECT_EQ(word.value(), 0x80000021u);
  word.reset(StatusWordBit::kHomingDone);
  EXPECT_EQ(word.value(), 0x80000001u);
  word.set(StatusWordBit::kEnable, false);
  EXPECT_EQ(word, StatusWordBits{0x80000000u});
  word.clear();
  EXPECT_EQ(word.value(), 0u);

  constexpr auto built = ErrorWordBits{}.set(ErrorWordBit::kAdaptionError).set(ErrorWordBit::kSystemFault);
  static_assert(built.value() == 0x8001u);
}

// spec 04 §5.4 (WarningWord X6 DynamicWarning, X16 SuperimposingWarning) and §5.2 (StatusWord2 X0
// StopCommand, X2 PassingBacklash, X10 OnProfile).
TEST(BitWord32, RawWordHelpers) {
  std::uint32_t word = 0;
  assign(word, WarningWordBit::kDynamicWarning, true);
  EXPECT_EQ(word, 0x40u);
  EXPECT_TRUE(test(word, WarningWordBit::kDynamicWarning));
  assign(word, WarningWordBit::kSuperimposingWarning, true);
  EXPECT_EQ(word, 0x10040u);
  assign(word, WarningWordBit::kDynamicWarning, false);
  EXPECT_EQ(word, 0x10000u);
  EXPECT_FALSE(test(word, WarningWordBit::kDynamicWarning));
  EXPECT_EQ(bit_mask(StatusWord2Bit::kOnProfile), 0x400u);
  EXPECT_EQ(bit_mask({StatusWord2Bit::kStopCommand, StatusWord2Bit::kPassingBacklash}), 0x5u);
}

}  // namespace
}  // namespace tomc::techobjects
