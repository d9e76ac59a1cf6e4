// Issue 21: a slow or hostile client on the machine must not block the diagnostics server — above all not
// the STOP of the engineer who holds an axis. The issue measured, on the cpp-httplib server: 30 connections
// trickling one header line every 4 s blocked every request for 60 s; 200 event streams left 160 unanswered;
// a STOP sent during the attack was answered 26 s later. Here 200 slow or idle connections (slowloris
// trickling headers, idle keep-alives, unread event streams) are held open on loopback while an
// authenticated STOP is sent: it must be answered by the cycle ("accepted" comes from the cycle itself, so
// the STOP was acted on); its latency is measured by `bench/stop_under_attack`. Every attack is bounded in
// connections and time and ends by itself; the attack and the served machine are in attack.hpp.
//
// Run serially (CMake RUN_SERIAL): 200 connections and a real-time runner per test.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "attack.hpp"
#include "build_paths.hpp"
#include "tomc/diagnostics/http_server.hpp"
#include "tomc/diagnostics/server.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace {

using namespace tomc;
using Json = nlohmann::json;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

using namespace tomc::testing::http_attack;

// The requirement of issue 21: under 200 slow or idle connections an authenticated STOP is answered and acted
// on. Five STOPs are sent during the attack, each answered "accepted" (the cycle's own answer to the queued
// command) within 3 s: the old server answered none of five within 3 s (decision D1). The latency itself
// (issue 21: within 100 ms) is a speed and is measured by `bench/stop_under_attack` (docs/performance.md),
// not here (docs/reliability.md §5: a timed check failed in the project's CI).
TEST(ServerAbuse, StopGetsThroughUnder200SlowAndIdleConnections) {
  Held h;
  ASSERT_TRUE(h.turn());
  {
    Attack attack(h.server->port(), 70, 70, 60);
    EXPECT_EQ(attack.failed_connects(), 0);
    // The server has taken every connection (the attack is in place) before the STOPs are timed.
    EXPECT_TRUE(eventually([&] { return h.server->statistics().http.accepted >= 200; }));
    std::vector<double> latencies;
    for (int i = 0; i < 5; ++i) {
      const Timed stop = h.panel("stop", {{"maximum", true}}, 3000ms);
      EXPECT_EQ(stop.status, 200) << "STOP " << i << " not answered within 3 s";
      EXPECT_EQ(stop.body.is_object() ? stop.body.value("answer", "") : "", "accepted");
      latencies.push_back(stop.ms);
      std::this_thread::sleep_for(50ms);
    }
    // Reading goes on as well: the page's status is answered during the attack.
    const Timed status = timed_request(h.server->port(), "GET", "/api/status", "", nullptr, 3000ms);
    EXPECT_EQ(status.status, 200);
    std::printf("STOP latency under 200 slow/idle connections (ms):");
    for (const double ms : latencies)
      std::printf(" %.1f", ms);
    std::printf("; /api/status %.1f ms\n", status.ms);
    // The 60 event streams got 16 (the cap) and 503 for the rest; /api/info shows the server's counters.
    EXPECT_LE(h.server->statistics().http.event_streams, 16u);
    const Timed info = timed_request(h.server->port(), "GET", "/api/info", "", nullptr, 3000ms);
    ASSERT_EQ(info.status, 200);
    EXPECT_GE(info.body["server"].value("accepted", 0), 200);
    EXPECT_EQ(info.body["server"].value("event_streams", 0), 16);
  }
  // Acted on: the panel's motion is a stop (or already none) and the speed setpoint falls to 0.
  const auto deadline = Clock::now() + 5s;
  Json last;
  while (Clock::now() < deadline) {
    last = h.status();
    if (last.is_object() && last.value(Json::json_pointer("/objects/0/panel/motion"), "") == "none" &&
        last.value(Json::json_pointer("/objects/0/panel/held"), false))
      break;
    std::this_thread::sleep_for(20ms);
  }
  ASSERT_TRUE(last.is_object());
  EXPECT_EQ(last["objects"][0]["panel"]["motion"], "none");
  EXPECT_EQ(last["objects"][0]["panel"]["held"], true);  // STOP, not a lifebeat expiry
}

