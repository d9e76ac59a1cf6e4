// DCP frames against their layout (IEC 61158-6-10 DCP; the same bytes Wireshark's packet-pn-dcp.c reads).
#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tomc/profinet/dcp.hpp"
#include "tomc/profinet/dcp_commissioning.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/io_device.hpp"

namespace pn = tomc::profinet;

namespace {

constexpr pn::MacAddress kController{0x02, 0x00, 0x00, 0x00, 0x00, 0x01};
constexpr pn::MacAddress kDevice{0x02, 0x00, 0x00, 0x00, 0x00, 0x02};

std::vector<std::uint8_t> encode(const pn::EthernetHeader& header, const pn::DcpMessage& message) {
  std::vector<std::uint8_t> bytes(1514);
  pn::WireWriter out(bytes);
  pn::encode(header, message, out);
  EXPECT_TRUE(out.ok());
  bytes.resize(out.position());
  return bytes;
}

pn::DcpMessage decode(const std::vector<std::uint8_t>& bytes,
                      pn::ProfinetError expected = pn::ProfinetError::kNone) {
  pn::WireReader in(bytes);
  (void)pn::decode_ethernet(in);
  pn::DcpMessage message = pn::decode_dcp(in);
  EXPECT_EQ(in.error(), expected) << pn::describe(in.error());
  return message;
}

}  // namespace

TEST(Dcp, IdentifyAllIsTheMinimalFrameWithTheAllSelector) {
  const auto bytes = encode({pn::kDcpIdentifyMulticast, kController, std::nullopt},
                            pn::dcp_identify_request(0x01020304, std::nullopt));
  const std::vector<std::uint8_t> head{
      0x01, 0x0E, 0xCF, 0x00, 0x00, 0x00,  // destination: DCP identify multicast
      0x02, 0x00, 0x00, 0x00, 0x00, 0x01,  // source
      0x88, 0x92,                          // EtherType PROFINET
      0xFE, 0xFE,                          // FrameID identify request
      0x05, 0x00,                          // ServiceID identify, ServiceType request
      0x01, 0x02, 0x03, 0x04,              // Xid
      0x00, 0x01,                          // ResponseDelayFactor
      0x00, 0x04,                          // DCPDataLength
      0xFF, 0xFF, 0x00, 0x00,              // All selector, length 0
  };
  ASSERT_EQ(bytes.size(), pn::kMinimumFrameBytes);
  EXPECT_TRUE(std::equal(head.begin(), head.end(), bytes.begin()));
  EXPECT_TRUE(std::all_of(bytes.begin() + static_cast<long>(head.size()), bytes.end(),
                          [](auto b) { return b == 0; }));
  const pn::DcpMessage message = decode(bytes);
  EXPECT_EQ(message.service, pn::DcpService::kIdentify);
  EXPECT_EQ(message.xid, 0x01020304u);
  EXPECT_FALSE(message.fields.name_of_station);
}

// IEC 61158-6-10 DCP Identify (NameOfStation option 2/2, blocks padded to even length), decision I4.
TEST(Dcp, IdentifyByNameCarriesTheNameWithoutBlockInfoAndPadsOddLengths) {
  const auto bytes = encode({pn::kDcpIdentifyMulticast, kController, std::nullopt},
                            pn::dcp_identify_request(7, std::string("drive-1")));
  // Block at byte 26: option 2/2, length 7, "drive-1", one padding byte; DCPDataLength 12.
  EXPECT_EQ(bytes[24], 0x00);
  EXPECT_EQ(bytes[25], 12);
  EXPECT_EQ(bytes[26], 0x02);
  EXPECT_EQ(bytes[27], 0x02);
  EXPECT_EQ(bytes[29], 7);
  EXPECT_EQ(std::string(bytes.begin() + 30, bytes.begin() + 37), "drive-1");
  EXPECT_EQ(decode(bytes).fields.name_of_station, "drive-1");
}

