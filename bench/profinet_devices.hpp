#pragma once
// The controller's cyclic PROFINET work for one drive on telegram 105 (20 bytes each way): put the setpoint
// telegram into the output C_SDU and encode the output frame, decode the device's input frame and take the
// actual telegram and its IOPS out. Shared by profinet_bench (ns) and profinet_cyclic_callgrind
// (instructions).
#include <array>
#include <cstdint>
#include <cstring>

#include "tomc/profinet/cyclic.hpp"

namespace tomc::bench {

struct ProfinetDevice {
  profinet::CyclicCodec output;
  profinet::CyclicCodec input;
  profinet::EthernetHeader to_device;
  std::array<std::uint8_t, 40> output_image{};
  std::array<std::uint8_t, 40> input_image{};
  std::array<std::uint8_t, 128> output_frame{};
  std::array<std::uint8_t, 128> input_frame{};
  std::size_t input_frame_bytes = 0;
  std::array<std::uint8_t, 20> setpoint{};
  std::array<std::uint8_t, 20> actual{};
  std::uint16_t cycle_counter = 0;

  explicit ProfinetDevice(std::uint16_t index) {
    const profinet::MacAddress controller{0x02, 0, 0, 0, 0, 0x01};
    const profinet::MacAddress device{0x02, 0, 0, 0, 1, static_cast<std::uint8_t>(index)};
    profinet::CyclicLayout out;  // telegram submodule data + IOPS, IOCS for the DAP's three and the telegram
    out.frame_id = static_cast<std::uint16_t>(0x8000 + 2 * index + 1);
    out.data_objects[0] = {1, 2, 0, 20};
    out.data_object_count = 1;
    out.iocs[0] = {0, 1, 21, 0};
    out.iocs[1] = {0, 0x8000, 22, 0};
    out.iocs[2] = {0, 0x8001, 23, 0};
    out.iocs[3] = {1, 2, 24, 0};
    out.iocs_count = 4;
    profinet::CyclicLayout in;  // DAP submodules (IOPS only), telegram data + IOPS, IOCS for the output
    in.frame_id = static_cast<std::uint16_t>(0x8000 + 2 * index);
    in.data_objects[0] = {0, 1, 0, 0};
    in.data_objects[1] = {0, 0x8000, 1, 0};
    in.data_objects[2] = {0, 0x8001, 2, 0};
    in.data_objects[3] = {1, 2, 3, 20};
    in.data_object_count = 4;
    in.iocs[0] = {1, 2, 24, 0};
    in.iocs_count = 1;
    (void)profinet::CyclicCodec::create(out, output);
    (void)profinet::CyclicCodec::create(in, input);
    to_device = {device, controller, profinet::VlanTag{profinet::kPriorityCyclic, 0}};
    // The device's frame as it arrives: everything good, ZSW1 0x0B37.
    std::array<std::uint8_t, 40> device_image{};
    for (std::size_t i = 0; i < 4; ++i)
      input.iops(device_image, i) = profinet::kIoxsGood;
    input.iocs(device_image, 0) = profinet::kIoxsGood;
    input.data(device_image, 3)[0] = 0x0B;
    input.data(device_image, 3)[1] = 0x37;
    (void)input.encode({controller, device, profinet::VlanTag{6, 0}}, device_image, {}, input_frame,
                       input_frame_bytes);
    for (std::size_t i = 0; i < 4; ++i)
      output.iocs(output_image, i) = profinet::kIoxsGood;
    output.iops(output_image, 0) = profinet::kIoxsGood;
  }

  // One cycle; returns the bytes to send (0 on a codec error) and whether the input was good.
  bool cycle(std::size_t& sent) noexcept {
    std::memcpy(output.data(output_image, 0).data(), setpoint.data(), setpoint.size());
    cycle_counter = static_cast<std::uint16_t>(cycle_counter + 32);  // 1 ms in 31.25 us units
    (void)output.encode(to_device, output_image, {cycle_counter, profinet::data_status::kRunning, 0},
                        output_frame, sent);
    profinet::ApduStatus status;
    if (input.decode(std::span(input_frame).first(input_frame_bytes), input_image, status) !=
        profinet::ProfinetError::kNone) {
      return false;
    }
    const auto data = input.read_data(input_image, 3);
    std::memcpy(actual.data(), data.data(), data.size());
    return input.read_iops(input_image, 3) == profinet::kIoxsGood &&
           (status.data_status & profinet::data_status::kDataValid) != 0;
  }
};

}  // namespace tomc::bench
