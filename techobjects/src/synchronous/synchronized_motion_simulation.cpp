// MC_SynchronizedMotionSimulation (spec 07 §4.4): the synchronous operation goes on without its follower.
// While simulated, the gearing or camming keeps computing its setpoints from the leading value, but the axis
// does not take them: it runs its own single-axis jobs and superimposed motion, may be disabled or stopped,
// and none of that ends the synchronous operation (seed 004 L10064: MC_Stop does not interrupt it). New
// synchronous jobs are refused with 16#8076. At the end the synchronous setpoint takes effect at once,
// without re-synchronization (a step if the follower is elsewhere: the user's procedure, decision C18).
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/synchronous/synchronous_operation.hpp"

namespace tomc::techobjects {

namespace {
constexpr double kStandstill = 1e-9;  // position units / s
}  // namespace

std::uint16_t SynchronousOperation::synchronous_job_rejection() const noexcept {
  if (const auto e = axis_.program_job_rejection()) return e;
  return simulation_ != 0 ? error_id::kSynchronousOperationSimulated : 0;
}

Submission SynchronousOperation::simulation_start() noexcept {
  if (const auto e = axis_.program_job_rejection()) return Submission::reject(e);
  if (simulation_ != 0) return Submission::reject(error_id::kRejectedByRunningJob);  // one simulation per TO
  if (active_.id == 0) return Submission::reject(error_id::kNoSynchronousOperation);
  if (active_.phase != Phase::kSynchronous) return Submission::reject(error_id::kNotSynchronous);
  // A waiting synchronization or desynchronization could not start while simulated (tomc, decision C18).
  if (pending_sync_.id != 0 || desync_.id != 0) return Submission::reject(error_id::kRejectedByRunningJob);
  // The manual's procedure: the leader at standstill. The follower too, so that the axis, handed back,
  // stands.
  const LeadingValue leader = sample(active_.source);
  if (std::fabs(leader.velocity) > kStandstill || std::fabs(axis_.setpoint().velocity) > kStandstill)
    return Submission::reject(error_id::kSimulationNeedsStandstill);
  simulation_ = axis_.jobs().create(JobKind::kSynchronizedMotionSimulation, JobState::kActive);
  // The axis is free for single-axis jobs: the synchronous job is no longer its motion (§9.19.1 sees none).
  axis_.end_motion(active_.id);
  axis_.hand_back();
  return Submission::accept(simulation_);
}

std::uint16_t SynchronousOperation::simulation_end(JobId job) noexcept {
  if (!in_simulation(job)) return 0;
  if (!axis_.enabled()) return error_id::kAxisNotEnabled;  // "requires the follower to be enabled" (§4.4)
  // As a new MC_GearIn (§9.19.1 R8): single-axis jobs end, superimposed motion ends and its shift is lost
  // (seed 004 §6.7.10.2 L4411), a running MC_Stop refuses the end (C6 "N"; the next call tries again).
  if (const auto e = axis_.arbitrate(NewJob::kGearIn)) return e;
  end_simulation(JobState::kDone);
  axis_.set_position_controlled(true);
  axis_.take_over(active_.id, active_.kind);
  axis_.set_setpoint(sync_setpoint_);  // at once, no re-synchronization
  return 0;
}

void SynchronousOperation::end_simulation(JobState state) noexcept {
  if (simulation_ == 0) return;
  axis_.jobs().set(simulation_, state);
  simulation_ = 0;
}

void SynchronousOperation::restart() noexcept {
  end_simulation(JobState::kAborted);  // a TO restart ends the simulation and the synchronous operation
  abort(0);
  additive_end(additive_.id, JobState::kAborted);  // and the additive leading value (spec 07 §4.3, C19)
}

// One MC_Interpolator cycle of a simulated synchronous operation: the chain of spec 07 §1.8 as in run(), but
// whatever the axis' state, without alarm reactions on the axis, and into sync_setpoint_ only.
void SynchronousOperation::run_simulated() noexcept {
  const LeadingValue leader = sample(active_.source);
  cycle_leader_ = leader;
  cycle_leader_source_ = active_.source;
  if (!leader.valid) return;  // the synchronous setpoint holds until the leading value is valid again
  LeadingValue function_leader = leader;
  step_shift(function_leader);
  function_leader.position += phase_shift_.value;
  function_leader.velocity += phase_shift_.velocity;
  function_leader.acceleration += phase_shift_.acceleration;
  step_active(function_leader);
  if (active_.id == 0) {  // a non-cyclic cam reached its end: nothing is left to simulate
    end_simulation(JobState::kDone);
    return;
  }
  sync_setpoint_.position += offset_.value;
  sync_setpoint_.velocity += offset_.velocity;
  sync_setpoint_.acceleration += offset_.acceleration;
}

}  // namespace tomc::techobjects
