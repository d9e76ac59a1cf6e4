#pragma once
// Sends fault-injection commands to gateway simulators over the command topic and waits until the addressed
// simulator reports them applied (GatewayStatus.command_number). Used by `tomc gateway-sim --send` and the
// two-process tests.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "tomc/drives/dds/network.hpp"

namespace tomc::gateway_sim {

enum class Command : std::uint8_t {
  kDropAnswers,   // value: number of answers (0xFFFFFFFFFFFFFFFF: until resume)
  kDelayAnswers,  // value: microseconds (0: off)
  kStop,
  kResume,
  kRestart,     // value: milliseconds of silence before the new incarnation answers
  kDriveFault,  // device, value: fault number (0 clears)
  kDisconnect,  // device
  kConnect,     // device
};
// "drop-answers", "delay-answers", "stop", "resume", "restart", "drive-fault", "disconnect", "connect".
std::optional<Command> parse_command(std::string_view text) noexcept;
std::string_view to_string(Command command) noexcept;

class GatewayCommander {
 public:
  // A participant on `domain`/`partition` on `network` (loopback by default; elsewhere its peers must
  // include the simulator's address). Throws std::invalid_argument for a wrong interface or peer,
  // std::runtime_error when Fast DDS refuses.
  GatewayCommander(int domain, const std::string& partition,
                   const drives::dds::NetworkSettings& network = {});
  ~GatewayCommander();
  GatewayCommander(const GatewayCommander&) = delete;
  GatewayCommander& operator=(const GatewayCommander&) = delete;

  // Waits until a simulator's command reader has matched this commander (call it before the cyclic part of a
  // test: a reliable topic's first sample can otherwise wait for a repair).
  bool wait_matched(std::chrono::milliseconds timeout);
  // Sends `command` to `gateway` ("" = every simulator on the domain) and waits until a simulator of that
  // name (any, for "") reports it applied. False on timeout (no simulator, or it did not answer).
  bool send(const std::string& gateway, Command command, std::uint64_t value = 0,
            const std::string& device = {}, std::chrono::milliseconds timeout = std::chrono::seconds(5));
  // The same without waiting for the confirmation, for a caller that keeps cycling meanwhile: returns the
  // command's number, 0 when no simulator has matched the command topic within `timeout`.
  std::uint64_t post(const std::string& gateway, Command command, std::uint64_t value = 0,
                     const std::string& device = {},
                     std::chrono::milliseconds timeout = std::chrono::seconds(5));
  // Whether a simulator named `gateway` ("" = any) reported command `number` applied.
  bool applied(std::uint64_t number, const std::string& gateway = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tomc::gateway_sim
