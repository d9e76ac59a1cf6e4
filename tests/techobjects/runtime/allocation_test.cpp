// Real-time discipline (issue 3): after start-up, the application cycle with 16 simulated drives allocates
// nothing. A counting global operator new proves it over 10^6 cycles (fewer under sanitizers, which run the
// same code 10-50x slower).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <optional>

#include "counting_allocator.hpp"
#include "speed_command_object.hpp"
#include "tomc/drives/simulated_actor_drive.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace {

using namespace tomc::techobjects;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 20'000;
#else
constexpr int kCycles = 1'000'000;
#endif

// tomc's own: proves the counting allocator counts, so the zero of the cyclic-path tests can fail.
TEST(Allocation, CountingAllocatorSeesSetUp) {
  // The counter works: set-up of a runtime allocates.
  const auto before = tomc::testing::allocation_count();
  Runtime rt(RuntimeConfig{});
  tomc::drives::DeviceConfig device;
  device.drive_telegram = 3;
  rt.add_device(
      std::make_unique<tomc::drives::SimulatedDrive>(device, tomc::drives::SimulatedDriveParameters{}));
  EXPECT_GT(tomc::testing::allocation_count(), before);
}

// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), over the drive telegrams of spec 06 §2 (1–6,
// 102, 103, 105, 106) and 750.
TEST(Allocation, SixteenDrivesRunWithoutAllocating) {
  Runtime rt(RuntimeConfig{0.001, 1, 1});
  // A mix of telegrams so every codec path and the encoder, torque and DSC models run.
  const std::uint16_t telegrams[] = {1, 2, 3, 4, 5, 6, 102, 103, 105, 106, 3, 3, 105, 105, 2, 4};
  std::vector<tomc::testing::SpeedCommandObject*> objects;
  for (std::uint16_t t : telegrams) {
    tomc::drives::DeviceConfig device;
    device.drive_telegram = t;
    if (t == 105) device.supplementary_telegram = 750;
    auto& io = rt.add_device(
        std::make_unique<tomc::drives::SimulatedDrive>(device, tomc::drives::SimulatedDriveParameters{}));
    objects.push_back(
        &rt.emplace<tomc::testing::SpeedCommandObject>(io, DriveConnectionConfig{}, 1000.0, 0.5));
  }
  std::uint64_t user_cycles = 0;
  rt.set_user_program([&](Runtime&) { ++user_cycles; });
  rt.start();

  const auto before = tomc::testing::allocation_count();
  for (int i = 0; i < kCycles; ++i)
    rt.step();
  const auto allocated = tomc::testing::allocation_count() - before;

  EXPECT_EQ(allocated, 0u) << "allocations in " << kCycles << " cycles";
  EXPECT_EQ(user_cycles, static_cast<std::uint64_t>(kCycles));
  // The cycle did real work: every drive is in operation and moving.
  for (auto* o : objects) {
    EXPECT_TRUE(o->connection().in_operation());
  }
}

// The analog actor on its simulated servo amplifier and the stepper actor on its simulated PTO/stepper motor
// (issue 20): the hardware I/O layer, the counter extension, the DAC quantisation, the pulse train, the
// lost-step model, the ready-input supervision and a separate 81/83 encoder allocate nothing either.
TEST(Allocation, AnalogAndStepperDrivesRunWithoutAllocating) {
  Runtime rt(RuntimeConfig{0.001, 1, 1});
  std::vector<tomc::testing::SpeedCommandObject*> objects;
  for (int i = 0; i < 6; ++i) {
    tomc::drives::io::SimulatedServoAmplifierParameters amplifier;
    tomc::drives::AnalogDriveParameters actor;
    actor.counts_per_revolution = 4.0 * amplifier.encoder.lines_per_revolution;
    actor.counter_width_bits = amplifier.encoder.width_bits = i % 2 == 0 ? 16 : 32;  // 16 bit: many wraps
    if (i >= 2) {
      actor.enable_output = amplifier.enable_input;
      actor.ready_input = amplifier.ready_output;
    }
    // 4 and 5: the position from a separate encoder on telegram 81 / 83 (telegram 2 + 81/83).
    std::optional<tomc::drives::SeparateEncoderParameters> encoder;
    if (i >= 4) {
      actor.feedback = tomc::drives::PositionFeedback::kSeparateEncoder;
      actor.counter_width_bits = 32;
      encoder.emplace();
      encoder->telegram = i == 4 ? 81 : 83;
      actor.counts_per_revolution = 2048.0 * 2048.0;
    }
    auto& io = rt.add_device(std::make_unique<tomc::drives::SimulatedAnalogDrive>(amplifier, actor, encoder));
    objects.push_back(
        &rt.emplace<tomc::testing::SpeedCommandObject>(io, DriveConnectionConfig{}, 1000.0, 0.5));
  }
  for (int i = 0; i < 2; ++i) {
    tomc::drives::io::SimulatedStepperMotorParameters motor;
    motor.feedback = i == 0 ? tomc::drives::io::SimulatedStepperMotorParameters::Feedback::kPulseCount
                            : tomc::drives::io::SimulatedStepperMotorParameters::Feedback::kEncoder;
    tomc::drives::StepperDriveParameters actor;
    actor.counts_per_revolution =
        i == 0 ? motor.steps_per_revolution : 4.0 * motor.encoder.lines_per_revolution;
    actor.enable_output = motor.enable_input;
    actor.ready_input = motor.ready_output;
    auto& io = rt.add_device(std::make_unique<tomc::drives::SimulatedStepperDrive>(motor, actor));
    objects.push_back(
        &rt.emplace<tomc::testing::SpeedCommandObject>(io, DriveConnectionConfig{}, 1000.0, 0.5));
  }
  rt.start();

  const auto before = tomc::testing::allocation_count();
  for (int i = 0; i < kCycles / 4; ++i)
    rt.step();
  const auto allocated = tomc::testing::allocation_count() - before;

  EXPECT_EQ(allocated, 0u) << "allocations in " << kCycles / 4 << " cycles";
  for (auto* o : objects) {
    EXPECT_TRUE(o->connection().in_operation());
  }
}

}  // namespace
