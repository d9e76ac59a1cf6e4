// MC_LeadingValueAdditive (spec 07 §4.3): a value added to the leading value of the follower — effective
// leading value = source + additive (§1.8) — at once, without dynamic limitation. It is independent of the
// synchronous jobs: it may start before one, survives overrides, desynchronization and a leader switchover,
// and ends only with Enable = FALSE or another MC_LeadingValueAdditive (§9.19.2 column S7).
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/synchronous/synchronous_operation.hpp"

namespace tomc::techobjects {

namespace {
bool finite(const LeadingValueAdditiveValues& v) noexcept {
  return std::isfinite(v.Position) && std::isfinite(v.Velocity) && std::isfinite(v.Acceleration);
}
}  // namespace

Submission SynchronousOperation::additive_start(const LeadingValueAdditiveValues& values) noexcept {
  // Requirement: the follower is enabled, or its synchronous operation simulated (spec 07 §4.3).
  if (!axis_.enabled() && simulation_ == 0) return Submission::reject(error_id::kAxisNotEnabled);
  if (!finite(values)) return Submission::reject(error_id::kInvalidPosition);
  if (additive_.id != 0) axis_.jobs().set(additive_.id, JobState::kAborted);  // S7 "A"
  additive_ = Additive{};
  additive_.id = axis_.jobs().create(JobKind::kLeadingValueAdditive, JobState::kActive);
  (void)additive_update(additive_.id, values);
  return Submission::accept(additive_.id);
}

std::uint16_t SynchronousOperation::additive_update(JobId job,
                                                    const LeadingValueAdditiveValues& values) noexcept {
  if (!additive_busy(job)) return 0;
  // A value that is not finite keeps the last one: ending the job would make the additive value vanish, a
  // step; the instance shows 16#8118 while the input stays invalid (decision C19).
  if (!finite(values)) return error_id::kInvalidPosition;
  additive_.position = values.Position;
  additive_.velocity = values.Velocity / axis_.units().velocity;
  additive_.acceleration = values.Acceleration / axis_.units().acceleration;
  return 0;
}

void SynchronousOperation::additive_end(JobId job, JobState state) noexcept {
  if (!additive_busy(job)) return;
  axis_.jobs().set(job, state);
  additive_ = Additive{};  // the additive value vanishes at once (a step if it was not 0)
}

}  // namespace tomc::techobjects
