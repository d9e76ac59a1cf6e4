#pragma once
// Technology alarms (seed 004 §6.6, §6.9.2; spec 02 §1.1, §1.3; spec 04 §0.5, §7): number, class (W/F/R),
// reaction (0..5) and the alarm's additional value; the alarms pending on one TO, the one ErrorDetail shows,
// and the runtime-wide log that diagnostics read later. Fixed capacity, no allocation: alarms are raised in
// MC_Servo and MC_Interpolator.

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace tomc::techobjects {

// <TO>.ErrorDetail.Reaction (spec 02 §1.1).
// One byte (decision M8): stored in every pending alarm; <TO>.ErrorDetail.Reaction (DINT) converts it.
enum class AlarmReaction : std::uint8_t {
  kNone = 0,
  kStopCurrentDynamics = 1,
  kStopMaxDynamics = 2,
  kStopEmergencyRamp = 3,
  kRemoveEnable = 4,
  kFollowSetpoint = 5,
};
std::string_view to_string(AlarmReaction reaction) noexcept;

// Alarm classes (spec 04 §0.5): W acknowledgeable warning, F acknowledgeable alarm, R needs a TO restart.
enum class AlarmClass : std::uint8_t { kWarning, kAcknowledge, kRestart };

struct AlarmDefinition {
  std::uint32_t number;
  AlarmClass alarm_class;
  AlarmReaction reaction;  // the system-defined reaction; configurable ones give their default here
  std::string_view text;
  // The bit of <TO>.ErrorWord (classes F/R) or <TO>.WarningWord (class W) that shows the alarm while it is
  // pending (spec 04 §5.3, §5.4), the same on every TO type; kNoWordBit where another status decides (the
  // limit switches' bits come from their monitors, with the side).
  std::int8_t word_bit = -1;
};
inline constexpr std::int8_t kNoWordBit = -1;

// The alarms tomc raises (docs/errors.md lists them with their sources). nullptr for an unknown number.
const AlarmDefinition* find_alarm(std::uint32_t number) noexcept;
std::span<const AlarmDefinition> alarm_definitions() noexcept;

// Alarm numbers (seed-named ones and [OUR CHOICE] ones for drive communication, docs/decisions.md A1).
// A restart found start values that cannot be applied together (ErrorWord.X1 ConfigFault, class R; the
// additional value names the rule, kConfiguration* below), [OUR CHOICE] B8.
inline constexpr std::uint32_t kAlarmConfiguration = 102;
inline constexpr std::uint32_t kAlarmDriveFault = 401;          // drive reports a fault (ZSW1.3)
inline constexpr std::uint32_t kAlarmDriveNotReady = 402;       // drive dropped "control requested" / left S4
inline constexpr std::uint32_t kAlarmDriveCommunication = 405;  // no fresh frames (link lost)
inline constexpr std::uint32_t kAlarmDriveSignOfLife = 406;     // drive sign-of-life failed
inline constexpr std::uint32_t kAlarmModuloTooFast = 412;       // seed L3946
inline constexpr std::uint32_t kAlarmDriveSto = 421;            // seed L2712
inline constexpr std::uint32_t kAlarmSensorFault = 431;         // encoder error (Gx_ZSW.15), [OUR CHOICE]
inline constexpr std::uint32_t kAlarmAdjustmentLost = 432;      // absolute-encoder adjustment not restored
// an encoder that does not close the position loop reported an error (Gx_ZSW.15), [OUR CHOICE] B2
inline constexpr std::uint32_t kAlarmAdditionalSensorFault = 433;
inline constexpr std::uint32_t kAlarmDynamicsLimitedVelocity = 501;  // seed §10.3.15
inline constexpr std::uint32_t kAlarmDynamicsLimitedAcceleration = 502;
inline constexpr std::uint32_t kAlarmDynamicsLimitedJerk = 503;
inline constexpr std::uint32_t kAlarmFollowingError = 521;
inline constexpr std::uint32_t kAlarmFollowingErrorWarning = 522;
inline constexpr std::uint32_t kAlarmHardwareLimit = 531;
inline constexpr std::uint32_t kAlarmSoftwareLimitReached = 533;
inline constexpr std::uint32_t kAlarmSoftwareLimitExceeded = 534;
inline constexpr std::uint32_t kAlarmPositioning = 541;
inline constexpr std::uint32_t kAlarmDriveSafeStop = 550;  // seed L2719
inline constexpr std::uint32_t kAlarmHomingFailed = 560;   // homing could not be completed, [OUR CHOICE]
inline constexpr std::uint32_t kAlarmLeadingAxisDefective = 601;         // spec 07 §1.10 (ALM8)
inline constexpr std::uint32_t kAlarmLeaderNotPositionControlled = 603;  // spec 07 §1.10
inline constexpr std::uint32_t kAlarmSynchronizationError = 608;  // leading value reversed, spec 07 §1.10
inline constexpr std::uint32_t kAlarmCamNotInterpolated = 612;    // camming with such a cam, spec 07 §3.2

// The additional values of alarm 102 (decision B8): which rule the start values of the restart broke.
// 1: Simulation.Mode 0 on an axis built without a drive ("at the end of the simulation a valid drive and
//    encoder integration must be present", seed 004 §6.1.7);
// 2: Simulation.Mode 1 with PositionControl.InitialOperativeSensor ≠ 1 ("encoder 1 must be used for position
//    control", seed 004 §6.1.7);
// 3: PositionControl.InitialOperativeSensor names an encoder whose Sensor[n].Existent is FALSE (spec 04
// §3.20).
inline constexpr std::uint32_t kConfigurationNoDrive = 1;
inline constexpr std::uint32_t kConfigurationSimulationEncoder = 2;
inline constexpr std::uint32_t kConfigurationNoSuchEncoder = 3;

// 16 bytes (24 before decision M8): the alarm numbers of the table fit 16 bits (find_alarm() admits no
// other).
struct PendingAlarm {
  std::uint16_t number = 0;
  AlarmClass alarm_class = AlarmClass::kAcknowledge;
  AlarmReaction reaction = AlarmReaction::kNone;
  std::uint32_t additional_value = 0;
  std::uint64_t raised_cycle = 0;
};

// The ErrorWord and WarningWord bits of the pending alarms (the table's word_bit column).
void alarm_words(std::span<const PendingAlarm> pending, std::uint32_t& error_word,
                 std::uint32_t& warning_word) noexcept;

// One record of the alarm history.
struct AlarmEvent {
  enum class Kind : std::uint8_t { kRaised, kAcknowledged };
  std::uint64_t sequence = 0;  // 1, 2, 3, ... per log (in a view of one TO: per TO)
  std::uint64_t cycle = 0;
  Kind kind = Kind::kRaised;
  std::uint32_t number = 0;
  std::uint32_t additional_value = 0;
  AlarmReaction reaction = AlarmReaction::kNone;
  std::uint32_t source = 0;           // the AlarmList that wrote it (AlarmList::attach), 0 = none
  std::uint64_t source_sequence = 0;  // 1, 2, 3, ... per source
};

// The alarm history of a runtime: the last kCapacity events of all its TOs, oldest overwritten first (one
// ring per runtime instead of one per TO; each TO keeps only its pending alarms). Written on the cycle; read
// by diagnostics on the same thread (a snapshot publisher hands it to other threads, issue 7).
class AlarmLog {
 public:
  static constexpr std::size_t kCapacity = 1024;
  void append(AlarmEvent event) noexcept;
  // Copies events with sequence > after, oldest first, into out; returns how many were copied. Events that
  // were overwritten before being read are lost (lost_before() tells up to where).
  std::size_t copy_since(std::uint64_t after, std::span<AlarmEvent> out) const noexcept;
  std::uint64_t last_sequence() const noexcept { return next_sequence_ - 1; }
  std::uint64_t lost_before() const noexcept;
  // The event with this sequence (lost_before() <= sequence <= last_sequence()).
  const AlarmEvent& at(std::uint64_t sequence) const noexcept { return ring_[(sequence - 1) % kCapacity]; }

 private:
  std::array<AlarmEvent, kCapacity> ring_{};
  std::uint64_t next_sequence_ = 1;
};

// The events of one TO in its runtime's AlarmLog, numbered per TO (AlarmList::log()).
class AlarmLogView {
 public:
  AlarmLogView(const AlarmLog* log, std::uint32_t source, std::uint64_t last,
               std::uint64_t last_in_log) noexcept
      : log_(log), source_(source), last_(last), last_in_log_(last_in_log) {}
  // As AlarmLog::copy_since, with the TO's own sequence numbers (AlarmEvent::sequence = source_sequence).
  std::size_t copy_since(std::uint64_t after, std::span<AlarmEvent> out) const noexcept;
  std::uint64_t last_sequence() const noexcept { return last_; }

 private:
  const AlarmLog* log_;
  std::uint32_t source_;
  std::uint64_t last_;         // the TO's events so far
  std::uint64_t last_in_log_;  // the log sequence of its newest event
};

// The technology alarms pending on one TO.
class AlarmList {
 public:
  static constexpr std::size_t kCapacity = 16;

  // Where raised and acknowledged alarms are recorded (the runtime's log; Runtime::add_technology_object
  // attaches it). Unattached, the events are counted but not kept.
  void attach(AlarmLog& log, std::uint32_t source) noexcept {
    log_ = &log;
    source_ = source;
  }

  // Raises an alarm (once: an alarm already pending with the same number keeps its first record). Returns
  // false for an unknown number or a full list (then the most severe pending reaction still governs).
  bool raise(std::uint32_t number, std::uint32_t additional_value, std::uint64_t cycle) noexcept;
  bool raise(std::uint32_t number, std::uint32_t additional_value, AlarmReaction reaction,
             std::uint64_t cycle) noexcept;
  // MC_Reset: clears W and F alarms; with restart also R alarms (spec 01 §7). Returns how many were cleared.
  std::size_t acknowledge(bool restart, std::uint64_t cycle) noexcept;

  bool pending(std::uint32_t number) const noexcept;
  bool any_error() const noexcept;    // F or R pending (ErrorWord side)
  bool any_warning() const noexcept;  // W pending (WarningWord side)
  // The strongest reaction pending (remove enable 4 > emergency 3 > max 2 > current 1; follow setpoint 5
  // counts as remove-enable-like blocking; none 0).
  AlarmReaction strongest_reaction() const noexcept;
  // What <TO>.ErrorDetail shows: the highest-priority pending alarm (strongest reaction, then the oldest).
  const PendingAlarm* error_detail() const noexcept;
  std::span<const PendingAlarm> alarms() const noexcept { return {alarms_.data(), count_}; }
  // This TO's alarm history (its events in the runtime's log).
  AlarmLogView log() const noexcept { return {log_, source_, events_, last_in_log_}; }

 private:
  void record(AlarmEvent event) noexcept;

  std::array<PendingAlarm, kCapacity> alarms_{};
  AlarmLog* log_ = nullptr;
  std::uint32_t count_ = 0;  // beside source_: no padding (decision M8)
  std::uint32_t source_ = 0;
  std::uint64_t events_ = 0;       // events raised/acknowledged so far
  std::uint64_t last_in_log_ = 0;  // the log sequence of the newest one
};

// Rank of a reaction for choosing among pending alarms: 4 remove enable, 5 follow setpoint, 3, 2, 1, 0.
int reaction_rank(AlarmReaction reaction) noexcept;

}  // namespace tomc::techobjects
