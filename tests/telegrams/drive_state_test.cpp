// PROFIdrive general state machine, spec 06 §4: transitions (§4.1), ZSW1 per state (§4.2), the decoding rule
// (§4.2), canonical STW1 words (§4.3) and the controller-side Stw1Sequencer against a simulated drive.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "tomc/telegrams/drive_state.hpp"

namespace tomc::telegrams {
namespace {

using enum DriveState;

constexpr std::uint16_t kOn = 0x0001;
constexpr std::uint16_t kNoOff2 = 0x0002;
constexpr std::uint16_t kNoOff3 = 0x0004;
constexpr std::uint16_t kEnableOp = 0x0008;
constexpr std::uint16_t kPlc = 0x0400;
constexpr std::uint16_t kRfg = 0x0070;  // bits 4-6, irrelevant to the state machine

std::string hex16(std::uint16_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%04X", static_cast<unsigned>(v));
  return buf;
}

struct TransitionRow {
  DriveState from;
  std::uint16_t stw1;
  bool standstill;
  DriveState to;
  const char* rule;  // the §4.1 row
};

// spec 06 §4.1: every row of the transition table, plus "stays" cases.
TEST(DriveStateMachine, EveryTransitionRowOfSpecTable) {
  const std::uint16_t base = kPlc | kRfg;
  const TransitionRow rows[] = {
      // S0
      {kS0NotReady, base | kNoOff2 | kNoOff3, false, kS1SwitchingOnInhibited, "S0 -> S1: bit 10 = 1"},
      {kS0NotReady, kRfg | kNoOff2 | kNoOff3, false, kS0NotReady, "S0 stays while bit 10 = 0"},
      {kS0NotReady, 0x0000, false, kS0NotReady, "S0 stays with 0x0000"},
      // S1
      {kS1SwitchingOnInhibited, base | kNoOff2 | kNoOff3, false, kS2ReadyForSwitchingOn,
       "S1 -> S2: bit0 = 0, bit1 = 1, bit2 = 1"},
      {kS1SwitchingOnInhibited, base | kNoOff2 | kNoOff3 | kEnableOp, false, kS2ReadyForSwitchingOn,
       "S1 -> S2 (bit 3 irrelevant)"},
      {kS1SwitchingOnInhibited, base | kOn | kNoOff2 | kNoOff3, false, kS1SwitchingOnInhibited,
       "S1 stays while bit0 = 1"},
      {kS1SwitchingOnInhibited, base | kNoOff3, false, kS1SwitchingOnInhibited, "S1 stays while bit1 = 0"},
      {kS1SwitchingOnInhibited, base | kNoOff2, false, kS1SwitchingOnInhibited, "S1 stays while bit2 = 0"},
      // S2
      {kS2ReadyForSwitchingOn, base | kNoOff3, false, kS1SwitchingOnInhibited, "S2 -> S1: bit1 = 0"},
      {kS2ReadyForSwitchingOn, base | kNoOff2, false, kS1SwitchingOnInhibited, "S2 -> S1: bit2 = 0"},
      {kS2ReadyForSwitchingOn, base | kOn | kNoOff3, false, kS1SwitchingOnInhibited,
       "S2 -> S1: bit1 = 0 wins over bit0 = 1"},
      {kS2ReadyForSwitchingOn, base | kOn | kNoOff2 | kNoOff3, false, kS3SwitchedOn, "S2 -> S3: bit0 = 1"},
      {kS2ReadyForSwitchingOn, base | kOn | kNoOff2 | kNoOff3 | kEnableOp, false, kS3SwitchedOn,
       "S2 -> S3 (one step per evaluation)"},
      {kS2ReadyForSwitchingOn, base | kNoOff2 | kNoOff3, false, kS2ReadyForSwitchingOn, "S2 stays"},
      // S3
      {kS3SwitchedOn, base | kOn | kNoOff3 | kEnableOp, false, kS1SwitchingOnInhibited, "S3 -> S1: bit1 = 0"},
      {kS3SwitchedOn, base | kOn | kNoOff2 | kEnableOp, false, kS1SwitchingOnInhibited, "S3 -> S1: bit2 = 0"},
      {kS3SwitchedOn, base | kNoOff2 | kNoOff3, false, kS2ReadyForSwitchingOn, "S3 -> S2: bit0 = 0"},
      {kS3SwitchedOn, base | kOn | kNoOff2 | kNoOff3 | kEnableOp, false, kS4Operation, "S3 -> S4: bit3 = 1"},
      {kS3SwitchedOn, base | kOn | kNoOff2 | kNoOff3, false, kS3SwitchedOn, "S3 stays while bit3 = 0"},
      // S4
      {kS4Operation, base | kOn | kNoOff3 | kEnableOp, false, kS1SwitchingOnInhibited, "S4 -> S1: bit1 = 0"},
      {kS4Operation, base | kOn | kNoOff2 | kEnableOp, false, kS5bQuickStop, "S4 -> S5b: bit2 = 0"},
      {kS4Operation, base | kNoOff2 | kNoOff3 | kEnableOp, false, kS5aRampStop, "S4 -> S5a: bit0 = 0"},
      {kS4Operation, base | kOn | kNoOff2 | kNoOff3, false, kS3SwitchedOn, "S4 -> S3: bit3 = 0"},
      {kS4Operation, base | kOn | kNoOff2 | kNoOff3 | kEnableOp, false, kS4Operation, "S4 stays with 0x047F"},
      {kS4Operation, base | kOn | kNoOff2 | kNoOff3 | kEnableOp, true, kS4Operation,
       "S4 stays at standstill"},
      // S5a
      {kS5aRampStop, base | kNoOff3 | kEnableOp, false, kS1SwitchingOnInhibited, "S5a -> S1: bit1 = 0"},
      {kS5aRampStop, base | kNoOff2 | kEnableOp, false, kS5bQuickStop, "S5a -> S5b: bit2 = 0"},
      {kS5aRampStop, base | kNoOff2 | kNoOff3, false, kS2ReadyForSwitchingOn, "S5a -> S2: bit3 = 0"},
      {kS5aRampStop, base | kNoOff2 | kNoOff3 | kEnableOp, true, kS2ReadyForSwitchingOn,
       "S5a -> S2: standstill reached"},
      {kS5aRampStop, base | kOn | kNoOff2 | kNoOff3 | kEnableOp, false, kS4Operation,
       "S5a -> S4: bit0 = 1 again (OFF1 interruptible)"},
      {kS5aRampStop, base | kNoOff2 | kNoOff3 | kEnableOp, false, kS5aRampStop, "S5a stays while ramping"},
      // S5b
      {kS5bQuickStop, base | kNoOff3 | kEnableOp, false, kS1SwitchingOnInhibited, "S5b -> S1: bit1 = 0"},
      {kS5bQuickStop, base | kOn | kNoOff2 | kNoOff3, false, kS1SwitchingOnInhibited, "S5b -> S1: bit3 = 0"},
      {kS5bQuickStop, base | kOn | kNoOff2 | kEnableOp, true, kS1SwitchingOnInhibited,
       "S5b -> S1: standstill reached"},
      {kS5bQuickStop, base | kOn | kNoOff2 | kNoOff3 | kEnableOp, false, kS5bQuickStop,
       "S5b stays: quick stop is not interruptible"},
      {kS5bQuickStop, base | kOn | kNoOff2 | kEnableOp, false, kS5bQuickStop, "S5b stays while ramping"},
  };
  for (const auto& row : rows) {
    EXPECT_EQ(next_drive_state(row.from, row.stw1, row.standstill), row.to)
        << row.rule << " (STW1 " << hex16(row.stw1) << ", got "
        << to_string(next_drive_state(row.from, row.stw1, row.standstill)) << ")";
  }
}

// spec 06 §4.3: the canonical words drive the expected transitions.
TEST(DriveStateMachine, CanonicalWordsGiveTheExpectedResults) {
  EXPECT_EQ(next_drive_state(kS1SwitchingOnInhibited, 0x047E, false), kS2ReadyForSwitchingOn);
  EXPECT_EQ(next_drive_state(kS2ReadyForSwitchingOn, 0x047F, false), kS3SwitchedOn);
  EXPECT_EQ(next_drive_state(kS3SwitchedOn, 0x047F, false), kS4Operation);
  EXPECT_EQ(next_drive_state(kS4Operation, 0x047E, false), kS5aRampStop);
  EXPECT_EQ(next_drive_state(kS5aRampStop, 0x047E, true), kS2ReadyForSwitchingOn);
  EXPECT_EQ(next_drive_state(kS4Operation, 0x047B, false), kS5bQuickStop);
  EXPECT_EQ(next_drive_state(kS5bQuickStop, 0x047B, true), kS1SwitchingOnInhibited);
  EXPECT_EQ(next_drive_state(kS4Operation, 0x047C, false), kS1SwitchingOnInhibited);
  EXPECT_EQ(next_drive_state(kS4Operation, 0x0477, false), kS3SwitchedOn);
  // 0x047C keeps S1 (bit 1 = 0) and 0x047E then leaves it.
  EXPECT_EQ(next_drive_state(kS1SwitchingOnInhibited, 0x047C, false), kS1SwitchingOnInhibited);
  // spec 06 §4.1: S1 can only be left with bit 0 = 0 (0x047F keeps it).
  EXPECT_EQ(next_drive_state(kS1SwitchingOnInhibited, 0x047F, false), kS1SwitchingOnInhibited);
  EXPECT_EQ(next_drive_state(kS0NotReady, 0x047E, false), kS1SwitchingOnInhibited);
}

struct ZswRow {
  DriveState state;
  std::uint16_t stw1;
  bool cyclic;
  std::uint16_t zsw1;
  const char* what;
};

// spec 06 §4.2: ZSW1 reported per state (no fault, no warning, OFF2/OFF3 not commanded unless stated).
TEST(DriveStateMachine, Zsw1PerStateOfSpecTable) {
  const ZswRow rows[] = {
      {kS0NotReady, 0x0000, false, 0x0000, "S0 power-on, no cyclic data"},
      {kS0NotReady, 0x047E, false, 0x0000, "S0 power-on ignores STW1"},
      {kS0NotReady, 0x0000, true, 0x0240, "S0 idle, STW1.1/2 = 0"},
      {kS0NotReady, 0x0006, true, 0x0270, "S0 idle + bits 4/5 mirroring STW1.1/2"},
      {kS0NotReady, 0x0002, true, 0x0250, "S0 idle, only STW1.1"},
      {kS0NotReady, 0x0004, true, 0x0260, "S0 idle, only STW1.2"},
      {kS1SwitchingOnInhibited, 0x047E, true, 0x0270, "S1"},
      {kS2ReadyForSwitchingOn, 0x047E, true, 0x0231, "S2"},
      {kS3SwitchedOn, 0x047F, true, 0x0233, "S3"},
      {kS3SwitchedOn, 0x0477, true, 0x0233, "S3 after pulse inhibit"},
      {kS4Operation, 0x047F, true, 0x0237, "S4"},
      {kS5aRampStop, 0x047E, true, 0x0233, "S5a"},
      {kS5bQuickStop, 0x047B, true, 0x0213, "S5b (bit 5 = 0)"},
      {kS5bQuickStop, 0x047F, true, 0x0213, "S5b: bit 5 = 0 even though STW1.2 = 1"},
      {kS1SwitchingOnInhibited, 0x047C, true, 0x0260, "S1 after OFF2 (bit 4 = 0)"},
  };
  for (const auto& row : rows) {
    EXPECT_EQ(zsw1_for(row.state, row.stw1, row.cyclic, false, false), row.zsw1)
        << row.what << ": got " << hex16(zsw1_for(row.state, row.stw1, row.cyclic, false, false));
  }
}

// spec 06 §3.2/§4.2: fault (bit 3) and warning (bit 7) are added on top of the state's word; FAULT with the
// fault reaction masking STW1.0-2 reports 0x0248 (TV24/TV26).
TEST(DriveStateMachine, Zsw1FaultAndWarningBits) {
  EXPECT_EQ(zsw1_for(kFault, 0x0478, true, true, false), 0x0248);
  EXPECT_EQ(zsw1_for(kFault, 0x0478, true, false, false), 0x0248);  // the state alone reports the fault
  EXPECT_EQ(zsw1_for(kS1SwitchingOnInhibited, 0x0478, true, true, false), 0x0248);
  EXPECT_EQ(zsw1_for(kS4Operation, 0x047F, true, false, true), 0x02B7);
  EXPECT_EQ(zsw1_for(kS2ReadyForSwitchingOn, 0x047E, true, true, true), 0x02B9);
  EXPECT_EQ(zsw1_for(kS4Operation, 0x047F, false, true, true), 0x0000);  // nothing before cyclic data
}

// spec 06 §4.2: zsw1_for and decode_zsw1 agree for every state the decoder can tell apart.
TEST(DriveStateMachine, DecodeOfReportedZsw1) {
  struct Row {
    DriveState state;
    std::uint16_t stw1;
    DriveState decoded;
  };
  const Row rows[] = {
      {kS1SwitchingOnInhibited, 0x047E, kS1SwitchingOnInhibited},
      {kS2ReadyForSwitchingOn, 0x047E, kS2ReadyForSwitchingOn},
      {kS3SwitchedOn, 0x047F, kS3SwitchedOn},
      {kS4Operation, 0x047F, kS4Operation},
      {kS5aRampStop, 0x047E, kS3SwitchedOn},  // S5a is indistinguishable from S3 (§4.2)
      {kS5bQuickStop, 0x047B, kS5bQuickStop},
      {kFault, 0x0478, kFault},
      {kS0NotReady, 0x0000, kS1SwitchingOnInhibited},  // S0 idle shows bit 6 like S1
  };
  for (const auto& row : rows) {
    const std::uint16_t zsw1 = zsw1_for(row.state, row.stw1, true, false, false);
    const DriveStatus status = decode_zsw1(zsw1);
    EXPECT_EQ(status.state, row.decoded) << to_string(row.state) << " " << hex16(zsw1);
    EXPECT_TRUE(status.control_requested) << to_string(row.state);
  }
  EXPECT_EQ(decode_zsw1(0x0000).state, kS0NotReady);
  EXPECT_FALSE(decode_zsw1(0x0000).control_requested);
}

// spec 06 §4.2 decoding rule, each branch, incl. TV24 and the priority order (fault first, then bit 6).
TEST(DriveStateMachine, DecodeZsw1Rule) {
  struct Row {
    std::uint16_t zsw1;
    DriveState state;
    bool control_ok;
  };
  const Row rows[] = {
      // TV24
      {0x0270, kS1SwitchingOnInhibited, true},
      {0x0231, kS2ReadyForSwitchingOn, true},
      {0x0233, kS3SwitchedOn, true},
      {0x0237, kS4Operation, true},
      {0x0213, kS5bQuickStop, true},
      {0x0248, kFault, true},
      {0x0037, kS4Operation, false},
      // priority and edges of the rule
      {0x023F, kFault, true},  // bit 3 beats everything
      {0x0008, kFault, false},
      {0x0247, kS1SwitchingOnInhibited, true},  // bit 6 beats bits 0..2
      {0x0260, kS1SwitchingOnInhibited, true},
      {0x0217, kS4Operation, true},   // S4 test comes before the bit-5 check
      {0x0203, kS5bQuickStop, true},  // bits 0,1 with bit 5 = 0
      {0x0223, kS3SwitchedOn, true},
      {0x0201, kS2ReadyForSwitchingOn, true},
      {0x0205, kS2ReadyForSwitchingOn, true},  // bit 0 without bit 1
      {0x0202, kS0NotReady, true},             // bit 1 alone: not ready
      {0x0200, kS0NotReady, true},
      {0xF800 | 0x0237, kS4Operation, true},            // drive-specific bits 11..15 never used (§3.2)
      {0xFD00 | 0x0231, kS2ReadyForSwitchingOn, true},  // bits 8, 10..15 set
  };
  for (const auto& row : rows) {
    const DriveStatus s = decode_zsw1(row.zsw1);
    EXPECT_EQ(s.state, row.state) << hex16(row.zsw1) << " got " << to_string(s.state);
    EXPECT_EQ(s.control_requested, row.control_ok) << hex16(row.zsw1);
  }
  EXPECT_TRUE(decode_zsw1(0x02B7).warning);
  EXPECT_FALSE(decode_zsw1(0x0237).warning);
  EXPECT_TRUE(decode_zsw1(0x0260).coast_stop_active);
  EXPECT_FALSE(decode_zsw1(0x0270).coast_stop_active);
  EXPECT_TRUE(decode_zsw1(0x0213).quick_stop_active);
  EXPECT_FALSE(decode_zsw1(0x0233).quick_stop_active);
}

// spec 06 §4.3 [OUR CHOICE] canonical STW1 words.
TEST(DriveStateMachine, Stw1ForEachCommand) {
  EXPECT_EQ(stw1_for(DriveCommand::kIdle), 0x047E);
  EXPECT_EQ(stw1_for(DriveCommand::kSwitchOnAndRun), 0x047F);
  EXPECT_EQ(stw1_for(DriveCommand::kNormalStop), 0x047E);
  EXPECT_EQ(stw1_for(DriveCommand::kQuickStop), 0x047B);
  EXPECT_EQ(stw1_for(DriveCommand::kCoastStop), 0x047C);
  EXPECT_EQ(stw1_for(DriveCommand::kPulseInhibit), 0x0477);
  EXPECT_EQ(stw1_for(DriveCommand::kAcknowledgeFault), 0x04FE);
  EXPECT_EQ(stw1_for(DriveCommand::kNoPlcControl), 0x0000);
}

// spec 06 §4.1 (the state names S0…S5b and the fault condition).
TEST(DriveStateMachine, StateNames) {
  EXPECT_EQ(to_string(kS0NotReady), "S0");
  EXPECT_EQ(to_string(kS1SwitchingOnInhibited), "S1");
  EXPECT_EQ(to_string(kS2ReadyForSwitchingOn), "S2");
  EXPECT_EQ(to_string(kS3SwitchedOn), "S3");
  EXPECT_EQ(to_string(kS4Operation), "S4");
  EXPECT_EQ(to_string(kS5aRampStop), "S5a");
  EXPECT_EQ(to_string(kS5bQuickStop), "S5b");
  EXPECT_EQ(to_string(kFault), "FAULT");
}

// A drive simulated with next_drive_state + zsw1_for (spec 06 §4.1/§4.2). A fault forces the fault reaction
// by masking STW1 bits 0..2 (§4.1 "Fault"); an acknowledge edge (STW1.7 0 -> 1) clears it and leaves the
// drive in S1 (§4.1 last paragraph). The ramps reach standstill `ramp_cycles` evaluations after they start.
class SimulatedDrive {
 public:
  explicit SimulatedDrive(int ramp_cycles = 2) : ramp_cycles_(ramp_cycles) {}

