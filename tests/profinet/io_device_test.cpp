// The IO device's protocol side (IoDevice) driven by a controller made of the codecs: DCP naming, Connect
// with and without a module difference, record write/read, PrmEnd, ApplicationReady, cyclic exchange,
// watchdog, Release, and the PNIOStatus of requests out of place (IEC 61158-6-10).
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "sample_frames.hpp"
#include "tomc/profinet/io_device.hpp"

namespace pn = tomc::profinet;
using pn::testing::kArUuid;
using pn::testing::kController;
using pn::testing::kDevice;

namespace {

pn::DeviceIdentity drive_identity(std::uint32_t telegram_module_ident = 0x100) {
  pn::DeviceIdentity identity;
  identity.name_of_station = "";
  identity.mac = kDevice;
  identity.vendor_id = 0x002A;
  identity.device_id = 0x0C01;
  identity.vendor = "tomc emulated drive";
  identity.modules = {{0, 0x1, {{1, 0x1, pn::SubmoduleDirection::kNoIo, 0, 0}}},
                      {1, telegram_module_ident, {{2, 0x101, pn::SubmoduleDirection::kInputOutput, 4, 4}}}};
  return identity;
}

std::vector<std::uint8_t> dcp(const pn::DcpMessage& message, const pn::MacAddress& destination) {
  std::vector<std::uint8_t> bytes(1514);
  pn::WireWriter out(bytes);
  pn::encode(pn::EthernetHeader{destination, kController, std::nullopt}, message, out);
  bytes.resize(out.position());
  return bytes;
}

pn::DcpMessage decode_dcp_frame(const std::vector<std::uint8_t>& bytes) {
  pn::WireReader in(bytes);
  (void)pn::decode_ethernet(in);
  pn::DcpMessage message = pn::decode_dcp(in);
  EXPECT_TRUE(in.ok());
  return message;
}

// A request of the controller and the device's answer, decoded.
struct Exchange {
  std::vector<std::uint8_t> answer;
  pn::RpcPacket packet;
};

Exchange call(pn::IoDevice& device, pn::PnioOperation operation, const auto& body,
              std::uint32_t sequence = 1) {
  std::vector<std::uint8_t> blocks(4096);
  pn::WireWriter block_out(blocks);
  pn::encode(body, block_out);
  pn::RpcHeader header;
  header.object = pn::pnio_object_uuid(1, 0x0C01, 0x002A);
  header.interface = pn::kPnioDeviceInterface;
  header.activity = {0xA1, 0xB1, 0xC1, {1}};
  header.sequence_number = sequence;
  header.opnum = static_cast<std::uint16_t>(operation);
  std::vector<std::uint8_t> request(8192);
  pn::WireWriter out(request);
  pn::encode_rpc(header, 4096, {}, block_out.written(), out);
  Exchange exchange;
  exchange.answer = device.on_rpc(out.written());
  pn::WireReader in(exchange.answer);
  exchange.packet = pn::decode_rpc(in);
  EXPECT_TRUE(in.ok());
  EXPECT_EQ(exchange.packet.header.packet_type, pn::RpcPacketType::kResponse);
  EXPECT_EQ(exchange.packet.header.sequence_number, sequence);
  return exchange;
}

pn::ControlBlock control(std::uint16_t type, std::uint16_t command, pn::Uuid ar = kArUuid) {
  return {type, ar, 1, command, 0};
}

// The controller's view of the drive's two IOCRs (offsets of sample_frames.hpp's Connect).
struct ControllerImages {
  pn::CyclicCodec output;
  pn::CyclicCodec input;
  ControllerImages() {
    pn::CyclicLayout out;
    out.frame_id = 0x8002;
    out.data_objects[0] = {1, 2, 0, 4};
    out.data_object_count = 1;
    out.iocs[0] = {0, 1, 5, 0};
    out.iocs[1] = {1, 2, 6, 0};
    out.iocs_count = 2;
    pn::CyclicLayout in;
    in.frame_id = 0x8001;
    in.data_objects[0] = {0, 1, 0, 0};
    in.data_objects[1] = {1, 2, 1, 4};
    in.data_object_count = 2;
    in.iocs[0] = {1, 2, 6, 0};
    in.iocs_count = 1;
    EXPECT_EQ(pn::CyclicCodec::create(out, output), pn::ProfinetError::kNone);
    EXPECT_EQ(pn::CyclicCodec::create(in, input), pn::ProfinetError::kNone);
  }
};

void connect_and_run(pn::IoDevice& device) {
  const Exchange connected = call(device, pn::PnioOperation::kConnect, pn::testing::drive_connect());
  ASSERT_TRUE(connected.packet.status.ok());
  ASSERT_TRUE(call(device, pn::PnioOperation::kControl,
                   control(pn::block_type::kPrmEndRequest, pn::control_command::kPrmEnd))
                  .packet.status.ok());
  ASSERT_TRUE(device.take_application_ready());
}

}  // namespace

