#include "tomc/techobjects/synchronous/synchronous_motion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tomc::techobjects {

namespace {

// The jerk for a synchronization step from (v0, a0): raised to what keeps |v| within v_limit, outward
// (a0·v0 >= 0: |v0| + a0²/(2j)) and after a zero crossing (a0·v0 < 0: a0²/(2j) − |v0| on the other side);
// 0 (no jerk limitation) when |v0| is at or beyond the limit already; R1 for a step to standstill.
double synchronization_jerk(double v0, double a0, double jerk, double v_limit, bool to_standstill) noexcept {
  if (!(jerk > 0.0) || a0 == 0.0) return jerk;
  if (a0 * v0 < 0.0 && to_standstill) return replanning_jerk(v0, a0, jerk, true);
  const double inf = std::numeric_limits<double>::infinity();
  double needed = 0.0;
  if (a0 * v0 >= 0.0) {
    const double margin = v_limit - std::fabs(v0);
    needed = margin > 0.0 ? a0 * a0 / (2.0 * margin) : inf;
  } else {
    needed = a0 * a0 / (2.0 * (v_limit + std::fabs(v0)));
  }
  if (needed <= jerk) return jerk;
  return std::isfinite(needed) ? needed : 0.0;
}

}  // namespace

SynchronizationStep synchronization_step(const MotionState& f, double vT, double aT, const ProfileLimits& l,
                                         double T) noexcept {
  SynchronizationStep s;
  const double eps_v = 1e-9 * std::max(1.0, std::fabs(vT));
  const double dv = vT - f.velocity;
  if (std::fabs(dv) <= eps_v) {
    s.state = MotionState{f.position + (f.velocity + vT) * 0.5 * T, vT, aT};
    s.locked = true;
    return s;
  }
  // A start acceleration that pushes |v| outward makes |v| overshoot by a0²/(2j) before the jerk can turn it
  // (a follower leaving synchronous travel keeps the leader's acceleration, spec 07 §2.1 "the current
  // dynamics are blended into the new job"). Unlike a replacing job of the axis (decision S4, which keeps the
  // job's jerk), a synchronization has its speed limited (spec 07 §2.1, §6.8): the jerk is raised so that the
  // overshoot stays within the velocity limit (MC_GearIn: MaxVelocity), or dropped (trapezoid) when |v| is
  // beyond it already; a step to standstill does not reverse (R1).
  const double v_limit = l.velocity > 0.0 ? l.velocity : std::numeric_limits<double>::infinity();
  const double jerk = synchronization_jerk(f.velocity, f.acceleration, l.jerk, v_limit, vT == 0.0);
  if (jerk > 0.0) {
    // Jerk-limited: the time-optimal velocity profile to vT from the present state, one cycle of it (the
    // profile brings the acceleration to 0 exactly at vT, never exceeding the jerk).
    VelocityProfile p;
    ProfileLimits pl = l;
    pl.velocity = 0.0;  // no clamp: the caller limited vT already
    pl.jerk = jerk;
    if (p.plan(f, vT, pl)) {
      if (p.duration() <= T + 1e-12) {
        s.state = MotionState{p.at(p.duration()).position + vT * (T - p.duration()), vT, aT};
        s.locked = std::fabs(aT) <= 1e-6 * std::max(1.0, std::fabs(vT));
        if (!s.locked) s.state.acceleration = 0.0;
        return s;
      }
      s.state = p.at(T);
      return s;
    }
  }
  // |v| grows when the step goes away from zero (acceleration limit), shrinks otherwise (deceleration).
  const bool grows = f.velocity == 0.0 ? true : (dv > 0.0) == (f.velocity > 0.0);
  const double lim = grows ? l.acceleration : l.deceleration;
  double a = std::clamp(dv / T, -lim, lim);
  double v = f.velocity + a * T;
  // Do not pass the target: the last step lands on it.
  if ((dv > 0.0 && v > vT) || (dv < 0.0 && v < vT)) {
    v = vT;
    a = (v - f.velocity) / T;
  }
  // A step that brakes through standstill: the deceleration limit holds only until v = 0, from there |v|
  // grows again and the acceleration limit holds (spec 07 §6.3; with MaxDeceleration > MaxAcceleration one
  // ramp at the deceleration through zero would accelerate the follower beyond MaxAcceleration).
  if (!grows && v != 0.0 && (v > 0.0) != (f.velocity > 0.0) && l.deceleration > 0.0 && l.acceleration > 0.0) {
    const double t0 = std::fabs(f.velocity) / l.deceleration;  // to standstill, within this step
    const double direction = dv > 0.0 ? 1.0 : -1.0;
    double t1 = T - t0;  // accelerating in the new direction
    double v_end = direction * l.acceleration * t1;
    if (std::fabs(v_end) >= std::fabs(vT) && (vT > 0.0) == (direction > 0.0)) {
      v_end = vT;  // reached within the step: at vT for the rest of it
      t1 = std::fabs(vT) / l.acceleration;
    }
    s.state = MotionState{f.position + 0.5 * f.velocity * t0 + 0.5 * v_end * t1 + v_end * (T - t0 - t1),
                          v_end, direction * l.acceleration};
    s.locked = std::fabs(v_end - vT) <= eps_v;
    if (s.locked) s.state.acceleration = aT;
    return s;
  }
  s.state = MotionState{f.position + (f.velocity + v) * 0.5 * T, v, a};
  s.locked = std::fabs(v - vT) <= eps_v;
  if (s.locked) s.state.acceleration = aT;
  return s;
}

