// The Execute-class handshake, cycle by cycle: spec 03 §3.2 (E1..E8) and the canonical sequences of §3.7.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "tomc/instructions/execute_handshake.hpp"

namespace {

using namespace tomc::instructions;
using tomc::techobjects::JobId;
using tomc::techobjects::JobState;
using tomc::techobjects::JobStatus;
using tomc::techobjects::Submission;

// A stand-in technology object whose jobs the test moves through their states.
struct FakeAxis {
  std::map<JobId, JobStatus> jobs;
  JobId next = 1;
  std::uint16_t reject_with = 0;
  int submissions = 0;
  Submission submit() {
    ++submissions;
    if (reject_with != 0) return Submission::reject(reject_with);
    const JobId id = next++;
    jobs[id] = JobStatus{JobState::kActive, 0, false};
    return Submission::accept(id);
  }
  JobStatus status(JobId id) const {
    const auto it = jobs.find(id);
    return it == jobs.end() ? JobStatus{} : it->second;
  }
  void set(JobId id, JobState s, std::uint16_t error = 0) { jobs[id] = JobStatus{s, error, false}; }
};

struct Instance {
  ExecuteHandshake hs;
  void call(FakeAxis& axis, bool execute) {
    hs.call(
        execute, [&] { return axis.submit(); }, [&](JobId id) { return axis.status(id); });
  }
  // "B A D CA Er" as 0/1 characters, for compact comparison with the §3.7 tables.
  std::string flags() const {
    const auto& o = hs.outputs();
    std::string s;
    for (bool b : {o.Busy, o.Active, o.Done, o.CommandAborted, o.Error})
      s += b ? '1' : '0';
    return s;
  }
};

// T-A: Execute held until after Done.
// spec 03 §3.7 T-A, rules E2, E4, E5 of §3.2.
TEST(ExecuteHandshake, TA_NormalCompletionExecuteHeld) {
  FakeAxis axis;
  Instance i;
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "00000");  // cycle 0
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "11000");  // cycle 1: edge, Busy + Active in the same call (E2)
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "11000");
  axis.set(1, JobState::kDone);
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "00100");  // n: Done, Busy FALSE (E4)
  i.call(axis, true);
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "00100");  // n+1..m: Done held while Execute = TRUE (E5)
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "00000");  // m+1: Execute falls, everything FALSE
  EXPECT_EQ(axis.submissions, 1);
}

// T-B: Execute pulse of a single cycle; the job continues (E3) and Done shows for exactly one call (E5).
// spec 03 §3.7 T-B, rules E3 and E5 of §3.2.
TEST(ExecuteHandshake, TB_SingleCyclePulse) {
  FakeAxis axis;
  Instance i;
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "11000");
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "11000");
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "11000");
  axis.set(1, JobState::kDone);
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "00100");
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "00000");
}

// E1: a level that is still TRUE does not start another job.
// spec 03 §3.2 E1 (a job starts on a rising edge only).
TEST(ExecuteHandshake, E1_LevelDoesNotRestart) {
  FakeAxis axis;
  Instance i;
  i.call(axis, true);
  axis.set(1, JobState::kDone);
  for (int k = 0; k < 5; ++k)
    i.call(axis, true);
  EXPECT_EQ(axis.submissions, 1);
  i.call(axis, false);
  i.call(axis, true);
  EXPECT_EQ(axis.submissions, 2);
}

// T-C: instance 1 aborted by another instance; CommandAborted held while Execute 1 is TRUE, one call
// otherwise.
// spec 03 §3.7 T-C, rules E5 and E8 of §3.2.
TEST(ExecuteHandshake, TC_AbortedByAnotherInstance) {
  FakeAxis axis;
  Instance i1;
  i1.call(axis, true);
  axis.set(1, JobState::kAborted);
  i1.call(axis, true);
  EXPECT_EQ(i1.flags(), "00010");
  i1.call(axis, true);
  EXPECT_EQ(i1.flags(), "00010");
  i1.call(axis, false);
  EXPECT_EQ(i1.flags(), "00000");

  Instance i2;
  i2.call(axis, true);
  i2.call(axis, false);
  axis.set(2, JobState::kAborted);
  i2.call(axis, false);
  EXPECT_EQ(i2.flags(), "00010");  // Execute already FALSE: exactly one call
  i2.call(axis, false);
  EXPECT_EQ(i2.flags(), "00000");
}

// T-D: rejection; Error + ErrorID in the edge call, held while Execute = TRUE, cleared by the first FALSE.
// spec 03 §3.7 T-D, rules E5 and E7 of §3.2.
TEST(ExecuteHandshake, TD_Rejection) {
  FakeAxis axis;
  axis.reject_with = 0x8001;
  Instance i;
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "00001");
  EXPECT_EQ(i.hs.outputs().ErrorID, 0x8001);
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "00001");
  EXPECT_EQ(i.hs.outputs().ErrorID, 0x8001);
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "00000");
  EXPECT_EQ(i.hs.outputs().ErrorID, 0);
}

// T-E: a pending (appended) job is Busy without Active until it becomes active.
// spec 03 §3.7 T-E (BufferMode 1: Busy without Active while pending).
TEST(ExecuteHandshake, TE_PendingThenActive) {
  FakeAxis axis;
  Instance i;
  i.call(axis, true);
  axis.set(1, JobState::kPending);
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "10000");
  axis.set(1, JobState::kActive);
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "11000");
  axis.set(1, JobState::kDone);
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "00100");
}

// An error while the job runs (e.g. an alarm reaction, spec 03 §6.6: ErrorID 16#8001).
TEST(ExecuteHandshake, ErrorWhileRunning) {
  FakeAxis axis;
  Instance i;
  i.call(axis, true);
  axis.set(1, JobState::kError, 0x8001);
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "00001");
  EXPECT_EQ(i.hs.outputs().ErrorID, 0x8001);
  i.call(axis, false);
  EXPECT_EQ(i.flags(), "00000");
}

// E6: a new edge on the same instance while Busy starts a new job; the outputs describe the new job.
// spec 03 §3.2 E6 (a new edge on the same instance starts a new job).
TEST(ExecuteHandshake, E6_NewEdgeWhileBusy) {
  FakeAxis axis;
  Instance i;
  i.call(axis, true);
  i.call(axis, false);
  i.call(axis, true);
  EXPECT_EQ(axis.submissions, 2);
  EXPECT_EQ(i.hs.job(), 2u);
  EXPECT_EQ(i.flags(), "11000");
  axis.set(1, JobState::kAborted);  // the first job's abort is not shown
  i.call(axis, true);
  EXPECT_EQ(i.flags(), "11000");
}

// E4: the three final flags are mutually exclusive and never coexist with Busy, for every end state.
// spec 03 §3.2 E4 (exactly one of Done, CommandAborted, Error; Busy FALSE).
TEST(ExecuteHandshake, E4_FinalFlagsExclusive) {
  for (JobState end : {JobState::kDone, JobState::kAborted, JobState::kError, JobState::kUnknown}) {
    FakeAxis axis;
    Instance i;
    i.call(axis, true);
    if (end == JobState::kUnknown) {
      axis.jobs.clear();
    } else {
      axis.set(1, end, 0x8001);
    }
    i.call(axis, true);
    const auto& o = i.hs.outputs();
    EXPECT_FALSE(o.Busy);
    EXPECT_EQ(int(o.Done) + int(o.CommandAborted) + int(o.Error), 1);
  }
}

}  // namespace