// IEC 61158-6-10 DCP (Identify All and by name, Set NameOfStation and IP to the device's MAC, answered per
// option).
TEST(IoDevice, DcpIdentifyAndNaming) {
  pn::IoDevice device(drive_identity());
  // A new device has no name; Identify All finds it, Identify by name does not.
  auto answer = device.on_dcp(dcp(pn::dcp_identify_request(1, std::nullopt), pn::kDcpIdentifyMulticast));
  ASSERT_FALSE(answer.empty());
  pn::DcpMessage identified = decode_dcp_frame(answer);
  EXPECT_EQ(identified.frame_id, pn::kFrameIdDcpIdentifyResponse);
  EXPECT_EQ(identified.xid, 1u);
  EXPECT_EQ(identified.fields.name_of_station, "");
  EXPECT_EQ(identified.fields.device_id, 0x0C01);
  EXPECT_TRUE(device.on_dcp(dcp(pn::dcp_identify_request(2, "drive-1"), pn::kDcpIdentifyMulticast)).empty());
  // Set name and IP (to the device's MAC), answered option by option; then Identify by name finds it.
  const pn::IpSuite ip{{10, 0, 0, 2}, {255, 255, 255, 0}, {}};
  const pn::DcpMessage set_answer =
      decode_dcp_frame(device.on_dcp(dcp(pn::dcp_set_request(3, "drive-1", ip, false), kDevice)));
  EXPECT_EQ(set_answer.results, (std::vector<pn::DcpSetResult>{{pn::dcp_option::kNameOfStation, 0},
                                                               {pn::dcp_option::kIpParameter, 0}}));
  // A Set to another MAC is not for this device.
  EXPECT_TRUE(device.on_dcp(dcp(pn::dcp_set_request(4, "x", std::nullopt, false), kController)).empty());
  identified =
      decode_dcp_frame(device.on_dcp(dcp(pn::dcp_identify_request(5, "drive-1"), pn::kDcpIdentifyMulticast)));
  EXPECT_EQ(identified.fields.ip, ip);
  EXPECT_EQ(identified.ip_block_info, 1);
  const pn::DcpMessage hello = decode_dcp_frame(device.hello());
  EXPECT_EQ(hello.service, pn::DcpService::kHello);
  EXPECT_EQ(hello.fields.name_of_station, "drive-1");
}

// IEC 61158-6-10 ObjectUUID: a request to DEA00000-6C97-11D1-8271-0001-{DeviceID}-{VendorID} of another
// device (or with the zeros of a controller that skipped the DCP DeviceID block) is rejected like an object a
// DCE/RPC server does not export (C706 Appendix E, nca_s_unsupported_type) and sets up no AR.
TEST(IoDevice, ARequestToAnotherObjectIsRejected) {
  pn::IoDevice device(drive_identity());  // VendorID 0x002A, DeviceID 0x0C01
  std::vector<std::uint8_t> blocks(4096);
  pn::WireWriter block_out(blocks);
  pn::encode(pn::testing::drive_connect(), block_out);
  const auto connect_to = [&](const pn::Uuid& object) {
    pn::RpcHeader header;
    header.object = object;
    header.interface = pn::kPnioDeviceInterface;
    header.activity = {0xA1, 0xB1, 0xC1, {1}};
    header.sequence_number = 7;
    std::vector<std::uint8_t> request(8192);
    pn::WireWriter out(request);
    pn::encode_rpc(header, 4096, {}, block_out.written(), out);
    return device.on_rpc(out.written());
  };
  for (const pn::Uuid& wrong :
       {pn::pnio_object_uuid(1, 0x0C01, 0x002B), pn::pnio_object_uuid(1, 0x0C02, 0x002A),
        pn::pnio_object_uuid(1, 0, 0), pn::pnio_object_uuid(2, 0x0C01, 0x002A)}) {
    const auto answer = connect_to(wrong);
    ASSERT_EQ(answer.size(), pn::kRpcHeaderBytes + 4) << pn::to_string(wrong);
    pn::WireReader in(answer);
    const pn::RpcPacket reject = pn::decode_rpc(in);
    ASSERT_TRUE(in.ok());
    EXPECT_EQ(reject.header.packet_type, pn::RpcPacketType::kReject);
    EXPECT_EQ(reject.header.sequence_number, 7u);
    EXPECT_EQ(reject.header.object, wrong);
    EXPECT_EQ(reject.reject_status, pn::kNcaUnsupportedType);
    EXPECT_EQ(device.state(), pn::ArState::kNone);
  }
  const auto accepted = connect_to(pn::pnio_object_uuid(1, 0x0C01, 0x002A));
  pn::WireReader in(accepted);
  EXPECT_EQ(pn::decode_rpc(in).header.packet_type, pn::RpcPacketType::kResponse);
  EXPECT_EQ(device.state(), pn::ArState::kParameterizing);
}

