#pragma once
// Position monitoring of the positioning axis (issue 5 groundwork), spec 02 §6:
//   FollowingErrorMonitor  — §6.2 permitted-following-error characteristic, alarms 521 / 522
//   PositioningMonitor     — §6.1 window, ToleranceTime, MinDwellTime, StatusWord.X6 Done, alarm 541 (1 / 2)
//   StandstillSignal       — §6.3 StatusWord.X7 Standstill with hysteresis
//
// The components only report; raising the alarm, its reaction (Remove enable for 521/541) and the status
// and error bits (ErrorWord.X11/X12, WarningWord.X11) are the caller's job.
//
// Timing is cycle-exact: every update() is one servo cycle; times are converted once in configure() into
// whole servo cycles (a relative tolerance of 1e-9 absorbs the floating-point error of e.g. 0.01/0.001).
//
// Real time: all member functions are noexcept, allocation-free and run in O(1).

#include <cstdint>

namespace tomc::techobjects {

// ---------------------------------------------------------------------------------------------------------
// §6.2 Following-error monitoring
// ---------------------------------------------------------------------------------------------------------

// Filled from <TO>.FollowingError.* (spec 04 §3.24) and <TO>.DynamicLimits.MaxVelocity.
struct FollowingErrorMonitoringConfig {
  bool EnableMonitoring = true;  // FollowingError.EnableMonitoring
  double MinValue = 2.0;         // FollowingError.MinValue: permitted FE for |v| <= MinVelocity
  double MaxValue = 10.0;        // FollowingError.MaxValue: permitted FE at the maximum velocity
  double MinVelocity = 10.0;     // FollowingError.MinVelocity
  double WarningLevel = 90.0;    // FollowingError.WarningLevel [%] of the current permitted FE
  double MaxVelocity = 500.0;    // DynamicLimits.MaxVelocity (v_max of the characteristic, [Derived])
};

enum class FollowingErrorAlarm : std::uint8_t {
  kNone = 0,
  kWarning522,  // |FE| >= WarningLevel % · FE_max: warning, no reaction (WarningWord.X11)
  kError521,    // |FE| > FE_max: reaction Remove enable (ErrorWord.X11)
};

struct FollowingErrorCheck {
  FollowingErrorAlarm alarm = FollowingErrorAlarm::kNone;
  double permitted = 0.0;          // FE_max(|v_set|)
  double warning_threshold = 0.0;  // WarningLevel/100 · FE_max
};

class FollowingErrorMonitor {
 public:
  FollowingErrorMonitor() noexcept = default;
  explicit FollowingErrorMonitor(const FollowingErrorMonitoringConfig& config) noexcept : config_(config) {}
  void configure(const FollowingErrorMonitoringConfig& config) noexcept { config_ = config; }
  const FollowingErrorMonitoringConfig& config() const noexcept { return config_; }

  // FE_max(v): MinValue for |v| <= MinVelocity, linear up to MaxValue at MaxVelocity, MaxValue above
  // (the clamp is [Derived]). With MaxVelocity <= MinVelocity the limit steps to MaxValue above MinVelocity.
  double permitted(double setpoint_velocity) const noexcept;
  // Level check of one servo cycle (the caller raises 522/521 on the rising edge). 521 takes precedence over
  // 522. With EnableMonitoring = FALSE the result is always kNone (limits are still reported).
  FollowingErrorCheck check(double following_error, double setpoint_velocity) const noexcept;

 private:
  FollowingErrorMonitoringConfig config_{};
};

// ---------------------------------------------------------------------------------------------------------
// §6.1 Positioning monitoring
// ---------------------------------------------------------------------------------------------------------

// Filled from <TO>.PositioningMonitoring.* (spec 04 §3.25).
struct PositioningMonitoringConfig {
  double Window = 0.01;        // PositioningMonitoring.Window: |x_target − x_act| <= Window is "in"
  double ToleranceTime = 1.0;  // PositioningMonitoring.ToleranceTime [s]
  double MinDwellTime = 0.01;  // PositioningMonitoring.MinDwellTime [s]
  double ServoCycle = 0.004;   // T_Servo [s], > 0
};

inline constexpr std::uint32_t kPositioningAlarm = 541;
// Additional values of alarm 541 (spec 02 §6.1).
inline constexpr std::uint32_t kPositioningTargetNotReached = 1;  // not in the window within ToleranceTime
inline constexpr std::uint32_t kPositioningTargetLeft = 2;        // window left again during MinDwellTime

enum class PositioningOutcome : std::uint8_t {
  kInactive = 0,  // no monitoring running (before start() or after cancel())
  kInProgress,    // waiting for the window or dwelling in it
  kDone,          // StatusWord.X6 Done: stays until the next start()/cancel()
  kFault,         // alarm 541 with additional_value 1 or 2: stays until the next start()/cancel()
};

struct PositioningStatus {
  PositioningOutcome outcome = PositioningOutcome::kInactive;
  std::uint32_t additional_value = 0;  // 1 or 2 with kFault, 0 otherwise
};

// State machine of spec 02 §6.1. Cycle convention: start() is called in the servo cycle in which setpoint
// interpolation has ended (t0); the update() of that same cycle evaluates now − t0 = 0, each further update()
// adds one servo cycle.
//   WAIT_ENTER: in            -> t_in = now, DWELL (and the dwell test below runs in the same cycle)
//               now − t0 > ToleranceTime -> 541/1. Entering at exactly now − t0 = ToleranceTime is in time;
//               the alarm comes in the first cycle with now − t0 > ToleranceTime (spec: ">").
//   DWELL:      !in           -> 541/2
//               now − t_in >= MinDwellTime -> Done (so MinDwellTime = 0 gives Done in the entry cycle and
//               MinDwellTime = n·T_s gives Done n cycles after the entry cycle)
class PositioningMonitor {
 public:
  PositioningMonitor() noexcept { configure(PositioningMonitoringConfig{}); }
  explicit PositioningMonitor(const PositioningMonitoringConfig& config) noexcept {
    configure(PositioningMonitoringConfig{});
    configure(config);
  }
  // Rejects (returns false, keeps the previous configuration) a ServoCycle <= 0 or a negative/non-finite
  // Window or time. Takes effect for the next start().
  bool configure(const PositioningMonitoringConfig& config) noexcept;
  const PositioningMonitoringConfig& config() const noexcept { return config_; }

