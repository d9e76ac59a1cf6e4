#pragma once
// MC_MoveJog on every axis type (spec 03 §3.4 rules J1–J5, §4 9.9): what the two level inputs of one call
// mean — start a jog job, run it at the live velocity, brake when released, or stop with 16#8007 when both
// are set. The axis supplies what differs: how a jog job starts (its dynamics, prerequisites, §9.19.1
// arbitration, position control) and how it brakes.
#include <cmath>

#include "tomc/techobjects/axis/axis_core.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/axis/job_inputs.hpp"

namespace tomc::techobjects {

// `motion` is the axis' running base motion (id, kind, limits, command_velocity, jog_stopping); `running` the
// instruction's job (0 before its first accepted call). `start()` creates the jog job in `motion` and returns
// 0 or the ErrorID that rejects it; `brake(limits)` plans the ramp to standstill. `velocity_unit` converts
// MC_MoveJog.Velocity into the axis' internal velocity.
template <typename Motion, typename Start, typename Brake>
Submission evaluate_jog(AxisCore& core, Motion& motion, JobId running, const JogInputs& in,
                        double velocity_unit, Start&& start, Brake&& brake) noexcept {
  const bool both = in.JogForward && in.JogBackward;
  const bool any = in.JogForward || in.JogBackward;
  const bool mine = running != 0 && running == motion.id && motion.kind == AxisJobKind::kJog;
  if (!mine) {
    if (!any) return Submission{};  // nothing to do, no job
    if (const auto e = core.control.program_job_rejection()) return Submission::reject(e);
    if (both) return Submission::reject(error_id::kJogWrongDirection);
    if (!std::isfinite(in.Velocity)) return Submission::reject(error_id::kInvalidVelocity);
    if (const std::uint16_t e = start()) return Submission::reject(e);
    running = motion.id;
  }
  if (both) {
    // J4: decelerate with the last valid deceleration; the job ends with 16#8007 (the ramp goes on).
    const ProfileLimits limits = motion.limits;
    core.jobs.set(motion.id, JobState::kError, error_id::kJogWrongDirection);
    motion = Motion{};
    brake(limits);
    return Submission::reject(error_id::kJogWrongDirection);
  }
  // J1/J3/J5: the velocity is live; a released input brakes; a new press during the ramp accelerates again.
  const double magnitude = std::fabs(in.Velocity) / velocity_unit;  // [AMB-3]: the magnitude
  motion.jog_stopping = !any;
  motion.command_velocity = any ? (in.JogForward ? magnitude : -magnitude) : 0.0;
  return Submission::accept(running);
}

}  // namespace tomc::techobjects
