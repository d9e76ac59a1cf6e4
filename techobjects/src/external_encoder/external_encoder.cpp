// TO_ExternalEncoder: an encoder telegram evaluated into user units (spec 01 §5.3), with enable, alarms,
// direct homing and the standstill signal.
#include "tomc/techobjects/external_encoder/external_encoder.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/axis/setup_checks.hpp"
#include "tomc/techobjects/datablocks/data_block_access.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"

namespace tomc::techobjects {

ExternalEncoder::ExternalEncoder(std::string name, DeviceIo* device, const ExternalEncoderData& start_values,
                                 const DriveConnectionConfig& connection)
    : DataBlockObject(std::move(name), device, start_values),
      encoder_(AxisMechanics{}, EncoderMechanics{}, 0.001, EncoderSource::kEncoderG1) {
  const auto fail = [&](std::string_view path, std::string_view message) {
    fail_start_value(name_, path, message);
  };
  check_start_values(name_, external_encoder_variables(), *start_);
  units_ = checked_unit_factors(name_, start_->Units.LengthUnit, start_->Units.VelocityUnit,
                                start_->Properties.MotionType, "encoder");
  if (device_ == nullptr)
    fail("Sensor.Interface", "an external encoder needs a device with telegram 81 or 83");
  const auto& cfg = device_->adapter->config();
  if (cfg.encoder_telegrams[0] != 81 && cfg.encoder_telegrams[0] != 83) {
    fail("Sensor.Interface", "the device carries no encoder telegram 81 or 83 (spec 01 §3.3)");
  }
  source_ = EncoderSource::kEncoderG1;
  drive_ = DriveConnection(*device_, connection);
  configure();
  if (const auto& p = encoder_.chain().config_problem()) fail(p->path, p->message);
}

// The external encoder has no mounting choice between motor and load: its measuring system is evaluated
// through load gear and leadscrew as MountingMode 0 with measuring gear 1:1 (actual_value_chain.hpp), or
// through DistancePerRevolution for a measuring wheel.
void ExternalEncoder::configure() noexcept {
  const auto& s = db_.Sensor;
  mechanics_.MotionType = static_cast<AxisMotionType>(db_.Properties.MotionType);
  mechanics_.LoadGear = GearRatio{db_.LoadGear.Numerator, db_.LoadGear.Denominator};
  mechanics_.Mechanics.LeadScrew = db_.Mechanics.LeadScrew * units_.leadscrew;
  mechanics_.Modulo = ModuloConfig{db_.Modulo.Enable, db_.Modulo.StartValue, db_.Modulo.Length};
  mechanics_.RotaryUnitsPerRevolution = units_.units_per_revolution;
  encoder_mechanics_ = sensor_encoder_mechanics(s);
  encoder_mechanics_.MountingMode =
      s.MountingMode == static_cast<std::int32_t>(SensorMountingMode::kExternalMeasuringSystem)
          ? EncoderMounting::kExternalMeasuringSystem
          : EncoderMounting::kMotorShaft;
  encoder_mechanics_.Nist = NistSource::kEncoderTelegram83;
  encoder_ = EncoderChannel(mechanics_, encoder_mechanics_, servo_cycle_s_, source_);
  (void)standstill_.configure(StandstillSignalConfig{db_.StandstillSignal.VelocityThreshold / units_.velocity,
                                                     db_.StandstillSignal.MinDwellTime, servo_cycle_s_});
}

void ExternalEncoder::servo(const CycleClock& clock) noexcept {
  if (!servo_cycle_known_ || clock.servo_cycle_s != servo_cycle_s_) {
    servo_cycle_s_ = clock.servo_cycle_s;
    servo_cycle_known_ = true;
    configure();
  }
  if (retained_restored_ && retained_.valid && !power_up_done_) {
    // Power-up of an absolute encoder with its retained adjustment (spec 01 §3.7, spec 02 §5.9).
    RetainedSensorState r;
    r.AbsEncoderOffset = retained_.AbsEncoderOffset;
    r.MeasuringRangeCount = retained_.MeasuringRangeCount;
    r.LastAbsoluteValue = retained_.LastAbsoluteValue;
    encoder_.chain().power_up(&r);
  }
  power_up_done_ = true;
  drive_.read();
  encoder_.read(drive_, device_->fresh);
  const bool error = encoder_.error();
  const bool communication = drive_.communication_ok();
  if (error && !error_seen_) {
    core_.raise(kAlarmSensorFault, encoder_.error_code());
    if (!encoder_.chain().absolute_type()) {  // spec 04 §8 rule 8; H11
      homed_ = false;
      db_.StatusSensor.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kNotAdjusted);
    }
  }
  error_seen_ = error;
  if (!communication && drive_.cycles_without_fresh_frame() > 0) {
    core_.raise(kAlarmDriveCommunication);
  }
  // A failed ZSW2_ENC sign-of-life (spec 06 §5.2) makes the value invalid like a lost link: say so with the
  // alarm the axes raise for it, instead of a silent StatusSensor.CommunicationOK = FALSE (issue 22).
  if (drive_.communication_fault() == CommunicationFault::kSignOfLifeFailed) {
    core_.raise(kAlarmDriveSignOfLife);
  }
  valid_ = encoder_.valid() && communication;
  velocity_ = encoder_.chain().velocity();
  (void)standstill_.update(velocity_);
  db_.ActualAcceleration = (velocity_ - last_velocity_) / servo_cycle_s_ * units_.acceleration;
  last_velocity_ = velocity_;
  db_.StatusSensor.CommunicationOK = communication;
  db_.StatusSensor.Error = error;
  db_.StatusSensor.State =
      static_cast<std::int32_t>(valid_ ? SensorState::VALID : SensorState::WAITING_FOR_VALID);
  db_.StatusSensor.Control = enabled_;
  input_edges_.observe(inputs_.HomingInput == db_.Sensor.PassiveHoming.SwitchLevel,
                       encoder_.chain().continuous_position());
  if (const auto mark = encoder_.take_reference_mark()) mark_position_ = *mark;
  if (retained_.valid) {
    const RetainedSensorState r = encoder_.chain().retained_state();
    retained_.MeasuringRangeCount = r.MeasuringRangeCount;
    retained_.LastAbsoluteValue = r.LastAbsoluteValue;
  }
  drive_.request(telegrams::DriveRequest::kOff);  // encoder-only: no drive state machine to run
  drive_.write(ServoCommand{.encoder = source_, .encoder_control = encoder_.control_word()});
}

