// Property test (issue 22): the fault matrix. One machine with every TO type on the simulated PROFIdrive
// drive — a speed axis S (telegram 2), a positioning axis P (telegram 3, active software limits), an external
// encoder E (telegram 83) and a synchronous axis F (telegram 3) that gears to P (setpoint coupling) or to E
// (actual-value coupling) — gets random jobs, and at random cycles one random fault on one random TO:
//   drive fault (ZSW1.3, reaction OFF1/OFF2/OFF3 at random), encoder error (Gx_ZSW.15), sign-of-life freeze,
//   sign-of-life jump (once: tolerated; twice: a failure), stale frames (the same bytes again), missing
//   frames, and, independently, windows in which the user program stops calling its MC_* instances.
// The faults sit between the adapter and the TO (FaultyLink), where a real link would break, or in the drive.
// The cause stays for a random time, is removed, and MC_Reset is called. Checked, each against its section:
//  F1 spec 02 §1.1, spec 04 §7 (docs/errors.md), spec 06 §5.2  the alarm of the fault is pending exactly from
//     the cycle the fault is detected, not one cycle earlier or later (a fault present at the start of cycle
//     k is read in MC_Servo of cycle k; "detection delay" below), with the TO's ErrorDetail.Reaction, and the
//     reaction "remove enable" takes effect in that cycle: StatusWord.X0 (Enable) FALSE;
//  F2 spec 02 §3.4, spec 06 §4  no setpoint moves an axis after its enable is removed other than the drive's
//     own stop ramp: from the cycle after detection every setpoint telegram requests no operation (STW1 bits
//     0..3 not all set) and the motor speed does not grow until the axis is enabled again;
//  F3 spec 02 §4.5  on the homed positioning axis, while it is enabled, the position setpoint never lies
//     beyond a software limit (further than it already was when it was enabled: a drive coasting to a stop
//     after its enable was removed may carry it past, and travel back in is then allowed);
//  F4 spec 07 §2.1 "Enable", §5.1, §1.10  followers: a fault of the setpoint-coupled leader P (its enable
//     removed by the alarm) does not end MC_GearIn and raises nothing on F while F stays on the gear line
//     (ΔF = N/D·ΔP); a fault of the actual-value leader E (its encoder error makes the leading value invalid)
//     raises alarm 601 on F in the same cycle with reaction 2 (stop with maximum dynamics) and ends
//     MC_GearIn;
//  F5 spec 01 §7, spec 03 §4.2  once the cause is gone, MC_Reset acknowledges every alarm (Done, ErrorWord 0)
//     and the MC_Power whose Enable stayed TRUE enables the axis again, within bounded cycles.
// Detection delays (cycles after the first faulty frame; DriveConnectionConfig defaults):
//   drive fault 0, encoder error 0, sign-of-life freeze or stale frame 1 (SignOfLifeMonitorConfig::tolerance
//   1: +10 per wrong counter, fault above 10, spec 06 §5.2), missing frames 3 (link_loss_tolerance_cycles 3:
//   the 4th missing frame), a single sign-of-life jump: never (one isolated error tolerated).
// A fixed base seed (TOMC_PROPERTY_SEED overrides it): a failure names its seed, cycle and the fault.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_gear_in.hpp"
#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/speed_axis/speed_axis.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace {

using namespace tomc;
namespace tg = tomc::telegrams;
using techobjects::AlarmReaction;
using techobjects::StatusWordBit;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 40'000;  // per seed; the sanitizers run the same code 10-50x slower
#else
constexpr int kCycles = 150'000;
#endif
constexpr int kSeeds = 2;
constexpr std::uint32_t kDefaultSeed = 20261127;
std::uint32_t base_seed() {
  const char* s = std::getenv("TOMC_PROPERTY_SEED");
  return s != nullptr ? static_cast<std::uint32_t>(std::strtoul(s, nullptr, 10)) : kDefaultSeed;
}

// ---- the link between a simulated drive and its TO, with the faults a real link has ----
class FaultyLink final : public drives::DriveAdapter {
 public:
  FaultyLink(const drives::DeviceConfig& config, const drives::SimulatedDriveParameters& parameters)
      : drive_(config, parameters), last_(drives::make_frames(config, tg::Direction::kActual)) {
    for (std::size_t i = 0; i < drives::kSlotCount; ++i) {
      const auto t = config.telegram(static_cast<drives::Slot>(i));
      if (t == 0) continue;
      actual_[i] = tg::TelegramCodec::create(t, tg::Direction::kActual, config.codec).value();
      setpoint_[i] = tg::TelegramCodec::create(t, tg::Direction::kSetpoint, config.codec).value();
    }
  }
  const drives::DeviceConfig& config() const noexcept override { return drive_.config(); }
  bool read_actual(drives::DeviceFrames& actual) noexcept override {
    drives::DeviceFrames fresh = last_;
    const bool arrived = drive_.read_actual(fresh);  // the drive runs its servo cycle in any case
    if (missing || !arrived) return false;
    if (stale && delivered_) {
      actual = last_;  // the same bytes again, as a link that repeats its buffer
      return true;
    }
    if (sign_of_life_jumps > 0) {
      --sign_of_life_jumps;
      jump_sign_of_life(fresh);
    }
    last_ = fresh;
    delivered_ = true;
    actual = fresh;
    return true;
  }
  void write_setpoint(const drives::DeviceFrames& setpoint) noexcept override {
    drive_.write_setpoint(setpoint);
    const auto& codec = setpoint_[0];
    if (codec.frame_size() != 0) (void)codec.decode(setpoint[drives::Slot::kDrive].view(), written_);
  }
  drives::LinkHealth link_health() const noexcept override { return drive_.link_health(); }

