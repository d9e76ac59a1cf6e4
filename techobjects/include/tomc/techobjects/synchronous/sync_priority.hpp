#pragma once
// The override matrix for synchronous-operation jobs, seed 004 §9.19.2 (spec 07 §5.1, spec 03 §6.2), as data:
// what a new job does to a running synchronous job. Rows are new jobs, columns the running synchronous jobs
// S1..S9. Together with the §9.19.1 table (job_priority.hpp, rows R8..R13 for synchronous jobs against motion
// jobs) it decides every job of a synchronous axis.

#include <cstdint>
#include <span>
#include <string_view>

#include "tomc/techobjects/axis/job_priority.hpp"

namespace tomc::techobjects {

// Columns: a running synchronous job (spec 07 §5.1).
enum class RunningSyncJob : std::uint8_t {
  kGearIn,                // S1 MC_GearIn
  kGearInVelocity,        // S2 MC_GearInVelocity
  kSyncInPending,         // S3 MC_GearInPos / MC_CamIn pending (Busy, not StartSync, not InSync)
  kSyncInActive,          // S4 MC_GearInPos / MC_CamIn active
  kPhasing,               // S5 MC_Phasing*
  kOffset,                // S6 MC_Offset*
  kLeadingValueAdditive,  // S7
  kSyncOutPending,        // S8 MC_GearOut / MC_CamOut pending
  kSyncOutActive,         // S9 MC_GearOut / MC_CamOut active
};
inline constexpr std::size_t kRunningSyncJobCount = 9;

// Rows: a new job (spec 07 §5.1).
enum class NewSyncRow : std::uint8_t {
  kActiveHoming,    // MC_Home Mode 3, 5
  kMotion,          // MC_Halt (0, 1); Move* BufferMode 0; MoveVelocity; MoveJog
  kAppendedMotion,  // Move* BufferMode 1
  kMotionIn,        // MotionInVelocity, MotionInPosition
  kSuperimposed,    // MoveSuperimposed, MotionInSuperimposed[Axes], HaltSuperimposed
  kStop,            // MC_Stop
  kGearIn,          // MC_GearIn, MC_GearInVelocity
  kSyncInPending,   // MC_GearInPos / MC_CamIn pending
  kSyncInActive,    // MC_GearInPos / MC_CamIn active
  kPhasing,
  kOffset,
  kLeadingValueAdditive,
  kSyncOutPending,  // MC_GearOut / MC_CamOut pending
  kSyncOutActive,   // MC_GearOut / MC_CamOut active
};
inline constexpr std::size_t kNewSyncRowCount = 14;

// The two families of footnote 7: MC_GearOut affects only gearing jobs, MC_CamOut only camming jobs.
enum class SyncFamily : std::uint8_t { kGearing, kCamming };

// Where each synchronous instruction stands in the matrix, gearing's and camming's side by side (spec 07
// §5.1): its rows as a new job and its columns as a running job, pending (waiting for its start) and active.
// MC_GearIn and MC_GearInVelocity are never pending; MC_GearInVelocity has a column of its own.
struct SyncInstructionPlace {
  std::string_view instruction;
  SyncFamily family;
  NewSyncRow pending_row;
  NewSyncRow active_row;
  RunningSyncJob pending_column;
  RunningSyncJob active_column;
};
std::span<const SyncInstructionPlace> sync_instruction_places() noexcept;
// The place of one instruction ("MC_CamIn"); nullptr for a name that is not in the table.
const SyncInstructionPlace* find_sync_instruction(std::string_view instruction) noexcept;

// A cell: "-", "A", "N", and the footnoted cells ("-/N" footnote 6: no effect if the follower is
// position-controlled, else reject; "A6": abort if position-controlled, else reject).
enum class SyncCell : std::uint8_t { kNoEffect, kAbort, kReject, kNoEffectOrReject, kAbortOrReject };

SyncCell sync_priority_cell(NewSyncRow row, RunningSyncJob column) noexcept;
std::string_view to_string(SyncCell cell) noexcept;

struct SyncContext {
  bool follower_position_controlled = true;  // footnote 6
  bool same_family = true;                   // footnote 7: GearOut affects Gear jobs only (CamOut: Cam jobs)
  bool cancel_pending_only = false;          // footnote 8: SyncProfileReference 5 aborts only pending jobs
  bool virtual_or_simulated_axis = false;    // footnote 1: active homing aborts nothing there
};

// What the cell means for this pair: proceed (no effect), abort the running job, or reject the new one.
Outcome resolve(NewSyncRow row, RunningSyncJob column, const SyncContext& context) noexcept;

}  // namespace tomc::techobjects
