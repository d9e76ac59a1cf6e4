// The diagnostics views of TO_PositioningAxis and TO_ExternalEncoder (spec 04 §9.2, §9.3): every variable of
// their reflection tables published, the layout items evaluated on real objects, the positioning axis'
// telegram words (telegram 3: G1_XIST1 etc.); the positioning axis has a control panel with homing and
// positioning (positioning_panel_test.cpp), the external encoder none.
#include <gtest/gtest.h>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace {

using namespace tomc;
namespace to = tomc::techobjects;

double item(const diagnostics::Diagnostics& d, const diagnostics::ObjectSnapshot& s, std::size_t object,
            std::string_view area, std::string_view label) {
  std::size_t index = 0;
  for (const auto& a : diagnostics::diagnostics_layout(d.view(object).type())) {
    for (const auto& i : a.items) {
      if (a.title == area && i.label == label) return d.layout_items(object)[index].evaluate(s.values);
      ++index;
    }
  }
  ADD_FAILURE() << area << "/" << label;
  return -1.0;
}

// spec 04 §9.2 and §9.3 (the positioning axis' and the external encoder's diagnostics pages), decision W10
// (no panel on an encoder).
TEST(PositioningViews, PositioningAxisAndExternalEncoder) {
  to::Runtime runtime(to::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig axis_device;
  axis_device.drive_telegram = 3;
  drives::SimulatedDriveParameters axis_drive;
  axis_drive.load_units_per_revolution = 10.0;  // the default positioning axis: 10 mm per revolution
  auto& axis_io = runtime.add_device(std::make_unique<drives::SimulatedDrive>(axis_device, axis_drive));
  to::PositioningAxisData axis_data;
  axis_data.DynamicLimits.MaxJerk = 0.0;
  auto& axis = runtime.emplace<to::PositioningAxis>("Slide", &axis_io, axis_data);
  drives::DeviceConfig encoder_device;
  encoder_device.encoder_telegrams[0] = 81;
  drives::SimulatedDriveParameters encoder_drive;
  encoder_drive.load_units_per_revolution = 360.0;
  encoder_drive.encoder1.shaft = drives::SimulatedEncoderParameters::Shaft::kLoad;
  auto& encoder_io =
      runtime.add_device(std::make_unique<drives::SimulatedDrive>(encoder_device, encoder_drive));
  auto& encoder = runtime.emplace<to::ExternalEncoder>("Encoder", &encoder_io, to::ExternalEncoderData{});

  diagnostics::Diagnostics d({1, 256, 100});
  d.add(axis);
  d.add(encoder);
  instructions::MC_Power<to::PositioningAxis> power;
  instructions::MC_MoveVelocity<to::PositioningAxis> move;
  power.Enable = true;
  move.Velocity = 20.0;  // mm/s
  runtime.set_user_program([&](to::Runtime&) {
    power(axis);
    move.Execute = power.Status;
    move(axis);
  });
  d.attach(runtime);
  runtime.start();
  for (int i = 0; i < 1000; ++i)
    runtime.step();
  ASSERT_TRUE(power.Status);
  d.poll();
  const auto state = d.read([](const diagnostics::Diagnostics::State& s) { return s.objects; });
  ASSERT_EQ(state.size(), 2u);
  const auto& p = state[0].snapshot;
  EXPECT_EQ(d.view(0).type(), to::TechnologyObjectType::kPositioningAxis);
  EXPECT_EQ(p.values.size(), d.view(0).variables().size());
  for (std::size_t i = 0; i < p.values.size(); ++i) {
    const auto& v = d.view(0).variables()[i];
    const double now = v.read(axis.data());
    EXPECT_TRUE(p.values[i] == now || (std::isnan(now) && std::isnan(p.values[i]))) << v.path;
  }
  EXPECT_EQ(item(d, p, 0, "Axis status", "Enabled"), 1.0);
  EXPECT_EQ(item(d, p, 0, "Axis status", "Axis control panel active"), 0.0);
  EXPECT_DOUBLE_EQ(item(d, p, 0, "Setpoints", "Setpoint velocity"), axis.data().Velocity);
  EXPECT_DOUBLE_EQ(item(d, p, 0, "Actual values", "Actual position"), axis.data().ActualPosition);
  EXPECT_GT(axis.data().ActualPosition, 0.0);
  bool has_xist1 = false;
  for (const auto& c : d.view(0).telegram_channels())
    has_xist1 = has_xist1 || c.signal == telegrams::Signal::G1_XIST1;
  EXPECT_TRUE(has_xist1);
  ASSERT_NE(d.panel(0), nullptr);
  EXPECT_NE(d.panel(0)->capabilities() & diagnostics::capability::kMoveAbsolute, 0u);
  EXPECT_EQ(d.view(1).type(), to::TechnologyObjectType::kExternalEncoder);
  EXPECT_EQ(state[1].snapshot.values.size(), d.view(1).variables().size());
  EXPECT_DOUBLE_EQ(item(d, state[1].snapshot, 1, "Actual values", "Actual position"),
                   encoder.data().ActualPosition);
  EXPECT_EQ(d.panel(1), nullptr);
  // A trace probe on the positioning axis' encoder word.
  EXPECT_TRUE(d.view(0).probe("telegram.drive.G1_XIST1").has_value());
  EXPECT_TRUE(d.view(0).probe("StatusWord.X5").has_value());
}

}  // namespace
