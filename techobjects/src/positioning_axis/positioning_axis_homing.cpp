// TO_PositioningAxis: MC_Home in every mode (spec 02 §5, spec 03 §4.3, seed 004 §6.11).
// Direct homing (0, 1), setting the setpoint (11, 12), absolute (6, 7) and incremental (13) encoder
// adjustment act in the call; active homing (3, 5) is a motion job with its own search sequence; passive
// homing (2, 8, 10) watches the motion the user commands; Mode 9 ends a passive homing.
//
// Reference marks: the encoder's zero mark through Gx_STW/Gx_ZSW (EncoderChannel), or an edge of the homing
// digital input (AxisDigitalInputs::HomingInput, evaluated at the servo rate: "reduced accuracy", spec 02
// §5.3).
#include <algorithm>
#include <cmath>
#include <limits>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::techobjects {

namespace {

// Additional values of alarm 560 (decision H3).
constexpr std::uint32_t kHomingMarkNotFound = 1;       // both limit switches reached without the cam/input
constexpr std::uint32_t kHomingLimitDuringSearch = 2;  // a limit switch reached after the cam/input was found

}  // namespace

void PositioningAxis::end_passive_homing(JobState state, std::uint16_t error_id) noexcept {
  core_.jobs.set(passive_.id, state, error_id);
  passive_ = PassiveHomingJob{};
  passive_search_.stop(encoder_);
}

bool PositioningAxis::input_active() const noexcept {
  const auto& s = db_.Sensor[db_.OperativeSensor - 1];
  const bool level = passive_.id != 0 && motion_.kind != JobKind::kHome ? s.PassiveHoming.SwitchLevel
                                                                        : s.ActiveHoming.SwitchLevel;
  return inputs_.HomingInput == level;
}

// MC_Servo: what the homing sequences react to, latched for the interpolator.
void PositioningAxis::homing_observe() noexcept {
  input_edges_.observe(input_active(), actual_position_);
  if (const auto mark = encoder_.take_reference_mark()) mark_position_ = *mark;
}

// The actual position at the mark becomes `value` (spec 02 §5.5/§5.6): the present actual position is `value`
// plus the distance travelled since the mark. The setpoint moves with it; the modulo counter follows the
// home-position rule of spec 01 §2.4.1 for `home_position` (H8).
void PositioningAxis::assign_reference(double mark_position, double value, double home_position) noexcept {
  const double now = value + (actual_position_ - mark_position);
  double delta = 0.0;
  if (drive_used()) {
    delta = encoder_.set_position(now, ModuloCycleRule::kHomePositionHalf, home_position);
  } else {
    delta = now - actual_position_;
  }
  shift_position(delta);
  homed_ = true;
  auto& sensor = db_.StatusSensor[db_.OperativeSensor - 1];
  // An absolute encoder keeps a stored adjustment; without one, homing stores it (spec 02 §5.1 note 2).
  if (encoder_.chain().absolute_type() && sensor.Adjusted == 0) store_adjustment();
  sensor.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
  reference_mark_position_ =
      modulo() ? modulo_wrap(value, db_.Modulo.StartValue, db_.Modulo.Length).position : value;
}

// A search motion of active homing with the homing dynamics (DynamicDefaults, spec 03 §4.3).
void PositioningAxis::homing_move(double direction, double velocity) noexcept {
  const double a = units_.acceleration;
  const ProfileLimits limits{velocity_limit(), db_.DynamicDefaults.Acceleration / a,
                             db_.DynamicDefaults.Deceleration / a, db_.DynamicDefaults.Jerk / a};
  homing_.travel_direction = direction;
  motion_.limits = limits;
  const double v = std::min(velocity / units_.velocity, velocity_limit());
  motion_.planned_velocity = direction * v;
  plan_velocity(direction * v, limits, false);
}

