// The synchronous function of camming (cam_synchronous_function.hpp; spec 07 §3.3, §6.2).
#include "tomc/techobjects/cam/cam_synchronous_function.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::techobjects {

void CamSynchronousFunction::start(const CamProfile& cam, const CamScaling& scaling,
                                   CamApplicationMode mode) noexcept {
  cam_ = cam.empty() ? nullptr : &cam;
  scaling_ = scaling;
  mode_ = mode;
  last_period_ = 0;
  piece_ = 0;
  first_ = true;
  period_gain_ = cam_ == nullptr ? 0.0 : cam.evaluate(cam.end()).y - cam.evaluate(cam.start()).y;
}

CamFollowingValue CamSynchronousFunction::evaluate(double x, double v, double a) noexcept {
  CamFollowingValue out;
  if (cam_ == nullptr || scaling_.MasterScaling == 0.0) return out;
  const double start = cam_->start();
  const double end = cam_->end();
  const double period_length = end - start;
  const double u = (x - scaling_.MasterOffset) / scaling_.MasterScaling;
  double u_cam = u;
  double appended = 0.0;
  std::int64_t n = 0;
  if (mode_ == CamApplicationMode::kNotCyclic) {
    if (u < start || u > end) {
      out.ended = true;
      u_cam = u < start ? start : end;
    }
  } else if (period_length > 0.0) {
    // The period count of a leading value 1e18 cam lengths away is meaningless; the clamp keeps the cast
    // defined.
    const double periods = std::clamp(std::floor((u - start) / period_length), -4.0e18, 4.0e18);
    n = std::isfinite(periods) ? static_cast<std::int64_t>(periods) : 0;
    u_cam = u - static_cast<double>(n) * period_length;
    // Rounding can leave u_cam a hair outside [start, end): the cam's own ends hold there.
    if (u_cam < start) u_cam = start;
    if (u_cam > end) u_cam = end;
    if (mode_ == CamApplicationMode::kCyclicAppending) {
      appended = static_cast<double>(n) * period_gain_;
    }
  }
  piece_ = cam_->find(u_cam, piece_);
  const CamValue f = CamProfile::evaluate(cam_->pieces()[piece_], u_cam);
  const double ms = scaling_.MasterScaling;
  const double ss = scaling_.SlaveScaling;
  out.position = ss * (f.y + appended) + scaling_.SlaveOffset;
  if (!out.ended) {
    out.velocity = ss * f.dy * v / ms;
    out.acceleration = ss * (f.ddy * v * v / (ms * ms) + f.dy * a / ms);
  }
  out.period = n;
  out.end_of_profile = out.ended || (!first_ && n != last_period_);
  last_period_ = n;
  first_ = false;
  return out;
}

}  // namespace tomc::techobjects
