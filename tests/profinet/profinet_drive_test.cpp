// The simulated PROFIdrive drive behind a PROFINET IO device (ProfinetDrive), driven by an IoController in
// memory at 1 ms: the telegram-1 start-up sequence through PROFINET (spec 06 §4: STW1 0x047E -> 0x047F,
// ZSW1 bit 2 operation enabled), the speed following NSOLL_A, a drive fault seen as ZSW1 bit 3 by the
// controller, the lost AR ending in the drive's setpoint-timeout fault F08501, and a controller configured
// for another telegram getting the submodule difference.
#include <gtest/gtest.h>

#include <array>

#include "in_memory_start_up.hpp"
#include "sample_frames.hpp"
#include "tomc/drives/profinet_drive.hpp"
#include "tomc/profinet/parameter_access.hpp"

namespace pn = tomc::profinet;
namespace dr = tomc::drives;

namespace {

struct Link {
  pn::IoController controller;
  dr::ProfinetDrive emulator;
  std::uint64_t now_us = 0;

  explicit Link(std::uint16_t configured_telegram = 1)
      : controller(pn::testing::kController, "tomc-gateway", config(configured_telegram),
                   pn::testing::kArUuid),
        emulator(identity(), dr::DeviceConfig{1, 0, {}, {}}, dr::SimulatedDriveParameters{}) {}

  static pn::ControllerDeviceConfig config(std::uint16_t telegram) {
    pn::ControllerDeviceConfig c;
    c.name_of_station = "drive-1";
    c.ip = {{10, 0, 0, 2}, {255, 255, 255, 0}, {}};
    c.modules = dr::profidrive_modules(telegram);
    return c;
  }
  static pn::DeviceIdentity identity() {
    pn::DeviceIdentity i;
    i.name_of_station = "drive-1";
    i.ip = {{10, 0, 0, 2}, {255, 255, 255, 0}, {}};
    i.mac = pn::testing::kDevice;
    return i;
  }
  // One millisecond: controller output -> device, one drive cycle, device input -> controller.
  void cycle(std::uint16_t stw1, std::uint16_t nsoll_a) {
    now_us += 1000;
    const auto out = controller.output_data(dr::kDriveObjectSlot, dr::kTelegramSubslot);
    const std::array<std::uint8_t, 4> setpoint{
        static_cast<std::uint8_t>(stw1 >> 8), static_cast<std::uint8_t>(stw1),
        static_cast<std::uint8_t>(nsoll_a >> 8), static_cast<std::uint8_t>(nsoll_a)};
    if (out.size() == 4) std::copy(setpoint.begin(), setpoint.end(), out.begin());
    std::array<std::uint8_t, 1518> frame{};
    std::size_t n = controller.next_output_frame(frame);
    if (n > 0) emulator.device().on_cyclic(std::span(frame).first(n), now_us);
    emulator.cycle();
    n = emulator.device().next_input_frame(frame);
    if (n > 0) controller.on_input_frame(std::span(frame).first(n), now_us);
  }
  std::uint16_t word(std::size_t at) const {
    const auto in = controller.input_data(dr::kDriveObjectSlot, dr::kTelegramSubslot);
    return in.size() < at + 2 ? 0 : static_cast<std::uint16_t>(in[at] << 8 | in[at + 1]);
  }
  std::uint16_t zsw1() const { return word(0); }
  std::int16_t nist_a() const { return static_cast<std::int16_t>(word(2)); }
};

constexpr std::uint16_t kZsw1OperationEnabled = 1u << 2;
constexpr std::uint16_t kZsw1Fault = 1u << 3;

}  // namespace

// spec 06 §4.3 (STW1 0x047E then 0x047F to S4) and §1.2 (NSOLL_A 0x2000 = 50 % of p2000), over IEC
// 61158-6-10 cyclic frames.
TEST(ProfinetDrive, SwitchOnAndRunThroughProfinet) {
  Link link;
  ASSERT_TRUE(pn::testing::start_up(link.controller, link.emulator.device()));
  EXPECT_TRUE(link.controller.module_diff().empty());
  for (int k = 0; k < 20; ++k)
    link.cycle(0x047E, 0);  // OFF1 inactive request: ready to switch on
  for (int k = 0; k < 20; ++k)
    link.cycle(0x047F, 0);  // enable operation
  EXPECT_NE(link.zsw1() & kZsw1OperationEnabled, 0) << std::hex << link.zsw1();
  EXPECT_EQ(link.emulator.drive().state(), tomc::telegrams::DriveState::kS4Operation);
  // NSOLL_A 0x2000 = 50 % of p2000 (3000 1/min): after 0.5 s the motor turns at 1500 1/min and NIST_A says
  // so.
  for (int k = 0; k < 500; ++k)
    link.cycle(0x047F, 0x2000);
  EXPECT_NEAR(link.emulator.drive().motor_speed_rpm(), 1500.0, 15.0);
  EXPECT_NEAR(link.nist_a(), 0x2000, 0x2000 / 100);
  EXPECT_TRUE(link.controller.input_valid(link.now_us));
}

