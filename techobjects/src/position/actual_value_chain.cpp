#include "tomc/techobjects/position/actual_value_chain.hpp"

#include <bit>
#include <cmath>
#include <limits>

#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

constexpr std::uint32_t kMaxStepsPerRevolution = 8388608;       // seed 004 §10.3 Sensor.Parameter
constexpr std::uint32_t kMaxDeterminableRevolutions = 8388608;  // seed 004 §10.3 Sensor.Parameter
constexpr std::uint32_t kMaxFineResolution = 31;
constexpr double kMinLength = 1.0E-12;  // LeadScrew / Resolution range of the manual
constexpr double kMaxLength = 1.0E12;
constexpr std::uint64_t kXist2Span = std::uint64_t{1} << 32;

bool positive_finite(double v) noexcept {
  return std::isfinite(v) && v > 0.0;
}
bool in_length_range(double v) noexcept {
  return std::isfinite(v) && v >= kMinLength && v <= kMaxLength;
}

// floor(a / b) for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

// int64 arithmetic that wraps instead of overflowing (no UB on garbage retained values).
std::int64_t wrapping_add(std::int64_t a, std::int64_t b) noexcept {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(b));
}
std::int64_t wrapping_mul(std::int64_t a, std::int64_t b) noexcept {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b));
}

// Load travel per load revolution: LeadScrew (linear axis) or 360° (rotary axis).
double units_per_load_revolution(const AxisMechanics& axis) noexcept {
  return axis.MotionType == AxisMotionType::kLinear ? axis.Mechanics.LeadScrew
                                                    : axis.RotaryUnitsPerRevolution;
}

std::uint64_t measuring_range_of(const EncoderMechanics& e) noexcept {
  if (e.Type == EncoderType::kIncremental || e.System != EncoderSystem::kRotary) return 0;
  return tg::absolute_range_counts(e.Parameter.StepsPerRevolution,
                                   static_cast<std::uint8_t>(e.Parameter.FineResolutionXist2),
                                   e.Parameter.DeterminableRevolutions);
}

// String literals only: the chain keeps the pointers (decision M5).
constexpr ConfigProblem problem(const char* path, const char* message) noexcept {
  return ConfigProblem{path, message};
}

}  // namespace

// ---- validation ----

std::optional<ConfigProblem> validate(const AxisMechanics& axis) noexcept {
  if (axis.MotionType != AxisMotionType::kLinear && axis.MotionType != AxisMotionType::kRotary)
    return problem("Properties.MotionType", "must be 0 (linear) or 1 (rotary)");
  if (axis.LoadGear.Numerator == 0)
    return problem("LoadGear.Numerator", "load gear motor revolutions must be 1 ... 4294967295");
  if (axis.LoadGear.Denominator == 0)
    return problem("LoadGear.Denominator", "load gear load revolutions must be 1 ... 4294967295");
  if (axis.MotionType == AxisMotionType::kLinear && !in_length_range(axis.Mechanics.LeadScrew))
    return problem("Mechanics.LeadScrew", "leadscrew pitch must be > 0 (1.0E-12 ... 1.0E12)");
  if (axis.Modulo.Enable) {
    if (!std::isfinite(axis.Modulo.StartValue))
      return problem("Modulo.StartValue", "modulo start value must be finite");
    if (!positive_finite(axis.Modulo.Length)) return problem("Modulo.Length", "modulo length must be > 0");
  }
  if (!positive_finite(axis.Actor.DriveParameter.ReferenceSpeed))
    return problem("Actor.DriveParameter.ReferenceSpeed", "reference speed must be > 0");
  return std::nullopt;
}

