#pragma once
// Motion laws of VDI Guideline 2143 as cam segments (spec 07 §3.2; SYNC8 "Interpolation according to VDI
// Guideline 2143"): the cam editor compiles such a law between (x0, y0) and (x1, y1) into segments of the
// data block; MC_InterpolateCam never makes them (the manual says so). These helpers do the editor's part for
// a program or a machine file. Laws whose normalized form fits y = polynomial(x) + b0·sin(b1·x + b2) per
// piece are offered; ξ = (x − x0)/(x1 − x0), h = y1 − y0:
//   line                     y = y0 + h·ξ                                        1 segment
//   quadratic parabola       y = y0 + 2h·ξ² | y0 + h·(1 − 2(1 − ξ)²)             2 segments
//   simple sine (cosine)     y = y0 + h/2·(1 − cos πξ)                           1 segment
//   inclined sine (cycloid)  y = y0 + h·(ξ − sin(2πξ)/(2π))                      1 segment
//   polynomial 5 (3-4-5)     y = y0 + h·(10ξ³ − 15ξ⁴ + 6ξ⁵)                      1 segment
//   modified sine            three pieces of line + sine (acceleration peak 5.53·h/L²)   3 segments
// The harmonic combination, the double harmonic and the sine-line combination need two sine terms in one
// piece, which TO_Cam_Struct_SegmentData does not have; they are not offered (docs/decisions.md C5).

#include <cstddef>
#include <cstdint>
#include <span>

#include "tomc/techobjects/cam/cam_data.hpp"

namespace tomc::techobjects {

enum class MotionLaw : std::uint8_t {
  kLine,
  kQuadraticParabola,
  kSimpleSine,
  kInclinedSine,
  kPolynomial5,
  kModifiedSine,
};

// The most segments a law needs.
inline constexpr std::size_t kMaxLawSegments = 3;

// Writes the segments of `law` from (x0, y0) to (x1, y1) into `out` (absolute x, as the data block holds
// them) and returns how many; 0 if x1 <= x0, a value is not finite or `out` is too small.
std::size_t motion_law_segments(MotionLaw law, double x0, double y0, double x1, double y1,
                                std::span<TO_Cam_Struct_SegmentData> out) noexcept;

}  // namespace tomc::techobjects
