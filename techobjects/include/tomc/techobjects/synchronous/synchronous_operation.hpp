#pragma once
// The synchronous operation of a synchronous axis (spec 07 §1.8, §2, §5, §6): the component that
// TO_SynchronousAxis adds to its positioning axis (issue 14) through the axis' synchronous slot. It owns the
// leading-value interconnections, the gearing jobs (MC_GearIn, MC_GearInPos, MC_GearInVelocity, MC_GearOut),
// the camming jobs (MC_CamIn, MC_CamOut; camming.cpp), the §9.19.2 decisions against them
// (sync_priority.hpp), the chain "function leading value -> synchronous function -> following value" and
// <TO>.StatusSynchronizedMotion. It reaches its axis only through the FollowingAxis port. Gearing and camming
// share the pending/active/desynchronizing job states, the leader-domain blend and the desynchronization;
// only the synchronous function differs (a gear line or a cam). Phasing and offsets (phasing_offset.cpp)
// shift the function leading value and the following value around it.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/cam/cam_synchronous_function.hpp"
#include "tomc/techobjects/positioning_axis/synchronous_slot.hpp"
#include "tomc/techobjects/synchronous/following_axis.hpp"
#include "tomc/techobjects/synchronous/leading_value.hpp"
#include "tomc/techobjects/synchronous/sync_priority.hpp"
#include "tomc/techobjects/synchronous/synchronous_motion.hpp"

