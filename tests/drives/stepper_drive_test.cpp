// The stepper actor on the simulated PTO/stepper motor (issue 20): spec 01 §3.11 / seed 004 §6.2.6 (telegram
// 3 to a pulse-train output), the pulse frequency from NSOLL_B, the PTO's pulse count or an encoder as XIST1,
// and the lost-step model of decision A12 (pull-in rate, pull-out rate, acceleration). The test plays the TO
// on telegram 3, as the TO's drive connection does.
#include <gtest/gtest.h>

#include <cmath>

#include "drive_harness.hpp"
#include "tomc/drives/io/simulated_stepper_motor.hpp"
#include "tomc/drives/stepper_drive.hpp"

namespace tomc::drives::test {
namespace {

using io::Channel;
using Feedback = io::SimulatedStepperMotorParameters::Feedback;

// 1600 steps/rev (200 full steps × 8), ReferenceSpeed 600 1/min: 100 % = 16 000 Hz. 1 ms servo cycle.
// Motor: pull-in 2000 Hz, pull-out 40 000 Hz, 400 000 Hz/s = 400 Hz per cycle.
struct StepperRig {
  io::SimulatedStepperMotorParameters motor;
  StepperDriveParameters actor;

  explicit StepperRig(Feedback feedback = Feedback::kPulseCount) {
    motor.feedback = feedback;
    motor.encoder.lines_per_revolution = 100;  // 400 counts/rev: coarser than the motor step
    motor.mechanics.servo_cycle_s = 0.001;
    actor.servo_cycle_s = 0.001;
    actor.reference_speed_rpm = 600.0;
    actor.steps_per_revolution = 1600.0;
    actor.enable_output = Channel{2, 0};
    actor.ready_input = Channel{3, 0};
    actor.counts_per_revolution = feedback == Feedback::kEncoder ? 400.0 : 1600.0;
    actor.standstill_threshold_rpm = 1.0;
  }
};

struct StepperHarness {
  explicit StepperHarness(const StepperRig& rig = StepperRig())
      : motor(rig.motor), h(drive_config(3), motor, rig.actor) {}
  io::SimulatedStepperMotor motor;
  BasicHarness<StepperDrive> h;

