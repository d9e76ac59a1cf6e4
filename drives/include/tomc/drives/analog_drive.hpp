#pragma once
// The analog drive actor (spec 01 §3.12, seed 004 §6.2.7/§6.5.1): a ±10 V speed setpoint on an analog
// output, an optional enable output and ready input, and an incremental encoder on a counter, all through the
// hardware I/O layer. Towards the technology object it is a drive on telegram 3 (telegram3_actor.hpp),
// exactly as the S7 puts its analog actor behind a telegram-3-like interface: no TO code knows which actor is
// behind the drive connection. docs/analog-drives.md describes every rule.

#include <cstdint>

#include "tomc/drives/telegram3_actor.hpp"

namespace tomc::drives {

struct AnalogDriveParameters : ActorParameters {
  double volts_at_reference = 10.0;  // U_100%
  double overdrive_percent = 117.0;  // |output| <= this % of U_100% (spec 01 §3.12 "≈ ±117 %")
  double offset_volts = 0.0;         // added to the output while the axis is enabled (TarOffs)
  io::DacFormat dac{};
  io::Channel analog_output{0, 0};  // <TO>.Actor.Interface.AddressOut
  // TarOffs (decision A15): standstill this long before measuring, then the mean output over measure_s.
  double calibration_settle_s = 0.1;
  double calibration_measure_s = 0.5;
};

// The outputs of the offset auto-calibration (seed 000 TarOffs, spec 05a §3.1), under the legacy names.
struct OffsetCalibration {
  bool EndTr = false;       // the calibration finished (with En still TRUE)
  std::int32_t ValOf = 0;   // the offset in use, in DAC codes (0 = none)
  std::uint32_t Error = 0;  // 11 or 90 (below); the offset in use stays
};
inline constexpr std::uint32_t kErrorOffsetExcessive = 11;  // seed 000 appendix 1: offset > 1 % of the DAC
// No encoder connected, or it failed during the calibration: seed 000 "ends at once" (spec 05a §3.1); the
// seed gives no number, 90 is tomc's (outside the seed's 1…84, decision A16).
inline constexpr std::uint32_t kErrorCalibrationNoEncoder = 90;

class AnalogDrive final : public Telegram3Actor {
 public:
  // `hardware` must outlive the actor. Telegram 3 facing the TO.
  AnalogDrive(io::HardwareIo& hardware, const AnalogDriveParameters& parameters);

  // Analog offset auto-calibration result (TarOffs): added to the output from the next cycle.
  void set_offset_volts(double volts) noexcept { p_.offset_volts = volts; }
  // TarOffs as an actor function, its inputs each cycle: `enable` (En) starts a calibration on its rising
  // edge (or, with `reset` TRUE, clears the offset); FALSE ends it and clears EndTr. The axis must stand
  // still in operation: EndTr stays FALSE until it does (spec 05a §3.1).
  void offset_calibration(bool enable, bool reset) noexcept;
  const OffsetCalibration& offset_calibration_status() const noexcept { return calibration_; }

  // ---- observation (diagnostics, tests) ----
  double output_volts() const noexcept { return output_volts_; }  // commanded, before quantisation
  std::int32_t output_code() const noexcept { return output_code_; }
  const AnalogDriveParameters& parameters() const noexcept { return p_; }

 private:
  void set_speed_output(bool enabled, double speed) noexcept override;

  void calibrate(bool enabled, double speed) noexcept;
  void finish_calibration(std::uint32_t error) noexcept;

  AnalogDriveParameters p_;
  double output_volts_ = 0.0;
  std::int32_t output_code_ = 0;

  enum class Calibration : std::uint8_t { kIdle, kWaitingForStandstill, kMeasuring, kFinished };
  Calibration calibration_state_ = Calibration::kIdle;
  bool calibration_enable_ = false;
  std::uint32_t calibration_cycles_ = 0;
  double calibration_sum_volts_ = 0.0;
  OffsetCalibration calibration_{};
};

}  // namespace tomc::drives