namespace tomc::techobjects {

// One configured possible leading value of the follower (spec 07 §1.2, "LeadingValueInterconnections").
struct LeadingValueInterconnection {
  TechnologyObject* object = nullptr;    // the leading TO (its place in the cycle)
  LeadingValueSource* source = nullptr;  // the same TO as a leading value
  LeadingValueCoupling coupling = LeadingValueCoupling::kSetpoint;
  // V10 "leading value reversal tolerance" (spec 07 §1.6 [OPEN], a tomc extension; decision C27): how far, in
  // the leader's length unit, the effective leading value may move back from the farthest value it reached
  // during synchronization or a leading/following value offset before that counts as a reversal (alarm 608,
  // 16#808C). 0: any reversal counts. A float fills the padding after `coupling` (24 bytes either way).
  float reversal_tolerance = 0.0F;
};

// Inputs of the gearing instructions (spec 07 §2, V8 parameter lists). Negative dynamics = DynamicDefaults.
struct GearInInputs {
  const LeadingValueSource* Master = nullptr;
  std::int32_t RatioNumerator = 1;
  std::int32_t RatioDenominator = 1;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
};
struct GearInPosInputs {
  const LeadingValueSource* Master = nullptr;
  std::int32_t RatioNumerator = 1;
  std::int32_t RatioDenominator = 1;
  double MasterSyncPosition = 0.0;
  double SlaveSyncPosition = 0.0;
  std::int32_t SyncProfileReference = 1;  // 0 dynamic parameters, 1 leading value distance, 3 subsequent
  double MasterStartDistance = 1.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t SyncDirection = 3;  // modulo follower: 1 positive, 2 negative, 3 shortest
};
struct GearInVelocityInputs {
  const LeadingValueSource* Master = nullptr;
  std::int32_t RatioNumerator = 1;
  std::int32_t RatioDenominator = 1;
  bool ContinuousUpdate = false;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool PositionControlled = false;
};
struct GearOutInputs {
  double SlavePosition = 0.0;
  std::int32_t SyncProfileReference = 1;  // 0 dynamic parameters, 1 leading value distance, 5 cancel pending
  double MasterStopDistance = 0.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t SyncOutDirection = 3;  // 1 only while moving positive, 2 only negative, 3 current direction
};

// MC_CamIn (spec 07 §3.4, V8 parameter list). Negative dynamics = DynamicDefaults (profile 0 only).
struct CamInInputs {
  const LeadingValueSource* Master = nullptr;
  techobjects::Cam* Cam = nullptr;  // interpolated; in use (StatusWord.X0) while the job runs or waits
  double MasterOffset = 0.0;        // profiles 0, 1, 3, 4
  double SlaveOffset = 0.0;         // profiles 0, 1, 3, 4, 6
  double MasterScaling = 1.0;
  double SlaveScaling = 1.0;
  double MasterSyncPosition = 0.0;        // leader units from the scaled cam start
  std::int32_t SyncProfileReference = 1;  // 0…6 (spec 07 §3.4 table)
  double MasterStartDistance = 0.0;       // profiles 1, 3, 4, 6: > 0
  double Velocity = -1.0;                 // profile 0
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t ApplicationMode = 0;  // 0 not cyclic, 1 cyclic, 2 cyclic appending
  std::int32_t SyncDirection = 3;    // modulo follower: 1 positive, 2 negative, 3 shortest
};
// MC_CamOut has MC_GearOut's parameters (spec 07 §3.5).
using CamOutInputs = GearOutInputs;

// MC_PhasingAbsolute / MC_PhasingRelative (spec 07 §4.1, V8 parameter list): a leading value offset.
// Negative dynamics = DynamicDefaults (profile 0 only; the velocity is not limited to MaxVelocity).
struct PhasingInputs {
  const LeadingValueSource* Master = nullptr;  // the leading value the synchronous operation follows
  double PhaseShift = 0.0;                     // absolute target or relative increment
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t ProfileReference = 0;  // 0 dynamics (gearing), 1 distance, 2 from StartPosition, 5 cancel
  double PhasingDistance = 0.0;
  double StartPosition = 0.0;
  std::int32_t Direction = 3;  // 1 only while the leading value moves positive, 2 negative, 3 current
};
// MC_OffsetAbsolute / MC_OffsetRelative (spec 07 §4.2): a following value offset, over a distance only.
struct OffsetInputs {
  double Offset = 0.0;
  std::int32_t ProfileReference = 1;  // 1 distance, 2 from StartPosition, 5 cancel a waiting job
  double OffsetDistance = 0.0;
  double StartPosition = 0.0;
  std::int32_t Direction = 3;
};
// MC_LeadingValueAdditive (spec 07 §4.3): added to the leading value (leader units; velocity and acceleration
// in the follower's velocity and acceleration units, as EffectiveLeadingValue shows them).
struct LeadingValueAdditiveValues {
  double Position = 0.0;
  double Velocity = 0.0;
  double Acceleration = 0.0;
};

// StartPhasing / StartOffset, and the shift reached: AbsolutePhaseShift / AbsoluteOffset (Absolute), the
// part this job covered: CoveredPhaseShift / CoveredOffset (Relative).
struct ShiftJobOutputs {
  bool Start = false;
  double Absolute = 0.0;
  double Covered = 0.0;
};

// Outputs beyond the handshake (spec 07 §2, §3.4): InGear/InSync, StartSync, StartSyncOut,
// ContinuousUpdateActive, and the cam ends a camming job passed (MC_CamIn.EndOfProfile shows a new count for
// one call, so that a user program slower than MC_Interpolator sees every end).
struct SyncJobOutputs {
  bool StartSync = false;
  bool InSync = false;
  bool StartSyncOut = false;
  bool ContinuousUpdateActive = false;
  std::uint32_t EndOfProfileCount = 0;
};

// <TO>.StatusSynchronizedMotion (spec 07 §1.9; the struct is not defined in the V10 manual).
struct StatusSynchronizedMotion {
  std::int32_t FunctionState =
      0;  // 0 none, 1 GearIn, 2 GearInPos, 3 CamIn, 4 GearOut, 5 CamOut, 6 GearInVel.
  std::int32_t WaitingFunctionState = 0;  // 0 none, 2 GearInPos, 3 CamIn, 4 GearOut, 5 CamOut waiting
  double PhaseShift = 0.0;
  std::uint16_t ActualMaster = 0;  // tomc: 1-based index of the interconnection in use; 0 = none
  std::uint16_t ActualCam = 0;     // tomc: Cam::number() of the cam in use; 0 = none (decision C8)
  // The cam in use with its offsets and scalings, automatic offsets of profiles 2, 5, 6 included (spec 07
  // §1.9).
  double MasterOffset = 0.0;
  double MasterScaling = 1.0;
  double SlaveOffset = 0.0;
  double SlaveScaling = 1.0;
  double Offset = 0.0;  // following value offset, the camming's SlaveOffset included
  struct {
    double Position = 0.0;
    double Velocity = 0.0;
    double Acceleration = 0.0;
  } EffectiveLeadingValue;
  struct {
    double Position = 0.0;
  } FunctionLeadingValue;
  struct {
    double Position = 0.0;
    double Velocity = 0.0;
    double Acceleration = 0.0;
  } FunctionFollowingValue;
  std::uint32_t StatusWord = 0;  // StatusSynchronizedMotionBit
};

class SynchronousOperation final : public SynchronousSlot {
 public:
  // `leaders`: the possible leading values (spec 07 §1.2). Throws std::invalid_argument for an
  // interconnection without source or with the axis itself (`name` names the axis in the message).
  SynchronousOperation(FollowingAxis axis, std::string_view name,
                       std::vector<LeadingValueInterconnection> leaders);