TEST(ProfinetDrive, DriveFaultReachesTheController) {
  Link link;
  ASSERT_TRUE(pn::testing::start_up(link.controller, link.emulator.device()));
  for (int k = 0; k < 40; ++k)
    link.cycle(k < 20 ? 0x047E : 0x047F, 0);
  ASSERT_NE(link.zsw1() & kZsw1OperationEnabled, 0);
  link.emulator.drive().inject_fault(7900, dr::SimulatedDriveParameters::FaultReaction::kOff2);
  link.cycle(0x047F, 0);
  link.cycle(0x047F, 0);
  EXPECT_NE(link.zsw1() & kZsw1Fault, 0) << std::hex << link.zsw1();  // ZSW1.3 through PROFINET
  EXPECT_EQ(link.zsw1() & kZsw1OperationEnabled, 0);
}

// Decision I14 (no setpoints taken without IOPS GOOD), decision R7 (F08501 setpoint timeout).
TEST(ProfinetDrive, LostArEndsInTheSetpointTimeoutFault) {
  Link link;
  ASSERT_TRUE(pn::testing::start_up(link.controller, link.emulator.device()));
  for (int k = 0; k < 40; ++k)
    link.cycle(k < 20 ? 0x047E : 0x047F, 0);
  link.emulator.device().abort_ar();  // e.g. the device's watchdog after a cable cut
  for (int k = 0; k < 30; ++k)
    link.emulator.cycle();
  EXPECT_EQ(link.emulator.drive().active_fault(), dr::kFaultSetpointTimeout);
}

// IEC 61158-6-10 ModuleDiffBlock (submodule IdentInfo Wrong, IOPS BAD), decision I15.
TEST(ProfinetDrive, ControllerConfiguredForAnotherTelegramGetsTheDifference) {
  Link link(2);  // the controller expects telegram 2; the drive runs telegram 1
  ASSERT_TRUE(pn::testing::start_up(link.controller, link.emulator.device()));
  ASSERT_EQ(link.controller.module_diff().size(), 1u);
  const pn::ModuleDiff& diff = link.controller.module_diff()[0];
  EXPECT_EQ(diff.slot, dr::kDriveObjectSlot);
  EXPECT_EQ(diff.state, pn::ModuleState::kProperModule);
  ASSERT_EQ(diff.submodules.size(), 1u);
  EXPECT_EQ(diff.submodules[0].ident, dr::telegram_submodule_ident(1));
  EXPECT_EQ(diff.submodules[0].ident_info, pn::SubmoduleIdentInfo::kWrong);
  link.cycle(0x047E, 0);
  EXPECT_EQ(link.controller.input_iops(dr::kDriveObjectSlot, dr::kTelegramSubslot), pn::kIoxsBad);
}