  void inject_fault() {
    fault_ = true;
    state_ = kFault;
  }
  DriveState state() const { return state_; }

  std::uint16_t cycle(std::uint16_t stw1) {
    const bool ack_edge = (stw1 & 0x0080u) != 0 && (previous_stw1_ & 0x0080u) == 0;
    previous_stw1_ = stw1;
    cyclic_ = true;
    if (fault_ && ack_edge) {
      fault_ = false;
      state_ = kS1SwitchingOnInhibited;
    } else if (!fault_) {
      const bool ramping = state_ == kS5aRampStop || state_ == kS5bQuickStop;
      ramp_elapsed_ = ramping ? ramp_elapsed_ + 1 : 0;
      state_ = next_drive_state(state_, stw1, ramping && ramp_elapsed_ >= ramp_cycles_);
    }
    return zsw1_for(state_, effective(stw1), cyclic_, fault_, false);
  }

 private:
  std::uint16_t effective(std::uint16_t stw1) const {
    return fault_ ? static_cast<std::uint16_t>(stw1 & ~0x0007u) : stw1;
  }
  int ramp_cycles_;
  int ramp_elapsed_ = 0;
  DriveState state_ = kS0NotReady;
  bool fault_ = false;
  bool cyclic_ = false;
  std::uint16_t previous_stw1_ = 0;
};

struct Step {
  std::uint16_t stw1;
  std::uint16_t zsw1;
};

// Runs the sequencer against the drive for steps.size() cycles and compares STW1/ZSW1 per cycle.
void expect_sequence(Stw1Sequencer& sequencer, SimulatedDrive& drive, std::uint16_t& zsw1,
                     DriveRequest request, const std::vector<Step>& steps, const char* what) {
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::uint16_t stw1 = sequencer.next(zsw1, request);
    EXPECT_EQ(hex16(stw1), hex16(steps[i].stw1)) << what << " cycle " << i;
    zsw1 = drive.cycle(stw1);
    EXPECT_EQ(hex16(zsw1), hex16(steps[i].zsw1)) << what << " cycle " << i;
  }
}

// spec 06 §11 TV26 + §4.3: fault -> acknowledge -> S1 -> S2 -> S3 -> S4, cycle by cycle.
TEST(Stw1Sequencer, Tv26FaultAcknowledgeToOperation) {
  SimulatedDrive drive;
  std::uint16_t zsw1 = drive.cycle(0x047E);  // S0 -> S1
  drive.inject_fault();
  zsw1 = drive.cycle(0x047E);
  ASSERT_EQ(zsw1, 0x0248);  // TV26 start

  Stw1Sequencer sequencer;
  // Without an acknowledge the sequencer keeps the drive off while it reports a fault.
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate, {{0x047E, 0x0248}, {0x047E, 0x0248}},
                  "fault, no acknowledge");
  sequencer.request_acknowledge();
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x04FE, 0x0270},   // acknowledge edge; drive clears bit 3 -> S1
                   {0x047E, 0x0231},   // ON = 0 first: S1 -> S2
                   {0x047F, 0x0233},   // S2 -> S3
                   {0x047F, 0x0237},   // S3 -> S4
                   {0x047F, 0x0237}},  // stays
                  "TV26");
  EXPECT_EQ(drive.state(), kS4Operation);
}

