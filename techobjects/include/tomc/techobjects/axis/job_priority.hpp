#pragma once
// Which running job a new job aborts, leaves alone, or is rejected by: the override matrix of seed 004
// §9.19.1 (spec 03 §6.1), kept as data so that a reader can hold it against the manual cell by cell.
// Shared by every motion instruction of every axis TO. Rows and columns are the manual's groups.

#include <cstdint>
#include <span>
#include <string_view>

namespace tomc::techobjects {

// Column: a job that is running on the TO (spec 03 §6.1, C1..C8).
enum class RunningJob : std::uint8_t {
  kPassiveHoming,      // C1 MC_Home Mode 2, 8, 10
  kActiveHoming,       // C2 MC_Home Mode 3, 5
  kBaseMotionActive,   // C3 MC_Halt Mode 1; MoveAbsolute/MoveRelative/PositionProfile active; MoveVelocity;
                       // MoveJog
  kBaseMotionPending,  // C4 MoveAbsolute/MoveRelative/PositionProfile with BufferMode 1, pending
  kHaltAll,            // C5 MC_Halt Mode 0
  kStop,               // C6 MC_Stop
  kSuperimposed,       // C7 MoveSuperimposed, MotionInSuperimposed(Axes), HaltSuperimposed
  kMotionIn,           // C8 MotionInVelocity, MotionInPosition
};
inline constexpr std::size_t kRunningJobCount = 8;

// Row: a new job (spec 03 §6.1, R1..R13).
enum class NewJob : std::uint8_t {
  kActiveHoming,    // R1 MC_Home Mode 3, 5
  kHomingMode9,     // R2 MC_Home Mode 9 (abort passive homing)
  kHaltBaseOnly,    // R3 MC_Halt Mode 1
  kBaseMotion,      // R4 MC_Halt Mode 0; Move*/PositionProfile BufferMode 0; MoveVelocity; MoveJog; MotionIn
  kAppendedMotion,  // R5 Move*/PositionProfile BufferMode 1
  kSuperimposed,    // R6 MoveSuperimposed, MotionInSuperimposed(Axes), HaltSuperimposed
  kStop,            // R7 MC_Stop
  kGearIn,          // R8 MC_GearIn, MC_GearInVelocity
  kSyncPending,     // R9 MC_GearInPos, MC_CamIn pending
  kSyncActive,      // R10 MC_GearInPos, MC_CamIn active
  kLeadingValueAdditive,  // R11 MC_LeadingValueAdditive
  kSyncOutPending,        // R12 MC_GearOut, MC_CamOut pending
  kSyncOutActive,         // R13 MC_GearOut, MC_CamOut active
  kOtherHoming,  // MC_Home Mode 0, 1, 2, 6, 7, 8, 10, 11, 12, 13: no row (spec 03 §6.1 [AMB-15]) -> "-"
};
inline constexpr std::size_t kNewJobCount = 14;

// A cell of the matrix: what happens to the running job (and whether the new one may start).
enum class Cell : std::uint8_t {
  kNoEffect,        // "-": the running job continues, the new job proceeds
  kAbort,           // "A": the running job ends with CommandAborted, the new job proceeds
  kReject,          // "N": the running job continues, the new job is rejected (Error)
  kStopWeight,      // "B" (R7 x C6): the new MC_Stop aborts the running one if its weight is equal or higher
  kAppendOrReject,  // "-/N" (R5 x C3): append behind a positioning/Halt Mode 1 job; reject behind
                    // MoveVelocity/Jog
};

Cell priority_cell(NewJob row, RunningJob column) noexcept;
std::string_view to_string(Cell cell) noexcept;

// Facts about the running and the new job that decide the conditional cells.
struct ArbitrationContext {
  bool running_job_ends_by_itself =
      true;  // C3: positioning or MC_Halt Mode 1 (true) vs MoveVelocity/MoveJog (false)
  bool virtual_or_simulated_axis = false;  // footnote 1: active homing aborts nothing on such axes
  int new_stop_weight = 0;                 // R7: weight of the new MC_Stop (see stop_weight())
  int running_stop_weight = 0;             // C6: weight of the running MC_Stop
};

enum class Outcome : std::uint8_t {
  kProceed,       // the running job continues; the new job starts
  kAbortRunning,  // the running job is aborted (CommandAborted); the new job starts
  kRejectNew,     // the new job is rejected (Error); the running job continues
  kQueueNew,      // the new job becomes pending behind the running one (BufferMode 1)
};

// The outcome of one cell for a concrete pair of jobs.
Outcome resolve(NewJob row, RunningJob column, const ArbitrationContext& context) noexcept;

// What to do with a new job given every running job of the TO (spec 03 §6.7): any reject rejects the new job
// and changes nothing; otherwise every abort is applied and the new job starts (or is queued).
struct Decision {
  bool reject = false;
  bool queue = false;
  std::uint8_t abort_mask = 0;  // bit i set: abort running[i]
};
Decision arbitrate(NewJob row, std::span<const RunningJob> running,
                   const ArbitrationContext& context) noexcept;

// Stop weights, seed 004 §6.9.4 (spec 02 §3.8): remove enable 4 > emergency stop 3 > max dynamics 2 >
// current/specified dynamics 1. MC_Stop.Mode 0/2/3; ErrorDetail.Reaction 1..4. 0 for anything else.
int stop_weight_of_mc_stop_mode(int mode) noexcept;
int stop_weight_of_reaction(int reaction) noexcept;

}  // namespace tomc::techobjects
