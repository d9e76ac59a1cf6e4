// MC_InterpolateCam's work: valid points and segments -> CamProfile (cam_interpolation.hpp; spec 07
// §3.1–§3.2).
#include "tomc/techobjects/cam/cam_interpolation.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "tomc/techobjects/axis/error_ids.hpp"

namespace tomc::techobjects {
namespace {

// Gaps narrower than this are closed by joining the elements (SYNC8 "Boundary conditions": 1.0e-4).
constexpr double kGapTolerance = 1.0e-4;

struct State {
  double y = 0.0;
  double v = 0.0;
  double a = 0.0;
};

struct PointXY {
  double x;
  double y;
};

// The part of a segment in force after later segments took their ranges.
struct SegmentSpan {
  double x0;
  double x1;
  std::size_t segment;
};

// A segment span or a run of points (indices first..last into the point list).
struct Element {
  bool is_segment = false;
  SegmentSpan span{};
  std::size_t first = 0;
  std::size_t last = 0;
  std::vector<CamPiece> pieces;
  double x0 = 0.0;
  double x1 = 0.0;
  State start{};
  State end{};
};

CamInterpolationResult failure(CamDefect defect, std::uint32_t element = 0) {
  return {defect == CamDefect::kEmpty ? error_id::kCamEmpty : error_id::kCamInvalid, defect, element};
}

bool finite(const TO_Cam_Struct_SegmentData& s) {
  for (const double v : {s.xmin, s.xmax, s.a0, s.a1, s.a2, s.a3, s.a4, s.a5, s.a6, s.sineAmplitude,
                         s.sinePeriod, s.sinePhase}) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

CamPiece segment_piece(const TO_Cam_Struct_SegmentData& s, double x0, double x1) {
  CamPiece p;
  p.x0 = x0;
  p.x1 = x1;
  p.origin = 0.0;  // absolute x (spec 07 O-7)
  p.c = {s.a0, s.a1, s.a2, s.a3, s.a4, s.a5, s.a6};
  p.sine_amplitude = s.sineAmplitude;
  p.sine_period = s.sinePeriod;
  p.sine_phase = s.sinePhase;
  return p;
}

State state_at(const CamPiece& p, double x) {
  const CamValue v = CamProfile::evaluate(p, x);
  return {v.y, v.dy, v.ddy};
}

// A generated piece on [x0, x0 + h] from coefficients in ξ = (x − x0)/h: c_k(u) = c_k(ξ)/h^k.
CamPiece normalized_piece(double x0, double h, const double* xi_coefficients, int count) {
  CamPiece p;
  p.x0 = x0;
  p.x1 = x0 + h;
  p.origin = x0;
  double scale = 1.0;
  for (int k = 0; k < count; ++k) {
    p.c[static_cast<std::size_t>(k)] = xi_coefficients[k] / scale;
    scale *= h;
  }
  return p;
}

// Quintic that matches position, velocity and acceleration at both ends of [xa, xb] (spec 07 §3.2 [IMPL]).
CamPiece quintic_transition(double xa, const State& a, double xb, const State& b) {
  const double h = xb - xa;
  Eigen::Matrix<double, 6, 6> m;
  // rows: Y(0), Y'(0), Y''(0), Y(1), Y'(1), Y''(1) of Y(ξ) = Σ q_k ξ^k
  m << 1, 0, 0, 0, 0, 0,  //
      0, 1, 0, 0, 0, 0,   //
      0, 0, 2, 0, 0, 0,   //
      1, 1, 1, 1, 1, 1,   //
      0, 1, 2, 3, 4, 5,   //
      0, 0, 2, 6, 12, 20;
  Eigen::Matrix<double, 6, 1> rhs;
  rhs << a.y, a.v * h, a.a * h * h, b.y, b.v * h, b.a * h * h;
  const Eigen::Matrix<double, 6, 1> q = m.partialPivLu().solve(rhs);
  return normalized_piece(xa, h, q.data(), 6);
}

// ---- point runs ----

void linear_run(std::span<const PointXY> pts, std::vector<CamPiece>& out) {
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double h = pts[i + 1].x - pts[i].x;
    const double q[2] = {pts[i].y, pts[i + 1].y - pts[i].y};
    out.push_back(normalized_piece(pts[i].x, h, q, 2));
  }
}

enum class SplineEnd : std::uint8_t { kNatural, kClamped };
struct SplineEnds {
  SplineEnd start = SplineEnd::kNatural;
  SplineEnd end = SplineEnd::kNatural;
  double start_slope = 0.0;
  double end_slope = 0.0;
  bool periodic = false;  // first and second derivatives equal at both ends (BoundaryConditions = 1)
};

// Second derivatives M_0..M_n of the interpolating cubic spline: the tridiagonal (periodic: cyclic
// tridiagonal) system is symmetric positive definite, solved by Eigen's sparse LDLᵀ.
std::optional<Eigen::VectorXd> spline_moments(std::span<const PointXY> pts, const SplineEnds& ends) {
  const std::size_t n = pts.size() - 1;  // intervals, ≥ 2 here
  const auto h = [&](std::size_t i) { return pts[i + 1].x - pts[i].x; };
  const auto slope = [&](std::size_t i) { return (pts[i + 1].y - pts[i].y) / h(i); };
  const auto size = static_cast<Eigen::Index>(ends.periodic ? n : n + 1);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(3 * static_cast<std::size_t>(size) + 2);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  const auto at = [&](std::size_t i) { return static_cast<Eigen::Index>(ends.periodic ? i % n : i); };
  // inner rows (periodic: also row 0, which wraps around to interval n − 1)
  for (std::size_t i = ends.periodic ? 0 : 1; i < n; ++i) {
    const std::size_t before = i == 0 ? n - 1 : i - 1;
    const Eigen::Index r = at(i);
    t.emplace_back(r, at(i == 0 ? n - 1 : i - 1), h(before));
    t.emplace_back(r, r, 2.0 * (h(before) + h(i)));
    t.emplace_back(r, at(i + 1), h(i));
    rhs(r) = 6.0 * (slope(i) - slope(before));
  }
  if (!ends.periodic) {
    // Natural ends keep M = 0 and their columns out of the inner rows, so that the matrix stays symmetric.
    const auto end_row = [&](std::size_t row, std::size_t neighbour, std::size_t interval, SplineEnd kind,
                             double s, double sign) {
      const auto r = static_cast<Eigen::Index>(row);
      if (kind == SplineEnd::kNatural) {
        t.emplace_back(r, r, 1.0);
        for (auto& e : t) {
          if (e.row() == static_cast<Eigen::Index>(neighbour) && e.col() == r)
            e = Eigen::Triplet<double>(e.row(), e.col(), 0.0);
        }
        return;
      }
      t.emplace_back(r, r, 2.0 * h(interval));
      t.emplace_back(r, static_cast<Eigen::Index>(neighbour), h(interval));
      rhs(r) = 6.0 * sign * (slope(interval) - s);
    };
    end_row(0, 1, 0, ends.start, ends.start_slope, 1.0);
    end_row(n, n - 1, n - 1, ends.end, ends.end_slope, -1.0);
  }
  Eigen::SparseMatrix<double> a(size, size);
  a.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success) return std::nullopt;
  Eigen::VectorXd m = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !m.allFinite()) return std::nullopt;
  if (ends.periodic) {
    Eigen::VectorXd full(static_cast<Eigen::Index>(n + 1));
    full.head(static_cast<Eigen::Index>(n)) = m;
    full(static_cast<Eigen::Index>(n)) = m(0);
    return full;
  }
  return m;
}

