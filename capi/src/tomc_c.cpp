// The C ABI of <tomc/tomc.h> over the C++ API: the machine loader of tools/scenario, Runtime and
// RealTimeRunner, the data-block reflection tables and the MC_* instruction classes. Every entry point
// catches everything (no exception crosses the C boundary) and reports failures as a status plus a
// thread-local message.
#include "tomc/tomc.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/diagnostics/server.hpp"
#include "tomc/diagnostics/triple_buffer.hpp"
#include "tomc/instructions/mc_cam_in.hpp"
#include "tomc/instructions/mc_cam_out.hpp"
#include "tomc/instructions/mc_copy_cam_data.hpp"
#include "tomc/instructions/mc_gear_in.hpp"
#include "tomc/instructions/mc_gear_in_pos.hpp"
#include "tomc/instructions/mc_gear_in_velocity.hpp"
#include "tomc/instructions/mc_gear_out.hpp"
#include "tomc/instructions/mc_get_cam_value.hpp"
#include "tomc/instructions/mc_halt.hpp"
#include "tomc/instructions/mc_halt_superimposed.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_interpolate_cam.hpp"
#include "tomc/instructions/mc_leading_value_additive.hpp"
#include "tomc/instructions/mc_motion_in.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_move_jog.hpp"
#include "tomc/instructions/mc_move_relative.hpp"
#include "tomc/instructions/mc_move_superimposed.hpp"
#include "tomc/instructions/mc_move_velocity.hpp"
#include "tomc/instructions/mc_phasing.hpp"
#include "tomc/instructions/mc_position_profile.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/instructions/mc_set_axis_stw.hpp"
#include "tomc/instructions/mc_set_sensor.hpp"
#include "tomc/instructions/mc_stop.hpp"
#include "tomc/instructions/mc_synchronized_motion_simulation.hpp"
#include "tomc/instructions/mc_torque_additive.hpp"
#include "tomc/instructions/mc_torque_limiting.hpp"
#include "tomc/instructions/mc_torque_range.hpp"
#include "tomc/instructions/mc_write_parameter.hpp"
#include "tomc/scenario/machine.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace instructions = tomc::instructions;
namespace techobjects = tomc::techobjects;
namespace scenario = tomc::scenario;
namespace diagnostics = tomc::diagnostics;

namespace {
struct Snapshot;
}

struct tomc_object {
  scenario::MachineObject machine;
  tomc_runtime* owner = nullptr;
  // With a user task: the data block as of the last interpolator cycle, for the task's reads.
  std::shared_ptr<Snapshot> snapshot;
};

namespace {

// The data block of one TO as of the last interpolator cycle, for the user task on its own thread: the servo
// thread publishes a copy after every cycle into a triple buffer (neither side waits), the task takes the
// newest at the start of each of its cycles, so one task cycle reads one consistent data block per TO.
struct Snapshot {
  virtual ~Snapshot() = default;
  virtual void publish() noexcept = 0;  // servo thread
  virtual void update() noexcept = 0;   // task thread
  virtual double read(const techobjects::VariableInfo* info,
                      const std::optional<techobjects::BitReference>& bit) const noexcept = 0;  // task thread
};

template <typename Data>
struct SnapshotOf final : Snapshot {
  explicit SnapshotOf(const Data& data) : live(&data) {
    buffer.for_each([&](Data& d) { d = data; });
  }
  void publish() noexcept override {
    buffer.back() = *live;
    buffer.publish();
  }
  void update() noexcept override { buffer.update(); }
  double read(const techobjects::VariableInfo* info,
              const std::optional<techobjects::BitReference>& bit) const noexcept override {
    const Data& d = buffer.front();
    return bit ? (bit->read(d) ? 1.0 : 0.0) : info->read(d);
  }
  const Data* live;
  diagnostics::TripleBuffer<Data> buffer;
};

// An instruction instance of the user task: the task's calls post the whole C struct (a mailbox that keeps
// the newest), the servo thread calls the C++ instance with it after every MC_Interpolator and posts the
// struct with its outputs back. Both directions are triple buffers: lock-free, nobody waits.
constexpr std::size_t kFbBytes = 512;
struct FbBytes {
  alignas(std::max_align_t) unsigned char bytes[kFbBytes];
};

struct TaskSlot {
  tomc_object* axis = nullptr;
  const void* user_struct = nullptr;  // the task's instance: its address identifies it
  void (*execute)(TaskSlot&) noexcept = nullptr;
  diagnostics::TripleBuffer<FbBytes> inputs;   // task -> servo
  diagnostics::TripleBuffer<FbBytes> outputs;  // servo -> task
  FbBytes current{};                           // servo thread: the inputs in force
  tomc_instance_data instance{};               // servo thread: the C++ instruction's state
};

}  // namespace

struct tomc_task {
  static constexpr std::size_t kCapacity = 64;  // instruction instances per task
  tomc_runtime* runtime = nullptr;
  tomc_task_program program = nullptr;
  void* context = nullptr;
  techobjects::RealTimeRunnerConfig runner_config{};
  int cpu = -1;
  std::unique_ptr<TaskSlot[]> slots = std::make_unique<TaskSlot[]>(kCapacity);
  std::atomic<std::size_t> slot_count{0};  // written by the task thread (release), read by the servo thread
  std::unique_ptr<techobjects::RealTimeRunner> runner;
  std::string runner_warnings;  // written by the task thread in its first cycle, read after stop()
  techobjects::RunnerStatistics last_statistics{};
};

struct tomc_runtime {
  std::unique_ptr<techobjects::Runtime> runtime;
  std::deque<tomc_object> objects;  // stable addresses: handed out as tomc_object*
  tomc_user_program program = nullptr;
  void* program_context = nullptr;
  std::unique_ptr<techobjects::RealTimeRunner> runner;
  std::atomic<bool> realtime{false};
  std::string runner_warnings;  // written by the runner thread in its first cycle, read after stop()
  techobjects::RunnerStatistics last_statistics{};
  std::unique_ptr<tomc_task> task;  // the user task on its own thread (at most one)
  // Last: destroyed first (the server reads the diagnostics, the runners are stopped by
  // tomc_runtime_destroy).
  std::unique_ptr<diagnostics::Diagnostics> diagnostics;
  std::unique_ptr<diagnostics::Server> server;
};

