// `tomc gateway`: the DDS contract in front of a PROFINET IO controller (profinet_gateway.hpp).
#include "tomc/gateway/profinet_gateway.hpp"

#include <pthread.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <fastdds/dds/publisher/DataWriter.hpp>

#include "start_up.hpp"
#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/gateway_side.hpp"
#include "tomc/drives/dds/latest_value.hpp"
#include "tomc/drives/dds/participant.hpp"
#include "tomc/drives/dds/type_support.hpp"
#include "tomc/drives/profinet_drive.hpp"
#include "tomc/profinet/dcp_commissioning.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/sockets.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"
#include "tomc/telegrams/layout.hpp"

namespace tomc::profinet_gateway {

namespace dds = tomc::drives::dds;
namespace fdds = eprosima::fastdds::dds;
namespace gw = tomc::gateway;
namespace pn = tomc::profinet;
using Clock = std::chrono::steady_clock;
using drives::Slot;

namespace {

constexpr std::uint16_t kZsw1Fault = 1u << 3;  // ZSW1 bit 3: fault present (spec 06 §3)
// How many send clocks an answer waits for the input frames sent after its setpoint: one is the normal case
// (the frames arrive within the cycle), more cover a device (or a loaded machine) that answers late. A new
// setpoint ends the wait at once (the answer goes out as it is, stale for the controller), so a controller in
// real time never waits on it; one in lock-step waits for it at most its answer timeout.
constexpr int kAnswerWaitCycles = 20;

std::uint64_t now_us() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now().time_since_epoch()).count());
}

pn::Uuid random_uuid() {
  const std::uint64_t a = dds::random_id();
  const std::uint64_t b = dds::random_id();
  pn::Uuid u;
  u.data1 = static_cast<std::uint32_t>(a);
  u.data2 = static_cast<std::uint16_t>(a >> 32);
  u.data3 = static_cast<std::uint16_t>(((a >> 48) & 0x0FFF) | 0x4000);  // version 4
  for (std::size_t i = 0; i < 8; ++i)
    u.data4[i] = static_cast<std::uint8_t>(b >> (8 * i));
  u.data4[0] = static_cast<std::uint8_t>((u.data4[0] & 0x3F) | 0x80);  // variant DCE
  return u;
}

std::vector<pn::ExpectedModule> expected_modules(const scenario::ProfinetDeviceConfig& c) {
  if (c.modules.empty()) return drives::profidrive_modules(c.device_config());
  std::vector<pn::ExpectedModule> modules;
  for (const auto& m : c.modules) {
    pn::ExpectedModule module{m.api, m.slot, m.ident, {}};
    for (const auto& s : m.submodules) {
      const auto direction = s.input_length != 0 && s.output_length != 0
                                 ? pn::SubmoduleDirection::kInputOutput
                             : s.input_length != 0  ? pn::SubmoduleDirection::kInput
                             : s.output_length != 0 ? pn::SubmoduleDirection::kOutput
                                                    : pn::SubmoduleDirection::kNoIo;
      module.submodules.push_back({s.subslot, s.ident, direction, s.input_length, s.output_length});
    }
    modules.push_back(std::move(module));
  }
  return modules;
}

// The setpoints of one applied SetpointCycle, listener thread -> cyclic thread.
struct SetpointImage {
  std::uint64_t controller = 0;
  std::uint64_t cycle = 0;
  bool released = false;            // the previous controller was released: forget its setpoints first
  std::vector<std::uint8_t> valid;  // per device: the entry matched (G3) and is applied
  std::vector<drives::DeviceFrames> frames;
};

// What the cyclic thread sampled, cyclic thread -> sender thread.
struct AnswerImage {
  std::uint64_t serial = 0;  // images published so far: a jump = answers overwritten before they were sent
  std::uint64_t controller = 0;  // 0: an idle answer (G7)
  std::vector<std::uint8_t> exchanging;
  std::vector<std::uint8_t> has_setpoint;
  std::vector<std::uint64_t> setpoint_cycle;
  std::vector<drives::DeviceFrames> actual;
};

// The last acknowledged alarm, for the status: the cyclic thread stores it in one atomic word (no lock).
std::uint64_t pack_alarm(const pn::AlarmBlock& alarm) noexcept {
  return std::uint64_t{alarm.alarm_type} << 48 | std::uint64_t{alarm.slot} << 32 |
         std::uint64_t{alarm.subslot} << 16 | alarm.user_structure_identifier;
}

