// The diagnostics web server (server.hpp): the routes of the API on the event-driven HTTP server
// (http_server.hpp). Which lane each route runs on is chosen here: cached or ready-made answers on the event
// thread, panel commands on the control lane (STOP and disable first), JSON built under the reader's lock
// on the read lane, trace exports on the export lane (one at a time, cached, at idle priority).
#include "tomc/diagnostics/server.hpp"

#include <atomic>
#include <charconv>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "tomc/diagnostics/api.hpp"
#include "tomc/diagnostics/trace_image.hpp"
#include "web_assets.hpp"

namespace tomc::diagnostics {

namespace {

using api::Json;

constexpr const char* kJson = "application/json";

using http::Lane;
using http::Request;
using http::Response;

Response reply(int status, const Json& body) {
  Response r;
  r.status = status;
  r.body = api::to_text(body);
  return r;
}

Response error(int status, std::string_view message) {
  return reply(status, Json{{"error", message}});
}

Response content(std::string body, std::string type) {
  Response r;
  r.body = std::move(body);
  r.content_type = std::move(type);
  return r;
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
std::optional<int> int_param(const Request& req, const char* name, int fallback, int lo, int hi) {
  if (!req.has_param(name)) return fallback;
  const std::string text = req.param(name);
  int value = 0;
  const auto [end, e] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (e != std::errc{} || end != text.data() + text.size() || value < lo || value > hi) return std::nullopt;
  return value;
}

bool loopback(const std::string& address) {
  return address.rfind("127.", 0) == 0 || address == "::1" || address == "localhost";
}

}  // namespace

struct Server::Impl {
  Impl(Diagnostics& d, ServerOptions o) : diagnostics(d), options(std::move(o)), http(options.limits) {}

  Diagnostics& diagnostics;
  ServerOptions options;
  http::Server http;
  std::thread collector;
  std::atomic<bool> running{false};
  int port = 0;
  std::string objects_json;
  std::vector<std::string> warnings;

  std::mutex collector_mutex;
  std::condition_variable collector_wake;
  bool stopping = false;

  std::mutex status_mutex;
  std::shared_ptr<const std::string> status_text;

  // Trace exports: only the export lane touches the cache; the counters are read by statistics().
  using ExportKey = std::tuple<std::uint32_t, std::size_t, int, int, int>;  // generation, rows, state, w, h
  std::optional<ExportKey> png_key, csv_key;
  // Shared with the answers being sent: one copy of each export in memory however many clients ask.
  std::shared_ptr<const std::string> png_cache, csv_cache;
  std::atomic<std::uint64_t> exports_rendered{0}, exports_cached{0};

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

  // The HTTP server's own counters (docs/diagnostics.md "A slow client cannot block the server").
  Json server_json() const {
    const http::ServerStatistics h = http.statistics();
    return Json{{"connections", h.open},
                {"event_streams", h.event_streams},
                {"accepted", h.accepted},
                {"evicted", h.evicted},
                {"refused", h.refused},
                {"timed_out", h.timed_out},
                {"errors", h.errors},
                {"busy", h.busy},
                {"exports_rendered", exports_rendered.load()},
                {"exports_cached", exports_cached.load()}};
  }

  std::string render_status() const {
    Json j = diagnostics.read([&](const Diagnostics::State& s) { return api::status(diagnostics, s); });
    j["read_only"] = options.token.empty();
    j["runner"] = runner_json();
    return api::to_text(j);
  }

  void publish_status() {
    auto text = std::make_shared<const std::string>(render_status());
    {
      std::lock_guard lock(status_mutex);
      status_text = text;
    }
    http.publish(std::move(text));
  }

  void collect() {
    auto next_event = std::chrono::steady_clock::now();
    std::unique_lock lock(collector_mutex);
    while (!stopping) {
      lock.unlock();
      diagnostics.poll();
      const auto now = std::chrono::steady_clock::now();
      if (now >= next_event) {
        publish_status();
        next_event = now + options.event_period;
      }
      lock.lock();
      collector_wake.wait_for(lock, options.poll_period, [&] { return stopping; });
    }
  }

