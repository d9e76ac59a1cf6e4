#pragma once
// Backlash compensation of the positioning axis (spec 01 §5.9, spec 04 §8 rule 10, spec 02 §1.2
// StatusWord2.X2, §5.11; seed 004 §6.4.8, §6.11.11): a motor-shaft encoder measures the motor, not the load;
// after a reversal the motor crosses the backlash (the gap) before the load moves. The compensation corrects
// the TO's actual value by the part of the gap the motor crosses.
//
// The model. p ∈ [0, Size] is where the motor stands in the gap: 0 = in contact on the negative side (the
// last load motion was negative), Size = in contact on the positive side. A motor step Δ moves p to clamp(p +
// Δ, 0, Size); the load moves only by what is left over. The TO actual value is x = x_motor + c, and a motor
// step inside the gap changes c by −(change of p), so x stays where the load is.
//
// Setpoint operation (position control, spec 01 §5.9 "funzionamento setpoint"): at the start of a reversing
// motion (the sign of the setpoint velocity turns against the contact side), c is shifted by the whole
// remaining gap towards the new contact side at Backlash.Velocity (0.0: within one servo cycle):
//   c −= d·step,  step = min(remaining, Velocity·T_s)  (d = new direction)
// The shift appears as a control deviation, so the position controller drives the motor through the gap; the
// crossing also depends on Kv. StatusWord2.X2 PassingBacklash is TRUE from the reversal until the shift is
// complete and the motor has crossed the gap; meanwhile ActualPosition shows the value from the start of the
// reversal (spec 04 §5.2 X2: "ActualPosition is not changing"): held_travel() is what the actual value moved
// since then.
// Follow-up mode and operation without position control ("funzionamento a seguire"): no shift ahead; c
// follows p as the motor moves, so the actual value is coupled to the motor again only once the gap is
// crossed. Non-homed axis (spec 01 §5.9): after power-up (and a restart of an incremental encoder) the side
// of the gap is unknown and the compensation inactive; it becomes known once the motor has moved Size away
// from the farthest point reached in the other direction, i.e. the gap has certainly been crossed, and the
// next reversal is compensated. Changing Enable or Size makes the side unknown again; the axis must be homed
// again (spec 04 §8 rule 10; HomingDone itself is not reset, spec 02 §5.12 does not list it).
//
// Homing needs no hook: the correction is added to the offset of the actual-value chain, so homing (which
// sets the chain's position) includes it, and reference marks are captured in the compensated coordinate.
// After the power-up of an adjusted absolute encoder the side is the one of the adjustment: the axis calls
// assume_contact(Backlash.DirectionAbsoluteHoming) (spec 02 §5.11 Mode 6/7).
//
// Real time: noexcept, no allocation, O(1) per cycle.

#include <cstdint>

namespace tomc::techobjects {

class ActualValueChain;

struct BacklashConfig {
  bool Enable = false;        // Sensor[n].Backlash.Enable, and the encoder is on the motor shaft
  double Size = 0.0;          // Sensor[n].Backlash.Size [position unit], >= 0
  double Velocity = 0.0;      // Sensor[n].Backlash.Velocity [position unit / s], 0 = within one servo cycle
  double ServoCycle = 0.001;  // T_s [s], > 0
};

struct BacklashInput {
  // The motor-side position without offsets (encoder counts × units per count): only its changes are used.
  double motor_position = 0.0;
  bool motor_valid = false;         // FALSE: no valid encoder value; the next valid one is a new reference
  bool setpoint_operation = false;  // position control with setpoints (not follow-up, not speed control)
  double setpoint_velocity = 0.0;   // its sign is the travel direction of the setpoint
};

class BacklashCompensation {
 public:
  // Returns false (configuration unchanged) for a negative or non-finite Size or Velocity or a servo cycle
  // <= 0. A change of Enable or Size makes the side of the gap unknown; Velocity acts at once.
  bool configure(const BacklashConfig& config) noexcept;
  const BacklashConfig& config() const noexcept { return config_; }

  // Power-up or restart of a non-homed axis: side of the gap unknown (first motion uncompensated).
  void reset() noexcept;
  // The gap is closed in `direction` (> 0 positive, < 0 negative), e.g. an adjusted absolute encoder after
  // power-up with Backlash.DirectionAbsoluteHoming. The actual value does not change.
  void assume_contact(int direction) noexcept;

  // One servo cycle: the correction to add to the actual value (and to the chain's offset) this cycle.
  double update(const BacklashInput& in) noexcept;
  // The same on an actual-value chain: reads the motor position from its counts, shifts its offset by the
  // correction (so homing and the modulo counter see the compensated value) and returns the correction.
  double compensate(ActualValueChain& chain, bool valid, bool setpoint_operation,
                    double setpoint_velocity) noexcept;

  bool active() const noexcept { return config_.Enable && config_.Size > 0.0; }
  bool passing() const noexcept { return passing_; }  // StatusWord2.X2 PassingBacklash
  // How far the actual value moved since the reversal began while passing, else 0: ActualPosition shows
  // actual − held_travel().
  double held_travel() const noexcept { return passing_ ? held_ : 0.0; }
  // +1 / −1: the gap is closed on that side; 0: unknown.
  int contact() const noexcept;
  bool known() const noexcept { return known_; }
  double gap_position() const noexcept { return gap_; }  // p, see above

 private:
  void become_known(double gap) noexcept;

  // The doubles first, the flags together: no padding (decision M5).
  BacklashConfig config_{};
  double last_motor_ = 0.0;
  double lowest_ = 0.0;  // unknown side: the motor's extremes since then
  double highest_ = 0.0;
  double gap_ = 0.0;      // p: where the motor is in the gap (tracked from its motion)
  double applied_ = 0.0;  // the p the correction c corresponds to (ahead of gap_ while shifting)
  double held_ = 0.0;
  int direction_ = 0;  // setpoint operation: the travel direction the compensation is set for
  bool have_reference_ = false;
  bool known_ = false;
  bool passing_ = false;
};

}  // namespace tomc::techobjects
