#pragma once
// The hosts of the PROFINET gateway's namespace tests (gateway_test.cpp, gateway_allocation_test.cpp): the
// emulated IO device hosting the simulated PROFIdrive drive on its own thread in the device namespace, the
// scenario of a positioning axis run through the DDS gateway adapter, and the two namespaces joined by a veth
// pair. Header-only; each test executable includes it once.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "netns_hosts.hpp"
#include "tomc/drives/profinet_drive.hpp"
#include "tomc/profinet/alarm.hpp"
#include "tomc/profinet/sockets.hpp"
#include "tomc/scenario/config.hpp"
#include "tomc/scenario/scenario.hpp"

namespace tomc::profinet::gateway_hosts {

namespace pn = tomc::profinet;
namespace sc = tomc::scenario;
using Json = nlohmann::ordered_json;

inline std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines)
    text += l + "\n";
  return text;
}

inline constexpr int kDomain = 175;  // DDS tests use 140-174 (decision G13)
inline constexpr pn::Ipv4Address kGatewayIp{10, 218, 0, 1};
inline constexpr pn::Ipv4Address kDeviceIp{10, 218, 0, 2};
inline constexpr double kTarget = 10.0;  // mm
// How long a lock-step cycle of the scenario waits for the gateway's answer: generous, so that a loaded
// machine cannot turn a slow answer (DDS threads are not real-time) into a missed cycle; a cycle waits only
// until its answer is in (as tests/dds's kAnswerTimeout). Below the gateway's G6 watchdog (0.5 s).
inline constexpr double kAnswerTimeout = 0.2;
inline constexpr int kDevicePriority = 40;  // SCHED_FIFO of the emulated devices' threads

using pn::testing::enter;
using pn::testing::now_us;
using pn::testing::quiet;

// The drive's parameters exactly as the scenario gives the embedded simulated drive (defaults of a telegram-3
// drive at the scenario's cycle time), so that the two runs can be compared.
inline sc::DriveSettings drive_settings(const std::string& drive) {
  sc::DriveSettings settings;
  sc::Problems problems;
  sc::load_drive(sc::Json::parse(drive), "drive", 0.001, settings, problems);
  return settings;
}

// What the emulated device is: its drive telegram (the module it has) and the p0922 it answers (0: the
// telegram, a drive as configured; another number: a drive reconfigured without changing its module).
struct DeviceOptions {
  int telegram = 3;
  std::uint16_t p0922 = 0;
  std::string interface = "pn-e";
  std::string name_of_station = "drive-1";
  pn::Ipv4Address ip = kDeviceIp;
  // The device announces no IP suite (0.0.0.0, as from the factory): the controller sets `ip` by DCP. Its
  // RPC socket listens on `ip` from the start (the namespace's address; the emulator does not rebind).
  bool factory_ip = false;
  // The drive object of a scenario file for the simulated drive ("": { "telegram": telegram }), e.g. with a
  // "supplementary_telegram" or an encoder-only device's "encoder_telegram" and "external_speed".
  std::string drive = {};
  // The device acknowledges the controller's AlarmAck DATA with an RTA ACK (IEC 61158-6-10 APMR, as p-net's
  // pf_alarm_apmr_send_ack); false: it never does, and the controller's RTA timer ends the AR.
  bool acknowledge_alarm_acks = true;
  // A device that answers no DCP Identify and announces itself with a DCP Hello every 300 ms while it has no
  // AR: only a controller that acts on Hello finds it (decision I36).
  bool hello_only = false;
};

