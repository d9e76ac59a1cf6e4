// Legacy regulator parameters -> PID option (legacy_regulator.hpp). Configuration time only (strings).
#include "tomc/techobjects/position/legacy_regulator.hpp"

#include <algorithm>
#include <cmath>

namespace tomc::techobjects {

namespace {
std::uint32_t derivative_cycles(double sample_s, double servo_cycle_s) {
  const double n = std::round(sample_s / servo_cycle_s);
  return static_cast<std::uint32_t>(std::clamp(n, 1.0, static_cast<double>(kMaxDerivativeCycles)));
}
}  // namespace

LegacyRegulator from_joint(const JointRegulatorParameters& p, double servo_cycle_s) {
  LegacyRegulator r;
  if (!(p.TCamp >= 0.001 && p.TCamp <= 0.255)) {
    r.problem = "TCamp: " + std::to_string(p.TCamp) + " s is outside 1 ... 255 ms";
  } else if (p.pgain < 0 || p.feedfw < 0 || p.integt < 0 || p.derivt < 0) {
    r.problem = "pgain, feedfw, integt, derivt: 0 ... 32767";
  } else if (!(p.maxvel > 0.0)) {
    r.problem = "maxvel: must be > 0";
  }
  if (!r.problem.empty()) return r;
  r.gains.Kv = (p.pgain / 1000.0) / p.TCamp;
  r.gains.IntegralTime = p.integt / 1000.0;
  r.gains.DerivativeTime = p.derivt / 1000.0;
  r.gains.DerivativeCycles = derivative_cycles(p.TCamp, servo_cycle_s);
  r.gains.OutputLimit = p.maxvel;  // the legacy output limit is 100 % (spec 05b C.1)
  r.Kpc = std::min(p.feedfw / 10.0, 150.0);
  r.offset_volts = p.offset * 10.0 / 32768.0;
  return r;
}

LegacyRegulator from_h3(const H3RegulatorParameters& p, double servo_cycle_s) {
  LegacyRegulator r;
  if (p.SampI > 255) {
    r.problem = "SampI: " + std::to_string(p.SampI) + " is outside 0 ... 255";
  } else if (!(p.kp > 0.0)) {
    r.problem = "kp: must be > 0 (I and D are expressed relative to the P gain)";
  } else if (p.ki < 0.0 || p.kd < 0.0 || p.IntL < 0.0) {
    r.problem = "ki, kd, IntL: must be >= 0";
  } else if (!(p.velocity_at_10V > 0.0)) {
    r.problem = "velocity_at_10V: must be > 0";
  }
  if (!r.problem.empty()) return r;
  const double scale = p.velocity_at_10V / 4095.0;  // one output code in velocity
  const double d_sample = (p.SampI + 1.0) * kH3SampleTime;
  r.gains.Kv = p.kp * scale;
  // IL bounds ki·Σe: IL = 0 leaves no integral action at all.
  r.gains.IntegralTime = p.ki > 0.0 && p.IntL > 0.0 ? kH3SampleTime * p.kp / p.ki : 0.0;
  r.gains.DerivativeTime = p.kd > 0.0 ? p.kd * d_sample / p.kp : 0.0;
  r.gains.DerivativeCycles = derivative_cycles(d_sample, servo_cycle_s);
  r.gains.IntegralLimit = p.IntL * scale;
  r.gains.OutputLimit = p.velocity_at_10V;
  r.Kpc = 0.0;
  return r;
}

}  // namespace tomc::techobjects