// IEC 61158-6-10 AR start-up (Connect, record write/read, PrmEnd, ApplicationReady),
// docs/profinet-gateway.md "How it is checked".
TEST(IoDevice, ConnectParameterizeAndRun) {
  pn::IoDevice device(drive_identity());
  const Exchange connected = call(device, pn::PnioOperation::kConnect, pn::testing::drive_connect());
  ASSERT_TRUE(connected.packet.status.ok());
  pn::WireReader blocks(connected.packet.blocks);
  const pn::ConnectResponse response = pn::decode_connect_response(blocks);
  ASSERT_TRUE(blocks.ok());
  EXPECT_EQ(response.ar.ar_uuid, kArUuid);
  EXPECT_EQ(response.ar.responder_mac, kDevice);
  ASSERT_EQ(response.iocrs.size(), 2u);
  EXPECT_EQ(response.iocrs[0].frame_id, 0x8001);
  EXPECT_TRUE(response.module_diff.empty());
  EXPECT_EQ(device.state(), pn::ArState::kParameterizing);

  // Start-up record: write, then read back (the default record handler keeps it).
  const pn::RecordAccess write = pn::testing::read_p0922_request();
  const Exchange written = call(device, pn::PnioOperation::kWrite, write, 2);
  ASSERT_TRUE(written.packet.status.ok());
  pn::RecordAccess read = write;
  read.header.type = pn::block_type::kIodReadRequest;
  read.header.record_data_length = 240;
  read.data.clear();
  const Exchange readback = call(device, pn::PnioOperation::kRead, read, 3);
  pn::WireReader read_in(readback.packet.blocks);
  EXPECT_EQ(pn::decode_record(read_in).data, write.data);
  read.header.index = 0xB02F;  // never written
  EXPECT_EQ(call(device, pn::PnioOperation::kRead, read, 4).packet.status,
            (pn::PnioStatus{0xDE, 0x80, 0xB0, 0x00}));

  // PrmEnd -> Done; the device then owes its ApplicationReady (to the controller interface), once.
  EXPECT_FALSE(device.take_application_ready());
  const Exchange prm_end = call(device, pn::PnioOperation::kControl,
                                control(pn::block_type::kPrmEndRequest, pn::control_command::kPrmEnd), 5);
  pn::WireReader done_in(prm_end.packet.blocks);
  const pn::ControlBlock done = pn::decode_control(done_in);
  EXPECT_EQ(done.type, pn::block_type::kPrmEndResponse);
  EXPECT_EQ(done.command, pn::control_command::kDone);
  EXPECT_EQ(device.state(), pn::ArState::kApplicationReady);
  const auto ready = device.take_application_ready();
  ASSERT_TRUE(ready);
  EXPECT_FALSE(device.take_application_ready());
  pn::WireReader ready_in(*ready);
  const pn::RpcPacket ready_packet = pn::decode_rpc(ready_in);
  EXPECT_EQ(ready_packet.header.interface, pn::kPnioControllerInterface);
  pn::WireReader ready_blocks(ready_packet.blocks);
  EXPECT_EQ(pn::decode_control(ready_blocks).command, pn::control_command::kApplicationReady);
  EXPECT_EQ(device.state(), pn::ArState::kRunning);
}

