// The synchronous operation of a synchronous axis: gearing (spec 07 §2, §5, §6) and what gearing and camming
// share — job states, §9.19.2, the pending start, desynchronization, the status (camming: camming.cpp).
#include "tomc/techobjects/synchronous/synchronous_operation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/position/limit_switches.hpp"

namespace tomc::techobjects {

namespace {

constexpr double kReversalEpsilon = 1e-9;  // position units / s: below this the leader counts as standing

double sign_or(double v, double fallback) noexcept {
  return v > kReversalEpsilon ? 1.0 : v < -kReversalEpsilon ? -1.0 : fallback;
}

}  // namespace

SynchronousOperation::SynchronousOperation(FollowingAxis axis, std::string_view name,
                                           std::vector<LeadingValueInterconnection> leaders)
    : interconnections_(std::move(leaders)), axis_(axis) {
  for (std::size_t i = 0; i < interconnections_.size(); ++i) {
    const auto& c = interconnections_[i];
    const std::string at = std::string(name) + ".LeadingValueInterconnections[" + std::to_string(i + 1) + "]";
    if (c.source == nullptr || c.object == nullptr) throw std::invalid_argument(at + ": no leading axis");
    if (c.object == axis_.as_object()) {
      throw std::invalid_argument(at + ": the axis cannot be its own leading value (spec 07 §1.2, 16#8019)");
    }
    if (!(c.reversal_tolerance >= 0.0F) || !std::isfinite(c.reversal_tolerance)) {
      throw std::invalid_argument(at +
                                  ".LeadingValueReversalTolerance: " + std::to_string(c.reversal_tolerance) +
                                  " is not a tolerance (0 or more; decision C27)");
    }
    leader_objects_.push_back(c.object);
  }
}

const LeadingValueSource* SynchronousOperation::followed_leading_value() const noexcept {
  return active_.id != 0 && active_.source >= 0
             ? interconnections_[static_cast<std::size_t>(active_.source)].source
             : nullptr;
}

// ---------------------------------------------------------------------------------------------------------
// Helpers

int SynchronousOperation::find_source(const LeadingValueSource* master) const noexcept {
  for (std::size_t i = 0; i < interconnections_.size(); ++i) {
    if (interconnections_[i].source == master) return static_cast<int>(i);
  }
  return -1;
}

LeadingValue SynchronousOperation::sample(int source) const noexcept {
  if (source < 0) return LeadingValue{};
  const auto& c = interconnections_[static_cast<std::size_t>(source)];
  LeadingValue v = c.source->leading_value(c.coupling);
  // The effective leading value: source + additive (spec 07 §1.8, §4.3); every phase uses it.
  v.position += additive_.position;
  v.velocity += additive_.velocity;
  v.acceleration += additive_.acceleration;
  return v;
}

// The leader of a new synchronous job (spec 07 §1.2, §1.3): configured, not the follower itself or led by it,
// valid, and position-controlled for setpoint coupling.
std::optional<std::uint16_t> SynchronousOperation::check_master(const LeadingValueSource* master,
                                                                int& source) noexcept {
  // The axis itself, or a leader that follows this axis (directly), would close a loop: 16#8019.
  const LeadingValueSource* self = axis_.as_leading_value();
  if (master == self) return error_id::kRecursiveLeadingValue;
  if (master != nullptr && master->followed_leading_value() == self) return error_id::kRecursiveLeadingValue;
  source = find_source(master);
  if (source < 0) {
    // Not a configured possible leading value: alarm 601, ErrorWord.X14; the job ends with 16#8001 (O-5).
    axis_.raise(kAlarmLeadingAxisDefective, 0);
    return error_id::kAbortedByAlarmReaction;
  }
  const LeadingValue v = sample(source);
  if (!v.valid) {
    axis_.raise(kAlarmLeadingAxisDefective, 1);
    return error_id::kAbortedByAlarmReaction;
  }
  // Setpoint coupling, delayed or not, needs a position-controlled leader (spec 07 §1.3, §1.5).
  if (interconnections_[static_cast<std::size_t>(source)].coupling != LeadingValueCoupling::kActualValue &&
      !v.position_controlled) {
    axis_.raise(kAlarmLeaderNotPositionControlled, 0);  // removes the follower's enable (spec 07 §1.3)
    return error_id::kAbortedByAlarmReaction;
  }
  return std::nullopt;
}

bool SynchronousOperation::synchronization_reversed(ActiveSync& a, double x,
                                                    bool velocity_reversed) noexcept {
  const double tolerance = reversal_tolerance(a.source);
  if (tolerance == 0.0) return velocity_reversed;
  if (a.direction == 0) {  // not moving yet: no direction to reverse
    a.x_extreme = x;
    return false;
  }
  const double back = a.direction * (a.x_extreme - x);
  if (back < 0.0) a.x_extreme = x;
  return back > tolerance + 1e-9 * std::max(1.0, std::fabs(x));  // beyond the rounding of a summed value
}

double SynchronousOperation::gear_line(const ActiveSync& a, double x) const noexcept {
  // y_sync + N·(x − x_sync)/D: the ratio applied to the distance, not a rounded quotient (spec 07 §6.2).
  return a.y_sync + static_cast<double>(a.numerator) * (x - a.x_sync) / static_cast<double>(a.denominator);
}

// The occurrence p + n·length of a position given in modulo coordinates that lies at least `min_ahead` ahead
// of `reference` in `direction` (spec 07 §6.1 item 3 [OPEN], decision Y3). Linear: the position itself.
double SynchronousOperation::modulo_occurrence(double p, const ModuloRange& range, double reference,
                                               double direction, double min_ahead) const noexcept {
  if (!range.enabled || !(range.length > 0.0)) return p;
  const double wrapped = modulo_wrap(p, range.start, range.length).position;
  const double base = reference + direction * min_ahead;
  // smallest n with direction·(wrapped + n·L − base) >= 0
  const double n = direction > 0.0 ? std::ceil((base - wrapped) / range.length)
                                   : std::floor((base - wrapped) / range.length);
  return wrapped + n * range.length;
}

// SlaveSyncPosition on a modulo follower: the occurrence the synchronization reaches in the SyncDirection,
// relative to where the follower would be without it (spec 07 §2.2 SyncDirection, [IMPL]).
double SynchronousOperation::choose_slave_sync(double slave_sync, std::int32_t direction,
                                               double estimate) const noexcept {
  if (!axis_.modulo().enabled) return slave_sync;
  const double L = axis_.data().Modulo.Length;
  const double w = modulo_wrap(slave_sync, axis_.data().Modulo.StartValue, L).position;
  const double n0 = std::floor((estimate - w) / L);
  const double below = w + n0 * L;  // <= estimate
  const double above = below + L;   // > estimate
  if (direction == 1) return estimate - below < 1e-9 ? below : above;
  if (direction == 2) return below;
  return (estimate - below) <= (above - estimate) ? below : above;
}

// Profile 0 (in advance, dynamic parameters, spec 07 §2.2, §3.4, §6.5, §6.8): tomc synchronizes over a
// leading-value distance just long enough that the follower's velocity, acceleration/deceleration and jerk
// stay within the job's Velocity, Acceleration/Deceleration and Jerk (clipped to DynamicLimits) for the
// present leader velocity (decisions Y6, C23). The blend runs onto the straight line through the synchronous
// point with the function's slope there (a cam's tangent: its curvature is not part of the synchronization,
// decision C23). The candidate is sampled at 17 points (2 % reserve for the interior peaks between them; the
// end, the synchronous velocity slope·v_leader, is exact and judged without it); the shortest fitting length
// is bracketed by doubling and then bisected: a fixed number of steps, no allocation. A synchronous velocity
// above the job's Velocity but within MaxVelocity raises the blend's velocity cap to it (§6.8: only
// MaxVelocity decides whether the synchronization may complete, decision C23).
// Negative: the synchronous velocity is above MaxVelocity, or no length holds the cap, and the
// synchronization may not start (§6.8: it completes only below MaxVelocity).
double SynchronousOperation::sync_length_profile0(const PendingSyncIn& p, const LeadingValue& leader,
                                                  double y_target, double r) const noexcept {
  const double v = std::max(std::fabs(leader.velocity), 1e-9);
  const double v_leader = p.direction * v;
  // The synchronous velocity is exact (the blend ends on the line), so it is judged without reserve against
  // MaxVelocity (spec 07 §2.2 profile 0, §6.8); the job's Velocity only shapes the blend.
  const double v_sync = std::fabs(r) * v;
  const double max_velocity = axis_.data().DynamicLimits.MaxVelocity / axis_.units().velocity;
  if (!(v_sync <= (1.0 + 1e-9) * max_velocity)) return -1.0;
  const double shape_v = std::max(p.limits.velocity, v_sync);
  const double max_v = 0.98 * shape_v;
  const double max_a = 0.98 * p.limits.acceleration;
  const double max_d = 0.98 * p.limits.deceleration;
  const double max_j = p.limits.jerk > 0.0 ? 0.98 * p.limits.jerk : std::numeric_limits<double>::infinity();
  // The follower's present motion is where the blend starts (ξ = 0 is not judged): a velocity or
  // acceleration it already has above the limits may stay, not grow ("current dynamics are blended into the
  // new job", spec 07 §2.1).
  const MotionState f = axis_.setpoint();
  const double cap_v = std::max(max_v, 0.98 * std::fabs(f.velocity));
  const double cap_a = std::max(max_a, 0.98 * std::fabs(f.acceleration));
  const double cap_d = std::max(max_d, 0.98 * std::fabs(f.acceleration));
  const auto fits = [&](double length) noexcept {
    LeaderDomainBlend b;
    const double x_a = p.master_sync - p.direction * length;
    b.start(x_a, p.direction * length, p.master_sync, y_target, r, f, v_leader, 0.0);
    if (std::fabs(b.jerk(x_a, v_leader)) > max_j) return false;
    const auto within = [&](double x, bool end) noexcept {
      const MotionState m = b.at(x, v_leader, 0.0);
      if (std::fabs(m.velocity) > (end ? std::max(cap_v, (1.0 + 1e-9) * shape_v) : cap_v)) return false;
      const bool decelerating = m.acceleration * m.velocity < 0.0;
      if (std::fabs(m.acceleration) > (decelerating ? cap_d : cap_a)) return false;
      return std::fabs(b.jerk(x, v_leader)) <= max_j;
    };
    for (int i = 1; i <= 16; ++i) {
      if (!within(x_a + p.direction * length * (i / 16.0), i == 16)) return false;
    }
    // The acceleration's and the jerk's peaks between the samples (a cubic and a quadratic in ξ).
    std::array<double, 3> peaks{};
    const std::size_t n = b.extrema(peaks);
    for (std::size_t i = 0; i < n; ++i) {
      if (!within(peaks[i], false)) return false;
    }
    return true;
  };
  // The shortest distance over which the leader velocity alone could be taken up with Acceleration.
  const double base = std::max(std::fabs(r) * v * v / std::max(p.limits.acceleration, 1e-9), 1e-6);
  if (fits(base)) return base;
  double low = base;
  double high = base;
  bool found = false;
  for (int i = 0; i < 40 && !found; ++i) {
    low = high;
    high = 2.0 * low;
    found = fits(high);
  }
  if (!found) return -1.0;
  for (int i = 0; i < 20; ++i) {  // 1e-6 of the bracket
    const double mid = 0.5 * (low + high);
    (fits(mid) ? high : low) = mid;
  }
  return high;
}

// Profile 0's synchronization length onto (y_target, slope), searched again (a few hundred blend evaluations)
// only when what it depends on changed: the leader velocity, the follower's velocity and acceleration and
// its distance to the target — a modulo follower's occurrence of the target moves with the leader, so the
// follower's own position is not the key. A new pass of a modulo leader clears it (the slope of a cam may
// differ there).
double SynchronousOperation::profile0_length(PendingSyncIn& p, const LeadingValue& leader, double y_target,
                                             double slope) noexcept {
  const MotionState f = axis_.setpoint();
  const double gap = f.position - y_target;
  if (leader.velocity != p.sized_leader_velocity || gap != p.sized_follower.position ||
      f.velocity != p.sized_follower.velocity || f.acceleration != p.sized_follower.acceleration) {
    p.sized_length = sync_length_profile0(p, leader, y_target, slope);
    p.sized_leader_velocity = leader.velocity;
    p.sized_follower = MotionState{gap, f.velocity, f.acceleration};
  }
  // A job that may not start synchronizing — its synchronous velocity above MaxVelocity, or no length holds
  // the velocity — waits visibly: alarm 501 "velocity limited" (a warning without reaction, WarningWord.X6),
  // additional value 1 (0: a job's dynamics clipped at its start), raised again if MC_Reset acknowledged it
  // while the job still waits; a 501 still pending from the job's start stays the indication (spec 07 §2.2
  // profile 0 "violations raise 501/502/503", §6.8; spec 04 §5.4; decision C23).
  if (p.sized_length < 0.0 && !axis_.alarm_pending(kAlarmDynamicsLimitedVelocity))
    axis_.raise(kAlarmDynamicsLimitedVelocity, 1);
  return p.sized_length;
}

// ---------------------------------------------------------------------------------------------------------
// Ending jobs

void SynchronousOperation::end_active(JobState state, std::uint16_t error_id) noexcept {
  if (active_.id == 0) return;
  end_shifts();  // leading and following value offsets end with the synchronous operation (spec 07 §1.8)
  last_synchronous_job_ = active_.id;
  last_outputs_ = SyncJobOutputs{};
  last_outputs_.EndOfProfileCount = active_.cam.ends;
  release_cam(active_.cam);
  axis_.jobs().set(active_.id, state, error_id);
  axis_.end_motion(active_.id);
  active_ = ActiveSync{};
  axis_.hand_back();  // the follower goes on with its present motion (spec 07 §2.5)
}

void SynchronousOperation::end_pending(JobState state, std::uint16_t error_id) noexcept {
  if (pending_sync_.id == 0) return;
  axis_.jobs().set(pending_sync_.id, state, error_id);
  release_cam(pending_sync_.cam);
  pending_sync_ = PendingSyncIn{};
}

void SynchronousOperation::end_desync(JobState state, std::uint16_t error_id) noexcept {
  if (desync_.id == 0) return;
  axis_.jobs().set(desync_.id, state, error_id);
  axis_.end_motion(desync_.id);
  desync_ = Desync{};
}

void SynchronousOperation::abort(std::uint16_t error_id) noexcept {
  // A simulated synchronous operation survives disabling, alarms and MC_Stop (spec 07 §4.4); a restart ends
  // it (restart()).
  if (simulation_ != 0) return;
  const JobState state = error_id == 0 ? JobState::kAborted : JobState::kError;
  end_shift(state, error_id);
  end_active(state, error_id);
  end_pending(state, error_id);
  end_desync(state, error_id);
}

// §9.19.2: a new job against the running synchronous jobs (spec 07 §5.1). Decide first, then abort.
std::uint16_t SynchronousOperation::arbitrate(NewJob row) noexcept {
  // Simulated: single-axis jobs move the follower and abort nothing synchronous (spec 07 §4.4); the new
  // synchronous jobs were refused with 16#8076 before they got here.
  if (simulation_ != 0) return 0;
  NewSyncRow r{};
  switch (row) {
    case NewJob::kActiveHoming:
      r = NewSyncRow::kActiveHoming;
      break;
    case NewJob::kHaltBaseOnly:
    case NewJob::kBaseMotion:
      r = NewSyncRow::kMotion;
      break;
    case NewJob::kAppendedMotion:
      r = NewSyncRow::kAppendedMotion;
      break;
    case NewJob::kSuperimposed:
      r = NewSyncRow::kSuperimposed;
      break;
    case NewJob::kStop:
      r = NewSyncRow::kStop;
      break;
    case NewJob::kGearIn:
      r = NewSyncRow::kGearIn;
      break;
    case NewJob::kSyncPending:
      r = NewSyncRow::kSyncInPending;
      break;
    case NewJob::kSyncActive:
      r = NewSyncRow::kSyncInActive;
      break;
    case NewJob::kSyncOutPending:
      r = NewSyncRow::kSyncOutPending;
      break;
    case NewJob::kSyncOutActive:
      r = NewSyncRow::kSyncOutActive;
      break;
    default:
      return 0;  // Mode 9 and the other homing modes: no row (spec 03 §6.1 [AMB-15])
  }
  return arbitrate_row(r);
}

std::uint16_t SynchronousOperation::arbitrate_row(NewSyncRow r) noexcept {
  struct Running {
    RunningSyncJob column;
    int which;  // 0 active, 1 pending sync-in, 2 desync, 3 phasing or offset
    SyncFamily family;
  };
  std::array<Running, 5> running{};
  std::size_t n = 0;
  // The columns of each instruction come from the table beside the matrix (sync_priority.hpp).
  const auto place = [](JobKind kind) noexcept {
    switch (kind) {
      case JobKind::kGearIn:
        return find_sync_instruction("MC_GearIn");
      case JobKind::kGearInVelocity:
        return find_sync_instruction("MC_GearInVelocity");
      case JobKind::kCamIn:
        return find_sync_instruction("MC_CamIn");
      case JobKind::kGearOut:
        return find_sync_instruction("MC_GearOut");
      case JobKind::kCamOut:
        return find_sync_instruction("MC_CamOut");
      default:
        return find_sync_instruction("MC_GearInPos");
    }
  };
  if (active_.id != 0) {
    const auto* p = place(active_.kind);
    running[n++] = Running{p->active_column, 0, p->family};
  }
  if (pending_sync_.id != 0) {
    const auto* p = place(pending_sync_.kind);
    running[n++] = Running{p->pending_column, 1, p->family};
  }
  if (desync_.id != 0) {
    const auto* p = place(desync_.kind);
    running[n++] = Running{desync_.active ? p->active_column : p->pending_column, 2, p->family};
  }
  if (shift_job_.id != 0) {
    running[n++] = Running{shift_job_.phasing ? RunningSyncJob::kPhasing : RunningSyncJob::kOffset, 3,
                           SyncFamily::kGearing};
  }
  SyncContext ctx;
  ctx.follower_position_controlled = axis_.position_controlled();
  ctx.virtual_or_simulated_axis = axis_.virtual_axis();
  std::uint8_t abort_mask = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ctx.same_family = running[i].family == new_job_family_;
    switch (resolve(r, running[i].column, ctx)) {
      case Outcome::kRejectNew:
        // MC_Home 3/5 while MC_GearInPos/MC_CamIn is active has its own ErrorID (spec 07 §1.10, 16#80A1);
        // so have a leading and a following value offset against each other (16#808A).
        if (r == NewSyncRow::kActiveHoming && running[i].column == RunningSyncJob::kSyncInActive)
          return error_id::kHomingDuringGearInPos;
        if (running[i].which >= 3 && (r == NewSyncRow::kPhasing || r == NewSyncRow::kOffset))
          return error_id::kPhasingAndOffsetExclusive;
        return error_id::kRejectedByRunningJob;
      case Outcome::kAbortRunning:
        abort_mask = static_cast<std::uint8_t>(abort_mask | (1u << i));
        break;
      default:
        break;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if ((abort_mask & (1u << i)) == 0) continue;
    if (running[i].which == 0) end_active(JobState::kAborted, 0);
    if (running[i].which == 1) end_pending(JobState::kAborted, 0);
    if (running[i].which == 2) end_desync(JobState::kAborted, 0);
    if (running[i].which == 3) end_shift(JobState::kAborted, 0);
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------------------
// Jobs

// What MC_GearIn and MC_GearInVelocity share (spec 07 §2.1, §2.3): the parameter checks, the leader, the
// §9.19.2 arbitration, and the start of an active gearing that synchronizes at once. The caller sets what
// differs (velocity limit, position control, InSync rules) on active_ afterwards.
Submission SynchronousOperation::start_gearing(JobKind kind, const LeadingValueSource* master,
                                               std::int32_t numerator, std::int32_t denominator,
                                               double acceleration, double deceleration,
                                               double jerk) noexcept {
  if (numerator == 0) return Submission::reject(error_id::kInvalidRatioNumerator);
  if (denominator < 1) return Submission::reject(error_id::kInvalidRatioDenominator);
  ProfileLimits limits;
  if (const auto e = axis_.resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), acceleration,
                                            deceleration, jerk, limits))
    return Submission::reject(*e);
  if (const auto e = axis_.motion_prerequisites()) return Submission::reject(e);
  int source = -1;
  if (const auto e = check_master(master, source)) return Submission::reject(*e);
  if (const auto e = axis_.arbitrate(NewJob::kGearIn)) return Submission::reject(e);
  axis_.abort_pending();
  const JobId id = axis_.jobs().create(kind, JobState::kActive);
  active_ = ActiveSync{};
  active_.id = id;
  active_.kind = kind;
  active_.source = source;
  active_.numerator = numerator;
  active_.denominator = denominator;
  active_.phase = Phase::kSynchronizing;
  active_.limits = limits;  // MC_GearIn: velocity = MaxVelocity, synchronization completes only below it
  sync_setpoint_ = axis_.setpoint();
  axis_.take_over(id, kind);
  last_synchronous_job_ = id;
  return Submission::accept(id);
}

Submission SynchronousOperation::gear_in(const GearInInputs& in) noexcept {
  if (const auto e = synchronous_job_rejection()) return Submission::reject(e);
  const Submission s = start_gearing(JobKind::kGearIn, in.Master, in.RatioNumerator, in.RatioDenominator,
                                     in.Acceleration, in.Deceleration, in.Jerk);
  if (!s.accepted()) return s;
  const LeadingValue leader = sample(active_.source);
  active_.direction = static_cast<std::int8_t>(sign_or(leader.velocity, 0.0));
  active_.x_extreme = leader.position;
  axis_.set_position_controlled(true);  // gearing forces position control (spec 07 §1.7)
  return s;
}

Submission SynchronousOperation::gear_in_velocity(const GearInVelocityInputs& in) noexcept {
  if (const auto e = synchronous_job_rejection()) return Submission::reject(e);
  const Submission s = start_gearing(JobKind::kGearInVelocity, in.Master, in.RatioNumerator,
                                     in.RatioDenominator, in.Acceleration, in.Deceleration, in.Jerk);
  if (!s.accepted()) return s;
  // The velocity is limited only by the drive during velocity gearing (spec 07 §2.3).
  active_.limits.velocity = std::numeric_limits<double>::infinity();
  active_.continuous_update = in.ContinuousUpdate;
  active_.start_sync = true;
  axis_.set_position_controlled(in.PositionControlled);  // spec 07 §1.7
  return s;
}

Submission SynchronousOperation::gear_in_pos(const GearInPosInputs& in) noexcept {
  if (const auto e = synchronous_job_rejection()) return Submission::reject(e);
  if (in.RatioNumerator == 0) return Submission::reject(error_id::kInvalidRatioNumerator);
  if (in.RatioDenominator < 1) return Submission::reject(error_id::kInvalidRatioDenominator);
  if (in.SyncProfileReference != 0 && in.SyncProfileReference != 1 && in.SyncProfileReference != 3) {
    return Submission::reject(error_id::kInvalidSyncProfileReference);  // 2, 4 reserved
  }
  if (in.SyncProfileReference != 0 &&
      !(std::isfinite(in.MasterStartDistance) && in.MasterStartDistance > 0.0)) {
    return Submission::reject(error_id::kInvalidMasterStartDistance);
  }
  if (!std::isfinite(in.MasterSyncPosition)) return Submission::reject(error_id::kInvalidMasterSyncPosition);
  if (!std::isfinite(in.SlaveSyncPosition)) return Submission::reject(error_id::kInvalidPosition);
  if (in.SyncDirection < 1 || in.SyncDirection > 3) return Submission::reject(error_id::kInvalidDirection);
  ProfileLimits limits;
  // Velocity, Acceleration, Deceleration and Jerk belong to profile 0 alone (spec 07 §2.2): the distance
  // profiles neither check them nor raise 501/502/503 for them (decisions C20, C24).
  const bool dynamic = in.SyncProfileReference == 0;
  if (const auto e =
          axis_.resolve_dynamics(dynamic ? in.Velocity : -1.0, dynamic ? in.Acceleration : -1.0,
                                 dynamic ? in.Deceleration : -1.0, dynamic ? in.Jerk : -1.0, limits))
    return Submission::reject(*e);
  if (const auto e = axis_.motion_prerequisites()) return Submission::reject(e);
  if (!axis_.homed()) return Submission::reject(error_id::kAxisNotHomed);  // spec 07 §2.2 requirements
  int source = -1;
  if (const auto e = check_master(in.Master, source)) return Submission::reject(*e);
  const LeadingValue leader = sample(source);
  const ModuloRange range =
      interconnections_[static_cast<std::size_t>(source)].source->leading_value_modulo();
  PendingSyncIn p;
  p.source = source;
  p.numerator = in.RatioNumerator;
  p.denominator = in.RatioDenominator;
  p.profile = in.SyncProfileReference;
  p.length = in.SyncProfileReference == 0 ? 0.0 : in.MasterStartDistance;
  p.sync_direction = in.SyncDirection;
  p.slave_sync = in.SlaveSyncPosition;
  p.limits = limits;
  p.direction = sign_or(leader.velocity, 1.0);
  // The leader's start position must still lie ahead (profile 1: MasterSyncPosition − MasterStartDistance,
  // profile 3: MasterSyncPosition); a modulo leader takes the next occurrence (decision Y3).
  const double ahead = in.SyncProfileReference == 1 ? in.MasterStartDistance : 0.0;
  p.master_sync = modulo_occurrence(in.MasterSyncPosition, range, leader.position, p.direction, ahead);
  if (!range.enabled && p.direction * (p.master_sync - p.direction * ahead - leader.position) < 0.0) {
    return Submission::reject(error_id::kInvalidMasterSyncPosition);
  }
  if (const auto e = axis_.arbitrate(NewJob::kSyncPending)) return Submission::reject(e);
  p.id = axis_.jobs().create(JobKind::kGearInPos, JobState::kActive);
  pending_sync_ = p;
  last_synchronous_job_ = p.id;
  return Submission::accept(p.id);
}

Submission SynchronousOperation::gear_out(const GearOutInputs& in) noexcept {
  return desynchronize(in, JobKind::kGearOut);
}

// MC_GearOut and MC_CamOut (spec 07 §2.4, §3.5): the same parameters and behaviour, each for its own family.
Submission SynchronousOperation::desynchronize(const GearOutInputs& in, JobKind kind) noexcept {
  if (const auto e = synchronous_job_rejection()) return Submission::reject(e);
  if (in.SyncProfileReference != 0 && in.SyncProfileReference != 1 && in.SyncProfileReference != 5) {
    return Submission::reject(error_id::kInvalidSyncProfileReference);
  }
  if (in.SyncProfileReference == 1 &&
      !(std::isfinite(in.MasterStopDistance) && in.MasterStopDistance > 0.0)) {
    return Submission::reject(error_id::kInvalidMasterStartDistance);
  }
  if (!std::isfinite(in.SlavePosition)) return Submission::reject(error_id::kInvalidPosition);
  if (in.SyncOutDirection < 1 || in.SyncOutDirection > 3)
    return Submission::reject(error_id::kInvalidDirection);
  if (!axis_.enabled()) return Submission::reject(error_id::kAxisNotEnabled);
  // Requirement: a job of the family active or pending (spec 07 §2.4: 16#8077, §3.5: 16#8078).
  const SyncFamily family = family_of(kind);
  const bool active =
      active_.id != 0 && active_.kind != JobKind::kGearInVelocity && family_of(active_.kind) == family;
  const bool pending = pending_sync_.id != 0 && family_of(pending_sync_.kind) == family;
  if (!active && !pending) {
    return Submission::reject(family == SyncFamily::kCamming ? error_id::kNoCamming : error_id::kNoGearing);
  }
  if (in.SyncProfileReference == 5) {
    // Only cancel a pending synchronization (and a pending desynchronization) of the family; an active one is
    // not affected (§5 fn. 7, 8).
    if (pending) end_pending(JobState::kAborted, 0);
    if (desync_.id != 0 && !desync_.active && desync_.kind == kind) end_desync(JobState::kAborted, 0);
    return Submission::accept(axis_.jobs().create(kind, JobState::kDone));
  }
  ProfileLimits limits;
  if (const auto e = axis_.resolve_dynamics(std::numeric_limits<double>::quiet_NaN(), in.Deceleration,
                                            in.Deceleration, in.Jerk, limits))
    return Submission::reject(*e);
  new_job_family_ = family;
  const std::uint16_t rejected = axis_.arbitrate(NewJob::kSyncOutPending);
  new_job_family_ = SyncFamily::kGearing;
  if (rejected != 0) return Submission::reject(rejected);
  Desync d;
  d.kind = kind;
  d.id = axis_.jobs().create(kind, JobState::kActive);
  d.profile = in.SyncProfileReference;
  d.slave_position = in.SlavePosition;
  d.stop_distance = in.MasterStopDistance;
  d.direction = in.SyncOutDirection;
  d.limits = limits;
  desync_ = d;
  last_synchronous_job_ = d.id;
  return Submission::accept(d.id);
}

void SynchronousOperation::update_ratio(JobId job, std::int32_t numerator,
                                        std::int32_t denominator) noexcept {
  if (job == 0 || job != active_.id || !active_.continuous_update) return;
  if (numerator == 0 || denominator < 1) return;  // the last valid ratio stays
  active_.numerator = numerator;
  active_.denominator = denominator;
}

SyncJobOutputs SynchronousOperation::sync_outputs(JobId job) const noexcept {
  SyncJobOutputs o;
  if (job != 0 && job == last_synchronous_job_ && job != active_.id) o = last_outputs_;
  if (job != 0 && job == active_.id) {
    o.StartSync = active_.start_sync;
    o.InSync = active_.in_sync;
    o.ContinuousUpdateActive = active_.continuous_update && active_.in_sync;
    o.EndOfProfileCount = active_.cam.ends;
  }
  if (job != 0 && job == desync_.id) o.StartSyncOut = desync_.start_sync_out;
  return o;
}

// ---------------------------------------------------------------------------------------------------------
// The cycle

// A pending MC_GearInPos starts when the leader crosses its start position in its direction of travel
// (spec 07 §2.2): it becomes active (§9.19.1 R10, §9.19.2 "active" row) and blends onto the gear line.
bool SynchronousOperation::start_pending_sync(const LeadingValue& leader) noexcept {
  if (pending_sync_.kind == JobKind::kCamIn) return start_pending_cam(leader);
  PendingSyncIn& p = pending_sync_;
  const double r = ratio(p.numerator, p.denominator);
  double length = p.length;
  double x_a = 0.0;
  double x_target = p.master_sync;
  if (p.profile == 0) {
    const double y_target = choose_slave_sync(
        p.slave_sync, p.sync_direction, axis_.setpoint().position + r * (p.master_sync - leader.position));
    profile0_length(p, leader, y_target, r);
    if (p.sized_length < 0.0) {  // cannot synchronize yet: alarm 501 shows it (spec 07 §6.8, decision C23)
      p.armed = false;
      return false;
    }
    length = p.sized_length;
    x_a = p.master_sync - p.direction * length;
    if (!profile0_start_crossed(p, leader, x_a)) return false;
  } else if (p.profile == 1) {
    x_a = p.master_sync - p.direction * length;
  } else {  // 3: subsequent — the blend starts at MasterSyncPosition and ends a distance later
    x_a = p.master_sync;
  }
  if (p.direction * (leader.position - x_a) < 0.0) return false;  // not there yet
  if (!(p.direction * leader.velocity > 0.0)) return false;       // reached, but not moving towards it
  // The follower's end of synchronization on the gear line; a modulo follower picks its occurrence.
  const double y_estimate = axis_.setpoint().position + r * (x_target - leader.position);
  const double y_target = choose_slave_sync(p.slave_sync, p.sync_direction, y_estimate);
  const PendingSyncIn started = p;
  if (!activate_pending(JobKind::kGearInPos)) return false;
  active_.numerator = started.numerator;
  active_.denominator = started.denominator;
  active_.x_sync = x_target;
  active_.y_sync = y_target;
  const double signed_length = started.direction * (started.profile == 3 ? started.length : length);
  // Profile 3: the line is y = SlaveSync + r·(x − MasterSync); the blend covers [MasterSync, MasterSync + L].
  // The blend starts at the nominal start position, so that it ends exactly at the synchronous point (the
  // leader may already be up to one cycle past the start when the crossing is seen).
  active_.blend.start(x_a, signed_length, x_target, y_target, r, axis_.setpoint(), leader.velocity,
                      leader.acceleration);
  return true;
}

// Profile 0 (GearInPos, CamIn): the start position moves with the computed length. Synchronization starts
// only when the leader crosses it, within one cycle's travel (spec 07 §6.5); a start position already passed
// (at the job's start, or because the length grew) is not caught up with a step of the follower: a modulo
// leader waits for the next pass, a linear one remains pending (decision Y12).
bool SynchronousOperation::profile0_start_crossed(PendingSyncIn& p, const LeadingValue& leader,
                                                  double x_a) noexcept {
  const double past = p.direction * (leader.position - x_a);
  if (past < 0.0) {
    p.armed = true;
    return false;
  }
  if (!p.armed || past > std::fabs(leader.velocity) * axis_.ipo_cycle_s() * (1.0 + 1e-9) + 1e-12) {
    p.armed = false;
    const ModuloRange range =
        interconnections_[static_cast<std::size_t>(p.source)].source->leading_value_modulo();
    if (range.enabled && range.length > 0.0) {
      p.master_sync += p.direction * (std::floor(past / range.length) + 1.0) * range.length;
      p.sized_leader_velocity = std::numeric_limits<double>::quiet_NaN();  // sized again for that pass
    }
    return false;
  }
  return true;
}

// The pending job starts: it becomes active (§9.19.1 R10, §9.19.2 "active" row, its aborts applied; the
// pending job itself is no longer pending) and takes the follower over in the blend phase. The caller sets
// the synchronous function and the blend. False if a running job rejects it (the job ends with Error).
bool SynchronousOperation::activate_pending(JobKind kind) noexcept {
  const PendingSyncIn started = pending_sync_;
  pending_sync_ = PendingSyncIn{};
  const JobId id = started.id;
  axis_.jobs().set(id, JobState::kActive);
  if (axis_.arbitrate(NewJob::kSyncActive) != 0) {
    axis_.jobs().set(id, JobState::kError, error_id::kRejectedByRunningJob);
    CamJob cam = started.cam;
    release_cam(cam);
    return false;
  }
  axis_.abort_pending();
  active_ = ActiveSync{};
  active_.id = id;
  active_.kind = kind;
  active_.source = started.source;
  active_.phase = Phase::kBlend;
  active_.direction = static_cast<std::int8_t>(started.direction);
  active_.x_extreme = sample(started.source).position;
  active_.start_sync = true;
  active_.cam = started.cam;
  axis_.set_position_controlled(true);
  sync_setpoint_ = axis_.setpoint();
  axis_.take_over(id, kind);
  return true;
}

void SynchronousOperation::step_active(const LeadingValue& leader) noexcept {
  if (active_.kind == JobKind::kCamIn) {
    step_cam(leader);
    return;
  }
  ActiveSync& a = active_;
  const double T = axis_.ipo_cycle_s();
  const double r = ratio(a.numerator, a.denominator);
  switch (a.phase) {
    case Phase::kSynchronizing: {
      // The leading value must not reverse during synchronization (spec 07 §2.1, alarm 608).
      const double now = sign_or(leader.velocity, 0.0);
      if (a.kind == JobKind::kGearIn &&
          synchronization_reversed(a, leader.position,
                                   a.direction != 0 && now != 0.0 && now != a.direction)) {
        axis_.raise(kAlarmSynchronizationError, 1);
        return;
      }
      if (a.direction == 0) a.direction = static_cast<std::int8_t>(now);
      double vT = r * leader.velocity;
      const double aT = r * leader.acceleration;
      // Synchronization completes only below the velocity limit; no alarm 501 (spec 07 §6.3).
      const bool clamped = std::fabs(vT) > a.limits.velocity;
      if (clamped) vT = std::copysign(a.limits.velocity, vT);
      const SynchronizationStep s =
          synchronization_step(axis_.setpoint(), vT, clamped ? 0.0 : aT, a.limits, T);
      sync_setpoint_ = s.state;
      if (s.locked && !clamped) {
        a.phase = Phase::kSynchronous;
        a.in_sync = true;
        a.x_sync = leader.position;
        a.y_sync = s.state.position;
      }
      break;
    }
    case Phase::kBlend: {
      if (synchronization_reversed(a, leader.position,
                                   sign_or(leader.velocity, a.direction) != a.direction)) {
        axis_.raise(kAlarmSynchronizationError, 1);  // reversal during synchronization (spec 07 §2.2)
        return;
      }
      sync_setpoint_ = a.blend.at(leader.position, leader.velocity, leader.acceleration);
      if (a.blend.progress(leader.position) >= 1.0 - 1e-12) {
        a.phase = Phase::kSynchronous;
        a.in_sync = true;
      }
      break;
    }
    case Phase::kSynchronous:
      if (a.kind == JobKind::kGearInVelocity) {
        // v = r·v_leader, the position integrated (spec 07 §6.2).
        const double v = r * leader.velocity;
        // Simulated, the axis' setpoint is not the synchronous one: integrate the synchronous setpoint.
        const MotionState& last = simulation_ != 0 ? sync_setpoint_ : axis_.setpoint();
        sync_setpoint_ =
            MotionState{last.position + 0.5 * (last.velocity + v) * T, v, r * leader.acceleration};
      } else {
        sync_setpoint_ =
            MotionState{gear_line(a, leader.position), r * leader.velocity, r * leader.acceleration};
      }
      break;
  }
  if (a.kind == JobKind::kGearInVelocity && a.phase == Phase::kSynchronizing) a.start_sync = true;
}

// MC_GearOut (spec 07 §2.4, §6.7): pending until its start condition, then the follower stops at
// SlavePosition — with the job's deceleration independently of the leader (profile 0) or over
// MasterStopDistance of the leader (profile 1).
void SynchronousOperation::step_desync(const LeadingValue& leader) noexcept {
  Desync& d = desync_;
  const double T = axis_.ipo_cycle_s();
  if (!d.active) {
    if (active_.id == 0 || active_.phase != Phase::kSynchronous) return;  // waits for synchronous travel
    const double v = sync_setpoint_.velocity;
    const double dir = sign_or(v, 0.0);
    if (dir == 0.0) return;
    if ((d.direction == 1 && dir < 0.0) || (d.direction == 2 && dir > 0.0)) return;  // SyncOutDirection
    const ModuloRange follower = axis_.modulo();
    const double r = function_slope(leader);
    bool start = false;
    // The stop travel: the follower's distance from the start of desynchronization to standstill.
    const double step = std::fabs(v) * T;  // the follower's travel in one cycle: a start is seen within it
    double stop_travel = 0.0;
    if (d.profile == 0) {
      stop_travel = limits::braking_distance(std::fabs(v), sync_setpoint_.acceleration * dir,
                                             d.limits.deceleration, d.limits.jerk);
    } else {
      // Profile 1: over L of leader travel the follower covers slope·L/2 (spec 07 §6.7; a cam: its present
      // slope, the [OPEN] predicate y_f(x) + Y'(x)·L/2 ≥ y_stop).
      if (sign_or(leader.velocity, 0.0) == 0.0) return;
      stop_travel = std::fabs(r) * d.stop_distance / 2.0;
    }
    // The stop position has to lie at least the stop travel ahead. A modulo follower takes the next
    // occurrence that does (spec 07 §6.7, §6.1 item 3); a linear one already inside the stop travel (or past
    // the stop position) could only reach it by reversing: the job ends with 16#8037 and the gearing goes on
    // (decision Y11). Margin: profile 0 looks one cycle ahead and starts before the follower is inside (up to
    // the look-ahead's rounding tolerance); profile 1 starts in the cycle nearest the crossing, up to half a
    // cycle's travel inside.
    const double margin =
        d.profile == 0 ? 1e-6 * std::max(1.0, std::fabs(sync_setpoint_.position) + stop_travel) : step;
    const double min_ahead = std::max(stop_travel - margin, 0.0);
    d.y_stop = modulo_occurrence(d.slave_position, follower, sync_setpoint_.position, dir, min_ahead);
    if (dir * (d.y_stop - sync_setpoint_.position) < min_ahead) {
      end_desync(JobState::kError, error_id::kInvalidSlavePosition);
      return;
    }
    if (d.profile == 0) {
      const auto look =
          limits::stop_at_limit_look_ahead(sync_setpoint_.position, v, sync_setpoint_.acceleration, d.y_stop,
                                           d.limits.deceleration, d.limits.jerk, T);
      start = look.stop_now;
    } else {
      const double leader_dir = sign_or(leader.velocity, 0.0);
      start = dir * (d.y_stop - sync_setpoint_.position) <= stop_travel + 0.5 * step;
      if (start) {
        d.blend.start(leader.position, leader_dir * d.stop_distance, leader.position, d.y_stop, 0.0,
                      sync_setpoint_, leader.velocity, leader.acceleration);
      }
    }
    if (!start) return;
    // Desynchronization starts: the synchronous job ends (CommandAborted, §9.19.2 "GearOut/CamOut active").
    d.active = true;
    d.start_sync_out = true;
    d.source = active_.source;
    const MotionState at = sync_setpoint_;
    end_active(JobState::kAborted, 0);
    if (d.profile == 0) {
      // The braking is planned from the previous cycle's setpoint, which the generator steps into this cycle
      // (planned from this cycle's gear-line value it would skip one cycle's travel: a velocity spike).
      ProfileLimits l = d.limits;
      l.velocity = std::max(std::fabs(at.velocity), 1e-9);
      l.acceleration = std::max(l.acceleration, l.deceleration);
      axis_.position_to(d.id, d.kind, d.y_stop, l);
    } else {
      axis_.set_setpoint(at);
      axis_.take_over(d.id, d.kind);
    }
    return;
  }
  if (d.profile == 1) {
    sync_setpoint_ = d.blend.at(leader.position, leader.velocity, leader.acceleration);
    if (d.blend.progress(leader.position) >= 1.0 - 1e-12) {
      sync_setpoint_ = MotionState{d.y_stop, 0.0, 0.0};
      axis_.set_setpoint(sync_setpoint_);
      axis_.hand_back();
      end_desync(JobState::kDone, 0);
    }
  } else if (axis_.generator_idle() && std::fabs(axis_.setpoint().velocity) < 1e-9) {
    end_desync(JobState::kDone, 0);  // at SlavePosition, standstill (spec 07 §2.4)
  }
}

void SynchronousOperation::run() noexcept {
  cycle_leader_source_ = -1;
  if (simulation_ != 0) {
    run_simulated();
    return;
  }
  if (active_.id == 0 && pending_sync_.id == 0 && desync_.id == 0) return;
  if (!axis_.enabled() || axis_.blocked()) return;  // the alarm/disable paths end the jobs
  const int source = active_.id != 0  ? active_.source
                     : desync_.active ? desync_.source
                                      : pending_sync_.source;
  const LeadingValue leader = sample(source);
  // The leader ran before this axis: its value stays the same for the rest of this MC_Interpolator, so the
  // status update reuses it (one virtual leading_value() call per cycle instead of three).
  cycle_leader_ = leader;
  cycle_leader_source_ = source;
  if (source >= 0 && !leader.valid) {
    axis_.raise(kAlarmLeadingAxisDefective,
                1);  // e.g. the external encoder of an actual-value coupling failed
    axis_.apply_alarm_reactions();
    return;
  }
  if (pending_sync_.id != 0 && active_.id == 0) {
    (void)start_pending_sync(leader);
  } else if (pending_sync_.id != 0) {
    // A pending MC_GearInPos while another gearing runs: it starts on its own leader's crossing.
    (void)start_pending_sync(sample(pending_sync_.source));
  }
  if (active_.id != 0) {
    // The chain of spec 07 §1.8: effective leading value (+ phase shift) = function leading value -> the
    // synchronous function -> (+ offset) the follower's setpoint. The offsets act only while Synchronous.
    LeadingValue function_leader = active_.source == source ? leader : sample(active_.source);
    if (active_.phase == Phase::kSynchronous) {
      step_shift(function_leader);
      function_leader.position += phase_shift_.value;
      function_leader.velocity += phase_shift_.velocity;
      function_leader.acceleration += phase_shift_.acceleration;
    }
    step_active(function_leader);
    if (active_.id != 0 && active_.phase == Phase::kSynchronous) {
      sync_setpoint_.position += offset_.value;
      sync_setpoint_.velocity += offset_.velocity;
      sync_setpoint_.acceleration += offset_.acceleration;
    }
    if (axis_.strongest_reaction() != AlarmReaction::kNone) {
      axis_.apply_alarm_reactions();
      return;
    }
  }
  if (desync_.id != 0) step_desync(leader);
}

void SynchronousOperation::update_status() noexcept {
  StatusSynchronizedMotion& s = status_;
  const int source = active_.id != 0 ? active_.source : pending_sync_.id != 0 ? pending_sync_.source : -1;
  s.FunctionState = 0;
  if (active_.id != 0) {
    s.FunctionState = active_.kind == JobKind::kGearIn      ? 1
                      : active_.kind == JobKind::kGearInPos ? 2
                      : active_.kind == JobKind::kCamIn     ? 3
                                                            : 6;
  }
  const bool cam_out = desync_.kind == JobKind::kCamOut;
  if (desync_.active) s.FunctionState = cam_out ? 5 : 4;
  s.WaitingFunctionState = pending_sync_.id != 0 ? (pending_sync_.kind == JobKind::kCamIn ? 3 : 2)
                           : (desync_.id != 0 && !desync_.active) ? (cam_out ? 5 : 4)
                                                                  : 0;
  // The cam in use and its offsets and scalings (a pending switch shows the running cam until it starts).
  const CamJob* cam = active_.id != 0 && active_.kind == JobKind::kCamIn               ? &active_.cam
                      : pending_sync_.id != 0 && pending_sync_.kind == JobKind::kCamIn ? &pending_sync_.cam
                                                                                       : nullptr;
  s.ActualCam = cam != nullptr && cam->cam != nullptr ? cam->cam->number() : 0;
  if (cam != nullptr) {
    const CamScaling& k = cam->function.scaling();
    s.MasterOffset = cam->shown_master_offset;
    s.MasterScaling = k.MasterScaling;
    s.SlaveOffset = k.SlaveOffset;
    s.SlaveScaling = k.SlaveScaling;
  } else {
    s.MasterOffset = s.SlaveOffset = 0.0;
    s.MasterScaling = s.SlaveScaling = 1.0;
  }
  // The following value offset includes the camming's SlaveOffset; MC_OffsetAbsolute targets the offset jobs'
  // part (spec 07 §1.8, O-4).
  s.Offset = (cam != nullptr ? s.SlaveOffset : 0.0) + offset_.value;
  s.PhaseShift = phase_shift_.value;
  s.ActualMaster = static_cast<std::uint16_t>(source >= 0 ? source + 1 : 0);
  if (source >= 0) shown_source_ = source;
  if (shown_source_ >= 0) {
    // Also after the synchronous operation ended: the leading value it used, with the additive value.
    const LeadingValue v = shown_source_ == cycle_leader_source_ ? cycle_leader_ : sample(shown_source_);
    s.EffectiveLeadingValue.Position = v.position;
    s.EffectiveLeadingValue.Velocity = v.velocity * axis_.units().velocity;
    s.EffectiveLeadingValue.Acceleration = v.acceleration * axis_.units().acceleration;
    s.FunctionLeadingValue.Position = v.position + (source >= 0 ? phase_shift_.value : 0.0);
  }
  // Before the following value offset (spec 07 §1.9).
  s.FunctionFollowingValue.Position = active_.id != 0 ? sync_setpoint_.position - offset_.value : 0.0;
  s.FunctionFollowingValue.Velocity =
      active_.id != 0 ? (sync_setpoint_.velocity - offset_.velocity) * axis_.units().velocity : 0.0;
  s.FunctionFollowingValue.Acceleration =
      active_.id != 0 ? (sync_setpoint_.acceleration - offset_.acceleration) * axis_.units().acceleration
                      : 0.0;
  // X0..X2: the follower's configured limits exceeded in synchronous operation (indication only, spec 07
  // §6.8).
  std::uint32_t w = 0;
  if (active_.id != 0 && simulation_ == 0) {
    const auto& l = axis_.data().DynamicLimits;
    const double v = axis_.setpoint().velocity * axis_.units().velocity;
    const double a = axis_.setpoint().acceleration * axis_.units().acceleration;
    assign(w, StatusSynchronizedMotionBit::kMaxVelocityExceeded, std::fabs(v) > l.MaxVelocity * (1.0 + 1e-9));
    assign(w, StatusSynchronizedMotionBit::kMaxAccelerationExceeded,
           a * v > 0.0 && std::fabs(a) > l.MaxAcceleration);
    assign(w, StatusSynchronizedMotionBit::kMaxDecelerationExceeded,
           a * v < 0.0 && std::fabs(a) > l.MaxDeceleration);
  }
  assign(w, StatusSynchronizedMotionBit::kLeadingValueAdditiveCommand, additive_.id != 0);
  assign(w, StatusSynchronizedMotionBit::kInSimulation, simulation_ != 0);
  s.StatusWord = w;
  // Simulated, the follower is not synchronous (X22 FALSE) while InGear/InSync stay TRUE (spec 07 §4.4).
  const bool driving = active_.id != 0 && simulation_ == 0;
  axis_.set_status(StatusWordBit::kSynchronizing, driving && active_.phase != Phase::kSynchronous);
  axis_.set_status(StatusWordBit::kSynchronous, driving && active_.phase == Phase::kSynchronous);
  axis_.set_status(StatusWord2Bit::kDesynchronizingCommand, desync_.active);
  const ShiftJob& k = shift_job_;
  axis_.set_status(StatusWordBit::kPhasingCommand, k.id != 0 && k.phasing && !k.waiting);
  axis_.set_status(StatusWord2Bit::kPhasingCommandWaiting, k.id != 0 && k.phasing && k.waiting);
  axis_.set_status(StatusWord2Bit::kOffsetCommand, k.id != 0 && !k.phasing && !k.waiting);
  axis_.set_status(StatusWord2Bit::kOffsetCommandWaiting, k.id != 0 && !k.phasing && k.waiting);
  cycle_leader_source_ = -1;  // a status update from a job call (user program) samples afresh
}

double SynchronousOperation::read(std::string_view m) const noexcept {
  const auto& s = status_;
  if (m == "FunctionState") return s.FunctionState;
  if (m == "WaitingFunctionState") return s.WaitingFunctionState;
  if (m == "PhaseShift") return s.PhaseShift;
  if (m == "ActualMaster") return s.ActualMaster;
  if (m == "ActualCam") return s.ActualCam;
  if (m == "MasterOffset") return s.MasterOffset;
  if (m == "MasterScaling") return s.MasterScaling;
  if (m == "SlaveOffset") return s.SlaveOffset;
  if (m == "SlaveScaling") return s.SlaveScaling;
  if (m == "Offset") return s.Offset;
  if (m == "EffectiveLeadingValue.Position") return s.EffectiveLeadingValue.Position;
  if (m == "EffectiveLeadingValue.Velocity") return s.EffectiveLeadingValue.Velocity;
  if (m == "EffectiveLeadingValue.Acceleration") return s.EffectiveLeadingValue.Acceleration;
  if (m == "FunctionLeadingValue.Position") return s.FunctionLeadingValue.Position;
  if (m == "FunctionFollowingValue.Position") return s.FunctionFollowingValue.Position;
  if (m == "FunctionFollowingValue.Velocity") return s.FunctionFollowingValue.Velocity;
  if (m == "FunctionFollowingValue.Acceleration") return s.FunctionFollowingValue.Acceleration;
  if (m == "StatusWord") return s.StatusWord;
  if (m.starts_with("StatusWord.X")) {
    const std::string_view digits = m.substr(12);
    unsigned bit = 32;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), bit);
    if (r.ec == std::errc{} && r.ptr == digits.data() + digits.size() && bit < 32) {
      return ((s.StatusWord >> bit) & 1u) != 0 ? 1.0 : 0.0;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}
}  // namespace tomc::techobjects