// "alarm 2 acknowledged: diagnosis, slot 1 subslot 2, USI 0x8000" (IEC 61158-6-10 AlarmType,
// UserStructureIdentifier 0x8000 = ChannelDiagnosis); "" before the first alarm.
std::string alarm_text(std::uint32_t count, std::uint64_t packed) {
  if (count == 0) return {};
  const auto type = static_cast<std::uint16_t>(packed >> 48);
  const char* name = type == pn::alarm_type::kDiagnosis             ? "diagnosis"
                     : type == pn::alarm_type::kProcess             ? "process"
                     : type == pn::alarm_type::kPull                ? "pull"
                     : type == pn::alarm_type::kPlug                ? "plug"
                     : type == pn::alarm_type::kStatus              ? "status"
                     : type == pn::alarm_type::kDiagnosisDisappears ? "diagnosis disappears"
                                                                    : nullptr;
  char usi[8];
  std::snprintf(usi, sizeof usi, "%04X", static_cast<unsigned>(packed & 0xFFFF));
  return "alarm " + std::to_string(count) +
         " acknowledged: " + (name != nullptr ? std::string(name) : "type " + std::to_string(type)) +
         ", slot " + std::to_string((packed >> 32) & 0xFFFF) + " subslot " +
         std::to_string((packed >> 16) & 0xFFFF) + ", USI 0x" + usi;
}

}  // namespace

struct ProfinetGateway::Impl {
  struct Device {
    scenario::ProfinetDeviceConfig config;
    drives::DeviceConfig device_config;
    gw::ByteOrder byte_order = gw::BYTE_ORDER_BIG;
    std::unique_ptr<pn::IoController> controller;
    std::size_t zsw1_low_byte = 1;  // where ZSW1 bit 3 is in the telegram's first word (byte order)
    // Where bit 15 (encoder error) of each encoder status word is in the actual frames: G1_ZSW/G2_ZSW of the
    // drive telegram, G1_ZSW of each encoder telegram (spec 06 §3.7); what the status calls it.
    std::array<scenario::ProfinetEncoderErrorBit, scenario::ProfinetDeviceConfig::kMaxEncoderErrorBits>
        encoder_words{};
    std::size_t encoder_word_count = 0;
    std::atomic<std::uint32_t> encoder_errors{0};  // bit k: encoder_words[k] reports an encoder error
    std::array<scenario::ProfinetTelegramPlace, drives::kSlotCount> places{};  // config.place() per slot
    // Who may touch `controller`: the start-up thread (false) or the cyclic thread (true).
    std::atomic<bool> cyclic{false};
    std::atomic<bool> faulted{false};
    std::atomic<std::uint32_t> alarms{0};
    std::atomic<std::uint64_t> last_alarm{0};        // the last acknowledged alarm, pack_alarm()
    std::atomic<std::uint32_t> alarm_timeouts{0};    // ARs the RTA timer ended in the cyclic thread
    std::atomic<bool> alarm_timeout_high{false};     // the priority of the last one
    std::atomic<std::uint32_t> rta_errors{0};        // ARs the device ended with an ERR-RTA-PDU (I35)
    std::atomic<std::uint32_t> rta_error_status{0};  // the last one's PNIOStatus
    std::atomic<bool> rta_error_high{false};
    std::atomic<std::uint32_t> ars{0};
    std::atomic<float> reference_speed_rpm{0.0f};  // p2000 as read at start-up (0: not read)
    // Cyclic thread only.
    bool has_setpoint = false;
    std::uint64_t setpoint_cycle = 0;  // the newest setpoint applied
    std::uint64_t answered_cycle = 0;  // the newest setpoint an input frame has answered
    bool answered = false;
    std::uint64_t input_frames = 0;     // input frames received
    std::uint64_t frames_at_apply = 0;  // input_frames when setpoint_cycle was applied
    // Under detail_mutex: the last start-up problem or module difference, and the controller's mismatch.
    std::string detail;
    std::string mismatch;
  };

  scenario::ProfinetGatewayConfig config;
  std::chrono::nanoseconds cycle{};
  std::uint64_t watchdog_us = 0;
  std::vector<std::unique_ptr<Device>> devices;
  pn::RawSocket cyclic_socket;  // the cyclic thread's: input, alarm and output frames
  // The start-up thread's: DCP and the starting device's alarms. Its kernel filter drops the cyclic frames,
  // which would otherwise fill its queue between start-ups and, with several running devices, delay a
  // starting device's alarm behind them (decision I30).
  pn::RawSocket start_socket;
  pn::UdpSocket rpc_socket;

  dds::LatestValue<SetpointImage> setpoints;
  dds::LatestValue<AnswerImage> answers;
  // Cyclic, listener and start-up thread -> sender: one atomic increment and one futex wake, never a wait
  // (docs/decisions.md G4). The cyclic thread wakes it at least once per cycle while idle and once per
  // applied setpoint, so the sender also runs its periodic work (status, G6) without a timer.
  std::atomic<std::uint32_t> wake_generation{0};
  void wake() noexcept {
    wake_generation.fetch_add(1, std::memory_order_release);
    wake_generation.notify_one();
  }
  std::atomic<std::uint64_t> probe{0};  // a controller whose probe is to be answered (G9)

  mutable std::mutex session_mutex;  // listener and sender thread
  dds::SetpointSession session{std::chrono::nanoseconds(1)};
  mutable std::mutex detail_mutex;

