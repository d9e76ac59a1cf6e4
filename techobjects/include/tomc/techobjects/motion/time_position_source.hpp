#pragma once
// MC_PositionProfile.TimePosition (spec 03 §4.7, seed 004 §6.8.4): the profile the axis follows, x = time in
// s, y = position in the axis' position unit. As the manual has it, an interpolated TO_Cam — its points and
// segments, read through the cam's profile — or tomc's plain point structure (decision L1). Only a pointer is
// kept: the cam or the structure must outlive the job. Nothing here allocates; a cam lookup is the cam's own
// bounded search.

#include <cstddef>
#include <cstdint>

#include "tomc/techobjects/motion/time_position_profile.hpp"

namespace tomc::techobjects {

class Cam;  // cam/cam.hpp (included by the .cpp: the cam includes the axis headers that include this one)

class TimePositionSource {
 public:
  constexpr TimePositionSource() noexcept = default;
  // Implicit on purpose: `fb.TimePosition = &cam;` and `fb.TimePosition = &points;` as in the manual.
  constexpr TimePositionSource(const TimePositionProfile* points) noexcept : points_(points) {}  // NOLINT
  constexpr TimePositionSource(const Cam* cam) noexcept : cam_(cam) {}                           // NOLINT
  constexpr TimePositionSource(std::nullptr_t) noexcept {}  // NOLINT: no profile

  const Cam* cam() const noexcept { return cam_; }
  const TimePositionProfile* points() const noexcept { return points_; }

  // 0 if the profile can be followed from `start_time`, else MC_PositionProfile's ErrorID: no profile or a
  // point structure validate() refuses; a cam not interpolated (16#8150); start_time not finite or outside
  // [the cam's first time, its last time) (16#8183); a cam whose velocity at its last time is not 0
  // (16#8187).
  std::uint16_t validate(double start_time) const noexcept;
  // Checked every cycle while the job follows the profile (the user may change either): 0 or the ErrorID.
  std::uint16_t still_valid() const noexcept;
  // Position, velocity and acceleration at `time`, clamped to the first/last time.
  MotionState evaluate(double time) const noexcept;
  double end_time() const noexcept;
  // The largest |velocity| and |acceleration| from start_time on: exact for the point structure; a cam's
  // polynomials have no closed-form maximum, so they are checked while the axis follows them (decision L8)
  // and this gives 0.
  ProfileDynamics max_dynamics(double start_time) const noexcept;

 private:
  const TimePositionProfile* points_ = nullptr;
  const Cam* cam_ = nullptr;
};

}  // namespace tomc::techobjects
