// The controller side of the gateway contract without Fast DDS (exchange_core.hpp, docs/gateway.md).
#include "tomc/drives/dds/exchange_core.hpp"

#include <algorithm>
#include <stdexcept>

#include "tomc/drives/dds/contract.hpp"
#include "tomc/telegrams/layout.hpp"

namespace tomc::drives::dds {

namespace tg = tomc::telegrams;

namespace {

std::int64_t steady_now_ns() noexcept {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

ExchangeCore::ExchangeCore(ExchangeOptions options) : options_(options) {
  if (options_.controller == 0) throw std::invalid_argument("gateway exchange: controller id must not be 0");
  if (options_.cycle_time_ns == 0) throw std::invalid_argument("gateway exchange: cycle time must be > 0");
}

namespace {

// Bits 12..15 of the 16-bit word at byte `offset` (STW2/ZSW2: the sign-of-life, spec 06 §5); a word's high
// byte comes first unless the device's words are little-endian.
int high_nibble(const Frame& frame, int offset, const DeviceConfig& config) noexcept {
  const auto at = static_cast<std::size_t>(offset);
  const bool low_first = config.codec.byte_order == tg::ByteOrder::kLittleBytes ||
                         config.codec.byte_order == tg::ByteOrder::kLittle;
  return std::to_integer<int>(frame.bytes[low_first ? at + 1 : at]) >> 4;
}

}  // namespace

std::size_t ExchangeCore::add_device(const std::string& name, const DeviceConfig& config) {
  if (frozen_) throw std::invalid_argument("gateway exchange: devices are added before the exchange starts");
  if (name.empty() || name.size() > kMaxNameLength) {
    throw std::invalid_argument("gateway device name '" + name + "': 1.." + std::to_string(kMaxNameLength) +
                                " characters");
  }
  if (find(name) != devices_.size()) {
    throw std::invalid_argument("gateway device '" + name + "' is added twice");
  }
  if (devices_.size() >= kMaxDevices) {
    throw std::invalid_argument("gateway exchange: more than " + std::to_string(kMaxDevices) +
                                " devices on one link");
  }
  if (const auto problem = validate(config); !problem.empty()) {
    throw std::invalid_argument("gateway device '" + name + "': " + problem);
  }
  auto d = std::make_unique<Device>();
  d->name = name;
  d->config = config;
  d->byte_order = to_contract(config.codec.byte_order);
  if (config.drive_telegram != 0) {
    if (const auto layout = tg::find_layout(config.drive_telegram, tg::Direction::kActual); layout.ok())
      d->zsw2_offset = layout.value().offset_of(tg::Signal::ZSW2);
    if (const auto layout = tg::find_layout(config.drive_telegram, tg::Direction::kSetpoint); layout.ok())
      d->stw2_offset = layout.value().offset_of(tg::Signal::STW2);
  }
  const DeviceFrames actual = make_frames(config, tg::Direction::kActual);
  d->answers.for_each_slot([&](Answer& a) { a.frames = actual; });
  devices_.push_back(std::move(d));
  by_name_.emplace_back(name, devices_.size() - 1);
  std::sort(by_name_.begin(), by_name_.end());
  return devices_.size() - 1;
}

void ExchangeCore::freeze() {
  if (frozen_) return;
  if (devices_.empty()) throw std::invalid_argument("gateway exchange: no device");
  batches_.for_each_slot([&](SetpointBatch& b) {
    b.devices.resize(devices_.size());
    for (std::size_t i = 0; i < devices_.size(); ++i)
      b.devices[i] = make_frames(devices_[i]->config, tg::Direction::kSetpoint);
  });
  round_trip_histogram_ = std::make_unique<std::array<std::atomic<std::uint32_t>, kRoundTripBuckets>>();
  frozen_ = true;
}

std::size_t ExchangeCore::find(std::string_view name) const noexcept {
  const auto it = std::lower_bound(by_name_.begin(), by_name_.end(), name,
                                   [](const auto& entry, std::string_view n) { return entry.first < n; });
  return it != by_name_.end() && it->first == name ? it->second : devices_.size();
}

// ---------------------------------------------------------------------------------------------------------
// Cyclic thread

bool ExchangeCore::is_current(const Answer& a, std::uint64_t sent) const noexcept {
  // Before the first setpoint: the gateway's idle answer, or its answer to this controller's probe, is the
  // drive as it stands (docs/gateway.md §4).
  if (sent == 0) return a.controller == 0 || (a.controller == options_.controller && !a.has_setpoint);
  if (a.controller != options_.controller || !a.has_setpoint || a.setpoint_cycle >= sent) return false;
  return sent - 1 - a.setpoint_cycle <= options_.max_answer_age_cycles;
}

bool ExchangeCore::read_actual(std::size_t device, DeviceFrames& actual) noexcept {
  Device& d = *devices_[device];
  LinkHealth& h = d.health;
  ++h.exchanges;
  const std::uint64_t sent = cycles_sent_.load(std::memory_order_relaxed);  // written by this thread
  bool fresh = false;
  if (frozen_ && d.answers.take()) {
    const Answer& a = d.answers.value();
    if (d.incarnation != 0 && a.incarnation != d.incarnation) {
      // A restarted gateway: whatever it answers now, the exchange was broken (the TO raises its link alarm).
      ++h.peer_restarts;
      d.restarts.fetch_add(1, std::memory_order_relaxed);
    }
    d.incarnation = a.incarnation;
    fresh = is_current(a, sent);
    if (fresh) {
      for (std::size_t i = 0; i < kSlotCount; ++i) {
        if (a.frames.slots[i].length == actual.slots[i].length) actual.slots[i] = a.frames.slots[i];
      }
    } else {
      d.stale.fetch_add(1, std::memory_order_relaxed);
    }
  }
  if (fresh) {
    h.up = true;
    h.consecutive_missed = 0;
    d.last_fresh.store(sent + 1, std::memory_order_relaxed);
  } else {
    // Nothing new, or nothing usable: the frames are left as they were and the TO counts the cycle as missed.
    h.up = false;
    ++h.consecutive_missed;
    ++h.missed_total;
  }
  return fresh;
}

void ExchangeCore::write_setpoint(std::size_t device, const DeviceFrames& setpoint) noexcept {
  if (!frozen_) return;
  Device& d = *devices_[device];
  const std::uint64_t sent = cycles_sent_.load(std::memory_order_relaxed);
  if (d.written_in == sent + 1) {
    // The device writes a second time before every device wrote once: some device of this link is not
    // written every cycle (not added to the runtime). Send what there is rather than nothing.
    incomplete_cycles_.fetch_add(1, std::memory_order_relaxed);
    flush();
  }
  SetpointBatch& batch = batches_.write_slot();
  DeviceFrames& into = batch.devices[device];
  for (std::size_t i = 0; i < kSlotCount; ++i) {
    if (into.slots[i].length != 0 && setpoint.slots[i].length == into.slots[i].length) {
      into.slots[i].bytes = setpoint.slots[i].bytes;
    }
  }
  d.written_in = cycles_sent_.load(std::memory_order_relaxed) + 1;
  if (++written_count_ == devices_.size()) flush();
}

void ExchangeCore::flush() noexcept {
  const std::uint64_t cycle = cycles_sent_.load(std::memory_order_relaxed);
  SetpointBatch& batch = batches_.write_slot();
  batch.cycle = cycle;
  // The slot the producer continues in holds frames of an older cycle; every device overwrites its own.
  batches_.publish();
  const std::size_t ring = cycle % kFlushRing;
  flush_ns_[ring].store(steady_now_ns(), std::memory_order_relaxed);
  flush_cycle_[ring].store(cycle + 1, std::memory_order_release);
  cycles_sent_.store(cycle + 1, std::memory_order_release);
  written_count_ = 0;
  setpoint_signal_.fetch_add(1, std::memory_order_release);
  setpoint_signal_.notify_one();  // a futex wake when the sender sleeps; never waits
}

// ---------------------------------------------------------------------------------------------------------
// Sender thread

void ExchangeCore::prepare_probe(gateway::SetpointCycle& sample) const {
  sample.contract_version(kContractVersion);
  sample.controller(options_.controller);
  sample.cycle(0);
  sample.cycle_time_ns(options_.cycle_time_ns);
  sample.devices().clear();
}

void ExchangeCore::prepare_sample(gateway::SetpointCycle& sample) const {
  sample.contract_version(kContractVersion);
  sample.controller(options_.controller);
  sample.cycle_time_ns(options_.cycle_time_ns);
  sample.devices().resize(devices_.size());
  for (std::size_t i = 0; i < devices_.size(); ++i) {
    auto& e = sample.devices()[i];
    e.device(devices_[i]->name);
    e.byte_order(devices_[i]->byte_order);
    for (std::size_t s = 0; s < kSlotCount; ++s) {
      e.slots()[s].number(devices_[i]->config.telegram(static_cast<Slot>(s)));
      e.slots()[s].pzd().reserve(tg::kMaxFrameBytes);
    }
  }
}

bool ExchangeCore::take_setpoints(gateway::SetpointCycle& sample) noexcept {
  if (!frozen_ || !batches_.take()) return false;
  const SetpointBatch& batch = batches_.value();
  sample.cycle(batch.cycle);
  for (std::size_t i = 0; i < devices_.size() && i < sample.devices().size(); ++i) {
    Device& d = *devices_[i];
    fill(d.config, batch.devices[i], sample.devices()[i].slots());
    if (d.stw2_offset >= 0) {
      const int sign_of_life = high_nibble(batch.devices[i][Slot::kDrive], d.stw2_offset, d.config);
      if (d.master_sign_of_life >= 0 && sign_of_life != d.master_sign_of_life)
        d.master_sign_of_life_changes.fetch_add(1, std::memory_order_relaxed);
      d.master_sign_of_life = sign_of_life;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------------------
// Listener thread

void ExchangeCore::route(const gateway::ActualCycle& sample, std::int64_t now_ns) noexcept {
  if (!frozen_) return;
  std::lock_guard<std::mutex> lock(route_mutex_);  // listener threads only; the cyclic thread never takes it
  samples_received_.fetch_add(1, std::memory_order_relaxed);
  if (sample.contract_version() != kContractVersion || sample.devices().size() > kMaxDevices ||
      sample.incarnation() == 0) {
    samples_rejected_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  try {
    // Sequence per gateway: a jump is lost answers, a step back is an old or duplicated sample.
    auto g = std::find_if(gateways_.begin(), gateways_.end(),
                          [&](const GatewaySequence& s) { return sample.gateway() == s.name; });
    if (g == gateways_.end()) {
      gateways_.push_back(GatewaySequence{sample.gateway().to_string(), 0, 0});
      g = gateways_.end() - 1;
    }
    if (g->incarnation == sample.incarnation()) {
      if (sample.sequence_number() <= g->sequence) {
        samples_rejected_.fetch_add(1, std::memory_order_relaxed);
        return;
      }
      answers_lost_.fetch_add(sample.sequence_number() - g->sequence - 1, std::memory_order_relaxed);
    }
    g->incarnation = sample.incarnation();
    g->sequence = sample.sequence_number();
  } catch (...) {
    samples_rejected_.fetch_add(1, std::memory_order_relaxed);  // out of memory for a new gateway's name
    return;
  }

  for (const gateway::DeviceActual& e : sample.devices()) {
    const std::size_t index = find(e.device().c_str());
    if (index == devices_.size()) {
      foreign_devices_.fetch_add(1, std::memory_order_relaxed);  // another controller's device
      continue;
    }
    Device& d = *devices_[index];
    if (!matches(d.config, tg::Direction::kActual, e.byte_order(), e.slots())) {
      d.rejected.fetch_add(1, std::memory_order_relaxed);
      try {
        d.mismatch = "gateway '" + sample.gateway().to_string() +
                     "': " + mismatch(d.config, tg::Direction::kActual, e.byte_order(), e.slots());
      } catch (...) {
      }
      continue;
    }
    Answer& a = d.answers.write_slot();
    a.incarnation = sample.incarnation();
    a.controller = sample.controller();
    a.has_setpoint = e.has_setpoint();
    a.setpoint_cycle = e.setpoint_cycle();
    extract(e.slots(), a.frames);
    if (d.zsw2_offset >= 0 && sample.controller() == options_.controller && e.has_setpoint()) {
      const auto sign_of_life =
          static_cast<std::uint8_t>(high_nibble(a.frames[Slot::kDrive], d.zsw2_offset, d.config));
      if (d.sign_of_life_answers.fetch_add(1, std::memory_order_relaxed) > 0 &&
          sign_of_life != d.sign_of_life)
        d.sign_of_life_changes.fetch_add(1, std::memory_order_relaxed);
      d.sign_of_life = sign_of_life;
    }
    d.answers.publish();
    d.answer_count.fetch_add(1, std::memory_order_relaxed);
    // Answered to this controller (a probe or a cycle): the whole loop works for this device.
    if (sample.controller() == options_.controller && !d.heard_by_us.exchange(true)) heard_.fetch_add(1);
    if (sample.controller() == options_.controller && e.has_setpoint() &&
        e.setpoint_cycle() + 1 > d.answered.load(std::memory_order_relaxed)) {
      d.answered.store(e.setpoint_cycle() + 1, std::memory_order_release);
    }
  }

  std::uint64_t completed = UINT64_MAX;
  for (const auto& d : devices_)
    completed = std::min(completed, d->answered.load(std::memory_order_relaxed));
  if (completed > completed_.load(std::memory_order_relaxed)) {
    completed_.store(completed, std::memory_order_release);
    record_round_trip(completed - 1, now_ns);
  }
  { std::lock_guard<std::mutex> wake(wait_mutex_); }
  answered_cv_.notify_all();
}

void ExchangeCore::record_round_trip(std::uint64_t cycle, std::int64_t now_ns) noexcept {
  const std::size_t ring = cycle % kFlushRing;
  if (flush_cycle_[ring].load(std::memory_order_acquire) != cycle + 1) return;  // overwritten: too old
  const std::int64_t rtt = now_ns - flush_ns_[ring].load(std::memory_order_relaxed);
  if (rtt < 0) return;
  const auto bucket = std::min<std::size_t>(static_cast<std::size_t>(rtt / 1000), kRoundTripBuckets - 1);
  (*round_trip_histogram_)[bucket].fetch_add(1, std::memory_order_relaxed);
  round_trips_.fetch_add(1, std::memory_order_relaxed);
  if (rtt > round_trip_max_ns_.load(std::memory_order_relaxed))
    round_trip_max_ns_.store(rtt, std::memory_order_relaxed);
}

// ---------------------------------------------------------------------------------------------------------
// Any thread

bool ExchangeCore::wait_for_answers(std::chrono::nanoseconds timeout) {
  const std::uint64_t target = cycles_sent();
  std::unique_lock<std::mutex> lock(wait_mutex_);
  return answered_cv_.wait_for(lock, timeout,
                               [&] { return completed_.load(std::memory_order_acquire) >= target; });
}

bool ExchangeCore::wait_until_heard(std::chrono::nanoseconds timeout) {
  std::unique_lock<std::mutex> lock(wait_mutex_);
  return answered_cv_.wait_for(lock, timeout, [&] { return heard_.load() >= devices_.size(); });
}

GatewayDeviceCounters ExchangeCore::counters(std::size_t device) const noexcept {
  const Device& d = *devices_[device];
  return GatewayDeviceCounters{d.answer_count.load(),
                               d.stale.load(),
                               d.rejected.load(),
                               d.restarts.load(),
                               d.sign_of_life_answers.load(),
                               d.sign_of_life_changes.load(),
                               d.master_sign_of_life_changes.load()};
}

std::string ExchangeCore::last_mismatch(std::size_t device) const {
  std::lock_guard<std::mutex> lock(route_mutex_);
  return devices_.at(device)->mismatch;
}

void ExchangeCore::reset_round_trips() noexcept {
  if (!round_trip_histogram_) return;
  for (auto& b : *round_trip_histogram_)
    b.store(0, std::memory_order_relaxed);
  round_trips_.store(0, std::memory_order_relaxed);
  round_trip_max_ns_.store(0, std::memory_order_relaxed);
}

ExchangeStatistics ExchangeCore::statistics() const {
  ExchangeStatistics s;
  s.cycles_sent = cycles_sent();
  s.cycles_answered = completed_.load();
  s.samples_received = samples_received_.load();
  s.samples_rejected = samples_rejected_.load();
  s.answers_lost = answers_lost_.load();
  s.foreign_devices = foreign_devices_.load();
  s.incomplete_cycles = incomplete_cycles_.load();
  s.round_trips = round_trips_.load();
  if (s.round_trips == 0 || !round_trip_histogram_) return s;
  s.round_trip_max_us = static_cast<double>(round_trip_max_ns_.load()) / 1000.0;
  std::uint64_t total = 0;
  for (const auto& b : *round_trip_histogram_)
    total += b.load(std::memory_order_relaxed);
  auto percentile = [&](double q) {
    const auto rank = static_cast<std::uint64_t>(q * static_cast<double>(total - 1));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < kRoundTripBuckets; ++i) {
      seen += (*round_trip_histogram_)[i].load(std::memory_order_relaxed);
      if (seen > rank) return static_cast<double>(i) + 0.5;  // middle of the 1 us bucket
    }
    return static_cast<double>(kRoundTripBuckets);
  };
  if (total != 0) {
    s.round_trip_median_us = percentile(0.5);
    s.round_trip_p99_us = percentile(0.99);
  }
  return s;
}

}  // namespace tomc::drives::dds
