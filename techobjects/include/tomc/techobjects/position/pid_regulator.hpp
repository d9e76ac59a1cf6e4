#pragma once
// PID position control as an option of the position controller (issue 20; spec 05b A.2 JOINT, B.4 SAIA H3,
// C.2 "EXT PID"; spec 05a where it differs). The S7 position controller is P (Kv) + velocity precontrol
// (spec 02 §7.4); this adds, per servo cycle k with T_s the servo cycle and e the control difference:
//
//   e'(k)  = 0 if |e(k)| <= DeadBand, else e(k)                                (dead band)
//   P(k)   = Kv·e'(k)
//   I(k)   = clamp(I(k−1) + Kv·(T_s/Ti)·e'(k), ±IntegralLimit)                (Ti = 0: no I)
//   D(k)   = Kv·Td·(e'(k) − e'(k−n))/(n·T_s), evaluated every n = DerivativeCycles cycles and held (Td = 0:
//   no D) u(k)   = clamp(P + I + D, ±OutputLimit)                                   (OutputLimit = 0: no
//   clamp)
//
// Anti-windup: the integral is limited to ±IntegralLimit (the H3's IL bounds ki·Σe, not Σe), and while u is
// saturated the integral does not grow further in the direction of the saturation (conditional
// integration). With Ti = Td = DeadBand = 0 the regulator is exactly Kv·e, the S7 default.
//
// Gains are double-buffered (H3 FLdRP/FUpDRP, spec 05b C.2): load() stores a set, apply() makes it active at
// the start of the next update(); a set loaded but not applied changes nothing.
//
// Real time: noexcept, allocation-free, O(1) per cycle.

#include <array>
#include <cstdint>

namespace tomc::techobjects {

struct PidGains {
  double Kv = 50.0;                    // proportional gain [1/s] (PositionControl.Kv)
  double IntegralTime = 0.0;           // Ti [s]; 0 = no integral action
  double DerivativeTime = 0.0;         // Td [s]; 0 = no derivative action
  std::uint32_t DerivativeCycles = 1;  // the D sample in servo cycles, 1 ... kMaxDerivativeCycles
  double IntegralLimit = 0.0;  // bound of |I| [unit/s]; 0 = unbounded (the output clamp still applies)
  double DeadBand = 0.0;       // |e| <= this is treated as 0 [unit]
  double OutputLimit = 0.0;    // bound of |P + I + D| [unit/s]; 0 = none
};

inline constexpr std::uint32_t kMaxDerivativeCycles = 256;  // H3: SampI 0 ... 255 -> 1 ... 256 samples

struct PidTerms {
  double p = 0.0;
  double i = 0.0;
  double d = 0.0;
  double output = 0.0;  // clamp(p + i + d)
  bool saturated = false;
};

class PidRegulator {
 public:
  // Rejects (returns false, keeps the previous set) negative or non-finite values and a DerivativeCycles
  // outside 1 ... kMaxDerivativeCycles.
  bool configure(const PidGains& gains, double servo_cycle_s) noexcept;
  // Double buffer: load a set now, make it active with apply() (at the next update()).
  bool load(const PidGains& gains) noexcept;
  void apply() noexcept {
    apply_pending_ = has_pending_;
    proportional_only_ = proportional_only_ && !apply_pending_;
  }
  const PidGains& gains() const noexcept { return active_; }
  // Forgets I, the D history and the held D: the next update starts from e alone.
  void reset() noexcept;

  // The terms of this cycle. Without an option set (the S7 P controller, the common case) only P is
  // computed, inline: the same terms as the full regulator gives for those gains, at a few instructions.
  PidTerms update(double control_difference) noexcept {
    if (!proportional_only_) return update_pid(control_difference);
    started_ = true;
    e_at_last_sample_ = control_difference;
    PidTerms t;
    t.p = active_.Kv * control_difference;
    t.i = integral_;
    t.output = t.p + t.i;
    return t;
  }

 private:
  static bool valid(const PidGains& g) noexcept;
  PidTerms update_pid(double control_difference) noexcept;
  void classify() noexcept {
    proportional_only_ = active_.IntegralTime == 0.0 && active_.DerivativeTime == 0.0 &&
                         active_.DeadBand == 0.0 && active_.OutputLimit == 0.0 && !apply_pending_;
  }

  PidGains active_{};
  PidGains pending_{};
  bool has_pending_ = false;
  bool apply_pending_ = false;
  double ts_ = 0.001;
  double integral_ = 0.0;
  double derivative_ = 0.0;        // held between D samples
  double e_at_last_sample_ = 0.0;  // e'(k − n)
  std::uint32_t cycles_since_sample_ = 0;
  bool started_ = false;
  bool proportional_only_ = true;  // no I, D, dead band or output limit active, no new set to apply
};

}  // namespace tomc::techobjects
