// Property test (issue 9): random gearing on TO_SynchronousAxis, driven through the MC_* instructions as a
// user program drives them. The follower F (virtual, linear or rotary modulo) has two or three possible
// leading values and gets MC_GearIn (two instances, so that one replaces the other), MC_GearInVelocity (with
// and without ContinuousUpdate and ratio changes), MC_GearInPos (profiles 0, 1, 3), MC_GearOut (profiles 0,
// 1, 5), MC_Halt, MC_Stop (Modes 0, 2), MC_MoveVelocity, MC_MoveAbsolute, MC_Power off/on and MC_Reset at
// random times, with random ratios (negative and fractional, now and then an illegal one) and random
// dynamics. The leaders move at random: a positioning axis with random MC_MoveAbsolute / MC_MoveVelocity /
// MC_Halt jobs and dynamics; per scenario the leading value is that axis (linear, or rotary modulo with a
// modulo follower), an external encoder on a simulated encoder device turned at random speeds (actual-value
// coupling), or a synchronous axis that itself follows the positioning axis and gets random jobs (a chain L
// -> F1 -> F).
//
// Checked every cycle right after MC_Interpolator (the post-interpolator hook: what the follower generated
// from the leading value of the same cycle, spec 07 §6.1), each against the section it comes from:
//  G1 spec 07 §2.1, §2.2, §6.2  while StatusWord.X22 (Synchronous) holds for a position gearing (MC_GearIn,
//     MC_GearInPos: FunctionState 1, 2), the follower's setpoint lies on the gear line: from the first
//     synchronous cycle of the coupling on, Δy = N/D·Δx for the continuous setpoint, and the data block's
//     Position does so modulo the follower's Modulo.Length; velocity = N/D·v_x and acceleration = N/D·a_x of
//     the leading value. Tolerance 1e-6 in position (spec 07 §8: "position tolerances are ±1e-6 after lock"),
//     1e-9 relative in velocity and acceleration (the gear line is evaluated in double precision: y_sync +
//     N·(x − x_sync)/D, spec 07 §6.2, so what remains is rounding). For MC_GearInVelocity (FunctionState 6)
//     the velocity setpoint is N/D·v_x (spec 07 §2.3), same tolerance.
//  G2 spec 07 §2.1, §2.3, §2.4, §6.8  the follower's own DynamicLimits hold in every phase §6.8 limits:
//     MaxVelocity during MC_GearIn synchronization (X21, FunctionState 1) and outside synchronous operation;
//     MaxAcceleration while |v| grows and MaxDeceleration while it shrinks during MC_GearIn and
//     MC_GearInVelocity synchronization, MC_GearOut profile 0 and outside synchronous operation
//     (EmergencyDeceleration under an emergency ramp: MC_Stop Mode 0, MC_Power StopMode 0, spec 02 §3.1).
//     Not limited (the leader's dynamics pass through, §6.8): synchronous travel, MC_GearInPos
//     synchronization over a leading-value distance (profiles 1, 3), MC_GearOut profile 1, the velocity
//     during MC_GearInVelocity synchronization. MC_GearInPos profile 0, a leader-domain blend (decision Y6)
//     sized for the leader's velocity at the start (later leader dynamics pass through scaled, spec 07 §6.5
//     "superimposed"), is judged on its own (decision C23): MaxVelocity, MaxAcceleration / MaxDeceleration
//     and MaxJerk while the leader keeps its velocity of the start, above them only what the follower
//     carried in at its start. Leaving such a
//     phase the follower keeps its dynamics and the new motion brings them back (§2.1 "current dynamics are
//     blended into the new job"): the hand-over cycle (one step of the new motion from the synchronous state
//     of the same cycle, which is not observable) is not judged, and from then on a velocity or acceleration
//     above the limit is admissible only while it does not grow. A cycle through standstill is judged by
//     |v0|/MaxDeceleration + |v1|/MaxAcceleration <= T.
//  G3 spec 07 §1.9, §6.8  during synchronous travel the exceedance is indicated, not alarmed:
//     StatusSynchronizedMotion.StatusWord.X0 = |v| > MaxVelocity, X1 / X2 = |a| beyond MaxAcceleration /
//     MaxDeceleration while |v| grows / shrinks (X0..X2 all FALSE without synchronous operation), and no
//     alarm 501/502/503 is raised in a cycle of unbroken synchronous travel; MC_GearIn synchronization
//     raises no 501 (spec 07 §2.1: the velocity is limited without it).
//  G4 every value of the follower's data block the checks read, and of the leading value, is finite; the
//     handshake of every instance is consistent (spec 03 §3.2): never two of Done / Error / CommandAborted,
//     Busy FALSE with any of them, InGear / InSync / StartSync only while Busy.
// A fixed base seed (TOMC_PROPERTY_SEED overrides it) and a seed loop: a failure names its seed, scenario
// and cycle and prints the last events and cycles. Found and fixed with it: synchronization steps through
// standstill and jerk-limited synchronization from synchronous travel exceeding the follower's limits
// (synchronous_motion_test.cpp), MC_GearInPos profile 0 starting late with a setpoint step (decision Y12),
// MC_GearOut turning back to a stop position behind the follower (decisions Y11, Y13).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>

#include "alarm_watch.hpp"
#include "gearing_fixture.hpp"
#include "property_harness.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"

