#pragma once
// The bit words of the axis and external-encoder technology objects: StatusWord, StatusWord2, ErrorWord,
// WarningWord (spec 04 §5.1-§5.4) and the small status words of spec 04 §5.5. The enum value IS the bit
// number, so every enumerator can be held against the spec table. One enum per word covers all TO types (the
// manual uses the same name for the same bit on every TO type); which bits a TO type defines is given by the
// *_mask() functions below (a bit outside the mask is "reserved" for that TO type).
//
// In the data blocks the words are plain DWORDs (std::uint32_t, spec 04 §0.4); BitWord32 and the free
// test/assign functions give named access to them. Header-only.

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <type_traits>

namespace tomc::techobjects {

// The TO types with a data block of their own (spec 04 §0.1). The synchronous axis has all positioning-axis
// variables, so it shares the positioning axis' bit tables.
enum class TechnologyObjectType : std::uint8_t {
  kSpeedAxis,        // S, TO_SpeedAxis
  kPositioningAxis,  // P, TO_PositioningAxis
  kSynchronousAxis,  // Y, TO_SynchronousAxis
  kExternalEncoder,  // E, TO_ExternalEncoder
  kCam,  // TO_Cam and its variants (spec 07 §3.1): StatusWord bits of their own (CamStatusWordBit)
};

// ---- bit numbers ----

// <TO>.StatusWord, spec 04 §5.1 (man. §10.2.15, §10.3.38, §10.4.15). Bits 19..22 and 24 are reserved on all
// TOs.
enum class StatusWordBit : std::uint8_t {
  kEnable = 0,
  kError = 1,
  kRestartActive = 2,
  kOnlineStartValuesChanged = 3,
  kControlPanelActive = 4,  // S, P/Y
  kHomingDone = 5,          // P/Y, E
  kDone = 6,
  kStandstill = 7,                // P/Y, E
  kPositioningCommand = 8,        // P/Y
  kJogCommand = 9,                // S, P/Y
  kVelocityCommand = 10,          // S, P/Y
  kHomingCommand = 11,            // P/Y, E
  kConstantVelocity = 12,         // S, P/Y
  kAccelerating = 13,             // S, P/Y
  kDecelerating = 14,             // S, P/Y
  kSWLimitMinActive = 15,         // P/Y
  kSWLimitMaxActive = 16,         // P/Y
  kHWLimitMinActive = 17,         // P/Y
  kHWLimitMaxActive = 18,         // P/Y
  kSynchronizing = 21,            // Y (spec 07 §1.9; reserved on P)
  kSynchronous = 22,              // Y (spec 07 §1.9; reserved on P)
  kMoveSuperimposedCommand = 23,  // P/Y
  kPhasingCommand = 24,           // Y (spec 07 §1.9, [T]; reserved on P)
  kAxisSimulation = 25,           // S, P/Y
  kTorqueLimitingCommand = 26,    // S, P/Y
  kInLimitation = 27,             // S, P/Y (correct only with SIEMENS telegram 10x, spec 04 §5.1 note 1)
  kNonPositionControlled = 28,    // P/Y
  kKinematicsMotionCommand = 29,  // P/Y (S7-1500T)
  kInClamping = 30,               // P/Y
  kMotionInCommand = 31,          // P/Y (S7-1500T); S uses StatusMotionIn.FunctionState instead
};

// <TO>.StatusWord2, spec 04 §5.2 (man. §10.2.16, §10.3.39). Not present on E.
enum class StatusWord2Bit : std::uint8_t {
  kStopCommand = 0,                      // S, P/Y
  kDesynchronizingCommand = 1,           // Y (spec 07 §1.9, [T]; reserved on P)
  kPassingBacklash = 2,                  // P/Y
  kPhasingCommandWaiting = 3,            // Y (spec 07 §1.9, [T]; reserved on P)
  kOffsetCommand = 4,                    // Y (spec 07 §1.9, [T]; reserved on P)
  kOffsetCommandWaiting = 5,             // Y (spec 07 §1.9, [T]; reserved on P)
  kMotionInSuperimposedCommand = 6,      // P/Y (T)
  kHaltSuperimposedCommand = 7,          // P/Y
  kMotionInSuperimposedAxesCommand = 8,  // P/Y (T)
  kPositionProfileCommand = 9,           // P/Y (T)
  kOnProfile = 10,                       // P/Y (T)
};

// <TO>.ErrorWord, spec 04 §5.3 (man. §10.2.17, §10.3.40, §10.4.16): groups with a pending class F or R alarm.
enum class ErrorWordBit : std::uint8_t {
  kSystemFault = 0,
  kConfigFault = 1,
  kUserFault = 2,
  kCommandNotAccepted = 3,
  kDriveFault = 4,    // S, P/Y
  kSensorFault = 5,   // P/Y, E
  kDynamicError = 6,  // S, P/Y
  kCommunicationFault = 7,
  kSWLimit = 8,                 // P/Y ("SwLimit" in man. ch. 8, spec 04 §14 item 4)
  kHWLimit = 9,                 // P/Y
  kHomingError = 10,            // P/Y, E
  kHomingFault = kHomingError,  // the same bit under its ch. 6/8 name (spec 04 §5.3, §14 item 4)
  kFollowingErrorFault = 11,    // P/Y
  kPositioningFault = 12,       // P/Y
  kPeripheralError = 13,
  kSynchronousError = 14,  // Y (spec 07 §1.9)
  kAdaptionError = 15,
  kSuperimposingError = 16,  // P/Y
};

// <TO>.WarningWord, spec 04 §5.4 (man. §10.2.19, §10.3.42, §10.4.18): groups with a pending class W alarm.
enum class WarningWordBit : std::uint8_t {
  kSystemWarning = 0,
  kConfigWarning = 1,
  kUserWarning = 2,
  kCommandNotAccepted = 3,
  kDriveWarning = 4,    // S, P/Y
  kSensorWarning = 5,   // P/Y, E
  kDynamicWarning = 6,  // S, P/Y
  kCommunicationWarning = 7,
  kSWLimitMin = 8,              // P/Y
  kSWLimitMax = 9,              // P/Y
  kHomingWarning = 10,          // P/Y, E
  kFollowingErrorWarning = 11,  // P/Y
  kPositioningWarning = 12,     // P/Y
  kPeripheralWarning = 13,
  kSynchronousWarning = 14,  // Y (spec 07 §1.9)
  kAdaptionWarning = 15,
  kSuperimposingWarning =
      16,  // P/Y (the P table prints "16...31 reserved"; read as 17...31, spec 04 §14 item 10)
};

// <TO>.StatusKinematicsMotion (P/Y, S7-1500T), spec 04 §5.5.
enum class StatusKinematicsMotionBit : std::uint8_t {
  kMaxVelocityExceeded = 0,
  kMaxAccelerationExceeded = 1,
  kMaxDecelerationExceeded = 2,
};

// <TO>.StatusMotionIn.StatusWord (P/Y), spec 04 §4.8 / §5.5.
enum class StatusMotionInBit : std::uint8_t {
  kMaxVelocityExceeded = 0,
};

// <TO>.StatusInterpreterMotion.StatusWord (S, P/Y), spec 04 §4.9 / §5.5.
enum class StatusInterpreterMotionBit : std::uint8_t {
  kControlledByInterpreter = 0,
  kMotionByInterpreter = 1,
};

// <TO>.StatusSynchronizedMotion.StatusWord (Y only; struct not defined in the manual), spec 04 §5.5.
enum class StatusSynchronizedMotionBit : std::uint8_t {
  kMaxVelocityExceeded = 0,
  kMaxAccelerationExceeded = 1,
  kMaxDecelerationExceeded = 2,
  kInSimulation = 3,                 // [T] spec 07 §1.9
  kLeadingValueAdditiveCommand = 4,  // [T] spec 07 §1.9
};

// ---- every enumerator once, in bit order (iteration for tables, traces and tests) ----

inline constexpr std::array kStatusWordBits{
    StatusWordBit::kEnable,
    StatusWordBit::kError,
    StatusWordBit::kRestartActive,
    StatusWordBit::kOnlineStartValuesChanged,
    StatusWordBit::kControlPanelActive,
    StatusWordBit::kHomingDone,
    StatusWordBit::kDone,
    StatusWordBit::kStandstill,
    StatusWordBit::kPositioningCommand,
    StatusWordBit::kJogCommand,
    StatusWordBit::kVelocityCommand,
    StatusWordBit::kHomingCommand,
    StatusWordBit::kConstantVelocity,
    StatusWordBit::kAccelerating,
    StatusWordBit::kDecelerating,
    StatusWordBit::kSWLimitMinActive,
    StatusWordBit::kSWLimitMaxActive,
    StatusWordBit::kHWLimitMinActive,
    StatusWordBit::kHWLimitMaxActive,
    StatusWordBit::kSynchronizing,
    StatusWordBit::kSynchronous,
    StatusWordBit::kMoveSuperimposedCommand,
    StatusWordBit::kPhasingCommand,
    StatusWordBit::kAxisSimulation,
    StatusWordBit::kTorqueLimitingCommand,
    StatusWordBit::kInLimitation,
    StatusWordBit::kNonPositionControlled,
    StatusWordBit::kKinematicsMotionCommand,
    StatusWordBit::kInClamping,
    StatusWordBit::kMotionInCommand,
};
inline constexpr std::array kStatusWord2Bits{
    StatusWord2Bit::kStopCommand,
    StatusWord2Bit::kDesynchronizingCommand,
    StatusWord2Bit::kPassingBacklash,
    StatusWord2Bit::kPhasingCommandWaiting,
    StatusWord2Bit::kOffsetCommand,
    StatusWord2Bit::kOffsetCommandWaiting,
    StatusWord2Bit::kMotionInSuperimposedCommand,
    StatusWord2Bit::kHaltSuperimposedCommand,
    StatusWord2Bit::kMotionInSuperimposedAxesCommand,
    StatusWord2Bit::kPositionProfileCommand,
    StatusWord2Bit::kOnProfile,
};
inline constexpr std::array kErrorWordBits{
    ErrorWordBit::kSystemFault,
    ErrorWordBit::kConfigFault,
    ErrorWordBit::kUserFault,
    ErrorWordBit::kCommandNotAccepted,
    ErrorWordBit::kDriveFault,
    ErrorWordBit::kSensorFault,
    ErrorWordBit::kDynamicError,
    ErrorWordBit::kCommunicationFault,
    ErrorWordBit::kSWLimit,
    ErrorWordBit::kHWLimit,
    ErrorWordBit::kHomingError,
    ErrorWordBit::kFollowingErrorFault,
    ErrorWordBit::kPositioningFault,
    ErrorWordBit::kPeripheralError,
    ErrorWordBit::kSynchronousError,
    ErrorWordBit::kAdaptionError,
    ErrorWordBit::kSuperimposingError,
};
inline constexpr std::array kWarningWordBits{
    WarningWordBit::kSystemWarning,        WarningWordBit::kConfigWarning,
    WarningWordBit::kUserWarning,          WarningWordBit::kCommandNotAccepted,
    WarningWordBit::kDriveWarning,         WarningWordBit::kSensorWarning,
    WarningWordBit::kDynamicWarning,       WarningWordBit::kCommunicationWarning,
    WarningWordBit::kSWLimitMin,           WarningWordBit::kSWLimitMax,
    WarningWordBit::kHomingWarning,        WarningWordBit::kFollowingErrorWarning,
    WarningWordBit::kPositioningWarning,   WarningWordBit::kPeripheralWarning,
    WarningWordBit::kSynchronousWarning,   WarningWordBit::kAdaptionWarning,
    WarningWordBit::kSuperimposingWarning,
};

// ---- names as printed in the manual ----

constexpr std::string_view name(StatusWordBit bit) noexcept {
  switch (bit) {
    case StatusWordBit::kEnable:
      return "Enable";
    case StatusWordBit::kError:
      return "Error";
    case StatusWordBit::kRestartActive:
      return "RestartActive";
    case StatusWordBit::kOnlineStartValuesChanged:
      return "OnlineStartValuesChanged";
    case StatusWordBit::kControlPanelActive:
      return "ControlPanelActive";
    case StatusWordBit::kHomingDone:
      return "HomingDone";
    case StatusWordBit::kDone:
      return "Done";
    case StatusWordBit::kStandstill:
      return "Standstill";
    case StatusWordBit::kPositioningCommand:
      return "PositioningCommand";
    case StatusWordBit::kJogCommand:
      return "JogCommand";
    case StatusWordBit::kVelocityCommand:
      return "VelocityCommand";
    case StatusWordBit::kHomingCommand:
      return "HomingCommand";
    case StatusWordBit::kConstantVelocity:
      return "ConstantVelocity";
    case StatusWordBit::kAccelerating:
      return "Accelerating";
    case StatusWordBit::kDecelerating:
      return "Decelerating";
    case StatusWordBit::kSWLimitMinActive:
      return "SWLimitMinActive";
    case StatusWordBit::kSWLimitMaxActive:
      return "SWLimitMaxActive";
    case StatusWordBit::kHWLimitMinActive:
      return "HWLimitMinActive";
    case StatusWordBit::kHWLimitMaxActive:
      return "HWLimitMaxActive";
    case StatusWordBit::kMoveSuperimposedCommand:
      return "MoveSuperimposedCommand";
    case StatusWordBit::kAxisSimulation:
      return "AxisSimulation";
    case StatusWordBit::kTorqueLimitingCommand:
      return "TorqueLimitingCommand";
    case StatusWordBit::kInLimitation:
      return "InLimitation";
    case StatusWordBit::kNonPositionControlled:
      return "NonPositionControlled";
    case StatusWordBit::kKinematicsMotionCommand:
      return "KinematicsMotionCommand";
    case StatusWordBit::kInClamping:
      return "InClamping";
    case StatusWordBit::kMotionInCommand:
      return "MotionInCommand";
    case StatusWordBit::kSynchronizing:
      return "Synchronizing";
    case StatusWordBit::kSynchronous:
      return "Synchronous";
    case StatusWordBit::kPhasingCommand:
      return "PhasingCommand";
  }
  return {};
}

constexpr std::string_view name(StatusWord2Bit bit) noexcept {
  switch (bit) {
    case StatusWord2Bit::kDesynchronizingCommand:
      return "DesynchronizingCommand";
    case StatusWord2Bit::kStopCommand:
      return "StopCommand";
    case StatusWord2Bit::kPassingBacklash:
      return "PassingBacklash";
    case StatusWord2Bit::kMotionInSuperimposedCommand:
      return "MotionInSuperimposedCommand";
    case StatusWord2Bit::kHaltSuperimposedCommand:
      return "HaltSuperimposedCommand";
    case StatusWord2Bit::kMotionInSuperimposedAxesCommand:
      return "MotionInSuperimposedAxesCommand";
    case StatusWord2Bit::kPositionProfileCommand:
      return "PositionProfileCommand";
    case StatusWord2Bit::kOnProfile:
      return "OnProfile";
    case StatusWord2Bit::kPhasingCommandWaiting:
      return "PhasingCommandWaiting";
    case StatusWord2Bit::kOffsetCommand:
      return "OffsetCommand";
    case StatusWord2Bit::kOffsetCommandWaiting:
      return "OffsetCommandWaiting";
  }
  return {};
}

constexpr std::string_view name(ErrorWordBit bit) noexcept {
  switch (bit) {
    case ErrorWordBit::kSystemFault:
      return "SystemFault";
    case ErrorWordBit::kConfigFault:
      return "ConfigFault";
    case ErrorWordBit::kUserFault:
      return "UserFault";
    case ErrorWordBit::kCommandNotAccepted:
      return "CommandNotAccepted";
    case ErrorWordBit::kDriveFault:
      return "DriveFault";
    case ErrorWordBit::kSensorFault:
      return "SensorFault";
    case ErrorWordBit::kDynamicError:
      return "DynamicError";
    case ErrorWordBit::kCommunicationFault:
      return "CommunicationFault";
    case ErrorWordBit::kSWLimit:
      return "SWLimit";
    case ErrorWordBit::kHWLimit:
      return "HWLimit";
    case ErrorWordBit::kHomingError:
      return "HomingError";
    case ErrorWordBit::kFollowingErrorFault:
      return "FollowingErrorFault";
    case ErrorWordBit::kPositioningFault:
      return "PositioningFault";
    case ErrorWordBit::kSynchronousError:
      return "SynchronousError";
    case ErrorWordBit::kPeripheralError:
      return "PeripheralError";
    case ErrorWordBit::kAdaptionError:
      return "AdaptionError";
    case ErrorWordBit::kSuperimposingError:
      return "SuperimposingError";
  }
  return {};
}

constexpr std::string_view name(WarningWordBit bit) noexcept {
  switch (bit) {
    case WarningWordBit::kSystemWarning:
      return "SystemWarning";
    case WarningWordBit::kConfigWarning:
      return "ConfigWarning";
    case WarningWordBit::kUserWarning:
      return "UserWarning";
    case WarningWordBit::kCommandNotAccepted:
      return "CommandNotAccepted";
    case WarningWordBit::kDriveWarning:
      return "DriveWarning";
    case WarningWordBit::kSensorWarning:
      return "SensorWarning";
    case WarningWordBit::kDynamicWarning:
      return "DynamicWarning";
    case WarningWordBit::kCommunicationWarning:
      return "CommunicationWarning";
    case WarningWordBit::kSWLimitMin:
      return "SWLimitMin";
    case WarningWordBit::kSWLimitMax:
      return "SWLimitMax";
    case WarningWordBit::kHomingWarning:
      return "HomingWarning";
    case WarningWordBit::kFollowingErrorWarning:
      return "FollowingErrorWarning";
    case WarningWordBit::kPositioningWarning:
      return "PositioningWarning";
    case WarningWordBit::kSynchronousWarning:
      return "SynchronousWarning";
    case WarningWordBit::kPeripheralWarning:
      return "PeripheralWarning";
    case WarningWordBit::kAdaptionWarning:
      return "AdaptionWarning";
    case WarningWordBit::kSuperimposingWarning:
      return "SuperimposingWarning";
  }
  return {};
}

// ---- bit access on a raw DWORD ----

template <typename Bit>
requires std::is_enum_v<Bit>
constexpr std::uint32_t bit_mask(Bit bit) noexcept {
  return std::uint32_t{1} << static_cast<unsigned>(bit);
}

template <typename Bit>
requires std::is_enum_v<Bit>
constexpr std::uint32_t bit_mask(std::initializer_list<Bit> bits) noexcept {
  std::uint32_t mask = 0;
  for (Bit bit : bits)
    mask |= bit_mask(bit);
  return mask;
}

template <typename Bit>
requires std::is_enum_v<Bit>
constexpr bool test(std::uint32_t word, Bit bit) noexcept {
  return (word & bit_mask(bit)) != 0;
}

template <typename Bit>
requires std::is_enum_v<Bit>
constexpr void assign(std::uint32_t& word, Bit bit, bool on) noexcept {
  word = on ? (word | bit_mask(bit)) : (word & ~bit_mask(bit));
}

// A 32-bit bit word with bits named by the enum Bit (e.g. BitWord32<StatusWordBit>).
template <typename Bit>
requires std::is_enum_v<Bit>
class BitWord32 {
 public:
  constexpr BitWord32() noexcept = default;
  constexpr explicit BitWord32(std::uint32_t value) noexcept : value_(value) {}

