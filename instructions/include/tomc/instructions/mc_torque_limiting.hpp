#pragma once
// MC_TorqueLimiting (spec 03 §4.18.3): Enable-level instruction, called once per user-program cycle. Limit
// and Mode are taken on every call while Enable is TRUE; no Done and no CommandAborted (spec 03 L3).
#include <cstdint>

#include "tomc/techobjects/axis/torque_limiting.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_TorqueLimiting {
  // inputs
  bool Enable = false;
  double Limit = -1.0;    // >= 0: this torque/force; < 0: TorqueLimiting.LimitDefaults
  std::int32_t Mode = 0;  // 0 force/torque limiting, 1 fixed-stop detection
  // outputs
  bool InClamping = false;
  bool InLimitation = false;
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    const techobjects::TorqueLimitingState s =
        axis.torque_limiting(techobjects::TorqueLimitingInputs{Enable, Limit, Mode});
    InClamping = s.InClamping;
    InLimitation = s.InLimitation;
    Busy = s.Busy;
    Error = s.Error;
    ErrorID = s.ErrorID;
  }
};

}  // namespace tomc::instructions
