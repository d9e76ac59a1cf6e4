#pragma once
// MC_Power (spec 03 §4.1, §3.3 L1/L2): enable-level instruction. Called once per user-program cycle.
#include <cstdint>

namespace tomc::instructions {

template <typename Axis>
struct MC_Power {
  // inputs
  bool Enable = false;
  std::int32_t StartMode = 1;
  std::int16_t StopMode = 0;
  // outputs
  bool Status = false;
  bool Busy = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    const auto s = axis.power(Enable, StartMode, StopMode);
    Status = s.Status;
    Busy = s.Busy;
    Error = s.Error;
    ErrorID = s.ErrorID;
  }
};

}  // namespace tomc::instructions
