// Leading and following value offsets of the synchronous operation (spec 07 §4.1, §4.2, §6.6):
// MC_PhasingAbsolute / MC_PhasingRelative shift the function leading value (StatusSynchronizedMotion.
// PhaseShift), MC_OffsetAbsolute / MC_OffsetRelative the following value (.Offset). Both act only while the
// gearing or camming is Synchronous and end with it (spec 07 §1.8); run() applies them around the synchronous
// function (synchronous_operation.cpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/synchronous/synchronous_operation.hpp"

namespace tomc::techobjects {

namespace {

constexpr double kMoving = 1e-9;  // leading value units / s: below this the leading value stands

double direction_of(double v) noexcept {
  return v > kMoving ? 1.0 : v < -kMoving ? -1.0 : 0.0;
}

// The committed direction a Direction input gives (1 positive, 2 negative, 3 that of the leading value).
double committed_direction(std::int32_t direction, double velocity) noexcept {
  return direction == 1 ? 1.0 : direction == 2 ? -1.0 : direction_of(velocity);
}

// S(ξ) = 10ξ³ − 15ξ⁴ + 6ξ⁵ and its derivatives: "continuous velocity and acceleration" (spec 07 §6.6).
struct Smooth {
  double s;
  double ds;
  double dds;
};
Smooth smooth_step(double xi) noexcept {
  const double x2 = xi * xi;
  return Smooth{x2 * xi * (10.0 - 15.0 * xi + 6.0 * x2), 30.0 * x2 * (1.0 - 2.0 * xi + x2),
                60.0 * xi * (1.0 - 3.0 * xi + 2.0 * x2)};
}

}  // namespace

// Requirements of a new phasing / offset job (spec 07 §4.1, §4.2; ALM8): a gearing (not MC_GearInVelocity) or
// camming in status Synchronous, and not the other kind of offset active or waiting.
std::optional<std::uint16_t> SynchronousOperation::shift_requirements(bool phasing) const noexcept {
  if (active_.id == 0) return error_id::kNoSynchronousOperation;
  if (active_.kind == JobKind::kGearInVelocity) return error_id::kVelocityGearingActive;
  if (active_.phase != Phase::kSynchronous) return error_id::kNotSynchronous;
  if (shift_job_.id != 0 && shift_job_.phasing != phasing) return error_id::kPhasingAndOffsetExclusive;
  return std::nullopt;
}

Submission SynchronousOperation::phasing(const PhasingInputs& in, bool absolute) noexcept {
  if (const auto e = axis_.program_job_rejection()) return Submission::reject(e);
  const std::int32_t p = in.ProfileReference;
  if (p != 0 && p != 1 && p != 2 && p != 5) return Submission::reject(error_id::kInvalidProfileReference);
  if (p == 5) {  // only cancel a waiting phasing job (spec 07 §4.1)
    cancel_waiting_shift(true);
    return Submission::accept(axis_.jobs().create(JobKind::kPhasing, JobState::kDone));
  }
  if (!std::isfinite(in.PhaseShift)) return Submission::reject(error_id::kInvalidPhaseShift);
  if (p != 0 && !(std::isfinite(in.PhasingDistance) && in.PhasingDistance > 0.0))
    return Submission::reject(error_id::kInvalidPhasingDistance);
  if (p == 2 && !std::isfinite(in.StartPosition)) return Submission::reject(error_id::kInvalidStartPosition);
  if (in.Direction < 1 || in.Direction > 3) return Submission::reject(error_id::kInvalidDirection);
  ProfileLimits limits;
  if (p == 0) {
    if (const auto e = axis_.resolve_dynamics(in.Velocity, in.Acceleration, in.Deceleration, in.Jerk, limits))
      return Submission::reject(*e);
    // The velocity of the follower's extra travel is limited by the drive only (spec 07 §4.1, §6.8).
    const double v = in.Velocity < 0.0 ? axis_.data().DynamicDefaults.Velocity : in.Velocity;
    limits.velocity = v / axis_.units().velocity;
  }
  if (const auto e = shift_requirements(true)) return Submission::reject(*e);
  if (in.Master != nullptr && in.Master != followed_leading_value())
    return Submission::reject(error_id::kNoSynchronousOperation);  // [IMPL] another leader: none with it
  if (p == 0 && active_.kind == JobKind::kCamIn)
    return Submission::reject(error_id::kPhasingProfileNeedsGearing);
  ShiftJob job;
  job.phasing = true;
  job.profile = p;
  job.length = in.PhasingDistance;
  job.start_position = in.StartPosition;
  job.committed = in.Direction;  // start_shift() turns the input into a direction
  job.ratio = ratio(active_.numerator, active_.denominator);
  if (p == 0) {
    // A time-based positioning of the follower's extra travel r·Δφ (spec 07 §6.6); φ = travel / r. A new job
    // starts from the phase shift reached (a running one is aborted below, S5 "A").
    const double delta = absolute ? in.PhaseShift - phase_shift_.value : in.PhaseShift;
    if (!job.travel.plan(job.ratio * delta, limits)) return Submission::reject(error_id::kInvalidVelocity);
  }
  if (const auto e = arbitrate_row(NewSyncRow::kPhasing)) return Submission::reject(e);  // S5 "A"
  return start_shift(job, in.PhaseShift, absolute);
}

Submission SynchronousOperation::offset(const OffsetInputs& in, bool absolute) noexcept {
  if (const auto e = axis_.program_job_rejection()) return Submission::reject(e);
  const std::int32_t p = in.ProfileReference;
  if (p != 1 && p != 2 && p != 5) return Submission::reject(error_id::kInvalidProfileReference);
  if (p == 5) {  // only cancel a waiting offset job (spec 07 §4.2)
    cancel_waiting_shift(false);
    return Submission::accept(axis_.jobs().create(JobKind::kOffset, JobState::kDone));
  }
  if (!std::isfinite(in.Offset)) return Submission::reject(error_id::kInvalidOffset);
  if (!(std::isfinite(in.OffsetDistance) && in.OffsetDistance > 0.0))
    return Submission::reject(error_id::kInvalidOffsetDistance);
  if (p == 2 && !std::isfinite(in.StartPosition)) return Submission::reject(error_id::kInvalidStartPosition);
  if (in.Direction < 1 || in.Direction > 3) return Submission::reject(error_id::kInvalidDirection);
  if (const auto e = shift_requirements(false)) return Submission::reject(*e);
  if (const auto e = arbitrate_row(NewSyncRow::kOffset)) return Submission::reject(e);  // S6 "A"
  ShiftJob job;
  job.profile = p;
  job.length = in.OffsetDistance;
  job.start_position = in.StartPosition;
  job.committed = in.Direction;
  return start_shift(job, in.Offset, absolute);
}

// What phasing and offset jobs share at their start: Δ from the present shift (absolute: to the target;
// relative: the increment, spec 07 §6.6), the leading value the distance starts from, the waiting state of
// profile 2. Δ = 0 ends the job at once (Done, no motion). `prepared.committed` holds the Direction input.
Submission SynchronousOperation::start_shift(const ShiftJob& prepared, double target,
                                             bool absolute) noexcept {
  const LeadingValue leader = sample(active_.source);
  const Shift& shift = shift_of(prepared.phasing);
  const AxisJobKind kind = prepared.phasing ? JobKind::kPhasing : JobKind::kOffset;
  const auto direction = static_cast<std::int32_t>(prepared.committed);
  ShiftJob j = prepared;
  j.from = shift.value;
  j.delta = absolute ? target - shift.value : target;
  j.waiting = j.profile == 2;
  j.committed = committed_direction(direction, leader.velocity);
  j.x_start = j.x_extreme = j.last_x = leader.position;
  if (j.delta == 0.0) {
    FinishedShift& finished = finished_of(prepared.phasing);
    finished.id = axis_.jobs().create(kind, JobState::kDone);
    finished.absolute = shift.value;
    finished.covered = 0.0;
    return Submission::accept(finished.id);
  }
  // Direction 1/2 fix the direction; 3 takes it from the leading value's motion (profile 2: at the crossing).
  if (direction == 3 && j.waiting) j.committed = 0.0;
  j.id = axis_.jobs().create(kind, JobState::kActive);
  shift_job_ = j;
  return Submission::accept(j.id);
}

void SynchronousOperation::end_shift(JobState state, std::uint16_t error_id) noexcept {
  ShiftJob& job = shift_job_;
  if (job.id == 0) return;
  axis_.jobs().set(job.id, state, error_id);
  const Shift& shift = shift_of(job.phasing);
  FinishedShift& finished = finished_of(job.phasing);
  finished.id = job.id;
  finished.absolute = shift.value;
  finished.covered = shift.value - job.from;
  job = ShiftJob{};
}

void SynchronousOperation::cancel_waiting_shift(bool phasing) noexcept {
  if (shift_job_.id != 0 && shift_job_.phasing == phasing && shift_job_.waiting)
    end_shift(JobState::kAborted, 0);
}

void SynchronousOperation::end_shifts() noexcept {
  end_shift(JobState::kAborted, 0);
  phase_shift_ = Shift{};
  offset_ = Shift{};
}

bool SynchronousOperation::RestToRestTravel::plan(double to, const ProfileLimits& l) noexcept {
  PositionProfile p;
  if (!p.plan(MotionState{}, to, l) || p.segments().size() > kMaxSegments) return false;
  limits = l;
  target = to;
  duration = p.duration();
  select(p, 0.0);
  return true;
}

void SynchronousOperation::RestToRestTravel::select(const PositionProfile& p, double t) noexcept {
  const auto segments = p.segments();
  next_start = std::numeric_limits<double>::infinity();
  segment = ProfileSegment{};
  if (segments.empty()) return;
  std::size_t i = segments.size() - 1;
  while (i > 0 && segments[i].start_time > t)
    --i;
  segment = segments[i];
  if (i + 1 < segments.size()) next_start = segments[i + 1].start_time;
}

MotionState SynchronousOperation::RestToRestTravel::at(double t) noexcept {
  if (!(t < duration)) return MotionState{target, 0.0, 0.0};
  if (t >= next_start) {  // the next segment: the same plan again (bounded, allocation-free)
    PositionProfile p;
    (void)p.plan(MotionState{}, target, limits);
    select(p, t);
  }
  const ProfileSegment& k = segment;
  const double d = std::max(0.0, t - k.start_time);
  const double a = k.acceleration + d * k.jerk;  // the cubic in the segment's local time
  const double v = k.velocity + d * (k.acceleration + a) / 2.0;
  return MotionState{k.position + d * k.velocity + d * d * (k.acceleration / 2.0 + d * k.jerk / 6.0), v, a};
}

// One MC_Interpolator cycle of a phasing or offset job (spec 07 §6.6).
void SynchronousOperation::step_shift(const LeadingValue& effective) noexcept {
  phase_shift_.velocity = phase_shift_.acceleration = offset_.velocity = offset_.acceleration = 0.0;
  ShiftJob& job = shift_job_;
  if (job.id == 0) return;
  Shift& shift = shift_of(job.phasing);
  const double x = effective.position;
  if (job.profile == 0) {
    // Phasing with dynamic parameters: independent of the leading value; φ follows the follower's profile.
    const double t = static_cast<double>(++job.cycles) * axis_.ipo_cycle_s();  // no summed rounding
    const MotionState z = job.travel.at(t);
    shift = Shift{job.from + z.position / job.ratio, z.velocity / job.ratio, z.acceleration / job.ratio};
    if (t >= job.travel.duration - 1e-12) {
      shift = Shift{job.from + job.delta, 0.0, 0.0};
      end_shift(JobState::kDone, 0);
    }
    return;
  }
  const double step = x - job.last_x;
  job.last_x = x;
  if (job.waiting) {
    // Profile 2: the effective leading value crosses StartPosition (a modulo leader: any occurrence) in the
    // committed direction, or in any direction for Direction 3 (spec 07 §6.6).
    const double moved = direction_of(step);
    if (moved == 0.0 || (job.committed != 0.0 && moved != job.committed)) return;
    const ModuloRange range =
        interconnections_[static_cast<std::size_t>(active_.source)].source->leading_value_modulo();
    const double lo = std::min(x - step, x);
    const double hi = std::max(x - step, x);
    double q = job.start_position;
    if (range.enabled && range.length > 0.0) {
      q = job.start_position + std::ceil((lo - job.start_position) / range.length - 1e-12) * range.length;
    }
    // No occurrence of StartPosition in [lo, hi] (up to the rounding of a summed leading value).
    if (q > hi + 1e-9 * std::max(1.0, std::fabs(hi))) return;
    job.waiting = false;
    job.committed = moved;
    job.x_start = job.x_extreme = q;
  }
  if (job.committed == 0.0) {
    job.committed = direction_of(x - job.x_start);
    if (job.committed == 0.0) return;  // the leading value has not moved yet
  }
  // A reversal beyond the interconnection's reversal tolerance (spec 07 §1.6, decision C27; 0 by default)
  // and a rounding tolerance cancels the job with 16#808C; the part covered stays (spec 07 §4.1, §6.6).
  const double back = job.committed * (job.x_extreme - x);
  if (back > reversal_tolerance(active_.source) + 1e-9 * std::max(1.0, std::fabs(x))) {
    end_shift(JobState::kError, error_id::kLeadingValueReversed);
    return;
  }
  if (back < 0.0) job.x_extreme = x;
  const double xi = std::clamp(job.committed * (job.x_extreme - job.x_start) / job.length, 0.0, 1.0);
  const Smooth s = smooth_step(xi);
  const double per_x = job.committed / job.length;  // dξ/dx
  shift.value = job.from + job.delta * s.s;
  shift.velocity = job.delta * s.ds * per_x * effective.velocity;
  shift.acceleration = job.delta * (s.dds * per_x * per_x * effective.velocity * effective.velocity +
                                    s.ds * per_x * effective.acceleration);
  if (xi >= 1.0 - 1e-12) {  // the summed leading value may end a rounding short of the distance
    shift = Shift{job.from + job.delta, 0.0, 0.0};
    end_shift(JobState::kDone, 0);
  }
}

ShiftJobOutputs SynchronousOperation::shift_outputs(JobId job) const noexcept {
  if (job == 0) return {};
  if (shift_job_.id == job) {
    const Shift& shift = shift_job_.phasing ? phase_shift_ : offset_;
    return ShiftJobOutputs{!shift_job_.waiting, shift.value, shift.value - shift_job_.from};
  }
  if (phasing_finished_.id == job) return phasing_finished_.outputs();
  if (offset_finished_.id == job) return offset_finished_.outputs();
  return {};
}

}  // namespace tomc::techobjects
