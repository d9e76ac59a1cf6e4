// DCP commissioning over a raw socket (commissioning.hpp).
#include "tomc/gateway/commissioning.hpp"

#include <unistd.h>

#include <array>
#include <stdexcept>

#include "tomc/profinet/sockets.hpp"

namespace tomc::profinet_gateway {

namespace pn = tomc::profinet;
using Clock = std::chrono::steady_clock;

namespace {

// The socket takes DCP (and alarm) frames only: the cyclic frames of a running gateway on the same
// interface never reach it (decision I31).
pn::RawSocket open_socket(const std::string& interface) {
  pn::RawSocket socket;
  if (std::string e = socket.open(interface, pn::RawSocketFrames::kDcpAndAlarms); !e.empty())
    throw std::runtime_error(e.find(interface) != std::string::npos ? e
                                                                    : "interface " + interface + ": " + e);
  return socket;
}

// An Xid of its own per run, so the answers to another tool's requests are not taken for ours.
std::uint32_t fresh_xid() {
  return static_cast<std::uint32_t>(::getpid()) << 16 ^
         static_cast<std::uint32_t>(Clock::now().time_since_epoch().count());
}

// Calls take(frame) for every frame received until `until`; stops early when take returns true.
template <typename Take>
void receive_until(pn::RawSocket& socket, Clock::time_point until, Take take) {
  std::array<std::uint8_t, 1518> frame{};
  for (auto now = Clock::now(); now < until; now = Clock::now()) {
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(until - now).count();
    const std::size_t n = socket.receive(frame, static_cast<int>(std::min<long long>(left, 20'000)));
    if (n > 0 && take(std::span<const std::uint8_t>(frame.data(), n))) return;
  }
}

}  // namespace

std::vector<pn::DcpStation> identify_all(const std::string& interface, std::chrono::milliseconds wait) {
  pn::RawSocket socket = open_socket(interface);
  pn::DcpScan scan(socket.mac(), fresh_xid());
  if (!socket.send(scan.request())) throw std::runtime_error("interface '" + interface + "': send failed");
  receive_until(socket, Clock::now() + wait, [&](std::span<const std::uint8_t> frame) {
    (void)scan.on_frame(frame);
    return false;  // all answers within the wait
  });
  return scan.stations();
}

std::string set_name_of_station(const std::string& interface, const pn::MacAddress& mac,
                                const std::string& name, bool permanent, std::chrono::milliseconds wait,
                                const std::optional<pn::IpSuite>& ip) {
  pn::RawSocket socket = open_socket(interface);
  const std::uint32_t xid = fresh_xid();
  const auto request = pn::dcp_set_name_request(socket.mac(), mac, xid, name, permanent, ip);
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (!socket.send(request)) throw std::runtime_error("interface '" + interface + "': send failed");
    std::optional<std::string> result;
    receive_until(socket, Clock::now() + wait, [&](std::span<const std::uint8_t> frame) {
      result = pn::dcp_set_name_result(frame, mac, xid, ip.has_value());
      return result.has_value();
    });
    if (result) return *result;
  }
  return "no answer from " + pn::to_string(mac) + " to DCP Set (3 tries, " + std::to_string(wait.count()) +
         " ms each)";
}

}  // namespace tomc::profinet_gateway