  // Cyclic thread state.
  std::array<std::uint8_t, 1518> frame{};
  std::array<std::uint8_t, 128> ack{};
  std::array<std::uint8_t, 256> alarm_ack{};
  int answer_wait = 0;  // cycles left to wait for the input frames that answer the applied setpoint
  std::uint64_t applied_controller = 0;
  bool serving = false;
  std::uint64_t last_setpoint_us = 0;
  std::uint64_t serial = 0;

  // Sender thread state.
  gw::ActualCycle answer;
  gw::GatewayStatus status;
  std::string status_signature;
  Clock::time_point status_time{};
  std::uint64_t last_serial = 0;

  std::unique_ptr<fdds::DataReaderListener> setpoint_listener;
  std::unique_ptr<dds::GatewayEndpoints> endpoints;  // after the listener: destroyed before it
  fdds::DataWriter* actual_writer = nullptr;
  fdds::DataWriter* status_writer = nullptr;

  std::unique_ptr<techobjects::RealTimeRunner> runner;
  std::atomic<bool> stop{false};
  std::thread sender_thread;
  std::thread start_thread;

  // ---- DDS listener thread ----
  void on_setpoint(const gw::SetpointCycle& sample) {
    if (stop.load()) return;
    std::lock_guard<std::mutex> lock(session_mutex);
    const dds::SetpointSession::Decision decision = session.accept(sample, Clock::now());
    if (decision.verdict == dds::SetpointSession::Verdict::kProbe) {
      probe.store(sample.controller(), std::memory_order_release);
      wake();
      return;
    }
    if (decision.verdict != dds::SetpointSession::Verdict::kApply) return;
    SetpointImage& image = setpoints.write_slot();
    image.controller = sample.controller();
    image.cycle = sample.cycle();
    image.released = decision.released;
    for (std::size_t i = 0; i < devices.size(); ++i) {
      Device& d = *devices[i];
      image.valid[i] = 0;
      for (const auto& e : sample.devices()) {
        if (!(e.device() == d.config.name)) continue;
        const bool ok =
            dds::matches(d.device_config, telegrams::Direction::kSetpoint, e.byte_order(), e.slots());
        {
          std::lock_guard<std::mutex> detail_lock(detail_mutex);
          d.mismatch =
              ok ? std::string{}
                 : dds::mismatch(d.device_config, telegrams::Direction::kSetpoint, e.byte_order(), e.slots());
        }
        if (ok) {
          dds::extract(e.slots(), image.frames[i]);
          image.valid[i] = 1;
        }
        break;
      }
    }
    setpoints.publish();
  }

  // ---- the cyclic thread (RealTimeRunner): no DDS, no lock, no allocation ----
  void cycle_step() noexcept {
    const std::uint64_t now = now_us();
    receive_frames(now);
    // The answer to the applied setpoint goes out as soon as every exchanging device has sent an input frame
    // after it (docs/gateway.md §4), at the latest after kAnswerWaitCycles; while idle, every cycle (G7).
    if (answer_wait > 0) {
      if (all_answered(now) || answer_wait == 1 || setpoints.pending()) {
        publish_answer(now);
        answer_wait = 0;
      } else {
        --answer_wait;
      }
    } else if (!serving) {
      publish_answer(now);
    }
    apply_setpoints(now);
    for (auto& owned : devices) {
      Device& d = *owned;
      if (!d.cyclic.load(std::memory_order_acquire)) continue;
      if (const std::size_t n = d.controller->next_output_frame(frame); n > 0)
        cyclic_socket.send(std::span(frame).first(n));
      if (alarm_timers(d, now) || d.controller->watchdog_expired(now)) lose_ar(d);
    }
  }

  // The RTA timer of both priorities (IoController::alarm_timer): our unacknowledged AlarmAck again, or the
  // AR ended after RTARetries resends (true; counted for the status, which names the priority).
  bool alarm_timers(Device& d, std::uint64_t now) noexcept {
    for (const bool high : {true, false}) {
      if (!d.controller->alarm_ack_pending(high)) continue;  // inline: the usual case costs no call
      std::size_t bytes = 0;
      const pn::AlarmTimerAction action = d.controller->alarm_timer(high, now, alarm_ack, bytes);
      // A resent AlarmAck, or the ERR-RTA-PDU that tells the device why its AR ends (decision I35).
      if (bytes > 0) cyclic_socket.send(std::span(alarm_ack).first(bytes));
      if (action == pn::AlarmTimerAction::kAbort) {
        d.alarm_timeout_high.store(high, std::memory_order_relaxed);
        d.alarm_timeouts.fetch_add(1, std::memory_order_release);
        return true;
      }
    }
    return false;
  }

  // A lost AR (watchdog or RTA timer) goes back to the start-up thread, which reconnects.
  void lose_ar(Device& d) noexcept {
    d.has_setpoint = d.answered = false;
    d.faulted.store(false, std::memory_order_relaxed);
    d.encoder_errors.store(0, std::memory_order_relaxed);
    d.cyclic.store(false, std::memory_order_release);
    wake();
  }