// IEC 61158-6-10 DCP Identify response (NameOfStation, vendor, IDs, role, IP suite with BlockInfo).
TEST(Dcp, IdentifyResponseRoundTripsEveryField) {
  pn::DcpMessage response;
  response.frame_id = pn::kFrameIdDcpIdentifyResponse;
  response.type = pn::DcpServiceType::kSuccess;
  response.xid = 99;
  response.fields.name_of_station = "drive-12";
  response.fields.vendor = "tomc emulated drive";
  response.fields.vendor_id = 0x002A;
  response.fields.device_id = 0x0C01;
  response.fields.device_role = 1;
  response.fields.ip = pn::IpSuite{{10, 0, 0, 2}, {255, 255, 255, 0}, {0, 0, 0, 0}};
  response.ip_block_info = 1;
  const auto bytes = encode({kController, kDevice, std::nullopt}, response);
  const pn::DcpMessage decoded = decode(bytes);
  EXPECT_EQ(decoded, response);
}

// IEC 61158-6-10 DCP Set (BlockQualifier 1 permanent; the response names each option's result).
TEST(Dcp, SetRequestUsesBlockQualifierAndTheResponseNamesEachOption) {
  const pn::DcpMessage set = pn::dcp_set_request(5, std::string("drive-3"),
                                                 pn::IpSuite{{10, 0, 0, 3}, {255, 255, 255, 0}, {}}, true);
  const auto bytes = encode({kDevice, kController, std::nullopt}, set);
  EXPECT_EQ(bytes[14], 0xFE);
  EXPECT_EQ(bytes[15], 0xFD);
  EXPECT_EQ(bytes[16], 4);  // Set
  // NameOfStation block: length = 2 (qualifier) + 7, qualifier 1 (permanent).
  EXPECT_EQ(bytes[29], 9);
  EXPECT_EQ(bytes[31], 1);
  EXPECT_EQ(decode(bytes), set);

  pn::DcpMessage answer;
  answer.frame_id = pn::kFrameIdDcpGetSet;
  answer.service = pn::DcpService::kSet;
  answer.type = pn::DcpServiceType::kSuccess;
  answer.xid = 5;
  answer.results = {{pn::dcp_option::kNameOfStation, 0}, {pn::dcp_option::kIpParameter, 0}};
  EXPECT_EQ(decode(encode({kController, kDevice, std::nullopt}, answer)), answer);
}

// IEC 61158-6-10 DCP Hello (blocks with BlockInfo).
TEST(Dcp, HelloCarriesBlockInfo) {
  pn::DcpMessage hello;
  hello.frame_id = pn::kFrameIdDcpHello;
  hello.service = pn::DcpService::kHello;
  hello.fields.name_of_station = "drive-1";
  hello.fields.ip = pn::IpSuite{{10, 0, 0, 2}, {255, 0, 0, 0}, {}};
  hello.fields.device_initiative = 1;
  const auto bytes = encode({pn::kDcpHelloMulticast, kDevice, std::nullopt}, hello);
  EXPECT_EQ(bytes[29], 9);  // 2 BlockInfo + 7
  EXPECT_EQ(decode(bytes), hello);
}

// IEC 61158-6-10 DCP (DCPDataLength, block length, ServiceID, FrameID checked); ARCHITECTURE-GUIDE §7
// (outside bytes never crash).
TEST(Dcp, MalformedInputIsAnErrorNotACrash) {
  auto bytes = encode({kController, kDevice, std::nullopt}, pn::dcp_identify_request(1, std::string("x")));
  // DCPDataLength beyond the frame.
  auto longer = bytes;
  longer[25] = 0xF0;
  decode(longer, pn::ProfinetError::kTruncated);
  // A block longer than DCPDataLength.
  auto block = bytes;
  block[29] = 40;
  decode(block, pn::ProfinetError::kBadBlockLength);
  // Unknown ServiceID.
  auto service = bytes;
  service[16] = 9;
  decode(service, pn::ProfinetError::kBadValue);
  // Not a DCP FrameID.
  auto id = bytes;
  id[14] = 0xC0;
  decode(id, pn::ProfinetError::kWrongFrameId);
  // Every truncation of the frame decodes to an error or to a shorter valid prefix, never past the end.
  for (std::size_t n = 0; n < 30; ++n) {
    std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<long>(n));
    pn::WireReader in(cut);
    (void)pn::decode_ethernet(in);
    (void)pn::decode_dcp(in);
    EXPECT_FALSE(in.ok()) << n;
  }
}