void PositioningAxis::fail_homing(std::uint32_t cause) noexcept {
  encoder_.cancel_reference_mark();
  raise_with(kAlarmHomingFailed, cause, static_cast<std::int32_t>(AlarmReaction::kStopMaxDynamics));
  apply_alarm_reactions();  // ends the homing job with 16#8001 and stops the axis in this cycle
}

void PositioningAxis::start_active_homing(JobId id, double home_position) noexcept {
  const auto& s = db_.Sensor[db_.OperativeSensor - 1];
  Motion m;
  m.id = id;
  m.kind = JobKind::kHome;
  motion_ = m;
  homing_ = ActiveHomingJob{};
  homing_.method = s.ActiveHoming.Mode;
  homing_.home_position = home_position;
  homing_.mark_value = home_position - s.ActiveHoming.HomePositionOffset;
  homing_.direction =
      s.ActiveHoming.Direction == static_cast<std::int32_t>(HomingDirection::kNegative) ? -1.0 : 1.0;
  homing_.mark_on_entering = homing_.direction > 0.0 ? !s.ActiveHoming.SideInput : s.ActiveHoming.SideInput;
  position_controlled_ = true;  // MC_Home 3/5 forces position control (spec 02 §7.7)
  positioning_.cancel();
  positioning_start_pending_ = false;
  // An incremental encoder is not homed from the start of active homing until the mark (spec 02 §5.12).
  if (!encoder_.chain().absolute_type()) homed_ = false;
  input_edges_.clear();
  mark_position_.reset();
  const double approach = db_.Homing.ApproachDirection ? -1.0 : 1.0;
  const bool on_input = input_active();
  switch (homing_.method) {
    case static_cast<std::int32_t>(SensorHomingMode::kZeroMarkViaTelegram):
      homing_.phase = HomingPhase::kSearchMark;
      encoder_.arm_reference_mark();
      homing_move(homing_.direction, db_.Homing.ReferencingVelocity);
      break;
    case static_cast<std::int32_t>(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam):
      if (on_input) {
        homing_.phase = HomingPhase::kSearchCamExit;
        homing_move(homing_.direction, db_.Homing.ReferencingVelocity);
      } else {
        homing_.phase = HomingPhase::kApproach;
        homing_move(approach, db_.Homing.ApproachVelocity);
      }
      break;
    default:  // reference mark via digital input
      if (on_input) {
        homing_.phase = homing_.mark_on_entering ? HomingPhase::kLeaveInput : HomingPhase::kSearchEdge;
        homing_move(homing_.mark_on_entering ? -homing_.direction : homing_.direction,
                    db_.Homing.ReferencingVelocity);
      } else {
        homing_.phase = HomingPhase::kApproach;
        homing_move(approach, db_.Homing.ApproachVelocity);
      }
      break;
  }
}

