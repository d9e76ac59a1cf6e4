// PROFINET over a real link: two network namespaces made by this test (controller and device) joined by a
// veth pair; an IoDevice on raw/UDP sockets in one (its own thread), an IoController in the other. DCP
// Identify All + Set name (commissioning), then the controller's start-up by name, 1 ms cyclic exchange, a
// cable cut (controller's veth down) that ends the AR on both sides, reconnect, Release. tshark captures the
// controller's end: every frame dissects without a malformed packet and the PNIO blocks are all there.
// Each namespace is checked to see only lo and its veth end before anything is sent; both are deleted at
// the end. Skipped (with the reason) where namespaces cannot be made.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "netns_hosts.hpp"
#include "sample_frames.hpp"
#include "tomc/profinet/io_controller.hpp"
#include "tomc/profinet/io_device.hpp"
#include "tomc/profinet/sockets.hpp"

namespace pn = tomc::profinet;
using Clock = std::chrono::steady_clock;

namespace {

constexpr pn::Ipv4Address kControllerIp{10, 217, 0, 1};
constexpr pn::Ipv4Address kDeviceIp{10, 217, 0, 2};
// Both host threads run SCHED_FIFO, as the gateway's cyclic thread does with `fifo_priority` (decision I22):
// under a load of 12 on two cores, normal threads were starved for more than the 20 ms watchdog and the AR
// ended in the middle of the 300 cycles (175 valid).
constexpr int kHostPriority = 40;

using pn::testing::enter;
using pn::testing::now_us;
using pn::testing::output_of;
using pn::testing::quiet;

// The device host: IoDevice behind the sockets, echoing its output telegram into its input telegram.
void run_device(const std::string& ns, std::atomic<bool>& stop, std::atomic<int>& ars, std::string& error) {
  if (!enter(ns)) {
    error = "setns into the device namespace failed";
    return;
  }
  (void)pn::testing::real_time(kHostPriority);
  pn::RawSocket raw;
  pn::UdpSocket udp;
  error = raw.open("pn-d");
  if (error.empty()) error = udp.open(kDeviceIp, pn::kPnioUdpPort);
  if (!error.empty()) return;
  pn::DeviceIdentity identity;
  identity.mac = raw.mac();
  identity.ip = {kDeviceIp, {255, 255, 255, 0}, {}};
  identity.vendor_id = 0x002A;
  identity.device_id = 0x0C01;
  identity.vendor = "tomc emulated drive";
  identity.modules = {{0, 0x1, {{1, 0x1, pn::SubmoduleDirection::kNoIo, 0, 0}}},
                      {1, 0x100, {{2, 0x101, pn::SubmoduleDirection::kInputOutput, 4, 4}}}};
  pn::IoDevice device(identity);
  std::array<std::uint8_t, 1518> frame{};
  std::uint64_t next_send = now_us();
  pn::ArState last = pn::ArState::kNone;
  while (!stop) {
    if (const std::size_t n = raw.receive(frame, 200); n > 0) {
      const auto in = std::span(frame).first(n);
      if (pn::classify_frame_id(pn::peek_frame_id(in)) == pn::FrameKind::kDcp) {
        if (const auto answer = device.on_dcp(in); !answer.empty()) raw.send(answer);
      } else {
        device.on_cyclic(in, now_us());
      }
    }
    pn::testing::serve_device_rpc(device, udp, frame, kControllerIp);
    if (device.state() == pn::ArState::kRunning && last != pn::ArState::kRunning) ++ars;
    last = device.state();
    const std::uint64_t now = now_us();
    if (now >= next_send) {
      next_send += 1000;
      if (device.state() != pn::ArState::kNone) {
        const auto out = device.output_data(1, 2);
        const auto in = device.input_data(1, 2);
        std::copy(out.begin(), out.end(), in.begin());
        if (const std::size_t n = device.next_input_frame(frame); n > 0) raw.send(std::span(frame).first(n));
      }
      device.watchdog_expired(now);
    }
  }
}

// The controller's RPC round trip: send, then wait up to 200 ms for the answer (or the device's request).
std::vector<std::uint8_t> call(pn::UdpSocket& udp, std::span<const std::uint8_t> request) {
  udp.send_to(request, kDeviceIp, pn::kPnioUdpPort);
  std::array<std::uint8_t, 4096> buffer{};
  pn::Ipv4Address from{};
  std::uint16_t port = 0;
  const std::size_t n = udp.receive(buffer, 200000, from, port);
  return {buffer.begin(), buffer.begin() + static_cast<long>(n)};
}

}  // namespace

