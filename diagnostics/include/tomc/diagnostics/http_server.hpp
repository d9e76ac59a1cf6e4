#pragma once
// A small event-driven HTTP/1.1 server for the diagnostics page (issue 21, docs/decisions.md D1). One thread
// owns every socket (epoll, non-blocking): a slow, idle or hostile connection costs a buffer, never a thread,
// so it cannot hold up anyone else's request. Complete requests are answered on the event thread when the
// answer is ready-made (page, cached status, event streams) or handed to one of three lanes, each its own
// thread with a bounded queue, so that a control request (STOP first) never waits behind reads or exports:
//
//   kInline   on the event thread: must not block (microseconds)
//   kControl  control actions (panel commands); "urgent" requests go to the front of the queue
//   kRead     JSON that is built under the diagnostics reader's lock
//   kExport   trace exports (PNG/CSV): one at a time, at idle priority (ServerLimits::export_priority)
//
// Defences (docs/diagnostics.md "Security and errors"): a total deadline for the request headers and one for
// the whole request, an idle timeout for keep-alive connections, a write timeout, a global and a per-client
// connection cap where a new connection evicts the oldest one that has not sent a complete request (so a
// flood of slow connections cannot lock the engineer out), event streams capped separately, the connection
// closed after every error answer, a listen backlog sized for the caps, bounded bodies (Content-Length and
// chunked alike: 413), TCP_NODELAY.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tomc::diagnostics::http {

struct Limits {
  std::size_t max_header_bytes = 8 * 1024;  // request line + headers
  std::size_t max_body_bytes = 64 * 1024;   // after de-chunking
  // On the wire, chunk framing included: a body sent in 1-byte chunks must not cost megabytes of buffer.
  std::size_t max_request_bytes() const noexcept { return max_header_bytes + 2 * max_body_bytes + 4096; }
};

struct Request {
  std::string method;
  std::string target;  // as sent: path and query
  std::string path;
  std::string query;
  int minor_version = 1;                                     // HTTP/1.<minor_version>
  std::vector<std::pair<std::string, std::string>> headers;  // names in lower case
  std::string body;
  std::string client;                 // the peer's address
  std::vector<std::string> captures;  // the "{}" segments of the route that matched

  // The value of a header (name in lower case); empty when absent.
  std::string_view header(std::string_view lower_case_name) const noexcept;
  bool has_param(std::string_view name) const;
  // A query parameter, percent-decoded; empty when absent.
  std::string param(std::string_view name) const;
};

struct Response {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  // Instead of `body`: a body shared with a cache (trace exports), sent without a copy per request.
  std::shared_ptr<const std::string> shared_body;
  std::vector<std::pair<std::string, std::string>> headers;
  // The connection becomes a server-sent event stream (text/event-stream); `body` is ignored.
  bool event_stream = false;
};

// Incremental request parser. parse() is called with the connection's input from the request's first byte
// each time more bytes arrived; it resumes where it stopped, so a request trickled byte by byte costs linear
// time. Refuses with 400 (malformed), 413 (body too large, Content-Length or chunked), 431 (headers too
// large), 501 (a transfer coding other than chunked), 505 (not HTTP/1.x).
class RequestParser {
 public:
  enum class State { kIncomplete, kComplete, kError };
  explicit RequestParser(Limits limits = {}) : limits_(limits) {}

  State parse(std::string_view input);
  bool headers_complete() const noexcept { return header_end_ != 0; }
  bool expects_continue() const noexcept { return expects_continue_; }
  Request& request() noexcept { return request_; }
  std::size_t consumed() const noexcept { return position_; }  // on kComplete: bytes of this request
  int error_status() const noexcept { return error_status_; }
  const std::string& error_message() const noexcept { return error_message_; }
  void reset();

 private:
  enum class Body : std::uint8_t { kNone, kLength, kChunkSize, kChunkData, kChunkEnd, kTrailers };
  State fail(int status, std::string message);
  State parse_head(std::string_view head);
  State parse_body(std::string_view input);
  State parse_body_bytes(std::string_view input);

