// MC_MoveSuperimposed, MC_HaltSuperimposed (spec 03 §4.10–4.11, spec 01 §8.14, seed 004 §6.7.10) and the
// superimposed MotionIn jobs MC_MotionInSuperimposed / MC_MotionInSuperimposedAxes (spec 03 §4.17.3–4.17.4,
// seed 004 §6.14.3) on the positioning axis: the jobs, their §9.19.1 row R6 / column C7, and the superimposed
// part of the setpoint.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

// ---- MotionIn (spec 03 §4.17.3–4.17.4): no profile, no dynamic limits (seed 004 §6.14.3 "the dynamics of
// the superimposed and of the total motion are not limited"); position control as for every superimposed
// motion (spec 02 §2.3).

namespace {

constexpr double kStandstillEpsilon = 1e-9;  // position units / s, as the cycle's standstill test

bool finite(const MotionState& s) noexcept {
  return std::isfinite(s.position) && std::isfinite(s.velocity) && std::isfinite(s.acceleration);
}

}  // namespace

Submission PositioningAxis::motion_in_superimposed(JobId running,
                                                   const MotionInSuperimposedInputs& in) noexcept {
  const MotionState input{in.Distance, in.VelocityDiff / units_.velocity,
                          in.AccelerationDiff / units_.acceleration};
  if (running != 0) {
    // While Enable = TRUE the inputs are taken every cycle; a job another one ended takes nothing.
    if (running != superimposed_.job_id() || superimposed_.job() != SuperimposedMotion::Job::kMotionIn)
      return Submission{};
    if (!finite(input)) {
      // The job ends with Error; the superimposed part brakes with DynamicDefaults instead of jumping (as
      // MotionInPosition's base motion does, decision U11).
      core_.jobs.set(running, JobState::kError, error_id::kInvalidMotionInSetpoint);
      superimposed_.halt(0, AxisCore::default_ramp(db_.DynamicDefaults, dynamic_units()), false);
      return Submission::reject(error_id::kInvalidMotionInSetpoint);
    }
    superimposed_.set_input(input);
    return Submission::accept(running);
  }
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!finite(input)) return Submission::reject(error_id::kInvalidMotionInSetpoint);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  if (!position_controlled_) return Submission::reject(error_id::kNotPositionControlled);
  bool queue = false;
  if (const auto e = arbitrate_motion(NewJob::kSuperimposed, queue)) return Submission::reject(e);
  const JobId id = core_.jobs.create(JobKind::kMotionInSuperimposed, JobState::kActive);
  superimposed_.start_motion_in(id, SuperimposedMotion::Job::kMotionIn);
  superimposed_.set_input(input);
  db_.StatusMotionIn.StatusWord = 0;  // MaxVelocityExceeded counts per MotionIn job
  return Submission::accept(id);
}

Submission PositioningAxis::motion_in_superimposed_axes(JobId running,
                                                        const LeadingValueSource* superimposing) noexcept {
  if (running != 0) {
    const bool ours =
        running == superimposed_.job_id() && superimposed_.job() == SuperimposedMotion::Job::kMotionInAxes;
    return ours ? Submission::accept(running) : Submission{};
  }
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  // SuperimposingAxis must be one of the configured possible superimposing axes (ErrorWord.X16).
  std::uint16_t index = 0;
  if (superimposing_axes_) {
    for (std::size_t i = 0; i < superimposing_axes_->count; ++i) {
      const auto* axis = static_cast<const PositioningAxis*>(superimposing_axes_->axes[i]);
      if (static_cast<const LeadingValueSource*>(axis) == superimposing)
        index = static_cast<std::uint16_t>(i + 1);
    }
  }
  if (index == 0) {
    superimposing_error_ = true;
    return Submission::reject(error_id::kSuperimposingAxisNotConfigured);
  }
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  // Both TOs position-controlled, neither homing (spec 03 §4.17.4 prerequisites).
  if (!position_controlled_) return Submission::reject(error_id::kNotPositionControlled);
  if (motion_.kind == JobKind::kHome || passive_.id != 0)
    return Submission::reject(error_id::kRejectedByRunningJob);
  const auto& other = *static_cast<const PositioningAxis*>(superimposing_axes_->axes[index - 1]);
  if (other.core_.phase != PowerPhase::kEnabled || !other.position_controlled_ ||
      other.motion_.kind == JobKind::kHome || other.passive_.id != 0)
    return Submission::reject(error_id::kSuperimposingAxisNotReady);
  // Its setpoint becomes the superimposition at once: it must stand where the superimposition is (seed 004
  // §6.14.3.2 warning), or the axis would jump (decision U10).
  if (std::fabs(other.setpoint_.position - superimposed_.distance()) > db_.PositioningMonitoring.Window ||
      std::fabs(other.setpoint_.velocity) >= kStandstillEpsilon)
    return Submission::reject(error_id::kSuperimposingAxisNotAtSuperimposition);
  bool queue = false;
  if (const auto e = arbitrate_motion(NewJob::kSuperimposed, queue)) return Submission::reject(e);
  const JobId id = core_.jobs.create(JobKind::kMotionInSuperimposedAxes, JobState::kActive);
  superimposed_.start_motion_in(id, SuperimposedMotion::Job::kMotionInAxes);
  db_.StatusMotionIn.ActualSuperimposingAxis = index;
  db_.StatusMotionIn.StatusWord = 0;
  superimposing_error_ = false;
  return Submission::accept(id);
}

