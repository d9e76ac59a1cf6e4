// The shared motor and load model (motor_load.hpp). Moved here unchanged from the simulated PROFIdrive drive,
// so that the servo amplifier of an analog drive turns the same mechanics.
#include "tomc/drives/motor_load.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tomc::drives {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMovingThreshold = 1e-6;  // rad/s: below this the shaft is at rest for friction
}  // namespace

MotorLoad::MotorLoad(const SimulatedDriveParameters& parameters) : p_(parameters) {
  ratio_ = p_.gear_motor_revolutions / p_.gear_load_revolutions;
  inertia_ = p_.motor_inertia_kgm2 + p_.load_inertia_kgm2 / (ratio_ * ratio_);
  time_constant_ = p_.speed_loop_time_constant_s;
  load_position_ = p_.initial_load_position;
  const double half_gap = std::max(0.0, 0.5 * p_.backlash);
  gap_ = std::clamp(p_.initial_backlash_offset, -half_gap, half_gap);
  motor_revolutions_ = (load_position_ + gap_) / p_.load_units_per_revolution * ratio_;
}

double MotorLoad::motor_speed_rpm() const noexcept {
  return omega_ * 60.0 / kTwoPi;
}

double MotorLoad::load_speed() const noexcept {
  if (p_.backlash > 0.0) return load_speed_;
  return omega_ / kTwoPi / ratio_ * p_.load_units_per_revolution;
}

void MotorLoad::move_externally(double load_units_per_second, double dt) noexcept {
  load_position_ += load_units_per_second * dt;
  motor_revolutions_ = load_position_ / p_.load_units_per_revolution * ratio_;
}

void MotorLoad::step(const MotorLoadCommand& command, double dt) noexcept {
  // With backlash the motor drives the load only in contact and moving into it; inside the gap it turns
  // alone.
  const double half_gap = 0.5 * p_.backlash;
  const double drive_direction = omega_ != 0.0 ? omega_ : command.reference_rpm;
  const bool coupled = half_gap <= 0.0 || (gap_ >= half_gap && drive_direction > 0.0) ||
                       (gap_ <= -half_gap && drive_direction < 0.0);
  const double inertia = coupled ? inertia_ : p_.motor_inertia_kgm2;
  const double reference = command.reference_rpm * kTwoPi / 60.0;

  // Friction at the motor shaft: viscous + Coulomb; static friction holds a shaft at rest.
  const double coulomb =
      std::fabs(omega_) > kMovingThreshold ? std::copysign(p_.coulomb_friction_nm, omega_) : 0.0;
  const double friction = p_.viscous_friction_nm_per_rad_s * omega_ + coulomb;

  double torque = 0.0;
  if (command.torque_enabled) {
    // Closed speed loop = first-order lag with time constant T (exact discretisation), friction compensated;
    // an additional torque (telegram 750 M_ADD1) is added to the demand.
    if (dt != lag_dt_) {  // the step is constant in practice: one exp() per configuration, not per step
      lag_dt_ = dt;
      lag_ = 1.0 - std::exp(-dt / time_constant_);
    }
    const double lag = lag_;
    const double accel_demand = (reference - omega_) * lag / dt;
    double demand = inertia * accel_demand + friction;
    // Break-away: at rest the friction to overcome acts against the reference (none with a zero reference).
    if (std::fabs(omega_) <= kMovingThreshold && reference != 0.0) {
      demand += std::copysign(p_.coulomb_friction_nm, reference);
    }
    demand += command.additional_torque_nm;
    if (blocked_) {
      // At a fixed stop the speed controller's integral winds up until the torque limit (spec: torque rises).
      stall_integral_ += inertia * reference / time_constant_ * dt / time_constant_;
      // Anti-windup: the integral grows only until the torque reaches the active limit, so the drive leaves
      // the stop as soon as the speed setpoint reverses.
      stall_integral_ = std::clamp(stall_integral_, std::min(0.0, command.torque_limit_negative - demand),
                                   std::max(0.0, command.torque_limit_positive - demand));
      demand += stall_integral_;
    } else {
      stall_integral_ = 0.0;
    }
    torque = std::clamp(demand, command.torque_limit_negative, command.torque_limit_positive);
  }
  torque_ = torque;

  double omega_next = omega_;
  if (std::fabs(omega_) <= kMovingThreshold && std::fabs(torque) <= p_.coulomb_friction_nm) {
    omega_next = 0.0;  // static friction holds
  } else {
    // Breaking away from rest, the Coulomb friction opposes the starting motion (the direction of the
    // torque).
    const double acting_friction =
        std::fabs(omega_) <= kMovingThreshold ? std::copysign(p_.coulomb_friction_nm, torque) : friction;
    omega_next = omega_ + (torque - acting_friction) / inertia * dt;
    if (!command.torque_enabled && omega_ * omega_next < 0.0) omega_next = 0.0;  // friction never reverses
  }
  const double delta_motor_revolutions = 0.5 * (omega_ + omega_next) * dt / kTwoPi;
  omega_ = omega_next;
  motor_revolutions_ += delta_motor_revolutions;
  const double motor_travel = delta_motor_revolutions / ratio_ * p_.load_units_per_revolution;
  if (half_gap > 0.0) {
    // Dead band (play): the load moves only by what the motor travels beyond the gap.
    const double before = load_position_;
    gap_ += motor_travel;
    if (gap_ > half_gap) {
      load_position_ += gap_ - half_gap;
      gap_ = half_gap;
    } else if (gap_ < -half_gap) {
      load_position_ += gap_ + half_gap;
      gap_ = -half_gap;
    }
    load_speed_ = (load_position_ - before) / dt;
  } else {
    load_position_ += motor_travel;
  }

  // Mechanical end stops: the load cannot pass; the motor shaft (rigid coupling) stops with it.
  const auto& m = p_.machine;
  blocked_ = false;
  auto stop_at = [&](double stop) {
    load_position_ = stop;
    motor_revolutions_ = (stop + gap_) / p_.load_units_per_revolution * ratio_;
    omega_ = 0.0;
    load_speed_ = 0.0;
    blocked_ = true;
  };
  if (fixed_stops_broken_) return;
  if (m.positive_fixed_stop && load_position_ >= *m.positive_fixed_stop && torque_ >= 0.0)
    stop_at(*m.positive_fixed_stop);
  if (m.negative_fixed_stop && load_position_ <= *m.negative_fixed_stop && torque_ <= 0.0)
    stop_at(*m.negative_fixed_stop);
}

MachineInputs MotorLoad::machine_inputs() const noexcept {
  const auto& m = p_.machine;
  MachineInputs in;
  in.negative_limit_switch = m.negative_limit_switch && load_position_ <= *m.negative_limit_switch;
  in.positive_limit_switch = m.positive_limit_switch && load_position_ >= *m.positive_limit_switch;
  in.reference_cam = m.reference_cam && m.reference_cam->contains(load_position_);
  in.probe1 = m.probe1 && m.probe1->contains(load_position_);
  in.probe2 = m.probe2 && m.probe2->contains(load_position_);
  in.at_fixed_stop = blocked_;
  return in;
}

}  // namespace tomc::drives