// MC_Interpolator: one step of the active homing sequence (spec 02 §5.5 A–D).
void PositioningAxis::run_homing() noexcept {
  if (motion_.kind == JobKind::kHome && homing_.phase != HomingPhase::kIdle) {
    const auto side = reversal_cam_;
    reversal_cam_ = limits::LimitSide::kNone;
    // Moving in the homing direction (an edge during a reversal's braking does not count).
    const bool in_homing_direction = actual_velocity_ * homing_.direction > 0.0;
    if (side != limits::LimitSide::kNone && homing_.phase != HomingPhase::kToHome) {
      // A limit switch as reversal cam (spec 02 §5.5 D): while looking for the cam/input, brake with the
      // dynamic defaults and go on the other way at ApproachVelocity; twice, or after the cam was found:
      // the mark is not in the travel range (decision H3).
      if (homing_.phase == HomingPhase::kApproach && homing_.limit_reversals == 0) {
        ++homing_.limit_reversals;
        homing_move(-homing_.travel_direction, db_.Homing.ApproachVelocity);
      } else {
        fail_homing(homing_.phase == HomingPhase::kApproach ? kHomingMarkNotFound : kHomingLimitDuringSearch);
      }
    }
    switch (homing_.phase) {
      case HomingPhase::kApproach:
        if (input_edges_.entered || input_active()) {
          if (homing_.method ==
              static_cast<std::int32_t>(SensorHomingMode::kZeroMarkViaTelegramAndReferenceCam)) {
            // The cam: on to its far side in the homing direction (reversing if that is the other way).
            homing_.phase = HomingPhase::kSearchCamExit;
            homing_move(homing_.direction, db_.Homing.ReferencingVelocity);
          } else {
            homing_.phase = homing_.mark_on_entering ? HomingPhase::kLeaveInput : HomingPhase::kSearchEdge;
            homing_move(homing_.mark_on_entering ? -homing_.direction : homing_.direction,
                        db_.Homing.ReferencingVelocity);
          }
        }
        break;
      case HomingPhase::kLeaveInput:
        if (!input_active()) {
          homing_.phase = HomingPhase::kSearchEdge;
          homing_move(homing_.direction, db_.Homing.ReferencingVelocity);
        }
        break;
      case HomingPhase::kSearchEdge: {
        const bool edge = homing_.mark_on_entering ? input_edges_.entered : input_edges_.left;
        if (edge && in_homing_direction) {
          assign_reference(input_edges_.position, homing_.mark_value, homing_.home_position);
          homing_.phase = HomingPhase::kToHome;
        }
        break;
      }
      case HomingPhase::kSearchCamExit:
        // The zero mark counts only after the cam was left in the homing direction (spec 02 §5.3; §10 item
        // 6).
        if (input_edges_.left && in_homing_direction) {
          homing_.phase = HomingPhase::kSearchMark;
          encoder_.arm_reference_mark();
        }
        break;
      case HomingPhase::kSearchMark:
        if (mark_position_) {
          assign_reference(*mark_position_, homing_.mark_value, homing_.home_position);
          homing_.phase = HomingPhase::kToHome;
        }
        break;
      case HomingPhase::kToHome:
      case HomingPhase::kIdle:
        break;
    }
    if (homing_.phase == HomingPhase::kToHome && motion_.planned_velocity != 0.0) {
      // Homed: to the home position at ApproachVelocity, the shortest way on a modulo axis (spec 02 §5.2).
      const double a = units_.acceleration;
      ProfileLimits limits{std::min(db_.Homing.ApproachVelocity / units_.velocity, velocity_limit()),
                           db_.DynamicDefaults.Acceleration / a, db_.DynamicDefaults.Deceleration / a,
                           db_.DynamicDefaults.Jerk / a};
      const double home = homing_.home_position;
      motion_.target =
          modulo() ? absolute_target(modulo_wrap(home, db_.Modulo.StartValue, db_.Modulo.Length).position, 3,
                                     setpoint_.position)
                         .value_or(setpoint_.position)
                   : home;
      motion_.limits = limits;
      motion_.planned_velocity = 0.0;  // marks the last phase as planned
      motion_.interpolation_done = false;
      plan_position(motion_.target, limits);
    }
  }
  if (passive_.id != 0) run_passive_homing();
  input_edges_.clear();
  mark_position_.reset();
}

// Passive homing (spec 02 §5.6), the search shared with the external encoder.
void PositioningAxis::run_passive_homing() noexcept {
  const auto mark = passive_search_.step(actual_velocity_, input_edges_, mark_position_, encoder_);
  if (mark) {
    assign_reference(*mark, passive_.value, passive_.value);
    core_.jobs.set(passive_.id, JobState::kDone);
    passive_ = PassiveHomingJob{};
  }
}

