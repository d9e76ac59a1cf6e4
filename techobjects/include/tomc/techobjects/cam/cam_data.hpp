#pragma once
// The technology data block of TO_Cam and its larger variants (spec 07 §3.1; SYNC8 "Tags of the cam
// technology object"; S004 L9106, L9551). Names as in the manual: Point[1..N] / ValidPoint[1..N],
// Segment[1..M] / ValidSegment[1..M], InterpolationSettings, StatusCam, StatusWord, ErrorWord, WarningWord,
// ErrorDetail. The arrays are sized once, when the TO is configured (CamVariant), and never resized: writing
// points and evaluating the cam never allocate.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/to_types.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {

// The cam TO types (spec 07 §3.1, §0.3). TO_Cam and TO_Cam_10k: SYNC8; TO_Cam_600Seg and TO_Cam_6kSeg: S004
// names only, their limits are [UNCONFIRMED] (spec 07 O-8): tomc gives them 600 / 6000 segments and the point
// capacity of TO_Cam / TO_Cam_10k (decisions C1).
enum class CamVariant : std::uint8_t { kCam, kCam10k, kCam600Seg, kCam6kSeg };

struct CamCapacity {
  std::size_t points;
  std::size_t segments;
};

constexpr CamCapacity capacity_of(CamVariant variant) noexcept {
  switch (variant) {
    case CamVariant::kCam:
      return {1000, 50};
    case CamVariant::kCam10k:
      return {10000, 50};
    case CamVariant::kCam600Seg:
      return {1000, 600};
    case CamVariant::kCam6kSeg:
      return {10000, 6000};
  }
  return {0, 0};
}

constexpr std::string_view type_name(CamVariant variant) noexcept {
  switch (variant) {
    case CamVariant::kCam:
      return "TO_Cam";
    case CamVariant::kCam10k:
      return "TO_Cam_10k";
    case CamVariant::kCam600Seg:
      return "TO_Cam_600Seg";
    case CamVariant::kCam6kSeg:
      return "TO_Cam_6kSeg";
  }
  return "?";
}

// TO_Cam_Struct_PointData: one point of the cam (LREAL ±1e12).
struct TO_Cam_Struct_PointData {
  double x = 0.0;
  double y = 0.0;
};

// TO_Cam_Struct_SegmentData: y(x) = a6·x⁶ + … + a1·x + a0 + sineAmplitude·sin(sinePeriod·x + sinePhase) on
// [xmin, xmax], x absolute (spec 07 §3.1, O-7 [OPEN]: absolute).
struct TO_Cam_Struct_SegmentData {
  double xmin = 0.0;
  double xmax = 0.0;
  double a0 = 0.0;
  double a1 = 0.0;
  double a2 = 0.0;
  double a3 = 0.0;
  double a4 = 0.0;
  double a5 = 0.0;
  double a6 = 0.0;
  double sineAmplitude = 0.0;
  double sinePeriod = 0.0;  // rad per leading-value unit
  double sinePhase = 0.0;   // rad
};

// InterpolationSettings.InterpolationMode (DINT).
enum class CamInterpolationMode : std::int32_t { kLinear = 0, kCubicSpline = 1, kBezierSpline = 2 };
// InterpolationSettings.BoundaryConditions (DINT).
enum class CamBoundaryConditions : std::int32_t { kNone = 0, kEqualFirstDerivative = 1 };

// <Cam>.StatusWord (spec 07 §3.1).
enum class CamStatusWordBit : std::uint8_t {
  kControl = 0,  // the cam is in use (by MC_CamIn)
  kError = 1,
  kRestartActive = 2,
  kOnlineStartValuesChanged = 3,
  kCamDataChanged = 4,  // the cam elements changed since the last MC_InterpolateCam
  kInterpolated = 5,
  kInInterpolation = 6,
  kCopyCamDataActive = 7,
};
using CamStatusWordBits = BitWord32<CamStatusWordBit>;

struct CamData {
  static constexpr TechnologyObjectType kTechnologyObjectType = TechnologyObjectType::kCam;

  explicit CamData(CamVariant variant = CamVariant::kCam)
      : Point(capacity_of(variant).points),
        ValidPoint(capacity_of(variant).points, 0),
        Segment(capacity_of(variant).segments),
        ValidSegment(capacity_of(variant).segments, 0) {}

  // CAL: the elements; 1-based in the manual, element i - 1 here. ValidPoint/ValidSegment are BOOL (stored as
  // bytes: std::vector<bool> has no addressable elements).
  std::vector<TO_Cam_Struct_PointData> Point;
  std::vector<std::uint8_t> ValidPoint;
  std::vector<TO_Cam_Struct_SegmentData> Segment;
  std::vector<std::uint8_t> ValidSegment;

  struct TO_Cam_Struct_InterpolationSettings {
    std::int32_t InterpolationMode = static_cast<std::int32_t>(CamInterpolationMode::kLinear);  // CAL
    std::int32_t BoundaryConditions = static_cast<std::int32_t>(CamBoundaryConditions::kNone);  // CAL
  } InterpolationSettings;

  // RON: the definition range after MC_InterpolateCam.
  struct TO_Cam_Struct_StatusCam {
    double StartLeadingValue = 0.0;
    double EndLeadingValue = 0.0;
    std::uint32_t NumberOfValidPoints = 0;
    std::uint32_t NumberOfValidSegments = 0;
  } StatusCam;

  std::uint32_t StatusWord = 0;  // RON, CamStatusWordBit
  std::uint32_t ErrorWord = 0;   // RON, X0…X3 as ErrorWordBit
  std::uint32_t WarningWord = 0;
  TO_Struct_ErrorDetail ErrorDetail;  // Reaction: 0 none, 9 terminate processing of the TO
};

// ---- reflection (variables.hpp): the scalar variables of the cam. Point[n]/Segment[n] are reached through
// the typed arrays (and MC_CopyCamData), not one table row per element of up to 10,000. ----
std::span<const VariableInfo> cam_variables() noexcept;
const VariableInfo* find_cam_variable(std::string_view path) noexcept;
std::optional<BitReference> find_cam_bit(std::string_view path) noexcept;

}  // namespace tomc::techobjects
