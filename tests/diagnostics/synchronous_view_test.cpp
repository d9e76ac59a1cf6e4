// The synchronous axis' own view and the cam plot (issue 19 "Page"): StatusSynchronizedMotion (spec 07 §1.9)
// published with the positioning axis' rows, its areas evaluated on a follower camming with a known cam, the
// synchronous variables as trace probes, and the cam plot against the closed form of a polynomial cam.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <thread>

#include "gearing_fixture.hpp"
#include "tomc/diagnostics/cam_plot.hpp"
#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/diagnostics/synchronous_view.hpp"
#include "tomc/diagnostics/units.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace {

using namespace tomc;
namespace to = tomc::techobjects;

// The cam "Poly" (number 21): one segment y = 0.5·x + 0.001·x² on [0, 360] (spec 07 §3.1 segment form).
constexpr double kA1 = 0.5;
constexpr double kA2 = 0.001;
double poly(double x) {
  return kA1 * x + kA2 * x * x;
}

struct DiagnosticsHolder {
  diagnostics::Diagnostics d{{1, 256, 100}};  // a snapshot every cycle
  to::Cam* cam = nullptr;
};

// Spec 07 §8's machine (gearing_fixture.hpp) with the cam and the diagnostics attached before it starts.
struct SyncMachine : DiagnosticsHolder, tomc::testing::GearingMachine {
  SyncMachine()
      : GearingMachine(tomc::testing::virtual_linear(), tomc::testing::virtual_linear(),
                       [this](to::Runtime& r) {
                         cam = &r.emplace<to::Cam>("Poly", to::CamVariant::kCam, 21);
                         to::TO_Cam_Struct_SegmentData s;
                         s.xmin = 0.0;
                         s.xmax = 360.0;
                         s.a1 = kA1;
                         s.a2 = kA2;
                         EXPECT_TRUE(cam->write_segment(1, s, true));
                         d.add(*F);
                         d.add(*cam);
                         d.attach(r);
                       }) {
    EXPECT_TRUE(cam->interpolate_cam().accepted());
  }
  double item(std::size_t object, std::string_view area, std::string_view label) {
    const auto values = d.read([&](const auto& s) { return s.objects[object].snapshot.values; });
    std::size_t index = 0;
    for (const auto& a : diagnostics::diagnostics_layout(d.view(object).type())) {
      for (const auto& i : a.items) {
        if (a.title == area && i.label == label) return d.layout_items(object)[index].evaluate(values);
        ++index;
      }
    }
    ADD_FAILURE() << area << "/" << label;
    return -1.0;
  }
};

// plot_cam() with the cycle running beside it, as with the web server: it waits for a snapshot taken after
// it sampled.
std::variant<diagnostics::CamPlot, std::string> plot_while_running(SyncMachine& m, std::size_t object,
                                                                   std::size_t samples,
                                                                   std::chrono::milliseconds timeout) {
  std::atomic<bool> stop{false};
  std::thread cycle([&] {
    while (!stop.load())
      m.run(1);
  });
  auto result = diagnostics::plot_cam(m.d, object, samples, timeout);
  stop = true;
  cycle.join();
  return result;
}

