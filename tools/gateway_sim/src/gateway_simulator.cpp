// The gateway simulator (gateway_simulator.hpp, docs/gateway.md "Gateway simulator"). A simulator, not a
// real-time component: one mutex guards the drives and the session, the DDS listener threads and the
// gateway's own clock thread take it in turn.
#include "tomc/gateway_sim/gateway_simulator.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <fastdds/dds/publisher/DataWriter.hpp>

#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/gateway_side.hpp"
#include "tomc/drives/dds/participant.hpp"
#include "tomc/drives/dds/type_support.hpp"
#include "tomc/drives/simulated_drive.hpp"

namespace tomc::gateway_sim {

namespace dds = tomc::drives::dds;
namespace fdds = eprosima::fastdds::dds;
namespace gw = tomc::gateway;
using Clock = std::chrono::steady_clock;

namespace {

constexpr std::uint64_t kMaxCatchUpSteps = 100;  // a longer gap is a new start, not lost cycles
constexpr std::uint64_t kDropForever = UINT64_MAX;

struct Device {
  std::string name;
  drives::DeviceConfig config;
  gw::ByteOrder byte_order = gw::BYTE_ORDER_BIG;
  std::unique_ptr<drives::SimulatedDrive> drive;
  drives::DeviceFrames setpoint{};
  drives::DeviceFrames actual{};
  bool has_setpoint = false;
  std::uint64_t setpoint_cycle = 0;
  bool disconnected = false;
  std::string mismatch;  // what the controller sends differently, "" when it matches
};

}  // namespace

struct GatewaySimulator::Impl {
  scenario::GatewaySimConfig config;
  std::vector<Device> devices;
  std::chrono::nanoseconds cycle{};
  std::chrono::nanoseconds watchdog{};

  // Listeners before the participant: members are destroyed in reverse order, entities before listeners.
  std::unique_ptr<fdds::DataReaderListener> setpoint_listener;
  std::unique_ptr<fdds::DataReaderListener> command_listener;
  std::unique_ptr<dds::GatewayEndpoints> endpoints;
  fdds::TypeSupport command_type{new dds::GatewayCommandType()};
  fdds::DataWriter* actual_writer = nullptr;
  fdds::DataWriter* status_writer = nullptr;

  mutable std::mutex mutex;                                   // everything below
  dds::SetpointSession session{std::chrono::nanoseconds(1)};  // G1, G2, G5, G6, G9
  bool stopped = false;
  Clock::time_point silent_until{};
  std::uint64_t drop_remaining = 0;
  std::uint32_t drop_every = 0;
  std::uint32_t delay_us = 0;
  std::uint64_t answer_count = 0;
  std::uint64_t command_number = 0;
  SimulatorCounters counters{};
  gw::ActualCycle answer;
  gw::GatewayStatus status;
  std::string status_signature;
  Clock::time_point status_time{};

  std::mutex delay_mutex;
  std::condition_variable delay_cv;
  std::deque<std::pair<Clock::time_point, gw::ActualCycle>> delayed;

  std::atomic<bool> stop{false};
  std::thread clock_thread;
  std::thread delay_thread;

  // ---- with `mutex` held ----
  void release_controller() {
    session.release();
    forget_setpoints();
  }
  void forget_setpoints() {
    for (auto& d : devices)
      d.has_setpoint = false;
  }

  void step_all() {
    for (auto& d : devices)
      (void)d.drive->read_actual(d.actual);
  }

