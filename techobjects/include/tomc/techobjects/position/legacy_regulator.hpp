#pragma once
// Conversions from the legacy regulators' parameters to the PID option of the position controller
// (pid_regulator.hpp), spec 05b C.2, docs/analog-drives.md "PID position control".
//
// JOINT (spec 05b A.2): the regulator output in DAC bits (±32767 = ±10 V = ±maxvel), P at gain 1.0 giving
// full scale for an error of E_max = maxvel·TCamp:
//   Kv [1/s] = (pgain/1000)/TCamp          Kpc [%] = feedfw/10 (clamped to 150 %)
//   Ti [s]   = integt/1000 (0: no I)        Td [s]  = derivt/1000 (0: no D), D sample = TCamp
//   offset [V] = offset·10/32768 (the analog actor's offset)     output limit = maxvel (100 %)
// H3 (spec 05b B.4): U(n) = kp·e(n) + ki·Σe + kd·[e(n') − e(n'−1)] every T_H3 = 341.33 µs, U in DAC codes of
// the 12 bit + sign output (±4095 = ±10 V = ±v_10V) [tomc's scaling: the source leaves it open]:
//   Kv = kp·v_10V/4095                     Ti = T_H3·kp/ki (ki = 0: no I)
//   Td = kd·(SampI+1)·T_H3/kp (kd = 0: no D), D sample = (SampI+1)·T_H3
//   IntegralLimit = IntL·v_10V/4095 (IL bounds ki·Σe)           Kpc = 0 (no precontrol)
// Times are converted to the servo cycle the regulator runs in: the D sample becomes the nearest whole number
// of servo cycles (at least 1).

#include <cstdint>
#include <string>

#include "tomc/techobjects/position/pid_regulator.hpp"

namespace tomc::techobjects {

struct JointRegulatorParameters {
  std::int32_t pgain = 1000;  // 1/1000: 1000 = 1.0
  std::int32_t feedfw = 0;    // 1/10 %: 1000 = 100 %
  std::int32_t integt = 0;    // ms
  std::int32_t derivt = 0;    // ms
  std::int32_t offset = 0;    // DAC bits
  double TCamp = 0.010;       // s (1 ... 255 ms)
  double maxvel = 10000.0;    // velocity at 10 V [unit/s]
};

inline constexpr double kH3SampleTime = 341.33e-6;  // s (spec 05b Part E #8)

struct H3RegulatorParameters {
  double kp = 0.0;
  double ki = 0.0;
  double kd = 0.0;
  double IntL = 0.0;             // bound of |ki·Σe| in output codes
  std::uint32_t SampI = 0;       // 0 ... 255: D sample = (SampI + 1)·341.33 µs
  double velocity_at_10V = 0.0;  // [unit/s]; e in the same unit (counts)
};

struct LegacyRegulator {
  PidGains gains{};
  double Kpc = 0.0;           // PositionControl.Kpc [%]
  double offset_volts = 0.0;  // the analog actor's offset
  std::string problem;        // empty when the parameters are usable, else one line naming the parameter
};

LegacyRegulator from_joint(const JointRegulatorParameters& p, double servo_cycle_s);
LegacyRegulator from_h3(const H3RegulatorParameters& p, double servo_cycle_s);

}  // namespace tomc::techobjects