  bool host_allowed(const Request& req) const {
    const std::string_view host = req.header("host");
    if (host.empty()) return req.minor_version == 0;  // HTTP/1.0 without Host: only the socket's address
    const std::string p = ":" + std::to_string(port);
    auto named = [&](const std::string& name) { return host == name + p || host == name; };
    const std::string& a = options.bind_address;
    if (a != "0.0.0.0" && a != "::") {
      if (named(a.find(':') != std::string::npos ? "[" + a + "]" : a)) return true;
    }
    for (const char* name : {"127.0.0.1", "localhost", "[::1]"}) {
      if (named(name)) return true;
    }
    for (const std::string& name : options.allowed_hosts) {
      if (named(name)) return true;
    }
    return false;
  }

  // nullopt when the request may go on, else the answer it is refused with.
  std::optional<Response> authorise(const Request& req) const {
    if (options.token.empty()) {
      return error(403, "read-only server: start it with a token to allow control actions and exports");
    }
    const std::string_view header = req.header("authorization");
    constexpr std::string_view kBearer = "Bearer ";
    if (!header.starts_with(kBearer)) {
      Response r = error(401, "control actions and exports need 'Authorization: Bearer <token>'");
      r.headers.emplace_back("WWW-Authenticate", "Bearer");
      return r;
    }
    if (!same_token(header.substr(kBearer.size()), options.token)) return error(403, "wrong token");
    return std::nullopt;
  }

  std::optional<std::size_t> object_of(const Request& req) const {
    const std::string name = req.captures.empty() ? std::string() : req.captures[0];
    return diagnostics.find_object(name);
  }
  Response no_object(const Request& req) const {
    return error(404,
                 "no technology object '" + (req.captures.empty() ? std::string() : req.captures[0]) + "'");
  }

  Response trace_png(const Request& req) {
    const auto width = int_param(req, "width", 1200, kMinImageWidth, kMaxImageWidth);
    const auto height = int_param(req, "height", 700, kMinImageHeight, kMaxImageHeight);
    if (!width || !height) {
      return error(400, "width " + std::to_string(kMinImageWidth) + " .. " + std::to_string(kMaxImageWidth) +
                            ", height " + std::to_string(kMinImageHeight) + " .. " +
                            std::to_string(kMaxImageHeight));
    }
    const ExportKey key = diagnostics.read([&](const Diagnostics::State& s) {
      return ExportKey{s.trace.generation, s.trace.rows(), static_cast<int>(s.trace.state), *width, *height};
    });
    if (png_key != key) {
      // One render at a time (this lane has one thread); the copy is taken out of the lock so that the
      // collector does not wait for the drawing.
      const TraceCapture capture = diagnostics.read([](const Diagnostics::State& s) { return s.trace; });
      const std::vector<std::uint8_t> png = render_trace_png(capture, *width, *height);
      png_cache = std::make_shared<const std::string>(png.begin(), png.end());
      png_key =
          ExportKey{capture.generation, capture.rows(), static_cast<int>(capture.state), *width, *height};
      ++exports_rendered;
    } else {
      ++exports_cached;
    }
    Response r;
    r.content_type = "image/png";
    r.shared_body = png_cache;
    return r;
  }

  Response trace_csv() {
    const ExportKey key = diagnostics.read([&](const Diagnostics::State& s) {
      return ExportKey{s.trace.generation, s.trace.rows(), static_cast<int>(s.trace.state), 0, 0};
    });
    if (csv_key != key) {
      csv_cache = std::make_shared<const std::string>(
          diagnostics.read([](const Diagnostics::State& s) { return api::trace_csv(s.trace); }));
      csv_key = key;
      ++exports_rendered;
    } else {
      ++exports_cached;
    }
    Response r;
    r.content_type = "text/csv";
    r.shared_body = csv_cache;
    r.headers.emplace_back("Content-Disposition", "attachment; filename=\"trace.csv\"");
    return r;
  }

