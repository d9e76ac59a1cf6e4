#pragma once
// The encoders of a positioning axis besides the operative one (spec 01 §3.8, seed 004 §6.2.4.5, spec 04
// Sensor[2..4]): "all encoders marked as used deliver updated actual values continuously", so each reads its
// own part of the telegrams every servo cycle into its own actual-value chain, keeps its own absolute-encoder
// adjustment and homing state (StatusSensor[n]), and may fail without stopping the axis as long as it does
// not close the position loop. MC_SetSensor exchanges one of them with the operative encoder. A simulated
// axis simulates them (seed 004 §6.2.4.5 "Simulazione"), a virtual axis shows its setpoints in them (B7).
//
// Memory (decision B1): the storage exists only for the Sensor[n].Existent encoders and is reserved when the
// axis is configured; nothing here allocates afterwards, and heap_bytes() enters memory_footprint().

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "tomc/techobjects/drive/encoder_channel.hpp"
#include "tomc/techobjects/runtime/retained_encoder_data.hpp"

namespace tomc::techobjects {

struct AdditionalEncoder {
  EncoderChannel channel{AxisMechanics{}, EncoderMechanics{}, 0.001, EncoderSource::kDriveG1};
  RetainedEncoderData retained{};  // its absolute-encoder adjustment (StatusSensor[n].AbsEncoderOffset)
  std::uint8_t number = 0;         // n of Sensor[n]
  bool fault_seen = false;         // Gx_ZSW.15 in the last servo cycle
  // Simulation (decision B7): the part of a Gx_XIST1 count the simulated motion has moved beyond the counts
  // delivered, so that the simulated encoder does not drift (|value| <= 0.5; in the padding, no growth).
  float simulated_fraction = 0.0f;
};

class AdditionalEncoders {
 public:
  // Configuration only (allocates): room for `count` encoders, 0 ... 3.
  void reserve(std::size_t count) {
    encoders_ = count == 0 ? nullptr : std::make_unique<AdditionalEncoder[]>(count);
    count_ = static_cast<std::uint8_t>(count);
  }
  std::span<AdditionalEncoder> all() noexcept { return {encoders_.get(), count_}; }
  std::span<const AdditionalEncoder> all() const noexcept { return {encoders_.get(), count_}; }
  // The encoder Sensor[number] among them; nullptr if it is the operative one or does not exist.
  AdditionalEncoder* find(std::uint32_t number) noexcept {
    for (AdditionalEncoder& e : all())
      if (e.number == number) return &e;
    return nullptr;
  }
  const AdditionalEncoder* find(std::uint32_t number) const noexcept {
    for (const AdditionalEncoder& e : all())
      if (e.number == number) return &e;
    return nullptr;
  }
  std::size_t heap_bytes() const noexcept { return count_ * sizeof(AdditionalEncoder); }

 private:
  std::unique_ptr<AdditionalEncoder[]> encoders_;
  std::uint8_t count_ = 0;
};

}  // namespace tomc::techobjects
