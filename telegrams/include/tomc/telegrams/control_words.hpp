#pragma once
// Control and status words with their named bits (spec 06 §3). Bit numbers are the enum values, so a reader
// can hold each enum against the spec table. Drive-specific bits (ZSW1 11..15, ZSW2 0..11) stay raw.

#include <cstdint>

namespace tomc::telegrams {

// A group of adjacent bits in a word, e.g. the 4-bit sign-of-life counter in bits 12..15.
struct BitField {
  std::uint8_t first_bit;
  std::uint8_t width;
  constexpr std::uint16_t mask() const noexcept {
    return static_cast<std::uint16_t>(((1u << width) - 1u) << first_bit);
  }
};

template <typename Bit>
class Word {
 public:
  constexpr Word() noexcept = default;
  constexpr explicit Word(std::uint16_t value) noexcept : value_(value) {}

  constexpr std::uint16_t value() const noexcept { return value_; }
  constexpr bool test(Bit bit) const noexcept { return ((value_ >> static_cast<unsigned>(bit)) & 1u) != 0; }
  constexpr Word& set(Bit bit, bool on = true) noexcept {
    const auto mask = static_cast<std::uint16_t>(1u << static_cast<unsigned>(bit));
    value_ = static_cast<std::uint16_t>(on ? (value_ | mask) : (value_ & ~mask));
    return *this;
  }
  constexpr std::uint16_t field(BitField f) const noexcept {
    return static_cast<std::uint16_t>((value_ & f.mask()) >> f.first_bit);
  }
  constexpr Word& set_field(BitField f, std::uint16_t v) noexcept {
    value_ = static_cast<std::uint16_t>((value_ & ~f.mask()) | ((v << f.first_bit) & f.mask()));
    return *this;
  }
  friend constexpr bool operator==(Word, Word) noexcept = default;

