// IoController against IoDevice in memory (frames and RPC packets handed over directly, time in µs): the
// start-up sequence of IEC 61158-6-10 (DCP identify + set IP, Connect, start-up record, PrmEnd,
// ApplicationReady), 4 drives exchanging telegrams at 1 ms, a cut cable (both watchdogs, reconnect), a wrong
// module, a refused Connect, an alarm acknowledged, no allocation in the cyclic calls.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "counting_allocator.hpp"
#include "in_memory_start_up.hpp"
#include "sample_frames.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/io_device.hpp"

namespace pn = tomc::profinet;

namespace {

constexpr std::uint64_t kCycleUs = 1000;

std::vector<pn::ExpectedModule> drive_modules(std::uint32_t telegram_module = 0x100) {
  return {{0, 0, 0x1, {{1, 0x1, pn::SubmoduleDirection::kNoIo, 0, 0}}},
          {0, 1, telegram_module, {{2, 0x101, pn::SubmoduleDirection::kInputOutput, 4, 4}}}};
}

pn::DeviceIdentity device_identity(int index, std::uint32_t telegram_module = 0x100) {
  pn::DeviceIdentity identity;
  identity.name_of_station = "drive-" + std::to_string(index);
  identity.mac = {0x02, 0, 0, 0, 1, static_cast<std::uint8_t>(index)};
  identity.vendor_id = 0x002A;
  identity.device_id = 0x0C01;
  for (const pn::ExpectedModule& module : drive_modules(telegram_module)) {
    pn::DeviceModule real{module.slot, module.ident, {}};
    for (const pn::ExpectedSubmodule& sub : module.submodules) {
      real.submodules.push_back({sub.subslot, sub.ident, sub.direction, sub.input_length, sub.output_length});
    }
    identity.modules.push_back(real);
  }
  return identity;
}

pn::ControllerDeviceConfig device_config(int index) {
  pn::ControllerDeviceConfig config;
  config.name_of_station = "drive-" + std::to_string(index);
  config.ip = {{10, 0, 0, static_cast<std::uint8_t>(10 + index)}, {255, 255, 255, 0}, {}};
  config.modules = drive_modules();
  config.startup_records = {{1, 1, 0xB02E, pn::testing::read_p0922_request().data, 0}};
  config.input_frame_id = static_cast<std::uint16_t>(0x8000 + 2 * index);
  config.output_frame_id = static_cast<std::uint16_t>(0x8001 + 2 * index);
  return config;
}

struct Pair {
  std::unique_ptr<pn::IoController> controller;
  std::unique_ptr<pn::IoDevice> device;
  bool cable = true;
};

Pair make_pair(int index, std::uint32_t real_telegram_module = 0x100) {
  pn::Uuid ar{0x10000000u + static_cast<std::uint32_t>(index), 1, 2, {3}};
  return {
      std::make_unique<pn::IoController>(pn::testing::kController, "tomc-gateway", device_config(index), ar),
      std::make_unique<pn::IoDevice>(device_identity(index, real_telegram_module))};
}

// One cycle of both sides: controller output -> device, device input -> controller.
bool start_up(Pair& pair, std::uint32_t xid = 1) {
  return pn::testing::start_up(*pair.controller, *pair.device, xid);
}

void cycle(Pair& pair, std::uint64_t now_us) {
  std::array<std::uint8_t, 1518> frame{};
  std::size_t n = pair.controller->next_output_frame(frame);
  if (n != 0 && pair.cable) pair.device->on_cyclic(std::span(frame).first(n), now_us);
  n = pair.device->next_input_frame(frame);
  if (n != 0 && pair.cable) pair.controller->on_input_frame(std::span(frame).first(n), now_us);
  pair.device->watchdog_expired(now_us);
  pair.controller->watchdog_expired(now_us);
}

}  // namespace

// IEC 61158-6-10 start-up (DCP naming and IP, Connect, record write, PrmEnd, ApplicationReady), decisions
// I16 and I29; docs/profinet-gateway.md "How it is checked".
TEST(IoController, StartUpNamesConnectsWritesAndRuns) {
  Pair pair = make_pair(1);
  ASSERT_TRUE(start_up(pair));
  // The device got the configured IP through DCP Set, and the start-up record through a write.
  EXPECT_EQ(pair.device->identity().ip, device_config(1).ip);
  EXPECT_EQ(pair.device->state(), pn::ArState::kRunning);
  EXPECT_TRUE(pair.controller->module_diff().empty());
  EXPECT_EQ(pair.controller->ar_count(), 1u);
  EXPECT_EQ(*pair.controller->device_mac(), pair.device->identity().mac);
  // The IOCR offsets the controller chose are the ones the device uses: the same 4 bytes arrive each way.
  const std::array<std::uint8_t, 4> stw1_nsoll{0x04, 0x7F, 0x10, 0x00};
  std::copy(stw1_nsoll.begin(), stw1_nsoll.end(), pair.controller->output_data(1, 2).begin());
  const std::array<std::uint8_t, 4> zsw1_nist{0x0B, 0x37, 0x10, 0x00};
  cycle(pair, 1000);
  std::copy(zsw1_nist.begin(), zsw1_nist.end(), pair.device->input_data(1, 2).begin());
  cycle(pair, 2000);
  const auto at_device = pair.device->output_data(1, 2);
  EXPECT_TRUE(std::equal(at_device.begin(), at_device.end(), stw1_nsoll.begin(), stw1_nsoll.end()));
  const auto at_controller = pair.controller->input_data(1, 2);
  EXPECT_TRUE(std::equal(at_controller.begin(), at_controller.end(), zsw1_nist.begin(), zsw1_nist.end()));
  EXPECT_EQ(pair.controller->input_iops(1, 2), pn::kIoxsGood);
  EXPECT_TRUE(pair.controller->input_valid(2000));
  EXPECT_TRUE(pair.controller->input_valid(1999));  // a time read before the frame: no unsigned wrap
  EXPECT_FALSE(pair.controller->watchdog_expired(1999));
  EXPECT_FALSE(pair.controller->input_valid(2000 + 3 * kCycleUs + 1));  // older than the watchdog
  // Release ends both sides.
  const auto release = pair.controller->release_request();
  EXPECT_TRUE(pair.controller->on_response(pair.device->on_rpc(release)));
  EXPECT_EQ(pair.device->state(), pn::ArState::kNone);
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kOffline);
}

