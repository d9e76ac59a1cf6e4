#pragma once
// TO_PositioningAxis (spec 01 §2–§8, spec 02 §2–§7, spec 03 §4, spec 04 column P): an axis that positions a
// load in user units. It assembles the issue-5 components — actual-value chain (encoder counts -> user units,
// modulo), position controller (Kv, precontrol, DSC), following-error / positioning / standstill monitors,
// software and hardware limit switches — around the job machinery the speed axis has: MC_Power, MC_Reset,
// alarm reactions, the §9.19.1 matrix, MC_Stop and MC_Halt. Motion jobs: MC_MoveAbsolute, MC_MoveRelative
// (BufferMode 0/1), MC_PositionProfile, MC_MoveVelocity, MC_MoveJog, MC_MotionInVelocity/Position, MC_Home.
//
// Units: the data block holds positions in Units.LengthUnit, velocities in Units.VelocityUnit; internally the
// axis computes in position units per second (axis_units.hpp). Positions are kept continuous internally; the
// data block shows them modulo-wrapped with their modulo cycle counters (spec 01 §2.4).
//
// Cycle: MC_Servo reads the drive and encoder, computes the actual values, runs the position controller on
// the setpoint of the last MC_Interpolator, and the servo-rate monitors; MC_Interpolator takes the jobs,
// applies alarm reactions, generates the setpoint, runs the software-limit look-ahead and updates the status.
// Both are noexcept and allocate nothing.

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

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
#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/drive/encoder_channel.hpp"
#include "tomc/techobjects/motion/axis_units.hpp"
#include "tomc/techobjects/motion/profiles.hpp"
#include "tomc/techobjects/motion/running_profile.hpp"
#include "tomc/techobjects/motion/time_position_profile.hpp"
#include "tomc/techobjects/position/actual_value_chain.hpp"
#include "tomc/techobjects/position/backlash.hpp"
#include "tomc/techobjects/position/dynamic_filter.hpp"
#include "tomc/techobjects/position/limit_switches.hpp"
#include "tomc/techobjects/position/passive_homing.hpp"
#include "tomc/techobjects/position/position_control.hpp"
#include "tomc/techobjects/position/position_monitoring.hpp"
#include "tomc/techobjects/positioning_axis/additional_encoders.hpp"
#include "tomc/techobjects/positioning_axis/superimposed_motion.hpp"
#include "tomc/techobjects/positioning_axis/superimposing_axes.hpp"
#include "tomc/techobjects/positioning_axis/synchronous_slot.hpp"
#include "tomc/techobjects/runtime/retained_encoder_data.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"
#include "tomc/techobjects/synchronous/actual_value_extrapolation.hpp"
#include "tomc/techobjects/synchronous/delayed_leading_value.hpp"
#include "tomc/techobjects/synchronous/leading_value.hpp"

namespace tomc::techobjects {

class PositioningAxis : public AxisObject<PositioningAxisData>, public LeadingValueSource {
 public:
  // `device` is the drive (and its encoders); nullptr for a virtual axis. Throws std::invalid_argument for
  // start values the data block does not permit, or mechanics/units that do not fit together, naming the
  // variable path.
  PositioningAxis(std::string name, DeviceIo* device, const PositioningAxisData& start_values,
                  const DriveConnectionConfig& drive = {});

  // ---- TechnologyObject ----
  void servo(const CycleClock& clock) noexcept override;
  void interpolate(const CycleClock& clock) noexcept override;

  // The object plus the heap it owns (start values only until the runtime adopted them), in bytes.
  std::size_t memory_footprint() const noexcept {
    return sizeof(*this) + shared_heap_bytes() + dynamic_filter_.history_bytes() + additional_.heap_bytes() +
           (superimposing_axes_ ? sizeof(SuperimposingAxisTable) : 0) +
           (delayed_ ? sizeof(DelayedLeadingValue) + delayed_->heap_bytes() : 0);
  }

  // ---- configuration before Runtime::start() ----
  // "Extended parameters > Superimposed axes" (seed 004 §6.14.3.2): `axis` becomes a possible superimposing
  // axis of this one for MC_MotionInSuperimposedAxes, and runs before it in every cycle (its setpoint is
  // added without a cycle offset). Throws std::invalid_argument for this axis itself, an axis given twice,
  // or more than SuperimposingAxisTable::kCapacity axes.
  void add_possible_superimposing_axis(PositioningAxis& axis);
  std::span<TechnologyObject* const> superimposing_axes() const noexcept override;

