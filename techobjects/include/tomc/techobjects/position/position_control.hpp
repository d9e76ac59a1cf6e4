#pragma once
// Position controller of the positioning axis (issue 5 groundwork): P controller with velocity precontrol
// and symmetry filter, position control in the PLC or in the drive with DSC, and the following error.
//
// Spec 02 §7.1 (structure), §7.2 (DSC: NSOLL_B, XERR, KPC), §7.3 (Kv, Kpc, T_vtc), §7.4 (controller
// equations, [Derived]), §6.2 and spec 01 §3.5 (following error with the setpoint delayed by
// T_i + T_o + T_DC + T_Servo + T_add).
//
// Per servo cycle k (T_s = servo cycle, kpc = Kpc/100):
//   x_d(k)   = x_f(k − D_ctrl),  D_ctrl = (T_i + T_o + T_DC + T_Servo)/T_s              §7.4 (2)
//   x_sym(k) = kpc·PT1_Tvtc(x_d)(k) + (1 − kpc)·x_d(k)          -> StatusServo.BalancedPosition §7.4 (3)
//   e(k)     = x_sym(k) − x_act(k)                              -> StatusServo.ControlDifference §7.4 (4)
//   PLC:  v_cmd(k) = kpc·v_f(k) + Kv·e(k)                                                §7.4 (5a)
//         with the PID option (issue 20, pid_regulator.hpp): kpc·v_f(k) + PID(e)(k); PID = Kv·e by default
//   DSC:  v_cmd(k) = NSOLL_B = kpc·v_f(k),  XERR = e(k),  KPC = Kv                       §7.4 (5b)
//   FE(k)    = x_ipo(k − D_fe) − x_act(k),  D_fe = D_ctrl + T_add/T_s  -> StatusPositioning.FollowingError
//
// Decisions:
// - Delays are held in a fixed-capacity delay line (kMaxSetpointDelayCycles samples incl. the current one).
//   A fractional delay D = n + r (0 <= r < 1) is realised by linear interpolation between the samples n and
//   n + 1 cycles old; this is exact for a setpoint ramp (constant velocity). Delays beyond the capacity are
//   clamped to kMaxSetpointDelayCycles − 1 cycles and reported by configure() / delay_clamped().
// - The symmetry filter PT1 is discretised with backward Euler, y(k) = y(k−1) + Ts/(T_vtc + Ts)·(u(k) −
//   y(k−1)): its lag behind a ramp of velocity v is exactly v·T_vtc (the continuous value), and T_vtc = 0
//   makes it a pass-through. A well-matched loop with 100 % precontrol therefore shows FE = v·T_vtc and
//   e = 0 in steady state; without precontrol e = FE = v/Kv; in general FE = kpc·v·T_vtc + (1−kpc)·v/Kv.
// - The precontrol velocity is not delayed (§7.4 (5a)); only the position setpoint is (symmetrisation).
// - x_ipo (before the dynamic filter, §6.2) and x_f (after it, §7.6) are separate inputs; without a dynamic
//   filter the caller passes the same value twice. T_add = FollowingError.AdditionalSetpointDelayTime
//   enters only the following error, never the control path.
// - Control-difference quantisation (spec 01 §3.11, spec 02 §7.4 (4), for stepper drives): the controller
//   (PID or DSC's XERR) gets e_q = q·trunc(e/q), so |e| < q gives 0 and the motor does not hunt between two
//   increments; StatusServo.ControlDifference shows e unquantised. q = 0: none. The caller resolves
//   ControlDifferenceQuantization.Mode 1 (encoder resolution) / 2 (Value) to q.
// - The output velocity is a load velocity in position units/s; conversion to NSOLL (% of the reference
//   speed) and of XERR to counts is the caller's job (actual_value_chain.hpp).
// - The first update() after construction/configure()/reset() fills the delay line and the symmetry filter
//   with the current setpoint, so the loop starts without a step.
//
// Real time: all member functions are noexcept, allocation-free and bounded (O(1) per cycle).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "tomc/techobjects/position/pid_regulator.hpp"

