// Property test (issue 4): random instruction sequences on several speed axes with random drive faults.
// In every cycle and on every axis: the setpoint never exceeds the dynamic limits (velocity limit, and the
// acceleration bound: MaxAcceleration while speeding up, MaxDeceleration while slowing down, except the
// emergency ramps that may use EmergencyDeceleration, spec 01 §8.9). The velocity limit only as far as the
// state allows since issue 23 (decision S4 re-decided, seed 004 §6.7.7): a jerk-limited job replacing an
// accelerating one carries the acceleration over "tramite lo strappo", so the velocity may pass the limit
// while an outward acceleration is being taken back (|a| shrinking), never under a steady or growing one
// (before: never past the limit, the jerk was raised); an alarm with reaction "remove enable"
// has taken the enable away in the cycle it is raised; and the cyclic path allocates nothing.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>

#include "counting_allocator.hpp"
#include "speed_axis_fixture.hpp"

namespace {

using namespace tomc;
using tomc::testing::SpeedAxisMachine;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 20'000;
#else
constexpr int kCycles = 200'000;
#endif

struct Violations {
  long moving_cycles = 0;  // enabled cycles with a non-zero setpoint: the checks had something to check
  int velocity = 0;
  long beyond_velocity_limit = 0;  // cycles past the limit with an outward acceleration being taken back
  int acceleration = 0;
  int reaction = 0;
  double worst_acceleration = 0;
};

void random_inputs(SpeedAxisMachine& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto chance = [&](double p) { return unit(rng) < p; };
  auto dynamic = [&] {
    const double r = unit(rng);
    return r < 0.2 ? -1.0 : (r < 0.23 ? 0.0 : 5.0 + 195.0 * unit(rng));  // default, invalid, or a value
  };
  if (chance(0.0005)) m.power.Enable = !m.power.Enable;
  if (chance(0.002)) m.power.StopMode = static_cast<std::int16_t>(rng() % 4);
  if (chance(0.01)) {
    m.move.Execute = !m.move.Execute;
    m.move.Velocity = -4000.0 + 8000.0 * unit(rng);
    m.move.Acceleration = dynamic();
    m.move.Deceleration = dynamic();
    m.move.Jerk = chance(0.5) ? 0.0 : (chance(0.5) ? -1.0 : 100.0 + 5000.0 * unit(rng));
  }
  if (chance(0.002)) {
    m.halt.Execute = !m.halt.Execute;
    m.halt.Deceleration = dynamic();
    m.halt.AbortAcceleration = chance(0.5);
  }
  if (chance(0.001)) {
    m.stop.Execute = !m.stop.Execute;
    m.stop.Mode = static_cast<std::int32_t>(rng() % 4);
    m.stop.Deceleration = dynamic();
  }
  if (chance(0.005)) {
    m.jog.JogForward = chance(0.5);
    m.jog.JogBackward = chance(0.2);
    m.jog.Velocity = 3000.0 * unit(rng);
  }
  if (chance(0.002)) (void)m.axis->write("Override.Velocity", 200.0 * unit(rng));
  if (chance(0.0003)) m.drive->inject_fault(7000, drives::SimulatedDriveParameters::FaultReaction::kOff3);
  if (chance(0.003)) m.drive->clear_injected_fault();
  if (chance(0.0002)) m.drive->freeze_sign_of_life(true);
  if (chance(0.003)) m.drive->freeze_sign_of_life(false);
  if (chance(0.004)) m.reset.Execute = !m.reset.Execute;
}

// `was_enabled`: the axis was enabled in the previous cycle too. Enabling a moving speed axis sets the speed
// setpoint to 0 at once by definition (spec 01 §6.2: "braked by speed setpoint zero", limits inactive), so
// the cycle of enabling is not a motion cycle.
void check(const SpeedAxisMachine& m, double previous_velocity, double previous_acceleration,
           bool was_enabled, Violations& v) {
  const auto& d = m.axis->data();
  const double dt = 0.001;
  const double eps = 1e-6;
  // Velocity limit (spec 01 §8.3/§8.5), in 1/min: beyond it only while an outward acceleration shrinks
  // (seed 004 §6.7.7, decision S4).
  const double vmax = std::min(d.DynamicLimits.MaxVelocity, d.DynamicLimits.Velocity);
  if (std::fabs(d.Velocity) > vmax + eps) {
    const bool outward = d.Acceleration * d.Velocity > 0.0;
    if (outward && !(std::fabs(d.Acceleration) < std::fabs(previous_acceleration))) {
      ++v.velocity;
    } else {
      ++v.beyond_velocity_limit;
    }
  }
  // Acceleration (1/s²), from the setpoint itself and from its change per cycle.
  const double a = d.Acceleration;
  const double dv = (d.Velocity - previous_velocity) / 60.0 / dt;  // 1/s²
  const bool enabled_motion = techobjects::test(d.StatusWord, techobjects::StatusWordBit::kEnable);
  const double bound = std::max({d.DynamicLimits.MaxAcceleration, d.DynamicLimits.MaxDeceleration,
                                 d.DynamicDefaults.EmergencyDeceleration});
  if (enabled_motion && was_enabled) {
    if (d.Velocity != 0.0) ++v.moving_cycles;
    const double worst = std::max(std::fabs(a), std::fabs(dv));
    v.worst_acceleration = std::max(v.worst_acceleration, worst);
    if (worst > bound * (1 + 1e-9) + eps) ++v.acceleration;
    const bool speeding_up = a * d.Velocity > 0.0;
    if (speeding_up && std::fabs(a) > d.DynamicLimits.MaxAcceleration * (1 + 1e-9) + eps) ++v.acceleration;
  }
  // Reaction 4 takes the enable away in the cycle the alarm is raised (spec 02 §3.4).
  if (d.ErrorDetail.Reaction == 4 && techobjects::test(d.StatusWord, techobjects::StatusWordBit::kEnable))
    ++v.reaction;
}

// The properties of the file header: spec 01 §8.3, §8.9, seed 004 §6.7.7 (decision S4), spec 02 §3.4,
// ARCHITECTURE-GUIDE §7.
TEST(SpeedAxisProperty, RandomSequencesKeepTheLimits) {
  constexpr int kAxes = 3;
  std::vector<std::unique_ptr<SpeedAxisMachine>> machines;
  for (int i = 0; i < kAxes; ++i) {
    techobjects::SpeedAxisData data;
    data.DynamicLimits.MaxJerk = i == 0 ? 0.0 : 2000.0;  // trapezoids on one axis, jerk-limited on the others
    machines.push_back(
        std::make_unique<SpeedAxisMachine>(static_cast<std::uint16_t>(i == 2 ? 105 : 2), data));
    machines.back()->power.Enable = true;
  }
  std::mt19937 rng(20261122);
  Violations v;
  std::vector<double> previous(kAxes, 0.0);
  std::vector<double> previous_acceleration(kAxes, 0.0);
  std::vector<int> was_enabled(kAxes, 0);
  const auto before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < kCycles; ++cycle) {
    for (int i = 0; i < kAxes; ++i) {
      auto& m = *machines[static_cast<std::size_t>(i)];
      random_inputs(m, rng);
      m.run(1);
      check(m, previous[static_cast<std::size_t>(i)], previous_acceleration[static_cast<std::size_t>(i)],
            was_enabled[static_cast<std::size_t>(i)] != 0, v);
      previous[static_cast<std::size_t>(i)] = m.axis->data().Velocity;
      previous_acceleration[static_cast<std::size_t>(i)] = m.axis->data().Acceleration;
      was_enabled[static_cast<std::size_t>(i)] =
          techobjects::test(m.axis->data().StatusWord, techobjects::StatusWordBit::kEnable) ? 1 : 0;
    }
  }
  const auto allocated = tomc::testing::allocation_count() - before;
  EXPECT_EQ(v.velocity, 0);
  RecordProperty("cycles_beyond_the_velocity_limit", static_cast<int>(v.beyond_velocity_limit));
  EXPECT_EQ(v.acceleration, 0) << "worst |a| " << v.worst_acceleration;
  EXPECT_EQ(v.reaction, 0);
  EXPECT_EQ(allocated, 0u);
  // The sequence did exercise the axes: something moved and something faulted.
  std::size_t alarms = 0;
  for (auto& m : machines)
    alarms += m->axis->alarms().log().last_sequence();
  EXPECT_GT(alarms, 0u);
  EXPECT_GT(v.moving_cycles, kCycles * kAxes / 5) << "too few cycles with an enabled, moving axis";
}

}  // namespace
