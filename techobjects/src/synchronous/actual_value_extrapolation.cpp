#include "tomc/techobjects/synchronous/actual_value_extrapolation.hpp"

#include <cmath>

namespace tomc::techobjects {

namespace {

// A PT1 stage, backward Euler: time constant 0 passes the input through.
double pt1(double state, double input, double time_constant, double cycle) noexcept {
  if (!(time_constant > 0.0)) return input;
  return state + cycle / (time_constant + cycle) * (input - state);
}

}  // namespace

ExtrapolationConfig extrapolation_config(TO_Struct_Extrapolation& e, double ti, double ipo_cycle_s,
                                         double velocity_factor) noexcept {
  ExtrapolationConfig c;
  c.position_t1 = e.PositionFilter.T1;
  c.position_t2 = e.PositionFilter.T2;
  c.velocity_t1 = e.VelocityFilter.T1;
  c.velocity_t2 = e.VelocityFilter.T2;
  c.tolerance_range = e.VelocityTolerance.Range / velocity_factor;
  c.hysteresis = e.Hysteresis.Value;
  c.velocity_mode = e.Settings.ExtrapolatedVelocityMode;
  c.cycle = ipo_cycle_s;
  const bool system = e.Settings.SystemDefinedExtrapolation != 0;
  e.LeadingAxisDependentTime = system ? ti + ipo_cycle_s + c.position_t1 + c.position_t2 : 0.0;
  if (!system) c.position_t1 = c.position_t2 = 0.0;  // the position filter goes with the system part
  c.time = e.LeadingAxisDependentTime + e.FollowingAxisDependentTime;
  return c;
}

void show_extrapolation(const ActualValueExtrapolation& e, double velocity_factor,
                        TO_Struct_StatusExtrapolation& status) noexcept {
  status.FilteredPosition = e.filtered_position();
  status.FilteredVelocity = e.filtered_velocity() * velocity_factor;
  status.ExtrapolatedPosition = e.extrapolated_position();
  status.ExtrapolatedVelocity = e.velocity() * velocity_factor;
}

void ActualValueExtrapolation::reset(double position, double velocity) noexcept {
  position_stage1_ = position_stage2_ = position;
  velocity_stage1_ = velocity_stage2_ = band_output_ = velocity;
  acceleration_ = 0.0;
  extrapolated_ = output_position_ = position;
  output_velocity_ = velocity;
  direction_ = 0;
  started_ = true;
}

void ActualValueExtrapolation::update(double x, double v) noexcept {
  if (!started_) reset(x, v);
  const double T = config_.cycle;
  // 1. position filter PT2, 2. velocity filter PT2 and tolerance band (spec 07 §1.4).
  position_stage1_ = pt1(position_stage1_, x, config_.position_t1, T);
  position_stage2_ = pt1(position_stage2_, position_stage1_, config_.position_t2, T);
  velocity_stage1_ = pt1(velocity_stage1_, v, config_.velocity_t1, T);
  velocity_stage2_ = pt1(velocity_stage2_, velocity_stage1_, config_.velocity_t2, T);
  const double previous_band = band_output_;
  const double half = 0.5 * config_.tolerance_range;
  if (half <= 0.0) {
    band_output_ = velocity_stage2_;
  } else if (velocity_stage2_ > band_output_ + half) {
    band_output_ = velocity_stage2_ - half;  // "the filtered velocity minus half the tolerance band"
  } else if (velocity_stage2_ < band_output_ - half) {
    band_output_ = velocity_stage2_ + half;
  }
  acceleration_ = (band_output_ - previous_band) / T;
  // 3. extrapolation over T_ext: exact at constant velocity and constant acceleration ([IMPL] formula).
  const double t = config_.time;
  extrapolated_ = position_stage2_ + band_output_ * t + 0.5 * acceleration_ * t * t;
  // 4. hysteresis: a reversal counts once the value moved back by more than Hysteresis.Value.
  const double previous_output = output_position_;
  const double h = config_.hysteresis;
  if (h <= 0.0) {
    output_position_ = extrapolated_;
  } else if (direction_ >= 0) {
    if (extrapolated_ > output_position_) {
      output_position_ = extrapolated_;
      direction_ = 1;
    } else if (extrapolated_ < output_position_ - h) {
      output_position_ = extrapolated_;
      direction_ = -1;
    }
  } else {
    if (extrapolated_ < output_position_) {
      output_position_ = extrapolated_;
    } else if (extrapolated_ > output_position_ + h) {
      output_position_ = extrapolated_;
      direction_ = 1;
    }
  }
  // 5. velocity of the leading value (V10 ExtrapolatedVelocityMode, decision Y4).
  output_velocity_ = config_.velocity_mode == 2 ? (output_position_ - previous_output) / T : band_output_;
}

}  // namespace tomc::techobjects
