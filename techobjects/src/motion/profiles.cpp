// Profile planners (spec 01 §8.7–§8.9); the semantics and their limits are documented in profiles.hpp.
#include "tomc/techobjects/motion/profiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tomc::techobjects {

namespace {

bool finite(double x) noexcept {
  return std::isfinite(x);
}

// Limits as the planners use them: validated, jerk 0 meaning "no jerk limitation".
struct Dynamics {
  double acceleration;
  double deceleration;
  double jerk;
};

bool make_dynamics(const ProfileLimits& limits, Dynamics& out) noexcept {
  if (!finite(limits.acceleration) || limits.acceleration <= 0) return false;
  if (!finite(limits.deceleration) || limits.deceleration <= 0) return false;
  if (std::isnan(limits.jerk) || limits.jerk < 0) return false;
  if (std::isnan(limits.velocity)) return false;
  // jerk = +inf is the limit of ever shorter rounding times (§8.2): the trapezoid.
  out = Dynamics{limits.acceleration, limits.deceleration, std::isinf(limits.jerk) ? 0.0 : limits.jerk};
  return true;
}

}  // namespace

// Appends segments while integrating the state in closed form; with no target profile it only integrates
// (the root search of the PositionProfile evaluates hundreds of candidate profiles this way).
class ProfileBuilder {
 public:
  ProfileBuilder(PiecewiseJerkProfile* out, const MotionState& start) noexcept
      : out_(out), p_(start.position), v_(start.velocity), a_(start.acceleration) {
    if (out_ != nullptr) out_->count_ = 0;
  }

  double time() const noexcept { return t_; }
  double position() const noexcept { return p_; }
  double velocity() const noexcept { return v_; }
  double acceleration() const noexcept { return a_; }

  // Constant jerk from the current (continuous) acceleration.
  void ramp(double duration, double jerk) noexcept { push(duration, a_, jerk); }
  // Constant acceleration; with jerk = 0 it may step (§8.8, replacement without jerk limitation).
  void hold(double duration, double acceleration) noexcept { push(duration, acceleration, 0.0); }

  // After a velocity change: the closed-form end velocity differs from the target by rounding only; continue
  // from the exact target with a = 0. Returns the error that was snapped away.
  double settle_velocity(double target) noexcept {
    const double error = v_ - target;
    v_ = target;
    a_ = 0;
    return error;
  }

  void finish(const MotionState& end) noexcept {
    if (out_ == nullptr) return;
    out_->duration_ = t_;
    out_->end_ = end;
  }

 private:
  void push(double duration, double acceleration, double jerk) noexcept {
    if (!(duration > 0)) return;  // also drops NaN
    if (out_ != nullptr && out_->count_ < kMaxProfileSegments) {
      out_->segments_[out_->count_++] = ProfileSegment{t_, p_, v_, acceleration, jerk};
    }
    const double d = duration;
    p_ += d * (v_ + d * (acceleration / 2 + d * jerk / 6));
    v_ += d * (acceleration + d * jerk / 2);
    a_ = acceleration + d * jerk;
    t_ += d;
  }

  PiecewiseJerkProfile* out_;
  double t_ = 0;
  double p_;
  double v_;
  double a_;
};

MotionState PiecewiseJerkProfile::at(double t) const noexcept {
  if (!(t < duration_) || count_ == 0) {
    // Beyond the end: continue at the exact final velocity (0 for positioning) with a = 0.
    const double dt = std::max(0.0, t - duration_);
    return MotionState{end_.position + end_.velocity * dt, end_.velocity, 0.0};
  }
  // Last segment that has started (≤ 12 segments: a linear scan beats a binary search here).
  std::size_t i = count_ - 1;
  while (i > 0 && segments_[i].start_time > t)
    --i;
  const ProfileSegment& s = segments_[i];
  const double d = std::max(0.0, t - s.start_time);
  return MotionState{s.position + d * (s.velocity + d * (s.acceleration / 2 + d * s.jerk / 6)),
                     s.velocity + d * (s.acceleration + d * s.jerk / 2), s.acceleration + d * s.jerk};
}