TEST(SynchronousView, CammingFollowerShowsItsSynchronousOperation) {
  SyncMachine m;
  ASSERT_EQ(m.d.view(0).type(), to::TechnologyObjectType::kSynchronousAxis);
  EXPECT_EQ(diagnostics::type_name(m.d.view(0).type()), "TO_SynchronousAxis");
  EXPECT_EQ(m.d.view(0).leading_value_names(), (std::vector<std::string>{"L", "L2"}));
  // MC_CamIn profile 2 (direct), cyclic, then the leader runs at 100 mm/s (spec 07 §3.4).
  m.cam_in.Cam = m.cam;
  m.cam_in.SyncProfileReference = 2;
  m.cam_in.ApplicationMode = 1;
  m.cam_in.Execute = true;
  m.move_L.Velocity = 100.0;
  m.move_L.Acceleration = m.move_L.Deceleration = 10000.0;
  m.move_L.Execute = true;
  m.run(500);
  ASSERT_TRUE(m.cam_in.InSync);
  m.d.poll();
  const auto& sync = m.F->synchronized_motion();
  EXPECT_EQ(sync.FunctionState, 3);
  EXPECT_EQ(sync.ActualCam, 21);
  EXPECT_GT(sync.EffectiveLeadingValue.Position, 40.0);  // ~0.49 s at 100 mm/s
  // Every row, the synchronous ones included, as the snapshot of the last cycle shows it.
  const auto values = m.d.read([](const auto& s) { return s.objects[0].snapshot.values; });
  const auto table = m.d.view(0).variables();
  ASSERT_EQ(values.size(), table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& v = table[i];
    const double now =
        v.owner == to::TechnologyObjectType::kSynchronousAxis ? m.F->read(v.path) : v.read(m.F->data());
    EXPECT_TRUE(values[i] == now || (std::isnan(now) && std::isnan(values[i]))) << v.path;
  }
  EXPECT_EQ(m.item(0, "Synchronous operation", "Synchronous (StatusWord.X22)"), 1.0);
  EXPECT_EQ(m.item(0, "Synchronous operation", "Camming active"), 1.0);
  EXPECT_EQ(m.item(0, "Synchronous operation", "Gearing active"), 0.0);
  EXPECT_EQ(m.item(0, "Synchronous operation", "Synchronous job waiting"), 0.0);
  EXPECT_EQ(m.item(0, "Following value", "Active cam (ActualCam)"), 21.0);
  EXPECT_EQ(m.item(0, "Leading value", "Leading axis (ActualMaster)"), 1.0);
  EXPECT_DOUBLE_EQ(m.item(0, "Leading value", "Effective leading value position"),
                   sync.EffectiveLeadingValue.Position);
  // While synchronous the follower's function value is the cam of the function leading value (§3.3).
  const double x = std::fmod(sync.FunctionLeadingValue.Position, 360.0);
  EXPECT_NEAR(m.item(0, "Following value", "Function following value position"),
              sync.FunctionFollowingValue.Position, 0.0);
  EXPECT_NEAR(std::fmod(sync.FunctionFollowingValue.Position, poly(360.0)), poly(x), 1e-9);
  // The synchronous variables are trace signals (probes read the operation's status, not the data block).
  const auto probe = m.d.view(0).probe("StatusSynchronizedMotion.EffectiveLeadingValue.Velocity");
  ASSERT_TRUE(probe.has_value());
  EXPECT_DOUBLE_EQ(probe->value(), 100.0);
  const auto state = m.d.view(0).probe("StatusSynchronizedMotion.FunctionState");
  ASSERT_TRUE(state.has_value());
  EXPECT_EQ(state->value(), 3.0);
  EXPECT_TRUE(m.d.view(0).probe("StatusSynchronizedMotion.StatusWord.X4").has_value());
  EXPECT_FALSE(m.d.view(0).probe("StatusSynchronizedMotion.Nothing").has_value());
  // Units: follower-side offsets in the follower's unit, leader-side positions without one (spec 07 §1.2).
  const auto* offset = to::find_variable(table, "StatusSynchronizedMotion.Offset");
  const auto* leading = to::find_variable(table, "StatusSynchronizedMotion.EffectiveLeadingValue.Position");
  ASSERT_TRUE(offset != nullptr && leading != nullptr);
  EXPECT_EQ(diagnostics::quantity_of(*offset), diagnostics::Quantity::kPosition);
  EXPECT_EQ(diagnostics::quantity_of(*leading), diagnostics::Quantity::kNone);
  // The cam's own view: interpolated, in use by the follower, its definition range.
  EXPECT_EQ(m.item(1, "Cam status", "Interpolated (StatusWord.X5)"), 1.0);
  EXPECT_EQ(m.item(1, "Cam status", "In use by camming (StatusWord.X0)"), 1.0);
  EXPECT_EQ(m.item(1, "Definition range", "End leading value"), 360.0);
}