  void receive_frames(std::uint64_t now) noexcept {
    for (int k = 0; k < 256; ++k) {  // bounded: at most this many frames per cycle
      const std::size_t n = cyclic_socket.receive(frame, 0);
      if (n == 0) return;
      const auto in = std::span<const std::uint8_t>(frame.data(), n);
      const std::uint16_t frame_id = pn::peek_frame_id(in);
      const pn::FrameKind kind = pn::classify_frame_id(frame_id);
      for (auto& owned : devices) {
        Device& d = *owned;
        if (!d.cyclic.load(std::memory_order_acquire)) continue;
        if (kind == pn::FrameKind::kCyclicRtClass1) {
          // Compared first: decoding another device's frame only to refuse it was most of the cyclic work
          // with 16 devices (docs/performance.md).
          if (d.controller->input_frame_id() == frame_id && d.controller->on_input_frame(in, now)) {
            ++d.input_frames;
            break;
          }
        } else if (kind == pn::FrameKind::kAlarm) {
          std::size_t ack_bytes = 0;
          std::size_t alarm_ack_bytes = 0;
          const std::uint32_t before = d.controller->alarms_acknowledged();
          const std::size_t frames =
              d.controller->on_alarm(in, ack, alarm_ack, ack_bytes, alarm_ack_bytes, now);
          if (d.controller->rta_error_received()) {  // the device ended the AR (ERR-RTA-PDU, decision I35)
            d.rta_error_status.store(d.controller->last_error().value(), std::memory_order_relaxed);
            d.rta_error_high.store(d.controller->rta_error_high_priority(), std::memory_order_relaxed);
            d.rta_errors.fetch_add(1, std::memory_order_release);
            lose_ar(d);
            break;
          }
          if (frames > 0) {
            if (ack_bytes > 0) cyclic_socket.send(std::span(ack).first(ack_bytes));
            if (alarm_ack_bytes > 0) cyclic_socket.send(std::span(alarm_ack).first(alarm_ack_bytes));
            if (d.controller->alarms_acknowledged() != before) {  // a resent notification is reported once
              d.last_alarm.store(pack_alarm(*d.controller->last_alarm()), std::memory_order_relaxed);
              d.alarms.fetch_add(1, std::memory_order_release);
            }
            break;
          }
        }
      }
    }
  }

  bool all_answered(std::uint64_t now) const noexcept {
    for (const auto& owned : devices) {
      const Device& d = *owned;
      if (d.has_setpoint && d.input_frames == d.frames_at_apply && d.cyclic.load(std::memory_order_acquire) &&
          d.controller->input_valid(now)) {
        return false;
      }
    }
    return true;
  }

  void publish_answer(std::uint64_t now) noexcept {
    AnswerImage& image = answers.write_slot();
    image.serial = ++serial;
    image.controller = serving ? applied_controller : 0;
    for (std::size_t i = 0; i < devices.size(); ++i) {
      Device& d = *devices[i];
      const bool running = d.cyclic.load(std::memory_order_acquire) && d.controller->input_valid(now);
      image.exchanging[i] = running ? 1 : 0;
      // Only an input frame received after the setpoint was sent answers it (docs/gateway.md §4: never claim
      // a setpoint the drive has not seen); without one the answer names the older setpoint: stale for tomc.
      if (d.has_setpoint && d.input_frames > d.frames_at_apply) {
        d.answered_cycle = d.setpoint_cycle;
        d.answered = true;
      }
      image.has_setpoint[i] = serving && d.has_setpoint && d.answered ? 1 : 0;
      image.setpoint_cycle[i] = d.answered_cycle;
      if (!running) continue;
      for (std::size_t s = 0; s < drives::kSlotCount; ++s) {  // every slot's submodule (G10: unchanged)
        drives::Frame& actual = image.actual[i].slots[s];
        if (actual.length == 0) continue;
        const auto input = d.controller->input_data(d.places[s].slot, d.places[s].subslot);
        if (input.size() == actual.length) std::memcpy(actual.bytes.data(), input.data(), input.size());
      }
      const drives::Frame& drive = image.actual[i][Slot::kDrive];
      d.faulted.store(
          drive.length > 1 && (std::to_integer<std::uint8_t>(drive.bytes[d.zsw1_low_byte]) & kZsw1Fault) != 0,
          std::memory_order_relaxed);
      std::uint32_t encoder_errors = 0;
      for (std::size_t k = 0; k < d.encoder_word_count; ++k) {
        const auto& w = d.encoder_words[k];
        const drives::Frame& f = image.actual[i].slots[static_cast<std::size_t>(w.slot)];
        if (f.length > w.byte && (std::to_integer<std::uint8_t>(f.bytes[w.byte]) & w.mask) != 0)
          encoder_errors |= 1u << k;
      }
      d.encoder_errors.store(encoder_errors, std::memory_order_relaxed);
    }
    answers.publish();
    wake();
  }

