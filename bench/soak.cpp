// The soak (issue 22, docs/reliability.md "Soak"; not a CI test): `tomc demo` — the demo machine with its
// diagnostics server and user program, in real time — with its Conveyor on a drive behind a `tomc
// gateway-sim` process (Fast DDS on loopback), a 32-channel trace re-armed whenever it completes, and the
// gateway killed and restarted every --fault-period seconds (link loss 405, acknowledged by the demo
// program's MC_Reset), so that the alarm history fills. Every --sample-period seconds it prints the demo
// process's resident memory (VmRSS) and the same net of the trace's samples (rows x 33 x 8 bytes: 32 values
// and the cycle; the capture grows while it records and starts again when re-armed), the real-time runner's
// cycles and overruns
// (/api/info), the alarm history kept per TO (/api/objects/<TO>/alarms) and the load average.
//
//   nice -n 19 build/bin/soak --seconds 3600 [--cycle-time 0.001] [--sample-period 60] [--fault-period 5]
//
// Free-running (--free-running): the same demo machine, diagnostics server, trace and program, but every
// drive is the demo's embedded simulated drive and `tomc demo --free-running` steps the cycles back to back
// on its virtual clock (a gateway-sim process runs in real time and cannot be compressed: 10^8 cycles would
// be 28 h). The faults are injected in the demo's cycle thread instead (`--inject-faults`: every N cycles a
// drive fault, an encoder error or a frozen sign-of-life on the next simulated drive in turn). The run ends
// after --cycles, samples are taken every --sample-cycles, and each also gives the demo's CPU time (cycles
// per CPU second):
//
//   nice -n 10 build/bin/soak --free-running --cycles 100000000 [--sample-cycles 5000000]
//       [--fault-period-cycles 2000] [--seconds 7200 (a cap)]
//
// Exit status 1 if the alarm history of a TO exceeds its bound (500 events), if resident memory net of the
// trace (free-running: VmRSS itself) grew by more than 1 MiB from the first sample after the warm-up (a
// quarter of the run) to the end, or if a step failed (the server not answering within 10 s is one).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <httplib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "../tests/dds/gateway_process.hpp"
#include "build_paths.hpp"

extern char** environ;

namespace {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}
using tomc::testing::GatewayProcess;

constexpr int kDomain = 57;  // a domain of its own (TOOLCHAIN §8): no test uses it
constexpr const char* kToken = "soak";
constexpr std::size_t kHistoryBound = 500;  // DiagnosticsConfig::alarm_history
constexpr long kRssGrowthBoundKib = 1024;
constexpr std::size_t kChannels = 32;

struct Options {
  double seconds = 600.0;
  double cycle_time_s = 0.001;
  double sample_period_s = 60.0;
  double fault_period_s = 5.0;
  bool free_running = false;
  double cycles = 1e8;  // free-running: the run's length
  double sample_cycles = 5e6;
  double fault_period_cycles = 2000;
};

Options parse(int argc, char** argv) {
  Options o;
  bool seconds_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--free-running") {
      o.free_running = true;
      continue;
    }
    if (i + 1 >= argc) throw std::invalid_argument("usage: see the comment at the top of bench/soak.cpp");
    const double v = std::stod(argv[++i]);
    if (!(v > 0.0)) throw std::invalid_argument(a + ": a positive number");
    const std::pair<const char*, double*> numbers[] = {{"--seconds", &o.seconds},
                                                       {"--cycle-time", &o.cycle_time_s},
                                                       {"--sample-period", &o.sample_period_s},
                                                       {"--fault-period", &o.fault_period_s},
                                                       {"--cycles", &o.cycles},
                                                       {"--sample-cycles", &o.sample_cycles},
                                                       {"--fault-period-cycles", &o.fault_period_cycles}};
    const auto known =
        std::find_if(std::begin(numbers), std::end(numbers), [&a](const auto& n) { return a == n.first; });
    if (known == std::end(numbers)) throw std::invalid_argument("unknown option " + a);
    if (a == "--fault-period-cycles" && !(v >= 40.0 && v == std::floor(v)))
      throw std::invalid_argument(a +
                                  ": a whole number of at least 40 (the demo's fault injector refuses less)");
    *known->second = v;
    seconds_given = seconds_given || a == "--seconds";
  }
  if (o.free_running && !seconds_given) o.seconds = 7200.0;  // a cap: the run ends after --cycles
  return o;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// `tomc demo` as a child process, its output in a log file; SIGTERM at the end (the demo's clean stop).