// Encoder paths start with "Sensor."; the caller inserts the encoder index ("Sensor[2].") when reporting.
std::optional<ConfigProblem> validate(const AxisMechanics& axis, const EncoderMechanics& e) noexcept {
  if (auto p = validate(axis)) return p;
  const auto& par = e.Parameter;
  const auto type = static_cast<std::int32_t>(e.Type);
  if (type < 0 || type > 2)
    return problem("Sensor.Type", "must be 0 (incremental), 1 (absolute) or 2 (cyclic absolute)");
  if (e.System != EncoderSystem::kLinear && e.System != EncoderSystem::kRotary)
    return problem("Sensor.System", "must be 0 (linear) or 1 (rotary)");
  const auto mounting = static_cast<std::int32_t>(e.MountingMode);
  if (mounting < 0 || mounting > 2)
    return problem("Sensor.MountingMode", "must be 0 (motor shaft), 1 (load side) or 2 (external)");
  const bool linear_system = e.System == EncoderSystem::kLinear;
  // spec 01 §5.2: a linear measuring system exists only on linear axes (load side, or the linear motor).
  if (linear_system && axis.MotionType == AxisMotionType::kRotary)
    return problem("Sensor.System", "a linear measuring system needs a linear axis");
  if (linear_system && e.MountingMode == EncoderMounting::kExternalMeasuringSystem)
    return problem("Sensor.MountingMode", "an external measuring system is a rotary measuring system");
  if (linear_system) {
    if (!in_length_range(par.Resolution))
      return problem("Sensor.Parameter.Resolution", "increment distance must be > 0 (1.0E-12 ... 1.0E12)");
  } else {
    if (par.StepsPerRevolution == 0 || par.StepsPerRevolution > kMaxStepsPerRevolution)
      return problem("Sensor.Parameter.StepsPerRevolution", "must be 1 ... 8388608");
    if (e.MeasuringGear.Numerator == 0)
      return problem("Sensor.MeasuringGear.Numerator", "measuring gear numerator must be 1 ... 4294967295");
    if (e.MeasuringGear.Denominator == 0)
      return problem("Sensor.MeasuringGear.Denominator",
                     "measuring gear encoder revolutions must be 1 ... 4294967295");
    if (e.MountingMode == EncoderMounting::kExternalMeasuringSystem &&
        !positive_finite(par.DistancePerRevolution))
      return problem("Sensor.Parameter.DistancePerRevolution",
                     "travel per measuring-wheel revolution must be > 0");
  }
  if (par.FineResolutionXist1 > kMaxFineResolution)
    return problem("Sensor.Parameter.FineResolutionXist1", "must be 0 ... 31");
  if (par.BehaviorGx_XIST1 != 0 && par.BehaviorGx_XIST1 != 1)
    return problem("Sensor.Parameter.BehaviorGx_XIST1", "must be 0 or 1");
  if (par.BehaviorGx_XIST1 == 0 && linear_system)
    return problem("Sensor.Parameter.BehaviorGx_XIST1",
                   "0 (width from the encoder parameters) needs a rotary measuring system");
  if (e.Type != EncoderType::kIncremental) {
    if (par.FineResolutionXist2 > kMaxFineResolution)
      return problem("Sensor.Parameter.FineResolutionXist2", "must be 0 ... 31");
    if (linear_system) {
      if (e.Type == EncoderType::kCyclicAbsolute)
        return problem("Sensor.Type", "cyclic absolute needs a rotary measuring system (measuring range)");
    } else {
      if (par.DeterminableRevolutions == 0 || par.DeterminableRevolutions > kMaxDeterminableRevolutions)
        return problem("Sensor.Parameter.DeterminableRevolutions",
                       "an absolute encoder needs 1 ... 8388608 determinable revolutions");
      if (measuring_range_of(e) > kXist2Span)
        return problem(
            "Sensor.Parameter.FineResolutionXist2",
            "StepsPerRevolution * 2^FineResolutionXist2 * DeterminableRevolutions exceeds Gx_XIST2");
    }
  }
  const auto vmode = static_cast<std::int32_t>(e.VelocityMode);
  if (vmode < 0 || vmode > 1) return problem("Sensor.ActualVelocityMode", "must be 0 or 1");
  if (e.VelocityMode == ActualVelocityMode::kProfidriveNist) {
    if (e.Nist != NistSource::kDriveTelegram && e.Nist != NistSource::kEncoderTelegram83)
      return problem("Sensor.ActualVelocityMode", "unknown NIST_B source");
    if (e.Nist == NistSource::kEncoderTelegram83) {
      if (linear_system && !positive_finite(par.ReferenceVelocity))
        return problem("Sensor.Parameter.ReferenceVelocity", "reference velocity must be > 0");
      if (!linear_system && !positive_finite(par.ReferenceSpeed))
        return problem("Sensor.Parameter.ReferenceSpeed", "reference speed must be > 0");
    }
  }
  return std::nullopt;
}

