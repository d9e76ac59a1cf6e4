#pragma once
// Travel-range limit monitors of the positioning / synchronous axis (spec 02 §4, spec 04 §3.16, §3.17,
// §8 rules 5-6): software limit switches (alarms 533 / 534) and hardware limit switches (alarm 531).
//
// Both monitors are standalone and real-time safe: fixed-size state, no allocation, noexcept, bounded
// run time. They return plain values (alarm number, ErrorDetail.Reaction code 0..5, side, status bits);
// raising the alarm through the alarm classes and executing the reaction is the caller's job.
//
// Decisions (where the spec leaves room):
// - SW: 533 is raised when the look-ahead starts the stop (spec 02 §4.5 "approach"), with the dynamics
//   the caller passes as stop_deceleration/stop_jerk (max or current dynamics per the reaction code); a
//   motion that brakes on its own to exactly the limit (MoveAbsolute to the limit) raises nothing.
//   X15/X16 are set with 533/534 or when monitoring starts outside the range, and reset once acknowledged
//   and back inside the work area; not merely because the setpoint equals a limit.
// - SW modulo: stop_position is in the coordinate of the current modulo cycle (may be Start + Length).
//   A position in the forbidden zone counts for the side it was entered from (latched side, else the
//   direction of motion, else the nearer limit).
// - HW: detection on the edge to the active level (and on activation while on a switch); a switch that
//   becomes active while the axis moves away from it (not the one just moved clear of) is taken as
//   reversed polarity / swapped switches: like both switches active, moving clear then needs
//   PositionLimits_HW.Active = FALSE (spec 02 §4.3). While one switch is latched, the other single switch
//   is not evaluated; both active at once always is.
#include <cstdint>

#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"

namespace tomc::techobjects::limits {

// Technology alarm numbers (spec 02 §1.3).
inline constexpr std::uint32_t kAlarmHwLimitApproached = 531;
inline constexpr std::uint32_t kAlarmSwLimitReached = 533;
inline constexpr std::uint32_t kAlarmSwLimitExceeded = 534;

// ErrorDetail.Reaction codes (spec 02 §1.1); same values as AlarmReaction in alarms.hpp.
inline constexpr std::int32_t kReactionNone = 0;
inline constexpr std::int32_t kReactionStopCurrentDynamics = 1;
inline constexpr std::int32_t kReactionStopMaxDynamics = 2;
inline constexpr std::int32_t kReactionStopEmergencyRamp = 3;
inline constexpr std::int32_t kReactionRemoveEnable = 4;

// Which limit: Min = negative side, Max = positive side. kBoth: both HW switches active at once.
enum class LimitSide : std::uint8_t { kNone = 0, kMin = 1, kMax = 2, kBoth = 3 };

// A technology alarm raised in this cycle (alarm == 0: none).
struct LimitAlarmEvent {
  std::uint32_t alarm = 0;
  std::int32_t reaction = kReactionNone;  // ErrorDetail.Reaction, 0..5
  LimitSide side = LimitSide::kNone;
  constexpr bool raised() const noexcept { return alarm != 0; }
  friend constexpr bool operator==(const LimitAlarmEvent&, const LimitAlarmEvent&) = default;
};

// Status bits owned by the limit monitors (spec 02 §1.2, spec 04 §5).
struct LimitStatusBits {
  bool sw_limit_min_active = false;   // StatusWord.X15 SWLimitMinActive
  bool sw_limit_max_active = false;   // StatusWord.X16 SWLimitMaxActive
  bool hw_limit_min_active = false;   // StatusWord.X17 HWLimitMinActive
  bool hw_limit_max_active = false;   // StatusWord.X18 HWLimitMaxActive
  bool sw_limit_error = false;        // ErrorWord.X8 SWLimit
  bool hw_limit_error = false;        // ErrorWord.X9 HWLimit
  bool sw_limit_min_warning = false;  // WarningWord.X8 SWLimitMin
  bool sw_limit_max_warning = false;  // WarningWord.X9 SWLimitMax

