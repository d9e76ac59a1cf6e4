#pragma once
// The retentive memory of absolute-encoder adjustments, as a file the runtime owns (spec 02 §5.9, seed 004
// §6.11.7–§6.11.8): what a CPU keeps across power-off (StatusSensor.AbsEncoderOffset, the cyclic encoder's
// measuring ranges) and what MC_SaveAbsoluteEncoderData backs up.
//
// The real-time side never does I/O: cycle() (call it once per cycle, e.g. from the MC_PostServo hook)
// notices a new adjustment and takes a snapshot into a buffer sized at set-up; request_save() does the same
// for MC_SaveAbsoluteEncoderData. service(), on a non-real-time thread (or between cycles), writes the
// snapshot: to "<file>.tmp", fsync, rename over <file>, fsync the directory — a crash leaves either the old
// or the new file, never a half-written one. The file carries a format line and a checksum; restore() at
// start-up hands each TO its record and raises alarm 432 on every absolute-encoder TO whose adjustment cannot
// be restored (file missing, corrupt, or no record for it), so that no axis starts with a silently wrong
// position.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/techobjects/axis/job.hpp"
#include "tomc/techobjects/axis/job_table.hpp"
#include "tomc/techobjects/runtime/retained_encoder_data.hpp"

namespace tomc::techobjects {

class PositioningAxis;
class ExternalEncoder;

struct RetainedRecord {
  std::string name;  // the TO's name: records are matched by name (the manual: identical TO names)
  RetainedEncoderData data;
};

enum class RetainFileStatus : std::uint8_t { kOk, kMissing, kCorrupt, kUnreadable };
std::string_view to_string(RetainFileStatus status) noexcept;

struct RetainFile {
  RetainFileStatus status = RetainFileStatus::kOk;
  std::vector<RetainedRecord> records;
  std::string message;  // what is wrong, with the line number, for the log
};

// The file format (text, one record per line, checksum over everything before the last line):
//   tomc-retain 1
//   <name> <valid 0|1> <AbsEncoderOffset %.17g> <MeasuringRangeCount> <LastAbsoluteValue> <sequence>
//   checksum <FNV-1a 64 of the lines above, 16 hex digits>
RetainFile read_retain_file(const std::filesystem::path& file);
// The same for the file's bytes (`source` names it in messages): what read_retain_file does after reading,
// and what the retain-file fuzzer feeds (tests/fuzz/retain_file_fuzzer.cpp).
RetainFile parse_retain_file(std::string_view text, std::string_view source);
// Writes atomically; false and `error` on failure (the old file, if any, is untouched then).
bool write_retain_file(const std::filesystem::path& file, std::span<const RetainedRecord> records,
                       std::string& error);

class RetentiveStore {
 public:
  explicit RetentiveStore(std::filesystem::path file);
  RetentiveStore(const RetentiveStore&) = delete;
  RetentiveStore& operator=(const RetentiveStore&) = delete;

  // ---- set-up (before Runtime::start()) ----
  // An axis' start-up encoder is the record named as the axis; every other absolute encoder Sensor[n] has its
  // own record "<axis>.Sensor[n]" (decision B6).
  void attach(PositioningAxis& axis);
  void attach(ExternalEncoder& encoder);
  // Reads the file and restores every attached TO; returns what was read (the caller logs `message`).
  RetainFile restore();

  // ---- real-time side: noexcept, no allocation, no I/O ----
  // Takes a snapshot when an attached TO has a new adjustment (its retained sequence changed).
  void cycle() noexcept;
  // MC_SaveAbsoluteEncoderData: snapshot all attached TOs; the job is Done once service() wrote the file.
  Submission request_save() noexcept;
  JobStatus job_status(JobId id) const noexcept { return jobs_.status(id); }

  // ---- non-real-time side ----
  // Writes a pending snapshot; returns true if it wrote one. Call it from a background thread or between
  // cycles of a single-threaded runtime.
  bool service();
  const std::filesystem::path& file() const noexcept { return file_; }
  std::uint64_t saves() const noexcept { return saves_.load(std::memory_order_acquire); }
  const std::string& last_error() const noexcept { return last_error_; }

 private:
  enum class JobKind : std::uint8_t { kNone, kSave };
  enum State : int { kIdle = 0, kRequested = 1, kFilling = 2 };  // kFilling: the cycle copies the snapshot
  struct Entry {
    PositioningAxis* axis = nullptr;
    ExternalEncoder* encoder = nullptr;
    std::uint64_t seen_sequence = 0;
    std::uint32_t sensor = 0;  // an axis' absolute Sensor[n] other than its start-up encoder (0: that one)
  };
  const RetainedEncoderData& retained_of(const Entry& e) const noexcept;
  bool snapshot(JobId job) noexcept;

  std::filesystem::path file_;
  std::vector<Entry> entries_;
  std::vector<RetainedRecord> buffer_;  // names filled at attach; data written by snapshot()
  std::atomic<int> state_{kIdle};
  JobId buffer_job_ = 0;  // the MC_SaveAbsoluteEncoderData job the snapshot belongs to (0: automatic)
  std::atomic<JobId> finished_job_{0};
  std::atomic<bool> finished_ok_{false};
  std::atomic<bool> retry_{false};
  std::atomic<std::uint64_t> saves_{0};
  JobTable<JobKind> jobs_;
  std::string last_error_;
};

}  // namespace tomc::techobjects