namespace {

using namespace tomc;
using techobjects::AlarmReaction;
using techobjects::StatusWordBit;
using techobjects::SynchronousAxis;
using tomc::testing::virtual_linear;
using tomc::testing::virtual_rotary_modulo;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 12'000;  // per run; the sanitizers run the same code 10-50x slower
#else
constexpr int kCycles = 200'000;  // per run: 1.6 million cycles in all
#endif
constexpr std::uint32_t kDefaultSeed = 20261124;
std::uint32_t base_seed() {
  return tomc::testing::property_base_seed(kDefaultSeed);
}
constexpr double kCycle = 0.001;

enum class LeaderKind { kAxis, kModulo, kEncoder, kChain };

const char* name_of(LeaderKind k) {
  switch (k) {
    case LeaderKind::kAxis:
      return "positioning-axis leader";
    case LeaderKind::kModulo:
      return "rotary modulo leader and follower";
    case LeaderKind::kEncoder:
      return "external-encoder leader (actual value)";
    case LeaderKind::kChain:
      return "chained follower as leader";
  }
  return "";
}

struct Stats {
  long synchronous_cycles = 0;       // G1 checks (position gearing)
  long velocity_gearing_cycles = 0;  // G1 checks (velocity gearing)
  long limited_cycles = 0;           // G2 checks
  long synchronizing_cycles = 0;     // MC_GearIn synchronization, limited
  long dynamic_sync_cycles = 0;      // MC_GearInPos profile 0 synchronization at a constant leader (G2)
  long elevated_cycles = 0;          // above a limit, admissibly (not growing after a pass-through phase)
  long indicated_cycles = 0;         // synchronous travel with X0 set
  long indicated_acceleration_cycles = 0;  // ... with X1 or X2 set
  long gear_in = 0, gear_in_velocity = 0, gear_in_pos_synchronous = 0, gear_out_done = 0, aborted = 0;
  long rejected = 0;  // jobs with Error
  long alarms_608 = 0;
  long gear_in_pos = 0, gear_in_pos_rejected = 0, gear_in_pos_started = 0;
};

class Run {
 public:
  Run(LeaderKind kind, std::uint32_t seed, bool jerk_limit)
      : kind_(kind), random_(seed), runtime_(techobjects::RuntimeConfig{kCycle, 1, 1}) {
    const bool modulo = kind == LeaderKind::kModulo;
    auto leader_data = modulo ? virtual_rotary_modulo() : virtual_linear();
    auto follower_data = modulo ? virtual_rotary_modulo() : virtual_linear();
    follower_data.DynamicLimits.MaxJerk = jerk_limit ? 1.0e6 : 0.0;
    follower_data.DynamicLimits.MaxVelocity = 600.0;  // below ratio x leader velocity now and then (X0)
    follower_data.DynamicLimits.Velocity = 600.0;
    follower_data.DynamicDefaults.Velocity = 300.0;
    follower_data.DynamicLimits.MaxAcceleration = 8000.0;
    follower_data.DynamicLimits.MaxDeceleration = 10000.0;
    auto l = std::make_unique<techobjects::PositioningAxis>("L", nullptr, leader_data);
    auto l2 = std::make_unique<techobjects::PositioningAxis>("L2", nullptr, leader_data);
    L_ = l.get();
    L2_ = l2.get();
    std::vector<techobjects::LeadingValueInterconnection> leaders{
        {L_, L_, techobjects::LeadingValueCoupling::kSetpoint},
        {L2_, L2_, techobjects::LeadingValueCoupling::kSetpoint}};
    runtime_.add_technology_object(std::move(l));
    runtime_.add_technology_object(std::move(l2));
    if (kind == LeaderKind::kEncoder) {
      drives::DeviceConfig device;
      device.encoder_telegrams[0] = 83;
      drives::SimulatedDriveParameters p;
      p.load_units_per_revolution = 360.0;
      p.encoder1.shaft = drives::SimulatedEncoderParameters::Shaft::kLoad;
      auto owned = std::make_unique<drives::SimulatedDrive>(device, p);
      encoder_drive_ = owned.get();
      auto& io = runtime_.add_device(std::move(owned));
      E_ = &runtime_.emplace<techobjects::ExternalEncoder>("E", &io, techobjects::ExternalEncoderData{});
      leaders.insert(leaders.begin(), {E_, E_, techobjects::LeadingValueCoupling::kActualValue});
    }
    if (kind == LeaderKind::kChain) {
      auto chain_data = virtual_linear();
      F1_ = &runtime_.emplace<SynchronousAxis>("F1", nullptr, chain_data,
                                               std::vector<techobjects::LeadingValueInterconnection>{
                                                   {L_, L_, techobjects::LeadingValueCoupling::kSetpoint}});
      leaders.insert(leaders.begin(), {F1_, F1_, techobjects::LeadingValueCoupling::kSetpoint});
    }
    F_ = &runtime_.emplace<SynchronousAxis>("F", nullptr, follower_data, leaders);
    runtime_.set_post_interpolator([this](techobjects::Runtime&) { check(); });
    runtime_.set_user_program([this](techobjects::Runtime&) { program(); });
    runtime_.start();
    leader_.power.Enable = true;
    leader2_.power.Enable = true;
    chain_.power.Enable = true;
    if (E_ != nullptr) encoder_power_.Enable = true;
    power_.Enable = true;
    home_.Mode = 0;
    home_.Position = 0.0;
    home_.Execute = true;
    checking_ = false;
    for (int i = 0; i < 20; ++i)
      runtime_.step();
    home_.Execute = false;
    checking_ = true;
  }

  void cycle(int k) {
    cycle_ = k;
    runtime_.step();
    check_handshakes();
    if (::testing::Test::HasFailure() && !dumped_) dump();
  }
  const Stats& stats() const { return stats_; }
  bool enabled() const { return power_.Status; }

 private:
  // ---- bookkeeping for the printout of a failure (fixed rings) ----
  struct State {
    int cycle = 0;
    double position = 0, velocity = 0, acceleration = 0, leader = 0, leader_velocity = 0;
    std::uint32_t status_word = 0;
    int function_state = 0, master = 0;
  };
  void note(const char* what, double x = 0, double y = 0, double z = 0) {
    events_.note(cycle_, what, {x, y, z});
  }
  void dump() {
    dumped_ = true;
    events_.print();
    states_.print(
        "cycle, F x v a, leading value x v, StatusWord, FunctionState, ActualMaster", [](const State& t) {
          std::printf("  %d %.6f %.6f %.3f %.6f %.6f %08x %d %d\n", t.cycle, t.position, t.velocity,
                      t.acceleration, t.leader, t.leader_velocity, t.status_word, t.function_state, t.master);
        });
  }
  std::string where() const { return std::string(name_of(kind_)) + ", cycle " + std::to_string(cycle_); }

  double uniform(double lo, double hi) { return random_.uniform(lo, hi); }
  bool chance(double p) { return random_.chance(p); }
  int pick(int n) { return random_.pick(n); }
  double dynamic(double high) { return chance(0.25) ? -1.0 : uniform(0.02, 1.0) * high; }
  double jerk() {
    const double r = uniform(0.0, 1.0);
    return r < 0.3 ? -1.0 : (r < 0.6 ? 0.0 : uniform(0.05, 1.0) * 2.0e6);
  }
  // Ratios N/D with N in [-5, 5] \ {0}, D in [1, 4] (so |N/D| from 0.2 to 5); now and then an illegal one
  // (16#8017 / 16#8018).
  void ratio(std::int32_t& n, std::int32_t& d) {
    n = pick(10) - 5;
    if (n >= 0) ++n;
    d = pick(4) + 1;
    if (chance(0.01)) n = 0;
    if (chance(0.01)) d = -pick(3);
  }
  const techobjects::LeadingValueSource* master() {
    const auto c = F_->interconnections();
    // The first interconnection (the scenario's leader) most of the time; L2 for switchovers.
    return chance(0.75) ? c[0].source : c[static_cast<std::size_t>(pick(static_cast<int>(c.size())))].source;
  }

