#include "demo_faults.hpp"

#include <algorithm>
#include <utility>

#include "tomc/telegrams/encoder.hpp"

namespace tomc::cli {

DemoFaultInjector::DemoFaultInjector(std::vector<drives::SimulatedDrive*> drives, std::uint64_t period_cycles)
    : drives_(std::move(drives)), period_(std::max(period_cycles, 2 * kHoldCycles)) {}

void DemoFaultInjector::apply(drives::SimulatedDrive& drive, Kind kind, bool active) noexcept {
  switch (kind) {
    case Kind::kDriveFault:
      if (active)
        drive.inject_fault(kDriveFault, drives::SimulatedDriveParameters::FaultReaction::kOff2);
      else
        drive.clear_injected_fault();
      break;
    case Kind::kEncoderError:
      if (active)
        drive.inject_encoder_error(1, telegrams::kEncoderErrorSensorGroup);
      else
        drive.clear_encoder_error(1);
      break;
    case Kind::kSignOfLifeFrozen:
      drive.freeze_sign_of_life(active);
      break;
  }
}

void DemoFaultInjector::operator()(std::uint64_t cycle) noexcept {
  if (drives_.empty() || cycle == 0) return;
  const std::uint64_t phase = cycle % period_;
  if (phase == kHoldCycles && active_ != nullptr) {
    apply(*active_, active_kind_, false);
    active_ = nullptr;
  } else if (phase == 0) {
    active_ = drives_[next_drive_];
    active_kind_ = static_cast<Kind>(next_kind_);
    apply(*active_, active_kind_, true);
    ++injected_;
    // Every drive gets every kind in turn: the kind advances once per round of the drives.
    if (++next_drive_ == drives_.size()) {
      next_drive_ = 0;
      next_kind_ = static_cast<std::uint8_t>((next_kind_ + 1) % 3);
    }
  }
}

}  // namespace tomc::cli
