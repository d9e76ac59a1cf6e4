// The §9.19.2 matrix (spec 07 §5.1, spec 03 §6.2) cell by cell, and its footnotes.
#include <gtest/gtest.h>

#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tomc/techobjects/synchronous/sync_priority.hpp"

namespace {

using namespace tomc::techobjects;

// Rows as printed in spec 07 §5.1, columns S1..S9 ("A6" = "A ⁶", "A" for "A ⁷", "A ⁷⁸").
const std::array<std::string, 14> kSpecRows = {
    "A A - N - - - - A",    // MC_Home Mode 3, 5
    "A A - A A A - A A",    // MC_Halt; Move* BufferMode 0; MoveVelocity; MoveJog
    "N N - N N N - N N",    // Move* BufferMode 1
    "A A - A A A - A A",    // MotionInVelocity, MotionInPosition
    "- -/N - - - - - - -",  // superimposed
    "A A A A A A - A A",    // MC_Stop
    "A A A A A A - A A",    // GearIn, GearInVelocity
    "- - A - - - - A -",    // GearInPos/CamIn pending
    "A A6 A A A A - A A",   // GearInPos/CamIn active
    "- N - - A N - - N",    // Phasing
    "- N - - N A - - N",    // Offset
    "- - - - - - A - -",    // LeadingValueAdditive
    "- N A - - - - A N",    // GearOut/CamOut pending
    "A N A A A A - A N",    // GearOut/CamOut active
};

std::vector<std::string> split(const std::string& row) {
  std::istringstream in(row);
  std::vector<std::string> cells;
  std::string cell;
  while (in >> cell)
    cells.push_back(cell);
  return cells;
}

// spec 07 §5.1 (the §9.19.2 matrix), spec 03 §6.2.
TEST(SyncPriority, MatrixMatchesTheManualCellByCell) {
  for (std::size_t r = 0; r < kSpecRows.size(); ++r) {
    const auto cells = split(kSpecRows[r]);
    ASSERT_EQ(cells.size(), kRunningSyncJobCount) << "row " << r;
    for (std::size_t c = 0; c < kRunningSyncJobCount; ++c) {
      EXPECT_EQ(to_string(sync_priority_cell(static_cast<NewSyncRow>(r), static_cast<RunningSyncJob>(c))),
                cells[c])
          << "row " << r << " x S" << c + 1;
    }
  }
}

// Footnote 6: superimposed jobs against velocity gearing, and an active GearInPos against it, depend on the
// follower's position control.
// spec 07 §5.1, footnote 6.
TEST(SyncPriority, Footnote6PositionControl) {
  SyncContext pc;
  SyncContext npc;
  npc.follower_position_controlled = false;
  EXPECT_EQ(resolve(NewSyncRow::kSuperimposed, RunningSyncJob::kGearInVelocity, pc), Outcome::kProceed);
  EXPECT_EQ(resolve(NewSyncRow::kSuperimposed, RunningSyncJob::kGearInVelocity, npc), Outcome::kRejectNew);
  EXPECT_EQ(resolve(NewSyncRow::kSyncInActive, RunningSyncJob::kGearInVelocity, pc), Outcome::kAbortRunning);
  EXPECT_EQ(resolve(NewSyncRow::kSyncInActive, RunningSyncJob::kGearInVelocity, npc), Outcome::kRejectNew);
}

// Footnote 7: MC_GearOut affects only gearing jobs; footnote 8: profile 5 only pending jobs; footnote 1:
// active homing aborts nothing on a virtual or simulated axis.
// spec 07 §5.1, footnotes 7, 8 and 1.
TEST(SyncPriority, Footnotes7And8And1) {
  SyncContext other_family;
  other_family.same_family = false;
  EXPECT_EQ(resolve(NewSyncRow::kSyncOutActive, RunningSyncJob::kGearIn, other_family), Outcome::kProceed);
  EXPECT_EQ(resolve(NewSyncRow::kSyncOutActive, RunningSyncJob::kGearIn, SyncContext{}),
            Outcome::kAbortRunning);
  SyncContext cancel;
  cancel.cancel_pending_only = true;
  EXPECT_EQ(resolve(NewSyncRow::kSyncOutActive, RunningSyncJob::kSyncInPending, cancel),
            Outcome::kAbortRunning);
  EXPECT_EQ(resolve(NewSyncRow::kSyncOutActive, RunningSyncJob::kSyncInActive, cancel), Outcome::kProceed);
  SyncContext simulated;
  simulated.virtual_or_simulated_axis = true;
  EXPECT_EQ(resolve(NewSyncRow::kActiveHoming, RunningSyncJob::kGearIn, simulated), Outcome::kProceed);
  EXPECT_EQ(resolve(NewSyncRow::kActiveHoming, RunningSyncJob::kGearIn, SyncContext{}),
            Outcome::kAbortRunning);
}

// The camming instructions stand in the §9.19.2 rows and columns of their gearing counterparts (spec 07 §5.1:
// "GearInPos/CamIn", "GearOut/CamOut"), in the other family of footnote 7; every instruction has one place.
TEST(SyncPriority, CammingTakesTheRowsAndColumnsOfItsGearingCounterpart) {
  const auto* cam_in = find_sync_instruction("MC_CamIn");
  const auto* gear_in_pos = find_sync_instruction("MC_GearInPos");
  const auto* cam_out = find_sync_instruction("MC_CamOut");
  const auto* gear_out = find_sync_instruction("MC_GearOut");
  ASSERT_TRUE(cam_in && gear_in_pos && cam_out && gear_out);
  EXPECT_EQ(find_sync_instruction("MC_Phasing"), nullptr);
  for (const auto& [cam, gear] : {std::pair{cam_in, gear_in_pos}, std::pair{cam_out, gear_out}}) {
    EXPECT_EQ(cam->family, SyncFamily::kCamming);
    EXPECT_EQ(gear->family, SyncFamily::kGearing);
    EXPECT_EQ(cam->pending_row, gear->pending_row);
    EXPECT_EQ(cam->active_row, gear->active_row);
    EXPECT_EQ(cam->pending_column, gear->pending_column);
    EXPECT_EQ(cam->active_column, gear->active_column);
  }
  EXPECT_EQ(cam_in->pending_row, NewSyncRow::kSyncInPending);
  EXPECT_EQ(cam_in->active_column, RunningSyncJob::kSyncInActive);
  EXPECT_EQ(cam_out->active_row, NewSyncRow::kSyncOutActive);
  EXPECT_EQ(sync_instruction_places().size(), 6u);
  // MC_Home 3/5 against an active MC_CamIn: "N" (16#80A1 on the axis), as against MC_GearInPos.
  EXPECT_EQ(to_string(sync_priority_cell(NewSyncRow::kActiveHoming, cam_in->active_column)), "N");
}

}  // namespace
