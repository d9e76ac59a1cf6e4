#include "tomc/profinet/io_controller.hpp"

#include <algorithm>

namespace tomc::profinet {

namespace {

std::vector<std::uint8_t> take(const WireWriter& out) {
  return {out.written().begin(), out.written().end()};
}

bool has_input(const ExpectedSubmodule& sub) {
  return sub.direction == SubmoduleDirection::kInput || sub.direction == SubmoduleDirection::kInputOutput;
}
bool has_output(const ExpectedSubmodule& sub) {
  return sub.direction == SubmoduleDirection::kOutput || sub.direction == SubmoduleDirection::kInputOutput;
}

}  // namespace

IoController::IoController(MacAddress own_mac, std::string own_name, ControllerDeviceConfig device,
                           Uuid ar_uuid)
    : own_mac_(own_mac), own_name_(std::move(own_name)), device_(std::move(device)), ar_uuid_(ar_uuid) {
  activity_ = ar_uuid_;
  activity_.data2 ^= 0x5A5A;  // the controller's activity: derived from, but not equal to, the AR UUID
}

std::vector<std::uint8_t> IoController::identify_request(std::uint32_t xid) const {
  std::vector<std::uint8_t> bytes(1514);
  WireWriter out(bytes);
  encode(EthernetHeader{kDcpIdentifyMulticast, own_mac_, std::nullopt},
         dcp_identify_request(xid, device_.name_of_station), out);
  return take(out);
}

std::vector<std::uint8_t> IoController::on_dcp(std::span<const std::uint8_t> frame, std::uint32_t xid) {
  WireReader in(frame);
  const EthernetHeader header = decode_ethernet(in);
  const DcpMessage message = decode_dcp(in);
  const bool answer = message.type == DcpServiceType::kSuccess && message.service == DcpService::kIdentify;
  const bool hello = message.service == DcpService::kHello;
  if (!in.ok() || !(answer || hello) || message.fields.name_of_station != device_.name_of_station) return {};
  device_mac_ = header.source;
  // The RPC object UUID names the device by these (pnio_object_uuid); a device without the DeviceID block
  // keeps the zeros it will then refuse, which the Connect's RPC Reject reports.
  device_object_ =
      pnio_object_uuid(1, message.fields.device_id.value_or(0), message.fields.vendor_id.value_or(0));
  if (message.fields.ip == device_.ip) return {};
  std::vector<std::uint8_t> bytes(1514);
  WireWriter out(bytes);
  encode(EthernetHeader{header.source, own_mac_, std::nullopt},
         dcp_set_request(xid, std::nullopt, device_.ip, false), out);
  return take(out);
}

std::vector<std::uint8_t> IoController::rpc_request(PnioOperation operation,
                                                    std::span<const std::uint8_t> blocks) {
  RpcHeader header;
  header.object = device_object_;
  header.interface = kPnioDeviceInterface;
  header.activity = activity_;
  header.sequence_number = sequence_++;
  header.opnum = static_cast<std::uint16_t>(operation);
  std::vector<std::uint8_t> bytes(kRpcHeaderBytes + kNdrHeaderBytes + blocks.size());
  WireWriter out(bytes);
  encode_rpc(header, 4096, {}, blocks, out);
  waiting_ = true;
  return take(out);
}

std::vector<std::uint8_t> IoController::connect_request() {
  if (!device_mac_) return {};
  ++session_key_;
  ConnectRequest request;
  request.ar.ar_uuid = ar_uuid_;
  request.ar.session_key = session_key_;
  request.ar.initiator_mac = own_mac_;
  // CMInitiatorObjectUUID: the controller's own instance. tomc has no PNO VendorID/DeviceID of its own, so
  // both stay 0; devices check only the DEA00000-6C97-11D1-8271 prefix (p-net pf_cmdev.c).
  request.ar.initiator_object_uuid = pnio_object_uuid(1, 0, 0);
  request.ar.station_name = own_name_;
  IocrBlockRequest input;
  input.type = IocrType::kInput;
  input.reference = 1;
  input.frame_id = device_.input_frame_id;
  IocrBlockRequest output = input;
  output.type = IocrType::kOutput;
  output.reference = 2;
  output.frame_id = device_.output_frame_id;
  // Frame offsets: each CR's data objects (data + IOPS) first, then its IOCS bytes, in module order.
  // Submodules without IO data are IOPS-only objects of the input CR (IEC 61158-6-10).
  std::uint16_t in_offset = 0;
  std::uint16_t out_offset = 0;
  for (auto* iocr : {&input, &output}) {
    for (const ExpectedModule& module : device_.modules) {
      if (iocr->apis.empty() || iocr->apis.back().api != module.api)
        iocr->apis.push_back({module.api, {}, {}});
    }
  }
  const auto api_of = [](IocrBlockRequest& iocr, std::uint32_t api) -> IocrApi& {
    for (IocrApi& entry : iocr.apis) {
      if (entry.api == api) return entry;
    }
    return iocr.apis.front();
  };
  for (const ExpectedModule& module : device_.modules) {
    for (const ExpectedSubmodule& sub : module.submodules) {
      if (has_input(sub) || sub.direction == SubmoduleDirection::kNoIo) {
        api_of(input, module.api).io_data.push_back({module.slot, sub.subslot, in_offset});
        in_offset = static_cast<std::uint16_t>(in_offset + sub.input_length + 1);
      }
      if (has_output(sub)) {
        api_of(output, module.api).io_data.push_back({module.slot, sub.subslot, out_offset});
        out_offset = static_cast<std::uint16_t>(out_offset + sub.output_length + 1);
      }
    }
  }
  for (const ExpectedModule& module : device_.modules) {
    for (const ExpectedSubmodule& sub : module.submodules) {
      if (has_output(sub)) api_of(input, module.api).iocs.push_back({module.slot, sub.subslot, in_offset++});
      if (has_input(sub) || sub.direction == SubmoduleDirection::kNoIo) {
        api_of(output, module.api).iocs.push_back({module.slot, sub.subslot, out_offset++});
      }
    }
  }
  for (auto* iocr : {&input, &output}) {
    const std::uint16_t used = iocr == &input ? in_offset : out_offset;
    iocr->c_sdu_length = std::max(kMinCSduLength, used);
    iocr->send_clock_factor = device_.send_clock_factor;
    iocr->reduction_ratio = device_.reduction_ratio;
    iocr->watchdog_factor = device_.watchdog_factor;
    iocr->data_hold_factor = device_.data_hold_factor;
  }
  request.iocrs = {input, output};
  request.expected = device_.modules;
  // A new AR starts both alarm channels afresh (the device's APMR expects SendSeqNum 0xFFFF first).
  alarm_channels_ = {};
  rta_error_received_ = false;
  request.alarm_cr.rta_timeout_factor = device_.rta_timeout_factor;
  request.alarm_cr.rta_retries = device_.rta_retries;
  alarm_retries_ = device_.rta_retries;
  alarm_timeout_us_ = std::uint64_t{device_.rta_timeout_factor} * 100'000;
  std::vector<std::uint8_t> blocks(8192);
  WireWriter out(blocks);
  encode(request, out);
  if (!out.ok()) return {};
  // The controller's own layouts from the same offsets.
  const auto to_layout = [&](const IocrBlockRequest& iocr, bool is_input) {
    CyclicLayout layout;
    layout.frame_id = iocr.frame_id;
    layout.c_sdu_length = iocr.c_sdu_length;
    for (const IocrApi& api : iocr.apis) {
      for (const IocrDataReference& ref : api.io_data) {
        std::uint16_t length = 0;
        for (const ExpectedModule& module : device_.modules) {
          for (const ExpectedSubmodule& sub : module.submodules) {
            if (module.slot == ref.slot && sub.subslot == ref.subslot) {
              length = is_input ? sub.input_length : sub.output_length;
            }
          }
        }
        if (layout.data_object_count < kMaxDataObjectsPerIocr) {
          layout.data_objects[layout.data_object_count++] = {ref.slot, ref.subslot, ref.frame_offset, length};
        }
      }
      for (const IocrDataReference& ref : api.iocs) {
        if (layout.iocs_count < kMaxDataObjectsPerIocr) {
          layout.iocs[layout.iocs_count++] = {ref.slot, ref.subslot, ref.frame_offset, 0};
        }
      }
    }
    return layout;
  };
  if (CyclicCodec::create(to_layout(input, true), input_codec_) != ProfinetError::kNone ||
      CyclicCodec::create(to_layout(output, false), output_codec_) != ProfinetError::kNone) {
    return {};
  }
  output_image_.fill(0);
  input_image_.fill(0);
  // Our provider and consumer states: good.
  for (std::size_t i = 0; i < output_codec_.layout().data_object_count; ++i) {
    output_codec_.iops(output_image_, i) = kIoxsGood;
  }
  for (std::size_t i = 0; i < output_codec_.layout().iocs_count; ++i)
    output_codec_.iocs(output_image_, i) = kIoxsGood;
  watchdog_us_ = std::uint64_t{device_.send_clock_factor} * device_.reduction_ratio *
                 device_.watchdog_factor * 3125 / 100;
  input_seen_ = false;
  module_diff_.clear();
  state_ = ControllerArState::kConnecting;
  return rpc_request(PnioOperation::kConnect, out.written());
}

bool IoController::check_response(std::span<const std::uint8_t> payload, RpcPacket& packet,
                                  bool abort_on_error) {
  WireReader in(payload);
  packet = decode_rpc(in);
  const RpcPacketType type = packet.header.packet_type;
  const bool refusal = type == RpcPacketType::kReject || type == RpcPacketType::kFault;
  if (!in.ok() || (type != RpcPacketType::kResponse && !refusal) || packet.header.activity != activity_ ||
      packet.header.sequence_number + 1 != sequence_) {
    return false;  // not the answer to our last request
  }
  waiting_ = false;
  last_reject_ = refusal ? packet.reject_status : 0;
  if (refusal) {
    last_error_ = {};
    if (abort_on_error) abort_ar();
    return false;
  }
  if (!packet.status.ok()) {
    last_error_ = packet.status;
    if (abort_on_error) abort_ar();
    return false;
  }
  return true;
}

bool IoController::on_connect_response(std::span<const std::uint8_t> payload) {
  RpcPacket packet;
  if (state_ != ControllerArState::kConnecting || !check_response(payload, packet)) return false;
  WireReader in(packet.blocks);
  const ConnectResponse response = decode_connect_response(in);
  if (!in.ok() || response.ar.ar_uuid != ar_uuid_ || response.iocrs.size() != 2) {
    last_error_ = {0xDB, 0x81, 0x40, 0x01};
    abort_ar();
    return false;
  }
  module_diff_ = response.module_diff;
  // The device may assign other FrameIDs than proposed: take them over.
  for (const IocrBlockResponse& iocr : response.iocrs) {
    CyclicCodec& codec = iocr.type == IocrType::kInput ? input_codec_ : output_codec_;
    if (codec.layout().frame_id != iocr.frame_id) {
      CyclicLayout layout = codec.layout();
      layout.frame_id = iocr.frame_id;
      if (CyclicCodec::create(layout, codec) != ProfinetError::kNone) {
        abort_ar();
        return false;
      }
    }
  }
  next_record_ = 0;
  state_ = ControllerArState::kParameterizing;
  ++ar_count_;
  return true;
}

std::vector<std::uint8_t> IoController::next_request() {
  if (waiting_ || state_ != ControllerArState::kParameterizing) return {};
  std::vector<std::uint8_t> blocks(8192);
  WireWriter out(blocks);
  if (next_record_ < device_.startup_records.size()) {
    const StartupRecord& record = device_.startup_records[next_record_];
    RecordAccess write;
    write.header.type = block_type::kIodWriteRequest;
    write.header.sequence_number = static_cast<std::uint16_t>(next_record_);
    write.header.ar_uuid = ar_uuid_;
    write.header.api = record.api;
    write.header.slot = record.slot;
    write.header.subslot = record.subslot;
    write.header.index = record.index;
    write.header.record_data_length = static_cast<std::uint32_t>(record.data.size());
    write.data = record.data;
    encode(write, out);
    return rpc_request(PnioOperation::kWrite, out.written());
  }
  encode(ControlBlock{block_type::kPrmEndRequest, ar_uuid_, session_key_, control_command::kPrmEnd, 0}, out);
  state_ = ControllerArState::kPrmEnd;
  return rpc_request(PnioOperation::kControl, out.written());
}

bool IoController::on_response(std::span<const std::uint8_t> payload) {
  RpcPacket packet;
  if (!check_response(payload, packet)) return false;
  WireReader in(packet.blocks);
  if (state_ == ControllerArState::kParameterizing) {
    const RecordAccess answer = decode_record(in);
    if (!in.ok() || answer.header.type != block_type::kIodWriteResponse || !answer.header.status.ok()) {
      last_error_ = answer.header.status;
      abort_ar();
      return false;
    }
    ++next_record_;
    return true;
  }
  if (state_ == ControllerArState::kPrmEnd) {
    const ControlBlock done = decode_control(in);
    if (!in.ok() || done.type != block_type::kPrmEndResponse || done.command != control_command::kDone) {
      abort_ar();
      return false;
    }
    state_ = ControllerArState::kWaitApplicationReady;
    return true;
  }
  return true;  // Release: nothing to keep
}

std::vector<std::uint8_t> IoController::record_write_request(std::uint16_t slot, std::uint16_t subslot,
                                                             std::uint16_t index,
                                                             std::span<const std::uint8_t> data) {
  RecordAccess write;
  write.header.type = block_type::kIodWriteRequest;
  write.header.sequence_number = static_cast<std::uint16_t>(sequence_);
  write.header.ar_uuid = ar_uuid_;
  write.header.slot = slot;
  write.header.subslot = subslot;
  write.header.index = index;
  write.header.record_data_length = static_cast<std::uint32_t>(data.size());
  write.data.assign(data.begin(), data.end());
  std::vector<std::uint8_t> blocks(128 + data.size());
  WireWriter out(blocks);
  encode(write, out);
  return rpc_request(PnioOperation::kWrite, out.written());
}

std::vector<std::uint8_t> IoController::record_read_request(std::uint16_t slot, std::uint16_t subslot,
                                                            std::uint16_t index, std::uint32_t max_length) {
  RecordAccess read;
  read.header.type = block_type::kIodReadRequest;
  read.header.sequence_number = static_cast<std::uint16_t>(sequence_);
  read.header.ar_uuid = ar_uuid_;
  read.header.slot = slot;
  read.header.subslot = subslot;
  read.header.index = index;
  read.header.record_data_length = max_length;
  std::vector<std::uint8_t> blocks(128);
  WireWriter out(blocks);
  encode(read, out);
  return rpc_request(PnioOperation::kRead, out.written());
}

std::optional<std::vector<std::uint8_t>> IoController::on_record_response(
    std::span<const std::uint8_t> payload) {
  RpcPacket packet;
  if (!check_response(payload, packet, false)) return std::nullopt;
  WireReader in(packet.blocks);
  RecordAccess answer = decode_record(in);
  const bool type_ok = answer.header.type == block_type::kIodWriteResponse ||
                       answer.header.type == block_type::kIodReadResponse;
  if (!in.ok() || !type_ok || !answer.header.status.ok()) {
    last_error_ = answer.header.status;
    return std::nullopt;
  }
  return std::move(answer.data);
}

std::vector<std::uint8_t> IoController::on_application_ready(std::span<const std::uint8_t> payload) {
  WireReader in(payload);
  const RpcPacket packet = decode_rpc(in);
  if (!in.ok() || packet.header.packet_type != RpcPacketType::kRequest ||
      packet.header.interface != kPnioControllerInterface) {
    return {};
  }
  WireReader blocks(packet.blocks);
  const ControlBlock ready = decode_control(blocks);
  PnioStatus status;
  if (!blocks.ok() || ready.type != block_type::kApplicationReadyRequest || ready.ar_uuid != ar_uuid_ ||
      state_ != ControllerArState::kWaitApplicationReady) {
    status = {0xDD, 0x81, 0x40, 0x06};  // Control: state conflict
  } else {
    state_ = ControllerArState::kRunning;
  }
  RpcHeader header = packet.header;
  header.packet_type = RpcPacketType::kResponse;
  header.flags1 = rpc_flags::kLastFragment | rpc_flags::kNoFack;
  std::vector<std::uint8_t> answer_blocks(64);
  WireWriter block_out(answer_blocks);
  if (status.ok()) {
    encode(ControlBlock{block_type::kApplicationReadyResponse, ar_uuid_, ready.session_key,
                        control_command::kDone, 0},
           block_out);
  }
  std::vector<std::uint8_t> bytes(256);
  WireWriter out(bytes);
  encode_rpc(header, 0, status, block_out.written(), out);
  return take(out);
}

std::vector<std::uint8_t> IoController::release_request() {
  if (state_ == ControllerArState::kOffline) return {};
  std::vector<std::uint8_t> blocks(64);
  WireWriter out(blocks);
  encode(ControlBlock{block_type::kReleaseRequest, ar_uuid_, session_key_, control_command::kRelease, 0},
         out);
  abort_ar();
  return rpc_request(PnioOperation::kRelease, out.written());
}

std::span<std::uint8_t> IoController::output_data(std::uint16_t slot, std::uint16_t subslot) noexcept {
  const CyclicLayout& layout = output_codec_.layout();
  for (std::size_t i = 0; i < layout.data_object_count; ++i) {
    if (layout.data_objects[i].slot == slot && layout.data_objects[i].subslot == subslot) {
      return output_codec_.data(std::span(output_image_).first(layout.c_sdu_length), i);
    }
  }
  return {};
}

std::span<const std::uint8_t> IoController::input_data(std::uint16_t slot,
                                                       std::uint16_t subslot) const noexcept {
  const CyclicLayout& layout = input_codec_.layout();
  for (std::size_t i = 0; i < layout.data_object_count; ++i) {
    if (layout.data_objects[i].slot == slot && layout.data_objects[i].subslot == subslot) {
      return input_codec_.read_data(std::span(input_image_).first(layout.c_sdu_length), i);
    }
  }
  return {};
}

std::uint8_t IoController::input_iops(std::uint16_t slot, std::uint16_t subslot) const noexcept {
  const CyclicLayout& layout = input_codec_.layout();
  for (std::size_t i = 0; i < layout.data_object_count; ++i) {
    if (layout.data_objects[i].slot == slot && layout.data_objects[i].subslot == subslot) {
      return input_codec_.read_iops(std::span(input_image_).first(layout.c_sdu_length), i);
    }
  }
  return kIoxsBad;
}

void IoController::set_outputs_valid(bool valid) noexcept {
  const std::size_t count = output_codec_.layout().data_object_count;
  for (std::size_t i = 0; i < count; ++i)
    output_codec_.iops(output_image_, i) = valid ? kIoxsGood : kIoxsBad;
}

std::size_t IoController::next_output_frame(std::span<std::uint8_t> out) noexcept {
  if (state_ == ControllerArState::kOffline || state_ == ControllerArState::kConnecting || !device_mac_)
    return 0;
  output_cycle_counter_ =
      static_cast<std::uint16_t>(output_cycle_counter_ + device_.send_clock_factor * device_.reduction_ratio);
  ApduStatus status{output_cycle_counter_, data_status::kRunning, 0};
  if (state_ != ControllerArState::kRunning)
    status.data_status &= static_cast<std::uint8_t>(~data_status::kDataValid);
  std::size_t written = 0;
  const EthernetHeader header{*device_mac_, own_mac_, VlanTag{kPriorityCyclic, 0}};
  if (output_codec_.encode(header, std::span(output_image_).first(output_codec_.layout().c_sdu_length),
                           status, out, written) != ProfinetError::kNone) {
    return 0;
  }
  return written;
}

bool IoController::on_input_frame(std::span<const std::uint8_t> frame, std::uint64_t now_us) noexcept {
  if (state_ == ControllerArState::kOffline || state_ == ControllerArState::kConnecting) return false;
  ApduStatus status;
  if (input_codec_.decode(frame, std::span(input_image_).first(input_codec_.layout().c_sdu_length), status) !=
      ProfinetError::kNone) {
    return false;
  }
  input_status_ = status;
  last_input_us_ = now_us;
  input_seen_ = true;
  return true;
}

bool IoController::input_valid(std::uint64_t now_us) const noexcept {
  constexpr std::uint8_t kValid = data_status::kDataValid | data_status::kProviderRun;
  return state_ == ControllerArState::kRunning && input_seen_ && now_us <= last_input_us_ + watchdog_us_ &&
         (input_status_.data_status & kValid) == kValid;
}

bool IoController::watchdog_expired(std::uint64_t now_us) noexcept {
  if (state_ != ControllerArState::kRunning || !input_seen_ || now_us <= last_input_us_ + watchdog_us_)
    return false;
  abort_ar();
  return true;
}

std::size_t IoController::on_alarm(std::span<const std::uint8_t> frame, std::span<std::uint8_t> ack_out,
                                   std::span<std::uint8_t> alarm_ack_out, std::size_t& ack_bytes,
                                   std::size_t& alarm_ack_bytes, std::uint64_t now_us) noexcept {
  ack_bytes = alarm_ack_bytes = 0;
  RtaFrame received;
  if (!device_mac_ || state_ == ControllerArState::kOffline ||
      decode_rta(frame, received) != ProfinetError::kNone)
    return 0;
  // Only this AR's device: with several devices on one interface, each alarm is its sender's.
  if (frame.size() < 12 || !std::equal(device_mac_->begin(), device_mac_->end(), frame.begin() + 6)) return 0;
  const bool high = received.frame_id == kFrameIdAlarmHigh;
  AlarmChannel& apm = channel(high);
  if (received.pdu_type == RtaPduType::kError) {
    // The device ends the AR (IEC 61158-6-10 RTA-ERR-PDU): so do we, with its reason (decision I35).
    abort_ar();
    last_error_ = received.error;
    rta_error_received_ = true;
    rta_error_high_ = high;
    return 0;
  }
  if (received.pdu_type == RtaPduType::kNack) {
    // The device could not take our DATA (out of sequence, no resources): our AlarmAck again at once, from
    // the same RTARetries budget as the timer's resends (decision I35). A NACK acknowledges nothing.
    if (!apm.unacknowledged || !resend_alarm_ack(apm, alarm_ack_out, alarm_ack_bytes, now_us)) return 0;
    return 1;
  }
  // Any other PDU of the device acknowledges our AlarmAck when its AckSeqNum names it.
  if (apm.unacknowledged && received.ack_sequence == apm.last_sent) apm.unacknowledged = false;
  if (received.pdu_type != RtaPduType::kData || !received.has_block || received.block.is_ack) return 0;
  const bool repeated = apm.received == received.send_sequence;
  const EthernetHeader header{*device_mac_, own_mac_,
                              VlanTag{high ? kPriorityAlarmHigh : kPriorityAlarmLow, 0}};
  RtaFrame transport;
  transport.frame_id = received.frame_id;
  transport.destination_endpoint = received.source_endpoint;
  transport.source_endpoint = received.destination_endpoint;
  transport.pdu_type = RtaPduType::kAck;
  transport.tack = false;
  transport.send_sequence = apm.last_sent;
  transport.ack_sequence = received.send_sequence;
  if (encode(header, transport, ack_out, ack_bytes) != ProfinetError::kNone) return 0;
  if (repeated) {
    // A resend of the notification: our ACK was lost. Our AlarmAck goes again, with its SendSeqNum, until
    // the device acknowledges it or RTARetries resends are used up.
    if (!apm.unacknowledged || !resend_alarm_ack(apm, alarm_ack_out, alarm_ack_bytes, now_us)) return 1;
    return 2;
  }
  RtaFrame ack = transport;
  ack.pdu_type = RtaPduType::kData;
  ack.tack = true;
  ack.send_sequence = apm.send_sequence;
  ack.has_block = true;
  ack.block = alarm_ack_for(received.block);
  if (encode(header, ack, apm.alarm_ack, apm.alarm_ack_bytes) != ProfinetError::kNone ||
      alarm_ack_out.size() < apm.alarm_ack_bytes) {
    ack_bytes = 0;
    return 0;
  }
  std::copy_n(apm.alarm_ack.begin(), apm.alarm_ack_bytes, alarm_ack_out.begin());
  alarm_ack_bytes = apm.alarm_ack_bytes;
  apm.last_sent = apm.send_sequence;
  apm.send_sequence = static_cast<std::uint16_t>((apm.send_sequence + 1) & 0x7FFF);  // 0xFFFF, 0 .. 0x7FFF
  apm.received = received.send_sequence;
  apm.device_endpoint = received.source_endpoint;
  apm.own_endpoint = received.destination_endpoint;
  apm.unacknowledged = true;
  apm.resends = 0;
  apm.sent_us = now_us;
  last_alarm_ = received.block;
  ++alarms_acknowledged_;
  return 2;
}

AlarmTimerAction IoController::alarm_timer(bool high_priority, std::uint64_t now_us,
                                           std::span<std::uint8_t> out, std::size_t& out_bytes) noexcept {
  out_bytes = 0;
  AlarmChannel& apm = channel(high_priority);
  // Added, not subtracted: a time taken just before the AlarmAck was sent (another thread's clock
  // reading) is earlier than sent_us and must not wrap into an expired timeout.
  if (state_ == ControllerArState::kOffline || !apm.unacknowledged ||
      now_us < apm.sent_us + alarm_timeout_us_)
    return AlarmTimerAction::kNone;
  if (apm.resends >= alarm_retries_) {
    // The ERR-RTA-PDU first (decision I35): the device learns why at once rather than by its data hold.
    RtaFrame error;
    error.frame_id = high_priority ? kFrameIdAlarmHigh : kFrameIdAlarmLow;
    error.destination_endpoint = apm.device_endpoint;
    error.source_endpoint = apm.own_endpoint;
    error.pdu_type = RtaPduType::kError;
    error.tack = false;
    error.send_sequence = apm.last_sent;
    error.ack_sequence = apm.received.value_or(0xFFFE);
    error.error = kAlarmAckSendTimeoutStatus;
    if (device_mac_) {
      const EthernetHeader header{*device_mac_, own_mac_,
                                  VlanTag{high_priority ? kPriorityAlarmHigh : kPriorityAlarmLow, 0}};
      if (encode(header, error, out, out_bytes) != ProfinetError::kNone) out_bytes = 0;
    }
    abort_ar();
    last_error_ = kAlarmAckSendTimeoutStatus;
    return AlarmTimerAction::kAbort;
  }
  if (!resend_alarm_ack(apm, out, out_bytes, now_us)) return AlarmTimerAction::kNone;
  return AlarmTimerAction::kResend;
}

bool IoController::resend_alarm_ack(AlarmChannel& apm, std::span<std::uint8_t> out, std::size_t& out_bytes,
                                    std::uint64_t now_us) noexcept {
  if (apm.resends >= alarm_retries_ || out.size() < apm.alarm_ack_bytes) return false;
  ++apm.resends;
  apm.sent_us = now_us;
  std::copy_n(apm.alarm_ack.begin(), apm.alarm_ack_bytes, out.begin());
  out_bytes = apm.alarm_ack_bytes;
  return true;
}

void IoController::abort_ar() noexcept {
  state_ = ControllerArState::kOffline;
  waiting_ = false;
  input_seen_ = false;
}

}  // namespace tomc::profinet
