#pragma once
// TO_SynchronousAxis (spec 07 §1): everything of TO_PositioningAxis plus gearing and camming to a leading
// value — MC_GearIn, MC_GearInPos, MC_GearInVelocity, MC_GearOut, MC_CamIn, MC_CamOut — over the
// leading-value interconnections configured at set-up (setpoint or actual-value coupling), with leading and
// following value offsets (MC_Phasing*, MC_Offset*). The §9.19.2 matrix decides between synchronous and
// other jobs (sync_priority.hpp); the motion laws are in synchronous_motion.hpp. The jobs live in the
// synchronous operation component (spec 07 §1.8).
//
// Leaders run before followers in every cycle (Runtime orders by leaders()), so a follower reads its leader's
// values of the same MC_Interpolator cycle (spec 07 §6.1). Positions are continuous on both sides: a modulo
// leader needs no unwrapping, and user positions in leader coordinates are mapped onto the next occurrence.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/synchronous/synchronous_operation.hpp"

namespace tomc::techobjects {

// A positioning axis plus its synchronous operation (synchronous_operation.hpp), the component it plugs into
// the axis' synchronous slot: the positioning axis is not opened up for it (issue 14).
class SynchronousAxis final : public PositioningAxis {
 public:
  // `leaders`: the possible leading values (spec 07 §1.2). Throws std::invalid_argument for an
  // interconnection without source or with the axis itself.
  SynchronousAxis(std::string name, DeviceIo* device, const PositioningAxisData& start_values,
                  std::vector<LeadingValueInterconnection> leaders, const DriveConnectionConfig& drive = {});

  // The object plus the heap it owns: the positioning axis' heap and the interconnection lists.
  std::size_t memory_footprint() const noexcept {
    return sizeof(*this) - sizeof(PositioningAxis) + PositioningAxis::memory_footprint() +
           operation_.heap_bytes();
  }

  std::span<TechnologyObject* const> leaders() const noexcept override { return operation_.leaders(); }
  // Set-up: each leader coupled "Delayed" keeps the history of its delayed value from now on (spec 07 §1.5);
  // throws std::invalid_argument, naming the leader's key, for a delay it cannot hold (decision C26).
  void attach(RuntimeServices& services) override;
  std::span<const LeadingValueInterconnection> interconnections() const noexcept {
    return operation_.interconnections();
  }
  const LeadingValueSource* followed_leading_value() const noexcept override {
    return operation_.followed_leading_value();
  }

  // ---- jobs (spec 07 §2) ----
  Submission gear_in(const GearInInputs& in) noexcept { return operation_.gear_in(in); }
  Submission gear_in_pos(const GearInPosInputs& in) noexcept { return operation_.gear_in_pos(in); }
  Submission gear_in_velocity(const GearInVelocityInputs& in) noexcept {
    return operation_.gear_in_velocity(in);
  }
  Submission gear_out(const GearOutInputs& in) noexcept { return operation_.gear_out(in); }
  // ---- camming (spec 07 §3.4–§3.5) ----
  Submission cam_in(const CamInInputs& in) noexcept { return operation_.cam_in(in); }
  Submission cam_out(const CamOutInputs& in) noexcept { return operation_.cam_out(in); }
  // ---- leading and following value offsets (spec 07 §4.1–§4.2) ----
  Submission phasing(const PhasingInputs& in, bool absolute) noexcept {
    return operation_.phasing(in, absolute);
  }
  Submission offset(const OffsetInputs& in, bool absolute) noexcept {
    return operation_.offset(in, absolute);
  }
  ShiftJobOutputs shift_outputs(JobId job) const noexcept { return operation_.shift_outputs(job); }
  // ---- MC_LeadingValueAdditive (spec 07 §4.3) ----
  Submission additive_start(const LeadingValueAdditiveValues& values) noexcept {
    return operation_.additive_start(values);
  }
  std::uint16_t additive_update(JobId job, const LeadingValueAdditiveValues& values) noexcept {
    return operation_.additive_update(job, values);
  }
  void additive_end(JobId job) noexcept { operation_.additive_end(job); }
  bool additive_busy(JobId job) const noexcept { return operation_.additive_busy(job); }
  // MC_GearInVelocity.ContinuousUpdate: the ratio of the running job, taken at once (spec 07 §2.3).
  void update_ratio(JobId job, std::int32_t numerator, std::int32_t denominator) noexcept {
    operation_.update_ratio(job, numerator, denominator);
  }
  SyncJobOutputs sync_outputs(JobId job) const noexcept { return operation_.sync_outputs(job); }
  // ---- MC_SynchronizedMotionSimulation (spec 07 §4.4) ----
  Submission simulation_start() noexcept { return operation_.simulation_start(); }
  std::uint16_t simulation_end(JobId job) noexcept { return operation_.simulation_end(job); }
  bool in_simulation(JobId job) const noexcept { return operation_.in_simulation(job); }

  // ---- the data block's synchronous part ----
  const StatusSynchronizedMotion& synchronized_motion() const noexcept { return operation_.status(); }
  // As PositioningAxis::read, plus "StatusSynchronizedMotion.*".
  double read(std::string_view path) const noexcept;
  // The data type of a "StatusSynchronizedMotion.*" path (spec 07 §1.9; all RON), nullopt for any other
  // path: that part of the data block is not in the positioning axis' variable table.
  std::optional<VariableType> synchronized_motion_type(std::string_view path) const noexcept;

 private:
  // Tells each leading value it is one (spec 01 §8.6), before the operation takes the list over.
  static std::vector<LeadingValueInterconnection> mark_leaders(
      std::vector<LeadingValueInterconnection> leaders) noexcept;
  SynchronousOperation operation_;
};

}  // namespace tomc::techobjects
