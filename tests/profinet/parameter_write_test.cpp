// PROFIdrive base-mode parameter access, change requests (request ID 0x02; decision I33): the codec's bytes
// of a change request and of its positive and negative responses, the emulated drive answering changes of the
// parameters it holds (p2000 writable within its limits, p0922 read-only), and write_parameter(), the
// gateway's start-up step (read for the format, change, read back), through an IoController in memory.
#include <gtest/gtest.h>

#include <bit>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "in_memory_start_up.hpp"
#include "sample_frames.hpp"
#include "tomc/drives/profinet_drive.hpp"
#include "tomc/profinet/parameter_access.hpp"
#include "tomc/profinet/parameter_write.hpp"

namespace pn = tomc::profinet;
namespace dr = tomc::drives;

namespace {

std::uint32_t float_bits(float value) {
  return std::bit_cast<std::uint32_t>(value);
}

// A controller with a running AR to the emulated telegram-3 drive, in memory.
struct Link {
  std::unique_ptr<pn::IoController> controller;
  std::unique_ptr<dr::ProfinetDrive> emulator;

  Link() {
    pn::ControllerDeviceConfig c;
    c.name_of_station = "drive-1";
    c.ip = {{10, 0, 0, 2}, {255, 255, 255, 0}, {}};
    c.modules = dr::profidrive_modules(3);
    controller = std::make_unique<pn::IoController>(pn::testing::kController, "gw", c, pn::testing::kArUuid);
    pn::DeviceIdentity identity;
    identity.name_of_station = "drive-1";
    identity.ip = c.ip;
    identity.mac = pn::testing::kDevice;
    emulator = std::make_unique<dr::ProfinetDrive>(identity, dr::DeviceConfig{3, 0, {}, {}},
                                                   dr::SimulatedDriveParameters{});
  }
  // The exchange of the gateway's start-up (start_up.cpp), in memory: write to 0xB02E of `slot`, read back.
  pn::ParameterExchange exchange(std::uint16_t slot = dr::kDriveObjectSlot) {
    return [this,
            slot](const pn::ParameterRequest& request) -> std::variant<pn::ParameterResponse, std::string> {
      if (!controller->on_record_response(emulator->device().on_rpc(
              controller->record_write_request(slot, 1, pn::kParameterAccessIndex, pn::encode(request))))) {
        return std::string("parameter request refused");
      }
      const auto data = controller->on_record_response(emulator->device().on_rpc(
          controller->record_read_request(slot, 1, pn::kParameterAccessIndex, 240)));
      if (!data) return std::string("parameter read refused");
      auto response = pn::decode_parameter_response(*data);
      if (!response) return std::string("malformed");
      return *response;
    };
  }
  pn::ParameterResponse ask(const pn::ParameterRequest& request) {
    auto answer = exchange()(request);
    EXPECT_TRUE(std::holds_alternative<pn::ParameterResponse>(answer));
    return std::holds_alternative<pn::ParameterResponse>(answer) ? std::get<pn::ParameterResponse>(answer)
                                                                 : pn::ParameterResponse{};
  }
};

}  // namespace

