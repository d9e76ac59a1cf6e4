#pragma once
// Internal: the start-up of one AR over the sockets (IEC 61158-6-10 order): DCP Identify by name of station
// (and Set of the IP suite when the device has another one), Connect, the start-up record writes, PrmEnd,
// the device's ApplicationReady answered; the device's alarms from the Connect on are acknowledged while it
// waits. Blocking with bounded waits; runs on the start-up thread, never on the cyclic one.

#include <cstdint>
#include <string>
#include <vector>

#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/sockets.hpp"

namespace tomc::profinet_gateway::detail {

// The telegram check after ApplicationReady: PROFIdrive parameter access to the drive object in `slot`.
struct TelegramCheck {
  std::uint16_t slot = 1;
  std::uint16_t telegram = 0;     // p0922 must be this
  float reference_speed_rpm = 0;  // p2000 as read (out)
};

// "" when the AR runs; otherwise one line saying which step failed ("no DCP answer to Identify
// 'drive-1'", "Connect refused, PNIOStatus 0xDB814004", "p0922 is 105: the drive sends telegram 105, the file
// says 3", describe_alarm_timeout() when the RTA timer ended the AR). With `check`, p0922 and p2000 are read
// once the AR runs, and a p0922 other than the configured telegram releases the AR again.
std::string start_up(profinet::IoController& controller, profinet::RawSocket& raw, profinet::UdpSocket& udp,
                     std::uint32_t& xid, TelegramCheck* check);

// Why the RTA timer ended an AR (IoController::alarm_timer's kAbort; the AR's PNIOStatus is
// kAlarmSendTimeoutStatus): "RTA timeout: AlarmAck (high) resent 3 times every 100 ms".
std::string describe_alarm_timeout(bool high_priority, const profinet::ControllerDeviceConfig& device);

// "slot 1 subslot 2: wrong submodule (ident 0x10002)"; "" when no module differs.
std::string describe(const std::vector<profinet::ModuleDiff>& diff);

}  // namespace tomc::profinet_gateway::detail
