#pragma once
// The embedded web server of the diagnostics page (cpp-httplib): the page, the JSON API and server-sent
// events (docs/diagnostics.md). It reads what Diagnostics collected and posts panel commands; the cycle never
// waits for it. A collector thread calls Diagnostics::poll() and renders the status once per event period for
// every client.
//
// Security: listens on 127.0.0.1 unless told otherwise; read-only unless a token is configured; every
// control action (panel, trace, switches) needs "Authorization: Bearer <token>"; requests for another Host
// than the bound address are refused (DNS rebinding); malformed requests get a 4xx answer.

#include <chrono>
#include <functional>
#include <memory>
#include <string>

#include "tomc/diagnostics/diagnostics.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace tomc::diagnostics {

struct ServerOptions {
  std::string bind_address = "127.0.0.1";
  int port = 8080;    // 0: any free port (see Server::port())
  std::string token;  // empty: read-only
  std::chrono::milliseconds poll_period{20};
  std::chrono::milliseconds event_period{100};  // server-sent events: 10 Hz
  std::size_t max_event_streams = 16;
  std::size_t worker_threads = 24;  // > max_event_streams: each open stream holds one worker
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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The page served at "/" (diagnostics/web/index.html, embedded at build time).
std::string_view web_page() noexcept;

}  // namespace tomc::diagnostics
