#pragma once
// The time-based position profile of MC_PositionProfile (spec 03 §4.7, seed 004 §6.8.4): x = time in s,
// y = position in the axis' position unit. The manual takes it from a TO_Cam; tomc takes it from a plain
// structure the user fills and keeps (like a PLC data block), so that the axis needs no cam TO and holds
// only a pointer to it (decision L1). Fixed capacity: nothing here allocates, and every loop is bounded by
// kMaxTimePositionPoints.
//
// Between the points the profile is a monotone piecewise cubic (Fritsch–Butland slopes): it never overshoots
// a point, its velocity is continuous and its acceleration finite. The first and the last point have
// velocity 0, so the axis starts from and stops at the profile's ends at rest ("when the end position of the
// profile is reached, the axis stops", seed 004 §9.7.1).

#include <array>
#include <cstddef>
#include <cstdint>

#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::techobjects {

inline constexpr std::size_t kMaxTimePositionPoints = 128;

struct TimePositionPoint {
  double Time = 0.0;      // s, strictly increasing from point to point
  double Position = 0.0;  // position unit of the axis (Units.LengthUnit)
};

// Point[0 .. NumberOfPoints-1] are used; at least 2.
struct TimePositionProfile {
  std::int32_t NumberOfPoints = 0;
  std::array<TimePositionPoint, kMaxTimePositionPoints> Point{};
};

// 0 if the profile can be followed from `start_time`; else the ErrorID of MC_PositionProfile: no profile or
// fewer than 2 / more than kMaxTimePositionPoints points (16#8160), times not strictly increasing (16#8161),
// a time or position not finite (16#8162), start_time not finite or outside [first, last) (16#8163).
std::uint16_t validate(const TimePositionProfile* profile, double start_time) noexcept;

// Position, velocity and acceleration of a valid profile at `time`, clamped to its first/last point (rest).
MotionState evaluate(const TimePositionProfile& profile, double time) noexcept;

// The time of the last point (the profile's end).
inline double end_time(const TimePositionProfile& profile) noexcept {
  return profile.Point[static_cast<std::size_t>(profile.NumberOfPoints) - 1].Time;
}

// The largest |velocity| and |acceleration| the profile asks for from `start_time` on (seed 004 §6.8.4
// "dynamic limits while following the profile"): exact for the cubic pieces (velocity extremum at the vertex,
// acceleration linear per piece).
struct ProfileDynamics {
  double velocity = 0.0;
  double acceleration = 0.0;
};
ProfileDynamics max_dynamics(const TimePositionProfile& profile, double start_time) noexcept;

}  // namespace tomc::techobjects
