#pragma once
// The synchronous function of camming (spec 07 §3.3, §6.2): from the function leading value (position,
// velocity, acceleration; unwrapped) to the function following value through a cam with the job's scaling
// and shifting and its application mode — the part of MC_CamIn that does not depend on how the synchronous
// axis is built (synchronizing, desynchronizing and the job handling are not here).
//
//   u = (x − MasterOffset) / MasterScaling
//   not cyclic (0):        u must lie in [Start, End]; leaving it ends the synchronous operation, the
//                          following value holds f(End) (f(Start) backwards) [IMPL, spec 07 §6.2]
//   cyclic (1):            n = floor((u − Start)/P), P = End − Start, u' = u − n·P
//   cyclic appending (2):  as cyclic, plus n·(f(End) − f(Start))
//   y = SlaveScaling·f(u') + SlaveOffset,  ẏ = SlaveScaling·f'(u')·v/MasterScaling,
//   ÿ = SlaveScaling·(f''(u')·v²/MasterScaling² + f'(u')·a/MasterScaling)
//
// noexcept, no allocation; switching to another cam is a pointer assignment (use() with acquire/release of
// the cam's StatusWord.X0 is the caller's business).

#include <cstddef>
#include <cstdint>

#include "tomc/techobjects/cam/cam_profile.hpp"

namespace tomc::techobjects {

// MC_CamIn.ApplicationMode (spec 07 §3.3).
enum class CamApplicationMode : std::int32_t { kNotCyclic = 0, kCyclic = 1, kCyclicAppending = 2 };

struct CamFollowingValue {
  double position = 0.0;        // FunctionFollowingValue.Position
  double velocity = 0.0;        // .Velocity
  double acceleration = 0.0;    // .Acceleration
  std::int64_t period = 0;      // n: the cam cycle the leading value is in (0 for the first)
  bool end_of_profile = false;  // a cam end was crossed in this evaluation (MC_CamIn.EndOfProfile)
  bool ended = false;           // not cyclic: the leading value left the cam (synchronous operation ends)
};

class CamSynchronousFunction {
 public:
  // Starts a camming with `cam` (interpolated, not empty): the first evaluate() reports no end of profile.
  void start(const CamProfile& cam, const CamScaling& scaling, CamApplicationMode mode) noexcept;
  bool active() const noexcept { return cam_ != nullptr; }
  void stop() noexcept { cam_ = nullptr; }
  const CamScaling& scaling() const noexcept { return scaling_; }
  CamApplicationMode mode() const noexcept { return mode_; }

  // The following value at function leading value x (velocity v, acceleration a); zero when not active.
  CamFollowingValue evaluate(double x, double v, double a) noexcept;

 private:
  const CamProfile* cam_ = nullptr;
  CamScaling scaling_{};
  double period_gain_ = 0.0;  // f(End) − f(Start): what cyclic appending adds per period
  std::int64_t last_period_ = 0;
  std::size_t piece_ = 0;  // the piece of the last evaluation (CamProfile::find's hint)
  CamApplicationMode mode_ = CamApplicationMode::kNotCyclic;  // next to first_: no padding (decision M6)
  bool first_ = true;
};

}  // namespace tomc::techobjects