TEST(ProfinetNetns, NamingConnectionCyclicCableCutAndReconnect) {
  pn::testing::Namespaces hosts("tomc17c", "tomc17d");
  if (const std::string why = hosts.make({"pn-c", "02:00:00:00:17:01", "10.217.0.1/24"},
                                         {"pn-d", "02:00:00:00:17:02", "10.217.0.2/24"});
      !why.empty()) {
    GTEST_SKIP() << why;
  }
  // Nothing is sent unless each namespace sees only lo and its own veth end (never the machine's interfaces).
  ASSERT_EQ(hosts.interfaces(hosts.first), (std::set<std::string>{"lo", "pn-c"}));
  ASSERT_EQ(hosts.interfaces(hosts.second), (std::set<std::string>{"lo", "pn-d"}));
  ASSERT_TRUE(hosts.carrier(hosts.first, "pn-c"));

  const bool capture = pn::testing::Capture::available();
  std::optional<pn::testing::Capture> dumpcap;
  if (capture) {
    dumpcap.emplace(
        hosts.first, "pn-c",
        std::filesystem::temp_directory_path() / ("tomc17-" + std::to_string(::getpid()) + ".pcap"));
  }
  std::atomic<bool> stop{false};
  std::atomic<int> device_ars{0};
  std::string device_error;
  std::thread device_host(run_device, hosts.second, std::ref(stop), std::ref(device_ars),
                          std::ref(device_error));

  std::string failure;
  int cycles_valid = 0;
  int cycles_to_loss = 0;
  std::uint64_t silence_us = 0;                  // from the last input frame to the end of the AR
  std::uint64_t silence_at_check_before_us = 0;  // ... to the watchdog check before that
  std::uint32_t ar_count = 0;
  bool controller_real_time = false;
  bool ran_through = false;  // the AR was still up after the 300 cycles
  std::thread controller_host([&] {
    if (!enter(hosts.first)) return void(failure = "setns into the controller namespace failed");
    controller_real_time = pn::testing::real_time(kHostPriority);
    pn::RawSocket raw;
    pn::UdpSocket udp;
    if (failure = raw.open("pn-c"); !failure.empty()) return;
    if (failure = udp.open(kControllerIp, pn::kPnioUdpPort); !failure.empty()) return;
    std::array<std::uint8_t, 1518> frame{};
    const auto receive_dcp = [&](std::uint32_t xid) -> std::vector<std::uint8_t> {
      for (const auto end = Clock::now() + std::chrono::milliseconds(200); Clock::now() < end;) {
        const std::size_t n = raw.receive(frame, 10000);
        pn::WireReader in{std::span<const std::uint8_t>(frame.data(), n)};
        (void)pn::decode_ethernet(in);
        const pn::DcpMessage message = pn::decode_dcp(in);
        if (n > 0 && in.ok() && message.xid == xid && message.type == pn::DcpServiceType::kSuccess) {
          return {frame.begin(), frame.begin() + static_cast<long>(n)};
        }
      }
      return {};
    };
    // Commissioning: Identify All finds the unnamed device; Set gives it its name.
    std::vector<std::uint8_t> request(1514);
    pn::WireWriter out(request);
    pn::encode(pn::EthernetHeader{pn::kDcpIdentifyMulticast, raw.mac(), std::nullopt},
               pn::dcp_identify_request(1, std::nullopt), out);
    std::vector<std::uint8_t> all;
    for (int attempt = 0; attempt < 10 && all.empty(); ++attempt) {  // the device host may still be starting
      raw.send(out.written());
      all = receive_dcp(1);
    }
    if (all.empty()) return void(failure = "no answer to Identify All");
    pn::MacAddress device_mac{};
    std::copy(all.begin() + 6, all.begin() + 12, device_mac.begin());
    pn::WireWriter set_out(request);
    pn::encode(pn::EthernetHeader{device_mac, raw.mac(), std::nullopt},
               pn::dcp_set_request(2, std::string("drive-1"), std::nullopt, false), set_out);
    raw.send(set_out.written());
    if (receive_dcp(2).empty()) return void(failure = "no answer to Set name");

    pn::ControllerDeviceConfig config;
    config.name_of_station = "drive-1";
    config.ip = {kDeviceIp, {255, 255, 255, 0}, {}};
    config.modules = {{0, 0, 0x1, {{1, 0x1, pn::SubmoduleDirection::kNoIo, 0, 0}}},
                      {0, 1, 0x100, {{2, 0x101, pn::SubmoduleDirection::kInputOutput, 4, 4}}}};
    config.startup_records = {{1, 1, 0xB02E, pn::testing::read_p0922_request().data, 0}};
    // 1 ms cycles with a 20 ms watchdog on both sides: the test's threads are not real-time and share two
    // cores with builds, so a 3 ms watchdog would end the AR at random (docs/profinet-gateway.md).
    config.watchdog_factor = 20;
    config.data_hold_factor = 20;
    pn::IoController controller(raw.mac(), "tomc-gateway", config, pn::testing::kArUuid);
    const auto start_up = [&](std::uint32_t xid) -> bool {
      raw.send(controller.identify_request(xid));
      const auto found = receive_dcp(xid);
      if (found.empty() || !controller.on_dcp(found, xid + 1).empty()) return false;
      if (!controller.on_connect_response(call(udp, controller.connect_request()))) return false;
      while (controller.state() == pn::ControllerArState::kParameterizing ||
             controller.state() == pn::ControllerArState::kPrmEnd) {
        if (!controller.on_response(call(udp, controller.next_request()))) return false;
      }
      std::array<std::uint8_t, 1024> ready{};
      pn::Ipv4Address from{};
      std::uint16_t port = 0;
      const std::size_t n = udp.receive(ready, 500000, from, port);
      const auto answer = controller.on_application_ready(std::span(ready).first(n));
      udp.send_to(answer, from, port);
      return controller.state() == pn::ControllerArState::kRunning;
    };
    // One cycle: send the output frame, take every input frame that arrived, check the watchdog.
    std::uint8_t counter = 0;
    std::uint64_t last_input_us = 0;
    std::uint64_t last_check_us = 0;
    const auto cycle = [&](std::uint64_t deadline) {
      controller.output_data(1, 2)[3] = ++counter;
      if (const std::size_t n = controller.next_output_frame(frame); n > 0)
        raw.send(std::span(frame).first(n));
      const auto take = [&](int wait_us) {
        const std::size_t n = raw.receive(frame, wait_us);
        if (n > 0 && controller.on_input_frame(std::span(frame).first(n), now_us())) last_input_us = now_us();
        return n > 0;
      };
      while (now_us() < deadline)
        (void)take(static_cast<int>(deadline - now_us()));
      // A cycle that starts late (this thread was not scheduled) has no time left before its deadline: it
      // still takes what arrived meanwhile, as the gateway's cycle does, so the watchdog judges the link and
      // not the scheduler (the ASan stage once saw the AR end with frames waiting in the socket).
      for (int k = 0; k < 64 && take(0); ++k) {
      }
      const std::uint64_t check_us = now_us();
      if (controller.watchdog_expired(check_us)) {
        silence_us = check_us - last_input_us;
        silence_at_check_before_us = last_check_us > last_input_us ? last_check_us - last_input_us : 0;
      }
      last_check_us = check_us;
    };
    if (!start_up(10))
      return void(failure = "start-up failed, PNIOStatus " + std::to_string(controller.last_error().value()));
    std::uint64_t deadline = now_us();
    for (int k = 0; k < 300; ++k) {
      cycle(deadline += 1000);
      cycles_valid += controller.input_valid(now_us()) ? 1 : 0;
    }
    ran_through = controller.state() == pn::ControllerArState::kRunning;
    quiet("ip -n " + hosts.first + " link set pn-c down");  // named: never the host's namespace
    // Count cycles from here: the `ip` child blocks this thread (60 ms once under load), and catching up on
    // the missed deadlines would run cycles back to back, right after the frames queued before the cut were
    // taken, so the count would measure the child's time and not the watchdog (41 and 58 at load 11-13).
    deadline = now_us();
    while (controller.state() == pn::ControllerArState::kRunning && cycles_to_loss < 200) {
      cycle(deadline += 1000);
      ++cycles_to_loss;
    }
    quiet("ip -n " + hosts.first + " link set pn-c up");
    bool reconnected = false;
    for (int attempt = 0; attempt < 20 && !reconnected; ++attempt) {
      reconnected = start_up(20 + 2 * static_cast<std::uint32_t>(attempt));
      if (!reconnected) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (!reconnected) return void(failure = "no reconnect after the link came back");
    deadline = now_us();
    for (int k = 0; k < 100; ++k)
      cycle(deadline += 1000);
    if (!controller.input_valid(now_us())) return void(failure = "no valid input after the reconnect");
    ar_count = controller.ar_count();
    controller.on_response(call(udp, controller.release_request()));
  });
  controller_host.join();
  stop = true;
  device_host.join();
  if (dumpcap) dumpcap->stop();

  ASSERT_EQ(device_error, "");
  ASSERT_EQ(failure, "");
  // Allow some cycles without a fresh frame (one run in ten under ASan with a parallel build, normal threads,
  // fell below 290 of 300); the AR itself must have run through all 300 (ar_count 2: this one and the
  // reconnect).
  EXPECT_TRUE(ran_through);
  EXPECT_GE(cycles_valid, 270) << (controller_real_time ? "" : "(SCHED_FIFO refused: normal threads)");
  // The controller's watchdog (20 × 1 ms) ends the AR more than 20 ms after the last input frame, at the
  // first check after that: the check before it still saw at most 20 ms. (Not a wall-time bound: the cycle
  // thread waits for the `ip link set down` child, which under load took 60 ms once.)
  EXPECT_GT(silence_us, 20000u);
  EXPECT_LE(silence_at_check_before_us, 20000u);
  EXPECT_LE(cycles_to_loss, 40);
  EXPECT_EQ(ar_count, 2u);
  EXPECT_EQ(device_ars, 2);
  if (!capture) GTEST_SKIP() << "tshark is not installed: the capture was not checked";
  const std::string tree = output_of("tshark -n -P -V -r " + dumpcap->file().string() + " 2>&1");
  EXPECT_EQ(tree.find("Malformed"), std::string::npos);
  EXPECT_EQ(tree.find("Expert Info (Error"), std::string::npos);
  EXPECT_EQ(tree.find("greater than remaining"), std::string::npos);
  for (const char* expected :
       {"Ident Req, Xid:0x1, All", "Set Req, Xid:0x2, NameOfStation:\"drive-1\"", "Set Ok",
        "Connect request, ARBlockReq, IOCRBlockReq, IOCRBlockReq, AlarmCRBlockReq, "
        "ExpectedSubmoduleBlockReq, "
        "ExpectedSubmoduleBlockReq",
        "Connect response, OK, ARBlockRes, IOCRBlockRes, IOCRBlockRes, AlarmCRBlockRes", "IODWriteReqHeader",
        "IODControlReq Prm End.req", "IOXBlockReq Application Ready.req", "IOXBlockRes Application Ready.rsp",
        "IODReleaseReq", "RTC1, ID:0x8000", "RTC1, ID:0x8001"}) {
    EXPECT_NE(tree.find(expected), std::string::npos) << "missing in the capture: " << expected;
  }
}
