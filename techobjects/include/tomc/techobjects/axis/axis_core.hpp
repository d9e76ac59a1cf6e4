#pragma once
// The behaviour every axis TO shares, written once (issue 14) and held by each axis TO by composition: the
// power phase of MC_Power with its StopMode, MC_Reset and the restart request, the technology alarms with the
// reaction in force and what it asks of the drive, the MC_Stop job and its lock, drive supervision, the
// resolution of job dynamics ("-1 = default", limits with warnings 501–503), the communication times of
// MC_WriteParameter 1010–1012, MC_SetAxisSTW, and the status/error words every axis shows.
//
// The TO keeps what is its own — its setpoint generator, its units, its monitors — and runs the cycle as a
// pipeline of named steps that call in here (docs/architecture.md, "The axis core"). The rules cite the
// manual where they are decided; noexcept, no allocation.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>

#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/axis/control_priority.hpp"
#include "tomc/techobjects/axis/job.hpp"
#include "tomc/techobjects/axis/job_inputs.hpp"
#include "tomc/techobjects/axis/job_priority.hpp"
#include "tomc/techobjects/axis/job_table.hpp"
#include "tomc/techobjects/axis/torque_data.hpp"
#include "tomc/techobjects/axis/torque_limiting.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/to_types.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/motion/profiles.hpp"
#include "tomc/telegrams/drive_state.hpp"

