// The simulated PROFIdrive drive. One call of read_actual() is one servo cycle of the drive: take the
// setpoints the controller wrote last cycle, run the state machine and the motor/load model for one cycle,
// answer with actual-value frames. Pure arithmetic on preallocated state: no allocation, no locks, no
// exceptions.
#include "tomc/drives/simulated_drive.hpp"

#include <algorithm>
#include <cmath>

#include "tomc/telegrams/layout.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace tomc::drives {

namespace tg = tomc::telegrams;
using Reaction = SimulatedDriveParameters::FaultReaction;

namespace {

constexpr bool bit(std::uint16_t w, unsigned n) {
  return ((w >> n) & 1u) != 0;
}

bool has_dsc(std::uint16_t telegram) {
  return telegram == 5 || telegram == 6 || telegram == 105 || telegram == 106;
}

// Encoder k (0 = G1, 1 = G2) of the drive telegram, or of a separate encoder slot (spec 01 §3.3).
int encoder_index_of_slot(const DeviceConfig& c, Slot slot) {
  if (slot == Slot::kEncoder2) return 1;
  const auto layout = tg::find_layout(c.drive_telegram, tg::Direction::kActual);
  const bool drive_has_g1 = layout && layout->carries(tg::Signal::G1_ZSW);
  return drive_has_g1 ? 1 : 0;
}

double counts_per_revolution(const SimulatedEncoderParameters& e) {
  return tg::counts_per_revolution(e.steps_per_revolution, e.fine_resolution_xist1);
}

}  // namespace

SimulatedDrive::SimulatedDrive(const DeviceConfig& config, const SimulatedDriveParameters& parameters)
    : config_(config), p_(parameters), mechanics_(p_), codecs_(config_) {
  if (p_.substeps == 0) p_.substeps = 1;
  setpoint_frames_ = make_frames(config_, tg::Direction::kSetpoint);
  // Which encoders exist: those carried by the drive telegram, plus separately connected ones.
  const auto& drive_actual = codecs_(tg::Direction::kActual, Slot::kDrive);
  encoders_[0].present = drive_actual.carries(tg::Signal::G1_ZSW);
  encoders_[1].present = drive_actual.carries(tg::Signal::G2_ZSW);
  for (Slot s : {Slot::kEncoder1, Slot::kEncoder2}) {
    if (config_.telegram(s) != 0)
      encoders_[static_cast<std::size_t>(encoder_index_of_slot(config_, s))].present = true;
  }
  master_monitor_ = tg::SignOfLifeMonitor(tg::SignOfLifeMonitorConfig{p_.sign_of_life_tolerance, 1});
  const auto& drive_setpoint = codecs_(tg::Direction::kSetpoint, Slot::kDrive);
  r_.nsoll_b = drive_setpoint.carries(tg::Signal::NSOLL_B);
  r_.stw2 = drive_setpoint.carries(tg::Signal::STW2);
  r_.momred = drive_setpoint.carries(tg::Signal::MOMRED);
  r_.g1_stw = drive_setpoint.carries(tg::Signal::G1_STW);
  r_.g2_stw = drive_setpoint.carries(tg::Signal::G2_STW);
  r_.dsc = has_dsc(config_.drive_telegram);
  r_.supplementary = config_.supplementary_telegram == 750;
  r_.ratio = p_.gear_motor_revolutions / p_.gear_load_revolutions;
  r_.dt = p_.servo_cycle_s / static_cast<double>(p_.substeps);
  for (int i = 0; i < 2; ++i) {
    const auto& e = i == 0 ? p_.encoder1 : p_.encoder2;
    r_.xist1_scale[static_cast<std::size_t>(i)] =
        e.linear ? std::ldexp(1.0, e.fine_resolution_xist1) : counts_per_revolution(e);
    r_.xist1_modulus[static_cast<std::size_t>(i)] =
        std::ldexp(1.0, std::clamp<int>(e.xist1_width_bits, 1, 32));
  }
  // DSC: XERR (encoder-1 counts) -> motor revolutions.
  if (p_.encoder1.linear) {
    r_.dsc_counts_to_motor_revolutions = p_.encoder1.resolution /
                                         std::ldexp(1.0, p_.encoder1.fine_resolution_xist1) /
                                         p_.load_units_per_revolution * r_.ratio;
  } else {
    r_.dsc_counts_to_motor_revolutions =
        1.0 / counts_per_revolution(p_.encoder1) *
        (p_.encoder1.shaft == SimulatedEncoderParameters::Shaft::kLoad ? r_.ratio : 1.0);
  }
  power_cycle();
}