  drives::SimulatedDrive& drive() noexcept { return drive_; }
  const tg::SetpointSignals& written() const noexcept { return written_; }  // the last drive setpoint frame

  bool missing = false;        // no fresh frame arrives
  bool stale = false;          // the previous frame arrives again as fresh
  int sign_of_life_jumps = 0;  // the next frames' slave sign-of-life jumps ahead by 5

 private:
  void jump_sign_of_life(drives::DeviceFrames& frames) noexcept {
    const auto slot = actual_[0].frame_size() != 0 ? std::size_t{0} : std::size_t{2};  // drive or encoder 1
    tg::ActualSignals a;
    if (actual_[slot].decode(frames.slots[slot].view(), a) != tg::TelegramError::kNone) return;
    auto jump = [](auto& word) {
      const auto counter = word.field(tg::kSignOfLifeField);
      word.set_field(tg::kSignOfLifeField, static_cast<std::uint16_t>((counter + 4) % 15 + 1));  // 1..15, +5
    };
    if (slot == 0) {
      jump(a.ZSW2);
    } else {
      jump(a.ZSW2_ENC);
    }
    (void)actual_[slot].encode(a, frames.slots[slot].view());
  }

  drives::SimulatedDrive drive_;
  std::array<tg::TelegramCodec, drives::kSlotCount> actual_{};
  std::array<tg::TelegramCodec, drives::kSlotCount> setpoint_{};
  drives::DeviceFrames last_{};
  bool delivered_ = false;
  tg::SetpointSignals written_{};
};

enum class Fault {
  kDrive,
  kEncoder,
  kSignOfLifeFreeze,
  kSignOfLifeJumpOnce,
  kSignOfLifeJumpTwice,
  kStale,
  kMissing
};
constexpr std::array kFaults{Fault::kDrive,
                             Fault::kEncoder,
                             Fault::kSignOfLifeFreeze,
                             Fault::kSignOfLifeJumpOnce,
                             Fault::kSignOfLifeJumpTwice,
                             Fault::kStale,
                             Fault::kMissing};
const char* name_of(Fault f) {
  switch (f) {
    case Fault::kDrive:
      return "drive fault (ZSW1.3)";
    case Fault::kEncoder:
      return "encoder error (Gx_ZSW.15)";
    case Fault::kSignOfLifeFreeze:
      return "sign-of-life freeze";
    case Fault::kSignOfLifeJumpOnce:
      return "sign-of-life jump (once)";
    case Fault::kSignOfLifeJumpTwice:
      return "sign-of-life jump (twice)";
    case Fault::kStale:
      return "stale frames";
    case Fault::kMissing:
      return "missing frames";
  }
  return "";
}

// The alarm a fault raises on the TO that owns the link, and the cycles from the first faulty frame to its
// detection (-1: tolerated, no alarm).
struct Expectation {
  std::uint32_t alarm;
  int delay;
};
Expectation expectation(Fault f) {
  using namespace techobjects;
  switch (f) {
    case Fault::kDrive:
      return {kAlarmDriveFault, 0};
    case Fault::kEncoder:
      return {kAlarmSensorFault, 0};
    case Fault::kSignOfLifeFreeze:
    case Fault::kStale:
    case Fault::kSignOfLifeJumpTwice:
      return {kAlarmDriveSignOfLife, 1};
    case Fault::kSignOfLifeJumpOnce:
      return {kAlarmDriveSignOfLife, -1};
    case Fault::kMissing:
      return {kAlarmDriveCommunication, 3};
  }
  return {0, 0};
}

// Counts per fault and TO, printed at the end (the table of docs/reliability.md).
struct Tally {
  std::array<std::array<int, 4>, kFaults.size()> detected{};
  int leader_setpoint_faults = 0, leader_actual_faults = 0, silent_faults = 0, recoveries = 0;
  int secondary_alarms = 0;
  std::array<int, 4> tolerated{};  // single sign-of-life jumps that ran to their end without an alarm  //
                                   // alarms raised while enabling again, acknowledged by one more MC_Reset
};