// Decision I7 (in memory: watchdog factor 3, its exact timing), docs/profinet-gateway.md "How it is
// checked" (the AR ends after the 4th silent ms).
TEST(IoController, FourDrivesAtOneMillisecondThenACableCutAndReconnect) {
  std::vector<Pair> drives;
  for (int i = 0; i < 4; ++i) {
    drives.push_back(make_pair(i));
    ASSERT_TRUE(start_up(drives.back())) << i;
  }
  std::uint64_t now = 0;
  // 100 cycles: each drive echoes a counter the controller sends; the answer arrives in the same cycle
  // (the device's frame follows the controller's).
  for (int k = 0; k < 100; ++k) {
    now += kCycleUs;
    for (std::size_t i = 0; i < drives.size(); ++i) {
      drives[i].controller->output_data(1, 2)[3] = static_cast<std::uint8_t>(k + i);
      cycle(drives[i], now);
      std::copy_n(drives[i].device->output_data(1, 2).begin(), 4, drives[i].device->input_data(1, 2).begin());
      ASSERT_TRUE(drives[i].controller->input_valid(now));
    }
  }
  for (std::size_t i = 0; i < drives.size(); ++i) {
    EXPECT_EQ(drives[i].controller->input_data(1, 2)[3],
              static_cast<std::uint8_t>(98 + i));  // one cycle behind
    EXPECT_EQ(drives[i].controller->last_input_status().cycle_counter, static_cast<std::uint16_t>(100 * 32));
  }
  // Cable of drive 2 cut: after watchdog factor 3 x 1 ms without frames both sides end the AR (the others
  // keep running); then the controller starts again with DCP and reconnects.
  drives[2].cable = false;
  int cycles_to_loss = 0;
  while (drives[2].controller->state() == pn::ControllerArState::kRunning && cycles_to_loss < 10) {
    now += kCycleUs;
    for (Pair& pair : drives)
      cycle(pair, now);
    ++cycles_to_loss;
  }
  EXPECT_EQ(cycles_to_loss, 4);  // 3 ms of silence is still tolerated; the 4th millisecond is not
  EXPECT_EQ(drives[2].device->state(), pn::ArState::kNone);
  for (int i : {0, 1, 3})
    EXPECT_EQ(drives[i].controller->state(), pn::ControllerArState::kRunning) << i;
  drives[2].cable = true;
  ASSERT_TRUE(start_up(drives[2], 100));
  EXPECT_EQ(drives[2].controller->ar_count(), 2u);
  now += kCycleUs;
  cycle(drives[2], now);
  EXPECT_TRUE(drives[2].controller->input_valid(now));
}

// IEC 61158-6-10 ModuleDiffBlock (WrongModule) and IOPS BAD for its data, decision I15.
TEST(IoController, WrongModuleIsReportedWithItsDifference) {
  Pair pair = make_pair(1, 0x102);
  ASSERT_TRUE(start_up(pair));
  ASSERT_EQ(pair.controller->module_diff().size(), 1u);
  const pn::ModuleDiff& diff = pair.controller->module_diff()[0];
  EXPECT_EQ(diff.slot, 1);
  EXPECT_EQ(diff.ident, 0x102u);
  EXPECT_EQ(diff.state, pn::ModuleState::kWrongModule);
  cycle(pair, 1000);
  EXPECT_EQ(pair.controller->input_iops(1, 2), pn::kIoxsBad);
}

// IEC 61158-6-10 PNIOStatus DB 81 40 04 (no AR resources for a second controller); DCP Identify by name.
TEST(IoController, RefusedConnectIsReportedAndIdentifyIgnoresOtherNames) {
  Pair first = make_pair(1);
  ASSERT_TRUE(start_up(first));
  // A second controller (other AR UUID) for the same device: the device refuses (no AR resources).
  pn::IoController second(pn::testing::kController, "other", device_config(1), pn::Uuid{0x77, 0, 0, {}});
  ASSERT_TRUE(second.on_dcp(first.device->on_dcp(second.identify_request(5)), 6).empty());
  EXPECT_FALSE(second.on_connect_response(first.device->on_rpc(second.connect_request())));
  EXPECT_EQ(second.last_error(), (pn::PnioStatus{0xDB, 0x81, 0x40, 0x04}));
  EXPECT_EQ(second.state(), pn::ControllerArState::kOffline);
  // An Identify answer of another station is not taken.
  pn::IoController third(pn::testing::kController, "x", device_config(7), pn::Uuid{0x78, 0, 0, {}});
  EXPECT_TRUE(third.on_dcp(first.device->on_dcp(second.identify_request(9)), 10).empty());
  EXPECT_FALSE(third.device_mac());
  EXPECT_TRUE(third.connect_request().empty());
}