  void hertz(double f) { h.speed_rpm(f / 1600.0 * 60.0); }
  std::int64_t xist1() const { return static_cast<std::int32_t>(h.actual.G1_XIST1); }
};

// spec 01 §3.11: telegram 3, NSOLL_B in % of the reference speed -> pulse frequency of the PTO.
TEST(StepperDrive, PulseFrequencyFromNsollB) {
  StepperRig rig;
  rig.actor.max_frequency_hz = 25000.0;
  StepperHarness s(rig);
  s.h.power_up_to_s4();
  struct Row {
    double rpm;
    double hertz;
  };
  // 600 1/min = 100 % = 16 000 Hz; 200 % of N4 would be 32 000 Hz, clamped to the PTO's 25 000 Hz.
  for (const Row row : {Row{600.0, 16000.0}, Row{300.0, 8000.0}, Row{-150.0, -4000.0}, Row{37.5, 1000.0},
                        Row{1200.0, 25000.0}, Row{-1200.0, -25000.0}, Row{0.0, 0.0}}) {
    s.h.speed_rpm(row.rpm);
    s.h.cycle();
    EXPECT_NEAR(s.h.drive.pulse_frequency_hz(), row.hertz, 1e-3) << row.rpm << " 1/min";
  }
}

// Whole pulses per cycle, the fraction carried: 8000 Hz = 8 pulses per 1 ms cycle; 1234.5 Hz for 1000 cycles
// = 1234 or 1235 pulses (never a drift).
// Decision A13 (pulse frequency from NSOLL_B, the PTO counts what it sent), decision R2 (the setpoint acts
// one cycle later).
TEST(StepperDrive, PulsesCountedExactlyWithFractionCarried) {
  StepperHarness s;
  s.h.power_up_to_s4();
  s.hertz(1000.0);  // within the pull-in rate: followed from standstill
  s.h.run(3);
  s.hertz(8000.0);
  s.h.run(20);  // 1000 -> 8000 Hz in one cycle exceeds 400 Hz/cycle: lost steps (next test); pulses count on
  const std::int64_t before = s.xist1();
  s.h.run(100);
  EXPECT_EQ(s.xist1() - before, 800);  // the PTO counts what it sent
  EXPECT_NEAR(s.h.nist_rpm(), 300.0, 1e-9);

  StepperHarness f;
  f.h.power_up_to_s4();
  f.hertz(1234.5);
  f.h.run(2);  // the setpoint acts one cycle later (R2)
  const std::int64_t start = f.motor.pulses_sent();
  f.h.run(1000);
  EXPECT_NEAR(static_cast<double>(f.motor.pulses_sent() - start), 1234.5, 1.0);
  EXPECT_EQ(f.motor.lost_steps(), 0);
  EXPECT_EQ(f.motor.rotor_steps(), f.motor.pulses_sent());
}

// Decision A12: above the pull-in rate the rotor follows rate changes up to max_acceleration (400 Hz per
// cycle here); a ramp at 300 or 399 Hz/cycle to 30 000 Hz loses nothing, a ramp at 401 or 500 Hz/cycle
// stalls as soon as it leaves the pull-in range.
TEST(StepperDrive, AccelerationAbovePullInLosesSteps) {
  struct Row {
    double hertz_per_cycle;
    bool loses;
  };
  for (const Row row : {Row{300.0, false}, Row{399.0, false}, Row{401.0, true}, Row{500.0, true}}) {
    StepperHarness s(StepperRig(Feedback::kEncoder));
    s.h.power_up_to_s4();
    double f = 0.0;
    int stall_cycle = -1;
    for (int k = 1; f < 30000.0; ++k) {
      f = std::min(30000.0, f + row.hertz_per_cycle);
      s.hertz(f);
      s.h.cycle();
      if (stall_cycle < 0 && !s.motor.in_step()) stall_cycle = k;
    }
    s.h.run(50);
    EXPECT_EQ(s.motor.lost_steps() > 0, row.loses) << row.hertz_per_cycle << " Hz/cycle";
    if (row.hertz_per_cycle == 500.0) {
      // 500 Hz/cycle: 2000 Hz (pull-in) in cycle 4; 2500 Hz in cycle 5 is the first rate above pull-in, a
      // change of 500 Hz in 1 ms.
      EXPECT_EQ(stall_cycle, 5);
    }
    if (row.loses) {
      EXPECT_EQ(s.motor.stalls(), 1u);
      // The stalled rotor stands: the encoder shows it, NIST_B is 0 although 30 000 Hz are sent.
      EXPECT_NEAR(s.h.nist_rpm(), 0.0, 1e-9);
      EXPECT_EQ(s.motor.rotor_steps() + s.motor.lost_steps(), s.motor.pulses_sent());
    } else {
      EXPECT_EQ(s.motor.rotor_steps(), s.motor.pulses_sent());
      // 1125 1/min = 7.5 counts per cycle of the 400-count encoder: NIST_B within one count (150 1/min).
      EXPECT_NEAR(s.h.nist_rpm(), 30000.0 / 1600.0 * 60.0, 75.0 + 1e-9);
    }
  }
}

// Above the pull-out rate the motor falls out of step; at or below the pull-in rate it pulls in again.
// Decision A12 (out of step above pull_out_rate_hz; in step again at or below pull_in_rate_hz).
TEST(StepperDrive, PullOutRateAndPullInAgain) {
  StepperRig rig(Feedback::kEncoder);
  rig.motor.pull_out_rate_hz = 20000.0;
  StepperHarness s(rig);
  s.h.power_up_to_s4();
  double f = 0.0;
  while (f < 20000.0) {
    f += 250.0;
    s.hertz(f);
    s.h.cycle();
  }
  s.h.run(5);
  EXPECT_TRUE(s.motor.in_step());
  EXPECT_EQ(s.motor.lost_steps(), 0);
  s.hertz(20250.0);  // within the acceleration, above the pull-out rate
  s.h.run(2);
  EXPECT_FALSE(s.motor.in_step());
  s.hertz(5000.0);  // slower, but above pull-in: still stalled
  s.h.run(10);
  EXPECT_FALSE(s.motor.in_step());
  const std::int64_t stood = s.motor.rotor_steps();
  s.hertz(2000.0);  // pull-in rate: in step again, the rotor moves 2 steps per cycle
  s.h.run(1);
  EXPECT_TRUE(s.motor.in_step());
  const std::int64_t resumed = s.motor.rotor_steps();
  EXPECT_EQ(resumed, stood + 2);
  s.h.run(10);
  EXPECT_EQ(s.motor.rotor_steps(), resumed + 20);
}

// With the PTO's pulse count as the actual value a lost step is invisible to the TO (the open-loop stepper's
// risk); with an encoder it is seen: the difference is exactly the lost steps (encoder: 1 count = 4 steps).
// Decision A13 (position from the pulse count: a lost step is invisible; with an encoder it is seen),
// decision A12.
TEST(StepperDrive, FeedbackPulseCountVersusEncoder) {
  for (const Feedback feedback : {Feedback::kPulseCount, Feedback::kEncoder}) {
    StepperHarness s{StepperRig(feedback)};
    s.h.power_up_to_s4();
    s.hertz(4000.0);  // a jump beyond the pull-in rate: stalls at once
    s.h.run(100);     // 100 cycles of 4 pulses
    s.hertz(0.0);
    s.h.run(3);
    EXPECT_EQ(s.motor.pulses_sent(), 400);
    EXPECT_EQ(s.motor.lost_steps(), 400);
    EXPECT_EQ(s.motor.rotor_steps(), 0);
    EXPECT_EQ(s.xist1(), feedback == Feedback::kPulseCount ? 400 : 0);
  }
}

// The stop reactions and the ready input are the telegram-3 actor's (spec 01 §3.12, shared with the analog
// actor): OFF1 stops the pulses at once (the TO's ramp is the stop ramp); a driver fault drops the ready
// signal, the actor shows fault 20001 and sends no pulses.
TEST(StepperDrive, StopAndReadyInput) {
  StepperHarness s;
  s.h.power_up_to_s4();
  s.hertz(1500.0);
  s.h.run(10);
  EXPECT_TRUE(s.h.drive.enable_output());
  s.h.stw1(0x047E);  // OFF1
  s.h.cycle();
  EXPECT_EQ(s.h.drive.pulse_frequency_hz(), 0.0);
  s.h.run(3);
  EXPECT_FALSE(s.h.drive.enable_output());  // standstill: the stop ends

  StepperHarness r;
  r.h.power_up_to_s4();
  r.hertz(1500.0);
  r.h.run(10);
  r.motor.set_fault(true);
  r.h.cycle();
  EXPECT_EQ(r.h.drive.active_fault(), kFaultDriveReadyLost);
  EXPECT_NE(r.h.zsw1() & 0x0008u, 0u);  // ZSW1.3 fault
  EXPECT_EQ(r.h.drive.pulse_frequency_hz(), 0.0);
  EXPECT_FALSE(r.h.drive.enable_output());
}

}  // namespace
}  // namespace tomc::drives::test
