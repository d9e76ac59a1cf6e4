// An out-of-tree C++ program against the installed package (find_package(tomc COMPONENTS core)): a
// positioning axis on the simulated drive, MC_Power, MC_Home (set position 0), MC_MoveAbsolute to 100 mm in
// the user program; exits 0 only if the move is Done at 100 mm.
#include <cmath>
#include <cstdio>
#include <memory>

#include "tomc/drives/dds/contract.hpp"  // tomc::dds: the gateway contract (with the generated IDL types)
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/instructions/mc_home.hpp"
#include "tomc/instructions/mc_move_absolute.hpp"
#include "tomc/instructions/mc_power.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

using namespace tomc;

int main() {
  techobjects::Runtime runtime(techobjects::RuntimeConfig{0.001, 1, 1});
  drives::DeviceConfig device;
  device.drive_telegram = 3;
  drives::SimulatedDriveParameters drive;
  drive.load_units_per_revolution = 10.0;  // the default axis: 10 mm leadscrew, no gear
  auto& io = runtime.add_device(std::make_unique<drives::SimulatedDrive>(device, drive));
  techobjects::PositioningAxisData data;
  data.DynamicLimits.MaxJerk = 0.0;
  auto& axis = runtime.emplace<techobjects::PositioningAxis>("Slide", &io, data);

  instructions::MC_Power<techobjects::PositioningAxis> power;
  instructions::MC_Home<techobjects::PositioningAxis> home;
  instructions::MC_MoveAbsolute<techobjects::PositioningAxis> move;
  power.Enable = true;
  move.Position = 100.0;
  runtime.set_user_program([&](techobjects::Runtime&) {
    power(axis);
    home.Execute = power.Status;
    home(axis);
    move.Execute = home.Done;
    move(axis);
  });
  runtime.start();
  int cycle = 0;
  for (; cycle < 10000 && !move.Done && !move.Error; ++cycle)
    runtime.step();
  const auto& db = axis.data();
  std::printf("cycle %d, Done %d, Error %d (16#%04X), Position %.4f mm, ActualPosition %.4f mm\n", cycle,
              move.Done ? 1 : 0, move.Error ? 1 : 0, move.ErrorID, db.Position, db.ActualPosition);
  return move.Done && std::abs(db.Position - 100.0) < 1e-6 && std::abs(db.ActualPosition - 100.0) < 0.01 ? 0
                                                                                                         : 1;
}
