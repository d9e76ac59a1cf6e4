#pragma once
// Two network namespaces made by a PROFINET test ("hosts"), joined by a veth pair that never exists in the
// machine's own namespace, deleted with the object. Shared by the namespace tests of tests/profinet: nothing
// is sent unless each namespace is checked to hold only lo and its own veth end.
#include <fcntl.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "tomc/profinet/io_device.hpp"
#include "tomc/profinet/sockets.hpp"

namespace tomc::profinet::testing {

inline int quiet(const std::string& command) {
  const int raw = std::system((command + " >/dev/null 2>&1").c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

inline std::string output_of(const std::string& command) {
  std::string text;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 1024> chunk{};
    for (std::size_t n; (n = std::fread(chunk.data(), 1, chunk.size(), pipe)) > 0;)
      text.append(chunk.data(), n);
    ::pclose(pipe);
  }
  return text;
}

inline std::uint64_t now_us() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

// Moves the calling thread into a named network namespace (sockets and threads made afterwards live there).
inline bool enter(const std::string& ns) {
  const int fd = ::open(("/var/run/netns/" + ns).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::setns(fd, CLONE_NEWNET) == 0;
  ::close(fd);
  return ok;
}

// Makes the calling thread SCHED_FIFO at `priority`, as a gateway's cyclic thread runs (`fifo_priority`),
// so that other processes' load cannot starve it for a watchdog time; children it forks start as normal
// processes again (SCHED_RESET_ON_FORK). False where the host refuses (no CAP_SYS_NICE).
inline bool real_time(int priority) {
  sched_param param{};
  param.sched_priority = priority;
  return ::pthread_setschedparam(::pthread_self(), SCHED_FIFO | SCHED_RESET_ON_FORK, &param) == 0;
}

// A device host's RPC side, once per loop: answers a pending request and sends the ApplicationReady when due.
inline void serve_device_rpc(IoDevice& device, UdpSocket& udp, std::span<std::uint8_t> buffer,
                             const Ipv4Address& controller) {
  Ipv4Address from{};
  std::uint16_t port = 0;
  if (const std::size_t n = udp.receive(buffer, 0, from, port); n > 0) {
    if (const auto answer = device.on_rpc(buffer.first(n)); !answer.empty()) udp.send_to(answer, from, port);
  }
  if (const auto ready = device.take_application_ready()) udp.send_to(*ready, controller, kPnioUdpPort);
}

// One end of the veth pair: its namespace's interface name, MAC address ("" = the kernel's) and IPv4/prefix.
struct VethEnd {
  std::string interface;
  std::string mac;
  std::string address;  // e.g. "10.217.0.1/24"
};

class Namespaces {
 public:
  // Names get the test's pid appended, so that two test runs on one machine do not meet.
  Namespaces(const std::string& first_name, const std::string& second_name)
      : first(first_name + "-" + std::to_string(::getpid())),
        second(second_name + "-" + std::to_string(::getpid())) {}
  ~Namespaces() {
    for (const std::string* ns : {&first, &second})
      quiet("ip netns del " + *ns);
  }
  Namespaces(const Namespaces&) = delete;
  Namespaces& operator=(const Namespaces&) = delete;

  // Makes both namespaces and the link; "" or why it cannot (the caller skips with that reason).
  std::string make(const VethEnd& a, const VethEnd& b) {
    if (::geteuid() != 0) return "not root: ip netns needs CAP_SYS_ADMIN";
    if (quiet("ip netns add " + first) != 0 || quiet("ip netns add " + second) != 0) {
      return "'ip netns add' failed (no permission or no iproute2)";
    }
    // One shell for the rest (`ip -n` instead of `ip netns exec`: fewer processes, the test stays short).
    const std::string f = "ip -n " + first + " ";
    const std::string s = "ip -n " + second + " ";
    const auto mac = [](const VethEnd& e) { return e.mac.empty() ? std::string() : " address " + e.mac; };
    const std::string script = f + "link add " + a.interface + mac(a) + " type veth peer name " +
                               b.interface + mac(b) + " && " + f + "link set " + b.interface + " netns " +
                               second + " && " + f + "addr add " + a.address + " dev " + a.interface +
                               " && " + s + "addr add " + b.address + " dev " + b.interface + " && " + f +
                               "link set lo up && " + s + "link set lo up && " + f + "link set " +
                               a.interface + " up && " + s + "link set " + b.interface + " up";
    return quiet("sh -c '" + script + "'") == 0 ? std::string{} : "could not set up the veth pair";
  }
  std::set<std::string> interfaces(const std::string& ns) const {
    std::set<std::string> names;
    std::istringstream lines(output_of("ip -n " + ns + " -o link show"));
    for (std::string line; std::getline(lines, line);) {
      const auto colon = line.find(": ");
      if (colon == std::string::npos) continue;
      const std::string name = line.substr(colon + 2, line.find(':', colon + 2) - colon - 2);
      names.insert(name.substr(0, name.find('@')));
    }
    return names;
  }
  bool carrier(const std::string& ns, const std::string& interface) const {
    for (int i = 0; i < 100; ++i) {
      const std::string state = output_of("ip -n " + ns + " -o link show dev " + interface);
      if (state.find("LOWER_UP") != std::string::npos && state.find("NO-CARRIER") == std::string::npos)
        return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
  }

  std::string first;
  std::string second;
};

// A capture of one interface of a namespace into a pcap file by dumpcap (tshark's capture engine, same
// Debian package; it starts much faster than tshark), from construction until stop(). `available()` is false
// where tshark is not installed: the caller skips the check with that reason.
class Capture {
 public:
  static bool available() { return !output_of("command -v tshark && command -v dumpcap").empty(); }
  Capture(const std::string& ns, const std::string& interface, const std::filesystem::path& file)
      : file_(file) {
    pid_ = ::fork();
    if (pid_ == 0) {
      ::execlp("ip", "ip", "netns", "exec", ns.c_str(), "dumpcap", "-q", "-i", interface.c_str(), "-w",
               file.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // dumpcap creates the file once it captures; a little more for the capture filter to be in place.
    for (int i = 0; i < 100 && !std::filesystem::exists(file); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  ~Capture() {
    stop();
    if (std::getenv("TOMC_KEEP_PCAP") == nullptr) std::filesystem::remove(file_);
  }
  Capture(const Capture&) = delete;
  Capture& operator=(const Capture&) = delete;
  // Lets the last frames reach the file, then ends dumpcap (SIGINT: it closes the file properly).
  void stop() {
    if (pid_ <= 0) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::kill(pid_, SIGINT);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  pid_t pid_ = -1;
};

}  // namespace tomc::profinet::testing
