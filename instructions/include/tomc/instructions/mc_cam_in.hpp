#pragma once
// MC_CamIn (spec 07 §3.4): start camming the follower (Slave) to a leading value (Master) through a cam,
// scaled and shifted, once or cyclically; pending until the start of synchronization (profiles 0, 1, 3, 4, 6)
// or the end of the running cam (profile 5), StartSync during it, InSync from the synchronous point on.
// EndOfProfile is TRUE for one call after each end of the cam passed. No Done: Busy until another job ends
// the camming, or a non-cyclic cam ends (then Busy and InSync FALSE, EndOfProfile TRUE as long as Done would
// be; spec 07 O-10, decision C11).
#include <algorithm>
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

template <typename Slave>
struct MC_CamIn : SyncInOutputs {  // outputs: StartSync, InSync, Busy, CommandAborted, Error, ErrorID
  const techobjects::LeadingValueSource* Master = nullptr;
  techobjects::Cam* Cam = nullptr;
  bool Execute = false;
  double MasterOffset = 0.0;
  double SlaveOffset = 0.0;
  double MasterScaling = 1.0;
  double SlaveScaling = 1.0;
  double MasterSyncPosition = 0.0;
  std::int32_t SyncProfileReference = 1;
  double MasterStartDistance = 0.0;
  double Velocity = -1.0;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  std::int32_t ApplicationMode = 0;
  std::int32_t SyncDirection = 3;
  bool EndOfProfile = false;

  void operator()(Slave& slave) noexcept {
    const techobjects::JobId before = handshake_.job();
    handshake_.call(
        Execute,
        [&] {
          return slave.cam_in(techobjects::CamInInputs{Master, Cam, MasterOffset, SlaveOffset, MasterScaling,
                                                       SlaveScaling, MasterSyncPosition, SyncProfileReference,
                                                       MasterStartDistance, Velocity, Acceleration,
                                                       Deceleration, Jerk, ApplicationMode, SyncDirection});
        },
        [&](techobjects::JobId id) { return slave.job_status(id); });
    const auto s = slave.sync_outputs(handshake_.job());
    show_sync_in_outputs(*this, handshake_.outputs(), s);
    if (handshake_.job() != before) ends_seen_ = 0;  // a new job counts its own cam ends
    // A new end passed, or the end of a non-cyclic cam that finished the job (held as Done would be).
    EndOfProfile = s.EndOfProfileCount > ends_seen_ || handshake_.outputs().Done;
    ends_seen_ = std::max(ends_seen_, s.EndOfProfileCount);
  }

 private:
  ExecuteHandshake handshake_;
  std::uint32_t ends_seen_ = 0;
};

}  // namespace tomc::instructions
