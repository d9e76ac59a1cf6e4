// A helper of abuse_test.cpp (ServerAbuse.OutOfDescriptorsTheNewestConnectionIsServed): an HTTP server with
// GET /ping in a process limited to 48 file descriptors. Prints its port on stdout, serves until stdin is
// closed (the test ends) or 10 s passed, then exits. A process of its own, started with posix_spawn: the
// descriptor limit must not touch the test, and a fork of the multi-threaded test process would inherit its
// locks.
#include <poll.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>

#include "tomc/diagnostics/http_server.hpp"

int main() {
  rlimit limit{48, 48};
  if (::setrlimit(RLIMIT_NOFILE, &limit) != 0) return 2;
  namespace http = tomc::diagnostics::http;
  http::Server server;
  server.route("GET", "/ping", http::Lane::kInline, [](const http::Request&) {
    http::Response r;
    r.body = "pong";
    return r;
  });
  const int port = server.bind("127.0.0.1", 0);
  server.start();
  std::printf("%d\n", port);
  std::fflush(stdout);
  pollfd in{STDIN_FILENO, POLLIN, 0};
  ::poll(&in, 1, 10000);  // readable (EOF) when the test closes its end
  server.stop();
  return 0;
}
