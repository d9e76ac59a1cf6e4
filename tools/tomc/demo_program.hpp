#pragma once
// The user program of `tomc demo`: a PLC-style loop per axis, forever.
//   - A speed axis runs through a list of velocities, each held for a dwell time (DemoAxisProgram).
//   - A positioning (or synchronous) axis is powered and homed (MC_Home Mode 0 "set position" or Mode 3
//     active homing), then positioned in a loop: MC_MoveAbsolute between a list of positions, or
//     MC_MoveRelative steps of one distance (a modulo axis turns on and on); a dwell time after each move
//     (DemoPositioningProgram).
//   - A synchronous axis with a cam in its program entry is powered, set to 0 (MC_Home Mode 0) and cams to
//   its
//     first leading value with MC_CamIn (direct synchronous setting, the configured application mode), so
//     that the page shows synchronous operation (DemoCammingProgram).
//   - An external encoder is enabled (DemoEncoderProgram).
// A program switch "<axis>.automatic" (shown on the page) takes an axis out of its loop: the program then
// disables it (MC_Power.Enable = FALSE), which is what the axis control panel needs before it can take master
// control (spec 02 §9.2, decision W15). Errors are acknowledged after a few seconds so that the demo recovers
// from faults injected while it runs. Runs in the cycle: noexcept, no allocation.

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "tomc/instructions/mc_cam_in.hpp"
#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_move_relative.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::cli {

// One program of the demo, called once per servo cycle by the user program.
class DemoProgram {
 public:
  static constexpr double kAcknowledgeAfterS = 5.0;

  virtual ~DemoProgram() = default;
  virtual void operator()(const techobjects::CycleClock& clock) noexcept = 0;
  // The program switch "<axis>.automatic"; nullptr for a program without one (an external encoder).
  virtual std::atomic<bool>* automatic() noexcept { return nullptr; }
};

struct DemoSequence {
  std::vector<double> velocities;  // in the axis' velocity unit; 0 = MC_Halt
  double dwell_s = 3.0;
};

class DemoAxisProgram final : public DemoProgram {
 public:
  DemoAxisProgram(techobjects::SpeedAxis& axis, DemoSequence sequence);
  std::atomic<bool>* automatic() noexcept override { return &automatic_; }
  const DemoSequence& sequence() const noexcept { return sequence_; }
  void operator()(const techobjects::CycleClock& clock) noexcept override;

 private:
  void start_step(std::size_t step) noexcept;

  techobjects::SpeedAxis& axis_;
  DemoSequence sequence_;
  std::atomic<bool> automatic_{true};
  instructions::MC_Power<techobjects::SpeedAxis> power_;
  instructions::MC_MoveVelocity<techobjects::SpeedAxis> move_;
  instructions::MC_Halt<techobjects::SpeedAxis> halt_;
  instructions::MC_Reset<techobjects::SpeedAxis> reset_;
  std::size_t step_ = 0;
  double step_time_s_ = 0.0;
  double error_time_s_ = 0.0;
  bool running_ = false;
};

struct DemoPositioning {
  std::int32_t home_mode = 0;  // MC_Home Mode: 0 set position, 3 active homing
  double home_position = 0.0;
  std::vector<double> positions;  // MC_MoveAbsolute targets in turn (when distance = 0)
  double distance = 0.0;          // != 0: MC_MoveRelative steps of this distance instead
  double velocity = -1.0;         // < 0: DynamicDefaults.Velocity
  double dwell_s = 1.0;           // after each move
};

class DemoPositioningProgram final : public DemoProgram {
 public:
  enum class Step : std::uint8_t { kDisabled, kHoming, kMoving, kDwell, kFault };

  DemoPositioningProgram(techobjects::PositioningAxis& axis, DemoPositioning plan);
  std::atomic<bool>* automatic() noexcept override { return &automatic_; }
  const DemoPositioning& plan() const noexcept { return plan_; }
  Step step() const noexcept { return step_; }
  std::size_t moves() const noexcept { return moves_; }  // completed moves
  void operator()(const techobjects::CycleClock& clock) noexcept override;

 private:
  void start_home() noexcept;
  void start_move() noexcept;
  void end_jobs() noexcept;

  techobjects::PositioningAxis& axis_;
  DemoPositioning plan_;
  std::atomic<bool> automatic_{true};
  instructions::MC_Power<techobjects::PositioningAxis> power_;
  instructions::MC_Home<techobjects::PositioningAxis> home_;
  instructions::MC_MoveAbsolute<techobjects::PositioningAxis> absolute_;
  instructions::MC_MoveRelative<techobjects::PositioningAxis> relative_;
  instructions::MC_Reset<techobjects::PositioningAxis> reset_;
  Step step_ = Step::kDisabled;
  std::size_t target_ = 0;
  std::size_t moves_ = 0;
  double step_time_s_ = 0.0;
  double error_time_s_ = 0.0;
};

struct DemoCamming {
  std::string cam;                    // the TO_Cam's name
  std::int32_t application_mode = 2;  // MC_CamIn.ApplicationMode: 0 not cyclic, 1 cyclic, 2 cyclic appending
};

class DemoCammingProgram final : public DemoProgram {
 public:
  enum class Step : std::uint8_t { kDisabled, kHoming, kCamming, kFault };

  // The leading value is the axis' first interconnection (spec 07 §1.2).
  DemoCammingProgram(techobjects::SynchronousAxis& axis, techobjects::Cam& cam,
                     std::int32_t application_mode);
  std::atomic<bool>* automatic() noexcept override { return &automatic_; }
  Step step() const noexcept { return step_; }
  void operator()(const techobjects::CycleClock& clock) noexcept override;

 private:
  techobjects::SynchronousAxis& axis_;
  std::atomic<bool> automatic_{true};
  instructions::MC_Power<techobjects::SynchronousAxis> power_;
  instructions::MC_Home<techobjects::SynchronousAxis> home_;
  instructions::MC_CamIn<techobjects::SynchronousAxis> cam_in_;
  instructions::MC_Reset<techobjects::SynchronousAxis> reset_;
  Step step_ = Step::kDisabled;
  double step_time_s_ = 0.0;
  double error_time_s_ = 0.0;
};

class DemoEncoderProgram final : public DemoProgram {
 public:
  explicit DemoEncoderProgram(techobjects::ExternalEncoder& encoder);
  void operator()(const techobjects::CycleClock& clock) noexcept override;

 private:
  techobjects::ExternalEncoder& encoder_;
  instructions::MC_Power<techobjects::ExternalEncoder> power_;
  instructions::MC_Reset<techobjects::ExternalEncoder> reset_;
  double error_time_s_ = 0.0;
};

}  // namespace tomc::cli
