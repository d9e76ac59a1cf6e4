// The web API over HTTP (docs/diagnostics.md), against a machine whose runtime runs in real time (1 ms) on
// its own thread, as in `tomc demo`: status JSON, control actions with and without the token, traces and
// their CSV/PNG export, server-sent events, and malformed requests, which get a 4xx answer and leave the
// runtime running undisturbed.
#include <gtest/gtest.h>
#include <httplib.h>

#include <sched.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <thread>

#include "../diagnostics/diagnostics_fixture.hpp"
#include "../diagnostics/positioning_panel_fixture.hpp"
#include "tomc/diagnostics/api.hpp"
#include "tomc/diagnostics/server.hpp"
#include "tomc/techobjects/runtime/realtime_runner.hpp"

namespace {

using namespace tomc;
using Json = nlohmann::json;
using namespace std::chrono_literals;

constexpr const char* kToken = "s3cret-t0ken";
constexpr const char* kSession = "00000000c0ffee01";

std::size_t item_index(const Json& objects, std::string_view area, std::string_view label,
                       std::size_t object);

// The index of a layout area of the first object by its title.
std::size_t item_area(const Json& objects, std::string_view title) {
  const Json& layout = objects["objects"][0]["layout"];
  for (std::size_t a = 0; a < layout.size(); ++a) {
    if (layout[a]["title"] == title) return a;
  }
  ADD_FAILURE() << "no area " << title;
  return 0;
}

// The speed setpoint of an object in a /api/status answer (the cycle's data are only read through the API:
// the runtime runs on another thread).
double speed_setpoint(const Json& objects, const Json& status, std::size_t object) {
  const Json& v =
      status["objects"][object]["items"][item_index(objects, "Setpoints", "Speed setpoint", object)];
  return v.is_number() ? v.get<double>() : 0.0;
}

// HTTP helpers against a running server.
struct Http {
  const diagnostics::Server* server = nullptr;
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", server->port());
    c.set_read_timeout(5, 0);
    return c;
  }
  // Status code and parsed body (null if the body is not JSON).
  std::pair<int, Json> get(const std::string& path) const {
    auto c = client();
    auto r = c.Get(path);
    if (!r) return {0, nullptr};
    return {r->status, Json::parse(r->body, nullptr, false)};
  }
  std::pair<int, Json> post(const std::string& path, const std::string& body,
                            const char* token = kToken) const {
    auto c = client();
    httplib::Headers headers;
    if (token != nullptr) headers.emplace("Authorization", std::string("Bearer ") + token);
    auto r = c.Post(path, headers, body, "application/json");
    if (!r) return {0, nullptr};
    return {r->status, Json::parse(r->body, nullptr, false)};
  }
  // Polls /api/status until `predicate(status)` holds (at most `timeout`).
  template <typename Predicate>
  Json wait_status(Predicate predicate, std::chrono::milliseconds timeout = 5000ms) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    Json last;
    while (std::chrono::steady_clock::now() < deadline) {
      last = get("/api/status").second;
      bool met = false;
      try {
        met = last.is_object() && predicate(last);  // a part not there yet (no snapshot) is "not yet"
      } catch (const Json::exception&) {
      }
      if (met) return last;
      std::this_thread::sleep_for(20ms);
    }
    ADD_FAILURE() << "condition not met; last status: " << last.dump().substr(0, 400);
    return last;
  }
};

using ExportPriority = diagnostics::http::ServerLimits::ExportPriority;

struct Served : Http {
  explicit Served(std::string token = kToken, std::size_t axes = 1,
                  ExportPriority exports = ExportPriority::kIdle)
      : machine(axes, diagnostics::DiagnosticsConfig{5, 4096, 500}) {
    // The program's inputs are set before the cycle starts: afterwards only the API changes the machine.
    for (std::size_t i = 1; i < axes; ++i) {
      machine.programs[i]->power.Enable = true;
      machine.programs[i]->move.Velocity = 300.0;
      machine.programs[i]->run = true;
    }
    diagnostics::ServerOptions options;
    options.port = 0;
    options.token = std::move(token);
    options.runner_statistics = [this] { return runner.statistics(); };
    options.limits.export_priority = exports;
    owned_server = std::make_unique<diagnostics::Server>(machine.diagnostics, options);
    server = owned_server.get();
    owned_server->start();
    runner.start();
    objects = get("/api/objects").second;
  }
  ~Served() {
    owned_server->stop();
    runner.stop();
  }
  std::pair<int, Json> panel(const std::string& command, Json extra = Json::object()) const {
    extra["command"] = command;
    extra["session"] = kSession;
    return post("/api/panel/Axis1", extra.dump());
  }

  tomc::testing::DiagnosticsMachine machine;
  techobjects::RealTimeRunner runner{techobjects::RealTimeRunnerConfig{1ms, 0, false},
                                     [this] { machine.runtime.step(); }};
  std::unique_ptr<diagnostics::Server> owned_server;
  Json objects;
};

