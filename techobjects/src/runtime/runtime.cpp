// One application cycle, in the order of ARCHITECTURE-GUIDE §2 and seed §6.2.3.2 as corrected by spec 01 §11
// A6 (MC_PreServo -> MC_Servo -> MC_PostServo).
#include "tomc/techobjects/runtime/runtime.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tomc::techobjects {

Runtime::Runtime(RuntimeConfig config) : config_(config) {
  if (!(config_.servo_cycle_s > 0.0)) throw std::invalid_argument("servo_cycle_s must be > 0");
  if (config_.interpolator_ratio == 0) throw std::invalid_argument("interpolator_ratio must be >= 1");
  if (config_.user_program_ratio == 0 || config_.user_program_ratio % config_.interpolator_ratio != 0) {
    throw std::invalid_argument("user_program_ratio must be a positive multiple of interpolator_ratio");
  }
  clock_.servo_cycle_s = config_.servo_cycle_s;
  clock_.interpolator_cycle_s = config_.servo_cycle_s * config_.interpolator_ratio;
}

void Runtime::require_setup(const char* what) const {
  if (started_) throw std::logic_error(std::string(what) + ": the runtime has started; set-up is over");
}

DeviceIo& Runtime::add_device(std::unique_ptr<drives::DriveAdapter> adapter) {
  require_setup("add_device");
  if (!adapter) throw std::invalid_argument("add_device: no adapter");
  auto io = std::make_unique<DeviceIo>();
  io->actual = drives::make_frames(adapter->config(), telegrams::Direction::kActual);
  io->setpoint = drives::make_frames(adapter->config(), telegrams::Direction::kSetpoint);
  io->adapter = std::move(adapter);
  devices_.push_back(std::move(io));
  return *devices_.back();
}

void Runtime::add_technology_object(std::unique_ptr<TechnologyObject> object) {
  require_setup("add_technology_object");
  if (!object) throw std::invalid_argument("add_technology_object: no object");
  RuntimeServices services{*alarm_log_, start_values_, static_cast<std::uint32_t>(objects_.size() + 1),
                           clock_.interpolator_cycle_s};
  object->attach(services);
  objects_.push_back(std::move(object));
}

void Runtime::set_pre_servo(Hook hook) {
  require_setup("set_pre_servo");
  pre_servo_ = std::move(hook);
}
void Runtime::set_post_servo(Hook hook) {
  require_setup("set_post_servo");
  post_servo_ = std::move(hook);
}
void Runtime::set_post_interpolator(Hook hook) {
  require_setup("set_post_interpolator");
  post_interpolator_ = std::move(hook);
}
void Runtime::set_user_program(Hook hook) {
  require_setup("set_user_program");
  user_program_ = std::move(hook);
}

void Runtime::start() {
  require_setup("start");
  // Leaders before followers (spec 07 §6.1): a depth-first topological order that keeps the order of
  // addition where nothing forces otherwise; a cycle in the coupling graph is a configuration error.
  enum class Mark : std::uint8_t { kNone, kVisiting, kDone };
  std::vector<Mark> marks(objects_.size(), Mark::kNone);
  std::vector<TechnologyObject*> order;
  const auto index_of = [&](const TechnologyObject* o) -> std::size_t {
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      if (objects_[i].get() == o) return i;
    }
    throw std::logic_error(
        "start: " + std::string(o != nullptr ? o->name() : "(null)") +
        " is a leading value or superimposing axis of another technology object but not in this runtime");
  };
  std::vector<std::size_t> path;
  const auto visit = [&](auto&& self, std::size_t i) -> void {
    if (marks[i] == Mark::kDone) return;
    if (marks[i] == Mark::kVisiting) {
      std::string chain;
      const auto from = std::find(path.begin(), path.end(), i);
      for (auto it = from; it != path.end(); ++it)
        chain += std::string(objects_[*it]->name()) + " -> ";
      throw std::logic_error("start: the leading-value / superimposing-axis interconnections form a cycle: " +
                             chain + std::string(objects_[i]->name()) + " (spec 07 §1.2)");
    }
    marks[i] = Mark::kVisiting;
    path.push_back(i);
    for (TechnologyObject* leader : objects_[i]->leaders())
      self(self, index_of(leader));
    for (TechnologyObject* superimposing : objects_[i]->superimposing_axes())
      self(self, index_of(superimposing));
    path.pop_back();
    marks[i] = Mark::kDone;
    order.push_back(objects_[i].get());
  };
  for (std::size_t i = 0; i < objects_.size(); ++i)
    visit(visit, i);
  cycle_order_ = std::move(order);
  started_ = true;
}

void Runtime::step() noexcept {
  if (!started_) return;
  // MC_PreServo
  if (pre_servo_) pre_servo_(*this);
  // MC_Servo: read every actual frame, servo part of every TO, write every setpoint frame.
  for (auto& d : devices_)
    d->fresh = d->adapter->read_actual(d->actual);
  for (TechnologyObject* o : cycle_order_)
    o->servo(clock_);
  for (auto& d : devices_)
    d->adapter->write_setpoint(d->setpoint);
  // MC_PostServo
  if (post_servo_) post_servo_(*this);
  const std::uint64_t cycle = clock_.servo_cycles;
  // MC_Interpolator, then the user program, at their ratios of the servo cycle.
  if (cycle % config_.interpolator_ratio == 0) {
    for (TechnologyObject* o : cycle_order_)
      o->interpolate(clock_);
    ++clock_.interpolator_cycles;
  }
  if (post_interpolator_) post_interpolator_(*this);
  if (cycle % config_.user_program_ratio == 0 && user_program_) user_program_(*this);
  ++clock_.servo_cycles;
}

}  // namespace tomc::techobjects
