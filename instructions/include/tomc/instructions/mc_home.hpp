#pragma once
// MC_Home (spec 03 §4.3): home the technology object or set its reference. ReferenceMarkPosition is valid
// with Done.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/positioning_axis.hpp"

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
    show_outputs(*this, handshake_.outputs());
    if (Done) ReferenceMarkPosition = axis.reference_mark_position();
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