// The positioning axis "Slide" (positioning_panel_fixture.hpp) served in real time.
struct ServedSlide : Http {
  ServedSlide() : machine(diagnostics::DiagnosticsConfig{5, 4096, 500}) {
    diagnostics::ServerOptions options;
    options.port = 0;
    options.token = kToken;
    owned_server = std::make_unique<diagnostics::Server>(machine.diagnostics, options);
    server = owned_server.get();
    owned_server->start();
    runner.start();
  }
  ~ServedSlide() {
    owned_server->stop();
    runner.stop();
  }
  std::pair<int, Json> panel(const std::string& command, Json extra = Json::object(),
                             const char* token = kToken) const {
    extra["command"] = command;
    extra["session"] = kSession;
    return post("/api/panel/Slide", extra.dump(), token);
  }
  // A data-block variable of the slide from /api/objects/Slide/variables.
  double variable(std::string_view path) const {
    const Json v = get("/api/objects/Slide/variables").second;
    for (const auto& x : v["variables"]) {
      if (x["path"] == path && x["value"].is_number()) return x["value"].get<double>();
    }
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Polls the variable until it equals `value` (5 s at most).
  bool wait_variable(std::string_view path, double value) const {
    const auto deadline = std::chrono::steady_clock::now() + 5s;
    while (std::chrono::steady_clock::now() < deadline) {
      if (variable(path) == value) return true;
      std::this_thread::sleep_for(20ms);
    }
    ADD_FAILURE() << path << " did not reach " << value << " (last " << variable(path) << ")";
    return false;
  }
  static std::uint32_t status_word(const Json& j) {
    return static_cast<std::uint32_t>(j["objects"][0]["words"]["StatusWord"].get<double>());
  }

  tomc::testing::PositioningDiagnosticsMachine machine;
  techobjects::RealTimeRunner runner{techobjects::RealTimeRunnerConfig{1ms, 0, false},
                                     [this] { machine.runtime.step(); }};
  std::unique_ptr<diagnostics::Server> owned_server;
};

// Index of a layout item of an object in /api/objects.
std::size_t item_index(const Json& objects, std::string_view area, std::string_view label,
                       std::size_t object = 0) {
  std::size_t index = 0;
  for (const auto& a : objects["objects"][object]["layout"]) {
    for (const auto& i : a["items"]) {
      if (a["title"] == area && i["label"] == label) return index;
      ++index;
    }
  }
  ADD_FAILURE() << "no item " << area << "/" << label;
  return 0;
}

TEST(WebApi, ObjectsAndStatus) {
  Served s;
  const auto [code, objects] = s.get("/api/objects");
  ASSERT_EQ(code, 200);
  ASSERT_EQ(objects["objects"].size(), 1u);
  const Json& o = objects["objects"][0];
  EXPECT_EQ(o["name"], "Axis1");
  EXPECT_EQ(o["type"], "TO_SpeedAxis");
  EXPECT_EQ(o["telegrams"]["drive"], 3);
  EXPECT_EQ(o["telegram"].size(), 10u);  // telegram 3: 6 actual + 4 setpoint words
  EXPECT_EQ(o["telegram"][0]["signal"], "ZSW1");
  EXPECT_FALSE(o["telegram"][0]["fields"].empty());
  const auto caps = o["capabilities"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(caps.begin(), caps.end(), "jog"), caps.end());
  EXPECT_EQ(std::find(caps.begin(), caps.end(), "move_absolute"), caps.end());

  // The first snapshot is of cycle 0: wait for one of a later cycle, so that "cycle" shows progress (on a
  // loaded machine the page can be asked between the first and the second publication).
  const Json status = s.wait_status(
      [](const Json& j) { return j["objects"][0]["valid"] == true && j["cycle"].get<std::uint64_t>() > 0; });
  const Json& a = status["objects"][0];
  EXPECT_EQ(a["name"], "Axis1");
  EXPECT_TRUE(a["words"]["StatusWord"].is_number());
  EXPECT_EQ(a["items"].size(), 7u + 8u + 3u + 8u + 2u + 2u + 4u);
  EXPECT_EQ(a["telegram"].size(), 10u);
  EXPECT_EQ(a["items"][item_index(objects, "Axis status", "Enabled")], 0.0);
  EXPECT_DOUBLE_EQ(a["items"][item_index(objects, "Dynamic limits", "Velocity")].get<double>(), 3000.0);
  EXPECT_EQ(status["read_only"], false);
  EXPECT_GT(status["runner"]["cycles"].get<std::uint64_t>(), 0u);
  EXPECT_GT(status["cycle"].get<std::uint64_t>(), 0u);

  const auto [vcode, vars] = s.get("/api/objects/Axis1/variables");
  ASSERT_EQ(vcode, 200);
  EXPECT_EQ(vars["variables"].size(), techobjects::speed_axis_variables().size());
  EXPECT_EQ(vars["variables"][0]["path"], "Velocity");
  // Units from the TO's configuration (issue 21; spec 04 §3.11): a speed axis in 1/min, 1/s², 1/s³.
  EXPECT_EQ(vars["variables"][0]["unit"], "1/min");
  EXPECT_EQ(o["units"]["velocity"], "1/min");
  EXPECT_EQ(o["units"]["acceleration"], "1/s²");
  EXPECT_EQ(o["units"]["jerk"], "1/s³");
  EXPECT_EQ(o["units"]["position"], "");
  const Json& limits = o["layout"][item_area(objects, "Dynamic limits")]["items"][0];
  EXPECT_EQ(limits["label"], "Velocity");
  EXPECT_EQ(limits["unit"], "1/min");
  EXPECT_GT(o["reference_speed"].get<double>(), 0.0);  // 100 % of NSOLL/NIST on the telegram page
  const auto [acode, alarms] = s.get("/api/objects/Axis1/alarms");
  ASSERT_EQ(acode, 200);
  EXPECT_TRUE(alarms["pending"].empty());
}

// Decision W14 (bearer token on every POST: 401 without, 403 wrong).
TEST(WebApi, ControlActionsNeedTheToken) {
  Served s;
  EXPECT_EQ(s.post("/api/panel/Axis1", R"({"command":"take","session":"1"})", nullptr).first, 401);
  EXPECT_EQ(s.post("/api/panel/Axis1", R"({"command":"take","session":"1"})", "wrong").first, 403);
  EXPECT_EQ(s.post("/api/panel/Axis1", R"({"command":"take","session":"1"})", "s3cret-t0ke").first, 403);
  EXPECT_EQ(s.post("/api/trace", R"({"channels":["Axis1.Velocity"]})", nullptr).first, 401);
  EXPECT_EQ(s.post("/api/trace/stop", "", nullptr).first, 401);
  EXPECT_EQ(s.wait_status([](const Json& j) {
    return j["objects"][0]["valid"] == true;
  })["objects"][0]["panel"]["held"],
            false);
  const auto [code, body] = s.post("/api/panel/Axis1", R"({"command":"take","session":"1"})");
  EXPECT_EQ(code, 200);
  EXPECT_EQ(body["answer"], "accepted");
}

// Decision W14 (read-only unless a token is configured).
TEST(WebApi, ReadOnlyWithoutToken) {
  Served s("");
  const auto [code, body] = s.post("/api/panel/Axis1", R"({"command":"take","session":"1"})", "anything");
  EXPECT_EQ(code, 403);
  EXPECT_NE(body["error"].get<std::string>().find("read-only"), std::string::npos);
  EXPECT_EQ(s.get("/api/status").first, 200);  // reading is allowed
  EXPECT_EQ(s.get("/api/status").second["read_only"], true);
}

// Take master control, enable, jog: the velocity rises; release; a second session is refused; give back.
TEST(WebApi, PanelJogsTheAxis) {
  Served s;
  ASSERT_EQ(s.panel("take", {{"lifebeat_s", 5.0}}).first, 200);
  ASSERT_EQ(s.panel("enable").first, 200);
  s.wait_status([](const Json& j) { return j["objects"][0]["panel"]["instructions"][0]["active"] == true; });
  ASSERT_EQ(s.panel("jog", {{"direction", 1}}).first, 200);
  s.wait_status([](const Json& j) {
    return (j["objects"][0]["panel"]["motion"] == "jog forwards") &&
           j["objects"][0]["words"]["StatusWord"].get<double>() > 0 &&
           (static_cast<std::uint32_t>(j["objects"][0]["words"]["StatusWord"].get<double>()) & (1u << 9)) !=
               0;
  });
  s.wait_status([&](const Json& j) { return speed_setpoint(s.objects, j, 0) > 100.0; });
  ASSERT_EQ(s.panel("lifebeat").first, 200);
  ASSERT_EQ(s.panel("jog", {{"direction", 0}}).first, 200);
  // Another page: refused while this one holds master control.
  Json other = {{"command", "take"}, {"session", "abcdef"}};
  const auto [code, body] = s.post("/api/panel/Axis1", other.dump());
  EXPECT_EQ(code, 409);
  EXPECT_EQ(body["answer"], "held_by_other_session");
  other["command"] = "enable";
  EXPECT_EQ(s.post("/api/panel/Axis1", other.dump()).first, 409);
  // Position functions do not exist on a speed axis.
  EXPECT_EQ(s.panel("move_absolute", {{"position", 10.0}}).first, 422);
  ASSERT_EQ(s.panel("give_back").first, 200);
  // Giving control back stops the axis with its ramp (spec 02 §9.2): the page no longer holds it and the
  // setpoint reaches 0. A status may show the first before the second on a slow (sanitizer) build, so the
  // test waits for both, bounded.
  const Json back = s.wait_status(
      [&](const Json& j) {
        return j["objects"][0]["panel"]["held"] == false && speed_setpoint(s.objects, j, 0) == 0.0;
      },
      15000ms);
  EXPECT_EQ(back["objects"][0]["panel"]["held"], false);
  EXPECT_EQ(speed_setpoint(s.objects, back, 0), 0.0);
}

// spec 02 §9.2: when the page stops sending lifebeats the axis stops and control priority returns.
TEST(WebApi, LifebeatLossOverHttp) {
  Served s;
  ASSERT_EQ(s.panel("take", {{"lifebeat_s", 0.3}}).first, 200);
  ASSERT_EQ(s.panel("enable").first, 200);
  ASSERT_EQ(s.panel("velocity", {{"direction", -1}}).first, 200);
  const Json j = s.wait_status([](const Json& j) {
    return j["objects"][0]["panel"]["held"] == false && j["objects"][0]["panel"]["error_id"] == "16#8013";
  });
  EXPECT_EQ(j["objects"][0]["panel"]["error_text"].get<std::string>().find("lifebeat"), 0u);
}

// The positioning axis' panel over HTTP (spec 02 §9.2-§9.4): the token is needed; set position (MC_Home
// Mode 0) makes the axis homed (StatusWord.X5); an absolute move reaches its target; parameters out of range
// get 400 before they reach the cycle, and an error of the TO (16#8105, not homed) reaches the status.
TEST(WebApi, PositioningPanelHomesAndPositions) {
  ServedSlide s;
  const auto objects = s.get("/api/objects").second;
  const auto caps = objects["objects"][0]["capabilities"].get<std::vector<std::string>>();
  // A linear positioning axis in mm and mm/s (the data block's defaults, spec 04 §3.11).
  EXPECT_EQ(objects["objects"][0]["units"]["position"], "mm");
  EXPECT_EQ(objects["objects"][0]["units"]["velocity"], "mm/s");
  EXPECT_EQ(objects["objects"][0]["units"]["acceleration"], "mm/s²");
  for (const char* c : {"home_active", "home_set", "move_absolute", "move_relative", "jog"})
    EXPECT_NE(std::find(caps.begin(), caps.end(), c), caps.end()) << c;
  EXPECT_EQ(objects["objects"][0]["instructions"].size(), 8u);
  EXPECT_EQ(s.panel("take", {{"lifebeat_s", 5.0}}, nullptr).first, 401);
  EXPECT_EQ(s.panel("take", {{"lifebeat_s", 5.0}}, "wrong").first, 403);
  ASSERT_EQ(s.panel("take", {{"lifebeat_s", 5.0}}).first, 200);
  ASSERT_EQ(s.panel("enable").first, 200);
  s.wait_status([](const Json& j) { return (ServedSlide::status_word(j) & 1u) != 0; });
  // Not homed: accepted by the panel, refused by the TO; the ErrorID reaches the page.
  ASSERT_EQ(s.panel("move_absolute", {{"position", 10.0}}).first, 200);
  s.wait_status([](const Json& j) { return j["objects"][0]["panel"]["error_id"] == "16#8105"; });

  struct Case {
    const char* command;
    Json parameters;
  };
  const std::vector<Case> bad = {
      {"home", {{"mode", "passive"}, {"position", 0.0}}},
      {"home", {{"mode", "set"}}},
      {"home", {{"mode", "set"}, {"position", "zero"}}},
      {"move_absolute", Json::object()},
      {"move_absolute", {{"position", 1.0}, {"direction", 2}}},
      {"move_relative", {{"distance", 1.0}, {"direction", 0}}},
      {"move_relative", {{"distance", 1.0}, {"speed", 3}}},
  };
  for (const auto& c : bad) {
    const auto [code, body] = s.panel(c.command, c.parameters);
    EXPECT_EQ(code, 400) << c.command << " " << c.parameters.dump();
    EXPECT_TRUE(body.contains("error")) << body.dump();
  }

  ASSERT_EQ(s.panel("home", {{"mode", "set"}, {"position", 40.0}}).first, 200);
  s.wait_status([](const Json& j) { return (ServedSlide::status_word(j) & (1u << 5)) != 0; });
  EXPECT_NEAR(s.variable("ActualPosition"), 40.0, 0.01);
  // The telegram page shows XIST1 with the position the TO derives from encoder 1 (issue 21).
  const Json homed = s.wait_status([](const Json& j) {
    const Json& p = j["objects"][0]["encoder_positions"][0];
    return p.is_number() && std::abs(p.get<double>() - 40.0) < 0.01;
  });
  EXPECT_TRUE(homed["objects"][0]["encoder_positions"][1].is_number());  // Sensor[2] exists, unused
  ASSERT_EQ(s.panel("move_absolute", {{"position", 60.0}}).first, 200);
  EXPECT_TRUE(s.wait_variable("Position", 60.0));
  ASSERT_EQ(s.panel("move_relative", {{"distance", 5.0}, {"direction", -1}}).first, 200);
  EXPECT_TRUE(s.wait_variable("Position", 55.0));
  s.wait_status([](const Json& j) { return j["objects"][0]["panel"]["motion"] == "none"; });
  ASSERT_EQ(s.panel("give_back").first, 200);
  s.wait_status([](const Json& j) {
    return j["objects"][0]["panel"]["held"] == false && (ServedSlide::status_word(j) & 1u) == 0;
  });
}

// spec 02 §9.2: the page stops sending lifebeats while the positioning axis moves: it stops, is disabled,
// master control returns to the program, 16#8013.
TEST(WebApi, PositioningAxisLifebeatLossOverHttp) {
  ServedSlide s;
  ASSERT_EQ(s.panel("take", {{"lifebeat_s", 0.5}}).first, 200);
  ASSERT_EQ(s.panel("enable").first, 200);
  s.wait_status([](const Json& j) { return (ServedSlide::status_word(j) & 1u) != 0; });
  ASSERT_EQ(s.panel("jog", {{"direction", 1}}).first, 200);
  s.wait_status([](const Json& j) {
    return (ServedSlide::status_word(j) & (1u << 9)) != 0;  // X9 JogCommand
  });
  const Json j = s.wait_status([](const Json& j) {
    return j["objects"][0]["panel"]["held"] == false && j["objects"][0]["panel"]["error_id"] == "16#8013";
  });
  s.wait_status([](const Json& j) { return (ServedSlide::status_word(j) & (1u | 16u)) == 0; });
  EXPECT_GT(s.variable("ActualPosition"), 0.0);
}

TEST(WebApi, TraceAndExports) {
  // Axis2 runs under its program at 300 1/min. Exports at normal priority: at SCHED_IDLE (the default, tested
  // below) they wait for spare CPU, minutes on a saturated CI machine (decision V13).
  Served s(kToken, 2, ExportPriority::kNormal);
  const Json request = {
      {"channels", {"Axis2.Velocity", "Axis2.StatusWord.X12", "Axis2.telegram.drive.NIST_B"}},
      {"trigger", {{"kind", "immediate"}}},
      {"post_samples", 300}};
  ASSERT_EQ(s.post("/api/trace", request.dump()).first, 200);
  s.wait_status([](const Json& j) { return j["trace"]["state"] == "complete"; });
  const auto [code, trace] = s.get("/api/trace?max_points=50");
  ASSERT_EQ(code, 200);
  EXPECT_EQ(trace["rows"], 300);
  EXPECT_LE(trace["time_s"].size(), 51u);
  EXPECT_EQ(trace["values"].size(), 3u);
  EXPECT_EQ(trace["channels"][0], "Axis2.Velocity");

  auto c = s.client();
  // Exports need the token (issue 21: they cost CPU and memory; anyone on the machine could ask for them).
  EXPECT_EQ(c.Get("/api/trace.csv")->status, 401);
  EXPECT_EQ(c.Get("/api/trace.png")->status, 401);
  c.set_bearer_token_auth(kToken);
  c.set_read_timeout(60, 0);  // a render under TSan on a loaded machine takes seconds
  auto csv = c.Get("/api/trace.csv");
  ASSERT_TRUE(csv);
  EXPECT_EQ(csv->status, 200);
  EXPECT_EQ(csv->get_header_value("Content-Type"), "text/csv");
  std::istringstream lines(csv->body);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "cycle,time,Axis2.Velocity,Axis2.StatusWord.X12,Axis2.telegram.drive.NIST_B");
  int rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 4) << line;
  }
  EXPECT_EQ(rows, 300);

  auto png = c.Get("/api/trace.png?width=800&height=500");
  ASSERT_TRUE(png);
  EXPECT_EQ(png->status, 200);
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  ASSERT_GT(png->body.size(), 8u);
  EXPECT_EQ(png->body.substr(1, 3), "PNG");
  const std::vector<std::uint8_t> bytes(png->body.begin(), png->body.end());
  const cv::Mat image = cv::imdecode(bytes, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 800);
  EXPECT_EQ(image.rows, 500);
  EXPECT_EQ(c.Get("/api/trace.png?width=10")->status, 400);
}