// ---------------------------------------------------------------------------------------------------------
// Adapter interface

void SimulatedDrive::write_setpoint(const DeviceFrames& setpoint) noexcept {
  if (link_lost_) return;  // the frame never reaches the drive
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    if (setpoint_frames_.slots[i].length == 0) continue;
    if (setpoint.slots[i].length != setpoint_frames_.slots[i].length) continue;  // malformed: ignored
    setpoint_frames_.slots[i].bytes = setpoint.slots[i].bytes;
  }
  fresh_setpoint_ = true;
}

bool SimulatedDrive::read_actual(DeviceFrames& actual) noexcept {
  apply_setpoints();
  update_state_machine();
  const double previous_load = mechanics_.load_position();
  const double previous_motor = mechanics_.motor_revolutions();
  motor_revolutions_at_sample_ = previous_motor;
  cycle_speed_setpoint_rpm_ = speed_setpoint_rpm();
  cycle_torque_limit_positive_ = torque_limit_positive();
  cycle_torque_limit_negative_ = torque_limit_negative();
  for (std::uint32_t i = 0; i < p_.substeps; ++i)
    integrate(r_.dt);
  update_encoders(previous_load, previous_motor);
  if (p_.isochronous && cyclic_data_ && !sign_of_life_frozen_) slave_counter_ = slave_sign_of_life_.next();

  ++health_.exchanges;
  if (link_lost_) {
    ++health_.consecutive_missed;
    ++health_.missed_total;
    health_.up = false;
    return false;
  }
  health_.consecutive_missed = 0;
  health_.up = true;
  encode_actuals(actual);
  return true;
}

// ---------------------------------------------------------------------------------------------------------
// Setpoints, faults and the PROFIdrive state machine (spec 06 §4)

void SimulatedDrive::apply_setpoints() noexcept {
  if (!fresh_setpoint_) {
    if (cyclic_data_ && ++missed_setpoints_ >= p_.setpoint_timeout_cycles &&
        fault_code_ != kFaultSetpointTimeout) {
      raise_fault(kFaultSetpointTimeout, p_.communication_fault_reaction);
    }
    return;
  }
  fresh_setpoint_ = false;
  // After a gap the master sign-of-life has moved on by the missed cycles: resynchronise (the gap itself is
  // the setpoint timeout's business, docs/decisions.md).
  if (missed_setpoints_ != 0) master_monitor_.reset();
  missed_setpoints_ = 0;
  cyclic_data_ = true;
  previous_stw1_ = drive_sp_.STW1.value();
  auto decode = [&](Slot s, tg::SetpointSignals& into) {
    const auto i = static_cast<std::size_t>(s);
    if (codecs_.setpoint[i]->frame_size() != 0)
      (void)codecs_.setpoint[i]->decode(setpoint_frames_.slots[i].view(), into);
  };
  decode(Slot::kDrive, drive_sp_);
  decode(Slot::kSupplementary, supplementary_sp_);
  decode(Slot::kEncoder1, encoder_sp_[0]);
  decode(Slot::kEncoder2, encoder_sp_[1]);

  // Master sign-of-life (spec 06 §5): in the drive telegram's STW2, or an encoder telegram's STW2_ENC.
  if (p_.isochronous) {
    std::uint8_t master = 0;
    bool monitored = false;
    if (r_.stw2) {
      master = static_cast<std::uint8_t>(drive_sp_.STW2.field(tg::kSignOfLifeField));
      monitored = true;
    } else if (config_.telegram(Slot::kEncoder1) != 0) {
      master = static_cast<std::uint8_t>(encoder_sp_[0].STW2_ENC.field(tg::kSignOfLifeField));
      monitored = true;
    }
    if (monitored && master_monitor_.check(master) == tg::SignOfLifeStatus::kFailed) {
      if (config_.drive_telegram != 0) {
        if (fault_code_ == 0) raise_fault(kFaultSignOfLife, p_.communication_fault_reaction);
      } else {
        const int e = encoder_index_of_slot(config_, Slot::kEncoder1);
        if (encoders_[static_cast<std::size_t>(e)].error_code == 0) {
          encoders_[static_cast<std::size_t>(e)].error_code = tg::kEncoderErrorMasterSignOfLife;
        }
      }
    }
  }
}