namespace {

// Jerk-limited velocity change in the "local" frame where the velocity must rise: from a0 to a plateau
// ap ≤ limit, hold, back to a = 0, gaining dv. The caller guarantees dv ≥ a0·|a0|/(2j) (a = 0 is reached at
// or below the target when a0 is ramped to zero at once). sign maps the local frame back.
void rise(ProfileBuilder& b, double sign, double a0, double dv, double limit, double jerk) noexcept {
  if (a0 > limit) {
    // The current acceleration is above what the new job allows: bring it back with the new jerk (§8.8),
    // never increase it; hold the limit; ramp out.
    const double hold = std::max(0.0, (dv - a0 * a0 / (2 * jerk)) / limit);
    b.ramp((a0 - limit) / jerk, -sign * jerk);
    b.hold(hold, sign * limit);
    b.ramp(limit / jerk, -sign * jerk);
    return;
  }
  // Without plateau the peak satisfies (2ap² − a0²)/(2j) = dv (a0 < 0 included: the ramp from a0 up to ap
  // first loses a0²/(2j) then gains ap²/(2j)).
  double peak = std::sqrt(std::max(0.0, (2 * jerk * dv + a0 * a0) / 2));
  double hold = 0;
  if (peak > limit) {
    peak = limit;
    hold = std::max(0.0, (dv - (2 * limit * limit - a0 * a0) / (2 * jerk)) / limit);
  }
  b.ramp((peak - a0) / jerk, sign * jerk);
  b.hold(hold, sign * peak);
  b.ramp(peak / jerk, -sign * jerk);
}

// Velocity change from the builder's state to target (a = 0 at the end). Returns the snapped velocity error.
double append_velocity_change(ProfileBuilder& b, double target, const Dynamics& dyn) noexcept {
  const double v0 = b.velocity();
  const double a0 = b.acceleration();
  const double j = dyn.jerk;
  if (j > 0) {
    // Velocity at which a reaches 0 if a0 is ramped out at once: decides the direction of the change.
    const double v_stop = v0 + a0 * std::abs(a0) / (2 * j);
    const double s = target >= v_stop ? 1.0 : -1.0;
    const double v0l = s * v0;
    const double a0l = s * a0;
    const double vtl = s * target;
    const double v_stopl = s * v_stop;
    // Lowest local velocity, where the acceleration turns positive (local frame): from there on a > 0.
    const double v_low = a0l < 0 ? v_stopl : v0l;
    if (v_low >= 0) {
      rise(b, s, a0l, vtl - v0l, dyn.acceleration, j);  // a > 0 at v ≥ 0: |v| grows
    } else if (vtl <= 0) {
      rise(b, s, a0l, vtl - v0l, dyn.deceleration, j);  // a > 0 at v ≤ 0: |v| shrinks
    } else if (v_stopl < 0) {
      // Through zero: brake to standstill with a = 0 there, then accelerate (see profiles.hpp).
      rise(b, s, a0l, -v0l, dyn.deceleration, j);
      b.settle_velocity(0.0);
      rise(b, s, 0.0, vtl, dyn.acceleration, j);
    } else {
      // a0 already carries the axis through zero: cross with a plateau admissible on both sides.
      rise(b, s, a0l, vtl - v0l, std::min(dyn.acceleration, dyn.deceleration), j);
    }
  } else {
    // Trapezoid: the acceleration steps at once (§8.8), at v = 0 from the deceleration to the acceleration.
    const double s = target >= v0 ? 1.0 : -1.0;
    const double v0l = s * v0;
    const double vtl = s * target;
    if (v0l >= 0) {
      b.hold((vtl - v0l) / dyn.acceleration, s * dyn.acceleration);
    } else if (vtl <= 0) {
      b.hold((vtl - v0l) / dyn.deceleration, s * dyn.deceleration);
    } else {
      b.hold(-v0l / dyn.deceleration, s * dyn.deceleration);
      b.hold(vtl / dyn.acceleration, s * dyn.acceleration);
    }
  }
  return b.settle_velocity(target);
}

// Distance of start -> peak -> 0 (start.position taken as the origin), plus `cruise` seconds at the peak.
double distance_via_peak(const MotionState& start, double peak, double cruise, const Dynamics& dyn) noexcept {
  ProfileBuilder b(nullptr, MotionState{0.0, start.velocity, start.acceleration});
  append_velocity_change(b, peak, dyn);
  b.hold(cruise, 0.0);
  append_velocity_change(b, 0.0, dyn);
  return b.position();
}

}  // namespace