bool cubic_spline_run(std::span<const PointXY> pts, const SplineEnds& ends, std::vector<CamPiece>& out) {
  if (pts.size() == 2 && !(ends.start == SplineEnd::kClamped || ends.end == SplineEnd::kClamped)) {
    linear_run(pts, out);  // natural or periodic through two points: the line
    return true;
  }
  std::optional<Eigen::VectorXd> moments;
  if (pts.size() == 2) {
    // A clamped end with two points: the system has the two end rows only.
    const double h = pts[1].x - pts[0].x;
    const double s = (pts[1].y - pts[0].y) / h;
    Eigen::Matrix2d a;
    Eigen::Vector2d rhs;
    a << (ends.start == SplineEnd::kClamped ? 2.0 * h : 1.0), (ends.start == SplineEnd::kClamped ? h : 0.0),
        (ends.end == SplineEnd::kClamped ? h : 0.0), (ends.end == SplineEnd::kClamped ? 2.0 * h : 1.0);
    rhs << (ends.start == SplineEnd::kClamped ? 6.0 * (s - ends.start_slope) : 0.0),
        (ends.end == SplineEnd::kClamped ? 6.0 * (ends.end_slope - s) : 0.0);
    moments = Eigen::VectorXd(a.partialPivLu().solve(rhs));
  } else {
    moments = spline_moments(pts, ends);
  }
  if (!moments) return false;
  const Eigen::VectorXd& m = *moments;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double h = pts[i + 1].x - pts[i].x;
    const auto k = static_cast<Eigen::Index>(i);
    // s(u) = y_i + b·u + M_i/2·u² + (M_{i+1} − M_i)/(6h)·u³ in ξ = u/h
    const double b = (pts[i + 1].y - pts[i].y) / h - h * (2.0 * m(k) + m(k + 1)) / 6.0;
    const double q[4] = {pts[i].y, b * h, 0.5 * m(k) * h * h, (m(k + 1) - m(k)) * h * h / 6.0};
    out.push_back(normalized_piece(pts[i].x, h, q, 4));
  }
  return true;
}