// spec 06 §11 TV26 with a drive that needs the acknowledge held: 0x04FE (>= 1 cycle) then 0x047E while the
// fault is still shown; a second acknowledge is again an edge.
TEST(Stw1Sequencer, AcknowledgeIsOneCycleEdgeAndCanBeRepeated) {
  Stw1Sequencer sequencer;
  sequencer.request_acknowledge();
  EXPECT_EQ(sequencer.next(0x0248, DriveRequest::kOperate), 0x04FE);
  EXPECT_EQ(sequencer.next(0x0248, DriveRequest::kOperate), 0x047E);
  EXPECT_EQ(sequencer.next(0x0248, DriveRequest::kOperate), 0x047E);
  sequencer.request_acknowledge();
  EXPECT_EQ(sequencer.next(0x0248, DriveRequest::kOperate), 0x04FE);
  // Two requests back to back: the second acknowledge waits one cycle so bit 7 has a 0 -> 1 edge again.
  sequencer.request_acknowledge();
  const std::uint16_t between = sequencer.next(0x0248, DriveRequest::kOperate);
  EXPECT_EQ(between & 0x0080u, 0u);
  EXPECT_EQ(sequencer.next(0x0248, DriveRequest::kOperate), 0x04FE);
}

// An acknowledge requested while the drive reports no fault (ZSW1.3 = 0) is dropped: its word has ON = 0
// (0x04FE), which would be an OFF1 for a drive in operation (spec 06 §3.1 bit 0, §4.1 S4 -> S5a). An MC_Reset
// for another alarm must not switch a healthy drive off (issue 22); a later fault is acknowledged as usual.
TEST(Stw1Sequencer, AcknowledgeWithoutAFaultIsNotSent) {
  Stw1Sequencer sequencer;
  sequencer.request_acknowledge();
  EXPECT_EQ(sequencer.next(0x0337, DriveRequest::kOperate), 0x047F);  // S4: stays in operation
  EXPECT_EQ(sequencer.next(0x0337, DriveRequest::kOperate), 0x047F);
  sequencer.request_acknowledge();
  EXPECT_EQ(sequencer.next(0x0231, DriveRequest::kOperate), 0x047F);  // S2: switched on as requested
  sequencer.request_acknowledge();
  EXPECT_EQ(sequencer.next(0x0248, DriveRequest::kOperate), 0x04FE);  // fault: acknowledged
}

