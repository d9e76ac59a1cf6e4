#pragma once
// Traces: up to 32 signals recorded in the cycle at the servo rate (or every n-th servo cycle) from a trigger
// on, with samples from before the trigger. The recorder runs in the cycle: it evaluates the trigger and
// writes one row per sample into a fixed ring buffer that a reader drains from another thread. The cycle
// never waits: a full ring drops the sample and counts it as lost. The capture (not real-time) keeps the rows
// of one recording and cuts them around the trigger.
//
// Hand-over of a new recording: the reader thread stages a TraceSetup (probes resolved beforehand) and bumps
// a generation number; the cycle copies it at its next sample and confirms. Rows carry their generation, so
// rows of an older recording still in the ring are skipped.

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tomc/diagnostics/probe.hpp"

namespace tomc::diagnostics {

inline constexpr std::size_t kMaxTraceChannels = 32;
inline constexpr std::uint32_t kMaxTraceSamples = 100'000;  // pre + post samples of one recording
inline constexpr std::uint32_t kMaxTraceDecimation = 1000;

enum class TriggerKind : std::uint8_t {
  kImmediate,    // the first sample
  kRisingEdge,   // a bit (or BOOL) goes 0 -> 1
  kFallingEdge,  // a bit goes 1 -> 0
  kAbove,        // a value rises above the threshold (was <= before)
  kBelow,        // a value falls below the threshold (was >= before)
};
std::string_view to_string(TriggerKind kind) noexcept;

struct TraceSetup {
  std::array<Probe, kMaxTraceChannels> channels{};
  std::uint32_t channel_count = 0;
  TriggerKind trigger = TriggerKind::kImmediate;
  Probe trigger_probe{};
  double threshold = 0.0;
  std::uint32_t decimation = 1;    // one sample every n servo cycles
  std::uint32_t post_samples = 1;  // samples from the trigger on (the trigger sample included)
};

struct TraceRow {
  std::uint64_t cycle = 0;
  std::uint32_t generation = 0;
  std::array<double, kMaxTraceChannels> values{};
};

// The recorder's phase for one generation, as the cycle reports it.
enum class TracePhase : std::uint8_t { kIdle, kWaitingForTrigger, kRecording, kDone, kStopped };
std::string_view to_string(TracePhase phase) noexcept;

class TraceRecorder {
 public:
  // ring_rows is rounded up to a power of two (at least 64).
  explicit TraceRecorder(std::size_t ring_rows = 4096);
  TraceRecorder(const TraceRecorder&) = delete;
  TraceRecorder& operator=(const TraceRecorder&) = delete;

  // ---- the reader's thread (one caller at a time) ----
  // Stages a recording; returns its generation, or 0 while the cycle has not yet taken the previous one.
  std::uint32_t submit(const TraceSetup& setup) noexcept;
  void stop(std::uint32_t generation) noexcept;  // ends a recording early (TracePhase::kStopped)
  struct Progress {
    std::uint32_t generation = 0;
    TracePhase phase = TracePhase::kIdle;
    std::uint64_t trigger_cycle = kNoTrigger;
    std::uint64_t lost = 0;  // samples of this generation dropped because the ring was full
  };
  static constexpr std::uint64_t kNoTrigger = ~std::uint64_t{0};
  Progress progress() const noexcept;
  // Copies the rows written since the last drain, oldest first, to `out` (cleared first).
  void drain(std::vector<TraceRow>& out);

  // ---- the cycle ----
  void sample(std::uint64_t cycle) noexcept;

  std::size_t capacity() const noexcept { return mask_ + 1; }

 private:
  void take_staged() noexcept;
  bool triggered_now(double value) noexcept;
  void set_phase(TracePhase phase) noexcept;

  // staging: written by the reader while staged_generation_ == taken_generation_, read by the cycle after it
  // sees staged_generation_ change
  TraceSetup staged_{};
  std::atomic<std::uint32_t> staged_generation_{0};
  std::atomic<std::uint32_t> taken_generation_{0};
  std::atomic<std::uint32_t> stop_generation_{0};
  std::uint32_t next_generation_ = 1;  // reader's

  // the cycle's
  TraceSetup active_{};
  std::uint32_t generation_ = 0;
  bool running_ = false;
  bool triggered_ = false;
  bool have_previous_ = false;
  double previous_ = 0.0;
  std::uint32_t post_left_ = 0;
  std::uint64_t phase_counter_ = 0;

  // ring: written by the cycle at head_, read by the reader at tail_
  std::unique_ptr<TraceRow[]> ring_;
  std::size_t mask_ = 0;
  alignas(64) std::atomic<std::uint64_t> head_{0};
  alignas(64) std::atomic<std::uint64_t> tail_{0};

  // published progress
  std::atomic<std::uint64_t> phase_word_{0};  // generation << 8 | phase
  std::atomic<std::uint64_t> trigger_cycle_{kNoTrigger};
  std::atomic<std::uint64_t> lost_{0};
};

// One recording as the reader keeps it (not real-time).
struct TraceCapture {
  enum class State : std::uint8_t { kIdle, kWaitingForTrigger, kRecording, kComplete, kStopped };
  State state = State::kIdle;
  std::uint32_t generation = 0;
  std::vector<std::string> channels;  // "<TO>.<path>"
  std::string trigger_description;
  std::uint32_t pre_samples = 0;
  std::uint32_t post_samples = 0;
  std::uint32_t decimation = 1;
  double sample_period_s = 0.001;
  std::vector<std::uint64_t> cycles;  // one per row
  std::vector<double> values;         // rows x channels, row-major
  std::uint64_t trigger_cycle = TraceRecorder::kNoTrigger;
  std::size_t trigger_row = 0;  // index of the trigger sample in cycles/values
  std::uint64_t lost = 0;

  std::size_t rows() const noexcept { return cycles.size(); }
  // Appends the drained rows of this capture's generation and advances the state.
  void absorb(const std::vector<TraceRow>& rows, const TraceRecorder::Progress& progress);
  // The recorder finished (every row absorbed): complete, or stopped early (then the samples before a trigger
  // that never came are kept, trigger_row == rows()).
  void finish(bool stopped);

 private:
  std::vector<TraceRow> pre_window_;  // rows before the trigger is known (at most pre_samples kept)
};
std::string_view to_string(TraceCapture::State state) noexcept;

}  // namespace tomc::diagnostics
