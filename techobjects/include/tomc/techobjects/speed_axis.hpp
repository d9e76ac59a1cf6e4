#pragma once
// TO_SpeedAxis: the speed-controlled axis of seed 004 (spec 01 §1–§2, §6–§8; spec 02 §2.1, §2.5, §3; spec 03
// §4.1, §4.2, §4.4, §4.8, §4.9, §4.13; spec 04 column S). It owns its data block, its drive connection, its
// technology alarms and its jobs; instructions reach it through the job API below, which arbitrates a new job
// at once (spec 03 §3.6) with the shared §9.19.1 table. Motion takes effect from the next MC_Interpolator.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "tomc/techobjects/alarms.hpp"
#include "tomc/techobjects/control_priority.hpp"
#include "tomc/techobjects/drive_connection.hpp"
#include "tomc/techobjects/job.hpp"
#include "tomc/techobjects/job_priority.hpp"
#include "tomc/techobjects/job_table.hpp"
#include "tomc/techobjects/profiles.hpp"
#include "tomc/techobjects/runtime.hpp"
#include "tomc/techobjects/speed_axis_data.hpp"
#include "tomc/techobjects/torque_limiting.hpp"
#include "tomc/techobjects/variables.hpp"

namespace tomc::techobjects {

// Inputs of the motion instructions, as the user gives them (negative = default, spec 03 §2.1).
struct MoveVelocityInputs {
  double Velocity = 100.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t Direction = 0;  // 0 sign of Velocity, 1 positive, 2 negative
  bool Current = false;
  bool PositionControlled = true;  // positioning/synchronous axes (spec 02 §2.1); ignored on a speed axis
};
struct HaltInputs {
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool AbortAcceleration = false;
  std::int32_t Mode = 0;
};
struct StopInputs {
  std::int32_t Mode = 0;  // 0 emergency, 2 max dynamics, 3 given dynamics; 1 invalid
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool AbortAcceleration = false;
};
struct JogInputs {
  bool JogForward = false;
  bool JogBackward = false;
  double Velocity = 100.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool PositionControlled = true;  // positioning/synchronous axes (spec 02 §2.5); ignored on a speed axis
};

// The result of writing a data-block variable from user code.
struct WriteResult {
  bool found = false;
  AccessError access = AccessError::kNone;
  ValueError value = ValueError::kNone;
  bool ok() const noexcept { return found && access == AccessError::kNone && value == ValueError::kNone; }
};

// What MC_Power shows (spec 03 §4.1, §3.3 L1/L2).
struct PowerState {
  bool Status = false;
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;
};

class SpeedAxis final : public TechnologyObject {
 public:
  // `device` is the drive; nullptr for a virtual axis or simulation (VirtualAxis.Mode / Simulation.Mode = 1).
  // Throws std::invalid_argument for start values the data block does not permit (reported with their path).
  SpeedAxis(std::string name, DeviceIo* device, const SpeedAxisData& start_values,
            const DriveConnectionConfig& drive = {});

  // ---- TechnologyObject ----
  std::string_view name() const noexcept override { return name_; }
  void servo(const CycleClock& clock) noexcept override;
  void interpolate(const CycleClock& clock) noexcept override;

  // ---- the data block ----
  const SpeedAxisData& data() const noexcept { return db_; }
  // A user-program write (spec 04 §0.2): DIR/CAL only; RES through write_start_value + restart.
  WriteResult write(std::string_view path, double value) noexcept;
  WriteResult write_start_value(std::string_view path, double value) noexcept;
  double read(std::string_view path) const noexcept;  // NaN for an unknown path; bits as "StatusWord.X5"
  const AlarmList& alarms() const noexcept { return alarms_; }
  // Simulation and commissioning: raise a technology alarm as if its cause had occurred, with the reaction it
  // would carry (for configurable reactions). Scenarios and tests use it to exercise every alarm reaction.
  // False for an alarm number tomc does not define.
  bool inject_alarm(std::uint32_t number, std::uint32_t additional_value, AlarmReaction reaction) noexcept;
  const DriveConnection* drive() const noexcept { return device_ == nullptr ? nullptr : &drive_; }

  // ---- the axis control panel (spec 02 §9.2) ----
  ControlPriority& control_priority() noexcept { return control_; }
  const ControlPriority& control_priority() const noexcept { return control_; }
  // Precondition of taking control priority: the user program has released the axis (MC_Power.Enable =
  // FALSE) and the TO is disabled.
  bool program_released() const noexcept { return !enable_ && phase_ == PowerPhase::kDisabled; }

