#include "tomc/techobjects/position/position_monitoring.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::techobjects {

namespace {

constexpr double kRelativeTimeTolerance = 1e-9;
constexpr double kMaxCycles = 1e18;  // 1.0E12 s / 1 µs; keeps the cycle counts inside std::uint64_t

bool non_negative_finite(double v) noexcept {
  return std::isfinite(v) && v >= 0.0;
}

double cycles_of(double time, double servo_cycle) noexcept {
  return std::min(time / servo_cycle, kMaxCycles);
}

// floor(time/Ts), tolerant to the rounding of e.g. 0.3/0.1 = 2.9999999999999996.
std::uint64_t floor_cycles(double time, double servo_cycle) noexcept {
  const double q = cycles_of(time, servo_cycle);
  return static_cast<std::uint64_t>(std::floor(q + kRelativeTimeTolerance * std::max(1.0, q)));
}

// ceil(time/Ts), tolerant to the rounding of e.g. 0.01/0.001 = 10.000000000000002.
std::uint64_t ceil_cycles(double time, double servo_cycle) noexcept {
  const double q = cycles_of(time, servo_cycle);
  return static_cast<std::uint64_t>(std::max(0.0, std::ceil(q - kRelativeTimeTolerance * std::max(1.0, q))));
}

std::uint64_t saturating_increment(std::uint64_t v) noexcept {
  return v == UINT64_MAX ? v : v + 1;
}

}  // namespace

// ---- FollowingErrorMonitor (spec 02 §6.2) ----

double FollowingErrorMonitor::permitted(double setpoint_velocity) const noexcept {
  const double v = std::fabs(setpoint_velocity);
  const auto& c = config_;
  if (!(v > c.MinVelocity)) return c.MinValue;  // also catches a NaN velocity
  if (c.MaxVelocity <= c.MinVelocity || v >= c.MaxVelocity) return c.MaxValue;
  return c.MinValue + (c.MaxValue - c.MinValue) * (v - c.MinVelocity) / (c.MaxVelocity - c.MinVelocity);
}

FollowingErrorCheck FollowingErrorMonitor::check(double following_error,
                                                 double setpoint_velocity) const noexcept {
  FollowingErrorCheck result;
  result.permitted = permitted(setpoint_velocity);
  result.warning_threshold = config_.WarningLevel / 100.0 * result.permitted;
  if (!config_.EnableMonitoring) return result;
  const double fe = std::fabs(following_error);
  if (std::isnan(fe) || fe > result.permitted) {
    result.alarm = FollowingErrorAlarm::kError521;
  } else if (fe >= result.warning_threshold) {
    result.alarm = FollowingErrorAlarm::kWarning522;
  }
  return result;
}

// ---- PositioningMonitor (spec 02 §6.1) ----

bool PositioningMonitor::configure(const PositioningMonitoringConfig& config) noexcept {
  if (!std::isfinite(config.ServoCycle) || config.ServoCycle <= 0.0 || !non_negative_finite(config.Window) ||
      !non_negative_finite(config.ToleranceTime) || !non_negative_finite(config.MinDwellTime)) {
    return false;
  }
  config_ = config;
  tolerance_cycles_ = floor_cycles(config.ToleranceTime, config.ServoCycle);
  dwell_cycles_ = ceil_cycles(config.MinDwellTime, config.ServoCycle);
  return true;
}

void PositioningMonitor::start(double target_position) noexcept {
  target_ = target_position;
  state_ = State::kWaitEnter;
  elapsed_ = 0;
  dwell_ = 0;
  status_ = PositioningStatus{PositioningOutcome::kInProgress, 0};
}

void PositioningMonitor::cancel() noexcept {
  state_ = State::kIdle;
  status_ = PositioningStatus{};
}

void PositioningMonitor::complete() noexcept {
  state_ = State::kFinished;
  status_ = PositioningStatus{PositioningOutcome::kDone, 0};
}

PositioningStatus PositioningMonitor::update(double actual_position) noexcept {
  if (state_ == State::kIdle || state_ == State::kFinished) return status_;
  const bool in = std::fabs(target_ - actual_position) <= config_.Window;  // NaN counts as outside
  if (state_ == State::kWaitEnter) {
    if (in) {
      state_ = State::kDwell;
      dwell_ = 0;
    } else if (elapsed_ > tolerance_cycles_) {
      state_ = State::kFinished;
      status_ = PositioningStatus{PositioningOutcome::kFault, kPositioningTargetNotReached};
      return status_;
    }
  } else if (!in) {  // kDwell
    state_ = State::kFinished;
    status_ = PositioningStatus{PositioningOutcome::kFault, kPositioningTargetLeft};
    return status_;
  }
  if (state_ == State::kDwell) {
    if (dwell_ >= dwell_cycles_) {
      state_ = State::kFinished;
      status_ = PositioningStatus{PositioningOutcome::kDone, 0};
      return status_;
    }
    dwell_ = saturating_increment(dwell_);
  }
  elapsed_ = saturating_increment(elapsed_);
  return status_;
}

// ---- StandstillSignal (spec 02 §6.3) ----

bool StandstillSignal::configure(const StandstillSignalConfig& config) noexcept {
  if (!std::isfinite(config.ServoCycle) || config.ServoCycle <= 0.0 ||
      !non_negative_finite(config.VelocityThreshold) || !non_negative_finite(config.MinDwellTime)) {
    return false;
  }
  config_ = config;
  dwell_cycles_ = std::max<std::uint64_t>(1, ceil_cycles(config.MinDwellTime, config.ServoCycle));
  return true;
}

bool StandstillSignal::update(double actual_velocity) noexcept {
  const double v = std::fabs(actual_velocity);
  if (v <= config_.VelocityThreshold) {
    counter_ = saturating_increment(counter_);
    if (counter_ >= dwell_cycles_) standstill_ = true;
  } else if (!(v <= config_.VelocityThreshold * (1.0 + kStandstillHysteresis))) {  // NaN leaves too
    counter_ = 0;
    standstill_ = false;
  }
  return standstill_;
}

}  // namespace tomc::techobjects