  std::uint32_t status_word() const noexcept;   // the X15..X18 bits
  std::uint32_t error_word() const noexcept;    // the X8/X9 bits
  std::uint32_t warning_word() const noexcept;  // the X8/X9 bits
  friend constexpr bool operator==(const LimitStatusBits&, const LimitStatusBits&) = default;
};
// Bitwise OR of the SW and the HW part.
LimitStatusBits merge(const LimitStatusBits& a, const LimitStatusBits& b) noexcept;

// ---------------------------------------------------------------------------------------------------
// Braking distance / stop-at-limit look-ahead (spec 02 §4.5: "cyclic look-ahead with the current dynamic
// values ... a stop at the SW limit position is started").

// Distance needed to brake from speed `speed` (>= 0, in the direction of motion) and acceleration
// `acceleration` (> 0 speeds up, < 0 already decelerating) to standstill with deceleration `deceleration`
// (> 0) and jerk `jerk` (<= 0 or infinite: no jerk limit, acceleration changes at once). Returns +inf
// for a non-positive deceleration with speed > 0.
double braking_distance(double speed, double acceleration, double deceleration, double jerk) noexcept;

struct StopLookAhead {
  bool stop_now = false;            // the stop must start in this cycle to end at `limit`
  double remaining_distance = 0.0;  // from the current setpoint to the limit, in the direction of motion
  double braking_distance = 0.0;    // from the state of the next cycle
};
// Whether a stop has to start now so that the setpoint (position, velocity, acceleration) stops at
// `limit` ahead of it: true if, after one more cycle `cycle_time` of unchanged motion, the braking
// distance (deceleration, jerk) would exceed the remaining distance. The stop then needs at most
// `deceleration` to end exactly at `limit`.
StopLookAhead stop_at_limit_look_ahead(double position, double velocity, double acceleration, double limit,
                                       double deceleration, double jerk, double cycle_time) noexcept;
// The same decision on the next cycle's setpoint as the caller's profile will produce it. Exact for a
// jerk-limited profile, whose acceleration changes within the cycle: extrapolated with constant acceleration,
// a rising acceleration is seen one cycle late and the stop can no longer end at the limit.
StopLookAhead stop_at_limit_look_ahead(double position, double velocity, double acceleration,
                                       double next_position, double next_velocity, double next_acceleration,
                                       double limit, double deceleration, double jerk) noexcept;

// ---------------------------------------------------------------------------------------------------
// Software limit switches (spec 02 §4.5, spec 04 §3.16, §8 rule 5).

struct SoftwareLimitConfig {
  bool active = false;                       // PositionLimits_SW.Active
  double min_position = -1000.0;             // PositionLimits_SW.MinPosition
  double max_position = 1000.0;              // PositionLimits_SW.MaxPosition
  std::int32_t limit_reached_behavior = 0;   // PositionLimits_SW.LimitReachedBehavior (533)
  std::int32_t limit_exceeded_behavior = 0;  // PositionLimits_SW.LimitExceededBehavior (534)
  bool modulo_enable = false;                // Modulo.Enable
  double modulo_start = 0.0;                 // Modulo.StartValue
  double modulo_length = 360.0;              // Modulo.Length
};
SoftwareLimitConfig software_limit_config(const PositioningAxisData::TO_Struct_PositionLimitsSW& sw,
                                          const TO_Struct_Modulo& modulo) noexcept;

// The limits that are actually monitored.
struct EffectiveSoftwareLimits {
  bool monitored = false;
  double min_position = 0.0;
  double max_position = 0.0;
};
// Not active → not monitored. Modulo (spec 04 §8 rule 5): both limits outside [start, start + length]
// → not monitored; one inside → the other one becomes the matching modulo boundary.
EffectiveSoftwareLimits effective_software_limits(const SoftwareLimitConfig& config) noexcept;

// Reaction codes: 533 per LimitReachedBehavior (0 → 2 max dynamics, 1 → 1 current dynamics; a following
// or kinematics axis always 2); 534 per LimitExceededBehavior (0 → 4 remove enable, 1 → 3 emergency ramp).
std::int32_t sw_limit_reached_reaction(std::int32_t limit_reached_behavior, bool following_axis) noexcept;
std::int32_t sw_limit_exceeded_reaction(std::int32_t limit_exceeded_behavior) noexcept;

struct SoftwareLimitInput {
  double position = 0.0;           // setpoint position (the modulo position on a modulo axis)
  double velocity = 0.0;           // setpoint velocity
  double acceleration = 0.0;       // setpoint acceleration
  bool homed = false;              // StatusWord.X5 HomingDone
  bool following_axis = false;     // following axis in synchronous operation / kinematics axis
  double stop_deceleration = 0.0;  // deceleration of the 533 stop (see sw_limit_reached_reaction)
  double stop_jerk = 0.0;          // jerk of the 533 stop (<= 0: none)
  double cycle_time = 0.0;         // look-ahead horizon (interpolator cycle)
  // The setpoint one cycle ahead, when the caller knows it from its profile (same coordinate as position);
  // otherwise the look-ahead extrapolates with constant acceleration.
  bool next_known = false;
  double next_position = 0.0;
  double next_velocity = 0.0;
  double next_acceleration = 0.0;
};

struct SoftwareLimitResult {
  LimitAlarmEvent alarm;  // 533 / 534 newly raised this cycle
  bool stop_now = false;  // decouple the motion and stop at `stop_position`
  double stop_position = 0.0;
  LimitStatusBits bits;  // X15/X16, ErrorWord.X8, WarningWord.X8/X9
};

class SoftwareLimitMonitor {
 public:
  SoftwareLimitMonitor() noexcept = default;
  explicit SoftwareLimitMonitor(const SoftwareLimitConfig& config) noexcept { configure(config); }

  void configure(const SoftwareLimitConfig& config) noexcept;  // also resets the state
  const EffectiveSoftwareLimits& effective_limits() const noexcept { return effective_; }

