// MC_MotionInVelocity on the speed axis (spec 03 §4.17.1, §3.3 L4, seed 004 §6.14.1): the application's
// velocity (and acceleration) acts directly — no profile, no DynamicLimits — from the MC_Interpolator after
// the call that wrote it; the falling edge of Enable makes velocity and acceleration 0 (the drive brakes as
// its own limits allow). As on the positioning axis (motion_in.cpp, decision L5/L6).
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"

namespace tomc::techobjects {

Submission SpeedAxis::motion_in_velocity(JobId running, const MotionInVelocityInputs& in) noexcept {
  const double velocity = in.Velocity / velocity_unit_per_revolution_per_second();
  const double acceleration = in.Acceleration / units().acceleration;
  const bool valid = std::isfinite(velocity) && std::isfinite(acceleration);
  if (running != 0) {
    // While Enable = TRUE the inputs are taken every cycle; a job another one ended takes nothing.
    if (running != motion_.id || motion_.kind != JobKind::kMotionInVelocity) return Submission{};
    if (!valid) {
      // Error; the axis brakes with DynamicDefaults instead of taking the value (decision L6).
      core_.jobs.set(motion_.id, JobState::kError, error_id::kInvalidMotionInSetpoint);
      const ProfileLimits stop = motion_.limits;
      motion_ = Motion{};
      plan_velocity(0.0, stop, false);
      return Submission::reject(error_id::kInvalidMotionInSetpoint);
    }
    motion_.command_velocity = velocity;
    motion_.planned_target = acceleration;
    return Submission::accept(running);
  }
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!valid) return Submission::reject(error_id::kInvalidMotionInSetpoint);
  if (const auto e = core_.motion_prerequisites()) return Submission::reject(e);
  if (const auto e = arbitrate_motion(NewJob::kBaseMotion)) return Submission::reject(e);  // §9.19.1 R4
  // No dynamics of its own: an alarm's stop reaction brakes with the defaults.
  motion_ =
      Motion{core_.jobs.create(JobKind::kMotionInVelocity, JobState::kActive), JobKind::kMotionInVelocity,
             AxisCore::default_ramp(db_.DynamicDefaults, units()), velocity, acceleration};
  generator_active_ = false;  // a replaced job's profile ends here
  return Submission::accept(motion_.id);
}

void SpeedAxis::end_motion_in(JobId running) noexcept {
  if (running == 0 || running != motion_.id || motion_.kind != JobKind::kMotionInVelocity) return;
  core_.jobs.set(motion_.id, JobState::kDone);
  motion_ = Motion{};
  setpoint_.velocity = 0.0;  // spec 03 §3.1 class M: the setpoints become 0.0
  setpoint_.acceleration = 0.0;
}

}  // namespace tomc::techobjects
