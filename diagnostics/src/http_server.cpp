// The event-driven HTTP/1.1 server (http_server.hpp, docs/decisions.md D1).
#include "tomc/diagnostics/http_server.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <pthread.h>
#include <sched.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unordered_map>

namespace tomc::diagnostics::http {

namespace {

using Clock = std::chrono::steady_clock;

char lower(char c) noexcept {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

bool token_char(char c) noexcept {
  if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')) return true;
  return std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
}

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
    s.remove_suffix(1);
  return s;
}

int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string percent_decode(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size() && hex_value(s[i + 1]) >= 0 && hex_value(s[i + 2]) >= 0) {
      out.push_back(static_cast<char>(hex_value(s[i + 1]) * 16 + hex_value(s[i + 2])));
      i += 2;
    } else {
      out.push_back(s[i] == '+' ? ' ' : s[i]);
    }
  }
  return out;
}

// Splits the query into (name, value) pairs, neither decoded.
template <typename F>
void for_each_param(std::string_view query, F&& f) {
  while (!query.empty()) {
    const std::size_t amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    const std::size_t eq = pair.find('=');
    f(pair.substr(0, eq), eq == std::string_view::npos ? std::string_view() : pair.substr(eq + 1));
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
}

}  // namespace

std::string_view reason_phrase(int status) noexcept {
  switch (status) {
    case 100:
      return "Continue";
    case 200:
      return "OK";
    case 204:
      return "No Content";
    case 400:
      return "Bad Request";
    case 401:
      return "Unauthorized";
    case 403:
      return "Forbidden";
    case 404:
      return "Not Found";
    case 405:
      return "Method Not Allowed";
    case 408:
      return "Request Timeout";
    case 409:
      return "Conflict";
    case 413:
      return "Payload Too Large";
    case 421:
      return "Misdirected Request";
    case 422:
      return "Unprocessable Content";
    case 431:
      return "Request Header Fields Too Large";
    case 500:
      return "Internal Server Error";
    case 501:
      return "Not Implemented";
    case 503:
      return "Service Unavailable";
    case 505:
      return "HTTP Version Not Supported";
    default:
      return "Status";
  }
}

// ---------------------------------------------------------------------------------------------------------
// Request

std::string_view Request::header(std::string_view name) const noexcept {
  for (const auto& [n, v] : headers) {
    if (n == name) return v;
  }
  return {};
}

bool Request::has_param(std::string_view name) const {
  bool found = false;
  for_each_param(query,
                 [&](std::string_view n, std::string_view) { found = found || percent_decode(n) == name; });
  return found;
}

std::string Request::param(std::string_view name) const {
  std::string value;
  bool found = false;
  for_each_param(query, [&](std::string_view n, std::string_view v) {
    if (!found && percent_decode(n) == name) {
      value = percent_decode(v);
      found = true;
    }
  });
  return value;
}

// ---------------------------------------------------------------------------------------------------------
// RequestParser

void RequestParser::reset() {
  request_ = Request{};
  scanned_ = header_end_ = position_ = remaining_ = trailer_bytes_ = 0;
  body_ = Body::kNone;
  expects_continue_ = false;
  state_ = State::kIncomplete;
  error_status_ = 0;
  error_message_.clear();
}

RequestParser::State RequestParser::fail(int status, std::string message) {
  error_status_ = status;
  error_message_ = std::move(message);
  return state_ = State::kError;
}

RequestParser::State RequestParser::parse(std::string_view input) {
  if (state_ != State::kIncomplete) return state_;
  if (header_end_ == 0) {
    const std::size_t from = scanned_ >= 3 ? scanned_ - 3 : 0;
    const std::size_t end = input.find("\r\n\r\n", from);
    if (end == std::string_view::npos) {
      scanned_ = input.size();
      if (input.size() > limits_.max_header_bytes) return fail(431, "request headers larger than 8 KiB");
      return State::kIncomplete;
    }
    if (end + 4 > limits_.max_header_bytes) return fail(431, "request headers larger than 8 KiB");
    header_end_ = end + 4;
    position_ = header_end_;
    if (parse_head(input.substr(0, end)) == State::kError) return state_;
  }
  return parse_body(input);
}