  template <typename P, typename Axis>
  void leader_jobs(P& p, Axis& a, double scale, bool modulo) {
    auto release = [&](auto& fb) {
      if (fb.Execute && (fb.Done || fb.Error || fb.CommandAborted || !fb.Busy) && chance(0.2))
        fb.Execute = false;
    };
    release(p.move_absolute);
    release(p.halt);
    if (p.move_velocity.Execute && chance(0.01)) p.move_velocity.Execute = false;
    if (p.reset.Execute && !p.reset.Busy) p.reset.Execute = false;
    if (!a.alarms().alarms().empty() && !p.reset.Execute && chance(0.01)) p.reset.Execute = true;
    const double p_job = busy_ ? 0.01 : 0.0015;
    if (chance(p_job)) {
      switch (pick(3)) {
        case 0:
          if (p.move_absolute.Execute) break;
          p.move_absolute.Position = modulo ? uniform(0.0, 360.0) : uniform(-2000.0, 2000.0) * scale;
          p.move_absolute.Velocity = uniform(5.0, 300.0) * scale;
          p.move_absolute.Acceleration = dynamic(6000.0 * scale);
          p.move_absolute.Deceleration = dynamic(6000.0 * scale);
          p.move_absolute.Jerk = chance(0.5) ? 0.0 : -1.0;
          p.move_absolute.Direction = modulo ? pick(3) + 1 : 1;
          p.move_absolute.Execute = true;
          break;
        case 1:
          p.move_velocity.Velocity = uniform(-300.0, 300.0) * scale;
          if (chance(0.1)) p.move_velocity.Velocity = 0.0;
          p.move_velocity.Acceleration = dynamic(6000.0 * scale);
          p.move_velocity.Deceleration = dynamic(6000.0 * scale);
          p.move_velocity.Jerk = chance(0.5) ? 0.0 : -1.0;
          p.move_velocity.Execute = false;  // a new rising edge in this cycle
          p.move_velocity(a);
          p.move_velocity.Execute = true;
          break;
        default:
          if (p.halt.Execute) break;
          p.halt.Deceleration = dynamic(6000.0 * scale);
          p.halt.Execute = true;
          break;
      }
    }
  }

  // The user program: the leaders' jobs first, then the follower's, each instance called once per cycle.
  void program() {
    if (!checking_) {
      leader_.call(*L_);
      leader2_.call(*L2_);
      if (F1_ != nullptr) {
        chain_.call(*F1_);
        chain_gear_(*F1_);
      }
      if (E_ != nullptr) encoder_power_(*E_);
      call_follower();
      return;
    }
    if (chance(busy_ ? 0.003 : 0.0005)) busy_ = !busy_;
    leader_jobs(leader_, *L_, 1.0, kind_ == LeaderKind::kModulo);
    leader_.call(*L_);
    leader_jobs(leader2_, *L2_, 0.5, kind_ == LeaderKind::kModulo);
    leader2_.call(*L2_);
    if (F1_ != nullptr) {
      // The chain's middle axis: geared to L again and again, its gearing ended by its own random jobs.
      leader_jobs(chain_, *F1_, 0.5, false);
      if (!chain_gear_.Busy && chance(0.003)) {
        chain_gear_.Execute = false;
        chain_gear_(*F1_);
        ratio(chain_gear_.RatioNumerator, chain_gear_.RatioDenominator);
        chain_gear_.RatioNumerator = std::max(1, std::abs(chain_gear_.RatioNumerator));
        chain_gear_.RatioDenominator = std::max(1, chain_gear_.RatioDenominator);
        chain_gear_.Acceleration = dynamic(8000.0);
        chain_gear_.Execute = true;
      }
      chain_.call(*F1_);
      chain_gear_(*F1_);
    }
    if (E_ != nullptr) {
      // The encoder's shaft: a new speed now and then (steps: the extrapolation's filters smooth them).
      if (chance(0.0015)) {
        encoder_speed_ = chance(0.15) ? 0.0 : uniform(-200.0, 200.0);
        encoder_drive_->set_external_speed(encoder_speed_);
        note("encoder speed", encoder_speed_);
      }
      encoder_power_(*E_);
    }
    follower_jobs();
    call_follower();
    // ContinuousUpdate: ratio changes while the velocity gearing runs (spec 07 §2.3).
    if (gear_velocity_.Busy && gear_velocity_.ContinuousUpdate && chance(0.002)) {
      std::int32_t n = 0, d = 0;
      ratio(n, d);
      gear_velocity_.RatioNumerator = n;
      gear_velocity_.RatioDenominator = d;
      gear_velocity_(*F_);
      if (n != 0 && d >= 1) velocity_ratio_ = static_cast<double>(n) / d;
      ++epoch_;
      note("GearInVelocity ratio update", n, d);
    }
  }

  void call_follower() {
    power_(*F_);
    reset_(*F_);
    home_(*F_);
    move_velocity_(*F_);
    move_absolute_(*F_);
    halt_(*F_);
    stop_(*F_);
    // A desynchronization job that is accepted and runs (profile 5 ends at once, Done).
    if (accepted(gear_out_, executed_[4])) {
      gear_out_profile_ = gear_out_.SyncProfileReference;
      note("MC_GearOut accepted (profile)", gear_out_profile_);
    }
    if (gear_out_.StartSyncOut && !was_start_out_)
      note("MC_GearOut StartSyncOut (y_stop)", gear_out_.SlavePosition, F_->setpoint().position,
           F_->setpoint().velocity);
    was_start_out_ = gear_out_.StartSyncOut;
    // The gearing instances last: a job accepted above shows in their outputs of this cycle.
    for (int i = 0; i < 2; ++i)
      call_gear(i);
    call_gear_velocity();
    call_gear_pos();
  }

  // Calls an instance and records the ratio a newly accepted gearing brings (effective from the next
  // MC_Interpolator on).
  void call_gear(int i) {
    auto& g = gear_[static_cast<std::size_t>(i)];
    if (accepted(g, executed_[static_cast<std::size_t>(i)]))
      gear_in_ratio_ = static_cast<double>(g.RatioNumerator) / g.RatioDenominator;
  }
  void call_gear_velocity() {
    if (accepted(gear_velocity_, executed_[2])) {
      velocity_ratio_ = static_cast<double>(gear_velocity_.RatioNumerator) / gear_velocity_.RatioDenominator;
    }
  }
  void call_gear_pos() {
    if (accepted(gear_pos_, executed_[3])) {
      ++stats_.gear_in_pos;
      pending_pos_ratio_ = static_cast<double>(gear_pos_.RatioNumerator) / gear_pos_.RatioDenominator;
      pending_pos_profile_ = gear_pos_.SyncProfileReference;
    }
    if (gear_pos_.Error && !was_error_pos_) ++stats_.gear_in_pos_rejected;
    was_error_pos_ = gear_pos_.Error;
    // The job the instance tracks started (in this cycle's MC_Interpolator): from now on it is the active
    // GearInPos (FunctionState 2); a job started before goes on until then (spec 07 §5.1, pending row "–").
    if ((gear_pos_.StartSync || gear_pos_.InSync) && !was_start_pos_) {
      gear_pos_ratio_ = pending_pos_ratio_;
      gear_pos_profile_ = pending_pos_profile_;
      ++stats_.gear_in_pos_started;
    }
    was_start_pos_ = gear_pos_.StartSync || gear_pos_.InSync;
  }
  // Calls the instance; true when this call's rising edge of Execute started a job (Busy, no Error).
  template <typename Fb>
  bool accepted(Fb& fb, bool& executed) {
    const bool edge = fb.Execute && !executed;
    fb(*F_);
    executed = fb.Execute;
    return edge && fb.Busy && !fb.Error;
  }

