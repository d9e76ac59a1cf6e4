#pragma once
// Actual-value chain and setpoint scaling of the positioning axis and the external encoder (issue 5
// groundwork): encoder counts (Gx_XIST1/Gx_XIST2, NIST_B) -> position and velocity in user units, modulo,
// and the reverse direction (load velocity -> motor speed, position error -> XERR counts).
//
// Spec 01 §2.3–§2.4.1 (units, modulo, modulo cycle counter), §3.6–§3.9 (reference speed, encoder types and
// parameters, BehaviorGx_XIST1, NIST_B), §5.2–§5.8 (mechanics), spec 06 §6 (XIST1/XIST2), §7 (XERR).
// Backlash (spec 01 §5.9) is a separate component (backlash.hpp) that shifts this chain's offset.
//
// Units: positions are in the axis' position unit, which this module takes to be mm (linear) or ° (rotary);
// LeadScrew is in mm/rev (spec 01 §2.3 leadscrew table for mm), Modulo and DistancePerRevolution are in the
// position unit; velocities in position units per second; motor speeds in 1/min. Other position units are a
// constant factor to be applied by the caller.
//
// Real time: every member function is noexcept, allocation-free and runs in bounded time; configuration
// checks use static strings only.
//
// External encoder TO (spec 01 §5.3): it has no mounting mode; its rotary measuring system is evaluated
// through load gear and leadscrew, which is MountingMode 0 with MeasuringGear 1:1 here. A linear EE is
// System = kLinear.

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include "tomc/telegrams/encoder.hpp"

