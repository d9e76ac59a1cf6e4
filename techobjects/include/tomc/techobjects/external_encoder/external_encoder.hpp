#pragma once
// TO_ExternalEncoder (spec 01 §1.1, §2.2, §5.3; spec 02 §5; spec 04 column E): acquires a position from an
// encoder telegram (81 or 83, spec 01 §3.3) and makes it available in user units — as a leading value, for
// measuring and cams. Mechanics (load gear, leadscrew, direction), modulo with its cycle counter, standstill
// signal, homing, MC_Power/MC_Reset/MC_WriteParameter (decision E1: MC_Power is accepted, spec 03 [AMB-1]).
//
// Cycle: MC_Servo reads the encoder and computes the actual values; MC_Interpolator takes MC_Reset and the
// enable, and updates the status. noexcept, no allocation.

#include <cstdint>
#include <string>
#include <string_view>

#include "tomc/techobjects/axis/alarms.hpp"
#include "tomc/techobjects/axis/axis_core.hpp"
#include "tomc/techobjects/axis/data_block_object.hpp"
#include "tomc/techobjects/axis/job.hpp"
#include "tomc/techobjects/axis/job_inputs.hpp"
#include "tomc/techobjects/axis/job_table.hpp"
#include "tomc/techobjects/axis/memory_footprint.hpp"
#include "tomc/techobjects/datablocks/external_encoder_data.hpp"
#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/drive/encoder_channel.hpp"
#include "tomc/techobjects/motion/axis_units.hpp"
#include "tomc/techobjects/position/passive_homing.hpp"
#include "tomc/techobjects/position/position_monitoring.hpp"
#include "tomc/techobjects/runtime/retained_encoder_data.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/techobjects/synchronous/actual_value_extrapolation.hpp"
#include "tomc/techobjects/synchronous/leading_value.hpp"

namespace tomc::techobjects {

class ExternalEncoder final : public DataBlockObject<ExternalEncoderData>, public LeadingValueSource {
 public:
  // `device` carries encoder telegram 81 or 83 (an encoder-only device, drive_telegram 0). Throws
  // std::invalid_argument for start values the data block does not permit or a device without it.
  ExternalEncoder(std::string name, DeviceIo* device, const ExternalEncoderData& start_values,
                  const DriveConnectionConfig& connection = {});

  // ---- TechnologyObject ----
  void servo(const CycleClock& clock) noexcept override;
  void interpolate(const CycleClock& clock) noexcept override;

  // The object plus the heap it owns (start values only until the runtime adopted them), in bytes.
  std::size_t memory_footprint() const noexcept { return sizeof(*this) + shared_heap_bytes(); }

  // ---- the data block (data_block_object.hpp), its encoder connection and digital inputs ----
  const DriveConnection& connection() const noexcept { return drive_; }
  // The homing digital input (AxisDigitalInputs::HomingInput), written before MC_Servo.
  AxisDigitalInputs& digital_inputs() noexcept { return inputs_; }

  // ---- jobs ----
  // MC_Power: Status once the encoder delivers valid values; StartMode/StopMode are ignored (spec 03 §4.1).
  PowerState power(bool enable, std::int32_t start_mode, std::int32_t stop_mode) noexcept;
  Submission reset(bool restart) noexcept;
  Submission home(const HomeInputs& in) noexcept;
  // 1010/1011/1012 communication times, effective after restart (spec 03 §4.15).
  Submission write_parameter(std::int32_t parameter_number, double value) noexcept;
  double reference_mark_position() const noexcept { return reference_mark_position_; }

  // Retentive data of an absolute encoder, as on the positioning axis (positioning_axis.hpp).
  const RetainedEncoderData& retained() const noexcept { return retained_; }
  bool absolute_encoder() const noexcept;
  void restore_retained(const RetainedEncoderData& data) noexcept;
  void report_adjustment_lost(std::uint32_t cause) noexcept;

  // As a leading value (spec 07 §1.4): the extrapolated actual value, whatever the coupling type says.
  LeadingValue leading_value(LeadingValueCoupling coupling) const noexcept override;
  ModuloRange leading_value_modulo() const noexcept override {
    return ModuloRange{db_.Modulo.Enable, db_.Modulo.StartValue, db_.Modulo.Length};
  }

  // Continuous actual position (before the modulo wrap) and velocity, position units.
  double continuous_position() const noexcept { return encoder_.chain().continuous_position(); }
  double velocity() const noexcept { return velocity_; }
  bool valid() const noexcept { return valid_; }

 private:
  using JobKind = AxisJobKind;

  void configure() noexcept;
  void written(std::string_view path) noexcept override;
  void configure_extrapolation() noexcept;
  void update_status() noexcept;
  void assign_reference(double mark_position, double value, ModuloCycleRule rule) noexcept;
  void store_adjustment() noexcept;

  AxisUnitFactors units_{};
  AxisMechanics mechanics_{};
  EncoderMechanics encoder_mechanics_{};
  EncoderSource source_ = EncoderSource::kEncoderG1;
  EncoderChannel encoder_;
  StandstillSignal standstill_;
  double servo_cycle_s_ = 0.001;
  bool servo_cycle_known_ = false;
  bool enable_ = false;
  bool enabled_ = false;
  bool valid_ = false;
  bool homed_ = false;
  bool error_seen_ = false;
  double velocity_ = 0.0;
  double last_velocity_ = 0.0;
  double reference_mark_position_ = 0.0;
  AxisDigitalInputs inputs_{};
  InputEdges input_edges_{};
  PassiveHomingSearch passive_search_{};
  JobId passive_job_ = 0;
  double passive_value_ = 0.0;
  std::optional<double> mark_position_;
  RetainedEncoderData retained_{};
  bool retained_restored_ = false;
  bool power_up_done_ = false;
  ActualValueExtrapolation extrapolation_{};
  double ipo_cycle_s_ = 0.0;  // 0 until the first MC_Interpolator configures the extrapolation
};

}  // namespace tomc::techobjects