namespace tomc::techobjects {

// Capacity of the position controller's setpoint delay lines in servo cycles (current sample included):
// delays up to 31 cycles (T_i + T_o + T_DC + T_servo and AdditionalSetpointDelayTime; decision M3). Longer
// delays are clamped and reported by configure().
inline constexpr std::size_t kMaxSetpointDelayCycles = 24;
// The simulated control loop of a simulated axis (Simulation.Mode = 1): T_t up to 63 cycles.
inline constexpr std::size_t kSimulationDelayCycles = 64;

// Filled from PositioningAxisData (spec 04 §3.20, §3.23, §3.24) and the communication times (spec 01 §3.5).
struct PositionControlConfig {
  double Kv = 50.0;                          // PositionControl.Kv [1/s], 0.0 ... 2147480.0
  double Kpc = 100.0;                        // PositionControl.Kpc [%], 0.0 ... 150.0
  double VelocityTimeConstant = 0.0;         // DynamicAxisModel.VelocityTimeConstant (T_vtc) [s]
  bool EnableDSC = false;                    // PositionControl.EnableDSC
  double AdditionalSetpointDelayTime = 0.0;  // FollowingError.AdditionalSetpointDelayTime (T_add) [s]
  double ServoCycle = 0.004;                 // T_Servo = MC_Servo cycle [s], > 0
  double Ti = 0.0;                           // MC_WriteParameter 1010 [s]
  double To = 0.0;                           // MC_WriteParameter 1011 [s]
  double Tdc = 0.0;                          // MC_WriteParameter 1012 [s]
  // PID option (issue 20; PositionControl.Pid.*, a tomc extension): all 0 = the S7's P controller. Only with
  // position control in the PLC (not with DSC).
  double IntegralTime = 0.0;                   // Ti [s]
  double DerivativeTime = 0.0;                 // Td [s]
  std::uint32_t DerivativeCycles = 1;          // the D sample in servo cycles
  double IntegralLimit = 0.0;                  // |I| bound [unit/s], 0 = none
  double DeadBand = 0.0;                       // [unit]
  double OutputLimit = 0.0;                    // |PID| bound [unit/s], 0 = none
  double ControlDifferenceQuantization = 0.0;  // q [unit], 0 = none (spec 01 §3.11)
};

enum class PositionControlConfigResult : unsigned char {
  kOk = 0,
  kInvalidServoCycle,  // ServoCycle <= 0 or not finite: configuration rejected, previous one kept
  kInvalidParameter,   // Kv, Kpc, T_vtc, a delay or a PID value invalid, or PID with DSC: rejected
  kDelayClamped,       // accepted, but a delay exceeds the delay line and was clamped
};

struct PositionControlInput {
  double interpolator_position = 0.0;  // x_ipo: interpolator setpoint before the dynamic filter (for FE)
  double position_setpoint = 0.0;      // x_f: position setpoint after the dynamic filter (control path)
  double velocity_setpoint = 0.0;      // v_f: velocity setpoint (precontrol) [unit/s]
  double actual_position = 0.0;        // x_act
};

struct PositionControlOutput {
  // Speed setpoint as load velocity [unit/s]: PLC: kpc·v_f + Kv·e; DSC: NSOLL_B = kpc·v_f.
  double velocity_setpoint = 0.0;
  double balanced_position = 0.0;   // StatusServo.BalancedPosition (x_sym)
  double control_difference = 0.0;  // StatusServo.ControlDifference (e)
  double following_error = 0.0;     // StatusPositioning.FollowingError
  PidTerms pid{};                   // the PID terms of this cycle (p = Kv·e without the option)
  // DSC only (§7.2), zero otherwise: XERR as a position difference (caller converts to counts), KPC = Kv.
  double dsc_position_error = 0.0;
  double dsc_kpc = 0.0;
};

// Fixed-capacity delay line with linear interpolation for fractional delays. The capacity is the longest
// delay
// + 1 in servo cycles (issue 14, memory per axis: the position controller's lines hold
// kMaxSetpointDelayCycles, the simulated control loop of a simulated axis kSimulationDelayCycles).
template <std::size_t Capacity>
class BasicSetpointDelayLine {
 public:
  static constexpr std::size_t kCapacity = Capacity;
  // Fills the whole history with value (used at start so there is no step).
  void fill(double value) noexcept {
    buffer_.fill(value);
    head_ = 0;
  }
  // Moves every stored sample by delta (a position shift by homing keeps the history's shape).
  void shift(double delta) noexcept {
    for (auto& v : buffer_)
      v += delta;
  }
  // The ring index wraps by a compare, not `%`: the capacity (24) is no power of two, and the servo cycle
  // pushes and reads two lines (issue 23, decision P26).
  void push(double value) noexcept {
    head_ = head_ + 1 == Capacity ? 0 : head_ + 1;
    buffer_[head_] = value;
  }
  // Value delay_cycles ago (0 = the last pushed value); 0 <= delay_cycles <= Capacity − 1, clamped otherwise.
  // Linear interpolation between neighbouring samples.
  double delayed(double delay_cycles) const noexcept { return delayed(tap(delay_cycles)); }
  // A delay resolved once (sample index and interpolation weight) for a delay that stays the same over many
  // cycles: delayed(tap(d)) == delayed(d).
  struct Tap {
    std::size_t samples = 0;
    double fraction = 0.0;
  };
  static Tap tap(double delay_cycles) noexcept {
    constexpr double kMax = static_cast<double>(Capacity - 1);
    const double d = std::clamp(std::isfinite(delay_cycles) ? delay_cycles : 0.0, 0.0, kMax);
    const auto n = static_cast<std::size_t>(std::floor(d));
    return Tap{n, d - static_cast<double>(n)};
  }
  double delayed(const Tap& tap) const noexcept {
    const std::size_t n = tap.samples;
    const double r = tap.fraction;
    if (n >= Capacity - 1 || r == 0.0) return at(n);
    return (1.0 - r) * at(n) + r * at(n + 1);
  }