// The scheduling policy the kernel reports for the server's export lane (the thread named "tomc-export").
int export_lane_policy() {
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream comm(task.path() / "comm");
    std::string name;
    std::getline(comm, name);
    if (name == "tomc-export") return ::sched_getscheduler(std::stoi(task.path().filename().string()));
  }
  return -1;
}

// Decisions D4 and V13: trace exports run at SCHED_IDLE unless the user chooses "normal"
// (`diagnostics.export_priority`), which leaves the lane at the server's own SCHED_OTHER.
TEST(WebApi, ExportLaneRunsAtIdlePriorityUnlessNormalIsChosen) {
  for (const auto& [priority, expected] :
       {std::pair{ExportPriority::kIdle, SCHED_IDLE}, std::pair{ExportPriority::kNormal, SCHED_OTHER}}) {
    Served s(kToken, 1, priority);
    int policy = export_lane_policy();
    const auto deadline = std::chrono::steady_clock::now() + 5s;  // the lane sets its policy when it starts
    while (policy != expected && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(10ms);
      policy = export_lane_policy();
    }
    EXPECT_EQ(policy, expected) << (priority == ExportPriority::kIdle ? "idle" : "normal");
  }
}
// docs/diagnostics.md "HTTP API" (GET /api/events: one data: <status> event per period), decision W12.
TEST(WebApi, ServerSentEvents) {
  Served s;
  auto c = s.client();
  int events = 0;
  std::string buffer;
  bool parsed = true;
  auto r = c.Get("/api/events", [&](const char* data, std::size_t length) {
    buffer.append(data, length);
    std::size_t end;
    while ((end = buffer.find("\n\n")) != std::string::npos) {
      const std::string event = buffer.substr(0, end);
      buffer.erase(0, end + 2);
      if (event.rfind("data: ", 0) == 0) {
        parsed = parsed && Json::parse(event.substr(6), nullptr, false).is_object();
        ++events;
      }
    }
    return events < 3;  // stop after three events
  });
  EXPECT_EQ(events, 3);
  EXPECT_TRUE(parsed);
}