// spec 06 §4.3: switch on from power-up: S0 -> S1 -> S2 -> S3 -> S4.
TEST(Stw1Sequencer, SwitchOnFromPowerUp) {
  SimulatedDrive drive;
  Stw1Sequencer sequencer;
  std::uint16_t zsw1 = 0x0000;  // nothing received yet
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x047E, 0x0270}, {0x047E, 0x0231}, {0x047F, 0x0233}, {0x047F, 0x0237}}, "switch on");
}

// spec 06 §4.3: quick stop (OFF3) S4 -> S5b -> S1, then 0x047E -> S2; and back to operation.
TEST(Stw1Sequencer, QuickStopSequence) {
  SimulatedDrive drive(2);
  Stw1Sequencer sequencer;
  std::uint16_t zsw1 = 0x0000;
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x047E, 0x0270}, {0x047E, 0x0231}, {0x047F, 0x0233}, {0x047F, 0x0237}}, "switch on");
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kQuickStop,
                  {{0x047B, 0x0213},   // S4 -> S5b, ZSW1.5 = 0
                   {0x047B, 0x0213},   // ramping (1)
                   {0x047B, 0x0250},   // standstill -> S1 (bit 4 mirrors STW1.1, bit 5 = STW1.2 = 0)
                   {0x047E, 0x0231},   // then 0x047E: S1 -> S2
                   {0x047E, 0x0231}},  // stays ready
                  "quick stop");
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate, {{0x047F, 0x0233}, {0x047F, 0x0237}},
                  "restart");
}