  void apply_setpoints(std::uint64_t now) noexcept {
    if (setpoints.take()) {
      const SetpointImage& image = setpoints.value();
      for (std::size_t i = 0; i < devices.size(); ++i) {
        Device& d = *devices[i];
        if (image.released) d.has_setpoint = d.answered = false;
        if (image.valid[i] == 0 || !d.cyclic.load(std::memory_order_acquire)) continue;
        // Every slot must fit its submodule before any is copied: the output frames go out every cycle, and a
        // frame of new and old slots would be a setpoint nobody sent (review finding).
        const auto output_of = [&](std::size_t s) {
          return d.controller->output_data(d.places[s].slot, d.places[s].subslot);
        };
        bool complete = true;
        for (std::size_t s = 0; s < drives::kSlotCount; ++s) {
          const drives::Frame& setpoint = image.frames[i].slots[s];
          if (setpoint.length != 0 && output_of(s).size() != setpoint.length) complete = false;
        }
        if (!complete) continue;
        for (std::size_t s = 0; s < drives::kSlotCount; ++s) {
          const drives::Frame& setpoint = image.frames[i].slots[s];
          if (setpoint.length != 0) std::memcpy(output_of(s).data(), setpoint.bytes.data(), setpoint.length);
        }
        d.controller->set_outputs_valid(true);
        d.has_setpoint = true;
        d.setpoint_cycle = image.cycle;
        d.frames_at_apply = d.input_frames;
      }
      applied_controller = image.controller;
      last_setpoint_us = now;
      serving = true;
      answer_wait = kAnswerWaitCycles;
    } else if (serving && now - last_setpoint_us >= watchdog_us) {
      // G6: the controller went silent. The outputs' provider state goes BAD, so the drives' own setpoint
      // monitoring takes over; the last setpoint is never repeated as if it were fresh.
      serving = false;
      for (auto& owned : devices) {
        Device& d = *owned;
        d.has_setpoint = d.answered = false;
        if (d.cyclic.load(std::memory_order_acquire)) d.controller->set_outputs_valid(false);
      }
    }
  }

  // ---- the sender thread: DDS writes ----
  void sender_loop() {
    std::uint32_t seen = wake_generation.load(std::memory_order_acquire);
    while (!stop.load()) {
      wake_generation.wait(seen, std::memory_order_acquire);
      seen = wake_generation.load(std::memory_order_acquire);
      if (stop.load()) break;
      const Clock::time_point now = Clock::now();
      std::lock_guard<std::mutex> lock(session_mutex);
      if (session.controller() != 0 && session.silent(now)) session.release();  // G6, G1
      if (const std::uint64_t prober = probe.exchange(0); prober != 0)
        write_answer(answers.value(), prober, true);
      if (answers.take()) {
        const AnswerImage& image = answers.value();
        // Answers the cyclic thread published that were overwritten before this thread took them are
        // counted as sent-not (G5): the controller sees the gap in sequence_number.
        for (std::uint64_t k = last_serial + 1; k < image.serial; ++k)
          (void)session.next_sequence();
        last_serial = image.serial;
        write_answer(image, image.controller, false);
      }
      publish_status(now, false);
    }
  }

  void write_answer(const AnswerImage& image, std::uint64_t controller, bool probe_answer) {
    session.fill_answer(answer, config.gateway, session.next_sequence(), controller);
    std::size_t n = 0;
    for (std::size_t i = 0; i < devices.size(); ++i)
      n += image.exchanging.empty() ? 0 : image.exchanging[i];
    answer.devices().resize(n);
    std::size_t k = 0;
    for (std::size_t i = 0; i < devices.size() && !image.exchanging.empty(); ++i) {
      if (image.exchanging[i] == 0) continue;
      const Device& d = *devices[i];
      auto& e = answer.devices()[k++];
      e.device(d.config.name);
      e.byte_order(d.byte_order);
      e.has_setpoint(!probe_answer && image.has_setpoint[i] != 0);
      e.setpoint_cycle(image.setpoint_cycle[i]);
      dds::fill(d.device_config, image.actual[i], e.slots());
    }
    ++session.counters().answers_published;
    actual_writer->write(&answer);
  }

