#pragma once
// The diagnostics views of synchronous operation (issue 19 "Page"): a TO_SynchronousAxis with its own
// reflection table — the positioning axis' rows followed by StatusSynchronizedMotion.* (spec 07 §1.9), which
// lives in the axis' synchronous operation rather than in PositioningAxisData — and a TO_Cam with its scalar
// variables and the revision of its interpolated form, which the cam plot (cam_plot.hpp) samples.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tomc/diagnostics/object_view.hpp"
#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::diagnostics {

// Every row of a synchronous axis: positioning_axis_variables(), then the StatusSynchronizedMotion rows
// (owner kSynchronousAxis: ObjectView::source_of() reads them from the view's extension block).
std::span<const techobjects::VariableInfo> synchronous_axis_variables() noexcept;

// "none", "gearing (MC_GearIn)", ..., "camming (MC_CamIn)" for StatusSynchronizedMotion.FunctionState (and
// WaitingFunctionState); "?" for a value the manual does not list.
std::string_view function_state_name(std::int32_t state) noexcept;

class SynchronousAxisView final : public ObjectView {
 public:
  explicit SynchronousAxisView(const techobjects::SynchronousAxis& axis);
  std::string_view name() const noexcept override { return axis_.name(); }
  techobjects::TechnologyObjectType type() const noexcept override {
    return techobjects::TechnologyObjectType::kSynchronousAxis;
  }
  const void* data_block() const noexcept override { return &axis_.data(); }
  const void* extension_block() const noexcept override { return &axis_.synchronized_motion(); }
  const techobjects::AlarmList* alarms() const noexcept override { return &axis_.alarms(); }
  const techobjects::DriveConnection* drive() const noexcept override { return axis_.drive(); }
  // The configured leading values, index i = StatusSynchronizedMotion.ActualMaster i + 1 (spec 07 §1.2).
  std::vector<std::string> leading_value_names() const override { return leaders_; }

 private:
  const techobjects::SynchronousAxis& axis_;
  std::vector<std::string> leaders_;
};

class CamView final : public ObjectView {
 public:
  explicit CamView(const techobjects::Cam& cam) : cam_(cam) {}
  std::string_view name() const noexcept override { return cam_.name(); }
  techobjects::TechnologyObjectType type() const noexcept override {
    return techobjects::TechnologyObjectType::kCam;
  }
  const void* data_block() const noexcept override { return &cam_.data(); }
  const techobjects::AlarmList* alarms() const noexcept override { return nullptr; }
  const techobjects::DriveConnection* drive() const noexcept override { return nullptr; }
  std::uint64_t revision() const noexcept override { return cam_.interpolation_count(); }
  const techobjects::Cam* cam() const noexcept override { return &cam_; }

 private:
  const techobjects::Cam& cam_;
};

}  // namespace tomc::diagnostics
