#pragma once
// Control priority ("master control") of the axis control panel (spec 02 §9.2, seed 004 §7.2): while the
// panel holds it, only the panel moves the axis, jobs from the user program are rejected with ErrorID
// 16#8012, and StatusWord.X4 ControlPanelActive is TRUE. Every axis TO type owns one and asks it at each job
// entry point; the panel (diagnostics/) brackets its own instruction calls with a PanelCall so that they get
// through. Plain data on the cycle's thread: no atomics, no allocation.

#include <cstdint>

#include "tomc/techobjects/axis/error_ids.hpp"

namespace tomc::techobjects {

class ControlPriority {
 public:
  // ---- the panel ----
  // The TO decides whether the user program has released the axis (its take_control_priority()); these only
  // record the state.
  void grant() noexcept { held_ = true; }
  void give_back() noexcept {
    held_ = false;
    panel_calling_ = false;
  }
  bool held() const noexcept { return held_; }

  // The panel's own instruction calls, as a scope: `ControlPriority::PanelCall
  // call(axis.control_priority());`
  class PanelCall {
   public:
    explicit PanelCall(ControlPriority& priority) noexcept : priority_(priority) {
      priority_.panel_calling_ = true;
    }
    ~PanelCall() { priority_.panel_calling_ = false; }
    PanelCall(const PanelCall&) = delete;
    PanelCall& operator=(const PanelCall&) = delete;

   private:
    ControlPriority& priority_;
  };

  // ---- the technology object ----
  // 16#8012 for a job of the user program while the panel holds priority; 0 when the job may go on.
  std::uint16_t program_job_rejection() const noexcept {
    return held_ && !panel_calling_ ? error_id::kControlPanelActive : error_id::kNone;
  }
  // Override.Velocity has no effect while the panel holds priority (spec 02 §9.3, seed 004 §7.4).
  bool override_ineffective() const noexcept { return held_; }

 private:
  bool held_ = false;
  bool panel_calling_ = false;
};

}  // namespace tomc::techobjects