// IEC 61158-6-10 (DataStatus DataValid, IOPS/IOCS, the watchdog factor × cycle), decision I7;
// docs/profinet-gateway.md "How it is checked" (3 × 1 ms + 1 µs).
TEST(IoDevice, CyclicExchangeAndWatchdog) {
  pn::IoDevice device(drive_identity());
  std::array<std::uint8_t, 128> frame{};
  // Before the Connect there is no input frame.
  EXPECT_EQ(device.next_input_frame(frame), 0u);
  const Exchange connected = call(device, pn::PnioOperation::kConnect, pn::testing::drive_connect());
  ASSERT_TRUE(connected.packet.status.ok());
  ControllerImages controller;
  std::array<std::uint8_t, 40> input_image{};
  pn::ApduStatus status;
  // Parameterizing: frames flow but DataValid is off.
  std::size_t n = device.next_input_frame(frame);
  ASSERT_EQ(controller.input.decode(std::span(frame).first(n), input_image, status),
            pn::ProfinetError::kNone);
  EXPECT_EQ(status.data_status & pn::data_status::kDataValid, 0);
  ASSERT_TRUE(call(device, pn::PnioOperation::kControl,
                   control(pn::block_type::kPrmEndRequest, pn::control_command::kPrmEnd))
                  .packet.status.ok());
  ASSERT_TRUE(device.take_application_ready());

  // Controller -> device: STW1 0x047F, NSOLL_A 0x2000 with IOPS good.
  std::array<std::uint8_t, 40> output_image{};
  const std::array<std::uint8_t, 4> setpoint{0x04, 0x7F, 0x20, 0x00};
  std::copy(setpoint.begin(), setpoint.end(), controller.output.data(output_image, 0).begin());
  controller.output.iops(output_image, 0) = pn::kIoxsGood;
  ASSERT_EQ(controller.output.encode({kDevice, kController, pn::VlanTag{6, 0}}, output_image, {32, 0x35, 0},
                                     frame, n),
            pn::ProfinetError::kNone);
  EXPECT_TRUE(device.on_cyclic(std::span(frame).first(n), 1000));
  const auto received = device.output_data(1, 2);
  EXPECT_TRUE(std::equal(received.begin(), received.end(), setpoint.begin(), setpoint.end()));
  EXPECT_EQ(device.last_output_status().cycle_counter, 32);

  // Device -> controller: ZSW1 0x0B37, NIST_A 0x2000; IOPS and IOCS good, DataValid, counter + 32 per frame.
  const std::array<std::uint8_t, 4> actual{0x0B, 0x37, 0x20, 0x00};
  std::copy(actual.begin(), actual.end(), device.input_data(1, 2).begin());
  EXPECT_TRUE(device.input_data(1, 9).empty());
  const std::uint16_t before = status.cycle_counter;
  n = device.next_input_frame(frame);
  ASSERT_EQ(controller.input.decode(std::span(frame).first(n), input_image, status),
            pn::ProfinetError::kNone);
  EXPECT_EQ(status.cycle_counter, static_cast<std::uint16_t>(before + 32));
  EXPECT_EQ(status.data_status, pn::data_status::kRunning);
  const auto data = controller.input.read_data(input_image, 1);
  EXPECT_TRUE(std::equal(data.begin(), data.end(), actual.begin(), actual.end()));
  EXPECT_EQ(controller.input.read_iops(input_image, 1), pn::kIoxsGood);
  EXPECT_EQ(controller.input.read_iocs(input_image, 0), pn::kIoxsGood);

  // Watchdog: DataHoldFactor 3 x 1 ms after the last output frame (received at 1000 us). A time read
  // before that frame arrived (999 us) is no expiry: the difference must not wrap around.
  EXPECT_FALSE(device.watchdog_expired(999));
  EXPECT_FALSE(device.watchdog_expired(4000));
  EXPECT_TRUE(device.watchdog_expired(4001));
  EXPECT_EQ(device.state(), pn::ArState::kNone);
  EXPECT_FALSE(device.on_cyclic(std::span(frame).first(n), 4002));
}