namespace {

thread_local std::string t_last_error;
// The runtime whose cycle runs on this thread (set around step() on the runner thread): calls from its user
// program are allowed while the runner runs, calls from other threads are not.
thread_local const tomc_runtime* t_cycle_of = nullptr;
// The user task running on this thread: its instruction calls go through the mailboxes, its reads to the
// snapshots.
thread_local tomc_task* t_task = nullptr;

bool in_task_of(const tomc_runtime* rt) noexcept {
  return t_task != nullptr && t_task->runtime == rt;
}

tomc_status fail(tomc_status status, std::string message) noexcept {
  try {
    t_last_error = std::move(message);
  } catch (...) {
    t_last_error.clear();  // out of memory: the status still says what happened
  }
  return status;
}

// Runs `body`, turning exceptions into statuses: nothing crosses the C boundary.
template <typename Body>
tomc_status guarded(Body&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return fail(TOMC_ERROR_SYSTEM, "out of memory");
  } catch (const std::exception& e) {
    return fail(TOMC_ERROR_INTERNAL, e.what());
  } catch (...) {
    return fail(TOMC_ERROR_INTERNAL, "unknown exception");
  }
}

tomc_status null_argument(const char* function, const char* argument) noexcept {
  return fail(TOMC_ERROR_NULL_ARGUMENT, std::string(function) + ": " + argument + " is NULL");
}

// While the runner runs, only its own thread (the user program) may touch the TOs.
tomc_status check_thread(const tomc_runtime* rt, const char* function) noexcept {
  if (rt->realtime.load(std::memory_order_acquire) && t_cycle_of != rt) {
    return fail(TOMC_ERROR_STATE, std::string(function) +
                                      ": the runtime runs on the real-time runner; call this from its user "
                                      "program (tomc_runtime_set_user_program)");
  }
  return TOMC_OK;
}

template <typename T>
bool header_ok(const T* s) noexcept {
  return s->header.size == sizeof(T) && s->header.version == TOMC_ABI_VERSION;
}

template <typename T>
tomc_status version_error(const char* function, const char* type, const T* s) noexcept {
  return fail(TOMC_ERROR_VERSION, std::string(function) + ": " + type + " header has size " +
                                      std::to_string(s->header.size) + " and version " +
                                      std::to_string(s->header.version) + ", this library expects " +
                                      std::to_string(sizeof(T)) + " and " + std::to_string(TOMC_ABI_VERSION) +
                                      " (initialise it with its init function or TOMC_STRUCT_HEADER)");
}

// ---- loading ----

using Json = scenario::Json;

// `directory`: where a cam's points file ({"file": ...}) is looked up (the machine file's folder).
tomc_status load(const std::string& text, tomc_runtime** out, const std::filesystem::path& directory = {}) {
  Json root;
  try {
    root = Json::parse(text);
  } catch (const Json::exception& e) {  // parse_error, and out_of_range for numbers beyond a double (fuzzer)
    return fail(TOMC_ERROR_CONFIG, std::string("not valid JSON: ") + e.what());
  }
  scenario::Problems problems;
  double cycle_time = 0.001;
  if (!root.is_object()) {
    return fail(TOMC_ERROR_CONFIG, ": expected a JSON object with cycle_time and technology_objects");
  }
  static constexpr std::string_view kKnown[] = {"comment", "cycle_time", "technology_objects",
                                                "cycles",  "timeline",   "trace",
                                                "expect",  "program",    "diagnostics"};
  for (const auto& item : root.items()) {
    if (std::find(std::begin(kKnown), std::end(kKnown), item.key()) == std::end(kKnown))
      problems.add(item.key(), "unknown key (known: cycle_time, technology_objects)");
  }
  if (const auto it = root.find("cycle_time"); it != root.end()) {
    if (!it->is_number() || !(it->get<double>() >= 1e-4 && it->get<double>() <= 0.1)) {
      problems.add("cycle_time", "expected a number 0.0001 .. 0.1 (s)");
    } else {
      cycle_time = it->get<double>();
    }
  }
  auto rt = std::make_unique<tomc_runtime>();
  rt->runtime = std::make_unique<techobjects::Runtime>(techobjects::RuntimeConfig{cycle_time, 1, 1});
  std::vector<scenario::MachineObject> objects;
  const auto list = root.find("technology_objects");
  if (list == root.end() || !list->is_array() || list->empty()) {
    problems.add("technology_objects", "expected a non-empty array of technology objects");
  } else {
    for (std::size_t i = 0; i < list->size(); ++i) {
      if (auto o = scenario::load_technology_object(
              (*list)[i], "technology_objects[" + std::to_string(i) + "]", cycle_time, *rt->runtime, objects,
              problems, "the C ABI", nullptr, directory)) {
        objects.push_back(std::move(*o));
      }
    }
  }
  if (!problems.empty()) {
    std::string message;
    for (const auto& line : problems.lines())
      message += (message.empty() ? "" : "\n") + line;
    return fail(TOMC_ERROR_CONFIG, std::move(message));
  }
  scenario::wire_machine_inputs(*rt->runtime, objects);
  for (auto& o : objects)
    rt->objects.push_back(tomc_object{std::move(o), rt.get(), nullptr});
  *out = rt.release();
  return TOMC_OK;
}

// The servo side of the user task: the instances it called run with their newest inputs, then the data
// blocks are published for its next cycle. Runs in the cycle's thread after MC_Interpolator; no allocation.
void service_task(tomc_task& task) noexcept {
  const std::size_t n = task.slot_count.load(std::memory_order_acquire);
  for (std::size_t i = 0; i < n; ++i)
    task.slots[i].execute(task.slots[i]);
  for (auto& o : task.runtime->objects)
    if (o.snapshot) o.snapshot->publish();
}

void install_user_program(tomc_runtime* rt) {
  if (rt->program == nullptr && !rt->task) return;
  rt->runtime->set_user_program([rt](techobjects::Runtime&) {
    if (rt->program != nullptr) rt->program(rt, rt->program_context);
    if (rt->task) service_task(*rt->task);
  });
}

// ---- variables ----

struct Variable {
  const techobjects::VariableInfo* info = nullptr;
  std::optional<techobjects::BitReference> bit;
  // A synchronous axis' StatusSynchronizedMotion.* (spec 07 §1.9): outside the variable table, RON.
  std::optional<techobjects::VariableType> synchronized_motion;
};