// Malformed requests: 4xx, and the runtime goes on undisturbed (no overrun, the cycle counter advances, the
// program's axis keeps its velocity).
TEST(WebApi, BadRequestsGet4xxAndDoNotDisturbTheRuntime) {
  Served s(kToken, 2);
  s.wait_status([&](const Json& j) { return speed_setpoint(s.objects, j, 1) == 300.0; });
  const auto cycles_before = s.runner.statistics().cycles;
  struct Case {
    std::string path;
    std::string body;
    int status;
  };
  const std::vector<Case> cases = {
      {"/api/panel/Axis1", "{", 400},
      {"/api/panel/Axis1", "[1,2]", 400},
      {"/api/panel/Axis1", "\"take\"", 400},
      {"/api/panel/Axis1", R"({"command":"fly","session":"1"})", 400},
      {"/api/panel/Axis1", R"({"command":"take"})", 400},
      {"/api/panel/Axis1", R"({"command":"take","session":"xyz"})", 400},
      {"/api/panel/Axis1", R"({"command":"take","session":"0"})", 400},
      {"/api/panel/Axis1", R"({"command":"take","session":"1","extra":1})", 400},
      {"/api/panel/Axis1", R"({"command":"jog","session":"1","direction":2})", 400},
      {"/api/panel/Axis1", R"({"command":"jog","session":"1","direction":"up"})", 400},
      {"/api/panel/Axis1", R"({"command":"adapt","session":"1","percent":1e999})", 400},
      {"/api/panel/Axis1", std::string(100, '[') + std::string(100, ']'), 400},
      {"/api/panel/Axis1", "\xff\xfe\x00\x01", 400},
      {"/api/panel/Nobody", R"({"command":"take","session":"1"})", 404},
      {"/api/panel/Axis1", R"({"command":"enable","session":"1"})", 409},  // not the holder
      {"/api/trace", R"({"channels":[]})", 400},
      {"/api/trace", R"({"channels":["Axis1.NoSuchThing"]})", 400},
      {"/api/trace",
       R"({"channels":["Axis1.Velocity"],"trigger":{"kind":"above","signal":"Axis1.Velocity"}})", 400},
      {"/api/trace", R"({"channels":["Axis1.Velocity"],"post_samples":1000000})", 400},
      {"/api/switches/none", R"({"on":true})", 404},
      {"/api/switches/none", R"({"on":"yes"})", 400},
      {"/api/nothing", "{}", 404},
  };
  for (const Case& k : cases) {
    const auto [code, body] = s.post(k.path, k.body);
    EXPECT_EQ(code, k.status) << k.path << " " << k.body;
    EXPECT_TRUE(body.is_object() && (body.contains("error") || body.contains("answer"))) << k.body;
  }
  auto c = s.client();
  EXPECT_EQ(c.Get("/api/nothing")->status, 404);
  EXPECT_EQ(c.Get("/api/objects/Nobody/variables")->status, 404);
  // The cam plot (decision W20) exists for cams only.
  EXPECT_EQ(c.Get("/api/objects/Nobody/plot")->status, 404);
  EXPECT_EQ(c.Get("/api/objects/Axis1/plot")->status, 404);
  EXPECT_EQ(c.Get("/api/trace?max_points=abc")->status, 400);
  httplib::Headers bearer{{"Authorization", std::string("Bearer ") + kToken}};
  EXPECT_EQ(c.Get("/api/trace.png?height=99999", bearer)->status, 400);
  // A body over 64 KiB.
  httplib::Headers auth{{"Authorization", std::string("Bearer ") + kToken}};
  const auto big = c.Post("/api/panel/Axis1", auth, std::string(70 * 1024, ' '), "application/json");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
  // Another Host (DNS rebinding): refused.
  httplib::Headers host{{"Host", "attacker.example:80"}};
  EXPECT_EQ(c.Get("/api/status", host)->status, 421);

  // The runtime ran on: cycles advanced, the program's axis still at its velocity, no panel was taken.
  // Waits for a cycle after the requests (bounded) instead of sleeping 50 ms: a starved runner thread is
  // late, not stopped (issue 22).
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (s.runner.statistics().cycles <= cycles_before && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(1ms);
  EXPECT_GT(s.runner.statistics().cycles, cycles_before);
  const Json after = s.wait_status([](const Json& j) { return j["objects"][1]["valid"] == true; });
  EXPECT_EQ(speed_setpoint(s.objects, after, 1), 300.0);
  EXPECT_EQ(after["objects"][0]["panel"]["held"], false);
}

// SO_REUSEPORT is off: a second server on the same port fails to start instead of sharing connections.
TEST(WebApi, SecondServerOnTheSamePortFails) {
  Served s;
  diagnostics::ServerOptions options;
  options.port = s.server->port();
  diagnostics::Server second(s.machine.diagnostics, options);
  EXPECT_THROW(second.start(), std::runtime_error);
}

TEST(WebApi, PageIsServed) {
  Served s;
  auto c = s.client();
  auto r = c.Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->get_header_value("Content-Type").find("text/html"), std::string::npos);
  EXPECT_FALSE(r->get_header_value("Content-Security-Policy").empty());
  EXPECT_EQ(r->body, std::string(diagnostics::web_page()));
  // The plotting library comes from this server, not from a CDN (issue 21): the page names only local files.
  EXPECT_EQ(r->body.find("https://"), std::string::npos);
  for (const auto& [path, type] : {std::pair{"/vendor/uPlot.iife.min.js", "text/javascript"},
                                   std::pair{"/vendor/uPlot.min.css", "text/css"}}) {
    EXPECT_NE(r->body.find(path), std::string::npos) << path;
    auto asset = c.Get(path);
    ASSERT_TRUE(asset) << path;
    EXPECT_EQ(asset->status, 200) << path;
    EXPECT_NE(asset->get_header_value("Content-Type").find(type), std::string::npos) << path;
    EXPECT_GT(asset->body.size(), 1000u) << path;  // the library (~50 KB), its style sheet (~2 KB)
  }
  auto script = c.Get("/vendor/uPlot.iife.min.js");
  ASSERT_TRUE(script);
  EXPECT_NE(script->body.find("uPlot"), std::string::npos);
}

