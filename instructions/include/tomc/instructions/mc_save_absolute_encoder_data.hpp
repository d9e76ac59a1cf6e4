#pragma once
// MC_SaveAbsoluteEncoderData (spec 03 §4.16, spec 02 §5.9): backs up the absolute-encoder adjustment of every
// TO with an absolute encoder. It has no Axis input: it works on the runtime's RetentiveStore, which writes
// the file off the real-time path; Done once the file is written, Error 16#810A if it could not be, 16#8109
// while an earlier backup is still being written.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"

namespace tomc::instructions {

template <typename Store>
struct MC_SaveAbsoluteEncoderData {
  bool Execute = false;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Store& store) noexcept {
    handshake_.call(
        Execute, [&] { return store.request_save(); },
        [&](techobjects::JobId id) { return store.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
