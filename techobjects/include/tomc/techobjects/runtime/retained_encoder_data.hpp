#pragma once
// What a CPU keeps retentively for an absolute encoder (spec 01 §3.7, spec 02 §5.9, spec 04 §8 item 9): the
// absolute-value offset of the adjustment and, for a cyclic absolute encoder, the traversed measuring ranges.
// Held by TO_PositioningAxis and TO_ExternalEncoder; persisted by RetentiveStore (retentive_store.hpp).

#include <cstdint>

namespace tomc::techobjects {

struct RetainedEncoderData {  // members ordered to leave no padding (8 KiB per axis TO)
  double AbsEncoderOffset = 0.0;
  std::int64_t MeasuringRangeCount = 0;  // cyclic absolute encoder
  std::uint64_t sequence = 0;            // increases with every new adjustment (a save is due)
  std::uint32_t LastAbsoluteValue = 0;   // Gx_XIST2 format, within the measuring range
  bool valid = false;  // an adjustment exists (StatusSensor.Adjusted of an absolute encoder)
  // A new adjustment of the operative encoder (MC_Home 6/7, the first homing of an absolute encoder).
  void adopt(double offset, std::int64_t ranges, std::uint32_t last_absolute) noexcept {
    valid = true;
    AbsEncoderOffset = offset;
    MeasuringRangeCount = ranges;
    LastAbsoluteValue = last_absolute;
    ++sequence;
  }
  friend bool operator==(const RetainedEncoderData&, const RetainedEncoderData&) = default;
};

// Why an absolute encoder's adjustment could not be restored (additional value of alarm 432).
enum class AdjustmentLoss : std::uint32_t { kBackupMissing = 1, kBackupCorrupt = 2, kNoRecord = 3 };

}  // namespace tomc::techobjects
