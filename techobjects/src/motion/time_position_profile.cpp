// The time-position profile of MC_PositionProfile: validation and evaluation (monotone piecewise cubic).
#include "tomc/techobjects/motion/time_position_profile.hpp"

#include <algorithm>
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"

namespace tomc::techobjects {

namespace {

const TimePositionPoint& point(const TimePositionProfile& p, std::size_t i) noexcept {
  return p.Point[i];
}

double slope(const TimePositionProfile& p, std::size_t i) noexcept {  // δ of the piece [i, i+1]
  return (point(p, i + 1).Position - point(p, i).Position) / (point(p, i + 1).Time - point(p, i).Time);
}

// The velocity at point i: 0 at both ends; inside, the weighted harmonic mean of the neighbouring slopes
// (Fritsch–Butland), 0 at a local extremum, so that the cubic never overshoots a point.
double point_velocity(const TimePositionProfile& p, std::size_t i) noexcept {
  const auto n = static_cast<std::size_t>(p.NumberOfPoints);
  if (i == 0 || i + 1 >= n) return 0.0;
  const double d0 = slope(p, i - 1);
  const double d1 = slope(p, i);
  if (d0 * d1 <= 0.0) return 0.0;
  const double h0 = point(p, i).Time - point(p, i - 1).Time;
  const double h1 = point(p, i + 1).Time - point(p, i).Time;
  const double w1 = 2.0 * h1 + h0;
  const double w2 = h1 + 2.0 * h0;
  return (w1 + w2) / (w1 / d0 + w2 / d1);
}

// The piece [i, i+1] that holds t (t within the profile): binary search, at most log2(128) = 7 steps.
std::size_t piece(const TimePositionProfile& p, double t) noexcept {
  std::size_t lo = 0;
  std::size_t hi = static_cast<std::size_t>(p.NumberOfPoints) - 1;  // Time[lo] <= t < Time[hi]
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    if (point(p, mid).Time <= t) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return lo;
}

// A cubic Hermite piece: position p0→p1 with velocities m0, m1 over h seconds.
struct Piece {
  double p0, p1, m0, m1, h;
  Piece(const TimePositionProfile& p, std::size_t i) noexcept
      : p0(point(p, i).Position),
        p1(point(p, i + 1).Position),
        m0(point_velocity(p, i)),
        m1(point_velocity(p, i + 1)),
        h(point(p, i + 1).Time - point(p, i).Time) {}
  MotionState at(double s) const noexcept {  // s in [0, 1]
    const double s2 = s * s;
    const double s3 = s2 * s;
    MotionState m;
    m.position = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 +
                 (s3 - s2) * h * m1;
    m.velocity = ((6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * h * m0 + (-6 * s2 + 6 * s) * p1 +
                  (3 * s2 - 2 * s) * h * m1) /
                 h;
    m.acceleration =
        ((12 * s - 6) * p0 + (6 * s - 4) * h * m0 + (-12 * s + 6) * p1 + (6 * s - 2) * h * m1) / (h * h);
    return m;
  }
  // The s in (0, 1) where the velocity has its extremum, or -1.
  double velocity_vertex() const noexcept {
    const double a = 6 * p0 + 3 * h * m0 - 6 * p1 + 3 * h * m1;
    const double b = -6 * p0 - 4 * h * m0 + 6 * p1 - 2 * h * m1;
    if (a == 0.0) return -1.0;
    const double s = -b / (2 * a);
    return s > 0.0 && s < 1.0 ? s : -1.0;
  }
};

}  // namespace

std::uint16_t validate(const TimePositionProfile* profile, double start_time) noexcept {
  if (profile == nullptr || profile->NumberOfPoints < 2 ||
      profile->NumberOfPoints > static_cast<std::int32_t>(kMaxTimePositionPoints)) {
    return error_id::kInvalidTimePositionProfile;
  }
  const auto n = static_cast<std::size_t>(profile->NumberOfPoints);
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(point(*profile, i).Time) || !std::isfinite(point(*profile, i).Position))
      return error_id::kTimePositionNotFinite;
    if (i > 0 && !(point(*profile, i).Time > point(*profile, i - 1).Time))
      return error_id::kTimePositionOutOfOrder;
  }
  if (!std::isfinite(start_time) || start_time < point(*profile, 0).Time || start_time >= end_time(*profile))
    return error_id::kInvalidStartTime;
  return 0;
}

MotionState evaluate(const TimePositionProfile& profile, double time) noexcept {
  const auto n = static_cast<std::size_t>(profile.NumberOfPoints);
  if (time <= point(profile, 0).Time) return MotionState{point(profile, 0).Position, 0.0, 0.0};
  if (time >= end_time(profile)) return MotionState{point(profile, n - 1).Position, 0.0, 0.0};
  const std::size_t i = piece(profile, time);
  const Piece c(profile, i);
  return c.at((time - point(profile, i).Time) / c.h);
}

ProfileDynamics max_dynamics(const TimePositionProfile& profile, double start_time) noexcept {
  ProfileDynamics d;
  const auto n = static_cast<std::size_t>(profile.NumberOfPoints);
  const std::size_t first = piece(profile, std::clamp(start_time, point(profile, 0).Time, end_time(profile)));
  for (std::size_t i = first; i + 1 < n; ++i) {
    const Piece c(profile, i);
    const double s0 = i == first ? std::clamp((start_time - point(profile, i).Time) / c.h, 0.0, 1.0) : 0.0;
    const double vertex = c.velocity_vertex();
    for (const double s : {s0, 1.0, vertex >= s0 ? vertex : s0}) {
      const MotionState m = c.at(s);
      d.velocity = std::max(d.velocity, std::fabs(m.velocity));
      d.acceleration = std::max(d.acceleration, std::fabs(m.acceleration));
    }
  }
  return d;
}

}  // namespace tomc::techobjects
