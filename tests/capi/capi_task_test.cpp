// The two-task model of the C ABI: MC_Servo/MC_Interpolator at 1 ms on the real-time runner, the user program
// in its own 10 ms task (tomc_runtime_add_task). Instruction calls from the task reach the TO through the
// mailboxes; the task reads a consistent data block of the last interpolator cycle. Run under ThreadSanitizer
// too (scripts/test, build-tsan): the only shared state is the lock-free triple buffers.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <thread>

#include "tomc/tomc.h"
#ifdef TOMC_COUNT_ALLOCATIONS
#include "counting_allocator.hpp"
#endif

namespace {

constexpr const char* kSlide = R"({
  "cycle_time": 0.001,
  "technology_objects": [
    {"name": "Slide", "type": "TO_PositioningAxis",
     "config": {"Mechanics.LeadScrew": 5.0, "LoadGear.Numerator": 2, "LoadGear.Denominator": 1,
                "DynamicLimits.MaxJerk": 0.0, "DynamicLimits.MaxVelocity": 120.0, "DynamicLimits.Velocity": 120.0,
                "DynamicDefaults.Velocity": 100.0, "DynamicDefaults.Acceleration": 1000.0,
                "DynamicDefaults.Deceleration": 1000.0},
     "drive": {"adapter": "simulated", "telegram": 3, "load_inertia_kgm2": 1.0e-4}}
  ]
})";

// The user program of the 10 ms task: MC_Power, MC_Home (set position 0), MC_MoveAbsolute to `target`.
struct Task {
  tomc_object* slide = nullptr;
  tomc_MC_Power power;
  tomc_MC_Home home;
  tomc_MC_MoveAbsolute move;
  std::atomic<int> cycles{0};
  std::atomic<int> failures{0};
  std::atomic<int> torn_reads{0};     // two reads of Position in one task cycle that differ
  std::atomic<int> moving_cycles{0};  // task cycles in which the axis moved
  std::atomic<bool> done{false};
  std::atomic<bool> refused_write{false};
  double last_position = 0.0;
  explicit Task(double target) {
    tomc_MC_Power_init(&power);
    tomc_MC_Home_init(&home);
    tomc_MC_MoveAbsolute_init(&move);
    power.Enable = true;
    move.Position = target;
  }
};

void task_program(void* context) {
  auto* t = static_cast<Task*>(context);
  t->cycles.fetch_add(1, std::memory_order_relaxed);
  tomc_status s = tomc_MC_Power_call(t->slide, &t->power);
  t->home.Execute = t->power.Status;
  if (s == TOMC_OK) s = tomc_MC_Home_call(t->slide, &t->home);
  t->move.Execute = t->home.Done;
  if (s == TOMC_OK) s = tomc_MC_MoveAbsolute_call(t->slide, &t->move);
  if (s != TOMC_OK) t->failures.fetch_add(1);
  // The data block of the last interpolator cycle: the same all through this task cycle, although MC_Servo
  // runs two more cycles meanwhile.
  double before = 0.0;
  double after = 0.0;
  if (tomc_read_lreal(t->slide, "Position", &before) != TOMC_OK) t->failures.fetch_add(1);
  std::this_thread::sleep_for(std::chrono::microseconds(2500));
  if (tomc_read_lreal(t->slide, "Position", &after) != TOMC_OK) t->failures.fetch_add(1);
  if (before != after) t->torn_reads.fetch_add(1);
  if (before != t->last_position) t->moving_cycles.fetch_add(1);
  t->last_position = before;
  if (t->move.Done) t->done.store(true);
}

struct Runtime {
  tomc_runtime* runtime = nullptr;
  Runtime() { EXPECT_EQ(tomc_runtime_create(kSlide, &runtime), TOMC_OK) << tomc_last_error(); }
  ~Runtime() { tomc_runtime_destroy(runtime); }
};

tomc_runner_config runner_config() {
  tomc_runner_config c = {TOMC_STRUCT_HEADER(tomc_runner_config), 0, 0, -1, false};
  return c;
}

tomc_task_config task_config(uint64_t period_ns) {
  tomc_task_config c = {TOMC_STRUCT_HEADER(tomc_task_config), period_ns, 0, -1};
  return c;
}

bool wait_for(const std::atomic<bool>& flag, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!flag.load() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return flag.load();
}

