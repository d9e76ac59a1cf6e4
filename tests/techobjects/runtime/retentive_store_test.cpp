// The retentive store of absolute-encoder adjustments (spec 02 §5.9, §11 scenario 39; spec 03 §4.16): the
// file format, atomic writes, corrupt/missing files, restoring a positioning axis after a restart, and
// MC_SaveAbsoluteEncoderData.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "positioning_axis_fixture.hpp"
#include "tomc/instructions/mc_save_absolute_encoder_data.hpp"
#include "tomc/instructions/mc_set_sensor.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/runtime/retentive_store.hpp"

namespace {

using namespace tomc;
namespace fs = std::filesystem;
using techobjects::RetainedRecord;
using techobjects::RetainFileStatus;
using techobjects::RetentiveStore;
using tomc::testing::linear_axis_data;
using tomc::testing::linear_drive;
using tomc::testing::PositioningAxisMachine;

class RetentiveStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/tomc-retain-XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Decision H5 (the retentive store file), spec 02 §5.9 (the absolute-encoder adjustment survives
// power-off).
TEST_F(RetentiveStoreTest, RoundTripIsExact) {
  const fs::path file = dir_ / "retain.dat";
  std::vector<RetainedRecord> records{
      {"Slide",
       {.AbsEncoderOffset = -1234.5678901234567, .sequence = 3, .LastAbsoluteValue = 123456, .valid = true}},
      {"Table",
       {.AbsEncoderOffset = 1.0e-17,
        .MeasuringRangeCount = -42,
        .sequence = 9,
        .LastAbsoluteValue = 4294967295u,
        .valid = true}},
      {"Spare", {}}};
  std::string error;
  ASSERT_TRUE(techobjects::write_retain_file(file, records, error)) << error;
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  const auto read = techobjects::read_retain_file(file);
  ASSERT_EQ(read.status, RetainFileStatus::kOk) << read.message;
  ASSERT_EQ(read.records.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(read.records[i].name, records[i].name);
    EXPECT_EQ(read.records[i].data, records[i].data);  // %.17g: every double reads back exactly
  }
}

// A crash while writing leaves "<file>.tmp" behind and the previous file intact: it still reads.
// Decision H5 (written atomically: tmp + fsync + rename).
TEST_F(RetentiveStoreTest, AnInterruptedWriteLeavesTheOldFile) {
  const fs::path file = dir_ / "retain.dat";
  std::string error;
  ASSERT_TRUE(techobjects::write_retain_file(
      file, std::vector<RetainedRecord>{{"Slide", {.AbsEncoderOffset = 5.0, .sequence = 1, .valid = true}}},
      error));
  std::ofstream(file.string() + ".tmp") << "tomc-retain 1\nSlide 1 7.0 0";  // half-written, never renamed
  const auto read = techobjects::read_retain_file(file);
  ASSERT_EQ(read.status, RetainFileStatus::kOk);
  EXPECT_EQ(read.records[0].data.AbsEncoderOffset, 5.0);
}

// Decision H5 (format line and FNV-1a checksum: a damaged file is never trusted).
TEST_F(RetentiveStoreTest, DamagedFilesAreReportedNotTrusted) {
  const fs::path file = dir_ / "retain.dat";
  EXPECT_EQ(techobjects::read_retain_file(file).status, RetainFileStatus::kMissing);
  std::string error;
  ASSERT_TRUE(techobjects::write_retain_file(
      file, std::vector<RetainedRecord>{{"Slide", {.AbsEncoderOffset = 5.0, .sequence = 1, .valid = true}}},
      error));
  const std::string good = read_text(file);
  // One changed digit of the offset: the checksum catches it.
  std::string altered = good;
  altered.replace(altered.find("1 5 "), 4, "1 6 ");
  std::ofstream(file, std::ios::binary | std::ios::trunc) << altered;
  auto read = techobjects::read_retain_file(file);
  EXPECT_EQ(read.status, RetainFileStatus::kCorrupt);
  EXPECT_NE(read.message.find("checksum mismatch"), std::string::npos) << read.message;
  EXPECT_TRUE(read.records.empty());
  // Cut short: no checksum line.
  std::ofstream(file, std::ios::binary | std::ios::trunc) << good.substr(0, good.size() / 2);
  read = techobjects::read_retain_file(file);
  EXPECT_EQ(read.status, RetainFileStatus::kCorrupt);
  EXPECT_NE(read.message.find("no checksum line"), std::string::npos) << read.message;
  // Not our format.
  std::ofstream(file, std::ios::binary | std::ios::trunc) << "hello\nchecksum 0000000000000000\n";
  EXPECT_EQ(techobjects::read_retain_file(file).status, RetainFileStatus::kCorrupt);
}

techobjects::PositioningAxisData absolute_data() {
  auto d = linear_axis_data();
  d.Sensor[0].Type = static_cast<std::int32_t>(techobjects::SensorEncoderType::ABSOLUTE);
  d.Sensor[0].Parameter.DeterminableRevolutions = 4096;
  return d;
}

// spec 02 §11 scenario 39: adjust (Mode 7, 250.0), the store notices the new adjustment in the cycle and
// writes it; a restarted runtime on the same mechanics restores 250.0 (plus the travel since), homed.
TEST_F(RetentiveStoreTest, AdjustmentSurvivesARuntimeRestart) {
  const fs::path file = dir_ / "retain.dat";
  double load = 0.0;
  {
    PositioningAxisMachine m(absolute_data());
    RetentiveStore store(file);
    store.attach(*m.axis);
    m.user = [&] { store.cycle(); };
    m.run(20);
    EXPECT_FALSE(store.service());  // nothing to write yet
    m.home.Mode = 7;
    m.home.Position = 250.0;
    m.home.Execute = true;
    m.run(2);
    EXPECT_TRUE(store.service());  // the new adjustment was snapshot by cycle() and is written now
    EXPECT_EQ(store.saves(), 1u);
    load = m.drive->load_position();
  }
  auto p = linear_drive();
  p.initial_load_position = load;
  PositioningAxisMachine n(absolute_data(), p);
  RetentiveStore store(file);
  store.attach(*n.axis);
  const auto restored = store.restore();
  EXPECT_EQ(restored.status, RetainFileStatus::kOk) << restored.message;
  n.run(20);
  EXPECT_TRUE(techobjects::test(n.db().StatusWord, techobjects::StatusWordBit::kHomingDone));
  EXPECT_NEAR(n.db().ActualPosition, 250.0, 0.001);
  EXPECT_FALSE(n.axis->alarms().pending(techobjects::kAlarmAdjustmentLost));
}

// Spec 01 §3.8 / seed 004 §6.2.4.5 (each encoder has its own absolute-encoder adjustment) with spec 02 §5.9
// (the adjustment is retentive), decision B6: two absolute encoders on telegram 4 (G1 motor side, G2 load
// side, gear 1:1, so both read the same distance). Sensor[1] is adjusted to 250 (Mode 7); MC_SetSensor makes
// Sensor[2] operative, which is adjusted to 100 (Mode 7), and Sensor[1] closes the loop again. After a power
// cycle both encoders come up adjusted: Sensor[1] at 250 (the axis, homed), Sensor[2] at 100. A file without
// Sensor[2]'s record leaves only Sensor[2] not adjusted: no alarm 432, the axis stays homed.
TEST_F(RetentiveStoreTest, EveryAbsoluteEncoderKeepsItsAdjustment) {
  namespace tt = techobjects;
  const fs::path file = dir_ / "retain.dat";
  auto data = absolute_data();
  data.Sensor[1].Existent = true;
  data.Sensor[1].Interface.Number = 2;  // G2 of telegram 4
  data.Sensor[1].MountingMode = static_cast<std::int32_t>(tt::SensorMountingMode::kLoadSide);
  data.Sensor[1].Type = static_cast<std::int32_t>(tt::SensorEncoderType::ABSOLUTE);
  data.Sensor[1].Parameter.DeterminableRevolutions = 4096;
  const auto adjusted = [](const PositioningAxisMachine& m, int n) {
    return m.db().StatusSensor[n - 1].Adjusted == static_cast<std::int32_t>(tt::SensorAdjusted::kAdjusted);
  };
  double load = 0.0;
  double offset2 = 0.0;
  {
    PositioningAxisMachine m(data, linear_drive(), 4);
    RetentiveStore store(file);
    store.attach(*m.axis);
    instructions::MC_SetSensor<tt::PositioningAxis> set_sensor;
    m.user = [&] {
      store.cycle();
      set_sensor(*m.axis);
    };
    const auto pulse = [&](bool& execute) {
      execute = true;
      m.run(2);
      execute = false;
      m.run(1);
    };
    m.run(20);
    m.home.Mode = 7;
    m.home.Position = 250.0;
    pulse(m.home.Execute);
    ASSERT_TRUE(store.service());
    set_sensor.Sensor = 2;
    set_sensor.Mode = 1;  // switch as it is (no take-over)
    pulse(set_sensor.Execute);
    ASSERT_EQ(m.db().OperativeSensor, 2u);
    m.home.Position = 100.0;
    pulse(m.home.Execute);
    EXPECT_NEAR(m.db().StatusSensor[1].Position, 100.0, 1e-6);
    offset2 = m.db().StatusSensor[1].AbsEncoderOffset;
    ASSERT_TRUE(store.service());  // Sensor[2]'s new adjustment
    set_sensor.Sensor = 1;
    pulse(set_sensor.Execute);
    ASSERT_EQ(m.db().OperativeSensor, 1u);
    m.run(5);
    EXPECT_FALSE(store.service());  // switching encoders is no new adjustment
    load = m.drive->load_position();
  }
  const std::string text = read_text(file);
  EXPECT_NE(text.find("\nAxis1 1 "), std::string::npos) << text;
  EXPECT_NE(text.find("\nAxis1.Sensor[2] 1 "), std::string::npos) << text;

  auto p = linear_drive();
  p.initial_load_position = load;
  const auto power_up = [&](PositioningAxisMachine& n) {
    RetentiveStore store(file);
    store.attach(*n.axis);
    EXPECT_EQ(store.restore().status, RetainFileStatus::kOk);
    n.run(20);
    EXPECT_TRUE(tt::test(n.db().StatusWord, tt::StatusWordBit::kHomingDone));
    EXPECT_NEAR(n.db().ActualPosition, 250.0, 1e-3);
    EXPECT_TRUE(adjusted(n, 1));
    EXPECT_FALSE(n.axis->alarms().pending(tt::kAlarmAdjustmentLost));
  };
  {
    PositioningAxisMachine n(data, p, 4);
    power_up(n);
    EXPECT_TRUE(adjusted(n, 2));
    EXPECT_NEAR(n.db().StatusSensor[1].Position, 100.0, 1e-3);
    EXPECT_EQ(n.db().StatusSensor[1].AbsEncoderOffset, offset2);
  }
  const auto records = techobjects::read_retain_file(file).records;
  const auto write_without = [&](const char* name) {
    auto kept = records;
    std::erase_if(kept, [&](const RetainedRecord& r) { return r.name == name; });
    std::string error;
    ASSERT_TRUE(techobjects::write_retain_file(file, kept, error)) << error;
  };
  {
    // Sensor[2]'s record lost: only that encoder is not adjusted; it reads its absolute value without offset.
    write_without("Axis1.Sensor[2]");
    PositioningAxisMachine k(data, p, 4);
    power_up(k);
    EXPECT_FALSE(adjusted(k, 2));
    EXPECT_NEAR(k.db().StatusSensor[1].Position, 100.0 - offset2, 1e-3);
  }
  // The start-up encoder's record lost: alarm 432, not homed (H5); Sensor[2] still comes up adjusted at 100.
  write_without("Axis1");
  PositioningAxisMachine k(data, p, 4);
  RetentiveStore store(file);
  store.attach(*k.axis);
  (void)store.restore();
  k.run(20);
  EXPECT_TRUE(k.axis->alarms().pending(tt::kAlarmAdjustmentLost));
  EXPECT_FALSE(tt::test(k.db().StatusWord, tt::StatusWordBit::kHomingDone));
  EXPECT_FALSE(adjusted(k, 1));
  EXPECT_TRUE(adjusted(k, 2));
  EXPECT_NEAR(k.db().StatusSensor[1].Position, 100.0, 1e-3);
}

// Missing file, corrupt file, no record for this TO: alarm 432 with the cause, not homed; an incremental axis
// attached to the same store is not concerned.
// Decision H5 (missing file, damaged file, no record: alarm 432 with the cause, not homed), spec 02 §5.12.
TEST_F(RetentiveStoreTest, LostAdjustmentsRaiseAlarm432) {
  const fs::path file = dir_ / "retain.dat";
  const auto check = [&](std::uint32_t cause) {
    PositioningAxisMachine m(absolute_data());
    PositioningAxisMachine incremental(linear_axis_data());
    RetentiveStore store(file);
    store.attach(*m.axis);
    store.attach(*incremental.axis);
    (void)store.restore();
    m.run(5);
    incremental.run(5);
    ASSERT_TRUE(m.axis->alarms().pending(techobjects::kAlarmAdjustmentLost)) << cause;
    EXPECT_EQ(m.axis->alarms().alarms()[0].additional_value, cause);
    EXPECT_FALSE(techobjects::test(m.db().StatusWord, techobjects::StatusWordBit::kHomingDone));
    EXPECT_FALSE(incremental.axis->alarms().pending(techobjects::kAlarmAdjustmentLost));
  };
  check(1);  // missing
  std::ofstream(file) << "tomc-retain 1\nAxis1 1 3.5 0 0 1\nchecksum 0123456789abcdef\n";
  check(2);  // corrupt
  std::string error;
  ASSERT_TRUE(techobjects::write_retain_file(
      file, std::vector<RetainedRecord>{{"Other", {.AbsEncoderOffset = 1.0, .sequence = 1, .valid = true}}},
      error));
  check(3);  // no record for Axis1
}

// spec 03 §4.16: MC_SaveAbsoluteEncoderData is Busy until the store has written the file, then Done; a file
// that cannot be written ends it with 16#810A; a second request while the first is pending: 16#8109.
TEST_F(RetentiveStoreTest, SaveAbsoluteEncoderData) {
  PositioningAxisMachine m(absolute_data());
  RetentiveStore store(dir_ / "retain.dat");
  store.attach(*m.axis);
  instructions::MC_SaveAbsoluteEncoderData<RetentiveStore> save;
  instructions::MC_SaveAbsoluteEncoderData<RetentiveStore> second;
  m.user = [&] {
    store.cycle();
    save(store);
    second(store);
  };
  save.Execute = true;
  m.run(1);
  EXPECT_TRUE(save.Busy);
  second.Execute = true;
  m.run(1);
  EXPECT_TRUE(second.Error);
  EXPECT_EQ(second.ErrorID, techobjects::error_id::kBusy);
  m.run(3);
  EXPECT_TRUE(save.Busy);  // nothing written yet: service() has not run
  ASSERT_TRUE(store.service());
  m.run(2);
  EXPECT_TRUE(save.Done);
  EXPECT_EQ(techobjects::read_retain_file(store.file()).status, RetainFileStatus::kOk);

  RetentiveStore broken(dir_ / "no-such-dir" / "retain.dat");
  broken.attach(*m.axis);
  instructions::MC_SaveAbsoluteEncoderData<RetentiveStore> failing;
  failing.Execute = true;
  m.user = [&] {
    broken.cycle();
    failing(broken);
  };
  m.run(1);
  ASSERT_TRUE(broken.service());
  m.run(2);
  EXPECT_TRUE(failing.Error);
  EXPECT_EQ(failing.ErrorID, techobjects::error_id::kBackupFailed);
  EXPECT_NE(broken.last_error().find("no-such-dir"), std::string::npos);
}

}  // namespace
