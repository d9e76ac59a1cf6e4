#pragma once
// Faults injected into the simulated PROFIdrive drives of `tomc demo --inject-faults N` (the free-running
// soak, bench/soak.cpp, docs/reliability.md §7): every N cycles the next drive in turn gets one fault, held
// for a few cycles and then cleared, the kinds taking turns: a drive fault (F07900 with OFF2: ZSW1.3), an
// encoder error (G1_ZSW.15 with error code 1, sensor group) and a frozen sign-of-life. The demo program
// acknowledges each alarm with MC_Reset after DemoProgram::kAcknowledgeAfterS, so the alarm history fills and
// the axes run again. Called on the cycle thread between two steps: noexcept, no allocation after
// construction.

#include <cstdint>
#include <vector>

#include "tomc/drives/simulated_drive.hpp"

namespace tomc::cli {

class DemoFaultInjector {
 public:
  enum class Kind : std::uint8_t { kDriveFault, kEncoderError, kSignOfLifeFrozen };
  static constexpr std::uint32_t kDriveFault = 7900;  // SINAMICS F07900 "motor blocked"
  static constexpr std::uint64_t kHoldCycles = 20;    // then cleared: the cause is gone before MC_Reset

  // `period_cycles` >= 2 * kHoldCycles; no drives: nothing happens.
  DemoFaultInjector(std::vector<drives::SimulatedDrive*> drives, std::uint64_t period_cycles);

  // Before step `cycle` (0, 1, 2, ...: the steps done so far).
  void operator()(std::uint64_t cycle) noexcept;
  std::uint64_t injected() const noexcept { return injected_; }

 private:
  static void apply(drives::SimulatedDrive& drive, Kind kind, bool active) noexcept;

  std::vector<drives::SimulatedDrive*> drives_;
  std::uint64_t period_;
  std::uint64_t injected_ = 0;
  std::size_t next_drive_ = 0;
  std::uint8_t next_kind_ = 0;
  drives::SimulatedDrive* active_ = nullptr;
  Kind active_kind_ = Kind::kDriveFault;
};

}  // namespace tomc::cli
