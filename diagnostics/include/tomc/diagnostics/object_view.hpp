#pragma once
// What the diagnostics layer sees of one technology object, for any TO type: its name and type, its data
// block through the type's reflection table (every leaf variable by its manual path,
// techobjects/variables.hpp), its technology alarms, and the PROFIdrive words of its drive and encoder
// telegrams. TechnologyObjectView<T> adapts any TO class with `name()`, `data()` (a data block with
// kTechnologyObjectType) and, if it has them, `alarms()` and `drive()`: SpeedAxis today, PositioningAxis and
// ExternalEncoder when they arrive.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "tomc/diagnostics/probe.hpp"
#include "tomc/drives/drive_adapter.hpp"
#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::techobjects {
class Cam;
}

namespace tomc::diagnostics {

// The reflection table of a TO type (the synchronous axis shares the positioning axis' table).
std::span<const techobjects::VariableInfo> variables_of(techobjects::TechnologyObjectType type) noexcept;
// "TO_SpeedAxis", "TO_PositioningAxis", ...
std::string_view type_name(techobjects::TechnologyObjectType type) noexcept;

// One word of a telegram the TO exchanges: which telegram slot, which direction, which signal.
struct TelegramChannel {
  drives::Slot slot;
  telegrams::Direction direction;
  telegrams::Signal signal;
};
std::string_view slot_name(drives::Slot slot) noexcept;  // "drive", "supplementary", "encoder1", "encoder2"

class ObjectView {
 public:
  virtual ~ObjectView() = default;
  virtual std::string_view name() const noexcept = 0;
  virtual techobjects::TechnologyObjectType type() const noexcept = 0;
  virtual const void* data_block() const noexcept = 0;  // read with the rows of variables()
  virtual const techobjects::AlarmList* alarms() const noexcept = 0;
  virtual const techobjects::DriveConnection* drive() const noexcept = 0;  // nullptr: virtual/simulated

  std::span<const techobjects::VariableInfo> variables() const noexcept { return variables_of(type()); }
  // Status a TO keeps outside its data block (a synchronous axis' StatusSynchronizedMotion): the rows of
  // variables() whose owner is kSynchronousAxis read it. nullptr: none.
  virtual const void* extension_block() const noexcept { return nullptr; }
  // What a row of variables() is read from.
  const void* source_of(const techobjects::VariableInfo& row) const noexcept {
    return row.owner == techobjects::TechnologyObjectType::kSynchronousAxis ? extension_block()
                                                                            : data_block();
  }
  // Changes whenever the TO rebuilds data that is not in its rows (a cam's interpolated form); 0: never.
  // Read in the cycle and published with the snapshot.
  virtual std::uint64_t revision() const noexcept { return 0; }
  // The names of the configured leading values of a synchronous axis (ActualMaster 1 is the first); empty
  // for every other TO.
  virtual std::vector<std::string> leading_value_names() const { return {}; }
  // The cam of a TO_Cam view (its plot: cam_plot.hpp); nullptr for every other TO.
  virtual const techobjects::Cam* cam() const noexcept { return nullptr; }

  // Set-up, once before the cycle runs: the telegram words of the configured telegrams.
  void resolve_telegrams();
  std::span<const TelegramChannel> telegram_channels() const noexcept { return channels_; }
  // The raw value of telegram_channels()[i] this cycle (0 without a drive). Cycle-safe.
  std::uint32_t telegram_word(std::size_t i) const noexcept;

  // A probe for a path of this object (non-RT; nullopt if unknown):
  //   a data-block variable "Velocity", "StatusDrive.InOperation";
  //   a bit of a word "StatusWord.X5";
  //   a telegram word "telegram.drive.ZSW1", "telegram.encoder1.G1_XIST1" (slot as slot_name()), or one of
  //   its bits "telegram.drive.ZSW1.X3".
  std::optional<Probe> probe(std::string_view path) const;

 private:
  // Where a channel's word lives in the drive connection, resolved once (no look-up, no virtual call in the
  // cycle). Stable addresses after resolve_telegrams(): trace probes point at them.
  struct TelegramSource {
    const telegrams::ActualSignals* actual;  // one of the two is set
    const telegrams::SetpointSignals* setpoint;
    telegrams::Signal signal;
    std::uint32_t read() const noexcept {
      return actual != nullptr ? actual->raw(signal) : setpoint->raw(signal);
    }
  };
  std::vector<TelegramChannel> channels_;
  std::unique_ptr<TelegramSource[]> sources_;
};

template <typename Object>
class TechnologyObjectView final : public ObjectView {
  using Data = std::remove_cvref_t<decltype(std::declval<const Object&>().data())>;

 public:
  explicit TechnologyObjectView(const Object& object) : object_(object) { resolve_telegrams(); }
  std::string_view name() const noexcept override { return object_.name(); }
  techobjects::TechnologyObjectType type() const noexcept override { return Data::kTechnologyObjectType; }
  const void* data_block() const noexcept override { return &object_.data(); }
  const techobjects::AlarmList* alarms() const noexcept override {
    if constexpr (requires { object_.alarms(); }) {
      return &object_.alarms();
    } else {
      return nullptr;
    }
  }
  const techobjects::DriveConnection* drive() const noexcept override {
    if constexpr (requires { object_.drive(); }) {
      return object_.drive();
    } else {
      return nullptr;
    }
  }

 private:
  const Object& object_;
};

}  // namespace tomc::diagnostics
