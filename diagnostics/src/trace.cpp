// Trace recorder (the cycle's side) and capture (the reader's side), trace.hpp.
#include "tomc/diagnostics/trace.hpp"

#include <algorithm>

namespace tomc::diagnostics {

std::string_view to_string(TriggerKind kind) noexcept {
  switch (kind) {
    case TriggerKind::kImmediate:
      return "immediate";
    case TriggerKind::kRisingEdge:
      return "rising";
    case TriggerKind::kFallingEdge:
      return "falling";
    case TriggerKind::kAbove:
      return "above";
    case TriggerKind::kBelow:
      return "below";
  }
  return "?";
}

std::string_view to_string(TracePhase phase) noexcept {
  switch (phase) {
    case TracePhase::kIdle:
      return "idle";
    case TracePhase::kWaitingForTrigger:
      return "waiting";
    case TracePhase::kRecording:
      return "recording";
    case TracePhase::kDone:
      return "done";
    case TracePhase::kStopped:
      return "stopped";
  }
  return "?";
}

std::string_view to_string(TraceCapture::State state) noexcept {
  switch (state) {
    case TraceCapture::State::kIdle:
      return "idle";
    case TraceCapture::State::kWaitingForTrigger:
      return "waiting for trigger";
    case TraceCapture::State::kRecording:
      return "recording";
    case TraceCapture::State::kComplete:
      return "complete";
    case TraceCapture::State::kStopped:
      return "stopped";
  }
  return "?";
}

TraceRecorder::TraceRecorder(std::size_t ring_rows) {
  std::size_t capacity = 64;
  while (capacity < ring_rows)
    capacity *= 2;
  ring_ = std::make_unique<TraceRow[]>(capacity);
  mask_ = capacity - 1;
}

// ---- the reader's thread ----

std::uint32_t TraceRecorder::submit(const TraceSetup& setup) noexcept {
  // The cycle may still be copying the previous setup: the staging area is free only once it confirmed.
  if (staged_generation_.load(std::memory_order_relaxed) !=
      taken_generation_.load(std::memory_order_acquire)) {
    return 0;
  }
  const std::uint32_t generation = next_generation_++;
  if (next_generation_ == 0) next_generation_ = 1;
  staged_ = setup;
  staged_generation_.store(generation, std::memory_order_release);
  return generation;
}

void TraceRecorder::stop(std::uint32_t generation) noexcept {
  stop_generation_.store(generation, std::memory_order_relaxed);
}

TraceRecorder::Progress TraceRecorder::progress() const noexcept {
  Progress p;
  const std::uint64_t word = phase_word_.load(std::memory_order_acquire);
  p.generation = static_cast<std::uint32_t>(word >> 8);
  p.phase = static_cast<TracePhase>(word & 0xFF);
  p.trigger_cycle = trigger_cycle_.load(std::memory_order_acquire);
  p.lost = lost_.load(std::memory_order_relaxed);
  return p;
}

void TraceRecorder::drain(std::vector<TraceRow>& out) {
  out.clear();
  const std::uint64_t head = head_.load(std::memory_order_acquire);
  std::uint64_t tail = tail_.load(std::memory_order_relaxed);
  out.reserve(static_cast<std::size_t>(head - tail));
  for (; tail != head; ++tail)
    out.push_back(ring_[tail & mask_]);
  tail_.store(tail, std::memory_order_release);
}

// ---- the cycle ----

void TraceRecorder::set_phase(TracePhase phase) noexcept {
  phase_word_.store((static_cast<std::uint64_t>(generation_) << 8) | static_cast<std::uint64_t>(phase),
                    std::memory_order_release);
}

void TraceRecorder::take_staged() noexcept {
  const std::uint32_t staged = staged_generation_.load(std::memory_order_acquire);
  if (staged == generation_) return;
  active_ = staged_;
  generation_ = staged;
  taken_generation_.store(staged, std::memory_order_release);
  running_ = active_.channel_count > 0 && active_.post_samples > 0 && active_.decimation > 0;
  triggered_ = false;
  have_previous_ = false;
  post_left_ = active_.post_samples;
  phase_counter_ = 0;
  // Reset before the first row of this generation is written, so a reader that sees a row also sees these.
  lost_.store(0, std::memory_order_relaxed);
  trigger_cycle_.store(kNoTrigger, std::memory_order_release);
  set_phase(running_ ? TracePhase::kWaitingForTrigger : TracePhase::kStopped);
}

bool TraceRecorder::triggered_now(double value) noexcept {
  const double before = previous_;
  const bool had = have_previous_;
  previous_ = value;
  have_previous_ = true;
  switch (active_.trigger) {
    case TriggerKind::kImmediate:
      return true;
    case TriggerKind::kRisingEdge:
      return had && before == 0.0 && value != 0.0;
    case TriggerKind::kFallingEdge:
      return had && before != 0.0 && value == 0.0;
    case TriggerKind::kAbove:
      return had && before <= active_.threshold && value > active_.threshold;
    case TriggerKind::kBelow:
      return had && before >= active_.threshold && value < active_.threshold;
  }
  return false;
}

void TraceRecorder::sample(std::uint64_t cycle) noexcept {
  take_staged();
  if (!running_) return;
  if (stop_generation_.load(std::memory_order_relaxed) == generation_) {
    running_ = false;
    set_phase(TracePhase::kStopped);
    return;
  }
  if (phase_counter_++ % active_.decimation != 0) return;
  if (!triggered_) {
    const double trigger_value =
        active_.trigger == TriggerKind::kImmediate ? 0.0 : active_.trigger_probe.value();
    if (triggered_now(trigger_value)) {
      triggered_ = true;
      trigger_cycle_.store(cycle, std::memory_order_release);  // before the row: readers classify by it
      set_phase(TracePhase::kRecording);
    }
  }
  const std::uint64_t head = head_.load(std::memory_order_relaxed);
  if (head - tail_.load(std::memory_order_acquire) > mask_) {
    lost_.fetch_add(1, std::memory_order_relaxed);  // the reader fell behind: drop, never wait
  } else {
    TraceRow& row = ring_[head & mask_];
    row.cycle = cycle;
    row.generation = generation_;
    for (std::uint32_t i = 0; i < active_.channel_count; ++i)
      row.values[i] = active_.channels[i].value();
    head_.store(head + 1, std::memory_order_release);
  }
  if (triggered_ && --post_left_ == 0) {
    running_ = false;
    set_phase(TracePhase::kDone);
  }
}

// ---- the capture ----

void TraceCapture::absorb(const std::vector<TraceRow>& rows, const TraceRecorder::Progress& progress) {
  if (state == State::kIdle || state == State::kComplete || state == State::kStopped) return;
  const std::size_t width = channels.size();
  const bool ours = progress.generation == generation;
  const bool trigger_known = ours && progress.trigger_cycle != TraceRecorder::kNoTrigger;
  auto append = [&](const TraceRow& row) {
    if (cycles.size() - trigger_row >= post_samples && trigger_cycle != TraceRecorder::kNoTrigger) return;
    cycles.push_back(row.cycle);
    values.insert(values.end(), row.values.begin(), row.values.begin() + static_cast<std::ptrdiff_t>(width));
  };
  for (const TraceRow& r : rows) {
    if (r.generation != generation) continue;  // an older recording still in the ring
    if (trigger_cycle == TraceRecorder::kNoTrigger) {
      pre_window_.push_back(r);
    } else if (r.cycle >= trigger_cycle) {
      append(r);
    }
  }
  if (trigger_cycle == TraceRecorder::kNoTrigger && trigger_known) {
    // The trigger is known now: the samples before it (at most pre_samples) open the recording, the rest
    // follow it.
    trigger_cycle = progress.trigger_cycle;
    std::size_t first_after = 0;
    while (first_after < pre_window_.size() && pre_window_[first_after].cycle < trigger_cycle)
      ++first_after;
    const std::size_t skip = first_after > pre_samples ? first_after - pre_samples : 0;
    for (std::size_t i = skip; i < first_after; ++i) {
      cycles.push_back(pre_window_[i].cycle);
      values.insert(values.end(), pre_window_[i].values.begin(),
                    pre_window_[i].values.begin() + static_cast<std::ptrdiff_t>(width));
    }
    trigger_row = cycles.size();
    for (std::size_t i = first_after; i < pre_window_.size(); ++i)
      append(pre_window_[i]);
    pre_window_.clear();
    state = State::kRecording;
  } else if (trigger_cycle == TraceRecorder::kNoTrigger && pre_window_.size() > pre_samples) {
    // Without a trigger only the newest pre_samples rows matter. (Rows at or after the trigger cannot be
    // here: the caller reads `progress` after draining, and the cycle publishes the trigger before its row.)
    pre_window_.erase(pre_window_.begin(),
                      pre_window_.begin() + static_cast<std::ptrdiff_t>(pre_window_.size() - pre_samples));
  }
  if (ours) lost = progress.lost;
}

void TraceCapture::finish(bool stopped) {
  if (state == State::kIdle || state == State::kComplete || state == State::kStopped) return;
  if (trigger_cycle == TraceRecorder::kNoTrigger) {
    for (const TraceRow& r : pre_window_) {
      cycles.push_back(r.cycle);
      values.insert(values.end(), r.values.begin(),
                    r.values.begin() + static_cast<std::ptrdiff_t>(channels.size()));
    }
    pre_window_.clear();
    trigger_row = cycles.size();
  }
  state = stopped ? State::kStopped : State::kComplete;
}

}  // namespace tomc::diagnostics