  std::span<TechnologyObject* const> leaders() const noexcept { return leader_objects_; }
  std::span<const LeadingValueInterconnection> interconnections() const noexcept { return interconnections_; }
  // The heap this component owns: the two lists of leading values (sized once at set-up).
  std::size_t heap_bytes() const noexcept {
    return interconnections_.capacity() * sizeof(LeadingValueInterconnection) +
           leader_objects_.capacity() * sizeof(TechnologyObject*);
  }
  // The leading value the active synchronous job follows (nullptr: none) — a loop check for other followers.
  const LeadingValueSource* followed_leading_value() const noexcept;

  // ---- jobs ----
  Submission gear_in(const GearInInputs& in) noexcept;
  Submission gear_in_pos(const GearInPosInputs& in) noexcept;
  Submission gear_in_velocity(const GearInVelocityInputs& in) noexcept;
  Submission gear_out(const GearOutInputs& in) noexcept;
  Submission cam_in(const CamInInputs& in) noexcept;    // camming.cpp
  Submission cam_out(const CamOutInputs& in) noexcept;  // camming.cpp
  // Leading and following value offsets (phasing_offset.cpp).
  Submission phasing(const PhasingInputs& in, bool absolute) noexcept;
  Submission offset(const OffsetInputs& in, bool absolute) noexcept;
  ShiftJobOutputs shift_outputs(JobId job) const noexcept;
  // MC_LeadingValueAdditive (leading_value_additive.cpp): started on Enable's rising edge (a running one of
  // another instance ends, §9.19.2 S7 "A"), its values taken on every call while Enable holds, ended by
  // Enable = FALSE. additive_busy(): the job's values are in the effective leading value.
  Submission additive_start(const LeadingValueAdditiveValues& values) noexcept;
  // 0, or 16#8118 for values that are not finite (the last ones stay).
  std::uint16_t additive_update(JobId job, const LeadingValueAdditiveValues& values) noexcept;
  // Enable = FALSE (Done); MC_Reset Restart ends it as CommandAborted (spec 07 §4.3).
  void additive_end(JobId job, JobState state = JobState::kDone) noexcept;
  bool additive_busy(JobId job) const noexcept { return job != 0 && job == additive_.id; }
  void update_ratio(JobId job, std::int32_t numerator, std::int32_t denominator) noexcept;
  SyncJobOutputs sync_outputs(JobId job) const noexcept;
  // MC_SynchronizedMotionSimulation (synchronized_motion_simulation.cpp, spec 07 §4.4): simulation_start() on
  // Enable's rising edge, simulation_end() on every call with Enable = FALSE while the simulation runs (it
  // ends once the follower can take the synchronous setpoint over). in_simulation(): InSimulation.
  Submission simulation_start() noexcept;
  std::uint16_t simulation_end(JobId job) noexcept;  // 0: ended (or not running), else the ErrorID
  bool in_simulation(JobId job) const noexcept { return job != 0 && job == simulation_; }

  const StatusSynchronizedMotion& status() const noexcept { return status_; }
  // "StatusSynchronizedMotion.<member>" without the prefix; NaN for an unknown member.
  double read(std::string_view member) const noexcept;

