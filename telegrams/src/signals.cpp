// Signal table (spec 06 §1.2, §2) and raw access to the value structs.
#include "tomc/telegrams/signals.hpp"

#include <array>

#include "tomc/telegrams/word_fields.hpp"

namespace tomc::telegrams {
namespace {

constexpr auto S = Direction::kSetpoint;
constexpr auto A = Direction::kActual;

constexpr std::array<SignalInfo, kSignalCount> kSignals{{
    {Signal::STW1, "STW1", S, 16, SignalKind::kWord},
    {Signal::NSOLL_A, "NSOLL_A", S, 16, SignalKind::kNormalised},
    {Signal::NSOLL_B, "NSOLL_B", S, 32, SignalKind::kNormalised},
    {Signal::STW2, "STW2", S, 16, SignalKind::kWord},
    {Signal::G1_STW, "G1_STW", S, 16, SignalKind::kWord},
    {Signal::G2_STW, "G2_STW", S, 16, SignalKind::kWord},
    {Signal::XERR, "XERR", S, 32, SignalKind::kSigned},
    {Signal::KPC, "KPC", S, 32, SignalKind::kSigned},
    {Signal::MOMRED, "MOMRED", S, 16, SignalKind::kUnsigned},
    {Signal::STW2_ENC, "STW2_ENC", S, 16, SignalKind::kWord},
    {Signal::M_ADD1, "M_ADD1", S, 16, SignalKind::kNormalised},
    {Signal::M_LIMIT_POS, "M_LIMIT_POS", S, 16, SignalKind::kNormalised},
    {Signal::M_LIMIT_NEG, "M_LIMIT_NEG", S, 16, SignalKind::kNormalised},
    {Signal::ZSW1, "ZSW1", A, 16, SignalKind::kWord},
    {Signal::NIST_A, "NIST_A", A, 16, SignalKind::kNormalised},
    {Signal::NIST_B, "NIST_B", A, 32, SignalKind::kNormalised},
    {Signal::ZSW2, "ZSW2", A, 16, SignalKind::kWord},
    {Signal::G1_ZSW, "G1_ZSW", A, 16, SignalKind::kWord},
    {Signal::G1_XIST1, "G1_XIST1", A, 32, SignalKind::kUnsigned},
    {Signal::G1_XIST2, "G1_XIST2", A, 32, SignalKind::kUnsigned},
    {Signal::G2_ZSW, "G2_ZSW", A, 16, SignalKind::kWord},
    {Signal::G2_XIST1, "G2_XIST1", A, 32, SignalKind::kUnsigned},
    {Signal::G2_XIST2, "G2_XIST2", A, 32, SignalKind::kUnsigned},
    {Signal::MELDW, "MELDW", A, 16, SignalKind::kWord},
    {Signal::ZSW2_ENC, "ZSW2_ENC", A, 16, SignalKind::kWord},
    {Signal::M_ACT, "M_ACT", A, 16, SignalKind::kNormalised},
}};

constexpr bool table_is_indexed_by_signal() {
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    if (static_cast<std::size_t>(kSignals[i].signal) != i) return false;
  }
  return true;
}
static_assert(table_is_indexed_by_signal());

constexpr bool is_signed(const SignalInfo& s) {
  return s.kind == SignalKind::kNormalised || s.kind == SignalKind::kSigned;
}

}  // namespace

const SignalInfo& info(Signal signal) noexcept {
  return kSignals[static_cast<std::size_t>(signal)];
}

std::optional<Signal> parse_signal(std::string_view text) noexcept {
  if (text == "M_ADD") return Signal::M_ADD1;
  for (const auto& s : kSignals) {
    if (s.name == text) return s.signal;
  }
  return std::nullopt;
}

std::int64_t raw_minimum(Signal signal) noexcept {
  const auto& s = info(signal);
  if (!is_signed(s)) return 0;
  return s.bits == 16 ? INT16_MIN : INT32_MIN;
}

std::int64_t raw_maximum(Signal signal) noexcept {
  const auto& s = info(signal);
  if (is_signed(s)) return s.bits == 16 ? INT16_MAX : INT32_MAX;
  return s.bits == 16 ? UINT16_MAX : UINT32_MAX;
}

namespace {
std::uint32_t bits_of(std::int16_t v) {
  return static_cast<std::uint16_t>(v);
}
std::uint32_t bits_of(std::int32_t v) {
  return static_cast<std::uint32_t>(v);
}
std::int16_t as_int16(std::uint32_t v) {
  return static_cast<std::int16_t>(static_cast<std::uint16_t>(v));
}
std::int32_t as_int32(std::uint32_t v) {
  return static_cast<std::int32_t>(v);
}
std::uint16_t as_uint16(std::uint32_t v) {
  return static_cast<std::uint16_t>(v);
}
}  // namespace

