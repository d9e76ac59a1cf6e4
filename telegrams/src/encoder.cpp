// Encoder values, spec 06 §6.
#include "tomc/telegrams/encoder.hpp"

namespace tomc::telegrams {

std::int64_t xist1_delta(std::uint32_t previous, std::uint32_t current, std::uint8_t width_bits) noexcept {
  if (width_bits == 0 || width_bits > 32) width_bits = 32;
  const std::uint64_t modulus = std::uint64_t{1} << width_bits;
  const std::uint64_t mask = modulus - 1;
  const std::uint64_t d = (static_cast<std::uint64_t>(current) - previous) & mask;
  // Sign-extend from width_bits: the shorter way round the counter is the real movement.
  return d >= (modulus >> 1) ? static_cast<std::int64_t>(d) - static_cast<std::int64_t>(modulus)
                             : static_cast<std::int64_t>(d);
}

std::int64_t IncrementalCount::update(std::uint32_t xist1) noexcept {
  std::int64_t delta = 0;
  if (has_previous_) delta = xist1_delta(previous_, xist1, width_bits_);
  previous_ = xist1;
  has_previous_ = true;
  counts_ += delta;
  return delta;
}

namespace encoder_request {
namespace {
constexpr std::uint16_t word(std::uint8_t functions, EncoderCommand command, bool measurement) {
  return static_cast<std::uint16_t>((functions & 0x0Fu) | (static_cast<unsigned>(command) << 4) |
                                    (measurement ? 0x0080u : 0u));
}
}  // namespace
std::uint16_t reference_mark_search(std::uint8_t f) noexcept {
  return word(f, EncoderCommand::kActivate, false);
}
std::uint16_t read_reference_mark(std::uint8_t f) noexcept {
  return word(f, EncoderCommand::kReadValue, false);
}
std::uint16_t flying_measurement(std::uint8_t f) noexcept {
  return word(f, EncoderCommand::kActivate, true);
}
std::uint16_t read_measured_value(std::uint8_t f) noexcept {
  return word(f, EncoderCommand::kReadValue, true);
}
std::uint16_t cancel(std::uint8_t f, bool measurement) noexcept {
  return word(f, EncoderCommand::kCancel, measurement);
}
std::uint16_t absolute_value() noexcept {
  return 0x2000;
}
std::uint16_t park() noexcept {
  return 0x4000;
}
std::uint16_t acknowledge_error() noexcept {
  return 0x8000;
}
}  // namespace encoder_request

std::string_view to_string(Xist2Content content) noexcept {
  switch (content) {
    case Xist2Content::kNotValid:
      return "not valid";
    case Xist2Content::kErrorCode:
      return "error code";
    case Xist2Content::kReferenceMark:
      return "reference mark";
    case Xist2Content::kMeasuredValue:
      return "measured value";
    case Xist2Content::kAbsoluteValue:
      return "absolute value";
  }
  return "?";
}

Xist2Content xist2_content(EncoderControlWord request, EncoderStatusWord status) noexcept {
  if (status.test(EncoderStatusBit::kEncoderError)) return Xist2Content::kErrorCode;
  const bool value_available = status.field(kEncoderValuesAvailableField) != 0;
  const bool read_requested =
      request.field(kEncoderCommandField) == static_cast<std::uint16_t>(EncoderCommand::kReadValue);
  if (value_available && read_requested) {
    return request.test(EncoderControlBit::kMeasurementMode) ? Xist2Content::kMeasuredValue
                                                             : Xist2Content::kReferenceMark;
  }
  if (status.test(EncoderStatusBit::kAbsoluteValueTransmitted)) return Xist2Content::kAbsoluteValue;
  return Xist2Content::kNotValid;
}

std::string_view describe_encoder_error(std::uint16_t code) noexcept {
  switch (code) {
    case kEncoderErrorSensorGroup:
      return "sensor group error (position cannot be read)";
    case kEncoderErrorZeroMarkMonitoring:
      return "zero-mark monitoring";
    case kEncoderErrorAbortParking:
      return "abort parking sensor";
    case kEncoderErrorAbortReferenceSearch:
      return "abort reference value search";
    case kEncoderErrorAbortReferenceRetrieval:
      return "abort reference value retrieval";
    case kEncoderErrorAbortFlyingMeasurement:
      return "abort measurement on the fly";
    case kEncoderErrorAbortMeasuredValueRetrieval:
      return "abort measured value retrieval";
    case kEncoderErrorAbortAbsoluteValue:
    case kEncoderErrorAbortAbsoluteValueAlt:
      return "abort absolute value transmission";
    case kEncoderErrorCommandNotSupported:
      return "command not supported / parameter or command error";
    case kEncoderErrorMasterSignOfLife:
      return "master sign-of-life error";
    case kEncoderErrorManufacturer:
      return "manufacturer-specific error";
    default:
      return "unknown encoder error code";
  }
}

std::uint64_t absolute_range_counts(std::uint32_t steps_per_revolution, std::uint8_t fine_resolution_xist2,
                                    std::uint32_t determinable_revolutions) noexcept {
  if (fine_resolution_xist2 > 31) return 0;
  const std::uint64_t per_revolution = std::uint64_t{steps_per_revolution} << fine_resolution_xist2;
  if (determinable_revolutions != 0 && per_revolution > UINT64_MAX / determinable_revolutions)
    return UINT64_MAX;
  return per_revolution * determinable_revolutions;
}

}  // namespace tomc::telegrams