  Limits limits_;
  Request request_;
  std::size_t scanned_ = 0;     // bytes searched for the end of the headers
  std::size_t header_end_ = 0;  // 0: headers not complete
  std::size_t position_ = 0;    // next unparsed byte of the body
  Body body_ = Body::kNone;
  std::size_t remaining_ = 0;  // bytes of the Content-Length body or of the current chunk
  std::size_t trailer_bytes_ = 0;
  bool expects_continue_ = false;
  State state_ = State::kIncomplete;
  int error_status_ = 0;
  std::string error_message_;
};

enum class Lane { kInline, kControl, kRead, kExport };

struct ServerLimits {
  Limits request;
  std::size_t max_connections = 512;  // all clients; the listen backlog is twice this (at least 128)
  std::size_t max_connections_per_client = 256;  // one peer address
  std::size_t max_event_streams = 16;
  std::chrono::milliseconds header_timeout{2000};   // first byte of a request -> end of its headers
  std::chrono::milliseconds request_timeout{5000};  // first byte of a request -> end of its body
  std::chrono::milliseconds idle_timeout{5000};     // a keep-alive connection without a request
  std::chrono::milliseconds write_timeout{5000};    // an answer not read on by the client
  std::size_t max_event_backlog = 512 * 1024;       // unsent event-stream bytes before it is closed
  std::size_t control_queue = 64;
  std::size_t read_queue = 64;
  std::size_t export_queue = 32;
  // kIdle (default): the export lane runs SCHED_IDLE, so a render never delays a cycle of a runner without
  // SCHED_FIFO, but on a machine that is never idle an export waits for spare CPU, possibly for minutes.
  // kNormal: the server's own scheduling, for a runtime whose cycle runs SCHED_FIFO (a render cannot delay
  // it) or a machine that is always busy (decision V13).
  enum class ExportPriority : std::uint8_t { kIdle, kNormal };
  ExportPriority export_priority = ExportPriority::kIdle;
};

struct ServerStatistics {
  std::uint64_t accepted = 0;
  std::uint64_t evicted = 0;    // closed to make room for a new connection
  std::uint64_t refused = 0;    // new connections closed at once (caps reached, nothing to evict)
  std::uint64_t timed_out = 0;  // header, request, idle or write deadline
  std::uint64_t errors = 0;     // answers >= 400 (the connection was closed after each)
  std::uint64_t busy = 0;       // 503: a lane's queue was full
  std::size_t open = 0;         // connections now
  std::size_t event_streams = 0;
  std::size_t max_open = 0;  // the most connections open at once
};

class Server {
 public:
  using Handler = std::function<Response(const Request&)>;
  // Runs on the event thread once a request's headers are complete (before its body is read): nullopt lets
  // it go on, a response refuses it (then the connection is closed). Must not block.
  using Gate = std::function<std::optional<Response>(const Request&, Lane)>;

  explicit Server(ServerLimits limits = {});
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Before start(). A pattern is a path whose "{}" segments match [A-Za-z0-9_.]+ (given in captures).
  void route(std::string method, std::string pattern, Lane lane, Handler handler);
  void set_gate(Gate gate);
  // Control requests for which this holds go to the front of the control queue (a STOP).
  void set_urgent(std::function<bool(const Request&)> urgent);
  // The answer to any error without a handler (404, 408, 413, 431, 503, ...), given status and message.
  void set_error_body(std::function<Response(int, std::string_view)> error_body);

  // Binds and listens (port 0: any free port); throws std::runtime_error. Returns the port.
  int bind(const std::string& address, int port);
  void start();
  void stop();

  // Any thread: one event for every event stream (the text after "data: ").
  void publish(std::shared_ptr<const std::string> event);
  ServerStatistics statistics() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

std::string_view reason_phrase(int status) noexcept;

}  // namespace tomc::diagnostics::http
