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

#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/axis/axis_core.hpp"
#include "tomc/techobjects/axis/control_priority.hpp"
#include "tomc/techobjects/axis/job.hpp"
#include "tomc/techobjects/axis/job_inputs.hpp"
#include "tomc/techobjects/axis/job_priority.hpp"
#include "tomc/techobjects/axis/job_table.hpp"
#include "tomc/techobjects/axis/memory_footprint.hpp"
#include "tomc/techobjects/axis/torque_limiting.hpp"
#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/motion/profiles.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::techobjects {

class SpeedAxis final : public TechnologyObject {
 public:
  // `device` is the drive; nullptr for a virtual axis or simulation (VirtualAxis.Mode / Simulation.Mode = 1).
  // Throws std::invalid_argument for start values the data block does not permit (reported with their path).
  SpeedAxis(std::string name, DeviceIo* device, const SpeedAxisData& start_values,
            const DriveConnectionConfig& drive = {});

  // ---- TechnologyObject ----
  std::string_view name() const noexcept override { return name_; }
  void servo(const CycleClock& clock) noexcept override;
  void attach(RuntimeServices& services) override {
    core_.alarms.attach(services.alarm_log, services.object_number);
    start_.move_to(services.start_values);
  }
  void interpolate(const CycleClock& clock) noexcept override;

  // The object plus the heap it owns (start values only until the runtime adopted them), in bytes.
  std::size_t memory_footprint() const noexcept {
    return sizeof(*this) + string_heap_bytes(name_) + start_.owned_bytes();
  }

  // ---- the data block ----
  const SpeedAxisData& data() const noexcept { return db_; }
  // A user-program write (spec 04 §0.2): DIR/CAL only; RES through write_start_value + restart.
  WriteResult write(std::string_view path, double value) noexcept;
  WriteResult write_start_value(std::string_view path, double value) noexcept;
  double read(std::string_view path) const noexcept;  // NaN for an unknown path; bits as "StatusWord.X5"
  const AlarmList& alarms() const noexcept { return core_.alarms; }
  // Simulation and commissioning: raise a technology alarm as if its cause had occurred, with the reaction it
  // would carry (for configurable reactions). Scenarios and tests use it to exercise every alarm reaction.
  // False for an alarm number tomc does not define.
  bool inject_alarm(std::uint32_t number, std::uint32_t additional_value, AlarmReaction reaction) noexcept;
  const DriveConnection* drive() const noexcept { return device_ == nullptr ? nullptr : &drive_; }

  // ---- the axis control panel (spec 02 §9.2) ----
  ControlPriority& control_priority() noexcept { return core_.control; }
  const ControlPriority& control_priority() const noexcept { return core_.control; }
  // Precondition of taking control priority: the user program has released the axis (MC_Power.Enable =
  // FALSE) and the TO is disabled.
  bool program_released() const noexcept { return !core_.enable && core_.phase == PowerPhase::kDisabled; }

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
  const CommunicationTimes& communication_times() const noexcept { return core_.communication_times; }
  JobStatus job_status(JobId id) const noexcept;

 private:
  using JobKind = AxisJobKind;
  struct Motion {  // the running base motion (MoveVelocity, Jog, Halt)
    JobId id = 0;
    JobKind kind = JobKind::kNone;
    ProfileLimits limits{};       // resolved, in revolutions/s, /s², /s³
    double command_velocity = 0;  // before override (rev/s, signed); Halt: 0
    double planned_target = 0;    // the target the profile was planned for
    bool jog_stopping = false;
    bool jog_error = false;
  };

  // The cycle, step by step (speed_axis.cpp).
  void read_actual_values() noexcept;     // MC_Servo: drive frames -> ActualSpeed, supervision
  void write_setpoint() noexcept;         // MC_Servo: drive request, speed setpoint, torque limit
  void take_reset() noexcept;             // MC_Interpolator: MC_Reset, restart
  void apply_alarm_reactions() noexcept;  // the reaction in force and its ramp
  void update_power_phase() noexcept;     // enable/disable per StopMode
  void update_live_motion() noexcept;     // jog inputs and the override
  void generate_setpoint() noexcept;      // profile or follow-up, job completion
  void update_status() noexcept;          // the data block's setpoints and words
  void restart() noexcept;
  // helpers
  std::array<RunningJob, 2> running_jobs(std::size_t& n) const noexcept;  // for the §9.19.1 columns
  std::uint16_t arbitrate_motion(NewJob row) noexcept;                    // 0 = accepted (aborts applied)
  void abort_motion(std::uint16_t error_id) noexcept;  // ends the base motion (0 = CommandAborted)
  void plan_velocity(double target, const ProfileLimits& limits, bool abort_acceleration) noexcept;
  std::optional<std::uint16_t> resolve_dynamics(double acceleration, double deceleration, double jerk,
                                                ProfileLimits& out) noexcept;
  DynamicUnits units() const noexcept { return {velocity_unit_per_revolution_per_second(), 1.0}; }
  double velocity_unit_per_revolution_per_second() const noexcept;
  double override_factor() const noexcept;
  double velocity_limit() const noexcept;  // rev/s
  bool virtual_axis() const noexcept { return device_ == nullptr; }

  std::string name_;
  DeviceIo* device_ = nullptr;
  StartValues<SpeedAxisData> start_;  // load memory (the runtime's StartValueStore once attached)
  SpeedAxisData db_;
  DriveConnectionConfig drive_config_;
  DriveConnection drive_;
  AxisCore core_;  // power, reset, alarms and reactions, MC_Stop, jobs, drive request, words

  // motion
  Motion motion_{};
  VelocityProfile profile_{};
  double profile_time_ = 0.0;
  bool generator_active_ = false;  // a profile drives the setpoint (else: hold / follow actual)
  MotionState setpoint_{};         // rev/s, rev/s²
  double actual_velocity_ = 0.0;   // rev/s, load side
  bool drive_has_momred_ = false;  // resolved at construction
  bool drive_has_meldw_ = false;
};

}  // namespace tomc::techobjects