// ---- encoder scaling ----

std::uint8_t xist1_width_bits(const EncoderMechanics& e) noexcept {
  const auto& par = e.Parameter;
  if (par.BehaviorGx_XIST1 != 0 || e.System != EncoderSystem::kRotary) return 32;
  if (par.StepsPerRevolution == 0 || par.FineResolutionXist1 > kMaxFineResolution) return 32;
  // seed 004 §6.2.4.4 L2270–L2276: W from the encoder parameterisation; see the header for the derivation.
  const std::uint64_t per_rev = std::uint64_t{par.StepsPerRevolution} << par.FineResolutionXist1;  // <= 2^54
  const std::uint64_t revs = par.DeterminableRevolutions > 1 ? par.DeterminableRevolutions : 1;
  if (per_rev > kXist2Span / revs) return 32;
  const std::uint64_t total = per_rev * revs;  // <= 2^32
  const int bits = std::bit_width(total - 1);  // ceil(log2(total)) for total >= 1
  return static_cast<std::uint8_t>(bits < 1 ? 1 : (bits > 32 ? 32 : bits));
}

double units_per_xist1_count(const AxisMechanics& axis, const EncoderMechanics& e) noexcept {
  if (validate(axis, e)) return 0.0;
  const auto& par = e.Parameter;
  const double fine = std::ldexp(1.0, static_cast<int>(par.FineResolutionXist1));
  double units = 0.0;
  if (e.System == EncoderSystem::kLinear) {
    units = par.Resolution / fine;  // spec 01 §5.8 linear measuring system
  } else {
    const double counts_per_rev =
        tg::counts_per_revolution(par.StepsPerRevolution, static_cast<std::uint8_t>(par.FineResolutionXist1));
    const double measuring_gear =
        static_cast<double>(e.MeasuringGear.Numerator) / static_cast<double>(e.MeasuringGear.Denominator);
    const double load_gear =
        static_cast<double>(axis.LoadGear.Denominator) / static_cast<double>(axis.LoadGear.Numerator);
    switch (e.MountingMode) {
      case EncoderMounting::kMotorShaft:  // r_load = r_enc * MG * Den/Num (spec 01 §5.8)
        units = measuring_gear * load_gear * units_per_load_revolution(axis) / counts_per_rev;
        break;
      case EncoderMounting::kLoadSide:
        units = measuring_gear * units_per_load_revolution(axis) / counts_per_rev;
        break;
      case EncoderMounting::kExternalMeasuringSystem:
        units = measuring_gear * par.DistancePerRevolution / counts_per_rev;
        break;
    }
  }
  return e.InverseDirection ? -units : units;  // spec 01 §5.4
}

// ---- modulo ----

ModuloPosition modulo_wrap(double position, double start, double length) noexcept {
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(position) || !std::isfinite(start))
    return ModuloPosition{position, 0};
  const double k = std::floor((position - start) / length);
  constexpr double kLimit = 4.0e18;  // keeps the int64 conversion defined
  const double kc = k > kLimit ? kLimit : (k < -kLimit ? -kLimit : k);
  auto cycle = static_cast<std::int64_t>(kc);
  double wrapped = position - kc * length;
  // Rounding can leave the result a hair outside the half-open range.
  if (wrapped >= start + length) {
    wrapped -= length;
    ++cycle;
  }
  if (wrapped < start) {
    wrapped += length;
    --cycle;
    if (wrapped >= start + length) wrapped = start;  // -tiny + length rounded up to length
  }
  return ModuloPosition{wrapped, cycle};
}

double modulo_shortest_distance(double from, double to, double start, double length) noexcept {
  if (!(length > 0.0) || !std::isfinite(length)) return to - from;
  const double a = modulo_wrap(from, start, length).position;
  const double b = modulo_wrap(to, start, length).position;
  double d = b - a;  // (-length, length), not crossing the range boundary
  const double half = 0.5 * length;
  if (d > half) {
    d -= length;
  } else if (d < -half) {
    d += length;
  }
  return d;  // |d| == half keeps the way without boundary crossing (A18)
}

