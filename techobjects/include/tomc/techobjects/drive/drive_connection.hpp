#pragma once
// The PROFIdrive side of an axis technology object (spec 01 §3, §6; spec 06 §4, §5): decodes the actual
// frames of its device, follows the drive state machine with the STW1 sequence, runs both sign-of-life
// directions and the link supervision, and encodes the setpoint frames. The speed/positioning axes of later
// layers own one.

#include <cstdint>
#include <string>

#include "tomc/drives/drive_adapter.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/sign_of_life.hpp"

namespace tomc::techobjects {

struct DriveConnectionConfig {
  double reference_speed_rpm = 3000.0;  // <TO>.Actor.DriveParameter.ReferenceSpeed (= p2000)
  double reference_torque_nm = 4.0;     // <TO>.Actor.DriveParameter.ReferenceTorque (= p2003)
  // Isochronous operation: sign-of-life generated in STW2 and monitored in ZSW2 (spec 06 §5.1; seed L11468).
  bool isochronous = true;
  telegrams::SignOfLifeMonitorConfig sign_of_life{};
  // Cycles in a row without a fresh actual frame before the link counts as lost.
  std::uint32_t link_loss_tolerance_cycles = 3;
};

// Where an encoder's signals are (decision P3).
enum class EncoderSource : std::uint8_t {
  kDriveG1,     // G1 of the drive telegram (3, 4, 5, 6, 102, 103, 105, 106)
  kDriveG2,     // G2 of the drive telegram (4, 6, 103, 106) — Sensor[n].Interface.Number = 2
  kEncoderG1,   // G1 of the separate encoder telegram 81/83 (slot kEncoder1)
  kEncoder2G1,  // G1 of the second separate encoder telegram 81/83 (slot kEncoder2; decision B3)
};

// What one MC_Servo cycle commands of the drive (issue 14: one writer of the setpoint telegram). The TO's
// servo steps fill it; DriveConnection::write() encodes it together with what the connection owns itself
// (the STW1 sequence, both sign-of-life counters, the user's MC_SetAxisSTW bits).
struct ServoCommand {
  double speed_rpm = 0.0;    // NSOLL_A / NSOLL_B, motor speed [1/min]
  std::int32_t xerr = 0;     // DSC: position deviation XERR (telegrams 5, 6, 105, 106); 0 without DSC
  std::int32_t kpc = 0;      // DSC: position controller gain KPC
  std::uint16_t momred = 0;  // torque reduction MOMRED (telegrams 10x); 0 = none
  bool travel_to_fixed_stop = false;  // STW2.8, set while MC_TorqueLimiting is active (spec 01 §8.13)
  EncoderSource encoder = EncoderSource::kDriveG1;  // where the operative encoder's Gx_STW goes
  telegrams::EncoderControlWord encoder_control{};  // that Gx_STW
};

// Ti, To, T_DC of isochronous operation in seconds (spec 01 §3.5; MC_WriteParameter 1010/1011/1012): they
// enter the following error of position-controlled axes.
struct CommunicationTimes {
  double Ti = 0.0;
  double To = 0.0;
  double Tdc = 0.0;
};

// Why StatusDrive.CommunicationOK is FALSE (seed L11468), the first reason found.
enum class CommunicationFault : std::uint8_t {
  kNone,
  kLinkLost,          // no fresh actual frames within the tolerance
  kNotControlled,     // ZSW1.9 "control requested" = 0
  kDriveFault,        // ZSW1.3 fault present
  kSignOfLifeFailed,  // slave sign-of-life monitoring tripped (isochronous only)
};
std::string_view to_string(CommunicationFault fault) noexcept;

class DriveConnection {
 public:
  DriveConnection() = default;
  // `device` must stay alive as long as this connection (the runtime owns it).
  DriveConnection(DeviceIo& device, const DriveConnectionConfig& config);

  // TO restart (MC_Reset Restart): new reference values, the user's STW bits cleared (spec 03 §4.14); the
  // link itself (sign-of-life counters, sequencer) runs on undisturbed, as the drive's monitor expects.
  void restart(const DriveConnectionConfig& config) noexcept;

  // ---- MC_Servo ----
  void read() noexcept;                              // first, after the runtime read the actual frames
  void write(const ServoCommand& command) noexcept;  // last: this cycle's setpoints, encoded
  // Before write(): the Gx_STW of an encoder that is not the operative one (spec 01 §3.8: every used encoder
  // is evaluated, so each needs its own requests); write() sets the operative encoder's from the command.
  void set_encoder_control(EncoderSource source, telegrams::EncoderControlWord word) noexcept;
  // Telegram 750 (spec 06 §2.14, §8), before write(): additive torque and torque limits, N2 of the reference
  // torque. Kept in the setpoint signals themselves, not in ServoCommand, so that no axis carries a copy (the
  // positioning axis' memory budget); until the first call the limits are ±100 % (TV14).
  void set_torque_data(std::int16_t m_add1, std::int16_t m_limit_pos, std::int16_t m_limit_neg) noexcept {
    supplementary_sp_.M_ADD1 = m_add1;
    supplementary_sp_.M_LIMIT_POS = m_limit_pos;
    supplementary_sp_.M_LIMIT_NEG = m_limit_neg;
  }