tomc_status find(const tomc_object* o, const char* function, const char* path, Variable& v) {
  v.info = o->machine.find_variable(path);
  if (v.info == nullptr) v.bit = o->machine.find_bit(path);
  if (v.info == nullptr && !v.bit && o->machine.synchronous_axis != nullptr)
    v.synchronized_motion = o->machine.synchronous_axis->synchronized_motion_type(path);
  if (v.info == nullptr && !v.bit && !v.synchronized_motion) {
    return fail(TOMC_ERROR_UNKNOWN_PATH, std::string(function) + ": " + o->machine.name + "." + path +
                                             ": no such variable of " + std::string(o->machine.type_name()));
  }
  return TOMC_OK;
}

tomc_status wrong_type(const tomc_object* o, const char* function, const char* path, const Variable& v,
                       const char* wanted) {
  const std::string_view type = v.bit                   ? "BOOL (a bit)"
                                : v.synchronized_motion ? techobjects::to_string(*v.synchronized_motion)
                                                        : techobjects::to_string(v.info->type);
  return fail(TOMC_ERROR_WRONG_TYPE, std::string(function) + ": " + o->machine.name + "." + path + " is " +
                                         std::string(type) + ", not " + wanted);
}

tomc_status write(tomc_object* o, const char* function, const char* path, double value) {
  const techobjects::WriteResult r = o->machine.write(path, value);
  const std::string where = std::string(function) + ": " + o->machine.name + "." + path;
  if (!r.found) return fail(TOMC_ERROR_UNKNOWN_PATH, where + ": no writable variable of that path");
  if (r.access != techobjects::AccessError::kNone)
    return fail(TOMC_ERROR_ACCESS, where + ": " + std::string(techobjects::to_string(r.access)));
  if (r.value != techobjects::ValueError::kNone) {
    const auto* info = o->machine.find_variable(path);
    std::string range;
    if (info != nullptr)
      range = " (range " + scenario::format_number(info->minimum) + " .. " +
              scenario::format_number(info->maximum) + ")";
    return fail(TOMC_ERROR_OUT_OF_RANGE, where + ": " + scenario::format_number(value) + ": " +
                                             std::string(techobjects::to_string(r.value)) + range);
  }
  return TOMC_OK;
}

// ---- instructions ----

enum Kind : unsigned { kSpeed = 1, kPositioning = 2, kSynchronous = 4, kEncoder = 8, kCam = 16 };

Kind kind_of(const tomc_object& o) noexcept {
  switch (o.machine.kind) {
    case scenario::TechnologyObjectKind::kSpeedAxis:
      return kSpeed;
    case scenario::TechnologyObjectKind::kPositioningAxis:
      return kPositioning;
    case scenario::TechnologyObjectKind::kSynchronousAxis:
      return kSynchronous;
    case scenario::TechnologyObjectKind::kExternalEncoder:
      return kEncoder;
    case scenario::TechnologyObjectKind::kCam:
      return kCam;
  }
  return kSpeed;
}

// MC_CamIn.Cam, MC_PositionProfile.TimePositionCam: the TO_Cam of a handle; nullptr for none or another TO
// type (call_fb refuses that).
techobjects::Cam* cam_of(const tomc_object* o) noexcept {
  return o != nullptr && o->machine.built ? o->machine.cam : nullptr;
}

// MC_CopyCamData's arrays: a pointer and its length from C (none when either is missing).
template <typename T>
std::span<const T> array_of(const T* data, std::int32_t length) noexcept {
  return data != nullptr && length > 0 ? std::span<const T>(data, static_cast<std::size_t>(length))
                                       : std::span<const T>();
}

// The instance data: words[0] says which C++ instance lives at words[1..] (0: none yet), so that a struct
// zeroed or initialised in C starts a fresh handshake, and one called with another TO type starts over.
constexpr std::uint64_t kInstanceMagic = 0x746f6d6300000000ull;  // "tomc"

template <typename Fb, typename Axis>
typename Fb::template Cpp<Axis>& instance(tomc_instance_data& data, Kind kind) noexcept {
  using T = typename Fb::template Cpp<Axis>;
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "the C struct may be copied and dropped by C code");
  static_assert(
      sizeof(T) <= sizeof(data.words) - sizeof(data.words[0]) && alignof(T) <= alignof(std::uint64_t),
      "tomc_instance_data is too small for this instruction");
  void* storage = &data.words[1];
  if (data.words[0] != (kInstanceMagic | kind)) {
    new (storage) T{};
    data.words[0] = kInstanceMagic | kind;
  }
  return *std::launder(static_cast<T*>(storage));
}

template <typename Fb, typename Axis>
void run(typename Fb::C& c, Axis& axis, Kind kind, const tomc_object* master) noexcept {
  auto& t = instance<Fb, Axis>(c.instance, kind);
  Fb::in(c, t);
  if constexpr (Fb::kMaster)
    Fb::set_master(t, master != nullptr ? master->machine.leading_value_source() : nullptr);
  t(axis);
  Fb::out(t, c);
}

template <typename Fb>
void dispatch(tomc_object& axis, typename Fb::C& c) noexcept {
  const Kind kind = kind_of(axis);
  const auto& m = axis.machine;
  const tomc_object* master = nullptr;
  if constexpr (Fb::kMaster) master = Fb::master(c);
  if constexpr ((Fb::kKinds & kSpeed) != 0)
    if (kind == kSpeed) run<Fb>(c, *m.speed_axis, kind, master);
  if constexpr ((Fb::kKinds & kPositioning) != 0)
    if (kind == kPositioning) run<Fb>(c, *m.positioning_axis, kind, master);
  if constexpr ((Fb::kKinds & kSynchronous) != 0)
    if (kind == kSynchronous) run<Fb>(c, *m.synchronous_axis, kind, master);
  if constexpr ((Fb::kKinds & kEncoder) != 0)
    if (kind == kEncoder) run<Fb>(c, *m.external_encoder, kind, master);
  if constexpr ((Fb::kKinds & kCam) != 0)
    if (kind == kCam) run<Fb>(c, *m.cam, kind, master);
}

// Servo thread: one call of a task's instance with the newest inputs the task posted.
template <typename Fb>
void execute_in_servo(TaskSlot& s) noexcept {
  using C = typename Fb::C;
  if (s.inputs.update()) std::memcpy(s.current.bytes, s.inputs.front().bytes, sizeof(C));
  C c;
  std::memcpy(static_cast<void*>(&c), s.current.bytes, sizeof c);
  c.instance = s.instance;
  dispatch<Fb>(*s.axis, c);
  s.instance = c.instance;
  std::memcpy(s.outputs.back().bytes, static_cast<const void*>(&c), sizeof c);
  s.outputs.publish();
}

