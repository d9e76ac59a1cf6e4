// The diagnostics web server (server.hpp) on cpp-httplib. TOOLCHAIN.md §6 pitfalls handled here: a larger
// worker pool (each server-sent-event stream holds a worker), no SO_REUSEPORT (a second server must fail to
// bind instead of silently sharing the port), and the library's pkg-config defines (CMake passes them).
#include "tomc/diagnostics/server.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <atomic>
#include <charconv>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "tomc/diagnostics/api.hpp"
#include "tomc/diagnostics/trace_image.hpp"

namespace tomc::diagnostics {

namespace {

using api::Json;

constexpr const char* kJson = "application/json";

void reply(httplib::Response& res, int status, const Json& body) {
  res.status = status;
  res.set_content(api::to_text(body), kJson);
}

void error(httplib::Response& res, int status, std::string_view message) {
  reply(res, status, Json{{"error", message}});
}

// Constant-time comparison: the time taken does not tell how much of a guessed token was right. `expected`
// is never empty (a server without a token is read-only).
bool same_token(std::string_view given, std::string_view expected) {
  std::size_t diff = given.size() ^ expected.size();
  for (std::size_t i = 0; i < given.size(); ++i)
    diff |= static_cast<unsigned char>(given[i] ^ expected[i % expected.size()]);
  return diff == 0;
}

int status_of(PanelAnswer answer) {
  switch (answer) {
    case PanelAnswer::kAccepted:
      return 200;
    case PanelAnswer::kInvalidValue:
      return 400;
    case PanelAnswer::kNotSupported:
      return 422;
    case PanelAnswer::kUnknownObject:
    case PanelAnswer::kNoPanel:
      return 404;
    case PanelAnswer::kProgramControlsAxis:
    case PanelAnswer::kHeldByOtherSession:
    case PanelAnswer::kNotHolder:
    case PanelAnswer::kGivingBack:
      return 409;
    case PanelAnswer::kQueueFull:
    case PanelAnswer::kNoAnswer:
      return 503;
  }
  return 500;
}

std::string_view answer_name(PanelAnswer answer) {
  switch (answer) {
    case PanelAnswer::kAccepted:
      return "accepted";
    case PanelAnswer::kNotSupported:
      return "not_supported";
    case PanelAnswer::kProgramControlsAxis:
      return "program_controls_axis";
    case PanelAnswer::kHeldByOtherSession:
      return "held_by_other_session";
    case PanelAnswer::kNotHolder:
      return "not_holder";
    case PanelAnswer::kGivingBack:
      return "giving_back";
    case PanelAnswer::kInvalidValue:
      return "invalid_value";
    case PanelAnswer::kUnknownObject:
      return "unknown_object";
    case PanelAnswer::kNoPanel:
      return "no_panel";
    case PanelAnswer::kQueueFull:
      return "queue_full";
    case PanelAnswer::kNoAnswer:
      return "no_answer";
  }
  return "?";
}

// An integer query parameter within [lo, hi]; `fallback` when absent; nullopt when malformed.
std::optional<int> int_param(const httplib::Request& req, const char* name, int fallback, int lo, int hi) {
  if (!req.has_param(name)) return fallback;
  const std::string text = req.get_param_value(name);
  int value = 0;
  const auto [end, e] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (e != std::errc{} || end != text.data() + text.size() || value < lo || value > hi) return std::nullopt;
  return value;
}

}  // namespace

struct Server::Impl {
  Impl(Diagnostics& d, ServerOptions o) : diagnostics(d), options(std::move(o)) {}

  Diagnostics& diagnostics;
  ServerOptions options;
  httplib::Server http;
  std::thread listener;
  std::thread collector;
  std::atomic<bool> running{false};
  int port = 0;
  std::string objects_json;

  std::mutex status_mutex;
  std::condition_variable status_changed;
  std::shared_ptr<const std::string> status_text;
  std::uint64_t status_version = 0;
  bool stopping = false;
  std::atomic<std::size_t> streams{0};

