// loopback_probe: the capture half of the loopback check (loopback_test.cpp, docs/gateway.md "Loopback
// only"). It must run in a fresh network namespace (the test forks, unshare(CLONE_NEWNET)s and execs it),
// where it
//   1. sets up lo and a veth pair with IPv4 addresses and a multicast route — a stand-in for eth0,
//   2. captures every frame on both veth ends (AF_PACKET),
//   3. runs the project's DDS exchange: `tomc gateway-sim` as a child process and a GatewayLink here, and
//      counts the IPv4 UDP/IGMP frames on the veth ends: they must be 0 while the exchange works,
//   4. as a control, creates one participant with Fast DDS's *default* QoS and counts again: it must be > 0,
//      proving the capture would have seen a leak.
// It refuses to do step 4 unless the only interfaces are lo and its veth pair, so default-QoS traffic can
// never reach a real network. Prints "project_frames=N fresh=F control_frames=M" and exits 0, or exits 3
// with a reason.
#include <arpa/inet.h>
#include <fcntl.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <netinet/ip.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>

#include "tomc/drives/dds/gateway_link.hpp"
#include "tomc/telegrams/layout.hpp"

namespace {

constexpr const char* kVethA = "tomcv0";
constexpr const char* kVethB = "tomcv1";

[[noreturn]] void fail(const std::string& why) {
  std::printf("probe failed: %s\n", why.c_str());
  std::fflush(stdout);
  std::_Exit(3);
}

void run(const std::string& command) {
  if (std::system(command.c_str()) != 0) fail("'" + command + "' failed");
}

std::vector<std::string> interfaces() {
  std::vector<std::string> names;
  if (struct if_nameindex* list = if_nameindex()) {
    for (struct if_nameindex* i = list; i->if_index != 0; ++i)
      names.emplace_back(i->if_name);
    if_freenameindex(list);
  }
  return names;
}

// Counts IPv4 UDP and IGMP frames seen on one interface (sent or received).
class Capture {
 public:
  explicit Capture(const char* interface) {
    fd_ = ::socket(AF_PACKET, SOCK_RAW | SOCK_NONBLOCK, htons(ETH_P_ALL));
    if (fd_ < 0) fail("AF_PACKET socket (needs CAP_NET_RAW)");
    sockaddr_ll address{};
    address.sll_family = AF_PACKET;
    address.sll_protocol = htons(ETH_P_ALL);
    address.sll_ifindex = static_cast<int>(if_nametoindex(interface));
    if (address.sll_ifindex == 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
      fail(std::string("bind to ") + interface);
    }
    thread_ = std::thread([this] { loop(); });
  }
  ~Capture() {
    stop_ = true;
    thread_.join();
    ::close(fd_);
  }
  std::uint64_t frames() const { return frames_.load(); }

 private:
  void loop() {
    unsigned char buffer[65536];
    while (!stop_.load()) {
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n < 0) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        continue;
      }
      if (n < static_cast<ssize_t>(sizeof(ether_header) + sizeof(iphdr))) continue;
      ether_header eth;  // copied out: the frame's headers are not aligned for the structs
      std::memcpy(&eth, buffer, sizeof eth);
      if (ntohs(eth.ether_type) != ETHERTYPE_IP) continue;
      iphdr ip;
      std::memcpy(&ip, buffer + sizeof(ether_header), sizeof ip);
      if (ip.protocol == IPPROTO_UDP || ip.protocol == IPPROTO_IGMP) frames_.fetch_add(1);
    }
  }
  int fd_ = -1;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> frames_{0};
  std::thread thread_;
};

pid_t spawn_gateway(const std::string& tomc, const std::string& config) {
  std::vector<std::string> args = {tomc, "gateway-sim", "--config", config};
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) ::dup2(null, 1);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) fail("usage: loopback_probe TOMC_BINARY DOMAIN");
  const std::string tomc = argv[1];
  const int domain = std::atoi(argv[2]);
  // Step 0: this must be a fresh namespace: nothing but lo.
  const auto before = interfaces();
  if (before.size() != 1 || before[0] != "lo")
    fail("not in a fresh network namespace (interfaces besides lo)");
  run("ip link set lo up");
  run(std::string("ip link add ") + kVethA + " type veth peer name " + kVethB);
  run(std::string("ip addr add 10.213.7.1/24 dev ") + kVethA);
  run(std::string("ip addr add 10.213.7.2/24 dev ") + kVethB);
  run(std::string("ip link set ") + kVethA + " up");
  run(std::string("ip link set ") + kVethB + " up");
  run(std::string("ip route add 224.0.0.0/4 dev ") + kVethA);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // links up

  Capture a(kVethA);
  Capture b(kVethB);

  // Step 3: the project's exchange.
  const auto dir = std::filesystem::temp_directory_path() / ("tomc-probe-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string config = (dir / "gateway.json").string();
  std::ofstream(config) << "{ \"gateway\": \"probe\", \"domain\": " << domain
                        << ", \"devices\": [ { \"name\": \"axis1\", \"drive\": { \"telegram\": 3 } } ] }";
  const pid_t gateway = spawn_gateway(tomc, config);
  std::uint64_t fresh = 0;
  {
    tomc::drives::dds::GatewayLinkConfig lc;
    lc.domain = domain;
    auto link = tomc::drives::dds::GatewayLink::create(lc);
    tomc::drives::DeviceConfig dc;
    dc.drive_telegram = 3;
    auto drive = link->make_drive("axis1", dc);
    const auto reports = link->connect(std::chrono::seconds(10));
    if (reports.empty() || reports[0].diagnosis != tomc::drives::dds::DeviceDiagnosis::kAnswering) {
      ::kill(gateway, SIGKILL);
      fail("the gateway did not answer on loopback: " + (reports.empty() ? std::string() : reports[0].text));
    }
    auto actual = tomc::drives::make_frames(dc, tomc::telegrams::Direction::kActual);
    auto setpoint = tomc::drives::make_frames(dc, tomc::telegrams::Direction::kSetpoint);
    for (int cycle = 0; cycle < 300; ++cycle) {
      fresh += drive->read_actual(actual) ? 1 : 0;
      drive->write_setpoint(setpoint);
      link->wait_for_answers(std::chrono::milliseconds(20));
    }
  }
  ::kill(gateway, SIGTERM);
  int status = 0;
  ::waitpid(gateway, &status, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // anything late is still counted
  const std::uint64_t project_frames = a.frames() + b.frames();

  // Step 4: the control. Only here, in this namespace, is default QoS ever used.
  const auto now = interfaces();
  for (const auto& name : now) {
    if (name != "lo" && name != kVethA && name != kVethB) fail("unexpected interface " + name);
  }
  auto* factory = eprosima::fastdds::dds::DomainParticipantFactory::get_instance();
  auto* control = factory->create_participant(domain + 1, eprosima::fastdds::dds::PARTICIPANT_QOS_DEFAULT);
  if (control == nullptr) fail("default participant");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  factory->delete_participant(control);
  const std::uint64_t control_frames = a.frames() + b.frames() - project_frames;

  std::filesystem::remove_all(dir);
  std::printf("project_frames=%llu fresh=%llu control_frames=%llu\n",
              static_cast<unsigned long long>(project_frames), static_cast<unsigned long long>(fresh),
              static_cast<unsigned long long>(control_frames));
  std::fflush(stdout);
  return 0;
}