// Task thread: take the newest outputs the servo thread posted, post the inputs.
template <typename Fb>
tomc_status task_call(tomc_task& task, tomc_object* axis, typename Fb::C* c) noexcept {
  using C = typename Fb::C;
  static_assert(sizeof(C) <= kFbBytes && std::is_trivially_copyable_v<C>);
  const std::size_t n = task.slot_count.load(std::memory_order_relaxed);  // written by this thread only
  TaskSlot* slot = nullptr;
  for (std::size_t i = 0; i < n && slot == nullptr; ++i)
    if (task.slots[i].user_struct == c && task.slots[i].axis == axis) slot = &task.slots[i];
  if (slot == nullptr) {
    if (n == tomc_task::kCapacity)
      return fail(TOMC_ERROR_STATE, std::string(Fb::kName) + ": the user task has " +
                                        std::to_string(tomc_task::kCapacity) +
                                        " instruction instances already");
    slot = &task.slots[n];
    slot->axis = axis;
    slot->user_struct = c;
    slot->execute = &execute_in_servo<Fb>;
    std::memcpy(slot->current.bytes, static_cast<const void*>(c), sizeof(C));
    task.slot_count.store(n + 1, std::memory_order_release);
  }
  if (slot->outputs.update()) {
    C out;
    std::memcpy(static_cast<void*>(&out), slot->outputs.front().bytes, sizeof out);
    Fb::copy_outputs(out, *c);
  }
  std::memcpy(slot->inputs.back().bytes, static_cast<const void*>(c), sizeof(C));
  slot->inputs.publish();
  return TOMC_OK;
}

template <typename Fb>
void init_fb(typename Fb::C* c) noexcept {
  if (c == nullptr) return;
  std::memset(static_cast<void*>(c), 0, sizeof *c);
  c->header = tomc_struct_header TOMC_STRUCT_HEADER(typename Fb::C);
  Fb::defaults(*c);
}

template <typename Fb>
tomc_status call_fb(tomc_object* axis, typename Fb::C* c) noexcept {
  return guarded([&]() -> tomc_status {
    if (c == nullptr) return null_argument(Fb::kName, "the instance");
    if (axis == nullptr) return null_argument(Fb::kName, "the technology object");
    if (!header_ok(c)) return version_error(Fb::kName, Fb::kName, c);
    const Kind kind = kind_of(*axis);
    if ((Fb::kKinds & kind) == 0) {
      return fail(TOMC_ERROR_WRONG_OBJECT_TYPE, std::string(Fb::kName) + ": not an instruction of " +
                                                    std::string(axis->machine.type_name()) + " (" +
                                                    axis->machine.name + ")");
    }
    if constexpr (Fb::kMaster) {
      const tomc_object* master = Fb::master(*c);
      if (master != nullptr && master->machine.leading_value_source() == nullptr) {
        return fail(TOMC_ERROR_WRONG_OBJECT_TYPE,
                    std::string(Fb::kName) + "." + Fb::kMasterName + ": " + master->machine.name + " (" +
                        std::string(master->machine.type_name()) + ") is not a leading value");
      }
    }
    if (const char* problem = Fb::wrong_object(*c)) {  // "<input>: <what is wrong>"
      return fail(TOMC_ERROR_WRONG_OBJECT_TYPE, std::string(Fb::kName) + "." + problem);
    }
    if (!axis->machine.built)
      return fail(TOMC_ERROR_STATE, std::string(Fb::kName) + ": " + axis->machine.name + " was not built");
    if (in_task_of(axis->owner)) {
      if constexpr (Fb::kUserProgramOnly) {
        // It would run in the cycle's thread: MC_InterpolateCam allocates, MC_CopyCamData reads the task's
        // arrays there (decision C22).
        return fail(TOMC_ERROR_STATE,
                    std::string(Fb::kName) +
                        ": not from a user task (call it from the program of "
                        "tomc_runtime_set_user_program or between tomc_runtime_step calls)");
      }
      return task_call<Fb>(*t_task, axis, c);
    }
    if (const auto s = check_thread(axis->owner, Fb::kName); s != TOMC_OK) return s;
    dispatch<Fb>(*axis, *c);
    return TOMC_OK;
  });
}

}  // namespace

#include "instructions.inc"

// ---- errors ----

extern "C" const char* tomc_last_error(void) {
  return t_last_error.c_str();
}

extern "C" const char* tomc_status_name(tomc_status status) {
  switch (status) {
    case TOMC_OK:
      return "TOMC_OK";
    case TOMC_ERROR_NULL_ARGUMENT:
      return "TOMC_ERROR_NULL_ARGUMENT";
    case TOMC_ERROR_VERSION:
      return "TOMC_ERROR_VERSION";
    case TOMC_ERROR_CONFIG:
      return "TOMC_ERROR_CONFIG";
    case TOMC_ERROR_UNKNOWN_OBJECT:
      return "TOMC_ERROR_UNKNOWN_OBJECT";
    case TOMC_ERROR_UNKNOWN_PATH:
      return "TOMC_ERROR_UNKNOWN_PATH";
    case TOMC_ERROR_WRONG_TYPE:
      return "TOMC_ERROR_WRONG_TYPE";
    case TOMC_ERROR_OUT_OF_RANGE:
      return "TOMC_ERROR_OUT_OF_RANGE";
    case TOMC_ERROR_ACCESS:
      return "TOMC_ERROR_ACCESS";
    case TOMC_ERROR_WRONG_OBJECT_TYPE:
      return "TOMC_ERROR_WRONG_OBJECT_TYPE";
    case TOMC_ERROR_STATE:
      return "TOMC_ERROR_STATE";
    case TOMC_ERROR_SYSTEM:
      return "TOMC_ERROR_SYSTEM";
    case TOMC_ERROR_INTERNAL:
      return "TOMC_ERROR_INTERNAL";
  }
  return "TOMC_ERROR_UNKNOWN_STATUS";
}

extern "C" const char* tomc_version(void) {
  return TOMC_VERSION_STRING;
}

// ---- the runtime ----

extern "C" tomc_status tomc_runtime_create(const char* machine_json, tomc_runtime** runtime) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_create", "runtime");
    *runtime = nullptr;
    if (machine_json == nullptr) return null_argument("tomc_runtime_create", "machine_json");
    return load(machine_json, runtime);
  });
}