// PROFIdrive base mode, change parameter: request header (reference, ID 0x02, axis, number of parameters),
// the parameter addresses (attribute 0x10 value, elements, number, subindex), then per parameter its value
// (format, number of values, values; FloatingPoint 0x08 as IEEE single). The positive response is the header
// alone (ID 0x02); the negative one (ID 0x82) has a value per parameter: format 0x40 (Zero) for an executed
// one, 0x44 (Error) with the error number for a refused one. Decision I33.
TEST(ParameterAccess, AChangeRequestAndItsResponsesHaveTheProfileBytes) {
  const pn::ParameterRequest change{5,
                                    pn::parameter_request_id::kChange,
                                    1,
                                    {{0x10, 1, 2000, 0}},
                                    {{pn::parameter_format::kFloatingPoint, {float_bits(6000.0f)}}}};
  const auto bytes = pn::encode(change);
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{0x05, 0x02, 0x01, 0x01,                 // header
                                              0x10, 0x01, 0x07, 0xD0, 0x00, 0x00,     // p2000, subindex 0
                                              0x08, 0x01, 0x45, 0xBB, 0x80, 0x00}));  // FloatingPoint 6000.0
  EXPECT_EQ(pn::decode_parameter_request(bytes), change);
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_FALSE(pn::decode_parameter_request(std::span(bytes).first(n)).has_value()) << n;
  // A value of unknown width, an error or Zero value in a request do not decode (the drive answers 0xB8).
  for (const std::uint8_t format :
       {std::uint8_t{0x99}, pn::parameter_format::kError, pn::parameter_format::kZero}) {
    auto other = bytes;
    other[10] = format;
    EXPECT_FALSE(pn::decode_parameter_request(other).has_value()) << int{format};
  }
  // Two parameters, Unsigned16 and Integer32 (16-bit values are two bytes, 32-bit four).
  const pn::ParameterRequest two{
      9,
      pn::parameter_request_id::kChange,
      2,
      {{0x10, 1, 922, 0}, {0x10, 1, 1082, 3}},
      {{pn::parameter_format::kUnsigned16, {105}}, {pn::parameter_format::kInteger32, {0xFFFFFFFEu}}}};
  EXPECT_EQ(pn::encode(two), (std::vector<std::uint8_t>{0x09, 0x02, 0x02, 0x02, 0x10, 0x01, 0x03, 0x9A, 0x00,
                                                        0x00, 0x10, 0x01, 0x04, 0x3A, 0x00, 0x03, 0x06, 0x01,
                                                        0x00, 0x69, 0x04, 0x01, 0xFF, 0xFF, 0xFF, 0xFE}));
  EXPECT_EQ(pn::decode_parameter_request(pn::encode(two)), two);

  const std::vector<std::uint8_t> positive{0x05, 0x02, 0x01, 0x01};
  const auto ok = pn::decode_parameter_response(positive);
  ASSERT_TRUE(ok.has_value());
  EXPECT_EQ(ok->id, pn::parameter_response_id::kChangeOk);
  ASSERT_EQ(ok->parameters.size(), 1u);
  EXPECT_EQ(ok->parameters[0].format, pn::parameter_format::kZero);
  EXPECT_EQ(pn::encode(*ok), positive);
  EXPECT_FALSE(pn::error_value(*ok, 0).has_value());

  const std::vector<std::uint8_t> negative{0x09, 0x82, 0x02, 0x02, 0x40, 0x00, 0x44, 0x01, 0x00, 0x02};
  const auto refused = pn::decode_parameter_response(negative);
  ASSERT_TRUE(refused.has_value());
  EXPECT_EQ(refused->id, pn::parameter_response_id::kChangeError);
  ASSERT_EQ(refused->parameters.size(), 2u);
  EXPECT_FALSE(pn::error_value(*refused, 0).has_value());  // executed
  EXPECT_EQ(pn::error_value(*refused, 1), pn::parameter_error::kLimitExceeded);
  EXPECT_EQ(pn::encode(*refused), negative);
  for (std::size_t n = 4; n < negative.size(); ++n)
    EXPECT_FALSE(pn::decode_parameter_response(std::span(negative).first(n)).has_value()) << n;
  auto zero_with_value = negative;
  zero_with_value[5] = 1;  // a Zero value carries no values
  EXPECT_FALSE(pn::decode_parameter_response(zero_with_value).has_value());
  EXPECT_EQ(pn::describe_parameter_error(0x02), "0x02 (low or high limit exceeded)");
  EXPECT_EQ(pn::describe_parameter_error(0x01), "0x01 (parameter value cannot be changed)");
  EXPECT_EQ(pn::describe_parameter_error(0x65), "0x65");  // vendor-specific: the number alone
}

// A number of the gateway file in a parameter's format (decision I33): integers only where integral and in
// the format's range, two's complement in the format's width; FloatingPoint as IEEE single. Table-driven.
TEST(ParameterAccess, AFileValueFitsItsParameterFormatOrIsRefused) {
  struct Case {
    std::uint8_t format;
    double value;
    std::optional<std::uint32_t> raw;
  };
  const Case cases[] = {
      {pn::parameter_format::kUnsigned16, 105.0, 105u},
      {pn::parameter_format::kUnsigned16, 65535.0, 0xFFFFu},
      {pn::parameter_format::kUnsigned16, 65536.0, std::nullopt},
      {pn::parameter_format::kUnsigned16, -1.0, std::nullopt},
      {pn::parameter_format::kUnsigned16, 3.5, std::nullopt},
      {pn::parameter_format::kInteger16, -1.0, 0xFFFFu},
      {pn::parameter_format::kInteger16, -32768.0, 0x8000u},
      {pn::parameter_format::kInteger16, 32768.0, std::nullopt},
      {pn::parameter_format::kInteger32, -2.0, 0xFFFFFFFEu},
      {pn::parameter_format::kUnsigned32, 4294967295.0, 0xFFFFFFFFu},
      {pn::parameter_format::kUnsigned32, 4294967296.0, std::nullopt},
      {pn::parameter_format::kWord, 0x1234, 0x1234u},
      {pn::parameter_format::kFloatingPoint, 3000.0, float_bits(3000.0f)},
      {pn::parameter_format::kFloatingPoint, -0.25, float_bits(-0.25f)},
      {pn::parameter_format::kFloatingPoint, 1e40, std::nullopt},
      {pn::parameter_format::kError, 1.0, std::nullopt},
      {pn::parameter_format::kZero, 0.0, std::nullopt},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(pn::raw_value(c.format, c.value), c.raw) << int{c.format} << " " << c.value;
    if (c.raw) {
      EXPECT_EQ(pn::numeric_value(c.format, *c.raw), c.value) << int{c.format} << " " << c.value;
    }
  }
}

