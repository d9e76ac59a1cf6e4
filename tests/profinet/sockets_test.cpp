// The start-up socket's kernel filter (decision I30), in memory: the same classic BPF program on an AF_UNIX
// datagram socket, whose data start with the Ethernet header as an AF_PACKET socket's do. Table-driven over
// the FrameID ranges of IEC 61158-6-10 (frame_id.hpp), with and without a VLAN tag.
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tomc/profinet/frame_id.hpp"
#include "tomc/profinet/sockets.hpp"

namespace pn = tomc::profinet;

namespace {

// Destination, source, [0x8100, TCI priority 6], EtherType, FrameID, zero padding to `length` bytes.
std::vector<std::uint8_t> frame(std::uint16_t ether_type, std::uint16_t frame_id, bool tagged,
                                std::size_t length = 60) {
  std::vector<std::uint8_t> bytes = {0x02, 0, 0, 0, 0, 0x01, 0x02, 0, 0, 0, 0, 0x02};
  if (tagged) bytes.insert(bytes.end(), {0x81, 0x00, 0xC0, 0x00});
  bytes.insert(bytes.end(),
               {static_cast<std::uint8_t>(ether_type >> 8), static_cast<std::uint8_t>(ether_type),
                static_cast<std::uint8_t>(frame_id >> 8), static_cast<std::uint8_t>(frame_id)});
  bytes.resize(length, 0);
  return bytes;
}

struct SocketPair {
  int send = -1;
  int receive = -1;
  SocketPair() {
    int fds[2] = {-1, -1};
    if (::socketpair(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0, fds) == 0) {
      send = fds[0];
      receive = fds[1];
    }
  }
  ~SocketPair() {
    if (send >= 0) ::close(send);
    if (receive >= 0) ::close(receive);
  }
  // The filter on the receiving end; "" when the pair exists and took it.
  std::string filtered() const {
    return receive < 0 ? "no socketpair" : pn::attach_dcp_and_alarm_filter(receive);
  }
  // The next datagram that passed the filter (empty: none).
  std::vector<std::uint8_t> take() const {
    std::array<std::uint8_t, 1518> buffer{};
    const ssize_t n = ::recv(receive, buffer.data(), buffer.size(), 0);
    return n > 0 ? std::vector<std::uint8_t>(buffer.begin(), buffer.begin() + n)
                 : std::vector<std::uint8_t>{};
  }
};

struct FilterCase {
  const char* what;
  std::uint16_t ether_type;
  std::uint16_t frame_id;
  bool tagged;
  std::size_t length;
  bool passes;
};

constexpr std::uint16_t kProfinet = pn::kEtherTypeProfinet;

// clang-format off
constexpr FilterCase kCases[] = {
    {"RT_CLASS_1 first",              kProfinet, pn::kFrameIdRtClass1First,        false, 60, false},
    {"RT_CLASS_1 tagged",             kProfinet, 0x8001,                           true,  60, false},
    {"RT_CLASS_1 last",               kProfinet, pn::kFrameIdRtClass1Last,         true,  60, false},
    {"RT_CLASS_1 legacy",             kProfinet, pn::kFrameIdRtClass1LegacyFirst,  true,  60, false},
    {"alarm high",                    kProfinet, pn::kFrameIdAlarmHigh,            false, 60, true},
    {"alarm high tagged",             kProfinet, pn::kFrameIdAlarmHigh,            true,  60, true},
    {"alarm low tagged",              kProfinet, pn::kFrameIdAlarmLow,             true,  60, true},
    {"alarm low",                     kProfinet, pn::kFrameIdAlarmLow,             false, 60, true},
    {"next to alarm high",            kProfinet, 0xFC02,                           true,  60, false},
    {"next to alarm low",             kProfinet, 0xFE00,                           true,  60, false},
    {"below DCP",                     kProfinet, 0xFEFB,                           false, 60, false},
    {"DCP Hello",                     kProfinet, pn::kFrameIdDcpHello,             false, 60, true},
    {"DCP Get/Set",                   kProfinet, pn::kFrameIdDcpGetSet,            false, 60, true},
    {"DCP Identify request",          kProfinet, pn::kFrameIdDcpIdentifyRequest,   false, 60, true},
    {"DCP Identify response",         kProfinet, pn::kFrameIdDcpIdentifyResponse,  false, 60, true},
    {"DCP Identify response tagged",  kProfinet, pn::kFrameIdDcpIdentifyResponse,  true,  60, true},
    {"above DCP",                     kProfinet, 0xFF00,                           false, 60, false},
    {"IPv4 with an alarm's bytes",    0x0800,    pn::kFrameIdAlarmHigh,            false, 60, false},
    {"tagged IPv4",                   0x0800,    pn::kFrameIdDcpHello,             true,  60, false},
    {"alarm cut in its FrameID",      kProfinet, pn::kFrameIdAlarmHigh,            false, 15, false},
    {"tagged alarm cut in its FrameID", kProfinet, pn::kFrameIdAlarmLow,           true,  19, false},
};
// clang-format on

}  // namespace

TEST(RawSocketFilter, OnlyDcpAndAlarmFramesPass) {
  const SocketPair pair;
  ASSERT_EQ(pair.filtered(), "");
  for (const FilterCase& c : kCases) {
    const std::vector<std::uint8_t> sent = frame(c.ether_type, c.frame_id, c.tagged, c.length);
    ASSERT_EQ(::send(pair.send, sent.data(), sent.size(), 0), static_cast<ssize_t>(sent.size())) << c.what;
    // Whole, unchanged, or not at all.
    EXPECT_EQ(pair.take(), c.passes ? sent : std::vector<std::uint8_t>{}) << c.what;
    // The table follows the codec's own classification where the frame is PROFINET and whole.
    if (c.ether_type == kProfinet && c.length == 60) {
      const pn::FrameKind kind = pn::classify_frame_id(c.frame_id);
      EXPECT_EQ(c.passes, kind == pn::FrameKind::kAlarm || kind == pn::FrameKind::kDcp) << c.what;
    }
  }
}

// With running devices, cyclic frames arrive every cycle while the start-up thread waits on an RPC answer;
// filtered, they never enter its queue, so an alarm behind a thousand of them is the first frame it reads.
// Decision I31 (the start-up thread's BPF filter lets only DCP and alarm FrameIDs in).
TEST(RawSocketFilter, AnAlarmBehindAThousandCyclicFramesIsTheFirstFrameRead) {
  const SocketPair pair;
  ASSERT_EQ(pair.filtered(), "");
  int sent = 0;
  for (int k = 0; k < 1000; ++k) {
    const auto cyclic = frame(kProfinet, static_cast<std::uint16_t>(0x8000 + k % 32), true);
    sent += ::send(pair.send, cyclic.data(), cyclic.size(), 0) == static_cast<ssize_t>(cyclic.size());
  }
  EXPECT_EQ(sent, 1000);  // dropped by the filter, not refused by a full queue
  const auto alarm = frame(kProfinet, pn::kFrameIdAlarmLow, true);
  ASSERT_EQ(::send(pair.send, alarm.data(), alarm.size(), 0), static_cast<ssize_t>(alarm.size()));
  EXPECT_EQ(pair.take(), alarm);
  EXPECT_EQ(pair.take(), std::vector<std::uint8_t>{});
}
