// The comedi backend of the hardware I/O layer (comedi_io.hpp). The constructor may throw (configuration);
// the cyclic calls neither throw nor allocate: the channel tables are sized at construction.
#include "tomc/drives/io/comedi_io.hpp"

#include <comedilib.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace tomc::drives::io {

namespace {

comedi_t* as_comedi(void* device) noexcept {
  return static_cast<comedi_t*>(device);
}

const ComediLibrary kComedi{
    [](const char* file) -> void* { return comedi_open(file); },
    [](void* d) { return comedi_close(as_comedi(d)); },
    [](void* d) { return comedi_get_n_subdevices(as_comedi(d)); },
    [](void* d, unsigned s) { return comedi_get_subdevice_type(as_comedi(d), s); },
    [](void* d, unsigned s) { return comedi_get_n_channels(as_comedi(d), s); },
    [](void* d, unsigned s, unsigned c) -> std::uint32_t { return comedi_get_maxdata(as_comedi(d), s, c); },
    [](void* d, unsigned s, unsigned c, std::uint32_t* v) {
      lsampl_t raw = 0;
      const int r = comedi_data_read(as_comedi(d), s, c, 0, AREF_GROUND, &raw);
      *v = raw;
      return r;
    },
    [](void* d, unsigned s, unsigned c, std::uint32_t v) {
      return comedi_data_write(as_comedi(d), s, c, 0, AREF_GROUND, v);
    },
    [](void* d, unsigned s, unsigned c, unsigned* bit) { return comedi_dio_read(as_comedi(d), s, c, bit); },
    [](void* d, unsigned s, unsigned c, unsigned bit) { return comedi_dio_write(as_comedi(d), s, c, bit); },
    []() -> const char* { return comedi_strerror(comedi_errno()); },
};

std::string where(const std::string& file, Channel c) {
  return file + " subdevice " + std::to_string(c.subdevice) + " channel " + std::to_string(c.channel);
}

const char* type_name(int type) {
  switch (static_cast<ComediSubdevice>(type)) {
    case ComediSubdevice::kAnalogOutput:
      return "analog output";
    case ComediSubdevice::kDigitalInput:
      return "digital input";
    case ComediSubdevice::kDigitalOutput:
      return "digital output";
    case ComediSubdevice::kDigitalIo:
      return "digital I/O";
    case ComediSubdevice::kCounter:
      return "counter";
  }
  return "another kind of subdevice";
}

}  // namespace

const ComediLibrary& real_comedi() noexcept {
  return kComedi;
}

ComediIo::ComediIo(const ComediIoParameters& p, const ComediLibrary& library)
    : lib_(&library), device_file_(p.device_file) {
  device_ = lib_->open(p.device_file.c_str());
  if (device_ == nullptr) {
    throw std::runtime_error("comedi: cannot open " + p.device_file + ": " + lib_->last_error() +
                             " (is the card's comedi driver loaded and the device file readable?)");
  }
  try {
    const int subdevices = lib_->n_subdevices(device_);
    // Each channel must exist on a subdevice of a fitting kind.
    const auto check = [&](Channel c, std::initializer_list<ComediSubdevice> kinds, const char* role) {
      if (static_cast<int>(c.subdevice) >= subdevices) {
        throw std::runtime_error("comedi: " + where(p.device_file, c) + " (" + role + "): the card has " +
                                 std::to_string(subdevices) + " subdevices");
      }
      const int type = lib_->subdevice_type(device_, c.subdevice);
      if (std::none_of(kinds.begin(), kinds.end(),
                       [&](ComediSubdevice k) { return static_cast<int>(k) == type; })) {
        throw std::runtime_error("comedi: " + where(p.device_file, c) + " (" + role + ") is " +
                                 type_name(type));
      }
      if (static_cast<int>(c.channel) >= lib_->n_channels(device_, c.subdevice)) {
        throw std::runtime_error("comedi: " + where(p.device_file, c) + " (" + role + "): no such channel");
      }
    };
    for (Channel c : p.analog_outputs) {
      check(c, {ComediSubdevice::kAnalogOutput}, "analog output");
      analog_outputs_.push_back({c, 0, lib_->maxdata(device_, c.subdevice, c.channel)});
      analog_outputs_.back().value = (analog_outputs_.back().maxdata + 1u) / 2u;  // 0 V of a bipolar range
    }
    for (Channel c : p.digital_inputs) {
      check(c, {ComediSubdevice::kDigitalInput, ComediSubdevice::kDigitalIo}, "digital input");
      digital_inputs_.push_back({c, false, 1});
    }
    for (Channel c : p.digital_outputs) {
      check(c, {ComediSubdevice::kDigitalOutput, ComediSubdevice::kDigitalIo}, "digital output");
      digital_outputs_.push_back({c, false, 1});
    }
    for (Channel c : p.counters) {
      check(c, {ComediSubdevice::kCounter}, "counter");
      counters_.push_back({c, 0, lib_->maxdata(device_, c.subdevice, c.channel)});
    }
  } catch (...) {
    lib_->close(device_);
    throw;
  }
  const int width = std::clamp<int>(p.counter_width_bits, 2, 32);
  counter_mask_ = width == 32 ? 0xFFFFFFFFu : (1u << width) - 1u;
}

