#pragma once
// The axis control panel (spec 02 §9, seed 004 §7.2-§7.8): a page takes control priority ("master control")
// over an axis, enables it, jogs it, runs it at a velocity, stops it, acknowledges its alarms, and, on axes
// that can, homes and positions it. The panel drives the axis through MC_* instances of its own, called in
// the cycle inside a ControlPriority::PanelCall, so that the same instructions and the same override matrix
// act as for the user program, whose jobs the TO meanwhile rejects with 16#8012.
//
// A lifebeat guards control priority: the page sends one periodically; when none arrived within the
// monitoring time, the axis is stopped with maximum deceleration (MC_Power Enable = FALSE, StopMode 2),
// 16#8013 is reported, and control priority returns to the user program once the axis is disabled
// (spec 02 §9.2 table "Online connection lost").
//
// Commands reach the cycle through Diagnostics (a lock-free queue); everything here runs on the cycle's
// thread: noexcept, no allocation.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_move_jog.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/axis/control_priority.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::diagnostics {

// What a panel can do on its axis (bit mask): the page shows and enables its controls by these.
namespace capability {
inline constexpr std::uint32_t kEnable = 1u << 0;           // enable / disable (MC_Power)
inline constexpr std::uint32_t kJog = 1u << 1;              // jog forwards / backwards (MC_MoveJog)
inline constexpr std::uint32_t kVelocity = 1u << 2;         // run at the panel velocity (MC_MoveVelocity)
inline constexpr std::uint32_t kStop = 1u << 3;             // stop (MC_Halt)
inline constexpr std::uint32_t kAcknowledge = 1u << 4;      // acknowledge alarms (MC_Reset)
inline constexpr std::uint32_t kAdaptVelocity = 1u << 5;    // "Adapt velocity" 1..200 % (spec 02 §9.3)
inline constexpr std::uint32_t kHomeActive = 1u << 6;       // active homing (MC_Home Mode 3)
inline constexpr std::uint32_t kHomeSetPosition = 1u << 7;  // set actual position (MC_Home Mode 0)
inline constexpr std::uint32_t kMoveAbsolute = 1u << 8;     // absolute positioning (MC_MoveAbsolute)
inline constexpr std::uint32_t kMoveRelative = 1u << 9;     // relative positioning (MC_MoveRelative)
}  // namespace capability

enum class PanelCommandKind : std::uint8_t {
  kTake,          // value = lifebeat monitoring time in s (0: the default)
  kGiveBack,      // disable (if enabled) and return control priority to the user program
  kLifebeat,      // the page is alive
  kEnable,        // MC_Power Enable = TRUE
  kDisable,       // MC_Power Enable = FALSE, StopMode 2
  kJog,           // direction +1 forwards, -1 backwards, 0 release
  kMoveVelocity,  // direction +1 / -1: run at the panel velocity
  kStop,          // mode 0: panel deceleration and jerk; mode 1: maximum (DynamicLimits)
  kAcknowledge,   // MC_Reset
  kSetDynamics,   // dynamics: velocity, acceleration, deceleration, jerk
  kSetAdapt,      // value = "Adapt velocity" in %, 1..200
  kHome,          // mode 3 active homing to value, mode 0 set the actual position to value
  kMoveAbsolute,  // value = target position; direction (modulo) 0 shortest, +1, -1
  kMoveRelative,  // value = distance; direction -1 travels it the other way
};

struct PanelDynamics {
  double velocity = 0.0;
  double acceleration = 0.0;
  double deceleration = 0.0;
  double jerk = 0.0;
};

struct PanelCommand {
  std::uint64_t request = 0;  // set by Diagnostics
  std::uint32_t object = 0;   // index of the technology object in Diagnostics
  std::uint64_t session = 0;  // the page's session key (control priority is held by one session)
  PanelCommandKind kind = PanelCommandKind::kLifebeat;
  std::int32_t direction = 0;
  std::int32_t mode = 0;
  double value = 0.0;
  PanelDynamics dynamics{};
};

