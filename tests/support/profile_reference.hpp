#pragma once
// Brute-force reference for the positioning planner (issue 23): the shortest profile found over a grid of
// phase durations, then refined by a pattern search, checked against the limits by dense sampling.
// Independent of the planner: it shares nothing but MotionState/ProfileLimits.
//
// Template (target at rest, spec 01 §8.7): a first change of jerk s1·j for t1, a hold for t2, optionally a
// ramp of s3·j for t3 to a second level held for t3h (a crossing of v = 0 between a deceleration and an
// acceleration limit), a ramp back to a = 0 (its duration follows from the acceleration) at the peak vp; a
// cruise t4; the stop from vp. For a given first change the total is T1 + (D − p1)/vp + T2/2 (the stop covers
// vp·T2/2), so the shortest admissible stop is best: ramps of t5 = min(sqrt(|vp|/j), deceleration/j) around
// a hold. Free: s1, t1, t2, s3·t3 and t3h on a grid, t1 and t3 also to the exact times to the limits; t4
// makes p = target and must not be negative. s3·t3 on a grid and exactly to the limit levels.
// Limits (profiles.hpp semantics): |v| ≤ velocity; |a| ≤ acceleration while a·v > 0, ≤ deceleration while
// a·v < 0 (both at v = 0), or ≤ |a0| − j·t while an initial a0 above them is being ramped back. A start state
// beyond the velocity limit (|v0| above it, or a0 carrying v past it: |v0 + a0|a0|/(2j)| above it) forces
// |v| above the limit for a while: then |v(t)| may be as high as on the fastest way back to the limit (the
// jerk-limited velocity change to ±limit, VelocityProfile) or, while a0 is ramped out, as with a0 ramped out
// at once; not higher.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::testing {

class ProfileReference {
 public:
  // The template's free parameters: jerk signs of the first and the optional second ramp, durations
  // (t1 ramp, t2 hold, t3 ramp to a second level, t3h hold there).
  struct Point {
    double s1, s3;
    std::array<double, 4> x;
    double duration;
  };

  ProfileReference(const techobjects::MotionState& start, double target, const techobjects::ProfileLimits& l)
      : v0_(start.velocity), a0_(start.acceleration), distance_(target - start.position), limits_(l) {
    const double v_stop = v0_ + a0_ * std::abs(a0_) / (2 * l.jerk);
    if (std::max(std::abs(v0_), std::abs(v_stop)) > l.velocity) {
      forced_ = forced_return_.plan(start, v_stop >= 0 ? l.velocity : -l.velocity, l);
    }
  }

  // Shortest duration over `grid` points per free duration plus `refine` halvings of the search step.
  // +inf if no grid point is admissible.
  double solve(int grid, int refine) const {
    const double j = limits_.jerk;
    const double a_max = std::max({limits_.acceleration, limits_.deceleration, std::abs(a0_)});
    const double span1 = (std::abs(a0_) + a_max) / j;  // t1: a1 anywhere in [−a_max, a_max]
    const double span2 = 2 * limits_.velocity / std::min(limits_.acceleration, limits_.deceleration) + span1;
    const double span3 = 2 * a_max / j;  // t3: from a1 to any level in [−a_max, a_max]
    const std::array<double, 4> levels{limits_.acceleration, limits_.deceleration, -limits_.acceleration,
                                       -limits_.deceleration};
    // The kStarts best grid points (sorted), each refined below: one start alone often stalls on a
    // constraint.
    constexpr std::size_t kStarts = 4;
    std::array<Point, kStarts> starts{};
    for (Point& p : starts)
      p.duration = kInf;
    auto consider = [&](Point p) {
      p.duration = evaluate(p);
      if (!(p.duration < starts.back().duration)) return;
      std::size_t k = kStarts - 1;
      for (; k > 0 && p.duration < starts[k - 1].duration; --k)
        starts[k] = starts[k - 1];
      starts[k] = p;
    };
    for (const double s1 : {1.0, -1.0}) {
      // t1 on the grid, and exactly where a reaches a limit (a start beyond the velocity limit must brake at
      // the limit at once: a grid point beside it is not admissible).
      std::vector<double> first;
      for (int i = 0; i <= grid; ++i)
        first.push_back(span1 * i / grid);
      for (const double a1 : levels)
        if ((a1 - a0_) * s1 > 0) first.push_back((a1 - a0_) * s1 / j);
      for (const double t1 : first) {
        const double a1 = a0_ + s1 * j * t1;
        for (int k = 0; k <= grid; ++k) {
          const double t2 = span2 * k / grid;
          consider(Point{s1, 1.0, {t1, t2, 0.0, 0.0}, 0.0});
          // A second level (a crossing of v = 0 between the two limits): on the grid or exactly at a limit.
          std::vector<double> third;
          for (int m = 1; m <= grid; ++m)
            third.push_back(-span3 + 2 * span3 * m / grid);
          for (const double a3 : levels)
            if (a3 != a1) third.push_back((a3 - a1) / j);
          for (const double signed_t3 : third) {
            for (int h = 0; h <= grid; ++h)
              consider(Point{
                  s1, signed_t3 > 0 ? 1.0 : -1.0, {t1, t2, std::abs(signed_t3), span2 * h / grid}, 0.0});
          }
        }
      }
    }
    double shortest = kInf;
    for (const Point& start : starts) {
      if (start.duration == kInf) break;
      shortest = std::min(
          shortest, refine_from(start, {span1 / grid, span2 / grid, span3 / grid, span2 / grid}, refine));
    }
    return shortest;
  }

