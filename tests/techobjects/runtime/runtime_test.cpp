// The application cycle of the runtime (ARCHITECTURE-GUIDE §2; spec 01 §3.4 and §11 A6: MC_PreServo ->
// MC_Servo -> MC_PostServo), the interpolator and user-program ratios, and the set-up rules.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tomc/techobjects/runtime/runtime.hpp"

namespace {

using tomc::drives::DeviceConfig;
using tomc::drives::DeviceFrames;
using tomc::drives::LinkHealth;
using namespace tomc::techobjects;

std::vector<std::string>* g_log = nullptr;
void log(const std::string& what) {
  g_log->push_back(what);
}

class RecordingAdapter final : public tomc::drives::DriveAdapter {
 public:
  explicit RecordingAdapter(std::string name) : name_(std::move(name)) { config_.drive_telegram = 1; }
  const DeviceConfig& config() const noexcept override { return config_; }
  bool read_actual(DeviceFrames& actual) noexcept override {
    log("read " + name_);
    actual.slots[0].bytes[0] = std::byte{0x42};
    return fresh;
  }
  void write_setpoint(const DeviceFrames& setpoint) noexcept override {
    log("write " + name_);
    last_written = setpoint.slots[0].bytes[1];
  }
  LinkHealth link_health() const noexcept override { return {}; }
  bool fresh = true;
  std::byte last_written{};

 private:
  std::string name_;
  DeviceConfig config_;
};

class RecordingObject final : public TechnologyObject {
 public:
  RecordingObject(std::string name, DeviceIo& io) : name_(std::move(name)), io_(io) {}
  std::string_view name() const noexcept override { return name_; }
  void servo(const CycleClock& c) noexcept override {
    log("servo " + name_ + " " + std::to_string(c.servo_cycles) + (io_.fresh ? " fresh" : " stale"));
    seen_actual = io_.actual.slots[0].bytes[0];
    io_.setpoint.slots[0].bytes[1] = std::byte{0x17};
  }
  void interpolate(const CycleClock& c) noexcept override {
    log("ipo " + name_ + " " + std::to_string(c.interpolator_cycles));
  }
  std::byte seen_actual{};

 private:
  std::string name_;
  DeviceIo& io_;
};

struct LogGuard {
  std::vector<std::string> entries;
  LogGuard() { g_log = &entries; }
  ~LogGuard() { g_log = nullptr; }
};

// ARCHITECTURE-GUIDE §2: PreServo, read every actual frame, servo of every TO, write every setpoint frame,
// PostServo, Interpolator, user program.
TEST(Runtime, OneCycleRunsThePhasesInOrder) {
  LogGuard guard;
  Runtime rt(RuntimeConfig{0.001, 1, 1});
  auto& a = rt.add_device(std::make_unique<RecordingAdapter>("A"));
  auto& b = rt.add_device(std::make_unique<RecordingAdapter>("B"));
  auto& ta = rt.emplace<RecordingObject>("TA", a);
  rt.emplace<RecordingObject>("TB", b);
  rt.set_pre_servo([](Runtime&) { log("pre-servo"); });
  rt.set_post_servo([](Runtime&) { log("post-servo"); });
  rt.set_post_interpolator([](Runtime&) { log("post-interpolator"); });
  rt.set_user_program([](Runtime&) { log("user"); });
  rt.start();
  rt.step();
  const std::vector<std::string> expected = {
      "pre-servo", "read A",     "read B",   "servo TA 0 fresh", "servo TB 0 fresh",  "write A",
      "write B",   "post-servo", "ipo TA 0", "ipo TB 0",         "post-interpolator", "user"};
  EXPECT_EQ(guard.entries, expected);
  // The TO saw the frame read this cycle and its setpoint reached the adapter in the same cycle.
  EXPECT_EQ(ta.seen_actual, std::byte{0x42});
  EXPECT_EQ(static_cast<RecordingAdapter&>(*a.adapter).last_written, std::byte{0x17});
  EXPECT_EQ(rt.clock().servo_cycles, 1u);
  EXPECT_EQ(rt.clock().interpolator_cycles, 1u);
}

// Decisions R1 (read_actual at the start of MC_Servo) and R9 (no fresh frame: a stale cycle).
TEST(Runtime, StaleFramesAreFlagged) {
  LogGuard guard;
  Runtime rt(RuntimeConfig{});
  auto& a = rt.add_device(std::make_unique<RecordingAdapter>("A"));
  rt.emplace<RecordingObject>("TA", a);
  rt.start();
  static_cast<RecordingAdapter&>(*a.adapter).fresh = false;
  rt.step();
  EXPECT_EQ(guard.entries[1], "servo TA 0 stale");
}

// The interpolator runs every n servo cycles and the user program every m (m a multiple of n).
// ARCHITECTURE-GUIDE §2 (one application cycle: servo, interpolator, user program).
TEST(Runtime, InterpolatorAndUserProgramRatios) {
  LogGuard guard;
  Runtime rt(RuntimeConfig{0.0005, 2, 4});
  auto& a = rt.add_device(std::make_unique<RecordingAdapter>("A"));
  rt.emplace<RecordingObject>("TA", a);
  int user_calls = 0;
  int post_interpolator_calls = 0;
  rt.set_user_program([&](Runtime&) { ++user_calls; });
  rt.set_post_interpolator([&](Runtime&) { ++post_interpolator_calls; });
  rt.start();
  for (int i = 0; i < 8; ++i)
    rt.step();
  int servo = 0;
  int ipo = 0;
  for (const auto& e : guard.entries) {
    servo += e.rfind("servo", 0) == 0;
    ipo += e.rfind("ipo", 0) == 0;
  }
  EXPECT_EQ(servo, 8);
  EXPECT_EQ(ipo, 4);
  EXPECT_EQ(user_calls, 2);
  EXPECT_EQ(post_interpolator_calls, 8);  // every servo cycle: traces sample at the servo rate
  EXPECT_DOUBLE_EQ(rt.clock().interpolator_cycle_s, 0.001);
  EXPECT_DOUBLE_EQ(rt.clock().time_s(), 0.004);
}

// ARCHITECTURE-GUIDE §6 (configuration at set-up, before the cycle starts).
TEST(Runtime, SetUpEndsAtStart) {
  Runtime rt(RuntimeConfig{});
  rt.start();
  EXPECT_THROW(rt.add_device(std::make_unique<RecordingAdapter>("A")), std::logic_error);
  EXPECT_THROW(rt.set_user_program([](Runtime&) {}), std::logic_error);
  EXPECT_THROW(rt.start(), std::logic_error);
}

// ARCHITECTURE-GUIDE §2, §6.
TEST(Runtime, StepBeforeStartDoesNothing) {
  LogGuard guard;
  Runtime rt(RuntimeConfig{});
  rt.add_device(std::make_unique<RecordingAdapter>("A"));
  rt.step();
  EXPECT_TRUE(guard.entries.empty());
  EXPECT_EQ(rt.clock().servo_cycles, 0u);
}

// ARCHITECTURE-GUIDE §2 (the user-program cycle a multiple of the interpolator's), §6.
TEST(Runtime, RejectsInvalidConfiguration) {
  EXPECT_THROW(Runtime(RuntimeConfig{0.0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(Runtime(RuntimeConfig{0.001, 0, 1}), std::invalid_argument);
  EXPECT_THROW(Runtime(RuntimeConfig{0.001, 2, 3}), std::invalid_argument);
  Runtime rt(RuntimeConfig{});
  EXPECT_THROW(rt.add_device(nullptr), std::invalid_argument);
}

}  // namespace