enum class Phase { kRunning, kFaulted, kCleared, kResetting, kEnabling };
enum Target { kS = 0, kP = 1, kE = 2, kF = 3 };
const char* kTargetNames[] = {"S (speed axis)", "P (positioning axis)", "E (external encoder)",
                              "F (synchronous axis)"};

class Machine {
 public:
  explicit Machine(std::uint32_t seed)
      : seed_(seed), rng_(seed), runtime_(techobjects::RuntimeConfig{0.001, 1, 1}) {
    drives::SimulatedDriveParameters linear;
    linear.load_units_per_revolution = 10.0;  // mm, a 10 mm leadscrew
    techobjects::PositioningAxisData p;
    p.DynamicLimits.MaxJerk = 0.0;
    p.PositionLimits_SW.Active = true;  // ±1000 mm
    auto make = [&](std::uint16_t telegram, std::uint16_t encoder,
                    const drives::SimulatedDriveParameters& q) {
      drives::DeviceConfig c;
      c.drive_telegram = telegram;
      c.encoder_telegrams[0] = encoder;
      auto owned = std::make_unique<FaultyLink>(c, q);
      links_[count_] = owned.get();
      ++count_;
      return &runtime_.add_device(std::move(owned));
    };
    auto* s_io = make(2, 0, {});
    auto* p_io = make(3, 0, linear);
    drives::SimulatedDriveParameters encoder;
    encoder.load_units_per_revolution = 360.0;
    encoder.encoder1.shaft = drives::SimulatedEncoderParameters::Shaft::kLoad;
    auto* e_io = make(0, 83, encoder);
    auto* f_io = make(3, 0, linear);
    S_ = &runtime_.emplace<techobjects::SpeedAxis>("S", s_io, techobjects::SpeedAxisData{});
    P_ = &runtime_.emplace<techobjects::PositioningAxis>("P", p_io, p);
    E_ = &runtime_.emplace<techobjects::ExternalEncoder>("E", e_io, techobjects::ExternalEncoderData{});
    techobjects::PositioningAxisData f = p;
    f.PositionLimits_SW.Active = false;
    F_ = &runtime_.emplace<techobjects::SynchronousAxis>(
        "F", f_io, f,
        std::vector<techobjects::LeadingValueInterconnection>{
            {P_, P_, techobjects::LeadingValueCoupling::kSetpoint},
            {E_, E_, techobjects::LeadingValueCoupling::kActualValue}});
    runtime_.set_user_program([this](techobjects::Runtime&) { program(); });
    runtime_.start();
    s_power_.Enable = p_power_.Enable = e_power_.Enable = f_power_.Enable = true;
    for (int i = 0; i < 300 && !(s_power_.Status && p_power_.Status && f_power_.Status); ++i)
      runtime_.step();
    EXPECT_TRUE(s_power_.Status && p_power_.Status && f_power_.Status)
        << "the machine did not enable: S " << s_power_.Status << " P " << p_power_.Status << " F "
        << f_power_.Status << " alarms " << alarm_list();
    home(P_, p_home_);
    home(F_, f_home_);
  }

  void cycle(int k) {
    cycle_ = k;
    if (phase_ == Phase::kRunning && chance(0.002)) silent_ = chance(0.3);
    schedule();
    before();
    runtime_.step();
    after();
  }
  const Tally& tally() const { return tally_; }

 private:
  // ---- the user program ----
  void program() {
    if (silent_) return;  // the user program stops calling its instances (the TOs run on)
    s_power_(*S_);
    p_power_(*P_);
    e_power_(*E_);
    f_power_(*F_);
    s_reset_(*S_);
    p_reset_(*P_);
    e_reset_(*E_);
    f_reset_(*F_);
    p_home_(*P_);
    f_home_(*F_);
    s_move_(*S_);
    s_halt_(*S_);
    p_move_(*P_);
    p_velocity_(*P_);
    p_halt_(*P_);
    f_gear_(*F_);
    f_halt_(*F_);
  }
  void home(techobjects::PositioningAxis* axis, instructions::MC_Home<techobjects::PositioningAxis>& h) {
    h.Mode = 1;  // direct homing, relative by 0: the present position becomes homed (spec 03 §4.3)
    h.Position = 0.0;
    h.Execute = true;
    runtime_.step();
    h.Execute = false;
    runtime_.step();
    EXPECT_TRUE(techobjects::test(axis->data().StatusWord, StatusWordBit::kHomingDone)) << axis->name();
  }