  void follower_jobs() {
    auto release = [&](auto& fb) {
      if (fb.Execute && (fb.Error || fb.CommandAborted || !fb.Busy) && chance(0.2)) {
        fb.Execute = false;
        if (fb.Error) ++stats_.rejected;
        if (fb.CommandAborted) ++stats_.aborted;
      }
    };
    for (auto& g : gear_)
      release(g);
    release(gear_velocity_);
    release(gear_pos_);
    if (gear_out_.Execute && (gear_out_.Done || gear_out_.Error || gear_out_.CommandAborted) && chance(0.2)) {
      if (gear_out_.Done) ++stats_.gear_out_done;
      gear_out_.Execute = false;
    }
    if (halt_.Execute && (halt_.Done || halt_.Error || halt_.CommandAborted) && chance(0.2))
      halt_.Execute = false;
    if (move_absolute_.Execute &&
        (move_absolute_.Done || move_absolute_.Error || move_absolute_.CommandAborted))
      move_absolute_.Execute = false;
    if (move_velocity_.Execute && (move_velocity_.Error || move_velocity_.CommandAborted || chance(0.002)))
      move_velocity_.Execute = false;
    if (stop_.Execute && (stop_.Done || stop_.Error || stop_.CommandAborted) && chance(0.01)) {
      stop_.Execute = false;
    }
    if (reset_.Execute && !reset_.Busy) reset_.Execute = false;
    const auto& d = F_->data();
    if (!reset_.Execute && (d.ErrorWord != 0 || !F_->alarms().alarms().empty()) && chance(0.01)) {
      reset_.Execute = true;
      ++epoch_;
      note("MC_Reset");
    }
    if (power_.Enable && chance(0.00015)) {
      power_.StopMode = static_cast<std::int16_t>(pick(3));
      power_.Enable = false;
      ++epoch_;
      note("MC_Power off (StopMode)", power_.StopMode);
    } else if (!power_.Enable && chance(0.01)) {
      power_.Enable = true;
      ++epoch_;
      note("MC_Power on");
    }

    // Fewer jobs while an MC_GearInPos waits or synchronizes (most of them would abort it).
    const bool gear_in_pos = gear_pos_.Busy && !gear_pos_.InSync;
    const double p_job = (busy_ ? 0.01 : 0.001) * (gear_in_pos ? 0.1 : 1.0);
    if (!chance(p_job)) return;
    ++epoch_;
    const int what = pick(11);
    switch (what) {
      case 0:
      case 1:
      case 2: {  // MC_GearIn, alternately the two instances (the second replaces the first)
        const auto i = static_cast<std::size_t>(next_gear_);
        auto& g = gear_[i];
        next_gear_ = 1 - next_gear_;
        if (g.Execute) {
          g.Execute = false;
          (void)accepted(g, executed_[i]);
        }
        g.Master = master();
        ratio(g.RatioNumerator, g.RatioDenominator);
        g.Acceleration = dynamic(12000.0);  // above MaxAcceleration now and then: clipped, alarm 502
        g.Deceleration = dynamic(12000.0);
        g.Jerk = jerk();
        g.Execute = true;
        ++stats_.gear_in;
        note("MC_GearIn (N, D, Acceleration)", g.RatioNumerator, g.RatioDenominator, g.Acceleration);
        break;
      }
      case 3: {
        auto& g = gear_velocity_;
        if (g.Execute) {
          g.Execute = false;
          (void)accepted(g, executed_[2]);
        }
        g.Master = master();
        ratio(g.RatioNumerator, g.RatioDenominator);
        g.ContinuousUpdate = chance(0.5);
        g.PositionControlled = chance(0.5);
        g.Acceleration = dynamic(12000.0);
        g.Deceleration = dynamic(12000.0);
        g.Jerk = jerk();
        g.Execute = true;
        ++stats_.gear_in_velocity;
        note("MC_GearInVelocity (N, D, ContinuousUpdate)", g.RatioNumerator, g.RatioDenominator,
             g.ContinuousUpdate);
        break;
      }
      case 4:
      case 5: {  // MC_GearInPos ahead of the leader in its direction of travel
        auto& g = gear_pos_;
        if (g.Execute) {
          g.Execute = false;
          (void)accepted(g, executed_[3]);
        }
        g.Master = master();
        ratio(g.RatioNumerator, g.RatioDenominator);
        const auto v = g.Master->leading_value(techobjects::LeadingValueCoupling::kSetpoint);
        const double dir = v.velocity < 0.0 ? -1.0 : 1.0;
        const int profiles[] = {0, 1, 3};
        g.SyncProfileReference = profiles[pick(3)];
        g.MasterStartDistance = uniform(10.0, 150.0);
        g.MasterSyncPosition = v.position + dir * (g.MasterStartDistance + uniform(1.0, 60.0));
        if (kind_ == LeaderKind::kModulo)
          g.MasterSyncPosition = std::fmod(std::fabs(g.MasterSyncPosition), 360.0);
        g.SlaveSyncPosition = kind_ == LeaderKind::kModulo ? uniform(0.0, 360.0)
                                                           : F_->setpoint().position + uniform(-200.0, 200.0);
        g.Velocity = dynamic(900.0);
        g.Acceleration = dynamic(12000.0);
        g.Deceleration = dynamic(12000.0);
        g.Jerk = jerk();
        g.SyncDirection = pick(3) + 1;
        g.Execute = true;
        note("MC_GearInPos (profile, MasterSyncPosition, SlaveSyncPosition)", g.SyncProfileReference,
             g.MasterSyncPosition, g.SlaveSyncPosition);
        break;
      }
      case 6: {
        auto& g = gear_out_;
        if (g.Execute) break;
        const int profiles[] = {0, 1, 5};
        g.SyncProfileReference = profiles[pick(3)];
        g.SlavePosition = kind_ == LeaderKind::kModulo ? uniform(0.0, 360.0)
                                                       : F_->setpoint().position + uniform(-500.0, 500.0);
        g.MasterStopDistance = uniform(10.0, 200.0);
        g.Deceleration = dynamic(12000.0);
        g.Jerk = jerk();
        g.SyncOutDirection = pick(3) + 1;
        g.Execute = true;
        note("MC_GearOut (profile, SlavePosition, Deceleration)", g.SyncProfileReference, g.SlavePosition,
             g.Deceleration);
        break;
      }
      case 7:
        if (halt_.Execute) break;
        halt_.Deceleration = dynamic(12000.0);
        halt_.Jerk = jerk();
        halt_.Execute = true;
        note("MC_Halt (Deceleration)", halt_.Deceleration);
        break;
      case 8:
        if (stop_.Execute || !chance(0.3)) break;
        stop_.Mode = chance(0.5) ? 0 : 2;
        stop_.Execute = true;
        note("MC_Stop (Mode)", stop_.Mode);
        break;
      case 9:
        move_velocity_.Execute = false;
        move_velocity_(*F_);
        move_velocity_.Velocity = uniform(-500.0, 500.0);
        move_velocity_.Acceleration = dynamic(12000.0);
        move_velocity_.Deceleration = dynamic(12000.0);
        move_velocity_.Jerk = jerk();
        move_velocity_.Execute = true;
        note("MC_MoveVelocity (Velocity)", move_velocity_.Velocity);
        break;
      default:
        if (move_absolute_.Execute) break;
        move_absolute_.Position = kind_ == LeaderKind::kModulo
                                      ? uniform(0.0, 360.0)
                                      : F_->setpoint().position + uniform(-300.0, 300.0);
        move_absolute_.Velocity = dynamic(900.0);
        move_absolute_.Acceleration = dynamic(12000.0);
        move_absolute_.Deceleration = dynamic(12000.0);
        move_absolute_.Jerk = jerk();
        move_absolute_.BufferMode = chance(0.2) ? 1 : 0;
        move_absolute_.Execute = true;
        note("MC_MoveAbsolute (Position, BufferMode)", move_absolute_.Position, move_absolute_.BufferMode);
        break;
    }
  }