  // ---- the data block (data_block_object.hpp), and its digital inputs ----
  AxisDigitalInputs& digital_inputs() noexcept { return inputs_; }
  const AxisDigitalInputs& digital_inputs() const noexcept { return inputs_; }

  // ---- jobs (called by instructions from the user program), in the order of spec 03 §4 (seed 004 ch. 9)
  // ----
  PowerState power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept;  // 9.1
  Submission reset(bool restart) noexcept;                                                  // 9.2
  Submission home(const HomeInputs& in) noexcept;                                           // 9.3
  Submission halt(const HaltInputs& in) noexcept;                                           // 9.4
  Submission move_absolute(const MoveAbsoluteInputs& in) noexcept;                          // 9.5
  Submission move_relative(const MoveRelativeInputs& in) noexcept;                          // 9.6
  Submission position_profile(const PositionProfileInputs& in) noexcept;                    // 9.7
  Submission move_velocity(const MoveVelocityInputs& in) noexcept;                          // 9.8
  Submission jog(JobId running, const JogInputs& in) noexcept;                              // 9.9
  Submission move_superimposed(const MoveSuperimposedInputs& in) noexcept;                  // 9.10
  Submission halt_superimposed(const HaltSuperimposedInputs& in) noexcept;                  // 9.11
  Submission stop(const StopInputs& in) noexcept;                                           // 9.13
  // 9.12 MC_SetSensor (positioning_axis_encoders.cpp): Mode 0/1 make Sensor the operative encoder with /
  // without taking over the actual position, Mode 2/3 give Sensor the axis' / ReferenceSensor's position.
  // Done at once; no other job aborts it and it aborts none (spec 03 §4.12).
  Submission set_sensor(const SetSensorInputs& in) noexcept;
  // 9.15: 1000 PositionLimits_HW.Active (immediately), 1010/1011/1012 communication times (after restart),
  // 1020 Actor.RemoveEnableReaction (immediately).
  Submission write_parameter(std::int32_t parameter_number, double value) noexcept;
  // 9.17.1, 9.17.2 MotionIn, called on every user-program cycle while Enable = TRUE: `running` = 0 (the
  // rising edge) submits the job, the job's id takes the inputs over as the setpoints of the next
  // MC_Interpolator (motion_in.cpp). end_motion_in(): the falling edge of Enable.
  Submission motion_in_velocity(JobId running, const MotionInVelocityInputs& in) noexcept;
  Submission motion_in_position(JobId running, const MotionInPositionInputs& in) noexcept;
  // 9.17.3, 9.17.4 the superimposed MotionIn jobs, called the same way (positioning_axis_superimposed.cpp):
  // MotionInSuperimposed's inputs, or the setpoints of `superimposing` (a possible superimposing axis).
  Submission motion_in_superimposed(JobId running, const MotionInSuperimposedInputs& in) noexcept;
  Submission motion_in_superimposed_axes(JobId running, const LeadingValueSource* superimposing) noexcept;
  void end_motion_in(JobId running) noexcept;
  // 9.18.3 MC_TorqueLimiting, called on every user-program cycle: Mode 0 limits the drive's torque/force
  // through MOMRED, Mode 1 adds fixed-stop detection (positioning_axis_torque.cpp).
  TorqueLimitingState torque_limiting(const TorqueLimitingInputs& in) noexcept;
  // 9.18.1 MC_TorqueAdditive / 9.18.2 MC_TorqueRange: telegram 750 (torque_data.hpp), on every call.
  TorqueJobState torque_additive(const TorqueAdditiveInputs& in) noexcept;
  TorqueJobState torque_range(const TorqueRangeInputs& in) noexcept;
  // MC_Home.ReferenceMarkPosition of the last completed homing (spec 03 §4.3).
  double reference_mark_position() const noexcept { return reference_mark_position_; }

