// VDI 2143 motion laws as cam segments (vdi2143.hpp).
#include "tomc/techobjects/cam/vdi2143.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>

namespace tomc::techobjects {
namespace {

constexpr double kPi = std::numbers::pi;

// A segment on [xa, xb] from a polynomial in ξ = (x − x0)/L (coefficients q[0..6]) plus A·sin(ω·ξ + φ),
// rewritten for absolute x: (x − x0)/L expanded binomially, the sine's period and phase in x.
TO_Cam_Struct_SegmentData segment(double xa, double xb, double x0, double length,
                                  const std::array<double, 7>& q, double amplitude = 0.0, double omega = 0.0,
                                  double phase = 0.0) {
  // p(x) = Σ q_k ((x − x0)/L)^k = Σ_j a_j x^j with a_j = Σ_{k≥j} q_k / L^k · C(k, j) · (−x0)^{k−j}
  std::array<double, 7> a{};
  for (std::size_t k = 0; k < 7; ++k) {
    if (q[k] == 0.0) continue;
    const double scaled = q[k] / std::pow(length, static_cast<double>(k));
    double binomial = 1.0;  // C(k, j), built from j = 0 upwards
    for (std::size_t j = 0; j <= k; ++j) {
      a[j] += scaled * binomial * std::pow(-x0, static_cast<double>(k - j));
      binomial = binomial * static_cast<double>(k - j) / static_cast<double>(j + 1);
    }
  }
  TO_Cam_Struct_SegmentData s;
  s.xmin = xa;
  s.xmax = xb;
  s.a0 = a[0];
  s.a1 = a[1];
  s.a2 = a[2];
  s.a3 = a[3];
  s.a4 = a[4];
  s.a5 = a[5];
  s.a6 = a[6];
  if (amplitude != 0.0) {
    s.sineAmplitude = amplitude;
    s.sinePeriod = omega / length;
    s.sinePhase = phase - omega * x0 / length;
  }
  return s;
}

}  // namespace

std::size_t motion_law_segments(MotionLaw law, double x0, double y0, double x1, double y1,
                                std::span<TO_Cam_Struct_SegmentData> out) noexcept {
  if (!(x1 > x0) || !std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(y0) || !std::isfinite(y1))
    return 0;
  const double l = x1 - x0;
  const double h = y1 - y0;
  const auto at = [&](double xi) { return x0 + xi * l; };
  const auto put = [&](std::initializer_list<TO_Cam_Struct_SegmentData> segments) -> std::size_t {
    if (segments.size() > out.size()) return 0;
    std::size_t i = 0;
    for (const auto& s : segments)
      out[i++] = s;
    return segments.size();
  };
  switch (law) {
    case MotionLaw::kLine:
      return put({segment(x0, x1, x0, l, {y0, h})});
    case MotionLaw::kQuadraticParabola:
      // 2hξ² up to ξ = 1/2, then h(1 − 2(1 − ξ)²) = h(−1 + 4ξ − 2ξ²)
      return put({segment(x0, at(0.5), x0, l, {y0, 0.0, 2.0 * h}),
                  segment(at(0.5), x1, x0, l, {y0 - h, 4.0 * h, -2.0 * h})});
    case MotionLaw::kSimpleSine:
      // h/2·(1 − cos πξ) = h/2 − h/2·sin(πξ + π/2)
      return put({segment(x0, x1, x0, l, {y0 + 0.5 * h}, -0.5 * h, kPi, 0.5 * kPi)});
    case MotionLaw::kInclinedSine:
      return put({segment(x0, x1, x0, l, {y0, h}, -h / (2.0 * kPi), 2.0 * kPi, 0.0)});
    case MotionLaw::kPolynomial5:
      return put({segment(x0, x1, x0, l, {y0, 0.0, 0.0, 10.0 * h, -15.0 * h, 6.0 * h})});
    case MotionLaw::kModifiedSine: {
      // Modified sine (Rothbart): with k = 4 + π,
      //   ξ ≤ 1/8:        h·(πξ/k − sin(4πξ)/(4k))
      //   1/8 ≤ ξ ≤ 7/8:  h·(2/k + πξ/k − 9·sin(π/3 + 4πξ/3)/(4k))
      //   ξ ≥ 7/8:        h·(4/k + πξ/k − sin(4πξ)/(4k))
      const double k = 4.0 + kPi;
      return put(
          {segment(x0, at(0.125), x0, l, {y0, h * kPi / k}, -h / (4.0 * k), 4.0 * kPi, 0.0),
           segment(at(0.125), at(0.875), x0, l, {y0 + 2.0 * h / k, h * kPi / k}, -9.0 * h / (4.0 * k),
                   4.0 * kPi / 3.0, kPi / 3.0),
           segment(at(0.875), x1, x0, l, {y0 + 4.0 * h / k, h * kPi / k}, -h / (4.0 * k), 4.0 * kPi, 0.0)});
    }
  }
  return 0;
}

}  // namespace tomc::techobjects