  Json runner_json() const {
    if (!options.runner_statistics) return nullptr;
    const techobjects::RunnerStatistics s = options.runner_statistics();
    return Json{{"cycles", s.cycles},
                {"overruns", s.overruns},
                {"skipped_periods", s.skipped_periods},
                {"jitter_median_us", s.jitter_median_us},
                {"jitter_p99_us", s.jitter_p99_us},
                {"jitter_max_us", s.jitter_max_us},
                {"warnings", s.setup_warnings}};
  }

  std::string render_status() const {
    Json j = diagnostics.read([&](const Diagnostics::State& s) { return api::status(diagnostics, s); });
    j["read_only"] = options.token.empty();
    j["runner"] = runner_json();
    return api::to_text(j);
  }

  void collect() {
    auto next_event = std::chrono::steady_clock::now();
    while (running.load()) {
      diagnostics.poll();
      const auto now = std::chrono::steady_clock::now();
      if (now >= next_event) {
        auto text = std::make_shared<const std::string>(render_status());
        {
          std::lock_guard lock(status_mutex);
          status_text = std::move(text);
          ++status_version;
        }
        status_changed.notify_all();
        next_event = now + options.event_period;
      }
      std::this_thread::sleep_for(options.poll_period);
    }
  }

  bool host_allowed(const httplib::Request& req) const {
    if (options.bind_address == "0.0.0.0" || options.bind_address == "::") return true;
    const std::string host = req.get_header_value("Host");
    const std::string p = ":" + std::to_string(port);
    for (const std::string& name :
         {options.bind_address, std::string("127.0.0.1"), std::string("localhost"), std::string("[::1]")}) {
      if (host == name + p || (port == 80 && host == name)) return true;
    }
    return false;
  }

  // 0 when the request may go on, else the HTTP status it was refused with.
  int authorise(const httplib::Request& req, httplib::Response& res) const {
    if (options.token.empty()) {
      error(res, 403, "read-only server: start it with a token to allow control actions");
      return 403;
    }
    const std::string header = req.get_header_value("Authorization");
    constexpr std::string_view kBearer = "Bearer ";
    if (!std::string_view(header).starts_with(kBearer)) {
      res.set_header("WWW-Authenticate", "Bearer");
      error(res, 401, "control actions need 'Authorization: Bearer <token>'");
      return 401;
    }
    if (!same_token(std::string_view(header).substr(kBearer.size()), options.token)) {
      error(res, 403, "wrong token");
      return 403;
    }
    return 0;
  }

  std::optional<std::size_t> object_of(const httplib::Request& req, httplib::Response& res) const {
    const std::string name = req.matches.size() > 1 ? std::string(req.matches[1]) : std::string();
    const auto index = diagnostics.find_object(name);
    if (!index) error(res, 404, "no technology object '" + name + "'");
    return index;
  }

