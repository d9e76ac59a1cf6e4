#include "tomc/techobjects/position/limit_switches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tomc::techobjects::limits {

namespace {

constexpr double kRelativeTolerance = 1.0E-9;

// Position tolerance around a limit (rounding of setpoints that are clamped to the limit).
double tolerance(double x) noexcept {
  return kRelativeTolerance * std::max(1.0, std::fabs(x));
}

constexpr std::uint32_t bit(unsigned n) noexcept {
  return std::uint32_t{1} << n;
}

// State (p, v, a) integrated over one constant-jerk segment.
struct Motion {
  double p = 0.0;
  double v = 0.0;
  double a = 0.0;
  void segment(double jerk, double t) noexcept {
    if (!(t > 0.0)) return;
    p += v * t + a * t * t / 2.0 + jerk * t * t * t / 6.0;
    v += a * t + jerk * t * t / 2.0;
    a += jerk * t;
  }
};

}  // namespace

std::uint32_t LimitStatusBits::status_word() const noexcept {
  return (sw_limit_min_active ? bit(15) : 0U) | (sw_limit_max_active ? bit(16) : 0U) |
         (hw_limit_min_active ? bit(17) : 0U) | (hw_limit_max_active ? bit(18) : 0U);
}
std::uint32_t LimitStatusBits::error_word() const noexcept {
  return (sw_limit_error ? bit(8) : 0U) | (hw_limit_error ? bit(9) : 0U);
}
std::uint32_t LimitStatusBits::warning_word() const noexcept {
  return (sw_limit_min_warning ? bit(8) : 0U) | (sw_limit_max_warning ? bit(9) : 0U);
}

LimitStatusBits merge(const LimitStatusBits& a, const LimitStatusBits& b) noexcept {
  LimitStatusBits r;
  r.sw_limit_min_active = a.sw_limit_min_active || b.sw_limit_min_active;
  r.sw_limit_max_active = a.sw_limit_max_active || b.sw_limit_max_active;
  r.hw_limit_min_active = a.hw_limit_min_active || b.hw_limit_min_active;
  r.hw_limit_max_active = a.hw_limit_max_active || b.hw_limit_max_active;
  r.sw_limit_error = a.sw_limit_error || b.sw_limit_error;
  r.hw_limit_error = a.hw_limit_error || b.hw_limit_error;
  r.sw_limit_min_warning = a.sw_limit_min_warning || b.sw_limit_min_warning;
  r.sw_limit_max_warning = a.sw_limit_max_warning || b.sw_limit_max_warning;
  return r;
}

// ---- braking distance -------------------------------------------------------------------------------

double braking_distance(double speed, double acceleration, double deceleration, double jerk) noexcept {
  if (!std::isfinite(speed) || !std::isfinite(acceleration)) return std::numeric_limits<double>::infinity();
  speed = std::max(speed, 0.0);
  if (!(deceleration > 0.0)) return speed > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  if (!(jerk > 0.0) || !std::isfinite(jerk)) return speed * speed / (2.0 * deceleration);

  Motion m{0.0, speed, acceleration};
  // Still accelerating: ramp the acceleration down to zero first.
  if (m.a > 0.0) m.segment(-jerk, m.a / jerk);
  if (!(m.v > 0.0)) return std::max(m.p, 0.0);
  const double current = -m.a;  // current deceleration, >= 0
  if (current * current / (2.0 * jerk) >= m.v) {
    // Taking the deceleration back to zero alone already reaches v = 0: stop there.
    const double t = (current - std::sqrt(std::max(current * current - 2.0 * jerk * m.v, 0.0))) / jerk;
    m.segment(jerk, t);
    return std::max(m.p, 0.0);
  }
  // Trapezoidal (or triangular) deceleration profile with peak `peak`.
  double peak = std::min(std::sqrt(jerk * m.v + current * current / 2.0), deceleration);
  peak = std::max(peak, current);
  m.segment(-jerk, (peak - current) / jerk);
  const double hold = (m.v - peak * peak / (2.0 * jerk)) / peak;
  m.segment(0.0, hold);
  m.segment(jerk, peak / jerk);
  return std::max(m.p, 0.0);
}

