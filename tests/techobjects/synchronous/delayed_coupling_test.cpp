// The local "Delayed" coupling (spec 07 §1.5, §6.1 item 2; decision C26): a leader gives its followers
// coupled "Delayed" its setpoint CrossPlcSynchronousOperation.LocalLeadingValueDelayTime in the past,
// linearly interpolated between interpolator cycles, and shows it in
// StatusProvidedLeadingValue.DelayedLeadingValue. Cycle 1 ms; L accelerates at 5,000 mm/s² to 100 mm/s and
// runs on, so position, velocity and acceleration all change while the followers are compared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "gearing_fixture.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"

namespace {

using namespace tomc;
using techobjects::LeadingValueCoupling;
using techobjects::MotionState;
using techobjects::PositioningAxis;
using techobjects::SynchronousAxis;
using tomc::testing::virtual_linear;

// L, F geared 1:1 to L's setpoint, D geared 1:1 to L's delayed setpoint; both couple at rest at 0 (GI-1: in
// gear at once), so F's setpoint is L's and D's is L's delayed.
struct DelayedMachine {
  explicit DelayedMachine(double delay_s) : runtime(techobjects::RuntimeConfig{0.001, 1, 1}) {
    auto leader = virtual_linear();
    leader.CrossPlcSynchronousOperation.LocalLeadingValueDelayTime = delay_s;
    L = &runtime.emplace<PositioningAxis>("L", nullptr, leader);
    F = &runtime.emplace<SynchronousAxis>(
        "F", nullptr, virtual_linear(),
        std::vector<techobjects::LeadingValueInterconnection>{{L, L, LeadingValueCoupling::kSetpoint}});
    D = &runtime.emplace<SynchronousAxis>(
        "D", nullptr, virtual_linear(),
        std::vector<techobjects::LeadingValueInterconnection>{{L, L, LeadingValueCoupling::kDelayed}});
    gear_F.Master = gear_D.Master = L;
    runtime.set_user_program([this](techobjects::Runtime&) {
      power_L(*L);
      power_F(*F);
      power_D(*D);
      gear_F(*F);
      gear_D(*D);
      move_L(*L);
    });
    runtime.start();
    power_L.Enable = power_F.Enable = power_D.Enable = true;
    run(3);
    gear_F.Execute = gear_D.Execute = true;
    run(2);
  }
  void run(int cycles) {
    for (int i = 0; i < cycles; ++i)
      runtime.step();
  }
  techobjects::Runtime runtime;
  PositioningAxis* L = nullptr;
  SynchronousAxis* F = nullptr;
  SynchronousAxis* D = nullptr;
  instructions::MC_Power<PositioningAxis> power_L;
  instructions::MC_Power<SynchronousAxis> power_F, power_D;
  instructions::MC_GearIn<SynchronousAxis> gear_F, gear_D;
  instructions::MC_MoveVelocity<PositioningAxis> move_L;
};

// The follower coupled "Delayed" lags the setpoint-coupled one by exactly the delay: 5 ms = 5 cycles gives
// D(k) = F(k − 5) in position, velocity and acceleration; 2.5 ms gives the mean of F(k − 2) and F(k − 3).
// spec 07 §1.5, §6.1 (the leader setpoint LocalLeadingValueDelayTime ago, interpolated); decision C26.
TEST(DelayedCoupling, FollowerLagsTheSetpointCoupledOneByTheDelay) {
  struct Row {
    double delay_s;
    int whole;        // n: whole cycles of the delay
    double fraction;  // f: the rest, interpolated
  };
  for (const Row& r : {Row{0.005, 5, 0.0}, Row{0.0025, 2, 0.5}, Row{0.0, 0, 0.0}}) {
    DelayedMachine m(r.delay_s);
    ASSERT_TRUE(m.gear_F.InGear && m.gear_D.InGear) << r.delay_s;
    m.move_L.Velocity = 100.0;
    m.move_L.Acceleration = 5000.0;
    m.move_L.Execute = true;
    std::vector<MotionState> f;  // F's setpoint, cycle by cycle from the start of L's motion
    for (int k = 0; k < 60; ++k) {
      m.run(1);
      f.push_back(m.F->setpoint());
      const MotionState& d = m.D->setpoint();
      const auto at = [&](int back) {
        const int i = k - back;
        return i >= 0 ? f[static_cast<std::size_t>(i)] : MotionState{};  // L stood at 0 before
      };
      const MotionState a = at(r.whole);
      const MotionState b = at(r.whole + 1);
      const double g = r.fraction;
      EXPECT_NEAR(d.position, a.position + g * (b.position - a.position), 1e-12) << r.delay_s << " " << k;
      EXPECT_NEAR(d.velocity, a.velocity + g * (b.velocity - a.velocity), 1e-9) << r.delay_s << " " << k;
      EXPECT_NEAR(d.acceleration, a.acceleration + g * (b.acceleration - a.acceleration), 1e-6)
          << r.delay_s << " " << k;
      // The leader shows the value it provides (spec 07 §1.5, StatusProvidedLeadingValue).
      EXPECT_EQ(m.L->data().StatusProvidedLeadingValue.DelayedLeadingValue.Position, d.position) << k;
      EXPECT_EQ(m.L->data().StatusProvidedLeadingValue.DelayedLeadingValue.Velocity, d.velocity) << k;
    }
    // The comparison covered the acceleration at 5,000 mm/s² and the constant velocity after it.
    const auto accelerating = std::count_if(
        f.begin(), f.end(), [](const MotionState& s) { return std::fabs(s.acceleration - 5000.0) < 1e-6; });
    EXPECT_GE(accelerating, 15) << r.delay_s;
    EXPECT_NEAR(f.back().velocity, 100.0, 1e-9);
    // 5 ms at 100 mm/s: the delayed follower is 0.5 mm behind once both run at constant velocity.
    EXPECT_NEAR(m.F->setpoint().position - m.D->setpoint().position, 100.0 * r.delay_s, 1e-9) << r.delay_s;
    EXPECT_TRUE(m.gear_D.InGear);
  }
}

// The history belongs to the leader, only while a follower couples "Delayed", sized by the delay: n + 2
// samples (decision C26), shared by every follower coupled "Delayed" to it.
TEST(DelayedCoupling, TheLeaderOwnsAHistorySizedByTheDelay) {
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  auto leader = virtual_linear();
  leader.CrossPlcSynchronousOperation.LocalLeadingValueDelayTime = 0.005;
  auto* L = &runtime.emplace<PositioningAxis>("L", nullptr, leader);
  const auto follower = [&](const char* name, LeadingValueCoupling coupling) {
    runtime.emplace<SynchronousAxis>(name, nullptr, virtual_linear(),
                                     std::vector<techobjects::LeadingValueInterconnection>{{L, L, coupling}});
  };
  const std::size_t alone = L->memory_footprint();
  follower("F", LeadingValueCoupling::kSetpoint);
  EXPECT_EQ(L->memory_footprint(), alone);
  follower("D", LeadingValueCoupling::kDelayed);
  EXPECT_EQ(L->memory_footprint() - alone,
            sizeof(techobjects::DelayedLeadingValue) + (5 + 2) * sizeof(MotionState));
  follower("D2", LeadingValueCoupling::kDelayed);
  EXPECT_EQ(L->memory_footprint() - alone,
            sizeof(techobjects::DelayedLeadingValue) + (5 + 2) * sizeof(MotionState));
}

// Configuration errors naming the key: a delay longer than the history may hold (1,000 cycles, C26) or
// far longer; "Delayed" on an external encoder (not yet: its actual value would need its own history).
TEST(DelayedCoupling, DelaysTheHistoryCannotHoldAreConfigurationErrors) {
  for (const double delay : {1.0011, 2.5}) {
    techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
    auto leader = virtual_linear();
    leader.CrossPlcSynchronousOperation.LocalLeadingValueDelayTime = delay;
    auto* L = &runtime.emplace<PositioningAxis>("L", nullptr, leader);
    try {
      runtime.emplace<SynchronousAxis>(
          "D", nullptr, virtual_linear(),
          std::vector<techobjects::LeadingValueInterconnection>{{L, L, LeadingValueCoupling::kDelayed}});
      ADD_FAILURE() << delay << " s was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("L.CrossPlcSynchronousOperation.LocalLeadingValueDelayTime"),
                std::string::npos)
          << e.what();
      EXPECT_TRUE(std::string(e.what()).starts_with("D.LeadingValueInterconnections[0] (\"Delayed\" to L): "))
          << e.what();
    }
    EXPECT_EQ(runtime.technology_object_count(), 1u);
  }
  // Exactly 1,000 cycles is the longest delay.
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  auto leader = virtual_linear();
  leader.CrossPlcSynchronousOperation.LocalLeadingValueDelayTime = 1.0;
  auto* L = &runtime.emplace<PositioningAxis>("L", nullptr, leader);
  EXPECT_NO_THROW(runtime.emplace<SynchronousAxis>(
      "D", nullptr, virtual_linear(),
      std::vector<techobjects::LeadingValueInterconnection>{{L, L, LeadingValueCoupling::kDelayed}}));
  drives::DeviceConfig encoder_device;
  encoder_device.encoder_telegrams[0] = 81;
  auto& io = runtime.add_device(
      std::make_unique<drives::SimulatedDrive>(encoder_device, drives::SimulatedDriveParameters{}));
  auto* E = &runtime.emplace<techobjects::ExternalEncoder>("E", &io, techobjects::ExternalEncoderData{});
  // The follower and its interconnection named as in a machine file (the leader L first, E second).
  try {
    runtime.emplace<SynchronousAxis>(
        "DE", nullptr, virtual_linear(),
        std::vector<techobjects::LeadingValueInterconnection>{{L, L, LeadingValueCoupling::kSetpoint},
                                                              {E, E, LeadingValueCoupling::kDelayed}});
    ADD_FAILURE() << "\"Delayed\" on an external encoder was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "DE.LeadingValueInterconnections[1] (\"Delayed\" to E): this leading value cannot be coupled "
              "\"Delayed\" (only a positioning or synchronous axis can, decision C26)");
  }
  EXPECT_EQ(runtime.technology_object_count(), 3u);  // L, D and E: DE was not added
}

}  // namespace