bool VelocityProfile::plan(const MotionState& start, double target_velocity,
                           const ProfileLimits& limits) noexcept {
  Dynamics dyn{};
  if (!make_dynamics(limits, dyn)) return false;
  if (!finite(start.position) || !finite(start.velocity) || !finite(start.acceleration)) return false;
  if (!finite(target_velocity)) return false;
  double target = target_velocity;
  if (finite(limits.velocity) && limits.velocity > 0) {
    target = std::clamp(target, -limits.velocity, limits.velocity);
  }
  ProfileBuilder b(&profile_, start);
  end_error_ = append_velocity_change(b, target, dyn);
  b.finish(MotionState{b.position(), target, 0.0});
  return true;
}

double PositionProfile::distance_via_peak(const MotionState& start, double peak,
                                          const ProfileLimits& limits) noexcept {
  Dynamics dyn{};
  if (!make_dynamics(limits, dyn)) return 0.0;
  return techobjects::distance_via_peak(start, peak, 0.0, dyn);
}

bool PositionProfile::plan(const MotionState& start, double target_position,
                           const ProfileLimits& limits) noexcept {
  Dynamics dyn{};
  if (!make_dynamics(limits, dyn)) return false;
  if (!finite(limits.velocity) || limits.velocity <= 0) return false;
  if (!finite(start.position) || !finite(start.velocity) || !finite(start.acceleration)) return false;
  if (!finite(target_position)) return false;

  const double vmax = limits.velocity;
  const double distance = target_position - start.position;
  auto f = [&](double peak) noexcept { return techobjects::distance_via_peak(start, peak, 0.0, dyn); };

  // Velocity where a0 has been ramped out: start -> peak rises for peak above it and falls below it. f(peak)
  // is increasing on [max(v_stop, 0), vmax] and on [-vmax, min(v_stop, 0)]; in between (two changes in the
  // same direction with an a = 0 pause) it is continuous but, with jerk, not monotonic.
  const double v_stop =
      dyn.jerk > 0 ? start.velocity + start.acceleration * std::abs(start.acceleration) / (2 * dyn.jerk)
                   : start.velocity;
  const double f_top = f(vmax);
  const double f_bottom = f(-vmax);
  double peak = 0;
  double cruise = 0;
  int iterations = 0;
  if (distance >= f_top) {
    peak = vmax;
    cruise = (distance - f_top) / vmax;
  } else if (distance <= f_bottom) {
    peak = -vmax;
    cruise = (f_bottom - distance) / vmax;
  } else {
    // Breakpoints -vmax ≤ low ≤ high ≤ vmax, one of low/high is 0. f is continuous, f(-vmax) < D < f(vmax):
    // one of the three intervals brackets D. Prefer the monotonic interval on the side the target lies
    // (beyond the stopping point: a higher peak is faster), then the middle, then the other side.
    const double low = std::clamp(std::min(v_stop, 0.0), -vmax, vmax);
    const double high = std::clamp(std::max(v_stop, 0.0), -vmax, vmax);
    const double f_low = f(low);
    const double f_high = f(high);
    const double f_zero = low == 0.0 ? f_low : f_high;
    struct Interval {
      double x0, x1, f0, f1;
    };
    const Interval up{high, vmax, f_high, f_top};
    const Interval middle{low, high, f_low, f_high};
    const Interval down{-vmax, low, f_bottom, f_low};
    const std::array<Interval, 3> order = distance >= f_zero ? std::array<Interval, 3>{up, middle, down}
                                                             : std::array<Interval, 3>{down, middle, up};
    Interval bracket = order[0];
    for (const Interval& candidate : order) {
      if (std::min(candidate.f0, candidate.f1) <= distance &&
          distance <= std::max(candidate.f0, candidate.f1)) {
        bracket = candidate;
        break;
      }
    }
    // Bracketed root search in u = peak·|peak|: the distance grows roughly with peak² (v²/2a), so in u it is
    // nearly linear and secant steps converge in a few iterations even when the root sits close to one end of
    // a wide bracket. Anderson–Björck regula falsi; a bisection step whenever the last two steps neither
    // halved the bracket nor divided the residual by 4, so the bracket shrinks whatever the shape of f (kinks
    // where a plateau starts to be reached, the non-monotonic middle interval). Fixed iteration bound.
    auto to_u = [](double v) noexcept { return v * std::abs(v); };
    auto to_peak = [](double u) noexcept { return std::copysign(std::sqrt(std::abs(u)), u); };
    double x0 = to_u(bracket.x0), x1 = to_u(bracket.x1);
    double g0 = bracket.f0 - distance, g1 = bracket.f1 - distance;
    double best = std::abs(g0) <= std::abs(g1) ? bracket.x0 : bracket.x1;
    double best_g = std::min(std::abs(g0), std::abs(g1));
    // f is evaluated to ~1e-16 of the motion; asking for more only burns iterations (the end error is
    // required below 1e-9 relative).
    const double tolerance = 1e-12 * (std::abs(distance) + std::abs(f_low) + std::abs(f_high)) + 1e-300;
    const double eps = std::numeric_limits<double>::epsilon();
    double width_before = INFINITY, width_before2 = INFINITY;  // bracket width 1 and 2 steps ago
    double best_before = INFINITY, best_before2 = INFINITY;    // residual 1 and 2 steps ago
    int retained = 0;  // which end was kept last time (-1: x0, +1: x1)
    while (best_g > tolerance && std::abs(x1 - x0) > 4 * eps * std::max(std::abs(x0), std::abs(x1)) &&
           iterations < kMaxPositionIterations) {
      ++iterations;
      const double width = std::abs(x1 - x0);
      double x = 0.5 * (x0 + x1);
      const bool progressing = width <= 0.5 * width_before2 || best_g <= 0.25 * best_before2;
      if (progressing && g1 != g0) {
        // Anchored at the end with the smaller residual: near convergence the step is tiny and would be lost
        // in rounding if computed from the far end.
        const double secant =
            std::abs(g1) < std::abs(g0) ? x1 - g1 * (x1 - x0) / (g1 - g0) : x0 - g0 * (x1 - x0) / (g1 - g0);
        if (secant > std::min(x0, x1) && secant < std::max(x0, x1)) x = secant;
      }
      width_before2 = width_before;
      width_before = progressing ? width : INFINITY;  // a bisection restarts the progress window
      best_before2 = best_before;
      best_before = progressing ? best_g : INFINITY;
      if (!(x > std::min(x0, x1) && x < std::max(x0, x1))) break;  // bracket exhausted in floating point
      const double peak_x = to_peak(x);
      const double g = f(peak_x) - distance;
      if (std::abs(g) < best_g) {
        best_g = std::abs(g);
        best = peak_x;
      }
      // Anderson–Björck: scale the retained end's residual by 1 - g/g_replaced (0.5 if that is not positive).
      if ((g < 0) == (g0 < 0)) {
        if (retained == 1) {
          const double m = 1 - g / g0;
          g1 *= m > 0 ? m : 0.5;
        }
        x0 = x;
        g0 = g;
        retained = 1;
      } else {
        if (retained == -1) {
          const double m = 1 - g / g1;
          g0 *= m > 0 ? m : 0.5;
        }
        x1 = x;
        g1 = g;
        retained = -1;
      }
    }
    peak = best;
  }

  ProfileBuilder b(&profile_, start);
  append_velocity_change(b, peak, dyn);
  b.hold(cruise, 0.0);
  append_velocity_change(b, 0.0, dyn);
  // Snap to the exact target (spec: rest at target); the error is the root-search residual plus rounding.
  end_error_ = b.position() - target_position;
  b.finish(MotionState{target_position, 0.0, 0.0});
  peak_velocity_ = peak;
  iterations_ = iterations;
  return true;
}

double replanning_jerk(double v0, double a0, double jerk, double v_limit, bool to_standstill) noexcept {
  if (!(jerk > 0.0) || a0 == 0.0) return jerk;
  const double inf = std::numeric_limits<double>::infinity();
  double needed = 0.0;
  if (a0 * v0 >= 0.0) {
    const double margin = v_limit - std::fabs(v0);
    needed = margin > 0.0 ? a0 * a0 / (2.0 * margin) : inf;
  } else if (to_standstill) {
    needed = a0 * a0 / (2.0 * std::fabs(v0));
  } else {
    needed = a0 * a0 / (2.0 * (v_limit + std::fabs(v0)));
  }
  if (needed <= jerk) return jerk;
  return std::isfinite(needed) ? needed : 0.0;
}

}  // namespace tomc::techobjects