  // ---- the checks, right after MC_Interpolator ----
  struct Snapshot {
    bool valid = false;
    bool synchronous = false;  // X22
    int function_state = 0;
    int master = 0;
    std::uint64_t epoch = 0;
    double position = 0, velocity = 0, acceleration = 0;  // continuous setpoint, position units
    double worst_acceleration = 0;                        // max(|a|, |dv|/T)
    bool unlimited = false;   // a phase in which the leader's dynamics pass through (spec 07 §6.8)
    bool elevated = false;    // above a limit, admissibly
    bool recovering = false;  // after a phase without limits, the acceleration falling back into them
    bool velocity_unlimited = false;
    bool dynamic_sync = false;  // MC_GearInPos profile 0 synchronizing
  };
  tomc::testing::DynamicSyncJudge dynamic_sync_;
  int prev_waiting_ = 0;
  int active_pos_profile_ = -1;

  void check() {
    if (!checking_) return;
    const auto& d = F_->data();
    const auto& sm = F_->synchronized_motion();
    const auto& sp = F_->setpoint();
    Snapshot now;
    now.valid = true;
    now.synchronous = techobjects::test(d.StatusWord, StatusWordBit::kSynchronous);
    const bool synchronizing = techobjects::test(d.StatusWord, StatusWordBit::kSynchronizing);
    now.function_state = sm.FunctionState;
    now.master = sm.ActualMaster;
    now.epoch = epoch_;
    now.position = sp.position;
    now.velocity = sp.velocity;
    now.acceleration = sp.acceleration;
    techobjects::LeadingValue lv{};
    if (now.master > 0) {
      const auto& c = F_->interconnections()[static_cast<std::size_t>(now.master - 1)];
      lv = c.source->leading_value(c.coupling);
    }
    states_.push(State{cycle_, sp.position, sp.velocity, sp.acceleration, lv.position, lv.velocity,
                       d.StatusWord, now.function_state, now.master});

    // G4: finite values.
    for (double x : {d.Position, d.Velocity, d.Acceleration, sp.position, sp.velocity, sp.acceleration,
                     lv.position, lv.velocity, lv.acceleration, sm.EffectiveLeadingValue.Position,
                     sm.FunctionFollowingValue.Position}) {
      ASSERT_TRUE(std::isfinite(x)) << where();
    }
    const bool enabled = techobjects::test(d.StatusWord, StatusWordBit::kEnable);
    const auto& l = d.DynamicLimits;

    // G1: on the gear line while synchronous (spec 07 §6.2, tolerance of §8).
    const bool position_gearing = now.synchronous && (now.function_state == 1 || now.function_state == 2);
    const bool same_coupling = prev_.valid && prev_.synchronous &&
                               prev_.function_state == now.function_state && prev_.master == now.master &&
                               prev_.epoch == now.epoch;
    if (position_gearing) {
      const double r = now.function_state == 1 ? gear_in_ratio_ : gear_pos_ratio_;
      if (!same_coupling || !anchored_) {
        anchored_ = true;
        anchor_x_ = lv.position;
        anchor_y_ = sp.position;
        anchor_db_ = d.Position;
      } else {
        ++stats_.synchronous_cycles;
        const double dx = lv.position - anchor_x_;
        const double tol = 1e-6 + 1e-13 * std::fabs(sp.position);
        EXPECT_NEAR(sp.position - anchor_y_, r * dx, tol) << where() << ": off the gear line, ratio " << r;
        double e = d.Position - anchor_db_ - r * dx;
        if (d.Modulo.Enable) e = std::remainder(e, d.Modulo.Length);
        EXPECT_NEAR(e, 0.0, tol) << where() << ": data block Position off the gear line";
        EXPECT_NEAR(sp.velocity, r * lv.velocity, 1e-9 * std::max(1.0, std::fabs(sp.velocity))) << where();
        EXPECT_NEAR(sp.acceleration, r * lv.acceleration, 1e-9 * std::max(1.0, std::fabs(sp.acceleration)))
            << where();
      }
    } else {
      anchored_ = false;
    }
    if (now.synchronous && now.function_state == 6 && same_coupling && enabled) {
      ++stats_.velocity_gearing_cycles;
      EXPECT_NEAR(sp.velocity, velocity_ratio_ * lv.velocity, 1e-9 * std::max(1.0, std::fabs(sp.velocity)))
          << where() << ": velocity gearing, ratio " << velocity_ratio_;
    }
    if (now.synchronous && now.function_state == 2 && !prev_.synchronous) ++stats_.gear_in_pos_synchronous;

    // G3: indication, no alarm, in synchronous travel (spec 07 §1.9, §6.8).
    const auto raised = new_alarms();
    if (now.function_state != 0 || sm.WaitingFunctionState != 0 || now.synchronous) {
      if (now.synchronous && now.function_state != 4) {
        // X0 |v| > MaxVelocity, X1 accelerating beyond MaxAcceleration, X2 decelerating beyond
        // MaxDeceleration (spec 07 §6.8 [IMPL] semantics, decision Y7: the condition of the cycle).
        EXPECT_EQ((sm.StatusWord & 1u) != 0, std::fabs(d.Velocity) > l.MaxVelocity * (1.0 + 1e-9)) << where();
        const double va = d.Velocity * d.Acceleration;
        EXPECT_EQ((sm.StatusWord & 2u) != 0, va > 0.0 && std::fabs(d.Acceleration) > l.MaxAcceleration)
            << where();
        EXPECT_EQ((sm.StatusWord & 4u) != 0, va < 0.0 && std::fabs(d.Acceleration) > l.MaxDeceleration)
            << where();
        if ((sm.StatusWord & 1u) != 0) ++stats_.indicated_cycles;
        if ((sm.StatusWord & 6u) != 0) ++stats_.indicated_acceleration_cycles;
      }
    } else {
      EXPECT_EQ(sm.StatusWord & 7u, 0u) << where() << ": X0..X2 without synchronous operation";
    }
    if (now.synchronous && same_coupling) {
      for (std::uint32_t n :
           {techobjects::kAlarmDynamicsLimitedVelocity, techobjects::kAlarmDynamicsLimitedAcceleration,
            techobjects::kAlarmDynamicsLimitedJerk}) {
        // A pending MC_GearInPos/MC_CamIn profile 0 that may not start synchronizing shows its wait with 501,
        // additional value 1 — that job's indication, not a limit of this synchronous travel (decision C23).
        const bool pending_wait =
            n == techobjects::kAlarmDynamicsLimitedVelocity && sm.WaitingFunctionState != 0;
        EXPECT_FALSE(pending_wait ? raised.count_except(n, 1) : raised.count(n))
            << where() << ": alarm " << n << " in synchronous travel";
      }
    }
    // MC_GearIn synchronization limits the velocity without alarm 501 (spec 07 §2.1, §6.3).
    if (now.function_state == 1 && synchronizing && prev_.valid && prev_.function_state == 1 &&
        prev_.epoch == now.epoch) {
      // (501 with additional value 1 is a pending profile-0 job's wait, decision C23.)
      EXPECT_FALSE(sm.WaitingFunctionState != 0
                       ? raised.count_except(techobjects::kAlarmDynamicsLimitedVelocity, 1)
                       : raised.count(techobjects::kAlarmDynamicsLimitedVelocity))
          << where() << ": alarm 501 during MC_GearIn synchronization";
    }
    if (raised.count(techobjects::kAlarmSynchronizationError)) ++stats_.alarms_608;

    // G2: the follower's own limits where spec 07 §6.8 applies them.
    now.unlimited = now.synchronous || (now.function_state == 2 && gear_pos_profile_ != 0) ||
                    (now.function_state == 4 && gear_out_profile_ == 1) || !enabled;
    // MC_GearInPos profile 0 synchronizes in the leader domain too (decision Y6): the leader's dynamics
    // pass through it as well (spec 07 §6.5 "changes in the leader's dynamics are superimposed").
    if (now.function_state == 2 && synchronizing) now.unlimited = true;
    now.velocity_unlimited = now.unlimited || (now.function_state == 6 && synchronizing);
    const double dv = prev_.valid ? (sp.velocity - prev_.velocity) / kCycle : 0.0;
    now.worst_acceleration = std::max(std::fabs(sp.acceleration), std::fabs(dv));
    if (prev_.valid && !now.unlimited && prev_enabled_) {
      ++stats_.limited_cycles;
      if (now.function_state == 1 && synchronizing) ++stats_.synchronizing_cycles;
      const double tol_v = 1e-9 * l.MaxVelocity;
      const double tol_a = 1e-6 * std::max(l.MaxAcceleration, l.MaxDeceleration);
      // After a phase without the limits the follower's acceleration may only fall until it is within them
      // (profiles.hpp: a start acceleration above the limit is brought back with the jerk, never increased;
      // with MaxAcceleration < MaxDeceleration a braking acceleration becomes one above the limit when the
      // new motion passes standstill).
      const bool after_free =
          prev_.unlimited || prev_.elevated || prev_.velocity_unlimited || prev_.recovering;
      now.recovering = after_free &&
                       now.worst_acceleration <= std::max(prev_.worst_acceleration, 0.0) + tol_a &&
                       now.worst_acceleration > std::min(l.MaxAcceleration, l.MaxDeceleration) - tol_a;
      if (prev_.unlimited || prev_.velocity_unlimited) {
        now.recovering = now.worst_acceleration > std::min(l.MaxAcceleration, l.MaxDeceleration) - tol_a;
      }
      bool elevated = false;
      if (!now.velocity_unlimited && std::fabs(sp.velocity) > l.MaxVelocity + tol_v) {
        // Above MaxVelocity only on the way down from a phase that may exceed it.
        // The cycle that hands over from a phase without the limit: its setpoint is one step of the new
        // motion from the synchronous state of this same cycle (the leader's dynamics, not observable here);
        // from the next cycle on it must not grow.
        // With a jerk limit an acceleration carried over outward is taken back with the jerk, so |v| still
        // grows by up to a0²/(2j) on the way (profiles.hpp, spec 01 §8.8 "tramite lo strappo"): admissible
        // while that acceleration falls and |v| grows by no more than it carries it in the cycle. Without a
        // jerk limit the acceleration is taken back at once: nothing is carried (decision C24).
        const bool carried = l.MaxJerk > 0.0 && sp.velocity * prev_.acceleration > 0.0 &&
                             std::fabs(sp.acceleration) < std::fabs(prev_.acceleration) &&
                             std::fabs(sp.velocity) <=
                                 std::fabs(prev_.velocity) + std::fabs(prev_.acceleration) * kCycle + tol_v;
        const bool admissible =
            prev_.velocity_unlimited ||
            (after_free && (std::fabs(sp.velocity) <= std::fabs(prev_.velocity) + tol_v || carried));
        EXPECT_TRUE(admissible) << where() << ": |v| " << sp.velocity << " above MaxVelocity "
                                << l.MaxVelocity;
        elevated = true;
      }
      // The acceleration at the sample against the limit of its direction (a·v > 0: |v| grows), the mean
      // dv/dt of the cycle against the limit of the way |v| went (a cycle may hold both phases).
      const bool emergency = (stop_.Busy && stop_.Mode == 0) || (!power_.Enable && power_.StopMode == 0) ||
                             F_->alarms().strongest_reaction() == AlarmReaction::kStopEmergencyRamp;
      const double braking = emergency ? std::max(l.MaxDeceleration, d.DynamicDefaults.EmergencyDeceleration)
                                       : l.MaxDeceleration;
      const double accelerating = emergency ? std::max(l.MaxAcceleration, braking) : l.MaxAcceleration;
      // At v = 0 the acceleration of a stop (against the previous velocity) is a deceleration.
      const bool stopping_at_zero = sp.velocity == 0.0 && sp.acceleration * prev_.velocity < 0.0;
      const bool a_grows = sp.acceleration * sp.velocity > 0.0 ||
                           (sp.velocity == 0.0 && sp.acceleration != 0.0 && !stopping_at_zero);
      const double bound_a = a_grows ? accelerating : braking;
      const bool v_grows = std::fabs(sp.velocity) > std::fabs(prev_.velocity);
      const double bound_dv = v_grows ? accelerating : braking;
      // Through standstill within one cycle: braking to v = 0, then growing in the other direction; the mean
      // dv/dt mixes the two limits. It must fit the cycle: |v0|/D + |v1|/A <= T.
      const bool through_zero = prev_.velocity * sp.velocity < 0.0;
      const bool dv_ok = through_zero
                             ? std::fabs(prev_.velocity) / braking + std::fabs(sp.velocity) / accelerating <=
                                   kCycle * (1.0 + 1e-6)
                             : std::fabs(dv) <= bound_dv + tol_a;
      if (std::fabs(sp.acceleration) > bound_a + tol_a || !dv_ok) {
        const bool admissible =
            prev_.unlimited || (after_free && now.worst_acceleration <= prev_.worst_acceleration + tol_a);
        EXPECT_TRUE(admissible) << where() << ": a " << sp.acceleration << " (limit " << bound_a
                                << "), dv/dt " << dv << " (limit " << bound_dv
                                << (through_zero ? ", through 0" : "") << "), v " << prev_.velocity << " -> "
                                << sp.velocity;
        elevated = true;
      }
      now.elevated = elevated;
      if (elevated) ++stats_.elevated_cycles;
    }
    // G2, MC_GearInPos profile 0 (spec 07 §2.2, §6.8; SYNC8 "in advance using dynamic parameters"):
    // MaxVelocity, MaxAcceleration / MaxDeceleration and MaxJerk hold during the synchronization, above them
    // only what the follower carried in at its start (not growing). Changes of the leader's dynamics after
    // the start are superimposed according to the gear ratio (the manual): a cycle is judged while the leader
    // keeps its velocity of the start and does not accelerate.
    // Which MC_GearInPos synchronizes: a pending job (the instance's last accepted one) becomes the active
    // one in the cycle its WaitingFunctionState 2 ends with FunctionState 2; until then an older job of the
    // same instance may still be active (spec 07 §5.1: a pending MC_GearInPos does not abort it).
    if (now.function_state == 2 && prev_waiting_ == 2 && sm.WaitingFunctionState != 2)
      active_pos_profile_ = pending_pos_profile_;
    prev_waiting_ = sm.WaitingFunctionState;
    now.dynamic_sync = now.function_state == 2 && synchronizing && active_pos_profile_ == 0 && enabled;
    if (now.dynamic_sync && !prev_.dynamic_sync)
      note("GearInPos profile 0 synchronizes (leader velocity, follower v, a)", lv.velocity, prev_.velocity,
           prev_.acceleration);
    const auto verdict = dynamic_sync_.judge(
        now.dynamic_sync, lv.velocity, lv.acceleration, sp.velocity, sp.acceleration, prev_.velocity,
        prev_.acceleration, {l.MaxVelocity, l.MaxAcceleration, l.MaxDeceleration, l.MaxJerk}, kCycle);
    if (verdict.judged) ++stats_.dynamic_sync_cycles;
    EXPECT_TRUE(verdict.problem.empty()) << where() << ": MC_GearInPos profile 0 " << verdict.problem;
    prev_enabled_ = enabled;
    prev_ = now;
  }