LeadingValue ExternalEncoder::leading_value(LeadingValueCoupling) const noexcept {
  LeadingValue v;
  v.position = extrapolation_.position();
  v.velocity = extrapolation_.velocity();
  v.acceleration = extrapolation_.acceleration();
  v.valid = valid_;
  v.position_controlled = true;  // an encoder has no position control to lose (spec 07 §1.4)
  return v;
}

void ExternalEncoder::interpolate(const CycleClock& clock) noexcept {
  core_.cycle = clock.interpolator_cycles + 1;
  core_.ipo_cycle_s = clock.interpolator_cycle_s;
  if (ipo_cycle_s_ != clock.interpolator_cycle_s) {
    ipo_cycle_s_ = clock.interpolator_cycle_s;
    configure_extrapolation();
  }
  extrapolation_.update(encoder_.chain().continuous_position(), velocity_);
  show_extrapolation(extrapolation_, units_.velocity, db_.StatusExtrapolation);
  if (const auto restart_requested = core_.begin_reset(core_.cycle)) {  // MC_Reset
    drive_.acknowledge();
    encoder_.acknowledge();
    if (*restart_requested) {
      const RetainedSensorState retained = encoder_.chain().retained_state();
      const std::int32_t adjusted = db_.StatusSensor.Adjusted;
      db_ = *start_;
      core_.restart();  // MC_WriteParameter 1010...1012 take effect now
      drive_.restart(drive_.config());
      configure();
      configure_extrapolation();
      if (encoder_.chain().absolute_type()) {
        // Adjusted stays until new encoder settings are downloaded; a restart is not one (spec 02 §5.1).
        encoder_.chain().power_up(&retained);
        db_.StatusSensor.Adjusted = adjusted;
      } else {
        homed_ = false;
      }
    }
    core_.finish_reset();
  }
  // Enabled while the encoder delivers valid values and no alarm is pending (reaction 10 "remove enable").
  enabled_ = core_.enable && valid_ && core_.alarms.strongest_reaction() != AlarmReaction::kRemoveEnable;
  core_.phase = enabled_ ? PowerPhase::kEnabled : PowerPhase::kDisabled;
  // Passive homing (spec 02 §5.6) needs the enabled encoder; it ends with an alarm or the disable.
  if (passive_job_ != 0) {
    if (!enabled_) {
      core_.jobs.set(passive_job_, JobState::kError, error_id::kAbortedByAlarmReaction);
      passive_job_ = 0;
      passive_search_.stop(encoder_);
    } else if (const auto mark = passive_search_.step(velocity_, input_edges_, mark_position_, encoder_)) {
      assign_reference(*mark, passive_value_, ModuloCycleRule::kHomePositionHalf);
      core_.jobs.set(passive_job_, JobState::kDone);
      passive_job_ = 0;
    }
  }
  input_edges_.clear();
  mark_position_.reset();
  update_status();
}

