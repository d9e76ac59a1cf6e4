#pragma once
// What an instruction instance learns about the job it submitted to a technology object. The TO owns the
// job records; instances keep only the JobId and read the status on each call (ARCHITECTURE-GUIDE §4).

#include <cstdint>

namespace tomc::techobjects {

using JobId = std::uint32_t;  // 0 = no job

enum class JobState : std::uint8_t {
  kUnknown,  // no such job (never submitted, or its record was reused long ago)
  kPending,  // accepted, waiting behind a running job (BufferMode 1): Busy, not Active
  kActive,   // controls the axis: Busy, Active
  kDone,     // completed: Done
  kAborted,  // ended by another job: CommandAborted
  kError,    // ended by an error (alarm reaction, invalid state): Error + ErrorID
};

struct JobStatus {
  JobState state = JobState::kUnknown;
  std::uint16_t error_id = 0;
  bool in_velocity = false;  // MC_MoveVelocity / MC_MoveJog: setpoint speed reached and constant
};

// The answer to a job submission: accepted with its id, or rejected with the ErrorID (spec 03 §3.2 E2, E7).
struct Submission {
  JobId id = 0;
  std::uint16_t error_id = 0;
  bool accepted() const noexcept { return id != 0; }
  static Submission accept(JobId id) noexcept { return Submission{id, 0}; }
  static Submission reject(std::uint16_t error_id) noexcept { return Submission{0, error_id}; }
};

}  // namespace tomc::techobjects
