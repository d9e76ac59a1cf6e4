#pragma once
// MC_Reset (spec 03 §4.2): acknowledge technology alarms; Restart = TRUE re-initialises the TO.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_Reset {
  bool Execute = false;
  bool Restart = false;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute, [&] { return axis.reset(Restart); },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