// The emulated drive answers change requests of what it holds: p2000 (FloatingPoint, SINAMICS' 6..210000 rpm)
// is taken and read back, and the drive's speed scaling follows it; p0922 is read-only (0x01); a value
// outside p2000's limits 0x02, another format 0x05, an unknown number 0x00, a subindex 0x03; one refusal in a
// two-parameter request makes the answer 0x82 with 0x40 for the executed one. The AR runs on throughout.
// Decision I33 (what the emulated drive holds and refuses).
TEST(ProfinetDrive, AnswersChangeRequestsOfTheParametersItHolds) {
  Link link;
  ASSERT_TRUE(pn::testing::start_up(*link.controller, link.emulator->device()));
  const auto change = [&](std::uint16_t number, std::uint16_t subindex, pn::ParameterValue value) {
    return link.ask({3, pn::parameter_request_id::kChange, 1, {{0x10, 1, number, subindex}}, {value}});
  };
  const pn::ParameterValue speed_6000{pn::parameter_format::kFloatingPoint, {float_bits(6000.0f)}};
  const pn::ParameterResponse ok = change(2000, 0, speed_6000);
  EXPECT_EQ(ok.id, pn::parameter_response_id::kChangeOk);
  EXPECT_EQ(ok.reference, 3);
  EXPECT_EQ(link.emulator->drive().parameters().reference_speed_rpm, 6000.0);
  const pn::ParameterResponse read =
      link.ask({4, pn::parameter_request_id::kRead, 1, {{0x10, 1, 922, 0}, {0x10, 1, 2000, 0}}, {}});
  EXPECT_EQ(pn::integer_value(read, 0), 3);
  EXPECT_EQ(pn::float_value(read, 1), 6000.0f);

  struct Refused {
    std::uint16_t number;
    std::uint16_t subindex;
    pn::ParameterValue value;
    std::uint16_t error;
  };
  const Refused refused[] = {
      {922, 0, {pn::parameter_format::kUnsigned16, {105}}, pn::parameter_error::kNotChangeable},
      {2000,
       0,
       {pn::parameter_format::kFloatingPoint, {float_bits(250000.0f)}},
       pn::parameter_error::kLimitExceeded},
      {2000,
       0,
       {pn::parameter_format::kFloatingPoint, {float_bits(5.0f)}},
       pn::parameter_error::kLimitExceeded},
      {2000, 0, {pn::parameter_format::kUnsigned16, {3000}}, pn::parameter_error::kIncorrectDataType},
      {2000, 1, speed_6000, pn::parameter_error::kFaultySubindex},
      {9999, 0, speed_6000, pn::parameter_error::kImpermissibleNumber},
  };
  for (const Refused& r : refused) {
    const pn::ParameterResponse answer = change(r.number, r.subindex, r.value);
    EXPECT_EQ(answer.id, pn::parameter_response_id::kChangeError) << r.number;
    EXPECT_EQ(pn::error_value(answer, 0), r.error) << r.number;
  }
  EXPECT_EQ(link.emulator->drive().parameters().reference_speed_rpm, 6000.0);  // none of them changed it

  const pn::ParameterResponse mixed =
      link.ask({6,
                pn::parameter_request_id::kChange,
                1,
                {{0x10, 1, 2000, 0}, {0x10, 1, 922, 0}},
                {{pn::parameter_format::kFloatingPoint, {float_bits(4500.0f)}},
                 {pn::parameter_format::kUnsigned16, {1}}}});
  EXPECT_EQ(mixed.id, pn::parameter_response_id::kChangeError);
  ASSERT_EQ(mixed.parameters.size(), 2u);
  EXPECT_EQ(mixed.parameters[0].format, pn::parameter_format::kZero);
  EXPECT_EQ(pn::error_value(mixed, 1), pn::parameter_error::kNotChangeable);
  EXPECT_EQ(link.emulator->drive().parameters().reference_speed_rpm, 4500.0);
  EXPECT_EQ(link.controller->state(), pn::ControllerArState::kRunning);
}

