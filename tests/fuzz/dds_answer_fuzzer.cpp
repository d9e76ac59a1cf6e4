// Outside bytes of the gateway link (docs/gateway.md): an ActualCycle sample as it arrives from the network.
// The first byte picks the path:
//   even: the bytes are a CDR payload, deserialized by the generated type support as Fast DDS does, then
//   routed; odd:  the bytes build a well-formed sample field by field (device names, telegram numbers, PZD
//   lengths,
//         byte orders, controller, cycles) so that the routing rules see every combination.
// After routing, the cyclic side reads every device. Nothing may crash, and a device's frames may only ever
// hold the configured lengths (a wrong entry must never reach the TO).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/exchange_core.hpp"
#include "tomc/drives/dds/type_support.hpp"

namespace {

namespace dds = tomc::drives::dds;
namespace gw = tomc::gateway;
using tomc::drives::DeviceConfig;
using tomc::drives::DeviceFrames;

constexpr std::uint64_t kController = 77;

struct Setup {
  Setup() : core(dds::ExchangeOptions{kController, 1'000'000, 1}) {
    DeviceConfig a;
    a.drive_telegram = 3;
    DeviceConfig b;
    b.drive_telegram = 105;
    b.supplementary_telegram = 750;
    DeviceConfig c;
    c.drive_telegram = 1;
    c.codec.byte_order = tomc::telegrams::ByteOrder::kLittle;
    configs = {a, b, c};
    core.add_device("axis1", a);
    core.add_device("axis2", b);
    core.add_device("axis3", c);
    core.freeze();
    for (const auto& cfg : configs)
      frames.push_back(tomc::drives::make_frames(cfg, tomc::telegrams::Direction::kActual));
  }
  dds::ExchangeCore core;
  std::vector<DeviceConfig> configs;
  std::vector<DeviceFrames> frames;
};

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i)
      v = (v << 8) | byte();
    return v;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

gw::ActualCycle build(Bytes& in) {
  static constexpr const char* kNames[] = {"axis1", "axis2", "axis3", "other", ""};
  static constexpr std::uint16_t kTelegrams[] = {0, 1, 3, 105, 750, 81, 2, 65535};
  gw::ActualCycle s;
  s.contract_version(in.byte() < 240 ? dds::kContractVersion : in.byte());
  s.gateway(in.byte() & 1 ? "gw1" : "gw2");
  s.incarnation(in.byte() & 3);
  s.sequence_number(in.byte());
  s.controller(in.byte() & 1 ? kController : in.byte());
  const std::size_t n = in.byte() % 5;
  s.devices().resize(n);
  for (auto& e : s.devices()) {
    e.device(kNames[in.byte() % 5]);
    e.byte_order(static_cast<gw::ByteOrder>(in.byte() % 6));
    e.has_setpoint(in.byte() & 1);
    e.setpoint_cycle(in.byte());
    for (auto& slot : e.slots()) {
      slot.number(kTelegrams[in.byte() % 8]);
      slot.pzd().resize(in.byte() % 40);
      for (auto& b : slot.pzd())
        b = in.byte();
    }
  }
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Setup setup;
  gw::ActualCycle sample;
  if ((data[0] & 1) == 0) {
    dds::ActualCycleType type;  // as every tomc reader: malformed bytes give a rejected sample
    eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(size - 1));
    // One byte leaves no payload (data == nullptr): memcpy from/to null is undefined even for 0 bytes
    // (UBSan).
    if (size > 1) std::memcpy(payload.data, data + 1, size - 1);
    payload.length = static_cast<std::uint32_t>(size - 1);
    (void)type.deserialize(&payload, &sample);  // as in Fast DDS: the sample is routed whatever it holds
    setup.core.route(sample, 0);
  } else {
    Bytes in(data + 1, size - 1);
    for (int round = 0; round < 3; ++round) {
      const gw::ActualCycle s = build(in);
      setup.core.route(s, 0);
    }
  }
  for (std::size_t i = 0; i < setup.frames.size(); ++i) {
    (void)setup.core.read_actual(i, setup.frames[i]);
    const DeviceFrames expected =
        tomc::drives::make_frames(setup.configs[i], tomc::telegrams::Direction::kActual);
    for (std::size_t k = 0; k < tomc::drives::kSlotCount; ++k) {
      if (setup.frames[i].slots[k].length != expected.slots[k].length) std::abort();
    }
    setup.core.write_setpoint(i, setup.frames[i]);  // wrong direction on purpose: lengths differ, ignored
  }
  return 0;
}
