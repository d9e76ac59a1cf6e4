#pragma once
// The motor and load of a simulated machine axis, behind a closed speed loop: the mechanics that the
// simulated PROFIdrive drive (simulated_drive.hpp) and the simulated servo amplifier of an analog drive
// (simulated_servo_amplifier.hpp) share. Speed loop as a first-order lag, inertia, viscous/Coulomb/static
// friction, a gear, backlash, the machine's fixed stops and its position-based inputs. Pure arithmetic on
// preallocated state: no allocation, no locks, no exceptions.

#include "tomc/drives/simulated_drive_parameters.hpp"

namespace tomc::drives {

// What the speed loop is told for one integration step.
struct MotorLoadCommand {
  double reference_rpm = 0.0;          // speed reference at the motor shaft (already limited by the caller)
  bool torque_enabled = false;         // pulses enabled: the speed loop acts; otherwise the shaft coasts
  double torque_limit_positive = 0.0;  // Nm, >= 0
  double torque_limit_negative = 0.0;  // Nm, <= 0
  double additional_torque_nm = 0.0;   // added to the demand (telegram 750 M_ADD1)
};

class MotorLoad {
 public:
  explicit MotorLoad(const SimulatedDriveParameters& parameters);

  // One integration step of dt seconds.
  void step(const MotorLoadCommand& command, double dt) noexcept;
  // A shaft that something else turns (an encoder-only device): the load moves as told, no dynamics.
  void move_externally(double load_units_per_second, double dt) noexcept;
  // The machine's fixed stops give way (a broken stop, a workpiece that yields): the load passes them.
  void break_fixed_stops(bool broken) noexcept { fixed_stops_broken_ = broken; }

  double motor_speed_rad_s() const noexcept { return omega_; }
  double motor_speed_rpm() const noexcept;
  double motor_revolutions() const noexcept { return motor_revolutions_; }
  double motor_torque_nm() const noexcept { return torque_; }
  double load_position() const noexcept { return load_position_; }
  double load_speed() const noexcept;  // load units per second
  // Backlash: motor − load position in load units, −backlash/2 ... +backlash/2 (0 without backlash).
  double backlash_offset() const noexcept { return gap_; }
  bool at_fixed_stop() const noexcept { return blocked_; }
  double ratio() const noexcept { return ratio_; }  // motor revolutions per load revolution
  MachineInputs machine_inputs() const noexcept;

 private:
  SimulatedDriveParameters p_;
  double ratio_ = 1.0;
  double inertia_ = 0.0;  // motor + load at the motor shaft
  double time_constant_ = 0.0;
  double lag_dt_ = 0.0;  // the step for which lag_ = 1 - exp(-dt/T) was computed
  double lag_ = 0.0;

  double omega_ = 0.0;  // motor speed, rad/s
  double motor_revolutions_ = 0.0;
  double load_position_ = 0.0;
  double torque_ = 0.0;          // motor torque, Nm
  double stall_integral_ = 0.0;  // speed-controller integral while blocked at a fixed stop
  double gap_ = 0.0;             // backlash: motor position − load position (load units), ±backlash/2
  double load_speed_ = 0.0;      // with backlash: the load's speed in the last step (load units/s)
  bool blocked_ = false;
  bool fixed_stops_broken_ = false;
};

}  // namespace tomc::drives