  // ---- SynchronousSlot ----
  std::uint16_t arbitrate(NewJob row) noexcept override;
  void abort(std::uint16_t error_id) noexcept override;
  void restart() noexcept override;
  void run() noexcept override;
  MotionState setpoint() const noexcept override { return sync_setpoint_; }
  bool following() const noexcept override { return active_.id != 0 && simulation_ == 0; }
  void update_status() noexcept override;

 private:
  using JobKind = AxisJobKind;
  enum class Phase : std::uint8_t { kSynchronizing, kBlend, kSynchronous };
  // What a camming job adds to a synchronous job: the cam (held in use) and its synchronous function, whose
  // MasterOffset is in the leader's continuous coordinates.
  struct CamJob {
    Cam* cam = nullptr;
    CamSynchronousFunction function{};
    double shown_master_offset = 0.0;  // StatusSynchronizedMotion.MasterOffset: a modulo leader's range
    double master_sync = 0.0;          // MasterSyncPosition as given (profiles 2, 5: placed when starting)
    std::uint32_t ends = 0;            // cam ends passed (EndOfProfileCount)
  };
  // The job states below keep their one-byte members together, so that they have no padding (decision M5).
  struct ActiveSync {
    JobId id = 0;
    int source = -1;
    std::int32_t numerator = 1;
    std::int32_t denominator = 1;
    JobKind kind = JobKind::kNone;
    Phase phase = Phase::kSynchronizing;
    bool continuous_update = false;
    bool start_sync = false;
    bool in_sync = false;
    bool line_blend = false;  // MC_CamIn profile 0: the blend runs onto the cam's tangent (decision C23)
    // The leader's direction the synchronization relies on (reversal: alarm 608): −1, 0 (not yet known), +1;
    // one byte in the padding here, so that x_extreme costs nothing (decision C27).
    std::int8_t direction = 0;
    ProfileLimits limits{};
    double x_sync = 0.0;  // leader and follower positions of the gear line y = y_sync + r·(x − x_sync)
    double y_sync = 0.0;
    LeaderDomainBlend blend{};
    double x_extreme = 0.0;  // the farthest leading value in `direction` during synchronization (C27)
    CamJob cam{};            // kind kCamIn
  };
  struct PendingSyncIn {  // MC_GearInPos / MC_CamIn waiting for its start (WaitingFunctionState 2 / 3)
    JobId id = 0;
    int source = -1;
    std::int32_t numerator = 1;
    std::int32_t denominator = 1;
    std::int32_t profile = 1;
    std::int32_t sync_direction = 3;
    JobKind kind = JobKind::kGearInPos;
    bool armed = false;        // profile 0: the leader was before the (moving) start position
    double master_sync = 0.0;  // continuous occurrence of MasterSyncPosition
    double slave_sync = 0.0;   // SlaveSyncPosition as given
    double length = 1.0;       // MasterStartDistance
    double direction = 1.0;    // the leader's direction of travel towards the start
    ProfileLimits limits{};    // profile 0
    // Profile 0: the last synchronization length and what it was computed from (reused while they stay).
    double sized_leader_velocity = std::numeric_limits<double>::quiet_NaN();
    MotionState sized_follower{};  // position: the follower's distance to the target
    double sized_length = 0.0;
    CamJob cam{};  // kind kCamIn
  };
  // Phasing profile 0's time-based travel of the follower (spec 07 §6.6): a PositionProfile planned from
  // rest. Only the segment in progress is kept: the plan, a function of distance and limits alone, is made
  // again when the time passes the segment's end — from rest to rest at most 7 times per job — instead of
  // keeping all 7 segments (decision M7: 304 -> 96 bytes; C17 kept 7 of the planner's 10 before).
  struct RestToRestTravel {
    static constexpr std::size_t kMaxSegments = 7;  // jerk up, hold, down, cruise, and the braking mirror
    ProfileLimits limits{};
    double target = 0.0;
    double duration = 0.0;
    double next_start = 0.0;  // start time of the segment after `segment` (infinity: none)
    ProfileSegment segment{};
    bool plan(double to, const ProfileLimits& l) noexcept;  // false: no plan, or more than 7 segments
    MotionState at(double t) noexcept;                      // t not falling; beyond duration: at the target