  // One ActualCycle of every connected device. `probe`: the answer to a probe of that controller, with no
  // setpoint applied for it.
  void publish_answer(Clock::time_point now, std::uint64_t probe = 0) {
    const std::uint64_t sequence = session.next_sequence();  // also for a dropped answer: the gap shows
    if (drop_remaining > 0) {
      if (drop_remaining != kDropForever) --drop_remaining;
      ++counters.answers_dropped;
      return;
    }
    ++answer_count;
    if (drop_every != 0 && answer_count % drop_every == 0) {
      ++counters.answers_dropped;
      return;
    }
    session.fill_answer(answer, config.gateway, sequence, probe != 0 ? probe : session.controller());
    std::size_t n = 0;
    for (const auto& d : devices)
      n += d.disconnected ? 0 : 1;
    answer.devices().resize(n);
    std::size_t i = 0;
    for (const auto& d : devices) {
      if (d.disconnected) continue;
      auto& e = answer.devices()[i++];
      e.device(d.name);
      e.byte_order(d.byte_order);
      e.has_setpoint(probe == 0 && d.has_setpoint);
      e.setpoint_cycle(d.setpoint_cycle);
      dds::fill(d.config, d.actual, e.slots());
    }
    ++session.counters().answers_published;
    if (delay_us != 0) {
      {
        std::lock_guard<std::mutex> lock(delay_mutex);
        delayed.emplace_back(now + std::chrono::microseconds(delay_us), answer);
      }
      delay_cv.notify_one();
      return;
    }
    actual_writer->write(&answer);
  }

  void publish_status(Clock::time_point now, bool force) {
    std::string signature = std::to_string(session.incarnation()) + "/" +
                            std::to_string(session.controller()) + "/" + std::to_string(command_number);
    status.devices().resize(devices.size());
    for (std::size_t i = 0; i < devices.size(); ++i) {
      const Device& d = devices[i];
      auto& s = status.devices()[i];
      s.device(d.name);
      s.byte_order(d.byte_order);
      const auto telegrams = dds::slot_telegrams(d.config);
      for (std::size_t k = 0; k < telegrams.size(); ++k)
        s.telegrams()[k] = telegrams[k];
      std::string detail;
      if (d.disconnected) {
        s.state(gw::DEVICE_DISCONNECTED);
        s.fault(0);
        detail = "disconnected (simulator command)";
      } else if (!d.mismatch.empty()) {
        s.state(gw::DEVICE_CONFIG_MISMATCH);
        s.fault(0);
        detail = "the controller sends " + d.mismatch;
      } else if (d.drive->active_fault() != 0) {
        s.state(gw::DEVICE_FAULTED);
        s.fault(d.drive->active_fault());
        detail = "drive fault F" + std::to_string(d.drive->active_fault());
      } else {
        s.state(gw::DEVICE_CONNECTED);
        s.fault(0);
      }
      s.detail(detail);
      signature += "/" + std::to_string(static_cast<int>(s.state())) + ":" + detail;
    }
    if (!force && signature == status_signature && now - status_time < std::chrono::seconds(1)) return;
    status_signature = std::move(signature);
    status_time = now;
    session.fill_status(status, config.gateway, static_cast<std::uint32_t>(cycle.count()), command_number);
    status_writer->write(&status);
  }

  Device* find(const char* name) {
    for (auto& d : devices) {
      if (d.name == name) return &d;
    }
    return nullptr;
  }

  // ---- DDS listener threads ----
  void on_setpoint(const gw::SetpointCycle& sample) {
    if (stop.load()) return;
    std::lock_guard<std::mutex> lock(mutex);
    const Clock::time_point now = Clock::now();
    if (stopped || now < silent_until) return;  // a hung or restarting gateway hears nothing
    const dds::SetpointSession::Decision decision = session.accept(sample, now);
    if (decision.released) forget_setpoints();  // the new controller's setpoints are not applied yet
    if (decision.verdict == dds::SetpointSession::Verdict::kProbe) publish_answer(now, sample.controller());
    if (decision.verdict != dds::SetpointSession::Verdict::kApply) return;
    // Lost setpoints: the drives ran those cycles without one (their setpoint timeout counts them).
    for (std::uint64_t k = 0; k < std::min(decision.gap, kMaxCatchUpSteps); ++k)
      step_all();
    for (const auto& e : sample.devices()) {
      Device* d = find(e.device().c_str());
      if (d == nullptr || d->disconnected) continue;
      if (!dds::matches(d->config, telegrams::Direction::kSetpoint, e.byte_order(), e.slots())) {
        d->mismatch = dds::mismatch(d->config, telegrams::Direction::kSetpoint, e.byte_order(), e.slots());
        continue;
      }
      d->mismatch.clear();
      dds::extract(e.slots(), d->setpoint);
      d->drive->write_setpoint(d->setpoint);
      d->has_setpoint = true;
      d->setpoint_cycle = sample.cycle();
    }
    step_all();
    publish_answer(now);
    publish_status(now, false);
  }