// The cycle's answer to a command.
enum class PanelAnswer : std::uint8_t {
  kAccepted = 1,
  kNotSupported,         // this axis' panel has no such function
  kProgramControlsAxis,  // take: the user program has not released the axis (MC_Power.Enable = TRUE or
                         // enabled)
  kHeldByOtherSession,   // take: another page holds control priority
  kNotHolder,            // this session does not hold control priority
  kGivingBack,           // control priority is being returned: only lifebeats are taken
  kInvalidValue,         // a number out of range
  kUnknownObject,
  kNoPanel,    // the technology object has no control panel (e.g. an external encoder)
  kQueueFull,  // the command queue to the cycle is full (the cycle does not run, or too many commands)
  kNoAnswer,   // the cycle did not answer in time (it does not run)
};
std::string_view to_string(PanelAnswer answer) noexcept;
std::string_view to_string(PanelCommandKind kind) noexcept;

// What the panel currently asks of its axis.
enum class PanelMotion : std::uint8_t {
  kNone,
  kJogForward,
  kJogBackward,
  kVelocityForward,
  kVelocityBackward,
  kStopping,
  kHoming,
  kPositioning
};
std::string_view to_string(PanelMotion motion) noexcept;

struct InstructionOutputs {
  bool busy = false;
  bool done = false;
  bool active = false;  // MC_Power.Status, MC_MoveVelocity/MC_MoveJog.InVelocity
  bool error = false;
  std::uint16_t error_id = 0;
};

inline constexpr std::size_t kMaxPanelInstructions = 8;

struct PanelStatus {
  std::uint32_t capabilities = 0;
  bool held = false;
  bool giving_back = false;
  std::uint64_t session = 0;
  double lifebeat_s = 0.0;      // monitoring time
  double lifebeat_age_s = 0.0;  // time since the last lifebeat
  PanelDynamics dynamics{};
  double adapt_percent = 100.0;
  PanelMotion motion = PanelMotion::kNone;
  std::uint16_t error_id = 0;  // the panel's latest error: 16#8013, or an instruction's ErrorID
  std::uint64_t error_cycle = 0;
  std::array<InstructionOutputs, kMaxPanelInstructions> instructions{};  // in instruction_names() order
};

class AxisPanel {
 public:
  static constexpr double kDefaultLifebeatS = 1.5;  // spec 02 §9.2 recommends 1000..2000 ms
  static constexpr double kMinLifebeatS = 0.1;
  static constexpr double kMaxLifebeatS = 60.0;

  virtual ~AxisPanel() = default;
  virtual std::uint32_t capabilities() const noexcept = 0;
  virtual std::span<const std::string_view> instruction_names() const noexcept = 0;
  // The cycle: one command (validated here), then once per servo cycle.
  virtual PanelAnswer command(const PanelCommand& command) noexcept = 0;
  virtual void cycle(const techobjects::CycleClock& clock) noexcept = 0;
  virtual void status(PanelStatus& out) const noexcept = 0;
};

// The panel of every axis that has MC_Power, MC_MoveJog, MC_MoveVelocity, MC_Halt and MC_Reset,
// control_priority(), program_released() and data().DynamicLimits. Axis types with more functions (homing,
// positioning) derive from it:
//   - extra_capabilities(): their capability bits (kHomeActive, kHomeSetPosition, kMoveAbsolute, ...);
//   - extra_command(): take their commands (kHome, kMoveAbsolute, kMoveRelative) and start their instruction
//     with start(fb) (a fresh Execute edge), using velocity() and dynamics(); set_motion() for the page;
//   - call_extra(): call their instructions each cycle (already inside the PanelCall), then
//   end_when_idle(fb);
//   - release_extra(): drop their Execute inputs when the panel stops, disables or gives back;
//   - watch_extra_errors(): watch(fb, flag) per instruction, so that errors reach the page;
//   - instruction_names() and extra_status(): their outputs in PanelStatus::instructions[5..7].
template <typename Axis>
class BasicAxisPanel : public AxisPanel {
 public:
  explicit BasicAxisPanel(Axis& axis) noexcept : axis_(axis) {}

  std::uint32_t capabilities() const noexcept override {
    using namespace capability;
    return kEnable | kJog | kVelocity | kStop | kAcknowledge | kAdaptVelocity | extra_capabilities();
  }
  std::span<const std::string_view> instruction_names() const noexcept override { return kNames; }

