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

// Integrates the state over pieces of constant jerk in closed form, storing nothing: the root search of the
// PositionProfile evaluates candidate profiles this way.
class Integrator {
 public:
  explicit Integrator(const MotionState& start) noexcept
      : p_(start.position), v_(start.velocity), a_(start.acceleration) {}

  double time() const noexcept { return t_; }
  double position() const noexcept { return p_; }
  double velocity() const noexcept { return v_; }
  double acceleration() const noexcept { return a_; }

  // Constant jerk from the current (continuous) acceleration.
  void ramp(double duration, double jerk) noexcept {
    if (duration > 0) advance(duration, a_, jerk);
  }
  // Constant acceleration; with jerk = 0 it may step (§8.8, replacement without jerk limitation).
  void hold(double duration, double acceleration) noexcept {
    if (duration > 0) {  // advance() without its jerk terms (x·0 cannot be folded away in IEEE arithmetic)
      p_ += duration * (v_ + duration * acceleration / 2);
      v_ += duration * acceleration;
      a_ = acceleration;
      t_ += duration;
    }
  }

  // After a velocity change: the closed-form end velocity differs from the target by rounding only; continue
  // from the exact target with a = 0. Returns the error that was snapped away.
  double settle_velocity(double target) noexcept {
    const double error = v_ - target;
    v_ = target;
    a_ = 0;
    return error;
  }

  // At a velocity snapped by settle_velocity: the acceleration the next piece starts from (continuous).
  void set_acceleration(double acceleration) noexcept { a_ = acceleration; }

 protected:
  void advance(double d, double acceleration, double jerk) noexcept {
    p_ += d * (v_ + d * (acceleration / 2 + d * jerk / 6));
    v_ += d * (acceleration + d * jerk / 2);
    a_ = acceleration + d * jerk;
    t_ += d;
  }

  double t_ = 0;
  double p_;
  double v_;
  double a_;
};

// The same integration, appending each piece to a profile's segments.
class ProfileBuilder : public Integrator {
 public:
  ProfileBuilder(PiecewiseJerkProfile* out, const MotionState& start) noexcept
      : Integrator(start), out_(out) {
    out_->count_ = 0;
    out_->truncated_ = false;
  }

  void ramp(double duration, double jerk) noexcept { push(duration, a_, jerk); }
  void hold(double duration, double acceleration) noexcept { push(duration, acceleration, 0.0); }

  void finish(const MotionState& end) noexcept {
    out_->duration_ = t_;
    out_->end_ = end;
  }

 private:
  void push(double duration, double acceleration, double jerk) noexcept {
    if (!(duration > 0)) return;  // also drops NaN
    if (out_->count_ < kMaxProfileSegments) {
      out_->segments_[out_->count_++] = ProfileSegment{t_, p_, v_, acceleration, jerk};
    } else {
      out_->truncated_ = true;
    }
    advance(duration, acceleration, jerk);
  }

  PiecewiseJerkProfile* out_;
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
  return segment_state(segments_[i], t);
}

