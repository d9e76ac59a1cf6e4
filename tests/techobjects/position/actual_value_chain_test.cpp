// Actual-value chain, setpoint scaling and modulo rules: spec 01 §2.4, §2.4.1, §3.6–§3.9, §5.2–§5.8, §11
// A1/A3/A18, §12 scenarios 4–7, 12, 15, 20; spec 06 §6.1, §6.2, §7, §11 TV06/TV12/TV19–TV21/TV25.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "tomc/techobjects/position/actual_value_chain.hpp"

namespace tomc::techobjects {
namespace {

constexpr double kServoCycle = 0.002;            // 2 ms
constexpr double kTv12CountsPerRev = 4194304.0;  // 2048 * 2^11

// Drives Gx_XIST1 like an encoder: a true 64-bit count, transmitted modulo 2^width.
class SimEncoder {
 public:
  explicit SimEncoder(std::uint8_t width = 32, std::uint32_t start = 0) : width_(width), true_count_(start) {}
  std::uint32_t xist1() const {
    const std::uint64_t mask = width_ >= 32 ? 0xFFFFFFFFull : ((std::uint64_t{1} << width_) - 1);
    return static_cast<std::uint32_t>(static_cast<std::uint64_t>(true_count_) & mask);
  }
  // Moves `delta` counts in steps of at most `max_step`, one servo cycle per step.
  void move(ActualValueChain& chain, std::int64_t delta, std::int64_t max_step = std::int64_t{1} << 24) {
    while (delta != 0) {
      const std::int64_t step = delta > 0 ? std::min(delta, max_step) : std::max(delta, -max_step);
      true_count_ += step;
      delta -= step;
      chain.update(EncoderSample{xist1(), std::nullopt, std::nullopt});
    }
  }
  void sample(ActualValueChain& chain) { chain.update(EncoderSample{xist1(), std::nullopt, std::nullopt}); }

