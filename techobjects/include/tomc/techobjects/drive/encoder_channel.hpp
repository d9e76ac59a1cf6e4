#pragma once
// One encoder of an axis or external encoder as the telegrams carry it (spec 01 §3.3–§3.9, spec 06 §6): which
// Gx_ZSW/Gx_XIST1/Gx_XIST2 of which telegram, the actual-value chain that turns them into user units, the
// encoder's error bit, and the Gx_STW requests (absolute value cyclically, error acknowledge). Shared by
// TO_PositioningAxis and TO_ExternalEncoder. noexcept, no allocation after construction.

#include <cstdint>
#include <optional>
#include <span>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/position/actual_value_chain.hpp"

namespace tomc::techobjects {

// The source of encoder `number` (Sensor[n].Interface.Number, 1 or 2) on a device: G1/G2 of the drive
// telegram if it carries them, else the first separate encoder telegram 81/83, else the second; a source in
// `taken` (another encoder of the same axis already reads it) is skipped (decision B3). nullopt: the device
// carries no such encoder. Set-up only (creates codecs).
std::optional<EncoderSource> find_encoder_source(const drives::DeviceConfig& device, std::uint32_t number,
                                                 std::span<const EncoderSource> taken = {});

class EncoderChannel {
 public:
  static constexpr std::uint32_t kAcknowledgeCycles = 10;  // Gx_STW.15 held after MC_Reset (spec 06 §6.3)

  EncoderChannel(const AxisMechanics& axis, const EncoderMechanics& encoder, double servo_cycle_s,
                 EncoderSource source) noexcept
      : chain_(axis, encoder, servo_cycle_s),
        source_(source),
        velocity_from_nist_(encoder.VelocityMode == ActualVelocityMode::kProfidriveNist) {}

  // MC_Servo, after DriveConnection::read(): takes this cycle's encoder values into the chain when they are
  // fresh and the encoder reports no error.
  void read(const DriveConnection& drive, bool fresh) noexcept;
  // MC_Servo, for DriveConnection::write(): this cycle's Gx_STW (reference-mark search, absolute value
  // cyclically, error acknowledge).
  telegrams::EncoderControlWord control_word() noexcept;
  void acknowledge() noexcept { acknowledge_cycles_ = kAcknowledgeCycles; }
  // Direct homing (MC_Home 0/1/11/12, spec 02 §5.7): the actual position becomes `position`, the modulo cycle
  // counter follows the shortest way (spec 01 §2.4.1). Returns how far the continuous position moved.
  double set_position(double position, ModuloCycleRule rule = ModuloCycleRule::kShortestDistance,
                      double home_position = std::numeric_limits<double>::quiet_NaN()) noexcept {
    const double before = chain_.continuous_position();
    chain_.set_position(position, rule, home_position);
    return chain_.continuous_position() - before;
  }

  // Reference-mark search through Gx_STW/Gx_ZSW (spec 06 §6.3, TV23; spec 02 §5.3): armed, the drive captures
  // Gx_XIST1 at the next zero mark (function 1, command 1), the channel reads the value (command 2) and turns
  // it into the continuous position at the mark, which take_reference_mark() hands out once.
  void arm_reference_mark() noexcept {
    if (mark_ == MarkState::kIdle || mark_ == MarkState::kCaptured) mark_ = MarkState::kArmed;
  }
  void cancel_reference_mark() noexcept { mark_ = MarkState::kIdle; }
  std::optional<double> take_reference_mark() noexcept {
    if (mark_ != MarkState::kCaptured) return std::nullopt;
    mark_ = MarkState::kIdle;
    return mark_position_;
  }

  bool error() const noexcept { return error_; }                     // Gx_ZSW.15
  std::uint32_t error_code() const noexcept { return error_code_; }  // Gx_XIST2 with the error bit
  bool valid() const noexcept { return chain_.position_valid() && !error_; }
  ActualValueChain& chain() noexcept { return chain_; }
  const ActualValueChain& chain() const noexcept { return chain_; }
  EncoderSource source() const noexcept { return source_; }

 private:
  enum class MarkState : std::uint8_t { kIdle, kArmed, kReading, kCaptured };

  // Wide members first, the bytes together: no padding (decision M5).
  ActualValueChain chain_;
  double mark_position_ = 0.0;
  std::uint32_t error_code_ = 0;
  std::uint32_t acknowledge_cycles_ = 0;
  telegrams::EncoderControlWord control_{};  // the Gx_STW of the last cycle
  EncoderSource source_ = EncoderSource::kDriveG1;
  MarkState mark_ = MarkState::kIdle;
  bool read_sent_ = false;
  bool velocity_from_nist_ = false;
  bool error_ = false;
};

}  // namespace tomc::techobjects