void SimulatedDrive::raise_fault(std::uint32_t code, Reaction reaction) noexcept {
  if (fault_code_ != 0) return;  // the first fault decides the reaction
  fault_code_ = code;
  fault_reaction_ = reaction;
}

void SimulatedDrive::inject_fault(std::uint32_t code, Reaction reaction) noexcept {
  injected_fault_ = code == 0 ? 1 : code;
  injected_reaction_ = reaction;
}

void SimulatedDrive::inject_encoder_error(int encoder, std::uint16_t code) noexcept {
  if (encoder < 1 || encoder > 2) return;
  encoders_[static_cast<std::size_t>(encoder - 1)].error_code =
      code == 0 ? tg::kEncoderErrorSensorGroup : code;
}

void SimulatedDrive::clear_encoder_error(int encoder) noexcept {
  if (encoder < 1 || encoder > 2) return;
  // The cause is gone; the error bit stays until the controller acknowledges (G_STW.15, spec 06 §6.3).
  auto& e = encoders_[static_cast<std::size_t>(encoder - 1)];
  if (e.error_code != tg::kEncoderErrorMasterSignOfLife) e.error_code = 0;
}

void SimulatedDrive::update_state_machine() noexcept {
  if (config_.drive_telegram == 0) return;  // encoder-only device
  const std::uint16_t stw1 = drive_sp_.STW1.value();
  const bool motor_encoder_error = encoders_[0].present && encoders_[0].error_code != 0 &&
                                   p_.encoder1.shaft == SimulatedEncoderParameters::Shaft::kMotor;

  // Causes that are present now raise their fault (once).
  if (injected_fault_ != 0) raise_fault(injected_fault_, injected_reaction_);
  if (motor_encoder_error) raise_fault(kFaultMotorEncoder, Reaction::kOff2);
  if (cyclic_data_ && !bit(stw1, 10) && state_ != tg::DriveState::kS0NotReady &&
      state_ != tg::DriveState::kS1SwitchingOnInhibited && state_ != tg::DriveState::kS2ReadyForSwitchingOn) {
    raise_fault(kFaultNoControlByPlc, Reaction::kOff1);
  }

  // Acknowledge: a 0 -> 1 edge of STW1.7 clears the fault when its cause is gone (spec 06 §3.1 bit 7).
  if (fault_code_ != 0 && bit(stw1, 7) && !bit(previous_stw1_, 7)) {
    const bool cause_present = (fault_code_ == injected_fault_ && injected_fault_ != 0) ||
                               (fault_code_ == kFaultMotorEncoder && motor_encoder_error) ||
                               (fault_code_ == kFaultSetpointTimeout && missed_setpoints_ != 0);
    if (!cause_present) {
      // Acknowledged: switching on inhibited; the next evaluation of STW1 happens next cycle (TV26).
      fault_code_ = 0;
      master_monitor_.reset();
      state_ = tg::DriveState::kS1SwitchingOnInhibited;
      previous_stw1_ = stw1;
      pulses_enabled_ = false;
      return;
    }
  }
  previous_stw1_ = stw1;

  // A fault forces its reaction by masking STW1 (DevKit behaviour, spec 06 §4.1) and blocks switching on.
  std::uint16_t effective = stw1;
  if (fault_code_ != 0) {
    switch (fault_reaction_) {
      case Reaction::kOff1:
        effective &= static_cast<std::uint16_t>(~0x0001u);
        break;
      case Reaction::kOff2:
        effective &= static_cast<std::uint16_t>(~0x0002u);
        break;
      case Reaction::kOff3:
        effective &= static_cast<std::uint16_t>(~0x0004u);
        break;
    }
  }
  if (!cyclic_data_) return;
  const bool standstill = std::fabs(mechanics_.motor_speed_rpm()) < p_.standstill_threshold_rpm;
  tg::DriveState next = tg::next_drive_state(state_, effective, standstill);
  // A present fault inhibits switching on: the drive ends in S1 once its fault reaction is complete.
  if (fault_code_ != 0 && (next == tg::DriveState::kS2ReadyForSwitchingOn ||
                           next == tg::DriveState::kS3SwitchedOn || next == tg::DriveState::kS4Operation)) {
    next = tg::DriveState::kS1SwitchingOnInhibited;
  }
  // Entering a ramp stop starts the ramp-function generator at the present speed.
  if ((next == tg::DriveState::kS5aRampStop || next == tg::DriveState::kS5bQuickStop) && next != state_) {
    ramp_setpoint_rpm_ = mechanics_.motor_speed_rpm();
  }
  state_ = next;
  pulses_enabled_ = state_ == tg::DriveState::kS4Operation || state_ == tg::DriveState::kS5aRampStop ||
                    state_ == tg::DriveState::kS5bQuickStop;
}