namespace {

// An RTA frame of the device to the controller, as bytes.
struct RawAlarm {
  std::array<std::uint8_t, 256> bytes{};
  std::size_t size = 0;
  std::span<const std::uint8_t> frame() const { return std::span(bytes).first(size); }
};

RawAlarm raw_alarm(const Pair& pair, const pn::RtaFrame& rta) {
  RawAlarm raw;
  EXPECT_EQ(pn::encode({pn::testing::kController, pair.device->identity().mac, pn::VlanTag{6, 0}}, rta,
                       raw.bytes, raw.size),
            pn::ProfinetError::kNone);
  return raw;
}

// What the controller answers to one: the transport ACK and the AlarmAck DATA.
struct AlarmAnswer {
  std::size_t frames = 0;
  std::vector<std::uint8_t> ack;
  std::vector<std::uint8_t> alarm_ack;
};

AlarmAnswer offer(Pair& pair, const pn::RtaFrame& rta, std::uint64_t now_us = 0) {
  const RawAlarm raw = raw_alarm(pair, rta);
  std::array<std::uint8_t, 128> ack{};
  std::array<std::uint8_t, 128> alarm_ack{};
  std::size_t ack_bytes = 0;
  std::size_t alarm_ack_bytes = 0;
  AlarmAnswer answer;
  answer.frames = pair.controller->on_alarm(raw.frame(), ack, alarm_ack, ack_bytes, alarm_ack_bytes, now_us);
  answer.ack.assign(ack.begin(), ack.begin() + static_cast<long>(ack_bytes));
  answer.alarm_ack.assign(alarm_ack.begin(), alarm_ack.begin() + static_cast<long>(alarm_ack_bytes));
  return answer;
}

pn::RtaFrame decoded_rta(const std::vector<std::uint8_t>& bytes) {
  pn::RtaFrame frame;
  EXPECT_EQ(pn::decode_rta(bytes, frame), pn::ProfinetError::kNone);
  return frame;
}

}  // namespace

// IEC 61158-6-10 ObjectUUID: the Connect goes to instance 1 of the VendorID/DeviceID that the DCP Identify
// answer's DeviceID block named (0x002A/0x0C01 here), the later Write and Control requests too.
TEST(IoController, RpcRequestsAddressTheDeviceOfTheDcpAnswer) {
  Pair pair = make_pair(1);
  const auto identified = pair.device->on_dcp(pair.controller->identify_request(1));
  (void)pair.controller->on_dcp(identified, 2);
  const pn::Uuid expected = pn::pnio_object_uuid(1, 0x0C01, 0x002A);
  EXPECT_EQ(pair.controller->device_object(), expected);
  const auto connect = pair.controller->connect_request();
  ASSERT_GE(connect.size(), 24u);
  // Little-endian drep: DEA00000 6C97 11D1 reversed, then 8271 0001 0C01 002A as they are.
  EXPECT_EQ(std::vector<std::uint8_t>(connect.begin() + 8, connect.begin() + 24),
            (std::vector<std::uint8_t>{0x00, 0x00, 0xA0, 0xDE, 0x97, 0x6C, 0xD1, 0x11, 0x82, 0x71, 0x00, 0x01,
                                       0x0C, 0x01, 0x00, 0x2A}));
  ASSERT_TRUE(pair.controller->on_connect_response(pair.device->on_rpc(connect)));
  const auto record = pair.controller->next_request();
  pn::WireReader in(record);
  EXPECT_EQ(pn::decode_rpc(in).header.object, expected);
  ASSERT_TRUE(pair.controller->on_response(pair.device->on_rpc(record)));
  const auto prm_end = pair.controller->next_request();
  pn::WireReader prm_in(prm_end);
  EXPECT_EQ(pn::decode_rpc(prm_in).header.object, expected);
  EXPECT_TRUE(pair.controller->on_response(pair.device->on_rpc(prm_end)));
  EXPECT_EQ(pair.controller->last_reject(), 0u);
}

// A DCP answer without the DeviceID block leaves the object's IDs 0: the device rejects the Connect
// (nca_s_unsupported_type), the controller reports it in last_reject() and goes back to kOffline.
// Decision I27 (the RPC object UUID from the DCP DeviceID block; a Reject reported in last_reject()).
TEST(IoController, ARejectedConnectIsReported) {
  Pair pair = make_pair(1);
  const auto identified = pair.device->on_dcp(pair.controller->identify_request(1));
  pn::WireReader in(identified);
  const pn::EthernetHeader ethernet = pn::decode_ethernet(in);
  pn::DcpMessage answer = pn::decode_dcp(in);
  ASSERT_TRUE(in.ok());
  answer.fields.vendor_id.reset();
  answer.fields.device_id.reset();
  std::vector<std::uint8_t> without_ids(1514);
  pn::WireWriter out(without_ids);
  pn::encode(ethernet, answer, out);
  without_ids.resize(out.position());
  (void)pair.controller->on_dcp(without_ids, 2);
  EXPECT_EQ(pair.controller->device_object(), pn::pnio_object_uuid(1, 0, 0));
  EXPECT_FALSE(pair.controller->on_connect_response(pair.device->on_rpc(pair.controller->connect_request())));
  EXPECT_EQ(pair.controller->last_reject(), pn::kNcaUnsupportedType);
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kOffline);
  EXPECT_EQ(pair.device->state(), pn::ArState::kNone);
  // Identified again with the block: the same controller connects.
  EXPECT_TRUE(start_up(pair, 5));
  EXPECT_EQ(pair.controller->last_reject(), 0u);
}