  // A drive its axis keeps but does not use (Simulation.Mode = 1, decision B8), once per servo cycle instead
  // of read/write: the link runs on (both signs of life, frames read and written, so that the drive sees no
  // communication loss) while the drive is asked to stay off (OFF1: STW1.0 = 0) with zero setpoints — a
  // simulated axis "outputs no setpoint to the drive" (seed 004 §6.1.7).
  void keep_off() noexcept {
    read();
    request(telegrams::DriveRequest::kOff);
    write(ServoCommand{});
  }

  // ---- what the TO asks of the drive ----
  void request(telegrams::DriveRequest request) noexcept { request_ = request; }
  telegrams::DriveRequest requested() const noexcept { return request_; }
  void acknowledge() noexcept;  // one STW1.7 edge, and resets the sign-of-life supervision
  // MC_SetAxisSTW (spec 03 §4.14): the user's bits of STW1 (8, 9, 11..15) and STW2 (0..11) under their
  // masks, sent from the next write() on and kept until changed or a TO restart.
  void set_user_control_bits(std::uint16_t stw1, std::uint16_t stw1_mask, std::uint16_t stw2,
                             std::uint16_t stw2_mask) noexcept;
  double speed_setpoint() const noexcept { return speed_setpoint_rpm_; }  // the last commanded [1/min]
  // The setpoint signals as last written (diagnostics, tests).
  const telegrams::SetpointSignals& drive_setpoint() const noexcept { return drive_sp_; }
  const telegrams::SetpointSignals& supplementary_setpoint() const noexcept { return supplementary_sp_; }
  const telegrams::SetpointSignals& encoder_setpoint(int index) const noexcept {
    return encoder_sp_[index == 0 ? 0 : 1];
  }

  // ---- what the drive reports ----
  const telegrams::ActualSignals& drive_actual() const noexcept { return drive_act_; }
  const telegrams::ActualSignals& supplementary_actual() const noexcept { return supplementary_act_; }
  const telegrams::ActualSignals& encoder_actual(int index) const noexcept {
    return encoder_act_[index == 0 ? 0 : 1];
  }
  const telegrams::DriveStatus& drive_status() const noexcept { return status_; }
  // StatusDrive.InOperation: S4 (spec 06 §4.3 [UNCONFIRMED] -> ZSW1.2). Inline: read several times a cycle.
  bool in_operation() const noexcept {
    return communication_ok() && status_.state == telegrams::DriveState::kS4Operation;
  }
  bool communication_ok() const noexcept { return communication_fault_ == CommunicationFault::kNone; }
  CommunicationFault communication_fault() const noexcept { return communication_fault_; }
  double actual_speed_rpm() const noexcept { return actual_speed_rpm_; }
  telegrams::SignOfLifeStatus slave_sign_of_life() const noexcept { return slave_monitor_.status(); }
  std::uint8_t master_sign_of_life() const noexcept { return master_.current(); }
  std::uint32_t cycles_without_fresh_frame() const noexcept { return missed_; }
  const drives::DeviceConfig& device_config() const noexcept { return device_->adapter->config(); }
  const DriveConnectionConfig& config() const noexcept { return config_; }

 private:
  DeviceIo* device_ = nullptr;
  DriveConnectionConfig config_{};
  drives::DeviceCodecs codecs_;  // pointers to shared, immutable codecs (64 bytes for the four slots)

  telegrams::SetpointSignals drive_sp_{};
  telegrams::SetpointSignals supplementary_sp_{};
  std::array<telegrams::SetpointSignals, 2> encoder_sp_{};
  telegrams::ActualSignals drive_act_{};
  telegrams::ActualSignals supplementary_act_{};
  std::array<telegrams::ActualSignals, 2> encoder_act_{};

  // Wider members first, the one-byte ones together: no holes (decision M10).
  double speed_setpoint_rpm_ = 0.0;
  double actual_speed_rpm_ = 0.0;
  telegrams::SignOfLifeMonitor slave_monitor_{};
  std::uint32_t missed_ = 0;
  std::uint32_t peer_restarts_ = 0;  // LinkHealth::peer_restarts last seen
  telegrams::DriveRequest request_ = telegrams::DriveRequest::kOff;
  telegrams::Stw1Sequencer sequencer_{};
  telegrams::SignOfLifeGenerator master_{};
  telegrams::DriveStatus status_{};
  CommunicationFault communication_fault_ = CommunicationFault::kLinkLost;
  bool ever_fresh_ = false;
  bool has_nist_b_ = false;  // resolved once: the cycle does no layout look-ups
  bool has_zsw2_ = false;
  bool fixed_stop_sent_ = false;  // STW2.8 as the last command set it (the user may set it too)
  // Bit n: slot n carries a telegram in that direction (resolved once: the cycle codes only those; O4).
  std::uint8_t actual_slots_ = 0;
  std::uint8_t setpoint_slots_ = 0;
};

}  // namespace tomc::techobjects