extern "C" tomc_status tomc_runtime_create_from_file(const char* path, tomc_runtime** runtime) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_create_from_file", "runtime");
    *runtime = nullptr;
    if (path == nullptr) return null_argument("tomc_runtime_create_from_file", "path");
    std::ifstream in(path);
    if (!in) return fail(TOMC_ERROR_SYSTEM, std::string(path) + ": cannot open: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    const tomc_status s = load(text.str(), runtime, std::filesystem::path(path).parent_path());
    if (s == TOMC_ERROR_CONFIG) t_last_error = std::string(path) + ":\n" + t_last_error;
    return s;
  });
}

extern "C" void tomc_runtime_destroy(tomc_runtime* runtime) {
  if (runtime == nullptr) return;
  try {
    if (runtime->server) runtime->server->stop();
    if (runtime->task && runtime->task->runner) runtime->task->runner->stop();
    if (runtime->runner) runtime->runner->stop();
  } catch (...) {
  }
  delete runtime;
}

extern "C" tomc_status tomc_runtime_set_user_program(tomc_runtime* runtime, tomc_user_program program,
                                                     void* context) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_set_user_program", "runtime");
    if (runtime->runtime->started())
      return fail(TOMC_ERROR_STATE, "tomc_runtime_set_user_program: the runtime has started");
    runtime->program = program;
    runtime->program_context = context;
    install_user_program(runtime);
    return TOMC_OK;
  });
}

extern "C" tomc_status tomc_runtime_start(tomc_runtime* runtime) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_start", "runtime");
    if (runtime->runtime->started()) return fail(TOMC_ERROR_STATE, "tomc_runtime_start: already started");
    runtime->runtime->start();
    return TOMC_OK;
  });
}

extern "C" tomc_status tomc_runtime_step(tomc_runtime* runtime, uint64_t cycles) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_step", "runtime");
    if (runtime->realtime.load(std::memory_order_acquire))
      return fail(TOMC_ERROR_STATE, "tomc_runtime_step: the real-time runner steps this runtime");
    if (!runtime->runtime->started()) runtime->runtime->start();
    const tomc_runtime* previous = t_cycle_of;
    t_cycle_of = runtime;
    for (uint64_t i = 0; i < cycles; ++i)
      runtime->runtime->step();
    t_cycle_of = previous;
    return TOMC_OK;
  });
}

extern "C" tomc_status tomc_runtime_cycle_time(const tomc_runtime* runtime, double* seconds) {
  if (runtime == nullptr) return null_argument("tomc_runtime_cycle_time", "runtime");
  if (seconds == nullptr) return null_argument("tomc_runtime_cycle_time", "seconds");
  *seconds = runtime->runtime->config().servo_cycle_s;
  return TOMC_OK;
}

extern "C" tomc_status tomc_runtime_cycle_count(const tomc_runtime* runtime, uint64_t* cycles) {
  if (runtime == nullptr) return null_argument("tomc_runtime_cycle_count", "runtime");
  if (cycles == nullptr) return null_argument("tomc_runtime_cycle_count", "cycles");
  if (const auto s = check_thread(runtime, "tomc_runtime_cycle_count"); s != TOMC_OK) return s;
  *cycles = runtime->runtime->clock().servo_cycles;
  return TOMC_OK;
}

extern "C" tomc_status tomc_runtime_run_realtime(tomc_runtime* runtime, const tomc_runner_config* config) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_run_realtime", "runtime");
    if (config == nullptr) return null_argument("tomc_runtime_run_realtime", "config");
    if (!header_ok(config)) return version_error("tomc_runtime_run_realtime", "tomc_runner_config", config);
    if (runtime->realtime.load()) return fail(TOMC_ERROR_STATE, "tomc_runtime_run_realtime: already running");
    if (config->fifo_priority < 0 || config->fifo_priority > 99)
      return fail(TOMC_ERROR_OUT_OF_RANGE, "tomc_runtime_run_realtime: fifo_priority " +
                                               std::to_string(config->fifo_priority) + " is not 0 .. 99");
    if (config->cpu < -1 || config->cpu >= CPU_SETSIZE)
      return fail(TOMC_ERROR_OUT_OF_RANGE, "tomc_runtime_run_realtime: cpu " + std::to_string(config->cpu) +
                                               " is not -1 or a CPU number");
    if (config->period_ns != 0 && (config->period_ns < 100'000 || config->period_ns > 100'000'000))
      return fail(TOMC_ERROR_OUT_OF_RANGE, "tomc_runtime_run_realtime: period_ns " +
                                               std::to_string(config->period_ns) +
                                               " is not 0 (the machine's cycle) or 100000 .. 100000000");
    if (!runtime->runtime->started()) runtime->runtime->start();
    const auto period =
        config->period_ns != 0
            ? std::chrono::nanoseconds(config->period_ns)
            : std::chrono::nanoseconds(std::llround(runtime->runtime->config().servo_cycle_s * 1e9));
    runtime->runner_warnings.clear();
    const int cpu = config->cpu;
    auto first = std::make_shared<bool>(true);
    runtime->runner = std::make_unique<techobjects::RealTimeRunner>(
        techobjects::RealTimeRunnerConfig{period, config->fifo_priority, config->lock_memory},
        [runtime, cpu, first]() {
          if (*first) {
            *first = false;
            t_cycle_of = runtime;
            if (cpu >= 0) {
              cpu_set_t set;
              CPU_ZERO(&set);
              CPU_SET(cpu, &set);
              if (const int e = pthread_setaffinity_np(pthread_self(), sizeof set, &set); e != 0)
                runtime->runner_warnings = "CPU " + std::to_string(cpu) + ": " + std::strerror(e);
            }
          }
          runtime->runtime->step();
        });
    runtime->realtime.store(true, std::memory_order_release);
    try {
      runtime->runner->start();
    } catch (const std::exception& e) {
      runtime->realtime.store(false);
      runtime->runner.reset();
      return fail(TOMC_ERROR_SYSTEM, std::string("tomc_runtime_run_realtime: ") + e.what());
    }
    if (runtime->task) {
      tomc_task* task = runtime->task.get();
      task->runner_warnings.clear();
      auto task_first = std::make_shared<bool>(true);
      task->runner = std::make_unique<techobjects::RealTimeRunner>(task->runner_config, [task, task_first]() {
        if (*task_first) {
          *task_first = false;
          t_task = task;
          if (task->cpu >= 0) {
            cpu_set_t set;
            CPU_ZERO(&set);
            CPU_SET(task->cpu, &set);
            if (const int e = pthread_setaffinity_np(pthread_self(), sizeof set, &set); e != 0)
              task->runner_warnings = "CPU " + std::to_string(task->cpu) + ": " + std::strerror(e);
          }
        }
        for (auto& o : task->runtime->objects)
          if (o.snapshot) o.snapshot->update();
        task->program(task->context);
      });
      try {
        task->runner->start();
      } catch (const std::exception& e) {
        task->runner.reset();
        runtime->runner->stop();
        runtime->runner.reset();
        runtime->realtime.store(false);
        return fail(TOMC_ERROR_SYSTEM, std::string("tomc_runtime_run_realtime: the user task: ") + e.what());
      }
    }
    return TOMC_OK;
  });
}

