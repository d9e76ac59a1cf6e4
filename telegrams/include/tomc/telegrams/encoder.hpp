#pragma once
// Encoder actual values (spec 06 §6, seed 004 §6.2.4): XIST1 deltas across the counter's wrap, the meaning
// of the multiplexed XIST2, Gx_STW requests and the error codes an encoder reports in XIST2.

#include <cstdint>
#include <string_view>

#include "tomc/telegrams/control_words.hpp"

namespace tomc::telegrams {

// Signed change of Gx_XIST1 between two samples of a counter `width_bits` wide (1..32). 32 is the TO default
// (BehaviorGx_XIST1 = 1); a narrower width is evaluated modulo 2^width (BehaviorGx_XIST1 = 0, seed L2270).
// Valid while the true movement per cycle is below 2^(width-1) counts.
std::int64_t xist1_delta(std::uint32_t previous, std::uint32_t current,
                         std::uint8_t width_bits = 32) noexcept;

// Accumulates XIST1 deltas into a 64-bit count that never wraps (spec 06 §6.1 position computation).
class IncrementalCount {
 public:
  explicit IncrementalCount(std::uint8_t width_bits = 32) noexcept : width_bits_(width_bits) {}
  // The first sample only sets the reference; returns the delta applied.
  std::int64_t update(std::uint32_t xist1) noexcept;
  std::int64_t counts() const noexcept { return counts_; }
  void set_counts(std::int64_t counts) noexcept { counts_ = counts; }
  void restart() noexcept { has_previous_ = false; }

 private:
  std::int64_t counts_ = 0;
  std::uint32_t previous_ = 0;
  std::uint8_t width_bits_ = 32;
  bool has_previous_ = false;
};

// Counts per encoder revolution in Gx_XIST1 format: StepsPerRevolution * 2^FineResolutionXist1.
inline constexpr double counts_per_revolution(std::uint32_t steps_per_revolution,
                                              std::uint8_t fine_resolution_bits) noexcept {
  return static_cast<double>(steps_per_revolution) *
         static_cast<double>(std::uint64_t{1} << fine_resolution_bits);
}

// Gx_STW requests, spec 06 §6.3 (TV23). `functions` is the 4-bit mask of bits 0..3 (function 1 = 0x1).
namespace encoder_request {
std::uint16_t reference_mark_search(std::uint8_t functions = 0x1) noexcept;  // 0x0011
std::uint16_t read_reference_mark(std::uint8_t functions = 0x1) noexcept;    // 0x0021
std::uint16_t flying_measurement(std::uint8_t functions = 0x1) noexcept;     // 0x0091
std::uint16_t read_measured_value(std::uint8_t functions = 0x1) noexcept;    // 0x00A1
std::uint16_t cancel(std::uint8_t functions, bool measurement) noexcept;     // 0x0031 / 0x00B1
std::uint16_t absolute_value() noexcept;                                     // 0x2000
std::uint16_t park() noexcept;                                               // 0x4000
std::uint16_t acknowledge_error() noexcept;                                  // 0x8000
}  // namespace encoder_request

// What Gx_XIST2 holds, spec 06 §6.2, from the Gx_STW last sent and the Gx_ZSW received.
enum class Xist2Content : std::uint8_t {
  kNotValid,
  kErrorCode,      // Gx_ZSW.15: code in the low 16 bits (§6.4); the position must not be used
  kReferenceMark,  // value available after "read value" in reference-mark mode (XIST1 format)
  kMeasuredValue,  // value available after "read value" in flying-measurement mode (XIST1 format)
  kAbsoluteValue,  // Gx_ZSW.13 after Gx_STW.13 (FineResolutionXist2 format)
};
std::string_view to_string(Xist2Content content) noexcept;
Xist2Content xist2_content(EncoderControlWord request, EncoderStatusWord status) noexcept;

// Encoder error codes in Gx_XIST2, spec 06 §6.4.
inline constexpr std::uint16_t kEncoderErrorSensorGroup = 0x0001;
inline constexpr std::uint16_t kEncoderErrorZeroMarkMonitoring = 0x0002;
inline constexpr std::uint16_t kEncoderErrorAbortParking = 0x0003;
inline constexpr std::uint16_t kEncoderErrorAbortReferenceSearch = 0x0004;
inline constexpr std::uint16_t kEncoderErrorAbortReferenceRetrieval = 0x0005;
inline constexpr std::uint16_t kEncoderErrorAbortFlyingMeasurement = 0x0006;
inline constexpr std::uint16_t kEncoderErrorAbortMeasuredValueRetrieval = 0x0007;
inline constexpr std::uint16_t kEncoderErrorAbortAbsoluteValue = 0x0008;
inline constexpr std::uint16_t kEncoderErrorAbortAbsoluteValueAlt = 0x000A;
inline constexpr std::uint16_t kEncoderErrorCommandNotSupported = 0x0F01;
inline constexpr std::uint16_t kEncoderErrorMasterSignOfLife = 0x0F02;
inline constexpr std::uint16_t kEncoderErrorManufacturer = 0x1001;

inline constexpr std::uint16_t encoder_error_code(std::uint32_t xist2) noexcept {
  return static_cast<std::uint16_t>(xist2 & 0xFFFFu);
}
// English description; "unknown encoder error code" for codes outside §6.4.
std::string_view describe_encoder_error(std::uint16_t code) noexcept;

// Absolute range in Gx_XIST2 counts: StepsPerRevolution * 2^FineResolutionXist2 * DeterminableRevolutions
// (spec 06 §6.2); 0 for an incremental encoder (DeterminableRevolutions = 0).
std::uint64_t absolute_range_counts(std::uint32_t steps_per_revolution, std::uint8_t fine_resolution_xist2,
                                    std::uint32_t determinable_revolutions) noexcept;

}  // namespace tomc::telegrams
