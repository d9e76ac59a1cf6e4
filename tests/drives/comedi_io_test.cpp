// The comedi backend of the hardware I/O layer (issue 20: "a missing device at start is a configuration error
// naming the device file; read/write failures raise a clear alarm"). Without a card: the missing device is
// tried with the real comedilib; the card's channel checks, the code conversion and the failing reads and
// writes run against a fake comedilib table (ComediLibrary).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "drive_harness.hpp"
#include "tomc/drives/analog_drive.hpp"
#include "tomc/drives/comedi_analog_drive.hpp"
#include "tomc/drives/io/comedi_io.hpp"

namespace tomc::drives::test {
namespace {

using io::Channel;
using io::ComediIo;
using io::ComediIoParameters;
using io::ComediSubdevice;
using io::IoStatus;

std::string open_error(const ComediIoParameters& p, const io::ComediLibrary& lib = io::real_comedi()) {
  try {
    ComediIo card(p, lib);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return {};
}

// A missing device file is a configuration error naming it (and what to check).
// Decision A20 (a missing device at start is a configuration error naming the device file),
// docs/analog-drives.md "The comedi backend".
TEST(ComediIo, MissingDeviceIsAConfigurationErrorNamingTheFile) {
  ComediIoParameters p;
  p.device_file = "/dev/comedi_tomc_test_missing";
  const std::string error = open_error(p);
  EXPECT_NE(error.find("comedi: cannot open /dev/comedi_tomc_test_missing: "), std::string::npos) << error;
  EXPECT_NE(error.find("driver loaded"), std::string::npos) << error;
  // A file that exists but is no comedi device.
  p.device_file = "/dev/null";
  EXPECT_NE(open_error(p).find("comedi: cannot open /dev/null: "), std::string::npos);
}

// The fake card: subdevice 0 AO (2 channels, 16 bit), 1 DIO (8), 2 counter (1, 32 bit).
struct FakeCard {
  bool open = false;
  bool fail_reads = false;
  bool fail_writes = false;
  std::uint32_t ao[2]{};
  unsigned dio[8]{};
  std::uint32_t count = 0;
};
FakeCard fake;

const io::ComediLibrary kFake{
    [](const char*) -> void* {
      fake.open = true;
      return &fake;
    },
    [](void*) {
      fake.open = false;
      return 0;
    },
    [](void*) { return 3; },
    [](void*, unsigned s) {
      return static_cast<int>(s == 0   ? ComediSubdevice::kAnalogOutput
                              : s == 1 ? ComediSubdevice::kDigitalIo
                                       : ComediSubdevice::kCounter);
    },
    [](void*, unsigned s) { return s == 0   ? 2
                                   : s == 1 ? 8
                                            : 1; },
    [](void*, unsigned s, unsigned) -> std::uint32_t { return s == 0   ? 65535u
                                                              : s == 1 ? 1u
                                                                       : 0xFFFFFFFFu; },
    [](void*, unsigned, unsigned, std::uint32_t* v) {
      *v = fake.count;
      return fake.fail_reads ? -1 : 1;
    },
    [](void*, unsigned, unsigned c, std::uint32_t v) {
      if (fake.fail_writes) return -1;
      fake.ao[c] = v;
      return 1;
    },
    [](void*, unsigned, unsigned c, unsigned* bit) {
      *bit = fake.dio[c];
      return fake.fail_reads ? -1 : 1;
    },
    [](void*, unsigned, unsigned c, unsigned bit) {
      if (fake.fail_writes) return -1;
      fake.dio[c] = bit;
      return 1;
    },
    []() -> const char* { return "Input/output error"; },
};

ComediIoParameters fake_wiring() {
  ComediIoParameters p;
  p.device_file = "/dev/comedi7";
  p.analog_outputs = {Channel{0, 1}};
  p.digital_outputs = {Channel{1, 0}};
  p.digital_inputs = {Channel{1, 1}};
  p.counters = {Channel{2, 0}};
  return p;
}

// Every channel is checked at open: subdevice, its kind, the channel; the device is closed again.
// Decision A20 (every channel checked at construction: the error names device, subdevice, channel and
// role).
TEST(ComediIo, ChannelChecksNameDeviceSubdeviceAndChannel) {
  fake = {};
  auto p = fake_wiring();
  p.analog_outputs = {Channel{1, 0}};
  EXPECT_EQ(open_error(p, kFake),
            "comedi: /dev/comedi7 subdevice 1 channel 0 (analog output) is digital I/O");
  EXPECT_FALSE(fake.open);
  p = fake_wiring();
  p.counters = {Channel{2, 3}};
  EXPECT_EQ(open_error(p, kFake), "comedi: /dev/comedi7 subdevice 2 channel 3 (counter): no such channel");
  p = fake_wiring();
  p.digital_inputs = {Channel{5, 0}};
  EXPECT_EQ(open_error(p, kFake),
            "comedi: /dev/comedi7 subdevice 5 channel 0 (digital input): the card has 3 subdevices");
  EXPECT_EQ(open_error(fake_wiring(), kFake), "");
}

// tomc's signed DAC codes become comedi's offset binary of a bipolar range; 0 V until the first write.
// docs/analog-drives.md "The comedi backend" (signed DAC code + (maxdata + 1)/2, saturated: offset binary
// of a bipolar range).
TEST(ComediIo, CodesAndChannels) {
  fake = {};
  ComediIo card(fake_wiring(), kFake);
  EXPECT_EQ(card.write_outputs(), IoStatus::kOk);
  EXPECT_EQ(fake.ao[1], 32768u);
  card.set_analog_output(Channel{0, 1}, 27648);  // 10 V in the S7 format
  card.set_digital_output(Channel{1, 0}, true);
  EXPECT_EQ(card.write_outputs(), IoStatus::kOk);
  EXPECT_EQ(fake.ao[1], 32768u + 27648u);
  EXPECT_EQ(fake.dio[0], 1u);
  card.set_analog_output(Channel{0, 1}, -40000);  // saturated
  (void)card.write_outputs();
  EXPECT_EQ(fake.ao[1], 0u);
  fake.dio[1] = 1;
  fake.count = 123456;
  EXPECT_EQ(card.sample_inputs(), IoStatus::kOk);
  EXPECT_TRUE(card.digital_input(Channel{1, 1}));
  EXPECT_EQ(card.counter(Channel{2, 0}).count, 123456u);
  EXPECT_STREQ(card.last_error(), "");
}

// A failing read or write is an IoStatus with the comedi error kept; behind the analog actor it is fault
// 20002 in ZSW1.3 (the TO's alarm 401), enable off, acknowledged once the card works again.
// Decision A20 (failures as IoStatus with the comedi text), docs/analog-drives.md (fault 20002 in ZSW1.3,
// alarm 401, acknowledged once the card works).
TEST(ComediIo, ReadAndWriteFailuresBecomeTheActorsIoFault) {
  fake = {};
  ComediIo card(fake_wiring(), kFake);
  fake.fail_reads = true;
  fake.count = 99;
  EXPECT_EQ(card.sample_inputs(), IoStatus::kReadFailed);
  EXPECT_EQ(card.counter(Channel{2, 0}).count, 0u);  // the last good value stays
  EXPECT_STREQ(card.last_error(), "/dev/comedi7: data_read subdevice 2 channel 0: Input/output error");
  fake.fail_reads = false;
  fake.fail_writes = true;
  EXPECT_EQ(card.write_outputs(), IoStatus::kWriteFailed);
  EXPECT_STREQ(card.last_error(), "/dev/comedi7: dio_write subdevice 1 channel 0: Input/output error");
  fake.fail_writes = false;

  AnalogDriveParameters actor;
  actor.analog_output = Channel{0, 1};
  actor.enable_output = Channel{1, 0};
  actor.ready_input = Channel{1, 1};
  actor.counter = Channel{2, 0};
  fake.dio[1] = 1;  // the amplifier is ready
  BasicHarness<AnalogDrive> h(drive_config(3), card, actor);
  h.run_at_speed(300.0, 5);
  EXPECT_TRUE(h.drive.enable_output());
  EXPECT_EQ(fake.dio[0], 1u);
  fake.fail_reads = true;
  h.cycle();
  EXPECT_EQ(h.drive.active_fault(), kFaultIo);
  EXPECT_NE(h.zsw1() & 0x0008u, 0u);
  EXPECT_FALSE(h.drive.enable_output());
  fake.fail_reads = false;
  h.cycle();
  EXPECT_EQ(fake.dio[0], 0u);  // the enable output is off at the card
  h.stw1(0x04FE);              // acknowledge (STW1.7 edge)
  h.cycle();
  EXPECT_EQ(h.drive.active_fault(), 0u);
}

// The drive a scenario or machine file builds from "analog": {"comedi": {...}} (decision A21): the card
// opened and owned with the actor, a telegram-3 drive to the TO; the card is closed with it.
TEST(ComediIo, AnalogDriveOnTheCardIsATelegram3Drive) {
  fake = {};
  AnalogDriveParameters actor;
  actor.analog_output = Channel{0, 1};
  actor.enable_output = Channel{1, 0};
  actor.ready_input = Channel{1, 1};
  actor.counter = Channel{2, 0};
  {
    ComediAnalogDrive drive(fake_wiring(), actor, kFake);
    EXPECT_TRUE(fake.open);
    EXPECT_EQ(drive.config().drive_telegram, 3);
    DeviceFrames frames = make_frames(drive.config(), tg::Direction::kSetpoint);
    fake.count = 40;
    fake.ao[1] = 7;
    EXPECT_TRUE(drive.read_actual(frames));
    drive.write_setpoint(make_frames(drive.config(), tg::Direction::kSetpoint));
    EXPECT_EQ(fake.ao[1], 32768u);  // switched off: 0 V, offset binary of the 16-bit bipolar range
    EXPECT_EQ(fake.dio[0], 0u);     // enable output off
  }
  EXPECT_FALSE(fake.open);
}

}  // namespace
}  // namespace tomc::drives::test
