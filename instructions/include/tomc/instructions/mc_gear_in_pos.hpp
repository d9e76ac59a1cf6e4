#pragma once
// MC_GearInPos (spec 07 §2.2): gearing with synchronous positions: pending until the leader reaches the start
// of synchronization, StartSync during it, InSync from the synchronous positions on.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

template <typename Slave>
struct MC_GearInPos : SyncInOutputs {  // outputs: StartSync, InSync, Busy, CommandAborted, Error, ErrorID
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
    show_sync_in_outputs(*this, handshake_.outputs(), slave.sync_outputs(handshake_.job()));
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
