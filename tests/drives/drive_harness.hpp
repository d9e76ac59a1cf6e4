#pragma once
// Test harness for the simulated drive: the test plays the controller. Each cycle it encodes its setpoint
// signals into DeviceFrames (make_frames(config, kSetpoint)), writes them, lets the drive run one servo cycle
// with read_actual() and decodes the actual frames with TelegramCodecs of its own.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/normalisation.hpp"
#include "tomc/telegrams/sign_of_life.hpp"

namespace tomc::drives::test {

namespace tg = tomc::telegrams;
using Reaction = SimulatedDriveParameters::FaultReaction;

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline double rpm_to_rad_s(double rpm) {
  return rpm * kTwoPi / 60.0;
}
inline double rad_s_to_rpm(double w) {
  return w * 60.0 / kTwoPi;
}

inline std::string hex16(std::uint16_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%04X", static_cast<unsigned>(v));
  return buf;
}

inline DeviceConfig drive_config(std::uint16_t drive_telegram, std::uint16_t supplementary = 0,
                                 std::array<std::uint16_t, 2> encoders = {}) {
  DeviceConfig c;
  c.drive_telegram = drive_telegram;
  c.supplementary_telegram = supplementary;
  c.encoder_telegrams = encoders;
  return c;
}

// Motor + load inertia reflected to the motor shaft through the gear (J_load / i^2).
inline double reflected_inertia(const SimulatedDriveParameters& p) {
  const double i = p.gear_motor_revolutions / p.gear_load_revolutions;
  return p.motor_inertia_kgm2 + p.load_inertia_kgm2 / (i * i);
}

// The harness around any DriveAdapter with state() and parameters().reference_speed_rpm: the simulated drive
// (Harness) or the analog actor (analog_drive_test.cpp). `args` construct the drive.
template <class Drive>
class BasicHarness {
  DeviceConfig config_;  // first: initialised before the drive

 public:
  template <class... Args>
  explicit BasicHarness(const DeviceConfig& config, Args&&... args)
      : config_(config), drive(std::forward<Args>(args)...) {
    EXPECT_EQ(validate(config), "");
    for (std::size_t i = 0; i < kSlotCount; ++i) {
      const auto t = config.telegram(static_cast<Slot>(i));
      if (t == 0) continue;
      auto s = tg::TelegramCodec::create(t, tg::Direction::kSetpoint, config.codec);
      auto a = tg::TelegramCodec::create(t, tg::Direction::kActual, config.codec);
      EXPECT_TRUE(s.ok() && a.ok()) << "telegram " << t;
      if (s) setpoint_codecs_[i] = s.value();
      if (a) actual_codecs_[i] = a.value();
    }
    actual_frames = make_frames(config, tg::Direction::kActual);
    // Telegram 750 default without MC_TorqueRange: limits = +/- reference torque (spec 06 §8, TV14).
    supplementary.M_LIMIT_POS = 0x4000;
    supplementary.M_LIMIT_NEG = static_cast<std::int16_t>(-0x4000);
    for (auto& e : encoder)
      e.STW2_ENC.set(tg::Stw2EncBit::kControlByPlc);
  }

  const DeviceConfig& config() const { return config_; }
  const auto& params() const { return drive.parameters(); }

  // One servo cycle: write this cycle's setpoints, run the drive, decode its answer. Returns read_actual().
  bool cycle() {
    advance_master_sign_of_life();
    DeviceFrames frames = make_frames(config_, tg::Direction::kSetpoint);
    encode_setpoints(frames);
    drive.write_setpoint(frames);
    return read();
  }
  // A cycle in which the controller sends nothing (before the first cyclic frame).
  bool cycle_without_setpoint() { return read(); }

  int run(int cycles) {
    for (int i = 0; i < cycles; ++i)
      cycle();
    return cycles;
  }
  // Runs until pred() holds after a cycle; returns the number of cycles run (max_cycles + 1 if never).
  template <typename Pred>
  int run_until(Pred pred, int max_cycles) {
    for (int i = 1; i <= max_cycles; ++i) {
      cycle();
      if (pred()) return i;
    }
    return max_cycles + 1;
  }

