#pragma once
// The diagnostics of a running machine, between the cycle and the web server (ARCHITECTURE-GUIDE §2):
//   - the cycle (Runtime's post-interpolator hook) publishes a snapshot of every technology object into a
//     triple buffer (staggered: one object every few cycles), runs the axis control panels and their
//     lifebeat, takes the panel commands from a lock-free queue, and feeds the trace recorder;
//   - other threads post panel commands and read the newest snapshots, the alarm history, the trace capture.
// The cycle never waits for the other side: no locks, no allocation, no I/O in cycle() (diagnostics
// allocation test). The non-real-time side is serialised by one mutex the cycle never touches.
//
//   diagnostics::Diagnostics diagnostics;
//   diagnostics.add(conveyor);            // a SpeedAxis: view + control panel
//   diagnostics.add(slide);               // a PositioningAxis/SynchronousAxis: view + panel with homing,
//                                         // positioning
//   diagnostics.attach(runtime);          // before runtime.start()
//   ... diagnostics.poll() every few tens of ms (the web server does), read with diagnostics.read(...)

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/diagnostics/actor_view.hpp"
#include "tomc/diagnostics/bounded_queue.hpp"
#include "tomc/diagnostics/layout.hpp"
#include "tomc/diagnostics/object_view.hpp"
#include "tomc/diagnostics/panel.hpp"
#include "tomc/diagnostics/trace.hpp"
#include "tomc/diagnostics/triple_buffer.hpp"
#include "tomc/diagnostics/units.hpp"
#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::techobjects {
class SpeedAxis;
class PositioningAxis;
class SynchronousAxis;
class ExternalEncoder;
class Cam;
}  // namespace tomc::techobjects

namespace tomc::diagnostics {

inline constexpr std::size_t kEventsPerSnapshot = 32;

// What the cycle publishes of one technology object.
struct ObjectSnapshot {
  std::uint64_t cycle = 0;
  std::uint64_t revision = 0;        // ObjectView::revision() when the snapshot was taken
  std::vector<double> values;        // one per row of the object's reflection table (sized at set-up)
  std::vector<std::uint32_t> words;  // one per telegram channel
  std::array<techobjects::PendingAlarm, techobjects::AlarmList::kCapacity> alarms{};
  std::uint32_t alarm_count = 0;
  std::array<techobjects::AlarmEvent, kEventsPerSnapshot> events{};  // the newest alarm events, oldest first
  std::uint32_t event_count = 0;
  PanelStatus panel{};
  ActorSnapshot actor{};  // an axis on an analog or stepper actor (set_actor); kind kNone otherwise
};

struct DiagnosticsConfig {
  std::uint32_t publish_period_cycles = 10;  // each object's snapshot every n servo cycles
  std::size_t trace_ring_rows = 4096;
  std::size_t alarm_history = 500;  // events kept per object on the reader's side
};

// An HMI-like switch the user program reads (e.g. "run this axis automatically"); written from the page.
struct ProgramSwitch {
  std::string name;
  std::string description;
  std::atomic<bool>* flag;
};

// A trace as the page asks for it.
struct TraceRequest {
  std::vector<std::string> channels;  // "<TO>.<path>" (ObjectView::probe paths)
  TriggerKind trigger = TriggerKind::kImmediate;
  std::string trigger_signal;  // "<TO>.<path>" for every trigger but kImmediate
  double threshold = 0.0;
  std::uint32_t pre_samples = 0;
  std::uint32_t post_samples = 1000;
  std::uint32_t decimation = 1;
};

class Diagnostics {
 public:
  explicit Diagnostics(DiagnosticsConfig config = {});
  ~Diagnostics();
  Diagnostics(const Diagnostics&) = delete;
  Diagnostics& operator=(const Diagnostics&) = delete;

  // ---- set-up (before attach) ----
  void add(techobjects::SpeedAxis& axis);  // view + control panel
  // View + control panel with homing and positioning (PositioningAxisPanel); also a SynchronousAxis.
  void add(techobjects::PositioningAxis& axis);
  // Its own view (the positioning axis' areas plus synchronous operation, StatusSynchronizedMotion in the
  // trace) and the positioning axis' panel.
  void add(techobjects::SynchronousAxis& axis);
  void add(const techobjects::Cam& cam);            // view and cam plot (no panel)
  void add(techobjects::ExternalEncoder& encoder);  // view (no panel: an encoder is not moved)
  // Any technology object: its view and, for an axis, its panel (nullptr: none).
  void add(std::unique_ptr<ObjectView> view, std::unique_ptr<AxisPanel> panel);
  // The analog or stepper actor of an added axis (issue 20): the page shows its terminals instead of
  // telegram words. Throws std::invalid_argument for an unknown name.
  void set_actor(std::string_view object, ActorSource actor);
  ActorKind actor_kind(std::size_t object) const noexcept { return objects_[object]->actor.kind(); }
  void add_switch(std::string name, std::string description, std::atomic<bool>& flag);
  // Sets the runtime's post-interpolator hook to cycle(); the runtime must not have started.
  void attach(techobjects::Runtime& runtime);

