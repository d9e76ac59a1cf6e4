#include "tomc/profinet/blocks.hpp"

namespace tomc::profinet {

namespace {

constexpr std::size_t kRecordPaddingWriteRequest = 24;
constexpr std::size_t kRecordPaddingWriteResponse = 16;
constexpr std::size_t kRecordPaddingReadRequest = 8;
constexpr std::size_t kRecordPaddingReadResponse = 20;
constexpr std::size_t kMaxRecordData = 65535;

std::size_t begin_block(WireWriter& out, std::uint16_t type) noexcept {
  const std::size_t at = out.position();
  out.u16(type);
  out.u16(0);  // BlockLength, patched by end_block
  out.u8(1);   // BlockVersionHigh
  out.u8(0);   // BlockVersionLow
  return at;
}

void end_block(WireWriter& out, std::size_t at) noexcept {
  out.patch_u16(at + 2, static_cast<std::uint16_t>(out.position() - at - 4));
}

// Reads a block header and returns a reader over its content (after the version bytes); failures of the
// header land in `in`.
WireReader open_block(WireReader& in, BlockHeader& header) noexcept {
  header = decode_block_header(in);
  if (!in.ok()) return WireReader({});
  const auto content = in.view(header.length - 2u);
  return WireReader(content);
}

// Closes a block read through open_block: the content's error, or bytes left over in a block of fixed
// layout, become the error of `in`.
void close_block(WireReader& in, const WireReader& content, bool fixed) noexcept {
  if (!content.ok()) {
    in.fail(content.error() == ProfinetError::kTruncated ? ProfinetError::kBadBlockLength : content.error());
  } else if (fixed && content.remaining() != 0) {
    in.fail(ProfinetError::kBadBlockLength);
  }
}

void put_mac(WireWriter& out, const MacAddress& mac) noexcept {
  out.bytes(mac);
}
MacAddress get_mac(WireReader& in) noexcept {
  MacAddress mac{};
  in.bytes(mac.data(), mac.size());
  return mac;
}

void encode_ar(const ArBlockRequest& ar, WireWriter& out) {
  const std::size_t at = begin_block(out, block_type::kArBlockRequest);
  out.u16(ar.ar_type);
  encode(ar.ar_uuid, out);
  out.u16(ar.session_key);
  put_mac(out, ar.initiator_mac);
  encode(ar.initiator_object_uuid, out);
  out.u32(ar.properties);
  out.u16(ar.activity_timeout_factor);
  out.u16(ar.udp_rt_port);
  out.u16(static_cast<std::uint16_t>(ar.station_name.size()));
  out.text(ar.station_name);
  end_block(out, at);
}

void encode_iocr(const IocrBlockRequest& iocr, WireWriter& out) {
  const std::size_t at = begin_block(out, block_type::kIocrBlockRequest);
  out.u16(static_cast<std::uint16_t>(iocr.type));
  out.u16(iocr.reference);
  out.u16(iocr.lt);
  out.u32(iocr.properties);
  out.u16(iocr.c_sdu_length);
  out.u16(iocr.frame_id);
  out.u16(iocr.send_clock_factor);
  out.u16(iocr.reduction_ratio);
  out.u16(iocr.phase);
  out.u16(iocr.sequence);
  out.u32(iocr.frame_send_offset);
  out.u16(iocr.watchdog_factor);
  out.u16(iocr.data_hold_factor);
  out.u16(iocr.tag_header);
  put_mac(out, iocr.multicast_mac);
  out.u16(static_cast<std::uint16_t>(iocr.apis.size()));
  for (const IocrApi& api : iocr.apis) {
    out.u32(api.api);
    for (const auto* list : {&api.io_data, &api.iocs}) {
      out.u16(static_cast<std::uint16_t>(list->size()));
      for (const IocrDataReference& reference : *list) {
        out.u16(reference.slot);
        out.u16(reference.subslot);
        out.u16(reference.frame_offset);
      }
    }
  }
  end_block(out, at);
}

void encode_alarm_cr(const AlarmCrBlockRequest& alarm, WireWriter& out) {
  const std::size_t at = begin_block(out, block_type::kAlarmCrBlockRequest);
  out.u16(alarm.alarm_cr_type);
  out.u16(alarm.lt);
  out.u32(alarm.properties);
  out.u16(alarm.rta_timeout_factor);
  out.u16(alarm.rta_retries);
  out.u16(alarm.local_alarm_reference);
  out.u16(alarm.max_alarm_data_length);
  out.u16(alarm.tag_header_high);
  out.u16(alarm.tag_header_low);
  end_block(out, at);
}

void put_data_description(WireWriter& out, std::uint16_t direction, std::uint16_t length) {
  out.u16(direction);
  out.u16(length);
  out.u8(1);  // LengthIOCS
  out.u8(1);  // LengthIOPS
}

void encode_expected(const ExpectedModule& module, WireWriter& out) {
  const std::size_t at = begin_block(out, block_type::kExpectedSubmoduleBlock);
  out.u16(1);  // NumberOfAPIs
  out.u32(module.api);
  out.u16(module.slot);
  out.u32(module.ident);
  out.u16(0);  // ModuleProperties
  out.u16(static_cast<std::uint16_t>(module.submodules.size()));
  for (const ExpectedSubmodule& sub : module.submodules) {
    out.u16(sub.subslot);
    out.u32(sub.ident);
    out.u16(static_cast<std::uint16_t>(sub.direction));
    switch (sub.direction) {
      case SubmoduleDirection::kNoIo:
        put_data_description(out, 1, 0);
        break;
      case SubmoduleDirection::kInput:
        put_data_description(out, 1, sub.input_length);
        break;
      case SubmoduleDirection::kOutput:
        put_data_description(out, 2, sub.output_length);
        break;
      case SubmoduleDirection::kInputOutput:
        put_data_description(out, 1, sub.input_length);
        put_data_description(out, 2, sub.output_length);
        break;
    }
  }
  end_block(out, at);
}

ArBlockRequest decode_ar_request(WireReader& in) {
  ArBlockRequest ar;
  ar.ar_type = in.u16();
  ar.ar_uuid = decode_uuid(in);
  ar.session_key = in.u16();
  ar.initiator_mac = get_mac(in);
  ar.initiator_object_uuid = decode_uuid(in);
  ar.properties = in.u32();
  ar.activity_timeout_factor = in.u16();
  ar.udp_rt_port = in.u16();
  const std::uint16_t name_length = in.u16();
  if (name_length > 240) in.fail(ProfinetError::kBadValue);
  const auto name = in.view(name_length);
  ar.station_name.assign(reinterpret_cast<const char*>(name.data()), name.size());
  return ar;
}

IocrBlockRequest decode_iocr_request(WireReader& in) {
  IocrBlockRequest iocr;
  const std::uint16_t type = in.u16();
  if (type != 1 && type != 2) in.fail(ProfinetError::kBadValue);
  iocr.type = static_cast<IocrType>(type);
  iocr.reference = in.u16();
  iocr.lt = in.u16();
  iocr.properties = in.u32();
  iocr.c_sdu_length = in.u16();
  iocr.frame_id = in.u16();
  iocr.send_clock_factor = in.u16();
  iocr.reduction_ratio = in.u16();
  iocr.phase = in.u16();
  iocr.sequence = in.u16();
  iocr.frame_send_offset = in.u32();
  iocr.watchdog_factor = in.u16();
  iocr.data_hold_factor = in.u16();
  iocr.tag_header = in.u16();
  iocr.multicast_mac = get_mac(in);
  const std::uint16_t api_count = in.u16();
  if (api_count > kMaxModules) in.fail(ProfinetError::kTooMany);
  for (std::uint16_t a = 0; a < api_count && in.ok(); ++a) {
    IocrApi api;
    api.api = in.u32();
    for (auto* list : {&api.io_data, &api.iocs}) {
      const std::uint16_t count = in.u16();
      if (count > kMaxModules * kMaxSubmodulesPerModule) in.fail(ProfinetError::kTooMany);
      for (std::uint16_t i = 0; i < count && in.ok(); ++i) {
        IocrDataReference reference;
        reference.slot = in.u16();
        reference.subslot = in.u16();
        reference.frame_offset = in.u16();
        list->push_back(reference);
      }
    }
    iocr.apis.push_back(std::move(api));
  }
  return iocr;
}

AlarmCrBlockRequest decode_alarm_cr_request(WireReader& in) noexcept {
  AlarmCrBlockRequest alarm;
  alarm.alarm_cr_type = in.u16();
  alarm.lt = in.u16();
  alarm.properties = in.u32();
  alarm.rta_timeout_factor = in.u16();
  alarm.rta_retries = in.u16();
  alarm.local_alarm_reference = in.u16();
  alarm.max_alarm_data_length = in.u16();
  alarm.tag_header_high = in.u16();
  alarm.tag_header_low = in.u16();
  return alarm;
}

void read_data_description(WireReader& in, std::uint16_t expected_direction, std::uint16_t& length) {
  const std::uint16_t direction = in.u16();
  length = in.u16();
  const std::uint8_t iocs_length = in.u8();
  const std::uint8_t iops_length = in.u8();
  if (in.ok() && (direction != expected_direction || iocs_length != 1 || iops_length != 1)) {
    in.fail(ProfinetError::kBadValue);
  }
}

void decode_expected(WireReader& in, std::vector<ExpectedModule>& modules) {
  const std::uint16_t api_count = in.u16();
  for (std::uint16_t a = 0; a < api_count && in.ok(); ++a) {
    if (modules.size() >= kMaxModules) return in.fail(ProfinetError::kTooMany);
    ExpectedModule module;
    module.api = in.u32();
    module.slot = in.u16();
    module.ident = in.u32();
    in.skip(2);  // ModuleProperties
    const std::uint16_t sub_count = in.u16();
    if (sub_count > kMaxSubmodulesPerModule) return in.fail(ProfinetError::kTooMany);
    for (std::uint16_t s = 0; s < sub_count && in.ok(); ++s) {
      ExpectedSubmodule sub;
      sub.subslot = in.u16();
      sub.ident = in.u32();
      sub.direction = static_cast<SubmoduleDirection>(in.u16() & 0x3);
      std::uint16_t unused = 0;
      switch (sub.direction) {
        case SubmoduleDirection::kNoIo:
          read_data_description(in, 1, unused);
          break;
        case SubmoduleDirection::kInput:
          read_data_description(in, 1, sub.input_length);
          break;
        case SubmoduleDirection::kOutput:
          read_data_description(in, 2, sub.output_length);
          break;
        case SubmoduleDirection::kInputOutput:
          read_data_description(in, 1, sub.input_length);
          read_data_description(in, 2, sub.output_length);
          break;
      }
      if (sub.direction == SubmoduleDirection::kNoIo && unused != 0) in.fail(ProfinetError::kBadValue);
      module.submodules.push_back(sub);
    }
    modules.push_back(std::move(module));
  }
}

void encode_module_diff(const std::vector<ModuleDiff>& diffs, WireWriter& out) {
  const std::size_t at = begin_block(out, block_type::kModuleDiffBlock);
  // One API entry per module keeps the encoder simple; the decoder accepts any grouping.
  out.u16(static_cast<std::uint16_t>(diffs.size()));
  for (const ModuleDiff& module : diffs) {
    out.u32(module.api);
    out.u16(1);  // NumberOfModules
    out.u16(module.slot);
    out.u32(module.ident);
    out.u16(static_cast<std::uint16_t>(module.state));
    out.u16(static_cast<std::uint16_t>(module.submodules.size()));
    for (const SubmoduleDiff& sub : module.submodules) {
      out.u16(sub.subslot);
      out.u32(sub.ident);
      out.u16(static_cast<std::uint16_t>(0x8000 | (static_cast<unsigned>(sub.ident_info) & 0xF) << 11 |
                                         (sub.ar_info & 0xFu) << 7 | (sub.fault ? 0x40u : 0u)));
    }
  }
  end_block(out, at);
}

void decode_module_diff(WireReader& in, std::vector<ModuleDiff>& diffs) {
  const std::uint16_t api_count = in.u16();
  for (std::uint16_t a = 0; a < api_count && in.ok(); ++a) {
    const std::uint32_t api = in.u32();
    const std::uint16_t module_count = in.u16();
    for (std::uint16_t m = 0; m < module_count && in.ok(); ++m) {
      if (diffs.size() >= kMaxModules) return in.fail(ProfinetError::kTooMany);
      ModuleDiff module;
      module.api = api;
      module.slot = in.u16();
      module.ident = in.u32();
      const std::uint16_t state = in.u16();
      if (state > 3) in.fail(ProfinetError::kBadValue);
      module.state = static_cast<ModuleState>(state);
      const std::uint16_t sub_count = in.u16();
      if (sub_count > kMaxSubmodulesPerModule) return in.fail(ProfinetError::kTooMany);
      for (std::uint16_t s = 0; s < sub_count && in.ok(); ++s) {
        SubmoduleDiff sub;
        sub.subslot = in.u16();
        sub.ident = in.u32();
        const std::uint16_t sub_state = in.u16();
        sub.ident_info = static_cast<SubmoduleIdentInfo>((sub_state >> 11) & 0xF);
        sub.ar_info = static_cast<std::uint8_t>((sub_state >> 7) & 0xF);
        sub.fault = (sub_state & 0x40) != 0;
        module.submodules.push_back(sub);
      }
      diffs.push_back(std::move(module));
    }
  }
}

}  // namespace

BlockHeader decode_block_header(WireReader& in) noexcept {
  BlockHeader header;
  header.type = in.u16();
  header.length = in.u16();
  const std::uint8_t version_high = in.u8();
  in.skip(1);  // BlockVersionLow: 0 or 1 depending on the block; the layouts here do not differ
  if (!in.ok()) return header;
  if (header.length < 2 || header.length - 2u > in.remaining()) {
    in.fail(ProfinetError::kBadBlockLength);
  } else if (version_high != 1) {
    in.fail(ProfinetError::kBadBlockVersion);
  }
  return header;
}

void encode(const ConnectRequest& request, WireWriter& out) {
  encode_ar(request.ar, out);
  for (const IocrBlockRequest& iocr : request.iocrs)
    encode_iocr(iocr, out);
  encode_alarm_cr(request.alarm_cr, out);
  for (const ExpectedModule& module : request.expected)
    encode_expected(module, out);
}

void encode(const ConnectResponse& response, WireWriter& out) {
  std::size_t at = begin_block(out, block_type::kArBlockResponse);
  out.u16(response.ar.ar_type);
  encode(response.ar.ar_uuid, out);
  out.u16(response.ar.session_key);
  put_mac(out, response.ar.responder_mac);
  out.u16(response.ar.udp_rt_port);
  end_block(out, at);
  for (const IocrBlockResponse& iocr : response.iocrs) {
    at = begin_block(out, block_type::kIocrBlockResponse);
    out.u16(static_cast<std::uint16_t>(iocr.type));
    out.u16(iocr.reference);
    out.u16(iocr.frame_id);
    end_block(out, at);
  }
  at = begin_block(out, block_type::kAlarmCrBlockResponse);
  out.u16(response.alarm_cr.alarm_cr_type);
  out.u16(response.alarm_cr.local_alarm_reference);
  out.u16(response.alarm_cr.max_alarm_data_length);
  end_block(out, at);
  if (!response.module_diff.empty()) encode_module_diff(response.module_diff, out);
}

ConnectRequest decode_connect_request(WireReader& in) {
  ConnectRequest request;
  bool have_ar = false;
  bool have_alarm_cr = false;
  while (in.ok() && in.remaining() > 0) {
    BlockHeader header;
    WireReader content = open_block(in, header);
    if (!in.ok()) break;
    switch (header.type) {
      case block_type::kArBlockRequest:
        request.ar = decode_ar_request(content);
        have_ar = true;
        close_block(in, content, true);
        break;
      case block_type::kIocrBlockRequest:
        if (request.iocrs.size() >= kMaxIocrs) return in.fail(ProfinetError::kTooMany), request;
        request.iocrs.push_back(decode_iocr_request(content));
        close_block(in, content, true);
        break;
      case block_type::kAlarmCrBlockRequest:
        request.alarm_cr = decode_alarm_cr_request(content);
        have_alarm_cr = true;
        close_block(in, content, true);
        break;
      case block_type::kExpectedSubmoduleBlock:
        decode_expected(content, request.expected);
        close_block(in, content, true);
        break;
      default:
        break;  // e.g. ARRPCBlockReq, ARVendorBlockReq: not used by this controller
    }
  }
  if (in.ok() && (!have_ar || !have_alarm_cr || request.iocrs.empty()))
    in.fail(ProfinetError::kWrongBlockType);
  return request;
}

ConnectResponse decode_connect_response(WireReader& in) {
  ConnectResponse response;
  bool have_ar = false;
  while (in.ok() && in.remaining() > 0) {
    BlockHeader header;
    WireReader content = open_block(in, header);
    if (!in.ok()) break;
    switch (header.type) {
      case block_type::kArBlockResponse:
        response.ar.ar_type = content.u16();
        response.ar.ar_uuid = decode_uuid(content);
        response.ar.session_key = content.u16();
        response.ar.responder_mac = get_mac(content);
        response.ar.udp_rt_port = content.u16();
        have_ar = true;
        close_block(in, content, true);
        break;
      case block_type::kIocrBlockResponse: {
        if (response.iocrs.size() >= kMaxIocrs) return in.fail(ProfinetError::kTooMany), response;
        IocrBlockResponse iocr;
        const std::uint16_t type = content.u16();
        if (type != 1 && type != 2) content.fail(ProfinetError::kBadValue);
        iocr.type = static_cast<IocrType>(type);
        iocr.reference = content.u16();
        iocr.frame_id = content.u16();
        response.iocrs.push_back(iocr);
        close_block(in, content, true);
        break;
      }
      case block_type::kAlarmCrBlockResponse:
        response.alarm_cr.alarm_cr_type = content.u16();
        response.alarm_cr.local_alarm_reference = content.u16();
        response.alarm_cr.max_alarm_data_length = content.u16();
        close_block(in, content, true);
        break;
      case block_type::kModuleDiffBlock:
        decode_module_diff(content, response.module_diff);
        close_block(in, content, true);
        break;
      default:
        break;  // ARServerBlock, ARRPCBlockRes, ...
    }
  }
  if (in.ok() && !have_ar) in.fail(ProfinetError::kWrongBlockType);
  return response;
}

void encode(const ControlBlock& block, WireWriter& out) noexcept {
  const std::size_t at = begin_block(out, block.type);
  out.u16(0);  // reserved
  encode(block.ar_uuid, out);
  out.u16(block.session_key);
  out.u16(0);  // reserved
  out.u16(block.command);
  out.u16(block.properties);
  end_block(out, at);
}

ControlBlock decode_control(WireReader& in) noexcept {
  ControlBlock block;
  BlockHeader header;
  WireReader content = open_block(in, header);
  if (!in.ok()) return block;
  const std::uint16_t base = header.type & 0x7FFF;
  if (base != block_type::kPrmEndRequest && base != block_type::kApplicationReadyRequest &&
      base != block_type::kReleaseRequest) {
    in.fail(ProfinetError::kWrongBlockType);
    return block;
  }
  block.type = header.type;
  content.skip(2);
  block.ar_uuid = decode_uuid(content);
  block.session_key = content.u16();
  content.skip(2);
  block.command = content.u16();
  block.properties = content.u16();
  close_block(in, content, true);
  return block;
}

void encode(const RecordAccess& record, WireWriter& out) noexcept {
  const RecordHeader& h = record.header;
  const std::size_t at = begin_block(out, h.type);
  out.u16(h.sequence_number);
  encode(h.ar_uuid, out);
  out.u32(h.api);
  out.u16(h.slot);
  out.u16(h.subslot);
  out.u16(0);  // padding
  out.u16(h.index);
  out.u32(h.record_data_length);
  switch (h.type) {
    case block_type::kIodWriteRequest:
      out.zeros(kRecordPaddingWriteRequest);
      break;
    case block_type::kIodReadRequest:
      encode(h.target_ar_uuid, out);
      out.zeros(kRecordPaddingReadRequest);
      break;
    case block_type::kIodWriteResponse:
      out.u16(h.additional_value1);
      out.u16(h.additional_value2);
      out.u32(h.status.value());
      out.zeros(kRecordPaddingWriteResponse);
      break;
    default:  // read response
      out.u16(h.additional_value1);
      out.u16(h.additional_value2);
      out.zeros(kRecordPaddingReadResponse);
      break;
  }
  end_block(out, at);
  out.bytes(record.data);
}

RecordAccess decode_record(WireReader& in) {
  RecordAccess record;
  RecordHeader& h = record.header;
  BlockHeader header;
  WireReader content = open_block(in, header);
  if (!in.ok()) return record;
  if (header.type != block_type::kIodWriteRequest && header.type != block_type::kIodReadRequest &&
      header.type != block_type::kIodWriteResponse && header.type != block_type::kIodReadResponse) {
    in.fail(ProfinetError::kWrongBlockType);
    return record;
  }
  h.type = header.type;
  h.sequence_number = content.u16();
  h.ar_uuid = decode_uuid(content);
  h.api = content.u32();
  h.slot = content.u16();
  h.subslot = content.u16();
  content.skip(2);
  h.index = content.u16();
  h.record_data_length = content.u32();
  switch (h.type) {
    case block_type::kIodWriteRequest:
      content.skip(kRecordPaddingWriteRequest);
      break;
    case block_type::kIodReadRequest:
      h.target_ar_uuid = decode_uuid(content);
      content.skip(kRecordPaddingReadRequest);
      break;
    case block_type::kIodWriteResponse:
      h.additional_value1 = content.u16();
      h.additional_value2 = content.u16();
      h.status = PnioStatus::from(content.u32());
      content.skip(kRecordPaddingWriteResponse);
      break;
    default:
      h.additional_value1 = content.u16();
      h.additional_value2 = content.u16();
      content.skip(kRecordPaddingReadResponse);
      break;
  }
  close_block(in, content, true);
  // Data follow the header in a write request and a read response; the others carry only the length.
  if (in.ok() && (h.type == block_type::kIodWriteRequest || h.type == block_type::kIodReadResponse)) {
    if (h.record_data_length > kMaxRecordData || h.record_data_length > in.remaining()) {
      in.fail(ProfinetError::kTruncated);
      return record;
    }
    const auto data = in.view(h.record_data_length);
    record.data.assign(data.begin(), data.end());
  }
  return record;
}

}  // namespace tomc::profinet