  void stw1(std::uint16_t w) { drive_sp.STW1 = tg::Stw1{w}; }
  void speed_rpm(double rpm) {
    drive_sp.NSOLL_A = tg::speed_to_n2(rpm, params().reference_speed_rpm);
    drive_sp.NSOLL_B = tg::speed_to_n4(rpm, params().reference_speed_rpm);
  }

  std::uint16_t zsw1() const { return actual.ZSW1.value(); }
  double nist_rpm() const {
    const auto& codec = actual_codecs_[static_cast<std::size_t>(Slot::kDrive)];
    return codec.carries(tg::Signal::NIST_B) ? tg::n4_to_speed(actual.NIST_B, params().reference_speed_rpm)
                                             : tg::n2_to_speed(actual.NIST_A, params().reference_speed_rpm);
  }
  std::uint8_t slave_sign_of_life() const {
    return static_cast<std::uint8_t>(actual.ZSW2.field(tg::kSignOfLifeField));
  }

  // spec 06 §4.3: 0x047E (S1 -> S2) twice, then 0x047F (S2 -> S3 -> S4) twice.
  void power_up_to_s4() {
    stw1(0x047E);
    run(2);
    stw1(0x047F);
    run(2);
    ASSERT_EQ(drive.state(), tg::DriveState::kS4Operation) << "ZSW1 " << hex16(zsw1());
  }
  // S4 and a steady speed after `settle` cycles (the speed loop settles within a few time constants).
  void run_at_speed(double rpm, int settle = 200) {
    power_up_to_s4();
    speed_rpm(rpm);
    run(settle);
  }

  // Master sign-of-life in STW2 (drive telegrams with STW2) and STW2_ENC (encoder telegrams), spec 06 §5.1.
  bool freeze_master = false;
  tg::SignOfLifeGenerator master;

  Drive drive;
  tg::SetpointSignals drive_sp{};
  tg::SetpointSignals supplementary{};
  std::array<tg::SetpointSignals, 2> encoder{};
  tg::ActualSignals actual{};
  tg::ActualSignals supplementary_actual{};
  std::array<tg::ActualSignals, 2> encoder_actual{};
  DeviceFrames actual_frames{};

 private:
  void advance_master_sign_of_life() {
    if (freeze_master) return;
    const auto ls = master.next();
    drive_sp.STW2.set_field(tg::kSignOfLifeField, ls);
    for (auto& e : encoder)
      e.STW2_ENC.set_field(tg::kSignOfLifeField, ls);
  }
  void encode_setpoints(DeviceFrames& frames) const {
    const std::array<const tg::SetpointSignals*, kSlotCount> values{&drive_sp, &supplementary, &encoder[0],
                                                                    &encoder[1]};
    for (std::size_t i = 0; i < kSlotCount; ++i) {
      if (setpoint_codecs_[i].frame_size() == 0) continue;
      EXPECT_EQ(setpoint_codecs_[i].encode(*values[i], frames.slots[i].view()), tg::TelegramError::kNone);
    }
  }
  bool read() {
    const bool ok = drive.read_actual(actual_frames);
    if (!ok) return false;
    const std::array<tg::ActualSignals*, kSlotCount> values{&actual, &supplementary_actual,
                                                            &encoder_actual[0], &encoder_actual[1]};
    for (std::size_t i = 0; i < kSlotCount; ++i) {
      if (actual_codecs_[i].frame_size() == 0) continue;
      EXPECT_EQ(actual_codecs_[i].decode(actual_frames.slots[i].view(), *values[i]),
                tg::TelegramError::kNone);
    }
    return true;
  }

  std::array<tg::TelegramCodec, kSlotCount> setpoint_codecs_{};
  std::array<tg::TelegramCodec, kSlotCount> actual_codecs_{};
};

class Harness : public BasicHarness<SimulatedDrive> {
 public:
  Harness(const DeviceConfig& config, const SimulatedDriveParameters& parameters)
      : BasicHarness(config, config, parameters) {}
};

}  // namespace tomc::drives::test
