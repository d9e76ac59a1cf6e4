// PROFIdrive general state machine, spec 06 §4.
#include "tomc/telegrams/drive_state.hpp"

namespace tomc::telegrams {
namespace {

constexpr bool bit(std::uint16_t word, unsigned n) {
  return ((word >> n) & 1u) != 0;
}

}  // namespace

std::string_view to_string(DriveState state) noexcept {
  switch (state) {
    case DriveState::kS0NotReady:
      return "S0";
    case DriveState::kS1SwitchingOnInhibited:
      return "S1";
    case DriveState::kS2ReadyForSwitchingOn:
      return "S2";
    case DriveState::kS3SwitchedOn:
      return "S3";
    case DriveState::kS4Operation:
      return "S4";
    case DriveState::kS5aRampStop:
      return "S5a";
    case DriveState::kS5bQuickStop:
      return "S5b";
    case DriveState::kFault:
      return "FAULT";
  }
  return "?";
}

DriveState next_drive_state(DriveState state, std::uint16_t stw1, bool standstill) noexcept {
  const bool on = bit(stw1, 0);
  const bool no_off2 = bit(stw1, 1);
  const bool no_off3 = bit(stw1, 2);
  const bool enable_operation = bit(stw1, 3);
  const bool plc_control = bit(stw1, 10);
  switch (state) {
    case DriveState::kS0NotReady:
      return plc_control ? DriveState::kS1SwitchingOnInhibited : state;
    case DriveState::kS1SwitchingOnInhibited:
      return (!on && no_off2 && no_off3) ? DriveState::kS2ReadyForSwitchingOn : state;
    case DriveState::kS2ReadyForSwitchingOn:
      if (!no_off2 || !no_off3) return DriveState::kS1SwitchingOnInhibited;
      return on ? DriveState::kS3SwitchedOn : state;
    case DriveState::kS3SwitchedOn:
      if (!no_off2 || !no_off3) return DriveState::kS1SwitchingOnInhibited;
      if (!on) return DriveState::kS2ReadyForSwitchingOn;
      return enable_operation ? DriveState::kS4Operation : state;
    case DriveState::kS4Operation:
      if (!no_off2) return DriveState::kS1SwitchingOnInhibited;
      if (!no_off3) return DriveState::kS5bQuickStop;
      if (!on) return DriveState::kS5aRampStop;
      if (!enable_operation) return DriveState::kS3SwitchedOn;
      return state;
    case DriveState::kS5aRampStop:
      if (!no_off2) return DriveState::kS1SwitchingOnInhibited;
      if (!no_off3) return DriveState::kS5bQuickStop;
      if (!enable_operation || standstill) return DriveState::kS2ReadyForSwitchingOn;
      return on ? DriveState::kS4Operation : state;
    case DriveState::kS5bQuickStop:
      if (!no_off2 || !enable_operation || standstill) return DriveState::kS1SwitchingOnInhibited;
      return state;
    case DriveState::kFault:
      return state;  // left only by an acknowledge, which the drive model handles
  }
  return state;
}

std::uint16_t zsw1_for(DriveState state, std::uint16_t stw1, bool cyclic_data, bool fault,
                       bool warning) noexcept {
  if (!cyclic_data) return 0x0000;
  std::uint16_t zsw1 = 0x0200;       // control requested, kept once cyclic data arrived
  if (bit(stw1, 1)) zsw1 |= 0x0010;  // ZSW1.4 mirrors STW1.1
  if (bit(stw1, 2) && state != DriveState::kS5bQuickStop) zsw1 |= 0x0020;  // ZSW1.5
  switch (state) {
    case DriveState::kS0NotReady:
    case DriveState::kS1SwitchingOnInhibited:
    case DriveState::kFault:
      zsw1 |= 0x0040;
      break;
    case DriveState::kS2ReadyForSwitchingOn:
      zsw1 |= 0x0001;
      break;
    case DriveState::kS3SwitchedOn:
    case DriveState::kS5aRampStop:
    case DriveState::kS5bQuickStop:
      zsw1 |= 0x0003;
      break;
    case DriveState::kS4Operation:
      zsw1 |= 0x0007;
      break;
  }
  if (fault || state == DriveState::kFault) zsw1 |= 0x0008;
  if (warning) zsw1 |= 0x0080;
  return zsw1;
}

std::uint16_t Stw1Sequencer::next(std::uint16_t zsw1, DriveRequest request) noexcept {
  // A fault acknowledge is one cycle of bit 7 with ON = 0 (TV26); it needs a 0 before it to be an edge. Only
  // a drive that reports a fault (ZSW1.3) gets it: ON = 0 would switch a healthy drive off (OFF1) under an
  // axis that stays enabled, e.g. on an MC_Reset for another TO's alarm (issue 22).
  if (acknowledge_pending_ && decode_zsw1(zsw1).state != DriveState::kFault) acknowledge_pending_ = false;
  if (acknowledge_pending_ && !acknowledge_sent_last_) {
    acknowledge_pending_ = false;
    acknowledge_sent_last_ = true;
    return stw1_for(DriveCommand::kAcknowledgeFault);
  }
  acknowledge_sent_last_ = false;

  const DriveState state = decode_zsw1(zsw1).state;
  // Where the drive is switched off, every request first needs ON = 0 with OFF2/OFF3 released (S1 -> S2).
  const bool off_state = state == DriveState::kS0NotReady || state == DriveState::kS1SwitchingOnInhibited ||
                         state == DriveState::kFault;
  switch (request) {
    case DriveRequest::kOff:
      return stw1_for(DriveCommand::kIdle);
    case DriveRequest::kOperate:
      return (off_state || state == DriveState::kS5bQuickStop) ? stw1_for(DriveCommand::kIdle)
                                                               : stw1_for(DriveCommand::kSwitchOnAndRun);
    case DriveRequest::kQuickStop:
      return (off_state || state == DriveState::kS2ReadyForSwitchingOn) ? stw1_for(DriveCommand::kIdle)
                                                                        : stw1_for(DriveCommand::kQuickStop);
    case DriveRequest::kCoastStop:
      return (off_state || state == DriveState::kS2ReadyForSwitchingOn) ? stw1_for(DriveCommand::kIdle)
                                                                        : stw1_for(DriveCommand::kCoastStop);
    case DriveRequest::kPulseInhibit:
      return off_state ? stw1_for(DriveCommand::kIdle) : stw1_for(DriveCommand::kPulseInhibit);
  }
  return stw1_for(DriveCommand::kIdle);
}

}  // namespace tomc::telegrams