StopLookAhead stop_at_limit_look_ahead(double position, double velocity, double acceleration, double limit,
                                       double deceleration, double jerk, double cycle_time) noexcept {
  const double t = std::max(cycle_time, 0.0);
  return stop_at_limit_look_ahead(position, velocity, acceleration,
                                  position + velocity * t + acceleration * t * t / 2.0,
                                  velocity + acceleration * t, acceleration, limit, deceleration, jerk);
}

StopLookAhead stop_at_limit_look_ahead(double position, double velocity, double acceleration,
                                       double next_position, double next_velocity, double next_acceleration,
                                       double limit, double deceleration, double jerk) noexcept {
  StopLookAhead r;
  const double direction = velocity > 0.0       ? 1.0
                           : velocity < 0.0     ? -1.0
                           : acceleration > 0.0 ? 1.0
                           : acceleration < 0.0 ? -1.0
                                                : 0.0;
  if (direction == 0.0) {
    r.remaining_distance = std::fabs(limit - position);
    return r;
  }
  r.remaining_distance = direction * (limit - position);
  r.braking_distance = braking_distance(std::max(direction * next_velocity, 0.0),
                                        direction * next_acceleration, deceleration, jerk);
  const double remaining_next = direction * (limit - next_position);
  r.stop_now = remaining_next + tolerance(limit) < r.braking_distance;
  return r;
}

// ---- software limit switches ----------------------------------------------------------------------

SoftwareLimitConfig software_limit_config(const PositioningAxisData::TO_Struct_PositionLimitsSW& sw,
                                          const TO_Struct_Modulo& modulo) noexcept {
  SoftwareLimitConfig c;
  c.active = sw.Active;
  c.min_position = sw.MinPosition;
  c.max_position = sw.MaxPosition;
  c.limit_reached_behavior = sw.LimitReachedBehavior;
  c.limit_exceeded_behavior = sw.LimitExceededBehavior;
  c.modulo_enable = modulo.Enable;
  c.modulo_start = modulo.StartValue;
  c.modulo_length = modulo.Length;
  return c;
}

EffectiveSoftwareLimits effective_software_limits(const SoftwareLimitConfig& config) noexcept {
  EffectiveSoftwareLimits e;
  if (!config.active) return e;
  double lo = config.min_position;
  double hi = config.max_position;
  if (config.modulo_enable) {
    if (!(config.modulo_length > 0.0)) return e;
    const double start = config.modulo_start;
    const double end = config.modulo_start + config.modulo_length;
    const bool min_inside = lo >= start && lo <= end;
    const bool max_inside = hi >= start && hi <= end;
    if (!min_inside && !max_inside) return e;  // spec 04 §8 rule 5: no monitoring
    if (!min_inside) lo = start;               // the other one becomes the modulo boundary
    if (!max_inside) hi = end;
  }
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) return e;  // implausible: not monitored
  e.monitored = true;
  e.min_position = lo;
  e.max_position = hi;
  return e;
}

std::int32_t sw_limit_reached_reaction(std::int32_t limit_reached_behavior, bool following_axis) noexcept {
  if (following_axis) return kReactionStopMaxDynamics;
  return limit_reached_behavior ==
                 static_cast<std::int32_t>(SoftwareLimitReachedBehavior::kStopCurrentDynamics)
             ? kReactionStopCurrentDynamics
             : kReactionStopMaxDynamics;
}

std::int32_t sw_limit_exceeded_reaction(std::int32_t limit_exceeded_behavior) noexcept {
  return limit_exceeded_behavior ==
                 static_cast<std::int32_t>(LimitViolationBehavior::kEmergencyStopKeepEnabled)
             ? kReactionStopEmergencyRamp
             : kReactionRemoveEnable;
}

void SoftwareLimitMonitor::configure(const SoftwareLimitConfig& config) noexcept {
  config_ = config;
  effective_ = effective_software_limits(config);
  reset();
}

void SoftwareLimitMonitor::reset() noexcept {
  side_ = LimitSide::kNone;
  kind_ = Kind::kNone;
  pending_ = false;
  engaged_ = false;
  active_limit_ = 0.0;
}