std::uint32_t SetpointSignals::raw(Signal signal) const noexcept {
  switch (signal) {
    case Signal::STW1:
      return STW1.value();
    case Signal::NSOLL_A:
      return bits_of(NSOLL_A);
    case Signal::NSOLL_B:
      return bits_of(NSOLL_B);
    case Signal::STW2:
      return STW2.value();
    case Signal::G1_STW:
      return G1_STW.value();
    case Signal::G2_STW:
      return G2_STW.value();
    case Signal::XERR:
      return bits_of(XERR);
    case Signal::KPC:
      return bits_of(KPC);
    case Signal::MOMRED:
      return MOMRED;
    case Signal::STW2_ENC:
      return STW2_ENC.value();
    case Signal::M_ADD1:
      return bits_of(M_ADD1);
    case Signal::M_LIMIT_POS:
      return bits_of(M_LIMIT_POS);
    case Signal::M_LIMIT_NEG:
      return bits_of(M_LIMIT_NEG);
    default:
      return 0;
  }
}

void SetpointSignals::set_raw(Signal signal, std::uint32_t v) noexcept {
  switch (signal) {
    case Signal::STW1:
      STW1 = Stw1{as_uint16(v)};
      break;
    case Signal::NSOLL_A:
      NSOLL_A = as_int16(v);
      break;
    case Signal::NSOLL_B:
      NSOLL_B = as_int32(v);
      break;
    case Signal::STW2:
      STW2 = Stw2{as_uint16(v)};
      break;
    case Signal::G1_STW:
      G1_STW = EncoderControlWord{as_uint16(v)};
      break;
    case Signal::G2_STW:
      G2_STW = EncoderControlWord{as_uint16(v)};
      break;
    case Signal::XERR:
      XERR = as_int32(v);
      break;
    case Signal::KPC:
      KPC = as_int32(v);
      break;
    case Signal::MOMRED:
      MOMRED = as_uint16(v);
      break;
    case Signal::STW2_ENC:
      STW2_ENC = Stw2Enc{as_uint16(v)};
      break;
    case Signal::M_ADD1:
      M_ADD1 = as_int16(v);
      break;
    case Signal::M_LIMIT_POS:
      M_LIMIT_POS = as_int16(v);
      break;
    case Signal::M_LIMIT_NEG:
      M_LIMIT_NEG = as_int16(v);
      break;
    default:
      break;
  }
}

std::uint32_t ActualSignals::raw(Signal signal) const noexcept {
  switch (signal) {
    case Signal::ZSW1:
      return ZSW1.value();
    case Signal::NIST_A:
      return bits_of(NIST_A);
    case Signal::NIST_B:
      return bits_of(NIST_B);
    case Signal::ZSW2:
      return ZSW2.value();
    case Signal::G1_ZSW:
      return G1_ZSW.value();
    case Signal::G1_XIST1:
      return G1_XIST1;
    case Signal::G1_XIST2:
      return G1_XIST2;
    case Signal::G2_ZSW:
      return G2_ZSW.value();
    case Signal::G2_XIST1:
      return G2_XIST1;
    case Signal::G2_XIST2:
      return G2_XIST2;
    case Signal::MELDW:
      return MELDW.value();
    case Signal::ZSW2_ENC:
      return ZSW2_ENC.value();
    case Signal::M_ACT:
      return bits_of(M_ACT);
    default:
      return 0;
  }
}

void ActualSignals::set_raw(Signal signal, std::uint32_t v) noexcept {
  switch (signal) {
    case Signal::ZSW1:
      ZSW1 = Zsw1{as_uint16(v)};
      break;
    case Signal::NIST_A:
      NIST_A = as_int16(v);
      break;
    case Signal::NIST_B:
      NIST_B = as_int32(v);
      break;
    case Signal::ZSW2:
      ZSW2 = Zsw2{as_uint16(v)};
      break;
    case Signal::G1_ZSW:
      G1_ZSW = EncoderStatusWord{as_uint16(v)};
      break;
    case Signal::G1_XIST1:
      G1_XIST1 = v;
      break;
    case Signal::G1_XIST2:
      G1_XIST2 = v;
      break;
    case Signal::G2_ZSW:
      G2_ZSW = EncoderStatusWord{as_uint16(v)};
      break;
    case Signal::G2_XIST1:
      G2_XIST1 = v;
      break;
    case Signal::G2_XIST2:
      G2_XIST2 = v;
      break;
    case Signal::MELDW:
      MELDW = Meldw{as_uint16(v)};
      break;
    case Signal::ZSW2_ENC:
      ZSW2_ENC = Zsw2Enc{as_uint16(v)};
      break;
    case Signal::M_ACT:
      M_ACT = as_int16(v);
      break;
    default:
      break;
  }
}

