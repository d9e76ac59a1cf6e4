// TO_PositioningAxis with several encoders (spec 01 §3.8, seed 004 §6.2.4.5, spec 04 Sensor[1..4] /
// StatusSensor[1..4]): the operative encoder closes the position loop (positioning_axis_cycle.cpp); every
// other existing encoder is read and monitored here in each servo cycle, with its own actual-value chain,
// homing state and absolute-encoder adjustment. No allocation: the storage was reserved at construction.
#include <cmath>
#include <utility>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/axis/setup_checks.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::techobjects {

namespace {

EncoderMechanics encoder_mechanics(const PositioningAxisData::TO_Struct_Sensor& s, EncoderSource source) {
  EncoderMechanics m = sensor_encoder_mechanics(s);
  m.MountingMode = static_cast<EncoderMounting>(s.MountingMode);
  m.MeasuringGear = GearRatio{s.MeasuringGear.Numerator, s.MeasuringGear.Denominator};
  const bool separate = source == EncoderSource::kEncoderG1 || source == EncoderSource::kEncoder2G1;
  m.Nist = separate ? NistSource::kEncoderTelegram83 : NistSource::kDriveTelegram;
  return m;
}

// Seed 004 §6.1.8: the fixed simulated incremental value of an absolute encoder after power-up.
constexpr std::int64_t kSimulatedAbsoluteIncrements = 240;

// Gx_XIST1 of `counts` continuous counts in the encoder's counter width.
std::uint32_t simulated_xist1(const ActualValueChain& chain, std::int64_t counts) {
  const std::uint8_t width = chain.xist1_width();
  const std::uint64_t mask = width >= 32 ? 0xFFFFFFFFu : (std::uint64_t{1} << width) - 1;
  return static_cast<std::uint32_t>(static_cast<std::uint64_t>(counts) & mask);
}

RetainedSensorState sensor_state(const RetainedEncoderData& r) {
  RetainedSensorState s;
  s.AbsEncoderOffset = r.AbsEncoderOffset;
  s.MeasuringRangeCount = r.MeasuringRangeCount;
  s.LastAbsoluteValue = r.LastAbsoluteValue;
  return s;
}

}  // namespace

void PositioningAxis::configure_encoders(const AxisMechanics& mechanics) noexcept {
  const auto channel = [&](std::uint32_t n, EncoderSource source) {
    return EncoderChannel(mechanics, encoder_mechanics(db_.Sensor[n - 1], source), servo_cycle_s_, source);
  };
  encoder_ = channel(db_.OperativeSensor, encoder_.source());
  for (AdditionalEncoder& e : additional_.all())
    e.channel = channel(e.number, e.channel.source());
}

void PositioningAxis::power_up_additional_encoders() noexcept {
  for (AdditionalEncoder& e : additional_.all()) {
    const bool absolute = e.channel.chain().absolute_type();
    if (e.retained.valid && absolute) {
      const RetainedSensorState r = sensor_state(e.retained);
      e.channel.chain().power_up(&r);
    }
    // A simulated absolute encoder comes up at its fixed simulated value of 240 increments plus its
    // AbsEncoderOffset (seed 004 §6.1.8, spec 01 §2.7); an incremental one at 0.
    if (simulated()) {
      const auto fine = static_cast<unsigned>(db_.Sensor[e.number - 1].Parameter.FineResolutionXist1);
      seed_simulated_encoder(e, absolute ? std::int64_t{kSimulatedAbsoluteIncrements} << fine : 0);
    }
  }
}

// Simulation (seed 004 §6.2.4.5 "Simulazione", §6.1.7; decision B7): the encoder sees the load travel of the
// simulated actual value. Its counts advance by travel / (its units per count) — its own resolution, gears,
// mounting and direction — the fraction of a count carried to the next cycle; its chain turns them into
// StatusSensor[n] as a real encoder's (own offset, adjustment, modulo counter).
void PositioningAxis::simulate_additional_encoders(double travel) noexcept {
  for (AdditionalEncoder& e : additional_.all()) {
    ActualValueChain& chain = e.channel.chain();
    if (!chain.position_valid()) {  // power-up or restart seed it; this is a fallback only
      seed_simulated_encoder(e, chain.encoder_counts());
      continue;
    }
    const double upc = chain.units_per_count();
    const double counts = (upc != 0.0 ? travel / upc : 0.0) + static_cast<double>(e.simulated_fraction);
    const double whole = std::round(counts);
    e.simulated_fraction = static_cast<float>(counts - whole);
    EncoderSample sample;
    sample.xist1 = simulated_xist1(chain, chain.encoder_counts() + static_cast<std::int64_t>(whole));
    chain.update(sample);
    auto& status = db_.StatusSensor[e.number - 1];
    status.State = static_cast<std::int32_t>(SensorState::VALID);
    status.CommunicationOK = true;
    status.Error = false;
  }
}

