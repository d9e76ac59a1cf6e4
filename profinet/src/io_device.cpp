#include "tomc/profinet/io_device.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <tuple>

namespace tomc::profinet {

namespace {

// PNIOStatus values (IEC 61158-6-10; the names p-net's pnet_api.h uses).
constexpr std::uint8_t kErrorCodeConnect = 0xDB;
constexpr std::uint8_t kErrorCodeControl = 0xDD;
constexpr std::uint8_t kErrorCodeRead = 0xDE;
constexpr std::uint8_t kErrorCodeWrite = 0xDF;
constexpr std::uint8_t kErrorDecodePnioRw = 0x80;
constexpr std::uint8_t kErrorDecodePnio = 0x81;
constexpr std::uint8_t kErrorCode1Cmrpc = 0x40;
constexpr std::uint8_t kErrorCode2NoArResources = 0x04;
constexpr std::uint8_t kErrorCode2ArUuidUnknown = 0x05;
constexpr std::uint8_t kErrorCode2StateConflict = 0x06;
constexpr std::uint8_t kErrorCode2UnknownBlocks = 0x01;
constexpr std::uint8_t kErrorCode1InvalidIndex = 0xB0;

constexpr std::size_t kMaxFrame = 1518;

std::vector<std::uint8_t> take(const WireWriter& out) {
  return {out.written().begin(), out.written().end()};
}

std::uint64_t cycle_us(const IocrBlockRequest& iocr) {
  return std::uint64_t{iocr.send_clock_factor} * iocr.reduction_ratio * 3125 / 100;  // 31.25 us units
}

}  // namespace

IoDevice::IoDevice(DeviceIdentity identity) : identity_(std::move(identity)) {
  // Default record access: writes are kept per (slot, subslot, index) and read back.
  auto records = std::make_shared<
      std::map<std::tuple<std::uint16_t, std::uint16_t, std::uint16_t>, std::vector<std::uint8_t>>>();
  write_handler_ = [records](const RecordHeader& h, std::span<const std::uint8_t> data) {
    (*records)[{h.slot, h.subslot, h.index}].assign(data.begin(), data.end());
    return PnioStatus{};
  };
  read_handler_ = [records](const RecordHeader& h, std::vector<std::uint8_t>& data) {
    const auto found = records->find({h.slot, h.subslot, h.index});
    if (found == records->end())
      return PnioStatus{kErrorCodeRead, kErrorDecodePnioRw, kErrorCode1InvalidIndex, 0};
    data = found->second;
    return PnioStatus{};
  };
}

std::vector<std::uint8_t> IoDevice::on_dcp(std::span<const std::uint8_t> frame) {
  WireReader in(frame);
  const EthernetHeader header = decode_ethernet(in);
  const DcpMessage request = decode_dcp(in);
  if (!in.ok() || request.type != DcpServiceType::kRequest) return {};
  DcpMessage answer;
  answer.service = request.service;
  answer.type = DcpServiceType::kSuccess;
  answer.xid = request.xid;
  if (request.service == DcpService::kIdentify) {
    const DcpDeviceFields& filter = request.fields;
    if ((filter.name_of_station && *filter.name_of_station != identity_.name_of_station) ||
        (filter.vendor_id && *filter.vendor_id != identity_.vendor_id) ||
        (filter.device_id && *filter.device_id != identity_.device_id)) {
      return {};
    }
    answer.frame_id = kFrameIdDcpIdentifyResponse;
    answer.fields.name_of_station = identity_.name_of_station;
    answer.fields.ip = identity_.ip;
    answer.fields.vendor = identity_.vendor;
    answer.fields.vendor_id = identity_.vendor_id;
    answer.fields.device_id = identity_.device_id;
    answer.fields.device_role = 1;  // IO device
    answer.ip_block_info = identity_.ip.address == Ipv4Address{} ? 0 : 1;
  } else if (request.service == DcpService::kSet && header.destination == identity_.mac) {
    answer.frame_id = kFrameIdDcpGetSet;
    if (request.fields.name_of_station) {
      identity_.name_of_station = *request.fields.name_of_station;
      answer.results.push_back({dcp_option::kNameOfStation, 0});
    }
    if (request.fields.ip) {
      identity_.ip = *request.fields.ip;
      answer.results.push_back({dcp_option::kIpParameter, 0});
    }
  } else {
    return {};
  }
  std::vector<std::uint8_t> bytes(kMaxFrame);
  WireWriter out(bytes);
  encode(EthernetHeader{header.source, identity_.mac, std::nullopt}, answer, out);
  return take(out);
}

std::vector<std::uint8_t> IoDevice::hello() const {
  DcpMessage hello;
  hello.frame_id = kFrameIdDcpHello;
  hello.service = DcpService::kHello;
  hello.fields.name_of_station = identity_.name_of_station;
  hello.fields.ip = identity_.ip;
  hello.fields.vendor_id = identity_.vendor_id;
  hello.fields.device_id = identity_.device_id;
  hello.fields.device_initiative = 1;
  std::vector<std::uint8_t> bytes(kMaxFrame);
  WireWriter out(bytes);
  encode(EthernetHeader{kDcpHelloMulticast, identity_.mac, std::nullopt}, hello, out);
  return take(out);
}

std::vector<std::uint8_t> IoDevice::response(const RpcHeader& request, PnioStatus status,
                                             std::span<const std::uint8_t> blocks) const {
  RpcHeader header = request;
  header.packet_type = RpcPacketType::kResponse;
  header.flags1 = rpc_flags::kLastFragment | rpc_flags::kNoFack;
  std::vector<std::uint8_t> bytes(kRpcHeaderBytes + kNdrHeaderBytes + blocks.size());
  WireWriter out(bytes);
  encode_rpc(header, 0, status, blocks, out);
  return take(out);
}

std::vector<std::uint8_t> IoDevice::on_rpc(std::span<const std::uint8_t> payload) {
  WireReader in(payload);
  const RpcPacket packet = decode_rpc(in);
  if (!in.ok() || packet.header.packet_type != RpcPacketType::kRequest ||
      packet.header.interface != kPnioDeviceInterface) {
    return {};
  }
  // A request to another object than this device's instance (another VendorID/DeviceID, or the zeros of a
  // controller that did not read the DCP DeviceID block) is rejected before any PNIO processing, as a DCE/RPC
  // server does for an object it does not export.
  if (packet.header.object != pnio_object_uuid(1, identity_.device_id, identity_.vendor_id)) {
    std::vector<std::uint8_t> bytes(kRpcHeaderBytes + 4);
    WireWriter out(bytes);
    encode_rpc_reject(packet.header, kNcaUnsupportedType, out);
    return take(out);
  }
  switch (static_cast<PnioOperation>(packet.header.opnum)) {
    case PnioOperation::kConnect:
      return answer_connect(packet);
    case PnioOperation::kWrite:
      return answer_record(packet, true);
    case PnioOperation::kRead:
      return answer_record(packet, false);
    case PnioOperation::kControl:
    case PnioOperation::kRelease:
      return answer_control(packet);
  }
  return {};
}

const DeviceSubmodule* IoDevice::real_submodule(std::uint16_t slot, std::uint16_t subslot) const {
  for (const DeviceModule& module : identity_.modules) {
    if (module.slot != slot) continue;
    for (const DeviceSubmodule& sub : module.submodules) {
      if (sub.subslot == subslot) return &sub;
    }
  }
  return nullptr;
}

std::vector<std::uint8_t> IoDevice::answer_connect(const RpcPacket& request) {
  WireReader in(request.blocks);
  ConnectRequest connect = decode_connect_request(in);
  if (!in.ok()) {
    return response(request.header,
                    {kErrorCodeConnect, kErrorDecodePnio, kErrorCode1Cmrpc, kErrorCode2UnknownBlocks}, {});
  }
  if (state_ != ArState::kNone && connect.ar.ar_uuid != connection_.ar.ar_uuid) {
    return response(request.header,
                    {kErrorCodeConnect, kErrorDecodePnio, kErrorCode1Cmrpc, kErrorCode2NoArResources}, {});
  }
  // The difference between the expected and the real configuration (IEC 61158-6-10 ModuleDiffBlock).
  module_diff_.clear();
  for (const ExpectedModule& expected : connect.expected) {
    const auto real = std::find_if(identity_.modules.begin(), identity_.modules.end(),
                                   [&](const DeviceModule& m) { return m.slot == expected.slot; });
    ModuleDiff diff{expected.api, expected.slot, 0, ModuleState::kProperModule, {}};
    if (real == identity_.modules.end()) {
      diff.state = ModuleState::kNoModule;
      module_diff_.push_back(diff);
      continue;
    }
    diff.ident = real->ident;
    if (real->ident != expected.ident) diff.state = ModuleState::kWrongModule;
    for (const ExpectedSubmodule& sub : expected.submodules) {
      const DeviceSubmodule* found = real_submodule(expected.slot, sub.subslot);
      if (found == nullptr) {
        diff.submodules.push_back({sub.subslot, 0, SubmoduleIdentInfo::kNoSubmodule, 0, false});
      } else if (found->ident != sub.ident || found->input_length != sub.input_length ||
                 found->output_length != sub.output_length) {
        diff.submodules.push_back({sub.subslot, found->ident, SubmoduleIdentInfo::kWrong, 0, false});
      }
    }
    if (diff.state != ModuleState::kProperModule || !diff.submodules.empty()) module_diff_.push_back(diff);
  }
  if (!build_cyclic(connect)) {
    return response(request.header,
                    {kErrorCodeConnect, kErrorDecodePnio, kErrorCode1Cmrpc, kErrorCode2UnknownBlocks}, {});
  }
  connection_ = std::move(connect);
  state_ = ArState::kParameterizing;
  output_seen_ = false;

  ConnectResponse answer;
  answer.ar = {connection_.ar.ar_type, connection_.ar.ar_uuid, connection_.ar.session_key, identity_.mac,
               kEtherTypeProfinet};
  for (const IocrBlockRequest& iocr : connection_.iocrs)
    answer.iocrs.push_back({iocr.type, iocr.reference, iocr.frame_id});
  answer.alarm_cr = {connection_.alarm_cr.alarm_cr_type, connection_.alarm_cr.local_alarm_reference,
                     connection_.alarm_cr.max_alarm_data_length};
  answer.module_diff = module_diff_;
  std::vector<std::uint8_t> blocks(4096);
  WireWriter out(blocks);
  encode(answer, out);
  return response(request.header, {}, out.written());
}

bool IoDevice::build_cyclic(const ConnectRequest& request) {
  const auto wrong = [&](std::uint16_t slot, std::uint16_t subslot) {
    for (const ModuleDiff& diff : module_diff_) {
      if (diff.slot != slot) continue;
      if (diff.state != ModuleState::kProperModule) return true;
      for (const SubmoduleDiff& sub : diff.submodules) {
        if (sub.subslot == subslot) return true;
      }
    }
    return false;
  };
  const auto expected_lengths = [&](std::uint16_t slot, std::uint16_t subslot, bool input) -> std::uint16_t {
    for (const ExpectedModule& module : request.expected) {
      if (module.slot != slot) continue;
      for (const ExpectedSubmodule& sub : module.submodules) {
        if (sub.subslot == subslot) return input ? sub.input_length : sub.output_length;
      }
    }
    return 0;
  };
  bool have_input = false;
  bool have_output = false;
  for (const IocrBlockRequest& iocr : request.iocrs) {
    const bool input = iocr.type == IocrType::kInput;
    CyclicLayout layout;
    layout.frame_id = iocr.frame_id;
    layout.c_sdu_length = iocr.c_sdu_length;
    for (const IocrApi& api : iocr.apis) {
      for (const IocrDataReference& ref : api.io_data) {
        if (layout.data_object_count == kMaxDataObjectsPerIocr) return false;
        layout.data_objects[layout.data_object_count++] = {ref.slot, ref.subslot, ref.frame_offset,
                                                           expected_lengths(ref.slot, ref.subslot, input)};
      }
      for (const IocrDataReference& ref : api.iocs) {
        if (layout.iocs_count == kMaxDataObjectsPerIocr) return false;
        layout.iocs[layout.iocs_count++] = {ref.slot, ref.subslot, ref.frame_offset, 0};
      }
    }
    CyclicCodec& codec = input ? input_codec_ : output_codec_;
    if (CyclicCodec::create(layout, codec) != ProfinetError::kNone) return false;
    (input ? have_input : have_output) = true;
    if (input) {
      input_image_.assign(layout.c_sdu_length, 0);
      // IOPS of the device's data and IOCS of the controller's: good unless the submodule is wrong/missing.
      for (std::size_t i = 0; i < layout.data_object_count; ++i) {
        const IoDataObject& object = layout.data_objects[i];
        codec.iops(input_image_, i) = wrong(object.slot, object.subslot) ? kIoxsBad : kIoxsGood;
      }
      for (std::size_t i = 0; i < layout.iocs_count; ++i) {
        codec.iocs(input_image_, i) =
            wrong(layout.iocs[i].slot, layout.iocs[i].subslot) ? kIoxsBad : kIoxsGood;
      }
      cycle_counter_step_ = static_cast<std::uint16_t>(iocr.send_clock_factor * iocr.reduction_ratio);
    } else {
      output_image_.assign(layout.c_sdu_length, 0);
      data_hold_us_ = cycle_us(iocr) * iocr.data_hold_factor;
    }
  }
  return have_input && have_output;
}

std::vector<std::uint8_t> IoDevice::answer_control(const RpcPacket& request) {
  WireReader in(request.blocks);
  const ControlBlock control = decode_control(in);
  const PnioStatus conflict{kErrorCodeControl, kErrorDecodePnio, kErrorCode1Cmrpc, kErrorCode2StateConflict};
  if (!in.ok()) return response(request.header, conflict, {});
  if (state_ == ArState::kNone || control.ar_uuid != connection_.ar.ar_uuid) {
    return response(request.header,
                    {kErrorCodeControl, kErrorDecodePnio, kErrorCode1Cmrpc, kErrorCode2ArUuidUnknown}, {});
  }
  ControlBlock answer = control;
  answer.type = static_cast<std::uint16_t>(control.type | 0x8000);
  answer.command = control_command::kDone;
  if (control.type == block_type::kPrmEndRequest && control.command == control_command::kPrmEnd &&
      state_ == ArState::kParameterizing) {
    state_ = ArState::kApplicationReady;
    application_ready_due_ = true;
  } else if (control.type == block_type::kReleaseRequest && control.command == control_command::kRelease) {
    abort_ar();
  } else {
    return response(request.header, conflict, {});
  }
  std::vector<std::uint8_t> blocks(64);
  WireWriter out(blocks);
  encode(answer, out);
  return response(request.header, {}, out.written());
}

std::vector<std::uint8_t> IoDevice::answer_record(const RpcPacket& request, bool write) {
  WireReader in(request.blocks);
  const RecordAccess record = decode_record(in);
  const std::uint8_t error_code = write ? kErrorCodeWrite : kErrorCodeRead;
  const bool expected_type =
      record.header.type == (write ? block_type::kIodWriteRequest : block_type::kIodReadRequest);
  if (!in.ok() || !expected_type) {
    return response(request.header,
                    {error_code, kErrorDecodePnio, kErrorCode1Cmrpc, kErrorCode2UnknownBlocks}, {});
  }
  if (state_ == ArState::kNone || record.header.ar_uuid != connection_.ar.ar_uuid) {
    return response(request.header,
                    {error_code, kErrorDecodePnio, kErrorCode1Cmrpc, kErrorCode2ArUuidUnknown}, {});
  }
  RecordAccess answer;
  answer.header = record.header;
  answer.header.type = write ? block_type::kIodWriteResponse : block_type::kIodReadResponse;
  PnioStatus status;
  if (write) {
    status = write_handler_(record.header, record.data);
    answer.header.status = status;
  } else {
    status = read_handler_(record.header, answer.data);
    if (answer.data.size() > record.header.record_data_length)
      answer.data.resize(record.header.record_data_length);
    answer.header.record_data_length = static_cast<std::uint32_t>(answer.data.size());
  }
  if (!status.ok()) return response(request.header, status, {});
  std::vector<std::uint8_t> blocks(128 + answer.data.size());
  WireWriter out(blocks);
  encode(answer, out);
  return response(request.header, {}, out.written());
}

std::optional<std::vector<std::uint8_t>> IoDevice::take_application_ready() {
  if (!application_ready_due_) return std::nullopt;
  application_ready_due_ = false;
  state_ = ArState::kRunning;
  RpcHeader header;
  header.object = pnio_object_uuid(1, identity_.device_id, identity_.vendor_id);
  header.interface = kPnioControllerInterface;
  header.activity = connection_.ar.ar_uuid;  // one activity per AR for the device's requests
  header.activity.data1 ^= 0xFFFFFFFF;
  header.sequence_number = application_ready_sequence_++;
  header.opnum = static_cast<std::uint16_t>(PnioOperation::kControl);
  std::vector<std::uint8_t> blocks(64);
  WireWriter block_out(blocks);
  encode(ControlBlock{block_type::kApplicationReadyRequest, connection_.ar.ar_uuid,
                      connection_.ar.session_key, control_command::kApplicationReady, 0},
         block_out);
  std::vector<std::uint8_t> bytes(256);
  WireWriter out(bytes);
  encode_rpc(header, 256, {}, block_out.written(), out);
  return take(out);
}

bool IoDevice::on_cyclic(std::span<const std::uint8_t> frame, std::uint64_t now_us) {
  if (state_ == ArState::kNone) return false;
  ApduStatus status;
  if (output_codec_.decode(frame, output_image_, status) != ProfinetError::kNone) return false;
  output_status_ = status;
  last_output_us_ = now_us;
  output_seen_ = true;
  return true;
}

std::size_t IoDevice::next_input_frame(std::span<std::uint8_t> out) {
  if (state_ == ArState::kNone) return 0;
  input_cycle_counter_ = static_cast<std::uint16_t>(input_cycle_counter_ + cycle_counter_step_);
  ApduStatus status{input_cycle_counter_, data_status::kRunning, 0};
  // Before ApplicationReady the data are not valid yet (IEC 61158-6-10: DataStatus.DataValid).
  if (state_ != ArState::kRunning) status.data_status &= static_cast<std::uint8_t>(~data_status::kDataValid);
  std::size_t written = 0;
  const EthernetHeader header{connection_.ar.initiator_mac, identity_.mac, VlanTag{kPriorityCyclic, 0}};
  if (input_codec_.encode(header, input_image_, status, out, written) != ProfinetError::kNone) return 0;
  return written;
}

std::span<std::uint8_t> IoDevice::input_data(std::uint16_t slot, std::uint16_t subslot) {
  if (state_ == ArState::kNone) return {};
  const CyclicLayout& layout = input_codec_.layout();
  for (std::size_t i = 0; i < layout.data_object_count; ++i) {
    if (layout.data_objects[i].slot == slot && layout.data_objects[i].subslot == subslot) {
      return input_codec_.data(input_image_, i);
    }
  }
  return {};
}

std::uint8_t IoDevice::output_iops(std::uint16_t slot, std::uint16_t subslot) const noexcept {
  if (state_ == ArState::kNone) return kIoxsBad;
  const CyclicLayout& layout = output_codec_.layout();
  for (std::size_t i = 0; i < layout.data_object_count; ++i) {
    if (layout.data_objects[i].slot == slot && layout.data_objects[i].subslot == subslot) {
      return output_codec_.read_iops(output_image_, i);
    }
  }
  return kIoxsBad;
}

std::span<const std::uint8_t> IoDevice::output_data(std::uint16_t slot, std::uint16_t subslot) const {
  if (state_ == ArState::kNone) return {};
  const CyclicLayout& layout = output_codec_.layout();
  for (std::size_t i = 0; i < layout.data_object_count; ++i) {
    if (layout.data_objects[i].slot == slot && layout.data_objects[i].subslot == subslot) {
      return output_codec_.read_data(output_image_, i);
    }
  }
  return {};
}

bool IoDevice::watchdog_expired(std::uint64_t now_us) {
  if (state_ != ArState::kRunning || !output_seen_) return false;
  // `now_us` may come from a clock read before the last frame's: that is no expiry (no unsigned wrap).
  if (now_us <= last_output_us_ + data_hold_us_) return false;
  abort_ar();
  return true;
}

void IoDevice::abort_ar() noexcept {
  state_ = ArState::kNone;
  application_ready_due_ = false;
  output_seen_ = false;
  module_diff_.clear();
}

}  // namespace tomc::profinet
