#pragma once
// Actual-value extrapolation of a leading axis (spec 07 §1.4, seed 004 §10.3.9/§10.3.33): the actual position
// and velocity are filtered (PT2 each), the velocity passes a tolerance band, the position is extrapolated
// over T_ext to compensate the delays of actual-value processing, and a hysteresis keeps a noisy value from
// reversing. Runs once per MC_Interpolator on the leader; a follower with actual-value coupling reads it.
// noexcept, no allocation.

#include <cstdint>

#include "tomc/techobjects/datablocks/to_types.hpp"

namespace tomc::techobjects {

struct ExtrapolationConfig {
  double position_t1 = 0.0;        // Extrapolation.PositionFilter.T1 [s] (0: no filter stage)
  double position_t2 = 0.0;        // .T2
  double velocity_t1 = 0.0;        // Extrapolation.VelocityFilter.T1
  double velocity_t2 = 0.0;        // .T2
  double tolerance_range = 0.0;    // Extrapolation.VelocityTolerance.Range (velocity units)
  double hysteresis = 0.0;         // Extrapolation.Hysteresis.Value (position units)
  double time = 0.0;               // T_ext = leading-axis part + Extrapolation.FollowingAxisDependentTime [s]
  std::int32_t velocity_mode = 0;  // Extrapolation.Settings.ExtrapolatedVelocityMode (0, 1, 2)
  double cycle = 0.001;            // interpolator cycle [s]
};

// The extrapolation of a leader's data block (spec 07 §1.4; S004 §10.3.9, SYNC8), the same for every TO
// that provides actual values: T_ext = Extrapolation.LeadingAxisDependentTime + FollowingAxisDependentTime,
// where the leading-axis part = T_i + T_ipo + T1 + T2 of the position filter, written back into the data
// block (RON), or 0 with Settings.SystemDefinedExtrapolation = 0, which also switches the position filter
// off (SYNC8 step 8). `ti` is the communication time T_i in force (MC_WriteParameter 1010, after restart),
// `velocity_factor` the data block's velocity unit per position unit per second.
ExtrapolationConfig extrapolation_config(TO_Struct_Extrapolation& settings, double ti, double ipo_cycle_s,
                                         double velocity_factor) noexcept;

class ActualValueExtrapolation;
// StatusExtrapolation of the data block (spec 07 §1.4, spec 04 §4.6) from the extrapolation's state.
void show_extrapolation(const ActualValueExtrapolation& e, double velocity_factor,
                        TO_Struct_StatusExtrapolation& status) noexcept;

class ActualValueExtrapolation {
 public:
  void configure(const ExtrapolationConfig& config) noexcept { config_ = config; }
  const ExtrapolationConfig& config() const noexcept { return config_; }
  // Starts the filters at this state (no step).
  void reset(double position, double velocity) noexcept;
  void update(double actual_position, double actual_velocity) noexcept;

  double filtered_position() const noexcept { return position_stage2_; }
  double filtered_velocity() const noexcept { return band_output_; }
  double extrapolated_position() const noexcept { return extrapolated_; }
  // The leading value: position after the hysteresis, velocity per ExtrapolatedVelocityMode, acceleration.
  double position() const noexcept { return output_position_; }
  double velocity() const noexcept { return output_velocity_; }
  double acceleration() const noexcept { return acceleration_; }

 private:
  ExtrapolationConfig config_{};
  // The two small members together: no padding (−8, decisions M10 and C26 both made this move; merged, the
  // 8 bytes are counted once: the positioning axis is 7,568 bytes with C26's pointer).
  bool started_ = false;
  int direction_ = 0;  // of the hysteresis: +1, -1, 0 (none yet)
  double position_stage1_ = 0.0;
  double position_stage2_ = 0.0;
  double velocity_stage1_ = 0.0;
  double velocity_stage2_ = 0.0;
  double band_output_ = 0.0;
  double acceleration_ = 0.0;
  double extrapolated_ = 0.0;
  double output_position_ = 0.0;
  double output_velocity_ = 0.0;
};

}  // namespace tomc::techobjects