  void routes() {
    http.set_error_body([](int status, std::string_view message) { return error(status, message); });
    http.set_gate([this](const Request& req, Lane lane) -> std::optional<Response> {
      if (!host_allowed(req))
        return error(421, "this server answers only for the names it is configured for");
      if (req.method == "POST" || lane == Lane::kExport) return authorise(req);
      return std::nullopt;
    });
    // STOP and disable go to the front of the control queue.
    http.set_urgent([](const Request& req) {
      const auto parsed = api::parse_panel_command(req.body);
      const auto* c = std::get_if<PanelCommand>(&parsed);
      return c != nullptr && (c->kind == PanelCommandKind::kStop || c->kind == PanelCommandKind::kDisable);
    });

    http.route("GET", "/", Lane::kInline, [](const Request&) {
      Response r = content(std::string(web_page()), "text/html; charset=utf-8");
      r.headers.emplace_back(
          "Content-Security-Policy",
          "default-src 'self'; script-src 'self' 'unsafe-inline'; style-src 'self' 'unsafe-inline'; "
          "img-src 'self' data: blob:; connect-src 'self'; frame-ancestors 'none'");
      return r;
    });
    // The plotting library: immutable for this build, shared without a copy per request.
    for (const auto& [path, bytes, type] :
         {std::tuple{"/vendor/uPlot.iife.min.js", uplot_script(), "text/javascript; charset=utf-8"},
          std::tuple{"/vendor/uPlot.min.css", uplot_style(), "text/css; charset=utf-8"}}) {
      auto body = std::make_shared<const std::string>(bytes);
      const char* content_type = type;  // a structured binding cannot be captured before C++20 in clang 14
      http.route("GET", path, Lane::kInline, [body, content_type](const Request&) {
        Response r;
        r.content_type = content_type;
        r.shared_body = body;
        r.headers.emplace_back("Cache-Control", "max-age=3600");
        return r;
      });
    }
    http.route("GET", "/favicon.ico", Lane::kInline, [](const Request&) {
      Response r;
      r.status = 204;
      return r;
    });
    http.route("GET", "/api/info", Lane::kInline, [this](const Request&) {
      return reply(200, Json{{"title", options.title},
                             {"version", "0.1.0"},
                             {"servo_cycle_s", diagnostics.servo_cycle_s()},
                             {"read_only", options.token.empty()},
                             {"event_period_s", std::chrono::duration<double>(options.event_period).count()},
                             {"runner", runner_json()},
                             {"server", server_json()}});
    });
    http.route("GET", "/api/objects", Lane::kInline,
               [this](const Request&) { return content(objects_json, kJson); });
    http.route("GET", "/api/status", Lane::kInline, [this](const Request&) {
      std::lock_guard lock(status_mutex);
      return content(*status_text, kJson);  // rendered once before start(), then by the collector
    });
    http.route("GET", "/api/events", Lane::kInline, [](const Request&) {
      Response r;
      r.event_stream = true;
      return r;
    });
    http.route("GET", "/api/objects/{}/variables", Lane::kRead, [this](const Request& req) {
      const auto i = object_of(req);
      if (!i) return no_object(req);
      return reply(200, diagnostics.read(
                            [&](const Diagnostics::State& s) { return api::variables(diagnostics, s, *i); }));
    });
    http.route("GET", "/api/objects/{}/alarms", Lane::kRead, [this](const Request& req) {
      const auto i = object_of(req);
      if (!i) return no_object(req);
      return reply(200, diagnostics.read(
                            [&](const Diagnostics::State& s) { return api::alarms(diagnostics, s, *i); }));
    });
    // The cam plot (issue 19): sampled here, on the read lane, never in the cycle (cam_plot.hpp).
    http.route("GET", "/api/objects/{}/plot", Lane::kRead, [this](const Request& req) {
      const auto i = object_of(req);
      if (!i) return no_object(req);
      if (diagnostics.view(*i).cam() == nullptr) return error(404, "'" + req.captures[0] + "' is not a cam");
      const auto samples = int_param(req, "samples", static_cast<int>(kDefaultCamSamples),
                                     static_cast<int>(kMinCamSamples), static_cast<int>(kMaxCamSamples));
      if (!samples) return error(400, "samples: an integer 2 .. 2001");
      auto plot = plot_cam(diagnostics, *i, static_cast<std::size_t>(*samples));
      if (auto* problem = std::get_if<std::string>(&plot)) return error(409, *problem);
      return reply(200, api::cam_plot(std::get<CamPlot>(plot)));
    });

    http.route("POST", "/api/panel/{}", Lane::kControl, [this](const Request& req) {
      const auto i = object_of(req);
      if (!i) return no_object(req);
      auto parsed = api::parse_panel_command(req.body);
      if (auto* problem = std::get_if<std::string>(&parsed)) return error(400, *problem);
      PanelCommand c = std::get<PanelCommand>(parsed);
      c.object = static_cast<std::uint32_t>(*i);
      // Ranges against the axis' limits (issue 21); only for commands that carry a value to check, so that a
      // STOP does not even take the reader's lock.
      std::vector<double> values;
      if (c.kind == PanelCommandKind::kSetDynamics || c.kind == PanelCommandKind::kHome ||
          c.kind == PanelCommandKind::kMoveAbsolute) {
        values = diagnostics.read([&](const Diagnostics::State& s) {
          return s.objects[*i].valid ? s.objects[*i].snapshot.values : std::vector<double>{};
        });
      }
      if (auto problem = api::check_panel_ranges(c, diagnostics.view(*i).variables(), values))
        return error(400, *problem);
      const PanelAnswer answer = diagnostics.command(c);
      return reply(status_of(answer), Json{{"answer", answer_name(answer)}, {"message", to_string(answer)}});
    });
    http.route("POST", "/api/switches/{}", Lane::kControl, [this](const Request& req) {
      auto parsed = api::parse_switch(req.body);
      if (auto* problem = std::get_if<std::string>(&parsed)) return error(400, *problem);
      const std::string& name = req.captures[0];
      if (!diagnostics.set_switch(name, std::get<bool>(parsed)))
        return error(404, "no switch '" + name + "'");
      return reply(200, Json{{"name", name}, {"on", std::get<bool>(parsed)}});
    });
    http.route("POST", "/api/trace", Lane::kControl, [this](const Request& req) {
      auto parsed = api::parse_trace_request(req.body);
      if (auto* problem = std::get_if<std::string>(&parsed)) return error(400, *problem);
      const std::vector<std::string> problems = diagnostics.start_trace(std::get<TraceRequest>(parsed));
      if (!problems.empty()) {
        std::string message;
        for (const auto& p : problems)
          message += (message.empty() ? "" : "; ") + p;
        const bool busy = problems.size() == 1 && problems[0].find("not yet taken") != std::string::npos;
        return error(busy ? 503 : 400, message);
      }
      return reply(200, Json{{"started", true}});
    });
    http.route("POST", "/api/trace/stop", Lane::kControl, [this](const Request&) {
      diagnostics.stop_trace();
      return reply(200, Json{{"stopping", true}});
    });
    http.route("GET", "/api/trace", Lane::kRead, [this](const Request& req) {
      const auto points = int_param(req, "max_points", 2000, 2, 200000);
      if (!points) return error(400, "max_points: an integer 2 .. 200000");
      return reply(200, diagnostics.read([&](const Diagnostics::State& s) {
        return api::trace(s.trace, static_cast<std::size_t>(*points));
      }));
    });
    http.route("GET", "/api/trace.csv", Lane::kExport, [this](const Request&) { return trace_csv(); });
    http.route("GET", "/api/trace.png", Lane::kExport, [this](const Request& req) { return trace_png(req); });
  }

