// Real-time discipline of the diagnostics layer: with Diagnostics attached (snapshots of every object in
// every cycle, the axis control panel taking commands and running its instructions, a 32-channel trace
// recording), Runtime::step() allocates nothing. A counting global operator new proves it; only allocations
// made inside step() are counted (the reader's side, poll(), allocates on purpose and runs between steps
// here).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "counting_allocator.hpp"
#include "diagnostics_fixture.hpp"
#include "gearing_fixture.hpp"
#include "positioning_panel_fixture.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace {

using namespace tomc;
using diagnostics::PanelCommandKind;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 5'000;
#else
constexpr int kCycles = 50'000;
#endif

// tomc's own: proves the counting allocator sees the diagnostics' set-up, so the zero of the cycle tests
// can fail.
TEST(DiagnosticsAllocation, CountingAllocatorSeesAllocations) {
  const auto before = tomc::testing::allocation_count();
  tomc::testing::DiagnosticsMachine m;
  m.diagnostics.poll();
  EXPECT_GT(tomc::testing::allocation_count(), before);
}

// ARCHITECTURE-GUIDE §2 (the RT side never waits for the web page) and §7 (no allocation in the cyclic
// path); 32 channels as docs/diagnostics.md "Traces".
TEST(DiagnosticsAllocation, CycleWithPanelSnapshotsAndTraceDoesNotAllocate) {
  tomc::testing::DiagnosticsMachine m(4, diagnostics::DiagnosticsConfig{1, 1024, 100});
  for (std::size_t i = 1; i < 4; ++i) {
    m.programs[i]->power.Enable = true;
    m.programs[i]->move.Velocity = 500.0 * static_cast<double>(i);
    m.programs[i]->run = true;
  }
  // A 32-channel trace of every object, triggered by the panel's axis reaching constant velocity.
  diagnostics::TraceRequest trace;
  const char* paths[] = {
      "Velocity",         "ActualSpeed",           "StatusWord",         "StatusWord.X12", "ErrorWord",
      "VelocitySetpoint", "telegram.drive.NIST_B", "telegram.drive.ZSW1"};
  for (int axis = 1; axis <= 4; ++axis) {
    for (const char* p : paths)
      trace.channels.push_back("Axis" + std::to_string(axis) + "." + p);
  }
  ASSERT_EQ(trace.channels.size(), 32u);
  trace.trigger = diagnostics::TriggerKind::kRisingEdge;
  trace.trigger_signal = "Axis1.StatusWord.X12";
  trace.pre_samples = 500;
  trace.post_samples = 2000;
  ASSERT_TRUE(m.diagnostics.start_trace(trace).empty());

  std::uint64_t in_cycle = 0;
  auto step = [&] {
    const auto before = tomc::testing::allocation_count();
    m.runtime.step();
    in_cycle += tomc::testing::allocation_count() - before;
  };
  auto post = [&](PanelCommandKind kind, std::int32_t direction = 0, double value = 0.0) {
    diagnostics::PanelCommand c;
    c.object = 0;
    c.session = 9;
    c.kind = kind;
    c.direction = direction;
    c.value = value;
    ASSERT_NE(m.diagnostics.post(c), 0u);
  };
  post(PanelCommandKind::kTake, 0, 60.0);
  post(PanelCommandKind::kEnable);
  int completed_traces = 0;
  for (int i = 0; i < kCycles; ++i) {
    // The panel jogs back and forth, changes its dynamics, stops; lifebeats keep it.
    if (i % 1000 == 100) post(PanelCommandKind::kJog, (i / 1000) % 2 == 0 ? +1 : -1);
    if (i % 1000 == 600) post(PanelCommandKind::kSetAdapt, 0, 50.0 + (i / 1000) % 100);
    if (i % 1000 == 800) post(PanelCommandKind::kJog, 0);
    if (i % 1000 == 900) post(PanelCommandKind::kMoveVelocity, +1);
    if (i % 1000 == 950) post(PanelCommandKind::kStop);
    if (i % 200 == 0) post(PanelCommandKind::kLifebeat);
    step();
    if (i % 20 == 0) {
      m.diagnostics.poll();  // the reader's side, outside the counted window
      const bool done = m.diagnostics.read([](const diagnostics::Diagnostics::State& s) {
        return s.trace.state == diagnostics::TraceCapture::State::kComplete;
      });
      if (done) {
        ++completed_traces;
        ASSERT_TRUE(m.diagnostics.start_trace(trace).empty());
      }
    }
  }
  EXPECT_EQ(in_cycle, 0u);
  EXPECT_GT(completed_traces, 0);
  EXPECT_TRUE(m.axes[0]->control_priority().held());
}