// The emulated IO device on its own thread in the device namespace: ProfinetDrive behind the sockets. Its
// drive application follows the controller's STW2 sign-of-life (isochronous: one drive cycle per servo cycle
// of tomc) and sends its input frame right after each drive cycle; without drive cycles for 5 ms the input
// frame goes out every 1 ms (the controller's watchdog must see frames).
//
// On request (any thread) the drive raises a fault (SINAMICS F07900 with OFF2: ZSW1 bit 3) and the device
// sends an alarm notification (diagnosis or process alarm of the telegram submodule); it counts the AlarmAcks
// the controller returns.
class DeviceHost {
 public:
  explicit DeviceHost(const std::string& ns, DeviceOptions options = {}) : options_(options) {
    thread_ = std::thread([this, ns] { run(ns); });
  }
  ~DeviceHost() {
    stop_ = true;
    thread_.join();
  }
  std::string error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
  }
  int ars() const { return ars_.load(); }
  void inject_fault() { fault_requested_ = true; }
  // Encoder 1 of the drive reports an error (G1_ZSW bit 15, `code` in G1_XIST2); 0 clears it.
  void set_encoder_error(std::uint16_t code) { encoder_error_requested_ = 0x10000u | code; }
  void send_alarm(std::uint16_t type) { alarm_requested_ = type; }
  // The device ends its running AR with an ERR-RTA-PDU (low priority) carrying `status` (decision I35).
  void send_rta_error(std::uint32_t status) { rta_error_requested_ = status; }
  int alarm_acks() const { return alarm_acks_.load(); }
  // Every AlarmAck DATA frame taken, resends included, and the µs from the first to the last of them.
  int alarm_ack_frames() const { return alarm_ack_frames_.load(); }
  std::uint64_t alarm_ack_span_us() const { return last_alarm_ack_us_.load() - first_alarm_ack_us_.load(); }
  // The controller's output frames taken by the device so far (the gateway sends them from its cyclic thread,
  // which owns the AR only after the start-up's p0922 check).
  int output_frames() const { return output_frames_.load(); }
  // M_ADD1 (N2, spec 06 §2.14) of the supplementary telegram 750 in the drive object's subslot 3, as the
  // drive application took it: the largest and the last value (0 without telegram 750).
  int m_add1_max() const { return m_add1_max_.load(); }
  int m_add1_last() const { return m_add1_last_.load(); }
  // The simulated drive's active fault (0: none), e.g. 8501 after its setpoint timeout.
  std::uint32_t drive_fault() const { return drive_fault_.load(); }
  // ERR-RTA-PDUs the controller sent (decision I35) and the last one's PNIOStatus (counted only: the device's
  // AR then ends by its data hold, or by the controller's next Connect, as before I35).
  int rta_errors() const { return rta_errors_.load(); }
  // hello_only: the Identify requests left unanswered and the Hellos sent.
  int identify_ignored() const { return identify_ignored_.load(); }
  int hellos() const { return hellos_.load(); }
  std::uint32_t last_rta_error() const { return last_rta_error_.load(); }
  // RTATimeoutFactor and RTARetries of the controller's AlarmCRBlock in the last AR.
  std::pair<int, int> alarm_cr_timing() const { return {rta_timeout_factor_.load(), rta_retries_.load()}; }
  // p2000 as the emulated drive holds it (changed by the controller's parameter access).
  double reference_speed_rpm() const { return reference_speed_rpm_.load(); }
  // How each AR ended that the device had running ("" while none ended): by its own data-hold watchdog (the
  // controller's output frames stopped) or by the controller (Release, or a new Connect after the
  // controller's watchdog ended its side), with the time since the device's start and the silences behind it.
  std::string ar_ends() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return ar_ends_;
  }
  // The longest silences while an AR ran: between two output frames taken, and between two passes of the
  // device's loop (its own scheduling), microseconds.
  std::uint64_t max_output_gap_us() const { return max_output_gap_us_.load(); }
  std::uint64_t max_loop_gap_us() const { return max_loop_gap_us_.load(); }
  std::uint64_t max_input_gap_us() const { return max_input_gap_us_.load(); }
  std::uint64_t max_loop_gap_at_ms() const { return max_loop_gap_at_ms_.load(); }

 private:
  // An alarm notification of the telegram submodule to the AR's controller (IEC 61158-6-10 RTA DATA): a
  // diagnosis alarm with a ChannelDiagnosis (USI 0x8000, channel 0x8000, error 9), or a process alarm with a
  // manufacturer-specific USI 0x0001 and two bytes; low priority (FrameID 0xFE01).
  std::size_t alarm_frame(const pn::IoDevice& device, const pn::MacAddress& own, std::uint16_t type,
                          std::span<std::uint8_t> out) {
    pn::RtaFrame alarm;
    alarm.frame_id = pn::kFrameIdAlarmLow;
    alarm.destination_endpoint = device.connection().alarm_cr.local_alarm_reference;
    alarm.source_endpoint = 3;
    alarm.send_sequence = alarm_sequence_;
    alarm.ack_sequence = 0xFFFE;
    alarm.has_block = true;
    alarm.block.alarm_type = type;
    alarm.block.slot = tomc::drives::kDriveObjectSlot;
    alarm.block.subslot = tomc::drives::kTelegramSubslot;
    alarm.block.module_ident = tomc::drives::kDriveObjectIdent;
    alarm.block.submodule_ident =
        tomc::drives::telegram_submodule_ident(static_cast<std::uint16_t>(options_.telegram));
    alarm.block.specifier = static_cast<std::uint16_t>(0x2000 | (alarm_sequence_ & 0x07FF));
    const std::array<std::uint8_t, 6> channel{0x80, 0x00, 0x08, 0x00, 0x00, 0x09};
    alarm.block.user_structure_identifier = type == pn::alarm_type::kDiagnosis ? 0x8000 : 0x0001;
    alarm.block.payload_length = type == pn::alarm_type::kDiagnosis ? 6 : 2;
    std::copy_n(channel.begin(), alarm.block.payload_length, alarm.block.payload.begin());
    ++alarm_sequence_;
    std::size_t written = 0;
    const pn::EthernetHeader header{device.connection().ar.initiator_mac, own, pn::VlanTag{5, 0}};
    return pn::encode(header, alarm, out, written) == pn::ProfinetError::kNone ? written : 0;
  }

  void observe_m_add1(const pn::IoDevice& device) {
    const auto out = device.output_data(tomc::drives::kDriveObjectSlot, tomc::drives::kSupplementarySubslot);
    if (out.size() < 2) return;
    const int value = static_cast<std::int16_t>(out[0] << 8 | out[1]);  // PROFINET order (big)
    m_add1_last_ = value;
    if (value > m_add1_max_) m_add1_max_ = value;
  }

  void fail(const std::string& why) {
    std::lock_guard<std::mutex> lock(mutex_);
    error_ = why;
  }
  void run(const std::string& ns) {
    if (!enter(ns)) return fail("setns into the device namespace failed");
    // As a drive's firmware: not starved by other processes for the controller's watchdog (decision I22).
    (void)pn::testing::real_time(kDevicePriority);
    pn::RawSocket raw;
    pn::UdpSocket udp;
    if (std::string e = raw.open(options_.interface); !e.empty()) return fail(e);
    if (std::string e = udp.open(options_.ip, pn::kPnioUdpPort); !e.empty()) return fail(e);
    pn::DeviceIdentity identity;
    identity.name_of_station = options_.name_of_station;
    identity.mac = raw.mac();
    if (!options_.factory_ip) identity.ip = {options_.ip, {255, 255, 255, 0}, {}};
    identity.vendor_id = 0x002A;
    identity.device_id = 0x0C01;
    identity.vendor = "tomc emulated drive";
    const sc::DriveSettings settings =
        drive_settings(options_.drive.empty() ? R"({ "telegram": )" + std::to_string(options_.telegram) + " }"
                                              : options_.drive);
    tomc::drives::ProfinetDrive host(identity, settings.device_config(), settings.parameters);
    if (options_.p0922 != 0) host.set_p0922(options_.p0922);
    host.drive().set_external_speed(settings.external_speed);
    pn::IoDevice& device = host.device();
    std::array<std::uint8_t, 1518> frame{};
    std::uint64_t next_send = now_us();
    std::uint64_t last_step = now_us();
    pn::ArState last = pn::ArState::kNone;
    const std::uint64_t start = now_us();
    std::uint64_t last_output = 0;  // when the last output frame was taken (0: none in this AR)
    std::uint64_t last_input = 0;
    std::uint64_t last_loop = 0;
    bool was_running = false;
    const auto note_gap = [&](std::atomic<std::uint64_t>& max, std::uint64_t since, std::uint64_t now) {
      if (since != 0 && now > since && now - since > max.load()) {
        max = now - since;
        if (&max == &max_loop_gap_us_) max_loop_gap_at_ms_ = (now - start) / 1000;
      }
    };
    const auto send_input = [&] {
      if (const std::size_t n = device.next_input_frame(frame); n > 0) {
        raw.send(std::span(frame).first(n));
        const std::uint64_t t = now_us();
        if (device.state() == pn::ArState::kRunning) note_gap(max_input_gap_us_, last_input, t);
        last_input = t;
      }
    };
    // Takes one frame if one comes within `timeout_us`; false if none came.
    const auto take = [&](int timeout_us) {
      const std::size_t n = raw.receive(frame, timeout_us);
      if (n > 0) {
        const auto in = std::span(frame).first(n);
        const pn::FrameKind kind = pn::classify_frame_id(pn::peek_frame_id(in));
        if (kind == pn::FrameKind::kDcp) {
          pn::WireReader dcp_in(in);
          (void)pn::decode_ethernet(dcp_in);
          const pn::DcpMessage asked = pn::decode_dcp(dcp_in);
          if (options_.hello_only && dcp_in.ok() && asked.service == pn::DcpService::kIdentify) {
            ++identify_ignored_;
          } else if (const auto answer = device.on_dcp(in); !answer.empty()) {
            raw.send(answer);
          }
        } else if (kind == pn::FrameKind::kAlarm) {
          pn::RtaFrame rta;
          if (pn::decode_rta(in, rta) == pn::ProfinetError::kNone && rta.pdu_type == pn::RtaPduType::kError &&
              device.state() != pn::ArState::kNone) {
            ++rta_errors_;
            last_rta_error_ = rta.error.value();
          } else if (pn::decode_rta(in, rta) == pn::ProfinetError::kNone &&
                     rta.pdu_type == pn::RtaPduType::kData && rta.has_block && rta.block.is_ack) {
            // A resend (the SendSeqNum taken last: our ACK was late or lost) is acknowledged again, counted
            // once.
            if (rta.send_sequence != last_alarm_ack_) ++alarm_acks_;
            if (alarm_ack_frames_++ == 0) first_alarm_ack_us_ = now_us();
            last_alarm_ack_us_ = now_us();
            last_alarm_ack_ = rta.send_sequence;
            if (options_.acknowledge_alarm_acks) {
              pn::RtaFrame transport;
              transport.frame_id = rta.frame_id;
              transport.destination_endpoint = rta.source_endpoint;
              transport.source_endpoint = rta.destination_endpoint;
              transport.pdu_type = pn::RtaPduType::kAck;
              transport.tack = false;
              transport.send_sequence = static_cast<std::uint16_t>(alarm_sequence_ - 1);  // our last DATA
              transport.ack_sequence = rta.send_sequence;
              std::array<std::uint8_t, 128> ack{};
              std::size_t written = 0;
              const pn::EthernetHeader header{
                  device.connection().ar.initiator_mac, raw.mac(),
                  pn::VlanTag{
                      rta.frame_id == pn::kFrameIdAlarmHigh ? pn::kPriorityAlarmHigh : pn::kPriorityAlarmLow,
                      0}};
              if (pn::encode(header, transport, ack, written) == pn::ProfinetError::kNone)
                raw.send(std::span(ack).first(written));
            }
          }
        } else if (const std::uint64_t t = now_us();
                   device.on_cyclic(in, t) && (++output_frames_, note_gap(max_output_gap_us_, last_output, t),
                                               last_output = t, host.follow_controller())) {
          last_step = now_us();
          send_input();
          observe_m_add1(device);
        }
      }
      return n > 0;
    };
    std::uint64_t next_hello = now_us();
    while (!stop_) {
      if (options_.hello_only && device.state() == pn::ArState::kNone && now_us() >= next_hello) {
        next_hello = now_us() + 300'000;
        raw.send(device.hello());
        ++hellos_;
      }
      if (device.state() == pn::ArState::kRunning) note_gap(max_loop_gap_us_, last_loop, now_us());
      last_loop = now_us();
      (void)take(200);
      pn::testing::serve_device_rpc(device, udp, frame, kGatewayIp);
      if (device.state() == pn::ArState::kRunning && last != pn::ArState::kRunning) {
        ++ars_;
        rta_timeout_factor_ = device.connection().alarm_cr.rta_timeout_factor;
        rta_retries_ = device.connection().alarm_cr.rta_retries;
        last_alarm_ack_ = 0xFFFE;  // a new AR: the controller's SendSeqNum starts at 0xFFFF again
      }
      if (fault_requested_.exchange(false))
        host.drive().inject_fault(7900, tomc::drives::SimulatedDriveParameters::FaultReaction::kOff2);
      if (const std::uint32_t e = encoder_error_requested_.exchange(0); e != 0) {
        if ((e & 0xFFFF) != 0)
          host.drive().inject_encoder_error(1, static_cast<std::uint16_t>(e));
        else
          host.drive().clear_encoder_error(1);
      }
      if (const std::uint16_t type = alarm_requested_.exchange(0);
          type != 0 && device.state() == pn::ArState::kRunning) {
        std::array<std::uint8_t, 256> alarm{};
        if (const std::size_t n = alarm_frame(device, raw.mac(), type, alarm); n > 0)
          raw.send(std::span(alarm).first(n));
      }
      if (const std::uint32_t status = rta_error_requested_.exchange(0);
          status != 0 && device.state() == pn::ArState::kRunning) {
        pn::RtaFrame error;
        error.frame_id = pn::kFrameIdAlarmLow;
        error.destination_endpoint = device.connection().alarm_cr.local_alarm_reference;
        error.source_endpoint = 3;
        error.pdu_type = pn::RtaPduType::kError;
        error.tack = false;
        error.send_sequence = 0xFFFF;
        error.ack_sequence = 0xFFFE;
        error.error = pn::PnioStatus::from(status);
        std::array<std::uint8_t, 128> frame_out{};
        std::size_t written = 0;
        const pn::EthernetHeader header{device.connection().ar.initiator_mac, raw.mac(), pn::VlanTag{5, 0}};
        if (pn::encode(header, error, frame_out, written) == pn::ProfinetError::kNone)
          raw.send(std::span(frame_out).first(written));
        device.abort_ar();  // its side of the AR ends with the PDU
      }
      last = device.state();
      drive_fault_ = host.drive().active_fault();
      reference_speed_rpm_ = host.drive().parameters().reference_speed_rpm;
      const std::uint64_t now = now_us();
      if (now >= next_send) {
        next_send = now + 1000;
        // The drive's clock is the controller's while the AR runs and the controller's outputs are valid
        // (IOPS GOOD: the gateway has a controller, G6): it waits for the controller however late a loaded
        // machine runs the lock-step scenario (after 50 ms it used to go on alone, and under load 14 the
        // drive moved ahead of tomc and faulted). Without it (no AR, IOPS BAD before the first setpoint or
        // after the gateway's watchdog) the drive runs on its own 1 ms clock and ends in F08501 like a real
        // one.
        const bool controller_clock = host.outputs_valid();
        if (!controller_clock) host.cycle();
        // While following the controller, every input frame answers a drive cycle; after 5 ms without one
        // (tomc waiting) the frame goes out every 1 ms again, for the controller's watchdog.
        // An output frame that came in since take() returned is taken first: a frame sent before it carries
        // the drive's state from before that setpoint, and the gateway, which pairs a setpoint with the first
        // input frame received after it, would hand tomc that stale frame as the answer: an unchanged drive
        // sign-of-life, one error; two within ten cycles are alarm 406 (one axis of four in one TSan run).
        for (int k = 0; k < 8 && take(0); ++k) {
        }
        if (device.state() != pn::ArState::kNone && now_us() - last_step > 5'000) send_input();
        const std::uint64_t checked = now_us();
        if (device.watchdog_expired(checked)) {
          note_end("by the device's data hold", checked - start, checked - last_output);
          last_output = last_input = 0;
        }
      }
      if (was_running && device.state() != pn::ArState::kRunning && last_output != 0) {
        note_end("by the controller", now_us() - start, now_us() - last_output);
        last_output = last_input = 0;
      }
      was_running = device.state() == pn::ArState::kRunning;
    }
  }
  void note_end(const char* how, std::uint64_t at_us, std::uint64_t silence_us) {
    std::lock_guard<std::mutex> lock(mutex_);
    ar_ends_ += std::string("AR ended ") + how + " at " + std::to_string(at_us / 1000) +
                " ms, the last output frame " + std::to_string(silence_us / 1000) + " ms before; ";
  }

  DeviceOptions options_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<int> ars_{0};
  std::atomic<bool> fault_requested_{false};
  std::atomic<std::uint32_t> encoder_error_requested_{0};  // 0x10000 | code; 0: nothing requested
  std::atomic<std::uint16_t> alarm_requested_{0};
  std::atomic<std::uint32_t> rta_error_requested_{0};
  std::atomic<int> alarm_acks_{0};
  std::atomic<int> alarm_ack_frames_{0};
  std::atomic<std::uint64_t> first_alarm_ack_us_{0};
  std::atomic<std::uint64_t> last_alarm_ack_us_{0};
  std::atomic<int> output_frames_{0};
  std::atomic<int> m_add1_max_{0};
  std::atomic<int> m_add1_last_{0};
  std::atomic<std::uint32_t> drive_fault_{0};
  std::atomic<double> reference_speed_rpm_{0.0};
  std::atomic<int> rta_errors_{0};
  std::atomic<int> identify_ignored_{0};
  std::atomic<int> hellos_{0};
  std::atomic<std::uint32_t> last_rta_error_{0};
  std::atomic<int> rta_timeout_factor_{0};
  std::atomic<int> rta_retries_{0};
  std::atomic<std::uint64_t> max_output_gap_us_{0};
  std::atomic<std::uint64_t> max_loop_gap_us_{0};
  std::atomic<std::uint64_t> max_input_gap_us_{0};
  std::atomic<std::uint64_t> max_loop_gap_at_ms_{0};
  std::string ar_ends_;                    // under mutex_
  std::uint16_t alarm_sequence_ = 0;       // device thread only
  std::uint16_t last_alarm_ack_ = 0xFFFE;  // device thread only: SendSeqNum of the last AlarmAck taken
  mutable std::mutex mutex_;
  std::string error_;
};