// "Bézier spline" (decisions C4): the clamped cubic B-spline with knots at the points whose control values
// are the polygon through the points at the Greville abscissae. It starts and ends at the end points, stays
// within the range of the points (convex hull) and is C² at every inner point; it does not pass through the
// inner points. Each knot interval becomes one cubic piece (a 4×4 Eigen fit of four de Boor values).
void bspline_run(std::span<const PointXY> pts, std::vector<CamPiece>& out) {
  const std::size_t n = pts.size() - 1;
  std::vector<double> knots;
  knots.reserve(n + 7);
  for (int i = 0; i < 3; ++i)
    knots.push_back(pts.front().x);
  for (const PointXY& p : pts)
    knots.push_back(p.x);
  for (int i = 0; i < 3; ++i)
    knots.push_back(pts.back().x);
  const auto polygon = [&](double x) {
    const auto it =
        std::upper_bound(pts.begin(), pts.end(), x, [](double v, const PointXY& p) { return v < p.x; });
    if (it == pts.begin()) return pts.front().y;
    if (it == pts.end()) return pts.back().y;
    const PointXY& r = *it;
    const PointXY& l = *(it - 1);
    return l.y + (r.y - l.y) * (x - l.x) / (r.x - l.x);
  };
  std::vector<double> control(n + 3);
  for (std::size_t j = 0; j < n + 3; ++j)
    control[j] = polygon((knots[j + 1] + knots[j + 2] + knots[j + 3]) / 3.0);
  // de Boor on knot span k (t_k ≤ x ≤ t_{k+1}).
  const auto de_boor = [&](std::size_t k, double x) {
    double d[4];
    for (std::size_t j = 0; j < 4; ++j)
      d[j] = control[j + k - 3];
    for (std::size_t r = 1; r <= 3; ++r) {
      for (std::size_t j = 3; j >= r; --j) {
        const double left = knots[j + k - 3];
        const double alpha = (x - left) / (knots[j + 1 + k - r] - left);
        d[j] = (1.0 - alpha) * d[j - 1] + alpha * d[j];
      }
    }
    return d[3];
  };
  Eigen::Matrix4d vandermonde;
  for (int i = 0; i < 4; ++i) {
    const double xi = i / 3.0;
    vandermonde.row(i) << 1.0, xi, xi * xi, xi * xi * xi;
  }
  const Eigen::PartialPivLU<Eigen::Matrix4d> fit(vandermonde);
  for (std::size_t i = 0; i < n; ++i) {
    const double h = pts[i + 1].x - pts[i].x;
    Eigen::Vector4d values;
    for (int s = 0; s < 4; ++s)
      values(s) = de_boor(i + 3, pts[i].x + h * (s / 3.0));
    const Eigen::Vector4d q = fit.solve(values);
    out.push_back(normalized_piece(pts[i].x, h, q.data(), 4));
  }
}

