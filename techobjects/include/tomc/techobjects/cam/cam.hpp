#pragma once
// TO_Cam (and TO_Cam_10k, TO_Cam_600Seg, TO_Cam_6kSeg; spec 07 §3): a unit-neutral transfer function
// y = f(x) defined by points and segments, interpolated by MC_InterpolateCam, read by MC_GetCamFollowingValue
// / MC_GetCamLeadingValue, filled by MC_CopyCamData, and evaluated every cycle by the followers that camm
// with it (profile()).
//
// The cam does nothing in MC_Servo / MC_Interpolator: its instructions complete within the call of the user
// program (decisions C2), and followers read profile() in their own cycle. MC_InterpolateCam allocates its
// work space (Eigen) and is refused while a follower uses the cam (16#80AB); everything a follower calls is
// noexcept and allocation-free.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "tomc/techobjects/axis/job.hpp"
#include "tomc/techobjects/axis/job_inputs.hpp"
#include "tomc/techobjects/cam/cam_data.hpp"
#include "tomc/techobjects/cam/cam_interpolation.hpp"
#include "tomc/techobjects/cam/cam_profile.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::techobjects {

// MC_CopyCamData inputs (spec 07 §3.6). StartPointCam / StartSegmentCam are 1-based like Point[1..N];
// StartPointArray / StartSegmentArray index the given arrays from 0 (a C++ span has no declared lower bound).
struct CopyCamDataInputs {
  std::int32_t Mode = 0;  // 0: invalidate every element of the cam first; 1: keep the others
  std::int32_t StartPointCam = 1;
  std::int32_t StartSegmentCam = 1;
  std::int32_t StartPointArray = 0;
  std::int32_t StartSegmentArray = 0;
  std::int32_t NumberOfPoints = 0;
  std::int32_t NumberOfSegments = 0;
  std::span<const TO_Cam_Struct_PointData> ArrayOfPoints;
  std::span<const TO_Cam_Struct_SegmentData> ArrayOfSegments;
};

class Cam final : public TechnologyObject {
 public:
  // `number` stands for the cam's DB number, which StatusSynchronizedMotion.ActualCam of a follower shows
  // (decision C8); machine files give each TO its 1-based place in the file.
  explicit Cam(std::string name, CamVariant variant = CamVariant::kCam, std::uint16_t number = 1);
  Cam(const Cam&) = delete;  // followers keep a reference; the profile's reserved capacity is not copied
  Cam& operator=(const Cam&) = delete;

  // ---- TechnologyObject: nothing cyclic ----
  std::string_view name() const noexcept override { return name_; }
  void servo(const CycleClock&) noexcept override {}
  void interpolate(const CycleClock&) noexcept override {}

  CamVariant variant() const noexcept { return variant_; }
  std::uint16_t number() const noexcept { return number_; }
  const CamData& data() const noexcept { return db_; }
  const CamProfile& profile() const noexcept { return profile_; }
  bool interpolated() const noexcept { return status().test(CamStatusWordBit::kInterpolated); }

  // ---- the elements, as the user program writes them (CAL: effective with the next MC_InterpolateCam) ----
  // `index` is 1-based as Point[1..N]; false if it is outside the cam's array.
  bool write_point(std::size_t index, const TO_Cam_Struct_PointData& point, bool valid) noexcept;
  bool write_segment(std::size_t index, const TO_Cam_Struct_SegmentData& segment, bool valid) noexcept;
  // The scalar variables (InterpolationSettings.*; the status variables are read-only).
  WriteResult write(std::string_view path, double value) noexcept;
  double read(std::string_view path) const noexcept;

  // ---- instructions (spec 07 §3.2, §3.6); each completes within its call ----
  Submission interpolate_cam() noexcept;  // MC_InterpolateCam
  CamLookup get_following_value(double leading_value, const CamScaling& scaling) const noexcept;
  CamLookup get_leading_value(double following_value, double approach, std::int32_t direction,
                              const CamScaling& scaling) const noexcept;
  Submission copy_cam_data(const CopyCamDataInputs& in) noexcept;  // MC_CopyCamData
  // Instant jobs: accepted ones are done (the id only identifies the call).
  JobStatus job_status(JobId id) const noexcept {
    return id != 0 && id <= last_job_ ? JobStatus{JobState::kDone, 0, false} : JobStatus{};
  }
  // How many times MC_InterpolateCam rebuilt (or began to rebuild) the profile: a reader outside the cycle
  // (the diagnostics page's cam plot) compares it before and after reading profile().
  std::uint32_t interpolation_count() const noexcept { return interpolation_count_; }
  // Why the last MC_InterpolateCam failed (kNone after a success).
  const CamInterpolationResult& last_interpolation() const noexcept { return last_interpolation_; }

  // ---- use by camming (StatusWord.X0 Control) ----
  void acquire() noexcept;
  void release() noexcept;
  std::uint32_t users() const noexcept { return users_; }

 private:
  CamStatusWordBits status() const noexcept { return CamStatusWordBits{db_.StatusWord}; }
  void set_status(CamStatusWordBit bit, bool on) noexcept;
  void count_valid_elements() noexcept;
  JobId next_job() noexcept { return ++last_job_; }

  std::string name_;
  std::uint16_t number_;
  CamVariant variant_;
  CamData db_;
  CamProfile profile_;
  CamInterpolationResult last_interpolation_{};
  std::uint32_t users_ = 0;
  std::uint32_t interpolation_count_ = 0;
  JobId last_job_ = 0;
};

}  // namespace tomc::techobjects