// A positioning axis on telegram 3: enable, home (mode 0 at 0), MC_MoveAbsolute to kTarget; with
// `reset_every`, an MC_Reset edge and a new MC_MoveVelocity edge every that many cycles instead of the move.
inline Json scenario(bool through_gateway, int cycles, int reset_every) {
  Json drive = {{"telegram", 3}};
  if (through_gateway) {
    drive["adapter"] = {{"type", "dds_gateway"},
                        {"domain", kDomain},
                        {"partition", "tomc-test-" + std::to_string(::getpid())},
                        {"device", "axis1"},
                        {"connect_timeout_s", 10.0},
                        {"answer_timeout_s", kAnswerTimeout}};
  }
  Json doc;
  doc["cycle_time"] = 0.001;
  doc["cycles"] = cycles;
  doc["technology_objects"] = Json::array({Json{{"name", "Slide"},
                                                {"type", "TO_PositioningAxis"},
                                                {"config", {{"DynamicLimits.MaxJerk", 0.0}}},
                                                {"drive", drive}}});
  Json timeline = Json::array();
  timeline.push_back({{"cycle", 0},
                      {"instance", "power"},
                      {"instruction", "MC_Power"},
                      {"axis", "Slide"},
                      {"inputs", {{"Enable", true}, {"StartMode", 1}}}});
  timeline.push_back({{"cycle", 5},
                      {"instance", "home"},
                      {"instruction", "MC_Home"},
                      {"axis", "Slide"},
                      {"inputs", {{"Execute", true}, {"Mode", 0}, {"Position", 0.0}}}});
  if (reset_every == 0) {
    timeline.push_back({{"cycle", 20},
                        {"instance", "move"},
                        {"instruction", "MC_MoveAbsolute"},
                        {"axis", "Slide"},
                        {"inputs", {{"Execute", true}, {"Position", kTarget}, {"Velocity", 100.0}}}});
  } else {
    for (int c = 20; c < cycles; c += reset_every) {
      timeline.push_back({{"cycle", c},
                          {"instance", "reset"},
                          {"instruction", "MC_Reset"},
                          {"axis", "Slide"},
                          {"inputs", {{"Execute", true}}}});
      timeline.push_back({{"cycle", c + 5}, {"instance", "reset"}, {"inputs", {{"Execute", false}}}});
      timeline.push_back({{"cycle", c + 10},
                          {"instance", "move"},
                          {"instruction", "MC_MoveVelocity"},
                          {"axis", "Slide"},
                          {"inputs", {{"Execute", true}, {"Velocity", 20.0}}}});
      timeline.push_back({{"cycle", c + 15}, {"instance", "move"}, {"inputs", {{"Execute", false}}}});
    }
  }
  doc["timeline"] = timeline;
  doc["trace"] = {"Slide.ActualPosition",
                  "Slide.ActualVelocity",
                  "power.Status",
                  reset_every == 0 ? "move.Done" : "move.InVelocity",
                  "Slide.ErrorDetail.Number",
                  "Slide.StatusDrive.CommunicationOK"};
  return doc;
}