  // Pattern search: move one duration, or two together in several ratios (optima lie on constraint edges,
  // e.g. where the cruise vanishes), by ±step; halve the steps `refine` times.
  double refine_from(Point best, std::array<double, 4> step, int refine) const {
    for (int r = 0; r < refine; ++r) {
      bool improved = true;
      while (improved) {
        improved = false;
        for (int d = 0; d < 4; ++d) {
          for (int e = d; e < 4; ++e) {
            for (const double ratio : {0.25, 0.5, 1.0, 2.0, 4.0}) {
              if (e == d && ratio != 1.0) continue;
              for (const double sd : {1.0, -1.0}) {
                for (const double se : {1.0, -1.0}) {
                  if (e == d && se < 0) continue;
                  Point p = best;
                  p.x[d] = std::max(0.0, p.x[d] + sd * step[d]);
                  if (e != d) p.x[e] = std::max(0.0, p.x[e] + se * ratio * step[e]);
                  const double t = evaluate(p);
                  if (t < best.duration * (1 - 1e-15)) {
                    best = p;
                    best.duration = t;
                    improved = true;
                  }
                }
              }
            }
          }
        }
      }
      for (double& s : step)
        s /= 2;
    }
    return best.duration;
  }

  // Whether a planned profile keeps the limits as this reference understands them.
  template <typename Segments>
  bool admissible(const Segments& segments, double duration) const {
    State s{0.0, 0.0, v0_, a0_};
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const double end = i + 1 < segments.size() ? segments[i + 1].start_time : duration;
      s = State{segments[i].start_time, 0.0, segments[i].velocity, segments[i].acceleration};
      if (!segment(s, end - segments[i].start_time, segments[i].jerk)) return false;
    }
    return true;
  }

  // Duration of the template at p, +inf if it is not admissible.
  double evaluate(const Point& pt) const {
    const double j = limits_.jerk;
    const double s1 = pt.s1, t1 = pt.x[0], t2 = pt.x[1], t3 = pt.x[2], t3h = pt.x[3];
    const double a1 = a0_ + s1 * j * t1;
    const double a3 = a1 + pt.s3 * j * t3;
    State s{0.0, 0.0, v0_, a0_};
    if (!segment(s, t1, s1 * j) || !segment(s, t2, 0.0) || !segment(s, t3, pt.s3 * j) ||
        !segment(s, t3h, 0.0) || !segment(s, std::abs(a3) / j, a3 > 0 ? -j : j)) {
      return kInf;
    }
    s.a = 0;
    const double vp = s.v;
    if (vp == 0) return kInf;
    const double s2 = vp > 0 ? -1.0 : 1.0;
    const double t5 = std::min(std::sqrt(std::abs(vp) / j), limits_.deceleration / j);
    const double t6 = std::max(0.0, std::abs(vp) / (j * t5) - t5);
    // Distance of the second change alone, to size the cruise.
    State probe{0.0, 0.0, vp, 0.0};
    integrate(probe, t5, s2 * j);
    integrate(probe, t6, 0.0);
    integrate(probe, t5, -s2 * j);
    const double t4 = (distance_ - s.p - probe.p) / vp;
    if (t4 < -1e-12 * (1 + std::abs(distance_)) / std::abs(vp)) return kInf;
    if (!segment(s, std::max(0.0, t4), 0.0) || !segment(s, t5, s2 * j) || !segment(s, t6, 0.0) ||
        !segment(s, t5, -s2 * j)) {
      return kInf;
    }
    return s.t;
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  struct State {
    double t, p, v, a;
  };

  static void integrate(State& s, double d, double jerk) {
    s.p += d * (s.v + d * (s.a / 2 + d * jerk / 6));
    s.v += d * (s.a + d * jerk / 2);
    s.a += d * jerk;
    s.t += d;
  }

  bool admissible(double t, double v, double a) const {
    const double v_tol = 1e-9 * limits_.velocity;
    double v_limit = limits_.velocity;
    if (forced_) {
      // As high as on the fastest way back, or with a0 ramped out at once (the first thing any plan does).
      v_limit = std::max(v_limit, std::abs(forced_return_.at(t).velocity));
      const double ramp_out = std::abs(a0_) / limits_.jerk;
      if (t <= ramp_out)
        v_limit = std::max(v_limit, std::abs(v0_ + a0_ * t - std::copysign(limits_.jerk, a0_) * t * t / 2));
    }
    if (std::abs(v) > v_limit + v_tol) return false;
    double limit = std::abs(v) <= v_tol ? std::min(limits_.acceleration, limits_.deceleration)
                                        : (a * v > 0 ? limits_.acceleration : limits_.deceleration);
    limit = std::max(limit, std::abs(a0_) - limits_.jerk * t);
    return std::abs(a) <= limit * (1 + 1e-9);
  }

  // Integrates one segment, sampling it densely (and at its v = 0 and a = 0 points); false if inadmissible.
  bool segment(State& s, double d, double jerk) const {
    if (d < 0) return false;
    if (d == 0) return true;
    std::array<double, 24> times{};
    std::size_t n = 0;
    constexpr int kSamples = 16;
    for (int k = 0; k <= kSamples; ++k)
      times[n++] = d * k / kSamples;
    if (jerk != 0) {
      const double zero_a = -s.a / jerk;
      if (zero_a > 0 && zero_a < d) times[n++] = zero_a;
    }
    // v(τ) = v + a τ + jerk τ²/2 = 0: check a just beside each crossing against both sides' limits.
    const double qa = jerk / 2, qb = s.a, qc = s.v;
    if (qa != 0) {
      const double disc = qb * qb - 4 * qa * qc;
      if (disc >= 0) {
        for (const double r : {(-qb - std::sqrt(disc)) / (2 * qa), (-qb + std::sqrt(disc)) / (2 * qa)})
          if (r > 0 && r < d) times[n++] = r;
      }
    } else if (qb != 0) {
      const double r = -qc / qb;
      if (r > 0 && r < d) times[n++] = r;
    }
    for (std::size_t k = 0; k < n; ++k) {
      State x = s;
      integrate(x, times[k], jerk);
      if (!admissible(x.t, x.v, x.a)) return false;
    }
    integrate(s, d, jerk);
    return true;
  }

  double v0_;
  double a0_;
  bool forced_ = false;
  techobjects::VelocityProfile forced_return_;
  double distance_;
  techobjects::ProfileLimits limits_;
};