// The gateway's start-up step (decision I33): p2000 = 3600 read for its format (FloatingPoint), changed and
// read back ""; a refused change names the parameter and the PROFIdrive error; a value that does not fit the
// format is not sent; every request's reference is new (1..255) and mirrored.
TEST(ParameterAccess, WriteParameterChangesReadsBackAndNamesARefusal) {
  Link link;
  ASSERT_TRUE(pn::testing::start_up(*link.controller, link.emulator->device()));
  std::vector<pn::ParameterRequest> sent;
  const pn::ParameterExchange inner = link.exchange();
  const pn::ParameterExchange recorded = [&](const pn::ParameterRequest& request) {
    sent.push_back(request);
    return inner(request);
  };
  std::uint8_t reference = 254;
  EXPECT_EQ(pn::write_parameter({2000, 0, 3600.0}, 1, reference, recorded), "");
  ASSERT_EQ(sent.size(), 3u);  // read, change, read back
  EXPECT_EQ(sent[0].id, pn::parameter_request_id::kRead);
  EXPECT_EQ(sent[1].id, pn::parameter_request_id::kChange);
  EXPECT_EQ(sent[1].values,
            (std::vector<pn::ParameterValue>{{pn::parameter_format::kFloatingPoint, {float_bits(3600.0f)}}}));
  EXPECT_EQ(sent[2].id, pn::parameter_request_id::kRead);
  EXPECT_EQ(sent[0].reference, 255);
  EXPECT_EQ(sent[1].reference, 1);  // 0 is skipped
  EXPECT_EQ(sent[2].reference, 2);
  EXPECT_EQ(link.emulator->drive().parameters().reference_speed_rpm, 3600.0);

  sent.clear();
  EXPECT_EQ(
      pn::write_parameter({922, 0, 105.0}, 1, reference, recorded),
      "p0922 = 105: the drive refused the change, PROFIdrive error 0x01 (parameter value cannot be changed)");
  EXPECT_EQ(sent.size(), 2u);  // no read-back after a refusal
  EXPECT_EQ(
      pn::write_parameter({2000, 0, 250000.0}, 1, reference, recorded),
      "p2000 = 250000: the drive refused the change, PROFIdrive error 0x02 (low or high limit exceeded)");
  sent.clear();
  EXPECT_EQ(pn::write_parameter({922, 0, 3.5}, 1, reference, recorded),
            "p0922 = 3.5 does not fit its format Unsigned16");
  EXPECT_EQ(sent.size(), 1u);  // only the read
  EXPECT_EQ(pn::write_parameter({1082, 0, 3000.0}, 1, reference, recorded),
            "p1082: the drive refused the read, PROFIdrive error 0x00 (impermissible parameter number)");
  EXPECT_EQ(link.emulator->drive().parameters().reference_speed_rpm, 3600.0);

  // A drive that takes the value and keeps another (read back 2999) and one that mirrors a wrong reference.
  const pn::ParameterExchange keeps_another = [](const pn::ParameterRequest& request) {
    pn::ParameterResponse r{request.reference,
                            pn::parameter_response_id::kReadOk,
                            1,
                            {{pn::parameter_format::kUnsigned16, {2999}}}};
    if (request.id == pn::parameter_request_id::kChange)
      r = {request.reference, pn::parameter_response_id::kChangeOk, 1, {{pn::parameter_format::kZero, {}}}};
    return std::variant<pn::ParameterResponse, std::string>(r);
  };
  EXPECT_EQ(pn::write_parameter({1082, 2, 3000.0}, 1, reference, keeps_another),
            "p1082[2] = 3000 reads back as 2999");
  const pn::ParameterExchange stale = [](const pn::ParameterRequest& request) {
    return std::variant<pn::ParameterResponse, std::string>(
        pn::ParameterResponse{static_cast<std::uint8_t>(request.reference + 1),
                              pn::parameter_response_id::kReadOk,
                              1,
                              {{pn::parameter_format::kUnsigned16, {1}}}});
  };
  EXPECT_EQ(pn::write_parameter({1082, 0, 1.0}, 1, reference, stale),
            "p1082: the drive's parameter response does not answer the read request");
}