  // ---- retentive data (spec 02 §5.9): the absolute-encoder adjustment that survives a power cycle ----
  // What the CPU keeps retentively for the start-up encoder (PositionControl.InitialOperativeSensor, the one
  // restore_retained() gives back at power-up, whichever encoder MC_SetSensor made operative since): valid
  // once an absolute encoder was adjusted. Changes (MC_Home 6/7, the first active/passive homing of an
  // absolute encoder) increase `sequence`. Every other absolute encoder keeps its own (retained_of_sensor).
  using RetainedEncoderData = techobjects::RetainedEncoderData;
  const RetainedEncoderData& retained() const noexcept {
    return *retained_of_sensor(db_.PositionControl.InitialOperativeSensor);
  }
  // The retained adjustment of encoder Sensor[n] (1...4), wherever MC_SetSensor put it: an absolute encoder
  // adjusted while it was operative keeps it when another one closes the loop (decision B6); nullptr when
  // Sensor[n] does not exist.
  const RetainedEncoderData* retained_of_sensor(std::uint32_t n) const noexcept {
    if (n == db_.OperativeSensor) return &retained_;
    const AdditionalEncoder* e = additional_.find(n);
    return e != nullptr ? &e->retained : nullptr;
  }
  bool absolute_encoder() const noexcept;
  // Before Runtime::start(): the retained data of the last run (power-up of an absolute encoder).
  void restore_retained(const RetainedEncoderData& data) noexcept;
  // The same for encoder Sensor[n] that is not the start-up encoder: it powers up with that adjustment
  // (StatusSensor[n].Adjusted); the axis' homing state is the start-up encoder's alone.
  void restore_retained(std::uint32_t n, const RetainedEncoderData& data) noexcept;
  // Before Runtime::start(): the retained data could not be restored (1 backup missing, 2 corrupt, 3 no
  // record for this TO): alarm 432, the axis stays not homed — never a silently wrong position.
  void report_adjustment_lost(std::uint32_t cause) noexcept;

  // ---- as a leading value (spec 07 §1.3, §1.4) ----
  LeadingValue leading_value(LeadingValueCoupling coupling) const noexcept override;
  ModuloRange leading_value_modulo() const noexcept override;
  // A synchronous axis has this axis among its possible leading values: a modulo axis is then limited to
  // half a modulo length per servo cycle with warning 501 instead of alarm 412 at a whole one (spec 01 §8.6).
  void set_possible_leading_value() noexcept override { possible_leading_value_ = true; }
  // A follower couples "Delayed" (spec 07 §1.5): the history of CrossPlcSynchronousOperation.
  // LocalLeadingValueDelayTime (the value in the data block now) is allocated once; later followers share it.
  // Throws std::invalid_argument naming the key for a delay the history cannot hold (decision C26).
  void provide_delayed_leading_value(double interpolator_cycle_s) override;

  // ---- for tests, diagnostics and the synchronous axis ----
  // The setpoint the interpolator generated last (continuous position, before modulo wrap).
  const MotionState& setpoint() const noexcept { return setpoint_; }
  // The superimposed part of it (MC_MoveSuperimposed, MC_HaltSuperimposed); the base motion is the rest.
  const SuperimposedMotion& superimposed() const noexcept { return superimposed_; }
  // The same after the dynamic filter, as the position controller used it in the last servo cycle.
  const MotionState& filtered_setpoint() const noexcept { return filtered_; }
  const BacklashCompensation& backlash() const noexcept { return backlash_; }
  const DynamicFilter& dynamic_filter() const noexcept { return dynamic_filter_; }
  double continuous_actual_position() const noexcept { return actual_position_; }
  bool position_controlled() const noexcept { return position_controlled_; }
  // The encoders besides the operative one (spec 01 §3.8).
  const AdditionalEncoders& additional_encoders() const noexcept { return additional_; }
  const EncoderChannel& operative_encoder() const noexcept { return encoder_; }
  const AxisUnitFactors& units() const noexcept { return units_; }

 protected:
  // A synchronous axis fills the slot once, at construction (synchronous_slot.hpp).
  void attach_synchronous(SynchronousSlot& slot) noexcept { synchronous_ = &slot; }

 private:
  friend class FollowingAxis;  // the synchronous operation's port (synchronous/following_axis.hpp)
  using JobKind = AxisJobKind;
  // What drives the setpoint this cycle.
  // kTimeProfile: MC_PositionProfile on its profile; kMotionIn: the MotionIn inputs act directly.
  enum class Generator : std::uint8_t { kIdle, kVelocity, kPosition, kSynchronous, kTimeProfile, kMotionIn };

