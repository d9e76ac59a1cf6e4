// Position controller (spec 02 §7.1–§7.4, DSC §7.2) and the following error (spec 02 §6.2, spec 01 §3.5).
#include "tomc/techobjects/position/position_control.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "tomc/techobjects/position/position_monitoring.hpp"

namespace tomc::techobjects {
namespace {

static_assert(noexcept(std::declval<PositionController&>().update(PositionControlInput{})));
static_assert(noexcept(std::declval<PositionController&>().configure(PositionControlConfig{})));
static_assert(noexcept(std::declval<const SetpointDelayLine&>().delayed(1.5)));

PositionControlInput input(double x_set, double v_set, double x_act) {
  return PositionControlInput{x_set, x_set, v_set, x_act};
}

// Drive model for the closed-loop tests: a dead time of whole servo cycles on the speed setpoint followed
// by the closed speed loop as a first-order lag with T_vtc, integrated exactly over each servo cycle (the
// setpoint is held for one cycle). The actual position is sampled at the end of the cycle.
class SpeedLoopPlant {
 public:
  SpeedLoopPlant(double tvtc, double ts, std::size_t dead_cycles)
      : tvtc_(tvtc), ts_(ts), pipeline_(dead_cycles, 0.0) {}
  void step(double command) {
    double u = command;
    if (!pipeline_.empty()) {
      u = pipeline_[head_];
      pipeline_[head_] = command;
      head_ = (head_ + 1) % pipeline_.size();
    }
    if (tvtc_ <= 0.0) {
      v_ = u;
      x_ += u * ts_;
      return;
    }
    const double decay = std::exp(-ts_ / tvtc_);
    x_ += u * ts_ + (v_ - u) * tvtc_ * (1.0 - decay);
    v_ = u + (v_ - u) * decay;
  }
  double position() const { return x_; }
  double velocity() const { return v_; }

