// DCE/RPC header + NDR (C706 ch. 12) and the PNIO blocks of Connect, Control and record access
// (IEC 61158-6-10): block lengths, byte order, round trips, malformed input.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "sample_frames.hpp"
#include "tomc/profinet/blocks.hpp"

namespace pn = tomc::profinet;

namespace {

using pn::testing::drive_connect;
using pn::testing::kArUuid;

std::vector<std::uint8_t> blocks_of(const auto& value) {
  std::vector<std::uint8_t> bytes(4096);
  pn::WireWriter out(bytes);
  pn::encode(value, out);
  EXPECT_TRUE(out.ok());
  bytes.resize(out.position());
  return bytes;
}

std::uint16_t be16(const std::vector<std::uint8_t>& b, std::size_t at) {
  return static_cast<std::uint16_t>(b[at] << 8 | b[at + 1]);
}

}  // namespace

// IEC 61158-6-10 ARBlockReq (0x0101) and IOCRBlockReq (0x0102) layouts, decision I4 (blocks big-endian).
TEST(RpcBlocks, ConnectRequestBlockLayout) {
  const auto bytes = blocks_of(drive_connect());
  // ARBlockReq: type 0x0101, BlockLength = 2 (version) + 52 + 12 (station name), version 1.0.
  EXPECT_EQ(be16(bytes, 0), 0x0101);
  EXPECT_EQ(be16(bytes, 2), 2 + 52 + 12);
  EXPECT_EQ(bytes[4], 1);
  EXPECT_EQ(bytes[5], 0);
  EXPECT_EQ(be16(bytes, 6), 0x0001);  // IOCARSingle
  std::size_t at = 4 + be16(bytes, 2);
  // IOCRBlockReq (input): 2 + 40 fixed + API 4 + 2 + 2x6 + 2 + 1x6.
  EXPECT_EQ(be16(bytes, at), 0x0102);
  EXPECT_EQ(be16(bytes, at + 2), 2 + 40 + 4 + 2 + 12 + 2 + 6);
  EXPECT_EQ(be16(bytes, at + 6), 1);        // InputCR
  EXPECT_EQ(be16(bytes, at + 10), 0x8892);  // LT
  EXPECT_EQ(be16(bytes, at + 18), 0x8001);  // FrameID
  EXPECT_EQ(be16(bytes, at + 20), 32);      // SendClockFactor: 1 ms
  at += 4 + be16(bytes, at + 2);
  EXPECT_EQ(be16(bytes, at), 0x0102);
  at += 4 + be16(bytes, at + 2);
  // AlarmCRBlockReq: 2 + 20.
  EXPECT_EQ(be16(bytes, at), 0x0103);
  EXPECT_EQ(be16(bytes, at + 2), 22);
  at += 26;
  // ExpectedSubmoduleBlockReq of the DAP: 2 + NumberOfAPIs 2 + API 4 + slot 2 + ident 4 + properties 2 +
  // count 2 + one submodule (2 + 4 + 2 + one data description of 6).
  EXPECT_EQ(be16(bytes, at), 0x0104);
  EXPECT_EQ(be16(bytes, at + 2), 2 + 2 + 4 + 2 + 4 + 2 + 2 + 14);
  at += 4 + be16(bytes, at + 2);
  // The telegram module: an IO submodule has two data descriptions (input, then output).
  EXPECT_EQ(be16(bytes, at + 2), 2 + 2 + 4 + 2 + 4 + 2 + 2 + 20);
  EXPECT_EQ(at + 4 + be16(bytes, at + 2), bytes.size());
}