double SoftwareLimitMonitor::linear_coordinate(double position, double velocity) const noexcept {
  if (!config_.modulo_enable) return position;
  const double start = config_.modulo_start;
  const double length = config_.modulo_length;
  double p = position - length * std::floor((position - start) / length);
  if (p >= start + length) p -= length;
  const double lo = effective_.min_position;
  const double hi = effective_.max_position;
  if (p >= lo - tolerance(lo) && p <= hi + tolerance(hi)) return p;
  // In the forbidden zone of the modulo circle: reached from the Max side (upwards, over the top of the
  // zone) or from the Min side. The latched side wins, then the direction of motion, then the nearer limit.
  const double via_max = p < lo ? p + length : p;  // coordinate seen from the Max side
  const double via_min = p > hi ? p - length : p;  // coordinate seen from the Min side
  LimitSide side = side_;
  if (side != LimitSide::kMin && side != LimitSide::kMax) {
    if (velocity > 0.0) {
      side = LimitSide::kMax;
    } else if (velocity < 0.0) {
      side = LimitSide::kMin;
    } else {
      side = (via_max - hi) <= (lo - via_min) ? LimitSide::kMax : LimitSide::kMin;
    }
  }
  return side == LimitSide::kMax ? via_max : via_min;
}

LimitStatusBits SoftwareLimitMonitor::bits() const noexcept {
  LimitStatusBits b;
  b.sw_limit_min_active = side_ == LimitSide::kMin;
  b.sw_limit_max_active = side_ == LimitSide::kMax;
  b.sw_limit_error = pending_;
  b.sw_limit_min_warning = b.sw_limit_min_active && kind_ == Kind::kReached;
  b.sw_limit_max_warning = b.sw_limit_max_active && kind_ == Kind::kReached;
  return b;
}

bool SoftwareLimitMonitor::motion_allowed(double direction) const noexcept {
  if (side_ == LimitSide::kNone || direction == 0.0) return true;
  if (pending_) return false;
  return side_ == LimitSide::kMax ? direction < 0.0 : direction > 0.0;
}

