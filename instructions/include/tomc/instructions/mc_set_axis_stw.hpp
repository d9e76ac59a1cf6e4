#pragma once
// MC_SetAxisSTW (spec 03 §4.14): write the user's bits of STW1 and STW2.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_SetAxisSTW {
  bool Execute = false;
  std::uint16_t STW1 = 0;
  std::uint16_t STW1BitMask = 0;
  std::uint16_t STW2 = 0;
  std::uint16_t STW2BitMask = 0;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute, [&] { return axis.set_axis_stw(STW1, STW1BitMask, STW2, STW2BitMask); },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