// The positioning axis' panel: homing (set position and active), absolute and relative positioning, jog and
// stop, in the cycle without allocation.
// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), over the panel functions of decisions W10/W17.
TEST(DiagnosticsAllocation, PositioningPanelDoesNotAllocate) {
  tomc::testing::PositioningDiagnosticsMachine m;
  std::uint64_t in_cycle = 0;
  auto post = [&](PanelCommandKind kind, std::int32_t direction = 0, double value = 0.0,
                  std::int32_t mode = 0) {
    diagnostics::PanelCommand c;
    c.session = 9;
    c.kind = kind;
    c.direction = direction;
    c.value = value;
    c.mode = mode;
    ASSERT_NE(m.diagnostics.post(c), 0u);
  };
  post(PanelCommandKind::kTake, 0, 60.0);
  post(PanelCommandKind::kEnable);
  for (int i = 0; i < kCycles / 5; ++i) {
    const int phase = i % 2000;
    if (phase == 100) post(PanelCommandKind::kHome, 0, 0.0, (i / 2000) % 2 == 0 ? 0 : 3);
    if (phase == 900) post(PanelCommandKind::kMoveAbsolute, 0, 20.0 * ((i / 2000) % 3));
    if (phase == 1400) post(PanelCommandKind::kMoveRelative, -1, 5.0);
    if (phase == 1700) post(PanelCommandKind::kJog, 1);
    if (phase == 1800) post(PanelCommandKind::kStop);
    if (i % 200 == 0) post(PanelCommandKind::kLifebeat);
    const auto before = tomc::testing::allocation_count();
    m.runtime.step();
    in_cycle += tomc::testing::allocation_count() - before;
    if (i % 20 == 0) m.diagnostics.poll();
  }
  EXPECT_EQ(in_cycle, 0u);
  EXPECT_TRUE(m.axis->control_priority().held());
}

// Issue 19: a camming follower's view (StatusSynchronizedMotion rows read from the synchronous operation) and
// its cam's view (its interpolation count), published in every cycle and traced, allocate nothing either.
struct SynchronousDiagnostics {
  diagnostics::Diagnostics d{{1, 1024, 100}};
  techobjects::Cam* cam = nullptr;
};
struct CammingDiagnosticsMachine : SynchronousDiagnostics, tomc::testing::GearingMachine {
  CammingDiagnosticsMachine()
      : GearingMachine(tomc::testing::virtual_linear(), tomc::testing::virtual_linear(), [this](auto& r) {
          cam = &r.template emplace<techobjects::Cam>("C", techobjects::CamVariant::kCam, 7);
          EXPECT_TRUE(cam->write_point(1, {0.0, 0.0}, true));
          EXPECT_TRUE(cam->write_point(2, {100.0, 50.0}, true));
          EXPECT_TRUE(cam->write_point(3, {200.0, 0.0}, true));
          d.add(*F);
          d.add(*cam);
          d.attach(r);
        }) {}
};

// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), over the synchronous view of decision W19.
TEST(DiagnosticsAllocation, SynchronousViewAndCamDoNotAllocate) {
  CammingDiagnosticsMachine m;
  ASSERT_TRUE(m.cam->interpolate_cam().accepted());
  diagnostics::TraceRequest trace;
  for (const char* p : {"F.StatusSynchronizedMotion.EffectiveLeadingValue.Position",
                        "F.StatusSynchronizedMotion.FunctionFollowingValue.Position",
                        "F.StatusSynchronizedMotion.FunctionState",
                        "F.StatusSynchronizedMotion.StatusWord.X4", "F.StatusWord.X22", "C.StatusWord.X0"})
    trace.channels.emplace_back(p);
  trace.post_samples = 1000;
  ASSERT_TRUE(m.d.start_trace(trace).empty());
  m.cam_in.Cam = m.cam;
  m.cam_in.SyncProfileReference = 2;
  m.cam_in.ApplicationMode = 1;
  m.cam_in.Execute = true;
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = m.move_L.Deceleration = 10000.0;
  m.move_L.Execute = true;
  std::uint64_t in_cycle = 0;
  for (int i = 0; i < kCycles / 5; ++i) {
    const auto before = tomc::testing::allocation_count();
    m.runtime.step();
    in_cycle += tomc::testing::allocation_count() - before;
    if (i % 20 == 0) m.d.poll();
  }
  EXPECT_EQ(in_cycle, 0u);
  EXPECT_TRUE(m.cam_in.InSync);
  EXPECT_EQ(m.d.read([](const auto& s) { return s.objects[1].snapshot.revision; }), 1u);
}

}  // namespace
