// The §9.19.1 cells (seed 004 §9.19.1, spec 03 §6.1) of MC_PositionProfile's and MotionIn's rows and columns
// as behaviour on the axis, not only as table data: each case starts a running job, submits a new one two
// cycles later, and checks what the manual's cell says happens to both.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "profile_motion_in_fixture.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"

namespace {

using namespace tomc;
using tomc::testing::ProfileMachine;
namespace eid = techobjects::error_id;

// What an instruction instance shows, for any of them.
struct Shown {
  bool busy = false;
  bool active = false;
  bool aborted = false;
  bool error = false;
};
template <typename FB>
Shown shown(const FB& fb) {
  Shown s{fb.Busy, fb.Busy, fb.CommandAborted, fb.Error};
  if constexpr (requires { fb.Active; }) s.active = fb.Active;
  return s;
}

enum class Expect { kAbort, kReject, kQueue, kBoth };

struct Case {
  std::string cell;  // row x column of §9.19.1
  std::function<void(ProfileMachine&)> start_running;
  std::function<Shown(const ProfileMachine&)> running;
  std::function<void(ProfileMachine&)> start_new;
  std::function<Shown(const ProfileMachine&)> fresh;
  Expect expect;
};

const techobjects::TimePositionProfile kProfile = tomc::testing::ramp_profile();

void profile(ProfileMachine& m, int buffer_mode) {
  m.profile.TimePosition = &kProfile;
  m.profile.BufferMode = buffer_mode;
  m.profile.Execute = true;
}
void profile2(ProfileMachine& m, int buffer_mode) {
  m.profile2.TimePosition = &kProfile;
  m.profile2.BufferMode = buffer_mode;
  m.profile2.Execute = true;
}
void move_velocity(ProfileMachine& m) {
  m.move_velocity.Velocity = 20.0;
  m.move_velocity.Execute = true;
}
void move_absolute(ProfileMachine& m) {
  m.move_absolute.Position = 500.0;
  m.move_absolute.Velocity = 50.0;
  m.move_absolute.Execute = true;
}
void motion_in(ProfileMachine& m) {
  m.motion_in_velocity.Velocity = 10.0;
  m.motion_in_velocity.Enable = true;
}
Shown p1(const ProfileMachine& m) {
  return shown(m.profile);
}
Shown p2(const ProfileMachine& m) {
  return shown(m.profile2);
}
Shown mv(const ProfileMachine& m) {
  return shown(m.move_velocity);
}
Shown ma(const ProfileMachine& m) {
  return shown(m.move_absolute);
}
Shown mr(const ProfileMachine& m) {
  return shown(m.move_relative);
}
Shown mi(const ProfileMachine& m) {
  return shown(m.motion_in_velocity);
}
Shown mip(const ProfileMachine& m) {
  return shown(m.motion_in_position);
}
Shown halt(const ProfileMachine& m) {
  return shown(m.halt);
}
// A running MC_Stop holds the axis while Execute stays TRUE, also once Done at standstill (spec 03 §8.2 T19).
Shown superimposed(const ProfileMachine& m) {
  return shown(m.move_superimposed);
}
Shown stop(const ProfileMachine& m) {
  Shown s = shown(m.stop);
  s.busy = s.active = m.stop.Busy || m.stop.Done;
  return s;
}

std::vector<Case> cases() {
  const auto start_halt = [](int mode) {
    return [mode](ProfileMachine& m) {
      m.halt.Mode = mode;
      m.halt.Execute = true;
    };
  };
  const auto start_stop = [](ProfileMachine& m) { m.stop.Execute = true; };
  const auto start_superimposed = [](ProfileMachine& m) {
    m.move_superimposed.Distance = 50.0;
    m.move_superimposed.VelocityDiff = 10.0;
    m.move_superimposed.Execute = true;
  };
  const auto relative_appended = [](ProfileMachine& m) {
    m.move_relative.Distance = 10.0;
    m.move_relative.BufferMode = 1;
    m.move_relative.Execute = true;
  };
  const auto moving_then_halt0 = [](ProfileMachine& m) {
    m.move_velocity.Velocity = 100.0;
    m.move_velocity.Execute = true;
    m.run(20);
    m.halt.Execute = true;
  };
  const auto absolute_with_pending = [](ProfileMachine& m) {
    move_absolute(m);
    m.run(2);
    m.move_relative.Distance = 10.0;
    m.move_relative.BufferMode = 1;
    m.move_relative.Execute = true;
  };
  const auto absolute_with_pending_profile = [](ProfileMachine& m) {
    move_absolute(m);
    m.run(2);
    profile(m, 1);
  };
  return {
      // MC_PositionProfile as the new job (rows R4 / R5)
      {"R4 PositionProfile BM0 x C3 MoveVelocity", move_velocity, mv, [](auto& m) { profile(m, 0); }, p1,
       Expect::kAbort},
      {"R5 PositionProfile BM1 x C3 MoveAbsolute (-)", move_absolute, ma, [](auto& m) { profile(m, 1); }, p1,
       Expect::kQueue},
      {"R5 PositionProfile BM1 x C3 MoveVelocity (N)", move_velocity, mv, [](auto& m) { profile(m, 1); }, p1,
       Expect::kReject},
      {"R5 PositionProfile BM1 x C4 pending MoveRelative", absolute_with_pending, mr,
       [](auto& m) { profile(m, 1); }, p1, Expect::kReject},
      {"R5 PositionProfile BM1 x C5 Halt Mode 0", moving_then_halt0, halt, [](auto& m) { profile(m, 1); }, p1,
       Expect::kReject},
      {"R4 PositionProfile BM0 x C6 MC_Stop", start_stop, stop, [](auto& m) { profile(m, 0); }, p1,
       Expect::kReject},
      {"R4 PositionProfile BM0 x C8 MotionIn", motion_in, mi, [](auto& m) { profile(m, 0); }, p1,
       Expect::kAbort},
      {"R5 PositionProfile BM1 x C8 MotionIn", motion_in, mi, [](auto& m) { profile(m, 1); }, p1,
       Expect::kReject},
      // MC_PositionProfile as the running job (columns C3 / C4)
      {"R4 PositionProfile BM0 x C3 PositionProfile", [](auto& m) { profile(m, 0); }, p1,
       [](auto& m) { profile2(m, 0); }, p2, Expect::kAbort},
      {"R5 PositionProfile BM1 x C3 PositionProfile (-)", [](auto& m) { profile(m, 0); }, p1,
       [](auto& m) { profile2(m, 1); }, p2, Expect::kQueue},
      {"R4 MoveAbsolute BM0 x C3 PositionProfile", [](auto& m) { profile(m, 0); }, p1, move_absolute, ma,
       Expect::kAbort},
      {"R5 MoveRelative BM1 x C3 PositionProfile (-)", [](auto& m) { profile(m, 0); }, p1, relative_appended,
       mr, Expect::kQueue},
      {"R3 Halt Mode 1 x C3 PositionProfile", [](auto& m) { profile(m, 0); }, p1, start_halt(1), halt,
       Expect::kAbort},
      {"R4 Halt Mode 0 x C3 PositionProfile", [](auto& m) { profile(m, 0); }, p1, start_halt(0), halt,
       Expect::kAbort},
      {"R4 MotionInVelocity x C3 PositionProfile", [](auto& m) { profile(m, 0); }, p1, motion_in, mi,
       Expect::kAbort},
      {"R7 MC_Stop x C3 PositionProfile", [](auto& m) { profile(m, 0); }, p1, start_stop, stop,
       Expect::kAbort},
      {"R4 MoveVelocity x C4 pending PositionProfile", absolute_with_pending_profile, p1, move_velocity, mv,
       Expect::kAbort},
      // MotionIn as the running job (column C8)
      {"R4 MoveVelocity x C8 MotionIn", motion_in, mi, move_velocity, mv, Expect::kAbort},
      {"R4 MoveAbsolute BM0 x C8 MotionIn", motion_in, mi, move_absolute, ma, Expect::kAbort},
      {"R5 MoveRelative BM1 x C8 MotionIn", motion_in, mi, relative_appended, mr, Expect::kReject},
      {"R3 Halt Mode 1 x C8 MotionIn", motion_in, mi, start_halt(1), halt, Expect::kAbort},
      {"R4 Halt Mode 0 x C8 MotionIn", motion_in, mi, start_halt(0), halt, Expect::kAbort},
      {"R7 MC_Stop x C8 MotionIn", motion_in, mi, start_stop, stop, Expect::kAbort},
      {"R4 MotionInPosition x C8 MotionInVelocity", motion_in, mi,
       [](auto& m) {
         m.motion_in_position.Position = m.db().Position;
         m.motion_in_position.Enable = true;
       },
       mip, Expect::kAbort},
      // With MC_MoveSuperimposed (R6 / C7)
      {"R6 MoveSuperimposed x C8 MotionIn (-)", motion_in, mi, start_superimposed, superimposed,
       Expect::kBoth},
      {"R6 MoveSuperimposed x C3 PositionProfile (-)", [](auto& m) { profile(m, 0); }, p1, start_superimposed,
       superimposed, Expect::kBoth},
      {"R4 MotionInVelocity x C7 MoveSuperimposed", start_superimposed, superimposed, motion_in, mi,
       Expect::kAbort},
      {"R4 PositionProfile BM0 x C7 MoveSuperimposed", start_superimposed, superimposed,
       [](auto& m) { profile(m, 0); }, p1, Expect::kAbort},
      // MotionIn as the new job against MC_Stop (R4 x C6)
      {"R4 MotionInVelocity x C6 MC_Stop", start_stop, stop, motion_in, mi, Expect::kReject},
  };
}

// spec 03 §6.1 (the §9.19.1 cells of MC_PositionProfile's and MotionIn's rows and columns).
TEST(ProfileMotionInPriority, MatrixCellsAsBehaviour) {
  for (const Case& c : cases()) {
    ProfileMachine m;
    ASSERT_GT(m.enable(), 0) << c.cell;
    ASSERT_TRUE(m.home_at(0.0)) << c.cell;
    c.start_running(m);
    m.run(2);
    ASSERT_TRUE(c.running(m).busy) << c.cell << ": the running job did not start";
    c.start_new(m);
    m.run(2);  // the new job's call, then every instance has shown the outcome once
    const Shown running = c.running(m);
    const Shown fresh = c.fresh(m);
    switch (c.expect) {
      case Expect::kAbort:
        EXPECT_TRUE(running.aborted) << c.cell;
        EXPECT_FALSE(running.busy) << c.cell;
        EXPECT_TRUE(fresh.busy && !fresh.error) << c.cell;
        break;
      case Expect::kReject:
        EXPECT_TRUE(running.busy && !running.aborted) << c.cell;
        EXPECT_TRUE(fresh.error) << c.cell;
        EXPECT_FALSE(fresh.busy) << c.cell;
        break;
      case Expect::kBoth:  // "-": both jobs go on
        EXPECT_TRUE(running.busy && !running.aborted && !running.error) << c.cell;
        EXPECT_TRUE(fresh.busy && !fresh.error) << c.cell;
        break;
      case Expect::kQueue:
        EXPECT_TRUE(running.busy && running.active && !running.aborted) << c.cell;
        EXPECT_TRUE(fresh.busy && !fresh.active && !fresh.error) << c.cell;
        break;
    }
  }
}

}  // namespace