// Total header deadline (issue 21: a header line every 4 s kept the old server's worker for ever): a client
// that trickles header lines is answered 408 and closed when the header deadline (here 300 ms) is over,
// although it keeps sending.
TEST(ServerAbuse, TrickledHeadersEndAtTheDeadline) {
  diagnostics::ServerOptions options;
  options.limits.header_timeout = 300ms;
  Held h(options);
  const int fd = connect_to(h.server->port());
  ASSERT_GE(fd, 0);
  ASSERT_TRUE(send_all(fd, "GET /api/status HTTP/1.1\r\nHost: 127.0.0.1\r\n"));
  std::string answer;
  bool closed = false;
  for (int line = 0; line < 30 && !closed; ++line) {  // 3 s of trickling at most
    ::send(fd, "X-Slow: 1\r\n", 11, MSG_NOSIGNAL);
    answer += receive(fd, 100ms, [](const std::string&) { return false; });
    pollfd p{fd, POLLIN, 0};
    char c;
    closed = ::poll(&p, 1, 0) > 0 && ::recv(fd, &c, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
  }
  ::close(fd);
  EXPECT_EQ(status_of(answer), 408) << answer;
  EXPECT_TRUE(closed) << "the server kept a connection that never finished its headers";
  EXPECT_GE(h.server->statistics().http.timed_out, 1u);
}

// Connection caps (global 32, per client 16): 100 idle and slow connections from this machine do not raise
// the open connections above the caps (each new one evicts the oldest that holds no complete request), and
// the engineer's STOP still gets through.
// Decision D2 (at the caps a new connection evicts the oldest that holds no complete request).
TEST(ServerAbuse, CapsEvictTheOldestIncompleteConnections) {
  diagnostics::ServerOptions options;
  options.limits.max_connections = 32;
  options.limits.max_connections_per_client = 16;
  Held h(options);
  ASSERT_TRUE(h.turn());
  {
    const auto start = Clock::now();
    Attack attack(h.server->port(), 50, 50, 0);
    // Every connection taken (and kept, evicted since or refused at once) before the STOP.
    EXPECT_TRUE(eventually([&] { return h.server->statistics().http.accepted >= 100; }));
    const auto t0 = Clock::now();
    const Timed stop = h.panel("stop", {{"maximum", true}});
    std::printf("attack set-up %.0f ms, STOP %.1f ms\n",
                std::chrono::duration<double, std::milli>(t0 - start).count(), stop.ms);
    EXPECT_EQ(stop.status, 200);
    EXPECT_EQ(stop.body.is_object() ? stop.body.value("answer", "") : "", "accepted");
    const auto stats = h.server->statistics().http;
    EXPECT_LE(stats.max_open, 32u);
    EXPECT_GE(stats.evicted, 100u - 16u);
  }
}

// Chunked request bodies are bounded like any other (413), and the connection is closed after the error;
// a small chunked body is taken.
// Decision W14 (bodies ≤ 64 KiB: 413), decision D3 (every error answer closes the connection).
TEST(ServerAbuse, ChunkedBodiesAreBounded) {
  Held h;
  const std::string head = "POST /api/panel/Axis1 HTTP/1.1\r\nHost: 127.0.0.1\r\nAuthorization: Bearer " +
                           std::string(kToken) + "\r\nTransfer-Encoding: chunked\r\n\r\n";
  {
    const int fd = connect_to(h.server->port());
    ASSERT_GE(fd, 0);
    send_all(fd, head);
    const std::string chunk = "1000\r\n" + std::string(0x1000, ' ') + "\r\n";  // 4 KiB each
    for (int i = 0; i < 18; ++i)                                               // 72 KiB > 64 KiB
      if (!send_all(fd, chunk)) break;
    const std::string answer = receive(fd, 3000ms, [](const std::string&) { return false; });  // until closed
    EXPECT_EQ(status_of(answer), 413) << answer.substr(0, 200);
    EXPECT_NE(answer.find("Connection: close"), std::string::npos);
    ::close(fd);
  }
  {
    const int fd = connect_to(h.server->port());
    ASSERT_GE(fd, 0);
    const std::string body =
        R"({"command":"take","session":")" + std::string(kSession) + R"(","lifebeat_s":5})";
    send_all(fd, head + "5\r\n" + body.substr(0, 5) + "\r\n" + std::to_string(0) + "\r\n\r\n");
    const std::string answer = receive(fd, 3000ms, complete_response);
    EXPECT_EQ(status_of(answer), 400) << answer;  // 5 bytes of JSON: malformed, refused by the API
    ::close(fd);
  }
  {
    const int fd = connect_to(h.server->port());
    ASSERT_GE(fd, 0);
    const std::string body =
        R"({"command":"take","session":")" + std::string(kSession) + R"(","lifebeat_s":5})";
    char size[16];
    std::snprintf(size, sizeof size, "%zx", body.size() - 10);
    send_all(fd, head + size + "\r\n" + body.substr(0, body.size() - 10) + "\r\na\r\n" +
                     body.substr(body.size() - 10) + "\r\n0\r\n\r\n");
    const std::string answer = receive(fd, 3000ms, complete_response);
    EXPECT_EQ(status_of(answer), 200) << answer;
    ::close(fd);
  }
}

// After an error the server closes the connection; after a success it keeps it (keep-alive).
// Decision D3 (every error answer closes the connection; keep-alive otherwise).
TEST(ServerAbuse, ConnectionsCloseAfterErrorsOnly) {
  Held h;
  const int port = h.server->port();
  {
    const int fd = connect_to(port);
    send_all(fd, "GET /api/nothing HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    const std::string answer = receive(fd, 3000ms, [](const std::string&) { return false; });  // until closed
    EXPECT_EQ(status_of(answer), 404);
    EXPECT_TRUE(complete_response(answer));
    ::close(fd);
  }
  {
    const int fd = connect_to(port);
    send_all(fd, "NOT HTTP AT ALL\r\n\r\n");
    const std::string answer = receive(fd, 3000ms, [](const std::string&) { return false; });
    EXPECT_EQ(status_of(answer), 400);
    ::close(fd);
  }
  {
    const int fd = connect_to(port);
    const std::string get = "GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
    send_all(fd, get);
    const std::string first = receive(fd, 3000ms, complete_response);
    EXPECT_EQ(status_of(first), 200);
    send_all(fd, get + get);  // the same connection, two requests pipelined
    const std::string both = receive(fd, 3000ms, [](const std::string& t) { return responses_in(t) == 2; });
    EXPECT_EQ(responses_in(both), 2);
    EXPECT_EQ(status_of(both), 200);
    ::close(fd);
  }
}

// Issue 21: 24 parallel trace.png requests of a large trace cost about 66 % of the servo cycles and 2.3 GB.
// Exports now need the token, are rendered one at a time and cached: 24 requests for the same picture are one
// render. Overruns of the 1 ms cycle are printed for an idle second and for the requests (not asserted: this
// machine's load is not the server's). Normal priority here: at SCHED_IDLE (the default, D4; tested in
// api_test.cpp) a busy CI machine starved the render for minutes (decision V13).
TEST(ServerAbuse, ParallelTraceExportsRenderOnce) {
  diagnostics::ServerOptions options;
  options.limits.export_priority = diagnostics::http::ServerLimits::ExportPriority::kNormal;
  Held h(options);
  const int port = h.server->port();
  const Json request = {
      {"channels", {"Axis1.Velocity", "Axis1.telegram.drive.NIST_B", "Axis1.StatusWord.X12"}},
      {"trigger", {{"kind", "immediate"}}},
      {"post_samples", 2000}};
  ASSERT_EQ(timed_request(port, "POST", "/api/trace", request.dump(), kToken, 3000ms).status, 200);
  const auto deadline = Clock::now() + 10s;
  while (Clock::now() < deadline &&
         h.status().value(Json::json_pointer("/trace/state"), std::string()) != "complete")
    std::this_thread::sleep_for(50ms);
  ASSERT_EQ(h.status().value(Json::json_pointer("/trace/state"), std::string()), "complete");
  EXPECT_EQ(timed_request(port, "GET", "/api/trace.png", "", nullptr, 3000ms).status, 401);

  const auto idle_before = h.runner.statistics().overruns;
  std::this_thread::sleep_for(1s);
  const auto idle = h.runner.statistics().overruns - idle_before;

  const auto before = h.runner.statistics().overruns;
  const auto start = Clock::now();
  std::vector<int> statuses(24, 0);
  std::vector<std::thread> clients;
  for (int i = 0; i < 24; ++i) {
    clients.emplace_back([&, i] {
      statuses[static_cast<std::size_t>(i)] =
          timed_request(port, "GET", "/api/trace.png?width=4000&height=3000", "", kToken, 60000ms).status;
    });
  }
  for (auto& t : clients)
    t.join();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const auto during = h.runner.statistics().overruns - before;
  std::printf(
      "servo overruns: %llu in 1 s idle; %llu in %.2f s of 24 parallel trace.png (4000x3000), %.0f per s\n",
      static_cast<unsigned long long>(idle), static_cast<unsigned long long>(during), seconds,
      static_cast<double>(during) / seconds);
  for (const int status : statuses)
    EXPECT_EQ(status, 200);
  const auto stats = h.server->statistics();
  EXPECT_EQ(stats.exports_rendered, 1u);
  EXPECT_EQ(stats.exports_cached, 23u);
}

// "Control requests (STOP first)": while a control request is being handled, further ones wait in the control
// queue; an urgent one (a STOP) is taken before those that came earlier. Reads and event streams have their
// own lanes, so a blocked read does not hold up control either.
// Decision D1 (bounded lanes; the control lane takes STOP/disable first).
TEST(ServerAbuse, UrgentControlRequestsGoFirst) {
  diagnostics::http::Server http;
  std::mutex mutex;
  std::condition_variable cv;
  bool release = false;
  std::vector<std::string> order;
  const auto blocking = [&](const diagnostics::http::Request& r) {
    std::unique_lock lock(mutex);
    order.push_back(r.body);
    cv.wait(lock, [&] { return release; });
    return diagnostics::http::Response{};
  };
  http.route("POST", "/control", diagnostics::http::Lane::kControl, blocking);
  http.route("GET", "/read", diagnostics::http::Lane::kRead, blocking);
  std::atomic<int> queued{0};  // the urgency is asked once per control request, as it is queued
  http.set_urgent([&](const diagnostics::http::Request& r) {
    ++queued;
    return r.body.starts_with("stop");
  });
  const int port = http.bind("127.0.0.1", 0);
  http.start();
  const auto post = [&](const std::string& body) {
    return std::thread([port, body] { timed_request(port, "POST", "/control", body, nullptr, 5000ms); });
  };
  const auto wait_for = [&](std::size_t n) {
    return eventually([&] {
      std::lock_guard lock(mutex);
      return order.size() >= n;
    });
  };
  std::vector<std::thread> clients;
  clients.push_back(std::thread([port] { timed_request(port, "GET", "/read", "", nullptr, 5000ms); }));
  EXPECT_TRUE(wait_for(1));  // the read lane is busy
  clients.push_back(post("first"));
  EXPECT_TRUE(wait_for(2));  // the control lane is busy with "first"
  const auto queued_reaches = [&](int n) {
    const auto deadline = Clock::now() + 5s;
    while (queued.load() < n && Clock::now() < deadline)
      std::this_thread::sleep_for(2ms);
    return queued.load() >= n;
  };
  int n = 1;
  for (const char* body : {"a", "stop1", "b", "c", "stop2"}) {  // queued in this order, one after the other
    clients.push_back(post(body));
    if (!queued_reaches(++n)) {
      ADD_FAILURE() << "'" << body << "' was not queued";
      break;
    }
  }
  {
    std::lock_guard lock(mutex);
    release = true;
  }
  cv.notify_all();
  for (auto& t : clients)
    t.join();
  http.stop();
  // STOPs first, among them first come first served; then the others in their order.
  const std::vector<std::string> expected = {"", "first", "stop1", "stop2", "a", "b", "c"};
  EXPECT_EQ(order, expected);
}

// Out of file descriptors (connections beyond the process' RLIMIT_NOFILE): the server evicts the oldest
// incomplete connection to take the new one, instead of leaving the new ones in the backlog until an idle
// connection times out (5 s) and spinning on a listener that stays readable. The server runs in a process of
// its own limited to 48 descriptors (limited_server_main.cpp); it ends when the test closes its stdin, at the
// latest after 10 s.
// Decision D2 (out of descriptors, EMFILE, the same eviction makes room).
TEST(ServerAbuse, OutOfDescriptorsTheNewestConnectionIsServed) {
  int to_child[2], from_child[2];
  ASSERT_EQ(::pipe2(to_child, O_CLOEXEC), 0);
  ASSERT_EQ(::pipe2(from_child, O_CLOEXEC), 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, to_child[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, from_child[1], STDOUT_FILENO);
  std::string program = TOMC_LIMITED_SERVER;
  char* path = program.data();
  char* argv[] = {path, nullptr};
  pid_t child = 0;
  const int spawned = ::posix_spawn(&child, path, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(to_child[0]);
  ::close(from_child[1]);
  ASSERT_EQ(spawned, 0);
  std::string line;  // the child's port, from a pipe (read, not recv)
  for (char c = 0; line.size() < 16 && c != '\n';) {
    pollfd p{from_child[0], POLLIN, 0};
    if (::poll(&p, 1, 5000) <= 0 || ::read(from_child[0], &c, 1) != 1) break;
    line.push_back(c);
  }
  const int port = std::atoi(line.c_str());
  EXPECT_GT(port, 0) << line;
  std::vector<int> idle;
  for (int i = 0; port > 0 && i < 60; ++i) {  // more than the child has descriptors for
    const int fd = connect_to(port);
    if (fd >= 0) idle.push_back(fd);
  }
  std::this_thread::sleep_for(100ms);
  if (port > 0) {
    const Timed ping = timed_request(port, "GET", "/ping", "", nullptr, 2000ms);
    EXPECT_EQ(ping.status, 200) << "not answered within 2 s with the descriptors exhausted";
    std::printf("/ping with the server's descriptors exhausted: %.1f ms\n", ping.ms);
  }
  for (const int fd : idle)
    ::close(fd);
  ::close(to_child[1]);  // the child's stdin ends: it stops
  ::close(from_child[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

}  // namespace
