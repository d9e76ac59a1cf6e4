// The start-up of one AR over the sockets (start_up.hpp).
#include "start_up.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <variant>

#include "tomc/profinet/dcp_commissioning.hpp"
#include "tomc/profinet/parameter_access.hpp"

namespace tomc::profinet_gateway::detail {

namespace pn = tomc::profinet;
using Clock = std::chrono::steady_clock;

namespace {

constexpr auto kDcpWait = std::chrono::milliseconds(500);  // DCP ResponseDelay is at most 400 ms
constexpr int kRpcWaitUs = 300'000;
constexpr int kRpcAttempts = 3;

std::string hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", value);
  return text;
}

std::string hex_short(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%X", value);
  return text;
}

// Why the device refused the last request: its PNIOStatus, or the RPC Reject of an object UUID it does not
// export (a VendorID/DeviceID other than its DCP answer named).
std::string refusal(const pn::IoController& controller) {
  if (controller.last_reject() != 0) {
    return "RPC Reject " + hex(controller.last_reject()) + " for object " +
           pn::to_string(controller.device_object());
  }
  return "PNIOStatus " + hex(controller.last_error().value());
}

// The DCP answer with this xid, skipping every other frame (cyclic frames of running ARs arrive too); with
// `hello_name`, a DCP Hello of that name is as good as the answer (the device announced itself, I36).
std::vector<std::uint8_t> receive_dcp(pn::RawSocket& raw, std::uint32_t xid,
                                      const std::string* hello_name = nullptr) {
  std::array<std::uint8_t, 1518> frame{};
  for (const auto end = Clock::now() + kDcpWait; Clock::now() < end;) {
    const std::size_t n = raw.receive(frame, 10'000);
    if (n == 0) continue;
    const auto in_frame = std::span<const std::uint8_t>(frame.data(), n);
    if (pn::classify_frame_id(pn::peek_frame_id(in_frame)) != pn::FrameKind::kDcp) continue;
    if (hello_name != nullptr && pn::dcp_hello_name(in_frame) == *hello_name)
      return {in_frame.begin(), in_frame.end()};
    pn::WireReader in{in_frame};
    (void)pn::decode_ethernet(in);
    const pn::DcpMessage message = pn::decode_dcp(in);
    if (in.ok() && message.xid == xid && message.type == pn::DcpServiceType::kSuccess) {
      return {in_frame.begin(), in_frame.end()};
    }
  }
  return {};
}

// One RPC request and its answer from the device's address (repeated on silence: UDP may lose it).
// The device's answer to `request`: the RPC response (or fault) with the request's activity UUID and sequence
// number. Anything else from the device is skipped: a late answer to an earlier attempt or to a Release sent
// without waiting would otherwise be taken for this answer, and every later call would read the answer of the
// call before it.
// Alarms of the starting device (its alarm CR exists from the Connect on): answered here, since the cyclic
// thread offers frames only to running ARs; a notification left unacknowledged would block the device's
// next ones (IEC 61158-6-10 RTA, window size 1). The RTA timer of our AlarmAcks runs here too, until the
// cyclic thread takes the AR over. Non-blocking: the frames already received.
struct AlarmTimeout {
  bool ended = false;  // the RTA ended the AR: our timer, or the device (device_error)
  bool high_priority = false;
  bool device_error = false;  // the device ended it (ERR-RTA-PDU, decision I35)
  std::uint32_t status = 0;   // the ERR's PNIOStatus
};

std::uint64_t now_us() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now().time_since_epoch()).count());
}

