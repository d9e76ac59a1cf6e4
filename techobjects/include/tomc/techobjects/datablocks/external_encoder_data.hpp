#pragma once
// The technology data block of TO_ExternalEncoder (spec 04 §1 column E; man. §10.4). Conventions as in
// speed_axis_data.hpp and positioning_axis_data.hpp (which holds the enum values and unit codes E shares with
// P/Y). `Sensor` and `StatusSensor` are single structures here (man. §10.4.2, §10.4.13; spec 04 §14 item 9),
// not arrays. Differences to the positioning axis, as printed in man. §10.4 (spec 04 §14 item 9):
// TO_Struct_ExternalEncoder_Sensor has no Existent, Backlash, ActiveHoming or MeasuringGear;
// Sensor.Parameter.Resolution is printed -1.0E12 ... 1.0E12; PassiveHoming.SwitchLevel is RON;
// ErrorDetail.Reaction is 0 or 10.
//
// Default encoder (all "chosen"): a rotary leading-value encoder on a rotating shaft, positions in degrees
// counted modulo 360°, measured by an encoder like the simulated one (2048 steps/rev, fine resolution 11/9,
// 32-bit Gx_XIST1) and evaluated as an incremental encoder (the same reasons as for the positioning axis,
// positioning_axis_data.hpp). tomc's encoder-only device measures a shaft turned by set_external_speed()
// (docs/simulated-drive.md), which matches a load-side mounting.
//
// Left out on purpose: `InternalToTrace` (spec 04 §4.11, man. §10.4.19: "no data relevant for the user").

#include <array>
#include <cstdint>

#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/to_types.hpp"

namespace tomc::techobjects {

// ErrorDetail.Reaction of the external encoder (DINT): 0 or 10, as printed (man. §10.4.17; spec 04 §14 item
// 7).
enum class ExternalEncoderReaction : std::int32_t { kNone = 0, kRemoveEnable = 10 };

struct ExternalEncoderData {
  static constexpr TechnologyObjectType kTechnologyObjectType = TechnologyObjectType::kExternalEncoder;

  // ---- §2 actual values (man. §10.4.1), all RON ----
  double ActualPosition = 0.0;
  double ActualVelocity = 0.0;
  double ActualAcceleration = 0.0;
  std::int32_t ActualModuloCycle = 0;

  // ---- §3.6 Sensor (man. §10.4.2): TO_Struct_ExternalEncoder_Sensor ----
  struct TO_Struct_ExternalEncoder_Sensor {
    // RON; chosen: 0 = INCREMENTAL (see the header comment of positioning_axis_data.hpp)
    std::int32_t Type = static_cast<std::int32_t>(SensorEncoderType::INCREMENTAL);
    bool InverseDirection = false;  // RES; chosen: FALSE
    // RES; chosen: 1 = ROTATORY (a rotary encoder)
    std::int32_t System = static_cast<std::int32_t>(SensorMeasuringSystem::ROTATORY);
    // RES; chosen: 1 = load side (the encoder sits on the measured shaft)
    std::int32_t MountingMode = static_cast<std::int32_t>(SensorMountingMode::kLoadSide);
    // RES; chosen: 0 = manual (the simulated device has no parameter channel)
    std::int32_t DataAdaption = static_cast<std::int32_t>(DataAdaptionMode::kManual);
    // RES; chosen: 0 = differentiate the position (high-resolution encoder)
    std::int32_t ActualVelocityMode =
        static_cast<std::int32_t>(SensorActualVelocityMode::kDifferentiatePosition);

    TO_Struct_SensorInterface Interface;

    TO_Struct_SensorParameter Parameter{.DistancePerRevolution = 360.0};

    TO_Struct_SensorPassiveHoming PassiveHoming;
  } Sensor;

  // ---- §3.7 CrossPlcSynchronousOperation (man. §10.4.3) ----
  TO_Struct_CrossPlcSynchronousOperation CrossPlcSynchronousOperation;

  // ---- §3.8 Extrapolation (man. §10.4.4); chosen as for the positioning axis ----
  TO_Struct_Extrapolation Extrapolation;

  // ---- §3.9 LoadGear (man. §10.4.5) ----
  TO_Struct_LoadGear LoadGear;

  // ---- §3.10 Properties (man. §10.4.6) ----
  // External-encoder default (chosen): 1 = rotary, a leading-value encoder on a rotating shaft.
  TO_Struct_Properties Properties{.MotionType = static_cast<std::int32_t>(PropertiesMotionType::kRotary)};

  // ---- §3.11 Units (man. §10.4.7): TO_Struct_ExternalEncoder_Units, all RON ----
  struct TO_Struct_ExternalEncoder_Units {
    std::uint32_t LengthUnit = unit_code::kDegree;             // chosen: ° (rotary)
    std::uint32_t VelocityUnit = unit_code::kDegreePerSecond;  // chosen: °/s
    std::uint32_t TimeUnit = unit_code::kSecond;               // the only code: s
  } Units;

  // ---- §3.12 Mechanics (man. §10.4.8) ----
  TO_Struct_Mechanics Mechanics;

  // ---- §3.13 Modulo (man. §10.4.9) ----
  // External-encoder default (chosen): TRUE, a leading value of a rotating shaft repeats every turn.
  TO_Struct_Modulo Modulo{.Enable = true};

  // ---- §3.18 Homing (man. §10.4.10): TO_Struct_ExternalEncoder_Homing ----
  struct TO_Struct_ExternalEncoder_Homing {
    double HomePosition = 0.0;  // CAL; chosen: 0
  } Homing;

  // ---- §3.26 StandstillSignal (man. §10.4.11) ----
  TO_Struct_StandstillSignal StandstillSignal;

  // ---- §4.4 StatusProvidedLeadingValue (man. §10.4.12), RON ----
  TO_Struct_StatusProvidedLeadingValue StatusProvidedLeadingValue;

  // ---- §4.5 StatusSensor (man. §10.4.13): a single TO_Struct_StatusSensor, RON ----
  TO_Struct_StatusSensor StatusSensor;

  // ---- §4.6 StatusExtrapolation (man. §10.4.14), RON ----
  TO_Struct_StatusExtrapolation StatusExtrapolation;

  // ---- §5 bit words (man. §10.4.15, §10.4.16, §10.4.18), RON; no StatusWord2 on E ----
  std::uint32_t StatusWord = 0;
  std::uint32_t ErrorWord = 0;

  // ---- §4.10 ErrorDetail (man. §10.4.17), RON ----
  TO_Struct_ErrorDetail ErrorDetail;

  std::uint32_t WarningWord = 0;
};

}  // namespace tomc::techobjects