// ---- named bits of the words (spec 06 §3) ----
namespace {

constexpr BitField bit(std::uint8_t n) {
  return BitField{n, 1};
}

constexpr NamedField kStw1Fields[] = {
    {"On", bit(0)},
    {"NoCoastStop", bit(1)},
    {"NoQuickStop", bit(2)},
    {"EnableOperation", bit(3)},
    {"EnableRampFunctionGenerator", bit(4)},
    {"UnfreezeRampFunctionGenerator", bit(5)},
    {"EnableSetpoint", bit(6)},
    {"AcknowledgeFault", bit(7)},
    {"Jog1", bit(8)},
    {"Jog2", bit(9)},
    {"ControlByPlc", bit(10)},
    {"DriveSpecific11", bit(11)},
    {"DriveSpecific12", bit(12)},
    {"DriveSpecific13", bit(13)},
    {"DriveSpecific14", bit(14)},
    {"DriveSpecific15", bit(15)},
};

constexpr NamedField kZsw1Fields[] = {
    {"ReadyToSwitchOn", bit(0)},
    {"Ready", bit(1)},
    {"OperationEnabled", bit(2)},
    {"FaultPresent", bit(3)},
    {"NoCoastStopActive", bit(4)},
    {"NoQuickStopActive", bit(5)},
    {"SwitchingOnInhibited", bit(6)},
    {"WarningPresent", bit(7)},
    {"SpeedDeviationWithinTolerance", bit(8)},
    {"ControlRequested", bit(9)},
    {"ComparisonValueReached", bit(10)},
    {"DriveSpecific11", bit(11)},
    {"DriveSpecific12", bit(12)},
    {"DriveSpecific13", bit(13)},
    {"DriveSpecific14", bit(14)},
    {"DriveSpecific15", bit(15)},
};

constexpr NamedField kStw2Fields[] = {
    {"DriveDataSetSelection", kDriveDataSetSelectionField},
    {"ParkingAxisSelection", bit(7)},
    {"TravelToFixedStop", bit(8)},
    {"MotorSwitchoverFinished", bit(11)},
    {"SignOfLife", kSignOfLifeField},
};

constexpr NamedField kZsw2Fields[] = {
    {"DriveDataSetEffective", kDriveDataSetEffectiveField},
    {"AlarmClass", kAlarmClassField},
    {"ParkingAxisActive", bit(7)},
    {"TravelToFixedStopActive", bit(8)},
    {"PulsesEnabled", bit(10)},
    {"MotorDataSetChangeoverActive", bit(11)},
    {"SignOfLife", kSignOfLifeField},
};

constexpr NamedField kMeldwFields[] = {
    {"RampFunctionCompleted", bit(0)},
    {"TorqueUtilisationBelowThreshold", bit(1)},
    {"SpeedBelowStandstillThreshold", bit(2)},
    {"SpeedAtOrBelowThreshold2", bit(3)},
    {"NoMotorOverTemperatureAlarm", bit(6)},
    {"NoPowerUnitOverloadAlarm", bit(7)},
    {"SpeedDeviationWithinTolerance", bit(8)},
    {"ControllerEnable", bit(11)},
    {"DriveReady", bit(12)},
    {"PulsesEnabled", bit(13)},
};

constexpr NamedField kEncoderControlFields[] = {
    {"Function1", bit(0)},
    {"Function2", bit(1)},
    {"Function3", bit(2)},
    {"Function4", bit(3)},
    {"Command", kEncoderCommandField},
    {"MeasurementMode", bit(7)},
    {"HomePositionShift", bit(11)},
    {"RequestSetHomePosition", bit(12)},
    {"RequestAbsoluteValue", bit(13)},
    {"RequestParkEncoder", bit(14)},
    {"AcknowledgeEncoderError", bit(15)},
};

constexpr NamedField kEncoderStatusFields[] = {
    {"Function1Active", bit(0)},
    {"Function2Active", bit(1)},
    {"Function3Active", bit(2)},
    {"Function4Active", bit(3)},
    {"Value1Available", bit(4)},
    {"Value2Available", bit(5)},
    {"Value3Available", bit(6)},
    {"Value4Available", bit(7)},
    {"Probe1Deflected", bit(8)},
    {"Probe2Deflected", bit(9)},
    {"EncoderFaultAcknowledgeActive", bit(11)},
    {"HomePositionSetExecuted", bit(12)},
    {"AbsoluteValueTransmitted", bit(13)},
    {"ParkingEncoderActive", bit(14)},
    {"EncoderError", bit(15)},
};

constexpr NamedField kStw2EncFields[] = {
    {"AcknowledgeFault", bit(7)},
    {"ControlByPlc", bit(10)},
    {"SignOfLife", kSignOfLifeField},
};

constexpr NamedField kZsw2EncFields[] = {
    {"FaultPresent", bit(3)},
    {"WarningPresent", bit(7)},
    {"ControlRequested", bit(9)},
    {"SignOfLife", kSignOfLifeField},
};

}  // namespace

std::span<const NamedField> word_fields(Signal signal) noexcept {
  switch (signal) {
    case Signal::STW1:
      return kStw1Fields;
    case Signal::ZSW1:
      return kZsw1Fields;
    case Signal::STW2:
      return kStw2Fields;
    case Signal::ZSW2:
      return kZsw2Fields;
    case Signal::MELDW:
      return kMeldwFields;
    case Signal::G1_STW:
    case Signal::G2_STW:
      return kEncoderControlFields;
    case Signal::G1_ZSW:
    case Signal::G2_ZSW:
      return kEncoderStatusFields;
    case Signal::STW2_ENC:
      return kStw2EncFields;
    case Signal::ZSW2_ENC:
      return kZsw2EncFields;
    default:
      return {};
  }
}

}  // namespace tomc::telegrams