// A trace sink that hands each finished row to `on_row` (cycle, values) as the scenario writes it.
class RowBuffer : public std::stringbuf {
 public:
  explicit RowBuffer(std::function<void(int, const std::vector<double>&)> on_row)
      : on_row_(std::move(on_row)) {}
  std::vector<std::vector<double>> rows;

 protected:
  int sync() override { return 0; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i)
      put(s[i]);
    return n;
  }
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) put(static_cast<char>(c));
    return c;
  }

 private:
  void put(char c) {
    if (c != '\n') {
      line_ += c;
      return;
    }
    if (!header_seen_) {
      header_seen_ = true;
    } else {
      std::vector<double> values;
      std::istringstream cells(line_);
      for (std::string cell; std::getline(cells, cell, ',');)
        values.push_back(cell == "true" ? 1.0 : cell == "false" ? 0.0 : std::strtod(cell.c_str(), nullptr));
      rows.push_back(values);
      on_row_(static_cast<int>(values.empty() ? -1 : values[0]), values);
    }
    line_.clear();
  }
  std::function<void(int, const std::vector<double>&)> on_row_;
  std::string line_;
  bool header_seen_ = false;
};

// Runs the scenario; through the gateway it runs on a thread in the gateway namespace (its DDS participant
// and sockets live there). Columns: 0 cycle, 1 time, then the trace in scenario() order.
inline std::vector<std::vector<double>> run(const Json& doc, const std::string& ns,
                                            std::function<void(int, const std::vector<double>&)> on_row,
                                            std::string& failure) {
  RowBuffer buffer(std::move(on_row));
  std::thread runner([&] {
    if (!ns.empty() && !enter(ns)) return void(failure = "setns into the gateway namespace failed");
    auto loaded = sc::Scenario::load(sc::Json::parse(doc.dump()));
    if (!loaded.scenario) return void(failure = "scenario: " + joined(loaded.problems));
    std::ostream out(&buffer);
    const sc::RunResult result = loaded.scenario->run(&out);
    if (!result.runtime_errors.empty()) failure = joined(result.runtime_errors);
    if (!result.warnings.empty()) failure += "warnings: " + joined(result.warnings);
  });
  runner.join();
  return buffer.rows;
}