  // A base motion job (running or appended); members ordered to leave no padding. MC_PositionProfile and
  // MotionIn reuse the fields named for them below instead of adding their own (the 8 KiB budget, decision
  // L2).
  struct Motion {
    ProfileLimits limits{};       // resolved (position units), velocity before override
    double command_velocity = 0;  // MoveVelocity/Jog: signed; positioning: v_cmd; before override and clamp;
                                  // MotionIn: Velocity
    double target = 0;            // positioning: continuous target position; MotionInPosition: Position
    double distance =
        0;  // appended positioning: target relative to the end of the running job; PositionProfile:
            // the time on the profile (StartTime until it follows it); MotionIn: Acceleration
    double absolute_position = 0;  // appended MoveAbsolute: the requested position; PositionProfile: the
                                   // shift from profile positions to the continuous position
    double planned_velocity = 0;   // the velocity limit the profile was planned with (override changes)
    // PositionProfile: the user's profile, a point structure or a TO_Cam by time_from_cam (one pointer for
    // either: the 8 KiB budget); time_source() reads it.
    union {
      const TimePositionProfile* time_points = nullptr;
      const Cam* time_cam;
    };  // PositionProfile: the user's profile
    JobId id = 0;
    std::int32_t direction = 1;  // appended MoveAbsolute on a modulo axis; PositionProfile: ProfileReference
    JobKind kind = JobKind::kNone;
    bool relative_to_end = false;  // appended MoveRelative: Distance counts from the running job's target
    bool jog_stopping = false;
    bool position_controlled = true;
    bool interpolation_done =
        false;                     // positioning: the setpoint has reached the target (PositionProfile: end)
    bool halt_base_only = false;   // MC_Halt Mode 1: a §9.19.1 C3 job, the superimposed motion goes on
    bool profile_limited = false;  // PositionProfile: DynamicLimits hold the setpoint off the profile
    bool time_from_cam = false;    // PositionProfile: time_cam, else time_points

    TimePositionSource time_source() const noexcept {
      return time_from_cam ? TimePositionSource{time_cam} : TimePositionSource{time_points};
    }
    void set_time_source(const TimePositionSource& source) noexcept {
      time_from_cam = source.cam() != nullptr;
      if (time_from_cam) {
        time_cam = source.cam();
      } else {
        time_points = source.points();
      }
    }
  };

  // homing (positioning_axis_homing.cpp)
  enum class HomingPhase : std::uint8_t {
    kIdle,
    kApproach,       // towards the reference cam / digital input at ApproachVelocity (ActiveHoming.Mode 1, 2)
    kLeaveInput,     // digital input: back off it, against the homing direction, to meet the mark edge
    kSearchEdge,     // digital input: towards the mark edge in the homing direction at ReferencingVelocity
    kSearchCamExit,  // cam + zero mark: leaving the cam in the homing direction arms the zero-mark search
    kSearchMark,     // zero mark armed, in the homing direction at ReferencingVelocity
    kToHome,         // homed: to the home position at ApproachVelocity
  };
  struct ActiveHomingJob {          // members ordered to leave no padding (8 KiB per axis TO)
    double home_position = 0.0;     // MC_Home.Position (3) or Homing.HomePosition (5)
    double mark_value = 0.0;        // home position - HomePositionOffset
    double direction = 1.0;         // homing direction (ActiveHoming.Direction)
    double travel_direction = 1.0;  // the direction of the present search motion
    std::int32_t method = 0;        // Sensor[n].ActiveHoming.Mode
    std::int16_t limit_reversals = 0;
    HomingPhase phase = HomingPhase::kIdle;
    bool mark_on_entering = false;  // digital input: the mark is the edge onto the input
  };
  struct PassiveHomingJob {
    JobId id = 0;
    double value = 0.0;  // position assigned at the mark
  };
  void start_active_homing(JobId id, double home_position) noexcept;
  Submission home_other_encoder(const HomeInputs& in) noexcept;  // MC_Home.Sensor: not the operative one
  void homing_observe() noexcept;  // MC_Servo: reference mark, digital-input edges, reversal cams
  void run_homing() noexcept;      // MC_Interpolator
  void run_passive_homing() noexcept;
  void end_passive_homing(JobState state, std::uint16_t error_id = 0) noexcept;
  void homing_move(double direction, double velocity) noexcept;
  void assign_reference(double mark_position, double value, double home_position) noexcept;
  void fail_homing(std::uint32_t cause) noexcept;
  bool input_active() const noexcept;
  void store_adjustment() noexcept;

  static constexpr bool synchronous_kind(JobKind k) noexcept {
    return k == JobKind::kGearIn || k == JobKind::kGearInPos || k == JobKind::kGearInVelocity ||
           k == JobKind::kGearOut || k == JobKind::kCamIn || k == JobKind::kCamOut;
  }

