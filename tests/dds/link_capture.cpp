// link_capture: counts every frame on one interface by kind, for the two-host test (two_host_test.cpp). It
// runs inside the test's controller network namespace (`ip netns exec`), on the veth end of the link:
//
//   link_capture INTERFACE ADDRESS_A ADDRESS_B DOMAIN
//
// prints "ready" once the AF_PACKET socket is bound, counts until SIGTERM/SIGINT, then prints one line
//   frames=N between=U rtps_ports=P icmp=I unicast_other=X multicast=M broadcast=B igmp=G arp=R other=O
// between: IPv4 UDP unicast between A and B (either direction); rtps_ports: those of them whose destination
// port is one of the RTPS formula's unicast ports of DOMAIN (discovery 7400 + 250 d + 10 + 2 i, user data
// 7400 + 250 d + 11 + 2 i, participant id i < 32; docs/gateway.md §11); icmp: ICMP between A and B (the
// kernel's "port unreachable" answers to discovery sent to unused participant ids); unicast_other: any other
// IPv4 unicast; multicast/broadcast: IPv4 to 224/4 or a broadcast address; arp: ARP frames (needed by unicast
// IPv4 itself); other: anything else (IPv6, ...). It only listens: it sends nothing.
#include <arpa/inet.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <netinet/ip.h>
#include <netinet/udp.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

volatile std::sig_atomic_t stop = 0;
void on_signal(int) {
  stop = 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: link_capture INTERFACE ADDRESS_A ADDRESS_B DOMAIN\n");
    return 2;
  }
  in_addr a{}, b{};
  if (::inet_pton(AF_INET, argv[2], &a) != 1 || ::inet_pton(AF_INET, argv[3], &b) != 1) {
    std::fprintf(stderr, "link_capture: bad address\n");
    return 2;
  }
  const int domain = std::atoi(argv[4]);
  struct sigaction action {};
  action.sa_handler = on_signal;
  ::sigaction(SIGTERM, &action, nullptr);
  ::sigaction(SIGINT, &action, nullptr);

  const int fd = ::socket(AF_PACKET, SOCK_RAW, htons(ETH_P_ALL));
  if (fd < 0) {
    std::perror("link_capture: AF_PACKET socket");
    return 3;
  }
  sockaddr_ll address{};
  address.sll_family = AF_PACKET;
  address.sll_protocol = htons(ETH_P_ALL);
  address.sll_ifindex = static_cast<int>(::if_nametoindex(argv[1]));
  if (address.sll_ifindex == 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    std::perror("link_capture: bind");
    return 3;
  }
  std::printf("ready\n");
  std::fflush(stdout);

  const std::uint32_t base = 7400u + 250u * static_cast<std::uint32_t>(domain);
  auto rtps_unicast_port = [&](std::uint32_t port) {
    if (port < base + 10 || port > base + 11 + 2 * 31) return false;
    return true;  // d1 + 2i (even offset) or d3 + 2i (odd offset), i < 32: every port in that range
  };
  std::uint64_t frames = 0, between = 0, rtps = 0, unicast_other = 0, icmp = 0, multicast = 0, broadcast = 0,
                igmp = 0, arp = 0, other = 0;
  unsigned char buffer[65536];
  while (stop == 0) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n < static_cast<ssize_t>(sizeof(ether_header))) continue;
    ++frames;
    ether_header eth;  // copied out: the frame's headers are not aligned for the structs
    std::memcpy(&eth, buffer, sizeof eth);
    const std::uint16_t type = ntohs(eth.ether_type);
    if (type == ETHERTYPE_ARP) {
      ++arp;
      continue;
    }
    if (type != ETHERTYPE_IP || n < static_cast<ssize_t>(sizeof(ether_header) + sizeof(iphdr))) {
      ++other;
      continue;
    }
    iphdr ip;
    std::memcpy(&ip, buffer + sizeof(ether_header), sizeof ip);
    const std::uint32_t dst = ntohl(ip.daddr);
    if ((dst >> 28) == 0xE) {
      ++multicast;
    } else if (dst == 0xFFFFFFFFu || (dst & 0xFFu) == 0xFFu) {
      ++broadcast;  // the test's /24 link: .255 is its broadcast address
    } else if (ip.protocol == IPPROTO_IGMP) {
      ++igmp;
    } else if (ip.protocol == IPPROTO_ICMP && ((ip.saddr == a.s_addr && ip.daddr == b.s_addr) ||
                                               (ip.saddr == b.s_addr && ip.daddr == a.s_addr))) {
      ++icmp;  // "port unreachable" for a probed participant id nobody uses, or while one side stops
    } else if (ip.protocol == IPPROTO_UDP && ((ip.saddr == a.s_addr && ip.daddr == b.s_addr) ||
                                              (ip.saddr == b.s_addr && ip.daddr == a.s_addr))) {
      ++between;
      const std::size_t udp_at = sizeof(ether_header) + static_cast<std::size_t>(ip.ihl) * 4;
      if (n >= static_cast<ssize_t>(udp_at + sizeof(udphdr))) {
        udphdr udp;
        std::memcpy(&udp, buffer + udp_at, sizeof udp);
        if (rtps_unicast_port(ntohs(udp.dest))) ++rtps;
      }
    } else {
      ++unicast_other;
    }
  }
  ::close(fd);
  std::printf(
      "frames=%llu between=%llu rtps_ports=%llu icmp=%llu unicast_other=%llu multicast=%llu broadcast=%llu "
      "igmp=%llu arp=%llu other=%llu\n",
      static_cast<unsigned long long>(frames), static_cast<unsigned long long>(between),
      static_cast<unsigned long long>(rtps), static_cast<unsigned long long>(icmp),
      static_cast<unsigned long long>(unicast_other), static_cast<unsigned long long>(multicast),
      static_cast<unsigned long long>(broadcast), static_cast<unsigned long long>(igmp),
      static_cast<unsigned long long>(arp), static_cast<unsigned long long>(other));
  std::fflush(stdout);
  return 0;
}
