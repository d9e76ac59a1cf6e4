// TO_Cam (cam.hpp; spec 07 §3).
#include "tomc/techobjects/cam/cam.hpp"

#include <algorithm>
#include <new>
#include <utility>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/datablocks/data_block_access.hpp"

namespace tomc::techobjects {

namespace {
constexpr DataBlockTable<CamData> kTable{&find_cam_variable, &find_cam_bit};
}  // namespace

Cam::Cam(std::string name, CamVariant variant, std::uint16_t number)
    : name_(std::move(name)),
      number_(number),
      variant_(variant),
      db_(variant),
      profile_(profile_capacity(capacity_of(variant))) {}

void Cam::set_status(CamStatusWordBit bit, bool on) noexcept {
  assign(db_.StatusWord, bit, on);
}

bool Cam::write_point(std::size_t index, const TO_Cam_Struct_PointData& point, bool valid) noexcept {
  if (index < 1 || index > db_.Point.size()) return false;
  db_.Point[index - 1] = point;
  db_.ValidPoint[index - 1] = valid ? 1 : 0;
  set_status(CamStatusWordBit::kCamDataChanged, true);
  return true;
}

bool Cam::write_segment(std::size_t index, const TO_Cam_Struct_SegmentData& segment, bool valid) noexcept {
  if (index < 1 || index > db_.Segment.size()) return false;
  db_.Segment[index - 1] = segment;
  db_.ValidSegment[index - 1] = valid ? 1 : 0;
  set_status(CamStatusWordBit::kCamDataChanged, true);
  return true;
}

WriteResult Cam::write(std::string_view path, double value) noexcept {
  const WriteResult r = kTable.write(db_, path, value);
  if (r.ok()) set_status(CamStatusWordBit::kCamDataChanged, true);
  return r;
}

double Cam::read(std::string_view path) const noexcept {
  return kTable.read(db_, path);
}

void Cam::count_valid_elements() noexcept {
  db_.StatusCam.NumberOfValidPoints =
      static_cast<std::uint32_t>(std::count(db_.ValidPoint.begin(), db_.ValidPoint.end(), 1));
  db_.StatusCam.NumberOfValidSegments =
      static_cast<std::uint32_t>(std::count(db_.ValidSegment.begin(), db_.ValidSegment.end(), 1));
}

Submission Cam::interpolate_cam() noexcept {
  // spec 07 §3.2: not while a follower uses the cam; the profile in use stays as it is.
  if (users_ > 0) return Submission::reject(error_id::kCamInUse);
  ++interpolation_count_;  // before the profile changes (diagnostics, cam plot)
  set_status(CamStatusWordBit::kInInterpolation, true);
  try {
    last_interpolation_ = ::tomc::techobjects::interpolate_cam(db_, profile_);
  } catch (const std::bad_alloc&) {  // the work space (decisions C2): reported, never thrown into the cycle
    profile_.clear();
    last_interpolation_ = {error_id::kCamInvalid, CamDefect::kCapacity, 0};
  }
  set_status(CamStatusWordBit::kInInterpolation, false);
  count_valid_elements();
  const bool ok = last_interpolation_.error_id == 0;
  set_status(CamStatusWordBit::kInterpolated, ok);
  if (!ok) return Submission::reject(last_interpolation_.error_id);
  set_status(CamStatusWordBit::kCamDataChanged, false);
  db_.StatusCam.StartLeadingValue = profile_.start();
  db_.StatusCam.EndLeadingValue = profile_.end();
  return Submission::accept(next_job());
}

CamLookup Cam::get_following_value(double leading_value, const CamScaling& scaling) const noexcept {
  if (!interpolated()) return CamLookup{error_id::kCamNotInterpolated, {}, 0.0};
  return following_value(profile_, leading_value, scaling);
}

CamLookup Cam::get_leading_value(double following_value, double approach, std::int32_t direction,
                                 const CamScaling& scaling) const noexcept {
  if (!interpolated()) return CamLookup{error_id::kCamNotInterpolated, {}, 0.0};
  return leading_value(profile_, following_value, approach, direction, scaling);
}

Submission Cam::copy_cam_data(const CopyCamDataInputs& in) noexcept {
  if (in.Mode != 0 && in.Mode != 1) return Submission::reject(error_id::kInvalidMode);
  // [first, first + count) must lie in the target (1-based) and in the source (0-based).
  const auto fits = [](std::int32_t target_start, std::int32_t source_start, std::int32_t count,
                       std::size_t target_size, std::size_t source_size) {
    if (count < 0 || target_start < 1 || source_start < 0) return false;
    const auto n = static_cast<std::size_t>(count);
    return static_cast<std::size_t>(target_start) - 1 + n <= target_size &&
           static_cast<std::size_t>(source_start) + n <= source_size;
  };
  if (!fits(in.StartPointCam, in.StartPointArray, in.NumberOfPoints, db_.Point.size(),
            in.ArrayOfPoints.size()) ||
      !fits(in.StartSegmentCam, in.StartSegmentArray, in.NumberOfSegments, db_.Segment.size(),
            in.ArrayOfSegments.size())) {
    return Submission::reject(error_id::kInvalidCamElementRange);
  }
  set_status(CamStatusWordBit::kCopyCamDataActive, true);
  if (in.Mode == 0) {
    std::fill(db_.ValidPoint.begin(), db_.ValidPoint.end(), 0);
    std::fill(db_.ValidSegment.begin(), db_.ValidSegment.end(), 0);
  }
  for (std::int32_t i = 0; i < in.NumberOfPoints; ++i) {
    const auto target = static_cast<std::size_t>(in.StartPointCam - 1 + i);
    db_.Point[target] = in.ArrayOfPoints[static_cast<std::size_t>(in.StartPointArray + i)];
    db_.ValidPoint[target] = 1;
  }
  for (std::int32_t i = 0; i < in.NumberOfSegments; ++i) {
    const auto target = static_cast<std::size_t>(in.StartSegmentCam - 1 + i);
    db_.Segment[target] = in.ArrayOfSegments[static_cast<std::size_t>(in.StartSegmentArray + i)];
    db_.ValidSegment[target] = 1;
  }
  set_status(CamStatusWordBit::kCopyCamDataActive, false);
  set_status(CamStatusWordBit::kCamDataChanged, true);
  count_valid_elements();
  return Submission::accept(next_job());
}

void Cam::acquire() noexcept {
  ++users_;
  set_status(CamStatusWordBit::kControl, true);
}

void Cam::release() noexcept {
  if (users_ > 0) --users_;
  set_status(CamStatusWordBit::kControl, users_ > 0);
}

}  // namespace tomc::techobjects