  // ---- the synchronous axis' slot (synchronous_slot.hpp; empty on a positioning axis) ----
  std::uint16_t arbitrate_synchronous(NewJob row) noexcept {
    return synchronous_ != nullptr ? synchronous_->arbitrate(row) : 0;
  }
  void abort_synchronous(std::uint16_t error_id) noexcept {
    if (synchronous_ != nullptr) synchronous_->abort(error_id);
  }
  void restart_synchronous() noexcept {
    if (synchronous_ != nullptr) synchronous_->restart();
  }
  void run_synchronous() noexcept {
    if (synchronous_ != nullptr) synchronous_->run();
  }
  MotionState synchronous_setpoint() const noexcept {
    return synchronous_ != nullptr ? synchronous_->setpoint() : setpoint_;
  }
  bool following_in_synchronous_operation() const noexcept {
    return synchronous_ != nullptr && synchronous_->following();
  }
  void update_synchronous_status() noexcept {
    if (synchronous_ != nullptr) synchronous_->update_status();
  }

  // a DIR/CAL write re-reads the components; a start value switching the dynamic filter on reserves it
  void written(std::string_view path) noexcept override;
  ValueError start_value_written(std::string_view path, double value) noexcept override;
  // configuration
  void configure_components() noexcept;
  void configure_monitoring() noexcept;
  void configure_backlash_and_filter() noexcept;  // Sensor[n].Backlash, SetpointFilter (issue 5)
  void configure_extrapolation() noexcept;
  PositionControlConfig position_control_config(double quantization) const noexcept;
  // multiple encoders (positioning_axis_encoders.cpp)
  // every encoder's chain from its Sensor[n], the axis mechanics and the cycle time
  void configure_encoders(const AxisMechanics& mechanics) noexcept;
  void read_additional_encoders() noexcept;  // MC_Servo: the encoders that do not close the loop
  void write_additional_encoder_controls() noexcept;
  void power_up_additional_encoders() noexcept;  // absolute ones with their retained adjustment
  void update_additional_encoder_status() noexcept;
  // A simulated axis (decision B7): every other encoder reads the simulated load travel of this servo cycle
  // through its own mechanics; seed_simulated_encoder() gives its chain `counts` Gx_XIST1 increments (and
  // an absolute encoder the matching Gx_XIST2) as its first value after power-up or restart.
  void simulate_additional_encoders(double travel) noexcept;
  void seed_simulated_encoder(AdditionalEncoder& e, std::int64_t counts) noexcept;
  // Encoder n's continuous position (the operative one of a virtual or simulated axis: the axis' own).
  double sensor_position(std::uint32_t n) noexcept;
  // The encoder Sensor[n] becomes the operative one: channel, retained data and fault state change places
  // with the additional encoder n (no allocation). n must exist.
  std::uint32_t make_operative(std::uint32_t n) noexcept;
  ActualValueChain* sensor_chain(std::uint32_t n) noexcept;  // encoder n's chain; nullptr: none
  void transfer_position(std::uint32_t n, double position, bool adjusted) noexcept;
  void discard_absolute_compensation() noexcept;  // returns the operative encoder number
  // jobs
  std::uint16_t motion_prerequisites() const noexcept { return core_.motion_prerequisites(); }
  std::optional<std::uint16_t> resolve_dynamics(double velocity, double acceleration, double deceleration,
                                                double jerk, ProfileLimits& out) noexcept;
  std::uint16_t arbitrate_motion(NewJob row, bool& queue) noexcept;
  std::array<RunningJob, 5> running_jobs(std::size_t& n) const noexcept;
  void abort_motion(std::uint16_t error_id) noexcept;
  void abort_pending(std::uint16_t error_id) noexcept;
  // superimposed motion (positioning_axis_superimposed.cpp)
  // The running superimposed job ends (CommandAborted, or Error with error_id). fold: its velocity and
  // acceleration go over into the base motion (every abort but a new superimposed job's, §9.19.1 R6 x C7).
  void abort_superimposed(std::uint16_t error_id, bool fold = true) noexcept;
  // MC_Interpolator, after the base setpoint: total = base + superimposed. Inline: an axis without
  // superimposed motion pays two tests per cycle.
  void run_superimposed() noexcept {
    if (superimposed_.moving()) advance_superimposed();
    const MotionState& s = superimposed_.state();
    if (s.position == 0.0 && s.velocity == 0.0 && s.acceleration == 0.0) return;
    setpoint_.position += s.position;
    setpoint_.velocity += s.velocity;
    setpoint_.acceleration += s.acceleration;
    // A positioning check that waits for the superimposed motion checks the total position; beside a MotionIn
    // superimposition, the base position (decision U13).
    if (positioning_start_pending_) positioning_target_ = positioning_reference();
  }
  // The position a finished base job's positioning check holds the actual value to: the total setpoint, or
  // beside a MotionIn superimposition the base setpoint (decision U13).
  double positioning_reference() const noexcept {
    return superimposed_.motion_in() ? base_setpoint().position : setpoint_.position;
  }
  void advance_superimposed() noexcept;
  void settle_superimposed() noexcept;  // both motions finished: the superimposed part joins the base
  MotionState base_setpoint() const noexcept {
    const MotionState& s = superimposed_.state();
    return MotionState{setpoint_.position - s.position, setpoint_.velocity - s.velocity,
                       setpoint_.acceleration - s.acceleration};
  }
  std::optional<double> absolute_target(double position, std::int32_t direction, double from) const noexcept;
  void start_positioning(Motion motion) noexcept;
  // MC_PositionProfile (position_profile_job.cpp)
  void start_motion(const Motion& motion) noexcept;  // an appended job becomes active
  void start_time_profile(Motion motion) noexcept;   // transition profile, or on the profile at once
  // The transition ended `elapsed` s ago (within this cycle) with the base setpoint at `base_position`:
  // follow the profile from StartTime + elapsed.
  void enter_time_profile(double base_position, double elapsed = 0.0) noexcept;
  void follow_time_profile() noexcept;  // Generator::kTimeProfile, one interpolator cycle
  void check_profile_limits(const Motion& motion) noexcept;  // alarms 501/502 (seed 004 §6.8.4)
  // MotionIn (motion_in.cpp)
  Submission motion_in(JobKind kind, JobId running, const MotionState& setpoint,
                       bool position_controlled) noexcept;
  void follow_motion_in() noexcept;  // Generator::kMotionIn
  // setpoint generation
  void plan_velocity(double target, const ProfileLimits& limits, bool abort_acceleration) noexcept;
  void plan_position(double target, const ProfileLimits& limits) noexcept;
  // The running positioning job's profile for velocity limit v (override applied); v = 0 (override 0 %):
  // stop, the job stays active until the override returns.
  void plan_positioning(double v) noexcept;
  double override_factor() const noexcept { return core_.override_factor(db_.Override); }
  double velocity_limit() const noexcept {  // position units / s
    return std::min(AxisCore::velocity_limit(db_.DynamicLimits, dynamic_units()),
                    modulo_leader_velocity_limit());
  }
  // Modulo.Length / (2·T_servo) on a modulo axis that is a possible leading value (spec 01 §8.6), else ∞.
  // Inline, as positioning_velocity(): the running positioning job reads them every interpolator cycle.
  double modulo_leader_velocity_limit() const noexcept {
    if (!possible_leading_value_ || !modulo()) return std::numeric_limits<double>::infinity();
    return db_.Modulo.Length / (2.0 * servo_cycle_s_);
  }
  DynamicUnits dynamic_units() const noexcept { return {units_.velocity, units_.acceleration}; }
  double positioning_velocity(const Motion& motion) const noexcept {  // spec 01 §8.5 v_eff
    return std::min(motion.command_velocity * override_factor(), velocity_limit());
  }
  void raise(std::uint32_t number, std::uint32_t additional = 0) noexcept { core_.raise(number, additional); }
  void raise_with(std::uint32_t number, std::uint32_t additional, std::int32_t reaction) noexcept;
  void apply_alarm_reactions() noexcept;
  void update_power_phase() noexcept;
  void update_live_motion() noexcept;
  void generate_setpoint() noexcept;
  void monitor_software_limits(const MotionState& previous_setpoint) noexcept;
  MotionState predicted_setpoint(double dt) const noexcept;  // the generator dt ahead, no job changes
  void complete_jobs() noexcept;
  void update_status() noexcept;
  void restart() noexcept;
  // The start values a restart takes over, checked together (decision B8): Simulation.Mode and
  // PositionControl.InitialOperativeSensor that break a rule of seed 004 §6.1.7 / spec 04 §3.20 keep the
  // values in force (`simulation_mode`, `initial_sensor`) and return the rule (alarm 102's additional value);
  // 0: all of them apply.
  std::uint32_t restart_configuration(std::uint32_t& simulation_mode,
                                      std::uint32_t& initial_sensor) const noexcept;
  void choose_control_loop() noexcept;  // PositionController with a drive in use, else the simulated delay
  // torque limiting and fixed-stop detection (positioning_axis_torque.cpp)
  std::uint16_t torque_limiting_rejection(const TorqueLimitingInputs& in) const noexcept;
  void servo_torque_limiting() noexcept;  // MC_Servo: MOMRED, STW2.8, InLimitation, clamping
  void apply_clamping() noexcept;         // MC_Interpolator: the jobs a clamping ends
  // MC_Servo: telegram 750 — M_ADD1 (MC_TorqueAdditive + torque precontrol), the limits of MC_TorqueRange,
  // StatusTorqueData from M_ACT (spec 01 §8.12/§8.13, spec 02 §7.5).
  void servo_torque_data() noexcept;
  double torque_precontrol() const noexcept;  // spec 02 §7.5, technology units (0 when not in force)
  TorqueDataConditions torque_data_conditions() const noexcept;
  // TorqueLimiting.PositionBasedMonitorings = 0: following-error and positioning monitoring are off while
  // MC_TorqueLimiting or MC_TorqueRange limits (spec 01 §8.10, §8.13; decision Q4).
  // Inline: the servo's monitoring asks it every cycle.
  bool position_monitorings_suspended() const noexcept {
    return (core_.torque.active || core_.torque_data.range_active()) &&
           db_.TorqueLimiting.PositionBasedMonitorings ==
               static_cast<std::int32_t>(PositionBasedMonitoringMode::kDeactivated);
  }
  // servo
  void read_actual_values() noexcept;
  void simulate_actual_values() noexcept;
  void control() noexcept;
  void servo_monitoring() noexcept;
  void shift_position(double delta) noexcept;  // direct homing: actual and setpoint move together
  bool blocked() const noexcept { return core_.blocked(); }
  // AxisObject::drive_used() as of the last construction or restart, the only moments its inputs change
  // (Simulation.Mode is RES): one byte the cycle tests instead of three members (decision B8).
  bool drive_used() const noexcept { return drive_used_; }
  // No drive in use: a virtual or a simulated axis, or one built without a drive (drive_used(), decision B8).
  bool virtual_axis() const noexcept { return !drive_used(); }
  // Simulation.Mode = 1 without VirtualAxis.Mode: actual values through a simulated control loop (§2.6);
  // the work memory's value, which a restart takes over (B8).
  bool simulated() const noexcept {
    return db_.Simulation.Mode == kModeOn && db_.VirtualAxis.Mode != kModeOn;
  }
  bool homed() const noexcept;
  bool follows_actual() const noexcept { return core_.follows_actual(); }
  bool modulo() const noexcept { return db_.Modulo.Enable; }