double SimulatedDrive::speed_setpoint_rpm() const noexcept {
  double n = r_.nsoll_b ? tg::n4_to_speed(drive_sp_.NSOLL_B, p_.reference_speed_rpm)
                        : tg::n2_to_speed(drive_sp_.NSOLL_A, p_.reference_speed_rpm);
  // STW1.4..6: ramp generator enable / unfreeze / setpoint enable; 0 forces the setpoint to 0.
  const std::uint16_t stw1 = drive_sp_.STW1.value();
  if (!bit(stw1, 4) || !bit(stw1, 6)) n = 0.0;
  return n;
}

double SimulatedDrive::torque_limit_positive() const noexcept {
  double limit = p_.torque_limit_nm;
  if (r_.momred) {
    limit = std::min(limit, tg::torque_limit_from_momred(drive_sp_.MOMRED, p_.reference_torque_nm));
  }
  if (config_.supplementary_telegram == 750) {
    limit = std::min(limit, tg::n2_to_torque(supplementary_sp_.M_LIMIT_POS, p_.reference_torque_nm));
  }
  return limit;
}

double SimulatedDrive::torque_limit_negative() const noexcept {
  double limit = -p_.torque_limit_nm;
  if (r_.momred) {
    limit = std::max(limit, -tg::torque_limit_from_momred(drive_sp_.MOMRED, p_.reference_torque_nm));
  }
  if (config_.supplementary_telegram == 750) {
    limit = std::max(limit, tg::n2_to_torque(supplementary_sp_.M_LIMIT_NEG, p_.reference_torque_nm));
  }
  return limit;
}

// ---------------------------------------------------------------------------------------------------------
// Motor and load

void SimulatedDrive::integrate(double dt) noexcept {
  if (config_.drive_telegram == 0) {  // encoder-only device: the shaft moves as told
    mechanics_.move_externally(external_speed_, dt);
    return;
  }

  // Speed reference of the speed loop for this state.
  double reference_rpm = 0.0;
  if (state_ == tg::DriveState::kS4Operation) {
    reference_rpm = cycle_speed_setpoint_rpm_;
    // DSC (spec 06 §7): position loop in the drive on XERR with gain KPC, plus the NSOLL_B pre-control.
    if (r_.dsc && drive_sp_.KPC != 0 && encoders_[0].present) {
      const double error_motor_revolutions =
          static_cast<double>(drive_sp_.XERR) * r_.dsc_counts_to_motor_revolutions;
      const double moved = mechanics_.motor_revolutions() - motor_revolutions_at_sample_;
      reference_rpm += tg::kv_from_kpc(drive_sp_.KPC) * (error_motor_revolutions - moved) * 60.0;
    }
  } else if (state_ == tg::DriveState::kS5aRampStop || state_ == tg::DriveState::kS5bQuickStop) {
    const double ramp_time =
        state_ == tg::DriveState::kS5aRampStop ? p_.off1_ramp_down_time_s : p_.off3_ramp_down_time_s;
    const double step = ramp_time > 0.0 ? p_.max_speed_rpm / ramp_time * dt : std::fabs(ramp_setpoint_rpm_);
    ramp_setpoint_rpm_ = ramp_setpoint_rpm_ > 0.0 ? std::max(0.0, ramp_setpoint_rpm_ - step)
                                                  : std::min(0.0, ramp_setpoint_rpm_ + step);
    reference_rpm = ramp_setpoint_rpm_;
  }
  MotorLoadCommand command;
  command.reference_rpm = std::clamp(reference_rpm, -p_.max_speed_rpm, p_.max_speed_rpm);
  command.torque_enabled = pulses_enabled_;
  command.torque_limit_positive = cycle_torque_limit_positive_;
  command.torque_limit_negative = cycle_torque_limit_negative_;
  if (config_.supplementary_telegram == 750)
    command.additional_torque_nm = tg::n2_to_torque(supplementary_sp_.M_ADD1, p_.reference_torque_nm);
  mechanics_.step(command, dt);
}

