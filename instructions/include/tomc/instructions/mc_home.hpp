#pragma once
// MC_Home (spec 03 §4.3): home the technology object or set its reference. ReferenceMarkPosition is valid
// with Done (seed 004 §9.3.1 "valido se Done = TRUE") and belongs to this instance's job: it is taken once,
// in the call that first shows Done, so a later homing by another instance does not change it.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_Home {
  bool Execute = false;
  double Position = 0.0;
  std::int16_t Mode = 0;
  std::int32_t Sensor = 0;
  double ReferenceMarkPosition = 0.0;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return axis.home(techobjects::HomeInputs{Position, Mode, Sensor});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    const bool was_done = Done;
    show_outputs(*this, handshake_.outputs());
    // The job completed in the last MC_Interpolator; no other homing job can have completed since (one
    // homing job aborts another, and a new one starts in the next MC_Interpolator at the earliest).
    if (Done && !was_done) ReferenceMarkPosition = axis.reference_mark_position();
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