// tomc's own: the colon-separated MAC text of the gateway's file and CLI (decision I32), anything else
// refused.
TEST(Dcp, MacAddressText) {
  EXPECT_EQ(pn::to_string(kDevice), "02:00:00:00:00:02");
  EXPECT_EQ(pn::parse_mac("02:00:00:00:00:02"), kDevice);
  EXPECT_FALSE(pn::parse_mac("02:00:00:00:00"));
  EXPECT_FALSE(pn::parse_mac("02-00-00-00-00-02"));
  EXPECT_FALSE(pn::parse_mac("0g:00:00:00:00:02"));
}

// IEC 61158-6-10 DCP (Control/Response only in a Set response; an Identify filter by DeviceID kept); found
// by the fuzzer (docs/reliability.md §2).
TEST(Dcp, BlocksOutOfPlaceAreSkippedAndFiltersOtherThanTheNameAreKept) {
  // A Control/Response block belongs to a Set response only: in a Set request it is skipped (found by the
  // fuzzer, where it broke decode -> encode -> decode).
  pn::DcpMessage set = pn::dcp_set_request(9, std::string("a"), std::nullopt, false);
  auto bytes = encode({kDevice, kController, std::nullopt}, set);
  const std::vector<std::uint8_t> control{0x05, 0x04, 0x00, 0x03, 0x02, 0x02, 0x00, 0x00};
  bytes.insert(bytes.begin() + 26, control.begin(), control.end());
  bytes[25] = static_cast<std::uint8_t>(bytes[25] + control.size());
  const pn::DcpMessage decoded = decode(bytes);
  EXPECT_TRUE(decoded.results.empty());
  EXPECT_EQ(decoded.fields.name_of_station, "a");
  // An Identify filtered by device ID is not turned into Identify All.
  pn::DcpMessage by_id = pn::dcp_identify_request(10, std::nullopt);
  by_id.fields.vendor_id = 0x002A;
  by_id.fields.device_id = 0x0C01;
  EXPECT_EQ(decode(encode({pn::kDcpIdentifyMulticast, kController, std::nullopt}, by_id)), by_id);
}

namespace {

pn::DeviceIdentity station(std::uint8_t last_mac_byte, std::string name, pn::IpSuite ip) {
  pn::DeviceIdentity identity;
  identity.name_of_station = std::move(name);
  identity.ip = ip;
  identity.mac = {0x02, 0, 0, 0, 1, last_mac_byte};
  identity.vendor_id = 0x002A;
  identity.device_id = 0x0C01;
  identity.vendor = "tomc emulated drive";
  return identity;
}

}  // namespace

// Commissioning (`tomc gateway --identify`, decision I32): one Identify All (no filter block, the multicast
// address) reaches every device; each answer to this xid is one station, sorted by MAC, a repeated answer
// replacing the earlier; answers to another xid, requests and Hellos are not stations.
TEST(DcpCommissioning, IdentifyAllListsEveryStationOnce) {
  pn::IoDevice named(station(7, "drive-1", {{10, 0, 0, 11}, {255, 255, 255, 0}, {}}));
  pn::IoDevice fresh(station(3, "", {}));  // as from the factory: no name, no IP
  pn::DcpScan scan(kController, 0x1234);
  const std::vector<std::uint8_t> request = scan.request();
  const pn::DcpMessage asked = decode(request);
  EXPECT_EQ(asked.service, pn::DcpService::kIdentify);
  EXPECT_EQ(asked.fields, pn::DcpDeviceFields{});  // the All selector
  EXPECT_EQ(std::vector<std::uint8_t>(request.begin(), request.begin() + 6),
            std::vector<std::uint8_t>(pn::kDcpIdentifyMulticast.begin(), pn::kDcpIdentifyMulticast.end()));
  const auto named_answer = named.on_dcp(request);
  EXPECT_TRUE(scan.on_frame(named_answer));
  EXPECT_TRUE(scan.on_frame(fresh.on_dcp(request)));
  EXPECT_TRUE(scan.on_frame(named_answer));  // again: still one station
  EXPECT_FALSE(scan.on_frame(request));
  EXPECT_FALSE(scan.on_frame(named.hello()));
  EXPECT_FALSE(scan.on_frame(named.on_dcp(pn::DcpScan(kController, 0x9999).request())));
  ASSERT_EQ(scan.stations().size(), 2u);
  EXPECT_EQ(pn::describe(scan.stations()[0]),
            "(no name)  02:00:00:00:01:03  (no IP)  VendorID 0x002A DeviceID 0x0C01  tomc emulated drive");
  EXPECT_EQ(pn::describe(scan.stations()[1]),
            "drive-1  02:00:00:00:01:07  10.0.0.11/255.255.255.0  VendorID 0x002A DeviceID 0x0C01  tomc "
            "emulated drive");
  EXPECT_EQ(scan.stations()[1].ip_block_info, 1);
}

