#include "tomc/techobjects/position/position_control.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::techobjects {

namespace {

constexpr double kMaxDelayCycles = static_cast<double>(kMaxSetpointDelayCycles - 1);
constexpr double kMaxKpc = 150.0;  // spec 02 §7.3 range of Kpc

bool non_negative_finite(double v) noexcept {
  return std::isfinite(v) && v >= 0.0;
}

}  // namespace

// ---- PositionController ----

PositionController::PositionController() noexcept {
  configure(PositionControlConfig{});
}

// An invalid configuration leaves the defaults in place.
PositionController::PositionController(const PositionControlConfig& config) noexcept : PositionController() {
  configure(config);
}

PositionControlConfigResult PositionController::configure(const PositionControlConfig& config) noexcept {
  if (!std::isfinite(config.ServoCycle) || config.ServoCycle <= 0.0) {
    return PositionControlConfigResult::kInvalidServoCycle;
  }
  if (!non_negative_finite(config.Kv) || !non_negative_finite(config.Kpc) ||
      !non_negative_finite(config.VelocityTimeConstant) ||
      !non_negative_finite(config.AdditionalSetpointDelayTime) || !non_negative_finite(config.Ti) ||
      !non_negative_finite(config.To) || !non_negative_finite(config.Tdc) ||
      !non_negative_finite(config.ControlDifferenceQuantization)) {
    return PositionControlConfigResult::kInvalidParameter;
  }
  PidGains gains;
  gains.Kv = config.Kv;
  gains.IntegralTime = config.IntegralTime;
  gains.DerivativeTime = config.DerivativeTime;
  gains.DerivativeCycles = config.DerivativeCycles;
  gains.IntegralLimit = config.IntegralLimit;
  gains.DeadBand = config.DeadBand;
  gains.OutputLimit = config.OutputLimit;
  const bool pid_option = gains.IntegralTime != 0.0 || gains.DerivativeTime != 0.0 || gains.DeadBand != 0.0 ||
                          gains.OutputLimit != 0.0;
  if ((pid_option && config.EnableDSC) || !pid_.configure(gains, config.ServoCycle)) {
    return PositionControlConfigResult::kInvalidParameter;
  }
  kv_ = config.Kv;
  quantization_ = config.ControlDifferenceQuantization;
  dsc_ = config.EnableDSC;
  const double ts = config.ServoCycle;
  kpc_ = std::min(config.Kpc, kMaxKpc) / 100.0;
  symmetry_gain_ = ts / (config.VelocityTimeConstant + ts);
  const double control = (config.Ti + config.To + config.Tdc + ts) / ts;
  const double fe = control + config.AdditionalSetpointDelayTime / ts;
  delay_clamped_ = control > kMaxDelayCycles || fe > kMaxDelayCycles;
  control_delay_cycles_ = std::min(control, kMaxDelayCycles);
  fe_delay_cycles_ = std::min(fe, kMaxDelayCycles);
  control_tap_ = SetpointDelayLine::tap(control_delay_cycles_);
  fe_tap_ = SetpointDelayLine::tap(fe_delay_cycles_);
  reset();
  return delay_clamped_ ? PositionControlConfigResult::kDelayClamped : PositionControlConfigResult::kOk;
}

void PositionController::reset() noexcept {
  started_ = false;
  symmetry_state_ = 0.0;
  pid_.reset();
}

PositionControlOutput PositionController::update(const PositionControlInput& in) noexcept {
  if (!started_) {
    control_line_.fill(in.position_setpoint);
    fe_line_.fill(in.interpolator_position);
    symmetry_state_ = in.position_setpoint;
    started_ = true;
  } else {
    control_line_.push(in.position_setpoint);
    fe_line_.push(in.interpolator_position);
  }

  const double x_d = control_line_.delayed(control_tap_);
  symmetry_state_ += symmetry_gain_ * (x_d - symmetry_state_);
  const double x_sym = kpc_ * symmetry_state_ + (1.0 - kpc_) * x_d;
  const double e = x_sym - in.actual_position;
  // spec 01 §3.11 / spec 02 §7.4 (4): the controller sees q·trunc(e/q); |e| < q -> 0.
  const double q = quantization_;
  const double e_controlled = q > 0.0 ? q * std::trunc(e / q) : e;
  const double precontrol = kpc_ * in.velocity_setpoint;

  PositionControlOutput out;
  out.balanced_position = x_sym;
  out.control_difference = e;
  out.following_error = fe_line_.delayed(fe_tap_) - in.actual_position;
  if (dsc_) {
    out.velocity_setpoint = precontrol;
    out.dsc_position_error = e_controlled;
    out.dsc_kpc = kv_;
  } else {
    out.pid = pid_.update(e_controlled);
    out.velocity_setpoint = precontrol + out.pid.output;
  }
  return out;
}

}  // namespace tomc::techobjects