ComediIo::~ComediIo() {
  if (device_ != nullptr) lib_->close(device_);
}

void ComediIo::record(const char* call, Channel c) noexcept {
  std::snprintf(last_error_.data(), last_error_.size(), "%s: %s subdevice %u channel %u: %s",
                device_file_.c_str(), call, static_cast<unsigned>(c.subdevice),
                static_cast<unsigned>(c.channel), lib_->last_error());
}

std::int32_t ComediIo::find(const auto& slots, Channel channel) noexcept {
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].channel == channel) return static_cast<std::int32_t>(i);
  }
  return -1;
}

IoStatus ComediIo::sample_inputs() noexcept {
  IoStatus status = IoStatus::kOk;
  // A failed read keeps the last good value (hardware_io.hpp) and is reported.
  for (auto& in : digital_inputs_) {
    unsigned bit = 0;
    if (lib_->dio_read(device_, in.channel.subdevice, in.channel.channel, &bit) < 0) {
      record("dio_read", in.channel);
      status = IoStatus::kReadFailed;
    } else {
      in.value = bit != 0;
    }
  }
  for (auto& c : counters_) {
    std::uint32_t raw = 0;
    if (lib_->data_read(device_, c.channel.subdevice, c.channel.channel, &raw) < 0) {
      record("data_read", c.channel);
      status = IoStatus::kReadFailed;
    } else {
      c.value = raw & counter_mask_;
    }
  }
  return status;
}

bool ComediIo::digital_input(Channel channel) const noexcept {
  const auto i = find(digital_inputs_, channel);
  return i >= 0 && digital_inputs_[static_cast<std::size_t>(i)].value;
}

CounterSample ComediIo::counter(Channel channel) const noexcept {
  CounterSample s;
  const auto i = find(counters_, channel);
  if (i >= 0) s.count = counters_[static_cast<std::size_t>(i)].value;
  return s;
}

void ComediIo::set_analog_output(Channel channel, std::int32_t code) noexcept {
  const auto i = find(analog_outputs_, channel);
  if (i < 0) return;
  auto& out = analog_outputs_[static_cast<std::size_t>(i)];
  // tomc's signed code (dac_code(): ±2^(bits−1) over the range) -> comedi's offset binary 0 ... maxdata of a
  // bipolar range, saturated. The actor's DacFormat must be the card's resolution and range.
  const std::int64_t raw = static_cast<std::int64_t>(code) + (static_cast<std::int64_t>(out.maxdata) + 1) / 2;
  out.value = static_cast<std::uint32_t>(std::clamp<std::int64_t>(raw, 0, out.maxdata));
}

void ComediIo::set_digital_output(Channel channel, bool value) noexcept {
  const auto i = find(digital_outputs_, channel);
  if (i >= 0) digital_outputs_[static_cast<std::size_t>(i)].value = value;
}

IoStatus ComediIo::write_outputs() noexcept {
  IoStatus status = IoStatus::kOk;
  for (const auto& out : analog_outputs_) {
    if (lib_->data_write(device_, out.channel.subdevice, out.channel.channel, out.value) < 0) {
      record("data_write", out.channel);
      status = IoStatus::kWriteFailed;
    }
  }
  for (const auto& out : digital_outputs_) {
    if (lib_->dio_write(device_, out.channel.subdevice, out.channel.channel, out.value ? 1u : 0u) < 0) {
      record("dio_write", out.channel);
      status = IoStatus::kWriteFailed;
    }
  }
  return status;
}

}  // namespace tomc::drives::io