  void publish_status(Clock::time_point now, bool force) {
    std::string signature =
        std::to_string(session.incarnation()) + "/" + std::to_string(session.controller());
    status.devices().resize(devices.size());
    for (std::size_t i = 0; i < devices.size(); ++i) {
      const Device& d = *devices[i];
      auto& s = status.devices()[i];
      s.device(d.config.name);
      s.byte_order(d.byte_order);
      const auto telegrams = dds::slot_telegrams(d.device_config);
      for (std::size_t k = 0; k < telegrams.size(); ++k)
        s.telegrams()[k] = telegrams[k];
      std::string detail;
      {
        std::lock_guard<std::mutex> lock(detail_mutex);
        detail = d.detail;
        if (!d.mismatch.empty()) {
          s.state(gw::DEVICE_CONFIG_MISMATCH);
          detail = "the controller sends " + d.mismatch;
        } else if (!d.cyclic.load(std::memory_order_acquire)) {
          s.state(gw::DEVICE_DISCONNECTED);
          if (detail.empty()) detail = "no AR with '" + d.config.name_of_station + "'";
        } else if (const std::uint32_t encoder_errors = d.encoder_errors.load(std::memory_order_relaxed);
                   d.faulted.load(std::memory_order_relaxed) || encoder_errors != 0) {
          // ZSW1.3 (the fault number needs parameter access, r0945) or an encoder's Gx_ZSW.15 (its error code
          // is in Gx_XIST2, which the TO reads: spec 06 §3.7).
          s.state(gw::DEVICE_FAULTED);
          std::string what =
              d.faulted.load(std::memory_order_relaxed) ? "ZSW1 bit 3: the drive reports a fault" : "";
          for (std::size_t k = 0; k < d.encoder_word_count; ++k) {
            if ((encoder_errors >> k & 1u) != 0)
              what += (what.empty() ? "" : "; ") + std::string(d.encoder_words[k].name) +
                      " bit 15: encoder error";
          }
          detail = what + (detail.empty() ? "" : "; " + detail);
        } else {
          s.state(gw::DEVICE_CONNECTED);
        }
      }
      for (const std::string& more :
           {timeout_text(d), alarm_text(d.alarms.load(std::memory_order_acquire),
                                        d.last_alarm.load(std::memory_order_relaxed))}) {
        if (!more.empty()) detail = detail.empty() ? more : detail + "; " + more;
      }
      s.fault(0);
      if (detail.size() > 127) detail.resize(127);
      s.detail(detail);
      signature += "/" + std::to_string(static_cast<int>(s.state())) + ":" + detail;
    }
    if (!force && signature == status_signature && now - status_time < std::chrono::seconds(1)) return;
    status_signature = std::move(signature);
    status_time = now;
    session.fill_status(status, config.gateway, static_cast<std::uint32_t>(cycle.count()), 0);
    status_writer->write(&status);
  }

  // ---- the start-up thread ----
  void start_loop() {
    std::uint32_t xid = 0;
    std::vector<std::uint8_t> hello;  // a DCP Hello of an absent device, seen while waiting (decision I36)
    while (!stop.load()) {
      bool waiting = false;
      // The device whose Hello came is tried first, with its Hello instead of an Identify.
      std::vector<Device*> order;
      for (auto& owned : devices) {
        if (!hello.empty() && pn::dcp_hello_name(hello) == owned->config.name_of_station)
          order.push_back(owned.get());
      }
      for (auto& owned : devices) {
        if (order.empty() || order.front() != owned.get()) order.push_back(owned.get());
      }
      for (Device* next : order) {
        if (stop.load()) return;
        Device& d = *next;
        if (d.cyclic.load(std::memory_order_acquire)) continue;
        // p0922 of the drive object, or of the encoder object in an encoder-only device.
        const Slot checked = d.config.telegram != 0 ? Slot::kDrive : Slot::kEncoder1;
        detail::ParameterSteps steps{d.config.place(checked).slot,
                                     d.config.check_telegram,
                                     d.device_config.telegram(checked),
                                     0.0f,
                                     {}};
        for (const scenario::ProfinetParameterConfig& p : d.config.parameters)
          steps.writes.push_back({p.slot != 0 ? p.slot : steps.slot, {p.number, p.subindex, p.value}});
        const bool parameter_access = steps.check_telegram || !steps.writes.empty();
        const std::uint32_t alarms_before = d.controller->alarms_acknowledged();
        const std::string problem = detail::start_up(*d.controller, start_socket, rpc_socket, xid,
                                                     parameter_access ? &steps : nullptr, hello);
        // Alarms answered during the start-up (start_up.hpp) are reported like the cyclic thread's.
        if (const std::uint32_t during = d.controller->alarms_acknowledged() - alarms_before; during > 0) {
          d.last_alarm.store(pack_alarm(*d.controller->last_alarm()), std::memory_order_relaxed);
          d.alarms.fetch_add(during, std::memory_order_release);
        }
        std::string text = problem;
        if (problem.empty()) {
          if (const std::string diff = detail::describe(d.controller->module_diff()); !diff.empty())
            text = "module difference: " + diff;
          // has_setpoint is the cyclic thread's (false for every device it does not exchange with: it clears
          // it before handing a device back and sets it only for exchanging ones); writing it here was a data
          // race with publish_answer(), found by the TSan stage.
          d.controller->set_outputs_valid(false);  // until a controller's setpoint is applied (G6)
          d.ars.fetch_add(1, std::memory_order_relaxed);
          d.reference_speed_rpm.store(steps.reference_speed_rpm, std::memory_order_relaxed);
          d.cyclic.store(true, std::memory_order_release);
        } else {
          waiting = true;
        }
        std::lock_guard<std::mutex> lock(detail_mutex);
        d.detail = text;
      }
      wake();
      // Retry absent devices every 200 ms, or at once when one announces itself with a DCP Hello (decision
      // I36); otherwise look again for lost ARs every 20 ms.
      hello.clear();
      std::vector<std::string> absent;
      for (auto& owned : devices) {
        if (!owned->cyclic.load(std::memory_order_acquire)) absent.push_back(owned->config.name_of_station);
      }
      for (int i = 0; i < (waiting ? 10 : 1) && !stop.load() && hello.empty(); ++i)
        hello = detail::wait_for_hello(start_socket, absent, std::chrono::milliseconds(20));
    }
  }