CamContinuity continuity_of(std::span<const CamPiece> pieces) {
  CamContinuity c;
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    const double x = pieces[i].x0;
    const CamValue l = CamProfile::evaluate(pieces[i - 1], x);
    const CamValue r = CamProfile::evaluate(pieces[i], x);
    const double steps[3] = {std::abs(r.y - l.y), std::abs(r.dy - l.dy), std::abs(r.ddy - l.ddy)};
    for (std::size_t k = 0; k < 3; ++k) {
      if (steps[k] > c.max_step[k]) {
        c.max_step[k] = steps[k];
        c.max_step_at[k] = x;
      }
    }
  }
  const CamValue s = CamProfile::evaluate(pieces.front(), pieces.front().x0);
  const CamValue e = CamProfile::evaluate(pieces.back(), pieces.back().x1);
  c.end_minus_start = {e.y - s.y, e.dy - s.dy, e.ddy - s.ddy};
  return c;
}

}  // namespace

std::size_t profile_capacity(CamCapacity capacity) noexcept {
  // point intervals + segments split in two by overlaps + one transition between any two elements
  return capacity.points + 2 * capacity.segments + (capacity.points + 2 * capacity.segments) + 1;
}

CamInterpolationResult interpolate_cam(const CamData& data, CamProfile& profile) {
  profile.clear();
  const auto mode = data.InterpolationSettings.InterpolationMode;
  const auto boundary = data.InterpolationSettings.BoundaryConditions;
  if (mode < 0 || mode > 2 || boundary < 0 || boundary > 1) return failure(CamDefect::kInvalidSettings);

  // Segments in index order; a later one takes its whole range from the earlier ones.
  std::vector<SegmentSpan> spans;
  for (std::size_t i = 0; i < data.Segment.size(); ++i) {
    if (data.ValidSegment[i] == 0) continue;
    const TO_Cam_Struct_SegmentData& s = data.Segment[i];
    const auto index = static_cast<std::uint32_t>(i + 1);
    if (!finite(s)) return failure(CamDefect::kNotFinite, index);
    if (!(s.xmin < s.xmax)) return failure(CamDefect::kSegmentRange, index);
    std::vector<SegmentSpan> kept;
    kept.reserve(spans.size() + 2);
    for (const SegmentSpan& o : spans) {
      if (o.x1 <= s.xmin || o.x0 >= s.xmax) {
        kept.push_back(o);
        continue;
      }
      if (o.x0 < s.xmin) kept.push_back({o.x0, s.xmin, o.segment});
      if (o.x1 > s.xmax) kept.push_back({s.xmax, o.x1, o.segment});
    }
    kept.push_back({s.xmin, s.xmax, i});
    std::sort(kept.begin(), kept.end(),
              [](const SegmentSpan& a, const SegmentSpan& b) { return a.x0 < b.x0; });
    spans = std::move(kept);
  }

  // Points in index order with rising x; equal x: the later one wins. Points a segment covers are dropped.
  std::vector<PointXY> points;
  for (std::size_t i = 0; i < data.Point.size(); ++i) {
    if (data.ValidPoint[i] == 0) continue;
    const TO_Cam_Struct_PointData& p = data.Point[i];
    const auto index = static_cast<std::uint32_t>(i + 1);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return failure(CamDefect::kNotFinite, index);
    if (!points.empty() && p.x < points.back().x) return failure(CamDefect::kPointsNotAscending, index);
    if (!points.empty() && p.x == points.back().x) {
      points.back().y = p.y;
    } else {
      points.push_back({p.x, p.y});
    }
  }
  std::erase_if(points, [&](const PointXY& p) {
    return std::any_of(spans.begin(), spans.end(),
                       [&](const SegmentSpan& s) { return p.x >= s.x0 && p.x <= s.x1; });
  });
  if (spans.empty() && points.empty()) return failure(CamDefect::kEmpty);
  if (spans.empty() && points.size() == 1) return failure(CamDefect::kSinglePoint);

  // The elements in x order: segment spans and the runs of points between them.
  std::vector<Element> elements;
  {
    std::size_t p = 0;
    for (std::size_t s = 0; s <= spans.size(); ++s) {
      const double limit = s < spans.size() ? spans[s].x0 : std::numeric_limits<double>::infinity();
      if (p < points.size() && points[p].x < limit) {
        Element run;
        run.first = p;
        while (p < points.size() && points[p].x < limit)
          ++p;
        run.last = p - 1;
        run.x0 = points[run.first].x;
        run.x1 = points[run.last].x;
        elements.push_back(std::move(run));
      }
      if (s < spans.size()) {
        Element seg;
        seg.is_segment = true;
        seg.span = spans[s];
        seg.x0 = spans[s].x0;
        seg.x1 = spans[s].x1;
        seg.pieces.push_back(segment_piece(data.Segment[spans[s].segment], seg.x0, seg.x1));
        seg.start = state_at(seg.pieces.front(), seg.x0);
        seg.end = state_at(seg.pieces.front(), seg.x1);
        elements.push_back(std::move(seg));
      }
    }
  }

  // Interpolate the runs of two or more points.
  const bool equal_ends = boundary == static_cast<std::int32_t>(CamBoundaryConditions::kEqualFirstDerivative);
  for (std::size_t k = 0; k < elements.size(); ++k) {
    Element& e = elements[k];
    if (e.is_segment || e.first == e.last) continue;
    const std::span<const PointXY> run(points.data() + e.first, e.last - e.first + 1);
    switch (static_cast<CamInterpolationMode>(mode)) {
      case CamInterpolationMode::kLinear:
        linear_run(run, e.pieces);
        break;
      case CamInterpolationMode::kCubicSpline: {
        SplineEnds ends;
        if (equal_ends && elements.size() == 1) {
          ends.periodic = true;
        } else if (equal_ends && k == 0 && elements.back().is_segment) {
          ends.start = SplineEnd::kClamped;  // the slope the last segment ends with
          ends.start_slope = elements.back().end.v;
        } else if (equal_ends && k + 1 == elements.size() && elements.front().is_segment) {
          ends.end = SplineEnd::kClamped;
          ends.end_slope = elements.front().start.v;
        }
        if (!cubic_spline_run(run, ends, e.pieces)) return failure(CamDefect::kSingularSystem);
        break;
      }
      case CamInterpolationMode::kBezierSpline:
        bspline_run(run, e.pieces);
        break;
    }
    e.start = state_at(e.pieces.front(), e.x0);
    e.end = state_at(e.pieces.back(), e.x1);
  }
  // A single point between other elements: the slope between its neighbours' facing ends, no curvature.
  for (std::size_t k = 0; k < elements.size(); ++k) {
    Element& e = elements[k];
    if (e.is_segment || e.first != e.last) continue;
    const double y = points[e.first].y;
    double v = 0.0;
    if (k > 0 && k + 1 < elements.size()) {
      v = (elements[k + 1].start.y - elements[k - 1].end.y) / (elements[k + 1].x0 - elements[k - 1].x1);
    } else if (k > 0) {
      v = (y - elements[k - 1].end.y) / (e.x0 - elements[k - 1].x1);
    } else if (k + 1 < elements.size()) {
      v = (elements[k + 1].start.y - y) / (elements[k + 1].x0 - e.x0);
    }
    e.start = e.end = State{y, v, 0.0};
  }

  // Join the elements: narrow gaps closed, wide gaps bridged by a quintic transition.
  std::vector<CamPiece> pieces;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    Element& e = elements[k];
    if (k > 0) {
      const Element& before = elements[k - 1];
      const double gap = e.x0 - before.x1;
      if (gap >= kGapTolerance) {
        pieces.push_back(quintic_transition(before.x1, before.end, e.x0, e.start));
      } else if (!e.pieces.empty()) {
        e.pieces.front().x0 = pieces.empty() ? before.x1 : pieces.back().x1;
      } else {
        continue;  // a single point within the gap tolerance of the element before: absorbed
      }
    }
    pieces.insert(pieces.end(), e.pieces.begin(), e.pieces.end());
  }
  if (pieces.empty()) return failure(CamDefect::kSinglePoint);
  if (pieces.size() > profile.capacity()) return failure(CamDefect::kCapacity);
  for (const CamPiece& p : pieces)
    profile.push(p);
  profile.set_continuity(continuity_of(pieces));
  return {};
}

}  // namespace tomc::techobjects