namespace tomc::techobjects {

// ---- configuration (manual names, spec 01 §5.11, seed 004 §10.3) ----

// <TO>.Properties.MotionType
enum class AxisMotionType : std::int32_t { kLinear = 0, kRotary = 1 };
// <TO>.Sensor[n].System
enum class EncoderSystem : std::int32_t { kLinear = 0, kRotary = 1 };
// <TO>.Sensor[n].MountingMode
enum class EncoderMounting : std::int32_t { kMotorShaft = 0, kLoadSide = 1, kExternalMeasuringSystem = 2 };
// <TO>.Sensor[n].Type
enum class EncoderType : std::int32_t { kIncremental = 0, kAbsolute = 1, kCyclicAbsolute = 2 };
// <TO>.Sensor[n].ActualVelocityMode (spec 01 §3.9)
enum class ActualVelocityMode : std::int32_t { kPositionDifference = 0, kProfidriveNist = 1 };
// Which telegram carries the NIST_B used with ActualVelocityMode = 1 (spec 01 §3.9): the drive telegram
// (motor speed, reference Actor.DriveParameter.ReferenceSpeed) or encoder telegram 83 (encoder speed,
// reference Sensor[n].Parameter.ReferenceSpeed / ReferenceVelocity).
enum class NistSource : std::int32_t { kDriveTelegram = 0, kEncoderTelegram83 = 1 };

// LoadGear (Numerator = motor revolutions, Denominator = load revolutions, spec 01 §5.5) and MeasuringGear
// (Numerator = motor/load/measuring-wheel revolutions per MountingMode, Denominator = encoder revolutions,
// spec 01 §5.6, A14). UDINT 1 ... 4294967295.
struct GearRatio {
  std::uint32_t Numerator = 1;
  std::uint32_t Denominator = 1;
};

// <TO>.Sensor[n].Parameter (TO_Struct_SensorParameter)
struct EncoderParameter {
  double Resolution = 0.001;  // linear measuring system: distance between two increments [position unit]
  std::uint32_t StepsPerRevolution = 2048;    // rotary: 1 ... 8388608
  std::uint32_t FineResolutionXist1 = 11;     // 0 ... 31
  std::uint32_t FineResolutionXist2 = 9;      // 0 ... 31
  std::uint32_t DeterminableRevolutions = 0;  // 0 incremental, 1 single-turn, n multi-turn
  double DistancePerRevolution = 10.0;        // external: load travel per measuring-wheel revolution
  std::int32_t BehaviorGx_XIST1 = 1;          // 1 = 32-bit counter, 0 = width from the encoder parameters
  double ReferenceSpeed = 3000.0;             // NIST_B of telegram 83, rotary encoder [1/min]
  double ReferenceVelocity = 1000.0;          // NIST_B of telegram 83, linear encoder [position unit/s]
};

// <TO>.Sensor[n] (mechanics-relevant part)
struct EncoderMechanics {
  EncoderType Type = EncoderType::kIncremental;
  EncoderSystem System = EncoderSystem::kRotary;
  EncoderMounting MountingMode = EncoderMounting::kMotorShaft;
  bool InverseDirection = false;
  GearRatio MeasuringGear{};
  EncoderParameter Parameter{};
  ActualVelocityMode VelocityMode =
      ActualVelocityMode::kPositionDifference;  // <TO>.Sensor[n].ActualVelocityMode
  NistSource Nist = NistSource::kDriveTelegram;
};

struct MechanicsConfig {
  double LeadScrew = 10.0;  // <TO>.Mechanics.LeadScrew [mm/rev], 1.0E-12 ... 1.0E12
};
struct ActorDriveParameter {
  double ReferenceSpeed = 3000.0;  // <TO>.Actor.DriveParameter.ReferenceSpeed [1/min]
};
struct ActorConfig {
  bool InverseDirection = false;  // <TO>.Actor.InverseDirection
  ActorDriveParameter DriveParameter{};
};
struct ModuloConfig {
  bool Enable = false;
  double StartValue = 0.0;
  double Length = 360.0;
};

// Axis side of the chain. Standard (rotary) motor only: a linear motor has neither load gear nor leadscrew
// and is not covered by SetpointScaling yet.
struct AxisMechanics {
  AxisMotionType MotionType = AxisMotionType::kLinear;
  GearRatio LoadGear{};
  MechanicsConfig Mechanics{};
  ActorConfig Actor{};
  ModuloConfig Modulo{};
  // Position units per load revolution of a rotary axis: 360 for °, 2π for rad (axis_units.hpp).
  double RotaryUnitsPerRevolution = 360.0;
};

// First configuration problem: variable path relative to <TO> and an English message (static strings).
struct ConfigProblem {
  std::string_view path;
  std::string_view message;
};

std::optional<ConfigProblem> validate(const AxisMechanics& axis) noexcept;
std::optional<ConfigProblem> validate(const AxisMechanics& axis, const EncoderMechanics& encoder) noexcept;

// Width W of Gx_XIST1 evaluated by the TO (spec 01 §3.7, spec 06 §6.1).
// BehaviorGx_XIST1 = 1: 32. BehaviorGx_XIST1 = 0: "only the data width according to the encoder
// parameterisation of the TO" (seed 004 §6.2.4.4 L2270–L2276, example L11887: 16 bit -> 0 ... 65535).
// [OUR CHOICE] derivation for a rotary measuring system:
//   W = ceil(log2(StepsPerRevolution * 2^FineResolutionXist1 * max(1, DeterminableRevolutions))), 1 ... 32
// i.e. the counter spans one revolution (incremental, single-turn) or the whole multi-turn range, clamped to
// the 32 bits of the telegram field. A linear measuring system has no range to derive W from; validate()
// rejects BehaviorGx_XIST1 = 0 there. Returns 32 for invalid parameters.
std::uint8_t xist1_width_bits(const EncoderMechanics& encoder) noexcept;

// Position units per Gx_XIST1 count, signed: Sensor[n].InverseDirection negates (spec 01 §5.4, §5.8).
//   linear system:         Resolution / 2^FineResolutionXist1
//   rotary, motor shaft:   1/(Steps*2^Fine1) * MG.Num/MG.Den * LG.Den/LG.Num * U
//   rotary, load side:     1/(Steps*2^Fine1) * MG.Num/MG.Den * U
//   rotary, external:      1/(Steps*2^Fine1) * MG.Num/MG.Den * DistancePerRevolution
// with U = LeadScrew (linear axis) or 360° (rotary axis). 0 for an invalid configuration.
double units_per_xist1_count(const AxisMechanics& axis, const EncoderMechanics& encoder) noexcept;

// ---- modulo (spec 01 §2.4, §2.4.1, §11 A18) ----

struct ModuloPosition {
  double position = 0.0;   // in [StartValue, StartValue + Length)
  std::int64_t cycle = 0;  // k = floor((p - StartValue) / Length)
};
// Wraps `position` into [start, start + length). length must be > 0 (otherwise returned unchanged, k = 0).
ModuloPosition modulo_wrap(double position, double start, double length) noexcept;

// Signed distance from `from` to `to` along the shorter way on the modulo circle (MoveAbsolute Direction 3);
// both are wrapped first. Result in [-length/2, +length/2].
// Tie (|distance| exactly length/2), spec 01 §11 A18 [OUR CHOICE]: the way that does NOT cross the range
// boundary StartValue/StartValue+Length, i.e. +length/2 when `to` > `from`, -length/2 otherwise. This agrees
// with the counter rule below (no counter change at the tie).
double modulo_shortest_distance(double from, double to, double start, double length) noexcept;

// Shortest-distance rule for the modulo cycle counter on direct homing / absolute encoder adjustment (spec 01
// §2.4.1): -1, 0 or +1 when moving from `old_position` to `new_position` the shorter way. Tie: 0 (A18).
std::int32_t modulo_cycle_change(double old_position, double new_position, double start,
                                 double length) noexcept;

// How set_position() changes ActualModuloCycle (spec 01 §2.4.1).
enum class ModuloCycleRule : std::uint8_t {
  kShortestDistance,  // direct homing Mode 0/1/11/12, incremental adjustment 13, absolute adjustment 6
  kHomePositionHalf,  // active/passive homing Mode 2/3/5/8/10: 0 if the home position <= Start + Length/2,
                      // else 1 (A1); the travel between home position and `position` is counted as motion
  kZero,              // absolute encoder adjustment Mode 7
};

// ---- setpoint scaling (spec 01 §3.6 [derived], spec 06 §7) ----

class SetpointScaling {
 public:
  SetpointScaling() noexcept = default;
  // `encoder1` is the first encoder of the telegram (the motor encoder with DSC); it gives the XERR format.
  SetpointScaling(const AxisMechanics& axis, const EncoderMechanics& encoder1) noexcept;