 private:
  double tvtc_;
  double ts_;
  std::vector<double> pipeline_;
  std::size_t head_ = 0;
  double x_ = 0.0;
  double v_ = 0.0;
};

// ---- delay line ----

// spec 02 §7.4 (2) (the communication/processing delay, fractional); decision M3.
TEST(SetpointDelayLine, IntegerAndFractionalDelays) {
  SetpointDelayLine line;
  line.fill(0.0);
  for (int k = 1; k <= 10; ++k)
    line.push(10.0 * k);  // newest 100, then 90, 80, ...
  EXPECT_DOUBLE_EQ(line.delayed(0.0), 100.0);
  EXPECT_DOUBLE_EQ(line.delayed(1.0), 90.0);
  EXPECT_DOUBLE_EQ(line.delayed(3.0), 70.0);
  EXPECT_DOUBLE_EQ(line.delayed(1.5), 85.0);   // linear interpolation
  EXPECT_DOUBLE_EQ(line.delayed(2.25), 77.5);  // 0.75·80 + 0.25·70
  EXPECT_DOUBLE_EQ(line.delayed(20.0), 0.0);   // older than the pushes: the fill value
  EXPECT_DOUBLE_EQ(line.delayed(-3.0), 100.0);
}

// Decision M3 (24 samples: longer delays are clamped).
TEST(SetpointDelayLine, ClampsToCapacity) {
  SetpointDelayLine line;
  line.fill(-1.0);
  for (std::size_t k = 0; k < 2 * kMaxSetpointDelayCycles; ++k)
    line.push(static_cast<double>(k));
  const double newest = static_cast<double>(2 * kMaxSetpointDelayCycles - 1);
  const double max_delay = static_cast<double>(kMaxSetpointDelayCycles - 1);
  EXPECT_DOUBLE_EQ(line.delayed(max_delay), newest - max_delay);
  EXPECT_DOUBLE_EQ(line.delayed(1000.0), newest - max_delay);
  EXPECT_DOUBLE_EQ(line.delayed(max_delay - 0.5), newest - max_delay + 0.5);
}

// ---- configuration ----

// spec 02 §7.3, §7.4 (2) (n_dead from T_i, T_o, T_DC, T_Servo).
TEST(PositionController, DelaysFromCommunicationTimes) {
  PositionControlConfig c;
  c.ServoCycle = 0.002;
  c.Ti = 0.000125;
  c.To = 0.000375;
  c.Tdc = 0.001;
  c.AdditionalSetpointDelayTime = 0.003;
  PositionController pc;
  ASSERT_EQ(pc.configure(c), PositionControlConfigResult::kOk);
  EXPECT_DOUBLE_EQ(pc.control_delay_cycles(), 1.75);          // (0.5 ms + 1 ms + 2 ms) / 2 ms
  EXPECT_DOUBLE_EQ(pc.following_error_delay_cycles(), 3.25);  // + 3 ms / 2 ms
  EXPECT_FALSE(pc.delay_clamped());

  c.AdditionalSetpointDelayTime = 1.0;  // 500 cycles
  EXPECT_EQ(pc.configure(c), PositionControlConfigResult::kDelayClamped);
  EXPECT_TRUE(pc.delay_clamped());
  EXPECT_DOUBLE_EQ(pc.following_error_delay_cycles(), static_cast<double>(kMaxSetpointDelayCycles - 1));
  EXPECT_DOUBLE_EQ(pc.control_delay_cycles(), 1.75);
}

// spec 02 §7.3 (the control variables); spec 04 §3.20 (PositionControl and its ranges).
TEST(PositionController, RejectsInvalidConfiguration) {
  PositionController pc;
  PositionControlConfig c;
  c.Kv = 20.0;
  ASSERT_EQ(pc.configure(c), PositionControlConfigResult::kOk);
  PositionControlConfig bad = c;
  bad.ServoCycle = 0.0;
  EXPECT_EQ(pc.configure(bad), PositionControlConfigResult::kInvalidServoCycle);
  bad = c;
  bad.Kv = -1.0;
  EXPECT_EQ(pc.configure(bad), PositionControlConfigResult::kInvalidParameter);
  bad = c;
  bad.VelocityTimeConstant = std::nan("");
  EXPECT_EQ(pc.configure(bad), PositionControlConfigResult::kInvalidParameter);
  EXPECT_DOUBLE_EQ(pc.kv(), 20.0);  // previous configuration kept
  PositionController from_bad(bad);
  EXPECT_DOUBLE_EQ(from_bad.kv(), PositionControlConfig{}.Kv);
}

// ---- open loop: the equations of §7.4 and §6.2 ----

// spec 02 §7.4 (2)–(4), §6.2 (the following error against the delayed setpoint).
TEST(PositionController, FollowingErrorUsesDelayedSetpointWithFractionalDelay) {
  PositionControlConfig c;
  c.ServoCycle = 0.001;
  c.Ti = 0.0005;                          // total delay 1.5 cycles
  c.AdditionalSetpointDelayTime = 0.001;  // FE delay 2.5 cycles
  c.Kpc = 0.0;
  c.Kv = 10.0;
  PositionController pc(c);
  const double v = 100.0;
  PositionControlOutput out;
  for (int k = 0; k <= 20; ++k) {
    const double x = v * 0.001 * k;
    out = pc.update(input(x, v, 1.0));
  }
  const double x_now = v * 0.001 * 20;
  // spec 01 §3.5: FE(t) = x(t − (Ti + To + TDC + Tservo + Tadd)) − x_act(t)
  EXPECT_NEAR(out.following_error, x_now - v * 0.0025 - 1.0, 1e-12);
  // control path without T_add, no precontrol: e = x(t − 1.5 Ts) − x_act, v_cmd = Kv·e
  EXPECT_NEAR(out.control_difference, x_now - v * 0.0015 - 1.0, 1e-12);
  EXPECT_NEAR(out.velocity_setpoint, 10.0 * out.control_difference, 1e-12);
  EXPECT_DOUBLE_EQ(out.balanced_position, out.control_difference + 1.0);
}

// spec 02 §7.4 (2)–(4) (the delay line starts at the first setpoint: no step).
TEST(PositionController, FirstCycleStartsWithoutStep) {
  PositionController pc;
  const auto out = pc.update(input(123.0, 0.0, 123.0));
  EXPECT_DOUBLE_EQ(out.velocity_setpoint, 0.0);
  EXPECT_DOUBLE_EQ(out.following_error, 0.0);
  EXPECT_DOUBLE_EQ(out.balanced_position, 123.0);
  pc.reset();
  const auto again = pc.update(input(-5.0, 0.0, -5.0));
  EXPECT_DOUBLE_EQ(again.velocity_setpoint, 0.0);
  EXPECT_DOUBLE_EQ(again.following_error, 0.0);
}

// spec 02 §7.4 (3) (the symmetry filter, T_vtc).
TEST(PositionController, SymmetryFilterLagsRampByVelocityTimeConstant) {
  PositionControlConfig c;
  c.ServoCycle = 0.001;
  c.Kpc = 100.0;
  c.VelocityTimeConstant = 0.004;
  c.Kv = 30.0;
  PositionController pc(c);
  const double v = 50.0;
  PositionControlOutput out;
  for (int k = 0; k <= 2000; ++k)
    out = pc.update(input(v * 0.001 * k, v, 0.0));
  const double x_d = v * 0.001 * 1999;  // delayed by T_servo
  EXPECT_NEAR(out.balanced_position, x_d - v * 0.004, 1e-9);
  EXPECT_NEAR(out.velocity_setpoint, v + 30.0 * out.balanced_position, 1e-9);  // kpc·v + Kv·e
}

// spec 02 §7.4 (3) (kpc = 0: the filter drops out).
TEST(PositionController, VelocityTimeConstantIrrelevantWithoutPrecontrol) {
  PositionControlConfig a;
  a.Kpc = 0.0;
  a.VelocityTimeConstant = 0.0;
  PositionControlConfig b = a;
  b.VelocityTimeConstant = 0.05;
  PositionController pa(a);
  PositionController pb(b);
  for (int k = 0; k < 100; ++k) {
    const auto in = input(std::sin(0.1 * k), std::cos(0.1 * k), 0.2 * std::sin(0.05 * k));
    const auto oa = pa.update(in);
    const auto ob = pb.update(in);
    EXPECT_DOUBLE_EQ(oa.velocity_setpoint, ob.velocity_setpoint);
    EXPECT_DOUBLE_EQ(oa.balanced_position, ob.balanced_position);
  }
}

// spec 02 §7.2 (DSC: precontrol, XERR and KPC to the drive).
TEST(PositionController, DscOutputsPrecontrolXerrAndKpc) {
  PositionControlConfig c;
  c.EnableDSC = true;
  c.Kv = 80.0;
  c.Kpc = 60.0;
  c.VelocityTimeConstant = 0.0;
  PositionController pc(c);
  pc.update(input(0.0, 0.0, 0.0));
  const auto out = pc.update(input(0.4, 100.0, 0.1));  // x_d = 0 (one cycle delay) -> e = 0 − 0.1
  EXPECT_DOUBLE_EQ(out.velocity_setpoint, 60.0);       // NSOLL_B = kpc·v_f
  EXPECT_DOUBLE_EQ(out.dsc_position_error, -0.1);
  EXPECT_DOUBLE_EQ(out.control_difference, -0.1);
  EXPECT_DOUBLE_EQ(out.dsc_kpc, 80.0);

  c.EnableDSC = false;
  PositionController plc(c);
  plc.update(input(0.0, 0.0, 0.0));
  const auto p = plc.update(input(0.4, 100.0, 0.1));
  EXPECT_DOUBLE_EQ(p.velocity_setpoint, 60.0 + 80.0 * -0.1);
  EXPECT_DOUBLE_EQ(p.dsc_position_error, 0.0);
  EXPECT_DOUBLE_EQ(p.dsc_kpc, 0.0);
}

// spec 01 §3.11 / spec 02 §7.4 (4): ControlDifferenceQuantization, e_q = q·trunc(e/q): the controller sees
// e_q (PLC: Kv·e_q; DSC: XERR = e_q), StatusServo.ControlDifference shows e. q = 0.1 mm, Kv 50, no
// precontrol.
TEST(PositionController, ControlDifferenceQuantizationTable) {
  struct Row {
    double e;
    double e_q;
  };
  for (const bool dsc : {false, true}) {
    PositionControlConfig c;
    c.Kv = 50.0;
    c.Kpc = 0.0;
    c.EnableDSC = dsc;
    c.ControlDifferenceQuantization = 0.1;
    for (const Row row : {Row{0.0, 0.0}, Row{0.05, 0.0}, Row{-0.099, 0.0}, Row{0.1, 0.1}, Row{0.25, 0.2},
                          Row{-0.25, -0.2}, Row{-0.31, -0.3}, Row{1.0, 1.0}}) {
      PositionController pc(c);
      const auto out = pc.update(input(0.0, 0.0, -row.e));  // first cycle: x_sym = 0, e = 0 − x_act
      EXPECT_DOUBLE_EQ(out.control_difference, row.e);
      if (dsc) {
        EXPECT_NEAR(out.dsc_position_error, row.e_q, 1e-12) << row.e;
      } else {
        EXPECT_NEAR(out.velocity_setpoint, 50.0 * row.e_q, 1e-10) << row.e;
      }
    }
  }
  PositionControlConfig invalid;
  invalid.ControlDifferenceQuantization = -0.1;
  EXPECT_EQ(PositionController().configure(invalid), PositionControlConfigResult::kInvalidParameter);
}

// ---- closed loop against the speed-loop plant ----

struct RampResult {
  double following_error;
  double control_difference;
  double velocity;
};

RampResult run_ramp(const PositionControlConfig& c, double plant_tvtc, std::size_t plant_dead_cycles,
                    double v, int cycles) {
  PositionController pc(c);
  SpeedLoopPlant plant(plant_tvtc, c.ServoCycle, plant_dead_cycles);
  PositionControlOutput out;
  for (int k = 0; k < cycles; ++k) {
    out = pc.update(input(v * c.ServoCycle * k, v, plant.position()));
    plant.step(out.velocity_setpoint);
  }
  return {out.following_error, out.control_difference, plant.velocity()};
}

// spec 02 §7.4 (steady state with full precontrol: e = v·T_vtc).
TEST(PositionControllerClosedLoop, FullPrecontrolSteadyStateErrorIsVelocityTimesTvtc) {
  PositionControlConfig c;
  c.ServoCycle = 0.001;
  c.Kv = 50.0;
  c.Kpc = 100.0;
  c.VelocityTimeConstant = 0.002;
  c.Tdc = 0.002;  // the plant's two-cycle dead time
  const double v = 200.0;
  const auto r = run_ramp(c, 0.002, 2, v, 3000);
  EXPECT_NEAR(r.velocity, v, 1e-6);
  EXPECT_NEAR(r.following_error, v * 0.002, 1e-6);  // 0.4 mm
  EXPECT_NEAR(r.control_difference, 0.0, 1e-6);
}

// spec 02 §7.4 (steady state without precontrol: e = v/Kv).
TEST(PositionControllerClosedLoop, NoPrecontrolSteadyStateErrorIsVelocityOverKv) {
  PositionControlConfig c;
  c.ServoCycle = 0.002;
  c.Kv = 25.0;
  c.Kpc = 0.0;
  c.VelocityTimeConstant = 0.004;
  const double v = 100.0;
  const auto r = run_ramp(c, 0.004, 0, v, 3000);
  EXPECT_NEAR(r.following_error, v / 25.0, 1e-6);  // 4 mm
  EXPECT_NEAR(r.control_difference, v / 25.0, 1e-6);
}

// spec 02 §7.4 (3), (5a) (kpc blends both errors).
TEST(PositionControllerClosedLoop, PartialPrecontrolBlendsBothErrors) {
  PositionControlConfig c;
  c.ServoCycle = 0.001;
  c.Kv = 40.0;
  c.Kpc = 50.0;
  c.VelocityTimeConstant = 0.003;
  const double v = 100.0;
  const auto r = run_ramp(c, 0.003, 0, v, 4000);
  EXPECT_NEAR(r.following_error, 0.5 * v * 0.003 + 0.5 * v / 40.0, 1e-6);  // 1.4 mm
  EXPECT_NEAR(r.control_difference, 0.5 * v / 40.0, 1e-6);
}

// spec 02 §7.4, §6.1 (a move converges; positioning monitoring reports Done).
TEST(PositionControllerClosedLoop, PositioningMoveConvergesAndPositioningMonitoringReportsDone) {
  PositionControlConfig c;
  c.ServoCycle = 0.001;
  c.Kv = 50.0;
  c.Kpc = 100.0;
  c.VelocityTimeConstant = 0.002;
  c.Tdc = 0.001;
  PositionController pc(c);
  SpeedLoopPlant plant(0.002, c.ServoCycle, 1);
  PositioningMonitor pm(PositioningMonitoringConfig{0.001, 0.5, 0.01, c.ServoCycle});
  FollowingErrorMonitor fem(FollowingErrorMonitoringConfig{true, 2.0, 10.0, 10.0, 90.0, 500.0});
  const double v = 100.0;
  const int ramp_cycles = 1000;  // 0 -> 100 mm in 1 s
  PositioningStatus status;
  int done_cycle = -1;
  double max_fe = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const bool moving = k < ramp_cycles;
    const double x_set = moving ? v * 0.001 * k : 100.0;
    const double v_set = moving ? v : 0.0;
    const auto out = pc.update(input(x_set, v_set, plant.position()));
    plant.step(out.velocity_setpoint);
    max_fe = std::max(max_fe, std::fabs(out.following_error));
    EXPECT_EQ(fem.check(out.following_error, v_set).alarm, FollowingErrorAlarm::kNone) << k;
    if (k == ramp_cycles) pm.start(100.0);
    status = pm.update(plant.position());
    if (status.outcome == PositioningOutcome::kDone && done_cycle < 0) done_cycle = k;
  }
  EXPECT_EQ(status.outcome, PositioningOutcome::kDone);
  EXPECT_GT(done_cycle, ramp_cycles + 10);  // at least MinDwellTime after the end of interpolation
  EXPECT_LT(done_cycle, ramp_cycles + 500);
  EXPECT_NEAR(plant.position(), 100.0, 1e-6);
  EXPECT_NEAR(max_fe, v * 0.002, 0.05);  // the velocity step gives a small overshoot over v·T_vtc at most
}

}  // namespace
}  // namespace tomc::techobjects

