#pragma once
// Issue 21's attack on the diagnostics server, shared by the abuse tests
// (tests/diagnostics_server/abuse_test.cpp) and the STOP-latency benchmark (bench/stop_under_attack.cpp):
// loopback HTTP helpers, the bounded attack of slow, idle and event-stream connections, and a speed axis
// turning under the panel's master control, served in real time (1 ms) as in `tomc demo`.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "../diagnostics/diagnostics_fixture.hpp"
#include "tomc/diagnostics/server.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace tomc::testing::http_attack {

using Json = nlohmann::json;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

inline constexpr const char* kToken = "s3cret-t0ken";
inline constexpr const char* kSession = "00000000c0ffee01";

// Polls `condition` every 5 ms until it holds or `bound` passes (a fixed sleep instead was too short when the
// machine was busy, issue 22); returns whether it held.
template <typename Condition>
inline bool eventually(Condition condition, std::chrono::milliseconds bound = 10000ms) {
  const auto deadline = Clock::now() + bound;
  while (!condition()) {
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(5ms);
  }
  return true;
}

// A loopback TCP connection to `port` (blocking connect; -1 on failure).
inline int connect_to(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

inline bool send_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

// Reads until the peer closes, `until` returns true for what was read, or `timeout` passes.
template <typename Until>
inline std::string receive(int fd, std::chrono::milliseconds timeout, Until until) {
  std::string got;
  const auto deadline = Clock::now() + timeout;
  char buffer[4096];
  while (!until(got)) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) break;
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    got.append(buffer, static_cast<std::size_t>(n));
  }
  return got;
}

// Whether a response with a Content-Length body is complete in `text`.
inline bool complete_response(const std::string& text) {
  const std::size_t end = text.find("\r\n\r\n");
  if (end == std::string::npos) return false;
  std::string head = text.substr(0, end);
  std::transform(head.begin(), head.end(), head.begin(), [](unsigned char c) { return std::tolower(c); });
  const std::size_t cl = head.find("content-length:");
  if (cl == std::string::npos) return true;
  const std::size_t length = std::strtoul(head.c_str() + cl + 15, nullptr, 10);
  return text.size() >= end + 4 + length;
}

// How many complete responses with a Content-Length body `text` holds, one after the other.
inline int responses_in(std::string_view text) {
  int count = 0;
  while (complete_response(std::string(text))) {
    const std::size_t end = text.find("\r\n\r\n");
    std::string head(text.substr(0, end));
    std::transform(head.begin(), head.end(), head.begin(), [](unsigned char c) { return std::tolower(c); });
    const std::size_t cl = head.find("content-length:");
    const std::size_t length =
        cl == std::string::npos ? 0 : std::strtoul(head.c_str() + cl + 15, nullptr, 10);
    text.remove_prefix(end + 4 + length);
    ++count;
  }
  return count;
}

inline int status_of(const std::string& response) {
  if (response.rfind("HTTP/1.", 0) != 0 || response.size() < 12) return 0;
  return std::atoi(response.c_str() + 9);
}

inline std::string body_of(const std::string& response) {
  const std::size_t end = response.find("\r\n\r\n");
  return end == std::string::npos ? std::string() : response.substr(end + 4);
}

struct Timed {
  int status = 0;  // 0: no answer within the timeout
  Json body;
  double ms = 0.0;
};

// One request on a new connection, timed from connect to the complete answer.
inline Timed timed_request(int port, const std::string& method, const std::string& path,
                           const std::string& body, const char* token, std::chrono::milliseconds timeout) {
  const auto start = Clock::now();
  Timed t;
  const int fd = connect_to(port);
  if (fd < 0) return t;
  std::string request = method + " " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n";
  if (token != nullptr) request += std::string("Authorization: Bearer ") + token + "\r\n";
  if (method == "POST") {
    request += "Content-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) + "\r\n";
  }
  request += "Connection: close\r\n\r\n" + body;
  if (send_all(fd, request)) {
    const std::string response = receive(fd, timeout, complete_response);
    t.status = complete_response(response) ? status_of(response) : 0;
    t.body = Json::parse(body_of(response), nullptr, false);
  }
  t.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  ::close(fd);
  return t;
}

