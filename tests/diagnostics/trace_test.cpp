// Traces recorded in the cycle (trace.hpp): triggers, samples before the trigger, decimation, lost samples
// when the reader falls behind, early stop, and rejected requests.
#include <gtest/gtest.h>

#include <cmath>

#include "diagnostics_fixture.hpp"

namespace {

using namespace tomc;
using diagnostics::TraceCapture;
using diagnostics::TriggerKind;
using tomc::testing::DiagnosticsMachine;

TraceCapture capture(DiagnosticsMachine& m) {
  m.diagnostics.poll();
  return m.diagnostics.read([](const diagnostics::Diagnostics::State& s) { return s.trace; });
}

// Runs, polling every `poll_every` cycles, until the capture is complete (or `limit` cycles).
TraceCapture record(DiagnosticsMachine& m, int limit, int poll_every = 5) {
  for (int i = 0; i < limit; ++i) {
    m.run(1);
    if (i % poll_every == 0) {
      const auto c = capture(m);
      if (c.state == TraceCapture::State::kComplete || c.state == TraceCapture::State::kStopped) return c;
    }
  }
  return capture(m);
}

double value(const TraceCapture& c, std::size_t row, std::size_t channel) {
  return c.values[row * c.channels.size() + channel];
}

// Immediate trigger: the first sample after the cycle took the setup is the trigger; post_samples rows in
// consecutive cycles, each the value of that cycle.
// docs/diagnostics.md "Traces" (immediate trigger, post_samples rows in consecutive cycles); 3 1/min per
// cycle from DynamicDefaults.Acceleration 50 1/s² (spec 01 §8.2).
TEST(Trace, ImmediateRecordsConsecutiveCycles) {
  DiagnosticsMachine m;
  m.programs[0]->power.Enable = true;
  m.programs[0]->move.Velocity = 600.0;
  m.programs[0]->run = true;
  m.run(10);
  diagnostics::TraceRequest r;
  r.channels = {"Axis1.Velocity", "Axis1.StatusWord.X0", "Axis1.telegram.drive.NSOLL_B"};
  r.post_samples = 200;
  ASSERT_TRUE(m.diagnostics.start_trace(r).empty());
  const auto c = record(m, 400);
  ASSERT_EQ(c.state, TraceCapture::State::kComplete);
  ASSERT_EQ(c.rows(), 200u);
  EXPECT_EQ(c.trigger_row, 0u);
  EXPECT_EQ(c.lost, 0u);
  EXPECT_DOUBLE_EQ(c.sample_period_s, 0.001);
  for (std::size_t i = 1; i < c.rows(); ++i)
    EXPECT_EQ(c.cycles[i], c.cycles[0] + i);
  // DynamicDefaults.Acceleration 50 1/s² raises the speed setpoint by 3 1/min per 1 ms cycle.
  for (std::size_t i = 1; i < 100; ++i)
    EXPECT_NEAR(value(c, i, 0) - value(c, i - 1, 0), 3.0, 1e-9) << i;
  EXPECT_EQ(value(c, 0, 1), 1.0);
  EXPECT_GT(value(c, 199, 2), 0.0);
}

// A bit trigger with samples before it: the trigger row is the first cycle in which StatusWord.X12
// (ConstantVelocity) is set, and pre_samples rows precede it.
// Decision W13 (an edge needs a previous sample; pre_samples before the trigger row).
TEST(Trace, RisingEdgeWithPreTrigger) {
  DiagnosticsMachine m;
  diagnostics::TraceRequest r;
  r.channels = {"Axis1.Velocity", "Axis1.StatusWord.X12"};
  r.trigger = TriggerKind::kRisingEdge;
  r.trigger_signal = "Axis1.StatusWord.X12";
  r.pre_samples = 50;
  r.post_samples = 20;
  m.run(1);
  ASSERT_TRUE(m.diagnostics.start_trace(r).empty());
  m.programs[0]->power.Enable = true;
  m.programs[0]->move.Velocity = 600.0;
  m.programs[0]->run = true;
  const auto c = record(m, 1000);
  ASSERT_EQ(c.state, TraceCapture::State::kComplete);
  ASSERT_EQ(c.rows(), 70u);
  ASSERT_EQ(c.trigger_row, 50u);
  EXPECT_EQ(value(c, 49, 1), 0.0);
  EXPECT_EQ(value(c, 50, 1), 1.0);
  EXPECT_DOUBLE_EQ(value(c, 50, 0), 600.0);
  EXPECT_LT(value(c, 49, 0), 600.0);
  EXPECT_EQ(c.cycles[50], c.trigger_cycle);
  for (std::size_t i = 1; i < c.rows(); ++i)
    EXPECT_EQ(c.cycles[i], c.cycles[i - 1] + 1) << i << " trigger " << c.trigger_cycle;
}

// A value trigger with decimation: every 4th cycle, trigger when Velocity rises above 300.
// Decision W13 (above = previous ≤ threshold < current, evaluated on every decimation-th cycle).
TEST(Trace, ValueAboveWithDecimation) {
  DiagnosticsMachine m;
  diagnostics::TraceRequest r;
  r.channels = {"Axis1.Velocity"};
  r.trigger = TriggerKind::kAbove;
  r.trigger_signal = "Axis1.Velocity";
  r.threshold = 300.0;
  r.pre_samples = 5;
  r.post_samples = 10;
  r.decimation = 4;
  m.run(1);
  ASSERT_TRUE(m.diagnostics.start_trace(r).empty());
  m.programs[0]->power.Enable = true;
  m.programs[0]->move.Velocity = 600.0;
  m.programs[0]->run = true;
  const auto c = record(m, 1000);
  ASSERT_EQ(c.state, TraceCapture::State::kComplete);
  ASSERT_EQ(c.rows(), 15u);
  ASSERT_EQ(c.trigger_row, 5u);
  EXPECT_DOUBLE_EQ(c.sample_period_s, 0.004);
  for (std::size_t i = 1; i < c.rows(); ++i)
    EXPECT_EQ(c.cycles[i] - c.cycles[i - 1], 4u);
  EXPECT_LE(value(c, 4, 0), 300.0);
  EXPECT_GT(value(c, 5, 0), 300.0);
}

// The reader falls behind: the cycle drops samples (counted), it never waits. A ring of 64 rows, polled only
// after 500 cycles: 64 rows recorded, 436 lost, and the recording still completes.
// ARCHITECTURE-GUIDE §2 (the cycle never waits for the reader), docs/diagnostics.md "Traces" (dropped
// samples counted as lost).
TEST(Trace, LossesAreCountedWhenTheReaderFallsBehind) {
  DiagnosticsMachine m(1, diagnostics::DiagnosticsConfig{1, 64, 100});
  diagnostics::TraceRequest r;
  r.channels = {"Axis1.Velocity"};
  r.post_samples = 500;
  m.run(1);
  ASSERT_TRUE(m.diagnostics.start_trace(r).empty());
  m.run(600);
  const auto c = capture(m);
  EXPECT_EQ(c.state, TraceCapture::State::kComplete);
  EXPECT_EQ(c.rows(), 64u);
  EXPECT_EQ(c.lost, 436u);
  // The rows kept are the first 64 samples, in order.
  for (std::size_t i = 1; i < c.rows(); ++i)
    EXPECT_EQ(c.cycles[i], c.cycles[0] + i);
}

// Stopped before the trigger: the samples kept so far remain, with no trigger row.
// tomc's own: a stopped recording keeps its samples and shows no trigger row (docs/diagnostics.md
// "Traces").
TEST(Trace, StopBeforeTrigger) {
  DiagnosticsMachine m;
  diagnostics::TraceRequest r;
  r.channels = {"Axis1.Velocity"};
  r.trigger = TriggerKind::kRisingEdge;
  r.trigger_signal = "Axis1.StatusWord.X1";  // Error: never set here
  r.pre_samples = 30;
  r.post_samples = 10;
  m.run(1);
  ASSERT_TRUE(m.diagnostics.start_trace(r).empty());
  m.run(100);
  EXPECT_EQ(capture(m).state, TraceCapture::State::kWaitingForTrigger);
  m.diagnostics.stop_trace();
  m.run(2);
  const auto c = capture(m);
  EXPECT_EQ(c.state, TraceCapture::State::kStopped);
  EXPECT_EQ(c.rows(), 30u);
  EXPECT_EQ(c.trigger_row, c.rows());
}

// A new recording replaces the running one; rows of the old generation do not leak into it.
// tomc's own: one recording at a time; a new request replaces the running one (docs/diagnostics.md
// "Traces").
TEST(Trace, NewRecordingReplacesTheOld) {
  DiagnosticsMachine m;
  diagnostics::TraceRequest a;
  a.channels = {"Axis1.Velocity"};
  a.post_samples = 1000;
  m.run(1);
  ASSERT_TRUE(m.diagnostics.start_trace(a).empty());
  m.run(50);  // 50 rows of the first recording stay in the ring (no poll)
  diagnostics::TraceRequest b;
  b.channels = {"Axis1.StatusWord", "Axis1.Velocity"};
  b.post_samples = 20;
  ASSERT_TRUE(m.diagnostics.start_trace(b).empty());
  const std::uint64_t started = m.runtime.clock().servo_cycles;
  const auto c = record(m, 100);
  ASSERT_EQ(c.state, TraceCapture::State::kComplete);
  ASSERT_EQ(c.rows(), 20u);
  EXPECT_EQ(c.channels.size(), 2u);
  EXPECT_EQ(c.cycles[0], started);
}

// docs/diagnostics.md "Traces" (32 signals at most, known signals, at most 100,000 samples; one message per
// problem).
TEST(Trace, RequestsAreChecked) {
  DiagnosticsMachine m;
  diagnostics::TraceRequest r;
  EXPECT_FALSE(m.diagnostics.start_trace(r).empty());  // no channels
  r.channels.assign(33, "Axis1.Velocity");
  EXPECT_FALSE(m.diagnostics.start_trace(r).empty());  // too many
  r.channels = {"Axis9.Velocity", "Axis1.NoSuchVariable", "Velocity"};
  EXPECT_EQ(m.diagnostics.start_trace(r).size(), 3u);
  r.channels = {"Axis1.Velocity"};
  r.trigger = TriggerKind::kAbove;
  r.trigger_signal = "Axis1.Nope";
  EXPECT_EQ(m.diagnostics.start_trace(r).size(), 1u);
  r.trigger_signal = "Axis1.Velocity";
  r.threshold = std::nan("");
  EXPECT_EQ(m.diagnostics.start_trace(r).size(), 1u);
  r.threshold = 1.0;
  r.pre_samples = 90'000;
  r.post_samples = 20'000;
  EXPECT_EQ(m.diagnostics.start_trace(r).size(), 1u);
  r.pre_samples = 0;
  r.post_samples = 0;
  EXPECT_EQ(m.diagnostics.start_trace(r).size(), 1u);
  r.post_samples = 10;
  r.decimation = 0;
  EXPECT_EQ(m.diagnostics.start_trace(r).size(), 1u);
  r.decimation = 1;
  EXPECT_TRUE(m.diagnostics.start_trace(r).empty());
  // The cycle has not run since: the next request must wait until it took this one.
  const auto busy = m.diagnostics.start_trace(r);
  ASSERT_EQ(busy.size(), 1u);
  EXPECT_NE(busy[0].find("not yet taken"), std::string::npos);
  m.run(1);
  EXPECT_TRUE(m.diagnostics.start_trace(r).empty());
}

}  // namespace