SoftwareLimitResult SoftwareLimitMonitor::update(const SoftwareLimitInput& in) noexcept {
  SoftwareLimitResult r;
  // spec 02 §4.5: effective only when activated and the axis is homed.
  if (!config_.active || !in.homed || !effective_.monitored) {
    reset();
    return r;
  }
  const double lo = effective_.min_position;
  const double hi = effective_.max_position;
  const double x = linear_coordinate(in.position, in.velocity);
  const bool outside_max = x > hi + tolerance(hi);
  const bool outside_min = x < lo - tolerance(lo);

  const auto raise = [&](std::uint32_t alarm, LimitSide side, Kind kind, double limit) noexcept {
    side_ = side;
    kind_ = kind;
    pending_ = true;
    active_limit_ = limit;
    r.alarm.alarm = alarm;
    r.alarm.side = side;
    r.alarm.reaction = alarm == kAlarmSwLimitExceeded
                           ? sw_limit_exceeded_reaction(config_.limit_exceeded_behavior)
                           : sw_limit_reached_reaction(config_.limit_reached_behavior, in.following_axis);
  };
  // Outside on `side` (sign: +1 Max, -1 Min): the current position acts as the limit (spec 02 §4.5).
  const auto outside = [&](LimitSide side, double sign) noexcept {
    if (side_ != side) {
      raise(kAlarmSwLimitExceeded, side, Kind::kExceeded, x);
    } else if (pending_ && kind_ == Kind::kExceeded) {
      active_limit_ = x;  // the 534 reaction is braking: the limit follows
    } else if (sign * (x - active_limit_) > tolerance(active_limit_)) {
      raise(kAlarmSwLimitExceeded, side, Kind::kExceeded, x);  // passed the active limit outwards
    } else if (sign * (x - active_limit_) < 0.0) {
      active_limit_ = x;  // moving clear towards the work area
    }
  };

  if (!engaged_) {
    // Monitoring becomes effective (activation, homing): outside → the position is the limit, no alarm.
    engaged_ = true;
    if (outside_max || outside_min) {
      side_ = outside_max ? LimitSide::kMax : LimitSide::kMin;
      kind_ = Kind::kOutside;
      active_limit_ = x;
    }
  } else if (outside_max) {
    outside(LimitSide::kMax, 1.0);
  } else if (outside_min) {
    outside(LimitSide::kMin, -1.0);
  }

  // Look-ahead: stop at the (active) limit ahead of the motion (spec 02 §4.5).
  if (!r.alarm.raised()) {
    const double direction = in.velocity != 0.0 ? in.velocity : in.acceleration;
    if (direction != 0.0) {
      const LimitSide ahead = direction > 0.0 ? LimitSide::kMax : LimitSide::kMin;
      double limit = ahead == LimitSide::kMax ? hi : lo;
      if (side_ == ahead && kind_ != Kind::kNone &&
          (ahead == LimitSide::kMax ? active_limit_ > limit : active_limit_ < limit)) {
        limit = active_limit_;
      }
      const bool stopping = side_ == ahead && pending_;  // the reaction of this side is running
      if (!stopping) {
        const StopLookAhead la =
            in.next_known
                ? stop_at_limit_look_ahead(x, in.velocity, in.acceleration,
                                           x + (in.next_position - in.position), in.next_velocity,
                                           in.next_acceleration, limit, in.stop_deceleration, in.stop_jerk)
                : stop_at_limit_look_ahead(x, in.velocity, in.acceleration, limit, in.stop_deceleration,
                                           in.stop_jerk, in.cycle_time);
        if (la.stop_now) {
          raise(kAlarmSwLimitReached, ahead, Kind::kReached, limit);
          r.stop_now = true;
          r.stop_position = limit;
        }
      }
    }
  }

  // X15/X16 reset: acknowledged and back inside the work area (spec 02 §4.5, spec 04 §8 rule 5).
  if (!r.alarm.raised() && !pending_) {
    if ((side_ == LimitSide::kMax && x < hi - tolerance(hi)) ||
        (side_ == LimitSide::kMin && x > lo + tolerance(lo))) {
      side_ = LimitSide::kNone;
      kind_ = Kind::kNone;
    }
  }
  r.bits = bits();
  return r;
}

// ---- hardware limit switches ----------------------------------------------------------------------

HardwareLimitConfig hardware_limit_config(
    const PositioningAxisData::TO_Struct_PositionLimitsHW& hw) noexcept {
  HardwareLimitConfig c;
  c.active = hw.Active;
  c.min_switch_level = hw.MinSwitchLevel;
  c.max_switch_level = hw.MaxSwitchLevel;
  c.mode = hw.Mode;
  c.approach_behavior = hw.ApproachBehavior;
  return c;
}

std::int32_t hw_limit_reaction(const HardwareLimitConfig& config) noexcept {
  if (config.mode == static_cast<std::int32_t>(HardwareLimitSwitchMode::kPassable))
    return kReactionRemoveEnable;
  return config.approach_behavior ==
                 static_cast<std::int32_t>(LimitViolationBehavior::kEmergencyStopKeepEnabled)
             ? kReactionStopEmergencyRamp
             : kReactionRemoveEnable;
}

void HardwareLimitMonitor::configure(const HardwareLimitConfig& config) noexcept {
  config_ = config;
  reset();
}

void HardwareLimitMonitor::set_active(bool active) noexcept {
  config_.active = active;
  reset();
}

void HardwareLimitMonitor::reset() noexcept {
  side_ = LimitSide::kNone;
  pending_ = false;
  blocked_ = false;
  position_stored_ = false;
  detection_position_ = 0.0;
  prev_min_ = false;
  prev_max_ = false;
  last_cleared_ = LimitSide::kNone;
}

LimitStatusBits HardwareLimitMonitor::bits() const noexcept {
  LimitStatusBits b;
  b.hw_limit_min_active = side_ == LimitSide::kMin || side_ == LimitSide::kBoth;
  b.hw_limit_max_active = side_ == LimitSide::kMax || side_ == LimitSide::kBoth;
  b.hw_limit_error = pending_;
  return b;
}

