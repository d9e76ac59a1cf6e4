#pragma once
// MC_GearInVelocity (spec 07 §2.3): velocity gearing v_follower = ratio · v_leader; with ContinuousUpdate the
// ratio inputs act at once while the job runs.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

template <typename Slave>
struct MC_GearInVelocity {
  const techobjects::LeadingValueSource* Master = nullptr;
  bool Execute = false;
  bool ContinuousUpdate = false;
  std::int32_t RatioNumerator = 1;
  std::int32_t RatioDenominator = 1;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool PositionControlled = false;
  bool StartSync = false;
  bool InSync = false;
  bool ContinuousUpdateActive = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Slave& slave) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return slave.gear_in_velocity(
              techobjects::GearInVelocityInputs{Master, RatioNumerator, RatioDenominator, ContinuousUpdate,
                                                Acceleration, Deceleration, Jerk, PositionControlled});
        },
        [&](techobjects::JobId id) { return slave.job_status(id); });
    const auto& o = handshake_.outputs();
    Busy = o.Busy;
    CommandAborted = o.CommandAborted;
    Error = o.Error;
    ErrorID = o.ErrorID;
    if (Busy && ContinuousUpdate) slave.update_ratio(handshake_.job(), RatioNumerator, RatioDenominator);
    const auto s = slave.sync_outputs(handshake_.job());
    StartSync = Busy && s.StartSync && !s.InSync;
    InSync = Busy && s.InSync;
    ContinuousUpdateActive = Busy && ContinuousUpdate && s.ContinuousUpdateActive;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
