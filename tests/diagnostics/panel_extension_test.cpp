// The extension points of BasicAxisPanel that the positioning axis' panel uses (homing, positioning): extra
// capabilities, commands routed to extra_command(), extra instructions called in the cycle inside the
// PanelCall (so the TO accepts their jobs while the panel holds priority), their outputs in the status.
// The extension here drives a speed axis with a second MC_MoveVelocity standing in for a positioning job.
#include <gtest/gtest.h>

#include "diagnostics_fixture.hpp"

namespace {

using namespace tomc;
using diagnostics::PanelAnswer;
using diagnostics::PanelCommandKind;

class ExtendedPanel final : public diagnostics::BasicAxisPanel<techobjects::SpeedAxis> {
 public:
  using BasicAxisPanel::BasicAxisPanel;
  std::span<const std::string_view> instruction_names() const noexcept override { return kNames; }

 protected:
  std::uint32_t extra_capabilities() const noexcept override {
    return diagnostics::capability::kMoveRelative;
  }
  PanelAnswer extra_command(const diagnostics::PanelCommand& c) noexcept override {
    if (c.kind != PanelCommandKind::kMoveRelative) return PanelAnswer::kNotSupported;
    extra_.Velocity = c.direction * velocity();
    start(extra_);
    set_motion(diagnostics::PanelMotion::kPositioning);
    return PanelAnswer::kAccepted;
  }
  void call_extra() noexcept override {
    extra_(axis());
    end_when_idle(extra_);
  }
  void release_extra() noexcept override { extra_.Execute = false; }
  void watch_extra_errors() noexcept override { watch(extra_, extra_error_); }
  void extra_status(diagnostics::PanelStatus& out) const noexcept override {
    out.instructions[5] = {extra_.Busy, false, extra_.InVelocity, extra_.Error, extra_.ErrorID};
  }

 private:
  static constexpr std::array<std::string_view, 6> kNames{
      "MC_Power", "MC_MoveJog", "MC_MoveVelocity", "MC_Halt", "MC_Reset", "MC_MoveVelocity (extra)"};
  instructions::MC_MoveVelocity<techobjects::SpeedAxis> extra_;
  bool extra_error_ = false;
};

struct ExtendedMachine {
  ExtendedMachine() : runtime(techobjects::RuntimeConfig{0.001, 1, 1}), diagnostics({1, 256, 100}) {
    drives::DeviceConfig device;
    device.drive_telegram = 2;
    auto& io = runtime.add_device(
        std::make_unique<drives::SimulatedDrive>(device, drives::SimulatedDriveParameters{}));
    axis = &runtime.emplace<techobjects::SpeedAxis>("Axis1", &io, tomc::testing::diagnostics_axis_data());
    diagnostics.add(std::make_unique<diagnostics::TechnologyObjectView<techobjects::SpeedAxis>>(*axis),
                    std::make_unique<ExtendedPanel>(*axis));
    diagnostics.attach(runtime);
    runtime.start();
  }
  PanelAnswer command(PanelCommandKind kind, std::int32_t direction = 0, double value = 0.0) {
    diagnostics::PanelCommand c;
    c.session = 5;
    c.kind = kind;
    c.direction = direction;
    c.value = value;
    const auto request = diagnostics.post(c);
    runtime.step();
    return diagnostics.answer_of(request).value_or(PanelAnswer::kNoAnswer);
  }
  techobjects::Runtime runtime;
  diagnostics::Diagnostics diagnostics;
  techobjects::SpeedAxis* axis = nullptr;
};

// Decision W10 (panel functions by capability), spec 02 §9.2 (the job runs while the panel holds priority),
// docs/diagnostics.md "Axis control panel" (STOP halts the axis).
TEST(AxisPanelExtension, ExtraFunctionsRunThroughTheBase) {
  ExtendedMachine m;
  const auto* panel = m.diagnostics.panel(0);
  ASSERT_NE(panel, nullptr);
  EXPECT_NE(panel->capabilities() & diagnostics::capability::kMoveRelative, 0u);
  EXPECT_NE(panel->capabilities() & diagnostics::capability::kJog, 0u);
  EXPECT_EQ(panel->instruction_names().size(), 6u);
  ASSERT_EQ(m.command(PanelCommandKind::kTake), PanelAnswer::kAccepted);
  ASSERT_EQ(m.command(PanelCommandKind::kEnable), PanelAnswer::kAccepted);
  for (int i = 0; i < 50; ++i)
    m.runtime.step();
  EXPECT_EQ(m.command(PanelCommandKind::kMoveAbsolute), PanelAnswer::kNotSupported);
  ASSERT_EQ(m.command(PanelCommandKind::kMoveRelative, -1, 100.0), PanelAnswer::kAccepted);
  // 300 1/min (10 % of 3000) at 10 1/s²: 500 cycles; the job runs while the panel holds priority.
  for (int i = 0; i < 600; ++i)
    m.runtime.step();
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, -300.0);
  m.diagnostics.poll();
  const auto status = m.diagnostics.read(
      [](const diagnostics::Diagnostics::State& s) { return s.objects[0].snapshot.panel; });
  EXPECT_EQ(status.motion, diagnostics::PanelMotion::kPositioning);
  EXPECT_TRUE(status.instructions[5].busy);
  EXPECT_TRUE(status.instructions[5].active);  // InVelocity
  // STOP releases the extra job's input and halts the axis.
  ASSERT_EQ(m.command(PanelCommandKind::kStop), PanelAnswer::kAccepted);
  for (int i = 0; i < 100; ++i)
    m.runtime.step();
  EXPECT_DOUBLE_EQ(m.axis->data().Velocity, 0.0);
}

}  // namespace