   private:
    void select(const PositionProfile& plan, double t) noexcept;  // the segment in progress at t
  };
  // A leading value offset (MC_Phasing*) or a following value offset (MC_Offset*) job (spec 07 §4.1, §4.2,
  // §6.6): the shift goes from `from` to `from + delta` over `length` of effective leading value from
  // `x_start` (profiles 1, 2), or, phasing profile 0, along a time-based profile of the follower. One job
  // slot serves both kinds: a leading and a following value offset exclude each other (16#808A, §4.1).
  struct ShiftJob {
    JobId id = 0;
    std::int32_t profile = 1;
    std::uint32_t cycles = 0;  // profile 0: MC_Interpolator cycles since the start
    bool phasing = false;      // MC_Phasing* (the phase shift), else MC_Offset* (the offset)
    bool waiting = false;      // profile 2 before StartPosition (StatusWord2.X3 / X5)
    double committed = 0.0;    // the leading value's direction the job relies on (0: not moving yet)
    double start_position = 0.0;
    double x_start = 0.0;
    double x_extreme = 0.0;  // farthest effective leading value reached in `committed` direction
    double last_x = 0.0;     // profile 2: the crossing test
    double length = 0.0;
    double from = 0.0;
    double delta = 0.0;
    double ratio = 1.0;         // profile 0: follower travel per leading value
    RestToRestTravel travel{};  // profile 0
  };
  struct Shift {  // a shift and its time derivatives in this cycle
    double value = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
  };
  struct FinishedShift {  // the outputs of the last job of each kind after it ended (Start is FALSE then)
    JobId id = 0;
    double absolute = 0.0;  // 24 bytes instead of 32 with a ShiftJobOutputs (decision M10)
    double covered = 0.0;
    ShiftJobOutputs outputs() const noexcept { return ShiftJobOutputs{false, absolute, covered}; }
  };
  struct Additive {  // the running MC_LeadingValueAdditive, in internal units
    JobId id = 0;
    double position = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
  };
  struct Desync {  // MC_GearOut / MC_CamOut
    JobId id = 0;
    std::int32_t profile = 1;
    std::int32_t direction = 3;
    int source = -1;  // the leading value of the gearing it ends (profile 1 runs over it after that ended)
    JobKind kind = JobKind::kGearOut;
    bool active = false;
    bool start_sync_out = false;
    double slave_position = 0.0;
    double stop_distance = 0.0;
    ProfileLimits limits{};
    double y_stop = 0.0;
    LeaderDomainBlend blend{};
  };