std::int32_t modulo_cycle_change(double old_position, double new_position, double start,
                                 double length) noexcept {
  if (!(length > 0.0) || !std::isfinite(length)) return 0;
  const double a = modulo_wrap(old_position, start, length).position;
  const double b = modulo_wrap(new_position, start, length).position;
  const double d = b - a;
  if (d > 0.5 * length) return -1;  // reached backwards across the boundary (spec 01 §2.4.1)
  if (d < -0.5 * length) return 1;  // reached forwards across the boundary
  return 0;
}

// ---- setpoint scaling ----

SetpointScaling::SetpointScaling(const AxisMechanics& axis, const EncoderMechanics& encoder1) noexcept {
  if (!validate(axis)) {
    motor_rev_per_unit_ = static_cast<double>(axis.LoadGear.Numerator) /
                          (static_cast<double>(axis.LoadGear.Denominator) * units_per_load_revolution(axis));
    direction_ = axis.Actor.InverseDirection ? -1.0 : 1.0;
    reference_speed_ = axis.Actor.DriveParameter.ReferenceSpeed;
  }
  const double upc = units_per_xist1_count(axis, encoder1);
  counts_per_unit_ = upc != 0.0 ? 1.0 / upc : 0.0;
}

std::int32_t SetpointScaling::nsoll_b(double load_velocity_value) const noexcept {
  return tg::speed_to_n4(motor_speed(load_velocity_value), reference_speed_);
}

double SetpointScaling::load_velocity_from_nist_b(std::int32_t nist_b) const noexcept {
  return load_velocity(tg::n4_to_speed(nist_b, reference_speed_));
}

std::int32_t SetpointScaling::xerr(double position_error) const noexcept {
  return tg::xerr_from_counts(position_error_to_counts(position_error));
}

// ---- actual-value chain ----

ActualValueChain::ActualValueChain(const AxisMechanics& axis, const EncoderMechanics& encoder,
                                   double servo_cycle_s) noexcept
    : modulo_start_(axis.Modulo.StartValue),
      modulo_length_(axis.Modulo.Length),
      servo_cycle_s_(servo_cycle_s),
      steps_per_revolution_(encoder.Parameter.StepsPerRevolution),
      fine_xist1_(static_cast<std::uint8_t>(encoder.Parameter.FineResolutionXist1)),
      fine_xist2_(static_cast<std::uint8_t>(encoder.Parameter.FineResolutionXist2)),
      type_(static_cast<std::uint8_t>(encoder.Type)),
      modulo_enable_(axis.Modulo.Enable),
      nist_velocity_(encoder.VelocityMode == ActualVelocityMode::kProfidriveNist),
      nist_from_drive_(encoder.Nist == NistSource::kDriveTelegram),
      rotary_(encoder.System == EncoderSystem::kRotary),
      inverse_(encoder.InverseDirection) {
  auto problem = validate(axis, encoder);
  if (!problem && !positive_finite(servo_cycle_s))
    problem = ConfigProblem{"ServoCycle", "servo cycle time must be > 0"};
  if (problem) {
    config_.problem = Problem{problem->path.data(), problem->message.data()};  // static strings (validate())
    has_problem_ = true;
  } else {
    scaling_ = SetpointScaling(axis, encoder);
    units_per_count_ = units_per_xist1_count(axis, encoder);
    width_ = xist1_width_bits(encoder);
    config_.values = Values{encoder.System == EncoderSystem::kRotary ? encoder.Parameter.ReferenceSpeed
                                                                     : encoder.Parameter.ReferenceVelocity,
                            measuring_range_of(encoder)};
  }
  power_up(nullptr);
}

std::int64_t ActualValueChain::xist2_to_xist1_counts(std::int64_t c) const noexcept {
  const int shift = static_cast<int>(fine_xist1_) - static_cast<int>(fine_xist2_);
  if (shift >= 0) return wrapping_mul(c, std::int64_t{1} << shift);
  // XIST1 is coarser: round to the nearest XIST1 count (arithmetic shift = floor in C++20).
  return wrapping_add(c, std::int64_t{1} << (-shift - 1)) >> (-shift);
}

