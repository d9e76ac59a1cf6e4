#include "tomc/profinet/sockets.hpp"

#include <arpa/inet.h>
#include <linux/filter.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <utility>

#include "tomc/profinet/frame_id.hpp"

namespace tomc::profinet {

namespace {

bool wait_readable(int fd, int timeout_us) noexcept {
  pollfd p{fd, POLLIN, 0};
  const int timeout_ms = timeout_us <= 0 ? 0 : (timeout_us + 999) / 1000;
  return ::poll(&p, 1, timeout_ms) > 0 && (p.revents & POLLIN) != 0;
}

std::string error(const char* what) {
  return std::string(what) + ": " + std::strerror(errno);
}

}  // namespace

std::string attach_dcp_and_alarm_filter(int fd) {
  // A = EtherType; a VLAN tag (0x8100) moves EtherType and FrameID 4 bytes on. Offsets past the end of a
  // short frame make the kernel drop it. Jump offsets count from the next instruction.
  static constexpr std::uint16_t kVlan = 0x8100;
  static sock_filter program[] = {
      BPF_STMT(BPF_LD | BPF_H | BPF_ABS, 12),                                  // 0
      BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kVlan, 3, 0),                        // 1: tagged -> 5
      BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kEtherTypeProfinet, 0, 10),          // 2: else drop (13)
      BPF_STMT(BPF_LD | BPF_H | BPF_ABS, 14),                                  // 3: FrameID
      BPF_JUMP(BPF_JMP | BPF_JA, 3, 0, 0),                                     // 4: -> 8
      BPF_STMT(BPF_LD | BPF_H | BPF_ABS, 16),                                  // 5: EtherType behind the tag
      BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kEtherTypeProfinet, 0, 6),           // 6: else drop (13)
      BPF_STMT(BPF_LD | BPF_H | BPF_ABS, 18),                                  // 7: FrameID
      BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kFrameIdAlarmHigh, 3, 0),            // 8: -> accept (12)
      BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, kFrameIdAlarmLow, 2, 0),             // 9: -> accept (12)
      BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, kFrameIdDcpHello, 0, 2),             // 10: below DCP -> drop (13)
      BPF_JUMP(BPF_JMP | BPF_JGT | BPF_K, kFrameIdDcpIdentifyResponse, 1, 0),  // 11: above -> drop
      BPF_STMT(BPF_RET | BPF_K, 0x40000),                                      // 12: accept the whole frame
      BPF_STMT(BPF_RET | BPF_K, 0),                                            // 13: drop
  };
  const sock_fprog filter{static_cast<unsigned short>(std::size(program)), program};
  if (::setsockopt(fd, SOL_SOCKET, SO_ATTACH_FILTER, &filter, sizeof filter) < 0)
    return error("SO_ATTACH_FILTER");
  return {};
}

RawSocket::RawSocket(RawSocket&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), interface_index_(other.interface_index_), mac_(other.mac_) {}

RawSocket& RawSocket::operator=(RawSocket&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    interface_index_ = other.interface_index_;
    mac_ = other.mac_;
  }
  return *this;
}

RawSocket::~RawSocket() {
  if (fd_ >= 0) ::close(fd_);
}

std::string RawSocket::open(const std::string& interface, RawSocketFrames frames) {
  if (interface.size() >= IFNAMSIZ) return "interface name too long: " + interface;
  const int fd = ::socket(AF_PACKET, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, htons(kEtherTypeProfinet));
  if (fd < 0) return error("socket(AF_PACKET)");
  ifreq request{};
  std::memcpy(request.ifr_name, interface.c_str(), interface.size() + 1);
  if (::ioctl(fd, SIOCGIFINDEX, &request) < 0) {
    const std::string text = error(("interface " + interface).c_str());
    ::close(fd);
    return text;
  }
  interface_index_ = request.ifr_ifindex;
  if (::ioctl(fd, SIOCGIFHWADDR, &request) < 0) {
    const std::string text = error("SIOCGIFHWADDR");
    ::close(fd);
    return text;
  }
  std::memcpy(mac_.data(), request.ifr_hwaddr.sa_data, mac_.size());
  sockaddr_ll address{};
  address.sll_family = AF_PACKET;
  address.sll_protocol = htons(kEtherTypeProfinet);
  address.sll_ifindex = interface_index_;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) < 0) {
    const std::string text = error("bind(AF_PACKET)");
    ::close(fd);
    return text;
  }
  // Tagged frames (VLAN priority) arrive with the tag stripped by most drivers; the DCP multicast
  // addresses must be let in explicitly.
  for (const MacAddress& group : {kDcpIdentifyMulticast, kDcpHelloMulticast}) {
    packet_mreq membership{};
    membership.mr_ifindex = interface_index_;
    membership.mr_type = PACKET_MR_MULTICAST;
    membership.mr_alen = 6;
    std::memcpy(membership.mr_address, group.data(), 6);
    (void)::setsockopt(fd, SOL_PACKET, PACKET_ADD_MEMBERSHIP, &membership, sizeof membership);
  }
  if (frames == RawSocketFrames::kDcpAndAlarms) {
    if (std::string text = attach_dcp_and_alarm_filter(fd); !text.empty()) {
      ::close(fd);
      return text;
    }
  }
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
  // Frames queued before the filter was attached (the socket takes frames from its creation on).
  if (frames == RawSocketFrames::kDcpAndAlarms) (void)discard_queued(4096);
  return {};
}