  // Alarm numbers the follower raised since the last call.
  using Raised = tomc::testing::RaisedAlarms;
  Raised new_alarms() {
    return alarm_watch_.take(F_->alarms(), [&](const techobjects::AlarmEvent& e) {
      note("alarm raised", e.number, e.additional_value);
    });
  }

  // G4: the handshake of every instance after the user program (spec 03 §3.2).
  template <typename Fb>
  void handshake(const Fb& fb, const char* name) {
    const int finals = (fb.Error ? 1 : 0) + (fb.CommandAborted ? 1 : 0);
    EXPECT_LE(finals, 1) << where() << ": " << name;
    EXPECT_FALSE((fb.Error || fb.CommandAborted) && fb.Busy) << where() << ": " << name;
  }
  template <typename Fb>
  void handshake_done(const Fb& fb, const char* name) {
    handshake(fb, name);
    EXPECT_FALSE(fb.Done && (fb.Error || fb.CommandAborted)) << where() << ": " << name;
    EXPECT_FALSE(fb.Done && fb.Busy) << where() << ": " << name;
  }
  void check_handshakes() {
    for (const auto& g : gear_) {
      handshake(g, "MC_GearIn");
      EXPECT_FALSE(g.InGear && !g.Busy) << where();
    }
    handshake(gear_velocity_, "MC_GearInVelocity");
    EXPECT_FALSE((gear_velocity_.InSync || gear_velocity_.StartSync) && !gear_velocity_.Busy) << where();
    EXPECT_FALSE(gear_velocity_.InSync && gear_velocity_.StartSync) << where();
    handshake(gear_pos_, "MC_GearInPos");
    EXPECT_FALSE((gear_pos_.InSync || gear_pos_.StartSync) && !gear_pos_.Busy) << where();
    handshake_done(gear_out_, "MC_GearOut");
    EXPECT_FALSE(gear_out_.StartSyncOut && !gear_out_.Busy) << where();
    handshake_done(halt_, "MC_Halt");
    handshake_done(stop_, "MC_Stop");
    handshake_done(move_absolute_, "MC_MoveAbsolute");
    handshake(move_velocity_, "MC_MoveVelocity");
    handshake_done(leader_.move_absolute, "leader MC_MoveAbsolute");
    handshake_done(leader_.halt, "leader MC_Halt");
  }