  // ---- random jobs and the fault episodes ----
  void schedule() {
    switch (phase_) {
      case Phase::kRunning:
        random_jobs();
        if (chance(0.004)) start_fault();
        break;
      case Phase::kFaulted:
        if (cycle_ >= clear_at_) clear_fault();
        break;
      case Phase::kCleared:
        // MC_Reset once the cause is gone, which includes a drive still coasting after OFF2: an axis that
        // coasts on past its software limit after the acknowledge raises 534 again, rightly (spec 02 §4.5).
        ASSERT_LE(cycle_ - clear_at_, 6000) << where() << "the drives did not come to rest in 6 s";
        if (cycle_ == reset_at_ - 1) {
          // The program calls its instances again, first with Execute FALSE: an instance last called with
          // TRUE before the silence needs to see FALSE for the next edge.
          silent_ = false;
          for (auto* r : {&s_reset_.Execute, &p_reset_.Execute, &e_reset_.Execute, &f_reset_.Execute})
            *r = false;
        } else if (cycle_ >= reset_at_ && at_rest()) {
          for (auto* r : {&s_reset_.Execute, &p_reset_.Execute, &e_reset_.Execute, &f_reset_.Execute})
            *r = true;
          last_reset_ = cycle_;
          phase_ = Phase::kResetting;
          phase_since_ = cycle_;
          resets_ = 0;
        }
        break;
      case Phase::kResetting:
      case Phase::kEnabling:
        break;
    }
  }

  void random_jobs() {
    if (silent_) return;
    auto pulse = [&](bool& execute) { execute = !execute && chance(0.5); };
    // Jobs are edge-triggered: an Execute that stayed TRUE one cycle is taken back.
    for (bool* e : {&s_move_.Execute, &s_halt_.Execute, &p_move_.Execute, &p_velocity_.Execute,
                    &p_halt_.Execute, &f_halt_.Execute, &p_home_.Execute, &f_home_.Execute}) {
      if (*e) *e = false;
    }
    if (f_gear_.Execute && !chance(0.001)) {
      // MC_GearIn stays Busy while coupled: Execute stays TRUE too (a level a program would hold).
    } else {
      f_gear_.Execute = false;
    }
    if (!chance(0.01)) return;
    last_job_ = cycle_;
    switch (uniform_int(0, 7)) {
      case 0:
        s_move_.Velocity = uniform(-2500.0, 2500.0);
        pulse(s_move_.Execute);
        break;
      case 1:
        pulse(s_halt_.Execute);
        break;
      case 2:
        p_move_.Position = uniform(-1300.0, 1300.0);  // beyond the ±1000 mm software limits now and then
        p_move_.Velocity = uniform(20.0, 250.0);
        pulse(p_move_.Execute);
        break;
      case 3:
        p_velocity_.Velocity = uniform(-150.0, 150.0);
        pulse(p_velocity_.Execute);
        break;
      case 4:
        pulse(p_halt_.Execute);
        break;
      case 5: {
        if (f_gear_.Execute) {  // the next MC_GearIn needs an edge: its inputs are taken with it
          f_gear_.Execute = false;
          break;
        }
        const bool to_encoder = chance(0.4);
        f_gear_.Master = to_encoder ? static_cast<const techobjects::LeadingValueSource*>(E_) : P_;
        static constexpr std::array<std::array<int, 2>, 3> kRatios{{{1, 1}, {1, 2}, {-1, 1}}};
        const auto& r = kRatios[static_cast<std::size_t>(uniform_int(0, 2))];
        f_gear_.RatioNumerator = r[0];
        f_gear_.RatioDenominator = r[1];
        f_gear_.Execute = true;
        gear_master_ = f_gear_.Master;
        gear_ratio_ = static_cast<double>(r[0]) / r[1];
        break;
      }
      case 6:
        pulse(f_halt_.Execute);
        break;
      case 7:
        links_[kE]->drive().set_external_speed(chance(0.2) ? 0.0 : uniform(-150.0, 150.0));
        break;
    }
  }