RequestParser::State RequestParser::parse_head(std::string_view head) {
  // Request line: METHOD SP origin-form SP HTTP/1.x
  const std::size_t eol = head.find("\r\n");
  const std::string_view line = head.substr(0, eol);
  const std::size_t sp1 = line.find(' ');
  const std::size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp1 == 0 || sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos)
    return fail(400, "malformed request line");
  const std::string_view method = line.substr(0, sp1);
  const std::string_view target = line.substr(sp1 + 1, sp2 - sp1 - 1);
  const std::string_view version = line.substr(sp2 + 1);
  if (!std::all_of(method.begin(), method.end(), token_char)) return fail(400, "malformed method");
  if (target.empty() || target.front() != '/') return fail(400, "the request target must be a path");
  for (const char c : target) {
    if (static_cast<unsigned char>(c) <= 0x20 || c == 0x7f) return fail(400, "malformed request target");
  }
  if (version.size() != 8 || version.substr(0, 7) != "HTTP/1.") return fail(505, "HTTP/1.x only");
  if (version[7] != '0' && version[7] != '1') return fail(505, "HTTP/1.0 or HTTP/1.1 only");
  request_.method = method;
  request_.target = target;
  request_.minor_version = version[7] - '0';
  const std::size_t q = target.find('?');
  request_.path = target.substr(0, q);
  request_.query = q == std::string_view::npos ? std::string_view() : target.substr(q + 1);

  std::optional<std::size_t> content_length;
  bool chunked = false;
  std::string_view rest = eol == std::string_view::npos ? std::string_view() : head.substr(eol + 2);
  while (!rest.empty()) {
    const std::size_t end = rest.find("\r\n");
    const std::string_view field = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 2);
    if (field.empty() || field.front() == ' ' || field.front() == '\t')
      return fail(400, "malformed header (folded lines are not accepted)");
    const std::size_t colon = field.find(':');
    if (colon == 0 || colon == std::string_view::npos) return fail(400, "malformed header");
    const std::string_view name = field.substr(0, colon);
    if (!std::all_of(name.begin(), name.end(), token_char)) return fail(400, "malformed header name");
    const std::string_view value = trim(field.substr(colon + 1));
    for (const char c : value) {
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
        return fail(400, "control character in a header value");
    }
    std::string lower_name(name);
    std::transform(lower_name.begin(), lower_name.end(), lower_name.begin(), lower);
    if (lower_name == "content-length") {
      std::size_t length = 0;
      const auto [p, e] = std::from_chars(value.data(), value.data() + value.size(), length);
      if (value.empty() || e != std::errc{} || p != value.data() + value.size())
        return fail(400, "malformed Content-Length");
      if (content_length && *content_length != length) return fail(400, "conflicting Content-Length");
      content_length = length;
    } else if (lower_name == "transfer-encoding") {
      std::string coding(value);
      std::transform(coding.begin(), coding.end(), coding.begin(), lower);
      if (coding != "chunked") return fail(501, "only the chunked transfer coding is accepted");
      if (chunked) return fail(400, "repeated Transfer-Encoding");
      chunked = true;
    } else if (lower_name == "expect") {
      std::string expectation(value);
      std::transform(expectation.begin(), expectation.end(), expectation.begin(), lower);
      if (expectation != "100-continue") return fail(400, "unsupported Expect");
      expects_continue_ = true;
    }
    request_.headers.emplace_back(std::move(lower_name), std::string(value));
  }
  if (chunked && content_length) return fail(400, "both Content-Length and Transfer-Encoding");
  if (request_.minor_version == 1 && request_.header("host").empty()) return fail(400, "no Host header");
  if (chunked) {
    body_ = Body::kChunkSize;
  } else if (content_length && *content_length > 0) {
    if (*content_length > limits_.max_body_bytes) return fail(413, "request body larger than 64 KiB");
    body_ = Body::kLength;
    remaining_ = *content_length;
  }
  return State::kIncomplete;
}

RequestParser::State RequestParser::parse_body(std::string_view input) {
  const State state = parse_body_bytes(input);
  // While the request is incomplete every byte of the input is part of it.
  if (state == State::kIncomplete && input.size() > limits_.max_request_bytes())
    return fail(413, "request larger than 64 KiB with its chunk framing");
  return state;
}

