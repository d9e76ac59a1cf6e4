#include "tomc/techobjects/position/passive_homing.hpp"

#include <cmath>

#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"

namespace tomc::techobjects {

std::optional<double> PassiveHomingSearch::step(double v, const InputEdges& edges, std::optional<double> mark,
                                                EncoderChannel& encoder) noexcept {
  if (!active_) return std::nullopt;
  const double sign = config_.direction == 0 ? 1.0 : config_.direction == 1 ? -1.0 : 0.0;
  const bool moving = std::fabs(v) > config_.moving_threshold;
  const bool in_direction = moving && (sign == 0.0 || v * sign > 0.0);
  std::optional<double> found;
  switch (config_.method) {
    case static_cast<std::int32_t>(SensorHomingMode::kZeroMarkViaTelegram):
      // Armed only while moving in the homing direction (spec 02 §5.6).
      if (in_direction) {
        encoder.arm_reference_mark();
        found = mark;
      } else if (moving) {
        encoder.cancel_reference_mark();
      }
      break;
    case static_cast<std::int32_t>(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam):
      if (moving && !in_direction) {
        // A reversal after the cam: the cam must be detected again (spec 02 §5.6).
        cam_seen_ = cam_left_ = false;
        encoder.cancel_reference_mark();
      }
      if (in_direction && edges.entered) cam_seen_ = true;
      if (in_direction && cam_seen_ && edges.left) {
        cam_left_ = true;
        encoder.arm_reference_mark();
      }
      if (cam_left_) found = mark;
      break;
    default: {  // digital input: the configured side (spec 02 §5.4 table)
      const bool positive = v > 0.0;
      const bool entering_is_mark = positive ? !config_.side_input : config_.side_input;
      if (in_direction && (entering_is_mark ? edges.entered : edges.left)) found = edges.position;
      break;
    }
  }
  if (found) stop(encoder);
  return found;
}

}  // namespace tomc::techobjects
