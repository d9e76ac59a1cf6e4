#pragma once
// MC_InterpolateCam (spec 07 §3.2): interpolates the cam's valid points and segments so that camming and the
// cam read instructions can use it. Completes within the call of the rising edge (decisions C2): Done, or
// Error with 16#80AA (empty), 16#80AB (in use), 16#80AC (no cam). Aborts nothing and is aborted by nothing.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace tomc::instructions {

struct MC_InterpolateCam {
  bool Execute = false;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;  // never set: no job aborts it (kept for show_outputs)
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(techobjects::Cam& cam) noexcept {
    handshake_.call(
        Execute, [&] { return cam.interpolate_cam(); },
        [&](techobjects::JobId id) { return cam.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