void PositioningAxis::add_possible_superimposing_axis(PositioningAxis& axis) {
  if (&axis == this)
    throw std::invalid_argument(std::string(name()) + ": an axis cannot be its own superimposing axis");
  if (!superimposing_axes_) superimposing_axes_ = std::make_unique<SuperimposingAxisTable>();
  auto& table = *superimposing_axes_;
  for (std::size_t i = 0; i < table.count; ++i) {
    if (table.axes[i] == &axis)
      throw std::invalid_argument(std::string(name()) + ": " + std::string(axis.name()) +
                                  " is already a possible superimposing axis");
  }
  if (table.count == SuperimposingAxisTable::kCapacity)
    throw std::invalid_argument(std::string(name()) + ": more than " +
                                std::to_string(SuperimposingAxisTable::kCapacity) +
                                " possible superimposing axes");
  table.axes[table.count++] = &axis;
}

std::span<TechnologyObject* const> PositioningAxis::superimposing_axes() const noexcept {
  if (!superimposing_axes_) return {};
  return {superimposing_axes_->axes.data(), superimposing_axes_->count};
}

// Out of line even under link-time optimisation (decision P28): a path the steady cycle does not take, kept
// out of the frame of the function that calls it every cycle, whose stack lines the cycle touches.
[[gnu::noinline]] void PositioningAxis::abort_superimposed(std::uint16_t error_id, bool fold) noexcept {
  const JobId id = superimposed_.job_id();
  if (id != 0) core_.jobs.set(id, error_id == 0 ? JobState::kAborted : JobState::kError, error_id);
  if (superimposed_.job() == SuperimposedMotion::Job::kMotionInAxes)
    db_.StatusMotionIn.ActualSuperimposingAxis = 0;
  if (fold) {
    superimposed_.fold();
  } else {
    superimposed_.end_job();
  }
}

// Out of line even under link-time optimisation (decision P28): a path the steady cycle does not take, kept
// out of the frame of the function that calls it every cycle, whose stack lines the cycle touches.
[[gnu::noinline]] void PositioningAxis::advance_superimposed() noexcept {
  // The headroom the base motion leaves (spec 01 §8.14): a following axis' synchronous motion is not limited
  // by its own dynamic limits, so there only VelocityDiff applies.
  const double inf = std::numeric_limits<double>::infinity();
  const bool limited = generator_ != Generator::kSynchronous;
  const double v_limit = velocity_limit();
  const double v_base = setpoint_.velocity;
  const JobId id = superimposed_.job_id();
  if (superimposed_.job() == SuperimposedMotion::Job::kMotionInAxes) {
    // The superimposing axis ran first in this cycle (Runtime orders by superimposing_axes()): its setpoint
    // of this cycle is the superimposition, without a cycle offset (seed 004 §6.14.3.2).
    const std::size_t index = db_.StatusMotionIn.ActualSuperimposingAxis;  // set by the job's start
    const PositioningAxis* other =
        superimposing_axes_ && index >= 1 && index <= superimposing_axes_->count
            ? static_cast<const PositioningAxis*>(superimposing_axes_->axes[index - 1])
            : nullptr;
    if (other != nullptr && other->core_.phase == PowerPhase::kEnabled && other->position_controlled_) {
      superimposed_.follow(other->setpoint_);
    } else {
      // The superimposing axis left enabled, position-controlled operation (or the job's table entry is
      // gone): the job ends with an error, the superimposition stays where it is (decision U10).
      core_.jobs.set(id, JobState::kError, error_id::kSuperimposingAxisNotReady);
      superimposed_.end_motion_in();
      db_.StatusMotionIn.ActualSuperimposingAxis = 0;
      return;
    }
  }
  // Acceleration (seed 004 §6.7.10.1, U16): MaxAcceleration where the total speeds up, MaxDeceleration where
  // it slows down, minus the base's present acceleration: its sample and its mean over the cycle (the base's
  // velocity step: a ramp that ends within the cycle samples 0 yet moved), the larger in each direction. The
  // last cycle's total is the data block's Velocity; the total's direction is that one's.
  const double v_sup = superimposed_.state().velocity;
  const double v_total_before = db_.Velocity / units_.velocity;
  const double a_mean = (v_base - (v_total_before - v_sup)) / core_.ipo_cycle_s;
  const double a_base_up = std::max(setpoint_.acceleration, a_mean);
  const double a_base_down = std::min(setpoint_.acceleration, a_mean);
  const bool forward = v_total_before >= 0.0;
  const double a_max = db_.DynamicLimits.MaxAcceleration / units_.acceleration;
  const double d_max = db_.DynamicLimits.MaxDeceleration / units_.acceleration;
  // Jerk (U17): MaxJerk (0: none, decision S3) less the base's jerk, its acceleration change since the last
  // cycle's total (the data block's Acceleration) less the superimposed part of it.
  const double j_max =
      db_.DynamicLimits.MaxJerk > 0.0 ? db_.DynamicLimits.MaxJerk / units_.acceleration : inf;
  const double a_sup = superimposed_.state().acceleration;
  const double j_base =
      (setpoint_.acceleration - (db_.Acceleration / units_.acceleration - a_sup)) / core_.ipo_cycle_s;
  const SuperimposedMotion::Headroom headroom =
      limited ? SuperimposedMotion::Headroom{v_limit - v_base,
                                             v_limit + v_base,
                                             (forward ? a_max : d_max) - a_base_up,
                                             (forward ? d_max : a_max) + a_base_down,
                                             j_max - j_base,
                                             j_max + j_base,
                                             a_base_up,
                                             a_base_down}
              : SuperimposedMotion::Headroom{inf, inf, inf, inf, inf, inf, 0.0, 0.0};
  if (superimposed_.advance(core_.ipo_cycle_s, headroom)) {
    // MoveSuperimposed: the distance is travelled; Halt: standing (id 0: the braking after a MotionIn
    // setpoint that was not a number).
    if (id != 0) core_.jobs.set(id, JobState::kDone);
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