// `tomc gateway --set-name`: a Set of NameOfStation to one MAC (BlockQualifier 1: permanent) names that
// device and no other; its answer is read as accepted, refused with the BlockError, or not that answer.
// Decision I32 (tomc gateway --set-name: one Set of NameOfStation to one MAC, answer read by xid and
// sender).
TEST(DcpCommissioning, SetNameOfStationNamesTheDeviceOfThatMac) {
  pn::IoDevice fresh(station(3, "", {}));
  pn::IoDevice other(station(4, "drive-2", {}));
  const pn::MacAddress mac = fresh.identity().mac;
  const auto request = pn::dcp_set_name_request(kController, mac, 77, "axis-x.cell-1", true);
  const pn::DcpMessage asked = decode(request);
  EXPECT_EQ(asked.service, pn::DcpService::kSet);
  EXPECT_EQ(asked.fields.name_of_station, "axis-x.cell-1");
  EXPECT_TRUE(asked.permanent);
  EXPECT_TRUE(other.on_dcp(request).empty());  // unicast to another MAC: not for it
  const auto answer = fresh.on_dcp(request);
  EXPECT_EQ(pn::dcp_set_name_result(answer, mac, 77), std::optional<std::string>(""));
  EXPECT_EQ(fresh.identity().name_of_station, "axis-x.cell-1");
  EXPECT_EQ(other.identity().name_of_station, "drive-2");
  EXPECT_EQ(pn::dcp_set_name_result(answer, mac, 78), std::nullopt);                   // another xid
  EXPECT_EQ(pn::dcp_set_name_result(answer, other.identity().mac, 77), std::nullopt);  // another sender
  EXPECT_EQ(pn::dcp_set_name_result(request, mac, 77), std::nullopt);                  // a request
  // Identified by its new name now.
  EXPECT_FALSE(fresh
                   .on_dcp(encode({pn::kDcpIdentifyMulticast, kController, std::nullopt},
                                  pn::dcp_identify_request(5, "axis-x.cell-1")))
                   .empty());
  // A device that refuses (BlockError 3: suboption not set) or does not support Set.
  pn::DcpMessage refused;
  refused.frame_id = pn::kFrameIdDcpGetSet;
  refused.service = pn::DcpService::kSet;
  refused.type = pn::DcpServiceType::kSuccess;
  refused.xid = 77;
  refused.results = {{pn::dcp_option::kNameOfStation, 3}};
  EXPECT_EQ(pn::dcp_set_name_result(encode({kController, mac, std::nullopt}, refused), mac, 77),
            std::optional<std::string>("the device refused the name: BlockError 3"));
  refused.type = pn::DcpServiceType::kNotSupported;
  refused.results.clear();
  EXPECT_EQ(pn::dcp_set_name_result(encode({kController, mac, std::nullopt}, refused), mac, 77),
            std::optional<std::string>("the device does not support DCP Set"));
}

