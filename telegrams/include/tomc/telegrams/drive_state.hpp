#pragma once
// The PROFIdrive general state machine (spec 06 §4): the controller's view (state from ZSW1, STW1 for the
// wanted transition) and the drive's view (next state for an STW1, ZSW1 reported per state), so that the
// simulated drive and the technology objects share one reading of the table.

#include <cstdint>
#include <string_view>

namespace tomc::telegrams {

enum class DriveState : std::uint8_t {
  kS0NotReady,  // power-on / no control by PLC
  kS1SwitchingOnInhibited,
  kS2ReadyForSwitchingOn,
  kS3SwitchedOn,
  kS4Operation,
  kS5aRampStop,   // OFF1 ramp (from ZSW1 indistinguishable from S3; decode reports S3)
  kS5bQuickStop,  // OFF3 ramp
  kFault,         // ZSW1.3: fault present, until acknowledged
};
std::string_view to_string(DriveState state) noexcept;

// What ZSW1 says about the drive (spec 06 §4.2 decoding rule).
struct DriveStatus {
  DriveState state = DriveState::kS0NotReady;
  bool control_requested = false;  // ZSW1.9; FALSE makes the TO's CommunicationOK false (seed L11468)
  bool warning = false;            // ZSW1.7
  bool coast_stop_active = false;  // ZSW1.4 == 0
  bool quick_stop_active = false;  // ZSW1.5 == 0
};
// Inline: it runs several times per axis and servo cycle.
constexpr DriveStatus decode_zsw1(std::uint16_t zsw1) noexcept {
  auto bit = [zsw1](unsigned n) { return ((zsw1 >> n) & 1u) != 0; };
  DriveStatus status;
  status.control_requested = bit(9);
  status.warning = bit(7);
  status.coast_stop_active = !bit(4);
  status.quick_stop_active = !bit(5);
  if (bit(3)) {
    status.state = DriveState::kFault;
  } else if (bit(6)) {
    status.state = DriveState::kS1SwitchingOnInhibited;
  } else if ((zsw1 & 0x0007u) == 0x0007u) {
    status.state = DriveState::kS4Operation;
  } else if ((zsw1 & 0x0003u) == 0x0003u) {
    // S3, or S5 while ramping; bit 5 = 0 means the OFF3 quick stop is running (S5b).
    status.state = bit(5) ? DriveState::kS3SwitchedOn : DriveState::kS5bQuickStop;
  } else if (bit(0)) {
    status.state = DriveState::kS2ReadyForSwitchingOn;
  } else {
    status.state = DriveState::kS0NotReady;
  }
  return status;
}

// Canonical STW1 words, spec 06 §4.3 [OUR CHOICE].
enum class DriveCommand : std::uint8_t {
  kIdle,              // 0x047E: keep off, no OFF2/OFF3 -> S1 -> S2
  kSwitchOnAndRun,    // 0x047F -> S3 -> S4
  kNormalStop,        // 0x047E: OFF1 ramp -> S5a -> S2
  kQuickStop,         // 0x047B: OFF3 ramp -> S5b -> S1
  kCoastStop,         // 0x047C: OFF2 -> S1 at once
  kPulseInhibit,      // 0x0477: S4 -> S3
  kAcknowledgeFault,  // 0x04FE for one cycle (bit 7 edge), then kIdle
  kNoPlcControl,      // 0x0000: drive ignores the process data
};
// Inline: the sequencer's constant commands fold into their words.
constexpr std::uint16_t stw1_for(DriveCommand command) noexcept {
  switch (command) {
    case DriveCommand::kIdle:
      return 0x047E;
    case DriveCommand::kSwitchOnAndRun:
      return 0x047F;
    case DriveCommand::kNormalStop:
      return 0x047E;
    case DriveCommand::kQuickStop:
      return 0x047B;
    case DriveCommand::kCoastStop:
      return 0x047C;
    case DriveCommand::kPulseInhibit:
      return 0x0477;
    case DriveCommand::kAcknowledgeFault:
      return 0x04FE;
    case DriveCommand::kNoPlcControl:
      return 0x0000;
  }
  return 0x047E;
}

// Drive side, spec 06 §4.1: the state after one evaluation of STW1 (already masked by any fault reaction).
// `standstill` ends the OFF1/OFF3 ramps. STW1.10 = 0 only matters in S0 (no control by PLC).
DriveState next_drive_state(DriveState state, std::uint16_t stw1, bool standstill) noexcept;

// Drive side, spec 06 §4.2: ZSW1 as the DevKit reports it; drive-specific bits 8, 10..15 are not set.
// `cyclic_data` is false only before the first cyclic setpoint frame (ZSW1 = 0 then).
std::uint16_t zsw1_for(DriveState state, std::uint16_t stw1, bool cyclic_data, bool fault,
                       bool warning) noexcept;

// Controller side: what the controller wants the drive to do.
enum class DriveRequest : std::uint8_t {
  kOff,           // OFF1 / stay ready for switching on
  kOperate,       // reach and stay in S4
  kQuickStop,     // OFF3
  kCoastStop,     // OFF2
  kPulseInhibit,  // stay switched on without pulses (S3)
};

// Produces the STW1 word each cycle for the requested behaviour, from the drive's last ZSW1. Walks the
// sequences of spec 06 §4.3, e.g. S1 needs ON = 0 before ON = 1, and a fault acknowledge is one cycle of
// 0x04FE (TV26). Holds one flag; no allocation.
class Stw1Sequencer {
 public:
  // Sends one acknowledge edge (bit 7) at the next call.
  void request_acknowledge() noexcept { acknowledge_pending_ = true; }
  std::uint16_t next(std::uint16_t zsw1, DriveRequest request) noexcept;

 private:
  bool acknowledge_pending_ = false;
  bool acknowledge_sent_last_ = false;
};

}  // namespace tomc::telegrams
