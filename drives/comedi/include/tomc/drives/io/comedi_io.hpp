#pragma once
// The real backend of the hardware I/O layer (hardware_io.hpp): a Linux DAQ card through comedilib (Debian's
// libcomedi-dev; optional build, -DTOMC_WITH_COMEDI=ON). Channels are (subdevice, channel) of the card as
// comedi numbers them. Opening checks everything that can be checked before the first cycle and throws a
// configuration error naming the device file, subdevice and channel; in the cycle every failed read or write
// is an IoStatus (the actor's fault 20002, the TO's alarm 401) with the comedi error text kept for the
// diagnostics. docs/analog-drives.md "The comedi backend".

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tomc/drives/io/hardware_io.hpp"

namespace tomc::drives::io {

// The comedilib calls the backend makes, as a table so that the error paths can be tested without a card
// (tests/drives/comedi_io_test.cpp); real_comedi() is the library. `device` is an opaque comedi_t*.
struct ComediLibrary {
  void* (*open)(const char* file);
  int (*close)(void* device);
  int (*n_subdevices)(void* device);
  int (*subdevice_type)(void* device, unsigned subdevice);
  int (*n_channels)(void* device, unsigned subdevice);
  std::uint32_t (*maxdata)(void* device, unsigned subdevice, unsigned channel);
  int (*data_read)(void* device, unsigned subdevice, unsigned channel, std::uint32_t* value);
  int (*data_write)(void* device, unsigned subdevice, unsigned channel, std::uint32_t value);
  int (*dio_read)(void* device, unsigned subdevice, unsigned channel, unsigned* bit);
  int (*dio_write)(void* device, unsigned subdevice, unsigned channel, unsigned bit);
  const char* (*last_error)();  // comedi_strerror(comedi_errno())
};
const ComediLibrary& real_comedi() noexcept;

// comedi subdevice types (comedi.h COMEDI_SUBD_*), for the checks at open.
enum class ComediSubdevice : int {
  kAnalogOutput = 2,
  kDigitalInput = 3,
  kDigitalOutput = 4,
  kDigitalIo = 5,
  kCounter = 6
};

struct ComediIoParameters {
  std::string device_file = "/dev/comedi0";
  std::vector<Channel> analog_outputs;   // AO subdevice channels (range 0, ground reference)
  std::vector<Channel> digital_inputs;   // DI or DIO
  std::vector<Channel> digital_outputs;  // DO or DIO
  std::vector<Channel> counters;         // counter subdevice channels, read as the raw count
  std::uint8_t counter_width_bits = 32;  // the card's counter register width (CounterExtension)
};

class ComediIo final : public HardwareIo {
 public:
  // Opens the card and checks every channel; throws std::runtime_error naming the device file (and the
  // subdevice/channel) when it cannot be used. `library` must outlive the object.
  explicit ComediIo(const ComediIoParameters& parameters, const ComediLibrary& library = real_comedi());
  ~ComediIo() override;
  ComediIo(const ComediIo&) = delete;
  ComediIo& operator=(const ComediIo&) = delete;

  IoStatus sample_inputs() noexcept override;
  bool digital_input(Channel channel) const noexcept override;
  CounterSample counter(Channel channel) const noexcept override;
  // comedi has no portable zero-mark latch (it is card-specific instruction configuration): never latches.
  void arm_zero_mark(Channel) noexcept override {}
  void set_analog_output(Channel channel, std::int32_t code) noexcept override;
  void set_digital_output(Channel channel, bool value) noexcept override;
  // No pulse-train output through comedi's portable calls: a stepper actor is refused at configuration.
  void set_pulse_frequency(Channel, double) noexcept override {}
  IoStatus write_outputs() noexcept override;

  // The last failure as "<device file>: <call> subdevice s channel c: <comedi error>" (empty = none); a
  // fixed buffer, written in the cycle without allocating.
  const char* last_error() const noexcept { return last_error_.data(); }

 private:
  template <class T>
  struct Slot {
    Channel channel;
    T value{};
    std::uint32_t maxdata = 0;
  };
  void record(const char* call, Channel channel) noexcept;
  static std::int32_t find(const auto& slots, Channel channel) noexcept;

  const ComediLibrary* lib_;
  std::string device_file_;
  void* device_ = nullptr;
  std::vector<Slot<std::uint32_t>> analog_outputs_;  // pending raw values
  std::vector<Slot<bool>> digital_inputs_;
  std::vector<Slot<bool>> digital_outputs_;
  std::vector<Slot<std::uint32_t>> counters_;
  std::uint32_t counter_mask_ = 0xFFFFFFFFu;
  std::array<char, 160> last_error_{};
};

}  // namespace tomc::drives::io
