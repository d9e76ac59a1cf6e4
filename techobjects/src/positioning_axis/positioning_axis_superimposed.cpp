// MC_MoveSuperimposed and MC_HaltSuperimposed on the positioning axis (spec 03 §4.10–4.11, spec 01 §8.14,
// seed 004 §6.7.10): the jobs, their §9.19.1 row R6 / column C7, and the superimposed part of the setpoint.
#include <cmath>
#include <limits>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::techobjects {

Submission PositioningAxis::move_superimposed(const MoveSuperimposedInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!std::isfinite(in.Distance)) return Submission::reject(error_id::kInvalidPosition);
  // NaN is resolve_dynamics' internal "no velocity": a user's NaN is an invalid input.
  if (std::isnan(in.VelocityDiff)) return Submission::reject(error_id::kInvalidVelocity);
  ProfileLimits limits;  // VelocityDiff < 0: DynamicDefaults.Velocity, = 0 invalid (spec 03 §2.1)
  if (const auto e = resolve_dynamics(in.VelocityDiff, in.Acceleration, in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  // "Superimposed motion requires position-controlled operation" (spec 03 §4.10).
  if (!position_controlled_) return Submission::reject(error_id::kNotPositionControlled);
  bool queue = false;
  if (const auto e = arbitrate_motion(NewJob::kSuperimposed, queue)) return Submission::reject(e);
  const JobId id = core_.jobs.create(JobKind::kMoveSuperimposed, JobState::kActive);
  superimposed_.move(id, in.Distance, limits);
  return Submission::accept(id);
}

Submission PositioningAxis::halt_superimposed(const HaltSuperimposedInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  ProfileLimits limits;
  if (const auto e = resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), in.Deceleration,
                                      in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  bool queue = false;
  if (const auto e = arbitrate_motion(NewJob::kSuperimposed, queue)) return Submission::reject(e);
  // No superimposed motion: Done at once, without effect (spec 01 §8.14).
  if (superimposed_.settled())
    return Submission::accept(core_.jobs.create(JobKind::kHaltSuperimposed, JobState::kDone));
  const JobId id = core_.jobs.create(JobKind::kHaltSuperimposed, JobState::kActive);
  superimposed_.halt(id, limits, in.AbortAcceleration);
  return Submission::accept(id);
}

void PositioningAxis::abort_superimposed(std::uint16_t error_id, bool fold) noexcept {
  const JobId id = superimposed_.job_id();
  if (id != 0) core_.jobs.set(id, error_id == 0 ? JobState::kAborted : JobState::kError, error_id);
  if (fold) {
    superimposed_.fold();
  } else {
    superimposed_.end_job();
  }
}

void PositioningAxis::advance_superimposed() noexcept {
  // The headroom the base motion leaves (spec 01 §8.14): a following axis' synchronous motion is not limited
  // by its own dynamic limits, so there only VelocityDiff applies.
  const double inf = std::numeric_limits<double>::infinity();
  const bool limited = generator_ != Generator::kSynchronous;
  const double v_limit = velocity_limit();
  const double v_base = setpoint_.velocity;
  const JobId id = superimposed_.job_id();
  if (superimposed_.advance(core_.ipo_cycle_s, limited ? v_limit - v_base : inf,
                            limited ? v_limit + v_base : inf) &&
      id != 0) {
    core_.jobs.set(id, JobState::kDone);  // MoveSuperimposed: the distance is travelled; Halt: standing
    superimposed_.end_job();
  }
}

// Both motions finished: the superimposed part becomes part of the base motion and SuperimposedDistance
// returns to 0 (spec 01 §8.14).
void PositioningAxis::settle_superimposed() noexcept {
  const bool base_finished = motion_.id == 0 && pending_.id == 0 && generator_ == Generator::kIdle &&
                             (core_.stop.id == 0 || core_.stop.done);
  if (!base_finished || !superimposed_.settled()) return;
  superimposed_.fold();
  superimposed_.reset_distance();
}

}  // namespace tomc::techobjects