double SimulatedDrive::motor_speed_rpm() const noexcept {
  return mechanics_.motor_speed_rpm();
}

double SimulatedDrive::load_speed() const noexcept {
  if (config_.drive_telegram == 0) return external_speed_;
  return mechanics_.load_speed();
}

MachineInputs SimulatedDrive::machine_inputs() const noexcept {
  return mechanics_.machine_inputs();
}

// ---------------------------------------------------------------------------------------------------------
// Encoders (spec 06 §6)

double SimulatedDrive::shaft_revolutions(const SimulatedEncoderParameters& e, double motor_revolutions,
                                         double load_position) const noexcept {
  if (e.linear) return load_position / e.resolution;  // in steps, see xist1_of
  if (e.shaft == SimulatedEncoderParameters::Shaft::kMotor) return motor_revolutions;
  return load_position / p_.load_units_per_revolution;
}

std::uint32_t SimulatedDrive::xist1_of(int index, double shaft) const noexcept {
  const auto& e = index == 0 ? p_.encoder1 : p_.encoder2;
  const auto& s = encoders_[static_cast<std::size_t>(index)];
  const double scale = r_.xist1_scale[static_cast<std::size_t>(index)];
  double counts = 0.0;
  if (e.determinable_revolutions == 0) {
    counts = static_cast<double>(s.xist1_at_power_on) + (shaft - s.revolutions_at_power_on) * scale;
  } else {
    counts = (shaft - (e.linear ? 0.0 : e.absolute_offset_revolutions)) * scale;
  }
  // Wrap at 2^width with integer arithmetic (two's complement keeps negative counts right); |counts| stays
  // far below 2^63 for any travel the model can make.
  const auto modulus = static_cast<std::uint64_t>(r_.xist1_modulus[static_cast<std::size_t>(index)]);
  const auto whole = static_cast<std::int64_t>(std::floor(counts));
  return static_cast<std::uint32_t>(static_cast<std::uint64_t>(whole) & (modulus - 1));
}

void SimulatedDrive::update_encoders(double previous_load_position,
                                     double previous_motor_revolutions) noexcept {
  for (int i = 0; i < 2; ++i) {
    if (!encoders_[static_cast<std::size_t>(i)].present) continue;
    const auto& e = i == 0 ? p_.encoder1 : p_.encoder2;
    update_encoder(i, shaft_revolutions(e, previous_motor_revolutions, previous_load_position),
                   shaft_revolutions(e, mechanics_.motor_revolutions(), mechanics_.load_position()),
                   previous_load_position, mechanics_.load_position());
  }
}

