#pragma once
// The protocol side of a PROFINET IO controller for one device (one AR), without sockets: the gateway puts
// its frames on a raw socket and its RPC packets on UDP port 34964. Start-up in the order of
// IEC 61158-6-10: DCP Identify by name of station (and Set of the IP suite if the device has another one),
// Connect with the expected modules, the start-up record writes one by one, PrmEnd, the device's
// ApplicationReady answered; then cyclic frames each send clock × reduction ratio with the data-hold
// watchdog, alarms acknowledged, Release. Cyclic calls are noexcept and do not allocate.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tomc/profinet/alarm.hpp"
#include "tomc/profinet/blocks.hpp"
#include "tomc/profinet/cyclic.hpp"
#include "tomc/profinet/dcp.hpp"

namespace tomc::profinet {

struct StartupRecord {
  std::uint16_t slot = 0;
  std::uint16_t subslot = 1;
  std::uint16_t index = 0;
  std::vector<std::uint8_t> data;
  std::uint32_t api = 0;  // of the submodule (e.g. 0x3A00 for a PROFIdrive one from a GSDML file)
};

struct ControllerDeviceConfig {
  std::string name_of_station;
  IpSuite ip;
  std::vector<ExpectedModule> modules;  // DAP first
  std::vector<StartupRecord> startup_records;
  std::uint16_t send_clock_factor = 32;  // × 31.25 µs
  std::uint16_t reduction_ratio = 1;
  std::uint16_t watchdog_factor = 3;
  std::uint16_t data_hold_factor = 3;
  std::uint16_t input_frame_id = kFrameIdRtClass1First;  // proposed; the device may change it
  std::uint16_t output_frame_id = kFrameIdRtClass1First + 1;
  // The AlarmCRBlock's RTA timer: our alarm DATA is resent after rta_timeout_factor × 100 ms without the
  // device's acknowledge, at most rta_retries times (IEC 61158-6-10 allows 1..100 and 3..15).
  std::uint16_t rta_timeout_factor = 1;
  std::uint16_t rta_retries = 3;
};

// What the RTA timer of one priority did in this call (IoController::alarm_timer).
enum class AlarmTimerAction : std::uint8_t {
  kNone,    // nothing waits for the device, or its timeout has not run out
  kResend,  // our AlarmAck DATA again, same SendSeqNum (the frame is in the caller's buffer)
  kAbort,   // RTARetries resends stayed unacknowledged: the AR is ended (kOffline, last_error() says why);
            // the caller's buffer holds the ERR-RTA-PDU that tells the device so (decision I35)
};

// The PNIOStatus of an AR this controller ended because the device did not acknowledge our alarm DATA:
// ErrorCode RTA error 0xCF, ErrorDecode PNIO 0x81, ErrorCode1 RTA_ERR_CLS_PROTOCOL 0xFD, ErrorCode2 0x09
// "AR alarm-ack-send.cnf(-)" (IEC 61158-6-10 AR abort reasons; p-net pnet_api.h).
inline constexpr PnioStatus kAlarmAckSendTimeoutStatus{0xCF, 0x81, 0xFD, 0x09};

enum class ControllerArState : std::uint8_t {
  kOffline,         // not found yet / AR lost: Identify again
  kConnecting,      // Connect sent
  kParameterizing,  // writing the start-up records
  kPrmEnd,          // PrmEnd sent
  kWaitApplicationReady,
  kRunning,
};

class IoController {
 public:
  IoController(MacAddress own_mac, std::string own_name, ControllerDeviceConfig device, Uuid ar_uuid);

  ControllerArState state() const noexcept { return state_; }
  const ControllerDeviceConfig& device() const noexcept { return device_; }
  const std::optional<MacAddress>& device_mac() const noexcept { return device_mac_; }
  const std::vector<ModuleDiff>& module_diff() const noexcept { return module_diff_; }
  PnioStatus last_error() const noexcept { return last_error_; }
  // The NCA status of an RPC Reject/Fault answering the last request (0: none), e.g. kNcaUnsupportedType
  // when the device does not know device_object().
  std::uint32_t last_reject() const noexcept { return last_reject_; }
  // The object UUID of the RPC requests: instance 1 with the VendorID/DeviceID of the device's DCP answer.
  const Uuid& device_object() const noexcept { return device_object_; }
  std::uint32_t ar_count() const noexcept { return ar_count_; }

  // --- DCP ---
  std::vector<std::uint8_t> identify_request(std::uint32_t xid) const;
  // An Identify response (or Hello) of this device's name: learns its MAC; returns the Set request of the
  // configured IP suite when the device has another one, else empty.
  std::vector<std::uint8_t> on_dcp(std::span<const std::uint8_t> frame, std::uint32_t xid);

