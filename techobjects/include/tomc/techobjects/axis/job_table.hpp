#pragma once
// The job records of one technology object: a fixed ring indexed by JobId, so that an instruction instance
// can read the status of the job it submitted for as long as the record has not been reused (32 newer jobs).
// Shared by every TO type; `Kind` is the TO's own job enumeration. No allocation, noexcept.

#include <array>
#include <cstddef>
#include <cstdint>

#include "tomc/techobjects/axis/job.hpp"

namespace tomc::techobjects {

// A record is 8 bytes (12 before decision M12): the id, the ErrorID, the kind and the state; the InVelocity
// flags of all records are one word beside them (−124 bytes per axis TO).
template <typename Kind, std::size_t Capacity = 32>
class JobTable {
  static_assert(Capacity <= 32, "the InVelocity flags are one 32-bit word");

 public:
  JobId create(Kind kind, JobState state) noexcept {
    const JobId id = next_++;
    if (next_ == 0) next_ = 1;
    records_[id % Capacity] = Record{id, 0, kind, state};
    in_velocity_ &= ~bit(id);
    return id;
  }
  // Ends or changes a job; leaving the active state clears InVelocity.
  void set(JobId id, JobState state, std::uint16_t error_id = 0) noexcept {
    Record& r = records_[id % Capacity];
    if (id == 0 || r.id != id) return;
    r.state = state;
    r.error_id = error_id;
    if (state != JobState::kActive) in_velocity_ &= ~bit(id);
  }
  // MC_MoveVelocity / MC_MoveJog: the setpoint speed reached and constant (JobStatus::in_velocity).
  void set_in_velocity(JobId id, bool in_velocity) noexcept {
    const Record& r = records_[id % Capacity];
    if (id == 0 || r.id != id) return;
    in_velocity_ = in_velocity ? in_velocity_ | bit(id) : in_velocity_ & ~bit(id);
  }
  JobStatus status(JobId id) const noexcept {
    const Record& r = records_[id % Capacity];
    if (id == 0 || r.id != id) return JobStatus{};
    return JobStatus{r.state, r.error_id, (in_velocity_ & bit(id)) != 0};
  }

 private:
  struct Record {
    JobId id = 0;
    std::uint16_t error_id = 0;
    Kind kind{};
    JobState state = JobState::kUnknown;
  };
  static constexpr std::uint32_t bit(JobId id) noexcept { return std::uint32_t{1} << (id % Capacity); }

  std::array<Record, Capacity> records_{};
  std::uint32_t in_velocity_ = 0;  // bit id % Capacity: the record's InVelocity
  JobId next_ = 1;
};

}  // namespace tomc::techobjects
