#pragma once
// MC_GearOut (spec 07 §2.4): desynchronize a gearing: pending until the start condition, StartSyncOut while
// the follower stops at SlavePosition, Done at standstill there. MC_CamOut (spec 07 §3.5) has the same
// parameters and behaviour for a camming: both are the one desynchronization instruction below.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

namespace detail {

template <typename Slave, bool kCamming>
struct SynchronousOut {
  bool Execute = false;
  double SlavePosition = 0.0;
  std::int32_t SyncProfileReference = 1;
  double MasterStopDistance = 0.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t SyncOutDirection = 3;
  bool StartSyncOut = false;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Slave& slave) noexcept {
    handshake_.call(
        Execute,
        [&] {
          const techobjects::GearOutInputs in{
              SlavePosition, SyncProfileReference, MasterStopDistance, Deceleration, Jerk, SyncOutDirection};
          if constexpr (kCamming) {
            return slave.cam_out(in);
          } else {
            return slave.gear_out(in);
          }
        },
        [&](techobjects::JobId id) { return slave.job_status(id); });
    show_outputs(*this, handshake_.outputs());
    StartSyncOut = Busy && slave.sync_outputs(handshake_.job()).StartSyncOut;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace detail

template <typename Slave>
struct MC_GearOut : detail::SynchronousOut<Slave, false> {};
template <typename Slave>
struct MC_CamOut : detail::SynchronousOut<Slave, true> {};

}  // namespace tomc::instructions