 private:
  std::uint16_t value_ = 0;
};

// The 4-bit sign-of-life counter of STW2, ZSW2, STW2_ENC and ZSW2_ENC (spec 06 §5.1).
inline constexpr BitField kSignOfLifeField{12, 4};

// STW1, spec 06 §3.1. The TO owns bits 0..7 and 10; 8, 9, 11..15 belong to MC_SetAxisSTW (seed §9.14.1).
enum class Stw1Bit : std::uint8_t {
  kOn = 0,           // 1 = ON, 0 = OFF1
  kNoCoastStop = 1,  // 0 = OFF2
  kNoQuickStop = 2,  // 0 = OFF3
  kEnableOperation = 3,
  kEnableRampFunctionGenerator = 4,
  kUnfreezeRampFunctionGenerator = 5,
  kEnableSetpoint = 6,
  kAcknowledgeFault = 7,  // 0 -> 1 edge
  kJog1 = 8,
  kJog2 = 9,
  kControlByPlc = 10,
  kDriveSpecific11 = 11,
  kDriveSpecific12 = 12,
  kDriveSpecific13 = 13,
  kDriveSpecific14 = 14,
  kDriveSpecific15 = 15,
};
using Stw1 = Word<Stw1Bit>;

// ZSW1, spec 06 §3.2. Bits 11..15 differ per drive and telegram ([CONFLICT]); the state logic never uses
// them.
enum class Zsw1Bit : std::uint8_t {
  kReadyToSwitchOn = 0,
  kReady = 1,
  kOperationEnabled = 2,
  kFaultPresent = 3,
  kNoCoastStopActive = 4,
  kNoQuickStopActive = 5,
  kSwitchingOnInhibited = 6,
  kWarningPresent = 7,
  kSpeedDeviationWithinTolerance = 8,
  kControlRequested = 9,
  kComparisonValueReached = 10,
  kDriveSpecific11 = 11,
  kDriveSpecific12 = 12,
  kDriveSpecific13 = 13,
  kDriveSpecific14 = 14,
  kDriveSpecific15 = 15,
};
using Zsw1 = Word<Zsw1Bit>;

// STW2, spec 06 §3.3. Bits 12..15 are the master sign-of-life, owned by the TO.
enum class Stw2Bit : std::uint8_t {
  kParkingAxisSelection = 7,
  kTravelToFixedStop = 8,
  kMotorSwitchoverFinished = 11,
};
using Stw2 = Word<Stw2Bit>;
inline constexpr BitField kDriveDataSetSelectionField{0, 5};

// ZSW2, spec 06 §3.4. Only bits 12..15 (slave sign-of-life) are normative; the rest is exposed raw.
enum class Zsw2Bit : std::uint8_t {
  kParkingAxisActive = 7,
  kTravelToFixedStopActive = 8,
  kPulsesEnabled = 10,
  kMotorDataSetChangeoverActive = 11,
};
using Zsw2 = Word<Zsw2Bit>;
inline constexpr BitField kDriveDataSetEffectiveField{0, 5};
inline constexpr BitField kAlarmClassField{5, 2};

// MELDW, spec 06 §3.5 (telegrams 102, 103, 105, 106).
enum class MeldwBit : std::uint8_t {
  kRampFunctionCompleted = 0,
  kTorqueUtilisationBelowThreshold = 1,
  kSpeedBelowStandstillThreshold = 2,
  kSpeedAtOrBelowThreshold2 = 3,
  kNoMotorOverTemperatureAlarm = 6,
  kNoPowerUnitOverloadAlarm = 7,
  kSpeedDeviationWithinTolerance = 8,
  kControllerEnable = 11,
  kDriveReady = 12,
  kPulsesEnabled = 13,
};
using Meldw = Word<MeldwBit>;

// G1_STW / G2_STW, spec 06 §3.6.
enum class EncoderControlBit : std::uint8_t {
  kFunction1 = 0,
  kFunction2 = 1,
  kFunction3 = 2,
  kFunction4 = 3,
  kMeasurementMode = 7,     // 0 = reference-mark search, 1 = flying measurement
  kHomePositionShift = 11,  // encoder profile: 0 = set, 1 = shift
  kRequestSetHomePosition = 12,
  kRequestAbsoluteValue = 13,
  kRequestParkEncoder = 14,
  kAcknowledgeEncoderError = 15,
};
using EncoderControlWord = Word<EncoderControlBit>;
inline constexpr BitField kEncoderFunctionsField{0, 4};
inline constexpr BitField kEncoderCommandField{4, 3};

enum class EncoderCommand : std::uint8_t {
  kNone = 0,
  kActivate = 1,
  kReadValue = 2,
  kCancel = 3,
};

// G1_ZSW / G2_ZSW, spec 06 §3.7.
enum class EncoderStatusBit : std::uint8_t {
  kFunction1Active = 0,
  kFunction2Active = 1,
  kFunction3Active = 2,
  kFunction4Active = 3,
  kValue1Available = 4,
  kValue2Available = 5,
  kValue3Available = 6,
  kValue4Available = 7,
  kProbe1Deflected = 8,
  kProbe2Deflected = 9,
  kEncoderFaultAcknowledgeActive = 11,
  kHomePositionSetExecuted = 12,
  kAbsoluteValueTransmitted = 13,
  kParkingEncoderActive = 14,
  kEncoderError = 15,  // the error code is in Gx_XIST2
};
using EncoderStatusWord = Word<EncoderStatusBit>;
inline constexpr BitField kEncoderFunctionsActiveField{0, 4};
inline constexpr BitField kEncoderValuesAvailableField{4, 4};

// STW2_ENC / ZSW2_ENC of encoder telegrams 81 and 83, spec 06 §3.8.
enum class Stw2EncBit : std::uint8_t {
  kAcknowledgeFault = 7,
  kControlByPlc = 10,
};
using Stw2Enc = Word<Stw2EncBit>;

enum class Zsw2EncBit : std::uint8_t {
  kFaultPresent = 3,
  kWarningPresent = 7,
  kControlRequested = 9,
};
using Zsw2Enc = Word<Zsw2EncBit>;

}  // namespace tomc::telegrams
