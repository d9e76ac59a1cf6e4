// The retentive store of absolute-encoder adjustments (retentive_store.hpp).
#include "tomc/techobjects/runtime/retentive_store.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::techobjects {

namespace {

constexpr std::string_view kFormatLine = "tomc-retain 1";

std::uint64_t fnv1a(std::string_view text) noexcept {
  std::uint64_t h = 1469598103934665603ULL;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

std::string hex64(std::uint64_t v) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016" PRIx64, v);
  return buffer;
}

bool write_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

template <typename T>
bool parse(std::string_view token, T& out) {
  const auto r = std::from_chars(token.data(), token.data() + token.size(), out);
  return r.ec == std::errc{} && r.ptr == token.data() + token.size();
}

// strtod for the offset: from_chars for double is not in libstdc++ 12's every configuration.
bool parse_double(const std::string& token, double& out) {
  char* end = nullptr;
  errno = 0;
  out = std::strtod(token.c_str(), &end);
  return errno == 0 && end == token.c_str() + token.size() && std::isfinite(out);
}

}  // namespace

std::string_view to_string(RetainFileStatus status) noexcept {
  switch (status) {
    case RetainFileStatus::kOk:
      return "ok";
    case RetainFileStatus::kMissing:
      return "missing";
    case RetainFileStatus::kCorrupt:
      return "corrupt";
    case RetainFileStatus::kUnreadable:
      return "unreadable";
  }
  return "?";
}

RetainFile read_retain_file(const std::filesystem::path& file) {
  RetainFile result;
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    const bool missing = errno == ENOENT;
    result.status = missing ? RetainFileStatus::kMissing : RetainFileStatus::kUnreadable;
    result.message = file.string() + ": " + (missing ? "no such file" : std::strerror(errno));
    return result;
  }
  std::ostringstream whole;
  whole << in.rdbuf();
  return parse_retain_file(whole.str(), file.string());
}

RetainFile parse_retain_file(std::string_view text, std::string_view source) {
  RetainFile result;
  const auto corrupt = [&](std::size_t line, const std::string& why) {
    result.status = RetainFileStatus::kCorrupt;
    result.records.clear();
    result.message = std::string(source) + ":" + std::to_string(line) + ": " + why;
    return result;
  };
  // The checksum line is the last one; it covers every byte before it.
  const auto last = text.rfind("checksum ");
  if (last == std::string::npos || (last != 0 && text[last - 1] != '\n')) {
    return corrupt(1, "no checksum line (the file was cut short)");
  }
  std::string checksum_line(text.substr(last + 9));
  while (!checksum_line.empty() && (checksum_line.back() == '\n' || checksum_line.back() == '\r'))
    checksum_line.pop_back();
  const std::string body(text.substr(0, last));
  if (checksum_line != hex64(fnv1a(body)))
    return corrupt(1, "checksum mismatch (the file was altered or damaged)");
  std::istringstream lines(body);
  std::string line;
  std::size_t number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (number == 1) {
      if (line != kFormatLine)
        return corrupt(1, "not a tomc retain file (expected '" + std::string(kFormatLine) + "')");
      continue;
    }
    std::istringstream fields(line);
    std::string name, valid, offset, ranges, last_value, sequence, extra;
    if (!(fields >> name >> valid >> offset >> ranges >> last_value >> sequence) || (fields >> extra)) {
      return corrupt(number, "expected: name valid offset ranges last_value sequence");
    }
    RetainedRecord r;
    r.name = name;
    int v = 0;
    if (!parse(valid, v) || (v != 0 && v != 1) || !parse_double(offset, r.data.AbsEncoderOffset) ||
        !parse(ranges, r.data.MeasuringRangeCount) || !parse(last_value, r.data.LastAbsoluteValue) ||
        !parse(sequence, r.data.sequence)) {
      return corrupt(number, "a field is not a number in range");
    }
    r.data.valid = v == 1;
    result.records.push_back(std::move(r));
  }
  if (number == 0) return corrupt(1, "empty");
  return result;
}

bool write_retain_file(const std::filesystem::path& file, std::span<const RetainedRecord> records,
                       std::string& error) {
  std::string body = std::string(kFormatLine) + "\n";
  char number[40];
  for (const auto& r : records) {
    std::snprintf(number, sizeof number, "%.17g", r.data.AbsEncoderOffset);
    body += r.name + " " + (r.data.valid ? "1" : "0") + " " + number + " " +
            std::to_string(r.data.MeasuringRangeCount) + " " + std::to_string(r.data.LastAbsoluteValue) +
            " " + std::to_string(r.data.sequence) + "\n";
  }
  const std::string text = body + "checksum " + hex64(fnv1a(body)) + "\n";
  const std::filesystem::path temporary = file.string() + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = temporary.string() + ": " + std::strerror(errno);
    return false;
  }
  const bool written = write_all(fd, text) && ::fsync(fd) == 0;
  const int saved_errno = errno;
  ::close(fd);
  if (!written) {
    error = temporary.string() + ": " + std::strerror(saved_errno);
    std::filesystem::remove(temporary);
    return false;
  }
  if (::rename(temporary.c_str(), file.c_str()) != 0) {
    error = file.string() + ": " + std::strerror(errno);
    std::filesystem::remove(temporary);
    return false;
  }
  // The rename itself must reach the disk.
  const std::filesystem::path directory = file.has_parent_path() ? file.parent_path() : ".";
  const int dir = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    (void)::fsync(dir);
    ::close(dir);
  }
  return true;
}

