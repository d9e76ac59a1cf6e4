#include "tomc/techobjects/motion/time_position_source.hpp"

#include <algorithm>
#include <cmath>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace tomc::techobjects {

std::uint16_t TimePositionSource::validate(double start_time) const noexcept {
  if (cam_ == nullptr) return techobjects::validate(points_, start_time);
  if (!cam_->interpolated() || cam_->profile().empty()) return error_id::kCamNotInterpolated;
  const CamProfile& p = cam_->profile();
  if (!std::isfinite(start_time) || start_time < p.start() || start_time >= p.end())
    return error_id::kInvalidStartTime;
  // "When the end position of the profile is reached, the axis stops" (seed 004 §9.7.1): a cam that still
  // moves there would stop with a velocity step.
  const double mean_velocity =
      std::fabs(p.evaluate(p.end()).y - p.evaluate(p.start()).y) / (p.end() - p.start());
  if (std::fabs(p.evaluate(p.end()).dy) > 1e-9 * std::max(1.0, mean_velocity))
    return error_id::kProfileNotAtRestAtEnd;
  return 0;
}

std::uint16_t TimePositionSource::still_valid() const noexcept {
  if (cam_ != nullptr)
    return cam_->interpolated() && !cam_->profile().empty() ? 0 : error_id::kCamNotInterpolated;
  if (points_ == nullptr || points_->NumberOfPoints < 2 ||
      points_->NumberOfPoints > static_cast<std::int32_t>(kMaxTimePositionPoints))
    return error_id::kInvalidTimePositionProfile;
  return 0;
}

MotionState TimePositionSource::evaluate(double time) const noexcept {
  if (cam_ == nullptr) return techobjects::evaluate(*points_, time);
  const CamProfile& p = cam_->profile();
  const CamValue v = p.evaluate(std::clamp(time, p.start(), p.end()));
  return MotionState{v.y, v.dy, v.ddy};  // x is time: dy/dx is the velocity, d²y/dx² the acceleration
}

double TimePositionSource::end_time() const noexcept {
  return cam_ != nullptr ? cam_->profile().end() : techobjects::end_time(*points_);
}

ProfileDynamics TimePositionSource::max_dynamics(double start_time) const noexcept {
  if (cam_ != nullptr) return ProfileDynamics{};
  return techobjects::max_dynamics(*points_, start_time);
}

}  // namespace tomc::techobjects