// IEC 61158-6-10 / C706 RPC header and NDR header in the sender's drep (decision I4), both byte orders.
TEST(RpcBlocks, ConnectRequestAndResponseRoundTripThroughRpc) {
  const pn::ConnectRequest request = drive_connect();
  const auto blocks = blocks_of(request);
  for (const bool little_endian : {true, false}) {
    pn::RpcHeader header;
    header.little_endian = little_endian;
    header.object = pn::pnio_object_uuid(1, 0x0C01, 0x002A);
    header.interface = pn::kPnioDeviceInterface;
    header.activity = kArUuid;
    header.sequence_number = 3;
    header.opnum = static_cast<std::uint16_t>(pn::PnioOperation::kConnect);
    std::vector<std::uint8_t> packet(4096);
    pn::WireWriter out(packet);
    pn::encode_rpc(header, 1024, {}, blocks, out);
    ASSERT_TRUE(out.ok());
    packet.resize(out.position());
    EXPECT_EQ(packet.size(), pn::kRpcHeaderBytes + pn::kNdrHeaderBytes + blocks.size());
    EXPECT_EQ(packet[4], little_endian ? 0x10 : 0x00);
    // Interface UUID DEA00001 in the sender's byte order.
    EXPECT_EQ(packet[24], little_endian ? 0x01 : 0xDE);

    pn::WireReader in(packet);
    const pn::RpcPacket decoded = pn::decode_rpc(in);
    ASSERT_TRUE(in.ok()) << pn::describe(in.error());
    EXPECT_EQ(decoded.header.interface, pn::kPnioDeviceInterface);
    EXPECT_EQ(decoded.header.object, header.object);
    EXPECT_EQ(decoded.header.sequence_number, 3u);
    EXPECT_EQ(decoded.args_maximum, 1024u);
    pn::WireReader block_reader(decoded.blocks);
    EXPECT_EQ(pn::decode_connect_request(block_reader), request);
    EXPECT_TRUE(block_reader.ok());
  }

  pn::ConnectResponse response;
  response.ar = {1, kArUuid, 1, {0x02, 0, 0, 0, 0, 2}, 0x8892};
  response.iocrs = {{pn::IocrType::kInput, 1, 0x8001}, {pn::IocrType::kOutput, 2, 0x8002}};
  response.alarm_cr = {1, 3, 200};
  response.module_diff = {{0,
                           1,
                           0x00000102,
                           pn::ModuleState::kWrongModule,
                           {{2, 0x00000102, pn::SubmoduleIdentInfo::kWrong, 0, false}}}};
  const auto response_blocks = blocks_of(response);
  pn::RpcHeader header;
  header.packet_type = pn::RpcPacketType::kResponse;
  std::vector<std::uint8_t> packet(4096);
  pn::WireWriter out(packet);
  pn::encode_rpc(header, 0, pn::PnioStatus{0xDB, 0x81, 0x01, 0x02}, response_blocks, out);
  packet.resize(out.position());
  pn::WireReader in(packet);
  const pn::RpcPacket decoded = pn::decode_rpc(in);
  ASSERT_TRUE(in.ok());
  EXPECT_EQ(decoded.status, (pn::PnioStatus{0xDB, 0x81, 0x01, 0x02}));
  pn::WireReader block_reader(decoded.blocks);
  EXPECT_EQ(pn::decode_connect_response(block_reader), response);
}

// IEC 61158-6-10 ModuleDiffBlock SubmoduleState (FormatIndicator, IdentInfo, ARInfo, Fault bits).
TEST(RpcBlocks, ModuleDiffSubmoduleStateBits) {
  pn::ConnectResponse response;
  response.module_diff = {
      {0, 1, 0x102, pn::ModuleState::kWrongModule, {{2, 0x102, pn::SubmoduleIdentInfo::kWrong, 1, true}}}};
  const auto bytes = blocks_of(response);
  // The ModuleDiffBlock is last; its SubmoduleState is the last u16: FormatIndicator 1, IdentInfo 2 (Wrong),
  // ARInfo 1 (ApplicationReadyPending), Fault 1.
  EXPECT_EQ(be16(bytes, bytes.size() - 2), 0x8000 | 2 << 11 | 1 << 7 | 0x40);
}