  void on_command(const gw::GatewayCommand& command) {
    if (stop.load()) return;
    if (command.number() == 0) return;  // malformed (type_support.hpp) or not from a commander
    if (command.gateway().size() != 0 && !(command.gateway() == config.gateway)) return;
    std::lock_guard<std::mutex> lock(mutex);
    const Clock::time_point now = Clock::now();
    Device* d = find(command.device().c_str());
    switch (command.kind()) {
      case gw::COMMAND_DROP_ANSWERS:
        drop_remaining = command.value();
        break;
      case gw::COMMAND_DELAY_ANSWERS:
        delay_us = static_cast<std::uint32_t>(std::min<std::uint64_t>(command.value(), 10'000'000));
        break;
      case gw::COMMAND_STOP:
        stopped = true;
        break;
      case gw::COMMAND_RESUME:
        stopped = false;
        drop_remaining = 0;
        break;
      case gw::COMMAND_RESTART:
        // A new run of the gateway: new incarnation, sequence from 1, no controller; the drives (separate
        // devices) keep running on the gateway's clock meanwhile.
        session.restart();
        release_controller();
        silent_until = now + std::chrono::milliseconds(std::min<std::uint64_t>(command.value(), 60'000));
        break;
      case gw::COMMAND_DRIVE_FAULT:
        if (d != nullptr) {
          if (command.value() == 0) {
            d->drive->clear_injected_fault();
          } else {
            d->drive->inject_fault(static_cast<std::uint32_t>(command.value()),
                                   drives::SimulatedDriveParameters::FaultReaction::kOff2);
          }
        }
        break;
      case gw::COMMAND_DISCONNECT:
        if (d != nullptr) d->disconnected = true;
        break;
      case gw::COMMAND_CONNECT:
        if (d != nullptr) d->disconnected = false;
        break;
    }
    command_number = command.number();
    ++counters.commands;
    publish_status(now, true);
  }

  // ---- the gateway's own clock ----
  void clock_loop() {
    Clock::time_point next = Clock::now() + cycle;
    while (!stop.load()) {
      std::this_thread::sleep_until(next);
      const Clock::time_point now = Clock::now();
      next += cycle;
      if (now > next + 10 * cycle) next = now + cycle;  // suspended: no burst of catch-up steps
      std::lock_guard<std::mutex> lock(mutex);
      if (session.silent(now)) {
        if (session.controller() != 0) release_controller();
        step_all();
        ++counters.idle_steps;
        if (!stopped && now >= silent_until) publish_answer(now);
      }
      publish_status(now, false);
    }
  }

  void delay_loop() {
    std::unique_lock<std::mutex> lock(delay_mutex);
    while (!stop.load()) {
      if (delayed.empty()) {
        delay_cv.wait(lock, [&] { return stop.load() || !delayed.empty(); });
        continue;
      }
      const Clock::time_point due = delayed.front().first;
      if (Clock::now() < due) {
        delay_cv.wait_until(lock, due, [&] { return stop.load(); });
        continue;
      }
      gw::ActualCycle sample = std::move(delayed.front().second);
      delayed.pop_front();
      lock.unlock();
      actual_writer->write(&sample);
      lock.lock();
    }
  }
};

GatewaySimulator::GatewaySimulator(const scenario::GatewaySimConfig& config)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.config = config;
  if (config.devices.empty()) throw std::invalid_argument("gateway-sim: no device");
  if (!(config.cycle_time > 0.0) || !(config.watchdog > 0.0)) {
    throw std::invalid_argument("gateway-sim: cycle_time and watchdog must be > 0");
  }
  m.cycle = std::chrono::nanoseconds(static_cast<std::int64_t>(std::llround(config.cycle_time * 1e9)));
  m.watchdog = std::chrono::nanoseconds(static_cast<std::int64_t>(std::llround(config.watchdog * 1e9)));
  m.session = dds::SetpointSession(m.watchdog);
  m.drop_every = config.drop_every;
  m.delay_us = config.delay_us;
  for (const auto& c : config.devices) {
    Device d;
    d.name = c.name;
    d.config = c.device_config();
    if (const auto problem = drives::validate(d.config); !problem.empty()) {
      throw std::invalid_argument("gateway-sim: device '" + c.name + "': " + problem);
    }
    d.byte_order = dds::to_contract(c.byte_order);
    d.drive = std::make_unique<drives::SimulatedDrive>(d.config, c.drive.parameters);
    d.setpoint = drives::make_frames(d.config, telegrams::Direction::kSetpoint);
    d.actual = drives::make_frames(d.config, telegrams::Direction::kActual);
    m.devices.push_back(std::move(d));
  }
  dds::reserve_answer(m.answer, m.devices.size());

  // A gateway need not know its controllers: with no peers it answers those that contact it.
  m.endpoints = std::make_unique<dds::GatewayEndpoints>(config.domain, "tomc gateway-sim " + config.gateway,
                                                        config.partition, config.network, "gateway-sim");
  m.actual_writer = &m.endpoints->actual_writer();
  m.status_writer = &m.endpoints->status_writer();
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    m.publish_status(Clock::now(), true);
  }
  auto on_setpoint = [&m](const gw::SetpointCycle& s) { m.on_setpoint(s); };
  auto on_command = [&m](const gw::GatewayCommand& c) { m.on_command(c); };
  m.setpoint_listener = dds::make_taking_listener<gw::SetpointCycle>(on_setpoint);
  m.command_listener = dds::make_taking_listener<gw::GatewayCommand>(on_command);
  m.endpoints->read_setpoints(m.setpoint_listener.get());
  dds::Participant& p = m.endpoints->participant();
  if (p.subscriber().create_datareader(&p.topic(dds::kCommandTopic, m.command_type),
                                       dds::command_reader_qos(), m.command_listener.get()) == nullptr) {
    throw std::runtime_error("gateway-sim: Fast DDS could not create the command reader");
  }
  m.clock_thread = std::thread([&m] { m.clock_loop(); });
  m.delay_thread = std::thread([&m] { m.delay_loop(); });
}

GatewaySimulator::~GatewaySimulator() {
  Impl& m = *impl_;
  m.stop.store(true);
  { std::lock_guard<std::mutex> lock(m.delay_mutex); }
  m.delay_cv.notify_all();
  if (m.clock_thread.joinable()) m.clock_thread.join();
  if (m.delay_thread.joinable()) m.delay_thread.join();
  m.endpoints.reset();  // readers first: no listener runs after this
}

SimulatorCounters GatewaySimulator::counters() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  SimulatorCounters c = impl_->counters;
  const dds::SessionCounters& s = impl_->session.counters();
  c.setpoints_applied = s.setpoints_applied;
  c.setpoint_gaps = s.setpoint_gaps;
  c.setpoints_rejected = s.setpoints_rejected;
  c.answers_published = s.answers_published;
  c.incarnation = impl_->session.incarnation();
  c.controller = impl_->session.controller();
  return c;
}

}  // namespace tomc::gateway_sim
