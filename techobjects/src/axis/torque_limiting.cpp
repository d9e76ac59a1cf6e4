#include "tomc/techobjects/axis/torque_limiting.hpp"

#include <cmath>
#include <numbers>

#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

bool drive_torque_limit(ServoCommand& command, const tg::ActualSignals& actual,
                        TorqueLimitingRequest& request, double motor_limit, double reference, bool has_momred,
                        bool has_meldw) noexcept {
  const bool active = request.active;
  command.momred =
      active && has_momred ? tg::momred_from_torque_limit(motor_limit, reference) : std::uint16_t{0};
  // Set while MC_TorqueLimiting is active, so that the drive does not fault at the limit (spec 01 §8.13
  // table, last row: MC_TorqueLimiting sets it, MC_TorqueRange does not).
  if (active != request.stw2_fixed_stop) {
    command.travel_to_fixed_stop = active;
    request.stw2_fixed_stop = active;
  }
  return active && has_meldw && !actual.MELDW.test(tg::MeldwBit::kTorqueUtilisationBelowThreshold);
}

double motor_torque_limit(double limit, const TorqueLimitMechanics& m) noexcept {
  if (m.linear_motor || !m.load_side) return limit;  // spec 01 §8.10: linear motor and motor side as given
  const double i = m.gear_ratio > 0.0 ? m.gear_ratio : 1.0;
  const double eta = m.efficiency > 0.0 ? m.efficiency : 1.0;
  if (m.linear_axis) return limit * m.leadscrew_per_rev / (2.0 * std::numbers::pi * i * eta);
  return limit / (i * eta);
}

ClampingEvent ClampingMonitor::update(double following_error, double actual_position,
                                      bool moving_away) noexcept {
  if (!clamped_) {
    // Fixed stop reached: the following error grows past the configured deviation (seed 004 §6.7.9.2).
    if (std::fabs(following_error) <= deviation_) return ClampingEvent::kNone;
    clamped_ = true;
    clamp_position_ = actual_position;
    direction_ = following_error > 0.0 ? 1.0 : -1.0;  // the setpoint lies beyond the stop
    return ClampingEvent::kClamped;
  }
  const double moved = actual_position - clamp_position_;
  if (std::fabs(moved) <= tolerance_) return ClampingEvent::kNone;
  // Leaving the tolerance ends clamping: released only by a position-controlled job away from the stop,
  // otherwise the stop broke or gave way (seed 004 §6.7.9.2 "Controllo del bloccaggio").
  const bool released = moving_away && moved * direction_ < 0.0;
  reset();
  return released ? ClampingEvent::kReleased : ClampingEvent::kLost;
}

}  // namespace tomc::techobjects
