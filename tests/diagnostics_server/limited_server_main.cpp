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
  rlimit original{};
  if (::getrlimit(RLIMIT_NOFILE, &original) != 0) return 2;
  rlimit limit{48, original.rlim_max};
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
  // The descriptors back before the threads end: UBSan's vptr check probes memory through a pipe, and with
  // none left it took the event loop's thread state for an object with an invalid vptr when that thread ended
  // ("memory cannot be printed"; 12 of 40 ASan+UBSan runs, stop 32). The test is about serving while
  // exhausted, which it was until here.
  limit.rlim_cur = original.rlim_cur;
  if (::setrlimit(RLIMIT_NOFILE, &limit) != 0) return 3;
  server.stop();
  return 0;
}
