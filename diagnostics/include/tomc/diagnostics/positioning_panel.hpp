#pragma once
// The axis control panel of TO_PositioningAxis and TO_SynchronousAxis (spec 02 §9.3, §9.4; seed 004
// §7.5-§7.7): everything of the speed axis' panel (BasicAxisPanel: enable, jog, velocity, stop, acknowledge,
// dynamics, "Adapt velocity", lifebeat) plus
//   - homing: active homing (MC_Home Mode 3) and "set actual position" (MC_Home Mode 0), to a position;
//   - positioning: absolute (MC_MoveAbsolute) and relative (MC_MoveRelative) with the panel's dynamics.
// The instructions run in the cycle inside the PanelCall of the base, so the TO accepts their jobs while the
// user program's are rejected with 16#8012. Runs on the cycle's thread: noexcept, no allocation.

#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "tomc/diagnostics/panel.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_move_relative.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::diagnostics {

class PositioningAxisPanel final : public BasicAxisPanel<techobjects::PositioningAxis> {
 public:
  using BasicAxisPanel::BasicAxisPanel;
  std::span<const std::string_view> instruction_names() const noexcept override { return kNames; }

 protected:
  std::uint32_t extra_capabilities() const noexcept override {
    using namespace capability;
    return kHomeActive | kHomeSetPosition | kMoveAbsolute | kMoveRelative;
  }

  // One panel job at a time: a homing/positioning command drops the Execute inputs of the other two (the TO
  // aborts their jobs by the override matrix anyway); start() gives its own instruction a fresh edge.
  PanelAnswer extra_command(const PanelCommand& c) noexcept override {
    switch (c.kind) {
      case PanelCommandKind::kHome:
        if ((c.mode != 0 && c.mode != 3) || !std::isfinite(c.value)) return PanelAnswer::kInvalidValue;
        absolute_.Execute = relative_.Execute = false;
        home_.Mode = static_cast<std::int16_t>(c.mode);
        home_.Position = c.value;
        start(home_);
        set_motion(c.mode == 3 ? PanelMotion::kHoming : PanelMotion::kNone);  // Mode 0 moves nothing
        return PanelAnswer::kAccepted;
      case PanelCommandKind::kMoveAbsolute:
        if (!std::isfinite(c.value) || c.direction < -1 || c.direction > 1) return PanelAnswer::kInvalidValue;
        home_.Execute = relative_.Execute = false;
        absolute_.Position = c.value;
        // Modulo axes: 0 shortest path (MC Direction 3), +1 positive (1), -1 negative (2); ignored otherwise.
        absolute_.Direction = c.direction == 0 ? 3 : c.direction > 0 ? 1 : 2;
        apply(absolute_);
        start(absolute_);
        set_motion(PanelMotion::kPositioning);
        return PanelAnswer::kAccepted;
      case PanelCommandKind::kMoveRelative:
        if (!std::isfinite(c.value) || (c.direction != 1 && c.direction != -1))
          return PanelAnswer::kInvalidValue;
        home_.Execute = absolute_.Execute = false;
        relative_.Distance = c.direction * c.value;
        apply(relative_);
        start(relative_);
        set_motion(PanelMotion::kPositioning);
        return PanelAnswer::kAccepted;
      default:
        return PanelAnswer::kNotSupported;
    }
  }

  void call_extra() noexcept override {
    home_(axis());
    absolute_(axis());
    relative_(axis());
    // The page shows homing/positioning until the job ended (done, aborted by another job, or an error).
    const bool running = home_.Busy || absolute_.Busy || relative_.Busy;
    if (!running && (motion() == PanelMotion::kHoming || motion() == PanelMotion::kPositioning))
      set_motion(PanelMotion::kNone);
    end_when_idle(home_);
    end_when_idle(absolute_);
    end_when_idle(relative_);
  }

  void release_extra() noexcept override {
    home_.Execute = false;
    absolute_.Execute = false;
    relative_.Execute = false;
  }

  void watch_extra_errors() noexcept override {
    watch(home_, errors_[0]);
    watch(absolute_, errors_[1]);
    watch(relative_, errors_[2]);
  }

  void extra_status(PanelStatus& out) const noexcept override {
    out.instructions[5] = {home_.Busy, home_.Done, false, home_.Error, home_.ErrorID};
    out.instructions[6] = {absolute_.Busy, absolute_.Done, absolute_.Active, absolute_.Error,
                           absolute_.ErrorID};
    out.instructions[7] = {relative_.Busy, relative_.Done, relative_.Active, relative_.Error,
                           relative_.ErrorID};
  }

 private:
  static constexpr std::array<std::string_view, 8> kNames{
      "MC_Power", "MC_MoveJog", "MC_MoveVelocity", "MC_Halt",
      "MC_Reset", "MC_Home",    "MC_MoveAbsolute", "MC_MoveRelative"};

  // A positioning job of the panel: its velocity with "Adapt velocity", the panel's dynamics (spec 02 §9.3).
  template <typename Instruction>
  void apply(Instruction& fb) const noexcept {
    fb.Velocity = velocity();
    fb.Acceleration = dynamics().acceleration;
    fb.Deceleration = dynamics().deceleration;
    fb.Jerk = dynamics().jerk;
  }

  instructions::MC_Home<techobjects::PositioningAxis> home_;
  instructions::MC_MoveAbsolute<techobjects::PositioningAxis> absolute_;
  instructions::MC_MoveRelative<techobjects::PositioningAxis> relative_;
  std::array<bool, 3> errors_{};
};

}  // namespace tomc::diagnostics
