// The controller's rules of the gateway contract (docs/gateway.md "What the controller does"), without DDS:
// the test plays the gateway by handing ActualCycle samples to route() and the runtime by calling
// read_actual()/write_setpoint() cycle by cycle.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <thread>

#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/exchange_core.hpp"
#include "tomc/drives/dds/latest_value.hpp"
#include "tomc/drives/dds/type_support.hpp"
#include "tomc/telegrams/layout.hpp"

namespace {

namespace tg = tomc::telegrams;
namespace gw = tomc::gateway;
using namespace tomc::drives;
using namespace tomc::drives::dds;

constexpr std::uint64_t kController = 0xC0FFEE;
constexpr std::uint64_t kIncarnation = 0xAB;

DeviceConfig telegram(std::uint16_t t, std::uint16_t supplementary = 0) {
  DeviceConfig c;
  c.drive_telegram = t;
  c.supplementary_telegram = supplementary;
  return c;
}

// A gateway's answer: every device's actual frames filled with `fill_byte`.
struct FakeGateway {
  std::string name = "gw1";
  std::uint64_t incarnation = kIncarnation;
  std::uint64_t sequence = 0;
  gw::ActualCycle answer(const ExchangeCore& core, std::uint64_t controller, bool has_setpoint,
                         std::uint64_t setpoint_cycle, std::uint8_t fill_byte) {
    gw::ActualCycle s;
    s.contract_version(kContractVersion);
    s.gateway(name);
    s.incarnation(incarnation);
    s.sequence_number(++sequence);
    s.controller(controller);
    s.devices().resize(core.device_count());
    for (std::size_t i = 0; i < core.device_count(); ++i) {
      auto& e = s.devices()[i];
      e.device(core.device_name(i));
      e.byte_order(gw::BYTE_ORDER_BIG);
      e.has_setpoint(has_setpoint);
      e.setpoint_cycle(setpoint_cycle);
      DeviceFrames frames = make_frames(core.device_config(i), tg::Direction::kActual);
      for (auto& f : frames.slots)
        std::memset(f.bytes.data(), fill_byte, f.length);
      fill(core.device_config(i), frames, e.slots());
    }
    return s;
  }
};

struct Fixture {
  explicit Fixture(std::uint32_t max_age = 1, std::vector<DeviceConfig> configs = {telegram(3)})
      : core(ExchangeOptions{kController, 1'000'000, max_age}) {
    for (std::size_t i = 0; i < configs.size(); ++i)
      core.add_device("axis" + std::to_string(i + 1), configs[i]);
    core.freeze();
    for (std::size_t i = 0; i < configs.size(); ++i) {
      actual.push_back(make_frames(configs[i], tg::Direction::kActual));
      setpoint.push_back(make_frames(configs[i], tg::Direction::kSetpoint));
    }
  }
  // One runtime cycle: read every device, write every device. Returns whether device 0 was fresh.
  bool cycle() {
    bool fresh0 = false;
    for (std::size_t i = 0; i < actual.size(); ++i) {
      const bool fresh = core.read_actual(i, actual[i]);
      if (i == 0) fresh0 = fresh;
    }
    for (std::size_t i = 0; i < setpoint.size(); ++i)
      core.write_setpoint(i, setpoint[i]);
    return fresh0;
  }
  std::uint8_t first_actual_byte(std::size_t device = 0) const {
    return static_cast<std::uint8_t>(actual[device].slots[0].bytes[0]);
  }
  ExchangeCore core;
  FakeGateway gateway;
  std::vector<DeviceFrames> actual;
  std::vector<DeviceFrames> setpoint;
};

// Decision G5 (the read side: per-device triple buffer, the newest value used once).
TEST(LatestValue, ReaderSeesOnlyPublishedValuesAndEachOnce) {
  LatestValue<int> v;
  EXPECT_FALSE(v.take());
  v.write_slot() = 1;
  EXPECT_FALSE(v.take());  // written, not published
  v.publish();
  EXPECT_TRUE(v.pending());
  EXPECT_TRUE(v.take());
  EXPECT_EQ(v.value(), 1);
  EXPECT_FALSE(v.take());  // taken once
  EXPECT_EQ(v.value(), 1);
  v.write_slot() = 2;
  v.publish();
  v.write_slot() = 3;
  v.publish();  // the reader was slower: 2 is overwritten by 3
  EXPECT_TRUE(v.take());
  EXPECT_EQ(v.value(), 3);
}

// A producer and a consumer on two threads: the consumer never sees a torn value and never goes backwards.
// Decision G5 (the listener thread hands answers to the cyclic thread lock-free).
TEST(LatestValue, NoTornOrOlderValueAcrossThreads) {
  struct Wide {
    std::array<std::uint64_t, 16> words{};
  };
  LatestValue<Wide> v;
  constexpr std::uint64_t kCount = 200'000;
  std::atomic<bool> done{false};
  std::thread producer([&] {
    for (std::uint64_t n = 1; n <= kCount; ++n) {
      v.write_slot().words.fill(n);
      v.publish();
    }
    done = true;
  });
  std::uint64_t last = 0;
  std::uint64_t taken = 0;
  bool torn = false;
  bool backwards = false;
  while (!done.load() || v.pending()) {
    if (!v.take()) continue;
    ++taken;
    const auto& w = v.value().words;
    for (auto x : w)
      torn = torn || x != w[0];
    backwards = backwards || w[0] <= last;
    last = w[0];
  }
  producer.join();
  EXPECT_FALSE(torn);
  EXPECT_FALSE(backwards);
  EXPECT_EQ(last, kCount);  // the newest value always arrives
  EXPECT_GT(taken, 0u);
}

// Before the first setpoint the gateway's idle answer (controller 0) is the drive as it stands: fresh in
// cycle 0. After that, only answers to this controller's previous cycle (max age 0).
// Decisions G7 (cycle 0: the idle answer) and G2 (fresh = the previous cycle); docs/gateway.md §6.
TEST(ExchangeCore, IdleAnswerBeforeTheFirstSetpointThenOnlyAnswersToTheLastCycle) {
  Fixture f(0);
  f.core.route(f.gateway.answer(f.core, 0, false, 0, 0x11), 0);
  EXPECT_TRUE(f.cycle());  // cycle 0: idle answer accepted, setpoint 0 sent
  EXPECT_EQ(f.first_actual_byte(), 0x11);
  EXPECT_EQ(f.core.cycles_sent(), 1u);
  f.core.route(f.gateway.answer(f.core, 0, false, 0, 0x22), 0);  // still idle: the gateway ignored us
  EXPECT_FALSE(f.cycle());                                       // cycle 1: not an answer to cycle 0
  EXPECT_EQ(f.first_actual_byte(), 0x11);                        // frames left as they were
  f.core.route(f.gateway.answer(f.core, kController, true, 1, 0x33), 0);
  EXPECT_TRUE(f.cycle());  // cycle 2 takes the answer to cycle 1
  EXPECT_EQ(f.first_actual_byte(), 0x33);
  EXPECT_FALSE(f.cycle());  // cycle 3: nothing new; the same answer is never used twice
  const LinkHealth h = f.core.link_health(0);
  EXPECT_EQ(h.exchanges, 4u);
  EXPECT_EQ(h.missed_total, 2u);
  EXPECT_EQ(h.consecutive_missed, 1u);
  EXPECT_FALSE(h.up);
  EXPECT_EQ(f.core.counters(0).stale, 1u);
}

// max_answer_age_cycles = 1: an answer one cycle late is still taken, two cycles late is stale.
// Decision G2 (max_answer_age_cycles); docs/gateway.md §6.
TEST(ExchangeCore, AnswerAgeLimit) {
  Fixture f(1);
  f.core.route(f.gateway.answer(f.core, 0, false, 0, 1), 0);
  for (int i = 0; i < 5; ++i)
    f.cycle();                                                         // cycles 0..4 sent
  f.core.route(f.gateway.answer(f.core, kController, true, 3, 2), 0);  // answers cycle 3 = one late
  EXPECT_TRUE(f.cycle());                                              // cycle 5
  f.core.route(f.gateway.answer(f.core, kController, true, 3, 3), 0);  // cycle 3 again, now two late
  EXPECT_FALSE(f.cycle());                                             // cycle 6
  f.core.route(f.gateway.answer(f.core, kController, true, 9, 4), 0);  // a cycle not sent yet: bogus
  EXPECT_FALSE(f.cycle());                                             // cycle 7
  EXPECT_EQ(f.core.counters(0).stale, 2u);
}

// Answers to another controller are never ours, whatever their cycle number.
// Decisions G2, G10 (an answer names its controller); docs/gateway.md §6.
TEST(ExchangeCore, AnswerForAnotherControllerIsStale) {
  Fixture f(1);
  f.cycle();
  f.core.route(f.gateway.answer(f.core, kController + 1, true, 0, 5), 0);
  EXPECT_FALSE(f.cycle());
  EXPECT_EQ(f.core.counters(0).stale, 1u);
}

// A new incarnation is a gateway restart: peer_restarts counts it (the drive connection raises its link
// alarm from it, techobjects drive_connection_test), even when the new gateway answers in time.
// Decision G6 (a gateway restart is a link loss: peer_restarts).
TEST(ExchangeCore, GatewayRestartIsCounted) {
  Fixture f(1);
  f.core.route(f.gateway.answer(f.core, 0, false, 0, 1), 0);
  EXPECT_TRUE(f.cycle());
  f.core.route(f.gateway.answer(f.core, kController, true, 0, 2), 0);
  EXPECT_TRUE(f.cycle());
  EXPECT_EQ(f.core.link_health(0).peer_restarts, 0u);
  f.gateway.incarnation = 0xCD;
  f.gateway.sequence = 0;
  f.core.route(f.gateway.answer(f.core, kController, true, 1, 3), 0);
  EXPECT_TRUE(f.cycle());
  EXPECT_EQ(f.core.link_health(0).peer_restarts, 1u);
  EXPECT_EQ(f.core.counters(0).restarts, 1u);
}

// Sequence numbers: a jump counts lost answers, an old or repeated sample is rejected and never reaches the
// devices.
// docs/gateway.md §3 (a late or lost sample), §6.
TEST(ExchangeCore, SequenceGapsAndOldSamples) {
  Fixture f(1);
  f.core.route(f.gateway.answer(f.core, 0, false, 0, 1), 0);  // sequence 1
  f.gateway.sequence = 4;
  f.core.route(f.gateway.answer(f.core, 0, false, 0, 2), 0);  // sequence 5: 2, 3, 4 lost
  EXPECT_EQ(f.core.statistics().answers_lost, 3u);
  f.gateway.sequence = 2;
  f.core.route(f.gateway.answer(f.core, 0, false, 0, 7), 0);  // sequence 3 after 5: old
  EXPECT_EQ(f.core.statistics().samples_rejected, 1u);
  EXPECT_TRUE(f.cycle());
  EXPECT_EQ(f.first_actual_byte(), 2);  // the old sample did not overwrite the newer one
}

// An entry with other telegrams, lengths or byte order is never used (its bytes would read as wrong
// values); the reason is kept for the diagnosis.
// docs/gateway.md §2 (Telegram: telegram, length, byte order), §6.
TEST(ExchangeCore, MismatchedEntriesAreRejected) {
  Fixture f(1);
  gw::ActualCycle s = f.gateway.answer(f.core, 0, false, 0, 1);
  s.devices()[0].slots()[0].number(2);  // telegram 2 instead of 3
  f.core.route(s, 0);
  EXPECT_FALSE(f.cycle());
  EXPECT_EQ(f.core.counters(0).rejected, 1u);
  EXPECT_EQ(f.core.last_mismatch(0), "gateway 'gw1': slot drive: telegram 2, expected 3");

  s = f.gateway.answer(f.core, kController, true, 0, 1);
  s.devices()[0].slots()[0].pzd().pop_back();  // 17 bytes instead of 18
  f.core.route(s, 0);
  EXPECT_EQ(f.core.last_mismatch(0), "gateway 'gw1': slot drive: 17 PZD bytes, expected 18");

  s = f.gateway.answer(f.core, kController, true, 0, 1);
  s.devices()[0].byte_order(gw::BYTE_ORDER_LITTLE);
  f.core.route(s, 0);
  EXPECT_EQ(f.core.last_mismatch(0), "gateway 'gw1': byte order little, expected big");

  s = f.gateway.answer(f.core, kController, true, 0, 1);
  s.devices()[0].byte_order(static_cast<gw::ByteOrder>(77));  // outside the enum
  f.core.route(s, 0);
  EXPECT_EQ(f.core.last_mismatch(0), "gateway 'gw1': byte order invalid (77), expected big");
  EXPECT_EQ(f.core.counters(0).rejected, 4u);
  EXPECT_FALSE(f.cycle());
}

// Samples of another contract version, with too many devices or incarnation 0, and entries for devices this
// controller does not have.
// docs/gateway.md §2 (contract version, devices, incarnation), §6.
TEST(ExchangeCore, ForeignAndMalformedSamples) {
  Fixture f(1);
  gw::ActualCycle s = f.gateway.answer(f.core, 0, false, 0, 1);
  s.contract_version(2);
  f.core.route(s, 0);
  s = f.gateway.answer(f.core, 0, false, 0, 1);
  s.incarnation(0);
  f.core.route(s, 0);
  s = f.gateway.answer(f.core, 0, false, 0, 1);
  s.devices().resize(kMaxDevices + 1);
  f.core.route(s, 0);
  EXPECT_EQ(f.core.statistics().samples_rejected, 3u);
  s = f.gateway.answer(f.core, 0, false, 0, 1);
  s.devices()[0].device("axis99");
  f.core.route(s, 0);
  EXPECT_EQ(f.core.statistics().foreign_devices, 1u);
  EXPECT_FALSE(f.cycle());
  EXPECT_EQ(f.core.counters(0).answers, 0u);
}

// The setpoints of a cycle go out once, when the last device has written; the sample carries every
// device's frames, names, telegrams and the cycle counter.
// Decision G1 (one SetpointCycle per servo cycle with every device of the link).
TEST(ExchangeCore, OneSetpointSamplePerCycleWithEveryDevice) {
  Fixture f(1, {telegram(3), telegram(105, 750)});
  gw::SetpointCycle sample;
  f.core.prepare_sample(sample);
  EXPECT_FALSE(f.core.take_setpoints(sample));
  const std::uint32_t signal_before = f.core.setpoint_signal().load();
  for (auto& frames : f.setpoint) {
    for (auto& slot : frames.slots)
      std::memset(slot.bytes.data(), 0x5A, slot.length);
  }
  f.core.write_setpoint(0, f.setpoint[0]);
  EXPECT_FALSE(f.core.take_setpoints(sample));  // device 2 has not written yet
  f.core.write_setpoint(1, f.setpoint[1]);
  EXPECT_EQ(f.core.setpoint_signal().load(), signal_before + 1);
  ASSERT_TRUE(f.core.take_setpoints(sample));
  EXPECT_EQ(sample.cycle(), 0u);
  EXPECT_EQ(sample.controller(), kController);
  EXPECT_EQ(sample.contract_version(), kContractVersion);
  EXPECT_EQ(sample.cycle_time_ns(), 1'000'000u);
  ASSERT_EQ(sample.devices().size(), 2u);
  EXPECT_EQ(sample.devices()[1].device(), std::string("axis2"));
  EXPECT_EQ(sample.devices()[1].slots()[0].number(), 105);
  EXPECT_EQ(sample.devices()[1].slots()[0].pzd().size(), 20u);  // telegram 105 setpoint: 10 words
  EXPECT_EQ(sample.devices()[1].slots()[1].number(), 750);
  EXPECT_EQ(sample.devices()[1].slots()[1].pzd().size(), 6u);
  EXPECT_EQ(sample.devices()[1].slots()[2].number(), 0);
  EXPECT_TRUE(sample.devices()[1].slots()[2].pzd().empty());
  EXPECT_EQ(sample.devices()[0].slots()[0].pzd()[4], 0x5A);
  EXPECT_TRUE(matches(f.core.device_config(1), tg::Direction::kSetpoint, sample.devices()[1].byte_order(),
                      sample.devices()[1].slots()));
  f.cycle();
  ASSERT_TRUE(f.core.take_setpoints(sample));
  EXPECT_EQ(sample.cycle(), 1u);
  EXPECT_EQ(f.core.statistics().incomplete_cycles, 0u);
}

// A device of the link that is not written every cycle must not stop the others' setpoints.
// Decision G1; docs/gateway.md §6.
TEST(ExchangeCore, IncompleteCycleStillSends) {
  Fixture f(1, {telegram(3), telegram(3)});
  gw::SetpointCycle sample;
  f.core.prepare_sample(sample);
  f.core.write_setpoint(0, f.setpoint[0]);
  f.core.write_setpoint(0, f.setpoint[0]);  // device 0 again: device 1 is not in the runtime
  EXPECT_EQ(f.core.statistics().incomplete_cycles, 1u);
  EXPECT_TRUE(f.core.take_setpoints(sample));
  EXPECT_EQ(f.core.cycles_sent(), 1u);
}

// Lock-step waiting and the round-trip statistics: complete when every device answered the last cycle.
// Decision G8 (lock-step pacing: wait until the answers are in).
TEST(ExchangeCore, WaitForAnswersAndRoundTrip) {
  Fixture f(1, {telegram(3), telegram(3)});
  f.cycle();  // cycle 0 sent
  EXPECT_FALSE(f.core.wait_for_answers(std::chrono::milliseconds(1)));
  gw::ActualCycle s = f.gateway.answer(f.core, kController, true, 0, 1);
  s.devices().resize(1);  // only axis1 answered
  f.core.route(s, 0);
  EXPECT_FALSE(f.core.wait_for_answers(std::chrono::milliseconds(1)));
  std::thread late([&] {
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    f.core.route(f.gateway.answer(f.core, kController, true, 0, 1),
                 std::chrono::duration_cast<std::chrono::nanoseconds>(now).count());
  });
  EXPECT_TRUE(f.core.wait_for_answers(std::chrono::seconds(5)));
  late.join();
  const ExchangeStatistics st = f.core.statistics();
  EXPECT_EQ(st.cycles_answered, 1u);
  EXPECT_EQ(st.round_trips, 1u);
  EXPECT_GT(st.round_trip_max_us, 0.0);
}

// docs/gateway.md §2 (device names ≤ 63 characters, controller 0 = none), §6.
TEST(ExchangeCore, SetUpErrors) {
  ExchangeCore core(ExchangeOptions{kController, 1'000'000, 1});
  EXPECT_THROW(core.add_device("", telegram(3)), std::invalid_argument);
  EXPECT_THROW(core.add_device(std::string(64, 'x'), telegram(3)), std::invalid_argument);
  EXPECT_THROW(core.add_device("a", telegram(104)), std::invalid_argument);
  core.add_device("a", telegram(3));
  EXPECT_THROW(core.add_device("a", telegram(3)), std::invalid_argument);
  core.freeze();
  EXPECT_THROW(core.add_device("b", telegram(3)), std::invalid_argument);
  EXPECT_THROW(ExchangeCore(ExchangeOptions{0, 1, 1}), std::invalid_argument);
  ExchangeCore empty(ExchangeOptions{kController, 1'000'000, 1});
  EXPECT_THROW(empty.freeze(), std::invalid_argument);
}

// Found by the fuzzer: the generated type support let Fast CDR's BadParamException (a malformed
// encapsulation) escape into the listener thread. The checked type support returns false and leaves a default
// sample, which route() rejects (contract version 0).
// Decision G15 (malformed samples: a checked type support).
TEST(ExchangeCore, MalformedPayloadIsRejectedNotThrown) {
  Fixture f(1);
  ActualCycleType type;
  gw::ActualCycle sample = f.gateway.answer(f.core, 0, false, 0, 1);
  eprosima::fastrtps::rtps::SerializedPayload_t payload(64);
  std::memset(payload.data, 0x0A, 64);  // encapsulation byte 0x0A: not CDR
  payload.length = 64;
  bool ok = true;
  EXPECT_NO_THROW(ok = type.deserialize(&payload, &sample));
  EXPECT_FALSE(ok);
  EXPECT_EQ(sample.contract_version(), 0u);
  f.core.route(sample, 0);
  EXPECT_EQ(f.core.statistics().samples_rejected, 1u);

  // And a well-formed payload still reads back.
  const gw::ActualCycle good = f.gateway.answer(f.core, 0, false, 0, 0x42);
  eprosima::fastrtps::rtps::SerializedPayload_t buffer(
      type.getSerializedSizeProvider(const_cast<gw::ActualCycle*>(&good))());
  ASSERT_TRUE(type.serialize(const_cast<gw::ActualCycle*>(&good), &buffer));
  ASSERT_TRUE(type.deserialize(&buffer, &sample));
  f.core.route(sample, 0);
  EXPECT_TRUE(f.cycle());
  EXPECT_EQ(f.first_actual_byte(), 0x42);
}

}  // namespace
