#pragma once
// MC_TorqueRange (spec 03 §4.18.2): Enable-level instruction, called once per user-program cycle. The limits
// are taken on every call while Enable is TRUE and sent as M_LIMIT_POS / M_LIMIT_NEG of telegram 750; with
// Enable FALSE the TO sends ±ReferenceTorque again. Rejected while MC_TorqueLimiting limits, and vice versa.
#include <cstdint>

#include "tomc/techobjects/axis/torque_data.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_TorqueRange {
  // inputs
  bool Enable = false;
  double UpperLimit = 1.0e12;  // must be above LowerLimit
  double LowerLimit = -1.0e12;
  // outputs
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    const techobjects::TorqueJobState s =
        axis.torque_range(techobjects::TorqueRangeInputs{Enable, UpperLimit, LowerLimit});
    Busy = s.Busy;
    Error = s.Error;
    ErrorID = s.ErrorID;
  }
};

}  // namespace tomc::instructions