 private:
  std::uint8_t width_;
  std::int64_t true_count_;
};

AxisMechanics linear_axis(std::uint32_t lg_num = 1, std::uint32_t lg_den = 1, double leadscrew = 10.0) {
  AxisMechanics a;
  a.MotionType = AxisMotionType::kLinear;
  a.LoadGear = {lg_num, lg_den};
  a.Mechanics.LeadScrew = leadscrew;
  return a;
}

AxisMechanics rotary_axis(std::uint32_t lg_num = 1, std::uint32_t lg_den = 1) {
  AxisMechanics a;
  a.MotionType = AxisMotionType::kRotary;
  a.LoadGear = {lg_num, lg_den};
  return a;
}

EncoderMechanics rotary_encoder(EncoderMounting mounting = EncoderMounting::kMotorShaft,
                                std::uint32_t steps = 2048, std::uint32_t fine1 = 11) {
  EncoderMechanics e;
  e.System = EncoderSystem::kRotary;
  e.MountingMode = mounting;
  e.Parameter.StepsPerRevolution = steps;
  e.Parameter.FineResolutionXist1 = fine1;
  return e;
}

// ---------------------------------------------------------------------------------------------------------
// Mounting mode × axis type (spec 01 §5.2, §5.5–§5.8)

struct MountingCase {
  const char* name;
  AxisMechanics axis;
  EncoderMechanics encoder;
  std::int64_t counts;  // Gx_XIST1 counts moved
  double expected;      // load position [mm] or [°]
};

std::vector<MountingCase> mounting_cases() {
  std::vector<MountingCase> cases;
  {  // spec 01 §5.7 seed example / §12 scenario 20: Den 2, Num 1, LeadScrew 10 mm, 50 motor rev -> 1000 mm
    cases.push_back(
        {"linear_motor_shaft_seed_5_7", linear_axis(1, 2, 10.0), rotary_encoder(), 50 * 4194304LL, 1000.0});
  }
  {  // spec 06 §11 TV21: 1 048 576 counts at 4 194 304 counts/rev, leadscrew 10 mm -> 2.5 mm
    cases.push_back({"linear_motor_shaft_tv21", linear_axis(1, 1, 10.0), rotary_encoder(), 1048576, 2.5});
  }
  {  // measuring gear 1 motor rev : 4 encoder rev, load gear 3 : 1, leadscrew 6: 4 enc rev -> 1/3 load rev ->
     // 2 mm
    auto e = rotary_encoder(EncoderMounting::kMotorShaft, 1000, 2);
    e.MeasuringGear = {1, 4};
    cases.push_back({"linear_motor_shaft_measuring_gear", linear_axis(3, 1, 6.0), e, 4 * 4000LL, 2.0});
  }
  {  // load side, rotary: 1 load rev : 2 encoder rev, leadscrew 5; load gear must not matter
    auto e = rotary_encoder(EncoderMounting::kLoadSide, 4096, 4);
    e.MeasuringGear = {1, 2};
    cases.push_back({"linear_load_side_rotary", linear_axis(7, 3, 5.0), e, 8 * 65536LL, 20.0});
  }
  {  // load side, linear scale: Resolution 5 µm, 2 fine bits -> 4000 counts = 1000 increments = 5 mm
    EncoderMechanics e;
    e.System = EncoderSystem::kLinear;
    e.MountingMode = EncoderMounting::kLoadSide;
    e.Parameter.Resolution = 0.005;
    e.Parameter.FineResolutionXist1 = 2;
    cases.push_back({"linear_load_side_linear", linear_axis(7, 3, 5.0), e, 4000, 5.0});
  }
  {  // linear motor: linear measuring system on the "motor shaft" (spec 01 §5.2), 1 µm, no fine bits
    EncoderMechanics e;
    e.System = EncoderSystem::kLinear;
    e.MountingMode = EncoderMounting::kMotorShaft;
    e.Parameter.Resolution = 0.001;
    e.Parameter.FineResolutionXist1 = 0;
    cases.push_back({"linear_motor_shaft_linear_scale", linear_axis(), e, 123456, 123.456});
  }
  {  // external: measuring wheel 100 mm/rev, 1 wheel rev : 2 encoder rev; 3 encoder rev -> 150 mm
    auto e = rotary_encoder(EncoderMounting::kExternalMeasuringSystem, 2048, 11);
    e.MeasuringGear = {1, 2};
    e.Parameter.DistancePerRevolution = 100.0;
    cases.push_back({"linear_external", linear_axis(5, 1, 10.0), e, 3 * 4194304LL, 150.0});
  }
  {  // spec 01 §12 scenario 20: rotary, Numerator 3, Denominator 1, motor turns 3 rev -> 360°
    cases.push_back(
        {"rotary_motor_shaft_scenario_20", rotary_axis(3, 1), rotary_encoder(), 3 * 4194304LL, 360.0});
  }
  {  // rotary, motor shaft, load gear 10 : 1, 25 motor rev -> 2.5 load rev -> 900°
    cases.push_back({"rotary_motor_shaft", rotary_axis(10, 1),
                     rotary_encoder(EncoderMounting::kMotorShaft, 1024, 0), 25 * 1024LL, 900.0});
  }
  {  // rotary, load side: a quarter encoder revolution = 90°; load gear must not matter
    cases.push_back(
        {"rotary_load_side", rotary_axis(10, 1), rotary_encoder(EncoderMounting::kLoadSide), 1048576, 90.0});
  }
  {  // rotary, external: 120° per wheel rev, 1 wheel rev : 3 encoder rev; 3 encoder rev -> 120°
    auto e = rotary_encoder(EncoderMounting::kExternalMeasuringSystem, 2048, 11);
    e.MeasuringGear = {1, 3};
    e.Parameter.DistancePerRevolution = 120.0;
    cases.push_back({"rotary_external", rotary_axis(10, 1), e, 3 * 4194304LL, 120.0});
  }
  return cases;
}

// spec 01 §5.8 chain for every mounting mode and axis type, with and without Sensor.InverseDirection (§5.4).
TEST(ActualValueChainMounting, EveryMountingModeAndAxisType) {
  for (const auto& c : mounting_cases()) {
    for (const bool inverted : {false, true}) {
      SCOPED_TRACE(std::string(c.name) + (inverted ? " inverted" : ""));
      auto enc = c.encoder;
      enc.InverseDirection = inverted;
      ActualValueChain chain(c.axis, enc, kServoCycle);
      ASSERT_FALSE(chain.config_problem().has_value()) << chain.config_problem()->path;
      SimEncoder sim(32, 0x12345678u);
      sim.sample(chain);
      EXPECT_TRUE(chain.position_valid());
      EXPECT_DOUBLE_EQ(chain.position(), 0.0);  // incremental: 0 at power-up (spec 01 §3.7)
      sim.move(chain, c.counts);
      const double sign = inverted ? -1.0 : 1.0;
      EXPECT_NEAR(chain.position(), sign * c.expected, 1e-9 * std::max(1.0, c.expected));
      EXPECT_NEAR(units_per_xist1_count(c.axis, enc) * static_cast<double>(c.counts), sign * c.expected,
                  1e-9);
      sim.move(chain, -c.counts);
      EXPECT_NEAR(chain.position(), 0.0, 1e-9);
    }
  }
}

// spec 01 §5.4: if positive motor speed with increasing encoder counts moves the axis negatively, invert
// drive and encoder direction together. Closed loop: a positive load velocity command gives a positive actual
// velocity for both settings of the pair; inverting only one side reverses the measured direction.
TEST(ActualValueChainMounting, DriveAndEncoderInversionTogether) {
  for (const bool actor_inverted : {false, true}) {
    for (const bool sensor_inverted : {false, true}) {
      SCOPED_TRACE(std::to_string(actor_inverted) + "/" + std::to_string(sensor_inverted));
      auto axis = linear_axis(1, 2, 10.0);
      axis.Actor.InverseDirection = actor_inverted;
      auto enc = rotary_encoder();
      enc.InverseDirection = sensor_inverted;
      ActualValueChain chain(axis, enc, kServoCycle);
      const double n = chain.scaling().motor_speed(100.0);  // 100 mm/s
      EXPECT_NEAR(std::abs(n), 100.0 / 10.0 * 0.5 * 60.0, 1e-9);
      EXPECT_EQ(n < 0.0, actor_inverted);
      // The motor encoder counts with the motor (SINAMICS default): counts per cycle = n/60 * T * counts/rev.
      const auto per_cycle =
          static_cast<std::int64_t>(std::llround(n / 60.0 * kServoCycle * kTv12CountsPerRev));
      SimEncoder sim;
      sim.sample(chain);
      for (int i = 0; i < 10; ++i)
        sim.move(chain, per_cycle);
      const double expected = actor_inverted == sensor_inverted ? 100.0 : -100.0;
      EXPECT_NEAR(chain.velocity(), expected, 1e-3);
      EXPECT_NEAR(chain.position(), expected * 10 * kServoCycle, 1e-5);
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
// Gx_XIST1 width and overflow (spec 01 §3.7, spec 06 §6.1, seed 004 §6.2.4.4)

// spec 01 §3.7, spec 06 §6.1 (the width of Gx_XIST1 from the encoder parameters).
TEST(Xist1Width, DerivedFromEncoderParameters) {
  struct Row {
    std::int32_t behavior;
    std::uint32_t steps, fine1, revolutions;
    std::uint8_t bits;
  };
  const Row rows[] = {
      {1, 2048, 11, 0, 32},     // default: 32-bit counter
      {0, 2048, 11, 0, 22},     // 2^22 counts per revolution
      {0, 512, 11, 0, 20},      // spec 01 §12 scenario 15: 20-bit counter
      {0, 32, 11, 0, 16},       // spec 06 TV20: W = 16
      {0, 65536, 0, 0, 16},     // seed L11887 example: 16 bit, 0 ... 65535
      {0, 2500, 11, 0, 23},     // non-power of two: ceil(log2(5 120 000)) = 23
      {0, 2048, 11, 1, 22},     // single-turn absolute
      {0, 4096, 0, 4096, 24},   // 12-bit multi-turn range
      {0, 2048, 11, 4096, 32},  // 34 bits -> clamped to the telegram's 32
      {0, 1, 0, 0, 1},          // degenerate 1 count: at least 1 bit
  };
  for (const auto& r : rows) {
    auto e = rotary_encoder(EncoderMounting::kMotorShaft, r.steps, r.fine1);
    e.Parameter.BehaviorGx_XIST1 = r.behavior;
    e.Parameter.DeterminableRevolutions = r.revolutions;
    EXPECT_EQ(xist1_width_bits(e), r.bits) << r.steps << " " << r.fine1 << " " << r.revolutions;
  }
}

// spec 01 §12 scenario 15; spec 06 TV19/TV20.
TEST(Xist1Width, OverflowAt32BitsAndAtTheDerivedWidth) {
  {
    auto enc = rotary_encoder(EncoderMounting::kLoadSide, 1, 0);  // 1 count = 360°: counts visible in °
    ActualValueChain chain(rotary_axis(), enc, kServoCycle);
    chain.update({4294967290u, std::nullopt, std::nullopt});
    chain.update({5u, std::nullopt, std::nullopt});
    EXPECT_EQ(chain.encoder_counts(), 11);
    chain.update({0xFFFFFF00u, std::nullopt, std::nullopt});
    chain.update({0x00000100u, std::nullopt, std::nullopt});  // TV19
    EXPECT_EQ(chain.encoder_counts(), 11 - (5 + 256) + 512);
  }
  {
    auto enc = rotary_encoder(EncoderMounting::kLoadSide, 512, 11);  // 20-bit counter
    enc.Parameter.BehaviorGx_XIST1 = 0;
    ActualValueChain chain(rotary_axis(), enc, kServoCycle);
    EXPECT_EQ(chain.xist1_width(), 20);
    chain.update({1048570u, std::nullopt, std::nullopt});
    chain.update({3u, std::nullopt, std::nullopt});
    EXPECT_EQ(chain.encoder_counts(), 9);
    chain.update({1048570u, std::nullopt, std::nullopt});
    EXPECT_EQ(chain.encoder_counts(), 0);
    // The same samples read as a 32-bit counter would be a huge jump: BehaviorGx_XIST1 matters.
    enc.Parameter.BehaviorGx_XIST1 = 1;
    ActualValueChain wide(rotary_axis(), enc, kServoCycle);
    wide.update({1048570u, std::nullopt, std::nullopt});
    wide.update({3u, std::nullopt, std::nullopt});
    EXPECT_EQ(wide.encoder_counts(), -1048567);
  }
}

// Randomized: many wraps of a 16-bit counter forward and backward keep the exact position (fixed seed).
// spec 06 §6.1 (Gx_XIST1 overflow), spec 01 §3.7.
TEST(Xist1Width, RandomWalkAcrossManyWrapsIsExact) {
  auto enc = rotary_encoder(EncoderMounting::kLoadSide, 32, 11);  // W = 16
  enc.Parameter.BehaviorGx_XIST1 = 0;
  ActualValueChain chain(rotary_axis(), enc, kServoCycle);
  ASSERT_EQ(chain.xist1_width(), 16);
  std::mt19937_64 rng(20240505u);
  std::uniform_int_distribution<std::int64_t> step(-32767, 32767);
  SimEncoder sim(16, 40000);
  sim.sample(chain);
  std::int64_t truth = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::int64_t d = step(rng);
    truth += d;
    sim.move(chain, d, 32767);
    ASSERT_EQ(chain.encoder_counts(), truth);
  }
  EXPECT_NEAR(chain.position(), static_cast<double>(truth) / 65536.0 * 360.0, 1e-6);
}

// ---------------------------------------------------------------------------------------------------------
// Absolute and cyclic absolute encoders (spec 01 §3.7, §2.7, A3; spec 06 §6.2)

EncoderMechanics absolute_encoder(EncoderType type, std::uint32_t steps, std::uint32_t fine1,
                                  std::uint32_t fine2, std::uint32_t revolutions) {
  auto e = rotary_encoder(EncoderMounting::kLoadSide, steps, fine1);
  e.Type = type;
  e.Parameter.FineResolutionXist2 = fine2;
  e.Parameter.DeterminableRevolutions = revolutions;
  return e;
}

// spec 01 §12 scenario 12 (A3 uses ×360°): Steps 2048, XIST2 = 240, AbsEncoderOffset 137.812° -> 179.9995°.
TEST(AbsoluteEncoder, PositionFromXist2PlusOffset) {
  const auto enc = absolute_encoder(EncoderType::kAbsolute, 2048, 11, 0, 1);
  ActualValueChain chain(rotary_axis(), enc, kServoCycle);
  RetainedSensorState retained;
  retained.AbsEncoderOffset = 137.812;
  chain.power_up(&retained);
  chain.update({0xCAFE0000u, std::nullopt, std::nullopt});
  EXPECT_FALSE(chain.position_valid());  // no absolute value yet
  chain.update({0xCAFE0000u, 240u, std::nullopt});
  EXPECT_TRUE(chain.position_valid());
  EXPECT_NEAR(chain.position(), 240.0 / 2048.0 * 360.0 + 137.812, 1e-9);
  EXPECT_NEAR(chain.position(), 179.9995, 1e-4);
  EXPECT_EQ(chain.encoder_counts(), 240 * 2048);  // XIST2 (0 fine bits) in XIST1 counts (11 fine bits)
  EXPECT_DOUBLE_EQ(chain.velocity(), 0.0);        // the anchor jump is no velocity
  // Between absolute values Gx_XIST1 continues the position.
  chain.update({0xCAFE0000u + 2048u * 2048u / 4u, std::nullopt, std::nullopt});  // +1/4 rev
  EXPECT_NEAR(chain.position(), 179.9995 + 90.0, 1e-3);
}

// Absolute encoder adjustment (MC_Home Mode 7) sets AbsEncoderOffset; it survives power-up as a plain value.
// spec 02 §5.9 (absolute encoder adjustment, retained); spec 01 §3.7.
TEST(AbsoluteEncoder, AdjustmentOffsetIsRetained) {
  const auto enc = absolute_encoder(EncoderType::kAbsolute, 4096, 11, 9, 1024);  // 2^31 counts range
  auto axis = linear_axis(1, 1, 5.0);
  ActualValueChain chain(axis, enc, kServoCycle);
  ASSERT_FALSE(chain.config_problem().has_value());
  const std::uint32_t xist2 = 3u * 4096u * 512u + 1024u * 512u;  // 3.25 rev
  chain.update({77u, xist2, std::nullopt});
  EXPECT_NEAR(chain.position(), 3.25 * 5.0, 1e-9);
  chain.set_position(100.0, ModuloCycleRule::kZero);
  EXPECT_NEAR(chain.position(), 100.0, 1e-9);
  EXPECT_NEAR(chain.abs_encoder_offset(), 100.0 - 16.25, 1e-9);
  const RetainedSensorState saved = chain.retained_state();
  EXPECT_NEAR(saved.AbsEncoderOffset, 83.75, 1e-9);

  ActualValueChain after(axis, enc, kServoCycle);
  after.power_up(&saved);
  after.update({5u, xist2 + 512u * 4096u, std::nullopt});  // moved 1 rev while the CPU was off
  EXPECT_NEAR(after.position(), 105.0, 1e-9);
}

// Fine resolution of Gx_XIST2 differs from Gx_XIST1 (spec 06 §6.2: XIST2 has FineResolutionXist2 bits): the
// absolute value is brought into Gx_XIST1 counts, rounded to the nearest count when XIST1 is coarser.
TEST(AbsoluteEncoder, DifferentFineResolutionsOfXist1AndXist2) {
  {
    const auto enc = absolute_encoder(EncoderType::kAbsolute, 1024, 2, 9, 1);  // XIST2 finer by 7 bits
    ActualValueChain chain(rotary_axis(), enc, kServoCycle);
    chain.update({0u, 1000u * 128u + 64u, std::nullopt});  // 1000.5 XIST1 counts
    EXPECT_EQ(chain.encoder_counts(), 1001);
    chain.update({0u, 1000u * 128u + 63u, std::nullopt});
    EXPECT_EQ(chain.encoder_counts(), 1000);
    EXPECT_NEAR(chain.position(), 1000.0 / 4096.0 * 360.0, 1e-9);
  }
  {
    const auto enc = absolute_encoder(EncoderType::kAbsolute, 1024, 11, 9, 1);  // XIST1 finer by 2 bits
    ActualValueChain chain(rotary_axis(), enc, kServoCycle);
    chain.update({0u, 3u * 512u * 256u, std::nullopt});  // 3/4 revolution
    EXPECT_EQ(chain.encoder_counts(), 3 * 2048 * 256);
    EXPECT_NEAR(chain.position(), 270.0, 1e-9);
  }
}

// Inverted absolute encoder: the absolute value counts negative; the adjustment compensates (spec 01 §5.4).
TEST(AbsoluteEncoder, InverseDirection) {
  auto enc = absolute_encoder(EncoderType::kAbsolute, 1024, 0, 0, 1);
  enc.InverseDirection = true;
  ActualValueChain chain(rotary_axis(), enc, kServoCycle);
  chain.update({0u, 256u, std::nullopt});
  EXPECT_NEAR(chain.position(), -90.0, 1e-9);
  chain.set_position(10.0);
  chain.update({10u, 266u, std::nullopt});
  EXPECT_NEAR(chain.position(), 10.0 - 10.0 / 1024.0 * 360.0, 1e-9);
}

// Cyclic absolute: 4096 steps × 16 revolutions = 65 536 counts measuring range, leadscrew 10 mm -> 160 mm.
// The TO counts the traversed measuring ranges in both directions (spec 01 §3.7).
TEST(CyclicAbsoluteEncoder, CountsMeasuringRangeOverflowsBothWays) {
  const auto enc = absolute_encoder(EncoderType::kCyclicAbsolute, 4096, 0, 0, 16);
  ActualValueChain chain(linear_axis(), enc, kServoCycle);
  ASSERT_FALSE(chain.config_problem());
  ASSERT_EQ(chain.measuring_range(), 65536u);
  std::int64_t truth = 60000;  // encoder position in counts (XIST1 = XIST2 here: both 0 fine bits)
  auto feed = [&](std::int64_t d) {
    truth += d;
    const auto v = static_cast<std::uint32_t>(((truth % 65536) + 65536) % 65536);
    chain.update({static_cast<std::uint32_t>(truth), v, std::nullopt});
  };
  feed(0);
  EXPECT_NEAR(chain.position(), 60000.0 / 4096.0 * 10.0, 1e-9);
  for (int i = 0; i < 100; ++i)
    feed(1000);  // forward over range boundaries
  EXPECT_NEAR(chain.position(), 160000.0 / 4096.0 * 10.0, 1e-9);
  EXPECT_EQ(chain.measuring_range_count(), 2);
  for (int i = 0; i < 250; ++i)
    feed(-1000);  // backward below encoder zero
  EXPECT_EQ(truth, -90000);
  EXPECT_NEAR(chain.position(), -90000.0 / 4096.0 * 10.0, 1e-9);
  EXPECT_EQ(chain.measuring_range_count(), -2);
}

// The counter and offset are persisted as plain values; a later power-up continues, also when the encoder
// crossed its zero while the CPU was off (nearest range to the retained position).
// spec 01 §3.7 (cyclic absolute encoder), spec 02 §5.9 (retained values).
TEST(CyclicAbsoluteEncoder, PersistedCounterAcrossPowerCycle) {
  const auto enc = absolute_encoder(EncoderType::kCyclicAbsolute, 4096, 11, 9, 16);
  const auto axis = linear_axis(1, 1, 10.0);
  const std::int64_t range = 4096LL * 512 * 16;  // XIST2 counts
  ActualValueChain chain(axis, enc, kServoCycle);
  std::int64_t truth2 = 3 * range + range - 100;  // XIST2 units, 3 ranges + almost one more
  auto sample = [&](ActualValueChain& c, std::int64_t t2, bool absolute) {
    const auto v = static_cast<std::uint32_t>(((t2 % range) + range) % range);
    const auto x1 = static_cast<std::uint32_t>(static_cast<std::uint64_t>(t2 * 4));  // 2 more fine bits
    c.update({x1, absolute ? std::optional<std::uint32_t>(v) : std::nullopt, std::nullopt});
  };
  // First power-up without retained values: the encoder value alone is the position (range 0).
  sample(chain, truth2, true);
  EXPECT_EQ(chain.measuring_range_count(), 0);
  chain.set_position(static_cast<double>(truth2) / (4096.0 * 512.0) * 10.0);  // adjustment: offset 3 ranges
  EXPECT_NEAR(chain.abs_encoder_offset(), 3.0 * 160.0, 1e-9);
  // Cross the range boundary with Gx_XIST1 only (XIST2 not transmitted every cycle).
  for (int i = 0; i < 4; ++i)
    sample(chain, truth2 += 50, false);
  EXPECT_EQ(chain.measuring_range_count(), 1);
  const double before_off = chain.position();
  EXPECT_NEAR(before_off, static_cast<double>(truth2) / (4096.0 * 512.0) * 10.0, 1e-9);
  const RetainedSensorState saved = chain.retained_state();
  EXPECT_EQ(saved.MeasuringRangeCount, 1);
  EXPECT_EQ(saved.LastAbsoluteValue, 100u);

  // Power-up: the axis was pushed back 300 counts (across the encoder zero) while the CPU was off.
  ActualValueChain restored(axis, enc, kServoCycle);
  restored.power_up(&saved);
  truth2 -= 300;
  sample(restored, truth2, true);
  EXPECT_EQ(restored.measuring_range_count(), 0);
  EXPECT_NEAR(restored.position(), before_off - 300.0 / (4096.0 * 512.0) * 10.0, 1e-9);
  // Without a new sample retained_state() hands back what was restored.
  ActualValueChain idle(axis, enc, kServoCycle);
  idle.power_up(&saved);
  EXPECT_EQ(idle.retained_state().MeasuringRangeCount, 1);
  EXPECT_EQ(idle.retained_state().LastAbsoluteValue, 100u);
  EXPECT_DOUBLE_EQ(idle.retained_state().AbsEncoderOffset, saved.AbsEncoderOffset);
}

// Randomized: a cyclic absolute encoder with XIST2 present in random cycles follows the true position.
// spec 01 §3.7, spec 06 §6.2 (Gx_XIST2 only in some cycles).
TEST(CyclicAbsoluteEncoder, RandomWalkWithSparseAbsoluteValues) {
  const auto enc = absolute_encoder(EncoderType::kCyclicAbsolute, 1024, 2, 2, 4);  // range 16384
  ActualValueChain chain(rotary_axis(), enc, kServoCycle);
  std::mt19937 rng(7u);
  std::uniform_int_distribution<int> step(-3000, 3000);
  std::bernoulli_distribution has_xist2(0.3);
  std::int64_t truth = 5;
  chain.update({static_cast<std::uint32_t>(truth), static_cast<std::uint32_t>(truth), std::nullopt});
  for (int i = 0; i < 5000; ++i) {
    truth += step(rng);
    const auto v = static_cast<std::uint32_t>(((truth % 16384) + 16384) % 16384);
    chain.update({static_cast<std::uint32_t>(static_cast<std::uint64_t>(truth)),
                  has_xist2(rng) ? std::optional<std::uint32_t>(v) : std::nullopt, std::nullopt});
    ASSERT_EQ(chain.encoder_counts(), truth) << i;
  }
  EXPECT_EQ(chain.measuring_range_count(), truth >= 0 ? truth / 16384 : -((-truth + 16383) / 16384));
}

// ---------------------------------------------------------------------------------------------------------
// Modulo (spec 01 §2.4, §2.4.1, A1, A18)

// spec 01 §2.4, §2.4.1 (modulo range and cycle counter).
TEST(Modulo, WrapTable) {
  struct Row {
    double p, start, length, wrapped;
    std::int64_t cycle;
  };
  const Row rows[] = {
      {0.0, 0.0, 360.0, 0.0, 0},         {359.999, 0.0, 360.0, 359.999, 0},  {360.0, 0.0, 360.0, 0.0, 1},
      {-0.001, 0.0, 360.0, 359.999, -1}, {-720.0, 0.0, 360.0, 0.0, -2},      {1090.0, 0.0, 360.0, 10.0, 3},
      {180.0, -180.0, 360.0, -180.0, 1}, {-181.0, -180.0, 360.0, 179.0, -1}, {7.5, 5.0, 2.0, 5.5, 1},
      {-1e-17, 0.0, 360.0, 0.0, 0},  // rounding must not give 360.0
  };
  for (const auto& r : rows) {
    const auto w = modulo_wrap(r.p, r.start, r.length);
    EXPECT_NEAR(w.position, r.wrapped, 1e-9) << r.p;
    EXPECT_GE(w.position, r.start);
    EXPECT_LT(w.position, r.start + r.length);
    if (r.p != -1e-17) {
      EXPECT_EQ(w.cycle, r.cycle) << r.p;
    }
  }
}

// spec 01 §12 scenario 4: 350° + 20° -> 10°, counter +1; -20° back -> 350°, counter -1.
TEST(Modulo, ActualPositionWrapsWithCycleCounter) {
  auto axis = rotary_axis();
  axis.Modulo = {true, 0.0, 360.0};
  ActualValueChain chain(axis, rotary_encoder(EncoderMounting::kLoadSide, 360, 0),
                         kServoCycle);  // 1 count = 1°
  SimEncoder sim;
  sim.sample(chain);
  chain.set_position(350.0, ModuloCycleRule::kZero);
  EXPECT_EQ(chain.modulo_cycle(), 0);
  sim.move(chain, 20, 1);
  EXPECT_NEAR(chain.position(), 10.0, 1e-9);
  EXPECT_EQ(chain.modulo_cycle(), 1);
  sim.move(chain, -20, 1);
  EXPECT_NEAR(chain.position(), 350.0, 1e-9);
  EXPECT_EQ(chain.modulo_cycle(), 0);
  sim.move(chain, -1090, 7);  // backwards through three boundaries
  EXPECT_NEAR(chain.position(), 340.0, 1e-9);
  EXPECT_EQ(chain.modulo_cycle(), -3);
  sim.move(chain, 3 * 360 + 25, 100);  // forwards: 340 + 1105 = 1445 -> 5°, four boundaries
  EXPECT_NEAR(chain.position(), 5.0, 1e-9);
  EXPECT_EQ(chain.modulo_cycle(), 1);
}

// Modulo on a linear axis with a start value: range [-50, 150) mm.
// spec 01 §2.4 (Modulo.StartValue on a linear axis).
TEST(Modulo, LinearAxisWithStartValue) {
  auto axis = linear_axis(1, 1, 10.0);
  axis.Modulo = {true, -50.0, 200.0};
  ActualValueChain chain(axis, rotary_encoder(EncoderMounting::kMotorShaft, 1000, 0), kServoCycle);
  SimEncoder sim;
  sim.sample(chain);
  sim.move(chain, 15000, 100);  // 150 mm
  EXPECT_NEAR(chain.position(), -50.0, 1e-9);
  EXPECT_NEAR(chain.continuous_position(), 150.0, 1e-9);
  EXPECT_EQ(chain.modulo_cycle(), 1);
}

// spec 01 §2.4 (modulo: the shortest distance).
TEST(Modulo, ShortestDistance) {
  struct Row {
    double from, to, distance;
  };
  const Row rows[] = {
      {350.0, 10.0, 20.0},  {10.0, 350.0, -20.0},  {0.0, 179.0, 179.0},
      {0.0, 181.0, -179.0}, {0.0, 180.0, 180.0},  // tie: the way that does not cross the 0/360 boundary (A18)
      {180.0, 0.0, -180.0}, {90.0, 270.0, 180.0},  {270.0, 90.0, -180.0},
      {45.0, 45.0, 0.0},    {710.0, -350.0, 20.0},  // inputs outside the range are wrapped first
  };
  for (const auto& r : rows) {
    EXPECT_NEAR(modulo_shortest_distance(r.from, r.to, 0.0, 360.0), r.distance, 1e-9)
        << r.from << "->" << r.to;
    // Counter rule consistent with the distance: crossing the boundary forwards +1, backwards -1.
    const double a = modulo_wrap(r.from, 0.0, 360.0).position;
    const double d = modulo_shortest_distance(r.from, r.to, 0.0, 360.0);
    const std::int32_t expected_change = a + d >= 360.0 ? 1 : (a + d < 0.0 ? -1 : 0);
    EXPECT_EQ(modulo_cycle_change(r.from, r.to, 0.0, 360.0), expected_change) << r.from << "->" << r.to;
  }
}

// spec 01 §12 scenario 7: absolute encoder at 350°, counter 4; direct homing to 10° -> 5; back to 350° -> 4.
TEST(Modulo, ShortestDistanceRuleOnDirectHoming) {
  auto axis = rotary_axis();
  axis.Modulo = {true, 0.0, 360.0};
  const auto enc = absolute_encoder(EncoderType::kAbsolute, 360, 0, 0, 4096);  // 1 count = 1°
  ActualValueChain chain(axis, enc, kServoCycle);
  RetainedSensorState retained;
  retained.AbsEncoderOffset = 4 * 360.0 + 350.0;
  chain.power_up(&retained);
  chain.update({0u, 0u, std::nullopt});
  EXPECT_NEAR(chain.position(), 350.0, 1e-9);
  EXPECT_EQ(chain.modulo_cycle(), 4);  // power-up: derived from absolute value + offset (spec 01 §2.4.1)
  chain.set_position(10.0, ModuloCycleRule::kShortestDistance);
  EXPECT_EQ(chain.modulo_cycle(), 5);
  EXPECT_NEAR(chain.position(), 10.0, 1e-9);
  chain.set_position(350.0, ModuloCycleRule::kShortestDistance);
  EXPECT_EQ(chain.modulo_cycle(), 4);
  chain.set_position(170.0, ModuloCycleRule::kShortestDistance);  // exactly Length/2: no change (A18)
  EXPECT_EQ(chain.modulo_cycle(), 4);
  // Movement after homing keeps counting from the homed counter.
  chain.update({200u, std::nullopt, std::nullopt});
  EXPECT_NEAR(chain.position(), 10.0, 1e-9);
  EXPECT_EQ(chain.modulo_cycle(), 5);
  // spec 01 §12 scenario 6: absolute adjustment Mode 7 -> 0; restart keeps the counter of an absolute
  // encoder.
  chain.restart();
  EXPECT_EQ(chain.modulo_cycle(), 5);
  chain.update({200u, 200u, std::nullopt});
  EXPECT_EQ(chain.modulo_cycle(), 5);
  EXPECT_NEAR(chain.position(), 10.0, 1e-9);
  chain.set_position(90.0, ModuloCycleRule::kZero);
  EXPECT_EQ(chain.modulo_cycle(), 0);
}

// spec 01 §12 scenarios 5 and 6 (incremental encoder).
TEST(Modulo, IncrementalHomingAndRestart) {
  auto axis = rotary_axis();
  axis.Modulo = {true, 0.0, 360.0};
  ActualValueChain chain(axis, rotary_encoder(EncoderMounting::kLoadSide, 360, 0), kServoCycle);
  SimEncoder sim;
  sim.sample(chain);
  struct Row {
    double home;
    std::int32_t cycle;
  };
  for (const Row r : {Row{100.0, 0}, Row{180.0, 0}, Row{200.0, 1}, Row{0.0, 0}, Row{359.0, 1}}) {
    sim.move(chain, 5 * 360 + 7, 90);  // arbitrary counter before homing
    chain.set_position(r.home, ModuloCycleRule::kHomePositionHalf);
    EXPECT_EQ(chain.modulo_cycle(), r.cycle) << r.home;
    EXPECT_NEAR(chain.position(), r.home, 1e-9);
  }
  sim.move(chain, 5 * 360, 90);
  EXPECT_EQ(chain.modulo_cycle(), 6);
  chain.restart();  // MC_Reset(Restart = TRUE): counter 0, position 0
  EXPECT_EQ(chain.modulo_cycle(), 0);
  sim.sample(chain);
  EXPECT_NEAR(chain.position(), 0.0, 1e-12);
}

// ---------------------------------------------------------------------------------------------------------
// Actual velocity (spec 01 §3.9)

// spec 01 §3.9 (actual velocity without NIST_B: position difference per servo cycle).
TEST(ActualVelocity, FromPositionDifferencePerServoCycle) {
  ActualValueChain chain(linear_axis(1, 1, 10.0), rotary_encoder(), kServoCycle);
  SimEncoder sim(32, 0xFFFFF000u);
  sim.sample(chain);
  EXPECT_DOUBLE_EQ(chain.velocity(), 0.0);
  sim.move(chain, 1048576);  // 2.5 mm in 2 ms across the 32-bit wrap
  EXPECT_NEAR(chain.velocity(), 1250.0, 1e-9);
  sim.move(chain, -419430);  // -0.99999... mm
  EXPECT_NEAR(chain.velocity(), -419430.0 / kTv12CountsPerRev * 10.0 / kServoCycle, 1e-9);
  chain.set_position(500.0);  // homing does not produce a velocity
  sim.move(chain, 0, 1);
  sim.sample(chain);
  EXPECT_DOUBLE_EQ(chain.velocity(), 0.0);
}

// NIST_B of the drive telegram: spec 06 TV06 (0x0CCCCCCD = 600 rpm at 3000 rpm) through load gear and
// leadscrew; with Actor.InverseDirection the sign follows the drive direction.
TEST(ActualVelocity, FromNistBOfTheDriveTelegram) {
  auto axis = linear_axis(1, 2, 10.0);
  auto enc = rotary_encoder();
  enc.VelocityMode = ActualVelocityMode::kProfidriveNist;
  enc.Nist = NistSource::kDriveTelegram;
  for (const bool inverted : {false, true}) {
    axis.Actor.InverseDirection = inverted;
    ActualValueChain chain(axis, enc, kServoCycle);
    chain.update({0u, std::nullopt, 0x0CCCCCCD});
    const double expected = 600.0000006 / 60.0 * 2.0 * 10.0;  // 200 mm/s
    EXPECT_NEAR(chain.velocity(), inverted ? -expected : expected, 1e-6);
    // Without NIST_B in this cycle: position difference.
    chain.update({4194304u, std::nullopt, std::nullopt});
    EXPECT_NEAR(chain.velocity(), 20.0 / kServoCycle, 1e-9);
  }
}

// NIST_B of encoder telegram 83: spec 06 TV25 0x06666666 = 10 % of 3000 rpm at the encoder shaft.
TEST(ActualVelocity, FromNistBOfTelegram83) {
  auto enc = rotary_encoder(EncoderMounting::kLoadSide);
  enc.VelocityMode = ActualVelocityMode::kProfidriveNist;
  enc.Nist = NistSource::kEncoderTelegram83;
  enc.Parameter.ReferenceSpeed = 3000.0;
  ActualValueChain chain(rotary_axis(), enc, kServoCycle);
  chain.update({0u, std::nullopt, 0x06666666});
  EXPECT_NEAR(chain.velocity(), 299.9999989 / 60.0 * 360.0, 1e-5);  // °/s
  enc.InverseDirection = true;
  ActualValueChain inverted(rotary_axis(), enc, kServoCycle);
  inverted.update({0u, std::nullopt, 0x06666666});
  EXPECT_NEAR(inverted.velocity(), -299.9999989 / 60.0 * 360.0, 1e-5);

  EncoderMechanics scale;  // linear scale: ReferenceVelocity in position units per second
  scale.System = EncoderSystem::kLinear;
  scale.MountingMode = EncoderMounting::kLoadSide;
  scale.VelocityMode = ActualVelocityMode::kProfidriveNist;
  scale.Nist = NistSource::kEncoderTelegram83;
  scale.Parameter.ReferenceVelocity = 500.0;
  ActualValueChain linear(linear_axis(), scale, kServoCycle);
  linear.update({0u, std::nullopt, 0x20000000});  // 50 %
  EXPECT_NEAR(linear.velocity(), 250.0, 1e-9);
}

// ---------------------------------------------------------------------------------------------------------
// Setpoint scaling (spec 01 §3.6, spec 06 §7)

// spec 06 §11 TV12: 1.000 mm, leadscrew 10 mm/rev, 2048 × 2^11 counts/rev -> XERR 419 430.
TEST(SetpointScaling, XerrTv12) {
  SetpointScaling s(linear_axis(1, 1, 10.0), rotary_encoder());
  EXPECT_EQ(s.xerr(1.0), 419430);
  EXPECT_EQ(s.xerr(-1.0), -419430);
  EXPECT_NEAR(s.position_error_to_counts(1.0), 419430.4, 1e-6);
  EXPECT_EQ(s.xerr(1.0e9), INT32_MAX);  // saturated
  auto inverted = rotary_encoder();
  inverted.InverseDirection = true;  // XERR is in the encoder's counting direction
  EXPECT_EQ(SetpointScaling(linear_axis(1, 1, 10.0), inverted).xerr(1.0), -419430);
}

// spec 01 §3.6 (setpoint normalisation), §5.2–§5.7 (mechanics).
TEST(SetpointScaling, MotorSpeedTable) {
  struct Row {
    const char* name;
    AxisMechanics axis;
    double load_velocity, motor_speed;
  };
  auto inverted = linear_axis(1, 2, 10.0);
  inverted.Actor.InverseDirection = true;
  const Row rows[] = {
      // spec 01 §3.6: n = v * 60 / (LeadScrew * Den/Num) = 100 * 60 / 20
      {"linear_1_2", linear_axis(1, 2, 10.0), 100.0, 300.0},
      {"linear_1_1", linear_axis(1, 1, 10.0), 250.0, 1500.0},
      {"linear_inverted", inverted, 100.0, -300.0},
      // rotary: n = v / 360 * 60 * Num/Den = 360 °/s with 3 : 1 -> 180 1/min
      {"rotary_3_1", rotary_axis(3, 1), 360.0, 180.0},
      {"rotary_1_4", rotary_axis(1, 4), -1440.0, -60.0},
  };
  for (const auto& r : rows) {
    SCOPED_TRACE(r.name);
    SetpointScaling s(r.axis, rotary_encoder());
    EXPECT_NEAR(s.motor_speed(r.load_velocity), r.motor_speed, 1e-9);
    EXPECT_NEAR(s.load_velocity(r.motor_speed), r.load_velocity, 1e-9);
  }
  SetpointScaling s(linear_axis(1, 1, 10.0), rotary_encoder());          // ReferenceSpeed 3000
  EXPECT_EQ(s.nsoll_b(250.0), 0x20000000);                               // 1500 rpm = 50 % (spec 06 TV03)
  EXPECT_EQ(s.nsoll_b(-500.0), static_cast<std::int32_t>(0xC0000000u));  // -3000 rpm (TV07)
  EXPECT_EQ(s.nsoll_b(1e6), INT32_MAX);                                  // saturated at +200 % (TV08)
  EXPECT_NEAR(s.load_velocity_from_nist_b(0x20000000), 250.0, 1e-9);
}

// Randomized round trips (fixed seed): load velocity -> motor speed -> load velocity, and
// position -> counts -> position through the chain's own scale.
// spec 01 §3.6, §5.8 (the complete chain, both ways).
TEST(SetpointScaling, RandomRoundTrips) {
  std::mt19937 rng(12345u);
  std::uniform_int_distribution<std::uint32_t> gear(1, 1000);
  std::uniform_real_distribution<double> pitch(0.1, 50.0);
  std::uniform_real_distribution<double> velocity(-5000.0, 5000.0);
  std::bernoulli_distribution flag(0.5);
  for (int i = 0; i < 500; ++i) {
    auto axis = flag(rng) ? linear_axis(gear(rng), gear(rng), pitch(rng)) : rotary_axis(gear(rng), gear(rng));
    axis.Actor.InverseDirection = flag(rng);
    auto enc = rotary_encoder(flag(rng) ? EncoderMounting::kMotorShaft : EncoderMounting::kLoadSide,
                              gear(rng) * 16, 11);
    enc.MeasuringGear = {gear(rng), gear(rng)};
    enc.InverseDirection = flag(rng);
    ASSERT_FALSE(validate(axis, enc).has_value());
    SetpointScaling s(axis, enc);
    const double v = velocity(rng);
    EXPECT_NEAR(s.load_velocity(s.motor_speed(v)), v, 1e-9 * std::max(1.0, std::abs(v)));
    const double upc = units_per_xist1_count(axis, enc);
    EXPECT_NEAR(s.encoder_counts_per_unit() * upc, 1.0, 1e-12);
    // Motor speed and motor-encoder counts agree for a motor-shaft encoder with 1:1 measuring gear.
    if (enc.MountingMode == EncoderMounting::kMotorShaft) {
      enc.MeasuringGear = {1, 1};
      enc.InverseDirection = axis.Actor.InverseDirection;
      const SetpointScaling s1(axis, enc);
      const double counts_per_s = s1.motor_speed(v) / 60.0 * enc.Parameter.StepsPerRevolution * 2048.0;
      EXPECT_NEAR(counts_per_s * units_per_xist1_count(axis, enc), v, 1e-9 * std::max(1.0, std::abs(v)));
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
// Validation: the first problem with its variable path

// spec 01 §3.7, §5.2–§5.7 (the configuration the chain needs), spec 04 §3.6.
TEST(Validation, FirstProblemWithPath) {
  struct Row {
    const char* path;
    void (*mutate)(AxisMechanics&, EncoderMechanics&);
  };
  const Row rows[] = {
      {"LoadGear.Numerator", [](AxisMechanics& a, EncoderMechanics&) { a.LoadGear.Numerator = 0; }},
      {"LoadGear.Denominator", [](AxisMechanics& a, EncoderMechanics&) { a.LoadGear.Denominator = 0; }},
      {"Mechanics.LeadScrew", [](AxisMechanics& a, EncoderMechanics&) { a.Mechanics.LeadScrew = 0.0; }},
      {"Mechanics.LeadScrew", [](AxisMechanics& a, EncoderMechanics&) { a.Mechanics.LeadScrew = -10.0; }},
      {"Mechanics.LeadScrew", [](AxisMechanics& a, EncoderMechanics&) { a.Mechanics.LeadScrew = NAN; }},
      {"Modulo.Length",
       [](AxisMechanics& a, EncoderMechanics&) {
         a.Modulo.Enable = true;
         a.Modulo.Length = 0.0;
       }},
      {"Modulo.Length",
       [](AxisMechanics& a, EncoderMechanics&) {
         a.Modulo.Enable = true;
         a.Modulo.Length = -360.0;
       }},
      {"Modulo.StartValue",
       [](AxisMechanics& a, EncoderMechanics&) {
         a.Modulo.Enable = true;
         a.Modulo.StartValue = INFINITY;
       }},
      {"Actor.DriveParameter.ReferenceSpeed",
       [](AxisMechanics& a, EncoderMechanics&) { a.Actor.DriveParameter.ReferenceSpeed = 0.0; }},
      {"Sensor.MeasuringGear.Numerator",
       [](AxisMechanics&, EncoderMechanics& e) { e.MeasuringGear.Numerator = 0; }},
      {"Sensor.MeasuringGear.Denominator",
       [](AxisMechanics&, EncoderMechanics& e) { e.MeasuringGear.Denominator = 0; }},
      {"Sensor.Parameter.StepsPerRevolution",
       [](AxisMechanics&, EncoderMechanics& e) { e.Parameter.StepsPerRevolution = 0; }},
      {"Sensor.Parameter.StepsPerRevolution",
       [](AxisMechanics&, EncoderMechanics& e) { e.Parameter.StepsPerRevolution = 8388609; }},
      {"Sensor.Parameter.FineResolutionXist1",
       [](AxisMechanics&, EncoderMechanics& e) { e.Parameter.FineResolutionXist1 = 32; }},
      {"Sensor.Parameter.BehaviorGx_XIST1",
       [](AxisMechanics&, EncoderMechanics& e) { e.Parameter.BehaviorGx_XIST1 = 2; }},
      {"Sensor.Parameter.DistancePerRevolution",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.MountingMode = EncoderMounting::kExternalMeasuringSystem;
         e.Parameter.DistancePerRevolution = 0.0;
       }},
      {"Sensor.Parameter.Resolution",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.System = EncoderSystem::kLinear;
         e.Parameter.Resolution = 0.0;
       }},
      {"Sensor.System",
       [](AxisMechanics& a, EncoderMechanics& e) {
         a.MotionType = AxisMotionType::kRotary;
         e.System = EncoderSystem::kLinear;
       }},
      {"Sensor.MountingMode",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.System = EncoderSystem::kLinear;
         e.MountingMode = EncoderMounting::kExternalMeasuringSystem;
       }},
      {"Sensor.Parameter.BehaviorGx_XIST1",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.System = EncoderSystem::kLinear;
         e.Parameter.BehaviorGx_XIST1 = 0;
       }},
      {"Sensor.Parameter.DeterminableRevolutions",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.Type = EncoderType::kAbsolute;
         e.Parameter.DeterminableRevolutions = 0;
       }},
      {"Sensor.Parameter.FineResolutionXist2",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.Type = EncoderType::kCyclicAbsolute;
         e.Parameter.DeterminableRevolutions = 4096;
         e.Parameter.FineResolutionXist2 = 11;  // 2048 * 2^11 * 4096 = 2^34 > Gx_XIST2
       }},
      {"Sensor.Type",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.System = EncoderSystem::kLinear;
         e.Type = EncoderType::kCyclicAbsolute;
       }},
      {"Sensor.Parameter.ReferenceSpeed",
       [](AxisMechanics&, EncoderMechanics& e) {
         e.VelocityMode = ActualVelocityMode::kProfidriveNist;
         e.Nist = NistSource::kEncoderTelegram83;
         e.Parameter.ReferenceSpeed = 0.0;
       }},
  };
  ASSERT_FALSE(validate(linear_axis(), rotary_encoder()).has_value());
  for (const auto& r : rows) {
    auto a = linear_axis();
    auto e = rotary_encoder();
    r.mutate(a, e);
    const auto p = validate(a, e);
    ASSERT_TRUE(p.has_value()) << r.path;
    EXPECT_EQ(p->path, r.path);
    EXPECT_FALSE(p->message.empty());
    // An invalid chain reports the problem and ignores samples.
    ActualValueChain chain(a, e, kServoCycle);
    ASSERT_TRUE(chain.config_problem().has_value());
    EXPECT_EQ(chain.config_problem()->path, r.path);
    chain.update({100u, std::nullopt, std::nullopt});
    EXPECT_FALSE(chain.position_valid());
  }
  // Leadscrew is not used on a rotary axis; the servo cycle is checked by the chain.
  auto rot = rotary_axis();
  rot.Mechanics.LeadScrew = 0.0;
  EXPECT_FALSE(validate(rot, rotary_encoder()).has_value());
  ActualValueChain bad_cycle(linear_axis(), rotary_encoder(), 0.0);
  ASSERT_TRUE(bad_cycle.config_problem().has_value());
  EXPECT_EQ(bad_cycle.config_problem()->path, "ServoCycle");
}

// Real-time contract: the cyclic interface is noexcept (no allocation by construction: no dynamic members).
// ARCHITECTURE-GUIDE §2 (MC_Servo: the cyclic path); the developer guide's real-time rules (no exceptions).
TEST(RealTime, CyclicInterfaceIsNoexcept) {
  ActualValueChain chain(linear_axis(), rotary_encoder(), kServoCycle);
  static_assert(noexcept(chain.update(EncoderSample{})));
  static_assert(noexcept(chain.set_position(1.0)));
  static_assert(noexcept(chain.position()));
  static_assert(noexcept(chain.retained_state()));
  static_assert(noexcept(modulo_wrap(1.0, 0.0, 1.0)));
  static_assert(std::is_trivially_copyable_v<RetainedSensorState>);
  static_assert(std::is_trivially_destructible_v<ActualValueChain>);
  SUCCEED();
}

}  // namespace
}  // namespace tomc::techobjects
