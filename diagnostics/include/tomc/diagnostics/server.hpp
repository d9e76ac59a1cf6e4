#pragma once
// The embedded web server of the diagnostics page: the page, the JSON API and server-sent events
// (docs/diagnostics.md), on the event-driven HTTP server of http_server.hpp (issue 21: a slow client cannot
// block it; a STOP never waits behind reads, exports or event streams). It reads what Diagnostics collected
// and posts panel commands; the cycle never waits for it. A collector thread calls Diagnostics::poll() and
// renders the status once per event period for every client.
//
// Security: listens on 127.0.0.1 unless told otherwise; read-only unless a token is configured; every
// control action (panel, trace, switches) and every trace export needs "Authorization: Bearer <token>";
// requests for a Host other than the bound address, the loopback names and `allowed_hosts` are refused
// (DNS rebinding), also when bound to every address; malformed requests get a 4xx answer and the connection
// is closed.

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/diagnostics/http_server.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace tomc::diagnostics {

struct ServerOptions {
  std::string bind_address = "127.0.0.1";
  int port = 8080;    // 0: any free port (see Server::port())
  std::string token;  // empty: read-only
  std::chrono::milliseconds poll_period{20};
  std::chrono::milliseconds event_period{100};  // server-sent events: 10 Hz
  // Host names (with or without ":port") the server answers besides the bound address and the loopback
  // names, e.g. the machine's name and address when bound to 0.0.0.0 (issue 21).
  std::vector<std::string> allowed_hosts;
  // Connection caps, deadlines, queues (http_server.hpp); max_event_streams there (16 by default).
  http::ServerLimits limits;
  std::string title = "tomc";
  // The real-time runner's statistics (cycles, overruns, jitter), shown in /api/info; optional.
  std::function<techobjects::RunnerStatistics()> runner_statistics;
};

class Server {
 public:
  Server(Diagnostics& diagnostics, ServerOptions options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Binds and starts serving; throws std::runtime_error if the address cannot be bound.
  void start();
  void stop();
  int port() const noexcept;
  std::string url() const;  // http://<address>:<port>/
  // Connections accepted, evicted, refused, timed out; trace exports rendered and answered from the cache.
  struct Statistics {
    http::ServerStatistics http;
    std::uint64_t exports_rendered = 0;
    std::uint64_t exports_cached = 0;
  };
  Statistics statistics() const;
  // What start() printed to stderr about the configuration (e.g. the token travels in clear).
  const std::vector<std::string>& warnings() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The page served at "/" (diagnostics/web/index.html, embedded at build time).
std::string_view web_page() noexcept;

}  // namespace tomc::diagnostics