  void start_fault() {
    // Only from a clean state: every TO enabled and without alarms.
    for (int t = 0; t < 4; ++t)
      if (alarm_count(t) != 0) return;
    if (!(enabled(kS) && enabled(kP) && enabled(kF))) return;
    // MC_Reset restarts the sign-of-life monitors (spec 06 §5.2): the exact detection cycles hold for a
    // monitor synchronised on good frames and with its error counter decayed (+10/-1: 10 frames).
    if (cycle_ - last_reset_ < 20) return;
    // A job of the last cycles (an MC_Halt of F, say) would still be taking effect: the fault comes alone.
    if (cycle_ - last_job_ < 10) return;
    fault_ = kFaults[static_cast<std::size_t>(uniform_int(0, static_cast<int>(kFaults.size()) - 1))];
    target_ = uniform_int(0, 3);
    if (fault_ == Fault::kEncoder && target_ == kS) target_ = kP;  // telegram 2: no encoder on S
    auto& link = *links_[target_];
    switch (fault_) {
      case Fault::kDrive: {
        if (target_ == kE) target_ = kP;  // an encoder-only device has no ZSW1
        using R = drives::SimulatedDriveParameters::FaultReaction;
        static constexpr std::array kReactions{R::kOff1, R::kOff2, R::kOff3};
        links_[target_]->drive().inject_fault(7900, kReactions[static_cast<std::size_t>(uniform_int(0, 2))]);
        break;
      }
      case Fault::kEncoder:
        link.drive().inject_encoder_error(1, tg::kEncoderErrorSensorGroup);
        break;
      case Fault::kSignOfLifeFreeze:
        link.drive().freeze_sign_of_life(true);
        break;
      case Fault::kSignOfLifeJumpOnce:
        link.sign_of_life_jumps = 1;
        break;
      case Fault::kSignOfLifeJumpTwice:
        link.sign_of_life_jumps = 2;
        break;
      case Fault::kStale:
        link.stale = true;
        break;
      case Fault::kMissing:
        link.missing = true;
        break;
    }
    const auto e = expectation(fault_);
    fault_cycle_ = cycle_;
    detect_at_ = e.delay < 0 ? -1 : cycle_ + e.delay;
    clear_at_ = cycle_ + std::max(e.delay, 0) + uniform_int(2, 400);
    leader_kind_ = LeaderKind::kNone;
    // The instance's outputs tell the coupling only while the program calls it.
    const bool in_gear = f_gear_.InGear && !silent_;
    if (in_gear && gear_master_ == P_ && target_ == kP) leader_kind_ = LeaderKind::kSetpoint;
    if (in_gear && gear_master_ == E_ && target_ == kE && e.delay >= 0) leader_kind_ = LeaderKind::kActual;
    if (silent_) ++tally_.silent_faults;
    phase_ = Phase::kFaulted;
    phase_since_ = cycle_;
  }

  void clear_fault() {
    auto& link = *links_[target_];
    link.drive().clear_injected_fault();
    link.drive().clear_encoder_error(1);
    link.drive().freeze_sign_of_life(false);
    link.missing = link.stale = false;
    link.sign_of_life_jumps = 0;
    phase_ = Phase::kCleared;
    reset_at_ = cycle_ + uniform_int(2, 60);
  }

  // ---- before the cycle: what the checks compare against ----
  void before() {
    for (int t : {kS, kP, kF}) {
      speed_before_[t] = std::fabs(links_[t]->drive().motor_speed_rpm());
      const double reference = links_[t]->drive().parameters().reference_speed_rpm;
      setpoint_before_[t] = std::fabs(tg::n4_to_speed(links_[t]->written().NSOLL_B, reference));
    }
    p_setpoint_before_ = P_->leading_value(techobjects::LeadingValueCoupling::kSetpoint).position;
    f_setpoint_before_ = F_->data().Position;
  }

  // ---- after the cycle: the properties ----
  void after() {
    if (phase_ == Phase::kFaulted || (phase_ == Phase::kCleared && detect_at_ >= 0 && cycle_ <= detect_at_)) {
      check_detection();
    }
    check_enable_removed();
    check_software_limits();
    check_followers();
    if (phase_ == Phase::kResetting) check_reset();
    if (phase_ == Phase::kEnabling) check_enabling();
  }

  void check_detection() {
    const auto e = expectation(fault_);
    const bool pending = pending_on(target_, e.alarm);
    if (detect_at_ < 0) {
      ASSERT_FALSE(pending) << where() << "a single sign-of-life error is tolerated (spec 06 §5.2)";
      if (cycle_ + 1 == clear_at_) ++tally_.tolerated[static_cast<std::size_t>(target_)];
      return;
    }
    if (cycle_ < detect_at_) {
      ASSERT_FALSE(pending) << where() << "alarm " << e.alarm << " before its detection cycle";
      return;
    }
    if (cycle_ != detect_at_) return;
    ASSERT_TRUE(pending) << where() << "alarm " << e.alarm << " not pending in its detection cycle";
    ++tally_.detected[static_cast<std::size_t>(fault_)][static_cast<std::size_t>(target_)];
    // spec 02 §1.1: the reaction of a remove-enable alarm in the same cycle.
    // (E shows 10 for "remove enable", spec 04 §14 item 7.)
    ASSERT_EQ(reaction_of(target_),
              target_ == kE ? 10 : static_cast<std::int32_t>(AlarmReaction::kRemoveEnable))
        << where();
    if (target_ != kE) {
      ASSERT_FALSE(techobjects::test(status_word(target_), StatusWordBit::kEnable)) << where();
      removed_since_[target_] = cycle_;
      // The motor may still reach the last speed setpoint sent before (the controller kept going on stale
      // actual values until the detection).
      // The telegram of the detection cycle itself was written in MC_Servo, before MC_Interpolator applied
      // the reaction: it may still carry such a setpoint, and the drive takes it in the next cycle.
      const double reference = links_[target_]->drive().parameters().reference_speed_rpm;
      const double written = std::fabs(tg::n4_to_speed(links_[target_]->written().NSOLL_B, reference));
      speed_at_removal_[target_] = std::max(
          {std::fabs(links_[target_]->drive().motor_speed_rpm()), setpoint_before_[target_], written});
    }
    if (leader_kind_ == LeaderKind::kActual) {
      // spec 07 §1.10: leading axis defective -> 601 with "stop with maximum dynamics" on the follower.
      ASSERT_TRUE(F_->alarms().pending(techobjects::kAlarmLeadingAxisDefective)) << where() << "no 601 on F";
      ASSERT_EQ(F_->data().ErrorDetail.Reaction, static_cast<std::int32_t>(AlarmReaction::kStopMaxDynamics));
      ++tally_.leader_actual_faults;
    }
    if (leader_kind_ == LeaderKind::kSetpoint) ++tally_.leader_setpoint_faults;
  }

