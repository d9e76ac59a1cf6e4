#pragma once
// Force/torque limiting and fixed-stop detection (MC_TorqueLimiting, spec 01 §8.10/§8.11, spec 03 §4.18.3,
// seed 004 §6.7.9.1/§6.7.9.2): the limit in technology units as a motor torque (or a linear motor's force),
// and the clamping state machine of "travel to fixed stop".
#include <cstdint>

#include "tomc/techobjects/axis/enable_level_job.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"

namespace tomc::techobjects {

// Additional value of alarm 541 when the position leaves Clamping.PositionTolerance (decision F4; 1 and 2
// are the positioning monitor's, position_monitoring.hpp).
inline constexpr std::uint32_t kClampingToleranceLeft = 3;

// Inputs of MC_TorqueLimiting, taken on every call while Enable is TRUE (spec 03 §4.18.3 note 5).
struct TorqueLimitingInputs {
  bool Enable = false;
  double Limit = -1.0;    // >= 0: this value; < 0: TorqueLimiting.LimitDefaults.Torque / .Force
  std::int32_t Mode = 0;  // 0 force/torque limiting, 1 fixed-stop detection
};

// Outputs of MC_TorqueLimiting (an Enable-level instruction without Done/CommandAborted, spec 03 L3).
struct TorqueLimitingState {
  bool Busy = false;
  bool InClamping = false;
  bool InLimitation = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;
};

// The TO's side of an MC_TorqueLimiting job, shared by the axis types.
struct TorqueLimitingRequest {
  bool active = false;           // Enable TRUE and accepted
  std::int32_t mode = 0;         // 0 limiting, 1 fixed-stop detection
  double limit = -1.0;           // as given (< 0: the defaults)
  std::uint16_t error = 0;       // latched until Enable goes FALSE (decision F7)
  bool stw2_fixed_stop = false;  // STW2.8 set by the limiting (cleared when it ends)

  // One MC_TorqueLimiting call (spec 03 §4.18.3, L3; enable_level_job.hpp): the inputs are checked by
  // `rejection` (0 = accepted) and taken on every call.
  template <typename Rejection>
  TorqueLimitingState call(const TorqueLimitingInputs& in, Rejection rejection) noexcept {
    enable_level_call(
        in.Enable, active, error, [&] { return rejection(in); },
        [&] {
          mode = in.Mode;
          limit = in.Limit;
        });
    TorqueLimitingState s;
    s.Error = error != 0;
    s.ErrorID = error;
    s.Busy = active;
    return s;
  }
};

// MC_Servo: the limit to the drive as MOMRED (a percentage reduction of `reference`, the same both ways) and
// STW2.8 "travel to fixed stop" while the job is active (decision F2), into this cycle's command;
// `motor_limit` in N·m (N for a linear motor). Returns InLimitation: MELDW.1 "torque utilisation below
// threshold (p2194)" cleared in the drive's last actual values.
bool drive_torque_limit(ServoCommand& command, const telegrams::ActualSignals& actual,
                        TorqueLimitingRequest& request, double motor_limit, double reference, bool has_momred,
                        bool has_meldw) noexcept;

// What the limit refers to (spec 01 §8.10 table).
struct TorqueLimitMechanics {
  bool linear_axis = false;        // Properties.MotionType = linear
  bool linear_motor = false;       // Actor.MotorType = 1: a force on the load side, efficiency not used
  bool load_side = false;          // TorqueLimiting.LimitBase = 1
  double gear_ratio = 1.0;         // motor revolutions per load revolution (LoadGear.Numerator/Denominator)
  double efficiency = 1.0;         // Actor.Efficiency
  double leadscrew_per_rev = 0.0;  // Mechanics.LeadScrew in metres per load revolution (linear axis)
};

// The limit as the drive sees it: a motor torque in N·m (linear motor: a force in N). Rotary, load side:
// T = T_load / (i·η); linear, load side: T = F·h / (2π·i·η); motor side and linear motor: as given.
double motor_torque_limit(double limit, const TorqueLimitMechanics& m) noexcept;

enum class ClampingEvent : std::uint8_t {
  kNone,
  kClamped,   // the following error passed Clamping.FollowingErrorDeviation: the running jobs end
  kReleased,  // a job away from the stop left Clamping.PositionTolerance: travel to fixed stop is over
  kLost,      // the position left the tolerance otherwise: the stop gave way or the load was pushed back
};

// The clamping state machine of spec 01 §8.11 / seed 004 §6.7.9.2, one update per servo cycle while
// fixed-stop detection is on and the axis is position-controlled (reset() otherwise). Positions in one
// continuous unit.
class ClampingMonitor {
 public:
  void configure(double following_error_deviation, double position_tolerance) noexcept {
    deviation_ = following_error_deviation;
    tolerance_ = position_tolerance;
  }
  // `moving_away`: a position-controlled motion job runs and its setpoint moves away from the stop.
  ClampingEvent update(double following_error, double actual_position, bool moving_away) noexcept;
  void reset() noexcept {
    clamped_ = false;
    direction_ = 0.0;
  }
  // Direct homing at the stop (spec 02 §5.7): the clamping position moves with the coordinates.
  void shift(double delta) noexcept { clamp_position_ += delta; }
  bool clamped() const noexcept { return clamped_; }
  // +1 if the stop lies in the positive direction, -1 if in the negative one, 0 while not clamped.
  double stop_direction() const noexcept { return direction_; }
  double clamp_position() const noexcept { return clamp_position_; }

 private:
  double deviation_ = 1.0;
  double tolerance_ = 0.5;
  bool clamped_ = false;
  double clamp_position_ = 0.0;
  double direction_ = 0.0;
};

}  // namespace tomc::techobjects
