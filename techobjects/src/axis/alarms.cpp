#include "tomc/techobjects/axis/alarms.hpp"

#include <algorithm>

namespace tomc::techobjects {
namespace {

using C = AlarmClass;
using R = AlarmReaction;

// The ErrorWord/WarningWord bit numbers of spec 04 §5.3/§5.4 that alarms show (the same number in both
// words).
namespace B {
constexpr std::int8_t kConfig = 1;           // ConfigFault
constexpr std::int8_t kDrive = 4;            // DriveFault / DriveWarning
constexpr std::int8_t kSensor = 5;           // SensorFault
constexpr std::int8_t kDynamic = 6;          // DynamicError / DynamicWarning
constexpr std::int8_t kCommunication = 7;    // CommunicationFault
constexpr std::int8_t kHoming = 10;          // HomingError
constexpr std::int8_t kFollowingError = 11;  // FollowingErrorFault / FollowingErrorWarning
constexpr std::int8_t kPositioning = 12;     // PositioningFault
constexpr std::int8_t kSynchronous = 14;     // SynchronousError (spec 07 §1.9)
}  // namespace B

// Reactions as the manual states them (spec 02 §1.3, spec 04 §7); 533/534/531 are configurable and carry
// their default here; the drive-communication alarms 401..406 are [OUR CHOICE] (docs/decisions.md A1).
constexpr AlarmDefinition kAlarms[] = {
    // Class R: only MC_Reset with Restart = TRUE clears it, and the restart checks the start values again.
    {kAlarmConfiguration, C::kRestart, R::kRemoveEnable,
     "configuration error at restart: start values that cannot be applied together (additional value: 1 "
     "Simulation.Mode 0 without a drive, 2 simulation without encoder 1 in the loop, 3 "
     "InitialOperativeSensor names no existing encoder); they are not taken over",
     B::kConfig},
    {kAlarmDriveFault, C::kAcknowledge, R::kRemoveEnable, "drive fault (ZSW1.3 fault present)", B::kDrive},
    {kAlarmDriveNotReady, C::kAcknowledge, R::kRemoveEnable,
     "drive not ready: control not requested or left operation", B::kDrive},
    {kAlarmDriveCommunication, C::kAcknowledge, R::kRemoveEnable, "communication with the drive lost",
     B::kCommunication},
    {kAlarmDriveSignOfLife, C::kAcknowledge, R::kRemoveEnable, "drive sign-of-life failure",
     B::kCommunication},
    {kAlarmModuloTooFast, C::kAcknowledge, R::kRemoveEnable,
     "modulo axis faster than Modulo.Length / servo cycle", B::kDynamic},
    {kAlarmDriveSto, C::kAcknowledge, R::kRemoveEnable, "drive STO / autonomous OFF2", B::kDrive},
    {kAlarmSensorFault, C::kAcknowledge, R::kRemoveEnable, "encoder error (Gx_ZSW.15, code in Gx_XIST2)",
     B::kSensor},
    {kAlarmAdditionalSensorFault, C::kAcknowledge, R::kNone,
     "error of an encoder that is not the operative one (additional value: encoder number * 65536 + code)",
     B::kSensor},
    {kAlarmAdjustmentLost, C::kAcknowledge, R::kNone,
     "absolute-encoder adjustment not restored (backup missing or corrupt): the axis is not homed",
     B::kHoming},
    {kAlarmDynamicsLimitedVelocity, C::kWarning, R::kNone,
     "programmed velocity limited to the dynamic limits", B::kDynamic},
    {kAlarmDynamicsLimitedAcceleration, C::kWarning, R::kNone, "programmed acceleration/deceleration limited",
     B::kDynamic},
    {kAlarmDynamicsLimitedJerk, C::kWarning, R::kNone, "programmed jerk limited", B::kDynamic},
    {kAlarmFollowingError, C::kAcknowledge, R::kRemoveEnable, "permissible following error exceeded",
     B::kFollowingError},
    {kAlarmFollowingErrorWarning, C::kWarning, R::kNone, "following-error warning level reached",
     B::kFollowingError},
    {kAlarmHardwareLimit, C::kAcknowledge, R::kRemoveEnable, "hardware limit switch approached", kNoWordBit},
    {kAlarmSoftwareLimitReached, C::kAcknowledge, R::kStopMaxDynamics, "software limit switch reached",
     kNoWordBit},
    {kAlarmSoftwareLimitExceeded, C::kAcknowledge, R::kRemoveEnable, "software limit switch passed",
     kNoWordBit},
    {kAlarmPositioning, C::kAcknowledge, R::kRemoveEnable, "positioning monitoring", B::kPositioning},
    {kAlarmDriveSafeStop, C::kAcknowledge, R::kFollowSetpoint, "drive-autonomous SS1/SS2 OFF3 braking",
     B::kDrive},
    {kAlarmHomingFailed, C::kAcknowledge, R::kStopMaxDynamics, "homing could not be completed", B::kHoming},
    {kAlarmLeadingAxisDefective, C::kAcknowledge, R::kStopMaxDynamics,
     "leading axis not assigned (not a configured leading value) or defective", B::kSynchronous},
    {kAlarmLeaderNotPositionControlled, C::kAcknowledge, R::kRemoveEnable,
     "leading axis not position-controlled (setpoint coupling)", B::kSynchronous},
    {kAlarmSynchronizationError, C::kAcknowledge, R::kStopMaxDynamics,
     "error during synchronization / desynchronization: the leading value reversed", B::kSynchronous},
    {kAlarmCamNotInterpolated, C::kAcknowledge, R::kRemoveEnable, "cyclic cam not interpolated (MC_CamIn)",
     B::kSynchronous},
};

}  // namespace

std::string_view to_string(AlarmReaction reaction) noexcept {
  switch (reaction) {
    case R::kNone:
      return "none";
    case R::kStopCurrentDynamics:
      return "stop with current dynamic values";
    case R::kStopMaxDynamics:
      return "stop with maximum dynamic values";
    case R::kStopEmergencyRamp:
      return "stop with emergency stop ramp";
    case R::kRemoveEnable:
      return "remove enable";
    case R::kFollowSetpoint:
      return "follow setpoint";
  }
  return "?";
}

// PendingAlarm keeps the number in 16 bits (decision M8): every number of the table must fit.
static_assert([] {
  for (const auto& a : kAlarms) {
    if (a.number > 0xFFFFu) return false;
  }
  return true;
}());

const AlarmDefinition* find_alarm(std::uint32_t number) noexcept {
  for (const auto& a : kAlarms) {
    if (a.number == number) return &a;
  }
  return nullptr;
}

std::span<const AlarmDefinition> alarm_definitions() noexcept {
  return kAlarms;
}

int reaction_rank(AlarmReaction reaction) noexcept {
  switch (reaction) {
    case R::kRemoveEnable:
      return 5;
    case R::kFollowSetpoint:
      return 4;
    case R::kStopEmergencyRamp:
      return 3;
    case R::kStopMaxDynamics:
      return 2;
    case R::kStopCurrentDynamics:
      return 1;
    case R::kNone:
      return 0;
  }
  return 0;
}

void AlarmLog::append(AlarmEvent event) noexcept {
  event.sequence = next_sequence_++;
  ring_[(event.sequence - 1) % kCapacity] = event;
}

std::uint64_t AlarmLog::lost_before() const noexcept {
  const std::uint64_t written = next_sequence_ - 1;
  return written > kCapacity ? written - kCapacity + 1 : 1;
}

std::size_t AlarmLog::copy_since(std::uint64_t after, std::span<AlarmEvent> out) const noexcept {
  std::uint64_t first = std::max(after + 1, lost_before());
  std::size_t copied = 0;
  for (std::uint64_t s = first; s < next_sequence_ && copied < out.size(); ++s)
    out[copied++] = ring_[(s - 1) % kCapacity];
  return copied;
}

void alarm_words(std::span<const PendingAlarm> pending, std::uint32_t& error_word,
                 std::uint32_t& warning_word) noexcept {
  for (const PendingAlarm& a : pending) {
    const AlarmDefinition* d = find_alarm(a.number);
    if (d == nullptr || d->word_bit < 0) continue;
    std::uint32_t& word = d->alarm_class == AlarmClass::kWarning ? warning_word : error_word;
    word |= 1u << static_cast<unsigned>(d->word_bit);
  }
}

void AlarmList::record(AlarmEvent event) noexcept {
  event.source = source_;
  event.source_sequence = ++events_;
  if (log_ == nullptr) return;
  log_->append(event);
  last_in_log_ = log_->last_sequence();
}

std::size_t AlarmLogView::copy_since(std::uint64_t after, std::span<AlarmEvent> out) const noexcept {
  if (log_ == nullptr || after >= last_ || out.empty()) return 0;  // the common case: nothing new, O(1)
  // Walk back from the TO's newest event to its first one after `after` (or the oldest kept), then copy
  // forwards, oldest first as AlarmLog::copy_since. Bounded by the log's capacity.
  const std::uint64_t oldest = log_->lost_before();
  std::uint64_t first = last_in_log_ + 1;
  for (std::uint64_t s = last_in_log_; s >= oldest && s >= 1; --s) {
    const AlarmEvent& e = log_->at(s);
    if (e.source != source_) continue;
    if (e.source_sequence <= after) break;
    first = s;
  }
  std::size_t copied = 0;
  for (std::uint64_t s = first; s <= last_in_log_ && copied < out.size(); ++s) {
    const AlarmEvent& e = log_->at(s);
    if (e.source != source_) continue;
    out[copied] = e;
    out[copied].sequence = e.source_sequence;
    ++copied;
  }
  return copied;
}

bool AlarmList::raise(std::uint32_t number, std::uint32_t additional_value, std::uint64_t cycle) noexcept {
  const auto* definition = find_alarm(number);
  if (definition == nullptr) return false;
  return raise(number, additional_value, definition->reaction, cycle);
}

bool AlarmList::raise(std::uint32_t number, std::uint32_t additional_value, AlarmReaction reaction,
                      std::uint64_t cycle) noexcept {
  const auto* definition = find_alarm(number);
  if (definition == nullptr) return false;
  if (pending(number)) return true;
  if (count_ == kCapacity) return false;
  alarms_[count_++] = PendingAlarm{static_cast<std::uint16_t>(number), definition->alarm_class, reaction,
                                   additional_value, cycle};
  record(AlarmEvent{0, cycle, AlarmEvent::Kind::kRaised, number, additional_value, reaction});
  return true;
}

std::size_t AlarmList::acknowledge(bool restart, std::uint64_t cycle) noexcept {
  std::uint32_t kept = 0;
  std::size_t cleared = 0;
  for (std::uint32_t i = 0; i < count_; ++i) {
    const PendingAlarm& a = alarms_[i];
    if (a.alarm_class != AlarmClass::kRestart || restart) {
      record(AlarmEvent{0, cycle, AlarmEvent::Kind::kAcknowledged, a.number, a.additional_value, a.reaction});
      ++cleared;
    } else {
      alarms_[kept++] = a;
    }
  }
  count_ = kept;
  return cleared;
}

bool AlarmList::pending(std::uint32_t number) const noexcept {
  return std::any_of(alarms_.begin(), alarms_.begin() + static_cast<std::ptrdiff_t>(count_),
                     [&](const PendingAlarm& a) { return a.number == number; });
}

bool AlarmList::any_error() const noexcept {
  return std::any_of(alarms_.begin(), alarms_.begin() + static_cast<std::ptrdiff_t>(count_),
                     [](const PendingAlarm& a) { return a.alarm_class != AlarmClass::kWarning; });
}

bool AlarmList::any_warning() const noexcept {
  return std::any_of(alarms_.begin(), alarms_.begin() + static_cast<std::ptrdiff_t>(count_),
                     [](const PendingAlarm& a) { return a.alarm_class == AlarmClass::kWarning; });
}

AlarmReaction AlarmList::strongest_reaction() const noexcept {
  const PendingAlarm* top = error_detail();
  return top == nullptr ? AlarmReaction::kNone : top->reaction;
}

const PendingAlarm* AlarmList::error_detail() const noexcept {
  const PendingAlarm* top = nullptr;
  for (std::size_t i = 0; i < count_; ++i) {
    // Strictly stronger only: among equals the oldest (first raised) stays on top.
    if (top == nullptr || reaction_rank(alarms_[i].reaction) > reaction_rank(top->reaction))
      top = &alarms_[i];
  }
  return top;
}

}  // namespace tomc::techobjects
