// The override matrix of seed 004 §9.19.1 (spec 03 §6.1), cell by cell, and its conditional cells.
#include <gtest/gtest.h>

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "tomc/techobjects/axis/job_priority.hpp"

namespace {

using namespace tomc::techobjects;

// The rows as printed in spec 03 §6.1, columns C1..C8; a reader can lay this next to the manual.
const std::array<std::string, 13> kSpecRows = {
    "A A A A A N A A",    // R1 MC_Home Mode 3, 5
    "A - - - - N - -",    // R2 MC_Home Mode 9
    "- A A A - N - A",    // R3 MC_Halt Mode 1
    "- A A A A N A A",    // R4 MC_Halt Mode 0; Move* BufferMode 0; MoveVelocity; MoveJog; MotionIn
    "N N -/N N N N - N",  // R5 Move* BufferMode 1
    "- - - - - N A -",    // R6 superimposed
    "A A A A A B A A",    // R7 MC_Stop
    "- A A A A N A A",    // R8 MC_GearIn, MC_GearInVelocity
    "- - - A - N - -",    // R9 MC_GearInPos, MC_CamIn pending
    "- A A A A N A A",    // R10 MC_GearInPos, MC_CamIn active
    "- - - - - - - -",    // R11 MC_LeadingValueAdditive
    "N N N N N N - N",    // R12 MC_GearOut, MC_CamOut pending
    "N N N N N N A N",    // R13 MC_GearOut, MC_CamOut active
};

std::vector<std::string> split(const std::string& row) {
  std::istringstream in(row);
  std::vector<std::string> cells;
  std::string cell;
  while (in >> cell)
    cells.push_back(cell);
  return cells;
}

// spec 03 §6.1: every one of the 13 x 8 cells.
TEST(JobPriority, MatrixMatchesTheManualCellByCell) {
  for (std::size_t r = 0; r < kSpecRows.size(); ++r) {
    const auto cells = split(kSpecRows[r]);
    ASSERT_EQ(cells.size(), kRunningJobCount) << "row R" << r + 1;
    for (std::size_t c = 0; c < kRunningJobCount; ++c) {
      EXPECT_EQ(to_string(priority_cell(static_cast<NewJob>(r), static_cast<RunningJob>(c))), cells[c])
          << "R" << r + 1 << " x C" << c + 1;
    }
  }
}

// spec 03 §6.1 [AMB-15]: MC_Home modes without a row abort nothing.
TEST(JobPriority, HomingModesWithoutARowAreNoEffect) {
  for (std::size_t c = 0; c < kRunningJobCount; ++c) {
    EXPECT_EQ(priority_cell(NewJob::kOtherHoming, static_cast<RunningJob>(c)), Cell::kNoEffect);
  }
}

// R5 x C3 "-/N": append behind positioning / MC_Halt Mode 1, reject behind MoveVelocity / MoveJog.
// spec 03 §6.1 (§9.19.1 R5 × C3 "–/N" and R5 × C4 = N; AMB-11 in §7).
TEST(JobPriority, AppendBehindJobsThatEnd) {
  ArbitrationContext positioning;
  positioning.running_job_ends_by_itself = true;
  EXPECT_EQ(resolve(NewJob::kAppendedMotion, RunningJob::kBaseMotionActive, positioning), Outcome::kQueueNew);
  ArbitrationContext velocity;
  velocity.running_job_ends_by_itself = false;
  EXPECT_EQ(resolve(NewJob::kAppendedMotion, RunningJob::kBaseMotionActive, velocity), Outcome::kRejectNew);
  // R5 x C4: at most one pending job per axis.
  EXPECT_EQ(resolve(NewJob::kAppendedMotion, RunningJob::kBaseMotionPending, positioning),
            Outcome::kRejectNew);
}

// Legend B: a new MC_Stop aborts a running one of equal or higher weight (0 emergency > 2 max > 3 specified).
// spec 03 §6.1 (§9.19.1 legend B: equal or higher stop weight aborts, 0 > 2 > 3).
TEST(JobPriority, StopAgainstStopByWeight) {
  const struct {
    int running_mode;
    int new_mode;
    Outcome expected;
  } cases[] = {
      {3, 3, Outcome::kAbortRunning}, {3, 2, Outcome::kAbortRunning}, {3, 0, Outcome::kAbortRunning},
      {2, 3, Outcome::kRejectNew},    {2, 2, Outcome::kAbortRunning}, {2, 0, Outcome::kAbortRunning},
      {0, 3, Outcome::kRejectNew},    {0, 2, Outcome::kRejectNew},    {0, 0, Outcome::kAbortRunning},
  };
  for (const auto& c : cases) {
    ArbitrationContext ctx;
    ctx.running_stop_weight = stop_weight_of_mc_stop_mode(c.running_mode);
    ctx.new_stop_weight = stop_weight_of_mc_stop_mode(c.new_mode);
    EXPECT_EQ(resolve(NewJob::kStop, RunningJob::kStop, ctx), c.expected)
        << "running Mode " << c.running_mode << ", new Mode " << c.new_mode;
  }
}

// Footnote 1: on a virtual or simulated axis, active homing aborts no running job.
// spec 03 §6.1 (§9.19.1 footnote 1: active homing on a virtual or simulated axis).
TEST(JobPriority, ActiveHomingOnVirtualAxisAbortsNothing) {
  ArbitrationContext ctx;
  ctx.virtual_or_simulated_axis = true;
  EXPECT_EQ(resolve(NewJob::kActiveHoming, RunningJob::kBaseMotionActive, ctx), Outcome::kProceed);
  EXPECT_EQ(resolve(NewJob::kActiveHoming, RunningJob::kStop, ctx), Outcome::kRejectNew);
  ctx.virtual_or_simulated_axis = false;
  EXPECT_EQ(resolve(NewJob::kActiveHoming, RunningJob::kBaseMotionActive, ctx), Outcome::kAbortRunning);
}

// spec 03 §6.7: any reject rejects and changes nothing; otherwise every abort applies.
TEST(JobPriority, ArbitrateOverEveryRunningJob) {
  const ArbitrationContext ctx;
  // MoveVelocity (R4) against an active move (C3) and a pending append (C4): both aborted.
  const RunningJob move_and_pending[] = {RunningJob::kBaseMotionActive, RunningJob::kBaseMotionPending};
  auto d = arbitrate(NewJob::kBaseMotion, move_and_pending, ctx);
  EXPECT_FALSE(d.reject);
  EXPECT_EQ(d.abort_mask, 0b11);
  // The same against a running MC_Stop (C6 = N): rejected, nothing aborted.
  const RunningJob move_and_stop[] = {RunningJob::kBaseMotionActive, RunningJob::kStop};
  d = arbitrate(NewJob::kBaseMotion, move_and_stop, ctx);
  EXPECT_TRUE(d.reject);
  EXPECT_EQ(d.abort_mask, 0);
  // MC_Halt Mode 1 (R3) leaves a superimposed motion (C7 "-") and aborts the base motion.
  const RunningJob base_and_superimposed[] = {RunningJob::kBaseMotionActive, RunningJob::kSuperimposed};
  d = arbitrate(NewJob::kHaltBaseOnly, base_and_superimposed, ctx);
  EXPECT_EQ(d.abort_mask, 0b01);
  // Appending behind a positioning job queues and aborts nothing.
  const RunningJob positioning[] = {RunningJob::kBaseMotionActive};
  d = arbitrate(NewJob::kAppendedMotion, positioning, ctx);
  EXPECT_TRUE(d.queue);
  EXPECT_EQ(d.abort_mask, 0);
  // Idle axis: the new job simply starts.
  d = arbitrate(NewJob::kAppendedMotion, {}, ctx);
  EXPECT_FALSE(d.reject);
  EXPECT_FALSE(d.queue);
}

// seed 004 §6.9.4 (spec 02 §3.8): ranks of MC_Stop modes and alarm reactions.
TEST(JobPriority, StopWeights) {
  EXPECT_EQ(stop_weight_of_reaction(4), 4);  // remove enable
  EXPECT_EQ(stop_weight_of_mc_stop_mode(0), 3);
  EXPECT_EQ(stop_weight_of_reaction(3), 3);  // emergency stop
  EXPECT_EQ(stop_weight_of_mc_stop_mode(2), 2);
  EXPECT_EQ(stop_weight_of_reaction(2), 2);  // max dynamics
  EXPECT_EQ(stop_weight_of_mc_stop_mode(3), 1);
  EXPECT_EQ(stop_weight_of_reaction(1), 1);      // current dynamics (the source prints 2: erratum)
  EXPECT_EQ(stop_weight_of_mc_stop_mode(1), 0);  // Mode 1 is not allowed
  EXPECT_EQ(stop_weight_of_reaction(0), 0);
  EXPECT_EQ(stop_weight_of_reaction(5), 0);  // follow setpoint: no stop
}

}  // namespace
