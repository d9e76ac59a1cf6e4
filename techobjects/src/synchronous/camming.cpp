// Camming as a synchronous function of the synchronous operation (spec 07 §3.3–§3.5, §6.2, §6.4, §6.5, §6.7,
// §6.8): MC_CamIn with the seven synchronization profiles, MC_CamOut. The job states, the pending start of
// profile 0, the activation (§9.19.1 R10 / §9.19.2), the leader-domain blend and the desynchronization are
// the gearing's (synchronous_operation.cpp); what is camming's own is the target function — the cam with the
// job's scaling, offsets and application mode — and where the synchronization starts and ends.
#include <algorithm>
#include <cmath>
#include <limits>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/position/limit_switches.hpp"
#include "tomc/techobjects/synchronous/synchronous_operation.hpp"

namespace tomc::techobjects {

namespace {

constexpr double kStanding = 1e-9;  // position units / s: below this the leader counts as standing

double direction_of(double v) noexcept {
  return v > kStanding ? 1.0 : v < -kStanding ? -1.0 : 0.0;
}

// The profiles that synchronize over MasterStartDistance (spec 07 §3.4 table).
bool over_distance(std::int32_t profile) noexcept {
  return profile == 1 || profile == 3 || profile == 4 || profile == 6;
}

}  // namespace

void SynchronousOperation::release_cam(CamJob& job) noexcept {
  if (job.cam != nullptr) job.cam->release();
  job.cam = nullptr;
  job.function.stop();
}

// x_sync = StartLeadingValue·MasterScaling + MasterOffset + MasterSyncPosition (spec 07 §3.3), with the
// job's MasterOffset in the leader's continuous coordinates.
double SynchronousOperation::cam_sync_point(const CamJob& job) const noexcept {
  const CamScaling& k = job.function.scaling();
  return job.cam->profile().start() * k.MasterScaling + k.MasterOffset + job.master_sync;
}

// The target following value Y(x) and its motion (spec 07 §6.2). Outside a non-cyclic cam — only while
// synchronizing onto it — the cam continues along its tangent at the end it left (spec 07 §6.4 [OPEN]).
MotionState SynchronousOperation::cam_target(CamJob& job, double x, double v, double a) const noexcept {
  const CamScaling& k = job.function.scaling();
  if (job.function.mode() == CamApplicationMode::kNotCyclic) {
    const CamProfile& p = job.cam->profile();
    const double u = (x - k.MasterOffset) / k.MasterScaling;
    const double edge = std::clamp(u, p.start(), p.end());
    if (edge != u) {
      const CamValue c = p.evaluate(edge);
      const double slope = k.SlaveScaling * c.dy / k.MasterScaling;
      return MotionState{k.SlaveScaling * (c.y + c.dy * (u - edge)) + k.SlaveOffset, slope * v, slope * a};
    }
  }
  const CamFollowingValue f = job.function.evaluate(x, v, a);
  return MotionState{f.position, f.velocity, f.acceleration};
}

// MasterOffset as StatusSynchronizedMotion shows it: for a modulo leader the offset that puts the synchronous
// point into the leader's modulo range (the profile-6 example of spec 07 §3.4: 270 + 180 − 180 ≡ −90).
namespace {
double shown_master_offset(double master_offset, double x_sync, const ModuloRange& range) noexcept {
  if (!range.enabled || !(range.length > 0.0)) return master_offset;
  return master_offset - (x_sync - modulo_wrap(x_sync, range.start, range.length).position);
}
}  // namespace

Submission SynchronousOperation::cam_in(const CamInInputs& in) noexcept {
  if (const auto e = synchronous_job_rejection()) return Submission::reject(e);
  // Parameters (spec 07 §3.4, §1.10).
  if (!std::isfinite(in.MasterOffset)) return Submission::reject(error_id::kInvalidMasterOffset);
  if (!std::isfinite(in.SlaveOffset)) return Submission::reject(error_id::kInvalidSlaveOffset);
  if (!std::isfinite(in.MasterScaling) || in.MasterScaling == 0.0)
    return Submission::reject(error_id::kInvalidMasterScaling);
  if (!std::isfinite(in.SlaveScaling)) return Submission::reject(error_id::kInvalidSlaveScaling);
  const std::int32_t profile = in.SyncProfileReference;
  if (profile < 0 || profile > 6) return Submission::reject(error_id::kInvalidSyncProfileReference);
  if (in.ApplicationMode < 0 || in.ApplicationMode > 2)
    return Submission::reject(error_id::kInvalidApplicationMode);
  if (over_distance(profile) && !(std::isfinite(in.MasterStartDistance) && in.MasterStartDistance > 0.0))
    return Submission::reject(error_id::kInvalidMasterStartDistance);
  if (in.SyncDirection < 1 || in.SyncDirection > 3) return Submission::reject(error_id::kInvalidDirection);
  if (in.Cam == nullptr || in.Cam->profile().empty()) return Submission::reject(error_id::kCamInvalid);
  const CamProfile& cam = in.Cam->profile();
  // MasterSyncPosition is measured from the scaled cam start and must lie in the cam (profiles 0–3, 5, 6).
  const double u_sync = cam.start() + in.MasterSyncPosition / in.MasterScaling;
  if (profile != 4 &&
      !(std::isfinite(u_sync) && u_sync >= cam.start() - 1e-9 * std::max(1.0, std::fabs(cam.start())) &&
        u_sync <= cam.end() + 1e-9 * std::max(1.0, std::fabs(cam.end())))) {
    return Submission::reject(error_id::kOutsideCam);
  }
  ProfileLimits limits;
  // Velocity, Acceleration, Deceleration and Jerk belong to profile 0 alone (spec 07 §3.4): the other
  // profiles neither check them nor raise 501/502/503 for them (decision C20).
  const bool dynamic = profile == 0;
  if (const auto e =
          axis_.resolve_dynamics(dynamic ? in.Velocity : -1.0, dynamic ? in.Acceleration : -1.0,
                                 dynamic ? in.Deceleration : -1.0, dynamic ? in.Jerk : -1.0, limits))
    return Submission::reject(*e);
  if (const auto e = axis_.motion_prerequisites()) return Submission::reject(e);
  if (!axis_.homed()) return Submission::reject(error_id::kAxisNotHomed);  // spec 07 §3.4 requirements
  int source = -1;
  if (const auto e = check_master(in.Master, source)) return Submission::reject(*e);
  if (!in.Cam->interpolated() ||
      CamStatusWordBits{in.Cam->data().StatusWord}.test(CamStatusWordBit::kCamDataChanged)) {
    // Camming with a cam not interpolated since its last change: alarm 612 removes the enable (spec 07
    // §3.2: interpolate after every change); the job ends as an alarm-terminated one (decision C8).
    axis_.raise(kAlarmCamNotInterpolated, 0);
    return Submission::reject(error_id::kAbortedByAlarmReaction);
  }
  if (profile == 5 && !(active_.id != 0 && active_.kind == JobKind::kCamIn && active_.in_sync)) {
    return Submission::reject(error_id::kNoActiveCamming);
  }
  const LeadingValue leader = sample(source);
  const ModuloRange range =
      interconnections_[static_cast<std::size_t>(source)].source->leading_value_modulo();
  const auto mode = static_cast<CamApplicationMode>(in.ApplicationMode);
  CamJob job;
  job.cam = in.Cam;
  job.master_sync = in.MasterSyncPosition;
  job.function.start(cam, CamScaling{in.MasterOffset, in.SlaveOffset, in.MasterScaling, in.SlaveScaling},
                     mode);
  job.shown_master_offset = in.MasterOffset;

  if (profile == 4 && mode == CamApplicationMode::kNotCyclic) {
    // The leader (any occurrence of a modulo leader) must lie in the scaled and shifted cam (16#80AD).
    double u = (leader.position - in.MasterOffset) / in.MasterScaling;
    if (range.enabled && range.length > 0.0) {
      const double period = range.length / std::fabs(in.MasterScaling);
      u = cam.start() + std::fmod(std::fmod(u - cam.start(), period) + period, period);
    }
    if (!(u >= cam.start() && u <= cam.end())) return Submission::reject(error_id::kOutsideCam);
  }

  if (profile == 2) {
    // Direct synchronous setting (spec 07 §3.4): synchronous at once at the present positions; the cam is
    // shifted in both ranges so that MasterSyncPosition falls on the leader and the cam value on the
    // follower.
    const double x = leader.position;
    CamScaling k = job.function.scaling();
    k.MasterOffset = x - cam.start() * k.MasterScaling - in.MasterSyncPosition;
    k.SlaveOffset = 0.0;
    job.function.start(cam, k, mode);
    k.SlaveOffset = axis_.setpoint().position - job.function.evaluate(x, 0.0, 0.0).position;
    job.function.start(cam, k, mode);
    job.shown_master_offset = shown_master_offset(k.MasterOffset, x, range);
    if (const auto e = axis_.arbitrate(NewJob::kSyncActive)) return Submission::reject(e);
    axis_.abort_pending();
    in.Cam->acquire();
    const JobId id = axis_.jobs().create(JobKind::kCamIn, JobState::kActive);
    active_ = ActiveSync{};
    active_.id = id;
    active_.kind = JobKind::kCamIn;
    active_.source = source;
    active_.phase = Phase::kSynchronous;
    active_.in_sync = true;
    active_.cam = job;
    axis_.set_position_controlled(true);  // spec 07 §1.7
    sync_setpoint_ = axis_.setpoint();
    axis_.take_over(id, JobKind::kCamIn);
    last_synchronous_job_ = id;
    return Submission::accept(id);
  }

  PendingSyncIn p;
  p.kind = JobKind::kCamIn;
  p.source = source;
  p.profile = profile;
  p.length = over_distance(profile) ? in.MasterStartDistance : 0.0;
  p.sync_direction = in.SyncDirection;
  p.limits = limits;
  p.direction = direction_of(leader.velocity) != 0.0 ? direction_of(leader.velocity) : 1.0;
  if (profile == 0 || profile == 1 || profile == 3) {
    // The synchronous point (profile 3: the start) in leader coordinates; a modulo leader takes the next
    // occurrence that leaves the distance ahead (decision Y3), a linear one must still be before it.
    const double ahead = profile == 1 ? in.MasterStartDistance : 0.0;
    const double nominal = cam_sync_point(job);
    p.master_sync = modulo_occurrence(nominal, range, leader.position, p.direction, ahead);
    if (!range.enabled && p.direction * (p.master_sync - p.direction * ahead - leader.position) < 0.0) {
      return Submission::reject(error_id::kInvalidMasterSyncPosition);
    }
    CamScaling k = job.function.scaling();
    k.MasterOffset += p.master_sync - nominal;
    job.function.start(cam, k, mode);
  }
  if (const auto e = axis_.arbitrate(NewJob::kSyncPending)) return Submission::reject(e);
  in.Cam->acquire();
  p.id = axis_.jobs().create(JobKind::kCamIn, JobState::kActive);
  p.cam = job;
  pending_sync_ = p;
  last_synchronous_job_ = p.id;
  return Submission::accept(p.id);
}

Submission SynchronousOperation::cam_out(const CamOutInputs& in) noexcept {
  return desynchronize(in, JobKind::kCamOut);
}

// A pending MC_CamIn starts (spec 07 §3.4 table, §6.4, §6.5): profiles 0, 1 before the synchronous point,
// 3 at it, 4 and 6 as soon as the leader moves; profile 5 waits for the end of the running cam (step_cam).
bool SynchronousOperation::start_pending_cam(const LeadingValue& leader) noexcept {
  PendingSyncIn& p = pending_sync_;
  CamJob& job = p.cam;
  if (p.profile == 5) return false;
  const ModuloRange range =
      interconnections_[static_cast<std::size_t>(p.source)].source->leading_value_modulo();
  const CamProfile& cam = job.cam->profile();
  CamScaling k = job.function.scaling();
  double x_a = 0.0;
  double x_sync = p.master_sync;
  if (p.profile == 4 || p.profile == 6) {
    const double dir = direction_of(leader.velocity);
    if (dir == 0.0) return false;  // pending while the leader stands (WaitingFunctionState 3)
    p.direction = dir;
    x_a = leader.position;
    x_sync = x_a + dir * p.length;
    if (p.profile == 6) {
      // The cam is shifted in the leader range so that MasterSyncPosition is reached after the distance.
      k.MasterOffset = x_sync - cam.start() * k.MasterScaling - job.master_sync;
      job.function.start(cam, k, job.function.mode());
      job.shown_master_offset = shown_master_offset(k.MasterOffset, x_sync, range);
    }
  } else {
    if (p.profile == 0) {
      // Sized onto the occurrence of the cam that SyncDirection will choose at the start (below).
      const MotionState end = cam_target(job, x_sync, 1.0, 0.0);
      const double estimate =
          axis_.setpoint().position + end.position - cam_target(job, leader.position, 0.0, 0.0).position;
      profile0_length(p, leader, choose_slave_sync(end.position, p.sync_direction, estimate), end.velocity);
      if (p.sized_length < 0.0) {  // cannot synchronize yet: alarm 501 shows it (spec 07 §6.8, decision C23)
        p.armed = false;
        return false;
      }
      p.length = p.sized_length;
    }
    x_a = p.profile == 3 ? p.master_sync : p.master_sync - p.direction * p.length;
    if (p.profile == 3) x_sync = p.master_sync + p.direction * p.length;
    if (p.profile == 0) {
      const double before = p.master_sync;
      if (!profile0_start_crossed(p, leader, x_a)) {
        if (p.master_sync != before) {  // waits for the next pass: the cam moves with its synchronous point
          k.MasterOffset += p.master_sync - before;
          job.function.start(cam, k, job.function.mode());
        }
        return false;
      }
    }
    if (p.direction * (leader.position - x_a) < 0.0) return false;  // not there yet
    if (!(p.direction * leader.velocity > 0.0)) return false;       // reached, but not moving towards it
  }
  // A non-cyclic cam must hold the synchronous point: profiles 3 and 4 reach it MasterStartDistance after
  // the start, which may lie beyond the cam's end; synchronous there, the job would end at once and the
  // follower jump to f(End). The job ends with 16#80AD when it would start instead (decision C21).
  if (job.function.mode() == CamApplicationMode::kNotCyclic) {
    const double u_sync = (x_sync - k.MasterOffset) / k.MasterScaling;
    const double slack = 1e-9 * std::max({1.0, std::fabs(cam.start()), std::fabs(cam.end())});
    if (!(u_sync >= cam.start() - slack && u_sync <= cam.end() + slack)) {
      end_pending(JobState::kError, error_id::kOutsideCam);
      return false;
    }
  }
  // A modulo follower reaches the occurrence of the cam that SyncDirection allows (spec 07 §3.4): the cam
  // is shifted by whole follower modulo lengths in the following range.
  const double y_end = cam_target(job, x_sync, 0.0, 0.0).position;
  const double estimate =
      axis_.setpoint().position + y_end - cam_target(job, leader.position, 0.0, 0.0).position;
  const double chosen = choose_slave_sync(y_end, p.sync_direction, estimate);
  if (chosen != y_end) {
    k = job.function.scaling();
    k.SlaveOffset += chosen - y_end;
    job.function.start(cam, k, job.function.mode());
  }
  const MotionState at_start = cam_target(job, x_a, 1.0, 0.0);    // Y, Y', Y'' at the start
  const MotionState at_sync = cam_target(job, x_sync, 1.0, 0.0);  // Y, Y' at the synchronous point
  const double signed_length = p.direction * p.length;
  const bool dynamic = p.profile == 0;
  if (!activate_pending(JobKind::kCamIn)) return false;
  active_.x_sync = x_sync;
  active_.line_blend = dynamic;
  // The blend starts at the nominal start position, so that it ends exactly at the synchronous point.
  // Profile 0 runs onto the cam's tangent at the synchronous point, the line its length was sized for:
  // within the job's dynamics at the present leader velocity, the cam's curvature taken up only when the
  // synchronous travel begins (spec 07 §6.8, decision C23). The others blend onto the cam itself (§6.4).
  if (dynamic) {
    active_.blend.start(x_a, signed_length, x_sync, at_sync.position, at_sync.velocity, axis_.setpoint(),
                        leader.velocity, leader.acceleration);
  } else {
    active_.blend.start_deviation(x_a, signed_length, at_start.position, at_start.velocity,
                                  at_start.acceleration, axis_.setpoint(), leader.velocity,
                                  leader.acceleration);
  }
  return true;
}

// One MC_Interpolator cycle of an active MC_CamIn: the blend onto the cam, then synchronous travel on it with
// EndOfProfile, the end of a non-cyclic cam and the switch to a waiting profile-5 job.
void SynchronousOperation::step_cam(const LeadingValue& leader) noexcept {
  ActiveSync& a = active_;
  CamJob& job = a.cam;
  if (a.phase != Phase::kSynchronous) {
    if (synchronization_reversed(a, leader.position, direction_of(leader.velocity) == -a.direction)) {
      axis_.raise(kAlarmSynchronizationError, 2);  // reversal during synchronization (spec 07 §3.4)
      return;
    }
    const MotionState y = cam_target(job, leader.position, leader.velocity, leader.acceleration);
    if (a.blend.progress(leader.position) >= 1.0 - 1e-12) {
      // Synchronous from this cycle on: the follower is on the cam (a line blend reached its tangent at the
      // synchronous point, up to one cycle ago).
      sync_setpoint_ = y;
      a.phase = Phase::kSynchronous;
      a.in_sync = true;
      return;
    }
    const MotionState d = a.blend.at(leader.position, leader.velocity, leader.acceleration);
    sync_setpoint_ = a.line_blend ? d
                                  : MotionState{y.position + d.position, y.velocity + d.velocity,
                                                y.acceleration + d.acceleration};
    return;
  }
  const CamFollowingValue f = job.function.evaluate(leader.position, leader.velocity, leader.acceleration);
  sync_setpoint_ = MotionState{f.position, f.velocity, f.acceleration};
  if (!f.end_of_profile) return;
  ++job.ends;
  if (pending_sync_.id != 0 && pending_sync_.kind == JobKind::kCamIn && pending_sync_.profile == 5) {
    // Profile 5 (spec 07 §3.4): the new cam takes over at the end just passed, from its MasterSyncPosition,
    // shifted in both ranges so that the following value goes on from the old cam's value there: the path
    // y(x) has no position step, and the new cam's phase is that of the end, not of the cycle that saw it
    // (decision C10). The old job ends (CommandAborted, R10).
    // `leader` is the function leading value; the new job starts without the old one's leading and following
    // value offsets (reset by the override, spec 07 §1.8): they are folded into its cam offsets instead.
    const double x = leader.position;
    const double phase = phase_shift_.value;
    const double offset = offset_.value;
    const CamProfile& old_cam = job.cam->profile();
    const CamScaling& old_k = job.function.scaling();
    const double u = (x - old_k.MasterOffset) / old_k.MasterScaling;
    const double period = old_cam.end() - old_cam.start();
    const double u_end = f.ended || !(period > 0.0)
                             ? (u > old_cam.end() ? old_cam.end() : old_cam.start())
                             : old_cam.start() + period * std::round((u - old_cam.start()) / period);
    const double x_end = old_k.MasterOffset + old_k.MasterScaling * u_end;
    CamSynchronousFunction old_function = job.function;  // a copy: the value at the end, not this cycle's
    const double y_end = old_function.evaluate(x_end, 0.0, 0.0).position + offset;
    const double x_end_source = x_end - phase;  // in the (effective) leading value of the new job
    CamJob next = pending_sync_.cam;
    const CamProfile& cam = next.cam->profile();
    CamScaling k = next.function.scaling();
    k.MasterOffset = x_end_source - cam.start() * k.MasterScaling - next.master_sync;
    k.SlaveOffset = 0.0;
    next.function.start(cam, k, next.function.mode());
    k.SlaveOffset = y_end - next.function.evaluate(x_end_source, 0.0, 0.0).position;
    next.function.start(cam, k, next.function.mode());
    next.shown_master_offset = shown_master_offset(
        k.MasterOffset, x_end_source,
        interconnections_[static_cast<std::size_t>(a.source)].source->leading_value_modulo());
    pending_sync_.cam = next;
    if (!activate_pending(JobKind::kCamIn)) return;
    active_.phase = Phase::kSynchronous;
    active_.in_sync = true;
    active_.start_sync = false;
    const CamFollowingValue g =
        active_.cam.function.evaluate(x - phase, leader.velocity, leader.acceleration);
    sync_setpoint_ = MotionState{g.position, g.velocity, g.acceleration};
    return;
  }
  if (f.ended) {
    // Not cyclic: the synchronous operation ends at the cam end, the follower holds it (spec 07 §6.2, O-10:
    // Busy and InSync FALSE, EndOfProfile TRUE).
    sync_setpoint_ = MotionState{f.position + offset_.value, 0.0, 0.0};
    if (simulation_ == 0) axis_.set_setpoint(sync_setpoint_);  // simulated, the axis is not following
    end_active(JobState::kDone, 0);
  }
}

// The slope dy/dx of the synchronous function in use (desynchronization over a distance, spec 07 §6.7).
double SynchronousOperation::function_slope(const LeadingValue& leader) const noexcept {
  if (active_.kind != JobKind::kCamIn) return ratio(active_.numerator, active_.denominator);
  return std::fabs(leader.velocity) > kStanding ? sync_setpoint_.velocity / leader.velocity : 0.0;
}

}  // namespace tomc::techobjects
