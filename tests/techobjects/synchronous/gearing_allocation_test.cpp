// Real-time discipline of TO_SynchronousAxis (issue 9): after Runtime::start(), MC_Servo, MC_Interpolator and
// the gearing instructions allocate nothing, whatever the coupling does. A counting global operator new
// watches one runtime with
//   L   a positioning axis on a simulated drive (telegram 3, codec included), the leader;
//   E   an external encoder on a simulated encoder device (telegram 83), a leader by actual value;
//   F1  a synchronous axis on a simulated drive, possible leaders L (setpoint) and E (actual value);
//   F2  a virtual synchronous axis following F1 (the chain L -> F1 -> F2), possible leaders F1 and L, the
//       latter coupled "Delayed" (L's setpoint 2.5 ms ago from its ring, decision C26);
// while a scripted user program runs them, in a loop, through every gearing job kind: MC_GearIn on all
// followers, a second MC_GearIn replacing the first, a leader switchover to the actual value of E,
// MC_GearInVelocity with ContinuousUpdate and ratio changes, MC_GearInPos profiles 0, 1 and 3, MC_GearOut
// profiles 0, 1 and 5 (cancelling a pending MC_GearInPos), MC_Halt and MC_Stop ending a gearing, rejected
// jobs (illegal ratio, a GearOut without gearing), a leading value reversing during synchronization (alarm
// 608) and MC_Reset; then camming (issue 19): MC_CamIn direct and cyclic, the switch to another cam at the
// end of the cam (profile 5, cyclic appending), MC_CamOut profiles 0 and 1, MC_CamIn profile 1; during the
// camming MC_OffsetRelative and MC_PhasingRelative over a distance and MC_LeadingValueAdditive, and during a
// gearing MC_PhasingRelative with dynamic parameters. The test also checks that the script reached every job
// kind.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdlib>
#include <functional>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "counting_allocator.hpp"
#include "gearing_fixture.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_leading_value_additive.hpp"
#include "tomc/instructions/mc_phasing.hpp"
#include "tomc/instructions/mc_reset.hpp"
#include "tomc/techobjects/cam/cam.hpp"
#include "tomc/techobjects/external_encoder/external_encoder.hpp"

