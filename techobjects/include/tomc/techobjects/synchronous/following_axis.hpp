#pragma once
// What the synchronous operation of a synchronous axis may do with its positioning axis (spec 07 §1.8), and
// nothing else: read the setpoint and the configuration, run its jobs through the axis' job table and §9.19.1
// check, take the setpoint over and hand it back, raise alarms, set the synchronous status bits. The
// positioning axis keeps its members private; this port is its only friend (issue 14), so everything
// synchronous operation touches is listed here.
#include <cstdint>
#include <optional>

#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::techobjects {

class FollowingAxis {
 public:
  explicit FollowingAxis(PositioningAxis& axis) noexcept : axis_(axis) {}

  // ---- state and configuration ----
  const TechnologyObject* as_object() const noexcept { return &axis_; }
  const LeadingValueSource* as_leading_value() const noexcept { return &axis_; }
  // The base motion's setpoint: synchronous operation generates the base; a superimposed motion (spec 01
  // §8.14: on a following axis it affects only the follower) is added on top by the axis.
  MotionState setpoint() const noexcept { return axis_.base_setpoint(); }
  const PositioningAxisData& data() const noexcept { return axis_.db_; }
  const AxisUnitFactors& units() const noexcept { return axis_.units_; }
  ModuloRange modulo() const noexcept {
    return ModuloRange{axis_.modulo(), axis_.db_.Modulo.StartValue, axis_.db_.Modulo.Length};
  }
  double ipo_cycle_s() const noexcept { return axis_.core_.ipo_cycle_s; }
  bool enabled() const noexcept { return axis_.core_.phase == PowerPhase::kEnabled; }
  bool alarm_pending(std::uint32_t number) const noexcept { return axis_.core_.alarms.pending(number); }
  bool blocked() const noexcept { return axis_.blocked(); }
  bool homed() const noexcept { return axis_.homed(); }
  bool position_controlled() const noexcept { return axis_.position_controlled_; }
  bool virtual_axis() const noexcept { return axis_.virtual_axis(); }
  bool generator_idle() const noexcept { return axis_.generator_ == PositioningAxis::Generator::kIdle; }

  // ---- jobs ----
  JobTable<AxisJobKind>& jobs() noexcept { return axis_.core_.jobs; }
  std::uint16_t program_job_rejection() const noexcept { return axis_.core_.control.program_job_rejection(); }
  std::uint16_t motion_prerequisites() const noexcept { return axis_.motion_prerequisites(); }
  std::optional<std::uint16_t> resolve_dynamics(double velocity, double acceleration, double deceleration,
                                                double jerk, ProfileLimits& out) noexcept {
    return axis_.resolve_dynamics(velocity, acceleration, deceleration, jerk, out);
  }
  // The §9.19.1 row (then §9.19.2 through the slot): 0 = accepted with its aborts applied.
  std::uint16_t arbitrate(NewJob row) noexcept {
    bool queue = false;
    return axis_.arbitrate_motion(row, queue);
  }
  void abort_pending() noexcept { axis_.abort_pending(0); }
  // MC_Stop is running (spec 03 §4.13): no synchronous operation may take the axis over (§9.19.1 C6).
  bool stop_running() const noexcept { return axis_.core_.stop.id != 0; }

  // ---- the setpoint ----
  // The job becomes the axis' motion and the synchronous operation generates its setpoint.
  void take_over(JobId id, AxisJobKind kind) noexcept {
    adopt_motion(id, kind);
    axis_.positioning_.cancel();
    axis_.generator_ = PositioningAxis::Generator::kSynchronous;
  }
  // MC_GearOut with dynamic parameters: the axis brakes to `target` with its own position generator.
  void position_to(JobId id, AxisJobKind kind, double target, const ProfileLimits& limits) noexcept {
    adopt_motion(id, kind);
    axis_.plan_position(target, limits);
  }
  void set_setpoint(const MotionState& s) noexcept {  // the base setpoint
    const MotionState& sup = axis_.superimposed_.state();
    axis_.setpoint_ =
        MotionState{s.position + sup.position, s.velocity + sup.velocity, s.acceleration + sup.acceleration};
  }
  // The job ended: it is no longer the axis' motion.
  void end_motion(JobId id) noexcept {
    if (axis_.motion_.id == id) axis_.motion_ = PositioningAxis::Motion{};
  }
  // The axis goes on with its present motion; the next job (or its own limits) takes over (spec 07 §2.5).
  void hand_back() noexcept {
    if (axis_.generator_ == PositioningAxis::Generator::kSynchronous) {
      axis_.generator_ = PositioningAxis::Generator::kIdle;
    }
  }
  void set_position_controlled(bool on) noexcept { axis_.position_controlled_ = on; }

  // ---- alarms and status ----
  void raise(std::uint32_t number, std::uint32_t additional) noexcept { axis_.raise(number, additional); }
  AlarmReaction strongest_reaction() const noexcept { return axis_.core_.alarms.strongest_reaction(); }
  void apply_alarm_reactions() noexcept { axis_.apply_alarm_reactions(); }
  void set_status(StatusWordBit bit, bool on) noexcept { assign(axis_.db_.StatusWord, bit, on); }
  void set_status(StatusWord2Bit bit, bool on) noexcept { assign(axis_.db_.StatusWord2, bit, on); }

 private:
  void adopt_motion(JobId id, AxisJobKind kind) noexcept {
    axis_.motion_ = PositioningAxis::Motion{};
    axis_.motion_.id = id;
    axis_.motion_.kind = kind;
  }

  PositioningAxis& axis_;
};

}  // namespace tomc::techobjects