std::int64_t ActualValueChain::xist1_to_xist2_counts(std::int64_t c) const noexcept {
  const int shift = static_cast<int>(fine_xist1_) - static_cast<int>(fine_xist2_);
  if (shift <= 0) return wrapping_mul(c, std::int64_t{1} << (-shift));
  return wrapping_add(c, std::int64_t{1} << (shift - 1)) >> shift;
}

std::int64_t ActualValueChain::cycle_index(double continuous) const noexcept {
  if (!modulo_enable_) return 0;
  return modulo_wrap(continuous, modulo_start_, modulo_length_).cycle;
}

void ActualValueChain::add_cycles(std::int64_t delta) noexcept {
  // DINT counter: wraps like the PLC's (two's complement).
  modulo_cycle_ = static_cast<std::int32_t>(static_cast<std::uint32_t>(modulo_cycle_) +
                                            static_cast<std::uint32_t>(static_cast<std::uint64_t>(delta)));
}

void ActualValueChain::power_up(const RetainedSensorState* retained) noexcept {
  tracker_ = tg::IncrementalCount(width_);
  offset_ = 0.0;
  velocity_ = 0.0;
  modulo_cycle_ = 0;
  cycle_index_ = 0;
  has_sample_ = false;
  anchored_ = false;
  derive_cycle_on_anchor_ = true;
  restored_ = false;
  restored_xist2_counts_ = 0;
  if (retained != nullptr && absolute_type()) {
    if (std::isfinite(retained->AbsEncoderOffset)) offset_ = retained->AbsEncoderOffset;
    if (type() == EncoderType::kCyclicAbsolute && range() != 0) {
      restored_ = true;
      restored_xist2_counts_ =
          wrapping_add(wrapping_mul(retained->MeasuringRangeCount, static_cast<std::int64_t>(range())),
                       static_cast<std::int64_t>(retained->LastAbsoluteValue % range()));
    }
  }
}

void ActualValueChain::restart() noexcept {
  if (!absolute_type()) {
    power_up(nullptr);  // spec 01 §2.4.1: incremental, counter 0; position 0 until homed again
    return;
  }
  // Absolute types: offset and counter are kept; the next Gx_XIST2 re-anchors the position, a cyclic absolute
  // encoder continuing from the current measuring range.
  if (type() == EncoderType::kCyclicAbsolute && anchored_) {
    restored_ = true;
    restored_xist2_counts_ = xist1_to_xist2_counts(tracker_.counts());
  }
  anchored_ = false;
  derive_cycle_on_anchor_ = false;
  has_sample_ = false;
  velocity_ = 0.0;
  tracker_.restart();
}

void ActualValueChain::update(const EncoderSample& sample) noexcept {
  if (has_problem_) return;
  const bool first_sample = !has_sample_;
  const std::int64_t previous_counts = tracker_.counts();
  tracker_.update(sample.xist1);  // first sample: reference only
  has_sample_ = true;

  bool anchored_now = false;
  if (absolute_type() && sample.xist2_absolute) {
    std::int64_t value = static_cast<std::int64_t>(*sample.xist2_absolute);
    if (config_.values.range != 0) value %= static_cast<std::int64_t>(config_.values.range);
    std::int64_t absolute = value;
    if (type() == EncoderType::kCyclicAbsolute && config_.values.range != 0) {
      // Measuring range nearest to the known position: overflow/underflow counting (spec 01 §3.7).
      std::int64_t k = 0;
      if (anchored_ || restored_) {
        const std::int64_t predicted =
            anchored_ ? xist1_to_xist2_counts(tracker_.counts()) : restored_xist2_counts_;
        const auto r = static_cast<std::int64_t>(config_.values.range);
        k = floor_div(wrapping_add(predicted - value, r / 2), r);
      }
      absolute = wrapping_add(wrapping_mul(k, static_cast<std::int64_t>(config_.values.range)), value);
    }
    tracker_.set_counts(xist2_to_xist1_counts(absolute));
    anchored_now = !anchored_;
    anchored_ = true;
    restored_ = false;
  }

  // Actual velocity (spec 01 §3.9).
  double v = 0.0;
  if (!first_sample && !anchored_now) {
    v = static_cast<double>(tracker_.counts() - previous_counts) * units_per_count_ / servo_cycle_s_;
  }
  if (nist_velocity_ && sample.nist_b) {
    if (nist_from_drive_) {
      v = scaling_.load_velocity_from_nist_b(*sample.nist_b);  // motor speed through the mechanics
    } else if (rotary_) {
      const double rev_per_s = tg::n4_to_speed(*sample.nist_b, config_.values.nist_reference) / 60.0;
      v = rev_per_s * tg::counts_per_revolution(steps_per_revolution_, fine_xist1_) * units_per_count_;
    } else {
      const double lin = tg::n4_to_speed(*sample.nist_b, config_.values.nist_reference);
      v = inverse_ ? -lin : lin;
    }
  }
  velocity_ = v;

  // ActualModuloCycle (spec 01 §2.4, §2.4.1).
  const std::int64_t k = cycle_index(continuous_position());
  if (anchored_now && derive_cycle_on_anchor_) {
    // Absolute encoder power-up: derived from absolute value + offset relative to the modulo length.
    modulo_cycle_ = 0;
    add_cycles(k);
    derive_cycle_on_anchor_ = false;
  } else if (!first_sample || anchored_now) {
    add_cycles(k - cycle_index_);
  }
  cycle_index_ = k;
}