// spec 06 §4.1: OFF3 cannot be interrupted; an operate request during S5b does not switch back on.
TEST(Stw1Sequencer, QuickStopIsNotInterruptedByOperate) {
  SimulatedDrive drive(3);
  Stw1Sequencer sequencer;
  std::uint16_t zsw1 = 0x0000;
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x047E, 0x0270}, {0x047E, 0x0231}, {0x047F, 0x0233}, {0x047F, 0x0237}}, "switch on");
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kQuickStop, {{0x047B, 0x0213}}, "quick stop");
  // Operate again while S5b is shown: the sequencer drops ON (0x047E) and the drive keeps ramping.
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x047E, 0x0213}},  // still S5b: ZSW1.5 stays 0 although STW1.2 = 1 (§4.2)
                  "operate during S5b");
  EXPECT_EQ(drive.state(), kS5bQuickStop);
}

// spec 06 §4.3: coast stop (OFF2) -> S1 immediately (0x0260), then 0x047E -> S2.
TEST(Stw1Sequencer, CoastStopSequence) {
  SimulatedDrive drive;
  Stw1Sequencer sequencer;
  std::uint16_t zsw1 = 0x0000;
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x047E, 0x0270}, {0x047E, 0x0231}, {0x047F, 0x0233}, {0x047F, 0x0237}}, "switch on");
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kCoastStop,
                  {{0x047C, 0x0260},  // S4 -> S1 at once, ZSW1.4 = 0 (§4.2 "S1 after OFF2")
                   {0x047E, 0x0231},  // then 0x047E
                   {0x047E, 0x0231}},
                  "coast stop");
}