class DemoProcess {
 public:
  DemoProcess(const std::filesystem::path& config, const std::filesystem::path& log, double seconds,
              const std::vector<std::string>& extra)
      : log_(log) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<std::string> args = {
        TOMC_BINARY, "demo",   "--config", config.string(), "--token",
        kToken,      "--port", "0",        "--seconds",     std::to_string(seconds)};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (auto& a : args)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    const int r = posix_spawn(&pid_, TOMC_BINARY, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (r != 0) throw std::runtime_error("cannot start tomc demo");
  }
  ~DemoProcess() {
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  DemoProcess(const DemoProcess&) = delete;
  DemoProcess& operator=(const DemoProcess&) = delete;

  pid_t pid() const { return pid_; }
  // The port of the printed URL, once the server listens (bounded: 30 s).
  int port() const {
    for (int i = 0; i < 300; ++i) {
      const std::string text = read_file(log_);
      if (const auto at = text.find("http://127.0.0.1:"); at != std::string::npos)
        return std::stoi(text.substr(at + 17));
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    throw std::runtime_error("tomc demo printed no URL: " + read_file(log_));
  }
  long resident_kib() const {
    std::istringstream status(read_file("/proc/" + std::to_string(pid_) + "/status"));
    std::string line;
    while (std::getline(status, line)) {
      if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    }
    return -1;
  }
  // User + system CPU time so far (/proc/<pid>/stat fields 14 and 15).
  double cpu_seconds() const {
    const std::string stat = read_file("/proc/" + std::to_string(pid_) + "/stat");
    std::istringstream fields(stat.substr(stat.rfind(')') + 2));  // after "pid (comm) "
    std::string field;
    double ticks = 0.0;
    for (int i = 3; i <= 15 && fields >> field; ++i) {
      if (i >= 14) ticks += std::stod(field);
    }
    return ticks / static_cast<double>(::sysconf(_SC_CLK_TCK));
  }

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
};

// The demo machine; in real time with Conveyor's drive behind the gateway (device "Conveyor", telegram 2).
Json soak_machine(const Options& o) {
  Json machine =
      Json::parse(read_file(std::filesystem::path(TOMC_SOURCE_DIR) / "examples/demo_machine.json"));
  machine["cycle_time"] = o.cycle_time_s;
  for (auto& object : machine["technology_objects"]) {
    if (o.free_running || object["name"] != "Conveyor") continue;
    object["drive"] = {{"adapter",
                        {{"type", "dds_gateway"},
                         {"domain", kDomain},
                         {"device", "Conveyor"},
                         {"partition", tomc::testing::test_partition()}}},
                       {"telegram", 2}};
  }
  return machine;
}

// 32 channels over the five TOs: data-block values, status words and telegram words.
Json trace_request() {
  Json channels = Json::array();
  for (const char* axis : {"Conveyor", "Mixer"}) {
    for (const char* path :
         {"Velocity", "ActualSpeed", "StatusWord", "ErrorWord", "telegram.drive.STW1", "telegram.drive.ZSW1"})
      channels.push_back(std::string(axis) + "." + path);
  }
  for (const char* axis : {"Slide", "Table"}) {
    for (const char* path : {"Position", "ActualPosition", "Velocity", "ActualVelocity", "StatusWord",
                             "ErrorWord", "telegram.drive.STW1", "telegram.drive.ZSW1"})
      channels.push_back(std::string(axis) + "." + path);
  }
  for (const char* path : {"ActualPosition", "ActualVelocity", "StatusWord", "ErrorWord"})
    channels.push_back(std::string("LineEncoder.") + path);
  return {{"channels", channels},
          {"trigger", {{"kind", "immediate"}}},
          {"pre_samples", 0},
          {"post_samples", 100000},
          {"decimation", 1}};
}

Json get_json(httplib::Client& client, const std::string& path) {
  const auto r = client.Get(path);
  if (!r || r->status != 200) throw std::runtime_error("GET " + path + " failed");
  return Json::parse(r->body);
}

double load_average() {
  std::ifstream in("/proc/loadavg");
  double one = 0.0;
  in >> one;
  return one;
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parse(argc, argv);
  const auto directory = tomc::testing::test_directory("soak");
  const std::string gateway_config = tomc::testing::gateway_config(kDomain, {{"Conveyor", 2}});
  std::unique_ptr<GatewayProcess> gateway;
  if (!o.free_running) gateway = std::make_unique<GatewayProcess>(directory, gateway_config);

  const Json machine = soak_machine(o);
  std::ofstream(directory / "machine.json") << machine.dump(2);
  std::vector<std::string> extra;
  if (o.free_running)
    extra = {"--free-running", "--inject-faults", std::to_string(std::llround(o.fault_period_cycles))};
  DemoProcess demo(directory / "machine.json", directory / "demo.log", o.seconds + 30.0, extra);
  httplib::Client client("127.0.0.1", demo.port());
  client.set_bearer_token_auth(kToken);
  client.set_read_timeout(10, 0);

  // Every TO with a drive or an encoder (the cam has no alarms of its own).
  std::vector<std::string> objects;
  for (const auto& object : machine["technology_objects"]) {
    if (object.contains("drive")) objects.push_back(object["name"].get<std::string>());
  }
  const std::string request = trace_request().dump();
  std::uint64_t traces = 0;
  std::uint64_t faults = 0;
  // The figure judged: net of the trace in real time (its capture grows for 100 s after each re-arm); when
  // free-running, where a capture fills in seconds, the whole VmRSS at its peak: a sample can fall between a
  // completed trace and its re-arm (94 MB against 142 MB once), so the highest sample of the second quarter
  // of the run is compared with the highest of the last quarter.
  long first_after_warmup = -1;
  long last_judged = -1;
  std::size_t trace_rows = 0;
  bool ok = true;

  std::printf("%8s %12s %9s %9s %9s %7s %8s %10s %7s %10s %6s %6s  %s\n", "t_s", "cycles", "overruns",
              "rss_kib", "net_kib", "rows", "cpu_s", "cycles/cpu", "load1", "history", "traces", "faults",
              "history per TO");
  const auto start = Clock::now();
  auto next_sample = start;
  double next_sample_cycles = 0.0;
  auto next_fault = start + seconds(o.fault_period_s);
  for (;;) {
    const auto now = Clock::now();
    const double t = std::chrono::duration<double>(now - start).count();
    // The trace: armed again as soon as it is no longer recording.
    const Json trace = get_json(client, "/api/trace?max_points=2");
    const std::string state = trace.value("state", "");
    trace_rows = trace.value("rows", std::size_t{0});
    if (state != "waiting for trigger" && state != "recording") {
      const auto r = client.Post("/api/trace", request, "application/json");
      if (!r || r->status != 200) throw std::runtime_error("POST /api/trace: " + (r ? r->body : "no answer"));
      ++traces;
    }
    if (gateway && now >= next_fault) {  // a gateway crash, restarted 1 s later
      gateway->kill_hard();
      std::this_thread::sleep_for(std::chrono::seconds(1));
      gateway = std::make_unique<GatewayProcess>(directory, gateway_config);
      ++faults;
      next_fault += seconds(o.fault_period_s);
    }
    const Json info = get_json(client, "/api/info");
    const auto cycles = info["runner"].value("cycles", 0ULL);
    if (o.free_running) faults = cycles / static_cast<std::uint64_t>(std::llround(o.fault_period_cycles));
    const bool last = t >= o.seconds || (o.free_running && static_cast<double>(cycles) >= o.cycles);
    const bool due = o.free_running ? static_cast<double>(cycles) >= next_sample_cycles : now >= next_sample;
    if (due || last) {
      std::size_t history_max = 0;
      std::string per_object;
      for (const auto& name : objects) {
        const std::size_t n = get_json(client, "/api/objects/" + name + "/alarms")["history"].size();
        history_max = std::max(history_max, n);
        per_object += name + "=" + std::to_string(n) + " ";
      }
      const long rss = demo.resident_kib();
      const double cpu = demo.cpu_seconds();
      const long net = rss - static_cast<long>(trace_rows * (kChannels + 1) * 8 / 1024);
      if (o.free_running) {
        const double progress = std::max(static_cast<double>(cycles) / o.cycles, t / o.seconds);
        if (progress >= 0.25 && progress < 0.5) first_after_warmup = std::max(first_after_warmup, rss);
        if (progress >= 0.75 || last) last_judged = std::max(last_judged, rss);
      } else {
        last_judged = net;
        if (first_after_warmup < 0 && t >= o.seconds / 4.0) first_after_warmup = net;
      }
      if (history_max > kHistoryBound) ok = false;
      std::printf("%8.0f %12llu %9llu %9ld %9ld %7zu %8.1f %10.0f %7.2f %10zu %6llu %6llu  %s\n", t,
                  static_cast<unsigned long long>(cycles),
                  static_cast<unsigned long long>(info["runner"].value("overruns", 0ULL)), rss, net,
                  trace_rows, cpu, cpu > 0.0 ? static_cast<double>(cycles) / cpu : 0.0, load_average(),
                  history_max, static_cast<unsigned long long>(traces),
                  static_cast<unsigned long long>(faults), per_object.c_str());
      std::fflush(stdout);
      next_sample += seconds(o.sample_period_s);
      while (next_sample_cycles <= static_cast<double>(cycles))
        next_sample_cycles += o.sample_cycles;
    }
    if (last) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  const long growth = last_judged - first_after_warmup;
  std::printf("resident memory%s after the warm-up: %ld KiB -> %ld KiB (%+ld KiB, bound %ld)\n",
              o.free_running ? " (peaks of the second and last quarters)" : " net of the trace",
              first_after_warmup, last_judged, growth, kRssGrowthBoundKib);
  if (first_after_warmup < 0 || last_judged < 0 || growth > kRssGrowthBoundKib) ok = false;
  std::printf("%s\n", ok ? "soak: passed" : "soak: FAILED");
  return ok ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "soak: %s\n", e.what());
  return 1;
}