  void warn(std::string text) {
    std::fprintf(stderr, "tomc diagnostics: %s\n", text.c_str());
    warnings.push_back(std::move(text));
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
  s.routes();
  s.port = s.http.bind(s.options.bind_address, s.options.port);
  s.warnings.clear();
  if (!loopback(s.options.bind_address)) {
    s.warn("listening on " + s.options.bind_address +
           " beyond loopback: the token travels in clear (plain HTTP); " +
           "use it only on a trusted network or behind a TLS proxy");
    if ((s.options.bind_address == "0.0.0.0" || s.options.bind_address == "::") &&
        s.options.allowed_hosts.empty()) {
      s.warn(
          "bound to every address but no allowed_hosts configured: only requests for the loopback names are "
          "answered (Host allow-list)");
    }
  }
  s.diagnostics.poll();
  s.publish_status();  // /api/status has an answer from the first request on
  {
    std::lock_guard lock(s.collector_mutex);
    s.stopping = false;
  }
  s.running.store(true);
  s.http.start();
  s.collector = std::thread([&s] { s.collect(); });
}

void Server::stop() {
  Impl& s = *impl_;
  if (!s.running.exchange(false)) return;
  {
    std::lock_guard lock(s.collector_mutex);
    s.stopping = true;
  }
  s.collector_wake.notify_all();
  if (s.collector.joinable()) s.collector.join();
  s.http.stop();
}

int Server::port() const noexcept {
  return impl_->port;
}

std::string Server::url() const {
  const std::string& a = impl_->options.bind_address;
  const std::string host = a == "0.0.0.0" ? "127.0.0.1" : a;
  return "http://" + host + ":" + std::to_string(impl_->port) + "/";
}

Server::Statistics Server::statistics() const {
  return Statistics{impl_->http.statistics(), impl_->exports_rendered.load(), impl_->exports_cached.load()};
}

const std::vector<std::string>& Server::warnings() const noexcept {
  return impl_->warnings;
}

}  // namespace tomc::diagnostics