  // The last AR the RTA timer ended in the cyclic thread, "" if none; "(n times)" from the second on.
  // And the last AR the device ended with an ERR-RTA-PDU (decision I35), the same way.
  static std::string timeout_text(const Device& d) {
    std::string text;
    if (const std::uint32_t count = d.alarm_timeouts.load(std::memory_order_acquire); count > 0) {
      text = detail::describe_alarm_timeout(d.alarm_timeout_high.load(std::memory_order_relaxed),
                                            d.controller->device()) +
             (count > 1 ? " (" + std::to_string(count) + " times)" : "");
    }
    if (const std::uint32_t count = d.rta_errors.load(std::memory_order_acquire); count > 0) {
      text += (text.empty() ? "" : "; ") +
              detail::describe_rta_error(d.rta_error_high.load(std::memory_order_relaxed),
                                         d.rta_error_status.load(std::memory_order_relaxed)) +
              (count > 1 ? " (" + std::to_string(count) + " times)" : "");
    }
    return text;
  }

  void release_all() {
    for (auto& owned : devices) {
      Device& d = *owned;
      if (d.controller->state() != pn::ControllerArState::kRunning) continue;
      rpc_socket.send_to(d.controller->release_request(), d.config.ip, pn::kPnioUdpPort);
      d.controller->abort_ar();
    }
  }
};

