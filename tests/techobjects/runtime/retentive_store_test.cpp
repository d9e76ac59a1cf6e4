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

// Missing file, corrupt file, no record for this TO: alarm 432 with the cause, not homed; an incremental axis
// attached to the same store is not concerned.
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