// Decision E6 (the user task on its own thread, triple-buffer mailboxes).
TEST(CApiTask, A10msTaskPositionsTheAxisThroughTheMailboxes) {
  Runtime r;
  Task task(50.0);
  ASSERT_EQ(tomc_runtime_find_object(r.runtime, "Slide", &task.slide), TOMC_OK);
  const tomc_task_config config = task_config(10'000'000);
  ASSERT_EQ(tomc_runtime_add_task(r.runtime, &config, task_program, &task), TOMC_OK) << tomc_last_error();
  EXPECT_EQ(tomc_runtime_add_task(r.runtime, &config, task_program, &task), TOMC_ERROR_STATE);
  const tomc_runner_config runner = runner_config();
  const auto started = std::chrono::steady_clock::now();
  ASSERT_EQ(tomc_runtime_run_realtime(r.runtime, &runner), TOMC_OK) << tomc_last_error();
  const bool done = wait_for(task.done, std::chrono::seconds(30));
  ASSERT_EQ(tomc_runtime_stop_realtime(r.runtime), TOMC_OK);
  const auto elapsed = std::chrono::steady_clock::now() - started;
  EXPECT_TRUE(done);
  EXPECT_EQ(task.failures.load(), 0);
  EXPECT_FALSE(task.move.Error) << task.move.ErrorID;
  EXPECT_EQ(task.torn_reads.load(), 0);
  EXPECT_GT(task.moving_cycles.load(), 10);  // the reads did see the axis move, task cycle by task cycle
  double position = 0.0;
  ASSERT_EQ(tomc_read_lreal(task.slide, "Position", &position), TOMC_OK);
  EXPECT_NEAR(position, 50.0, 1e-9);
  tomc_runner_statistics servo = {TOMC_STRUCT_HEADER(tomc_runner_statistics), 0, 0, 0, 0, 0, ""};
  tomc_runner_statistics user = servo;
  ASSERT_EQ(tomc_runtime_runner_statistics(r.runtime, &servo), TOMC_OK);
  ASSERT_EQ(tomc_runtime_task_statistics(r.runtime, &user), TOMC_OK);
  // Two threads at their own periods: the task never runs more often than its 10 ms (absolute deadlines), the
  // servo thread at 1 ms runs at least twice as often as the task. On an idle machine that is about ten per
  // task cycle; under load each thread skips the periods it missed, the 1 ms one more of them (issue 22: 4.7
  // servo cycles per task cycle at a load of 17, where "more than 5" failed 2 times in 10).
  EXPECT_GT(user.cycles, 20u);
  EXPECT_LE(user.cycles, static_cast<uint64_t>(elapsed / std::chrono::milliseconds(10)) + 1);
  EXPECT_GT(servo.cycles, 2 * user.cycles);
  EXPECT_EQ(user.cycles, static_cast<uint64_t>(task.cycles.load()));
}

// Decision C22: from a user task, MC_InterpolateCam (it allocates) and MC_CopyCamData (it reads the task's
// arrays) would run in the cycle's thread: refused with TOMC_ERROR_STATE and a message; a TO_Cam's variables
// are not in the task's snapshots (TOMC_ERROR_STATE). MC_GetCamFollowingValue works from the task.
struct CamTask {
  tomc_object* cam = nullptr;
  tomc_MC_InterpolateCam interpolate;
  tomc_MC_GetCamFollowingValue following;
  std::atomic<int> interpolate_status{-1};
  std::atomic<int> read_status{-1};
  std::atomic<bool> read_done{false};
  std::string message;
};

void cam_task_program(void* context) {
  auto* t = static_cast<CamTask*>(context);
  if (t->interpolate_status.load() < 0) {
    t->interpolate.Execute = true;
    t->interpolate_status.store(tomc_MC_InterpolateCam_call(t->cam, &t->interpolate));
    t->message = tomc_last_error();
    bool interpolated = false;
    t->read_status.store(tomc_read_bool(t->cam, "StatusWord.X5", &interpolated));
  }
  t->following.Execute = true;
  t->following.LeadingValue = 90.0;
  if (tomc_MC_GetCamFollowingValue_call(t->cam, &t->following) == TOMC_OK && t->following.Done)
    t->read_done.store(true);
}

