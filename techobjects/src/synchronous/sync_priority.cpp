// The §9.19.2 matrix (seed 004 L10968-L11056; spec 07 §5.1), one row per new job, one column per running
// synchronous job.
#include "tomc/techobjects/synchronous/sync_priority.hpp"

#include <array>

namespace tomc::techobjects {
namespace {

constexpr SyncCell _ = SyncCell::kNoEffect;
constexpr SyncCell A = SyncCell::kAbort;
constexpr SyncCell N = SyncCell::kReject;
constexpr SyncCell X = SyncCell::kNoEffectOrReject;  // "-/N" footnote 6
constexpr SyncCell Y = SyncCell::kAbortOrReject;     // "A" footnote 6

// clang-format off
//                                     S1 GearIn S2 GearVel S3 InPend S4 InAct S5 Phase S6 Offs S7 LVA S8 OutPend S9 OutAct
constexpr std::array<std::array<SyncCell, kRunningSyncJobCount>, kNewSyncRowCount> kMatrix{{
    /* MC_Home 3, 5 (1)            */ {A,        A,         _,        N,       _,       _,      _,     _,         A},
    /* Halt, Move* BM0, Vel, Jog   */ {A,        A,         _,        A,       A,       A,      _,     A,         A},
    /* Move* BufferMode 1          */ {N,        N,         _,        N,       N,       N,      _,     N,         N},
    /* MotionInVelocity/Position   */ {A,        A,         _,        A,       A,       A,      _,     A,         A},
    /* superimposed                */ {_,        X,         _,        _,       _,       _,      _,     _,         _},
    /* MC_Stop                     */ {A,        A,         A,        A,       A,       A,      _,     A,         A},
    /* GearIn, GearInVelocity      */ {A,        A,         A,        A,       A,       A,      _,     A,         A},
    /* GearInPos/CamIn pending (2) */ {_,        _,         A,        _,       _,       _,      _,     A,         _},
    /* GearInPos/CamIn active (3)  */ {A,        Y,         A,        A,       A,       A,      _,     A,         A},
    /* Phasing                     */ {_,        N,         _,        _,       A,       N,      _,     _,         N},
    /* Offset                      */ {_,        N,         _,        _,       N,       A,      _,     _,         N},
    /* LeadingValueAdditive        */ {_,        _,         _,        _,       _,       _,      A,     _,         _},
    /* GearOut/CamOut pending (4)  */ {_,        N,         A,        _,       _,       _,      _,     A,         N},
    /* GearOut/CamOut active (5)   */ {A,        N,         A,        A,       A,       A,      _,     A,         N},
}};
// clang-format on

using R = NewSyncRow;
using C = RunningSyncJob;
constexpr std::array<SyncInstructionPlace, 6> kPlaces{{
    {"MC_GearIn", SyncFamily::kGearing, R::kGearIn, R::kGearIn, C::kGearIn, C::kGearIn},
    {"MC_GearInVelocity", SyncFamily::kGearing, R::kGearIn, R::kGearIn, C::kGearInVelocity,
     C::kGearInVelocity},
    {"MC_GearInPos", SyncFamily::kGearing, R::kSyncInPending, R::kSyncInActive, C::kSyncInPending,
     C::kSyncInActive},
    {"MC_CamIn", SyncFamily::kCamming, R::kSyncInPending, R::kSyncInActive, C::kSyncInPending,
     C::kSyncInActive},
    {"MC_GearOut", SyncFamily::kGearing, R::kSyncOutPending, R::kSyncOutActive, C::kSyncOutPending,
     C::kSyncOutActive},
    {"MC_CamOut", SyncFamily::kCamming, R::kSyncOutPending, R::kSyncOutActive, C::kSyncOutPending,
     C::kSyncOutActive},
}};

}  // namespace

std::span<const SyncInstructionPlace> sync_instruction_places() noexcept {
  return kPlaces;
}

const SyncInstructionPlace* find_sync_instruction(std::string_view instruction) noexcept {
  for (const auto& p : kPlaces) {
    if (p.instruction == instruction) return &p;
  }
  return nullptr;
}

SyncCell sync_priority_cell(NewSyncRow row, RunningSyncJob column) noexcept {
  return kMatrix[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)];
}

std::string_view to_string(SyncCell cell) noexcept {
  switch (cell) {
    case SyncCell::kNoEffect:
      return "-";
    case SyncCell::kAbort:
      return "A";
    case SyncCell::kReject:
      return "N";
    case SyncCell::kNoEffectOrReject:
      return "-/N";
    case SyncCell::kAbortOrReject:
      return "A6";
  }
  return "?";
}

Outcome resolve(NewSyncRow row, RunningSyncJob column, const SyncContext& context) noexcept {
  const bool desync_row = row == NewSyncRow::kSyncOutPending || row == NewSyncRow::kSyncOutActive;
  const bool gear_column = column == RunningSyncJob::kGearIn || column == RunningSyncJob::kSyncInPending ||
                           column == RunningSyncJob::kSyncInActive ||
                           column == RunningSyncJob::kSyncOutPending;
  SyncCell cell = sync_priority_cell(row, column);
  // Footnote 7: MC_GearOut affects only MC_Gear... jobs, MC_CamOut only MC_Cam... jobs.
  if (desync_row && gear_column && !context.same_family) cell = SyncCell::kNoEffect;
  // Footnote 8: SyncProfileReference 5 aborts a pending synchronous operation only.
  if (desync_row && context.cancel_pending_only && column != RunningSyncJob::kSyncInPending &&
      column != RunningSyncJob::kSyncOutPending && cell == SyncCell::kAbort) {
    cell = SyncCell::kNoEffect;
  }
  switch (cell) {
    case SyncCell::kNoEffect:
      return Outcome::kProceed;
    case SyncCell::kAbort:
      if (row == NewSyncRow::kActiveHoming && context.virtual_or_simulated_axis) return Outcome::kProceed;
      return Outcome::kAbortRunning;
    case SyncCell::kReject:
      return Outcome::kRejectNew;
    case SyncCell::kNoEffectOrReject:
      return context.follower_position_controlled ? Outcome::kProceed : Outcome::kRejectNew;
    case SyncCell::kAbortOrReject:
      return context.follower_position_controlled ? Outcome::kAbortRunning : Outcome::kRejectNew;
  }
  return Outcome::kRejectNew;
}

}  // namespace tomc::techobjects