  void routes() {
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (!host_allowed(req)) {
        error(res, 421, "this server answers only for the address it is bound to");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (req.method == "POST" && authorise(req, res) != 0) return httplib::Server::HandlerResponse::Handled;
      return httplib::Server::HandlerResponse::Unhandled;
    });
    http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (!res.body.empty()) return;
      switch (res.status) {
        case 404:
          return error(res, 404, "no such resource");
        case 413:
          return error(res, 413, "request body larger than 64 KiB");
        case 400:
          return error(res, 400, "malformed request");
        default:
          return error(res, res.status, "HTTP status " + std::to_string(res.status));
      }
    });
    http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
      error(res, 500, "internal error");
    });

    http.Get("/", [](const httplib::Request&, httplib::Response& res) {
      res.set_header(
          "Content-Security-Policy",
          "default-src 'self'; script-src 'self' 'unsafe-inline'; style-src 'self' 'unsafe-inline'; "
          "img-src 'self' data: blob:; connect-src 'self'; frame-ancestors 'none'");
      res.set_content(std::string(web_page()), "text/html; charset=utf-8");
    });
    http.Get("/favicon.ico", [](const httplib::Request&, httplib::Response& res) { res.status = 204; });

    http.Get("/api/info", [this](const httplib::Request&, httplib::Response& res) {
      reply(res, 200,
            Json{{"title", options.title},
                 {"version", "0.1.0"},
                 {"servo_cycle_s", diagnostics.servo_cycle_s()},
                 {"read_only", options.token.empty()},
                 {"event_period_s", std::chrono::duration<double>(options.event_period).count()},
                 {"runner", runner_json()}});
    });
    http.Get("/api/objects", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(objects_json, kJson);
    });
    http.Get("/api/status", [this](const httplib::Request&, httplib::Response& res) {
      std::shared_ptr<const std::string> text;
      {
        std::lock_guard lock(status_mutex);
        text = status_text;
      }
      res.set_content(text ? *text : render_status(), kJson);
    });
    http.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
      if (streams.fetch_add(1) >= options.max_event_streams) {
        streams.fetch_sub(1);
        error(res, 503, "too many event streams");
        return;
      }
      auto seen = std::make_shared<std::uint64_t>(0);
      res.set_chunked_content_provider(
          "text/event-stream",
          [this, seen](std::size_t, httplib::DataSink& sink) {
            std::shared_ptr<const std::string> text;
            {
              std::unique_lock lock(status_mutex);
              status_changed.wait_for(lock, std::chrono::seconds(1),
                                      [&] { return stopping || status_version != *seen; });
              if (stopping) return false;
              if (status_version != *seen) {
                text = status_text;
                *seen = status_version;
              }
            }
            const std::string chunk = text ? "data: " + *text + "\n\n" : std::string(": keep-alive\n\n");
            return sink.write(chunk.data(), chunk.size());
          },
          [this](bool) { streams.fetch_sub(1); });
    });
    http.Get(R"(/api/objects/([A-Za-z_][A-Za-z0-9_]*)/variables)",
             [this](const httplib::Request& req, httplib::Response& res) {
               if (const auto i = object_of(req, res)) {
                 reply(res, 200, diagnostics.read([&](const Diagnostics::State& s) {
                   return api::variables(diagnostics, s, *i);
                 }));
               }
             });
    http.Get(R"(/api/objects/([A-Za-z_][A-Za-z0-9_]*)/alarms)", [this](const httplib::Request& req,
                                                                       httplib::Response& res) {
      if (const auto i = object_of(req, res)) {
        reply(res, 200,
              diagnostics.read([&](const Diagnostics::State& s) { return api::alarms(diagnostics, s, *i); }));
      }
    });

    http.Post(R"(/api/panel/([A-Za-z_][A-Za-z0-9_]*))", [this](const httplib::Request& req,
                                                               httplib::Response& res) {
      const auto i = object_of(req, res);
      if (!i) return;
      auto parsed = api::parse_panel_command(req.body);
      if (auto* problem = std::get_if<std::string>(&parsed)) {
        error(res, 400, *problem);
        return;
      }
      PanelCommand c = std::get<PanelCommand>(parsed);
      c.object = static_cast<std::uint32_t>(*i);
      const PanelAnswer answer = diagnostics.command(c);
      reply(res, status_of(answer), Json{{"answer", answer_name(answer)}, {"message", to_string(answer)}});
    });
    http.Post(R"(/api/switches/([A-Za-z0-9_.]+))",
              [this](const httplib::Request& req, httplib::Response& res) {
                auto parsed = api::parse_switch(req.body);
                if (auto* problem = std::get_if<std::string>(&parsed)) {
                  error(res, 400, *problem);
                  return;
                }
                const std::string name = req.matches[1];
                if (!diagnostics.set_switch(name, std::get<bool>(parsed))) {
                  error(res, 404, "no switch '" + name + "'");
                  return;
                }
                reply(res, 200, Json{{"name", name}, {"on", std::get<bool>(parsed)}});
              });
    http.Post("/api/trace", [this](const httplib::Request& req, httplib::Response& res) {
      auto parsed = api::parse_trace_request(req.body);
      if (auto* problem = std::get_if<std::string>(&parsed)) {
        error(res, 400, *problem);
        return;
      }
      const std::vector<std::string> problems = diagnostics.start_trace(std::get<TraceRequest>(parsed));
      if (!problems.empty()) {
        std::string message;
        for (const auto& p : problems)
          message += (message.empty() ? "" : "; ") + p;
        const bool busy = problems.size() == 1 && problems[0].find("not yet taken") != std::string::npos;
        error(res, busy ? 503 : 400, message);
        return;
      }
      reply(res, 200, Json{{"started", true}});
    });
    http.Post("/api/trace/stop", [this](const httplib::Request&, httplib::Response& res) {
      diagnostics.stop_trace();
      reply(res, 200, Json{{"stopping", true}});
    });
    http.Get("/api/trace", [this](const httplib::Request& req, httplib::Response& res) {
      const auto points = int_param(req, "max_points", 2000, 2, 200000);
      if (!points) return error(res, 400, "max_points: an integer 2 .. 200000");
      reply(res, 200, diagnostics.read([&](const Diagnostics::State& s) {
        return api::trace(s.trace, static_cast<std::size_t>(*points));
      }));
    });
    http.Get("/api/trace.csv", [this](const httplib::Request&, httplib::Response& res) {
      res.set_header("Content-Disposition", "attachment; filename=\"trace.csv\"");
      res.set_content(diagnostics.read([](const Diagnostics::State& s) { return api::trace_csv(s.trace); }),
                      "text/csv");
    });
    http.Get("/api/trace.png", [this](const httplib::Request& req, httplib::Response& res) {
      const auto width = int_param(req, "width", 1200, kMinImageWidth, kMaxImageWidth);
      const auto height = int_param(req, "height", 700, kMinImageHeight, kMaxImageHeight);
      if (!width || !height) {
        return error(res, 400,
                     "width " + std::to_string(kMinImageWidth) + " .. " + std::to_string(kMaxImageWidth) +
                         ", height " + std::to_string(kMinImageHeight) + " .. " +
                         std::to_string(kMaxImageHeight));
      }
      // Copy the capture out of the lock: drawing takes milliseconds, the collector must not wait for it.
      const TraceCapture capture = diagnostics.read([](const Diagnostics::State& s) { return s.trace; });
      const std::vector<std::uint8_t> png = render_trace_png(capture, *width, *height);
      res.set_content(std::string(png.begin(), png.end()), "image/png");
    });
  }
};