  PanelAnswer command(const PanelCommand& c) noexcept override {
    if (c.kind == PanelCommandKind::kTake) return take(c);
    if (!held_ || c.session != session_) return PanelAnswer::kNotHolder;
    if (c.kind == PanelCommandKind::kLifebeat) {
      lifebeat_age_cycles_ = 0;
      return PanelAnswer::kAccepted;
    }
    if (giving_back_) return PanelAnswer::kGivingBack;
    switch (c.kind) {
      case PanelCommandKind::kGiveBack:
        begin_give_back();
        return PanelAnswer::kAccepted;
      case PanelCommandKind::kEnable:
        power_.Enable = true;
        return PanelAnswer::kAccepted;
      case PanelCommandKind::kDisable:
        release_motion();
        power_.Enable = false;
        return PanelAnswer::kAccepted;
      case PanelCommandKind::kJog:
        return jog(c.direction);
      case PanelCommandKind::kMoveVelocity:
        return move_velocity(c.direction);
      case PanelCommandKind::kStop:
        if (c.mode != 0 && c.mode != 1) return PanelAnswer::kInvalidValue;
        stop(c.mode == 1);
        return PanelAnswer::kAccepted;
      case PanelCommandKind::kAcknowledge:
        start(reset_);
        return PanelAnswer::kAccepted;
      case PanelCommandKind::kSetDynamics:
        return set_dynamics(c.dynamics);
      case PanelCommandKind::kSetAdapt:
        return set_adapt(c.value);
      default:
        return extra_command(c);
    }
  }

  void cycle(const techobjects::CycleClock& clock) noexcept override {
    if (!held_) return;
    cycle_ = clock.servo_cycles;
    servo_cycle_s_ = clock.servo_cycle_s;
    // The time since the last lifebeat, in whole cycles: a lifebeat taken in cycle c is 0 s old in c.
    const double age_s = static_cast<double>(lifebeat_age_cycles_) * clock.servo_cycle_s;
    ++lifebeat_age_cycles_;
    if (!giving_back_ && age_s > lifebeat_s_ + 1e-12) {
      // spec 02 §9.2: online connection lost and the lifebeat time elapsed -> 16#8013, stop with maximum
      // deceleration, control priority back to the user program.
      report_error(techobjects::error_id::kLifebeatExpired);
      begin_give_back();
    }
    {
      techobjects::ControlPriority::PanelCall call(axis_.control_priority());
      call_all();
    }
    // Execute-edge instructions: Execute stays TRUE while the job runs and falls when it has ended, so that
    // the next command gives a new edge.
    end_when_idle(reset_);
    if (!halt_.Busy) {
      halt_.Execute = false;
      if (motion_ == PanelMotion::kStopping) motion_ = PanelMotion::kNone;
    }
    if (!move_.Busy) {
      move_.Execute = false;
      if (motion_ == PanelMotion::kVelocityForward || motion_ == PanelMotion::kVelocityBackward)
        motion_ = PanelMotion::kNone;
    }
    watch_errors();
    if (giving_back_ && (axis_.program_released() || give_back_wait_s_ > kGiveBackTimeoutS))
      finish_give_back();
    if (giving_back_) give_back_wait_s_ += clock.servo_cycle_s;
  }

  void status(PanelStatus& out) const noexcept override {
    out.capabilities = capabilities();
    out.held = held_;
    out.giving_back = giving_back_;
    out.session = session_;
    out.lifebeat_s = lifebeat_s_;
    out.lifebeat_age_s = static_cast<double>(lifebeat_age_cycles_) * servo_cycle_s_;
    out.dynamics = dynamics_;
    out.adapt_percent = adapt_percent_;
    out.motion = motion_;
    out.error_id = error_id_;
    out.error_cycle = error_cycle_;
    out.instructions[0] = {power_.Busy, false, power_.Status, power_.Error, power_.ErrorID};
    out.instructions[1] = {jog_.Busy, false, jog_.InVelocity, jog_.Error, jog_.ErrorID};
    out.instructions[2] = {move_.Busy, false, move_.InVelocity, move_.Error, move_.ErrorID};
    out.instructions[3] = {halt_.Busy, halt_.Done, false, halt_.Error, halt_.ErrorID};
    out.instructions[4] = {reset_.Busy, reset_.Done, false, reset_.Error, reset_.ErrorID};
    extra_status(out);
  }

 protected:
  // ---- for axis types with more panel functions (homing, positioning) ----
  virtual std::uint32_t extra_capabilities() const noexcept { return 0; }
  virtual PanelAnswer extra_command(const PanelCommand&) noexcept { return PanelAnswer::kNotSupported; }
  virtual void call_extra() noexcept {}
  virtual void release_extra() noexcept {}  // stop, disable, give back: end the extra jobs' inputs
  virtual void watch_extra_errors() noexcept {}
  virtual void extra_status(PanelStatus&) const noexcept {}  // instructions[5..7]

