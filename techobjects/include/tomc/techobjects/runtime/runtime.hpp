#pragma once
// The runtime that owns the technology objects and their drive adapters and runs one application cycle
// (ARCHITECTURE-GUIDE §2): MC_PreServo hook, MC_Servo, MC_PostServo hook, MC_Interpolator, post-interpolator
// hook (diagnostics: axis control panel, snapshots, traces), user program.
// step() is deterministic on virtual time (an integer cycle counter times the cycle time). After start()
// nothing in step() allocates, locks, throws or does I/O (tests/techobjects/runtime/allocation_test.cpp
// proves it).

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/runtime/start_value_store.hpp"

namespace tomc::techobjects {

struct RuntimeConfig {
  double servo_cycle_s = 0.001;          // MC_Servo cycle
  std::uint32_t interpolator_ratio = 1;  // MC_Interpolator runs every n servo cycles
  std::uint32_t user_program_ratio = 1;  // the user program runs every m servo cycles (a multiple of n)
};

// Virtual time of the runtime.
struct CycleClock {
  std::uint64_t servo_cycles = 0;  // completed MC_Servo runs before the current one
  std::uint64_t interpolator_cycles = 0;
  double servo_cycle_s = 0.001;
  double interpolator_cycle_s = 0.001;
  double time_s() const noexcept { return static_cast<double>(servo_cycles) * servo_cycle_s; }
};

// One device as MC_Servo sees it: the adapter, this cycle's frames and whether the actual ones are fresh.
struct DeviceIo {
  std::unique_ptr<drives::DriveAdapter> adapter;
  drives::DeviceFrames actual{};    // newest actual frames; unchanged when nothing fresh arrived
  drives::DeviceFrames setpoint{};  // written by the owning technology object during servo()
  bool fresh = false;               // actual frames arrived this cycle
};

// What a runtime lends each technology object when it is added (set-up time): the runtime-wide alarm history
// and the load memory for its start values.
struct RuntimeServices {
  AlarmLog& alarm_log;
  StartValueStore& start_values;
  std::uint32_t object_number;  // 1, 2, ... in the order the objects were added
  double interpolator_cycle_s;  // MC_Interpolator's cycle (a leader sizes its delayed value's history)
};

// The cyclic parts of a technology object. Both are called from the real-time path: noexcept, no allocation.
class TechnologyObject {
 public:
  virtual ~TechnologyObject() = default;
  virtual std::string_view name() const noexcept = 0;
  virtual void servo(const CycleClock& clock) noexcept = 0;  // MC_Servo: actual values, control, setpoints
  virtual void interpolate(
      const CycleClock& clock) noexcept = 0;  // MC_Interpolator: jobs, profiles, monitoring
  // The TOs whose values this one reads in its cycle (a synchronous axis: its possible leading values). The
  // runtime evaluates them first (spec 07 §6.1); a cycle in this graph is a configuration error.
  virtual std::span<TechnologyObject* const> leaders() const noexcept { return {}; }
  // The same for the axes whose setpoints an axis may add to its own without a cycle offset (its possible
  // superimposing axes, MC_MotionInSuperimposedAxes, seed 004 §6.14.3.2).
  virtual std::span<TechnologyObject* const> superimposing_axes() const noexcept { return {}; }
  // Called once when the object is added to a runtime (set-up; may allocate): attach the alarm list to the
  // runtime's alarm log, hand the start values to its load memory.
  virtual void attach(RuntimeServices& services) { (void)services; }
};

class Runtime {
 public:
  // Hooks must not throw (they run inside the noexcept cycle).
  using Hook = std::function<void(Runtime&)>;

  explicit Runtime(RuntimeConfig config);
  Runtime(const Runtime&) = delete;
  Runtime& operator=(const Runtime&) = delete;

  // ---- set-up (before start(); may allocate and throw std::logic_error) ----
  // start() orders the TOs so that every leader runs before its followers (TechnologyObject::leaders(), and
  // every superimposing axis before the axis it superimposes) and throws std::logic_error naming the TOs of
  // a coupling cycle or a leader that is not in this runtime.
  DeviceIo& add_device(std::unique_ptr<drives::DriveAdapter> adapter);
  void add_technology_object(std::unique_ptr<TechnologyObject> object);
  template <typename T, typename... Args>
  T& emplace(Args&&... args) {
    auto object = std::make_unique<T>(std::forward<Args>(args)...);
    T& ref = *object;
    add_technology_object(std::move(object));
    return ref;
  }
  void set_pre_servo(Hook hook);
  void set_post_servo(Hook hook);
  // Runs in every servo cycle right after the MC_Interpolator slot (also in servo cycles in which the
  // interpolator does not run, so that a trace samples at the servo rate) and before the user program.
  void set_post_interpolator(Hook hook);
  void set_user_program(Hook hook);
  void start();
  bool started() const noexcept { return started_; }

  // ---- the cycle ----
  void step() noexcept;

  const RuntimeConfig& config() const noexcept { return config_; }
  const CycleClock& clock() const noexcept { return clock_; }
  std::size_t device_count() const noexcept { return devices_.size(); }
  DeviceIo& device(std::size_t i) noexcept { return *devices_[i]; }
  std::size_t technology_object_count() const noexcept { return objects_.size(); }
  TechnologyObject& technology_object(std::size_t i) noexcept { return *objects_[i]; }
  // The alarm events of every TO (AlarmList::log() shows one TO's).
  const AlarmLog& alarm_log() const noexcept { return *alarm_log_; }
  const StartValueStore& start_values() const noexcept { return start_values_; }

 private:
  void require_setup(const char* what) const;

  RuntimeConfig config_;
  CycleClock clock_{};
  bool started_ = false;
  std::vector<std::unique_ptr<DeviceIo>> devices_;          // stable addresses: TOs keep DeviceIo&
  std::vector<std::unique_ptr<TechnologyObject>> objects_;  // in the order they were added
  std::vector<TechnologyObject*> cycle_order_;              // leaders before followers (start())
  std::unique_ptr<AlarmLog> alarm_log_ = std::make_unique<AlarmLog>();
  StartValueStore start_values_;
  Hook pre_servo_;
  Hook post_servo_;
  Hook post_interpolator_;
  Hook user_program_;
};

}  // namespace tomc::techobjects
