#pragma once
// The one place where a synchronous axis plugs its synchronous operation (gearing today, camming next) into
// the positioning axis' job machinery and cycle (spec 07 §1.8, issue 14: a component, not a base class opened
// up). A positioning axis has no slot filled; a synchronous axis fills it once at construction. Every call
// comes from the positioning axis' own job or cycle code, in the order its comments state; all are noexcept
// and allocation-free (they run in MC_Interpolator).
#include <cstdint>

#include "tomc/techobjects/axis/job_priority.hpp"
#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::techobjects {

class SynchronousSlot {
 public:
  // The §9.19.2 row of a new job against the running synchronous jobs: 0 = proceed (the aborts it implies
  // applied), else the ErrorID that rejects the new job. Called after the §9.19.1 check passed.
  virtual std::uint16_t arbitrate(NewJob row) noexcept = 0;
  // Every synchronous job ends (alarm reaction, disable, MC_Stop, restart): error_id 0 = CommandAborted.
  virtual void abort(std::uint16_t error_id) noexcept = 0;
  // MC_Reset Restart = TRUE: every synchronous job ends, also a simulated synchronous operation (spec 07
  // §4.4), which the other aborts leave running.
  virtual void restart() noexcept = 0;
  // MC_Interpolator, before the setpoint is generated: pending jobs, synchronization, desynchronization.
  virtual void run() noexcept = 0;
  // The setpoint of this cycle while the synchronous operation drives the axis.
  virtual MotionState setpoint() const noexcept = 0;
  // The axis follows a leading value (a software limit then stops it with maximum dynamics, spec 02 §4.5).
  virtual bool following() const noexcept = 0;
  // MC_Interpolator, at the end of the status update: StatusSynchronizedMotion and the synchronous bits.
  virtual void update_status() noexcept = 0;

 protected:
  ~SynchronousSlot() = default;
};

}  // namespace tomc::techobjects