extern "C" tomc_status tomc_runtime_stop_realtime(tomc_runtime* runtime) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_stop_realtime", "runtime");
    if (!runtime->runner) return fail(TOMC_ERROR_STATE, "tomc_runtime_stop_realtime: not running");
    if (runtime->task && runtime->task->runner) {  // the task first: it posts to the servo side
      runtime->task->runner->stop();
      runtime->task->last_statistics = runtime->task->runner->statistics();
      runtime->task->runner.reset();
    }
    runtime->runner->stop();
    runtime->last_statistics = runtime->runner->statistics();
    runtime->runner.reset();
    runtime->realtime.store(false, std::memory_order_release);
    return TOMC_OK;
  });
}

namespace {

void copy_statistics(const techobjects::RunnerStatistics& s, const std::string& more,
                     tomc_runner_statistics* out) {
  out->cycles = s.cycles;
  out->overruns = s.overruns;
  out->jitter_median_us = s.jitter_median_us;
  out->jitter_p99_us = s.jitter_p99_us;
  out->jitter_max_us = s.jitter_max_us;
  std::string warnings = s.setup_warnings;
  if (!more.empty()) warnings += (warnings.empty() ? "" : "; ") + more;
  std::snprintf(out->warnings, sizeof out->warnings, "%s", warnings.c_str());
}

}  // namespace

extern "C" tomc_status tomc_runtime_add_task(tomc_runtime* runtime, const tomc_task_config* config,
                                             tomc_task_program program, void* context) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_add_task", "runtime");
    if (config == nullptr) return null_argument("tomc_runtime_add_task", "config");
    if (program == nullptr) return null_argument("tomc_runtime_add_task", "program");
    if (!header_ok(config)) return version_error("tomc_runtime_add_task", "tomc_task_config", config);
    if (runtime->runtime->started())
      return fail(TOMC_ERROR_STATE, "tomc_runtime_add_task: the runtime has started (add the task before)");
    if (runtime->task)
      return fail(TOMC_ERROR_STATE, "tomc_runtime_add_task: the runtime has a user task already");
    if (config->period_ns < 1'000'000 || config->period_ns > 1'000'000'000)
      return fail(TOMC_ERROR_OUT_OF_RANGE, "tomc_runtime_add_task: period_ns " +
                                               std::to_string(config->period_ns) +
                                               " is not 1000000 .. 1000000000 (1 ms .. 1 s)");
    if (config->fifo_priority < 0 || config->fifo_priority > 99)
      return fail(TOMC_ERROR_OUT_OF_RANGE, "tomc_runtime_add_task: fifo_priority " +
                                               std::to_string(config->fifo_priority) + " is not 0 .. 99");
    if (config->cpu < -1 || config->cpu >= CPU_SETSIZE)
      return fail(TOMC_ERROR_OUT_OF_RANGE,
                  "tomc_runtime_add_task: cpu " + std::to_string(config->cpu) + " is not -1 or a CPU number");
    auto task = std::make_unique<tomc_task>();
    task->runtime = runtime;
    task->program = program;
    task->context = context;
    task->runner_config = techobjects::RealTimeRunnerConfig{std::chrono::nanoseconds(config->period_ns),
                                                            config->fifo_priority, false};
    task->cpu = config->cpu;
    for (auto& o : runtime->objects) {
      const auto& m = o.machine;
      if (!m.built) continue;
      if (m.positioning_axis != nullptr) {
        o.snapshot =
            std::make_shared<SnapshotOf<techobjects::PositioningAxisData>>(m.positioning_axis->data());
      } else if (m.speed_axis != nullptr) {
        o.snapshot = std::make_shared<SnapshotOf<techobjects::SpeedAxisData>>(m.speed_axis->data());
      } else if (m.external_encoder != nullptr) {
        o.snapshot =
            std::make_shared<SnapshotOf<techobjects::ExternalEncoderData>>(m.external_encoder->data());
      }
    }
    runtime->task = std::move(task);
    install_user_program(runtime);
    return TOMC_OK;
  });
}

extern "C" tomc_status tomc_runtime_task_statistics(const tomc_runtime* runtime,
                                                    tomc_runner_statistics* statistics) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_task_statistics", "runtime");
    if (statistics == nullptr) return null_argument("tomc_runtime_task_statistics", "statistics");
    if (!header_ok(statistics))
      return version_error("tomc_runtime_task_statistics", "tomc_runner_statistics", statistics);
    if (!runtime->task)
      return fail(TOMC_ERROR_STATE, "tomc_runtime_task_statistics: the runtime has no user task");
    const tomc_task& task = *runtime->task;
    const bool running = task.runner != nullptr;
    copy_statistics(running ? task.runner->statistics() : task.last_statistics,
                    running ? std::string() : task.runner_warnings, statistics);
    return TOMC_OK;
  });
}

extern "C" tomc_status tomc_runtime_runner_statistics(const tomc_runtime* runtime,
                                                      tomc_runner_statistics* statistics) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_runner_statistics", "runtime");
    if (statistics == nullptr) return null_argument("tomc_runtime_runner_statistics", "statistics");
    if (!header_ok(statistics))
      return version_error("tomc_runtime_runner_statistics", "tomc_runner_statistics", statistics);
    const bool running = runtime->runner != nullptr;
    const techobjects::RunnerStatistics s =
        running ? runtime->runner->statistics() : runtime->last_statistics;
    statistics->cycles = s.cycles;
    statistics->overruns = s.overruns;
    statistics->jitter_median_us = s.jitter_median_us;
    statistics->jitter_p99_us = s.jitter_p99_us;
    statistics->jitter_max_us = s.jitter_max_us;
    // The CPU warning is written by the runner thread: read it only once the runner has stopped.
    std::string warnings = s.setup_warnings;
    if (!running && !runtime->runner_warnings.empty())
      warnings += (warnings.empty() ? "" : "; ") + runtime->runner_warnings;
    std::snprintf(statistics->warnings, sizeof statistics->warnings, "%s", warnings.c_str());
    return TOMC_OK;
  });
}