void PositioningAxis::seed_simulated_encoder(AdditionalEncoder& e, std::int64_t counts) noexcept {
  ActualValueChain& chain = e.channel.chain();
  const auto& parameter = db_.Sensor[e.number - 1].Parameter;
  EncoderSample sample;
  sample.xist1 = simulated_xist1(chain, counts);
  if (chain.absolute_type()) {
    // Gx_XIST2 holds the absolute value in its own fine resolution, within the measuring range.
    const int shift =
        static_cast<int>(parameter.FineResolutionXist1) - static_cast<int>(parameter.FineResolutionXist2);
    std::int64_t xist2 = shift >= 0 ? counts >> shift : counts * (std::int64_t{1} << -shift);
    const auto range = static_cast<std::int64_t>(chain.measuring_range());
    if (range > 0) xist2 = ((xist2 % range) + range) % range;
    sample.xist2_absolute = static_cast<std::uint32_t>(xist2);
  }
  chain.update(sample);
  e.simulated_fraction = 0.0f;
}

void PositioningAxis::read_additional_encoders() noexcept {
  for (AdditionalEncoder& e : additional_.all()) {
    e.channel.read(drive_, device_->fresh);
    auto& status = db_.StatusSensor[e.number - 1];
    const bool error = e.channel.error();
    status.CommunicationOK =
        drive_.communication_ok() || drive_.communication_fault() == CommunicationFault::kDriveFault;
    status.Error = error;
    // An encoder outside the loop may fail without stopping the axis (seed 004 §6.2.4.5): an alarm without
    // reaction; an incremental one loses its reference (spec 04 §8 rule 8), the axis' homing state stays.
    if (error && (!e.fault_seen || !core_.held_off())) {
      raise(kAlarmAdditionalSensorFault, e.number * 65536u + (e.channel.error_code() & 0xFFFFu));
      if (!e.channel.chain().absolute_type()) {
        status.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kNotAdjusted);
      }
    }
    e.fault_seen = error;
    const bool valid = e.channel.valid() && drive_.communication_ok();
    status.State = static_cast<std::int32_t>(valid ? SensorState::VALID : SensorState::WAITING_FOR_VALID);
    // A cyclic absolute encoder's traversed measuring ranges are kept as they change (as the operative's).
    if (e.retained.valid) {
      const RetainedSensorState r = e.channel.chain().retained_state();
      e.retained.MeasuringRangeCount = r.MeasuringRangeCount;
      e.retained.LastAbsoluteValue = r.LastAbsoluteValue;
    }
  }
}

void PositioningAxis::write_additional_encoder_controls() noexcept {
  for (AdditionalEncoder& e : additional_.all())
    drive_.set_encoder_control(e.channel.source(), e.channel.control_word());
}

void PositioningAxis::update_additional_encoder_status() noexcept {
  for (const AdditionalEncoder& e : additional_.all()) {
    auto& status = db_.StatusSensor[e.number - 1];
    if (!drive_used() && !simulated()) {
      // A virtual axis reads no encoder: every used encoder shows its actual values, the setpoints of one
      // servo cycle before, adjusted (seed 004 §6.1.5/§6.1.6 table, decision B7).
      const auto& operative = db_.StatusSensor[db_.OperativeSensor - 1];
      status.Position = operative.Position;
      status.Velocity = operative.Velocity;
      status.ModuloCycle = operative.ModuloCycle;
      status.Adjusted = static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
      status.State = static_cast<std::int32_t>(SensorState::VALID);
      status.CommunicationOK = true;
      status.Error = false;
      continue;
    }
    const ActualValueChain& chain = e.channel.chain();
    status.Position = chain.position();
    status.Velocity = chain.velocity() * units_.velocity;
    status.ModuloCycle = chain.modulo_cycle();
    status.AbsEncoderOffset = e.retained.valid ? e.retained.AbsEncoderOffset : 0.0;
  }
}

std::uint32_t PositioningAxis::make_operative(std::uint32_t n) noexcept {
  AdditionalEncoder* e = additional_.find(n);
  if (e == nullptr) return db_.OperativeSensor;
  std::swap(encoder_, e->channel);
  std::swap(retained_, e->retained);
  std::swap(encoder_fault_seen_, e->fault_seen);
  e->number = static_cast<std::uint8_t>(db_.OperativeSensor);
  db_.OperativeSensor = n;
  return n;
}

// ---------------------------------------------------------------------------------------------------------
// MC_SetSensor (spec 03 §4.12, seed 004 §6.2.4.5)

ActualValueChain* PositioningAxis::sensor_chain(std::uint32_t n) noexcept {
  if (n == db_.OperativeSensor) return &encoder_.chain();
  AdditionalEncoder* e = additional_.find(n);
  return e != nullptr ? &e->channel.chain() : nullptr;
}

double PositioningAxis::sensor_position(std::uint32_t n) noexcept {
  // A virtual or simulated axis' operative encoder reads nothing: the axis' actual value is its position.
  if (n == db_.OperativeSensor && !drive_used()) return actual_position_;
  return sensor_chain(n)->continuous_position();
}

