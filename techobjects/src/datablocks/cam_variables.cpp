// The reflection table of TO_Cam (spec 07 §3.1; SYNC8 "Tags of the cam technology object"): the scalar
// variables. Point[n] / Segment[n] are reached through Cam::write_point / write_segment and MC_CopyCamData.
#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "tomc/techobjects/cam/cam_data.hpp"
#include "tomc/techobjects/datablocks/variable_table_support.hpp"

namespace tomc::techobjects {
namespace {

using detail::kAny;
using detail::kDintMax;
using detail::kDintMin;
using detail::kLrealMax;
using detail::kLrealMin;
using detail::kUdintMax;

// ErrorDetail.Reaction of the cam: 0 none, 9 terminate processing of the TO (spec 07 §3.1).
constexpr std::array<double, 2> kReactionValues{0.0, 9.0};

#define TOMC_C_ROW(...) TOMC_DB_ROW(CamData, kCam, __VA_ARGS__)
#define TOMC_C_VARIABLE(member, ...) TOMC_C_ROW(#member, member, __VA_ARGS__)

// clang-format off
constexpr auto kCamVariables = std::to_array<VariableInfo>({
    TOMC_C_VARIABLE(InterpolationSettings.InterpolationMode, kDint, kCAL, kConfiguration, 0.0, 2.0, kAny, 0),
    TOMC_C_VARIABLE(InterpolationSettings.BoundaryConditions, kDint, kCAL, kConfiguration, 0.0, 1.0, kAny, 0),
    TOMC_C_VARIABLE(StatusCam.StartLeadingValue, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_C_VARIABLE(StatusCam.EndLeadingValue, kLreal, kRON, kStatus, kLrealMin, kLrealMax, kAny, 0),
    TOMC_C_VARIABLE(StatusCam.NumberOfValidPoints, kUdint, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_C_VARIABLE(StatusCam.NumberOfValidSegments, kUdint, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_C_VARIABLE(StatusWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_C_VARIABLE(ErrorWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_C_VARIABLE(WarningWord, kDword, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_C_VARIABLE(ErrorDetail.Number, kUdint, kRON, kStatus, 0.0, kUdintMax, kAny, 0),
    TOMC_C_VARIABLE(ErrorDetail.Reaction, kDint, kRON, kStatus, kDintMin, kDintMax, kReactionValues, 0),
});
// clang-format on

#undef TOMC_C_VARIABLE
#undef TOMC_C_ROW

static_assert(detail::paths_unique(kCamVariables), "duplicate path in the cam table");
static_assert(detail::ranges_valid(kCamVariables),
              "a cam range is empty, exceeds its data type or excludes a permitted value");

}  // namespace

std::span<const VariableInfo> cam_variables() noexcept {
  return kCamVariables;
}

const VariableInfo* find_cam_variable(std::string_view path) noexcept {
  return find_variable(kCamVariables, path);
}

std::optional<BitReference> find_cam_bit(std::string_view path) noexcept {
  return find_bit(kCamVariables, path);
}

}  // namespace tomc::techobjects