// IEC 61158-6-10 ModuleDiffBlock (WrongModule), its data with IOPS BAD; decision I15.
TEST(IoDevice, WrongModuleIsReportedAndItsDataAreBad) {
  pn::IoDevice device(drive_identity(0x102));  // the drive has another telegram module in slot 1
  const Exchange connected = call(device, pn::PnioOperation::kConnect, pn::testing::drive_connect());
  ASSERT_TRUE(connected.packet.status.ok());
  pn::WireReader blocks(connected.packet.blocks);
  const pn::ConnectResponse response = pn::decode_connect_response(blocks);
  ASSERT_EQ(response.module_diff.size(), 1u);
  EXPECT_EQ(response.module_diff[0].slot, 1);
  EXPECT_EQ(response.module_diff[0].ident, 0x102u);
  EXPECT_EQ(response.module_diff[0].state, pn::ModuleState::kWrongModule);
  ASSERT_TRUE(call(device, pn::PnioOperation::kControl,
                   control(pn::block_type::kPrmEndRequest, pn::control_command::kPrmEnd))
                  .packet.status.ok());
  ASSERT_TRUE(device.take_application_ready());
  ControllerImages controller;
  std::array<std::uint8_t, 128> frame{};
  std::array<std::uint8_t, 40> input_image{};
  pn::ApduStatus status;
  const std::size_t n = device.next_input_frame(frame);
  ASSERT_EQ(controller.input.decode(std::span(frame).first(n), input_image, status),
            pn::ProfinetError::kNone);
  EXPECT_EQ(controller.input.read_iops(input_image, 0), pn::kIoxsGood);  // the DAP is fine
  EXPECT_EQ(controller.input.read_iops(input_image, 1), pn::kIoxsBad);   // the wrong module's data
  EXPECT_EQ(controller.input.read_iocs(input_image, 0), pn::kIoxsBad);

  // A missing submodule is reported as NoSubmodule.
  pn::DeviceIdentity without = drive_identity();
  without.modules[1].submodules.clear();
  pn::IoDevice bare(without);
  const Exchange bare_connect = call(bare, pn::PnioOperation::kConnect, pn::testing::drive_connect());
  pn::WireReader bare_blocks(bare_connect.packet.blocks);
  const pn::ConnectResponse bare_response = pn::decode_connect_response(bare_blocks);
  ASSERT_EQ(bare_response.module_diff.size(), 1u);
  EXPECT_EQ(bare_response.module_diff[0].state, pn::ModuleState::kProperModule);
  ASSERT_EQ(bare_response.module_diff[0].submodules.size(), 1u);
  EXPECT_EQ(bare_response.module_diff[0].submodules[0].ident_info, pn::SubmoduleIdentInfo::kNoSubmodule);
}

// IEC 61158-6-10 PNIOStatus of out-of-place requests (DD 81 40 05, DB 81 40 04, DD 81 40 06).
TEST(IoDevice, RequestsOutOfPlaceGetTheirPnioStatus) {
  pn::IoDevice device(drive_identity());
  // Control without an AR: AR UUID unknown.
  EXPECT_EQ(call(device, pn::PnioOperation::kControl,
                 control(pn::block_type::kPrmEndRequest, pn::control_command::kPrmEnd))
                .packet.status,
            (pn::PnioStatus{0xDD, 0x81, 0x40, 0x05}));
  connect_and_run(device);
  // A second controller's Connect: no AR resources.
  pn::ConnectRequest other = pn::testing::drive_connect();
  other.ar.ar_uuid.data1 = 0x99;
  EXPECT_EQ(call(device, pn::PnioOperation::kConnect, other).packet.status,
            (pn::PnioStatus{0xDB, 0x81, 0x40, 0x04}));
  // PrmEnd again while running: state conflict.
  EXPECT_EQ(call(device, pn::PnioOperation::kControl,
                 control(pn::block_type::kPrmEndRequest, pn::control_command::kPrmEnd))
                .packet.status,
            (pn::PnioStatus{0xDD, 0x81, 0x40, 0x06}));
  // Release ends the AR; the same AR UUID is then unknown.
  const Exchange released = call(device, pn::PnioOperation::kRelease,
                                 control(pn::block_type::kReleaseRequest, pn::control_command::kRelease));
  ASSERT_TRUE(released.packet.status.ok());
  pn::WireReader released_in(released.packet.blocks);
  EXPECT_EQ(pn::decode_control(released_in).type, pn::block_type::kReleaseResponse);
  EXPECT_EQ(device.state(), pn::ArState::kNone);
  EXPECT_EQ(call(device, pn::PnioOperation::kWrite, pn::testing::read_p0922_request()).packet.status,
            (pn::PnioStatus{0xDF, 0x81, 0x40, 0x05}));
  // Garbage and packets for other interfaces get no answer at all.
  const std::array<std::uint8_t, 10> garbage{4, 0, 0, 0, 0x10};
  EXPECT_TRUE(device.on_rpc(garbage).empty());
  EXPECT_TRUE(device.on_dcp(garbage).empty());
}