  // --- Connection establishment (RPC payloads) ---
  std::vector<std::uint8_t> connect_request();
  // The Connect response: false (state kOffline, last_error set) on an error status or a missing block.
  // A ModuleDiffBlock is kept in module_diff(); the AR goes on (its submodules' data have bad IOPS).
  bool on_connect_response(std::span<const std::uint8_t> payload);
  // The next start-up record write, or PrmEnd once all are acknowledged; empty while an answer is pending.
  std::vector<std::uint8_t> next_request();
  bool on_response(std::span<const std::uint8_t> payload);
  // The device's ApplicationReady request (to the controller interface): the answer to send back.
  std::vector<std::uint8_t> on_application_ready(std::span<const std::uint8_t> payload);
  std::vector<std::uint8_t> release_request();

  // --- Record access while the AR runs (e.g. PROFIdrive parameter access at start-up) ---
  std::vector<std::uint8_t> record_write_request(std::uint16_t slot, std::uint16_t subslot,
                                                 std::uint16_t index, std::span<const std::uint8_t> data);
  std::vector<std::uint8_t> record_read_request(std::uint16_t slot, std::uint16_t subslot,
                                                std::uint16_t index, std::uint32_t max_length);
  // The answer to one of them: the data read (empty for a write), or nullopt when the device refused
  // (last_error() says why) or the answer is malformed. The AR goes on either way.
  std::optional<std::vector<std::uint8_t>> on_record_response(std::span<const std::uint8_t> payload);

  // --- Cyclic (noexcept, allocation-free) ---
  std::span<std::uint8_t> output_data(std::uint16_t slot, std::uint16_t subslot) noexcept;
  std::span<const std::uint8_t> input_data(std::uint16_t slot, std::uint16_t subslot) const noexcept;
  std::uint8_t input_iops(std::uint16_t slot, std::uint16_t subslot) const noexcept;
  // The provider state (IOPS) of every output data object: false = BAD, the device must not use the data
  // (the gateway's watchdog when its controller went silent, docs/gateway.md G6); true = GOOD (default).
  void set_outputs_valid(bool valid) noexcept;
  // The output frame of this cycle into out (0 before the Connect response).
  std::size_t next_output_frame(std::span<std::uint8_t> out) noexcept;
  // The FrameID of this AR's input frames (the device's choice once the Connect is answered): with several
  // devices on one interface, a received frame is offered only to the AR whose FrameID it carries.
  std::uint16_t input_frame_id() const noexcept { return input_codec_.layout().frame_id; }
  // A received input frame of this AR; false if it is another frame or malformed.
  bool on_input_frame(std::span<const std::uint8_t> frame, std::uint64_t now_us) noexcept;
  // True while the last input frame is valid data (DataValid, provider RUN) and younger than the watchdog.
  bool input_valid(std::uint64_t now_us) const noexcept;
  // The watchdog: no input frame for watchdog factor × cycle ends the AR (kOffline; reconnect from DCP).
  bool watchdog_expired(std::uint64_t now_us) noexcept;
  ApduStatus last_input_status() const noexcept { return input_status_; }

  // --- Alarms (RTA, IEC 61158-6-10; one sequence-number pair per priority, as p-net's APMS/APMR) ---
  // A received alarm frame of this AR's device (from the Connect on, so also during start-up): the frames
  // to send, as bytes in ack_out / alarm_ack_out (0 bytes: nothing to send), and their number.
  // - a new notification: its transport ACK, then the AlarmAck DATA (SendSeqNum 0xFFFF, 0, 1, ... 0x7FFF);
  //   it is kept in last_alarm() and counted in alarms_acknowledged();
  // - the same notification again (same SendSeqNum: the device lost our ACK and resends): the ACK again and,
  //   while the device has not acknowledged it, our AlarmAck again with its SendSeqNum (at most RTARetries
  //   times); neither kept nor counted;
  // - the device's ACK of our AlarmAck (an ACK PDU, or AckSeqNum of its next DATA): 0 frames;
  // - the device's NACK while our AlarmAck waits: the AlarmAck again at once (in alarm_ack_out), within the
  //   RTARetries budget the timer's resends share; 1 frame (none once the budget is used up);
  // - the device's ERR-RTA-PDU: the device has ended the AR; so does this controller (kOffline, last_error()
  //   the ERR's PNIOStatus, rta_error_received() true); 0 frames. Decision I35.
  // now_us (the caller's cycle clock) starts the RTA timer of an AlarmAck sent.
  std::size_t on_alarm(std::span<const std::uint8_t> frame, std::span<std::uint8_t> ack_out,
                       std::span<std::uint8_t> alarm_ack_out, std::size_t& ack_bytes,
                       std::size_t& alarm_ack_bytes, std::uint64_t now_us) noexcept;
  // True while an AlarmAck of ours waits for the device's ACK (high or low priority).
  bool alarm_ack_pending(bool high_priority) const noexcept { return channel(high_priority).unacknowledged; }
  // The RTA timer of one priority (APMS, IEC 61158-6-10; as p-net's pf_alarm_apms_timeout on the device's
  // side), called every cycle with the cycle's clock: while our AlarmAck DATA waits for the device's
  // acknowledge, RTATimeoutFactor × 100 ms after it was last sent it is sent again (kResend, its bytes in out
  // and out_bytes), at most RTARetries times counting the resends of on_alarm; one timeout after the last
  // one, the AR ends (kAbort: kOffline, last_error() kAlarmAckSendTimeoutStatus; the caller sends the
  // ERR-RTA-PDU in out, which names that status to the device, and reconnects). Resends from all causes
  // (timer, repeated notification, NACK) share the RTARetries budget and restart the timeout.
  AlarmTimerAction alarm_timer(bool high_priority, std::uint64_t now_us, std::span<std::uint8_t> out,
                               std::size_t& out_bytes) noexcept;
  std::uint64_t alarm_timeout_us() const noexcept { return alarm_timeout_us_; }
  std::uint16_t alarm_retries() const noexcept { return alarm_retries_; }
  const std::optional<AlarmBlock>& last_alarm() const noexcept { return last_alarm_; }
  // The device ended the AR with an ERR-RTA-PDU (since the last Connect); its priority.
  bool rta_error_received() const noexcept { return rta_error_received_; }
  bool rta_error_high_priority() const noexcept { return rta_error_high_; }
  std::uint32_t alarms_acknowledged() const noexcept { return alarms_acknowledged_; }

