// MC_MotionInVelocity and MC_MotionInPosition on the positioning axis (spec 03 §4.17, §3.3 L4, seed 004
// §9.17): the application's setpoints act directly — no profile, no DynamicLimits — from the MC_Interpolator
// after the call that wrote them; the falling edge of Enable ends the job with velocity and acceleration 0
// and the position kept. A setpoint step is executed as given; the following-error monitoring answers it
// with alarm 521 where it is active (spec 03 §5).
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::techobjects {

Submission PositioningAxis::motion_in_velocity(JobId running, const MotionInVelocityInputs& in) noexcept {
  // [S6] PositionControlled FALSE forces non-position-controlled operation, TRUE position control.
  return motion_in(JobKind::kMotionInVelocity, running,
                   MotionState{0.0, in.Velocity / units_.velocity, in.Acceleration / units_.acceleration},
                   in.PositionControlled);
}

Submission PositioningAxis::motion_in_position(JobId running, const MotionInPositionInputs& in) noexcept {
  // [S6] MotionInPosition always forces position control.
  return motion_in(
      JobKind::kMotionInPosition, running,
      MotionState{in.Position, in.Velocity / units_.velocity, in.Acceleration / units_.acceleration}, true);
}

Submission PositioningAxis::motion_in(JobKind kind, JobId running, const MotionState& setpoint,
                                      bool position_controlled) noexcept {
  const bool valid = std::isfinite(setpoint.position) && std::isfinite(setpoint.velocity) &&
                     std::isfinite(setpoint.acceleration);
  if (running != 0) {
    // While Enable = TRUE the inputs are taken every cycle (spec 03 §3.3 L4); a job that another one ended
    // takes nothing (the instruction reads its CommandAborted / Error).
    if (running != motion_.id || motion_.kind != kind) return Submission{};
    if (!valid) {
      // A setpoint that is not a number ends the job with Error; the axis brakes with the default
      // dynamics instead of moving to it.
      core_.jobs.set(motion_.id, JobState::kError, error_id::kInvalidMotionInSetpoint);
      const ProfileLimits stop = motion_.limits;
      motion_ = Motion{};
      plan_velocity(0.0, stop, false);
      return Submission::reject(error_id::kInvalidMotionInSetpoint);
    }
    motion_.target = setpoint.position;
    motion_.command_velocity = setpoint.velocity;
    motion_.distance = setpoint.acceleration;
    return Submission::accept(running);
  }
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!valid) return Submission::reject(error_id::kInvalidMotionInSetpoint);
  if (const auto e = motion_prerequisites()) return Submission::reject(e);
  bool queue = false;
  if (const auto e = arbitrate_motion(NewJob::kBaseMotion, queue))
    return Submission::reject(e);  // §9.19.1 R4
  abort_pending(0);
  Motion m;
  m.id = core_.jobs.create(kind, JobState::kActive);
  m.kind = kind;
  // No dynamics of its own: an alarm's stop reaction or a software-limit stop brakes with the defaults.
  m.limits = AxisCore::default_ramp(db_.DynamicDefaults, dynamic_units());
  m.position_controlled = position_controlled;
  m.target = setpoint.position;
  m.command_velocity = setpoint.velocity;
  m.distance = setpoint.acceleration;
  motion_ = m;
  db_.StatusMotionIn.StatusWord = 0;  // MaxVelocityExceeded counts per MotionIn job
  position_controlled_ = position_controlled;
  positioning_.cancel();
  positioning_start_pending_ = false;
  generator_ = Generator::kMotionIn;
  return Submission::accept(m.id);
}

void PositioningAxis::end_motion_in(JobId running) noexcept {
  if (running == 0) return;
  if (running == superimposed_.job_id() && superimposed_.motion_in()) {
    // MotionInSuperimposed(Axes): the superimposed velocity and acceleration drop to 0.0, its position stays
    // (spec 03 §4.17.3/4.17.4 Enable); the base motion goes on unchanged.
    core_.jobs.set(running, JobState::kDone);
    const MotionState& s = superimposed_.state();
    setpoint_.velocity -= s.velocity;  // base_setpoint() = setpoint_ - superimposed stays the base
    setpoint_.acceleration -= s.acceleration;
    superimposed_.end_motion_in();
    db_.StatusMotionIn.ActualSuperimposingAxis = 0;
    return;
  }
  if (running != motion_.id) return;
  if (motion_.kind != JobKind::kMotionInVelocity && motion_.kind != JobKind::kMotionInPosition) return;
  core_.jobs.set(motion_.id, JobState::kDone);
  motion_ = Motion{};
  // spec 03 §3.1 class M: velocity and acceleration drop to 0.0, the position setpoint keeps its value
  // (those of the base motion: a superimposed motion goes on, §9.19.1 R6 x C8 "-").
  const MotionState base = base_setpoint();
  setpoint_.velocity -= base.velocity;
  setpoint_.acceleration -= base.acceleration;
  generator_ = Generator::kIdle;
  if (position_controlled_) {  // StatusWord.X6 Done after the positioning window (spec 04 §8 rule 2)
    positioning_target_ = positioning_reference();
    positioning_start_pending_ = true;
  }
}

// The setpoints of the last call, as given (spec 03 §4.17: no profile, the TO's dynamic limits do not apply).
// MotionInPosition on a modulo axis: the position within the range, reached by the shortest way from the
// present setpoint, so that the continuous setpoint makes no jump of a modulo length.
// Out of line even under link-time optimisation (decision P28): a path the steady cycle does not take, kept
// out of the frame of the function that calls it every cycle, whose stack lines the cycle touches.
[[gnu::noinline]] void PositioningAxis::follow_motion_in() noexcept {
  const double dt = core_.ipo_cycle_s;
  switch (motion_.kind) {
    case JobKind::kMotionInPosition: {
      double position = motion_.target;
      if (modulo()) {
        const double start = db_.Modulo.StartValue;
        const double length = db_.Modulo.Length;
        position = setpoint_.position +
                   modulo_shortest_distance(modulo_wrap(setpoint_.position, start, length).position,
                                            modulo_wrap(position, start, length).position, start, length);
      }
      setpoint_ = MotionState{position, motion_.command_velocity, motion_.distance};
      break;
    }
    case JobKind::kMotionInVelocity:
      setpoint_ = MotionState{setpoint_.position + motion_.command_velocity * dt, motion_.command_velocity,
                              motion_.distance};
      break;
    default:  // the job ended without a new generator: hold the velocity (as Generator::kIdle)
      generator_ = Generator::kIdle;
      setpoint_.position += setpoint_.velocity * dt;
      setpoint_.acceleration = 0.0;
      break;
  }
}

}  // namespace tomc::techobjects
