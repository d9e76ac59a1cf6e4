#pragma once
// MC_TorqueAdditive (spec 03 §4.18.1): Enable-level instruction, called once per user-program cycle. Value is
// taken on every call while Enable is TRUE and sent as M_ADD1 of telegram 750; Enable FALSE sends zero.
#include <cstdint>

#include "tomc/techobjects/axis/torque_data.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_TorqueAdditive {
  // inputs
  bool Enable = false;
  double Value = 0.0;  // additional torque (linear motor: force), technology units
  // outputs
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    const techobjects::TorqueJobState s =
        axis.torque_additive(techobjects::TorqueAdditiveInputs{Enable, Value});
    Busy = s.Busy;
    Error = s.Error;
    ErrorID = s.ErrorID;
  }
};

}  // namespace tomc::instructions
