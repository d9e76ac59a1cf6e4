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
#include "tomc/techobjects/axis/data_block_object.hpp"
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

class SpeedAxis final : public AxisObject<SpeedAxisData> {
 public:
  // `device` is the drive; nullptr for a virtual axis or simulation (VirtualAxis.Mode / Simulation.Mode = 1).
  // With Simulation.Mode = 1 a given drive is kept unused (the link on, the drive off) until a restart ends
  // the simulation (decision B8).
  // Throws std::invalid_argument for start values the data block does not permit (reported with their path).
  SpeedAxis(std::string name, DeviceIo* device, const SpeedAxisData& start_values,
            const DriveConnectionConfig& drive = {});

  // ---- TechnologyObject ----
  void servo(const CycleClock& clock) noexcept override;
  void interpolate(const CycleClock& clock) noexcept override;

  // The object plus the heap it owns (start values only until the runtime adopted them), in bytes.
  std::size_t memory_footprint() const noexcept { return sizeof(*this) + shared_heap_bytes(); }

  // ---- jobs (called by instructions from the user program), in the order of spec 03 §4 (seed 004 ch. 9)
  // ---- 9.1 MC_Power: level-class; called once per instruction call.
  PowerState power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept;
  Submission reset(bool restart) noexcept;                          // 9.2
  Submission halt(const HaltInputs& in) noexcept;                   // 9.4
  Submission move_velocity(const MoveVelocityInputs& in) noexcept;  // 9.8
  // 9.9 MC_MoveJog: level-class. Starts a jog job on the first call with an input set, updates it later.
  Submission jog(JobId running, const JogInputs& in) noexcept;
  Submission stop(const StopInputs& in) noexcept;  // 9.13
  // 9.15 MC_WriteParameter: 1010/1011/1012 communication times (s, after restart), 1020
  // Actor.RemoveEnableReaction (immediately). 1000 belongs to positioning axes.
  Submission write_parameter(std::int32_t parameter_number, double value) noexcept;
  // 9.17.1 MC_MotionInVelocity (speed_axis_motion_in.cpp), called on every user-program cycle while Enable =
  // TRUE: the Velocity (and Acceleration) act directly in the next MC_Interpolator; end_motion_in() is the
  // falling edge. PositionControlled does not apply to a speed axis.
  Submission motion_in_velocity(JobId running, const MotionInVelocityInputs& in) noexcept;
  void end_motion_in(JobId running) noexcept;
  // 9.18.3 MC_TorqueLimiting: Mode 0 torque limiting through MOMRED (telegrams 10x); fixed-stop detection
  // (Mode 1) is for positioning and synchronous axes only.
  TorqueLimitingState torque_limiting(const TorqueLimitingInputs& in) noexcept;
  // 9.18.1 MC_TorqueAdditive / 9.18.2 MC_TorqueRange: telegram 750 (torque_data.hpp), on every call.
  TorqueJobState torque_additive(const TorqueAdditiveInputs& in) noexcept;
  TorqueJobState torque_range(const TorqueRangeInputs& in) noexcept;

 private:
  using JobKind = AxisJobKind;
  struct Motion {  // the running base motion (MoveVelocity, Jog, Halt, MotionInVelocity)
    JobId id = 0;
    JobKind kind = JobKind::kNone;
    ProfileLimits limits{};       // resolved, in revolutions/s, /s², /s³
    double command_velocity = 0;  // before override (rev/s, signed); Halt: 0; MotionIn: Velocity
    double planned_target = 0;    // the target the profile was planned for; MotionIn: Acceleration
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
  double velocity_limit() const noexcept;                       // rev/s
  bool virtual_axis() const noexcept { return !drive_used(); }  // virtual, simulated or built without drive
  TorqueDataConditions torque_data_conditions() const noexcept;

  ServoCommand command_{};  // what MC_Servo sends the drive (one writer: DriveConnection::write)

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