// A device's diagnosis alarm: the controller answers with an RTA ACK and an AlarmAck (block sequence number
// and subslot of the notification), counts and keeps it, and acknowledges no AlarmAck (decisions I19, I28).
TEST(IoController, AlarmIsAcknowledged) {
  Pair pair = make_pair(1);
  ASSERT_TRUE(start_up(pair));
  std::array<std::uint8_t, 256> alarm{};
  std::size_t alarm_bytes = 0;
  const pn::RtaFrame notification = pn::testing::diagnosis_alarm();
  ASSERT_EQ(pn::encode({pn::testing::kController, pair.device->identity().mac, pn::VlanTag{6, 0}},
                       notification, alarm, alarm_bytes),
            pn::ProfinetError::kNone);
  std::array<std::uint8_t, 128> transport{};
  std::array<std::uint8_t, 128> ack{};
  std::size_t transport_bytes = 0;
  std::size_t ack_bytes = 0;
  ASSERT_EQ(pair.controller->on_alarm(std::span(alarm).first(alarm_bytes), transport, ack, transport_bytes,
                                      ack_bytes, 0),
            2u);
  pn::RtaFrame decoded;
  ASSERT_EQ(pn::decode_rta(std::span(transport).first(transport_bytes), decoded), pn::ProfinetError::kNone);
  EXPECT_EQ(decoded.pdu_type, pn::RtaPduType::kAck);
  EXPECT_EQ(decoded.ack_sequence, notification.send_sequence);
  EXPECT_EQ(decoded.destination_endpoint, notification.source_endpoint);
  ASSERT_EQ(pn::decode_rta(std::span(ack).first(ack_bytes), decoded), pn::ProfinetError::kNone);
  EXPECT_TRUE(decoded.block.is_ack);
  EXPECT_EQ(decoded.block.sequence_number(), 5);
  EXPECT_EQ(decoded.block.subslot, 2);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 1u);
  EXPECT_EQ(pair.controller->last_alarm()->alarm_type, pn::alarm_type::kDiagnosis);
  // An AlarmAck (from the device's direction) or a non-alarm frame is not acknowledged again.
  EXPECT_EQ(pair.controller->on_alarm(std::span(ack).first(ack_bytes), transport, ack, transport_bytes,
                                      ack_bytes, 0),
            0u);
}

// IEC 61158-6-10 RTA (as p-net's APMR/APMS): a DATA with the SendSeqNum of the last one taken is a resend
// after a lost ACK. It is acknowledged again, and our AlarmAck DATA goes again with its own SendSeqNum
// (0xFFFF: the first of an AR) while the device has not acknowledged it, at most RTARetries (3) times; the
// notification is counted and kept once. High and low priority have their own sequence numbers.
// Decision I28 (RTA duplicates and resends).
TEST(IoController, ARepeatedAlarmIsAcknowledgedAgainButCountedOnce) {
  Pair pair = make_pair(1);
  ASSERT_TRUE(start_up(pair));
  pn::RtaFrame notification = pn::testing::diagnosis_alarm();  // high, SendSeqNum 0, alarm sequence 5
  const AlarmAnswer first = offer(pair, notification);
  ASSERT_EQ(first.frames, 2u);
  EXPECT_EQ(decoded_rta(first.ack).pdu_type, pn::RtaPduType::kAck);
  EXPECT_EQ(decoded_rta(first.ack).ack_sequence, 0u);
  EXPECT_EQ(decoded_rta(first.ack).send_sequence, 0xFFFEu);  // nothing sent yet
  const pn::RtaFrame alarm_ack = decoded_rta(first.alarm_ack);
  EXPECT_EQ(alarm_ack.send_sequence, 0xFFFFu);
  EXPECT_EQ(alarm_ack.ack_sequence, 0u);
  EXPECT_TRUE(alarm_ack.tack);
  EXPECT_TRUE(pair.controller->alarm_ack_pending(true));
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 1u);
  // Three resends: each time the transport ACK again (its SendSeqNum now our last DATA's, 0xFFFF) and our
  // AlarmAck byte for byte; the fourth gets the transport ACK only.
  for (int resend = 1; resend <= 4; ++resend) {
    const AlarmAnswer again = offer(pair, notification);
    EXPECT_EQ(again.frames, resend <= 3 ? 2u : 1u) << resend;
    EXPECT_EQ(decoded_rta(again.ack).pdu_type, pn::RtaPduType::kAck);
    EXPECT_EQ(decoded_rta(again.ack).ack_sequence, 0u);
    EXPECT_EQ(decoded_rta(again.ack).send_sequence, 0xFFFFu);
    EXPECT_EQ(again.alarm_ack, resend <= 3 ? first.alarm_ack : std::vector<std::uint8_t>{}) << resend;
  }
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 1u);
  // The device's ACK of our AlarmAck (AckSeqNum 0xFFFF): nothing to send, nothing pending.
  pn::RtaFrame device_ack = notification;
  device_ack.pdu_type = pn::RtaPduType::kAck;
  device_ack.tack = false;
  device_ack.has_block = false;
  device_ack.ack_sequence = 0xFFFF;
  EXPECT_EQ(offer(pair, device_ack).frames, 0u);
  EXPECT_FALSE(pair.controller->alarm_ack_pending(true));
  // A resend now gets the transport ACK only: our AlarmAck arrived.
  EXPECT_EQ(offer(pair, notification).frames, 1u);
  // The next notification (SendSeqNum 1, alarm sequence 6) is new; our AlarmAck is SendSeqNum 0.
  notification.send_sequence = 1;
  notification.ack_sequence = 0xFFFF;
  notification.block.specifier = 0x0800 | 0x2000 | 6;
  const AlarmAnswer second = offer(pair, notification);
  ASSERT_EQ(second.frames, 2u);
  EXPECT_EQ(decoded_rta(second.alarm_ack).send_sequence, 0u);
  EXPECT_EQ(decoded_rta(second.alarm_ack).block.sequence_number(), 6);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 2u);
  EXPECT_EQ(pair.controller->last_alarm()->sequence_number(), 6);
  // Low priority: its own numbers, so its SendSeqNum 0 is new and our first low AlarmAck is 0xFFFF again.
  notification.frame_id = pn::kFrameIdAlarmLow;
  notification.block.high_priority = false;
  notification.send_sequence = 0;
  const AlarmAnswer low = offer(pair, notification);
  ASSERT_EQ(low.frames, 2u);
  EXPECT_EQ(decoded_rta(low.alarm_ack).send_sequence, 0xFFFFu);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 3u);
  EXPECT_TRUE(pair.controller->alarm_ack_pending(false));
  EXPECT_TRUE(pair.controller->alarm_ack_pending(true));  // SendSeqNum 0 of the high channel
  // The cyclic thread answers alarms: a new notification and its resend allocate nothing.
  notification.send_sequence = 1;
  const RawAlarm raw = raw_alarm(pair, notification);
  std::array<std::uint8_t, 128> ack{};
  std::array<std::uint8_t, 128> alarm_ack_out{};
  std::size_t ack_n = 0;
  std::size_t alarm_ack_n = 0;
  const std::uint64_t before = tomc::testing::allocation_count();
  EXPECT_EQ(pair.controller->on_alarm(raw.frame(), ack, alarm_ack_out, ack_n, alarm_ack_n, 0), 2u);
  EXPECT_EQ(pair.controller->on_alarm(raw.frame(), ack, alarm_ack_out, ack_n, alarm_ack_n, 0), 2u);
  EXPECT_EQ(tomc::testing::allocation_count() - before, 0u);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 4u);
}

