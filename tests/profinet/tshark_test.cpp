// Every frame type the codecs write, checked by Wireshark's own dissectors (tshark, Debian package
// "tshark"): a pcap file with DCP, RT_CLASS_1 cyclic, RTA alarm and DCE/RPC (in IPv4/UDP to port 34964)
// frames must dissect without a malformed packet or an error-level expert item, with the PNIO block types
// named where the codecs put them and every block of a Connect found. Skipped when tshark is not installed
// (scripts/setup installs it).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sample_frames.hpp"
#include "tomc/profinet/alarm.hpp"
#include "tomc/profinet/blocks.hpp"
#include "tomc/profinet/cyclic.hpp"
#include "tomc/profinet/dcp.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/parameter_access.hpp"

namespace pn = tomc::profinet;

namespace {

using pn::testing::kArUuid;
using pn::testing::kController;
using pn::testing::kDevice;
const pn::Uuid kActivity{0xA1A2A3A4, 0xB1B2, 0xC1C2, {1, 1, 1, 1, 1, 1, 1, 1}};

using Frame = std::vector<std::uint8_t>;

void put16(Frame& f, std::size_t at, std::uint16_t v) {
  f[at] = static_cast<std::uint8_t>(v >> 8);
  f[at + 1] = static_cast<std::uint8_t>(v);
}

// Ethernet + IPv4 + UDP around an RPC payload (the controller's kernel does this on the wire).
Frame udp_frame(bool to_device, const Frame& payload) {
  Frame f(14 + 20 + 8);
  std::copy(to_device ? kDevice.begin() : kController.begin(), to_device ? kDevice.end() : kController.end(),
            f.begin());
  std::copy(to_device ? kController.begin() : kDevice.begin(), to_device ? kController.end() : kDevice.end(),
            f.begin() + 6);
  put16(f, 12, 0x0800);
  f[14] = 0x45;
  put16(f, 16, static_cast<std::uint16_t>(20 + 8 + payload.size()));
  f[22] = 64;
  f[23] = 17;
  const std::array<std::uint8_t, 4> controller_ip{10, 0, 0, 1};
  const std::array<std::uint8_t, 4> device_ip{10, 0, 0, 2};
  std::copy(controller_ip.begin(), controller_ip.end(), f.begin() + (to_device ? 26 : 30));
  std::copy(device_ip.begin(), device_ip.end(), f.begin() + (to_device ? 30 : 26));
  std::uint32_t sum = 0;
  for (std::size_t i = 14; i < 34; i += 2)
    sum += static_cast<std::uint32_t>(f[i] << 8 | f[i + 1]);
  while (sum >> 16)
    sum = (sum & 0xFFFF) + (sum >> 16);
  put16(f, 24, static_cast<std::uint16_t>(~sum));
  put16(f, 34, to_device ? 0xC000 : pn::kPnioUdpPort);
  put16(f, 36, to_device ? pn::kPnioUdpPort : 0xC000);
  put16(f, 38, static_cast<std::uint16_t>(8 + payload.size()));
  f.insert(f.end(), payload.begin(), payload.end());
  return f;
}

Frame rpc(bool request, pn::PnioOperation operation, const auto& body) {
  Frame blocks(2048);
  pn::WireWriter block_writer(blocks);
  pn::encode(body, block_writer);
  blocks.resize(block_writer.position());
  pn::RpcHeader header;
  header.packet_type = request ? pn::RpcPacketType::kRequest : pn::RpcPacketType::kResponse;
  header.object = pn::pnio_object_uuid(1, 0x0C01, 0x002A);
  header.interface = pn::kPnioDeviceInterface;
  header.activity = kActivity;
  header.opnum = static_cast<std::uint16_t>(operation);
  Frame payload(4096);
  pn::WireWriter out(payload);
  pn::encode_rpc(header, 4096, {}, blocks, out);
  payload.resize(out.position());
  return udp_frame(request, payload);
}

Frame dcp(const pn::EthernetHeader& header, const pn::DcpMessage& message) {
  Frame f(1514);
  pn::WireWriter out(f);
  pn::encode(header, message, out);
  f.resize(out.position());
  return f;
}

std::vector<Frame> every_frame_type() {
  std::vector<Frame> frames;
  frames.push_back(
      dcp({pn::kDcpIdentifyMulticast, kController, {}}, pn::dcp_identify_request(1, std::nullopt)));
  frames.push_back(dcp({pn::kDcpIdentifyMulticast, kController, {}}, pn::dcp_identify_request(2, "drive-1")));
  pn::DcpMessage identified;
  identified.frame_id = pn::kFrameIdDcpIdentifyResponse;
  identified.type = pn::DcpServiceType::kSuccess;
  identified.xid = 2;
  identified.fields = {"drive-1", pn::IpSuite{{10, 0, 0, 2}, {255, 255, 255, 0}, {}}, "tomc", 0x2A, 0xC01, 1,
                       {}};
  identified.ip_block_info = 1;
  frames.push_back(dcp({kController, kDevice, {}}, identified));
  frames.push_back(
      dcp({kDevice, kController, {}},
          pn::dcp_set_request(3, "drive-1", pn::IpSuite{{10, 0, 0, 2}, {255, 255, 255, 0}, {}}, false)));
  pn::DcpMessage set_answer;
  set_answer.frame_id = pn::kFrameIdDcpGetSet;
  set_answer.service = pn::DcpService::kSet;
  set_answer.type = pn::DcpServiceType::kSuccess;
  set_answer.xid = 3;
  set_answer.results = {{pn::dcp_option::kNameOfStation, 0}, {pn::dcp_option::kIpParameter, 0}};
  frames.push_back(dcp({kController, kDevice, {}}, set_answer));
  pn::DcpMessage hello;
  hello.frame_id = pn::kFrameIdDcpHello;
  hello.service = pn::DcpService::kHello;
  hello.fields.name_of_station = "drive-1";
  hello.fields.ip = pn::IpSuite{{10, 0, 0, 2}, {255, 255, 255, 0}, {}};
  frames.push_back(dcp({pn::kDcpHelloMulticast, kDevice, {}}, hello));

  const pn::ConnectRequest connect = pn::testing::drive_connect();
  frames.push_back(rpc(true, pn::PnioOperation::kConnect, connect));
  pn::ConnectResponse connected;
  connected.ar = {1, kArUuid, 0, kDevice, 0x8892};
  connected.iocrs = {{pn::IocrType::kInput, 1, 0x8001}, {pn::IocrType::kOutput, 2, 0x8002}};
  connected.module_diff = {
      {0, 1, 0x102, pn::ModuleState::kWrongModule, {{2, 0x102, pn::SubmoduleIdentInfo::kWrong, 0, false}}}};
  frames.push_back(rpc(false, pn::PnioOperation::kConnect, connected));

  const pn::RecordAccess write = pn::testing::read_p0922_request();
  frames.push_back(rpc(true, pn::PnioOperation::kWrite, write));
  pn::RecordAccess written = write;
  written.header.type = pn::block_type::kIodWriteResponse;
  written.data.clear();
  frames.push_back(rpc(false, pn::PnioOperation::kWrite, written));
  pn::RecordAccess read = write;
  read.header.type = pn::block_type::kIodReadRequest;
  read.header.record_data_length = 240;
  read.data.clear();
  frames.push_back(rpc(true, pn::PnioOperation::kRead, read));
  pn::RecordAccess read_answer = write;
  read_answer.header.type = pn::block_type::kIodReadResponse;
  frames.push_back(rpc(false, pn::PnioOperation::kRead, read_answer));
  // A PROFIdrive change request (ID 0x02, decision I33): p2000 = 6000.0 as FloatingPoint.
  pn::RecordAccess change = write;
  change.data = pn::encode(pn::ParameterRequest{2,
                                                pn::parameter_request_id::kChange,
                                                1,
                                                {{0x10, 1, 2000, 0}},
                                                {{pn::parameter_format::kFloatingPoint, {0x45BB8000u}}}});
  change.header.record_data_length = static_cast<std::uint32_t>(change.data.size());
  frames.push_back(rpc(true, pn::PnioOperation::kWrite, change));

  for (const auto& [request, response, command] :
       {std::tuple{pn::block_type::kPrmEndRequest, pn::block_type::kPrmEndResponse,
                   pn::control_command::kPrmEnd},
        std::tuple{pn::block_type::kApplicationReadyRequest, pn::block_type::kApplicationReadyResponse,
                   pn::control_command::kApplicationReady},
        std::tuple{pn::block_type::kReleaseRequest, pn::block_type::kReleaseResponse,
                   pn::control_command::kRelease}}) {
    const auto operation = request == pn::block_type::kReleaseRequest ? pn::PnioOperation::kRelease
                                                                      : pn::PnioOperation::kControl;
    frames.push_back(rpc(true, operation, pn::ControlBlock{request, kArUuid, 0, command, 0}));
    frames.push_back(
        rpc(false, operation, pn::ControlBlock{response, kArUuid, 0, pn::control_command::kDone, 0}));
  }

  pn::CyclicLayout layout;
  layout.frame_id = 0x8001;
  layout.data_objects[0] = {0, 1, 0, 0};
  layout.data_objects[1] = {1, 2, 1, 4};
  layout.data_object_count = 2;
  layout.iocs[0] = {1, 2, 6, 0};
  layout.iocs_count = 1;
  pn::CyclicCodec codec;
  EXPECT_EQ(pn::CyclicCodec::create(layout, codec), pn::ProfinetError::kNone);
  std::array<std::uint8_t, 40> c_sdu{};
  c_sdu[0] = c_sdu[5] = c_sdu[6] = pn::kIoxsGood;
  Frame cyclic(128);
  std::size_t size = 0;
  EXPECT_EQ(codec.encode({kController, kDevice, pn::VlanTag{6, 0}}, c_sdu, {32, pn::data_status::kRunning, 0},
                         cyclic, size),
            pn::ProfinetError::kNone);
  cyclic.resize(size);
  frames.push_back(cyclic);

  const pn::RtaFrame alarm = pn::testing::diagnosis_alarm();
  pn::RtaFrame ack;
  ack.frame_id = pn::kFrameIdAlarmHigh;
  ack.destination_endpoint = 3;
  ack.source_endpoint = 1;
  ack.has_block = true;
  ack.block = pn::alarm_ack_for(alarm.block);
  pn::RtaFrame transport;
  transport.frame_id = pn::kFrameIdAlarmHigh;
  transport.pdu_type = pn::RtaPduType::kAck;
  transport.tack = false;
  // The ERR-RTA-PDU that tells the device why the controller ends its AR (decision I35).
  pn::RtaFrame error = transport;
  error.frame_id = pn::kFrameIdAlarmLow;
  error.pdu_type = pn::RtaPduType::kError;
  error.error = pn::kAlarmAckSendTimeoutStatus;
  for (const auto& [rta, to_controller] :
       {std::pair{alarm, true}, {transport, false}, {ack, false}, {error, false}}) {
    Frame f(256);
    EXPECT_EQ(pn::encode({to_controller ? kController : kDevice, to_controller ? kDevice : kController,
                          pn::VlanTag{6, 0}},
                         rta, f, size),
              pn::ProfinetError::kNone);
    f.resize(size);
    frames.push_back(f);
  }
  return frames;
}

void write_pcap(const std::filesystem::path& path, const std::vector<Frame>& frames) {
  std::ofstream out(path, std::ios::binary);
  const auto put32 = [&](std::uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
  const auto put16le = [&](std::uint16_t v) { out.write(reinterpret_cast<const char*>(&v), 2); };
  put32(0xA1B2C3D4);
  put16le(2);
  put16le(4);
  put32(0);
  put32(0);
  put32(65535);
  put32(1);  // LINKTYPE_ETHERNET
  std::uint32_t second = 1;
  for (const Frame& f : frames) {
    put32(second++);
    put32(0);
    put32(static_cast<std::uint32_t>(f.size()));
    put32(static_cast<std::uint32_t>(f.size()));
    out.write(reinterpret_cast<const char*>(f.data()), static_cast<std::streamsize>(f.size()));
  }
}

std::string run(const std::string& command) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return output;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    output.append(buffer.data(), n);
  pclose(pipe);
  return output;
}

}  // namespace

