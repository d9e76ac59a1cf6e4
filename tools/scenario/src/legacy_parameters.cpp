// The legacy parameter sets of JOINT and the H3 onto the S7 model (legacy_parameters.hpp). Configuration time
// only: strings, JSON and exceptions are fine here.
#include "legacy_parameters.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "json_reader.hpp"
#include "tomc/techobjects/position/legacy_regulator.hpp"

namespace tomc::scenario::detail {

namespace to = tomc::techobjects;

namespace {

// The regulator keys of both systems (spec 05b C.2): the PID option, Kv and Kpc.
void put_regulator(const to::LegacyRegulator& r, LegacyExpansion& e) {
  e.config["PositionControl.Kv"] = r.gains.Kv;
  e.config["PositionControl.Kpc"] = r.Kpc;
  e.config["PositionControl.Pid.IntegralTime"] = r.gains.IntegralTime;
  e.config["PositionControl.Pid.DerivativeTime"] = r.gains.DerivativeTime;
  e.config["PositionControl.Pid.DerivativeCycles"] = r.gains.DerivativeCycles;
  e.config["PositionControl.Pid.IntegralLimit"] = r.gains.IntegralLimit;
  e.config["PositionControl.Pid.OutputLimit"] = r.gains.OutputLimit;
  e.drive["analog"]["offset_volts"] = r.offset_volts;
}

// The analog axis both systems are: a ±10 V DAC of `dac_bits` with the legacy 100 % output limit (spec 05b
// C.1), the encoder counted ×4 on the card's counter as a motor-shaft encoder of `counts_per_turn` counts per
// `lead_mm` of travel (so that the TO's position is exactly counts · lead / counts_per_turn).
void put_axis(double counts_per_turn, double lead_mm, double velocity_at_10v_mm_s, int dac_bits,
              LegacyExpansion& e) {
  const double reference_rpm = velocity_at_10v_mm_s / lead_mm * 60.0;
  e.config["Sensor[1].Parameter.StepsPerRevolution"] = static_cast<std::uint32_t>(counts_per_turn);
  e.config["Sensor[1].Parameter.FineResolutionXist1"] = 0;
  e.config["Mechanics.LeadScrew"] = lead_mm;
  e.config["Actor.DriveParameter.ReferenceSpeed"] = reference_rpm;
  e.config["Actor.DriveParameter.MaxSpeed"] = reference_rpm;
  e.config["DynamicLimits.MaxVelocity"] = velocity_at_10v_mm_s;
  e.config["DynamicLimits.MaxJerk"] = 0.0;  // trapezoids (JOINT ramptype 0; the H3 has no jerk limit)
  e.config["DynamicDefaults.Jerk"] = 0.0;
  e.drive["adapter"] = "analog";
  e.drive["telegram"] = 3;
  e.drive["max_speed_rpm"] = 1.2 * reference_rpm;
  e.drive["analog"]["volts_at_reference"] = 10.0;
  e.drive["analog"]["overdrive_percent"] = 100.0;
  e.drive["analog"]["dac_bits"] = dac_bits;
  e.drive["analog"]["dac_full_scale_volts"] = 10.0;
}

void put_dynamics(double velocity, double acceleration, double deceleration, LegacyExpansion& e) {
  if (velocity > 0.0) e.config["DynamicDefaults.Velocity"] = velocity;
  if (acceleration > 0.0) {
    e.config["DynamicDefaults.Acceleration"] = acceleration;
    e.config["DynamicLimits.MaxAcceleration"] = acceleration;
  }
  if (deceleration > 0.0) {
    e.config["DynamicDefaults.Deceleration"] = deceleration;
    e.config["DynamicLimits.MaxDeceleration"] = deceleration;
  }
}

void put_following_error(double limit_mm, LegacyExpansion& e) {
  e.config["FollowingError.EnableMonitoring"] = limit_mm > 0.0;
  if (limit_mm > 0.0) {  // a constant limit: no dynamic adaptation (spec 05b A.2, B.10 FSetPE)
    e.config["FollowingError.MaxValue"] = limit_mm;
    e.config["FollowingError.MinValue"] = limit_mm;
  }
}

// The JOINT `INTDEVICE` declaration line (spec 05b A.1.1): "<name> JOINT TCamp NAxis Buffer" then ICont IntL
// IAZero IoutA for X, Y, Z and IOut1..IOut4, 21 tokens on one line; "X.X" (IntL: "X") marks an unused
// resource. `axis` (X, Y, Z) says which axis of the device this TO is: it needs its counter and DAC (A.1
// "minimum resources") and, for homing, the enable input (all modes) and the zero-pulse input (mode 1).
struct JointDeclaration {
  std::int64_t TCamp = 0;
  bool has_enable_input = false;  // IAZero
  bool has_zero_input = false;    // IntL
};

bool is_address(const std::string& t) {  // "<n>.<m>"
  const auto dot = t.find('.');
  const auto digits = [](std::string_view s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
  };
  return dot != std::string::npos && digits(std::string_view(t).substr(0, dot)) &&
         digits(std::string_view(t).substr(dot + 1));
}

std::optional<JointDeclaration> read_intdevice(const std::string& line, const std::string& axis,
                                               const std::string& path, const std::string& axis_path,
                                               Problems& problems) {
  std::istringstream in(line);
  std::vector<std::string> t;
  for (std::string token; in >> token;)
    t.push_back(token);
  if (t.size() != 21 || t[1] != "JOINT") {
    problems.add(path,
                 std::to_string(t.size()) +
                     " tokens: expected 21 on one line, '<name> JOINT TCamp NAxis Buffer', ICont IntL "
                     "IAZero IoutA of X, Y, Z, IOut1 ... IOut4 (X.X / X for an unused one; spec 05b A.1.1)");
    return std::nullopt;
  }
  const std::size_t before = problems.size();
  const auto number = [&](std::size_t i, const char* field, std::int64_t lo,
                          std::int64_t hi) -> std::int64_t {
    std::int64_t v = 0;
    const bool digits = !t[i].empty() && t[i].find_first_not_of("0123456789") == std::string::npos;
    if (digits && t[i].size() < 7) v = std::stoll(t[i]);
    if (!digits || t[i].size() >= 7 || v < lo || v > hi) {
      problems.add(path, std::string(field) + " '" + t[i] + "' out of range " + std::to_string(lo) + ".." +
                             std::to_string(hi));
    }
    return v;
  };
  JointDeclaration d;
  d.TCamp = number(2, "TCamp", 1, 255);
  const std::int64_t axes = number(3, "NAxis", 2, 3);
  (void)number(4, "Buffer", 3, 30000);
  static constexpr const char* kAxes = "XYZ";
  for (std::size_t a = 0; a < 3; ++a) {
    const std::size_t f = 5 + 4 * a;
    const std::string name(1, kAxes[a]);
    for (std::size_t k : {f, f + 2, f + 3}) {
      if (t[k] != "X.X" && !is_address(t[k])) {
        problems.add(path, "'" + t[k] + "' of axis " + name + " is no address (<module>.<channel>, or X.X)");
      }
    }
    if (t[f + 1] != "X" && t[f + 1].find_first_not_of("0123456789") != std::string::npos) {
      problems.add(path, "IntL" + name + " '" + t[f + 1] + "' is no input number (or X)");
    }
  }
  for (std::size_t k = 17; k < 21; ++k) {
    if (!is_address(t[k]))
      problems.add(path, "IOut" + std::to_string(k - 16) + " '" + t[k] + "' is no address");
  }
  const auto index = std::string_view(kAxes).find(axis);
  if (axis.size() != 1 || index == std::string_view::npos) {
    problems.add(axis_path, "'" + axis + "' is not an axis of the device (X, Y or Z)");
  } else if (static_cast<std::int64_t>(index) >= axes && problems.size() == before) {
    problems.add(axis_path, "axis " + axis + " is beyond NAxis " + std::to_string(axes));
  } else if (problems.size() == before) {
    const std::size_t f = 5 + 4 * index;
    if (t[f] == "X.X" || t[f + 3] == "X.X") {
      problems.add(path, "axis " + axis + " needs its counter (ICont" + axis + ") and its DAC (IoutA" + axis +
                             "): at least one bidirectional counter and one 16-bit DAC (spec 05b A.1)");
    }
    d.has_zero_input = t[f + 1] != "X";
    d.has_enable_input = t[f + 2] != "X.X";
  }
  if (problems.size() != before) return std::nullopt;
  return d;
}

// JOINT homing (spec 05b A.4) as MC_Home's configuration (C.4, decision A23). PRESET is MC_Home Mode 5 for
// prsmode 0/1 (active homing to Homing.HomePosition = prspos with offset 0: the axis returns onto the mark,
// as JOINT positions to prspos) and Mode 10 for prsmode 2 (passive, the mark := HomePosition). The enable
// input (IAZero) is the TO's homing input (the machine's reference cam), high while on the cam.
//   prsmode 0: the input's falling edge in the homing direction = active homing via digital input, the mark
//              "leaving the input" (positive: SideInput TRUE, negative: FALSE; spec 02 §5.4);
//   prsmode 1: the first zero mark after leaving the cam = active homing with cam + zero mark;
//   prsmode 2: the rising edge = passive homing via digital input, the mark "entering" while moving in
//   prsdir.
// prsvel / sprsvel: ApproachVelocity / ReferencingVelocity; prsdir: the approach and homing direction.
void put_joint_homing(std::int64_t prsmode, bool negative, double prsvel, double sprsvel, double prspos,
                      LegacyExpansion& e) {
  e.config["Homing.HomePosition"] = prspos;
  e.config["Homing.ApproachDirection"] = negative;
  if (prsvel > 0.0) e.config["Homing.ApproachVelocity"] = prsvel;
  if (sprsvel > 0.0) e.config["Homing.ReferencingVelocity"] = sprsvel;
  if (prsmode == 2) {
    e.config["Sensor[1].PassiveHoming.Mode"] = 2;
    e.config["Sensor[1].PassiveHoming.Direction"] = negative ? 1 : 0;
    e.config["Sensor[1].PassiveHoming.SideInput"] = negative;  // entering: positive-FALSE, negative-TRUE
  } else {
    e.config["Sensor[1].ActiveHoming.Mode"] = prsmode == 0 ? 2 : 1;
    e.config["Sensor[1].ActiveHoming.Direction"] = negative ? 1 : 0;
    e.config["Sensor[1].ActiveHoming.SideInput"] = !negative;  // leaving: positive-TRUE, negative-FALSE
    e.config["Sensor[1].ActiveHoming.HomePositionOffset"] = 0.0;
  }
}

// ---- DEVICE JOINT (spec 05b A.2, A.3, A.8; C.1, C.2, C.3, C.5) ----
void expand_joint(ObjectReader& r, double cycle_time_s, LegacyExpansion& e, Problems& problems) {
  const std::size_t before = problems.size();
  std::int64_t tcamp = 0, measure = 0, pulse = 0, unitvel = 1, decpt = 0, maxvel = 0, setvel = 0;
  std::int64_t rampmode = 0, ramptype = 0, taccdec = 0, tacc = 0, tdec = 0, toldly = 0, maxfolterr = 0;
  std::int64_t pgain = 1000, feedfw = 0, integt = 0, derivt = 0, offset = 0;
  std::int64_t prsmode = 0, prsdir = 0, prsvel = 0, sprsvel = 0;
  std::optional<double> maxpos, minpos, tol, prspos;
  // The declaration line gives TCamp (and says which resources the axis has); else the key TCamp.
  std::optional<JointDeclaration> declaration;
  if (const Json* v = r.get("INTDEVICE")) {
    std::string axis = "X";
    if (const Json* a = r.get("axis")) axis = read_string(*a, r.path_of("axis"), problems).value_or("X");
    if (auto line = read_string(*v, r.path_of("INTDEVICE"), problems)) {
      declaration = read_intdevice(*line, axis, r.path_of("INTDEVICE"), r.path_of("axis"), problems);
    }
    if (declaration) tcamp = declaration->TCamp;
    if (r.has("TCamp")) {
      r.get("TCamp");
      problems.add(r.path_of("TCamp"), "given by the INTDEVICE line");
    }
  } else {
    r.integer("TCamp", tcamp, 1, 255, false, true);
    if (r.has("axis")) {
      r.get("axis");
      problems.add(r.path_of("axis"), "names the axis of an INTDEVICE line, which is not given");
    }
  }
  r.integer("measure", measure, 1, 999999, false, true);
  r.integer("pulse", pulse, 1, 999999, false, true);
  r.integer("unitvel", unitvel, 0, 1);
  r.integer("decpt", decpt, 0, 3);
  r.integer("maxvel", maxvel, 1, 999999, false, true);
  r.integer("setvel", setvel, 0, 999999);
  r.integer("rampmode", rampmode, 0, 1);
  r.integer("ramptype", ramptype, 0, 3);
  r.integer("taccdec", taccdec, 0, 999);
  r.integer("tacc", tacc, 0, 999);
  r.integer("tdec", tdec, 0, 999);
  r.optional_real("maxpos", maxpos);
  r.optional_real("minpos", minpos);
  r.optional_real("tol", tol);
  r.integer("toldly", toldly, 0, 999);
  r.integer("maxfolterr", maxfolterr, 0, 2147483648LL);
  r.integer("pgain", pgain, 0, 32767);
  r.integer("feedfw", feedfw, 0, 32767);
  r.integer("integt", integt, 0, 32767);
  r.integer("derivt", derivt, 0, 32767);
  r.integer("offset", offset, -32768, 32767);
  // Homing ("preset", A.4, A.8): modes 0/1/2, direction, fast and slow velocity (Uv), home position (Um).
  r.integer("prsmode", prsmode, 0, 2);
  r.integer("prsdir", prsdir, 0, 1);
  r.integer("prsvel", prsvel, 0, 999999);
  r.integer("sprsvel", sprsvel, 0, 999999);
  r.optional_real("prspos", prspos);
  if (problems.size() != before) return;

  if (std::fabs(static_cast<double>(tcamp) / 1000.0 - cycle_time_s) > 1e-12) {
    problems.add(r.path_of("TCamp"), std::to_string(tcamp) + " ms differs from cycle_time " +
                                         format_number(cycle_time_s) +
                                         " s (the regulator runs in the MC_Servo cycle, spec 05b C.1)");
  }
  const double um_per_pulse = static_cast<double>(measure) / static_cast<double>(pulse);
  if (um_per_pulse < 0.00935 || um_per_pulse > 1.0) {
    problems.add(r.path_of("measure"), "measure/pulse = " + format_number(um_per_pulse) +
                                           " is outside 0.00935 ... 1 Um per pulse (spec 05b A.3)");
  }
  if (setvel > maxvel) {
    problems.add(r.path_of("setvel"), std::to_string(setvel) + " exceeds maxvel " + std::to_string(maxvel));
  }
  if (ramptype != 0) {
    problems.add(r.path_of("ramptype"),
                 std::to_string(ramptype) +
                     ": epicycloidal ramps are not mapped (spec 05b C.3: an extension); "
                     "only 0 (trapezoidal)");
  }
  for (const auto& [key, value] : {std::pair{"maxpos", maxpos}, std::pair{"minpos", minpos}}) {
    if (value && std::fabs(*value) > 999999.0) {
      problems.add(r.path_of(key), format_number(*value) + " is outside -999999 ... 999999");
    }
  }
  if (maxpos.has_value() != minpos.has_value()) {
    problems.add(r.path_of(maxpos ? "minpos" : "maxpos"), "missing: give both software limits or neither");
  } else if (maxpos && *maxpos <= *minpos) {
    problems.add(r.path_of("maxpos"),
                 format_number(*maxpos) + " must be above minpos " + format_number(*minpos));
  }
  // Homing needs the enable input (IAZero) in every mode and the zero-pulse input (IntL) in mode 1 (A.4).
  if (declaration && (r.has("prsmode") || prspos)) {
    if (!declaration->has_enable_input) {
      problems.add(r.path_of("prsmode"), "homing needs the enable input IAZero, X.X in the INTDEVICE line");
    } else if (prsmode == 1 && !declaration->has_zero_input) {
      problems.add(r.path_of("prsmode"), "1 needs the zero-pulse input IntL, X in the INTDEVICE line");
    }
  }
  for (const auto& [key, value] : {std::pair{"prsvel", prsvel}, std::pair{"sprsvel", sprsvel}}) {
    if (value > maxvel) {
      problems.add(r.path_of(key), std::to_string(value) + " exceeds maxvel " + std::to_string(maxvel));
    }
  }
  if (prspos && maxpos && (*prspos > *maxpos || *prspos < *minpos)) {
    problems.add(r.path_of("prspos"), format_number(*prspos) + " is outside minpos ... maxpos (" +
                                          format_number(*minpos) + " ... " + format_number(*maxpos) + ")");
  }
  if (tol && !(*tol > 0.0 && *tol <= 999999.0)) {
    problems.add(r.path_of("tol"), format_number(*tol) + ": the tolerance window must be > 0 (≤ 999999)");
  }
  to::JointRegulatorParameters jp;
  jp.pgain = static_cast<std::int32_t>(pgain);
  jp.feedfw = static_cast<std::int32_t>(feedfw);
  jp.integt = static_cast<std::int32_t>(integt);
  jp.derivt = static_cast<std::int32_t>(derivt);
  jp.offset = static_cast<std::int32_t>(offset);
  jp.TCamp = static_cast<double>(tcamp) / 1000.0;
  // Um = mm (the TO's length unit); Uv = Um·10^decpt per s (unitvel 1) or per min (unitvel 0).
  const double uv = std::pow(10.0, static_cast<double>(decpt)) / (unitvel == 1 ? 1.0 : 60.0);
  jp.maxvel = static_cast<double>(maxvel) * uv;
  const to::LegacyRegulator regulator = to::from_joint(jp, cycle_time_s);
  if (!regulator.problem.empty()) problems.add(r.path(), regulator.problem);
  if (problems.size() != before) return;

  // One encoder "revolution" = `pulse` pulses = `measure` Um: posit = encoder·measure/pulse exactly.
  put_axis(static_cast<double>(pulse), static_cast<double>(measure), jp.maxvel, 16, e);
  put_regulator(regulator, e);
  // Ramp times from 0 to maxvel (A.3): a = maxvel/(t/100); 0 keeps the TO's default (C.3).
  const auto ramp = [&](std::int64_t t) {
    return t > 0 ? jp.maxvel / (static_cast<double>(t) / 100.0) : 0.0;
  };
  const double acceleration = ramp(rampmode == 0 ? taccdec : tacc);
  const double deceleration = ramp(rampmode == 0 ? taccdec : tdec);
  put_dynamics(static_cast<double>(setvel) * uv, acceleration, deceleration, e);
  if (maxpos) {
    e.config["PositionLimits_SW.Active"] = true;
    e.config["PositionLimits_SW.MaxPosition"] = *maxpos;
    e.config["PositionLimits_SW.MinPosition"] = *minpos;
  }
  if (tol) e.config["PositioningMonitoring.Window"] = *tol;
  if (r.has("toldly")) e.config["PositioningMonitoring.MinDwellTime"] = static_cast<double>(toldly) / 100.0;
  put_following_error(static_cast<double>(maxfolterr) * um_per_pulse, e);
  const bool homing = r.has("prsmode") || r.has("prsdir") || r.has("prsvel") || r.has("sprsvel") || prspos;
  if (homing)
    put_joint_homing(prsmode, prsdir == 1, static_cast<double>(prsvel) * uv,
                     static_cast<double>(sprsvel) * uv, prspos.value_or(0.0), e);
}

// ---- SAIA PCD4.H3 (spec 05b B.4, B.7.1, B.8, B.9; C.1, C.2) ----

// The lead (whole mm, 1 ... 1000) over which `counts_per_mm` makes a whole number of counts divisible by 4
// (a ×4 quadrature encoder of whole lines; "whole" within 1 ppm, as k is often written rounded: 1.33333); 0
// if there is none.
double lead_for(double counts_per_mm) {
  for (int lead = 1; lead <= 1000; ++lead) {
    const double counts = counts_per_mm * lead;
    const double whole = std::round(counts);
    if (whole >= 4.0 && std::fabs(counts - whole) < 1e-6 * whole && std::fmod(whole, 4.0) == 0.0) {
      return lead;
    }
  }
  return 0.0;
}

void expand_h3(ObjectReader& r, double cycle_time_s, LegacyExpansion& e, Problems& problems) {
  const std::size_t before = problems.size();
  double unit_mm = 0.0, velocity_at_10v = 0.0, mcfac = 0.0;
  std::int64_t kprop = 0, kint = 0, kder = 0, intl = 0, sampi = 0, poser = 0, mcw = 0x41B, veloc = 0,
               accel = 0;
  r.real("unit_mm", unit_mm, kPositive, true);
  r.real("velocity_at_10V", velocity_at_10v, kPositive, true);
  r.real("MCFac", mcfac, Range{0.0, 9.223371e18, true}, true);
  // B.7.1 / B.12: a control value above 32767 or SampI above 255 is a command error of FLdRP.
  r.integer("KProp", kprop, 0, 32767, false, true);
  r.integer("KInt", kint, 0, 32767);
  r.integer("KDer", kder, 0, 32767);
  r.integer("IntL", intl, 0, 32767);
  r.integer("SampI", sampi, 0, 255);
  r.integer("PosEr", poser, 0, 32767);
  r.integer("MCW", mcw, 0, 0xFFFFFFFFLL, true);
  // FLdVA / FLdAA take absolute values only: a negative one is a command error (B.10, B.12).
  r.integer("Veloc", veloc, 0, 1073741823);
  r.integer("Accel", accel, 0, 1073741824);
  if (problems.size() != before) return;

  // B.9: the low byte is the position-error reaction (1AH flag + motor off, 1BH flag only), exactly one of
  // the stop bits 8/9/10.
  const auto reaction = mcw & 0xFF;
  const auto stop_bits = ((mcw >> 8) & 1) + ((mcw >> 9) & 1) + ((mcw >> 10) & 1);
  if (reaction != 0x1A && reaction != 0x1B) {
    problems.add(
        r.path_of("MCW"), "low byte 16#" + [&] {
          char b[8];
          std::snprintf(b, sizeof b, "%02X", static_cast<unsigned>(reaction));
          return std::string(b);
        }() + " is not a position-error reaction (16#1A flag and motor off, 16#1B flag only; spec 05b B.9)");
  }
  if (stop_bits != 1) {
    problems.add(r.path_of("MCW"), "bits 8, 9, 10 (stop type): exactly one must be set, " +
                                       std::to_string(stop_bits) + " are (spec 05b B.9)");
  }
  const double counts_per_mm = mcfac / unit_mm;
  const double lead = lead_for(counts_per_mm);
  if (lead == 0.0) {
    problems.add(r.path_of("MCFac"), format_number(mcfac) + " counts per " + format_number(unit_mm) +
                                         " mm is no whole number of ×4 counts over 1 ... 1000 mm");
  }
  const double v10_mm_s = velocity_at_10v * unit_mm;
  if (static_cast<double>(veloc) > velocity_at_10v) {
    problems.add(r.path_of("Veloc"),
                 std::to_string(veloc) + " exceeds velocity_at_10V " + format_number(velocity_at_10v));
  }
  to::H3RegulatorParameters hp;
  hp.kp = static_cast<double>(kprop);
  hp.ki = static_cast<double>(kint);
  hp.kd = static_cast<double>(kder);
  hp.IntL = static_cast<double>(intl);
  hp.SampI = static_cast<std::uint32_t>(sampi);
  hp.velocity_at_10V = velocity_at_10v * mcfac;  // counts/s: e is in counts (B.4)
  to::LegacyRegulator regulator = to::from_h3(hp, cycle_time_s);
  if (!regulator.problem.empty()) {
    problems.add(r.path_of("KProp"),
                 regulator.problem.starts_with("kp") ? regulator.problem.substr(4) : regulator.problem);
  }
  if (problems.size() != before) return;

  // from_h3's limits are in counts/s; the TO's velocity unit is mm/s.
  regulator.gains.IntegralLimit *= unit_mm / mcfac;
  regulator.gains.OutputLimit *= unit_mm / mcfac;
  put_axis(counts_per_mm * lead, lead, v10_mm_s, 13, e);  // 12 bit + sign (B.6)
  put_regulator(regulator, e);
  // One acceleration for both directions of change (B.3).
  const double a = static_cast<double>(accel) * unit_mm;
  put_dynamics(static_cast<double>(veloc) * unit_mm, a, a, e);
  put_following_error(static_cast<double>(poser) / counts_per_mm, e);
  // MCW 1BH, "flag only" (B.9, C.5: ExcPEr → 522, the regulator stays on): the warning at PosEr as 1 % of a
  // limit 100 × PosEr, so 521 (remove enable) is only a far backstop; 1AH keeps 522 at 90 % and 521 at PosEr.
  if (reaction == 0x1B && poser > 0) {
    const double limit = 100.0 * static_cast<double>(poser) / counts_per_mm;
    e.config["FollowingError.MaxValue"] = limit;
    e.config["FollowingError.MinValue"] = limit;
    e.config["FollowingError.WarningLevel"] = 1.0;
  }
}

void merge_into(Json& target, const Json& patch) {
  for (auto it = patch.begin(); it != patch.end(); ++it) {
    if (it.value().is_object() && target.contains(it.key()) && target[it.key()].is_object()) {
      merge_into(target[it.key()], it.value());
    } else {
      target[it.key()] = it.value();
    }
  }
}

}  // namespace

std::optional<LegacyExpansion> expand_legacy(const Json& legacy, std::string_view path, double cycle_time_s,
                                             Problems& problems) {
  ObjectReader r(legacy, std::string(path), problems);
  if (!r.valid()) return std::nullopt;
  const std::size_t before = problems.size();
  LegacyExpansion e;
  std::optional<std::size_t> system;
  if (const Json* v = r.get("system", true))
    system = read_choice(*v, r.path_of("system"), {"JOINT", "H3"}, problems);
  if (!system) return std::nullopt;  // its keys cannot be checked against an unknown system
  if (*system == 0) expand_joint(r, cycle_time_s, e, problems);
  if (*system == 1) expand_h3(r, cycle_time_s, e, problems);
  r.finish();
  if (problems.size() != before) return std::nullopt;
  return e;
}

std::optional<Json> with_legacy_expanded(const Json& entry, std::string_view path, double cycle_time_s,
                                         Problems& problems) {
  if (!entry.is_object() || !entry.contains("legacy")) return entry;
  const Json* type = entry.contains("type") ? &entry["type"] : nullptr;
  if (type == nullptr || (*type != "TO_PositioningAxis" && *type != "TO_SynchronousAxis")) {
    problems.add(join_path(path, "legacy"),
                 "only a TO_PositioningAxis or TO_SynchronousAxis takes a legacy "
                 "parameter set (a JOINT or H3 axis is a positioning axis)");
    return std::nullopt;
  }
  const auto e = expand_legacy(entry["legacy"], join_path(path, "legacy"), cycle_time_s, problems);
  if (!e) return std::nullopt;
  Json out = entry;
  out.erase("legacy");
  Json config = e->config;
  if (entry.contains("config")) merge_into(config, entry["config"]);  // the file's own keys win
  out["config"] = config;
  Json drive = e->drive;
  if (entry.contains("drive")) merge_into(drive, entry["drive"]);
  out["drive"] = drive;
  return out;
}

}  // namespace tomc::scenario::detail