void ExternalEncoder::update_status() noexcept {
  const auto& chain = encoder_.chain();
  db_.ActualPosition = chain.position();
  db_.ActualVelocity = velocity_ * units_.velocity;
  db_.ActualModuloCycle = db_.Modulo.Enable ? chain.modulo_cycle() : 0;
  db_.StatusSensor.Position = db_.ActualPosition;
  db_.StatusSensor.Velocity = db_.ActualVelocity;
  db_.StatusSensor.ModuloCycle = db_.ActualModuloCycle;
  db_.StatusSensor.AbsEncoderOffset = retained_.valid ? retained_.AbsEncoderOffset : 0.0;
  std::uint32_t sw = db_.StatusWord & (1u << static_cast<unsigned>(StatusWordBit::kOnlineStartValuesChanged));
  std::uint32_t no_status_word2 = 0;  // E has no StatusWord2 (spec 04 §5)
  std::uint32_t ew = 0;
  std::uint32_t ww = 0;
  core_.update_words(sw, no_status_word2, ew, ww, db_.ErrorDetail, false);
  assign(sw, StatusWordBit::kHomingDone, homed_);
  assign(sw, StatusWordBit::kDone, passive_job_ == 0);  // E: no job except MC_Power (spec 04 §5.1)
  assign(sw, StatusWordBit::kHomingCommand, passive_job_ != 0);
  assign(sw, StatusWordBit::kStandstill, standstill_.standstill());
  db_.StatusWord = sw;
  db_.ErrorWord = ew;
  db_.WarningWord = ww;
  // E shows 0 or 10 (spec 04 §14 item 7): 10 for an alarm that removes the enable.
  db_.ErrorDetail.Reaction = static_cast<std::int32_t>(
      db_.ErrorDetail.Reaction == static_cast<std::int32_t>(AlarmReaction::kRemoveEnable)
          ? ExternalEncoderReaction::kRemoveEnable
          : ExternalEncoderReaction::kNone);
}

PowerState ExternalEncoder::power(bool enable, std::int32_t, std::int32_t) noexcept {
  core_.enable = enable;  // StartMode/StopMode do not apply to an encoder (spec 03 §4.1)
  PowerState s;
  s.Status = enabled_;
  s.Busy = core_.enable;
  return s;
}

Submission ExternalEncoder::reset(bool restart) noexcept {
  return core_.reset(restart);  // Restart needs the encoder disabled (core_.phase mirrors it)
}