TEST(Tshark, EveryFrameTypeDissectsWithoutMalformedPackets) {
  if (run("command -v tshark").empty()) GTEST_SKIP() << "tshark is not installed (scripts/setup installs it)";
  const auto dir = std::filesystem::temp_directory_path() / ("tomc_profinet_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto pcap = dir / "frames.pcap";
  const auto frames = every_frame_type();
  write_pcap(pcap, frames);
  // -P -V: each frame's summary line, then its full dissection tree (one tshark run: it takes about 1 s).
  const std::string tree = run("tshark -n -P -V -r " + pcap.string() + " 2>&1");
  if (std::getenv("TOMC_KEEP_PCAP") == nullptr) std::filesystem::remove_all(dir);

  ASSERT_NE(tree.find("Frame " + std::to_string(frames.size()) + ":"), std::string::npos)
      << tree.substr(0, 2000);
  EXPECT_EQ(tree.find("Malformed"), std::string::npos) << tree;
  EXPECT_EQ(tree.find("Expert Info (Error"), std::string::npos) << tree;
  // Wireshark only notes a block longer than its packet and goes on; the summary lines below list every
  // block it found, so a wrong length shows as a missing block there.
  EXPECT_EQ(tree.find("greater than remaining"), std::string::npos) << tree;
  EXPECT_NE(tree.find("Connect request, ARBlockReq, IOCRBlockReq, IOCRBlockReq, AlarmCRBlockReq, "
                      "ExpectedSubmoduleBlockReq, ExpectedSubmoduleBlockReq\n"),
            std::string::npos);
  EXPECT_NE(tree.find("Connect response, OK, ARBlockRes, IOCRBlockRes, IOCRBlockRes, AlarmCRBlockRes, "
                      "ModuleDiffBlock\n"),
            std::string::npos);
  EXPECT_NE(
      tree.find("Ident Ok , Xid:0x2, DeviceVendorValue, NameOfStation:\"drive-1\", Dev-ID, Dev-Role, IP\n"),
      std::string::npos);
  EXPECT_NE(tree.find("Set Ok , Xid:0x3, Response(Ok), Response(Ok)\n"), std::string::npos);
  for (const char* expected : {"PROFINET DCP",
                               "ServiceID: Identify",
                               "ServiceID: Set",
                               "ServiceID: Hello",
                               "NameOfStation: drive-1",
                               "ARBlockReq",
                               "IOCRBlockReq",
                               "AlarmCRBlockReq",
                               "ExpectedSubmoduleBlockReq",
                               "ARBlockRes",
                               "IOCRBlockRes",
                               "AlarmCRBlockRes",
                               "ModuleDiffBlock",
                               "IODWriteReqHeader",
                               "IODWriteResHeader",
                               "IODReadReqHeader",
                               "IODReadResHeader",
                               "IODControlReq",
                               "IODControlRes",
                               "IOXBlockReq",
                               "IOXBlockRes",
                               "IODReleaseReq",
                               "IODReleaseRes",
                               "Alarm Notification High",
                               "Alarm Ack High",
                               "ACK-RTA",
                               "ERR-RTA",
                               "ReqId:Change request",
                               "RTC1, ID:0x8001",
                               "CycleCounter: 32",
                               "PROFIDrive Parameter Request: ReqRef:0x01, ReqId:Read request, DO:1",
                               "Parameter: 922"}) {
    EXPECT_NE(tree.find(expected), std::string::npos) << "missing in the dissection: " << expected;
  }
}
