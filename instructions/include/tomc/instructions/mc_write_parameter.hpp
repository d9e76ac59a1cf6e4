#pragma once
// MC_WriteParameter (spec 03 §4.15): write a parameter by number; Value is the source value (LREAL/WORD).
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_WriteParameter {
  bool Execute = false;
  std::int32_t ParameterNumber = 0;
  double Value = 0.0;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute, [&] { return axis.write_parameter(ParameterNumber, Value); },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
