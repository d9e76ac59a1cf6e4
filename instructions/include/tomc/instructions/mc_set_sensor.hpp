#pragma once
// MC_SetSensor (spec 03 §4.12, S7-1500T): makes another configured encoder the operative one (Mode 0 with,
// Mode 1 without taking over the actual position) or gives an encoder the axis' (Mode 2) or a reference
// encoder's (Mode 3) actual position without switching. Done at once; no other job aborts it and it aborts
// none.
#include <cstdint>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/positioning_axis/positioning_axis.hpp"

namespace tomc::instructions {

template <typename Axis>
struct MC_SetSensor {
  bool Execute = false;
  std::int16_t Sensor = 1;  // INT (spec 03 AMB-26)
  std::int32_t Mode = 0;
  std::int16_t ReferenceSensor = 1;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(Axis& axis) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return axis.set_sensor(techobjects::SetSensorInputs{Sensor, Mode, ReferenceSensor});
        },
        [&](techobjects::JobId id) { return axis.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