// MC_Home on the external encoder (spec 02 §5.1: modes 0, 1, 2, 6, 7, 8, 9, 10, 11, 12, 13; no active
// homing).
Submission ExternalEncoder::home(const HomeInputs& in) noexcept {
  if (!std::isfinite(in.Position)) return Submission::reject(error_id::kInvalidPosition);
  if (in.Mode < 0 || in.Mode > 13 || in.Mode == 4) return Submission::reject(error_id::kInvalidMode);
  if (in.Mode == 3 || in.Mode == 5)
    return Submission::reject(error_id::kHomingModeNotAvailable);  // active: axes
  if (in.Sensor != 0 && in.Sensor != 1) return Submission::reject(error_id::kInvalidSensor);
  const bool absolute = absolute_encoder();
  if ((in.Mode == 6 || in.Mode == 7) && !absolute)
    return Submission::reject(error_id::kHomingModeNotAvailable);
  if (in.Mode == 13 && absolute) return Submission::reject(error_id::kHomingModeNotAvailable);
  if (in.Mode == 9) {
    if (passive_job_ != 0) {  // also on a homed encoder (Mode 2), H10
      core_.jobs.set(passive_job_, JobState::kAborted);
      passive_job_ = 0;
      passive_search_.stop(encoder_);
    }
    return Submission::accept(core_.jobs.create(JobKind::kHome, JobState::kDone));
  }
  if (in.Mode == 2 || in.Mode == 8 || in.Mode == 10) {
    if (!enabled_) return Submission::reject(error_id::kAxisNotEnabled);  // spec 02 §5.6
    if (passive_job_ != 0) {
      core_.jobs.set(passive_job_, JobState::kAborted);
      passive_search_.stop(encoder_);
    }
    if (in.Mode != 2 && !absolute) homed_ = false;
    passive_job_ = core_.jobs.create(JobKind::kHome, JobState::kActive);
    passive_value_ = in.Mode == 10 ? db_.Homing.HomePosition : in.Position;
    const auto& p = db_.Sensor.PassiveHoming;
    passive_search_.start(PassiveHomingSearch::Config{
        p.Mode, p.Direction, p.SideInput, db_.StandstillSignal.VelocityThreshold / units_.velocity});
    input_edges_.was_active = inputs_.HomingInput == p.SwitchLevel;
    return Submission::accept(passive_job_);
  }
  if (!valid_) return Submission::reject(error_id::kEncoderNotValid);
  if (in.Mode == 13 && core_.alarms.any_error()) return Submission::reject(error_id::kAxisBlockedByAlarm);
  // An external encoder has no setpoint: 11/12 set/shift its actual value like 0/1 (spec 02 §5.1 table).
  const double shown = db_.ActualPosition;
  const bool relative = in.Mode == 1 || in.Mode == 6 || in.Mode == 12;
  const double wanted = relative ? shown + in.Position : in.Position;
  const double now = encoder_.chain().continuous_position();
  assign_reference(now, wanted, in.Mode == 7 ? ModuloCycleRule::kZero : ModuloCycleRule::kShortestDistance);
  if (in.Mode == 6 || in.Mode == 7) store_adjustment();  // retentive (spec 02 §5.9)
  if (in.Mode != 6 && in.Mode != 7 && in.Mode != 13) {
    // 0, 1, 11, 12 set HomingDone, not Adjusted (spec 02 §5.1)
  } else {
    db_.StatusSensor.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
  }
  update_status();
  return Submission::accept(core_.jobs.create(JobKind::kHome, JobState::kDone));
}

// The position at the mark becomes `value`; the present position is `value` plus the travel since the mark.
void ExternalEncoder::assign_reference(double mark_position, double value, ModuloCycleRule rule) noexcept {
  const double now = value + (encoder_.chain().continuous_position() - mark_position);
  (void)encoder_.set_position(now, rule, value);  // passive homing: the rule looks at the home position (H8)
  homed_ = true;
  if (rule == ModuloCycleRule::kHomePositionHalf) {  // passive homing: referenced (spec 02 §5.1)
    if (absolute_encoder() && db_.StatusSensor.Adjusted == 0) store_adjustment();
    db_.StatusSensor.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
  }
  reference_mark_position_ =
      db_.Modulo.Enable ? modulo_wrap(value, db_.Modulo.StartValue, db_.Modulo.Length).position : value;
}

bool ExternalEncoder::absolute_encoder() const noexcept {
  return db_.Sensor.Type != static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL);
}

void ExternalEncoder::store_adjustment() noexcept {
  const RetainedSensorState r = encoder_.chain().retained_state();
  retained_.adopt(r.AbsEncoderOffset, r.MeasuringRangeCount, r.LastAbsoluteValue);
}

void ExternalEncoder::restore_retained(const RetainedEncoderData& data) noexcept {
  if (!absolute_encoder() || !data.valid) return;
  retained_ = data;
  retained_restored_ = true;
  homed_ = true;
  db_.StatusSensor.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
}

void ExternalEncoder::report_adjustment_lost(std::uint32_t cause) noexcept {
  if (absolute_encoder()) core_.raise(kAlarmAdjustmentLost, cause);
}

// 1010/1011/1012 communication times, effective after restart (spec 03 §4.15); 1000 and 1020 belong to axes.
Submission ExternalEncoder::write_parameter(std::int32_t parameter_number, double value) noexcept {
  return core_.write_communication_time(parameter_number, value, db_.StatusWord);
}

// A DIR write: the standstill signal and the extrapolation take the new values at once.
void ExternalEncoder::written(std::string_view path) noexcept {
  (void)standstill_.configure(StandstillSignalConfig{db_.StandstillSignal.VelocityThreshold / units_.velocity,
                                                     db_.StandstillSignal.MinDwellTime, servo_cycle_s_});
  if (path.starts_with("Extrapolation.")) configure_extrapolation();
}

// Extrapolation of the encoder value as a leading value (spec 07 §1.4, extrapolation_config), as on the
// positioning axis.
void ExternalEncoder::configure_extrapolation() noexcept {
  extrapolation_.configure(
      extrapolation_config(db_.Extrapolation, core_.communication_times.Ti, ipo_cycle_s_, units_.velocity));
}

}  // namespace tomc::techobjects