namespace {

using namespace tomc;
using techobjects::ExternalEncoder;
using techobjects::LeadingValueCoupling;
using techobjects::PositioningAxis;
using techobjects::SynchronousAxis;

#ifdef TOMC_SANITIZED_BUILD
constexpr int kCycles = 40'000;
#else
constexpr int kCycles = 300'000;
#endif

template <typename Axis>
struct FollowerProgram {
  instructions::MC_Power<Axis> power;
  instructions::MC_Reset<Axis> reset;
  instructions::MC_Home<Axis> home;
  instructions::MC_GearIn<Axis> gear;
  instructions::MC_GearIn<Axis> gear2;
  instructions::MC_GearInVelocity<Axis> gear_velocity;
  instructions::MC_GearInPos<Axis> gear_pos;
  instructions::MC_GearOut<Axis> gear_out;
  instructions::MC_Halt<Axis> halt;
  instructions::MC_Stop<Axis> stop;
  instructions::MC_CamIn<Axis> cam_in;
  instructions::MC_CamIn<Axis> cam_in2;
  instructions::MC_CamOut<Axis> cam_out;
  instructions::MC_PhasingRelative<Axis> phasing;
  instructions::MC_OffsetRelative<Axis> offset;
  instructions::MC_LeadingValueAdditive<Axis> additive;
  void call(Axis& a) {
    power(a);
    reset(a);
    home(a);
    halt(a);
    stop(a);
    gear_out(a);
    gear(a);
    gear2(a);
    gear_velocity(a);
    gear_pos(a);
    cam_out(a);
    cam_in(a);
    cam_in2(a);
    phasing(a);
    offset(a);
    additive(a);
  }
};

// Rising edges of the outputs that show a job kind was reached (fixed arrays: nothing allocates in the loop).
enum Reached {
  kInGear,
  kReplaced,
  kActualValue,
  kVelocityInSync,
  kPosProfile0,
  kPosProfile1,
  kPosProfile3,
  kGearOutDone,
  kGearOutCancel,
  kHaltDone,
  kStopDone,
  kRejected,
  kAlarm608,
  kResetDone,
  kChainInGear,
  kCamInSync,
  kCamSwitched,
  kCamProfile1,
  kCamOutDone,
  kOffsetDone,
  kPhasingDone,
  kAdditiveBusy,
  kReachedCount
};
constexpr const char* kReachedNames[kReachedCount] = {"MC_GearIn InGear",
                                                      "MC_GearIn replaced (CommandAborted)",
                                                      "InGear on the actual value of E",
                                                      "MC_GearInVelocity InSync",
                                                      "MC_GearInPos profile 0 InSync",
                                                      "MC_GearInPos profile 1 InSync",
                                                      "MC_GearInPos profile 3 InSync",
                                                      "MC_GearOut Done",
                                                      "MC_GearOut profile 5 (cancel)",
                                                      "MC_Halt Done after gearing",
                                                      "MC_Stop Done after gearing",
                                                      "job rejected (Error)",
                                                      "alarm 608",
                                                      "MC_Reset Done",
                                                      "chained follower InGear",
                                                      "MC_CamIn profile 2 InSync",
                                                      "MC_CamIn profile 5 switched at the cam end",
                                                      "MC_CamIn profile 1 InSync",
                                                      "MC_CamOut Done",
                                                      "MC_OffsetRelative Done",
                                                      "MC_PhasingRelative Done",
                                                      "MC_LeadingValueAdditive Busy"};

struct Machine {
  Machine() : runtime(techobjects::RuntimeConfig{0.001, 1, 1}) {
    auto drive_io = [&](std::uint16_t telegram, bool encoder_only) -> techobjects::DeviceIo& {
      drives::DeviceConfig device;
      drives::SimulatedDriveParameters p;
      if (encoder_only) {
        device.encoder_telegrams[0] = telegram;
        p.load_units_per_revolution = 360.0;
        p.encoder1.shaft = drives::SimulatedEncoderParameters::Shaft::kLoad;
      } else {
        device.drive_telegram = telegram;
        p.load_units_per_revolution = 10.0;  // the 10 mm leadscrew of the default data block
      }
      auto owned = std::make_unique<drives::SimulatedDrive>(device, p);
      if (encoder_only) encoder_drive = owned.get();
      return runtime.add_device(std::move(owned));
    };
    techobjects::PositioningAxisData axis;  // the default data block (mm, 10 mm leadscrew)
    axis.DynamicLimits.MaxJerk = 0.0;
    auto leader = axis;
    leader.CrossPlcSynchronousOperation.LocalLeadingValueDelayTime = 0.0025;
    L = &runtime.emplace<PositioningAxis>("L", &drive_io(3, false), leader);
    E = &runtime.emplace<ExternalEncoder>("E", &drive_io(83, true), techobjects::ExternalEncoderData{});
    F1 = &runtime.emplace<SynchronousAxis>(
        "F1", &drive_io(3, false), axis,
        std::vector<techobjects::LeadingValueInterconnection>{{L, L, LeadingValueCoupling::kSetpoint},
                                                              {E, E, LeadingValueCoupling::kActualValue}});
    F2 = &runtime.emplace<SynchronousAxis>(
        "F2", nullptr, tomc::testing::virtual_linear(),
        std::vector<techobjects::LeadingValueInterconnection>{{F1, F1, LeadingValueCoupling::kSetpoint},
                                                              {L, L, LeadingValueCoupling::kDelayed}});
    // Two cams on 0…36 mm: C a closed curve (cyclic), C2 rising by 20 per period (cyclic appending).
    C = &runtime.emplace<techobjects::Cam>("C");
    C2 = &runtime.emplace<techobjects::Cam>("C2");
    const techobjects::TO_Cam_Struct_PointData c[] = {{0, 0}, {9, 1}, {18, 0}, {27, -1}, {36, 0}};
    const techobjects::TO_Cam_Struct_PointData c2[] = {{0, 0}, {18, 5}, {36, 20}};
    for (std::size_t i = 0; i < std::size(c); ++i)
      (void)C->write_point(i + 1, c[i], true);
    for (std::size_t i = 0; i < std::size(c2); ++i)
      (void)C2->write_point(i + 1, c2[i], true);
    (void)C->write("InterpolationSettings.InterpolationMode", 1.0);
    (void)C->write("InterpolationSettings.BoundaryConditions", 1.0);
    runtime.set_user_program([this](techobjects::Runtime&) {
      power_L(*L);
      reset_L(*L);
      move_L(*L);
      power_E(*E);
      f1.call(*F1);
      f2.call(*F2);
    });
    runtime.start();
    (void)C->interpolate_cam();
    (void)C2->interpolate_cam();
  }
  techobjects::Runtime runtime;
  PositioningAxis* L = nullptr;
  ExternalEncoder* E = nullptr;
  SynchronousAxis* F1 = nullptr;
  SynchronousAxis* F2 = nullptr;
  drives::SimulatedDrive* encoder_drive = nullptr;
  techobjects::Cam* C = nullptr;
  techobjects::Cam* C2 = nullptr;
  instructions::MC_Power<PositioningAxis> power_L;
  instructions::MC_Reset<PositioningAxis> reset_L;
  instructions::MC_MoveVelocity<PositioningAxis> move_L;
  instructions::MC_Power<ExternalEncoder> power_E;
  FollowerProgram<SynchronousAxis> f1;
  FollowerProgram<SynchronousAxis> f2;
};

struct Step {
  std::string name;
  std::function<void(Machine&)> start;
  std::function<bool(Machine&, int)> finished;  // (machine, cycles since start)
  std::function<void(Machine&)> end;
  int max_cycles = 5000;
};

// A rising edge of Execute in this cycle: the instance sees FALSE once (its previous job may have ended in
// the same cycle the script set Execute again).
template <typename Fb, typename Axis>
void execute(Fb& fb, Axis& axis) {
  fb.Execute = false;
  fb(axis);
  fb.Execute = true;
}

// The leader L at velocity v (a new MC_MoveVelocity edge).
void leader_velocity(Machine& m, double v) {
  m.move_L.Execute = false;
  m.move_L(*m.L);
  m.move_L.Velocity = v;
  m.move_L.Acceleration = 2000.0;
  m.move_L.Deceleration = 2000.0;
  m.move_L.Execute = true;
}

std::vector<Step> script() {
  using M = Machine;
  const auto nothing = [](M&) {};
  std::vector<Step> s;
  s.push_back({"enable",
               [](M& m) {
                 m.power_L.Enable = m.power_E.Enable = m.f1.power.Enable = m.f2.power.Enable = true;
                 m.encoder_drive->set_external_speed(45.0);
               },
               [](M& m, int) {
                 return m.power_L.Status && m.power_E.Status && m.f1.power.Status && m.f2.power.Status;
               },
               nothing, 3000});
  s.push_back({"home followers",
               [](M& m) {
                 m.f1.home.Mode = m.f2.home.Mode = 0;
                 m.f1.home.Execute = m.f2.home.Execute = true;
               },
               [](M& m, int) { return m.f1.home.Done && m.f2.home.Done; },
               [](M& m) { m.f1.home.Execute = m.f2.home.Execute = false; }, 10});
  s.push_back({"leader at 50", [](M& m) { leader_velocity(m, 50.0); },
               [](M& m, int) { return m.move_L.InVelocity; }, nothing});
  // MC_GearIn on F1 (L, setpoint) and on F2 (F1): the chain.
  s.push_back({"gear in, chain",
               [](M& m) {
                 m.f1.gear.Master = m.L;
                 m.f1.gear.RatioNumerator = 2;
                 m.f1.gear.Acceleration = 2000.0;
                 execute(m.f1.gear, *m.F1);
                 m.f2.gear.Master = m.F1;
                 m.f2.gear.RatioNumerator = -1;
                 m.f2.gear.RatioDenominator = 2;
                 m.f2.gear.Acceleration = 2000.0;
                 execute(m.f2.gear, *m.F2);
               },
               [](M& m, int k) { return k > 300 && m.f1.gear.InGear && m.f2.gear.InGear; }, nothing});
  // A second MC_GearIn replaces the first (CommandAborted), then a leader switchover to E's actual value.
  s.push_back({"gear in replaced",
               [](M& m) {
                 m.f1.gear2.Master = m.L;
                 m.f1.gear2.RatioNumerator = 3;
                 m.f1.gear2.RatioDenominator = 2;
                 execute(m.f1.gear2, *m.F1);
               },
               [](M& m, int k) { return k > 100 && m.f1.gear2.InGear; },
               [](M& m) { m.f1.gear.Execute = false; }});
  s.push_back({"switch to the actual value of E",
               [](M& m) {
                 m.f1.gear.Master = m.E;
                 m.f1.gear.RatioNumerator = 1;
                 m.f1.gear.RatioDenominator = 1;
                 execute(m.f1.gear, *m.F1);
               },
               [](M& m, int k) { return k > 200 && m.f1.gear.InGear; },
               [](M& m) {
                 m.f1.gear2.Execute = false;
                 m.f1.gear.Execute = false;
               }});
  // A rejected job: illegal ratio (16#8017) on F2; its gearing continues.
  s.push_back({"rejected gear in",
               [](M& m) {
                 m.f2.gear2.Master = m.L;
                 m.f2.gear2.RatioNumerator = 0;
                 execute(m.f2.gear2, *m.F2);
               },
               [](M& m, int) { return m.f2.gear2.Error; },
               [](M& m) {
                 m.f2.gear2.Execute = false;
                 m.f2.gear2.RatioNumerator = 1;
               },
               10});
  // MC_GearInVelocity on F1 with ContinuousUpdate and ratio changes.
  s.push_back({"gear in velocity",
               [](M& m) {
                 auto& g = m.f1.gear_velocity;
                 g.Master = m.L;
                 g.RatioNumerator = 100;
                 g.RatioDenominator = 100;
                 g.ContinuousUpdate = true;
                 g.PositionControlled = true;
                 g.Acceleration = 2000.0;
                 execute(g, *m.F1);
               },
               [](M& m, int k) {
                 auto& g = m.f1.gear_velocity;
                 if (g.InSync && k % 50 == 0) g.RatioNumerator = 90 + (k / 50) % 20;
                 return k > 600 && g.InSync;
               },
               [](M& m) { m.f1.gear_velocity.Execute = false; }});
  // MC_GearInPos profiles 0, 1, 3 on F1 ahead of L.
  for (const std::int32_t profile : {1, 3, 0}) {
    s.push_back({"gear in pos profile " + std::to_string(profile),
                 [profile](M& m) {
                   auto& g = m.f1.gear_pos;
                   g.Master = m.L;
                   g.RatioNumerator = profile == 3 ? 1 : 2;
                   g.SyncProfileReference = profile;
                   g.MasterStartDistance = 20.0;
                   g.MasterSyncPosition = m.L->setpoint().position + 40.0;
                   g.SlaveSyncPosition = m.F1->setpoint().position + 80.0;
                   g.Velocity = 400.0;
                   g.Acceleration = 4000.0;
                   g.Deceleration = 4000.0;
                   g.Jerk = 0.0;
                   execute(g, *m.F1);
                 },
                 [](M& m, int k) { return k > 20 && m.f1.gear_pos.InSync; },
                 [](M& m) { m.f1.gear_pos.Execute = false; }});
  }
  // MC_GearOut profile 0 (dynamic parameters) and, after a new MC_GearIn, profile 1 (leader distance).
  s.push_back({"gear out profile 0",
               [](M& m) {
                 auto& o = m.f1.gear_out;
                 o.SyncProfileReference = 0;
                 o.SlavePosition = m.F1->setpoint().position + 50.0;
                 o.Deceleration = 2000.0;
                 execute(o, *m.F1);
               },
               [](M& m, int) { return m.f1.gear_out.Done; }, [](M& m) { m.f1.gear_out.Execute = false; }});
  s.push_back({"gear in again",
               [](M& m) {
                 m.f1.gear.Master = m.L;
                 m.f1.gear.RatioNumerator = 1;
                 execute(m.f1.gear, *m.F1);
               },
               [](M& m, int k) { return k > 50 && m.f1.gear.InGear; }, nothing});
  s.push_back({"phasing with dynamic parameters during gearing",
               [](M& m) {
                 auto& p = m.f1.phasing;
                 p.Master = m.L;
                 p.PhaseShift = 1.0;
                 p.ProfileReference = 0;
                 p.Velocity = 100.0;
                 p.Acceleration = p.Deceleration = 1000.0;
                 execute(p, *m.F1);
               },
               [](M& m, int) { return m.f1.phasing.Done; }, [](M& m) { m.f1.phasing.Execute = false; }});
  s.push_back({"gear out profile 1",
               [](M& m) {
                 auto& o = m.f1.gear_out;
                 o.SyncProfileReference = 1;
                 o.MasterStopDistance = 20.0;
                 o.SlavePosition = m.F1->setpoint().position + 30.0;
                 execute(o, *m.F1);
               },
               [](M& m, int) { return m.f1.gear_out.Done; },
               [](M& m) {
                 m.f1.gear_out.Execute = false;
                 m.f1.gear.Execute = false;
               }});
  // A pending MC_GearInPos far ahead, cancelled by MC_GearOut profile 5.
  s.push_back({"gear out cancels a pending gear in pos",
               [](M& m) {
                 auto& g = m.f1.gear_pos;
                 g.SyncProfileReference = 1;
                 g.MasterSyncPosition = m.L->setpoint().position + 1.0e5;
                 execute(g, *m.F1);
               },
               [](M& m, int k) {
                 if (k == 5) {
                   m.f1.gear_out.SyncProfileReference = 5;
                   execute(m.f1.gear_out, *m.F1);
                 }
                 return k > 5 && m.f1.gear_pos.CommandAborted && m.f1.gear_out.Done;
               },
               [](M& m) {
                 m.f1.gear_pos.Execute = false;
                 m.f1.gear_out.Execute = false;
               },
               50});
  // A GearOut without gearing is rejected (16#8077).
  s.push_back({"gear out without gearing",
               [](M& m) {
                 m.f1.gear_out.SyncProfileReference = 0;
                 execute(m.f1.gear_out, *m.F1);
               },
               [](M& m, int) { return m.f1.gear_out.Error; }, [](M& m) { m.f1.gear_out.Execute = false; },
               10});
  // MC_Halt and MC_Stop end a gearing.
  s.push_back({"gear in, halt",
               [](M& m) {
                 m.f1.gear.Master = m.L;
                 execute(m.f1.gear, *m.F1);
               },
               [](M& m, int k) {
                 if (k == 300) execute(m.f1.halt, *m.F1);
                 return k > 300 && m.f1.halt.Done && m.f1.gear.CommandAborted;
               },
               [](M& m) {
                 m.f1.halt.Execute = false;
                 m.f1.gear.Execute = false;
               }});
  s.push_back({"gear in, stop",
               [](M& m) {
                 m.f2.gear.Master = m.L;
                 execute(m.f2.gear, *m.F2);
               },
               [](M& m, int k) {
                 if (k == 200) execute(m.f2.stop, *m.F2);
                 return k > 200 && m.f2.stop.Done;
               },
               [](M& m) {
                 m.f2.stop.Execute = false;
                 m.f2.gear.Execute = false;
               }});
  // The leader reverses while F1 synchronizes: alarm 608 (stop with maximum dynamics), then MC_Reset.
  s.push_back({"reversal during synchronization",
               [](M& m) {
                 m.f1.gear.Master = m.L;
                 m.f1.gear.RatioNumerator = 4;
                 m.f1.gear.Acceleration = 100.0;  // long synchronization
                 execute(m.f1.gear, *m.F1);
               },
               [](M& m, int k) {
                 if (k == 50) leader_velocity(m, -50.0);
                 return m.F1->alarms().pending(techobjects::kAlarmSynchronizationError);
               },
               [](M& m) {
                 m.f1.gear.Execute = false;
                 m.f1.gear.Acceleration = 2000.0;
                 m.f1.gear.RatioNumerator = 1;
               },
               3000});
  s.push_back({"reset",
               [](M& m) {
                 execute(m.f1.reset, *m.F1);
                 leader_velocity(m, 50.0);
               },
               [](M& m, int k) { return k > 300 && m.f1.reset.Done && m.f1.power.Status; },
               [](M& m) { m.f1.reset.Execute = false; }});
  // Camming on F1 (L at 50 mm/s): direct and cyclic on C, switched at the end of C to C2 (appending), CamOut
  // profile 0; CamIn profile 1 on C2, CamOut profile 1.
  s.push_back({"cam in direct, cyclic",
               [](M& m) {
                 auto& c = m.f1.cam_in;
                 c.Master = m.L;
                 c.Cam = m.C;
                 c.SyncProfileReference = 2;
                 c.ApplicationMode = 1;
                 execute(c, *m.F1);
               },
               [](M& m, int k) { return k > 100 && m.f1.cam_in.InSync; }, nothing});
  s.push_back({"offset and additive during camming",
               [](M& m) {
                 auto& o = m.f1.offset;
                 o.Offset = 2.0;
                 o.OffsetDistance = 5.0;
                 m.f1.additive.Position = 0.5;
                 m.f1.additive.Enable = true;
                 execute(o, *m.F1);
               },
               [](M& m, int) { return m.f1.offset.Done; }, [](M& m) { m.f1.offset.Execute = false; }});
  s.push_back({"phasing over a distance during camming",
               [](M& m) {
                 auto& p = m.f1.phasing;
                 p.Master = m.L;
                 p.PhaseShift = 3.0;
                 p.ProfileReference = 1;
                 p.PhasingDistance = 5.0;
                 execute(p, *m.F1);
               },
               [](M& m, int) { return m.f1.phasing.Done; },
               [](M& m) {
                 m.f1.phasing.Execute = false;
                 // Removed during synchronous travel: the step back of the effective leading value is
                 // not a reversal there (it would cancel a phasing/offset over a distance, 16#808C).
                 m.f1.additive.Enable = false;
               }});
  s.push_back({"cam switch at the end of the cam",
               [](M& m) {
                 auto& c = m.f1.cam_in2;
                 c.Master = m.L;
                 c.Cam = m.C2;
                 c.SyncProfileReference = 5;
                 c.ApplicationMode = 2;
                 execute(c, *m.F1);
               },
               [](M& m, int) { return m.f1.cam_in2.InSync && m.f1.cam_in.CommandAborted; },
               [](M& m) { m.f1.cam_in.Execute = false; }, 3000});
  s.push_back({"cam out profile 0",
               [](M& m) {
                 auto& o = m.f1.cam_out;
                 o.SyncProfileReference = 0;
                 o.SlavePosition = m.F1->setpoint().position + 20.0;
                 o.Deceleration = 2000.0;
                 execute(o, *m.F1);
               },
               [](M& m, int) { return m.f1.cam_out.Done; },
               [](M& m) {
                 m.f1.cam_out.Execute = false;
                 m.f1.cam_in2.Execute = false;
               }});
  s.push_back({"cam in profile 1",
               [](M& m) {
                 auto& c = m.f1.cam_in;
                 c.Cam = m.C2;
                 c.SyncProfileReference = 1;
                 c.ApplicationMode = 2;
                 c.MasterOffset = m.L->setpoint().position + 40.0;
                 c.SlaveOffset = m.F1->setpoint().position;  // the cam where the follower stands
                 c.MasterStartDistance = 20.0;
                 execute(c, *m.F1);
               },
               [](M& m, int k) { return k > 20 && m.f1.cam_in.InSync; }, nothing});
  s.push_back({"cam out profile 1",
               [](M& m) {
                 auto& o = m.f1.cam_out;
                 o.SyncProfileReference = 1;
                 o.MasterStopDistance = 10.0;
                 o.SlavePosition = m.F1->setpoint().position + 30.0;
                 execute(o, *m.F1);
               },
               [](M& m, int) { return m.f1.cam_out.Done; },
               [](M& m) {
                 m.f1.cam_out.Execute = false;
                 m.f1.cam_in.Execute = false;
                 m.f1.cam_in.MasterOffset = 0.0;
                 m.f1.cam_in.SlaveOffset = 0.0;
               }});
  // F2 back on the chain for the next loop.
  s.push_back({"chain again",
               [](M& m) {
                 m.f2.gear.Master = m.F1;
                 execute(m.f2.gear, *m.F2);
               },
               [](M& m, int k) { return k > 10 && m.f2.gear.InGear; },
               [](M& m) { m.f2.gear.Execute = false; }});
  return s;
}

// ARCHITECTURE-GUIDE §7 (no allocation in the cyclic path), over the gearing jobs of spec 07 §2.
TEST(GearingAllocation, EveryGearingJobKindRunsWithoutAllocating) {
  Machine m;
  const std::vector<Step> steps = script();
  std::vector<long> timeouts(steps.size(), 0);
  std::array<bool, kReachedCount> last{};
  std::array<long, kReachedCount> count{};
  auto see = [&](Reached what, bool value) {
    if (value && !last[what]) ++count[what];
    last[what] = value;
  };
  std::size_t step = 0;
  int since = 0;
  bool started = false;
  long loops = 0;

  const auto before = tomc::testing::allocation_count();
  for (int cycle = 0; cycle < kCycles; ++cycle) {
    const Step& st = steps[step];
    if (!started) {
      st.start(m);
      started = true;
      since = 0;
    }
    m.runtime.step();
    ++since;
    const bool finished = st.finished(m, since);
    if (finished || since >= st.max_cycles) {
      if (!finished) ++timeouts[step];
      st.end(m);
      started = false;
      if (++step == steps.size()) {
        step = 0;
        ++loops;
      }
    }
    const auto& f1 = m.f1;
    see(kInGear, f1.gear.InGear || f1.gear2.InGear);
    see(kReplaced, f1.gear.CommandAborted);
    see(kActualValue, f1.gear.InGear && f1.gear.Master == m.E);
    see(kVelocityInSync, f1.gear_velocity.InSync);
    see(kPosProfile0, f1.gear_pos.InSync && f1.gear_pos.SyncProfileReference == 0);
    see(kPosProfile1, f1.gear_pos.InSync && f1.gear_pos.SyncProfileReference == 1);
    see(kPosProfile3, f1.gear_pos.InSync && f1.gear_pos.SyncProfileReference == 3);
    see(kGearOutDone, f1.gear_out.Done && f1.gear_out.SyncProfileReference != 5);
    see(kGearOutCancel, f1.gear_out.Done && f1.gear_out.SyncProfileReference == 5);
    see(kHaltDone, f1.halt.Done);
    see(kStopDone, m.f2.stop.Done);
    see(kRejected, m.f2.gear2.Error || f1.gear_out.Error);
    see(kAlarm608, m.F1->alarms().pending(techobjects::kAlarmSynchronizationError));
    see(kResetDone, f1.reset.Done);
    see(kChainInGear, m.f2.gear.InGear && m.f2.gear.Master == m.F1);
    see(kCamInSync, f1.cam_in.InSync && f1.cam_in.SyncProfileReference == 2);
    see(kCamSwitched, f1.cam_in2.InSync && f1.cam_in2.SyncProfileReference == 5);
    see(kCamProfile1, f1.cam_in.InSync && f1.cam_in.SyncProfileReference == 1);
    see(kCamOutDone, f1.cam_out.Done);
    see(kOffsetDone, f1.offset.Done);
    see(kPhasingDone, f1.phasing.Done);
    see(kAdditiveBusy, f1.additive.Busy);
  }
  const auto allocated = tomc::testing::allocation_count() - before;
  EXPECT_EQ(allocated, 0u) << "allocations in " << kCycles << " cycles";

  // The script reached what it is about, in at least two full loops.
  EXPECT_GE(loops, 2);
  for (int k = 0; k < kReachedCount; ++k)
    EXPECT_GE(count[static_cast<std::size_t>(k)], loops) << kReachedNames[k];
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (timeouts[k] != 0)
      ADD_FAILURE() << "step " << k << " '" << steps[k].name << "' timed out " << timeouts[k] << " times";
  }
  std::printf("%ld loops of %zu steps in %d cycles\n", loops, steps.size(), kCycles);
}

}  // namespace