  LeaderKind kind_;
  tomc::testing::PropertyRandom random_;
  techobjects::Runtime runtime_;
  techobjects::PositioningAxis* L_ = nullptr;
  techobjects::PositioningAxis* L2_ = nullptr;
  SynchronousAxis* F1_ = nullptr;
  SynchronousAxis* F_ = nullptr;
  techobjects::ExternalEncoder* E_ = nullptr;
  drives::SimulatedDrive* encoder_drive_ = nullptr;
  double encoder_speed_ = 0.0;

  template <typename Axis>
  struct Program {
    instructions::MC_Power<Axis> power;
    instructions::MC_Reset<Axis> reset;
    instructions::MC_MoveAbsolute<Axis> move_absolute;
    instructions::MC_MoveVelocity<Axis> move_velocity;
    instructions::MC_Halt<Axis> halt;
    void call(Axis& a) {
      power(a);
      reset(a);
      move_absolute(a);
      move_velocity(a);
      halt(a);
    }
  };
  Program<techobjects::PositioningAxis> leader_, leader2_;
  Program<SynchronousAxis> chain_;
  instructions::MC_GearIn<SynchronousAxis> chain_gear_;
  instructions::MC_Power<techobjects::ExternalEncoder> encoder_power_;

  instructions::MC_Power<SynchronousAxis> power_;
  instructions::MC_Reset<SynchronousAxis> reset_;
  instructions::MC_Home<SynchronousAxis> home_;
  std::array<instructions::MC_GearIn<SynchronousAxis>, 2> gear_;
  instructions::MC_GearInVelocity<SynchronousAxis> gear_velocity_;
  instructions::MC_GearInPos<SynchronousAxis> gear_pos_;
  instructions::MC_GearOut<SynchronousAxis> gear_out_;
  instructions::MC_Halt<SynchronousAxis> halt_;
  instructions::MC_Stop<SynchronousAxis> stop_;
  instructions::MC_MoveVelocity<SynchronousAxis> move_velocity_;
  instructions::MC_MoveAbsolute<SynchronousAxis> move_absolute_;
  int next_gear_ = 0;
  bool was_error_pos_ = false, was_start_pos_ = false, was_start_out_ = false;
  std::array<bool, 5> executed_{};  // Execute as the instance saw it in its last call
  double gear_in_ratio_ = 1.0, velocity_ratio_ = 1.0, gear_pos_ratio_ = 1.0;
  int gear_pos_profile_ = 1, gear_out_profile_ = 1;
  double pending_pos_ratio_ = 1.0;
  int pending_pos_profile_ = 1;

