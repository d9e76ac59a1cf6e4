#pragma once
// MC_InterpolateCam's work (spec 07 §3.1–§3.2): from the valid points and segments of a cam data block to
// the gap-free CamProfile that followers evaluate.
//
// - Segments: polynomials of degree ≤ 6 plus a sine term on [xmin, xmax], absolute x (O-7). A later segment
//   (higher index) overlapping an earlier one is used over its whole range; the earlier one continues after
//   it. A segment wins over points in its range (SYNC8 "Boundary conditions").
// - Points: valid points in index order with rising x (equal x: the later one wins); a run of points between
//   segments is interpolated by InterpolationSettings.InterpolationMode: 0 linear, 1 cubic spline (natural,
//   or with BoundaryConditions = 1 equal first and second derivatives at the start and the end of the cam), 2
//   "Bézier spline": a clamped cubic B-spline over the points (decisions C4). The spline systems are solved
//   with Eigen (a sparse LDLᵀ of the tridiagonal / cyclic tridiagonal system).
// - Gaps between elements below 1e-4 in x are closed by joining the elements; wider gaps get a quintic
//   transition that matches position, velocity and acceleration at both ends (a 6×6 Eigen solve).
//
// Not cyclic: it allocates its work space (an instruction of the user program, refused while a follower uses
// the cam, spec 07 §3.2), the result goes into the CamProfile's reserved capacity.

#include <cstdint>

#include "tomc/techobjects/cam/cam_data.hpp"
#include "tomc/techobjects/cam/cam_profile.hpp"

namespace tomc::techobjects {

// Why a cam cannot be interpolated (ErrorDetail of the MC_InterpolateCam error; docs/errors.md 16#80AC).
enum class CamDefect : std::uint8_t {
  kNone,
  kEmpty,               // 16#80AA: no valid point and no valid segment
  kSinglePoint,         // 16#80AC: one valid point and no segment
  kPointsNotAscending,  // 16#80AC: a valid point with a smaller x than the valid point before it
  kSegmentRange,        // 16#80AC: a valid segment with xmin >= xmax
  kNotFinite,           // 16#80AC: a coordinate or coefficient that is not a finite number
  kInvalidSettings,     // 16#80AC: InterpolationMode not 0...2 or BoundaryConditions not 0/1
  kCapacity,            // 16#80AC: more pieces than the profile can hold (cannot happen with capacity_of)
  kSingularSystem,      // 16#80AC: the spline system could not be solved
};

struct CamInterpolationResult {
  std::uint16_t error_id = 0;
  CamDefect defect = CamDefect::kNone;
  std::uint32_t element = 0;  // 1-based index of the point or segment at fault (0: none / not one element)
};

// The piece capacity a CamProfile needs for a data block of this variant: every point interval, every
// segment (twice: an overlapped one may be split) and a transition between any two elements.
std::size_t profile_capacity(CamCapacity capacity) noexcept;

// Interpolates `data` into `profile` (cleared first; on an error it is left empty).
CamInterpolationResult interpolate_cam(const CamData& data, CamProfile& profile);

}  // namespace tomc::techobjects