  void abort_ar() noexcept;

 private:
  std::vector<std::uint8_t> rpc_request(PnioOperation operation, std::span<const std::uint8_t> blocks);
  // An error status ends the AR, except for record access (a refused record is the device's answer).
  bool check_response(std::span<const std::uint8_t> payload, RpcPacket& packet, bool abort_on_error = true);
  bool build_layouts();

  // One priority's alarm protocol state (APMS sender of our AlarmAcks, APMR receiver of notifications).
  struct AlarmChannel {
    std::uint16_t send_sequence = 0xFFFF;       // SendSeqNum of our next DATA
    std::uint16_t last_sent = 0xFFFE;           // of our last DATA (the SendSeqNum of our ACK PDUs)
    std::optional<std::uint16_t> received;      // SendSeqNum of the last notification taken
    std::array<std::uint8_t, 128> alarm_ack{};  // our last AlarmAck frame, kept for its resends
    std::size_t alarm_ack_bytes = 0;
    bool unacknowledged = false;
    std::uint16_t resends = 0;
    std::uint64_t sent_us = 0;          // when our AlarmAck was last sent: the RTA timer runs from here
    std::uint16_t device_endpoint = 0;  // the device's alarm reference (AlarmDstEndpoint of our PDUs)
    std::uint16_t own_endpoint = 0;
  };
  // Our AlarmAck of this channel again into out (a NACK or a repeated notification): false once the
  // RTARetries budget is used up or out is too small.
  bool resend_alarm_ack(AlarmChannel& apm, std::span<std::uint8_t> out, std::size_t& out_bytes,
                        std::uint64_t now_us) noexcept;
  AlarmChannel& channel(bool high) noexcept { return alarm_channels_[high ? 1 : 0]; }
  const AlarmChannel& channel(bool high) const noexcept { return alarm_channels_[high ? 1 : 0]; }

  MacAddress own_mac_;
  std::string own_name_;
  ControllerDeviceConfig device_;
  Uuid ar_uuid_;
  Uuid activity_;
  std::uint32_t sequence_ = 0;
  std::uint16_t session_key_ = 0;
  ControllerArState state_ = ControllerArState::kOffline;
  std::optional<MacAddress> device_mac_;
  std::vector<ModuleDiff> module_diff_;
  PnioStatus last_error_;
  std::uint32_t last_reject_ = 0;
  Uuid device_object_ = pnio_object_uuid(1, 0, 0);
  std::uint32_t ar_count_ = 0;
  std::size_t next_record_ = 0;
  bool waiting_ = false;
  CyclicCodec output_codec_;
  CyclicCodec input_codec_;
  std::array<std::uint8_t, kMaxCSduLength> output_image_{};
  std::array<std::uint8_t, kMaxCSduLength> input_image_{};
  std::uint16_t output_cycle_counter_ = 0;
  ApduStatus input_status_{0, 0, 0};
  std::uint64_t last_input_us_ = 0;
  bool input_seen_ = false;
  std::uint64_t watchdog_us_ = 3000;
  std::array<AlarmChannel, 2> alarm_channels_{};  // low, high
  std::uint16_t alarm_retries_ = 3;               // RTARetries of our AlarmCRBlockReq
  std::uint64_t alarm_timeout_us_ = 100'000;      // its RTATimeoutFactor × 100 ms
  std::optional<AlarmBlock> last_alarm_;
  std::uint32_t alarms_acknowledged_ = 0;
  bool rta_error_received_ = false;
  bool rta_error_high_ = false;
};

}  // namespace tomc::profinet
