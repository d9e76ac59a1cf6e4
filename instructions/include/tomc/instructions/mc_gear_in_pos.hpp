#pragma once
// MC_GearInPos (spec 07 §2.2): gearing with synchronous positions: pending until the leader reaches the start
// of synchronization, StartSync during it, InSync from the synchronous positions on.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

template <typename Slave>
struct MC_GearInPos {
  const techobjects::LeadingValueSource* Master = nullptr;
  bool Execute = false;
  std::int32_t RatioNumerator = 1;
  std::int32_t RatioDenominator = 1;
  double MasterSyncPosition = 0.0;
  double SlaveSyncPosition = 0.0;
  std::int32_t SyncProfileReference = 1;
  double MasterStartDistance = 1.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t SyncDirection = 3;
  bool StartSync = false;
  bool InSync = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Slave& slave) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return slave.gear_in_pos(
              techobjects::GearInPosInputs{Master, RatioNumerator, RatioDenominator, MasterSyncPosition,
                                           SlaveSyncPosition, SyncProfileReference, MasterStartDistance,
                                           Velocity, Acceleration, Deceleration, Jerk, SyncDirection});
        },
        [&](techobjects::JobId id) { return slave.job_status(id); });
    const auto& o = handshake_.outputs();
    Busy = o.Busy;
    CommandAborted = o.CommandAborted;
    Error = o.Error;
    ErrorID = o.ErrorID;
    const auto s = slave.sync_outputs(handshake_.job());
    StartSync = Busy && s.StartSync && !s.InSync;
    InSync = Busy && s.InSync;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
