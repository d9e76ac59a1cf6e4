#pragma once
// The PNIO blocks of connection establishment and record access (IEC 61158-6-10 "Coding of the fields";
// layouts checked against Wireshark's packet-dcerpc-pn-io.c and p-net's pf_block_reader.c/pf_block_writer.c).
// Every block: BlockType, BlockLength (the bytes after this field), BlockVersionHigh 1, BlockVersionLow 0,
// content; always big-endian. Start-up only, never in the cyclic path: vectors and strings are fine here.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tomc/profinet/ethernet.hpp"
#include "tomc/profinet/frame_id.hpp"
#include "tomc/profinet/rpc.hpp"

namespace tomc::profinet {

namespace block_type {
inline constexpr std::uint16_t kAlarmNotificationHigh = 0x0001;
inline constexpr std::uint16_t kAlarmNotificationLow = 0x0002;
inline constexpr std::uint16_t kIodWriteRequest = 0x0008;
inline constexpr std::uint16_t kIodReadRequest = 0x0009;
inline constexpr std::uint16_t kArBlockRequest = 0x0101;
inline constexpr std::uint16_t kIocrBlockRequest = 0x0102;
inline constexpr std::uint16_t kAlarmCrBlockRequest = 0x0103;
inline constexpr std::uint16_t kExpectedSubmoduleBlock = 0x0104;
inline constexpr std::uint16_t kPrmEndRequest = 0x0110;
inline constexpr std::uint16_t kApplicationReadyRequest = 0x0112;
inline constexpr std::uint16_t kReleaseRequest = 0x0114;
inline constexpr std::uint16_t kAlarmAckHigh = 0x8001;
inline constexpr std::uint16_t kAlarmAckLow = 0x8002;
inline constexpr std::uint16_t kIodWriteResponse = 0x8008;
inline constexpr std::uint16_t kIodReadResponse = 0x8009;
inline constexpr std::uint16_t kArBlockResponse = 0x8101;
inline constexpr std::uint16_t kIocrBlockResponse = 0x8102;
inline constexpr std::uint16_t kAlarmCrBlockResponse = 0x8103;
inline constexpr std::uint16_t kModuleDiffBlock = 0x8104;
inline constexpr std::uint16_t kPrmEndResponse = 0x8110;
inline constexpr std::uint16_t kApplicationReadyResponse = 0x8112;
inline constexpr std::uint16_t kReleaseResponse = 0x8114;
}  // namespace block_type

// Limits of what the decoders accept (a drive has a handful of submodules; these bound memory on bad input).
inline constexpr std::size_t kMaxModules = 64;
inline constexpr std::size_t kMaxSubmodulesPerModule = 64;
inline constexpr std::size_t kMaxIocrs = 8;

struct BlockHeader {
  std::uint16_t type = 0;
  std::uint16_t length = 0;  // bytes after the length field, version included
};

// --- Connect ---------------------------------------------------------------------------------------------

namespace ar_properties {
inline constexpr std::uint32_t kStateActive = 0x00000001;
inline constexpr std::uint32_t kParameterizationServerCmInitiator = 0x00000010;
inline constexpr std::uint32_t kStartupModeAdvanced = 0x40000000;
}  // namespace ar_properties

struct ArBlockRequest {
  std::uint16_t ar_type = 0x0001;  // IOCARSingle
  Uuid ar_uuid;
  std::uint16_t session_key = 0;
  MacAddress initiator_mac{};
  Uuid initiator_object_uuid;
  std::uint32_t properties = ar_properties::kStateActive | ar_properties::kParameterizationServerCmInitiator;
  std::uint16_t activity_timeout_factor = 1000;  // x 100 ms
  std::uint16_t udp_rt_port = kEtherTypeProfinet;
  std::string station_name;  // the controller's name of station
  bool operator==(const ArBlockRequest&) const = default;
};

struct ArBlockResponse {
  std::uint16_t ar_type = 0x0001;
  Uuid ar_uuid;
  std::uint16_t session_key = 0;
  MacAddress responder_mac{};
  std::uint16_t udp_rt_port = kEtherTypeProfinet;
  bool operator==(const ArBlockResponse&) const = default;
};

enum class IocrType : std::uint16_t { kInput = 1, kOutput = 2 };

struct IocrDataReference {
  std::uint16_t slot = 0;
  std::uint16_t subslot = 0;
  std::uint16_t frame_offset = 0;
  bool operator==(const IocrDataReference&) const = default;
};

struct IocrApi {
  std::uint32_t api = 0;
  std::vector<IocrDataReference> io_data;  // IODataObjects: data + IOPS at frame_offset
  std::vector<IocrDataReference> iocs;     // consumer status of the other direction's data
  bool operator==(const IocrApi&) const = default;
};

struct IocrBlockRequest {
  IocrType type = IocrType::kInput;
  std::uint16_t reference = 1;
  std::uint16_t lt = kEtherTypeProfinet;
  std::uint32_t properties = kIocrRtClass1;  // bits 0-3 RTClass (frame_id.hpp)
  std::uint16_t c_sdu_length = 40;
  std::uint16_t frame_id =
      kFrameIdRtClass1First;  // output CR: proposed by the controller; input CR: the device's choice
  std::uint16_t send_clock_factor = 32;  // x 31.25 us: 32 = 1 ms
  std::uint16_t reduction_ratio = 1;
  std::uint16_t phase = 1;
  std::uint16_t sequence = 0;
  std::uint32_t frame_send_offset = 0xFFFFFFFF;  // best effort
  std::uint16_t watchdog_factor = 3;
  std::uint16_t data_hold_factor = 3;
  std::uint16_t tag_header = 0xC000;  // VLAN priority 6, VLAN ID 0
  MacAddress multicast_mac{};
  std::vector<IocrApi> apis;
  bool operator==(const IocrBlockRequest&) const = default;
};

struct IocrBlockResponse {
  IocrType type = IocrType::kInput;
  std::uint16_t reference = 1;
  std::uint16_t frame_id = kFrameIdRtClass1First;
  bool operator==(const IocrBlockResponse&) const = default;
};

struct AlarmCrBlockRequest {
  std::uint16_t alarm_cr_type = 1;
  std::uint16_t lt = kEtherTypeProfinet;
  std::uint32_t properties = 0;            // bit 0 priority ignored, bit 1 transport over UDP: both off
  std::uint16_t rta_timeout_factor = 100;  // x 100 ms
  std::uint16_t rta_retries = 3;
  std::uint16_t local_alarm_reference = 1;
  std::uint16_t max_alarm_data_length = 200;
  std::uint16_t tag_header_high = 0xC000;  // priority 6
  std::uint16_t tag_header_low = 0xA000;   // priority 5
  bool operator==(const AlarmCrBlockRequest&) const = default;
};

struct AlarmCrBlockResponse {
  std::uint16_t alarm_cr_type = 1;
  std::uint16_t local_alarm_reference = 1;
  std::uint16_t max_alarm_data_length = 200;
  bool operator==(const AlarmCrBlockResponse&) const = default;
};

enum class SubmoduleDirection : std::uint16_t { kNoIo = 0, kInput = 1, kOutput = 2, kInputOutput = 3 };

struct ExpectedSubmodule {
  std::uint16_t subslot = 1;
  std::uint32_t ident = 0;
  SubmoduleDirection direction = SubmoduleDirection::kNoIo;
  std::uint16_t input_length = 0;   // device -> controller data bytes
  std::uint16_t output_length = 0;  // controller -> device data bytes
  bool operator==(const ExpectedSubmodule&) const = default;
};

struct ExpectedModule {
  std::uint32_t api = 0;
  std::uint16_t slot = 0;
  std::uint32_t ident = 0;
  std::vector<ExpectedSubmodule> submodules;
  bool operator==(const ExpectedModule&) const = default;
};

// ModuleState / SubmoduleState.IdentInfo (IEC 61158-6-10): how the real module differs from the expected one.
enum class ModuleState : std::uint16_t {
  kNoModule = 0,
  kWrongModule = 1,
  kProperModule = 2,
  kSubstitute = 3
};
enum class SubmoduleIdentInfo : std::uint8_t { kOk = 0, kSubstitute = 1, kWrong = 2, kNoSubmodule = 3 };

struct SubmoduleDiff {
  std::uint16_t subslot = 0;
  std::uint32_t ident = 0;  // the real submodule's ident (0 when there is none)
  SubmoduleIdentInfo ident_info = SubmoduleIdentInfo::kOk;
  std::uint8_t ar_info = 0;  // 0 own, 1 ApplicationReadyPending, 2-4 locked
  bool fault = false;
  bool operator==(const SubmoduleDiff&) const = default;
};

struct ModuleDiff {
  std::uint32_t api = 0;
  std::uint16_t slot = 0;
  std::uint32_t ident = 0;  // the real module's ident (0 when there is none)
  ModuleState state = ModuleState::kProperModule;
  std::vector<SubmoduleDiff> submodules;
  bool operator==(const ModuleDiff&) const = default;
};

struct ConnectRequest {
  ArBlockRequest ar;
  std::vector<IocrBlockRequest> iocrs;
  AlarmCrBlockRequest alarm_cr;
  std::vector<ExpectedModule> expected;  // one ExpectedSubmoduleBlockReq per module
  bool operator==(const ConnectRequest&) const = default;
};

struct ConnectResponse {
  ArBlockResponse ar;
  std::vector<IocrBlockResponse> iocrs;
  AlarmCrBlockResponse alarm_cr;
  std::vector<ModuleDiff> module_diff;  // empty: no ModuleDiffBlock, the configuration matches
  bool operator==(const ConnectResponse&) const = default;
};

// --- Control (PrmEnd, ApplicationReady, Release) ---------------------------------------------------------

namespace control_command {
inline constexpr std::uint16_t kPrmEnd = 0x0001;
inline constexpr std::uint16_t kApplicationReady = 0x0002;
inline constexpr std::uint16_t kRelease = 0x0004;
inline constexpr std::uint16_t kDone = 0x0008;
}  // namespace control_command

// IODControlReq/Res and IOXControlReq/Res (block types 0x0110/0x0112/0x0114 and their 0x8000 answers).
struct ControlBlock {
  std::uint16_t type = block_type::kPrmEndRequest;
  Uuid ar_uuid;
  std::uint16_t session_key = 0;
  std::uint16_t command = control_command::kPrmEnd;
  std::uint16_t properties = 0;
  bool operator==(const ControlBlock&) const = default;
};

// --- Record data (IODWriteReq/Res, IODReadReq/Res) -------------------------------------------------------

struct RecordHeader {
  std::uint16_t type = block_type::kIodWriteRequest;
  std::uint16_t sequence_number = 0;
  Uuid ar_uuid;
  std::uint32_t api = 0;
  std::uint16_t slot = 0;
  std::uint16_t subslot = 0;
  std::uint16_t index = 0;
  std::uint32_t record_data_length = 0;
  Uuid target_ar_uuid;                  // read request only
  std::uint16_t additional_value1 = 0;  // responses only
  std::uint16_t additional_value2 = 0;
  PnioStatus status;  // write response only
  bool operator==(const RecordHeader&) const = default;
};

// A record header with its data (the data follow the header block, outside its BlockLength).
struct RecordAccess {
  RecordHeader header;
  std::vector<std::uint8_t> data;
  bool operator==(const RecordAccess&) const = default;
};

// --- Encoders: append one request/response body (the PNIO blocks of the RPC) ----------------------------

void encode(const ConnectRequest& request, WireWriter& out);
void encode(const ConnectResponse& response, WireWriter& out);
void encode(const ControlBlock& block, WireWriter& out) noexcept;
void encode(const RecordAccess& record, WireWriter& out) noexcept;

// --- Decoders: the blocks of one RPC body; unknown block types in a Connect are skipped --------------------

ConnectRequest decode_connect_request(WireReader& in);
ConnectResponse decode_connect_response(WireReader& in);
ControlBlock decode_control(WireReader& in) noexcept;
RecordAccess decode_record(WireReader& in);
BlockHeader decode_block_header(WireReader& in) noexcept;

}  // namespace tomc::profinet