// Issue 21: panel values are range-checked against the axis' limits and the data-block ranges before they
// reach the cycle, with a message that says which limit (a 1e308 velocity, a ±1e308 set position on a modulo
// axis were accepted before).
TEST(PanelRanges, AgainstTheDataBlock) {
  const auto table = diagnostics::variables_of(techobjects::TechnologyObjectType::kPositioningAxis);
  std::vector<double> values(table.size(), 0.0);
  const auto set = [&](std::string_view path, double v) {
    for (std::size_t i = 0; i < table.size(); ++i)
      if (table[i].path == path) return void(values[i] = v);
    ADD_FAILURE() << "no variable " << path;
  };
  set("DynamicLimits.MaxVelocity", 500.0);
  set("DynamicLimits.MaxAcceleration", 1000.0);
  set("DynamicLimits.MaxDeceleration", 2000.0);
  set("DynamicLimits.MaxJerk", 0.0);  // no jerk limit: any jerk up to the data-block range
  set("Modulo.Enable", 1.0);
  set("Modulo.StartValue", 0.0);
  set("Modulo.Length", 360.0);
  diagnostics::PanelCommand c;
  const auto check = [&] { return diagnostics::api::check_panel_ranges(c, table, values); };

  c.kind = diagnostics::PanelCommandKind::kSetDynamics;
  c.dynamics = {500.0, 1000.0, 2000.0, 1e6};
  EXPECT_EQ(check(), std::nullopt);
  c.dynamics.velocity = 1e308;
  ASSERT_TRUE(check());
  EXPECT_NE(check()->find("outside -1.0E12 .. 1.0E12"), std::string::npos) << *check();
  c.dynamics.velocity = 500.5;
  ASSERT_TRUE(check());
  EXPECT_EQ(*check(), "velocity: 500.5 above the axis' DynamicLimits.MaxVelocity 500");
  c.dynamics = {100.0, 1000.1, 100.0, 0.0};
  EXPECT_NE(check().value_or("").find("MaxAcceleration"), std::string::npos);
  set("DynamicLimits.MaxJerk", 50.0);
  c.dynamics = {100.0, 100.0, 100.0, 60.0};
  EXPECT_NE(check().value_or("").find("MaxJerk"), std::string::npos);

  c.kind = diagnostics::PanelCommandKind::kHome;
  c.mode = 0;
  for (const double bad : {1e308, -1e308, 360.0, -0.001}) {
    c.value = bad;
    EXPECT_TRUE(check()) << bad;
  }
  c.value = 359.9;
  EXPECT_EQ(check(), std::nullopt);
  c.kind = diagnostics::PanelCommandKind::kMoveAbsolute;
  c.value = 400.0;
  EXPECT_NE(check().value_or("").find("modulo range 0 .. 360"), std::string::npos) << check().value_or("");

  // A linear axis with active software limits: an absolute target beyond them is refused; without a snapshot
  // only the data-block range is checked.
  set("Modulo.Enable", 0.0);
  set("PositionLimits_SW.Active", 1.0);
  set("PositionLimits_SW.MinPosition", -5.0);
  set("PositionLimits_SW.MaxPosition", 305.0);
  c.kind = diagnostics::PanelCommandKind::kMoveAbsolute;
  c.value = 400.0;
  EXPECT_NE(check().value_or("").find("software limits -5 .. 305"), std::string::npos);
  c.value = 300.0;
  EXPECT_EQ(check(), std::nullopt);
  EXPECT_EQ(diagnostics::api::check_panel_ranges(c, table, {}), std::nullopt);
  c.value = -2e12;
  EXPECT_TRUE(diagnostics::api::check_panel_ranges(c, table, {}));
  c.kind = diagnostics::PanelCommandKind::kMoveRelative;
  c.value = 1e308;
  EXPECT_TRUE(check());
  c.kind = diagnostics::PanelCommandKind::kTake;
  c.value = 3600.0;
  EXPECT_NE(check().value_or("").find("lifebeat_s"), std::string::npos);
}