// IEC 61158-6-10 IODControlReq (PrmEnd) and IODWriteReqHeader/IODReadReqHeader layouts.
TEST(RpcBlocks, ControlAndRecordBlocks) {
  const pn::ControlBlock prm_end{pn::block_type::kPrmEndRequest, kArUuid, 1, pn::control_command::kPrmEnd, 0};
  const auto control = blocks_of(prm_end);
  ASSERT_EQ(control.size(), 32u);
  EXPECT_EQ(be16(control, 2), 28);
  EXPECT_EQ(be16(control, 28), 0x0001);
  pn::WireReader control_in(control);
  EXPECT_EQ(pn::decode_control(control_in), prm_end);

  const pn::RecordAccess write = pn::testing::read_p0922_request();
  const auto bytes = blocks_of(write);
  EXPECT_EQ(be16(bytes, 2), 60);  // IODWriteReqHeader: the data are outside the block
  EXPECT_EQ(bytes.size(), 64u + write.data.size());
  pn::WireReader write_in(bytes);
  EXPECT_EQ(pn::decode_record(write_in), write);

  pn::RecordAccess answer;
  answer.header = write.header;
  answer.header.type = pn::block_type::kIodWriteResponse;
  answer.header.status = {0xDF, 0x80, 0xB0, 0x00};
  const auto answer_bytes = blocks_of(answer);
  EXPECT_EQ(answer_bytes.size(), 64u);
  pn::WireReader answer_in(answer_bytes);
  EXPECT_EQ(pn::decode_record(answer_in), answer);

  pn::RecordAccess read;
  read.header.type = pn::block_type::kIodReadResponse;
  read.header.index = 0xB02E;
  read.data = {1, 2, 3};
  read.header.record_data_length = 3;
  const auto read_bytes = blocks_of(read);
  pn::WireReader read_in(read_bytes);
  EXPECT_EQ(pn::decode_record(read_in), read);
}

// IEC 61158-6-10 block checks (BlockLength, BlockVersion, name lengths); ARCHITECTURE-GUIDE §7 (outside
// bytes never crash).
TEST(RpcBlocks, MalformedInputIsAnError) {
  const auto blocks = blocks_of(drive_connect());
  // A BlockLength beyond the body.
  auto too_long = blocks;
  too_long[2] = 0x7F;
  pn::WireReader a(too_long);
  (void)pn::decode_connect_request(a);
  EXPECT_EQ(a.error(), pn::ProfinetError::kBadBlockLength);
  // BlockVersionHigh 2.
  auto version = blocks;
  version[4] = 2;
  pn::WireReader b(version);
  (void)pn::decode_connect_request(b);
  EXPECT_EQ(b.error(), pn::ProfinetError::kBadBlockVersion);
  // A station name longer than its block.
  auto name = blocks;
  name[56] = 0x00;  // StationNameLength: 6 (header) + 50
  name[57] = 0x40;
  pn::WireReader c(name);
  (void)pn::decode_connect_request(c);
  EXPECT_EQ(c.error(), pn::ProfinetError::kBadBlockLength);
  // A Connect without the AR block.
  const std::size_t ar_bytes = 4 + be16(blocks, 2);
  std::vector<std::uint8_t> no_ar(blocks.begin() + static_cast<long>(ar_bytes), blocks.end());
  pn::WireReader d(no_ar);
  (void)pn::decode_connect_request(d);
  EXPECT_EQ(d.error(), pn::ProfinetError::kWrongBlockType);
  // Every cut inside a block fails (a cut between blocks is a shorter, well-formed body).
  std::vector<std::size_t> boundaries;
  for (std::size_t at = 0; at < blocks.size(); at += 4 + be16(blocks, at + 2))
    boundaries.push_back(at);
  for (std::size_t n = 1; n < blocks.size(); ++n) {
    if (std::find(boundaries.begin(), boundaries.end(), n) != boundaries.end()) continue;
    std::vector<std::uint8_t> cut(blocks.begin(), blocks.begin() + static_cast<long>(n));
    pn::WireReader e(cut);
    (void)pn::decode_connect_request(e);
    EXPECT_FALSE(e.ok()) << n;
  }
  // RPC: version 5, body beyond the packet, ArgsLength beyond the body.
  pn::RpcHeader header;
  std::vector<std::uint8_t> packet(512);
  pn::WireWriter out(packet);
  pn::encode_rpc(header, 512, {}, std::span(blocks).first(32), out);
  packet.resize(out.position());
  auto bad_version = packet;
  bad_version[0] = 5;
  pn::WireReader f(bad_version);
  (void)pn::decode_rpc(f);
  EXPECT_EQ(f.error(), pn::ProfinetError::kBadValue);
  auto bad_body = packet;
  bad_body[74] = 0xFF;  // body length, little-endian low byte
  bad_body[75] = 0x7F;
  pn::WireReader g(bad_body);
  (void)pn::decode_rpc(g);
  EXPECT_EQ(g.error(), pn::ProfinetError::kTruncated);
  auto bad_args = packet;
  bad_args[84] = 0xFF;  // ArgsLength
  pn::WireReader h(bad_args);
  (void)pn::decode_rpc(h);
  EXPECT_EQ(h.error(), pn::ProfinetError::kBadBlockLength);
}

