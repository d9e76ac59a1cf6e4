#pragma once
// Values shared by the profinet tests: a controller and a drive, the Connect of a drive with a DAP and one
// telegram module (IO submodule of 4 bytes each way), a diagnosis alarm of that drive.
#include <algorithm>
#include <array>

#include "tomc/profinet/alarm.hpp"
#include "tomc/profinet/blocks.hpp"

namespace tomc::profinet::testing {

inline constexpr MacAddress kController{0x02, 0, 0, 0, 0, 0x01};
inline constexpr MacAddress kDevice{0x02, 0, 0, 0, 0, 0x02};
inline const Uuid kArUuid{0x11223344, 0x5566, 0x7788, {1, 2, 3, 4, 5, 6, 7, 8}};

inline ConnectRequest drive_connect() {
  ConnectRequest request;
  request.ar.ar_uuid = kArUuid;
  request.ar.session_key = 1;
  request.ar.initiator_mac = kController;
  request.ar.initiator_object_uuid = pnio_object_uuid(1, 0x0C01, 0x002A);
  request.ar.station_name = "tomc-gateway";
  IocrBlockRequest input;
  input.type = IocrType::kInput;
  input.reference = 1;
  input.frame_id = 0x8001;
  input.apis = {{0, {{0, 1, 0}, {1, 2, 1}}, {{1, 2, 6}}}};
  IocrBlockRequest output = input;
  output.type = IocrType::kOutput;
  output.reference = 2;
  output.frame_id = 0x8002;
  output.apis = {{0, {{1, 2, 0}}, {{0, 1, 5}, {1, 2, 6}}}};
  request.iocrs = {input, output};
  request.expected = {{0, 0, 0x00000001, {{1, 0x00000001, SubmoduleDirection::kNoIo, 0, 0}}},
                      {0, 1, 0x00000100, {{2, 0x00000101, SubmoduleDirection::kInputOutput, 4, 4}}}};
  return request;
}

// A PROFIdrive base-mode parameter request (record index 0xB02E) to read p0922 of drive object 1: request
// reference 1, request ID 1 (read), DO 1, one parameter: attribute 0x10 (value), 1 element, p922, index 0.
inline RecordAccess read_p0922_request() {
  RecordAccess write;
  write.header.type = block_type::kIodWriteRequest;
  write.header.sequence_number = 4;
  write.header.ar_uuid = kArUuid;
  write.header.slot = 1;
  write.header.subslot = 1;
  write.header.index = 0xB02E;
  write.data = {0x01, 0x01, 0x01, 0x01, 0x10, 0x01, 0x03, 0x9A, 0x00, 0x00};
  write.header.record_data_length = static_cast<std::uint32_t>(write.data.size());
  return write;
}

// A channel diagnosis of the telegram submodule (slot 1, subslot 2), high priority, sequence number 5.
inline RtaFrame diagnosis_alarm() {
  RtaFrame frame;
  frame.frame_id = kFrameIdAlarmHigh;
  frame.destination_endpoint = 1;
  frame.source_endpoint = 3;
  frame.send_sequence = 0;
  frame.ack_sequence = 0xFFFE;
  frame.has_block = true;
  frame.block.high_priority = true;
  frame.block.alarm_type = alarm_type::kDiagnosis;
  frame.block.slot = 1;
  frame.block.subslot = 2;
  frame.block.module_ident = 0x100;
  frame.block.submodule_ident = 0x101;
  frame.block.specifier = 0x0800 | 0x2000 | 5;     // channel + submodule diagnosis, sequence 5
  frame.block.user_structure_identifier = 0x8000;  // ChannelDiagnosis
  const std::array<std::uint8_t, 6> channel{0x80, 0x00, 0x08, 0x00, 0x00, 0x09};  // channel 0x8000, error 9
  std::copy(channel.begin(), channel.end(), frame.block.payload.begin());
  frame.block.payload_length = channel.size();
  return frame;
}

}  // namespace tomc::profinet::testing