  // A new gearing, camming or desynchronization job: refused by the program state, or 16#8076 while the
  // synchronous operation is simulated (spec 07 §4.4). 0: none.
  std::uint16_t synchronous_job_rejection() const noexcept;
  int find_source(const LeadingValueSource* master) const noexcept;
  LeadingValue sample(int source) const noexcept;
  std::optional<std::uint16_t> check_master(const LeadingValueSource* master, int& source) noexcept;
  double ratio(std::int32_t n, std::int32_t d) const noexcept { return static_cast<double>(n) / d; }
  Submission start_gearing(JobKind kind, const LeadingValueSource* master, std::int32_t numerator,
                           std::int32_t denominator, double acceleration, double deceleration,
                           double jerk) noexcept;
  double gear_line(const ActiveSync& a, double x) const noexcept;
  // The effective leading value reversed during synchronization (alarm 608): against the velocity's sign
  // when the interconnection's reversal tolerance is 0 (`velocity_reversed`, as before), else once it moved
  // back more than the tolerance from a.x_extreme (spec 07 §1.6, decision C27).
  bool synchronization_reversed(ActiveSync& a, double x, bool velocity_reversed) noexcept;
  float reversal_tolerance(int source) const noexcept {
    return source >= 0 ? interconnections_[static_cast<std::size_t>(source)].reversal_tolerance : 0.0F;
  }
  void end_active(JobState state, std::uint16_t error_id) noexcept;
  void end_pending(JobState state, std::uint16_t error_id) noexcept;
  void end_desync(JobState state, std::uint16_t error_id) noexcept;
  bool start_pending_sync(const LeadingValue& leader) noexcept;
  void step_active(const LeadingValue& leader) noexcept;
  void step_desync(const LeadingValue& leader) noexcept;
  double modulo_occurrence(double position, const ModuloRange& range, double reference, double direction,
                           double min_ahead) const noexcept;
  double choose_slave_sync(double slave_sync, std::int32_t direction,
                           double follower_end_estimate) const noexcept;
  double sync_length_profile0(const PendingSyncIn& p, const LeadingValue& leader, double y_target,
                              double slope) const noexcept;
  double profile0_length(PendingSyncIn& p, const LeadingValue& leader, double y_target,
                         double slope) noexcept;
  bool profile0_start_crossed(PendingSyncIn& p, const LeadingValue& leader, double x_a) noexcept;
  bool activate_pending(JobKind kind) noexcept;
  Submission desynchronize(const GearOutInputs& in, JobKind kind) noexcept;
  double function_slope(const LeadingValue& leader) const noexcept;
  SyncFamily family_of(JobKind kind) const noexcept {
    return kind == JobKind::kCamIn || kind == JobKind::kCamOut ? SyncFamily::kCamming : SyncFamily::kGearing;
  }
  std::uint16_t arbitrate_row(NewSyncRow row) noexcept;
  // ---- leading and following value offsets (phasing_offset.cpp) ----
  std::optional<std::uint16_t> shift_requirements(bool phasing) const noexcept;
  Submission start_shift(const ShiftJob& prepared, double target, bool absolute) noexcept;
  void step_shift(const LeadingValue& effective) noexcept;
  void end_shift(JobState state, std::uint16_t error_id) noexcept;  // the running phasing or offset job
  void cancel_waiting_shift(bool phasing) noexcept;                 // ProfileReference 5
  void end_shifts() noexcept;  // the synchronous operation ended: the job ends, both shifts are 0 again
  Shift& shift_of(bool phasing) noexcept { return phasing ? phase_shift_ : offset_; }
  FinishedShift& finished_of(bool phasing) noexcept { return phasing ? phasing_finished_ : offset_finished_; }
  // ---- simulation (synchronized_motion_simulation.cpp) ----
  void run_simulated() noexcept;  // the synchronous operation goes on without the axis
  void end_simulation(JobState state) noexcept;
  // ---- camming (camming.cpp) ----
  bool start_pending_cam(const LeadingValue& leader) noexcept;
  void step_cam(const LeadingValue& leader) noexcept;
  void release_cam(CamJob& job) noexcept;
  MotionState cam_target(CamJob& job, double x, double v, double a) const noexcept;
  double cam_sync_point(const CamJob& job) const noexcept;

  std::vector<LeadingValueInterconnection> interconnections_;
  std::vector<TechnologyObject*> leader_objects_;
  ActiveSync active_{};
  PendingSyncIn pending_sync_{};
  Desync desync_{};
  JobId last_synchronous_job_ = 0;  // for the outputs of a job that ended
  SyncJobOutputs last_outputs_{};
  MotionState sync_setpoint_{};
  LeadingValue cycle_leader_{};  // the leading value run_synchronous() sampled in this MC_Interpolator
  int cycle_leader_source_ = -1;
  SyncFamily new_job_family_ = SyncFamily::kGearing;  // of the desynchronization being arbitrated (fn. 7)
  StatusSynchronizedMotion status_{};
  ShiftJob shift_job_{};  // the running MC_Phasing* or MC_Offset* job
  Shift phase_shift_{};
  Shift offset_{};
  FinishedShift phasing_finished_{};
  FinishedShift offset_finished_{};
  Additive additive_{};
  JobId simulation_ = 0;   // the running MC_SynchronizedMotionSimulation
  int shown_source_ = -1;  // the leading value EffectiveLeadingValue shows (the last one used)

  FollowingAxis axis_;
};

}  // namespace tomc::techobjects