  Axis& axis() noexcept { return axis_; }
  const PanelDynamics& dynamics() const noexcept { return dynamics_; }
  // The panel velocity with "Adapt velocity" applied (spec 02 §9.3: configured velocity x factor).
  double velocity() const noexcept { return dynamics_.velocity * adapt_percent_ / 100.0; }
  void set_motion(PanelMotion motion) noexcept { motion_ = motion; }
  PanelMotion motion() const noexcept { return motion_; }
  // A new job of an Execute-edge instruction: a falling edge first if Execute is still TRUE.
  template <typename Instruction>
  void start(Instruction& fb) noexcept {
    if (fb.Execute) {
      fb.Execute = false;
      techobjects::ControlPriority::PanelCall call(axis_.control_priority());
      fb(axis_);
    }
    fb.Execute = true;
  }
  template <typename Instruction>
  void watch(const Instruction& fb, bool& was_error) noexcept {
    if (fb.Error && !was_error) report_error(fb.ErrorID);
    was_error = fb.Error;
  }
  // An Execute-edge instruction whose job ended gets Execute = FALSE, so that the next command gives an edge.
  template <typename Instruction>
  static void end_when_idle(Instruction& fb) noexcept {
    if (!fb.Busy) fb.Execute = false;
  }
  void report_error(std::uint16_t error_id) noexcept {
    error_id_ = error_id;
    error_cycle_ = cycle_;
  }

 private:
  static constexpr std::array<std::string_view, 5> kNames{"MC_Power", "MC_MoveJog", "MC_MoveVelocity",
                                                          "MC_Halt", "MC_Reset"};
  static constexpr double kGiveBackTimeoutS = 30.0;  // priority returns even if the axis never disables

  PanelAnswer take(const PanelCommand& c) noexcept {
    if (c.session == 0) return PanelAnswer::kInvalidValue;
    const double lifebeat = c.value == 0.0 ? kDefaultLifebeatS : c.value;
    if (!(lifebeat >= kMinLifebeatS && lifebeat <= kMaxLifebeatS)) return PanelAnswer::kInvalidValue;
    if (held_) {
      if (c.session != session_) return PanelAnswer::kHeldByOtherSession;
      if (giving_back_) return PanelAnswer::kGivingBack;
      lifebeat_s_ = lifebeat;  // the holder adjusts its lifebeat time
      lifebeat_age_cycles_ = 0;
      return PanelAnswer::kAccepted;
    }
    // spec 02 §9.2 precondition: the TO is disabled by the user program (MC_Power.Enable = FALSE).
    if (!axis_.program_released()) return PanelAnswer::kProgramControlsAxis;
    axis_.control_priority().grant();
    held_ = true;
    giving_back_ = false;
    session_ = c.session;
    lifebeat_s_ = lifebeat;
    lifebeat_age_cycles_ = 0;
    error_id_ = 0;
    power_ = {};
    power_.StartMode = 1;
    power_.StopMode = 2;  // disable with maximum dynamics (spec 02 §9.2: "stopped with max deceleration")
    jog_ = {};
    move_ = {};
    halt_ = {};
    reset_ = {};
    errors_ = {};
    motion_ = PanelMotion::kNone;
    // spec 02 §9.3, seed 004 §7.4: 10 % of the velocity and acceleration limits, 100 % of deceleration and
    // jerk.
    const auto& l = axis_.data().DynamicLimits;
    dynamics_ = PanelDynamics{0.1 * l.MaxVelocity, 0.1 * l.MaxAcceleration, l.MaxDeceleration, l.MaxJerk};
    adapt_percent_ = 100.0;
    apply_dynamics();
    return PanelAnswer::kAccepted;
  }

  PanelAnswer jog(std::int32_t direction) noexcept {
    if (direction < -1 || direction > 1) return PanelAnswer::kInvalidValue;
    if (direction != 0) {
      move_.Execute = false;
      halt_.Execute = false;
    }
    jog_.JogForward = direction > 0;
    jog_.JogBackward = direction < 0;
    motion_ = direction > 0   ? PanelMotion::kJogForward
              : direction < 0 ? PanelMotion::kJogBackward
                              : PanelMotion::kNone;
    return PanelAnswer::kAccepted;
  }