std::size_t RawSocket::discard_queued(std::size_t max_frames) noexcept {
  std::size_t dropped = 0;
  std::array<std::uint8_t, 1518> frame{};
  while (fd_ >= 0 && dropped<max_frames&& ::recv(fd_, frame.data(), frame.size(), 0)> 0)
    ++dropped;
  return dropped;
}

bool RawSocket::send(std::span<const std::uint8_t> frame) noexcept {
  if (fd_ < 0) return false;
  sockaddr_ll address{};
  address.sll_family = AF_PACKET;
  address.sll_ifindex = interface_index_;
  address.sll_halen = 6;
  std::memcpy(address.sll_addr, frame.data(), std::min<std::size_t>(6, frame.size()));
  return ::sendto(fd_, frame.data(), frame.size(), 0, reinterpret_cast<sockaddr*>(&address),
                  sizeof address) == static_cast<ssize_t>(frame.size());
}

std::size_t RawSocket::receive(std::span<std::uint8_t> buffer, int timeout_us) noexcept {
  if (fd_ < 0) return 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    sockaddr_ll from{};
    socklen_t length = sizeof from;
    const ssize_t n =
        ::recvfrom(fd_, buffer.data(), buffer.size(), 0, reinterpret_cast<sockaddr*>(&from), &length);
    if (n > 0) {
      if (from.sll_pkttype == PACKET_OUTGOING) continue;
      return static_cast<std::size_t>(n);
    }
    if (attempt == 0 && !wait_readable(fd_, timeout_us)) return 0;
  }
  return 0;
}

UdpSocket::~UdpSocket() {
  if (fd_ >= 0) ::close(fd_);
}

std::string UdpSocket::open(const Ipv4Address& address, std::uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) return error("socket(UDP)");
  const int yes = 1;
  (void)::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in local{};
  local.sin_family = AF_INET;
  local.sin_port = htons(port);
  std::memcpy(&local.sin_addr, address.data(), 4);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) < 0) {
    const std::string text = error("bind(UDP)");
    ::close(fd);
    return text;
  }
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
  return {};
}

bool UdpSocket::send_to(std::span<const std::uint8_t> payload, const Ipv4Address& address,
                        std::uint16_t port) noexcept {
  if (fd_ < 0) return false;
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(port);
  std::memcpy(&to.sin_addr, address.data(), 4);
  return ::sendto(fd_, payload.data(), payload.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to) ==
         static_cast<ssize_t>(payload.size());
}

std::size_t UdpSocket::receive(std::span<std::uint8_t> buffer, int timeout_us, Ipv4Address& from,
                               std::uint16_t& from_port) noexcept {
  if (fd_ < 0) return 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    sockaddr_in sender{};
    socklen_t length = sizeof sender;
    const ssize_t n =
        ::recvfrom(fd_, buffer.data(), buffer.size(), 0, reinterpret_cast<sockaddr*>(&sender), &length);
    if (n > 0) {
      std::memcpy(from.data(), &sender.sin_addr, 4);
      from_port = ntohs(sender.sin_port);
      return static_cast<std::size_t>(n);
    }
    if (attempt == 0 && !wait_readable(fd_, timeout_us)) return 0;
  }
  return 0;
}

}  // namespace tomc::profinet