void answer_alarms(pn::IoController& controller, pn::RawSocket& raw, AlarmTimeout& timeout) {
  std::array<std::uint8_t, 1518> frame{};
  std::array<std::uint8_t, 128> ack{};
  std::array<std::uint8_t, 128> alarm_ack{};
  for (int k = 0; k < 64; ++k) {  // bounded: the frames of one wait (the socket's filter lets only DCP and
                                  // alarm frames in, so running devices' cyclic frames cannot fill it)
    const std::size_t n = raw.receive(frame, 0);
    if (n == 0) break;
    const auto in = std::span<const std::uint8_t>(frame.data(), n);
    if (pn::classify_frame_id(pn::peek_frame_id(in)) != pn::FrameKind::kAlarm) continue;
    std::size_t ack_bytes = 0;
    std::size_t alarm_ack_bytes = 0;
    const std::size_t frames = controller.on_alarm(in, ack, alarm_ack, ack_bytes, alarm_ack_bytes, now_us());
    if (controller.rta_error_received() && !timeout.ended) {
      timeout = {true, controller.rta_error_high_priority(), true, controller.last_error().value()};
      return;
    }
    if (frames == 0) continue;
    if (ack_bytes > 0) raw.send(std::span(ack).first(ack_bytes));
    if (alarm_ack_bytes > 0) raw.send(std::span(alarm_ack).first(alarm_ack_bytes));
  }
  for (const bool high : {true, false}) {
    std::size_t bytes = 0;
    const pn::AlarmTimerAction action = controller.alarm_timer(high, now_us(), alarm_ack, bytes);
    if (bytes > 0) raw.send(std::span(alarm_ack).first(bytes));  // a resend, or the ERR-RTA-PDU (I35)
    if (action == pn::AlarmTimerAction::kAbort && !timeout.ended) timeout = {true, high, false, 0};
  }
}

std::vector<std::uint8_t> call(pn::UdpSocket& udp, const pn::Ipv4Address& device,
                               std::span<const std::uint8_t> request, const std::function<void()>& waiting) {
  pn::WireReader request_in(request);
  const pn::RpcHeader asked = pn::decode_rpc(request_in).header;
  std::array<std::uint8_t, 4096> buffer{};
  for (int attempt = 0; attempt < kRpcAttempts; ++attempt) {
    udp.send_to(request, device, pn::kPnioUdpPort);
    for (const auto end = Clock::now() + std::chrono::microseconds(kRpcWaitUs); Clock::now() < end;) {
      pn::Ipv4Address from{};
      std::uint16_t port = 0;
      const std::size_t n = udp.receive(buffer, 20'000, from, port);
      waiting();
      if (n == 0 || from != device) continue;
      pn::WireReader in(std::span<const std::uint8_t>(buffer.data(), n));
      const pn::RpcHeader answer = pn::decode_rpc(in).header;
      if (in.ok() && answer.packet_type != pn::RpcPacketType::kRequest && answer.activity == asked.activity &&
          answer.sequence_number == asked.sequence_number) {
        return {buffer.begin(), buffer.begin() + static_cast<long>(n)};
      }
    }
  }
  return {};
}

}  // namespace

namespace {

// One base-mode parameter request to the object in `slot` (write it to index 0xB02E, read the response).
std::variant<pn::ParameterResponse, std::string> exchange(pn::IoController& controller, pn::UdpSocket& udp,
                                                          std::uint16_t slot,
                                                          const pn::ParameterRequest& request,
                                                          const std::function<void()>& waiting) {
  const pn::Ipv4Address& ip = controller.device().ip.address;
  const auto status = [&] { return "PNIOStatus " + hex(controller.last_error().value()); };
  const auto written =
      call(udp, ip, controller.record_write_request(slot, 1, pn::kParameterAccessIndex, pn::encode(request)),
           waiting);
  if (written.empty()) return std::string("no answer to the parameter request");
  if (!controller.on_record_response(written)) return "parameter request refused, " + status();
  const auto read =
      call(udp, ip, controller.record_read_request(slot, 1, pn::kParameterAccessIndex, 240), waiting);
  if (read.empty()) return std::string("no answer to the parameter read");
  const auto data = controller.on_record_response(read);
  if (!data) return "parameter read refused, " + status();
  auto response = pn::decode_parameter_response(*data);
  // The codec decodes the 16- and 32-bit formats (Integer16/32, Unsigned16/32, FloatingPoint, Word,
  // DoubleWord, Error); a byte-wide value (Unsigned8, Byte, Boolean, ...) fails here too (review of stop 33).
  if (!response) {
    return std::string(
        "the drive's parameter response is malformed or has a format other than the 16- and 32-bit ones "
        "tomc reads (Integer16/32, Unsigned16/32, FloatingPoint, Word, DoubleWord)");
  }
  return std::move(*response);
}

// p0922 and p2000 of the drive object through base-mode parameter access (one request, decision I16).
std::string check_telegram(pn::IoController& controller, pn::UdpSocket& udp, ParameterSteps& steps,
                           const std::function<void()>& waiting) {
  const pn::ParameterRequest request{
      1, pn::parameter_request_id::kRead, 1, {{0x10, 1, 922, 0}, {0x10, 1, 2000, 0}}, {}};
  auto answer = exchange(controller, udp, steps.slot, request, waiting);
  if (auto* problem = std::get_if<std::string>(&answer)) return *problem + " (p0922)";
  const auto& response = std::get<pn::ParameterResponse>(answer);
  const auto telegram = pn::integer_value(response, 0);
  if (!telegram) return "p0922 unreadable in the drive's parameter response";
  if (*telegram != steps.telegram) {
    return "p0922 is " + std::to_string(*telegram) + ": the drive sends telegram " +
           std::to_string(*telegram) + ", the file says " + std::to_string(steps.telegram);
  }
  steps.reference_speed_rpm =
      response.parameters.size() > 1 ? pn::float_value(response, 1).value_or(0.0f) : 0.0f;
  return {};
}

// The file's parameters (decision I33), each changed and read back; the first refusal ends the start-up.
std::string write_parameters(pn::IoController& controller, pn::UdpSocket& udp, ParameterSteps& steps,
                             const std::function<void()>& waiting) {
  std::uint8_t reference = 1;  // the telegram check used 1
  for (const SlotParameterWrite& w : steps.writes) {
    const pn::ParameterExchange to_object = [&](const pn::ParameterRequest& request) {
      return exchange(controller, udp, w.slot, request, waiting);
    };
    if (std::string problem = pn::write_parameter(w.write, 1, reference, to_object); !problem.empty())
      return problem;
    if (w.write.number == 2000 && w.slot == steps.slot && w.write.subindex == 0)
      steps.reference_speed_rpm = static_cast<float>(w.write.value);  // read back equal: the drive's p2000
  }
  return {};
}

}  // namespace