  bool checking_ = false;
  bool busy_ = false;
  std::uint64_t epoch_ = 0;
  Snapshot prev_{};
  bool prev_enabled_ = false;
  bool anchored_ = false;
  double anchor_x_ = 0, anchor_y_ = 0, anchor_db_ = 0;
  tomc::testing::AlarmWatch alarm_watch_;
  Stats stats_{};
  int cycle_ = 0;
  tomc::testing::EventRing<120> events_;
  tomc::testing::StateRing<State, 60> states_;
  bool dumped_ = false;
};

void run_scenario(LeaderKind kind, std::uint32_t seed, bool jerk_limit, Stats& total) {
  SCOPED_TRACE("seed " + std::to_string(seed) + ", " + name_of(kind) + (jerk_limit ? ", MaxJerk 1e6" : ""));
  Run run(kind, seed, jerk_limit);
  ASSERT_TRUE(run.enabled()) << "enabled at the start";
  for (int k = 0; k < kCycles && !::testing::Test::HasFailure(); ++k)
    run.cycle(k);
  const Stats& s = run.stats();
  std::printf(
      "seed %u, %s: %ld synchronous cycles checked on the gear line, %ld velocity-gearing cycles, %ld "
      "limited "
      "cycles (%ld MC_GearIn synchronizing, %ld above a limit on the way down), %ld with X0; %ld GearIn, %ld "
      "GearInVelocity, %ld GearInPos synchronous, %ld GearOut Done, %ld aborted, %ld rejected, %ld alarms "
      "608; GearInPos %ld accepted, %ld rejected, %ld started, %ld profile-0 cycles at a constant leader\n",
      seed, name_of(kind), s.synchronous_cycles, s.velocity_gearing_cycles, s.limited_cycles,
      s.synchronizing_cycles, s.elevated_cycles, s.indicated_cycles, s.gear_in, s.gear_in_velocity,
      s.gear_in_pos_synchronous, s.gear_out_done, s.aborted, s.rejected, s.alarms_608, s.gear_in_pos,
      s.gear_in_pos_rejected, s.gear_in_pos_started, s.dynamic_sync_cycles);
  total.synchronous_cycles += s.synchronous_cycles;
  total.velocity_gearing_cycles += s.velocity_gearing_cycles;
  total.limited_cycles += s.limited_cycles;
  total.synchronizing_cycles += s.synchronizing_cycles;
  total.indicated_cycles += s.indicated_cycles;
  total.indicated_acceleration_cycles += s.indicated_acceleration_cycles;
  total.gear_in_pos_synchronous += s.gear_in_pos_synchronous;
  total.gear_out_done += s.gear_out_done;
  total.aborted += s.aborted;
  total.dynamic_sync_cycles += s.dynamic_sync_cycles;
}

// The properties of the file header: spec 07 §2.1, §2.3, §6.1, §6.2, §6.5, §1.9, spec 02 §3.1.
TEST(GearingProperty, RandomLeadersRatiosAndJobs) {
  std::printf("base seed %u, 8 runs (4 leader kinds, MaxJerk 0 / 1e6) x %d cycles\n", base_seed(), kCycles);
  Stats total;
  const LeaderKind kinds[] = {LeaderKind::kAxis, LeaderKind::kModulo, LeaderKind::kEncoder,
                              LeaderKind::kChain};
  for (int i = 0; i < 8 && !HasFailure(); ++i)
    run_scenario(kinds[i % 4], base_seed() + static_cast<std::uint32_t>(i), i >= 4, total);
  // The sequences exercised what the properties are about.
  EXPECT_GT(total.synchronous_cycles, 8L * kCycles / 10);
  EXPECT_GT(total.velocity_gearing_cycles, kCycles / 20);
  EXPECT_GT(total.limited_cycles, 8L * kCycles / 10);
  EXPECT_GT(total.synchronizing_cycles, kCycles / 100);
  EXPECT_GT(total.aborted, kCycles / 10'000);
#ifndef TOMC_SANITIZED_BUILD
  // Rarer events, reached in the full run (the sanitizer build's shorter run looks for memory and UB errors
  // on the same paths; CI runs both).
  EXPECT_GT(total.indicated_cycles, 0);
  EXPECT_GT(total.indicated_acceleration_cycles, 0);
  EXPECT_GT(total.gear_in_pos_synchronous, 4);
  EXPECT_GT(total.gear_out_done, 2);
  EXPECT_GT(total.dynamic_sync_cycles, 0);
#endif
}

}  // namespace