  // ---- the cycle ----
  void cycle(const techobjects::CycleClock& clock) noexcept;

  // ---- any other thread ----
  std::size_t object_count() const noexcept { return objects_.size(); }
  std::optional<std::size_t> find_object(std::string_view name) const noexcept;
  const ObjectView& view(std::size_t object) const noexcept { return *objects_[object]->view; }
  const AxisPanel* panel(std::size_t object) const noexcept { return objects_[object]->panel.get(); }
  std::span<const ResolvedItem> layout_items(std::size_t object) const noexcept {
    return objects_[object]->items;
  }
  // Unit symbols of the object's data block (read by attach(), before the cycle runs; units.hpp).
  const ObjectUnits& units(std::size_t object) const noexcept { return objects_[object]->units; }
  // Actor.DriveParameter.ReferenceSpeed (1/min; read by attach()): 100 % of NSOLL/NIST (spec 06). 0: none.
  double reference_speed(std::size_t object) const noexcept { return objects_[object]->reference_speed; }
  std::span<const ProgramSwitch> switches() const noexcept { return switches_; }
  double servo_cycle_s() const noexcept { return servo_cycle_s_; }

  // Posts a command without waiting: its request number (0: the queue is full or the object has no panel).
  std::uint64_t post(PanelCommand command) noexcept;
  // The cycle's answer to a posted request, once it came.
  std::optional<PanelAnswer> answer_of(std::uint64_t request) const noexcept;
  // Posts a command and waits for the cycle's answer (kNoAnswer after `timeout`).
  PanelAnswer command(PanelCommand command,
                      std::chrono::milliseconds timeout = std::chrono::milliseconds(1000));
  // Sets a program switch; false for an unknown name.
  bool set_switch(std::string_view name, bool on);

  // Takes the newest snapshots, extends the alarm histories, drains the trace ring. Call every few tens of
  // ms.
  void poll();

  // What poll() collected, read under the reader's lock.
  struct ObjectState {
    bool valid = false;  // a snapshot arrived
    ObjectSnapshot snapshot;
    std::deque<techobjects::AlarmEvent> history;  // oldest first
    // When each event of `history` happened by the wall clock (Unix time, s): the poll that first saw it
    // dates it back from the newest snapshot's cycle (the cycle runs in real time).
    std::deque<double> history_unix_s;
    std::uint64_t history_lost = 0;  // events the reader missed (overwritten before read)
    std::uint64_t last_sequence = 0;
  };
  struct State {
    std::vector<ObjectState> objects;
    TraceCapture trace;
    std::uint64_t polls = 0;
  };
  template <typename F>
  auto read(F&& f) const {
    std::lock_guard lock(mutex_);
    return f(state_);
  }

  // Traces (any thread). An empty vector: started; otherwise one line per problem.
  std::vector<std::string> start_trace(const TraceRequest& request);
  void stop_trace();

 private:
  struct Object {
    std::unique_ptr<ObjectView> view;
    std::unique_ptr<AxisPanel> panel;
    std::vector<ResolvedItem> items;  // diagnostics_layout(type), in order
    TripleBuffer<ObjectSnapshot> buffer;
    std::uint64_t publish_slot = 0;  // published when servo_cycles % publish_period_cycles == publish_slot
    ObjectUnits units;
    double reference_speed = 0.0;
    ActorSource actor;
  };
  void publish(Object& object, std::uint64_t cycle) noexcept;
  void answer(std::uint64_t request, PanelAnswer answer) noexcept;

  DiagnosticsConfig config_;
  std::vector<std::unique_ptr<Object>> objects_;  // stable addresses: triple buffers hold atomics
  std::vector<ProgramSwitch> switches_;
  double servo_cycle_s_ = 0.001;
  bool attached_ = false;

  BoundedQueue<PanelCommand, 256> commands_;
  std::array<std::atomic<std::uint64_t>, 256> answers_{};  // request << 8 | PanelAnswer
  std::atomic<std::uint64_t> next_request_{1};
  TraceRecorder recorder_;

  mutable std::mutex mutex_;  // the reader's side only
  State state_;
  std::vector<TraceRow> drained_;
};

}  // namespace tomc::diagnostics