namespace {

// Jerk-limited velocity change in the "local" frame where the velocity must rise: from a0 over a plateau
// ap ≤ limit down to a_end ≥ 0, gaining dv. A ramp between accelerations x and y gains (y² − x²)/(2j) in
// either direction of x and y, so with a peak ap ≥ max(a0, a_end) the gain is (2ap² − a0² − a_end²)/(2j) plus
// ap · hold. The caller guarantees dv at least the gain of the direct ramp a0 → a_end. sign maps the local
// frame back.
template <typename Builder>
[[gnu::always_inline]] inline void rise(Builder& b, double sign, double a0, double dv, double limit,
                                        double jerk, double a_end = 0.0) noexcept {
  const double end2 = a_end * a_end;
  if (a0 > limit) {
    // The current acceleration is above what the new job allows: bring it back with the new jerk (§8.8),
    // never increase it; hold the limit; ramp out.
    const double hold = std::max(0.0, (dv - (a0 * a0 - end2) / (2 * jerk)) / limit);
    b.ramp((a0 - limit) / jerk, -sign * jerk);
    b.hold(hold, sign * limit);
    b.ramp((limit - a_end) / jerk, -sign * jerk);
    return;
  }
  double peak = std::sqrt(std::max(0.0, (2 * jerk * dv + a0 * a0 + end2) / 2));
  double hold = 0;
  if (peak > limit) {
    peak = limit;
    hold = std::max(0.0, (dv - (2 * limit * limit - a0 * a0 - end2) / (2 * jerk)) / limit);
  }
  peak = std::max({peak, a0, a_end});  // rounding: never ramp backwards
  b.ramp((peak - a0) / jerk, sign * jerk);
  b.hold(hold, sign * peak);
  b.ramp((peak - a_end) / jerk, -sign * jerk);
}

// A rising change through v = 0 (local frame: v0 < 0 < target − here dv0 = −v0 to zero, dv1 = target from
// zero). The acceleration is continuous, so its value a_c at the crossing must be admissible on both sides:
// a_c ≤ min(acc, dec). The fastest profile keeps a as high as the limits let it: deceleration limit while
// v < 0, acceleration limit after, a_c as high as min(acc, dec) and both halves allow. Each half is then a
// single-peak change, and a_c = min(..) joins them without a dip.
template <typename Builder>
[[gnu::always_inline]] inline void rise_through_zero(Builder& b, double sign, double a0, double dv0,
                                                     double dv1, double acc, double dec,
                                                     double jerk) noexcept {
  const double both = std::min(acc, dec);
  // The half before the crossing reaches a_c by at most a ramp from a0 (a_c² ≤ 2j·dv0 + a0²); the half after
  // ramps a_c out at most (a_c² ≤ 2j·dv1).
  const double crossing = std::min(
      {both, std::sqrt(std::max(0.0, 2 * jerk * dv0 + a0 * a0)), std::sqrt(2 * jerk * std::max(0.0, dv1))});
  // Lowest a_c the state allows: a0 ramped down at once (a0² − 2j·dv0). Above `both` the state forces an
  // inadmissible crossing: bring a0 back with the jerk at once and hold `both` (admissible on both sides).
  if (a0 * a0 - 2 * jerk * dv0 > crossing * crossing * (1 + 1e-12) && a0 > crossing) {
    rise(b, sign, a0, dv0 + dv1, both, jerk);
    return;
  }
  rise(b, sign, a0, dv0, dec, jerk, crossing);
  b.settle_velocity(0.0);
  b.set_acceleration(sign * crossing);
  rise(b, sign, crossing, dv1, acc, jerk);
}

// Velocity change from the builder's state to target (a = 0 at the end). Returns the snapped velocity error.
template <typename Builder>
double append_velocity_change(Builder& b, double target, const Dynamics& dyn) noexcept {
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
    } else {
      rise_through_zero(b, s, a0l, -v0l, vtl, dyn.acceleration, dyn.deceleration, j);
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

// Distance and duration of start -> peak -> 0 (start.position taken as the origin), no cruise.
struct ViaPeak {
  double distance;
  double duration;
};

// The stop from v with a = 0 (|v| shrinks: deceleration limit). Its velocity is point-symmetric about the
// half-way point, so it covers v·T/2 (spec 01 §8.7 "s_ramp = v · t_total / 2").
ViaPeak stop_from(double v, const Dynamics& dyn) noexcept {
  const double speed = std::abs(v);
  double duration = speed / dyn.deceleration;  // trapezoid
  if (dyn.jerk > 0) {
    const double d = dyn.deceleration;
    duration = speed * dyn.jerk >= d * d ? speed / d + d / dyn.jerk : 2 * std::sqrt(speed / dyn.jerk);
  }
  return ViaPeak{v * duration / 2, duration};
}

ViaPeak via_peak(const MotionState& start, double peak, const Dynamics& dyn) noexcept {
  Integrator b(MotionState{0.0, start.velocity, start.acceleration});
  append_velocity_change(b, peak, dyn);
  const ViaPeak stop = stop_from(peak, dyn);
  return ViaPeak{b.position() + stop.distance, b.time() + stop.duration};
}

// via_peak(start, v_stop) in closed form: a0 ramped out at once (one piece of constant jerk), then the stop.
ViaPeak ramp_out_and_stop(const MotionState& start, double v_stop, const Dynamics& dyn) noexcept {
  const double a0 = dyn.jerk > 0 ? start.acceleration : 0.0;
  const double t = std::abs(a0) / (dyn.jerk > 0 ? dyn.jerk : 1.0);
  const double jerk = -std::copysign(dyn.jerk, a0);
  const ViaPeak stop = stop_from(v_stop, dyn);
  return ViaPeak{t * (start.velocity + t * (a0 / 2 + t * jerk / 6)) + stop.distance, t + stop.duration};
}

// One bracket [x0, x1] of peak velocities with f(x) − D changing sign (or zero) at its ends.
struct Bracket {
  double x0, x1, f0, f1;
  bool contains(double d) const noexcept { return std::min(f0, f1) <= d && d <= std::max(f0, f1); }
};

struct Root {
  double peak;
  double duration;
  int iterations;
};

// Bracketed root search in u = peak·|peak|: the distance grows roughly with peak² (v²/2a), so in u it is
// nearly linear. Chandrupatla's method: inverse quadratic interpolation through the last three points while
// they show a smooth enough f, else bisection, never a step closer than the resolution to an end, so the
// bracket shrinks whatever the shape of f (kinks where a plateau starts to be reached, the non-monotonic
// middle interval). The first step is the secant. At most kMaxPositionIterations steps.
Root solve_peak(const MotionState& start, const Dynamics& dyn, const Bracket& bracket, double distance,
                double tolerance) noexcept {
  auto to_u = [](double v) noexcept { return v * std::abs(v); };
  auto to_peak = [](double u) noexcept { return std::copysign(std::sqrt(std::abs(u)), u); };
  // a: the newest point, b: the other end of the bracket, c: the end b replaced (the third point).
  double a = to_u(bracket.x1), b = to_u(bracket.x0), c = b;
  double fa = bracket.f1 - distance, fb = bracket.f0 - distance, fc = fb;
  double best = std::abs(fa) <= std::abs(fb) ? bracket.x1 : bracket.x0;
  double best_g = std::min(std::abs(fa), std::abs(fb));
  double best_duration = -1;  // not evaluated yet (an end of the bracket)
  const double eps = std::numeric_limits<double>::epsilon();
  double t = fa != fb ? fa / (fa - fb) : 0.5;  // first step: the secant
  int iterations = 0;
  while (best_g > tolerance && iterations < kMaxPositionIterations) {
    // No step closer to an end than the resolution of u; stop when the bracket is that narrow.
    const double limit = 2 * eps * std::max(std::abs(a), std::abs(b)) / std::abs(b - a);
    if (!(limit < 0.5)) break;
    t = std::clamp(t, limit, 1 - limit);
    const double x = a + t * (b - a);
    ++iterations;
    const ViaPeak v = via_peak(start, to_peak(x), dyn);
    const double g = v.distance - distance;
    if (std::abs(g) < best_g) {
      best_g = std::abs(g);
      best = to_peak(x);
      best_duration = v.duration;
    }
    if ((g < 0) == (fa < 0)) {
      c = a;
      fc = fa;
    } else {
      c = b;
      fc = fb;
      b = a;
      fb = fa;
    }
    a = x;
    fa = g;
    // Inverse quadratic interpolation where the three points allow it (Chandrupatla's criterion), else halve.
    const double xi = (a - b) / (c - b);
    const double phi = (fa - fb) / (fc - fb);
    t = 0.5;
    if (phi * phi < xi && (1 - phi) * (1 - phi) < 1 - xi) {
      t = fa / (fb - fa) * fc / (fb - fc) + (c - a) / (b - a) * fa / (fc - fa) * fb / (fc - fb);
    }
  }
  if (best_duration < 0) best_duration = via_peak(start, best, dyn).duration;
  return Root{best, best_duration, iterations};
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
  return via_peak(start, peak, dyn).distance;
}

bool PositionProfile::plan(const MotionState& start, double target_position,
                           const ProfileLimits& limits) noexcept {
  Dynamics dyn{};
  if (!make_dynamics(limits, dyn)) return false;
  if (!finite(limits.velocity) || limits.velocity <= 0) return false;
  if (!finite(start.position) || !finite(start.velocity) || !finite(start.acceleration)) return false;
  if (!finite(target_position)) return false;

  // Every time-optimal profile to rest has the form start -> peak (a = 0 there) -> cruise -> 0, each change
  // time-optimal (the template of the jerk-limited positioning profile, spec 01 §8.7). The planner chooses
  // the peak: ±vmax with a cruise when the distance needs one, else the fastest peak f(peak) = D.
  const double vmax = limits.velocity;
  const double distance = target_position - start.position;
  auto f = [&](double peak) noexcept { return via_peak(start, peak, dyn); };

  // Velocity where a0 has been ramped out: start -> peak rises for peak above it and falls below it. f(peak)
  // is increasing on [max(v_stop, 0), vmax] and on [-vmax, min(v_stop, 0)]; in between (two changes in the
  // same direction with an a = 0 pause) it is continuous but, with jerk, not monotonic.
  const double v_stop =
      dyn.jerk > 0 ? start.velocity + start.acceleration * std::abs(start.acceleration) / (2 * dyn.jerk)
                   : start.velocity;
  // Breakpoints -vmax ≤ low ≤ high ≤ vmax, one of low/high is 0. f is continuous and increasing on
  // [high, vmax] and [-vmax, low], so f(low) and f(high) tell which intervals can hold D: only then are
  // f(vmax) and f(-vmax) evaluated (each evaluation is most of a plan's cost). f(v_stop) is a closed form.
  const double low = std::clamp(std::min(v_stop, 0.0), -vmax, vmax);
  const double high = std::clamp(std::max(v_stop, 0.0), -vmax, vmax);
  auto f_at = [&](double peak) noexcept {
    return peak == v_stop ? ramp_out_and_stop(start, v_stop, dyn).distance : f(peak).distance;
  };
  const double f_low = f_at(low);
  const double f_high = high == low ? f_low : f_at(high);
  const bool needs_top = distance > f_high;
  const bool needs_bottom = distance < f_low;
  const double top = needs_top ? (high == vmax ? f_high : f(vmax).distance) : f_high;
  const double bottom = needs_bottom ? (low == -vmax ? f_low : f(-vmax).distance) : f_low;
  double peak = 0;
  double cruise = 0;
  int iterations = 0;
  if (needs_top && distance >= top) {
    peak = vmax;
    cruise = (distance - top) / vmax;
  } else if (needs_bottom && distance <= bottom) {
    peak = -vmax;
    cruise = (bottom - distance) / vmax;
  } else {
    // f(-vmax) < D < f(vmax): at least one of the three intervals brackets D; a root in each that does is a
    // candidate (at most 3 root searches), the fastest wins (a reversal against the motion can beat braking
    // to a lower peak).
    const std::array<Bracket, 3> brackets{Bracket{high, vmax, f_high, top}, Bracket{low, high, f_low, f_high},
                                          Bracket{-vmax, low, bottom, f_low}};
    // f is evaluated to ~1e-16 of the motion; asking for more only burns iterations (the end error is
    // required below 1e-9 relative).
    const double tolerance = 1e-12 * (std::abs(distance) + std::abs(f_low) + std::abs(f_high)) + 1e-300;
    double fastest = INFINITY;
    for (const Bracket& bracket : brackets) {
      if (!bracket.contains(distance) || bracket.x0 == bracket.x1) continue;
      const Root root = solve_peak(start, dyn, bracket, distance, tolerance);
      iterations = std::max(iterations, root.iterations);
      if (root.duration < fastest) {
        fastest = root.duration;
        peak = root.peak;
      }
    }
    if (fastest == INFINITY) peak = std::abs(f_low - distance) <= std::abs(f_high - distance) ? low : high;
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

double replanning_jerk(double v0, double a0, double jerk, bool to_standstill) noexcept {
  // Decision R1 only: the job's jerk otherwise, whatever the velocity does on the way (decision S4).
  if (!(jerk > 0.0) || !to_standstill || a0 * v0 >= 0.0) return jerk;
  const double needed = a0 * a0 / (2.0 * std::fabs(v0));
  return needed > jerk ? needed : jerk;
}

}  // namespace tomc::techobjects
