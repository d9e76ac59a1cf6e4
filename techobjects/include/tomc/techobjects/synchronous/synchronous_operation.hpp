#pragma once
// The synchronous operation of a synchronous axis (spec 07 §1.8, §2, §5, §6): the component that
// TO_SynchronousAxis adds to its positioning axis (issue 14) through the axis' synchronous slot. It owns the
// leading-value interconnections, the gearing jobs (MC_GearIn, MC_GearInPos, MC_GearInVelocity, MC_GearOut),
// the §9.19.2 decisions against them (sync_priority.hpp), the chain "function leading value -> synchronous
// function -> following value" and <TO>.StatusSynchronizedMotion. It reaches its axis only through the
// FollowingAxis port. Camming, phasing and offsets join here as further synchronous functions.
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

// Outputs beyond the handshake (spec 07 §2): InGear/InSync, StartSync, StartSyncOut, ContinuousUpdateActive.
struct SyncJobOutputs {
  bool StartSync = false;
  bool InSync = false;
  bool StartSyncOut = false;
  bool ContinuousUpdateActive = false;
};

// <TO>.StatusSynchronizedMotion (spec 07 §1.9; the struct is not defined in the V10 manual).
struct StatusSynchronizedMotion {
  std::int32_t FunctionState = 0;         // 0 none, 1 GearIn, 2 GearInPos, 4 GearOut, 6 GearInVelocity
  std::int32_t WaitingFunctionState = 0;  // 0 none, 2 GearInPos waiting, 4 GearOut waiting
  double PhaseShift = 0.0;
  std::uint16_t ActualMaster = 0;  // tomc: 1-based index of the interconnection in use; 0 = none
  double Offset = 0.0;
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
  // The leading value the active synchronous job follows (nullptr: none) — a loop check for other followers.
  const LeadingValueSource* followed_leading_value() const noexcept;

  // ---- jobs ----
  Submission gear_in(const GearInInputs& in) noexcept;
  Submission gear_in_pos(const GearInPosInputs& in) noexcept;
  Submission gear_in_velocity(const GearInVelocityInputs& in) noexcept;
  Submission gear_out(const GearOutInputs& in) noexcept;
  void update_ratio(JobId job, std::int32_t numerator, std::int32_t denominator) noexcept;
  SyncJobOutputs sync_outputs(JobId job) const noexcept;

  const StatusSynchronizedMotion& status() const noexcept { return status_; }
  // "StatusSynchronizedMotion.<member>" without the prefix; NaN for an unknown member.
  double read(std::string_view member) const noexcept;

  // ---- SynchronousSlot ----
  std::uint16_t arbitrate(NewJob row) noexcept override;
  void abort(std::uint16_t error_id) noexcept override;
  void run() noexcept override;
  MotionState setpoint() const noexcept override { return sync_setpoint_; }
  bool following() const noexcept override { return active_.id != 0; }
  void update_status() noexcept override;

 private:
  using JobKind = AxisJobKind;
  enum class Phase : std::uint8_t { kSynchronizing, kBlend, kSynchronous };
  struct ActiveSync {
    JobId id = 0;
    JobKind kind = JobKind::kNone;
    int source = -1;
    std::int32_t numerator = 1;
    std::int32_t denominator = 1;
    Phase phase = Phase::kSynchronizing;
    ProfileLimits limits{};
    double x_sync = 0.0;  // leader and follower positions of the gear line y = y_sync + r·(x − x_sync)
    double y_sync = 0.0;
    LeaderDomainBlend blend{};
    double direction = 0.0;  // the leader's direction the synchronization relies on (reversal: alarm 608)
    bool continuous_update = false;
    bool start_sync = false;
    bool in_sync = false;
  };
  struct PendingSyncIn {  // MC_GearInPos waiting for its start (WaitingFunctionState 2)
    JobId id = 0;
    int source = -1;
    std::int32_t numerator = 1;
    std::int32_t denominator = 1;
    double master_sync = 0.0;  // continuous occurrence of MasterSyncPosition
    double slave_sync = 0.0;   // SlaveSyncPosition as given
    std::int32_t profile = 1;
    double length = 1.0;  // MasterStartDistance
    std::int32_t sync_direction = 3;
    double direction = 1.0;  // the leader's direction of travel towards the start
    ProfileLimits limits{};  // profile 0
    // Profile 0: the last synchronization length and what it was computed from (reused while they stay).
    double sized_leader_velocity = std::numeric_limits<double>::quiet_NaN();
    MotionState sized_follower{};
    double sized_length = 0.0;
    bool armed = false;  // profile 0: the leader was before the (moving) start position
  };
  struct Desync {  // MC_GearOut
    JobId id = 0;
    bool active = false;
    std::int32_t profile = 1;
    double slave_position = 0.0;
    double stop_distance = 0.0;
    std::int32_t direction = 3;
    ProfileLimits limits{};
    double y_stop = 0.0;
    LeaderDomainBlend blend{};
    bool start_sync_out = false;
    int source = -1;  // the leading value of the gearing it ends (profile 1 runs over it after that ended)
  };

  int find_source(const LeadingValueSource* master) const noexcept;
  LeadingValue sample(int source) const noexcept;
  std::optional<std::uint16_t> check_master(const LeadingValueSource* master, int& source) noexcept;
  double ratio(std::int32_t n, std::int32_t d) const noexcept { return static_cast<double>(n) / d; }
  Submission start_gearing(JobKind kind, const LeadingValueSource* master, std::int32_t numerator,
                           std::int32_t denominator, double acceleration, double deceleration,
                           double jerk) noexcept;
  double gear_line(const ActiveSync& a, double x) const noexcept;
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
  double sync_length_profile0(const PendingSyncIn& p, const LeadingValue& leader) const noexcept;

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
  StatusSynchronizedMotion status_{};

  FollowingAxis axis_;
};

}  // namespace tomc::techobjects