// PROFIdrive base-mode parameter access through record index 0xB02E, as `tomc gateway` checks a drive at
// start-up: the request (write) for p0922 and p2000 of DO 1, then the response (read): Unsigned16 telegram
// number, FloatingPoint reference speed; the AR runs on.
// Decision I16 (base-mode parameter request for p0922 and p2000 through record index 0xB02E).
TEST(ProfinetDrive, AnswersP0922AndP2000ThroughParameterAccess) {
  Link link;
  ASSERT_TRUE(pn::testing::start_up(link.controller, link.emulator.device()));
  const pn::ParameterRequest request{
      7, pn::parameter_request_id::kRead, 1, {{0x10, 1, 922, 0}, {0x10, 1, 2000, 0}}, {}};
  const auto written = link.emulator.device().on_rpc(link.controller.record_write_request(
      dr::kDriveObjectSlot, 1, pn::kParameterAccessIndex, pn::encode(request)));
  ASSERT_TRUE(link.controller.on_record_response(written).has_value());
  const auto read = link.emulator.device().on_rpc(
      link.controller.record_read_request(dr::kDriveObjectSlot, 1, pn::kParameterAccessIndex, 240));
  const auto data = link.controller.on_record_response(read);
  ASSERT_TRUE(data.has_value());
  const auto response = pn::decode_parameter_response(*data);
  ASSERT_TRUE(response.has_value());
  EXPECT_EQ(response->reference, 7);  // mirrored
  EXPECT_EQ(response->id, pn::parameter_response_id::kReadOk);
  ASSERT_EQ(response->parameters.size(), 2u);
  EXPECT_EQ(response->parameters[0].format, pn::parameter_format::kUnsigned16);
  EXPECT_EQ(pn::integer_value(*response, 0), 1);  // the emulated drive runs telegram 1
  EXPECT_EQ(pn::float_value(*response, 1), 3000.0f);
  // A read without a pending request and an unknown parameter: refused / error value, and the AR runs on.
  const auto again = link.emulator.device().on_rpc(
      link.controller.record_read_request(dr::kDriveObjectSlot, 1, pn::kParameterAccessIndex, 240));
  EXPECT_FALSE(link.controller.on_record_response(again).has_value());
  EXPECT_EQ(link.controller.last_error().value(), 0xDE80B800u);
  EXPECT_EQ(link.controller.state(), pn::ControllerArState::kRunning);
  const pn::ParameterRequest unknown{8, pn::parameter_request_id::kRead, 1, {{0x10, 1, 9999, 0}}, {}};
  (void)link.controller.on_record_response(link.emulator.device().on_rpc(link.controller.record_write_request(
      dr::kDriveObjectSlot, 1, pn::kParameterAccessIndex, pn::encode(unknown))));
  const auto error = link.controller.on_record_response(link.emulator.device().on_rpc(
      link.controller.record_read_request(dr::kDriveObjectSlot, 1, pn::kParameterAccessIndex, 240)));
  ASSERT_TRUE(error.has_value());
  const auto refused = pn::decode_parameter_response(*error);
  ASSERT_TRUE(refused.has_value());
  EXPECT_EQ(refused->id, pn::parameter_response_id::kReadError);
  EXPECT_EQ(refused->parameters.at(0).format, pn::parameter_format::kError);
  EXPECT_FALSE(pn::integer_value(*refused, 0).has_value());
}

// The codec: the bytes of a p0922 read request (as in the tshark test's record) and of its response; round
// trips; truncated and malformed input refused.
// Decision I16 (PROFIdrive base-mode parameter access), ARCHITECTURE-GUIDE §7 (outside bytes: truncated or
// malformed refused).
TEST(ParameterAccess, BytesRoundTripsAndMalformedInput) {
  const pn::ParameterRequest request{1, pn::parameter_request_id::kRead, 1, {{0x10, 1, 922, 0}}, {}};
  const auto bytes = pn::encode(request);
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{0x01, 0x01, 0x01, 0x01, 0x10, 0x01, 0x03, 0x9A, 0x00, 0x00}));
  EXPECT_EQ(bytes, pn::testing::read_p0922_request().data);
  EXPECT_EQ(pn::decode_parameter_request(bytes), request);
  const pn::ParameterResponse response{
      1, pn::parameter_response_id::kReadOk, 1, {{pn::parameter_format::kUnsigned16, {105}}}};
  const auto answer = pn::encode(response);
  EXPECT_EQ(answer, (std::vector<std::uint8_t>{0x01, 0x01, 0x01, 0x01, 0x06, 0x01, 0x00, 0x69}));
  EXPECT_EQ(pn::decode_parameter_response(answer), response);
  for (std::size_t n = 0; n < bytes.size(); ++n)
    EXPECT_FALSE(pn::decode_parameter_request(std::span(bytes).first(n)).has_value()) << n;
  for (std::size_t n = 0; n < answer.size(); ++n)
    EXPECT_FALSE(pn::decode_parameter_response(std::span(answer).first(n)).has_value()) << n;
  auto unknown_format = answer;
  unknown_format[4] = 0x99;  // a format whose value length is unknown
  EXPECT_FALSE(pn::decode_parameter_response(unknown_format).has_value());
  auto zero_parameters = bytes;
  zero_parameters[3] = 0;
  EXPECT_FALSE(pn::decode_parameter_request(zero_parameters).has_value());
}