namespace tomc::techobjects {
namespace {

// ---- PID option (issue 20, pid_regulator.hpp) ----

// Without precontrol on the speed-loop plant (2 ms lag, one cycle dead time), a ramp of 100 mm/s leaves
// e = v/Kv with the S7's P controller; the integral of the PID option removes it (spec 05b A.2 "I removes the
// steady error").
TEST(PositionControllerPid, RampErrorVanishesWithIntegral) {
  for (const double ti : {0.0, 0.1}) {
    PositionControlConfig c;
    c.Kv = 30.0;
    c.Kpc = 0.0;
    c.ServoCycle = 0.001;
    c.IntegralTime = ti;
    PositionController pc(c);
    SpeedLoopPlant plant(0.002, 0.001, 1);
    PositionControlOutput out;
    for (int k = 0; k < 8000; ++k) {
      out = pc.update(input(0.1 * k, 100.0, plant.position()));
      plant.step(out.velocity_setpoint);
    }
    if (ti == 0.0) {
      EXPECT_NEAR(out.control_difference, 100.0 / 30.0, 1e-3);
      EXPECT_EQ(out.pid.i, 0.0);
    } else {
      EXPECT_NEAR(out.control_difference, 0.0, 1e-3);
      EXPECT_NEAR(out.pid.i, 100.0, 1e-3);  // the integral carries the whole velocity
    }
  }
}

// Decision A8 (the PID is refused with DSC: the loop is in the drive).
TEST(PositionControllerPid, RejectedWithDscOrInvalid) {
  PositionControlConfig c;
  c.IntegralTime = 0.1;
  c.EnableDSC = true;
  PositionController pc;
  EXPECT_EQ(pc.configure(c), PositionControlConfigResult::kInvalidParameter);
  c.EnableDSC = false;
  c.DerivativeCycles = 0;
  EXPECT_EQ(pc.configure(c), PositionControlConfigResult::kInvalidParameter);
  c.DerivativeCycles = 4;
  EXPECT_EQ(pc.configure(c), PositionControlConfigResult::kOk);
}

// FLdRP/FUpDRP: a loaded Kv acts from the update after apply_gains(), the integral is kept.
// Decision A8 (Pid.* are DIR: new gains take effect without resetting the integral).
TEST(PositionControllerPid, DoubleBufferedGainsKeepTheIntegral) {
  PositionControlConfig c;
  c.Kv = 10.0;
  c.Kpc = 0.0;
  c.IntegralTime = 0.01;
  c.ServoCycle = 0.001;
  PositionController pc(c);
  for (int k = 0; k < 5; ++k)
    (void)pc.update(input(1.0, 0.0, 0.0));  // e = 1: I grows by 1 per cycle
  PidGains g = pc.active_gains();
  g.Kv = 20.0;
  ASSERT_TRUE(pc.load_gains(g));
  EXPECT_DOUBLE_EQ(pc.update(input(1.0, 0.0, 0.0)).velocity_setpoint, 10.0 + 6.0);
  pc.apply_gains();
  EXPECT_DOUBLE_EQ(pc.update(input(1.0, 0.0, 0.0)).velocity_setpoint, 20.0 + 8.0);
}

}  // namespace
}  // namespace tomc::techobjects
