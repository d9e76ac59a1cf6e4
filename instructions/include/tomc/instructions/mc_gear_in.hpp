#pragma once
// MC_GearIn (spec 07 §2.1): start gearing the follower (Slave) to a leading value (Master) with the ratio
// RatioNumerator/RatioDenominator; synchronizes with the given dynamics, then InGear. No Done: Busy until
// another job ends the gearing.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

namespace tomc::instructions {

template <typename Slave>
struct MC_GearIn {
  const techobjects::LeadingValueSource* Master = nullptr;
  bool Execute = false;
  std::int32_t RatioNumerator = 1;
  std::int32_t RatioDenominator = 1;
  double Acceleration = -1.0;
  double Deceleration = -1.0;
  double Jerk = -1.0;
  bool InGear = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Slave& slave) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return slave.gear_in(techobjects::GearInInputs{Master, RatioNumerator, RatioDenominator,
                                                         Acceleration, Deceleration, Jerk});
        },
        [&](techobjects::JobId id) { return slave.job_status(id); });
    const auto& o = handshake_.outputs();
    Busy = o.Busy;
    CommandAborted = o.CommandAborted;
    Error = o.Error;
    ErrorID = o.ErrorID;
    InGear = Busy && slave.sync_outputs(handshake_.job()).InSync;
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