  // F2: after the enable is removed, the setpoint telegram requests no operation and the motor slows down.
  void check_enable_removed() {
    for (int t : {kS, kP, kF}) {
      if (removed_since_[t] < 0) continue;
      if (reaction_of(t) != static_cast<std::int32_t>(AlarmReaction::kRemoveEnable)) {
        removed_since_[t] = -1;  // acknowledged by MC_Reset: the TO may enable the drive again (F5)
        continue;
      }
      if (cycle_ <= removed_since_[t]) continue;
      const auto stw1 = links_[t]->written().STW1.value();
      ASSERT_NE(stw1 & 0x000Fu, 0x000Fu) << where() << kTargetNames[t] << ": STW1 requests operation";
      const double speed = std::fabs(links_[t]->drive().motor_speed_rpm());
      // The drive's own ramp (or coasting) only slows the motor: 0.5 rpm for the speed loop's lag, and a
      // motor that was reversing may swing through zero within the standstill threshold (p1226). In the first
      // cycles the motor lags its accelerating setpoint (the detection cycle's telegram, then the speed-loop
      // time constant 2 ms, so 6 cycles): it may still gain up to 1 % there.
      const double threshold = links_[t]->drive().parameters().standstill_threshold_rpm;
      const double bound =
          cycle_ <= removed_since_[t] + 6 ? 1.01 * speed_at_removal_[t] : speed_before_[t] + 0.5;
      ASSERT_LE(speed, std::max(bound, threshold)) << where() << kTargetNames[t] << ": motor speeds up";
    }
  }

  // F3: software limits on P while it is enabled.
  void check_software_limits() {
    const auto& d = P_->data();
    const bool enabled = techobjects::test(d.StatusWord, StatusWordBit::kEnable);
    const bool homed = techobjects::test(d.StatusWord, StatusWordBit::kHomingDone);
    if (!enabled || !homed) {
      allowance_valid_ = false;
      return;
    }
    const double lo = d.PositionLimits_SW.MinPosition, hi = d.PositionLimits_SW.MaxPosition;
    if (!allowance_valid_) {  // enabled (again): how far outside it stands now
      below_ = std::max(0.0, lo - d.Position);
      above_ = std::max(0.0, d.Position - hi);
      allowance_valid_ = true;
    }
    ASSERT_GE(d.Position, lo - below_ - 1e-9) << where() << "P below MinPosition";
    ASSERT_LE(d.Position, hi + above_ + 1e-9) << where() << "P above MaxPosition";
    below_ = std::min(below_, std::max(0.0, lo - d.Position));  // travel back in narrows the allowance
    above_ = std::min(above_, std::max(0.0, d.Position - hi));
  }

  // F4: followers.
  void check_followers() {
    if (phase_ != Phase::kFaulted && phase_ != Phase::kCleared) return;
    const bool synchronous = techobjects::test(F_->data().StatusWord, StatusWordBit::kSynchronous);
    if (leader_kind_ == LeaderKind::kSetpoint && cycle_ >= fault_cycle_ && synchronous) {
      ASSERT_FALSE(F_->alarms().pending(techobjects::kAlarmLeadingAxisDefective)) << where();
      const double dx =
          P_->leading_value(techobjects::LeadingValueCoupling::kSetpoint).position - p_setpoint_before_;
      const double dy = F_->data().Position - f_setpoint_before_;
      ASSERT_NEAR(dy, gear_ratio_ * dx, 1e-6) << where() << "F left the gear line while P faulted";
    }
    if (leader_kind_ == LeaderKind::kSetpoint && cycle_ == detect_at_ && !silent_) {
      ASSERT_TRUE(f_gear_.Busy && !f_gear_.CommandAborted && !f_gear_.Error)
          << where() << "a leader's fault ended MC_GearIn (spec 07 §2.1: disabling the leader does not)";
    }
    if (leader_kind_ == LeaderKind::kActual && cycle_ == detect_at_ + 1 && !silent_) {
      ASSERT_FALSE(f_gear_.Busy) << where() << "MC_GearIn still coupled to a defective leader";
    }
  }

