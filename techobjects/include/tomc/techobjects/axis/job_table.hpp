#pragma once
// The job records of one technology object: a fixed ring indexed by JobId, so that an instruction instance
// can read the status of the job it submitted for as long as the record has not been reused (32 newer jobs).
// Shared by every TO type; `Kind` is the TO's own job enumeration. No allocation, noexcept.

#include <array>
#include <cstddef>

#include "tomc/techobjects/axis/job.hpp"

namespace tomc::techobjects {

template <typename Kind, std::size_t Capacity = 32>
class JobTable {
 public:
  struct Record {
    JobId id = 0;
    Kind kind{};
    JobStatus status{};
  };

  JobId create(Kind kind, JobState state) noexcept {
    const JobId id = next_++;
    if (next_ == 0) next_ = 1;
    records_[id % Capacity] = Record{id, kind, JobStatus{state, 0, false}};
    return id;
  }
  Record* find(JobId id) noexcept {
    auto& r = records_[id % Capacity];
    return (id != 0 && r.id == id) ? &r : nullptr;
  }
  // Ends or changes a job; leaving the active state clears InVelocity.
  void set(JobId id, JobState state, std::uint16_t error_id = 0) noexcept {
    if (auto* r = find(id)) {
      r->status.state = state;
      r->status.error_id = error_id;
      if (state != JobState::kActive) r->status.in_velocity = false;
    }
  }
  JobStatus status(JobId id) const noexcept {
    const auto& r = records_[id % Capacity];
    return (id != 0 && r.id == id) ? r.status : JobStatus{};
  }

 private:
  std::array<Record, Capacity> records_{};
  JobId next_ = 1;
};

}  // namespace tomc::techobjects