Server::Server(Diagnostics& diagnostics, ServerOptions options)
    : impl_(std::make_unique<Impl>(diagnostics, std::move(options))) {}

Server::~Server() {
  stop();
}

void Server::start() {
  Impl& s = *impl_;
  if (s.running.load()) return;
  s.objects_json = api::to_text(api::describe_objects(s.diagnostics));
  s.http.new_task_queue = [n = s.options.worker_threads] { return new httplib::ThreadPool(n); };
  // Only SO_REUSEADDR: with httplib's default SO_REUSEPORT a stale server on the same port would share the
  // connections silently (TOOLCHAIN.md §6).
  s.http.set_socket_options([](socket_t sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  s.http.set_payload_max_length(api::kMaxBodyBytes);
  s.http.set_read_timeout(5, 0);
  s.http.set_write_timeout(5, 0);
  s.http.set_keep_alive_timeout(5);
  s.http.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Cache-Control", "no-store"}});
  s.routes();
  if (s.options.port == 0) {
    s.port = s.http.bind_to_any_port(s.options.bind_address);
    if (s.port <= 0) throw std::runtime_error("cannot listen on " + s.options.bind_address + " (any port)");
  } else {
    if (!s.http.bind_to_port(s.options.bind_address, s.options.port)) {
      throw std::runtime_error("cannot listen on " + s.options.bind_address + ":" +
                               std::to_string(s.options.port) +
                               " (in use, or not an address of this machine)");
    }
    s.port = s.options.port;
  }
  s.running.store(true);
  {
    std::lock_guard lock(s.status_mutex);
    s.stopping = false;
  }
  s.collector = std::thread([&s] { s.collect(); });
  s.listener = std::thread([&s] { s.http.listen_after_bind(); });
}

void Server::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  {
    std::lock_guard lock(s.status_mutex);
    s.stopping = true;
  }
  s.status_changed.notify_all();
  s.http.stop();
  if (s.listener.joinable()) s.listener.join();
  if (s.collector.joinable()) s.collector.join();
}

int Server::port() const noexcept {
  return impl_->port;
}

std::string Server::url() const {
  const std::string& a = impl_->options.bind_address;
  const std::string host = a == "0.0.0.0" ? "127.0.0.1" : a;
  return "http://" + host + ":" + std::to_string(impl_->port) + "/";
}

}  // namespace tomc::diagnostics