// ---- the diagnostics server ----

extern "C" tomc_status tomc_runtime_serve_diagnostics(tomc_runtime* runtime,
                                                      const tomc_diagnostics_config* config) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_serve_diagnostics", "runtime");
    if (config == nullptr) return null_argument("tomc_runtime_serve_diagnostics", "config");
    if (!header_ok(config))
      return version_error("tomc_runtime_serve_diagnostics", "tomc_diagnostics_config", config);
    if (runtime->runtime->started())
      return fail(TOMC_ERROR_STATE, "tomc_runtime_serve_diagnostics: the runtime has started (serve before)");
    if (runtime->diagnostics) return fail(TOMC_ERROR_STATE, "tomc_runtime_serve_diagnostics: already served");
    if (config->port < 0 || config->port > 65535)
      return fail(TOMC_ERROR_OUT_OF_RANGE, "tomc_runtime_serve_diagnostics: port " +
                                               std::to_string(config->port) +
                                               " is not 0 (any free port) .. 65535");
    auto d = std::make_unique<diagnostics::Diagnostics>();
    for (auto& o : runtime->objects) {
      const auto& m = o.machine;
      if (m.speed_axis != nullptr) {
        d->add(*m.speed_axis);
      } else if (m.synchronous_axis != nullptr) {  // its own view (synchronous status), not the PA's
        d->add(*m.synchronous_axis);
      } else if (m.positioning_axis != nullptr) {
        d->add(*m.positioning_axis);
      } else if (m.external_encoder != nullptr) {
        d->add(*m.external_encoder);
      } else if (m.cam != nullptr) {
        d->add(*m.cam);
      }
    }
    diagnostics::ServerOptions options;
    options.bind_address = config->bind_address != nullptr && config->bind_address[0] != '\0'
                               ? config->bind_address
                               : "127.0.0.1";
    options.port = config->port;
    options.token = config->token != nullptr ? config->token : "";
    auto server = std::make_unique<diagnostics::Server>(*d, options);
    try {
      server->start();
    } catch (const std::runtime_error& e) {
      return fail(TOMC_ERROR_SYSTEM, std::string("tomc_runtime_serve_diagnostics: ") + e.what());
    }
    d->attach(*runtime->runtime);
    runtime->diagnostics = std::move(d);
    runtime->server = std::move(server);
    return TOMC_OK;
  });
}

extern "C" tomc_status tomc_runtime_diagnostics_port(const tomc_runtime* runtime, int32_t* port) {
  if (runtime == nullptr) return null_argument("tomc_runtime_diagnostics_port", "runtime");
  if (port == nullptr) return null_argument("tomc_runtime_diagnostics_port", "port");
  if (!runtime->server) return fail(TOMC_ERROR_STATE, "tomc_runtime_diagnostics_port: no diagnostics server");
  *port = runtime->server->port();
  return TOMC_OK;
}

extern "C" tomc_status tomc_runtime_stop_diagnostics(tomc_runtime* runtime) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_stop_diagnostics", "runtime");
    if (!runtime->server)
      return fail(TOMC_ERROR_STATE, "tomc_runtime_stop_diagnostics: no diagnostics server");
    runtime->server->stop();  // the diagnostics stay attached to the cycle (publishing costs it nothing more)
    runtime->server.reset();
    return TOMC_OK;
  });
}

// ---- technology objects ----

extern "C" tomc_status tomc_runtime_object_count(const tomc_runtime* runtime, size_t* count) {
  if (runtime == nullptr) return null_argument("tomc_runtime_object_count", "runtime");
  if (count == nullptr) return null_argument("tomc_runtime_object_count", "count");
  *count = runtime->objects.size();
  return TOMC_OK;
}

extern "C" tomc_status tomc_runtime_object_at(tomc_runtime* runtime, size_t index, tomc_object** object) {
  if (runtime == nullptr) return null_argument("tomc_runtime_object_at", "runtime");
  if (object == nullptr) return null_argument("tomc_runtime_object_at", "object");
  *object = nullptr;
  if (index >= runtime->objects.size())
    return fail(TOMC_ERROR_UNKNOWN_OBJECT, "tomc_runtime_object_at: index " + std::to_string(index) +
                                               " >= " + std::to_string(runtime->objects.size()) + " objects");
  *object = &runtime->objects[index];
  return TOMC_OK;
}

extern "C" tomc_status tomc_runtime_find_object(tomc_runtime* runtime, const char* name,
                                                tomc_object** object) {
  return guarded([&] {
    if (runtime == nullptr) return null_argument("tomc_runtime_find_object", "runtime");
    if (name == nullptr) return null_argument("tomc_runtime_find_object", "name");
    if (object == nullptr) return null_argument("tomc_runtime_find_object", "object");
    *object = nullptr;
    for (auto& o : runtime->objects) {
      if (o.machine.name == name) {
        *object = &o;
        return TOMC_OK;
      }
    }
    std::string names;
    for (const auto& o : runtime->objects)
      names += (names.empty() ? "" : ", ") + o.machine.name;
    return fail(TOMC_ERROR_UNKNOWN_OBJECT, std::string("tomc_runtime_find_object: no technology object '") +
                                               name + "' (have: " + names + ")");
  });
}

extern "C" tomc_status tomc_object_name(const tomc_object* object, const char** name) {
  if (object == nullptr) return null_argument("tomc_object_name", "object");
  if (name == nullptr) return null_argument("tomc_object_name", "name");
  *name = object->machine.name.c_str();
  return TOMC_OK;
}

extern "C" tomc_status tomc_object_type_of(const tomc_object* object, tomc_object_type* type) {
  if (object == nullptr) return null_argument("tomc_object_type_of", "object");
  if (type == nullptr) return null_argument("tomc_object_type_of", "type");
  switch (kind_of(*object)) {
    case kSpeed:
      *type = TOMC_TO_SPEED_AXIS;
      break;
    case kPositioning:
      *type = TOMC_TO_POSITIONING_AXIS;
      break;
    case kSynchronous:
      *type = TOMC_TO_SYNCHRONOUS_AXIS;
      break;
    case kEncoder:
      *type = TOMC_TO_EXTERNAL_ENCODER;
      break;
    case kCam:
      *type = TOMC_TO_CAM;
      break;
  }
  return TOMC_OK;
}