// MC_Home with Sensor = n, an encoder that is not the operative one (S7-1500T): only the incremental encoder
// adjustment (Mode 13) addresses such an encoder (spec 02 §5.10); it sets that encoder's actual position, and
// the axis' position and homing state stay as they are (decision B5). Other modes: 16#811A.
Submission PositioningAxis::home_other_encoder(const HomeInputs& in) noexcept {
  AdditionalEncoder* e =
      in.Sensor >= 1 && in.Sensor <= 4 ? additional_.find(static_cast<std::uint32_t>(in.Sensor)) : nullptr;
  // A virtual axis reads no encoder, each shows the setpoints: none can be adjusted alone (decision B7).
  if (e == nullptr || in.Mode != 13 || (!drive_used() && !simulated())) {
    return Submission::reject(error_id::kInvalidSensor);
  }
  if (e->channel.chain().absolute_type()) return Submission::reject(error_id::kHomingModeNotAvailable);
  // Enabled with position control, or disabled; no alarm pending (spec 02 §5.10).
  if (core_.alarms.any_error()) return Submission::reject(error_id::kAxisBlockedByAlarm);
  if (core_.phase == PowerPhase::kEnabled && !position_controlled_) {
    return Submission::reject(error_id::kNotPositionControlled);
  }
  if (!e->channel.valid()) return Submission::reject(error_id::kEncoderNotValid);
  (void)e->channel.set_position(in.Position);
  db_.StatusSensor[e->number - 1].Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
  return Submission::accept(core_.jobs.create(JobKind::kHome, JobState::kDone));
}