void ActualValueChain::set_position(double value, ModuloCycleRule rule, double home_position) noexcept {
  if (has_problem_ || !std::isfinite(value)) return;
  const double old_position = position();
  offset_ = value - static_cast<double>(tracker_.counts()) * units_per_count_;
  if (modulo_enable_) {
    const double start = modulo_start_;
    const double length = modulo_length_;
    const double new_position = modulo_wrap(value, start, length).position;
    switch (rule) {
      case ModuloCycleRule::kShortestDistance:
        add_cycles(modulo_cycle_change(old_position, new_position, start, length));
        break;
      case ModuloCycleRule::kHomePositionHalf: {
        // The rule applies to the home position ("posizione del punto di riferimento", seed 004 §6.1.4), not
        // to where the axis is when the mark is evaluated; the travel from there counts like a motion (H8).
        const double home = std::isfinite(home_position) ? home_position : value;
        const double home_in_range = modulo_wrap(home, start, length).position;
        modulo_cycle_ = home_in_range <= start + 0.5 * length ? 0 : 1;  // A1: literal "1"
        add_cycles(cycle_index(value) - cycle_index(home));
        break;
      }
      case ModuloCycleRule::kZero:
        modulo_cycle_ = 0;
        break;
    }
    cycle_index_ = cycle_index(continuous_position());
  }
}

void ActualValueChain::shift_offset(double delta) noexcept {
  if (has_problem_ || !std::isfinite(delta) || delta == 0.0) return;
  offset_ += delta;
  if (!modulo_enable_) return;
  const std::int64_t k = cycle_index(continuous_position());
  add_cycles(k - cycle_index_);
  cycle_index_ = k;
}

double ActualValueChain::position() const noexcept {
  const double p = continuous_position();
  if (!modulo_enable_) return p;
  return modulo_wrap(p, modulo_start_, modulo_length_).position;
}

std::int64_t ActualValueChain::measuring_range_count() const noexcept {
  if (type() != EncoderType::kCyclicAbsolute || range() == 0) return 0;
  return floor_div(xist1_to_xist2_counts(tracker_.counts()), static_cast<std::int64_t>(range()));
}

RetainedSensorState ActualValueChain::retained_state() const noexcept {
  RetainedSensorState s{};
  s.AbsEncoderOffset = abs_encoder_offset();
  if (type() == EncoderType::kCyclicAbsolute && range() != 0) {
    if (!anchored_ && restored_) {  // nothing new since the restore: hand the restored values back
      const auto r = static_cast<std::int64_t>(range());
      s.MeasuringRangeCount = floor_div(restored_xist2_counts_, r);
      s.LastAbsoluteValue = static_cast<std::uint32_t>(restored_xist2_counts_ - s.MeasuringRangeCount * r);
      return s;
    }
    const std::int64_t c = xist1_to_xist2_counts(tracker_.counts());
    s.MeasuringRangeCount = measuring_range_count();
    s.LastAbsoluteValue =
        static_cast<std::uint32_t>(c - s.MeasuringRangeCount * static_cast<std::int64_t>(range()));
  }
  return s;
}

}  // namespace tomc::techobjects