// The alarm CR exists from the Connect on: a notification while the start-up records are written is
// answered (and counted once when the device repeats it after ApplicationReady); before the Connect there
// is no AR to take it.
// Decision I28 (alarms during start-up).
TEST(IoController, AnAlarmDuringStartUpIsAnswered) {
  Pair pair = make_pair(1);
  const pn::RtaFrame notification = pn::testing::diagnosis_alarm();
  (void)pair.controller->on_dcp(pair.device->on_dcp(pair.controller->identify_request(1)), 2);
  EXPECT_EQ(offer(pair, notification).frames, 0u);  // kOffline: no Connect yet
  ASSERT_TRUE(pair.controller->on_connect_response(pair.device->on_rpc(pair.controller->connect_request())));
  ASSERT_EQ(pair.controller->state(), pn::ControllerArState::kParameterizing);
  EXPECT_EQ(offer(pair, notification).frames, 2u);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 1u);
  for (int guard = 0; guard < 4 && pair.controller->state() != pn::ControllerArState::kWaitApplicationReady;
       ++guard) {
    ASSERT_TRUE(pair.controller->on_response(pair.device->on_rpc(pair.controller->next_request())));
  }
  const auto ready = pair.device->take_application_ready();
  ASSERT_TRUE(ready);
  EXPECT_FALSE(pair.controller->on_application_ready(*ready).empty());
  ASSERT_EQ(pair.controller->state(), pn::ControllerArState::kRunning);
  EXPECT_EQ(offer(pair, notification).frames, 2u);  // the device's resend: ACK and AlarmAck again
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 1u);
  // A new AR (reconnect) starts the sequence numbers afresh: SendSeqNum 0 is new again.
  pair.controller->abort_ar();
  pair.device->abort_ar();
  ASSERT_TRUE(start_up(pair, 7));
  const AlarmAnswer fresh = offer(pair, notification);
  EXPECT_EQ(fresh.frames, 2u);
  EXPECT_EQ(decoded_rta(fresh.alarm_ack).send_sequence, 0xFFFFu);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 2u);
}

namespace {

// A pair whose Connect offers RTATimeoutFactor `factor` (× 100 ms) and RTARetries `retries`.
Pair make_rta_pair(std::uint16_t factor, std::uint16_t retries) {
  pn::ControllerDeviceConfig config = device_config(1);
  config.rta_timeout_factor = factor;
  config.rta_retries = retries;
  return {std::make_unique<pn::IoController>(pn::testing::kController, "tomc-gateway", config,
                                             pn::Uuid{0x10000001u, 1, 2, {3}}),
          std::make_unique<pn::IoDevice>(device_identity(1))};
}

// What the RTA timers of one cycle did: each priority's action and the resent frame.
struct TimerCycle {
  pn::AlarmTimerAction high = pn::AlarmTimerAction::kNone;
  pn::AlarmTimerAction low = pn::AlarmTimerAction::kNone;
  std::vector<std::uint8_t> resent;
};

TimerCycle run_timers(Pair& pair, std::uint64_t now_us) {
  TimerCycle result;
  std::array<std::uint8_t, 128> out{};
  for (const bool high : {true, false}) {
    std::size_t bytes = 0;
    const pn::AlarmTimerAction action = pair.controller->alarm_timer(high, now_us, out, bytes);
    (high ? result.high : result.low) = action;
    if (bytes > 0) result.resent.assign(out.begin(), out.begin() + static_cast<long>(bytes));
  }
  return result;
}

// The device's transport ACK of our DATA with this SendSeqNum (high priority).
pn::RtaFrame device_ack_of(std::uint16_t our_send_sequence) {
  pn::RtaFrame ack = pn::testing::diagnosis_alarm();
  ack.pdu_type = pn::RtaPduType::kAck;
  ack.tack = false;
  ack.has_block = false;
  ack.ack_sequence = our_send_sequence;
  return ack;
}

// The high-priority notification after diagnosis_alarm(): its SendSeqNum, AckSeqNum and alarm sequence.
pn::RtaFrame next_notification(std::uint16_t send_sequence, std::uint16_t ack_sequence, std::uint16_t alarm) {
  pn::RtaFrame notification = pn::testing::diagnosis_alarm();
  notification.send_sequence = send_sequence;
  notification.ack_sequence = ack_sequence;
  notification.block.specifier = static_cast<std::uint16_t>(0x0800 | 0x2000 | alarm);
  return notification;
}

// The high-priority timer resends `sent`'s AlarmAck at `due_us`, not 1 µs earlier.
void expect_resent_at(Pair& pair, const AlarmAnswer& sent, std::uint64_t due_us) {
  EXPECT_EQ(run_timers(pair, due_us - 1).high, pn::AlarmTimerAction::kNone);
  const TimerCycle resent = run_timers(pair, due_us);
  EXPECT_EQ(resent.high, pn::AlarmTimerAction::kResend);
  EXPECT_EQ(resent.resent, sent.alarm_ack);
}

}  // namespace