// The two hosts joined by the veth pair; "" or why the test must skip. Nothing is sent unless each namespace
// sees only lo and its own veth end (never the machine's interfaces): the caller asserts own_interfaces_only.
inline std::string make_hosts(pn::testing::Namespaces& hosts) {
  return hosts.make({"pn-g", "", "10.218.0.1/24"}, {"pn-e", "", "10.218.0.2/24"});
}
// `drives` device veth pairs whose gateway ends (pn-g0, pn-g1, ...) are ports of a bridge pn-g (10.218.0.1,
// the gateway's interface) and whose device ends pn-e<k> (10.218.0.<10+k>) are in the device namespace; ""
// or why not. Nothing is sent unless bridged_interfaces_only() holds.
inline std::string make_bridged_hosts(pn::testing::Namespaces& hosts, int drives) {
  if (::geteuid() != 0) return "not root: ip netns needs CAP_SYS_ADMIN";
  if (quiet("ip netns add " + hosts.first) != 0 || quiet("ip netns add " + hosts.second) != 0)
    return "'ip netns add' failed (no permission or no iproute2)";
  const std::string g = "ip -n " + hosts.first + " ";
  const std::string d = "ip -n " + hosts.second + " ";
  std::string script = g + "link add pn-g type bridge && " + g + "addr add 10.218.0.1/24 dev pn-g && " + g +
                       "link set lo up && " + d + "link set lo up";
  for (int k = 0; k < drives; ++k) {
    const std::string n = std::to_string(k);
    script += " && " + g + "link add pn-g" + n + " type veth peer name pn-e" + n + " && " + g +
              "link set pn-e" + n + " netns " + hosts.second + " && " + g + "link set pn-g" + n +
              " master pn-g && " + g + "link set pn-g" + n + " up && " + d + "addr add 10.218.0." +
              std::to_string(10 + k) + "/24 dev pn-e" + n + " && " + d + "link set pn-e" + n + " up";
  }
  script += " && " + g + "link set pn-g up";
  return quiet("sh -c '" + script + "'") == 0 ? std::string{} : "could not set up the bridge and veth pairs";
}
inline bool bridged_interfaces_only(const pn::testing::Namespaces& hosts, int drives) {
  std::set<std::string> gateway_side{"lo", "pn-g"};
  std::set<std::string> device_side{"lo"};
  for (int k = 0; k < drives; ++k) {
    gateway_side.insert("pn-g" + std::to_string(k));
    device_side.insert("pn-e" + std::to_string(k));
  }
  return hosts.interfaces(hosts.first) == gateway_side && hosts.interfaces(hosts.second) == device_side &&
         hosts.carrier(hosts.first, "pn-g");
}
// The emulated device on pn-e<k> of make_bridged_hosts(): drive-<k+1> at 10.218.0.<10+k>.
inline DeviceOptions bridged_device(int k) {
  DeviceOptions options;
  options.interface = "pn-e" + std::to_string(k);
  options.name_of_station = "drive-" + std::to_string(k + 1);
  options.ip = {10, 218, 0, static_cast<std::uint8_t>(10 + k)};
  return options;
}