  PositionController* controller() noexcept { return std::get_if<PositionController>(&control_loop_); }
  BasicSetpointDelayLine<kSimulationDelayCycles>* simulation_delay() noexcept {
    return std::get_if<BasicSetpointDelayLine<kSimulationDelayCycles>>(&control_loop_);
  }

  // Member order (decision O5): what the steady MC_Servo + MC_Interpolator cycle reads and writes comes first
  // and together — the superimposed motion, whose own state sits at its end, then the scalars and flags, then
  // the monitors and components with their hot parts; what only jobs, homing or configuration use comes last.
  // bench/touched_bytes.py --offsets measures it; sizeof 6,864 since decision M12 (memory_per_axis_tests).
  SuperimposedMotion superimposed_{};
  double servo_cycle_s_ = 0.001;
  AxisUnitFactors units_{};
  ServoCommand command_{};  // what MC_Servo sends the drive (one writer: DriveConnection::write)
  MotionState setpoint_{};  // continuous position units: base + superimposed
  double profile_time_ = 0.0;
  MotionState filtered_{};  // x_f, v_f, a_f: the setpoint after the dynamic filter, this servo cycle
  // actual values (continuous position units)
  double actual_position_ = 0.0;
  double actual_velocity_ = 0.0;
  // MC_SetSensor Mode 1: the old encoder's position minus the new one's, added to the actual value and
  // decaying with PositionControl.SmoothingTimeByChangeDifference (spec 01 §3.8).
  double sensor_switch_difference_ = 0.0;
  double profile_offset_ = 0.0;  // direct homing during a profile: its positions move with the axis
  double last_actual_velocity_ = 0.0;
  SynchronousSlot* synchronous_ = nullptr;

