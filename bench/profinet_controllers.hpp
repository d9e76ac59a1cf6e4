#pragma once
// The calls `tomc gateway`'s cyclic thread makes for N devices in one cycle (tools/gateway/src/
// profinet_gateway.cpp, cycle_step), on IoControllers brought up in memory against IoDevices with the
// emulated drive's telegram-105 modules (DAP, drive object, 20 bytes each way): every device's input frame
// dispatched to the controllers in file order until one takes it (receive_frames: so the last device's frame
// is tried by all N), input_valid and the actual telegram copied out (publish_answer), the setpoint telegram
// copied into the output data (apply_setpoints), next_output_frame, both RTA timers (alarm_timer, idle) and
// watchdog_expired. Shared by
// profinet_bench (ns) and profinet_cyclic_callgrind (instructions); no sockets, so the figures are the
// gateway's own work.
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "../tests/profinet/in_memory_start_up.hpp"
#include "tomc/drives/profinet_drive.hpp"
#include "tomc/profinet/cyclic.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/io_device.hpp"

namespace tomc::bench {

class ProfinetControllers {
 public:
  static constexpr std::uint16_t kTelegram = 105;

  explicit ProfinetControllers(int count) {
    const auto modules = drives::profidrive_modules(kTelegram);
    for (int i = 0; i < count; ++i) {
      const auto index = static_cast<std::uint8_t>(i);
      profinet::DeviceIdentity identity;
      identity.name_of_station = "drive-" + std::to_string(i);
      identity.mac = {0x02, 0, 0, 0, 1, index};
      identity.ip = {{10, 0, 0, static_cast<std::uint8_t>(10 + i)}, {255, 255, 255, 0}, {}};
      for (const profinet::ExpectedModule& m : modules) {
        profinet::DeviceModule real{m.slot, m.ident, {}};
        for (const profinet::ExpectedSubmodule& s : m.submodules)
          real.submodules.push_back({s.subslot, s.ident, s.direction, s.input_length, s.output_length});
        identity.modules.push_back(real);
      }
      profinet::ControllerDeviceConfig config;
      config.name_of_station = identity.name_of_station;
      config.ip = identity.ip;
      config.modules = modules;
      config.input_frame_id = static_cast<std::uint16_t>(profinet::kFrameIdRtClass1First + 2 * i);
      config.output_frame_id = static_cast<std::uint16_t>(profinet::kFrameIdRtClass1First + 2 * i + 1);
      const profinet::Uuid ar{0x10000000u + index, 1, 2, {3}};
      auto controller = std::make_unique<profinet::IoController>(profinet::MacAddress{0x02, 0, 0, 0, 0, 1},
                                                                 "tomc-gateway", config, ar);
      auto device = std::make_unique<profinet::IoDevice>(identity);
      ok_ = ok_ && profinet::testing::start_up(*controller, *device);
      controller->set_outputs_valid(true);
      // The device's input frame as it arrives every cycle: ZSW1 0x0B37, everything valid.
      auto actual = device->input_data(drives::kDriveObjectSlot, drives::kTelegramSubslot);
      if (actual.size() >= 2) actual[0] = 0x0B, actual[1] = 0x37;
      Input input;
      input.bytes = device->next_input_frame(input.frame);
      inputs_.push_back(input);
      controllers_.push_back(std::move(controller));
      devices_.push_back(std::move(device));
    }
  }
  // Every AR came up and every device has an input frame.
  bool ready() const {
    for (const Input& i : inputs_) {
      if (i.bytes == 0) return false;
    }
    return ok_;
  }

  // One gateway cycle at `now_us`; returns the bytes of the output frames (what would be sent).
  std::size_t cycle(std::uint64_t now_us) noexcept {
    std::size_t valid = 0;
    for (const Input& input : inputs_) {
      const auto frame = std::span(input.frame).first(input.bytes);
      const std::uint16_t frame_id = profinet::peek_frame_id(frame);
      for (auto& c : controllers_) {
        if (c->input_frame_id() == frame_id && c->on_input_frame(frame, now_us)) break;
      }
    }
    for (auto& c : controllers_) {
      if (!c->input_valid(now_us)) continue;
      const auto in = c->input_data(drives::kDriveObjectSlot, drives::kTelegramSubslot);
      std::memcpy(actual_.data(), in.data(), in.size());
      ++valid;
    }
    std::size_t sent = 0;
    for (auto& c : controllers_) {
      const auto out = c->output_data(drives::kDriveObjectSlot, drives::kTelegramSubslot);
      setpoint_[0] = static_cast<std::uint8_t>(now_us);  // a setpoint that changes every cycle
      std::memcpy(out.data(), setpoint_.data(), out.size());
      sent += c->next_output_frame(frame_);
      for (const bool high : {true, false}) {  // the RTA timers: nothing waits for an acknowledge here
        std::size_t resent = 0;
        if (c->alarm_ack_pending(high)) (void)c->alarm_timer(high, now_us, frame_, resent);
      }
      (void)c->watchdog_expired(now_us);
    }
    return valid == controllers_.size() ? sent : 0;
  }

 private:
  struct Input {
    std::array<std::uint8_t, 1518> frame{};
    std::size_t bytes = 0;
  };
  std::vector<std::unique_ptr<profinet::IoController>> controllers_;
  std::vector<std::unique_ptr<profinet::IoDevice>> devices_;
  std::vector<Input> inputs_;
  std::array<std::uint8_t, 1518> frame_{};
  std::array<std::uint8_t, 64> actual_{};
  std::array<std::uint8_t, 64> setpoint_{};
  bool ok_ = true;
};

}  // namespace tomc::bench