// ---- variables ----

namespace {

template <typename Out, typename Convert>
tomc_status read_typed(const tomc_object* object, const char* function, const char* path, Out* value,
                       bool (*accepts)(const Variable&), const char* wanted, Convert convert) {
  return guarded([&] {
    if (object == nullptr) return null_argument(function, "object");
    if (path == nullptr) return null_argument(function, "path");
    if (value == nullptr) return null_argument(function, "value");
    const bool task = in_task_of(object->owner);
    if (!task)
      if (const auto s = check_thread(object->owner, function); s != TOMC_OK) return s;
    Variable v;
    if (const auto s = find(object, function, path, v); s != TOMC_OK) return s;
    if (!accepts(v)) return wrong_type(object, function, path, v, wanted);
    if (task) {
      if (v.synchronized_motion) {
        return fail(TOMC_ERROR_STATE, std::string(function) + ": " + object->machine.name + "." + path +
                                          ": StatusSynchronizedMotion is not mirrored for a user task");
      }
      // The user task reads the data block of the last interpolator cycle (taken at its cycle's start).
      if (!object->snapshot) {
        // A TO_Cam's data block (points and segments) is not mirrored for the task (decision C22).
        return fail(TOMC_ERROR_STATE,
                    std::string(function) + ": " + object->machine.name +
                        (object->machine.cam != nullptr ? ": a TO_Cam is not readable from a user task"
                                                        : " was not built"));
      }
      *value = convert(object->snapshot->read(v.info, v.bit));
      return TOMC_OK;
    }
    *value = convert(object->machine.read(path));
    return TOMC_OK;
  });
}

template <typename Accepts>
tomc_status write_typed(tomc_object* object, const char* function, const char* path, double value,
                        Accepts accepts, const char* wanted) {
  return guarded([&] {
    if (object == nullptr) return null_argument(function, "object");
    if (path == nullptr) return null_argument(function, "path");
    if (const auto s = check_thread(object->owner, function); s != TOMC_OK) return s;
    Variable v;
    if (const auto s = find(object, function, path, v); s != TOMC_OK) return s;
    if (v.bit)
      return fail(TOMC_ERROR_ACCESS, std::string(function) + ": " + object->machine.name + "." + path +
                                         ": a bit of a status word, written by the TO only");
    if (v.synchronized_motion)
      return fail(TOMC_ERROR_ACCESS, std::string(function) + ": " + object->machine.name + "." + path +
                                         ": StatusSynchronizedMotion is read only (RON)");
    if (!accepts(v)) return wrong_type(object, function, path, v, wanted);
    return write(object, function, path, value);
  });
}

std::optional<techobjects::VariableType> type_of(const Variable& v) {
  if (v.synchronized_motion) return v.synchronized_motion;
  if (v.info != nullptr) return v.info->type;
  return std::nullopt;
}
bool is_lreal(const Variable& v) {
  return type_of(v) == techobjects::VariableType::kLreal;
}
bool is_bool(const Variable& v) {
  return v.bit.has_value() || type_of(v) == techobjects::VariableType::kBool;
}
bool is_int(const Variable& v) {
  const auto t = type_of(v);
  return t.has_value() && techobjects::is_integer(*t);
}

}  // namespace

extern "C" tomc_status tomc_read_lreal(const tomc_object* object, const char* path, double* value) {
  return read_typed(object, "tomc_read_lreal", path, value, is_lreal, "LREAL", [](double x) { return x; });
}

extern "C" tomc_status tomc_read_bool(const tomc_object* object, const char* path, bool* value) {
  return read_typed(object, "tomc_read_bool", path, value, is_bool, "BOOL",
                    [](double x) { return x != 0.0; });
}

extern "C" tomc_status tomc_read_int(const tomc_object* object, const char* path, int64_t* value) {
  return read_typed(object, "tomc_read_int", path, value, is_int, "an integer or bit-string type",
                    [](double x) { return static_cast<int64_t>(x); });
}

extern "C" tomc_status tomc_write_lreal(tomc_object* object, const char* path, double value) {
  return write_typed(object, "tomc_write_lreal", path, value, is_lreal, "LREAL");
}

extern "C" tomc_status tomc_write_bool(tomc_object* object, const char* path, bool value) {
  return write_typed(object, "tomc_write_bool", path, value ? 1.0 : 0.0, is_bool, "BOOL");
}

extern "C" tomc_status tomc_write_int(tomc_object* object, const char* path, int64_t value) {
  return write_typed(object, "tomc_write_int", path, static_cast<double>(value), is_int,
                     "an integer or bit-string type");
}

// ---- alarms ----

extern "C" tomc_status tomc_object_alarm_count(const tomc_object* object, size_t* count) {
  if (object == nullptr) return null_argument("tomc_object_alarm_count", "object");
  if (count == nullptr) return null_argument("tomc_object_alarm_count", "count");
  if (const auto s = check_thread(object->owner, "tomc_object_alarm_count"); s != TOMC_OK) return s;
  *count = object->machine.built ? object->machine.alarms().alarms().size() : 0;
  return TOMC_OK;
}

extern "C" tomc_status tomc_object_alarm(const tomc_object* object, size_t index, tomc_alarm* alarm) {
  return guarded([&] {
    if (object == nullptr) return null_argument("tomc_object_alarm", "object");
    if (alarm == nullptr) return null_argument("tomc_object_alarm", "alarm");
    if (!header_ok(alarm)) return version_error("tomc_object_alarm", "tomc_alarm", alarm);
    if (const auto s = check_thread(object->owner, "tomc_object_alarm"); s != TOMC_OK) return s;
    const auto pending = object->machine.alarms().alarms();
    if (index >= pending.size())
      return fail(TOMC_ERROR_OUT_OF_RANGE, "tomc_object_alarm: index " + std::to_string(index) + ", " +
                                               object->machine.name + " has " +
                                               std::to_string(pending.size()) + " pending alarms");
    const auto& a = pending[index];
    alarm->number = a.number;
    alarm->additional_value = a.additional_value;
    alarm->alarm_class = static_cast<uint32_t>(a.alarm_class);
    alarm->reaction = static_cast<uint32_t>(a.reaction);
    alarm->raised_cycle = a.raised_cycle;
    return TOMC_OK;
  });
}