  constexpr std::uint32_t value() const noexcept { return value_; }
  constexpr bool test(Bit bit) const noexcept { return techobjects::test(value_, bit); }
  constexpr BitWord32& set(Bit bit, bool on = true) noexcept {
    assign(value_, bit, on);
    return *this;
  }
  constexpr BitWord32& reset(Bit bit) noexcept { return set(bit, false); }
  constexpr BitWord32& clear() noexcept {
    value_ = 0;
    return *this;
  }
  friend constexpr bool operator==(BitWord32, BitWord32) noexcept = default;

 private:
  std::uint32_t value_ = 0;
};

using StatusWordBits = BitWord32<StatusWordBit>;
using StatusWord2Bits = BitWord32<StatusWord2Bit>;
using ErrorWordBits = BitWord32<ErrorWordBit>;
using WarningWordBits = BitWord32<WarningWordBit>;

// ---- which bits each TO type defines (the "S", "P/Y", "E" columns of spec 04 §5.1-§5.4) ----

constexpr std::uint32_t status_word_mask(TechnologyObjectType type) noexcept {
  using enum StatusWordBit;
  switch (type) {
    case TechnologyObjectType::kSpeedAxis:  // spec 04 §5.1 column S (man. §10.2.15)
      return bit_mask({kEnable, kError, kRestartActive, kOnlineStartValuesChanged, kControlPanelActive, kDone,
                       kJogCommand, kVelocityCommand, kConstantVelocity, kAccelerating, kDecelerating,
                       kAxisSimulation, kTorqueLimitingCommand, kInLimitation});
    case TechnologyObjectType::kSynchronousAxis:  // P/Y plus the synchronous bits of spec 07 §1.9
      return status_word_mask(TechnologyObjectType::kPositioningAxis) |
             bit_mask({kSynchronizing, kSynchronous, kPhasingCommand});
    case TechnologyObjectType::kPositioningAxis:  // spec 04 §5.1 column P/Y (man. §10.3.38)
      return bit_mask({kEnable,
                       kError,
                       kRestartActive,
                       kOnlineStartValuesChanged,
                       kControlPanelActive,
                       kHomingDone,
                       kDone,
                       kStandstill,
                       kPositioningCommand,
                       kJogCommand,
                       kVelocityCommand,
                       kHomingCommand,
                       kConstantVelocity,
                       kAccelerating,
                       kDecelerating,
                       kSWLimitMinActive,
                       kSWLimitMaxActive,
                       kHWLimitMinActive,
                       kHWLimitMaxActive,
                       kMoveSuperimposedCommand,
                       kAxisSimulation,
                       kTorqueLimitingCommand,
                       kInLimitation,
                       kNonPositionControlled,
                       kKinematicsMotionCommand,
                       kInClamping,
                       kMotionInCommand});
    case TechnologyObjectType::kExternalEncoder:  // spec 04 §5.1 column E (man. §10.4.15)
      return bit_mask({kEnable, kError, kRestartActive, kOnlineStartValuesChanged, kHomingDone, kDone,
                       kStandstill, kHomingCommand});
    case TechnologyObjectType::kCam:  // the cam's StatusWord has its own bits (CamStatusWordBit)
      return 0;
  }
  return 0;
}

constexpr std::uint32_t status_word2_mask(TechnologyObjectType type) noexcept {
  using enum StatusWord2Bit;
  switch (type) {
    case TechnologyObjectType::kSpeedAxis:  // spec 04 §5.2 column S: bit 0 only
      return bit_mask(kStopCommand);
    case TechnologyObjectType::kSynchronousAxis:
      return status_word2_mask(TechnologyObjectType::kPositioningAxis) |
             bit_mask(
                 {kDesynchronizingCommand, kPhasingCommandWaiting, kOffsetCommand, kOffsetCommandWaiting});
    case TechnologyObjectType::kPositioningAxis:
      return bit_mask({kStopCommand, kPassingBacklash, kMotionInSuperimposedCommand, kHaltSuperimposedCommand,
                       kMotionInSuperimposedAxesCommand, kPositionProfileCommand, kOnProfile});
    case TechnologyObjectType::kExternalEncoder:  // spec 04 §5.2: not present on E
    case TechnologyObjectType::kCam:
      return 0;
  }
  return 0;
}

constexpr std::uint32_t error_word_mask(TechnologyObjectType type) noexcept {
  using enum ErrorWordBit;
  switch (type) {
    case TechnologyObjectType::kSpeedAxis:  // spec 04 §5.3 column S (man. §10.2.17)
      return bit_mask({kSystemFault, kConfigFault, kUserFault, kCommandNotAccepted, kDriveFault,
                       kDynamicError, kCommunicationFault, kPeripheralError, kAdaptionError});
    case TechnologyObjectType::kSynchronousAxis:
      return error_word_mask(TechnologyObjectType::kPositioningAxis) | bit_mask(kSynchronousError);
    case TechnologyObjectType::kPositioningAxis:
      return bit_mask({kSystemFault, kConfigFault, kUserFault, kCommandNotAccepted, kDriveFault, kSensorFault,
                       kDynamicError, kCommunicationFault, kSWLimit, kHWLimit, kHomingError,
                       kFollowingErrorFault, kPositioningFault, kPeripheralError, kAdaptionError,
                       kSuperimposingError});
    case TechnologyObjectType::kExternalEncoder:
      return bit_mask({kSystemFault, kConfigFault, kUserFault, kCommandNotAccepted, kSensorFault,
                       kCommunicationFault, kHomingError, kPeripheralError, kAdaptionError});
    case TechnologyObjectType::kCam:  // spec 07 §3.1: X0...X3
      return bit_mask({kSystemFault, kConfigFault, kUserFault, kCommandNotAccepted});
  }
  return 0;
}

constexpr std::uint32_t warning_word_mask(TechnologyObjectType type) noexcept {
  using enum WarningWordBit;
  switch (type) {
    case TechnologyObjectType::kSpeedAxis:  // spec 04 §5.4 column S (man. §10.2.19)
      return bit_mask({kSystemWarning, kConfigWarning, kUserWarning, kCommandNotAccepted, kDriveWarning,
                       kDynamicWarning, kCommunicationWarning, kPeripheralWarning, kAdaptionWarning});
    case TechnologyObjectType::kSynchronousAxis:
      return warning_word_mask(TechnologyObjectType::kPositioningAxis) | bit_mask(kSynchronousWarning);
    case TechnologyObjectType::kPositioningAxis:
      return bit_mask({kSystemWarning, kConfigWarning, kUserWarning, kCommandNotAccepted, kDriveWarning,
                       kSensorWarning, kDynamicWarning, kCommunicationWarning, kSWLimitMin, kSWLimitMax,
                       kHomingWarning, kFollowingErrorWarning, kPositioningWarning, kPeripheralWarning,
                       kAdaptionWarning, kSuperimposingWarning});
    case TechnologyObjectType::kExternalEncoder:
      return bit_mask({kSystemWarning, kConfigWarning, kUserWarning, kCommandNotAccepted, kSensorWarning,
                       kCommunicationWarning, kHomingWarning, kPeripheralWarning, kAdaptionWarning});
    case TechnologyObjectType::kCam:  // spec 07 §3.1: X0...X3
      return bit_mask({kSystemWarning, kConfigWarning, kUserWarning, kCommandNotAccepted});
  }
  return 0;
}

constexpr bool defined_on(TechnologyObjectType type, StatusWordBit bit) noexcept {
  return (status_word_mask(type) & bit_mask(bit)) != 0;
}
constexpr bool defined_on(TechnologyObjectType type, StatusWord2Bit bit) noexcept {
  return (status_word2_mask(type) & bit_mask(bit)) != 0;
}
constexpr bool defined_on(TechnologyObjectType type, ErrorWordBit bit) noexcept {
  return (error_word_mask(type) & bit_mask(bit)) != 0;
}
constexpr bool defined_on(TechnologyObjectType type, WarningWordBit bit) noexcept {
  return (warning_word_mask(type) & bit_mask(bit)) != 0;
}

}  // namespace tomc::techobjects