  // ---- jobs (called by instructions from the user program) ----
  // MC_Power: level-class; called once per instruction call.
  PowerState power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept;
  Submission reset(bool restart) noexcept;
  Submission move_velocity(const MoveVelocityInputs& in) noexcept;
  Submission halt(const HaltInputs& in) noexcept;
  Submission stop(const StopInputs& in) noexcept;
  // MC_Stop's Execute level: while TRUE for an accepted MC_Stop, new motion jobs are rejected (spec 03
  // §4.13).
  void stop_execute(JobId job, bool execute) noexcept;
  // MC_MoveJog: level-class. Starts a jog job on the first call with an input set, updates it on later calls.
  Submission jog(JobId running, const JogInputs& in) noexcept;
  // MC_SetAxisSTW (spec 03 §4.14): the user's bits of STW1 (8, 9, 11..15) and STW2 (0..11).
  Submission set_axis_stw(std::uint16_t stw1, std::uint16_t stw1_mask, std::uint16_t stw2,
                          std::uint16_t stw2_mask) noexcept;
  // MC_WriteParameter (spec 03 §4.15): 1010/1011/1012 communication times (s, after restart), 1020
  // Actor.RemoveEnableReaction (immediately). 1000 belongs to positioning axes.
  Submission write_parameter(std::int32_t parameter_number, double value) noexcept;
  // MC_TorqueLimiting (spec 03 §4.18.3): Mode 0 torque limiting through MOMRED (telegrams 10x); fixed-stop
  // detection (Mode 1) is for positioning and synchronous axes only.
  TorqueLimitingState torque_limiting(const TorqueLimitingInputs& in) noexcept;
  // Ti, To, T_DC (seconds) in effect; they enter the following error of position-controlled axes.
  using CommunicationTimes = techobjects::CommunicationTimes;
  const CommunicationTimes& communication_times() const noexcept { return communication_times_; }
  JobStatus job_status(JobId id) const noexcept;

 private:
  enum class JobKind : std::uint8_t {
    kNone,
    kReset,
    kMoveVelocity,
    kJog,
    kHalt,
    kStop,
    kSetAxisStw,
    kWriteParameter
  };
  enum class PowerPhase : std::uint8_t { kDisabled, kEnabling, kEnabled, kDisabling };

  struct Motion {  // the running base motion (MoveVelocity, Jog, Halt)
    JobId id = 0;
    JobKind kind = JobKind::kNone;
    ProfileLimits limits{};       // resolved, in revolutions/s, /s², /s³
    double command_velocity = 0;  // before override (rev/s, signed); Halt: 0
    double planned_target = 0;    // the target the profile was planned for
    bool jog_stopping = false;
    bool jog_error = false;
  };
  struct StopJob {
    JobId id = 0;
    int weight = 0;
    ProfileLimits limits{};
    bool execute = false;
    bool done = false;
  };

  // helpers
  JobId new_job(JobKind kind, JobState state) noexcept;
  void set_job(JobId id, JobState state, std::uint16_t error_id = 0) noexcept;
  std::uint16_t motion_prerequisites() const noexcept;
  std::optional<std::uint16_t> resolve_dynamics(double acceleration, double deceleration, double jerk,
                                                ProfileLimits& out) noexcept;
  std::uint16_t arbitrate_motion(NewJob row) noexcept;  // 0 = accepted (aborts applied)
  void abort_motion(std::uint16_t error_id) noexcept;   // ends the base motion (0 = CommandAborted)
  void plan_velocity(double target, const ProfileLimits& limits, bool abort_acceleration) noexcept;
  void raise(std::uint32_t number, std::uint32_t additional = 0) noexcept;
  void supervise_drive() noexcept;
  void apply_alarm_reactions() noexcept;
  void generate_setpoint() noexcept;
  void update_status() noexcept;
  void restart() noexcept;
  double velocity_unit_per_revolution_per_second() const noexcept;
  double override_factor() const noexcept;
  double velocity_limit() const noexcept;  // rev/s
  bool blocked() const noexcept;
  bool virtual_axis() const noexcept { return device_ == nullptr; }

  std::string name_;
  DeviceIo* device_ = nullptr;
  SpeedAxisData start_;
  SpeedAxisData db_;
  DriveConnectionConfig drive_config_;
  DriveConnection drive_;
  AlarmList alarms_;
  ControlPriority control_;
  JobTable<JobKind> jobs_;
  std::uint64_t cycle_ = 0;
  double ipo_cycle_s_ = 0.001;

  // power
  PowerPhase phase_ = PowerPhase::kDisabled;
  bool enable_ = false;
  std::int32_t stop_mode_ = 0;
  std::uint64_t enabling_since_ = 0;
  double enable_timeout_s_ = 2.0;

  // motion
  Motion motion_{};
  StopJob stop_{};
  VelocityProfile profile_{};
  double profile_time_ = 0.0;
  bool generator_active_ = false;  // a profile drives the setpoint (else: hold / follow actual)
  MotionState setpoint_{};         // rev/s, rev/s²
  double actual_velocity_ = 0.0;   // rev/s, load side
  AlarmReaction reaction_in_force_ = AlarmReaction::kNone;
  bool reset_pending_ = false;
  JobId reset_job_ = 0;
  bool restart_requested_ = false;
  std::uint64_t acknowledged_at_ = 0;
  bool drive_fault_seen_ = false;
  bool limited_velocity_ = false;
  bool limited_dynamics_ = false;
  CommunicationTimes communication_times_{};
  CommunicationTimes communication_times_start_{};
  // MC_TorqueLimiting
  TorqueLimitingRequest torque_{};
  bool in_limitation_ = false;
  bool drive_has_momred_ = false;  // resolved at construction
  bool drive_has_meldw_ = false;
};

}  // namespace tomc::techobjects