namespace tomc::techobjects {

// The jobs of every axis TO (one enumeration, so that one job table serves them all).
enum class AxisJobKind : std::uint8_t {
  kNone,
  kReset,
  kHome,
  kMoveAbsolute,
  kMoveRelative,
  kMoveVelocity,
  kJog,
  kHalt,
  kStop,
  kSetAxisStw,
  kWriteParameter,
  kGearIn,                    // synchronous axis: MC_GearIn
  kGearInPos,                 // MC_GearInPos, once synchronization started
  kGearInVelocity,            // MC_GearInVelocity
  kGearOut,                   // MC_GearOut, once desynchronization started
  kCamIn,                     // MC_CamIn
  kCamOut,                    // MC_CamOut, once desynchronization started
  kPositionProfile,           // MC_PositionProfile (spec 03 §4.7)
  kMotionInVelocity,          // MC_MotionInVelocity (spec 03 §4.17.1)
  kMotionInPosition,          // MC_MotionInPosition (spec 03 §4.17.2)
  kMoveSuperimposed,          // MC_MoveSuperimposed (positioning_axis/superimposed_motion.hpp)
  kHaltSuperimposed,          // MC_HaltSuperimposed
  kMotionInSuperimposed,      // MC_MotionInSuperimposed (spec 03 §4.17.3)
  kMotionInSuperimposedAxes,  // MC_MotionInSuperimposedAxes (spec 03 §4.17.4)
  kPhasing,  // MC_PhasingAbsolute / MC_PhasingRelative (the synchronous operation's leading value offset)
  kOffset,   // MC_OffsetAbsolute / MC_OffsetRelative (its following value offset)
  kLeadingValueAdditive,          // MC_LeadingValueAdditive
  kSynchronizedMotionSimulation,  // MC_SynchronizedMotionSimulation
  kSetSensor,                     // MC_SetSensor (positioning_axis_encoders.cpp)
};

// The enable state of an axis (MC_Power, spec 01 §6, spec 02 §3.1).
enum class PowerPhase : std::uint8_t { kDisabled, kEnabling, kEnabled, kDisabling };

// The running MC_Stop (spec 03 §4.13): its weight against alarm reactions (seed §6.9.4), its dynamics, and
// whether Execute still holds the lock.
struct StopJob {
  JobId id = 0;
  int weight = 0;
  ProfileLimits limits{};
  bool execute = false;
  bool done = false;
};

// The data block's units per internal unit: velocity (DB velocity unit per internal unit/s) and acceleration
// (the same for /s² and /s³).
struct DynamicUnits {
  double velocity = 1.0;
  double acceleration = 1.0;
};

// What a change of the strongest pending alarm asks of the TO (AxisCore::reaction_change()).
enum class ReactionChange : std::uint8_t {
  kNone,       // the reaction in force did not change
  kReleased,   // weaker or none after MC_Reset: the TO is no longer blocked (the phase is updated)
  kEscalated,  // a stronger reaction: end the jobs, then stop_ramp()/stop_keeps_control() decide the motion
};

// What update_power_phase() asks of the TO.
enum class PowerEvent : std::uint8_t {
  kNone,
  kEnabled,    // enabling finished: take the actual state as setpoint (spec 01 §6.2)
  kDisabling,  // Enable = FALSE: end every job; disable_ramp() says how the setpoint stops
};

class AxisCore {
 public:
  // ---- MC_Power (spec 03 §4.1): 16#8012 under the panel, invalid StartMode/StopMode ----
  PowerState power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept;
  // ---- MC_Reset (spec 03 §4.2): Restart needs a disabled axis ----
  Submission reset(bool restart) noexcept;
  // The MC_Reset job in this interpolator cycle: acknowledges the alarms and returns whether a restart was
  // asked for (nullopt: no reset pending). The TO acknowledges its own monitors, restarts, then
  // finish_reset().
  std::optional<bool> begin_reset(std::uint64_t cycle) noexcept;
  void finish_reset() noexcept { jobs.set(reset_job_, JobState::kDone); }
  // An MC_Reset with Restart = TRUE waits for its interpolator cycle (MC_SetSensor's prerequisite).
  bool restart_pending() const noexcept { return reset_pending_ && restart_requested_; }
  // ---- MC_Stop (spec 03 §4.13) ----
  // Whether a stop reaction of an alarm with a higher weight is in force: the MC_Stop ends with
  // CommandAborted, not Error (seed §6.9.4, spec 02 §3.8).
  bool stop_outweighed(int weight) const noexcept {
    return stop_weight_of_reaction(static_cast<int>(reaction_in_force)) > weight;
  }
  // Records a new MC_Stop (the running one, if any, aborted).
  JobId start_stop(int weight, const ProfileLimits& limits) noexcept;
  void stop_execute(JobId job, bool execute) noexcept;
  void abort_stop() noexcept;
  bool stop_locks() const noexcept { return stop.id != 0 && stop.execute; }  // 16#8013 for new motion
  bool stop_running() const noexcept { return stop.id != 0 && (!stop.done || stop.execute); }
  // The stop ramp reached standstill: Done (released at once without Execute).
  void stop_reached_standstill() noexcept;
  // ---- job prerequisites (spec 03 §3.2) and dynamics (spec 03 §2.1, spec 01 §8.1/§8.5) ----
  std::uint16_t motion_prerequisites() const noexcept;
  // < 0 -> DynamicDefaults, = 0 invalid (jerk: no jerk limit), > 0 as given; limited to DynamicLimits with
  // warnings 501/502/503. MaxJerk > 0 also caps a job without jerk limit (docs/decisions.md S3). Velocity
  // NaN: the caller's (MoveVelocity, Jog, Halt), `out.velocity` = the velocity limit.
  std::optional<std::uint16_t> resolve_dynamics(double velocity, double acceleration, double deceleration,
                                                double jerk, const TO_Struct_DynamicDefaults& defaults,
                                                const TO_Struct_DynamicLimits& limits, DynamicUnits units,
                                                ProfileLimits& out) noexcept;
  // The override in force (spec 01 §8.4: 0 ... 200 %; none while the axis control panel adapts the velocity,
  // spec 02 §9.3) and the velocity limit min(MaxVelocity, Velocity) (spec 01 §8.3) in internal units.
  double override_factor(const TO_Struct_Override& o) const noexcept {
    if (control.override_ineffective()) return 1.0;  // spec 02 §9.3: the panel has its own "adapt velocity"
    return std::clamp(o.Velocity, 0.0, 200.0) / 100.0;  // spec 01 §8.4: 0..200 %
  }
  static double velocity_limit(const TO_Struct_DynamicLimits& l, DynamicUnits u) noexcept {
    return std::min(l.MaxVelocity, l.Velocity) / u.velocity;
  }
  // The checks of a new MC_Stop every axis shares (spec 03 §4.13): 16#8012 under the panel, Mode 1 or an
  // unknown Mode invalid, the dynamics per Mode (0 emergency ramp without jerk limit, 2 maximum dynamics, 3
  // as given), the axis enabled, a stronger alarm reaction in force (accepted as CommandAborted, seed
  // §6.9.4), then the §9.19.1 row MC_Stop against the TO's `running` jobs (a stop of a lower weight cannot
  // replace a running one: 16#8016). A Submission when that decides; nullopt: the TO ends its jobs and calls
  // start_stop(weight, limits).
  std::optional<Submission> stop_request(const StopInputs& in, const TO_Struct_DynamicDefaults& d,
                                         const TO_Struct_DynamicLimits& l, DynamicUnits u,
                                         std::span<const RunningJob> running, int& weight,
                                         ProfileLimits& limits) noexcept;
  // ---- ramps (spec 02 §3.1, §3.7): internal units ----
  static ProfileLimits emergency_ramp(const TO_Struct_DynamicDefaults& d, DynamicUnits u) noexcept;
  static ProfileLimits max_dynamics_ramp(const TO_Struct_DynamicLimits& l, DynamicUnits u) noexcept;
  static ProfileLimits default_ramp(const TO_Struct_DynamicDefaults& d, DynamicUnits u) noexcept;
  // ---- alarms and reactions (spec 02 §1, §3.4) ----
  void raise(std::uint32_t number, std::uint32_t additional = 0) noexcept {
    (void)alarms.raise(number, additional, cycle);
  }
  bool blocked() const noexcept { return reaction_in_force != AlarmReaction::kNone; }
  bool enable_removed() const noexcept { return reaction_in_force == AlarmReaction::kRemoveEnable; }
  // MC_Interpolator: takes the strongest pending reaction over. On release after "remove enable" / "follow
  // setpoint" an MC_Power whose Enable stayed TRUE enables the axis again (spec 03 §3.3 L2).
  // Inline: the steady cycle (no reaction, no alarm) returns before the call (issue 23, decision P26).
  ReactionChange reaction_change() noexcept {
    if (reaction_in_force == AlarmReaction::kNone && alarms.alarms().empty()) return ReactionChange::kNone;
    return take_reaction();
  }
  // After an escalation: a running MC_Stop of at least the alarm's weight keeps control (seed §6.9.4), else
  // it ends with CommandAborted. `stop_may_keep` = FALSE where another rule takes over (software-limit stop).
  bool stop_keeps_control(bool stop_may_keep = true) noexcept;
  // The ramp of the stop reaction in force (1, 2, 3); nullopt for 4/5, where the drive brakes or is followed.
  std::optional<ProfileLimits> reaction_ramp(const ProfileLimits& current, const TO_Struct_DynamicDefaults& d,
                                             const TO_Struct_DynamicLimits& l, DynamicUnits u) const noexcept;
  // ---- the drive (spec 02 §3.1, §3.4) ----
  // Within the hold-off after an MC_Reset: a condition still present is not raised again yet.
  bool held_off() const noexcept {
    return acknowledged_at_ != 0 && cycle < acknowledged_at_ + kReRaiseHoldOffCycles;
  }
  // MC_Servo: drive alarms 401/402/405/406, once per appearance and again after MC_Reset's hold-off; the
  // drive-autonomous stops of Safety Integrated (spec 01 §4, seed §6.3.1): 421 when the drive coasts (OFF2,
  // STO) and 550 when it brakes on its OFF3 ramp (SS1/SS2) while the TO asks for operation.
  void supervise_drive(const DriveConnection& drive) noexcept;
  // What the drive is asked to do: remove enable -> Actor.RemoveEnableReaction (OFF1/OFF2/OFF3), enabling
  // and enabled -> operate, disabling and disabled per StopMode.
  telegrams::DriveRequest drive_request(std::int32_t remove_enable_reaction) const noexcept;
  // The drive follows the TO's setpoint (enabled, or ramping down with StopMode 0/2).
  bool drive_follows_setpoint() const noexcept {
    return phase == PowerPhase::kEnabled ||
           (phase == PowerPhase::kDisabling && stop_mode != 1 && stop_mode != 3);
  }
  // The setpoint follows the actual value (spec 02 §3.2): disabled, enabling, remove enable, follow setpoint,
  // or disabling with StopMode 1/3.
  bool follows_actual() const noexcept {
    return phase == PowerPhase::kDisabled || phase == PowerPhase::kEnabling ||
           reaction_in_force == AlarmReaction::kRemoveEnable ||
           reaction_in_force == AlarmReaction::kFollowSetpoint ||
           (phase == PowerPhase::kDisabling && (stop_mode == 1 || stop_mode == 3));
  }
  // ---- the power phase, MC_Interpolator ----
  // `ready`: the drive is in operation with valid actual values (always TRUE on a virtual axis).
  // Inline: an enabled axis whose Enable stays TRUE has nothing to change (issue 23, decision P26).
  PowerEvent update_power_phase(bool ready) noexcept {
    if (phase == PowerPhase::kEnabled && enable) return PowerEvent::kNone;
    return change_power_phase(ready);
  }
  // The ramp of a disable with StopMode 0 (emergency) or 2 (maximum dynamics); nullopt for 1/3.
  std::optional<ProfileLimits> disable_ramp(const TO_Struct_DynamicDefaults& d,
                                            const TO_Struct_DynamicLimits& l, DynamicUnits u) const noexcept;
  // MC_Interpolator while disabling: settled = the setpoint ramp ended at standstill (StopMode 0/2),
  // drive_stopped = the drive left operation and stands (StopMode 1).
  void finish_disabling(bool settled, bool drive_stopped) noexcept;
  // ---- MC_WriteParameter 1010–1012 and MC_SetAxisSTW (spec 03 §4.15, §4.16) ----
  // T_i/T_o/T_DC, effective after restart (StatusWord.X3 meanwhile).
  Submission write_communication_time(std::int32_t number, double value, std::uint32_t& status_word) noexcept;
  Submission set_axis_stw(DriveConnection* drive, std::uint16_t stw1, std::uint16_t stw1_mask,
                          std::uint16_t stw2, std::uint16_t stw2_mask) noexcept;
  // ---- restart (MC_Reset Restart = TRUE, spec 01 §7) ----
  void restart() noexcept;
  // ---- status (spec 04 §5) ----
  // The bits every axis shows: X0 Enable, X1 Error, X4 ControlPanelActive, X25 TorqueLimitingCommand, X26
  // InLimitation, X30 AxisSimulation, X3 kept; StatusWord2 X0 StopCommand; the ErrorWord/WarningWord bits of
  // the pending alarms (a column of the alarm table) and ErrorDetail.
  // Inline: once per interpolator cycle of every axis; the words stay in registers (issue 23, P26).
  void update_words(std::uint32_t& status_word, std::uint32_t& status_word2, std::uint32_t& error_word,
                    std::uint32_t& warning_word, TO_Struct_ErrorDetail& detail,
                    bool simulation) const noexcept {
    assign(status_word, StatusWordBit::kEnable, phase == PowerPhase::kEnabled && !enable_removed());
    const bool pending = !alarms.alarms().empty();
    assign(status_word, StatusWordBit::kError, pending && alarms.any_error());
    assign(status_word, StatusWordBit::kControlPanelActive, control.held());
    assign(status_word, StatusWordBit::kTorqueLimitingCommand, torque.active);
    assign(status_word, StatusWordBit::kInLimitation, in_limitation);
    assign(status_word, StatusWordBit::kAxisSimulation, simulation);
    assign(status_word2, StatusWord2Bit::kStopCommand, stop.id != 0);
    if (!pending) {  // the usual cycle: nothing to look up
      detail = TO_Struct_ErrorDetail{};
      return;
    }
    alarm_status(error_word, warning_word, detail);
  }