  // End of setpoint interpolation (target reached or position-controlled stop): monitoring restarts.
  void start(double target_position) noexcept;
  void cancel() noexcept;
  // Monitoring switched off (torque limiting with PositionBasedMonitorings = 0): Done without the window
  // check.
  void complete() noexcept;
  PositioningStatus update(double actual_position) noexcept;
  PositioningStatus status() const noexcept { return status_; }

  std::uint64_t tolerance_cycles() const noexcept { return tolerance_cycles_; }
  std::uint64_t dwell_cycles() const noexcept { return dwell_cycles_; }

 private:
  enum class State : std::uint8_t { kIdle, kWaitEnter, kDwell, kFinished };
  PositioningMonitoringConfig config_{};
  std::uint64_t tolerance_cycles_ = 0;  // floor(ToleranceTime/T_s): alarm when elapsed cycles exceed it
  std::uint64_t dwell_cycles_ = 0;      // ceil(MinDwellTime/T_s)
  State state_ = State::kIdle;
  double target_ = 0.0;
  std::uint64_t elapsed_ = 0;  // cycles since start() (0 in the start cycle)
  std::uint64_t dwell_ = 0;    // cycles since entering the window
  PositioningStatus status_{};
};

// ---------------------------------------------------------------------------------------------------------
// §6.3 Standstill signal
// ---------------------------------------------------------------------------------------------------------

// Filled from <TO>.StandstillSignal.* (spec 04 §3.26).
struct StandstillSignalConfig {
  double VelocityThreshold = 1.0;  // StandstillSignal.VelocityThreshold [unit/s]
  double MinDwellTime = 0.01;      // StandstillSignal.MinDwellTime [s]
  double ServoCycle = 0.004;       // T_Servo [s], > 0
};

// Hysteresis on leaving the standstill window (spec 02 §6.3 gives no number; [Derived] suggests 10 %):
// X7 and the dwell timer are reset only when |v_act| > VelocityThreshold · (1 + kStandstillHysteresis).
// Between the threshold and that value the state holds (the timer neither runs nor resets).
inline constexpr double kStandstillHysteresis = 0.10;

// Spec 02 §6.3 pseudocode: |v| <= threshold -> timer += T_s, X7 once timer >= MinDwellTime. The first cycle
// below the threshold therefore counts as one servo cycle of dwell: X7 is set in the n-th consecutive cycle
// below the threshold, n = max(1, ceil(MinDwellTime/T_s)).
class StandstillSignal {
 public:
  StandstillSignal() noexcept { configure(StandstillSignalConfig{}); }
  explicit StandstillSignal(const StandstillSignalConfig& config) noexcept {
    configure(StandstillSignalConfig{});
    configure(config);
  }
  // Rejects (returns false, keeps the previous configuration) a ServoCycle <= 0 or negative/non-finite
  // values. Does not reset the state.
  bool configure(const StandstillSignalConfig& config) noexcept;
  const StandstillSignalConfig& config() const noexcept { return config_; }
  void reset() noexcept {
    counter_ = 0;
    standstill_ = false;
  }
  // One servo cycle with the actual velocity; returns StatusWord.X7.
  bool update(double actual_velocity) noexcept;
  bool standstill() const noexcept { return standstill_; }
  std::uint64_t dwell_cycles() const noexcept { return dwell_cycles_; }

 private:
  StandstillSignalConfig config_{};
  std::uint64_t dwell_cycles_ = 1;
  std::uint64_t counter_ = 0;
  bool standstill_ = false;
};

}  // namespace tomc::techobjects