// spec 06 §4.3: normal stop (OFF1) S4 -> S5a -> S2.
TEST(Stw1Sequencer, NormalStopSequence) {
  SimulatedDrive drive(2);
  Stw1Sequencer sequencer;
  std::uint16_t zsw1 = 0x0000;
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x047E, 0x0270}, {0x047E, 0x0231}, {0x047F, 0x0233}, {0x047F, 0x0237}}, "switch on");
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOff,
                  {{0x047E, 0x0233}, {0x047E, 0x0233}, {0x047E, 0x0231}, {0x047E, 0x0231}}, "OFF1");
}

// spec 06 §4.3: pulse inhibit S4 -> S3 and back.
TEST(Stw1Sequencer, PulseInhibitSequence) {
  SimulatedDrive drive;
  Stw1Sequencer sequencer;
  std::uint16_t zsw1 = 0x0000;
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate,
                  {{0x047E, 0x0270}, {0x047E, 0x0231}, {0x047F, 0x0233}, {0x047F, 0x0237}}, "switch on");
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kPulseInhibit, {{0x0477, 0x0233}, {0x0477, 0x0233}},
                  "pulse inhibit");
  expect_sequence(sequencer, drive, zsw1, DriveRequest::kOperate, {{0x047F, 0x0237}}, "enable again");
}

// spec 06 §4.3: from a switched-off drive, stop requests only hold it ready (0x047E).
TEST(Stw1Sequencer, StopRequestsWhileOff) {
  Stw1Sequencer sequencer;
  for (const std::uint16_t zsw1 : {0x0000, 0x0270, 0x0231, 0x0248}) {
    EXPECT_EQ(sequencer.next(zsw1, DriveRequest::kQuickStop), 0x047E) << hex16(zsw1);
    EXPECT_EQ(sequencer.next(zsw1, DriveRequest::kCoastStop), 0x047E) << hex16(zsw1);
    EXPECT_EQ(sequencer.next(zsw1, DriveRequest::kOff), 0x047E) << hex16(zsw1);
  }
}

}  // namespace
}  // namespace tomc::telegrams