// The gateway file's "devices" for the bridged_device()s 0..drives-1: axis<k+1> on telegram 3.
inline std::string bridged_devices(int drives) {
  std::string devices = "[";
  for (int k = 0; k < drives; ++k) {
    const std::string n = std::to_string(k + 1);
    devices += std::string(k == 0 ? "" : ", ") + R"({ "name": "axis)" + n +
               R"(", "name_of_station": "drive-)" + n + R"(", "ip": "10.218.0.)" + std::to_string(10 + k) +
               R"(", "telegram": 3 })";
  }
  return devices + "]";
}

// Positioning axes Axis1..AxisN, each through the gateway's device axis<k>: MC_Power at cycle 0,
// MC_MoveVelocity 20 mm/s at cycle 20; traced: ActualVelocity, ErrorDetail.Number, CommunicationOK per axis.
inline Json velocity_scenario(int drives, int cycles) {
  Json doc;
  doc["cycle_time"] = 0.001;
  doc["cycles"] = cycles;
  doc["technology_objects"] = Json::array();
  doc["timeline"] = Json::array();
  doc["trace"] = Json::array();
  Json moves = Json::array();  // after every MC_Power: the timeline is in time order
  for (int k = 1; k <= drives; ++k) {
    const std::string axis = "Axis" + std::to_string(k);
    doc["technology_objects"].push_back({{"name", axis},
                                         {"type", "TO_PositioningAxis"},
                                         {"drive",
                                          {{"telegram", 3},
                                           {"adapter",
                                            {{"type", "dds_gateway"},
                                             {"domain", kDomain},
                                             {"partition", "tomc-test-" + std::to_string(::getpid())},
                                             {"device", "axis" + std::to_string(k)},
                                             {"connect_timeout_s", 10.0},
                                             {"answer_timeout_s", kAnswerTimeout}}}}}});
    doc["timeline"].push_back({{"cycle", 0},
                               {"instance", "power" + std::to_string(k)},
                               {"instruction", "MC_Power"},
                               {"axis", axis},
                               {"inputs", {{"Enable", true}, {"StartMode", 1}}}});
    moves.push_back({{"cycle", 20},
                     {"instance", "move" + std::to_string(k)},
                     {"instruction", "MC_MoveVelocity"},
                     {"axis", axis},
                     {"inputs", {{"Execute", true}, {"Velocity", 20.0}}}});
    for (const char* variable : {".ActualVelocity", ".ErrorDetail.Number", ".StatusDrive.CommunicationOK"})
      doc["trace"].push_back(axis + variable);
  }
  for (const auto& move : moves)
    doc["timeline"].push_back(move);
  return doc;
}

inline bool own_interfaces_only(const pn::testing::Namespaces& hosts) {
  return hosts.interfaces(hosts.first) == std::set<std::string>{"lo", "pn-g"} &&
         hosts.interfaces(hosts.second) == std::set<std::string>{"lo", "pn-e"} &&
         hosts.carrier(hosts.first, "pn-g");
}

}  // namespace tomc::profinet::gateway_hosts
