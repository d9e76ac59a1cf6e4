#pragma once
// Loading a technology object's configuration and its simulated drive from JSON, as `tomc sim` and an
// embedding program do (docs/scenarios.md "config", "drive"). Every problem is reported with its JSON path,
// and all of them are reported, not just the first: a commissioning engineer fixes a file in one go.
//
// Nothing here throws for bad input; problems are collected in a Problems list.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "tomc/drives/io/hardware_io.hpp"
#include "tomc/drives/simulated_drive.hpp"
#include "tomc/scenario/gateway_adapter.hpp"
#include "tomc/techobjects/cam/cam_data.hpp"
#include "tomc/techobjects/datablocks/external_encoder_data.hpp"
#include "tomc/techobjects/datablocks/positioning_axis_data.hpp"
#include "tomc/techobjects/datablocks/speed_axis_data.hpp"

namespace tomc::scenario {

// The loaders keep the key order of the file so that problems are listed in the order the user wrote them.
using Json = nlohmann::ordered_json;

// One line per problem: "<JSON path>: <what is wrong>".
class Problems {
 public:
  void add(std::string_view path, std::string_view message);
  bool empty() const noexcept { return lines_.empty(); }
  std::size_t size() const noexcept { return lines_.size(); }
  const std::vector<std::string>& lines() const noexcept { return lines_; }

 private:
  std::vector<std::string> lines_;
};

// Shortest text that reads back as the same double, with a plain exponent ("1e12", "0.001", "2.5e-05" ->
// "2.5e-5"): messages quote numbers the way a user types them.
std::string format_number(double value);

// "a.b" + "c" -> "a.b.c"; "a" + "[2]" -> "a[2]".
std::string join_path(std::string_view base, std::string_view key);

// The `config` object of a TO_SpeedAxis: keys are exact data-block paths of the reflection table
// (techobjects::speed_axis_variables(), e.g. "DynamicLimits.MaxVelocity"), values are start values. BOOL
// takes true/false, integers and bit strings take a JSON integer (bit strings also "16#7" or "0x7"), LREAL
// any number. Unknown paths, status variables, wrong types, values out of range or not permitted are problems
// at `path`.<key>. Variables not given keep the start value already in `data`.
void load_speed_axis_config(const Json& config, std::string_view path, techobjects::SpeedAxisData& data,
                            Problems& problems);
// The same for TO_PositioningAxis (positioning_axis_variables(): "Sensor[1].Parameter.StepsPerRevolution")
// and TO_ExternalEncoder. A TO_SynchronousAxis has the positioning axis' data block; `type_name` names the TO
// type in the messages.
void load_positioning_axis_config(const Json& config, std::string_view path,
                                  techobjects::PositioningAxisData& data, Problems& problems,
                                  std::string_view type_name = "TO_PositioningAxis");
void load_external_encoder_config(const Json& config, std::string_view path,
                                  techobjects::ExternalEncoderData& data, Problems& problems);
// The scalar variables of a cam (cam_variables(): "InterpolationSettings.InterpolationMode"); its points and
// segments are keys beside `config` (docs/scenarios.md "Cams").
void load_cam_config(const Json& config, std::string_view path, techobjects::CamData& data,
                     Problems& problems, std::string_view type_name = "TO_Cam");

// The `analog` object of a drive with "adapter": "analog" (docs/analog-drives.md): the actor's output
// scaling and the simulated servo amplifier. The enable output and the ready input are the TO's
// Actor.Interface.EnableDriveOutput / DriveReadyInput; the motor, load, encoder and machine keys are the
// simulated drive's.
// `"comedi"` in the `analog` object: the analog actor on a real DAQ card instead of the simulated amplifier
// (drives/comedi, built with -DTOMC_WITH_COMEDI=ON). Channels are (subdevice, channel) as comedi numbers
// them; the enable output and the ready input are wired when the TO's Actor.Interface says so.
struct ComediSettings {
  std::string device_file;  // "/dev/comedi0"
  drives::io::Channel analog_output{};
  std::optional<drives::io::Channel> enable_output;  // needed exactly when Actor.Interface.EnableDriveOutput
  std::optional<drives::io::Channel> ready_input;    // needed exactly when Actor.Interface.DriveReadyInput
  drives::io::Channel counter{};
  std::uint8_t counter_width_bits = 32;
};

struct AnalogSettings {
  double volts_at_reference = 10.0;  // U_100%
  double overdrive_percent = 117.0;
  double offset_volts = 0.0;
  drives::io::DacFormat dac{};
  double amplifier_rpm_per_volt = 0.0;  // 0: matched, reference_speed_rpm / volts_at_reference
  double amplifier_offset_volts = 0.0;  // the amplifier's drift
  double ready_delay_s = 0.02;
  std::optional<ComediSettings> comedi;  // set: a real card, not the simulated amplifier
};

// The `stepper` object of a drive with "adapter": "stepper" (docs/analog-drives.md): the PTO module and the
// simulated stepper driver and motor (decision A12). The enable output and the ready input are the TO's
// Actor.Interface.EnableDriveOutput / DriveReadyInput; gear, load, encoder 1 and machine keys are the
// simulated drive's.
struct StepperSettings {
  double steps_per_revolution = 1600.0;  // motor steps per revolution (full steps × microsteps)
  double max_frequency_hz = 200000.0;    // the PTO's output range
  bool encoder_feedback = false;         // "feedback": "pulses" (the PTO's pulse count) or "encoder"
  double pull_in_rate_hz = 2000.0;
  double pull_out_rate_hz = 40000.0;
  double max_acceleration_hz_per_s = 400000.0;
  double ready_delay_s = 0.02;
};

// The `drive` object: which adapter (the simulated drive, the analog actor on a simulated amplifier, the
// stepper actor on a simulated stepper motor, or a dds_gateway object), which telegram(s) and, for the
// simulated drive and amplifier, the machine model.
struct DriveSettings {
  std::string adapter = "simulated";
  std::uint16_t telegram = 0;                // a drive telegram (1..6, 102, 103, 105, 106)
  std::uint16_t supplementary_telegram = 0;  // 0 or 750
  std::uint16_t encoder_telegram = 0;        // 0, 81 or 83: a separately connected encoder (slot kEncoder1)
  drives::SimulatedDriveParameters parameters{};
  double external_speed = 0.0;  // encoder-only device: speed of the measured shaft (load units per second)
  // Set when `adapter` is a dds_gateway object: the drive is a real or simulated one behind a gateway, and
  // the simulated-drive parameters do not apply (gateway_adapter.hpp).
  std::optional<GatewayAdapterSettings> gateway;
  std::optional<AnalogSettings> analog;    // set when `adapter` is "analog"
  std::optional<StepperSettings> stepper;  // set when `adapter` is "stepper"
  drives::DeviceConfig device_config() const;
};

// Reads `drive` into `settings` (whose parameters are the defaults: a caller sets servo_cycle_s and the
// reference speed/torque of the TO first). Every SimulatedDriveParameters field is a key under its C++ name,
// encoder1/encoder2/machine are nested objects (docs/simulated-drive.md); `servo_cycle_s`, if given, must
// equal `cycle_time_s` because the drive runs in the MC_Servo cycle.
void load_drive(const Json& drive, std::string_view path, double cycle_time_s, DriveSettings& settings,
                Problems& problems);

}  // namespace tomc::scenario