// The same over HTTP: 400 with the message, before the command reaches the cycle.
TEST(WebApi, PanelValuesAreRangeChecked) {
  ServedSlide s;
  s.wait_status([](const Json& j) { return j["objects"][0]["valid"] == true; });
  ASSERT_EQ(s.panel("take", {{"lifebeat_s", 5.0}}).first, 200);
  const double max_velocity = s.variable("DynamicLimits.MaxVelocity");
  ASSERT_GT(max_velocity, 0.0);
  Json dynamics = {{"velocity", 1e308}, {"acceleration", 1.0}, {"deceleration", 1.0}, {"jerk", 0.0}};
  auto [code, body] = s.panel("dynamics", dynamics);
  EXPECT_EQ(code, 400);
  EXPECT_NE(body.value("error", "").find("1.0E12"), std::string::npos) << body.dump();
  dynamics["velocity"] = max_velocity * 1.5;
  std::tie(code, body) = s.panel("dynamics", dynamics);
  EXPECT_EQ(code, 400);
  EXPECT_NE(body.value("error", "").find("DynamicLimits.MaxVelocity"), std::string::npos) << body.dump();
  dynamics["velocity"] = max_velocity / 2;
  EXPECT_EQ(s.panel("dynamics", dynamics).first, 200);
  std::tie(code, body) = s.panel("home", {{"mode", "set"}, {"position", -1e308}});
  EXPECT_EQ(code, 400);
  EXPECT_NE(body.value("error", "").find("position"), std::string::npos) << body.dump();
  EXPECT_EQ(s.panel("move_relative", {{"distance", 1e300}}).first, 400);
  ASSERT_EQ(s.panel("give_back").first, 200);
}

