// The §9.19.1 matrix (seed 004 L10890-L10930; spec 03 §6.1), one row per new job, one column per running job.
#include "tomc/techobjects/axis/job_priority.hpp"

#include <array>

namespace tomc::techobjects {
namespace {

constexpr Cell _ = Cell::kNoEffect;
constexpr Cell A = Cell::kAbort;
constexpr Cell N = Cell::kReject;
constexpr Cell B = Cell::kStopWeight;
constexpr Cell X = Cell::kAppendOrReject;

// clang-format off
//                                   C1 passive  C2 active  C3 base   C4 pending  C5 halt  C6 stop  C7 superimp.  C8 MotionIn
constexpr std::array<std::array<Cell, kRunningJobCount>, kNewJobCount> kMatrix{{
    /* R1  MC_Home 3, 5          */ {A,          A,         A,        A,          A,       N,       A,            A},
    /* R2  MC_Home 9             */ {A,          _,         _,        _,          _,       N,       _,            _},
    /* R3  MC_Halt Mode 1        */ {_,          A,         A,        A,          _,       N,       _,            A},
    /* R4  base motion           */ {_,          A,         A,        A,          A,       N,       A,            A},
    /* R5  BufferMode 1          */ {N,          N,         X,        N,          N,       N,       _,            N},
    /* R6  superimposed          */ {_,          _,         _,        _,          _,       N,       A,            _},
    /* R7  MC_Stop               */ {A,          A,         A,        A,          A,       B,       A,            A},
    /* R8  GearIn, GearInVel.    */ {_,          A,         A,        A,          A,       N,       A,            A},
    /* R9  GearInPos/CamIn pend. */ {_,          _,         _,        A,          _,       N,       _,            _},
    /* R10 GearInPos/CamIn act.  */ {_,          A,         A,        A,          A,       N,       A,            A},
    /* R11 LeadingValueAdditive  */ {_,          _,         _,        _,          _,       _,       _,            _},
    /* R12 GearOut/CamOut pend.  */ {N,          N,         N,        N,          N,       N,       _,            N},
    /* R13 GearOut/CamOut act.   */ {N,          N,         N,        N,          N,       N,       A,            N},
    /* MC_Home other modes       */ {_,          _,         _,        _,          _,       _,       _,            _},
}};
// clang-format on

}  // namespace

Cell priority_cell(NewJob row, RunningJob column) noexcept {
  return kMatrix[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)];
}

std::string_view to_string(Cell cell) noexcept {
  switch (cell) {
    case Cell::kNoEffect:
      return "-";
    case Cell::kAbort:
      return "A";
    case Cell::kReject:
      return "N";
    case Cell::kStopWeight:
      return "B";
    case Cell::kAppendOrReject:
      return "-/N";
  }
  return "?";
}

Outcome resolve(NewJob row, RunningJob column, const ArbitrationContext& context) noexcept {
  switch (priority_cell(row, column)) {
    case Cell::kNoEffect:
      // R5 against a pending-capable column with "-" (C7): the appended job starts; nothing to queue behind.
      return Outcome::kProceed;
    case Cell::kAbort:
      // Footnote 1: MC_Home Mode 3/5 on a virtual or simulated axis aborts nothing.
      if (row == NewJob::kActiveHoming && context.virtual_or_simulated_axis) return Outcome::kProceed;
      return Outcome::kAbortRunning;
    case Cell::kReject:
      return Outcome::kRejectNew;
    case Cell::kStopWeight:
      // Legend B: a new MC_Stop with equal or higher weight aborts the running MC_Stop; a lighter one is
      // rejected.
      return context.new_stop_weight >= context.running_stop_weight ? Outcome::kAbortRunning
                                                                    : Outcome::kRejectNew;
    case Cell::kAppendOrReject:
      // Spec 03 §6.1 [IMPL] for [AMB-11]: append behind jobs that end by themselves, reject behind endless
      // ones.
      return context.running_job_ends_by_itself ? Outcome::kQueueNew : Outcome::kRejectNew;
  }
  return Outcome::kRejectNew;
}

Decision arbitrate(NewJob row, std::span<const RunningJob> running,
                   const ArbitrationContext& context) noexcept {
  Decision d;
  for (std::size_t i = 0; i < running.size() && i < 8; ++i) {
    switch (resolve(row, running[i], context)) {
      case Outcome::kRejectNew:
        return Decision{true, false, 0};
      case Outcome::kAbortRunning:
        d.abort_mask = static_cast<std::uint8_t>(d.abort_mask | (1u << i));
        break;
      case Outcome::kQueueNew:
        d.queue = true;
        break;
      case Outcome::kProceed:
        break;
    }
  }
  // A queued job aborts nothing: the running job it waits for goes on.
  if (d.queue) d.abort_mask = 0;
  return d;
}

int stop_weight_of_mc_stop_mode(int mode) noexcept {
  switch (mode) {
    case 0:
      return 3;  // emergency stop
    case 2:
      return 2;  // maximum dynamics
    case 3:
      return 1;  // specified dynamics
    default:
      return 0;
  }
}

int stop_weight_of_reaction(int reaction) noexcept {
  return (reaction >= 1 && reaction <= 4) ? reaction : 0;
}

}  // namespace tomc::techobjects