TEST(SynchronousView, FunctionStateNames) {
  // spec 07 §1.9: 0 none, 1 GearIn, 2 GearInPos, 3 CamIn, 4 GearOut, 5 CamOut, 6 GearInVel.
  EXPECT_EQ(diagnostics::function_state_name(0), "none");
  EXPECT_EQ(diagnostics::function_state_name(1), "gearing (MC_GearIn)");
  EXPECT_EQ(diagnostics::function_state_name(3), "camming (MC_CamIn)");
  EXPECT_EQ(diagnostics::function_state_name(5), "desynchronizing (MC_CamOut)");
  EXPECT_EQ(diagnostics::function_state_name(6), "velocity gearing (MC_GearInVelocity)");
  EXPECT_EQ(diagnostics::function_state_name(7), "?");
}

// The plot samples f, f', f'' of the interpolated form at evenly spaced leading values, end included.
// Decision W20 (f, f′, f″ at N evenly spaced leading values, end exact; N capped).
TEST(CamPlot, SamplesThePolynomialCamInClosedForm) {
  SyncMachine m;
  const auto result = plot_while_running(m, 1, 5, std::chrono::milliseconds(5000));
  const auto too_many = plot_while_running(m, 1, 100000, std::chrono::milliseconds(5000));
  const auto not_a_cam = plot_while_running(m, 0, 5, std::chrono::milliseconds(100));
  ASSERT_TRUE(std::holds_alternative<diagnostics::CamPlot>(result)) << std::get<std::string>(result);
  const auto& plot = std::get<diagnostics::CamPlot>(result);
  EXPECT_EQ(plot.start, 0.0);
  EXPECT_EQ(plot.end, 360.0);
  EXPECT_EQ(plot.revision, 1u);  // interpolated once
  ASSERT_EQ(plot.leading.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const double x = 90.0 * static_cast<double>(i);
    EXPECT_DOUBLE_EQ(plot.leading[i], x);
    EXPECT_NEAR(plot.position[i], poly(x), 1e-9) << x;
    EXPECT_NEAR(plot.velocity[i], kA1 + 2.0 * kA2 * x, 1e-12) << x;
    EXPECT_NEAR(plot.acceleration[i], 2.0 * kA2, 1e-12) << x;
  }
  ASSERT_TRUE(std::holds_alternative<diagnostics::CamPlot>(too_many));
  EXPECT_EQ(std::get<diagnostics::CamPlot>(too_many).leading.size(), diagnostics::kMaxCamSamples);
  EXPECT_TRUE(std::holds_alternative<std::string>(not_a_cam));
}

TEST(CamPlot, AnUninterpolatedCamIsRefused) {
  SyncMachine m;
  // Changing a point makes the cam's data differ from its interpolated form; a failed interpolation
  // (falling x, decisions C3) leaves it not interpolated.
  EXPECT_TRUE(m.cam->write_point(1, {10.0, 0.0}, true));
  EXPECT_TRUE(m.cam->write_point(2, {5.0, 0.0}, true));
  EXPECT_FALSE(m.cam->interpolate_cam().accepted());
  EXPECT_EQ(m.cam->interpolation_count(), 2u);
  const auto result = plot_while_running(m, 1, 5, std::chrono::milliseconds(5000));
  ASSERT_TRUE(std::holds_alternative<std::string>(result));
  EXPECT_NE(std::get<std::string>(result).find("not interpolated"), std::string::npos);
  EXPECT_TRUE(diagnostics::sample_cam(to::CamProfile{}, 10).leading.empty());
}

}  // namespace
