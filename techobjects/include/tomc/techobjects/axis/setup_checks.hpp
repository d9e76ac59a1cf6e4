#pragma once
// The checks every TO runs on its start values when it is created (set-up: throws std::invalid_argument
// "<TO name>.<variable path>: <problem>", never in the cycle): each configuration variable within the
// range and permitted values of its data-block table (spec 04), and position/velocity units that measure
// the same quantity and fit the motion type (spec 04 §3.11).
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tomc/techobjects/datablocks/variables.hpp"
#include "tomc/techobjects/motion/axis_units.hpp"
#include "tomc/techobjects/position/actual_value_chain.hpp"

namespace tomc::techobjects {

[[noreturn]] inline void fail_start_value(std::string_view to_name, std::string_view path,
                                          std::string_view problem) {
  throw std::invalid_argument(std::string(to_name) + "." + std::string(path) + ": " + std::string(problem));
}

template <typename Data>
void check_start_values(std::string_view to_name, std::span<const VariableInfo> table, const Data& data) {
  for (const auto& v : table) {
    if (v.role != VariableRole::kConfiguration) continue;
    const ValueError e = check_value(v, v.read(data));
    if (e != ValueError::kNone) fail_start_value(to_name, v.path, to_string(e));
  }
}

// `what` names the TO in the message ("axis", "encoder").
AxisUnitFactors checked_unit_factors(std::string_view to_name, std::uint32_t length_unit,
                                     std::uint32_t velocity_unit, std::int32_t motion_type,
                                     std::string_view what);

// The encoder mechanics every position-measuring TO reads from its Sensor (TO_Struct_Sensor of P/Y,
// TO_Struct_ExternalEncoder_Sensor of E): type, system, direction, the encoder parameters and the
// actual-velocity mode. The mounting, measuring gear and NIST source differ by TO and are the caller's.
template <typename Sensor>
EncoderMechanics sensor_encoder_mechanics(const Sensor& s) noexcept {
  EncoderMechanics m;
  m.Type = static_cast<EncoderType>(s.Type);
  m.System = static_cast<EncoderSystem>(s.System);
  m.InverseDirection = s.InverseDirection;
  const auto& p = s.Parameter;
  m.Parameter = EncoderParameter{p.Resolution,          p.StepsPerRevolution,      p.FineResolutionXist1,
                                 p.FineResolutionXist2, p.DeterminableRevolutions, p.DistancePerRevolution,
                                 p.BehaviorGx_XIST1,    p.ReferenceSpeed,          p.ReferenceVelocity};
  m.VelocityMode = static_cast<ActualVelocityMode>(s.ActualVelocityMode);
  return m;
}

}  // namespace tomc::techobjects