// The exact optimum of the positioning template (start -> peak with a = 0 -> cruise -> stop, each velocity
// change the time-optimal one of VelocityProfile) by exhaustion over the peak instead of the planner's root
// selection (decision S18): `grid` peaks evenly over [-limit, limit], every admissible one (cruise ≥ 0) a
// candidate, and every sign change of the cruise between neighbours bisected to the peak where the cruise
// vanishes (the usual optimum of a short move). Finds the planner's errors of root bracketing and choice
// (a root inside the non-monotonic middle interval, a slower root taken); the brute-force ProfileReference
// above covers what the template itself leaves out.
inline double shortest_over_peaks(const techobjects::MotionState& start, double target,
                                  const techobjects::ProfileLimits& l, int grid) {
  const double distance = target - start.position;
  techobjects::VelocityProfile first, stop;
  struct Candidate {
    double cruise;    // time at the peak, negative when the two changes alone overshoot the target
    double duration;  // with the cruise (meaningful when cruise >= 0)
  };
  auto candidate = [&](double peak) {
    first.plan(techobjects::MotionState{0.0, start.velocity, start.acceleration}, peak, l);
    stop.plan(techobjects::MotionState{0.0, peak, 0.0}, 0.0, l);
    const double covered = first.at(first.duration()).position + stop.at(stop.duration()).position;
    const double cruise = peak != 0 ? (distance - covered) / peak : (distance == covered ? 0.0 : -1.0);
    return Candidate{cruise, first.duration() + std::max(0.0, cruise) + stop.duration()};
  };
  double shortest = std::numeric_limits<double>::infinity();
  double previous_peak = 0;
  Candidate previous{};
  for (int k = 0; k <= grid; ++k) {
    const double peak = l.velocity * (2.0 * k / grid - 1.0);
    const Candidate c = candidate(peak);
    if (c.cruise >= 0) shortest = std::min(shortest, c.duration);
    if (k > 0 && (c.cruise >= 0) != (previous.cruise >= 0)) {
      // The cruise vanishes in between: bisect to the admissible side's limit.
      double inside = c.cruise >= 0 ? peak : previous_peak;
      double outside = c.cruise >= 0 ? previous_peak : peak;
      for (int i = 0; i < 60; ++i) {
        const double middle = (inside + outside) / 2;
        (candidate(middle).cruise >= 0 ? inside : outside) = middle;
      }
      shortest = std::min(shortest, candidate(inside).duration);
    }
    previous_peak = peak;
    previous = c;
  }
  return shortest;
}

}  // namespace tomc::testing
