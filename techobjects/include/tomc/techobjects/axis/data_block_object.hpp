#pragma once
// What every TO with a data block holds (issue 14): its name, the device, the data block in work memory and
// its start values in load memory (spec 04 §0.2), the connection to its drive or encoder, and the axis core
// (power phase, reset, alarms and reactions, MC_Stop, jobs, words). The TO types add their own cycle and
// jobs; this class only owns the shared state and the accessors that read it the same way on every type.
#include <string>
#include <string_view>
#include <utility>

#include "tomc/techobjects/axis/axis_core.hpp"
#include "tomc/techobjects/axis/memory_footprint.hpp"
#include "tomc/techobjects/datablocks/data_block_access.hpp"
#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/runtime/start_value_store.hpp"

namespace tomc::techobjects {

// The drive's reference speed (p2000) and torque (p2003) are the axis' Actor.DriveParameter values.
inline DriveConnectionConfig with_reference_values(DriveConnectionConfig config,
                                                   const TO_Struct_Actor& actor) noexcept {
  config.reference_speed_rpm = actor.DriveParameter.ReferenceSpeed;
  config.reference_torque_nm = actor.DriveParameter.ReferenceTorque;
  return config;
}

// The reflection table of each data-block type (spec 04 §1 columns S, P/Y, E).
template <typename Data>
struct DataBlockTraits;
template <>
struct DataBlockTraits<SpeedAxisData> {
  static constexpr DataBlockTable<SpeedAxisData> table{&find_speed_axis_variable, &find_speed_axis_bit};
};
template <>
struct DataBlockTraits<PositioningAxisData> {
  static constexpr DataBlockTable<PositioningAxisData> table{&find_positioning_axis_variable,
                                                             &find_positioning_axis_bit};
};
template <>
struct DataBlockTraits<ExternalEncoderData> {
  static constexpr DataBlockTable<ExternalEncoderData> table{&find_external_encoder_variable,
                                                             &find_external_encoder_bit};
};

template <typename Data>
class DataBlockObject : public TechnologyObject {
 public:
  std::string_view name() const noexcept final { return name_; }
  // Alarm events go to the runtime-wide log; the start values move into the runtime's store.
  void attach(RuntimeServices& services) override {
    core_.alarms.attach(services.alarm_log, services.object_number);
    start_.move_to(services.start_values);
  }

  // ---- the data block (spec 04 §0.2, §0.3; data_block_access.hpp) ----
  const Data& data() const noexcept { return db_; }
  // A user-program write: DIR/CAL variables at once (the TO re-reads what depends on them); RES only
  // through write_start_value + MC_Reset Restart.
  WriteResult write(std::string_view path, double value) noexcept {
    const WriteResult r = table().write(db_, path, value);
    if (r.ok()) written(path);
    return r;
  }
  // A start value (load memory); a RES value that differs from the work memory sets StatusWord.X3.
  WriteResult write_start_value(std::string_view path, double value) noexcept {
    WriteResult r = table().write_start_value(*start_, db_, path, value);
    if (r.ok()) r.value = start_value_written(path, value);
    return r;
  }
  double read(std::string_view path) const noexcept { return table().read(db_, path); }  // NaN: unknown path

  const AlarmList& alarms() const noexcept { return core_.alarms; }
  // Simulation and commissioning: raise a technology alarm as if its cause had occurred, with the reaction it
  // would carry (for configurable reactions). Scenarios and tests use it to exercise every alarm reaction.
  // False for an alarm number tomc does not define.
  bool inject_alarm(std::uint32_t number, std::uint32_t additional_value, AlarmReaction reaction) noexcept {
    return core_.alarms.raise(number, additional_value, reaction, core_.cycle);
  }
  JobStatus job_status(JobId id) const noexcept { return core_.jobs.status(id); }
  // Ti, To, T_DC (seconds) in force; MC_WriteParameter 1010...1012 take effect at the next restart.
  const CommunicationTimes& communication_times() const noexcept { return core_.communication_times; }

 protected:
  DataBlockObject(std::string name, DeviceIo* device, const Data& start_values)
      : name_(std::move(name)), device_(device), start_(start_values), db_(start_values) {}

  static constexpr const DataBlockTable<Data>& table() noexcept { return DataBlockTraits<Data>::table; }
  // A DIR/CAL variable changed by a user-program write: re-configure what depends on it (user call, not
  // cycle).
  virtual void written(std::string_view path) noexcept { (void)path; }
  // A start value was written: the TO may refuse it (an error other than kNone) after preparing for it.
  virtual ValueError start_value_written(std::string_view path, double value) noexcept {
    (void)path;
    (void)value;
    return ValueError::kNone;
  }

  // The heap this part owns (the name; the start values until the runtime adopted them), in bytes.
  std::size_t shared_heap_bytes() const noexcept { return string_heap_bytes(name_) + start_.owned_bytes(); }

  std::string name_;
  DeviceIo* device_ =
      nullptr;               // nullptr: built without a drive (axes: drive_used() tells whether it is used)
  StartValues<Data> start_;  // load memory (the runtime's StartValueStore once attached)
  Data db_;                  // work memory
  DriveConnection drive_;    // its configuration: drive_.config()
  AxisCore core_;
};

// What the speed, positioning and synchronous axes add: the axis control panel's priority (spec 02 §9.2),
// MC_Stop's Execute level and MC_SetAxisSTW, and their drive.
template <typename Data>
class AxisObject : public DataBlockObject<Data> {
 public:
  // The drive in use: nullptr on a virtual or simulated axis, also when it keeps a drive (decision B8).
  const DriveConnection* drive() const noexcept { return drive_used() ? &this->drive_ : nullptr; }
  // The axis commands and reads its drive: it has one (the device it was built with, kept for its life) and
  // neither VirtualAxis.Mode nor Simulation.Mode of the work memory is 1. Both are read from the data block,
  // so a restart that takes a changed Simulation.Mode (RES, seed 004 §6.1.7) over also decides this anew.
  bool drive_used() const noexcept {
    return this->device_ != nullptr && this->db_.VirtualAxis.Mode != kModeOn &&
           this->db_.Simulation.Mode != kModeOn;
  }

  // ---- the axis control panel (spec 02 §9.2) ----
  ControlPriority& control_priority() noexcept { return this->core_.control; }
  const ControlPriority& control_priority() const noexcept { return this->core_.control; }
  // Precondition of taking control priority: the user program has released the axis (MC_Power.Enable =
  // FALSE) and the TO is disabled (decision W1).
  bool program_released() const noexcept {
    return !this->core_.enable && this->core_.phase == PowerPhase::kDisabled;
  }

  // MC_Stop's Execute level: while TRUE for an accepted MC_Stop, new motion jobs are rejected (spec 03
  // §4.13).
  void stop_execute(JobId job, bool execute) noexcept { this->core_.stop_execute(job, execute); }
  // MC_SetAxisSTW (spec 03 §4.14): the user's bits of STW1 (8, 9, 11..15) and STW2 (0..11).
  Submission set_axis_stw(std::uint16_t stw1, std::uint16_t stw1_mask, std::uint16_t stw2,
                          std::uint16_t stw2_mask) noexcept {
    return this->core_.set_axis_stw(drive_or_null(), stw1, stw1_mask, stw2, stw2_mask);
  }

 protected:
  using DataBlockObject<Data>::DataBlockObject;
  DriveConnection* drive_or_null() noexcept { return drive_used() ? &this->drive_ : nullptr; }
};

}  // namespace tomc::techobjects