RetentiveStore::RetentiveStore(std::filesystem::path file) : file_(std::move(file)) {}

void RetentiveStore::attach(PositioningAxis& axis) {
  entries_.push_back(Entry{&axis, nullptr, 0, 0});
  buffer_.push_back(RetainedRecord{std::string(axis.name()), {}});
  for (const AdditionalEncoder& e : axis.additional_encoders().all()) {
    if (!e.channel.chain().absolute_type()) continue;
    entries_.push_back(Entry{&axis, nullptr, 0, e.number});
    buffer_.push_back(
        RetainedRecord{std::string(axis.name()) + ".Sensor[" + std::to_string(e.number) + "]", {}});
  }
}

void RetentiveStore::attach(ExternalEncoder& encoder) {
  entries_.push_back(Entry{nullptr, &encoder, 0});
  buffer_.push_back(RetainedRecord{std::string(encoder.name()), {}});
}

const RetainedEncoderData& RetentiveStore::retained_of(const Entry& e) const noexcept {
  if (e.axis == nullptr) return e.encoder->retained();
  return e.sensor == 0 ? e.axis->retained() : *e.axis->retained_of_sensor(e.sensor);
}

RetainFile RetentiveStore::restore() {
  RetainFile file = read_retain_file(file_);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    Entry& e = entries_[i];
    const bool absolute = e.axis != nullptr ? e.axis->absolute_encoder() : e.encoder->absolute_encoder();
    if (!absolute && e.sensor == 0) continue;
    const auto report = [&](AdjustmentLoss cause) {
      const auto c = static_cast<std::uint32_t>(cause);
      // An encoder Sensor[n] outside the loop powers up not adjusted (StatusSensor[n].Adjusted 0); the axis'
      // homing state is not concerned, so no alarm 432 (decision B6).
      if (e.sensor != 0) return;
      if (e.axis != nullptr) {
        e.axis->report_adjustment_lost(c);
      } else {
        e.encoder->report_adjustment_lost(c);
      }
    };
    if (file.status == RetainFileStatus::kMissing) {
      report(AdjustmentLoss::kBackupMissing);
      continue;
    }
    if (file.status != RetainFileStatus::kOk) {
      report(AdjustmentLoss::kBackupCorrupt);
      continue;
    }
    const auto it = std::find_if(file.records.begin(), file.records.end(),
                                 [&](const RetainedRecord& r) { return r.name == buffer_[i].name; });
    if (it == file.records.end() || !it->data.valid) {
      report(AdjustmentLoss::kNoRecord);
      continue;
    }
    if (e.sensor != 0) {
      e.axis->restore_retained(e.sensor, it->data);
    } else if (e.axis != nullptr) {
      e.axis->restore_retained(it->data);
    } else {
      e.encoder->restore_retained(it->data);
    }
    e.seen_sequence = it->data.sequence;
  }
  return file;
}

bool RetentiveStore::snapshot(JobId job) noexcept {
  int expected = kIdle;
  if (!state_.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) return false;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    buffer_[i].data = retained_of(entries_[i]);
    entries_[i].seen_sequence = buffer_[i].data.sequence;
  }
  buffer_job_ = job;
  state_.store(kRequested, std::memory_order_release);  // service() may write it now
  return true;
}

void RetentiveStore::cycle() noexcept {
  // A write that finished: its MC_SaveAbsoluteEncoderData job ends.
  if (const JobId done = finished_job_.exchange(0, std::memory_order_acq_rel); done != 0) {
    const bool ok = finished_ok_.load(std::memory_order_acquire);
    jobs_.set(done, ok ? JobState::kDone : JobState::kError, ok ? 0 : error_id::kBackupFailed);
  }
  // A write that failed is tried again with the next snapshot (the adjustment must reach the file).
  if (retry_.exchange(false, std::memory_order_acq_rel)) {
    for (Entry& e : entries_)
      e.seen_sequence = ~std::uint64_t{0};
  }
  for (const Entry& e : entries_) {
    if (retained_of(e).sequence != e.seen_sequence) {
      (void)snapshot(0);  // busy: retried in a later cycle, the sequence still differs
      return;
    }
  }
}

Submission RetentiveStore::request_save() noexcept {
  const JobId id = jobs_.create(JobKind::kSave, JobState::kActive);
  if (!snapshot(id)) {
    jobs_.set(id, JobState::kError, error_id::kBusy);
    return Submission::reject(error_id::kBusy);
  }
  return Submission::accept(id);
}

bool RetentiveStore::service() {
  if (state_.load(std::memory_order_acquire) != kRequested) return false;
  std::string error;
  const bool ok = write_retain_file(file_, buffer_, error);
  last_error_ = ok ? std::string() : error;
  if (ok) saves_.fetch_add(1, std::memory_order_acq_rel);
  const JobId job = buffer_job_;
  finished_ok_.store(ok, std::memory_order_release);
  if (!ok) retry_.store(true, std::memory_order_release);
  if (job != 0) finished_job_.store(job, std::memory_order_release);
  state_.store(kIdle, std::memory_order_release);
  return true;
}

}  // namespace tomc::techobjects