  // The start conditions of MC_TorqueAdditive / MC_TorqueRange (torque_data.hpp): `drive` nullptr on a
  // virtual or simulated axis; `reference` and `inverse` give the wire format of the limits.
  TorqueDataConditions torque_data_conditions(const DriveConnection* drive, double reference,
                                              bool inverse) const noexcept {
    TorqueDataConditions c;
    c.drive = drive != nullptr;
    c.telegram_750 = drive != nullptr && drive->device_config().supplementary_telegram == 750;
    c.enabled = phase == PowerPhase::kEnabled;
    c.stop_locks = stop_locks();
    c.panel = control.program_job_rejection();
    c.torque_limiting = torque.active;
    c.reference = reference;
    c.inverse = inverse;
    return c;
  }

  // ---- state: read by the TO's own steps ----
  AlarmList alarms;
  JobTable<AxisJobKind> jobs;
  ControlPriority control;
  PowerPhase phase = PowerPhase::kDisabled;
  bool enable = false;
  std::int32_t start_mode = 1;
  std::int32_t stop_mode = 0;
  AlarmReaction reaction_in_force = AlarmReaction::kNone;  // one byte since decision M8
  bool in_limitation = false;  // MELDW.1 while limiting (beside the one-byte reaction: no padding)
  StopJob stop{};
  CommunicationTimes communication_times{};        // in force
  CommunicationTimes communication_times_start{};  // written by MC_WriteParameter, taken at restart
  TorqueLimitingRequest torque{};                  // MC_TorqueLimiting
  TorqueDataJobs torque_data{};                    // MC_TorqueAdditive, MC_TorqueRange (telegram 750)
  std::uint64_t cycle = 0;                         // interpolator cycles + 1 (0 = never)
  double ipo_cycle_s = 0.001;
  double enable_timeout_s = 2.0;

 private:
  bool safe_stop(const DriveConnection& drive) noexcept;  // 421/550; TRUE while a safe stop is seen
  // update_words() with alarms pending: their ErrorWord/WarningWord bits and ErrorDetail.
  void alarm_status(std::uint32_t& error_word, std::uint32_t& warning_word,
                    TO_Struct_ErrorDetail& detail) const noexcept;
  ReactionChange take_reaction() noexcept;             // reaction_change() with an alarm or a reaction
  PowerEvent change_power_phase(bool ready) noexcept;  // update_power_phase() off its steady state
  // A condition still present this long after MC_Reset is raised again (drive supervision, decision S8).
  static constexpr std::uint64_t kReRaiseHoldOffCycles = 20;
  std::uint64_t enabling_since_ = 0;
  std::uint64_t acknowledged_at_ = 0;
  bool drive_fault_seen_ = false;
  std::uint8_t safe_stop_seen_ = 0;  // drive-autonomous stops seen (kSafeTorqueOff, kSafeStopRamp bits)
  bool reset_pending_ = false;
  bool restart_requested_ = false;
  JobId reset_job_ = 0;
};

}  // namespace tomc::techobjects