// Encoder n takes over `position` (continuous). An absolute encoder's take-over is a compensation that a
// later switch discards (seed 004 §6.2.4.5), so its retained adjustment stays as it is; an incremental one
// is adjusted when the position it takes over is (Adjusted follows the source, decision B4).
void PositioningAxis::transfer_position(std::uint32_t n, double position, bool adjusted) noexcept {
  ActualValueChain& chain = *sensor_chain(n);
  if (n == db_.OperativeSensor) {
    // Mode 3 onto the operative encoder: the setpoint moves with the actual value, as in direct homing, so
    // that the new position causes no motion.
    shift_position(drive_used() ? encoder_.set_position(position) : position - actual_position_);
  } else {
    chain.set_position(position);
  }
  if (!chain.absolute_type()) {
    db_.StatusSensor[n - 1].Adjusted =
        static_cast<std::int32_t>(adjusted ? SensorAdjusted::kAdjusted : SensorAdjusted::kNotAdjusted);
  }
}

// The operative absolute encoder that MC_SetSensor switches away from delivers absolute value +
// AbsEncoderOffset again: a take-over (Mode 0/2/3) is discarded.
void PositioningAxis::discard_absolute_compensation() noexcept {
  ActualValueChain& chain = encoder_.chain();
  if (!chain.absolute_type()) return;
  chain.shift_offset((retained_.valid ? retained_.AbsEncoderOffset : 0.0) - chain.offset());
}

Submission PositioningAxis::set_sensor(const SetSensorInputs& in) noexcept {
  if (const auto e = core_.control.program_job_rejection()) return Submission::reject(e);
  if (in.Mode < 0 || in.Mode > 3) return Submission::reject(error_id::kInvalidMode);
  const auto configured = [&](std::int32_t n) { return n >= 1 && n <= 4 && sensor_chain(n) != nullptr; };
  if (!configured(in.Sensor) || (in.Mode == 3 && !configured(in.ReferenceSensor))) {
    return Submission::reject(error_id::kSensorNotConfigured);
  }
  // "Not possible while a homing job or a restart is in progress" (seed 004 §6.2.4.5, spec 03 T44).
  if (motion_.kind == JobKind::kHome || passive_.id != 0 || core_.restart_pending()) {
    return Submission::reject(error_id::kSensorSwitchBlocked);
  }
  const auto n = static_cast<std::uint32_t>(in.Sensor);
  if (!drive_used() && !simulated()) {
    // A virtual axis reads no encoder: every encoder shows the setpoints, so a switch changes only which
    // Sensor[n]'s configuration applies and a transfer has nothing to transfer (decision B7).
    if (in.Mode <= 1) (void)make_operative(n);
    return Submission::accept(core_.jobs.create(JobKind::kSetSensor, JobState::kDone));
  }
  // A simulated axis closes the loop on encoder 1 (seed 004 §6.1.7); Modes 2 and 3 only prepare (B7).
  if (simulated() && in.Mode <= 1 && n != db_.OperativeSensor) {
    return Submission::reject(error_id::kSensorSwitchSimulated);
  }
  // An encoder outside the loop with an error or no value yet can neither close the loop nor take or give a
  // position (never a silently wrong motion; decision B4).
  const auto valid = [&](std::uint32_t k) {
    const AdditionalEncoder* e = additional_.find(k);
    return k == db_.OperativeSensor || (e != nullptr && e->channel.valid());
  };
  if (!valid(n) || (in.Mode == 3 && !valid(static_cast<std::uint32_t>(in.ReferenceSensor)))) {
    return Submission::reject(error_id::kEncoderNotValid);
  }
  const double axis_position = sensor_position(db_.OperativeSensor);
  const bool axis_adjusted = db_.StatusSensor[db_.OperativeSensor - 1].Adjusted ==
                             static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
  switch (in.Mode) {
    case 0:  // switch, the new encoder takes the actual position over: no jump
    case 1:  // switch as it is: the difference reaches the actual value smoothed (spec 01 §3.8)
      if (n == db_.OperativeSensor) break;
      if (in.Mode == 0) {
        transfer_position(n, axis_position, axis_adjusted);
      } else {
        sensor_switch_difference_ += axis_position - sensor_chain(n)->continuous_position();
      }
      discard_absolute_compensation();
      (void)make_operative(n);
      break;
    case 2:  // the axis' actual position to Sensor, no switch
      if (n != db_.OperativeSensor) transfer_position(n, axis_position, axis_adjusted);
      break;
    default: {  // 3: ReferenceSensor's actual position to Sensor, no switch
      const auto r = static_cast<std::uint32_t>(in.ReferenceSensor);
      if (n == r) break;
      const bool r_adjusted =
          db_.StatusSensor[r - 1].Adjusted == static_cast<std::int32_t>(SensorAdjusted::kAdjusted);
      transfer_position(n, sensor_position(r), r_adjusted);
      break;
    }
  }
  return Submission::accept(core_.jobs.create(JobKind::kSetSensor, JobState::kDone));
}

}  // namespace tomc::techobjects