  // Motor revolutions per position unit: LG.Num / (LG.Den * U), U = LeadScrew or 360°.
  double motor_revolutions_per_unit() const noexcept { return motor_rev_per_unit_; }

  // Load velocity [unit/s] -> motor speed [1/min], incl. Actor.InverseDirection (spec 01 §3.6, §5.4); and
  // back.
  double motor_speed(double load_velocity) const noexcept {
    return direction_ * load_velocity * motor_rev_per_unit_ * 60.0;
  }
  double load_velocity(double motor_speed_per_min) const noexcept {
    if (motor_rev_per_unit_ == 0.0) return 0.0;
    return direction_ * motor_speed_per_min / (60.0 * motor_rev_per_unit_);
  }
  // NSOLL_B / NIST_B (N4 of Actor.DriveParameter.ReferenceSpeed, saturated = ±200 %).
  std::int32_t nsoll_b(double load_velocity) const noexcept;
  double load_velocity_from_nist_b(std::int32_t nist_b) const noexcept;

  // Encoder-1 Gx_XIST1 counts per position unit (signed with Sensor[1].InverseDirection) and the DSC
  // following error XERR = round(error * counts_per_unit), saturated to int32 (spec 06 §7 [OUR CHOICE]).
  double encoder_counts_per_unit() const noexcept { return counts_per_unit_; }
  double position_error_to_counts(double error) const noexcept { return error * counts_per_unit_; }
  std::int32_t xerr(double position_error) const noexcept;

