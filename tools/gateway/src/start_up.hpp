#pragma once
// Internal: the start-up of one AR over the sockets (IEC 61158-6-10 order): DCP Identify by name of station
// (and Set of the IP suite when the device has another one), Connect, the start-up record writes, PrmEnd,
// the device's ApplicationReady answered; the device's alarms from the Connect on are acknowledged while it
// waits. Blocking with bounded waits; runs on the start-up thread, never on the cyclic one.

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/parameter_write.hpp"
#include "tomc/profinet/sockets.hpp"

namespace tomc::profinet_gateway::detail {

// A parameter of the file's "parameters" (decision I33): changed through the parameter access point of the
// object in `slot`.
struct SlotParameterWrite {
  std::uint16_t slot = 1;
  profinet::ParameterWrite write;
};

// The PROFIdrive parameter access after ApplicationReady (decisions I16, I33): the telegram check on the
// object in `slot`, then the file's parameter writes, in order.
struct ParameterSteps {
  std::uint16_t slot = 1;
  bool check_telegram = true;
  std::uint16_t telegram = 0;     // p0922 must be this
  float reference_speed_rpm = 0;  // p2000 (out): read with p0922 before the writes; a written p2000 replaces it
  std::vector<SlotParameterWrite> writes;
};

// "" when the AR runs; otherwise one line saying which step failed ("no DCP answer to Identify
// 'drive-1'", "Connect refused, PNIOStatus 0xDB814004", "p0922 is 105: the drive sends telegram 105, the file
// says 3", "p2000 = 250000: the drive refused the change, PROFIdrive error 0x02 (low or high limit
// exceeded)", describe_alarm_timeout() when the RTA timer ended the AR). With `steps`, p0922 is checked and
// the parameters written once the AR runs, and a p0922 other than the configured telegram or a parameter the
// drive refuses or reads back otherwise releases the AR again.
// `hello`: a DCP Hello the device sent (wait_for_hello), used instead of the Identify when it names this
// device (decision I36); a Hello that arrives while the Identify's answer is awaited is taken as the answer.
std::string start_up(profinet::IoController& controller, profinet::RawSocket& raw, profinet::UdpSocket& udp,
                     std::uint32_t& xid, ParameterSteps* steps, std::span<const std::uint8_t> hello = {});

// Waits up to `wait` for a DCP Hello (a device starting up) that names one of `names`: the frame, or empty.
// Other frames on the start-up socket are dropped (each start-up drops what queued before it anyway).
std::vector<std::uint8_t> wait_for_hello(profinet::RawSocket& raw, const std::vector<std::string>& names,
                                         std::chrono::milliseconds wait);

// Why the RTA timer ended an AR (IoController::alarm_timer's kAbort; the AR's PNIOStatus is
// kAlarmAckSendTimeoutStatus): "RTA timeout: AlarmAck (high) resent 3 times every 100 ms".
std::string describe_alarm_timeout(bool high_priority, const profinet::ControllerDeviceConfig& device);

// Why the device ended an AR (its ERR-RTA-PDU, decision I35): "RTA ERR from the device (low): PNIOStatus
// 0xCF81FD09".
std::string describe_rta_error(bool high_priority, std::uint32_t status);

// "slot 1 subslot 2: wrong submodule (ident 0x10002)"; "" when no module differs.
std::string describe(const std::vector<profinet::ModuleDiff>& diff);

}  // namespace tomc::profinet_gateway::detail