void SimulatedDrive::update_encoder(int index, double previous_shaft, double shaft, double previous_load,
                                    double load) noexcept {
  auto& s = encoders_[static_cast<std::size_t>(index)];
  const auto& e = index == 0 ? p_.encoder1 : p_.encoder2;
  // The Gx_STW of this encoder: in the drive telegram (G1/G2) or in its separate encoder telegram.
  std::uint16_t control = 0;
  bool control_by_plc = true;
  if (index == 0 && r_.g1_stw) {
    control = drive_sp_.G1_STW.value();
  } else if (index == 1 && r_.g2_stw) {
    control = drive_sp_.G2_STW.value();
  } else {
    for (Slot slot : {Slot::kEncoder1, Slot::kEncoder2}) {
      if (config_.telegram(slot) != 0 && encoder_index_of_slot(config_, slot) == index) {
        const auto& sp = encoder_sp_[slot == Slot::kEncoder1 ? 0 : 1];
        control = sp.G1_STW.value();
        control_by_plc = sp.STW2_ENC.test(tg::Stw2EncBit::kControlByPlc);
      }
    }
  }
  s.control = control;
  std::uint16_t status = s.status & 0x00FFu;  // functions active / values available persist
  const tg::EncoderControlWord stw{control};

  // Encoder error and its acknowledge (spec 06 §6.3, §6.4): the error bit is set while the cause is present
  // and stays after it is gone until the controller acknowledges with Gx_STW.15 (shown as Gx_ZSW.11).
  const bool acknowledge = stw.test(tg::EncoderControlBit::kAcknowledgeEncoderError);
  if (acknowledge) status |= 0x0800u;
  if (s.error_code != 0) s.reported_error_code = s.error_code;
  const bool error = s.error_code != 0 || ((s.status & 0x8000u) != 0 && !acknowledge);
  if (error) status |= 0x8000u;

  // Parking, cyclic absolute value.
  if (stw.test(tg::EncoderControlBit::kRequestParkEncoder)) status |= 0x4000u;
  const bool absolute = e.determinable_revolutions != 0 && control_by_plc &&
                        stw.test(tg::EncoderControlBit::kRequestAbsoluteValue);
  if (absolute) status |= 0x2000u;

  // Reference-mark search and flying measurement (functions 1..4, command, mode).
  const std::uint16_t functions = stw.field(tg::kEncoderFunctionsField);
  const std::uint16_t command = stw.field(tg::kEncoderCommandField);
  const bool measurement = stw.test(tg::EncoderControlBit::kMeasurementMode);
  std::uint16_t active = status & 0x000Fu;
  std::uint16_t available = (status >> 4) & 0x000Fu;
  if (command > 3) {
    // Present while the invalid command is; latched in Gx_ZSW.15 until acknowledged like any encoder error.
    s.reported_error_code = tg::kEncoderErrorCommandNotSupported;
    status |= 0x8000u;
  } else if (command == 1) {
    const std::uint16_t newly = functions & static_cast<std::uint16_t>(~active);
    active |= newly;
    available &= static_cast<std::uint16_t>(~newly);
  } else if (command == 3) {
    active &= static_cast<std::uint16_t>(~functions);
    available &= static_cast<std::uint16_t>(~functions);
  }
  // Functions whose request bit was removed are switched off (PROFIdrive: deactivate by resetting the bits).
  if (command != 3) {
    active &= functions;
    available &= functions;
  }
  // Events: a reference mark crossed (mode 0) or a probe edge (mode 1) captures XIST1 at that position.
  const bool encoder_ok = (status & 0x8000u) == 0;
  if (encoder_ok && active != 0 && (active & static_cast<std::uint16_t>(~available)) != 0) {
    if (!measurement) {
      const double interval = e.reference_mark_interval_revolutions;
      const double offset = e.reference_mark_offset_revolutions;
      const double prev_rev =
          e.linear ? previous_shaft * e.resolution / p_.load_units_per_revolution : previous_shaft;
      const double now_rev = e.linear ? shaft * e.resolution / p_.load_units_per_revolution : shaft;
      const double k_prev = std::floor((prev_rev - offset) / interval);
      const double k_now = std::floor((now_rev - offset) / interval);
      if (k_prev != k_now && interval > 0.0) {
        const double mark_rev = offset + std::max(k_prev, k_now) * interval;
        const double mark_shaft =
            e.linear ? mark_rev * p_.load_units_per_revolution / e.resolution : mark_rev;
        s.captured = xist1_of(index, mark_shaft);
        available |= active & 0x0001u;  // reference mark 1 (function 1)
        if ((active & 0x0002u) != 0) available |= 0x0002u;
      }
    } else {
      // Probe windows are in load units; the edge is interpolated inside this cycle.
      const auto& m = p_.machine;
      auto edge = [&](const std::optional<PositionWindow>& w, std::uint16_t rising_bit,
                      std::uint16_t falling_bit) {
        if (!w) return;
        const bool was = w->contains(previous_load);
        const bool is = w->contains(load);
        if (was == is) return;
        // The boundary crossed: moving up, a rising edge enters at `from` and a falling one leaves at `to`.
        const bool moving_up = load > previous_load;
        const double boundary = moving_up == is ? w->from : w->to;
        const double span = load - previous_load;
        const double t = span != 0.0 ? std::clamp((boundary - previous_load) / span, 0.0, 1.0) : 1.0;
        const double shaft_at_edge = previous_shaft + t * (shaft - previous_shaft);
        const std::uint16_t wanted = is ? rising_bit : falling_bit;
        if ((active & wanted & static_cast<std::uint16_t>(~available)) != 0) {
          s.captured = xist1_of(index, shaft_at_edge);
          available |= wanted;
        }
      };
      edge(m.probe1, 0x0001u, 0x0002u);
      edge(m.probe2, 0x0004u, 0x0008u);
    }
  }
  status = static_cast<std::uint16_t>((status & 0xFF00u) | active | (available << 4));
  const auto& machine = p_.machine;
  if (machine.probe1 && machine.probe1->contains(load)) status |= 0x0100u;
  if (machine.probe2 && machine.probe2->contains(load)) status |= 0x0200u;

  // XIST2: error code > requested value > absolute value > nothing (spec 06 §6.2).
  if ((status & 0x8000u) != 0) {
    s.xist2 = s.reported_error_code;
  } else if (command == 2 && available != 0) {
    s.xist2 = s.captured;
  } else if (absolute) {
    const double range = static_cast<double>(e.determinable_revolutions);
    double revolutions = e.linear ? shaft * e.resolution / p_.load_units_per_revolution
                                  : shaft - e.absolute_offset_revolutions;
    revolutions = std::fmod(revolutions, range);
    if (revolutions < 0.0) revolutions += range;
    s.xist2 = static_cast<std::uint32_t>(
        std::floor(revolutions * tg::counts_per_revolution(e.steps_per_revolution, e.fine_resolution_xist2)));
  } else {
    s.xist2 = 0;
  }
  s.status = status;
}