bool HardwareLimitMonitor::motion_allowed(double direction) const noexcept {
  if (side_ == LimitSide::kNone || direction == 0.0) return true;
  if (pending_ || blocked_ || side_ == LimitSide::kBoth) return false;
  return side_ == LimitSide::kMax ? direction < 0.0 : direction > 0.0;
}

LimitAlarmEvent HardwareLimitMonitor::raise(LimitSide side, const HardwareLimitInput& in) noexcept {
  side_ = side;
  pending_ = true;
  const bool passable = config_.mode == static_cast<std::int32_t>(HardwareLimitSwitchMode::kPassable);
  if (passable && !position_stored_ && (side == LimitSide::kMin || side == LimitSide::kMax)) {
    position_stored_ = true;  // spec 02 §4.2: the position at detection is stored (passable only)
    detection_position_ = in.position;
  }
  return LimitAlarmEvent{kAlarmHwLimitApproached, hw_limit_reaction(config_), side};
}

HardwareLimitResult HardwareLimitMonitor::update(const HardwareLimitInput& in) noexcept {
  HardwareLimitResult r;
  if (!config_.active) {  // spec 02 §4.4: Active = FALSE disables both switches
    reset();
    return r;
  }
  // FALSE = low-active, TRUE = high-active (spec 02 §4.4).
  const bool min_on = in.min_switch_input == config_.min_switch_level;
  const bool max_on = in.max_switch_input == config_.max_switch_level;
  const bool min_edge = min_on && !prev_min_;
  const bool max_edge = max_on && !prev_max_;
  prev_min_ = min_on;
  prev_max_ = max_on;

  if (in.homing_reversal) {
    // spec 02 §4.2: reversal cams during active homing, monitoring not effective (no 531).
    r.reversal_cam = min_on && max_on ? LimitSide::kBoth
                     : max_on         ? LimitSide::kMax
                     : min_on         ? LimitSide::kMin
                                      : LimitSide::kNone;
    r.bits = bits();
    // A switch still active when homing ends (alarm 560, an aborted search) must raise 531 then: it counts
    // as not seen, so its level is an edge in the first monitored cycle (spec 02 §4.1-§4.3).
    prev_min_ = false;
    prev_max_ = false;
    return r;
  }

  if (min_on && max_on && !blocked_) {
    // spec 02 §4.3: both switches active → move clear only with PositionLimits_HW.Active = FALSE.
    r.alarm = raise(LimitSide::kBoth, in);
    blocked_ = true;
  } else if (!blocked_) {
    if (side_ == LimitSide::kNone) {
      const LimitSide side = max_edge ? LimitSide::kMax : min_edge ? LimitSide::kMin : LimitSide::kNone;
      if (side != LimitSide::kNone) {
        r.alarm = raise(side, in);
        // A switch that becomes active while the axis moves away from it: reversed polarity / swapped
        // switches (spec 02 §4.3 special case). Not for the switch just moved clear of (contact bounce).
        const bool moving_away =
            (side == LimitSide::kMin && in.velocity > 0.0) || (side == LimitSide::kMax && in.velocity < 0.0);
        if (moving_away && side != last_cleared_) blocked_ = true;
      }
    } else if (!pending_) {
      const bool max_side = side_ == LimitSide::kMax;
      const bool on = max_side ? max_on : min_on;
      const bool passable = config_.mode == static_cast<std::int32_t>(HardwareLimitSwitchMode::kPassable);
      // spec 02 §4.3: passable → the stored detection position must be passed back; non-passable → the
      // input no longer shows the active level.
      const bool cleared =
          passable ? (max_side ? in.position < detection_position_ : in.position > detection_position_) : !on;
      const bool towards_switch = max_side ? in.velocity > 0.0 : in.velocity < 0.0;
      if (cleared) {
        last_cleared_ = side_;
        side_ = LimitSide::kNone;
        position_stored_ = false;
      } else if (towards_switch) {
        r.alarm = raise(side_, in);  // wrong direction before leaving the switch: re-armed
      }
    }
  }
  r.deactivation_required = blocked_;
  r.bits = bits();
  return r;
}

}  // namespace tomc::techobjects::limits