// IEC 61158-6-10 APMS (as p-net's pf_alarm_apms_timeout on the device's side): our AlarmAck DATA that the
// device does not acknowledge is sent again RTATimeoutFactor × 100 ms after it was last sent. Factor 2 at a
// 1 ms cycle: the AlarmAck of cycle 10 is lost, resent in cycle 210 and 410 (not one cycle earlier), the
// device's ACK in cycle 450 stops it; the next AlarmAck (SendSeqNum 0) is acknowledged by the AckSeqNum of
// the device's next notification instead. The AR runs on throughout.
TEST(IoController, ALostAlarmAckIsResentAfterTheRtaTimeoutUntilTheDeviceAcknowledges) {
  Pair pair = make_rta_pair(2, 3);
  ASSERT_TRUE(start_up(pair));
  EXPECT_EQ(pair.device->connection().alarm_cr.rta_timeout_factor, 2);  // our AlarmCRBlock says so
  EXPECT_EQ(pair.device->connection().alarm_cr.rta_retries, 3);
  EXPECT_EQ(pair.controller->alarm_timeout_us(), 200'000u);
  const pn::RtaFrame notification = pn::testing::diagnosis_alarm();  // high, SendSeqNum 0
  std::vector<std::uint8_t> first;
  std::vector<int> resend_cycles;
  for (int k = 1; k <= 1500; ++k) {
    const std::uint64_t now = static_cast<std::uint64_t>(k) * kCycleUs;
    cycle(pair, now);
    if (k == 10) first = offer(pair, notification, now).alarm_ack;  // sent, lost on its way
    if (k == 450) {
      EXPECT_EQ(offer(pair, device_ack_of(0xFFFF), now).frames, 0u);
    }
    const TimerCycle timers = run_timers(pair, now);
    EXPECT_EQ(timers.low, pn::AlarmTimerAction::kNone) << k;
    if (timers.high == pn::AlarmTimerAction::kResend) {
      resend_cycles.push_back(k);
      EXPECT_EQ(timers.resent, first) << k;  // byte for byte: same SendSeqNum 0xFFFF
    } else {
      EXPECT_EQ(timers.high, pn::AlarmTimerAction::kNone) << k;
    }
  }
  EXPECT_EQ(decoded_rta(first).send_sequence, 0xFFFFu);
  EXPECT_EQ(resend_cycles, (std::vector<int>{210, 410}));
  EXPECT_FALSE(pair.controller->alarm_ack_pending(true));
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kRunning);
  // The next notification's AlarmAck (SendSeqNum 0) is lost too: resent 200 ms later; the device's third
  // notification carries AckSeqNum 0, which acknowledges it, so it is not resent again.
  std::uint64_t now = 2'000'000;
  const AlarmAnswer second = offer(pair, next_notification(1, 0xFFFF, 6), now);
  ASSERT_EQ(second.frames, 2u);
  EXPECT_EQ(decoded_rta(second.alarm_ack).send_sequence, 0u);
  expect_resent_at(pair, second, now + 200'000);
  now += 250'000;
  const AlarmAnswer third = offer(pair, next_notification(2, 0, 7), now);
  ASSERT_EQ(third.frames, 2u);
  EXPECT_EQ(decoded_rta(third.alarm_ack).send_sequence, 1u);
  // From now on only SendSeqNum 1 waits: its timeout runs from `now`, not from the resend of 0.
  expect_resent_at(pair, third, now + 200'000);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 3u);
}

// After RTARetries resends without the device's acknowledge, one more timeout ends the AR (APMS
// TimerExpired with the retry counter at 0: A_Data.cnf(-), the AR aborted with "AR alarm-ack-send.cnf(-)",
// p-net PNET_ERROR_CODE_2_ABORT_AR_ALARM_ACK_SEND_CNF_NEG). Factor 1, retries 3, 1 ms cycles: the AlarmAck of
// cycle 5 is resent in cycles 105, 205 and 305, the AR ends in cycle 405 (kOffline, PNIOStatus 0xCF81FD09),
// the cyclic frames stop; the same controller reconnects and its channels start afresh. Low priority here;
// a repeated notification's resend counts towards the same RTARetries and restarts the timeout (I28).
// IEC 61158-6-10 APMS (RTARetries, TimerExpired: the AR aborted), decisions I28 and I30.
TEST(IoController, RtaRetriesUnacknowledgedResendsEndTheAr) {
  Pair pair = make_rta_pair(1, 3);
  ASSERT_TRUE(start_up(pair));
  pn::RtaFrame notification = pn::testing::diagnosis_alarm();
  notification.frame_id = pn::kFrameIdAlarmLow;
  notification.block.high_priority = false;
  std::vector<int> resends;
  int aborted_in = 0;
  for (int k = 1; k <= 600 && aborted_in == 0; ++k) {
    const std::uint64_t now = static_cast<std::uint64_t>(k) * kCycleUs;
    cycle(pair, now);
    if (k == 5) {
      ASSERT_EQ(offer(pair, notification, now).frames, 2u);
    }
    const TimerCycle timers = run_timers(pair, now);
    EXPECT_EQ(timers.high, pn::AlarmTimerAction::kNone) << k;
    if (timers.low == pn::AlarmTimerAction::kResend) resends.push_back(k);
    if (timers.low == pn::AlarmTimerAction::kAbort) aborted_in = k;
    if (aborted_in == 0) {
      EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kRunning) << k;
    }
  }
  EXPECT_EQ(resends, (std::vector<int>{105, 205, 305}));
  EXPECT_EQ(aborted_in, 405);
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kOffline);
  EXPECT_EQ(pair.controller->last_error().value(), 0xCF81FD09u);
  EXPECT_EQ(pn::kAlarmAckSendTimeoutStatus.value(), 0xCF81FD09u);
  std::array<std::uint8_t, 1518> frame{};
  EXPECT_EQ(pair.controller->next_output_frame(frame), 0u);  // the device's watchdog will end its side
  EXPECT_EQ(run_timers(pair, 10'000'000).low, pn::AlarmTimerAction::kNone);  // nothing after the end
  // Reconnect (as the gateway does after a lost AR): a new AR, fresh channels.
  pair.device->abort_ar();
  ASSERT_TRUE(start_up(pair, 9));
  EXPECT_FALSE(pair.controller->alarm_ack_pending(false));
  std::uint64_t now = 20'000'000;
  const AlarmAnswer fresh = offer(pair, notification, now);
  ASSERT_EQ(fresh.frames, 2u);
  EXPECT_EQ(decoded_rta(fresh.alarm_ack).send_sequence, 0xFFFFu);
  // The device repeats its notification 50 ms later (our ACK lost): the AlarmAck again (I28), which counts
  // as the first of the three resends and restarts the timeout from there.
  EXPECT_EQ(offer(pair, notification, now + 50'000).alarm_ack, fresh.alarm_ack);
  EXPECT_EQ(run_timers(pair, now + 149'999).low, pn::AlarmTimerAction::kNone);
  EXPECT_EQ(run_timers(pair, now + 150'000).low, pn::AlarmTimerAction::kResend);
  EXPECT_EQ(run_timers(pair, now + 250'000).low, pn::AlarmTimerAction::kResend);
  EXPECT_EQ(offer(pair, notification, now + 260'000).alarm_ack, std::vector<std::uint8_t>{});  // none left
  EXPECT_EQ(run_timers(pair, now + 349'999).low, pn::AlarmTimerAction::kNone);
  EXPECT_EQ(run_timers(pair, now + 350'000).low, pn::AlarmTimerAction::kAbort);
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kOffline);
  EXPECT_EQ(pair.controller->alarms_acknowledged(), 2u);
}

// The timer runs in the cyclic thread: its calls allocate nothing, whether idle, resending or ending the AR.
// Decision I30 (the RTA timer is called by the cyclic thread), decision I3 (no allocation there).
TEST(IoController, TheRtaTimerDoesNotAllocate) {
  Pair pair = make_rta_pair(1, 3);
  ASSERT_TRUE(start_up(pair));
  ASSERT_EQ(offer(pair, pn::testing::diagnosis_alarm(), 0).frames, 2u);
  std::array<std::uint8_t, 128> out{};
  int resends = 0;
  int aborts = 0;
  const std::uint64_t before = tomc::testing::allocation_count();
  for (std::uint64_t now = 0; now <= 500'000; now += kCycleUs) {
    for (const bool high : {true, false}) {
      std::size_t bytes = 0;
      const pn::AlarmTimerAction action = pair.controller->alarm_timer(high, now, out, bytes);
      resends += action == pn::AlarmTimerAction::kResend;
      aborts += action == pn::AlarmTimerAction::kAbort;
    }
  }
  EXPECT_EQ(tomc::testing::allocation_count() - before, 0u);
  EXPECT_EQ(resends, 3);
  EXPECT_EQ(aborts, 1);
}

// Decision I3 (cyclic frames without allocation), decision I10 (the cyclic thread owns running ARs).
TEST(IoController, CyclicCallsDoNotAllocate) {
  Pair pair = make_pair(1);
  ASSERT_TRUE(start_up(pair));
  std::array<std::uint8_t, 1518> frame{};
  std::uint32_t bad = 0;
  std::uint64_t now = 0;
  const std::uint64_t before = tomc::testing::allocation_count();
  for (int k = 0; k < 10000; ++k) {
    now += kCycleUs;
    std::size_t n = pair.controller->next_output_frame(frame);
    bad += n == 0;
    pair.controller->output_data(1, 2)[0] = static_cast<std::uint8_t>(k);
    n = pair.device->next_input_frame(frame);
    bad += !pair.controller->on_input_frame(std::span(frame).first(n), now);
    bad += !pair.controller->input_valid(now);
    bad += pair.controller->watchdog_expired(now);
  }
  EXPECT_EQ(tomc::testing::allocation_count() - before, 0u);
  EXPECT_EQ(bad, 0u);
}

// Decision I35, IEC 61158-6-10 RTA-ERR-PDU: when the RTA timer ends the AR (factor 1, retries 3: the
// AlarmAck of cycle 5 resent in 105, 205, 305, the end in 405), the timer's buffer holds an ERR-RTA-PDU for
// the device: PDUType 4, the device's alarm reference as destination (the notification's source endpoint),
// the same priority's FrameID and VLAN priority, VarPart the PNIOStatus of the end (0xCF81FD09, "AR
// alarm-ack-send.cnf(-)": the DATA left unacknowledged is our AlarmAck), as the device would read it.
TEST(IoController, TheRtaTimerSendsAnErrRtaPduBeforeItEndsTheAr) {
  Pair pair = make_rta_pair(1, 3);
  ASSERT_TRUE(start_up(pair));
  const pn::RtaFrame notification = pn::testing::diagnosis_alarm();  // high priority, endpoints 1 ← 3
  ASSERT_EQ(offer(pair, notification, 5 * kCycleUs).frames, 2u);
  std::vector<std::uint8_t> error_frame;
  int ended_in = 0;
  for (int k = 6; k <= 500 && ended_in == 0; ++k) {
    const TimerCycle timers = run_timers(pair, static_cast<std::uint64_t>(k) * kCycleUs);
    if (timers.high == pn::AlarmTimerAction::kAbort) {
      ended_in = k;
      error_frame = timers.resent;
    }
  }
  EXPECT_EQ(ended_in, 405);
  ASSERT_FALSE(error_frame.empty());
  const pn::RtaFrame error = decoded_rta(error_frame);
  EXPECT_EQ(error.frame_id, pn::kFrameIdAlarmHigh);
  EXPECT_EQ(error.pdu_type, pn::RtaPduType::kError);
  EXPECT_EQ(error.destination_endpoint, notification.source_endpoint);
  EXPECT_EQ(error.source_endpoint, notification.destination_endpoint);
  EXPECT_FALSE(error.has_block);
  EXPECT_EQ(error.error.value(), 0xCF81FD09u);
  EXPECT_EQ(error.ack_sequence, notification.send_sequence);
  // Ethernet: to the device, from us, VLAN priority 6 (high); then FrameID 0xFC01, the endpoints, PDUType
  // 0x14 (ERR, version 1) at byte 24, AddFlags, SendSeqNum, AckSeqNum, VarPartLen 4 and the status bytes.
  ASSERT_GE(error_frame.size(), 36u);
  EXPECT_TRUE(std::equal(pair.device->identity().mac.begin(), pair.device->identity().mac.end(),
                         error_frame.begin()));
  EXPECT_EQ(error_frame[14] >> 5, 6);
  EXPECT_EQ(error_frame[24], 0x14);
  EXPECT_EQ((std::vector<std::uint8_t>(error_frame.begin() + 30, error_frame.begin() + 36)),
            (std::vector<std::uint8_t>{0x00, 0x04, 0xCF, 0x81, 0xFD, 0x09}));
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kOffline);
}

// Decision I35: a NACK-RTA-PDU of the device while our AlarmAck waits gets the AlarmAck again at once (byte
// for byte), from the same RTARetries budget as the timer: with retries 3 three NACKs are answered, the
// fourth is not, and the timer ends the AR one timeout (100 ms) after the last resend. A NACK acknowledges
// nothing, and without a pending AlarmAck it is ignored.
TEST(IoController, ANackGetsOurAlarmAckAgainWithinTheRtaRetries) {
  Pair pair = make_rta_pair(1, 3);
  ASSERT_TRUE(start_up(pair));
  pn::RtaFrame nack = pn::testing::diagnosis_alarm();
  nack.pdu_type = pn::RtaPduType::kNack;
  nack.has_block = false;
  nack.tack = false;
  EXPECT_EQ(offer(pair, nack, 1000).frames, 0u);  // nothing of ours waits
  const AlarmAnswer sent = offer(pair, pn::testing::diagnosis_alarm(), 2000);
  ASSERT_EQ(sent.frames, 2u);
  nack.ack_sequence = decoded_rta(sent.alarm_ack).send_sequence;  // even naming ours, a NACK is no ACK
  for (const std::uint64_t at : {10'000u, 20'000u, 30'000u}) {
    const AlarmAnswer again = offer(pair, nack, at);
    EXPECT_EQ(again.frames, 1u) << at;
    EXPECT_TRUE(again.ack.empty()) << at;
    EXPECT_EQ(again.alarm_ack, sent.alarm_ack) << at;
    EXPECT_TRUE(pair.controller->alarm_ack_pending(true)) << at;
  }
  const AlarmAnswer none = offer(pair, nack, 40'000);  // the budget is used up
  EXPECT_EQ(none.frames, 0u);
  EXPECT_TRUE(none.alarm_ack.empty());
  EXPECT_EQ(run_timers(pair, 129'999).high, pn::AlarmTimerAction::kNone);  // 100 ms after the last resend
  EXPECT_EQ(run_timers(pair, 130'000).high, pn::AlarmTimerAction::kAbort);
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kOffline);
}

// Decision I35: an ERR-RTA-PDU of the device ends the AR on our side too, with the device's PNIOStatus in
// last_error() and rta_error_received() (its priority named); nothing is sent back. A new AR clears it.
TEST(IoController, TheDevicesErrRtaPduEndsTheAr) {
  Pair pair = make_rta_pair(1, 3);
  ASSERT_TRUE(start_up(pair));
  pn::RtaFrame error = pn::testing::diagnosis_alarm();
  error.frame_id = pn::kFrameIdAlarmLow;
  error.pdu_type = pn::RtaPduType::kError;
  error.has_block = false;
  error.tack = false;
  error.error = {0xCF, 0x81, 0xFD, 0x05};  // the device's reason: "AR consumer DHT/WDT expired"
  const AlarmAnswer answer = offer(pair, error, 1000);
  EXPECT_EQ(answer.frames, 0u);
  EXPECT_TRUE(answer.ack.empty());
  EXPECT_EQ(pair.controller->state(), pn::ControllerArState::kOffline);
  EXPECT_EQ(pair.controller->last_error().value(), 0xCF81FD05u);  // the device's, not ours
  EXPECT_TRUE(pair.controller->rta_error_received());
  EXPECT_FALSE(pair.controller->rta_error_high_priority());
  std::array<std::uint8_t, 1518> frame{};
  EXPECT_EQ(pair.controller->next_output_frame(frame), 0u);
  pair.device->abort_ar();
  ASSERT_TRUE(start_up(pair, 9));
  EXPECT_FALSE(pair.controller->rta_error_received());
  // Codec: an ERR PDU cut inside its PNIOStatus does not decode.
  const RawAlarm raw = raw_alarm(pair, error);
  pn::RtaFrame decoded;
  EXPECT_EQ(pn::decode_rta(raw.frame(), decoded), pn::ProfinetError::kNone);
  EXPECT_EQ(decoded.error, error.error);
  std::vector<std::uint8_t> cut(raw.frame().begin(), raw.frame().end());
  cut[31] = 2;  // VarPartLen 2
  EXPECT_NE(pn::decode_rta(cut, decoded), pn::ProfinetError::kNone);
}