// Issue 21: the Host allow-list (no DNS rebinding) holds for the configured names too: a name is answered
// only when it is the bound address, a loopback name or in allowed_hosts.
TEST(WebApi, HostAllowList) {
  tomc::testing::DiagnosticsMachine machine(1);
  for (const bool allowed : {false, true}) {
    diagnostics::ServerOptions options;
    options.port = 0;
    if (allowed) options.allowed_hosts = {"plc7.local", "192.168.0.7:8080"};
    diagnostics::Server server(machine.diagnostics, options);
    server.start();
    EXPECT_TRUE(server.warnings().empty());  // loopback: nothing to warn about
    httplib::Client c("127.0.0.1", server.port());
    const std::string port = ":" + std::to_string(server.port());
    const auto status = [&](const std::string& host) {
      auto r = c.Get("/api/info", httplib::Headers{{"Host", host}});
      return r ? r->status : 0;
    };
    EXPECT_EQ(status("127.0.0.1" + port), 200);
    EXPECT_EQ(status("localhost" + port), 200);
    EXPECT_EQ(status("plc7.local" + port), allowed ? 200 : 421);
    EXPECT_EQ(status("192.168.0.7:8080"), allowed ? 200 : 421);
    EXPECT_EQ(status("attacker.example" + port), 421);
    server.stop();
  }
}

}  // namespace