  // One cycle of the monitoring (setpoint-based, spec 02 §4.5).
  SoftwareLimitResult update(const SoftwareLimitInput& in) noexcept;
  // MC_Reset acknowledged 533/534: moving clear is allowed towards the work area (spec 02 §4.5).
  void acknowledge() noexcept { pending_ = false; }

  // Whether a motion with the sign of `direction` may start: TRUE when no limit is active; while an
  // alarm is not acknowledged FALSE; after acknowledgement only towards the work area (the other
  // direction re-triggers 533/534).
  bool motion_allowed(double direction) const noexcept;
  LimitSide active_side() const noexcept { return side_; }
  bool alarm_pending() const noexcept { return pending_; }
  LimitStatusBits bits() const noexcept;
  // What update() does with an input it does not monitor (not active, not homed): the state is forgotten. An
  // axis whose limits are not effective calls it instead of building an input (issue 23).
  void reset() noexcept;

 private:
  enum class Kind : std::uint8_t { kNone, kReached, kExceeded, kOutside };
  double linear_coordinate(double position, double velocity) const noexcept;

  SoftwareLimitConfig config_{};
  EffectiveSoftwareLimits effective_{};
  LimitSide side_ = LimitSide::kNone;
  Kind kind_ = Kind::kNone;
  bool pending_ = false;
  bool engaged_ = false;       // the monitoring has been effective since the last reset
  double active_limit_ = 0.0;  // the current position acts as the limit while outside (spec 02 §4.5)
};

// ---------------------------------------------------------------------------------------------------
// Hardware limit switches (spec 02 §4.1-§4.4, spec 04 §3.17, §8 rule 6).

struct HardwareLimitConfig {
  bool active = false;                 // PositionLimits_HW.Active (MC_WriteParameter 1000)
  bool min_switch_level = false;       // PositionLimits_HW.MinSwitchLevel: FALSE low-active, TRUE high-active
  bool max_switch_level = false;       // PositionLimits_HW.MaxSwitchLevel
  std::int32_t mode = 0;               // PositionLimits_HW.Mode: 0 non-passable, 1 passable
  std::int32_t approach_behavior = 0;  // PositionLimits_HW.ApproachBehavior: 0 disable, 1 emergency stop
};
HardwareLimitConfig hardware_limit_config(const PositioningAxisData::TO_Struct_PositionLimitsHW& hw) noexcept;

// 531: passable → 4 (remove enable, drive ramp); non-passable → ApproachBehavior 0 → 4, 1 → 3.
std::int32_t hw_limit_reaction(const HardwareLimitConfig& config) noexcept;

struct HardwareLimitInput {
  bool min_switch_input = false;  // signal level of the negative switch input
  bool max_switch_input = false;  // signal level of the positive switch input
  double position = 0.0;          // actual position (stored at detection of a passable switch)
  double velocity = 0.0;          // direction of motion (setpoint velocity)
  bool homing_reversal = false;   // active homing with Homing.AutoReversal: switches act as reversal cams
};

struct HardwareLimitResult {
  LimitAlarmEvent alarm;                      // 531 newly raised this cycle
  LimitSide reversal_cam = LimitSide::kNone;  // homing_reversal: switch reached, reverse (no alarm)
  bool deactivation_required = false;  // both active / reversed polarity: move clear only with Active = FALSE
  LimitStatusBits bits;                // X17/X18, ErrorWord.X9
};

class HardwareLimitMonitor {
 public:
  HardwareLimitMonitor() noexcept = default;
  explicit HardwareLimitMonitor(const HardwareLimitConfig& config) noexcept { configure(config); }

  void configure(const HardwareLimitConfig& config) noexcept;  // also resets the state
  // MC_WriteParameter 1000: takes effect at once; FALSE clears the state (spec 02 §4.4).
  void set_active(bool active) noexcept;

  HardwareLimitResult update(const HardwareLimitInput& in) noexcept;
  // MC_Reset acknowledged 531 (no restart needed, spec 02 §4.3).
  void acknowledge() noexcept { pending_ = false; }

  // Moving clear (spec 02 §4.3): TRUE when no switch is latched; FALSE while 531 is not acknowledged or
  // after both switches / reversed polarity; otherwise only away from the switch.
  bool motion_allowed(double direction) const noexcept;
  LimitSide active_side() const noexcept { return side_; }
  bool alarm_pending() const noexcept { return pending_; }
  bool detection_position_stored() const noexcept { return position_stored_; }
  double detection_position() const noexcept { return detection_position_; }
  LimitStatusBits bits() const noexcept;

 private:
  void reset() noexcept;
  LimitAlarmEvent raise(LimitSide side, const HardwareLimitInput& in) noexcept;

  HardwareLimitConfig config_{};
  LimitSide side_ = LimitSide::kNone;
  bool pending_ = false;
  bool blocked_ = false;  // both switches active or reversed polarity
  bool position_stored_ = false;
  double detection_position_ = 0.0;
  bool prev_min_ = false;
  bool prev_max_ = false;
  LimitSide last_cleared_ = LimitSide::kNone;  // switch most recently moved clear of
};

}  // namespace tomc::techobjects::limits