  // ---- one-byte state, kept together so that it leaves no padding (8 KiB per axis TO, issue 18) ----
  AxisDigitalInputs inputs_{};
  bool servo_cycle_known_ = false;
  bool position_controlled_ = true;
  Generator generator_ = Generator::kIdle;
  bool positioning_start_pending_ = false;  // servo starts the positioning monitor with positioning_target_
  bool limit_stop_ = false;                 // a software-limit stop to limit_stop_position_ is in force
  limits::LimitSide reversal_cam_ = limits::LimitSide::kNone;  // reached this cycle (for the interpolator)
  limits::LimitSide reversal_cam_seen_ = limits::LimitSide::kNone;  // reported by the monitor last cycle
  bool retained_restored_ = false;
  bool homed_ = false;
  bool actual_valid_ = false;
  bool encoder_fault_seen_ = false;
  FollowingErrorAlarm following_error_state_ = FollowingErrorAlarm::kNone;
  bool clamp_abort_pending_ = false;     // MC_Servo detected the stop; MC_Interpolator ends the jobs
  bool drive_has_momred_ = false;        // the drive telegram carries MOMRED (resolved at construction)
  bool drive_has_meldw_ = false;         // ... and MELDW
  bool possible_leading_value_ = false;  // interconnected as a leading value of a synchronous axis
  bool acceleration_was_zero_ = true;    // the setpoint's acceleration in the last cycle (ConstantVelocity)
  bool superimposing_error_ = false;     // ErrorWord.X16: a superimposing axis was not a possible one
  bool positioning_on_base_ = false;     // the positioning check runs on actual - superimposed (U13)
  bool drive_used_ = false;              // AxisObject::drive_used(), set by choose_control_loop() (B8)

