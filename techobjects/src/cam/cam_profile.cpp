// Evaluation and inversion of an interpolated cam (cam_profile.hpp; spec 07 §3.3, §3.6).
#include "tomc/techobjects/cam/cam_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tomc/techobjects/axis/error_ids.hpp"

namespace tomc::techobjects {

bool CamProfile::push(const CamPiece& piece) noexcept {
  if (pieces_.size() >= pieces_.capacity()) return false;
  pieces_.push_back(piece);
  return true;
}

std::size_t CamProfile::find(double x) const noexcept {
  if (pieces_.size() < 2) return 0;
  // First piece whose x1 is not below x: at a join the left piece wins, so a cam ending a period at x1 shows
  // the left value there.
  const auto it = std::lower_bound(pieces_.begin(), pieces_.end(), x,
                                   [](const CamPiece& p, double value) { return p.x1 < value; });
  if (it == pieces_.end()) return pieces_.size() - 1;
  return static_cast<std::size_t>(it - pieces_.begin());
}

std::size_t CamProfile::find(double x, std::size_t hint) const noexcept {
  // The piece find(x) returns is the first whose x1 is not below x: piece i qualifies if x <= x1(i) and
  // (i == 0 or x > x1(i − 1)).
  const auto holds = [&](std::size_t i) {
    return i < pieces_.size() && x <= pieces_[i].x1 && (i == 0 || x > pieces_[i - 1].x1);
  };
  if (holds(hint)) return hint;
  if (holds(hint + 1)) return hint + 1;
  if (hint > 0 && holds(hint - 1)) return hint - 1;
  return find(x);
}

CamValue CamProfile::evaluate(const CamPiece& p, double x) noexcept {
  const double u = x - p.origin;
  // Horner for the value and both derivatives at once.
  double y = p.c[6];
  double dy = 0.0;
  double ddy = 0.0;
  for (int k = 5; k >= 0; --k) {
    ddy = ddy * u + 2.0 * dy;
    dy = dy * u + y;
    y = y * u + p.c[static_cast<std::size_t>(k)];
  }
  if (p.sine_amplitude != 0.0) {
    const double phase = p.sine_period * x + p.sine_phase;
    const double s = std::sin(phase);
    const double c = std::cos(phase);
    y += p.sine_amplitude * s;
    dy += p.sine_amplitude * p.sine_period * c;
    ddy -= p.sine_amplitude * p.sine_period * p.sine_period * s;
  }
  return {y, dy, ddy};
}

CamValue CamProfile::evaluate(double x) const noexcept {
  if (pieces_.empty()) return {};
  const double clamped = std::clamp(x, start(), end());
  return evaluate(pieces_[find(clamped)], clamped);
}

CamLookup following_value(const CamProfile& cam, double x, const CamScaling& s) noexcept {
  CamLookup r;
  if (s.MasterScaling == 0.0 || !std::isfinite(s.MasterScaling)) {
    r.error_id = error_id::kInvalidMasterScaling;
    return r;
  }
  const double u = (x - s.MasterOffset) / s.MasterScaling;
  if (!std::isfinite(u) || !cam.contains(u)) {
    r.error_id = error_id::kNoFollowingValue;
    return r;
  }
  const CamValue f = cam.evaluate(u);
  r.value = {s.SlaveScaling * f.y + s.SlaveOffset, s.SlaveScaling * f.dy / s.MasterScaling,
             s.SlaveScaling * f.ddy / (s.MasterScaling * s.MasterScaling)};
  return r;
}

namespace {

// Roots of g(u) = f(u) − target on one piece: sign changes on a fixed grid refined by bisection, plus
// touching roots (a local extremum of g within the tolerance). Calls `emit(u)` in ascending order.
template <typename Emit>
void piece_roots(const CamPiece& p, double target, double tolerance, Emit&& emit) noexcept {
  constexpr int kGrid = 32;        // subintervals per piece: bounded work, polynomials of degree ≤ 6
  constexpr int kBisections = 80;  // enough to reach adjacent doubles on any interval
  const auto g = [&](double u) { return CamProfile::evaluate(p, u).y - target; };
  const auto dg = [&](double u) { return CamProfile::evaluate(p, u).dy; };
  const double width = p.x1 - p.x0;
  double a = p.x0;
  double ga = g(a);
  if (std::abs(ga) <= tolerance) emit(a);
  for (int i = 1; i <= kGrid; ++i) {
    const double b = i == kGrid ? p.x1 : p.x0 + width * i / kGrid;
    const double gb = g(b);
    if (std::abs(gb) <= tolerance) {
      emit(b);
    } else if (std::abs(ga) > tolerance && (ga < 0.0) != (gb < 0.0)) {
      double lo = a;
      double hi = b;
      double glo = ga;
      for (int k = 0; k < kBisections && hi - lo > 0.0; ++k) {
        const double mid = 0.5 * (lo + hi);
        const double gm = g(mid);
        if ((gm < 0.0) == (glo < 0.0)) {
          lo = mid;
          glo = gm;
        } else {
          hi = mid;
        }
      }
      emit(0.5 * (lo + hi));
    } else if (std::abs(ga) > tolerance && (dg(a) < 0.0) != (dg(b) < 0.0)) {
      // g keeps its sign but has an extremum inside: a touching root if the extremum reaches the target.
      double lo = a;
      double hi = b;
      const bool rising_at_lo = dg(a) > 0.0;
      for (int k = 0; k < kBisections && hi - lo > 0.0; ++k) {
        const double mid = 0.5 * (lo + hi);
        if ((dg(mid) > 0.0) == rising_at_lo) {
          lo = mid;
        } else {
          hi = mid;
        }
      }
      const double u = 0.5 * (lo + hi);
      if (std::abs(g(u)) <= tolerance) emit(u);
    }
    a = b;
    ga = gb;
  }
}

}  // namespace

CamLookup leading_value(const CamProfile& cam, double y, double approach, std::int32_t direction,
                        const CamScaling& s) noexcept {
  CamLookup r;
  if (s.MasterScaling == 0.0 || !std::isfinite(s.MasterScaling)) {
    r.error_id = error_id::kInvalidMasterScaling;
    return r;
  }
  if (s.SlaveScaling == 0.0 || !std::isfinite(s.SlaveScaling)) {
    r.error_id = error_id::kInvalidSlaveScaling;
    return r;
  }
  if (direction < 1 || direction > 3) {
    r.error_id = error_id::kInvalidApproachDirection;
    return r;
  }
  if (!std::isfinite(approach) || !std::isfinite(y)) {
    r.error_id = error_id::kInvalidApproachValue;
    return r;
  }
  const double target = (y - s.SlaveOffset) / s.SlaveScaling;
  const double tolerance = 1e-9 * (1.0 + std::abs(target));
  const auto dir = static_cast<ApproachDirection>(direction);
  // Candidates in leading-value coordinates x = MO + MS·u; a root equal to the approach value (within the
  // tolerance of the leading value) counts only for "nearest".
  const double same = 1e-9 * (1.0 + std::abs(approach));
  bool found_any = false;
  bool found = false;
  double best = 0.0;
  double last_u = -std::numeric_limits<double>::infinity();
  for (const CamPiece& p : cam.pieces()) {
    piece_roots(p, target, tolerance, [&](double u) {
      if (u - last_u <= 1e-12 * (1.0 + std::abs(u))) return;  // the same root seen at a join
      last_u = u;
      found_any = true;
      const double x = s.MasterOffset + s.MasterScaling * u;
      bool better = false;
      switch (dir) {
        case ApproachDirection::kPositive:
          better = x > approach + same && (!found || x < best);
          break;
        case ApproachDirection::kNegative:
          better = x < approach - same && (!found || x > best);
          break;
        case ApproachDirection::kNearest:
          // Ties go to the positive side (tomc's choice; the manual's example has none).
          better = !found || std::abs(x - approach) < std::abs(best - approach) ||
                   (std::abs(x - approach) == std::abs(best - approach) && x > best);
          break;
      }
      if (better) {
        best = x;
        found = true;
      }
    });
  }
  if (!found_any) {
    r.error_id = error_id::kNoLeadingValue;
  } else if (!found) {
    r.error_id = error_id::kCamEndReached;
  } else {
    r.leading_value = best;
    r.value = following_value(cam, best, s).value;
  }
  return r;
}

}  // namespace tomc::techobjects
