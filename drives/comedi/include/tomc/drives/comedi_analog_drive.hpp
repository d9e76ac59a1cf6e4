#pragma once
// An analog drive on a real DAQ card: the analog actor (analog_drive.hpp) on the comedi backend
// (io/comedi_io.hpp), owned together so that the card outlives the actor. To the TO it is the actor, a drive
// on telegram 3 (spec 01 §3.12), exactly as the simulated analog drive of `tomc sim`/`tomc demo`. Built from
// a scenario or machine file by `"analog": {"comedi": {...}}` (docs/analog-drives.md "The comedi backend").

#include "tomc/drives/analog_drive.hpp"
#include "tomc/drives/io/comedi_io.hpp"

namespace tomc::drives {

class ComediAnalogDrive final : public DriveAdapter {
 public:
  // Opens the card and checks its channels: throws std::runtime_error naming the device file (and subdevice,
  // channel) when it cannot be used (ComediIo). The actor's analog_output, enable_output, ready_input and
  // counter must be among `card`'s channels. `library` must outlive the object.
  ComediAnalogDrive(const io::ComediIoParameters& card, const AnalogDriveParameters& actor,
                    const io::ComediLibrary& library = io::real_comedi())
      : card_(card, library), actor_(card_, actor) {}

  const DeviceConfig& config() const noexcept override { return actor_.config(); }
  bool read_actual(DeviceFrames& actual) noexcept override { return actor_.read_actual(actual); }
  void write_setpoint(const DeviceFrames& setpoint) noexcept override { actor_.write_setpoint(setpoint); }
  LinkHealth link_health() const noexcept override { return actor_.link_health(); }

  io::ComediIo& card() noexcept { return card_; }
  AnalogDrive& actor() noexcept { return actor_; }
  const AnalogDrive& actor() const noexcept { return actor_; }

 private:
  io::ComediIo card_;  // first: the actor holds a reference to it
  AnalogDrive actor_;
};

}  // namespace tomc::drives