  // monitors
  FollowingErrorMonitor following_error_;
  StandstillSignal standstill_;
  limits::HardwareLimitMonitor hardware_limits_;
  ClampingMonitor clamping_{};  // MC_TorqueLimiting (spec 01 §8.10/§8.11)
  PassiveHomingJob passive_{};
  InputEdges input_edges_{};  // edges of the homing digital input / cam, latched by MC_Servo
  limits::SoftwareLimitMonitor software_limits_;
  // ---- backlash compensation (spec 01 §5.9) ----
  BacklashCompensation backlash_;

  // motion and the components the cycle runs
  Motion motion_{};
  ActualValueExtrapolation extrapolation_{};  // the actual value as a leading value (spec 07 §1.4)
  EncoderChannel
      encoder_;  // the operative encoder, Sensor[OperativeSensor] (its mechanics: encoder_.chain())
  // A drive-connected axis closes the position loop (PositionController); a virtual or simulated axis has
  // none, only the simulated control loop's delay (spec 01 §2.5, §2.6). One storage for either (issue 14).
  std::variant<PositionController, BasicSetpointDelayLine<kSimulationDelayCycles>> control_loop_;
  // The generator's profile: a velocity plan for Generator::kVelocity, a position plan for kPosition (one
  // storage for both, issue 14; planned into a temporary and taken over only when the plan succeeds), kept
  // as its inputs and two segments (decision M12).
  RunningProfile profile_;

  // ---- cold: options that are off in the steady cycle, jobs and homing state, configuration ----
  DynamicFilter dynamic_filter_;  // spec 02 §7.6
  PositioningMonitor positioning_;
  AdditionalEncoders additional_;        // the other Sensor[n].Existent encoders (spec 01 §3.8, decision B1)
  std::optional<double> mark_position_;  // a reference mark captured by MC_Servo
  RetainedEncoderData retained_{};
  Motion pending_{};  // BufferMode 1
  ActiveHomingJob homing_{};
  PassiveHomingSearch passive_search_{};
  double positioning_target_ = 0.0;
  double limit_stop_position_ = 0.0;
  double reference_mark_position_ = 0.0;
  std::unique_ptr<SuperimposingAxisTable> superimposing_axes_;  // configured only when used
  std::unique_ptr<DelayedLeadingValue> delayed_;  // only while a follower couples "Delayed" (C26)
};

}  // namespace tomc::techobjects