// Decision I36: a DCP Hello (FrameID 0xFEFC, service Hello, a device starting up) names the device the
// running gateway tries at once; an Identify request or answer, a Set, or a Hello of a device without a name
// (as from the factory) name none. The controller takes the Hello like an Identify answer (learns the MAC).
TEST(DcpCommissioning, AHelloNamesTheDeviceThatStarts) {
  pn::IoDevice named(station(7, "drive-1", {{10, 0, 0, 11}, {255, 255, 255, 0}, {}}));
  pn::IoDevice fresh(station(3, "", {}));
  const std::vector<std::uint8_t> hello = named.hello();
  EXPECT_EQ(pn::peek_frame_id(std::span(hello).subspan(0)), pn::kFrameIdDcpHello);
  EXPECT_EQ(pn::dcp_hello_name(hello), std::optional<std::string>("drive-1"));
  EXPECT_EQ(pn::dcp_hello_name(fresh.hello()), std::nullopt);
  const std::vector<std::uint8_t> identify = pn::DcpScan(kController, 0x1234).request();
  EXPECT_EQ(pn::dcp_hello_name(identify), std::nullopt);
  EXPECT_EQ(pn::dcp_hello_name(named.on_dcp(identify)), std::nullopt);
  EXPECT_EQ(
      pn::dcp_hello_name(pn::dcp_set_name_request(kController, named.identity().mac, 5, "drive-1", true)),
      std::nullopt);
  for (std::size_t n = 0; n < hello.size(); n += 7)
    (void)pn::dcp_hello_name(std::span(hello).first(n));  // cut frames: no crash, no name from a cut name
  pn::ControllerDeviceConfig config;
  config.name_of_station = "drive-1";
  config.ip = {{10, 0, 0, 11}, {255, 255, 255, 0}, {}};
  pn::IoController controller(kController, "gw", config, pn::Uuid{1, 2, 3, {4}});
  EXPECT_TRUE(controller.on_dcp(hello, 9).empty());  // same IP suite: no Set needed
  ASSERT_TRUE(controller.device_mac().has_value());
  EXPECT_EQ(*controller.device_mac(), named.identity().mac);
}

// Decision I37: `tomc gateway --set-name` with `--ip`: one DCP Set with the NameOfStation and the IP
// parameter blocks (IP, netmask, gateway) to that MAC; the answer must take both (a Control/Response entry
// without error for each), a refused or missing IP entry is named. parse_ipv4 takes dotted quads only.
TEST(DcpCommissioning, SetNameWithAnIpSuiteSetsBoth) {
  pn::IoDevice fresh(station(3, "", {}));
  const pn::MacAddress mac = fresh.identity().mac;
  const pn::IpSuite suite{{10, 218, 0, 9}, {255, 255, 0, 0}, {10, 218, 0, 1}};
  const auto request = pn::dcp_set_name_request(kController, mac, 80, "axis-8", true, suite);
  const pn::DcpMessage asked = decode(request);
  EXPECT_EQ(asked.fields.name_of_station, "axis-8");
  EXPECT_EQ(asked.fields.ip, suite);
  EXPECT_TRUE(asked.permanent);
  const auto answer = fresh.on_dcp(request);
  EXPECT_EQ(pn::dcp_set_name_result(answer, mac, 80, true), std::optional<std::string>(""));
  EXPECT_EQ(fresh.identity().name_of_station, "axis-8");
  EXPECT_EQ(fresh.identity().ip, suite);
  // An answer for the name only does not confirm the IP suite; a refused one is named.
  pn::DcpMessage partial;
  partial.frame_id = pn::kFrameIdDcpGetSet;
  partial.service = pn::DcpService::kSet;
  partial.type = pn::DcpServiceType::kSuccess;
  partial.xid = 80;
  partial.results = {{pn::dcp_option::kNameOfStation, 0}};
  const auto name_only = encode({kController, mac, std::nullopt}, partial);
  EXPECT_EQ(pn::dcp_set_name_result(name_only, mac, 80, false), std::optional<std::string>(""));
  EXPECT_EQ(pn::dcp_set_name_result(name_only, mac, 80, true),
            std::optional<std::string>("the device's Set response does not answer the IP suite"));
  partial.results.push_back({pn::dcp_option::kIpParameter, 3});
  EXPECT_EQ(pn::dcp_set_name_result(encode({kController, mac, std::nullopt}, partial), mac, 80, true),
            std::optional<std::string>("the device refused the IP suite: BlockError 3"));

  struct Case {
    const char* text;
    std::optional<pn::Ipv4Address> address;
  };
  const Case cases[] = {{"10.218.0.9", pn::Ipv4Address{10, 218, 0, 9}},
                        {"255.255.255.0", pn::Ipv4Address{255, 255, 255, 0}},
                        {"0.0.0.0", pn::Ipv4Address{0, 0, 0, 0}},
                        {"10.0.0.256", std::nullopt},
                        {"10.0.0", std::nullopt},
                        {"10.0.0.1.", std::nullopt},
                        {"10..0.1", std::nullopt},
                        {"1000.0.0.1", std::nullopt},
                        {" 10.0.0.1", std::nullopt},
                        {"", std::nullopt}};
  for (const Case& c : cases)
    EXPECT_EQ(pn::parse_ipv4(c.text), c.address) << c.text;
}