namespace {

struct Basis {
  double h0, h1, h2;     // H0, H1, H2
  double d0, d1, d2;     // first derivatives in ξ
  double dd0, dd1, dd2;  // second derivatives in ξ
};

Basis basis(double x) noexcept {
  const double x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
  Basis b{};
  b.h0 = 1.0 - 10.0 * x3 + 15.0 * x4 - 6.0 * x5;
  b.h1 = x - 6.0 * x3 + 8.0 * x4 - 3.0 * x5;
  b.h2 = 0.5 * x2 - 1.5 * x3 + 1.5 * x4 - 0.5 * x5;
  b.d0 = -30.0 * x2 + 60.0 * x3 - 30.0 * x4;
  b.d1 = 1.0 - 18.0 * x2 + 32.0 * x3 - 15.0 * x4;
  b.d2 = x - 4.5 * x2 + 6.0 * x3 - 2.5 * x4;
  b.dd0 = -60.0 * x + 180.0 * x2 - 120.0 * x3;
  b.dd1 = -36.0 * x + 96.0 * x2 - 60.0 * x3;
  b.dd2 = 1.0 - 9.0 * x + 18.0 * x2 - 10.0 * x3;
  return b;
}

}  // namespace

void LeaderDomainBlend::start(double x_a, double length, double x_target, double y_target, double slope,
                              const MotionState& f, double v_a, double a_a) noexcept {
  x_a_ = x_a;
  length_ = length != 0.0 ? length : 1.0;
  x_target_ = x_target;
  y_target_ = y_target;
  slope_ = slope;
  deviate(f, v_a, a_a, line(x_a), slope, 0.0);
}

void LeaderDomainBlend::start_deviation(double x_a, double length, double target, double target_slope,
                                        double target_curvature, const MotionState& f, double v_a,
                                        double a_a) noexcept {
  x_a_ = x_a;
  length_ = length != 0.0 ? length : 1.0;
  x_target_ = 0.0;
  y_target_ = 0.0;
  slope_ = 0.0;
  deviate(f, v_a, a_a, target, target_slope, target_curvature);
}

void LeaderDomainBlend::deviate(const MotionState& f, double v_a, double a_a, double y, double dy,
                                double ddy) noexcept {
  // Follower slope and curvature in the leader domain (spec 07 §6.4); a leader at rest gives 0 (a dynamic
  // step is then possible, as the manual warns).
  double s0 = 0.0;
  double c0 = 0.0;
  if (std::fabs(v_a) > 1e-12) {
    s0 = f.velocity / v_a;
    c0 = (f.acceleration - s0 * a_a) / (v_a * v_a);
  }
  d0_ = f.position - y;
  d1_ = s0 - dy;
  d2_ = c0 - ddy;
}

double LeaderDomainBlend::progress(double x) const noexcept {
  return std::clamp((x - x_a_) / length_, 0.0, 1.0);
}

MotionState LeaderDomainBlend::at(double x, double v_x, double a_x) const noexcept {
  const double xi = progress(x);
  const Basis b = basis(xi);
  const double L = length_;
  const double y = line(x) + d0_ * b.h0 + L * d1_ * b.h1 + L * L * d2_ * b.h2;
  const double dy = slope_ + d0_ * b.d0 / L + d1_ * b.d1 + L * d2_ * b.d2;
  const double ddy = d0_ * b.dd0 / (L * L) + d1_ * b.dd1 / L + d2_ * b.dd2;
  return MotionState{y, dy * v_x, ddy * v_x * v_x + dy * a_x};
}

std::size_t LeaderDomainBlend::extrema(std::array<double, 3>& x) const noexcept {
  // d³y/dx³ as c0 + c1·ξ + c2·ξ² (the ξ-derivatives of dd0, dd1, dd2 above, scaled by L).
  const double L = length_;
  const double k0 = d0_ / (L * L * L), k1 = d1_ / (L * L), k2 = d2_ / L;
  const double c0 = -60.0 * k0 - 36.0 * k1 - 9.0 * k2;
  const double c1 = 360.0 * k0 + 192.0 * k1 + 36.0 * k2;
  const double c2 = -360.0 * k0 - 180.0 * k1 - 30.0 * k2;
  std::size_t n = 0;
  const auto add = [&](double xi) noexcept {
    if (xi > 0.0 && xi < 1.0 && std::isfinite(xi)) x[n++] = x_a_ + xi * L;
  };
  if (c2 != 0.0) {
    add(-c1 / (2.0 * c2));  // the jerk's extremum
    const double disc = c1 * c1 - 4.0 * c0 * c2;
    if (disc >= 0.0) {
      const double r = std::sqrt(disc);
      add((-c1 + r) / (2.0 * c2));
      add((-c1 - r) / (2.0 * c2));
    }
  } else if (c1 != 0.0) {
    add(-c0 / c1);
  }
  return n;
}

double LeaderDomainBlend::jerk(double x, double v_x) const noexcept {
  const double xi = progress(x);
  if (xi >= 1.0) return 0.0;
  const double L = length_;
  const double ddd0 = -60.0 + 360.0 * xi - 360.0 * xi * xi;
  const double ddd1 = -36.0 + 192.0 * xi - 180.0 * xi * xi;
  const double ddd2 = -9.0 + 36.0 * xi - 30.0 * xi * xi;
  const double dddy = d0_ * ddd0 / (L * L * L) + d1_ * ddd1 / (L * L) + d2_ * ddd2 / L;
  return dddy * v_x * v_x * v_x;
}

}  // namespace tomc::techobjects