namespace {

std::string start_up_steps(pn::IoController& controller, pn::RawSocket& raw, pn::UdpSocket& udp,
                           std::uint32_t& xid, ParameterSteps* steps, std::span<const std::uint8_t> hello,
                           AlarmTimeout& timeout) {
  const std::string& name = controller.device().name_of_station;
  const pn::Ipv4Address& ip = controller.device().ip.address;
  // What queued while no device was starting is older than this start-up: DCP answers to earlier xids and
  // alarm notifications of ARs that have ended, which the new AR's fresh alarm channels would take for new
  // ones and acknowledge (an AlarmAck the device never expects, so the RTA timer would end the new AR).
  (void)raw.discard_queued(4096);
  std::vector<std::uint8_t> found;
  if (!hello.empty() && pn::dcp_hello_name(hello) == name) {
    found.assign(hello.begin(), hello.end());  // its Hello says where it is: no Identify needed (I36)
  } else {
    const std::uint32_t identify = ++xid;
    raw.send(controller.identify_request(identify));
    found = receive_dcp(raw, identify, &name);
  }
  if (found.empty()) return "no DCP answer to Identify '" + name + "'";
  const std::uint32_t set = ++xid;
  if (const auto set_ip = controller.on_dcp(found, set); !set_ip.empty()) {
    raw.send(set_ip);
    if (receive_dcp(raw, set).empty()) return "DCP Set of the IP suite unanswered by '" + name + "'";
  }
  if (!controller.device_mac()) return "the DCP answer did not name '" + name + "'";
  const auto alarms = [&] { answer_alarms(controller, raw, timeout); };
  const auto connect = call(udp, ip, controller.connect_request(), alarms);
  if (connect.empty()) return "no answer to Connect (UDP 34964)";
  if (!controller.on_connect_response(connect)) {
    return "Connect refused, " + refusal(controller);
  }
  while (controller.state() == pn::ControllerArState::kParameterizing ||
         controller.state() == pn::ControllerArState::kPrmEnd) {
    const auto request = controller.next_request();
    const auto answer = call(udp, ip, request, alarms);
    if (answer.empty()) {
      controller.abort_ar();
      return "no answer to a start-up record or PrmEnd";
    }
    if (!controller.on_response(answer)) {
      controller.abort_ar();
      return "record write or PrmEnd refused, " + refusal(controller);
    }
  }
  // The device's ApplicationReady request comes to our port 34964.
  std::array<std::uint8_t, 2048> ready{};
  for (const auto end = Clock::now() + std::chrono::seconds(1); Clock::now() < end;) {
    pn::Ipv4Address from{};
    std::uint16_t port = 0;
    const std::size_t n = udp.receive(ready, 20'000, from, port);
    alarms();
    if (timeout.ended) break;
    if (n == 0 || from != ip) continue;
    const auto answer = controller.on_application_ready(std::span(ready).first(n));
    if (!answer.empty()) udp.send_to(answer, from, port);
    if (controller.state() != pn::ControllerArState::kRunning) continue;
    if (steps == nullptr) return {};
    std::string problem = steps->check_telegram ? check_telegram(controller, udp, *steps, alarms) : "";
    if (problem.empty()) problem = write_parameters(controller, udp, *steps, alarms);
    if (!problem.empty()) {
      // Not this drive's telegram (or unknown), or a parameter the drive refused: the AR must not carry
      // setpoints of another layout or to a drive set up other than the file says. A module difference of
      // this Connect is named first: a wrong telegram submodule is usually why.
      if (const std::string diff = describe(controller.module_diff()); !diff.empty())
        problem = "module difference: " + diff + "; " + problem;
      (void)call(udp, ip, controller.release_request(), alarms);
      controller.abort_ar();
    }
    return problem;
  }
  controller.abort_ar();
  return "no ApplicationReady from '" + name + "'";
}

}  // namespace

std::string start_up(pn::IoController& controller, pn::RawSocket& raw, pn::UdpSocket& udp, std::uint32_t& xid,
                     ParameterSteps* steps, std::span<const std::uint8_t> hello) {
  AlarmTimeout timeout;
  std::string problem = start_up_steps(controller, raw, udp, xid, steps, hello, timeout);
  // The timer may end the AR in any wait, even one whose step then succeeded (the parameter read): the AR
  // is gone, and that is the reason whatever the later steps said.
  if (!timeout.ended) return problem;
  controller.abort_ar();
  return timeout.device_error ? describe_rta_error(timeout.high_priority, timeout.status)
                              : describe_alarm_timeout(timeout.high_priority, controller.device());
}

std::vector<std::uint8_t> wait_for_hello(pn::RawSocket& raw, const std::vector<std::string>& names,
                                         std::chrono::milliseconds wait) {
  std::array<std::uint8_t, 1518> frame{};
  for (const auto end = Clock::now() + wait; Clock::now() < end;) {
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(end - Clock::now()).count();
    const std::size_t n = raw.receive(frame, static_cast<int>(std::clamp<long long>(left, 0, 20'000)));
    if (n == 0) continue;
    const auto in = std::span<const std::uint8_t>(frame.data(), n);
    const auto name = pn::dcp_hello_name(in);
    if (name && std::find(names.begin(), names.end(), *name) != names.end()) return {in.begin(), in.end()};
  }
  return {};
}

std::string describe_rta_error(bool high_priority, std::uint32_t status) {
  return std::string("RTA ERR from the device (") + (high_priority ? "high" : "low") + "): PNIOStatus " +
         hex(status);
}

std::string describe_alarm_timeout(bool high_priority, const pn::ControllerDeviceConfig& device) {
  // Short: the DDS status carries 127 characters of detail, and the last alarm follows it.
  return std::string("RTA timeout: AlarmAck (") + (high_priority ? "high" : "low") + ") resent " +
         std::to_string(device.rta_retries) + " times every " +
         std::to_string(device.rta_timeout_factor * 100) + " ms";
}

std::string describe(const std::vector<pn::ModuleDiff>& diff) {
  static constexpr const char* kModule[] = {"no module", "wrong module", "proper module", "substitute"};
  static constexpr const char* kSub[] = {"ok", "substitute", "wrong submodule", "no submodule"};
  std::string text;
  for (const pn::ModuleDiff& m : diff) {
    if (m.state != pn::ModuleState::kProperModule) {
      text += (text.empty() ? "" : "; ") + std::string("slot ") + std::to_string(m.slot) + ": " +
              kModule[static_cast<std::size_t>(m.state) & 3] + " (ident " + hex_short(m.ident) + ")";
    }
    for (const pn::SubmoduleDiff& s : m.submodules) {
      if (s.ident_info == pn::SubmoduleIdentInfo::kOk) continue;
      text += (text.empty() ? "" : "; ") + std::string("slot ") + std::to_string(m.slot) + " subslot " +
              std::to_string(s.subslot) + ": " + kSub[static_cast<std::size_t>(s.ident_info) & 3] +
              " (ident " + hex_short(s.ident) + ")";
    }
  }
  return text;
}

}  // namespace tomc::profinet_gateway::detail