// The attack: `slow` connections trickling one header line every `trickle` (a request never completes),
// `idle` keep-alive connections that asked once and then say nothing, and `streams` event streams that are
// never read. Bounded: it ends when the object is destroyed, and at the latest after `lifetime`.
class Attack {
 public:
  Attack(int port, int slow, int idle, int streams, std::chrono::milliseconds trickle = 1000ms,
         std::chrono::seconds lifetime = 30s)
      : port_(port) {
    const std::string host = "Host: 127.0.0.1:" + std::to_string(port) + "\r\n";
    for (int i = 0; i < slow + idle + streams; ++i) {
      const int fd = connect_to(port);
      if (fd < 0) {
        ++failed_connects_;
        continue;
      }
      if (i < slow) {
        send_all(fd, "POST /api/panel/Axis1 HTTP/1.1\r\n" + host);
        slow_.push_back(fd);
      } else if (i < slow + idle) {
        send_all(fd, "GET /api/info HTTP/1.1\r\n" + host + "\r\n");
        others_.push_back(fd);
      } else {
        send_all(fd, "GET /api/events HTTP/1.1\r\n" + host + "\r\n");
        others_.push_back(fd);
      }
    }
    trickler_ = std::thread([this, trickle, lifetime] {
      const auto end = Clock::now() + lifetime;
      int line = 0;
      while (!done_.load() && Clock::now() < end) {
        for (const int fd : slow_) {
          const std::string header = "X-Slow-" + std::to_string(line) + ": x\r\n";
          ::send(fd, header.data(), header.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
        }
        ++line;
        const auto next = Clock::now() + trickle;
        while (!done_.load() && Clock::now() < next)
          std::this_thread::sleep_for(10ms);
      }
    });
  }
  ~Attack() {
    done_.store(true);
    trickler_.join();
    for (const int fd : slow_)
      ::close(fd);
    for (const int fd : others_)
      ::close(fd);
  }
  int failed_connects() const { return failed_connects_; }
  // How many of the slow connections the server has closed by now (read returns 0 or an error).
  int slow_closed_by_server() const {
    int closed = 0;
    for (const int fd : slow_) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 0) > 0) {
        char c;
        const ssize_t n = ::recv(fd, &c, 1, MSG_PEEK | MSG_DONTWAIT);
        if (n == 0 || (n < 0 && errno != EAGAIN)) ++closed;
        if (n > 0) ++closed;  // the server answered (e.g. 408) and will close
      }
    }
    return closed;
  }

 private:
  int port_;
  std::vector<int> slow_;
  std::vector<int> others_;
  int failed_connects_ = 0;
  std::atomic<bool> done_{false};
  std::thread trickler_;
};

// A speed axis turning under the panel's master control, served in real time (1 ms), as in `tomc demo`.
struct Held {
  explicit Held(diagnostics::ServerOptions options = {})
      : machine(1, diagnostics::DiagnosticsConfig{5, 4096, 500}) {
    options.port = 0;
    options.token = kToken;
    options.runner_statistics = [this] { return runner.statistics(); };
    server = std::make_unique<diagnostics::Server>(machine.diagnostics, options);
    server->start();
    runner.start();
  }
  ~Held() {
    server->stop();
    runner.stop();
  }
  Timed panel(const std::string& command, Json extra = Json::object(),
              std::chrono::milliseconds timeout = 3000ms) const {
    extra["command"] = command;
    extra["session"] = kSession;
    return timed_request(server->port(), "POST", "/api/panel/Axis1", extra.dump(), kToken, timeout);
  }
  Json status() const {
    return timed_request(server->port(), "GET", "/api/status", "", nullptr, 3000ms).body;
  }
  // Takes master control (lifebeat 30 s: longer than the attack), enables, turns forwards; whether every
  // command was answered 200.
  [[nodiscard]] bool turn() const {
    if (panel("take", {{"lifebeat_s", 30.0}}).status != 200 || panel("enable").status != 200) return false;
    const auto deadline = Clock::now() + 5s;
    while (Clock::now() < deadline) {
      const Json s = status();
      if (s.is_object() && s.value(Json::json_pointer("/objects/0/panel/instructions/0/active"), false))
        break;
      std::this_thread::sleep_for(20ms);
    }
    return panel("velocity", {{"direction", 1}}).status == 200;
  }

  tomc::testing::DiagnosticsMachine machine;
  techobjects::RealTimeRunner runner{techobjects::RealTimeRunnerConfig{1ms, 0, false},
                                     [this] { machine.runtime.step(); }};
  std::unique_ptr<diagnostics::Server> server;
};

}  // namespace tomc::testing::http_attack