// Decision C22 (MC_InterpolateCam and MC_CopyCamData refused from a user task) and C2.
TEST(CApiTask, CamInstructionsThatAllocateAreRefusedInTheTask) {
  tomc_runtime* runtime = nullptr;
  ASSERT_EQ(tomc_runtime_create(R"({"cycle_time": 0.001, "technology_objects": [
      {"name": "C", "type": "TO_Cam", "Points": [[0, 0], [180, 100], [360, 0]], "Interpolate": true}]})",
                                &runtime),
            TOMC_OK)
      << tomc_last_error();
  CamTask task;
  tomc_MC_InterpolateCam_init(&task.interpolate);
  tomc_MC_GetCamFollowingValue_init(&task.following);
  ASSERT_EQ(tomc_runtime_find_object(runtime, "C", &task.cam), TOMC_OK);
  const tomc_task_config config = task_config(2'000'000);
  ASSERT_EQ(tomc_runtime_add_task(runtime, &config, cam_task_program, &task), TOMC_OK) << tomc_last_error();
  const tomc_runner_config runner = runner_config();
  ASSERT_EQ(tomc_runtime_run_realtime(runtime, &runner), TOMC_OK) << tomc_last_error();
  const bool read = wait_for(task.read_done, std::chrono::seconds(10));
  ASSERT_EQ(tomc_runtime_stop_realtime(runtime), TOMC_OK);
  EXPECT_EQ(task.interpolate_status.load(), TOMC_ERROR_STATE);
  EXPECT_NE(task.message.find("MC_InterpolateCam: not from a user task"), std::string::npos) << task.message;
  EXPECT_EQ(task.read_status.load(), TOMC_ERROR_STATE);
  EXPECT_TRUE(read);
  EXPECT_DOUBLE_EQ(task.following.Value, 50.0);
  tomc_runtime_destroy(runtime);
}

// Decision E6 (one task per runtime, its settings checked); E2.
TEST(CApiTask, BadTaskSettingsAreRefused) {
  Runtime r;
  Task task(1.0);
  tomc_task_config config = task_config(100'000);  // 0.1 ms: faster than a PLC task may be here
  EXPECT_EQ(tomc_runtime_add_task(r.runtime, &config, task_program, &task), TOMC_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(tomc_last_error()).find("period_ns 100000"), std::string::npos) << tomc_last_error();
  config = task_config(10'000'000);
  EXPECT_EQ(tomc_runtime_add_task(r.runtime, &config, nullptr, &task), TOMC_ERROR_NULL_ARGUMENT);
  config.header.size = 4;
  EXPECT_EQ(tomc_runtime_add_task(r.runtime, &config, task_program, &task), TOMC_ERROR_VERSION);
  config = task_config(10'000'000);
  config.fifo_priority = 100;
  EXPECT_EQ(tomc_runtime_add_task(r.runtime, &config, task_program, &task), TOMC_ERROR_OUT_OF_RANGE);
  tomc_runner_statistics s = {TOMC_STRUCT_HEADER(tomc_runner_statistics), 0, 0, 0, 0, 0, ""};
  EXPECT_EQ(tomc_runtime_task_statistics(r.runtime, &s), TOMC_ERROR_STATE);
  ASSERT_EQ(tomc_runtime_step(r.runtime, 1), TOMC_OK);
  config = task_config(10'000'000);
  EXPECT_EQ(tomc_runtime_add_task(r.runtime, &config, task_program, &task), TOMC_ERROR_STATE);
}

#ifdef TOMC_COUNT_ALLOCATIONS
// While the task calls its instructions and reads the data block and the servo thread runs them, nobody
// allocates: the mailboxes, snapshots and instances were all made at set-up or the task's first calls.
// Decision E6 (the servo thread never waits or allocates); the guide's real-time rules.
TEST(CApiTaskAllocation, NeitherThreadAllocatesWhileTheTaskCalls) {
  const std::uint64_t at_start = tomc::testing::allocation_count();
  Runtime r;
  EXPECT_GT(tomc::testing::allocation_count(), at_start);  // the counter sees libtomc.so's allocations
  Task task(200.0);                                        // 2.1 s of motion: the window below lies inside it
  ASSERT_EQ(tomc_runtime_find_object(r.runtime, "Slide", &task.slide), TOMC_OK);
  const tomc_task_config config = task_config(10'000'000);
  ASSERT_EQ(tomc_runtime_add_task(r.runtime, &config, task_program, &task), TOMC_OK) << tomc_last_error();
  const tomc_runner_config runner = runner_config();
  ASSERT_EQ(tomc_runtime_run_realtime(r.runtime, &runner), TOMC_OK) << tomc_last_error();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (task.moving_cycles.load() < 5 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const int cycles_before = task.cycles.load();
  const std::uint64_t before = tomc::testing::allocation_count();
  // At least 21 task cycles inside the motion (500 ms on an idle machine; bounded wait on a busy one, issue
  // 22).
  const auto window_end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  while (task.cycles.load() - cycles_before <= 20 && std::chrono::steady_clock::now() < window_end)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const std::uint64_t after = tomc::testing::allocation_count();
  const int cycles_after = task.cycles.load();
  ASSERT_EQ(tomc_runtime_stop_realtime(r.runtime), TOMC_OK);
  EXPECT_GE(task.moving_cycles.load(), 5);
  EXPECT_GT(cycles_after - cycles_before, 20);  // the task ran (and called) meanwhile
  EXPECT_EQ(after - before, 0u);
  EXPECT_EQ(task.failures.load(), 0);
}
#endif

}  // namespace