  // F5: MC_Reset acknowledges every alarm once the cause is gone.
  void check_reset() {
    ASSERT_FALSE(s_reset_.Error || p_reset_.Error || e_reset_.Error || f_reset_.Error)
        << where() << "MC_Reset Error";
    bool clean = true;
    for (int t = 0; t < 4; ++t)
      clean = clean && alarm_count(t) == 0;
    if (clean) {
      for (auto* r : {&s_reset_.Execute, &p_reset_.Execute, &e_reset_.Execute, &f_reset_.Execute})
        *r = false;
      phase_ = Phase::kEnabling;
      phase_since_ = cycle_;
      return;
    }
    ASSERT_LE(cycle_ - phase_since_, 20)
        << where() << "alarms still pending 20 cycles after MC_Reset: " << alarm_list();
  }
  void check_enabling() {
    bool clean = true;
    for (int t = 0; t < 4; ++t)
      clean = clean && alarm_count(t) == 0;
    if (!clean) {
      // An alarm of the re-enabling itself, e.g. 521 on F when P's setpoint steps as P is enabled again
      // (spec 07 §1.3: "a following error may result"): one more MC_Reset, a bounded number of times.
      ASSERT_LT(++resets_, 4) << where() << "alarms keep coming back after MC_Reset: " << alarm_list();
      ++tally_.secondary_alarms;
      for (auto* r : {&s_reset_.Execute, &p_reset_.Execute, &e_reset_.Execute, &f_reset_.Execute})
        *r = true;
      last_reset_ = cycle_;
      phase_ = Phase::kResetting;
      phase_since_ = cycle_;
      return;
    }
    const bool all = enabled(kS) && enabled(kP) && enabled(kF);
    if (all) {
      // Direct homing again where the fault took the homing (an incremental encoder's error).
      if (!techobjects::test(P_->data().StatusWord, StatusWordBit::kHomingDone)) home(P_, p_home_);
      if (!techobjects::test(F_->data().StatusWord, StatusWordBit::kHomingDone)) home(F_, f_home_);
      ++tally_.recoveries;
      phase_ = Phase::kRunning;
      return;
    }
    // The drive coasts to standstill (OFF2 from 3000 rpm takes about 3 s) before it can be switched on.
    ASSERT_LE(cycle_ - phase_since_, 6000)
        << where() << "not enabled again 6 s after MC_Reset: " << alarm_list();
  }

  // ---- helpers ----
  std::uint32_t status_word(int t) const {
    switch (t) {
      case kS:
        return S_->data().StatusWord;
      case kP:
        return P_->data().StatusWord;
      case kE:
        return E_->data().StatusWord;
      default:
        return F_->data().StatusWord;
    }
  }
  std::int32_t reaction_of(int t) const {
    switch (t) {
      case kS:
        return S_->data().ErrorDetail.Reaction;
      case kP:
        return P_->data().ErrorDetail.Reaction;
      case kE:
        return E_->data().ErrorDetail.Reaction;
      default:
        return F_->data().ErrorDetail.Reaction;
    }
  }
  const techobjects::AlarmList& alarms(int t) const {
    switch (t) {
      case kS:
        return S_->alarms();
      case kP:
        return P_->alarms();
      case kE:
        return E_->alarms();
      default:
        return F_->alarms();
    }
  }
  // Every drive whose TO is not enabled stands (the enabled ones may run their jobs).
  bool at_rest() {
    for (int t : {kS, kP, kF}) {
      auto& d = links_[t]->drive();
      if (!enabled(t) && std::fabs(d.motor_speed_rpm()) >= d.parameters().standstill_threshold_rpm)
        return false;
    }
    return true;
  }
  bool pending_on(int t, std::uint32_t number) const { return alarms(t).pending(number); }
  std::size_t alarm_count(int t) const { return alarms(t).alarms().size(); }
  bool enabled(int t) const { return techobjects::test(status_word(t), StatusWordBit::kEnable); }
  std::string alarm_list() const {
    std::string s;
    for (int t = 0; t < 4; ++t)
      for (const auto& a : alarms(t).alarms())
        s += std::string(kTargetNames[t]).substr(0, 1) + ":" + std::to_string(a.number) + " ";
    return s;
  }
  std::string where() const {
    char buf[256];
    std::snprintf(buf, sizeof buf, "seed %u, cycle %d, fault '%s' on %s from cycle %d%s, alarms [", seed_,
                  cycle_, name_of(fault_), kTargetNames[target_], fault_cycle_,
                  silent_ ? " (user program silent)" : "");
    return buf + alarm_list() + "]: ";
  }
  bool chance(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p; }
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int uniform_int(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }

  enum class LeaderKind { kNone, kSetpoint, kActual };

  std::uint32_t seed_;
  std::mt19937 rng_;
  techobjects::Runtime runtime_;
  std::array<FaultyLink*, 4> links_{};
  int count_ = 0;
  techobjects::SpeedAxis* S_ = nullptr;
  techobjects::PositioningAxis* P_ = nullptr;
  techobjects::ExternalEncoder* E_ = nullptr;
  techobjects::SynchronousAxis* F_ = nullptr;

