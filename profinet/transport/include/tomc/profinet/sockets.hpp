#pragma once
// The two Linux sockets a PROFINET IO controller or device needs: a raw AF_PACKET socket for the layer-2
// frames (EtherType 0x8892: DCP, cyclic, alarms) bound to one interface, and a UDP socket on port 34964 for
// the DCE/RPC packets. Non-blocking; receive with a timeout through poll. Linux only (tomc::profinet stays
// socket-free); opening a raw socket needs CAP_NET_RAW.

#include <cstdint>
#include <span>
#include <string>

#include "tomc/profinet/dcp.hpp"

namespace tomc::profinet {

// Which frames a raw socket takes in: every PROFINET frame, or only the acyclic ones a start-up needs (DCP
// and RTA alarms) — the running devices' cyclic frames, one per device and cycle, are then dropped by the
// kernel before they reach the socket's queue.
enum class RawSocketFrames : std::uint8_t { kAll, kDcpAndAlarms };

// Attaches the classic BPF program of kDcpAndAlarms to any socket whose data start with the Ethernet header
// (an AF_PACKET socket; a test's AF_UNIX datagram socket): FrameID 0xFC01, 0xFE01 or 0xFEFC..0xFEFF after
// EtherType 0x8892, with or without a VLAN tag. The error text is empty on success.
std::string attach_dcp_and_alarm_filter(int fd);

class RawSocket {
 public:
  RawSocket() = default;
  RawSocket(const RawSocket&) = delete;
  RawSocket& operator=(const RawSocket&) = delete;
  RawSocket(RawSocket&& other) noexcept;
  RawSocket& operator=(RawSocket&& other) noexcept;
  ~RawSocket();

  // Opens the socket on interface (e.g. "eth1"); the error text is empty on success.
  std::string open(const std::string& interface, RawSocketFrames frames = RawSocketFrames::kAll);
  bool is_open() const noexcept { return fd_ >= 0; }
  const MacAddress& mac() const noexcept { return mac_; }

  bool send(std::span<const std::uint8_t> frame) noexcept;
  // One received PROFINET frame into buffer, waiting up to timeout_us; 0 if none arrived. Frames this
  // socket sent itself are not returned.
  std::size_t receive(std::span<std::uint8_t> buffer, int timeout_us) noexcept;
  // Drops what is queued (at most max_frames frames, so a sender faster than this loop cannot hold it);
  // returns how many were dropped.
  std::size_t discard_queued(std::size_t max_frames) noexcept;

 private:
  int fd_ = -1;
  int interface_index_ = 0;
  MacAddress mac_{};
};

class UdpSocket {
 public:
  UdpSocket() = default;
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;
  ~UdpSocket();

  // Binds to address:port (address 0.0.0.0 for any); the error text is empty on success.
  std::string open(const Ipv4Address& address, std::uint16_t port);
  bool send_to(std::span<const std::uint8_t> payload, const Ipv4Address& address,
               std::uint16_t port) noexcept;
  // One datagram into buffer, waiting up to timeout_us; 0 if none. from/from_port: the sender.
  std::size_t receive(std::span<std::uint8_t> buffer, int timeout_us, Ipv4Address& from,
                      std::uint16_t& from_port) noexcept;

 private:
  int fd_ = -1;
};

}  // namespace tomc::profinet