 private:
  // age <= Capacity - 1 (tap() clamps, delayed() reads n + 1 only for n < Capacity - 1).
  double at(std::size_t age) const noexcept {
    return buffer_[head_ >= age ? head_ - age : head_ + Capacity - age];
  }
  std::array<double, Capacity> buffer_{};
  std::size_t head_ = 0;  // index of the newest sample
};
// The position controller's delay line (delays up to kMaxSetpointDelayCycles − 1 cycles).
using SetpointDelayLine = BasicSetpointDelayLine<kMaxSetpointDelayCycles>;

class PositionController {
 public:
  PositionController() noexcept;
  explicit PositionController(const PositionControlConfig& config) noexcept;

  PositionControlConfigResult configure(const PositionControlConfig& config) noexcept;
  // The configured Kv [1/s] (DSC sends it as KPC; the PID's own copy may change with apply_gains()).
  double kv() const noexcept { return kv_; }
  double quantization() const noexcept { return quantization_; }  // ControlDifferenceQuantization
  // Forgets the history (and the PID's integral); the next update() starts without a step.
  void reset() noexcept;
  // Double-buffered PID gains (H3 FLdRP/FUpDRP): load_gains() stores a set (Kv included), apply_gains() makes
  // it active from the next update() without resetting the integral. False: invalid set, nothing stored.
  bool load_gains(const PidGains& gains) noexcept { return pid_.load(gains); }
  void apply_gains() noexcept { pid_.apply(); }
  const PidGains& active_gains() const noexcept { return pid_.gains(); }
  // The coordinate system moved by delta (homing during motion, decision P7): the setpoint histories and the
  // symmetry filter move with it, so the following error and the output are unchanged.
  void shift(double delta) noexcept {
    if (!started_) return;
    control_line_.shift(delta);
    fe_line_.shift(delta);
    symmetry_state_ += delta;
  }

  // One servo cycle.
  PositionControlOutput update(const PositionControlInput& in) noexcept;

  // Effective delays in servo cycles after clamping.
  double control_delay_cycles() const noexcept { return control_delay_cycles_; }
  double following_error_delay_cycles() const noexcept { return fe_delay_cycles_; }
  bool delay_clamped() const noexcept { return delay_clamped_; }

 private:
  // Of the configuration only what update() reads is kept; the delays are resolved into the taps (M5).
  double kv_ = PositionControlConfig{}.Kv;
  double quantization_ = 0.0;   // ControlDifferenceQuantization
  double kpc_ = 1.0;            // Kpc/100
  double symmetry_gain_ = 1.0;  // Ts/(T_vtc + Ts)
  double control_delay_cycles_ = 1.0;
  double fe_delay_cycles_ = 1.0;
  SetpointDelayLine::Tap control_tap_ = SetpointDelayLine::tap(1.0);  // resolved in configure()
  SetpointDelayLine::Tap fe_tap_ = SetpointDelayLine::tap(1.0);
  bool delay_clamped_ = false;
  bool started_ = false;
  bool dsc_ = false;  // EnableDSC
  double symmetry_state_ = 0.0;
  SetpointDelayLine control_line_{};
  SetpointDelayLine fe_line_{};
  PidRegulator pid_{};
};

}  // namespace tomc::techobjects