  PanelAnswer move_velocity(std::int32_t direction) noexcept {
    if (direction != 1 && direction != -1) return PanelAnswer::kInvalidValue;
    jog_.JogForward = jog_.JogBackward = false;
    move_.Velocity = direction * velocity();
    start(move_);
    motion_ = direction > 0 ? PanelMotion::kVelocityForward : PanelMotion::kVelocityBackward;
    return PanelAnswer::kAccepted;
  }

  void stop(bool maximum) noexcept {
    release_motion();
    if (!power_.Status) return;  // nothing moves on a disabled axis: no MC_Halt (it would report 16#8103)
    const auto& l = axis_.data().DynamicLimits;
    halt_.Deceleration = maximum ? l.MaxDeceleration : dynamics_.deceleration;
    halt_.Jerk = maximum ? l.MaxJerk : dynamics_.jerk;
    start(halt_);
    motion_ = PanelMotion::kStopping;
  }

  PanelAnswer set_dynamics(const PanelDynamics& d) noexcept {
    const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
    if (!positive(d.velocity) || !positive(d.acceleration) || !positive(d.deceleration) ||
        !(std::isfinite(d.jerk) && d.jerk >= 0.0)) {
      return PanelAnswer::kInvalidValue;
    }
    dynamics_ = d;
    apply_dynamics();
    return PanelAnswer::kAccepted;
  }

  PanelAnswer set_adapt(double percent) noexcept {
    if (!(percent >= 1.0 && percent <= 200.0)) return PanelAnswer::kInvalidValue;  // spec 02 §9.3
    adapt_percent_ = percent;
    apply_dynamics();
    return PanelAnswer::kAccepted;
  }

  // New dynamics act at once on a jog (its velocity is live, spec 03 §3.4) and restart a velocity job.
  void apply_dynamics() noexcept {
    jog_.Velocity = velocity();
    jog_.Acceleration = move_.Acceleration = dynamics_.acceleration;
    jog_.Deceleration = move_.Deceleration = dynamics_.deceleration;
    jog_.Jerk = move_.Jerk = dynamics_.jerk;
    if (move_.Execute &&
        (motion_ == PanelMotion::kVelocityForward || motion_ == PanelMotion::kVelocityBackward)) {
      move_.Velocity = (motion_ == PanelMotion::kVelocityForward ? 1.0 : -1.0) * velocity();
      start(move_);
    }
  }

  void release_motion() noexcept {
    jog_.JogForward = jog_.JogBackward = false;
    move_.Execute = false;
    release_extra();
    motion_ = PanelMotion::kNone;
  }

  void begin_give_back() noexcept {
    release_motion();
    power_.Enable = false;
    power_.StopMode = 2;
    giving_back_ = true;
    give_back_wait_s_ = 0.0;
  }

  void finish_give_back() noexcept {
    axis_.control_priority().give_back();
    held_ = false;
    giving_back_ = false;
    session_ = 0;
    motion_ = PanelMotion::kNone;
  }

  void call_all() noexcept {
    power_(axis_);
    reset_(axis_);
    jog_(axis_);
    move_(axis_);
    halt_(axis_);
    call_extra();
  }

  void watch_errors() noexcept {
    watch(power_, errors_[0]);
    watch(jog_, errors_[1]);
    watch(move_, errors_[2]);
    watch(halt_, errors_[3]);
    watch(reset_, errors_[4]);
    watch_extra_errors();
  }

  Axis& axis_;
  instructions::MC_Power<Axis> power_;
  instructions::MC_MoveJog<Axis> jog_;
  instructions::MC_MoveVelocity<Axis> move_;
  instructions::MC_Halt<Axis> halt_;
  instructions::MC_Reset<Axis> reset_;
  std::array<bool, 5> errors_{};
  bool held_ = false;
  bool giving_back_ = false;
  std::uint64_t session_ = 0;
  double lifebeat_s_ = kDefaultLifebeatS;
  std::uint64_t lifebeat_age_cycles_ = 0;
  double servo_cycle_s_ = 0.001;
  double give_back_wait_s_ = 0.0;
  PanelDynamics dynamics_{};
  double adapt_percent_ = 100.0;
  PanelMotion motion_ = PanelMotion::kNone;
  std::uint16_t error_id_ = 0;
  std::uint64_t error_cycle_ = 0;
  std::uint64_t cycle_ = 0;
};

}  // namespace tomc::diagnostics