ProfinetGateway::ProfinetGateway(const scenario::ProfinetGatewayConfig& config)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.config = config;
  if (config.devices.empty()) throw std::invalid_argument("gateway: no device");
  m.cycle = std::chrono::nanoseconds(std::int64_t{config.send_clock_factor} * config.reduction_ratio * 31250);
  m.watchdog_us = static_cast<std::uint64_t>(config.watchdog * 1e6);
  m.session =
      dds::SetpointSession(std::chrono::nanoseconds(static_cast<std::int64_t>(config.watchdog * 1e9)));
  if (std::string e = m.cyclic_socket.open(config.interface); !e.empty())
    throw std::runtime_error("profinet.interface: " + e);
  if (std::string e = m.start_socket.open(config.interface, pn::RawSocketFrames::kDcpAndAlarms); !e.empty())
    throw std::runtime_error("profinet.interface: " + e);
  if (std::string e = m.rpc_socket.open(config.ip, pn::kPnioUdpPort); !e.empty())
    throw std::runtime_error("profinet.ip: " + e + " (is it an address of '" + config.interface + "'?)");
  for (std::size_t i = 0; i < config.devices.size(); ++i) {
    const scenario::ProfinetDeviceConfig& c = config.devices[i];
    auto d = std::make_unique<Impl::Device>();
    d->config = c;
    d->device_config = c.device_config();
    for (std::size_t s = 0; s < drives::kSlotCount; ++s)
      d->places[s] = c.place(static_cast<Slot>(s));
    d->byte_order = dds::to_contract(c.byte_order);
    d->zsw1_low_byte =
        c.byte_order == telegrams::ByteOrder::kBig || c.byte_order == telegrams::ByteOrder::kSwappedWords ? 1
                                                                                                          : 0;
    for (const scenario::ProfinetEncoderErrorBit& bit : c.encoder_error_bits()) {
      if (d->encoder_word_count < d->encoder_words.size()) d->encoder_words[d->encoder_word_count++] = bit;
    }
    pn::ControllerDeviceConfig pc;
    pc.name_of_station = c.name_of_station;
    pc.ip = {c.ip, c.netmask, {}};
    pc.modules = expected_modules(c);
    for (const scenario::ProfinetRecordConfig& r : c.records)
      pc.startup_records.push_back({r.slot, r.subslot, r.index, r.data, r.api});
    pc.send_clock_factor = config.send_clock_factor;
    pc.reduction_ratio = config.reduction_ratio;
    pc.watchdog_factor = config.watchdog_factor;
    pc.data_hold_factor = config.watchdog_factor;
    pc.rta_timeout_factor = config.rta_timeout_factor;  // into the AlarmCRBlock (decision I35)
    pc.rta_retries = config.rta_retries;
    pc.input_frame_id = static_cast<std::uint16_t>(pn::kFrameIdRtClass1First + 2 * i);
    pc.output_frame_id = static_cast<std::uint16_t>(pn::kFrameIdRtClass1First + 2 * i + 1);
    d->controller = std::make_unique<pn::IoController>(m.cyclic_socket.mac(), "tomc-gateway", std::move(pc),
                                                       random_uuid());
    m.devices.push_back(std::move(d));
  }
  const std::size_t n = m.devices.size();
  m.setpoints.for_each_slot([&](SetpointImage& s) {
    s.valid.assign(n, 0);
    s.frames.resize(n);
  });
  m.answers.for_each_slot([&](AnswerImage& a) {
    a.exchanging.assign(n, 0);
    a.has_setpoint.assign(n, 0);
    a.setpoint_cycle.assign(n, 0);
    a.actual.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      a.actual[i] = drives::make_frames(m.devices[i]->device_config, telegrams::Direction::kActual);
  });
  for (std::size_t i = 0; i < n; ++i) {
    m.setpoints.for_each_slot([&](SetpointImage& s) {
      s.frames[i] = drives::make_frames(m.devices[i]->device_config, telegrams::Direction::kSetpoint);
    });
  }
  dds::reserve_answer(m.answer, n);

  m.endpoints = std::make_unique<dds::GatewayEndpoints>(config.domain, "tomc gateway " + config.gateway,
                                                        config.partition, config.network, "gateway");
  m.actual_writer = &m.endpoints->actual_writer();
  m.status_writer = &m.endpoints->status_writer();
  {
    std::lock_guard<std::mutex> lock(m.session_mutex);
    m.publish_status(Clock::now(), true);
  }
  m.setpoint_listener =
      dds::make_taking_listener<gw::SetpointCycle>([&m](const gw::SetpointCycle& s) { m.on_setpoint(s); });
  m.endpoints->read_setpoints(m.setpoint_listener.get());
  techobjects::RealTimeRunnerConfig rt;
  rt.period = m.cycle;
  rt.fifo_priority = config.fifo_priority;
  rt.lock_memory = config.lock_memory;
  rt.wake_margin = std::chrono::microseconds(config.wake_margin_us);
  // The cyclic thread is named "tomc-pn-cyclic" (top -H, perf, ps -L on a gateway box; the allocation test
  // counts on it by name) once, on its first cycle.
  m.runner = std::make_unique<techobjects::RealTimeRunner>(rt, [&m, named = false]() mutable {
    if (!named) {
      (void)::pthread_setname_np(::pthread_self(), kCyclicThreadName);
      named = true;
    }
    m.cycle_step();
  });
  m.sender_thread = std::thread([&m] { m.sender_loop(); });
  m.start_thread = std::thread([&m] { m.start_loop(); });
  m.runner->start();
}

ProfinetGateway::~ProfinetGateway() {
  Impl& m = *impl_;
  m.stop.store(true);
  m.runner->stop();
  m.wake();
  if (m.start_thread.joinable()) m.start_thread.join();
  if (m.sender_thread.joinable()) m.sender_thread.join();
  m.release_all();      // every thread has stopped: this thread owns every controller now
  m.endpoints.reset();  // the reader first: no listener runs after this
}

GatewayCounters ProfinetGateway::counters() const {
  GatewayCounters c;
  {
    std::lock_guard<std::mutex> lock(impl_->session_mutex);
    const dds::SessionCounters& s = impl_->session.counters();
    c.setpoints_applied = s.setpoints_applied;
    c.setpoint_gaps = s.setpoint_gaps;
    c.setpoints_rejected = s.setpoints_rejected;
    c.answers_published = s.answers_published;
  }
  const techobjects::RunnerStatistics r = impl_->runner->statistics();
  c.cycles = r.cycles;
  c.overruns = r.overruns;
  c.start_latency_p99_us = r.jitter_p99_us;
  c.start_latency_max_us = r.jitter_max_us;
  c.early_starts = r.early_starts;
  c.spin_mean_us = r.spin_mean_us;
  c.late_wakeups = r.late_wakeups;
  return c;
}

std::vector<GatewayDeviceStatus> ProfinetGateway::devices() const {
  std::vector<GatewayDeviceStatus> out;
  std::lock_guard<std::mutex> lock(impl_->detail_mutex);
  for (const auto& d : impl_->devices) {
    const std::uint32_t alarms = d->alarms.load(std::memory_order_acquire);
    const std::string timeout = Impl::timeout_text(*d);
    out.push_back({d->config.name, d->cyclic.load(std::memory_order_acquire), d->ars.load(), alarms,
                   d->reference_speed_rpm.load(),
                   d->detail.empty() || timeout.empty() ? d->detail + timeout : d->detail + "; " + timeout,
                   alarm_text(alarms, d->last_alarm.load(std::memory_order_relaxed))});
  }
  return out;
}

}  // namespace tomc::profinet_gateway