// Decision I27 (object UUID DEA00000-6C97-11D1-8271-{instance}{DeviceID}{VendorID}), IEC 61158-6-10.
TEST(RpcBlocks, ObjectUuidCarriesInstanceDeviceAndVendor) {
  EXPECT_EQ(pn::to_string(pn::pnio_object_uuid(1, 0x0C01, 0x002A)), "dea00000-6c97-11d1-8271-00010c01002a");
  EXPECT_EQ(pn::to_string(pn::kPnioDeviceInterface), "dea00001-6c97-11d1-8271-00a02442df7d");
}

// The object UUID's bytes 8..23 of the RPC header (C706 12.5.2: the first three fields in the drep's byte
// order, the last eight as they are): instance 0x0001, DeviceID 0x0C01, VendorID 0x002A big-endian at the
// end whatever the drep, as Wireshark's PN-IO dissector reads them. And a Reject: 80 header bytes and the
// 4-byte NCA status.
// Decision I27 (the last six bytes big-endian whatever the drep; a Reject with the NCA status), C706
// 12.5.2.
TEST(RpcBlocks, ObjectUuidAndRejectGoldenBytes) {
  pn::RpcHeader header;
  header.object = pn::pnio_object_uuid(1, 0x0C01, 0x002A);
  header.interface = pn::kPnioDeviceInterface;
  header.sequence_number = 9;
  for (const bool little_endian : {true, false}) {
    header.little_endian = little_endian;
    std::vector<std::uint8_t> packet(256);
    pn::WireWriter out(packet);
    pn::encode_rpc(header, 64, {}, {}, out);
    const std::vector<std::uint8_t> object(packet.begin() + 8, packet.begin() + 24);
    const std::vector<std::uint8_t> le{0x00, 0x00, 0xA0, 0xDE, 0x97, 0x6C, 0xD1, 0x11,
                                       0x82, 0x71, 0x00, 0x01, 0x0C, 0x01, 0x00, 0x2A};
    const std::vector<std::uint8_t> be{0xDE, 0xA0, 0x00, 0x00, 0x6C, 0x97, 0x11, 0xD1,
                                       0x82, 0x71, 0x00, 0x01, 0x0C, 0x01, 0x00, 0x2A};
    EXPECT_EQ(object, little_endian ? le : be);

    std::vector<std::uint8_t> reject(128);
    pn::WireWriter reject_out(reject);
    pn::encode_rpc_reject(header, pn::kNcaUnsupportedType, reject_out);
    ASSERT_TRUE(reject_out.ok());
    reject.resize(reject_out.position());
    ASSERT_EQ(reject.size(), 84u);
    EXPECT_EQ(reject[1], 6);  // PTYPE reject
    EXPECT_EQ(std::vector<std::uint8_t>(reject.begin() + 8, reject.begin() + 24), object);
    EXPECT_EQ(std::vector<std::uint8_t>(reject.begin() + 74, reject.begin() + 76),
              (little_endian ? std::vector<std::uint8_t>{4, 0} : std::vector<std::uint8_t>{0, 4}));
    EXPECT_EQ(std::vector<std::uint8_t>(reject.begin() + 80, reject.end()),
              (little_endian ? std::vector<std::uint8_t>{0x17, 0x00, 0x01, 0x1C}
                             : std::vector<std::uint8_t>{0x1C, 0x01, 0x00, 0x17}));
    pn::WireReader in(reject);
    const pn::RpcPacket decoded = pn::decode_rpc(in);
    ASSERT_TRUE(in.ok());
    EXPECT_EQ(decoded.header.packet_type, pn::RpcPacketType::kReject);
    EXPECT_EQ(decoded.header.sequence_number, 9u);
    EXPECT_EQ(decoded.reject_status, 0x1C010017u);
    EXPECT_TRUE(decoded.blocks.empty());
  }
}