Submission PositioningAxis::home(const HomeInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (!std::isfinite(in.Position)) return Submission::reject(error_id::kInvalidPosition);
  if (in.Mode < 0 || in.Mode > 13 || in.Mode == 4) return Submission::reject(error_id::kInvalidMode);
  if (in.Sensor != 0 && static_cast<std::uint32_t>(in.Sensor) != db_.OperativeSensor) {
    return home_other_encoder(in);  // [T] an encoder that does not close the loop
  }
  const auto& sensor_config = db_.Sensor[db_.OperativeSensor - 1];
  const bool absolute = sensor_config.Type != static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL);
  const double start = db_.Modulo.StartValue;
  const double length = db_.Modulo.Length;

  switch (in.Mode) {
    case 9: {
      // Abort passive homing (spec 02 §5.6): the passive job ends with CommandAborted; Mode 9 is Done. Also
      // on a homed axis: Mode 2 keeps "homed", and the §6.1 matrix aborts every passive job (H10).
      if (passive_.id != 0) {
        end_passive_homing(JobState::kAborted);
      }
      return Submission::accept(core_.jobs.create(JobKind::kHome, JobState::kDone));
    }
    case 3:
    case 5: {
      if (const auto e = motion_prerequisites()) return Submission::reject(e);
      bool queue = false;
      if (const auto e = arbitrate_motion(NewJob::kActiveHoming, queue)) return Submission::reject(e);
      abort_pending(0);
      const double home = in.Mode == 3 ? in.Position : db_.Homing.HomePosition;
      const JobId id = core_.jobs.create(JobKind::kHome, JobState::kActive);
      if (virtual_axis()) {
        // Virtual and simulated axes: homing is executed directly, without motion (spec 01 §2.5).
        assign_reference(actual_position_, home, home);
        core_.jobs.set(id, JobState::kDone);
        update_status();
        return Submission::accept(id);
      }
      start_active_homing(id, home);
      return Submission::accept(id);
    }
    case 2:
    case 8:
    case 10: {
      if (const auto e = motion_prerequisites()) return Submission::reject(e);
      if (!position_controlled_) return Submission::reject(error_id::kNotPositionControlled);
      if (passive_.id != 0) {
        core_.jobs.set(passive_.id, JobState::kAborted);  // a new passive homing replaces the running one
        encoder_.cancel_reference_mark();
      }
      const double value = in.Mode == 10 ? db_.Homing.HomePosition : in.Position;
      const JobId id = core_.jobs.create(JobKind::kHome, JobState::kActive);
      // Modes 8 and 10 reset "homed" of an incremental encoder at the start; Mode 2 keeps it (spec 02 §5.6).
      if (in.Mode != 2 && !absolute) homed_ = false;
      if (virtual_axis()) {
        assign_reference(actual_position_, value, value);
        core_.jobs.set(id, JobState::kDone);
        update_status();
        return Submission::accept(id);
      }
      passive_ = PassiveHomingJob{id, value};
      passive_search_.start(PassiveHomingSearch::Config{
          sensor_config.PassiveHoming.Mode, sensor_config.PassiveHoming.Direction,
          sensor_config.PassiveHoming.SideInput, db_.StandstillSignal.VelocityThreshold / units_.velocity});
      input_edges_.was_active = input_active();
      return Submission::accept(id);
    }
    case 6:
    case 7:
      if (!absolute) return Submission::reject(error_id::kHomingModeNotAvailable);  // spec 02 §5.1
      break;
    case 13:
      if (absolute) return Submission::reject(error_id::kHomingModeNotAvailable);
      // Enabled with position control, or disabled; no alarm pending (spec 02 §5.10).
      if (core_.alarms.any_error()) return Submission::reject(error_id::kAxisBlockedByAlarm);
      if (core_.phase == PowerPhase::kEnabled && !position_controlled_) {
        return Submission::reject(error_id::kNotPositionControlled);
      }
      break;
    default:
      break;
  }

  // Modes 0, 1, 6, 7, 11, 12, 13 act at once (spec 02 §5.7–§5.10); the TO need not be enabled.
  if (!actual_valid_) return Submission::reject(error_id::kEncoderNotValid);
  if (blocked()) return Submission::reject(error_id::kAxisBlockedByAlarm);
  const JobId id = core_.jobs.create(JobKind::kHome, JobState::kActive);
  // Everything becomes "the actual position is set to ...": 11/12 move the setpoint and keep the following
  // distance, so the actual position moves by the same amount (spec 02 §5.8 [Derived]).
  const double shown_actual = db_.ActualPosition;
  const double shown_setpoint = db_.Position;
  double wanted = in.Position;  // 0, 7, 13
  if (in.Mode == 1 || in.Mode == 6 || in.Mode == 12) wanted = shown_actual + in.Position;
  if (in.Mode == 11) wanted = shown_actual + (in.Position - shown_setpoint);
  const ModuloCycleRule rule = in.Mode == 7 ? ModuloCycleRule::kZero : ModuloCycleRule::kShortestDistance;
  double delta = 0.0;
  if (drive_used()) {
    delta = encoder_.set_position(wanted, rule);
  } else if (modulo()) {
    const double w = modulo_wrap(wanted, start, length).position;
    delta = rule == ModuloCycleRule::kZero
                ? w - actual_position_
                : w - shown_actual + length * modulo_cycle_change(shown_actual, w, start, length);
  } else {
    delta = wanted - shown_actual;
  }
  shift_position(delta);
  // Direct homing moves every encoder of the axis by the same amount; only Mode 13 adjusts the one encoder
  // (spec 02 §5.10: "unlike Mode 0, the shift is not applied to all encoders").
  if (in.Mode != 13) {
    for (AdditionalEncoder& e : additional_.all())
      e.channel.chain().shift_offset(delta);
  }
  double reference = wanted;
  if (in.Mode == 11) reference = in.Position;
  if (in.Mode == 12) reference = shown_setpoint + in.Position;
  reference_mark_position_ = modulo() ? modulo_wrap(reference, start, length).position : reference;
  homed_ = true;
  // Adjusted: set by encoder adjustment (6, 7, 13), not by 0, 1, 11, 12 (spec 02 §5.1).
  if (in.Mode == 6 || in.Mode == 7 || in.Mode == 13) {
    db_.StatusSensor[db_.OperativeSensor - 1].Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
    if (in.Mode != 13) store_adjustment();  // retentive (spec 02 §5.9); Mode 13 is not (§5.10)
  }
  core_.jobs.set(id, JobState::kDone);
  update_status();
  return Submission::accept(id);
}

}  // namespace tomc::techobjects