void SimulatedDrive::power_cycle() noexcept {
  state_ = tg::DriveState::kS0NotReady;
  cyclic_data_ = false;
  fresh_setpoint_ = false;
  // After a gap the master sign-of-life has moved on by the missed cycles: resynchronise (the gap itself is
  // the setpoint timeout's business, docs/decisions.md).
  if (missed_setpoints_ != 0) master_monitor_.reset();
  missed_setpoints_ = 0;
  fault_code_ = 0;
  pulses_enabled_ = false;
  drive_sp_ = {};
  previous_stw1_ = 0;
  master_monitor_.reset();
  slave_sign_of_life_.reset(1);
  slave_counter_ = 0;
  for (int i = 0; i < 2; ++i) {
    auto& s = encoders_[static_cast<std::size_t>(i)];
    const auto& e = i == 0 ? p_.encoder1 : p_.encoder2;
    s.status = 0;
    s.control = 0;
    s.captured = 0;
    s.xist2 = 0;
    s.xist1_at_power_on = e.xist1_at_power_on;
    s.revolutions_at_power_on =
        shaft_revolutions(e, mechanics_.motor_revolutions(), mechanics_.load_position());
  }
}

// ---------------------------------------------------------------------------------------------------------
// Actual-value frames

void SimulatedDrive::encode_actuals(DeviceFrames& actual) noexcept {
  const bool fault = fault_code_ != 0;
  const double speed_rpm = mechanics_.motor_speed_rpm();
  const double torque_nm = mechanics_.motor_torque_nm();
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    const auto& codec = *codecs_.actual[i];
    if (codec.frame_size() == 0) continue;
    const auto slot = static_cast<Slot>(i);
    tg::ActualSignals a;
    if (slot == Slot::kDrive) {
      std::uint16_t zsw1 = tg::zsw1_for(state_, drive_sp_.STW1.value(), cyclic_data_, fault, false);
      // In fault the drive shows OFF2 and OFF3 active (switching on inhibited), as 0x0248 of spec 06
      // TV24/TV26.
      if (fault) zsw1 &= static_cast<std::uint16_t>(~0x0030u);
      const double deviation = std::fabs(cycle_speed_setpoint_rpm_ - speed_rpm);
      if (state_ == tg::DriveState::kS4Operation && deviation < p_.speed_deviation_tolerance_rpm)
        zsw1 |= 0x0100u;
      a.ZSW1 = tg::Zsw1{zsw1};
      if (r_.nsoll_b) {  // telegram 1 carries NIST_A, all others NIST_B
        a.NIST_B = tg::speed_to_n4(speed_rpm, p_.reference_speed_rpm);
      } else {
        a.NIST_A = tg::speed_to_n2(speed_rpm, p_.reference_speed_rpm);
      }
      a.ZSW2.set(tg::Zsw2Bit::kPulsesEnabled, pulses_enabled_);
      a.ZSW2.set(tg::Zsw2Bit::kTravelToFixedStopActive, drive_sp_.STW2.test(tg::Stw2Bit::kTravelToFixedStop));
      a.ZSW2.set_field(tg::kSignOfLifeField, slave_counter_);
      tg::Meldw meldw;
      meldw.set(tg::MeldwBit::kRampFunctionCompleted,
                state_ != tg::DriveState::kS5aRampStop && state_ != tg::DriveState::kS5bQuickStop);
      // Torque utilisation (r0033) is relative to the limit in force, MOMRED included (p2194 = 90 %).
      const double active_limit =
          torque_nm >= 0.0 ? cycle_torque_limit_positive_ : -cycle_torque_limit_negative_;
      meldw.set(tg::MeldwBit::kTorqueUtilisationBelowThreshold, std::fabs(torque_nm) < 0.9 * active_limit);
      meldw.set(tg::MeldwBit::kSpeedBelowStandstillThreshold,
                std::fabs(speed_rpm) < p_.standstill_threshold_rpm);
      meldw.set(tg::MeldwBit::kSpeedAtOrBelowThreshold2, std::fabs(speed_rpm) <= p_.standstill_threshold_rpm);
      meldw.set(tg::MeldwBit::kNoMotorOverTemperatureAlarm);
      meldw.set(tg::MeldwBit::kNoPowerUnitOverloadAlarm);
      meldw.set(tg::MeldwBit::kSpeedDeviationWithinTolerance, (zsw1 & 0x0100u) != 0);
      meldw.set(tg::MeldwBit::kControllerEnable, pulses_enabled_);
      meldw.set(tg::MeldwBit::kDriveReady, cyclic_data_ && !fault);
      meldw.set(tg::MeldwBit::kPulsesEnabled, pulses_enabled_);
      a.MELDW = meldw;
      a.G1_ZSW = tg::EncoderStatusWord{encoders_[0].status};
      if (encoders_[0].present)
        a.G1_XIST1 = xist1_of(
            0, shaft_revolutions(p_.encoder1, mechanics_.motor_revolutions(), mechanics_.load_position()));
      a.G1_XIST2 = encoders_[0].xist2;
      a.G2_ZSW = tg::EncoderStatusWord{encoders_[1].status};
      if (encoders_[1].present)
        a.G2_XIST1 = xist1_of(
            1, shaft_revolutions(p_.encoder2, mechanics_.motor_revolutions(), mechanics_.load_position()));
      a.G2_XIST2 = encoders_[1].xist2;
    } else if (slot == Slot::kSupplementary) {
      a.M_ACT = tg::torque_to_n2(torque_nm, p_.reference_torque_nm);
    } else {
      const int e = encoder_index_of_slot(config_, slot);
      const auto& s = encoders_[static_cast<std::size_t>(e)];
      const auto& ep = e == 0 ? p_.encoder1 : p_.encoder2;
      const auto& sp = encoder_sp_[slot == Slot::kEncoder1 ? 0 : 1];
      tg::Zsw2Enc zsw2;
      zsw2.set(tg::Zsw2EncBit::kControlRequested, cyclic_data_);
      zsw2.set(tg::Zsw2EncBit::kFaultPresent, (s.status & 0x8000u) != 0);
      zsw2.set_field(tg::kSignOfLifeField, slave_counter_);
      a.ZSW2_ENC = zsw2;
      const bool plc = sp.STW2_ENC.test(tg::Stw2EncBit::kControlByPlc);
      a.G1_ZSW = tg::EncoderStatusWord{plc ? s.status : static_cast<std::uint16_t>(s.status & 0x8000u)};
      a.G1_XIST1 =
          xist1_of(e, shaft_revolutions(ep, mechanics_.motor_revolutions(), mechanics_.load_position()));
      a.G1_XIST2 = plc ? s.xist2 : 0;  // no XIST2 without control by PLC (spec 06 §3.8)
      const double shaft_speed = ep.linear ? load_speed()
                                           : (ep.shaft == SimulatedEncoderParameters::Shaft::kMotor
                                                  ? speed_rpm
                                                  : load_speed() / p_.load_units_per_revolution * 60.0);
      a.NIST_B = tg::speed_to_n4(shaft_speed, ep.nist_reference_speed);
    }
    (void)codec.encode(a, actual.slots[i].view());
  }
}

}  // namespace tomc::drives