 private:
  double motor_rev_per_unit_ = 0.0;
  double direction_ = 1.0;
  double reference_speed_ = 0.0;
  double counts_per_unit_ = 0.0;
};

// ---- actual-value chain ----

// One servo cycle of encoder input.
struct EncoderSample {
  std::uint32_t xist1 = 0;                      // Gx_XIST1
  std::optional<std::uint32_t> xist2_absolute;  // Gx_XIST2 when it holds the absolute value (G1_ZSW.13)
  std::optional<std::int32_t> nist_b;           // NIST_B of the drive telegram / telegram 83, if received
};

// Values kept retentively across CPU power-off (spec 01 §3.7): the absolute-value offset
// (<TO>.StatusSensor[n].AbsEncoderOffset) and, for the cyclic absolute encoder, the number of traversed
// measuring ranges plus the last absolute value inside the range (used to tell an encoder zero crossing
// while the CPU was off, below).
struct RetainedSensorState {
  double AbsEncoderOffset = 0.0;
  std::int64_t MeasuringRangeCount = 0;  // cyclic absolute only
  std::uint32_t LastAbsoluteValue = 0;   // Gx_XIST2 format, 0 ... range - 1
};

class ActualValueChain {
 public:
  // Checks validate(axis, encoder) and servo_cycle_s > 0; with a problem the chain stays invalid and
  // update() does nothing. Starts in the power-up state (no retained values).
  ActualValueChain(const AxisMechanics& axis, const EncoderMechanics& encoder, double servo_cycle_s) noexcept;

  std::optional<ConfigProblem> config_problem() const noexcept {
    if (!has_problem_) return std::nullopt;
    return ConfigProblem{config_.problem.path, config_.problem.message};
  }

  // CPU power-up: incremental encoder at 0, ActualModuloCycle 0; absolute encoders wait for Gx_XIST2 and take
  // AbsEncoderOffset (and the cyclic counter) from `retained`.
  void power_up(const RetainedSensorState* retained = nullptr) noexcept;

  // One servo cycle. The first sample after power-up only references Gx_XIST1.
  // Absolute/cyclic absolute: each valid `xist2_absolute` (re-)anchors the position; between anchors Gx_XIST1
  // increments continue it. Cyclic absolute: the measuring range is chosen so that the absolute position is
  // nearest to the position known so far (overflow in either direction while |move| < range/2).
  void update(const EncoderSample& sample) noexcept;

  // Homing / absolute encoder adjustment: the actual position becomes `position` (direct set). Incremental:
  // homing offset; absolute types: new AbsEncoderOffset. kHomePositionHalf decides the counter from
  // `home_position` (the same coordinate as `position`; NaN: `position` itself), H8.
  void set_position(double position, ModuloCycleRule rule = ModuloCycleRule::kShortestDistance,
                    double home_position = std::numeric_limits<double>::quiet_NaN()) noexcept;
  // Backlash compensation (backlash.hpp): the position moves by `delta` without motion of the encoder; the
  // modulo cycle counter follows a crossed range boundary like a motion.
  void shift_offset(double delta) noexcept;

  // MC_Reset(Restart = TRUE), spec 01 §2.4.1: incremental as power-up (position 0, counter 0); absolute
  // encoders keep counter and offset; the next Gx_XIST2 re-anchors the position.
  void restart() noexcept;

  // <TO>.ActualPosition: modulo-wrapped if Modulo.Enable.
  double position() const noexcept;
  // Position without modulo wrap (counts * units_per_count + offset).
  double continuous_position() const noexcept {
    return static_cast<double>(tracker_.counts()) * units_per_count_ + offset_;
  }
  // <TO>.ActualVelocity [unit/s]
  double velocity() const noexcept { return velocity_; }
  // <TO>.ActualModuloCycle (DINT, wraps like the PLC counter); 0 without modulo.
  std::int32_t modulo_cycle() const noexcept { return modulo_cycle_; }

  // Incremental: a sample was received. Absolute types: Gx_XIST2 has anchored the position.
  bool position_valid() const noexcept { return has_sample_ && (!absolute_type() || anchored_); }
  bool absolute_type() const noexcept { return type() != EncoderType::kIncremental; }