  instructions::MC_Power<techobjects::SpeedAxis> s_power_;
  instructions::MC_Power<techobjects::PositioningAxis> p_power_;
  instructions::MC_Power<techobjects::ExternalEncoder> e_power_;
  instructions::MC_Power<techobjects::SynchronousAxis> f_power_;
  instructions::MC_Reset<techobjects::SpeedAxis> s_reset_;
  instructions::MC_Reset<techobjects::PositioningAxis> p_reset_;
  instructions::MC_Reset<techobjects::ExternalEncoder> e_reset_;
  instructions::MC_Reset<techobjects::SynchronousAxis> f_reset_;
  instructions::MC_Home<techobjects::PositioningAxis> p_home_;
  instructions::MC_Home<techobjects::PositioningAxis> f_home_;
  instructions::MC_MoveVelocity<techobjects::SpeedAxis> s_move_;
  instructions::MC_Halt<techobjects::SpeedAxis> s_halt_;
  instructions::MC_MoveAbsolute<techobjects::PositioningAxis> p_move_;
  instructions::MC_MoveVelocity<techobjects::PositioningAxis> p_velocity_;
  instructions::MC_Halt<techobjects::PositioningAxis> p_halt_;
  instructions::MC_GearIn<techobjects::SynchronousAxis> f_gear_;
  instructions::MC_Halt<techobjects::SynchronousAxis> f_halt_;

  int cycle_ = 0;
  bool silent_ = false;
  Phase phase_ = Phase::kRunning;
  int phase_since_ = 0;
  Fault fault_ = Fault::kDrive;
  int target_ = kS;
  int resets_ = 0;
  int last_reset_ = 0;
  int last_job_ = 0;
  int fault_cycle_ = 0, detect_at_ = -1, clear_at_ = 0, reset_at_ = 0;
  LeaderKind leader_kind_ = LeaderKind::kNone;
  const techobjects::LeadingValueSource* gear_master_ = nullptr;  // of the running MC_GearIn (its edge)
  double gear_ratio_ = 1.0;
  std::array<int, 4> removed_since_{-1, -1, -1, -1};
  std::array<double, 4> speed_before_{}, speed_at_removal_{}, setpoint_before_{};
  double p_setpoint_before_ = 0.0, f_setpoint_before_ = 0.0;
  bool allowance_valid_ = false;
  double below_ = 0.0, above_ = 0.0;
  Tally tally_;
};

// Properties F1–F5 of the file header: spec 02 §1.1, §3.4, §4.5, spec 04 §7, spec 06 §4, §5.2, spec 07
// §2.1, spec 01 §7; table in docs/reliability.md §1.
TEST(FaultMatrixProperty, AlarmsReactionsLimitsFollowersAndResetUnderRandomFaults) {
  Tally total;
  for (int s = 0; s < kSeeds; ++s) {
    const std::uint32_t seed = base_seed() + static_cast<std::uint32_t>(s);
    Machine m(seed);
    for (int k = 1; k <= kCycles && !::testing::Test::HasFatalFailure(); ++k)
      m.cycle(k);
    if (::testing::Test::HasFatalFailure()) return;
    const auto& t = m.tally();
    for (std::size_t f = 0; f < kFaults.size(); ++f)
      for (std::size_t o = 0; o < 4; ++o)
        total.detected[f][o] += t.detected[f][o];
    total.leader_setpoint_faults += t.leader_setpoint_faults;
    total.leader_actual_faults += t.leader_actual_faults;
    total.silent_faults += t.silent_faults;
    total.recoveries += t.recoveries;
    total.secondary_alarms += t.secondary_alarms;
    for (std::size_t o = 0; o < 4; ++o)
      total.tolerated[o] += t.tolerated[o];
  }
  std::printf("detected per fault (S P E F):\n");
  for (std::size_t f = 0; f < kFaults.size(); ++f) {
    std::printf("  %-28s %4d %4d %4d %4d\n", name_of(kFaults[f]), total.detected[f][0], total.detected[f][1],
                total.detected[f][2], total.detected[f][3]);
  }
  std::printf("  single sign-of-life jump tolerated (no alarm) %4d %4d %4d %4d\n", total.tolerated[0],
              total.tolerated[1], total.tolerated[2], total.tolerated[3]);
  std::printf(
      "leader faults under a follower: setpoint coupling %d, actual-value coupling %d; faults while the "
      "user program was silent %d; recoveries by MC_Reset %d (%d needed a second MC_Reset)\n",
      total.leader_setpoint_faults, total.leader_actual_faults, total.silent_faults, total.recoveries,
      total.secondary_alarms);
  // The run must have exercised what it claims.
  EXPECT_GT(total.recoveries, 20);
  EXPECT_GT(total.silent_faults, 0);
}

}  // namespace