RequestParser::State RequestParser::parse_body_bytes(std::string_view input) {
  for (;;) {
    switch (body_) {
      case Body::kNone:
        return state_ = State::kComplete;
      case Body::kLength: {
        const std::size_t take = std::min(remaining_, input.size() - position_);
        request_.body.append(input.substr(position_, take));
        position_ += take;
        remaining_ -= take;
        if (remaining_ != 0) return State::kIncomplete;
        body_ = Body::kNone;
        break;
      }
      case Body::kChunkSize: {
        const std::size_t end = input.find("\r\n", position_);
        if (end == std::string_view::npos) {
          if (input.size() - position_ > 256) return fail(400, "malformed chunk size");
          return State::kIncomplete;
        }
        std::string_view line = input.substr(position_, end - position_);
        line = line.substr(0, line.find(';'));  // chunk extensions are ignored
        line = trim(line);
        std::size_t size = 0;
        const auto [p, e] = std::from_chars(line.data(), line.data() + line.size(), size, 16);
        if (line.empty() || p != line.data() + line.size()) return fail(400, "malformed chunk size");
        if (e != std::errc{} || size > limits_.max_body_bytes ||
            request_.body.size() + size > limits_.max_body_bytes)
          return fail(413, "request body larger than 64 KiB");
        position_ = end + 2;
        remaining_ = size;
        body_ = size == 0 ? Body::kTrailers : Body::kChunkData;
        break;
      }
      case Body::kChunkData: {
        const std::size_t take = std::min(remaining_, input.size() - position_);
        request_.body.append(input.substr(position_, take));
        position_ += take;
        remaining_ -= take;
        if (remaining_ != 0) return State::kIncomplete;
        body_ = Body::kChunkEnd;
        break;
      }
      case Body::kChunkEnd:
        if (input.size() - position_ < 2) return State::kIncomplete;
        if (input.substr(position_, 2) != "\r\n") return fail(400, "malformed chunk");
        position_ += 2;
        body_ = Body::kChunkSize;
        break;
      case Body::kTrailers: {
        const std::size_t end = input.find("\r\n", position_);
        if (end == std::string_view::npos) {
          if (trailer_bytes_ + input.size() - position_ > limits_.max_header_bytes)
            return fail(431, "request trailers larger than 8 KiB");
          return State::kIncomplete;
        }
        trailer_bytes_ += end + 2 - position_;
        if (trailer_bytes_ > limits_.max_header_bytes) return fail(431, "request trailers larger than 8 KiB");
        const bool last = end == position_;
        position_ = end + 2;
        if (last) body_ = Body::kNone;
        break;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
// Server

namespace {

struct Route {
  std::string method;
  std::vector<std::string> segments;  // "{}" matches one name segment
  Lane lane;
  Server::Handler handler;
};

bool name_segment(std::string_view s) noexcept {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
  });
}

std::vector<std::string> split_path(std::string_view path) {
  std::vector<std::string> parts;
  std::size_t start = 1;  // after the leading '/'
  while (start <= path.size()) {
    const std::size_t slash = path.find('/', start);
    parts.emplace_back(path.substr(start, slash == std::string_view::npos ? slash : slash - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return parts;
}

bool matches(const Route& r, const std::vector<std::string>& parts, std::vector<std::string>* captures) {
  if (parts.size() != r.segments.size()) return false;
  std::vector<std::string> found;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (r.segments[i] == "{}") {
      if (!name_segment(parts[i])) return false;
      found.push_back(parts[i]);
    } else if (r.segments[i] != parts[i]) {
      return false;
    }
  }
  if (captures != nullptr) *captures = std::move(found);
  return true;
}

enum class Phase : std::uint8_t {
  kReading,    // waiting for (the rest of) a request; `idle` when none of it came yet
  kHandling,   // a lane works on the request
  kWriting,    // the answer is being sent
  kStreaming,  // an event stream
  kClosing,    // answer sent, write side shut: the rest of the client's bytes are read and dropped
};

struct Connection {
  int fd = -1;
  std::uint64_t id = 0;
  std::string client;
  Phase phase = Phase::kReading;
  bool idle = true;
  bool gated = false;  // the gate saw this request's headers
  bool continue_sent = false;
  bool close_after_write = false;
  Lane lane = Lane::kInline;
  const Route* route = nullptr;
  std::string in;
  std::string out;
  std::size_t out_sent = 0;
  // A large answer body shared with a cache (a trace export), sent after `out` without being copied.
  std::shared_ptr<const std::string> body;
  std::size_t body_sent = 0;
  bool writing() const noexcept { return out_sent < out.size() || body != nullptr; }
  RequestParser parser;
  Clock::time_point since;        // accept, first byte of the request, or end of the previous answer
  Clock::time_point write_since;  // last time bytes of `out` went out (or were queued on an empty `out`)
  std::uint32_t interest = 0;
};

constexpr std::uint64_t kListenerId = 0;
constexpr std::uint64_t kWakeId = 1;

struct Job {
  std::uint64_t connection = 0;
  Request request;
  const Route* route = nullptr;
  bool urgent = false;
};

struct LaneQueue {
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<Job> jobs;
  std::size_t capacity = 0;
  bool stopping = false;
  bool low_priority = false;
  std::thread thread;
};

}  // namespace

struct Server::Impl {
  explicit Impl(ServerLimits l) : limits(l) {
    control.capacity = l.control_queue;
    read.capacity = l.read_queue;
    exports.capacity = l.export_queue;
    exports.low_priority = l.export_priority == ServerLimits::ExportPriority::kIdle;
  }

  ServerLimits limits;
  std::vector<std::unique_ptr<Route>> routes;
  Gate gate;
  std::function<bool(const Request&)> urgent;
  std::function<Response(int, std::string_view)> error_body = [](int status, std::string_view message) {
    Response r;
    r.status = status;
    r.content_type = "text/plain; charset=utf-8";
    r.body = std::string(message);
    return r;
  };

  int listen_fd = -1;
  int epoll_fd = -1;
  int wake_fd = -1;
  std::thread loop_thread;
  std::atomic<bool> running{false};

  std::unordered_map<std::uint64_t, std::unique_ptr<Connection>> connections;
  std::unordered_map<std::string, std::size_t> per_client;
  std::uint64_t next_id = 2;
  std::vector<std::uint64_t> pending_input;  // connections with a buffered request to parse
  std::size_t streams = 0;

  // Lanes -> event thread.
  std::mutex done_mutex;
  std::vector<std::pair<std::uint64_t, Response>> done;
  // Publisher -> event thread.
  std::mutex event_mutex;
  std::shared_ptr<const std::string> event;
  std::uint64_t event_version = 0;
  std::uint64_t event_sent = 0;
  std::shared_ptr<const std::string> last_event;

  LaneQueue control, read, exports;

  mutable std::mutex statistics_mutex;
  ServerStatistics stats;

  void count(std::uint64_t ServerStatistics::*field) {
    std::lock_guard lock(statistics_mutex);
    ++(stats.*field);
  }
  void update_open() {
    std::lock_guard lock(statistics_mutex);
    stats.open = connections.size();
    stats.max_open = std::max(stats.max_open, stats.open);
    stats.event_streams = streams;
  }

  void wake() const {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(wake_fd, &one, sizeof one);
  }

  // ---- lanes ----
  LaneQueue& queue_of(Lane lane) {
    switch (lane) {
      case Lane::kControl:
        return control;
      case Lane::kExport:
        return exports;
      default:
        return read;
    }
  }

  void run_lane(LaneQueue& q) {
    if (q.low_priority) {
      // Exports must not compete with the real-time thread nor the user program (issue 21). SCHED_IDLE: the
      // lowest weight of the scheduler, and any other thread that wakes up preempts it at once, so a cycle
      // never waits for a render. Measured against nice 10 with 24 parallel 4000x3000 PNGs: nice 10 cost 20
      // overruns per second of a 1 ms cycle on a quiet machine, SCHED_IDLE about as many as idle. The price:
      // on a saturated machine an export waits for spare CPU. Allowed without privileges; if refused, the
      // thread runs at normal priority.
      sched_param p{};
      p.sched_priority = 0;
      ::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &p);
    } else if (&q == &exports) {
      // kNormal: SCHED_OTHER whatever the thread that called start() runs at (a SCHED_FIFO caller must not
      // make renders real-time).
      sched_param p{};
      p.sched_priority = 0;
      ::pthread_setschedparam(::pthread_self(), SCHED_OTHER, &p);
    }
    for (;;) {
      Job job;
      {
        std::unique_lock lock(q.mutex);
        q.ready.wait(lock, [&] { return q.stopping || !q.jobs.empty(); });
        if (q.stopping) return;
        job = std::move(q.jobs.front());
        q.jobs.pop_front();
      }
      Response response;
      try {
        response = job.route->handler(job.request);
      } catch (...) {
        response = error_body(500, "internal error");
      }
      {
        std::lock_guard lock(done_mutex);
        done.emplace_back(job.connection, std::move(response));
      }
      wake();
    }
  }

  bool enqueue(Lane lane, Job job) {
    LaneQueue& q = queue_of(lane);
    job.urgent = lane == Lane::kControl && urgent && urgent(job.request);
    {
      std::lock_guard lock(q.mutex);
      if (q.jobs.size() >= q.capacity) return false;
      // An urgent job goes behind the urgent ones already waiting (first come, first served among STOPs) and
      // before every other.
      auto at = q.jobs.end();
      if (job.urgent) at = std::find_if(q.jobs.begin(), q.jobs.end(), [](const Job& j) { return !j.urgent; });
      q.jobs.insert(at, std::move(job));
    }
    q.ready.notify_one();
    return true;
  }

  // ---- sockets ----
  void set_interest(Connection& c) {
    std::uint32_t want = EPOLLRDHUP;
    if (c.phase == Phase::kReading || c.phase == Phase::kClosing) want |= EPOLLIN;
    if (c.writing()) want |= EPOLLOUT;
    if (want == c.interest) return;
    epoll_event ev{};
    ev.events = want;
    ev.data.u64 = c.id;
    ::epoll_ctl(epoll_fd, EPOLL_CTL_MOD, c.fd, &ev);
    c.interest = want;
  }

  void close_connection(std::uint64_t id) {
    const auto it = connections.find(id);
    if (it == connections.end()) return;
    Connection& c = *it->second;
    ::epoll_ctl(epoll_fd, EPOLL_CTL_DEL, c.fd, nullptr);
    ::close(c.fd);
    if (c.phase == Phase::kStreaming) --streams;
    if (--per_client[c.client] == 0) per_client.erase(c.client);
    connections.erase(it);
    update_open();
  }

  // The connection a new one may replace: one that holds no complete request (idle keep-alive, a request
  // still arriving), an answer the client does not read, or one being closed; the oldest first. From
  // `client` only when that client is at its cap.
  Connection* victim(const std::string* client) {
    Connection* oldest = nullptr;
    const auto now = Clock::now();
    for (auto& [id, owned] : connections) {
      Connection& c = *owned;
      if (client != nullptr && c.client != *client) continue;
      const bool stalled_write = c.phase == Phase::kWriting && now - c.write_since > std::chrono::seconds(1);
      if (c.phase != Phase::kReading && c.phase != Phase::kClosing && !stalled_write) continue;
      if (oldest == nullptr || c.since < oldest->since) oldest = &c;
    }
    return oldest;
  }

  Clock::time_point listener_paused_until{};
  bool listener_paused = false;

  void pause_listener() {
    epoll_event ev{};
    ev.events = 0;
    ev.data.u64 = kListenerId;
    ::epoll_ctl(epoll_fd, EPOLL_CTL_MOD, listen_fd, &ev);
    listener_paused = true;
    listener_paused_until = Clock::now() + std::chrono::milliseconds(100);
  }

  void resume_listener_when_due(Clock::time_point now) {
    if (!listener_paused || now < listener_paused_until) return;
    epoll_event ev{};
    ev.events = EPOLLIN;
    ev.data.u64 = kListenerId;
    ::epoll_ctl(epoll_fd, EPOLL_CTL_MOD, listen_fd, &ev);
    listener_paused = false;
  }

  void accept_all() {
    for (int i = 0; i < 256; ++i) {
      sockaddr_storage address{};
      socklen_t length = sizeof address;
      const int fd =
          ::accept4(listen_fd, reinterpret_cast<sockaddr*>(&address), &length, SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) {
        if (errno == EMFILE || errno == ENFILE) {
          // Out of descriptors: the listener would stay readable and spin this thread. Make room by evicting
          // the oldest incomplete connection and take the new one; with nothing to evict, listen again a
          // little later (the rest wait in the backlog).
          if (Connection* v = victim(nullptr)) {
            count(&ServerStatistics::evicted);
            close_connection(v->id);
            continue;
          }
          pause_listener();
        }
        return;  // EAGAIN: all taken
      }
      count(&ServerStatistics::accepted);
      char text[INET6_ADDRSTRLEN] = "?";
      if (address.ss_family == AF_INET) {
        ::inet_ntop(AF_INET, &reinterpret_cast<sockaddr_in*>(&address)->sin_addr, text, sizeof text);
      } else if (address.ss_family == AF_INET6) {
        ::inet_ntop(AF_INET6, &reinterpret_cast<sockaddr_in6*>(&address)->sin6_addr, text, sizeof text);
      }
      std::string client(text);
      const std::size_t* mine = nullptr;
      if (const auto it = per_client.find(client); it != per_client.end()) mine = &it->second;
      bool room = true;
      if (mine != nullptr && *mine >= limits.max_connections_per_client) {
        Connection* v = victim(&client);
        if (v != nullptr) {
          count(&ServerStatistics::evicted);
          close_connection(v->id);
        } else {
          room = false;
        }
      }
      if (room && connections.size() >= limits.max_connections) {
        Connection* v = victim(nullptr);
        if (v != nullptr) {
          count(&ServerStatistics::evicted);
          close_connection(v->id);
        } else {
          room = false;
        }
      }
      if (!room) {
        count(&ServerStatistics::refused);
        ::close(fd);
        continue;
      }
      const int yes = 1;
      ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);  // issue 21: 40 ms per keep-alive GET
      auto c = std::make_unique<Connection>();
      c->fd = fd;
      c->id = next_id++;
      c->client = std::move(client);
      c->parser = RequestParser(limits.request);
      c->since = Clock::now();
      c->interest = EPOLLIN | EPOLLRDHUP;
      epoll_event ev{};
      ev.events = c->interest;
      ev.data.u64 = c->id;
      if (::epoll_ctl(epoll_fd, EPOLL_CTL_ADD, fd, &ev) != 0) {
        ::close(fd);
        continue;
      }
      ++per_client[c->client];
      connections.emplace(c->id, std::move(c));
      update_open();
    }
  }

  // Queues bytes and sends what the socket takes now. False: the connection was closed.
  bool write_out(Connection& c) {
    while (c.out_sent < c.out.size()) {
      const ssize_t n = ::send(c.fd, c.out.data() + c.out_sent, c.out.size() - c.out_sent, MSG_NOSIGNAL);
      if (n > 0) {
        c.out_sent += static_cast<std::size_t>(n);
        c.write_since = Clock::now();
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
      if (n < 0 && errno == EINTR) continue;
      close_connection(c.id);
      return false;
    }
    if (c.out_sent == c.out.size()) {
      c.out.clear();
      c.out_sent = 0;
      while (c.body != nullptr && c.body_sent < c.body->size()) {
        const ssize_t n =
            ::send(c.fd, c.body->data() + c.body_sent, c.body->size() - c.body_sent, MSG_NOSIGNAL);
        if (n > 0) {
          c.body_sent += static_cast<std::size_t>(n);
          c.write_since = Clock::now();
          continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
        if (n < 0 && errno == EINTR) continue;
        close_connection(c.id);
        return false;
      }
      if (c.body != nullptr && c.body_sent == c.body->size()) {
        c.body.reset();
        c.body_sent = 0;
      }
    }
    if (!c.writing()) {
      if (c.phase == Phase::kWriting) {
        if (c.close_after_write) {
          // Shut the write side and drop what the client still sends, so that the answer is not destroyed
          // by a reset (a close with unread bytes); the connection goes after a short linger.
          ::shutdown(c.fd, SHUT_WR);
          c.phase = Phase::kClosing;
          c.since = Clock::now();
        } else {
          c.phase = Phase::kReading;
          c.idle = true;
          c.gated = false;
          c.continue_sent = false;
          c.since = Clock::now();
          // A request that came in behind this one (pipelined) is parsed by the loop, not here: no
          // recursion however many requests one read brought.
          if (!c.in.empty()) pending_input.push_back(c.id);
        }
      }
    }
    set_interest(c);
    return true;
  }

  void queue_bytes(Connection& c, std::string_view bytes) {
    if (!c.writing()) c.write_since = Clock::now();
    c.out.append(bytes);
  }

  // Sends an answer; closes the connection after it if it is an error or the client asked to.
  bool respond(Connection& c, const Response& r, bool keep_alive) {
    const bool close = !keep_alive || r.status >= 400;
    if (r.status >= 400) count(&ServerStatistics::errors);
    const std::size_t length = r.shared_body != nullptr ? r.shared_body->size() : r.body.size();
    std::string head = "HTTP/1.1 " + std::to_string(r.status) + " " + std::string(reason_phrase(r.status)) +
                       "\r\nContent-Type: " + r.content_type +
                       "\r\nContent-Length: " + std::to_string(length) +
                       "\r\nX-Content-Type-Options: nosniff\r\nCache-Control: no-store\r\n";
    for (const auto& [n, v] : r.headers)
      head += n + ": " + v + "\r\n";
    head += close ? "Connection: close\r\n\r\n" : "Connection: keep-alive\r\n\r\n";
    queue_bytes(c, head);
    if (r.shared_body != nullptr) {
      c.body = r.shared_body;
      c.body_sent = 0;
    } else {
      queue_bytes(c, r.body);
    }
    c.phase = Phase::kWriting;
    c.close_after_write = close;
    return write_out(c);
  }

  bool respond_error(Connection& c, int status, std::string_view message) {
    return respond(c, error_body(status, message), false);
  }

  static bool keep_alive(const Request& r) {
    std::string connection(r.header("connection"));
    std::transform(connection.begin(), connection.end(), connection.begin(), lower);
    if (r.minor_version == 0) return connection == "keep-alive";
    return connection != "close";
  }

  static std::string event_chunk(const std::string& data) {
    char size[20];
    const std::string payload = "data: " + data + "\n\n";
    std::snprintf(size, sizeof size, "%zx\r\n", payload.size());
    return size + payload + "\r\n";
  }

  bool start_stream(Connection& c) {
    if (streams >= limits.max_event_streams) return respond_error(c, 503, "too many event streams");
    ++streams;
    update_open();
    c.phase = Phase::kStreaming;
    queue_bytes(c,
                "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\n"
                "X-Content-Type-Options: nosniff\r\nTransfer-Encoding: chunked\r\n\r\n");
    if (last_event) queue_bytes(c, event_chunk(*last_event));
    return write_out(c);
  }

  // Parses what arrived; dispatches a complete request. False: the connection was closed.
  bool process_input(Connection& c) {
    if (c.phase != Phase::kReading || c.in.empty()) return true;
    if (c.idle) {
      // Empty lines before a request are ignored (RFC 9112 §2.2: some clients send CRLF after a body).
      const std::size_t start = c.in.find_first_not_of("\r\n");
      c.in.erase(0, start == std::string::npos ? c.in.size() : start);
      if (c.in.empty()) return true;
      c.idle = false;
      c.since = Clock::now();
    }
    const RequestParser::State state = c.parser.parse(c.in);
    if (state == RequestParser::State::kError)
      return respond_error(c, c.parser.error_status(), c.parser.error_message());
    if (c.parser.headers_complete() && !c.gated) {
      c.gated = true;
      Request& r = c.parser.request();
      r.client = c.client;
      // Route before the body is read: a request for nothing, or one the gate refuses, is answered at once.
      const std::vector<std::string> parts = split_path(r.path);
      c.route = nullptr;
      bool path_known = false;
      for (const auto& route : routes) {
        if (!matches(*route, parts, nullptr)) continue;
        path_known = true;
        if (route->method == r.method) {
          c.route = route.get();
          matches(*route, parts, &r.captures);
          break;
        }
      }
      if (gate) {
        if (auto refusal = gate(r, c.route != nullptr ? c.route->lane : Lane::kInline))
          return respond(c, *refusal, false);
      }
      if (c.route == nullptr)
        return respond_error(c, path_known ? 405 : 404,
                             path_known ? "method not allowed" : "no such resource");
      if (state == RequestParser::State::kIncomplete && c.parser.expects_continue() && !c.continue_sent) {
        c.continue_sent = true;
        queue_bytes(c, "HTTP/1.1 100 Continue\r\n\r\n");
        if (!write_out(c)) return false;
      }
    }
    if (state != RequestParser::State::kComplete) return true;

    Job job{c.id, std::move(c.parser.request()), c.route, false};
    c.in.erase(0, c.parser.consumed());
    c.parser.reset();
    const bool keep = keep_alive(job.request);
    c.close_after_write = !keep;
    if (c.route->lane == Lane::kInline) {
      Response r;
      try {
        r = c.route->handler(job.request);
      } catch (...) {
        r = error_body(500, "internal error");
      }
      if (r.event_stream) return start_stream(c);
      return respond(c, r, keep);
    }
    c.lane = c.route->lane;
    c.phase = Phase::kHandling;
    set_interest(c);
    if (!enqueue(c.lane, std::move(job))) {
      count(&ServerStatistics::busy);
      return respond_error(c, 503, "the server is busy with requests of this kind; try again");
    }
    return true;
  }

  void on_readable(Connection& c) {
    char buffer[16 * 1024];
    // At most 16 reads per event (level-triggered: the rest comes with the next one), so that a client that
    // sends as fast as it can does not keep the event thread to itself.
    for (int reads = 0; reads < 16; ++reads) {
      const ssize_t n = ::recv(c.fd, buffer, sizeof buffer, 0);
      if (n > 0) {
        if (c.phase == Phase::kClosing) continue;  // dropped
        c.in.append(buffer, static_cast<std::size_t>(n));
        // Never more than one request's worth in memory: the parser refuses bigger ones.
        if (c.in.size() > limits.request.max_request_bytes()) break;
        continue;
      }
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
      if (n < 0 && errno == EINTR) continue;
      close_connection(c.id);  // closed by the client, or reset
      return;
    }
    process_input(c);
  }

  void deliver_done() {
    std::vector<std::pair<std::uint64_t, Response>> ready;
    {
      std::lock_guard lock(done_mutex);
      ready.swap(done);
    }
    for (auto& [id, response] : ready) {
      const auto it = connections.find(id);
      if (it == connections.end() || it->second->phase != Phase::kHandling) continue;
      Connection& c = *it->second;
      respond(c, response, !c.close_after_write);
    }
  }

  void deliver_event() {
    std::shared_ptr<const std::string> e;
    {
      std::lock_guard lock(event_mutex);
      if (event_version == event_sent) return;
      event_sent = event_version;
      e = event;
    }
    last_event = e;
    if (!e || streams == 0) return;
    const std::string chunk = event_chunk(*e);
    std::vector<std::uint64_t> ids;
    for (auto& [id, c] : connections) {
      if (c->phase == Phase::kStreaming) ids.push_back(id);
    }
    for (const std::uint64_t id : ids) {
      const auto it = connections.find(id);
      if (it == connections.end()) continue;
      Connection& c = *it->second;
      if (c.out.size() - c.out_sent > limits.max_event_backlog) {  // a client that does not read
        count(&ServerStatistics::timed_out);
        close_connection(id);
        continue;
      }
      queue_bytes(c, chunk);
      write_out(c);
    }
  }

  void check_deadlines() {
    const auto now = Clock::now();
    std::vector<std::pair<std::uint64_t, int>> expired;  // status 0: close without an answer
    for (auto& [id, owned] : connections) {
      Connection& c = *owned;
      switch (c.phase) {
        case Phase::kReading:
          if (c.idle && now - c.since > limits.idle_timeout) {
            expired.emplace_back(id, 0);
          } else if (!c.idle && !c.parser.headers_complete() && now - c.since > limits.header_timeout) {
            expired.emplace_back(id, 408);
          } else if (!c.idle && now - c.since > limits.request_timeout) {
            expired.emplace_back(id, 408);
          }
          break;
        case Phase::kWriting:
        case Phase::kStreaming:
          if (c.writing() && now - c.write_since > limits.write_timeout) expired.emplace_back(id, 0);
          break;
        case Phase::kClosing:
          if (now - c.since > std::chrono::milliseconds(500)) expired.emplace_back(id, -1);
          break;
        case Phase::kHandling:
          break;
      }
    }
    for (const auto& [id, status] : expired) {
      if (status >= 0) count(&ServerStatistics::timed_out);
      const auto it = connections.find(id);
      if (it == connections.end()) continue;
      if (status > 0) {
        respond_error(*it->second, status, "request not complete in time");
      } else {
        close_connection(id);
      }
    }
  }

  void loop() {
    epoll_event events[128];
    auto next_check = Clock::now();
    while (running.load(std::memory_order_relaxed)) {
      const int n = ::epoll_wait(epoll_fd, events, 128, pending_input.empty() ? 20 : 0);
      for (int i = 0; i < n; ++i) {
        const std::uint64_t id = events[i].data.u64;
        if (id == kListenerId) {
          accept_all();
          continue;
        }
        if (id == kWakeId) {
          std::uint64_t value;
          [[maybe_unused]] const ssize_t r = ::read(wake_fd, &value, sizeof value);
          deliver_done();
          deliver_event();
          continue;
        }
        const auto it = connections.find(id);
        if (it == connections.end()) continue;
        Connection& c = *it->second;
        const std::uint32_t e = events[i].events;
        if ((e & EPOLLOUT) != 0 && !write_out(c)) continue;
        if (connections.find(id) == connections.end()) continue;
        if ((e & (EPOLLIN | EPOLLERR | EPOLLHUP)) != 0) {
          on_readable(c);
        } else if ((e & EPOLLRDHUP) != 0 && c.phase != Phase::kReading) {
          close_connection(id);  // the client went away while its answer was prepared or streamed
        }
      }
      std::vector<std::uint64_t> pending;
      pending.swap(pending_input);
      for (const std::uint64_t id : pending) {
        const auto it = connections.find(id);
        if (it != connections.end()) process_input(*it->second);
      }
      const auto now = Clock::now();
      if (now >= next_check) {
        resume_listener_when_due(now);
        check_deadlines();
        next_check = now + std::chrono::milliseconds(20);
      }
    }
  }

  void stop_lane(LaneQueue& q) {
    {
      std::lock_guard lock(q.mutex);
      q.stopping = true;
      q.jobs.clear();
    }
    q.ready.notify_all();
    if (q.thread.joinable()) q.thread.join();
  }
};

Server::Server(ServerLimits limits) : impl_(std::make_unique<Impl>(limits)) {}

Server::~Server() {
  stop();
  Impl& s = *impl_;
  if (s.listen_fd >= 0) ::close(s.listen_fd);
}

void Server::route(std::string method, std::string pattern, Lane lane, Handler handler) {
  auto r = std::make_unique<Route>();
  r->method = std::move(method);
  r->segments = split_path(pattern);
  r->lane = lane;
  r->handler = std::move(handler);
  impl_->routes.push_back(std::move(r));
}

void Server::set_gate(Gate gate) {
  impl_->gate = std::move(gate);
}

void Server::set_urgent(std::function<bool(const Request&)> urgent) {
  impl_->urgent = std::move(urgent);
}

void Server::set_error_body(std::function<Response(int, std::string_view)> error_body) {
  impl_->error_body = std::move(error_body);
}

int Server::bind(const std::string& address, int port) {
  Impl& s = *impl_;
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo* found = nullptr;
  const std::string service = std::to_string(port);
  if (::getaddrinfo(address.c_str(), service.c_str(), &hints, &found) != 0 || found == nullptr)
    throw std::runtime_error("cannot listen on " + address + ": not an address");
  const int fd = ::socket(found->ai_family, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  // Only SO_REUSEADDR, never SO_REUSEPORT: a second server on the same port must fail to bind instead of
  // silently sharing the connections (TOOLCHAIN.md §6).
  const int yes = 1;
  const bool ok =
      fd >= 0 && ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes) == 0 &&
      ::bind(fd, found->ai_addr, found->ai_addrlen) == 0 &&
      ::listen(fd, static_cast<int>(std::max<std::size_t>(2 * s.limits.max_connections, 128))) == 0;
  ::freeaddrinfo(found);
  if (!ok) {
    if (fd >= 0) ::close(fd);
    throw std::runtime_error("cannot listen on " + address + ":" + service +
                             " (in use, or not an address of this machine)");
  }
  sockaddr_storage bound{};
  socklen_t length = sizeof bound;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &length);
  s.listen_fd = fd;
  if (bound.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&bound)->sin6_port);
  return ntohs(reinterpret_cast<sockaddr_in*>(&bound)->sin_port);
}

void Server::start() {
  Impl& s = *impl_;
  if (s.running.load() || s.listen_fd < 0) return;
  s.epoll_fd = ::epoll_create1(EPOLL_CLOEXEC);
  s.wake_fd = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (s.epoll_fd < 0 || s.wake_fd < 0) throw std::runtime_error("cannot create the server's event loop");
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.u64 = kListenerId;
  ::epoll_ctl(s.epoll_fd, EPOLL_CTL_ADD, s.listen_fd, &ev);
  ev.data.u64 = kWakeId;
  ::epoll_ctl(s.epoll_fd, EPOLL_CTL_ADD, s.wake_fd, &ev);
  // Named for `top -H` and for the test that checks the export lane's scheduling.
  // (A pair, not a structured binding: clang 14, the fuzz build's compiler, cannot capture one.)
  for (const auto& lane :
       {std::pair{&s.control, "tomc-control"}, {&s.read, "tomc-read"}, {&s.exports, "tomc-export"}}) {
    LaneQueue* q = lane.first;
    q->stopping = false;
    q->thread = std::thread([&s, q] { s.run_lane(*q); });
    ::pthread_setname_np(q->thread.native_handle(), lane.second);
  }
  s.running.store(true);
  s.loop_thread = std::thread([&s] { s.loop(); });
  ::pthread_setname_np(s.loop_thread.native_handle(), "tomc-http");
}

void Server::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  s.wake();
  if (s.loop_thread.joinable()) s.loop_thread.join();
  for (LaneQueue* q : {&s.control, &s.read, &s.exports})
    s.stop_lane(*q);
  std::vector<std::uint64_t> ids;
  for (const auto& [id, c] : s.connections)
    ids.push_back(id);
  for (const std::uint64_t id : ids)
    s.close_connection(id);
  ::close(s.epoll_fd);
  ::close(s.wake_fd);
  s.epoll_fd = s.wake_fd = -1;
  ::close(s.listen_fd);
  s.listen_fd = -1;
}

void Server::publish(std::shared_ptr<const std::string> event) {
  Impl& s = *impl_;
  {
    std::lock_guard lock(s.event_mutex);
    s.event = std::move(event);
    ++s.event_version;
  }
  if (s.running.load()) s.wake();
}

ServerStatistics Server::statistics() const {
  std::lock_guard lock(impl_->statistics_mutex);
  return impl_->stats;
}

}  // namespace tomc::diagnostics::http