  std::int64_t encoder_counts() const noexcept { return tracker_.counts(); }  // continuous, Gx_XIST1 units
  double offset() const noexcept { return offset_; }  // homing offset / AbsEncoderOffset
  double abs_encoder_offset() const noexcept { return absolute_type() ? offset_ : 0.0; }
  std::int64_t measuring_range_count() const noexcept;                // cyclic absolute; 0 otherwise
  std::uint64_t measuring_range() const noexcept { return range(); }  // Gx_XIST2 counts; 0 incremental
  RetainedSensorState retained_state() const noexcept;

  double units_per_count() const noexcept { return units_per_count_; }
  std::uint8_t xist1_width() const noexcept { return width_; }
  const SetpointScaling& scaling() const noexcept { return scaling_; }

 private:
  std::int64_t xist2_to_xist1_counts(std::int64_t xist2_counts) const noexcept;
  std::int64_t xist1_to_xist2_counts(std::int64_t xist1_counts) const noexcept;
  std::int64_t cycle_index(double continuous) const noexcept;
  void add_cycles(std::int64_t delta) noexcept;

  EncoderType type() const noexcept { return static_cast<EncoderType>(type_); }
  // The absolute measuring range in Gx_XIST2 counts (0: incremental, linear, or a configuration problem).
  std::uint64_t range() const noexcept { return has_problem_ ? 0 : config_.values.range; }

  // Of the axis mechanics only the modulo setting is needed after construction (decision M5), of Sensor[n]
  // only what the cycle reads (decision M6: 88 bytes of EncoderMechanics -> 16). The first configuration
  // problem is kept as its two static strings in the storage of two values only update() reads, which a
  // chain with a problem never runs (decision M11). One-byte members last, the flags as bits (M11).
  struct Values {
    double nist_reference;  // NIST_B of telegram 83: Parameter.ReferenceSpeed (rotary) / ReferenceVelocity
    std::uint64_t range;    // absolute measuring range in Gx_XIST2 counts
  };
  struct Problem {
    const char* path;
    const char* message;
  };
  union Config {
    Values values;    // !has_problem_
    Problem problem;  // has_problem_
  };
  SetpointScaling scaling_{};
  Config config_{Values{0.0, 0}};
  double modulo_start_ = 0.0;     // Modulo.StartValue
  double modulo_length_ = 360.0;  // Modulo.Length
  double servo_cycle_s_ = 0.0;
  double units_per_count_ = 0.0;

  // state
  telegrams::IncrementalCount tracker_{};  // continuous position in Gx_XIST1 counts
  double offset_ = 0.0;
  double velocity_ = 0.0;
  std::int64_t cycle_index_ = 0;  // floor((continuous - Start) / Length) at the last update
  std::int64_t restored_xist2_counts_ = 0;
  std::int32_t modulo_cycle_ = 0;

  std::uint32_t steps_per_revolution_ = 0;  // Parameter.StepsPerRevolution
  std::uint8_t fine_xist1_ = 0;             // Parameter.FineResolutionXist1 (0 ... 31)
  std::uint8_t fine_xist2_ = 0;             // Parameter.FineResolutionXist2 (0 ... 31)
  std::uint8_t type_ = 0;                   // EncoderType
  std::uint8_t width_ = 32;
  bool has_sample_ = false;
  bool anchored_ = false;
  bool modulo_enable_ = false;              // Modulo.Enable (a byte: read several times a cycle)
  bool nist_velocity_ : 1 = false;          // VelocityMode = kProfidriveNist
  bool nist_from_drive_ : 1 = true;         // Nist = kDriveTelegram
  bool rotary_ : 1 = true;                  // System = kRotary
  bool inverse_ : 1 = false;                // InverseDirection
  bool derive_cycle_on_anchor_ : 1 = true;  // absolute power-up: ActualModuloCycle from the absolute value
  bool restored_ : 1 = false;               // retained cyclic state present for the first anchor
  bool has_problem_ : 1 = false;            // config_ holds the problem
};

}  // namespace tomc::techobjects
