// `tomc gateway` (docs/profinet-gateway.md): its configuration file's problems, each naming its key, and the
// whole path end to end in network namespaces made by the test:
//
//   scenario (tomc's runtime, dds_gateway adapter) --DDS, UDP on 127.0.0.1--> `tomc gateway` process
//   --PROFINET RT_CLASS_1 over a veth pair--> the emulated IO device hosting the simulated PROFIdrive drive
//
// The controller and the gateway share the namespace "gateway host" (DDS on its loopback only, TOOLCHAIN §5);
// the device has its own. Each namespace is checked to hold only lo and its veth end before anything is sent.
// A positioning move gives the trace of the embedded simulated drive within one cycle of transport delay; a
// cable cut gives alarm 405, and after the link is back the gateway reconnects and MC_Reset recovers.
// Skipped with the reason where namespaces cannot be made (not root).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "../dds/gateway_process.hpp"
#include "netns_hosts.hpp"
#include "tomc/drives/dds/gateway_link.hpp"
#include "tomc/drives/profinet_drive.hpp"
#include "tomc/profinet/alarm.hpp"
#include "tomc/profinet/sockets.hpp"
#include "tomc/scenario/profinet_gateway_config.hpp"
#include "tomc/scenario/scenario.hpp"

#ifndef TOMC_BINARY
#error "TOMC_BINARY must name build/bin/tomc"
#endif

namespace pn = tomc::profinet;
namespace sc = tomc::scenario;
using Clock = std::chrono::steady_clock;
using Json = nlohmann::ordered_json;

namespace {

// ---- the configuration file ----

std::vector<std::string> problems_of(const std::string& text) {
  sc::ProfinetGatewayConfig config;
  sc::Problems problems;
  sc::load_profinet_gateway_config(sc::Json::parse(text), config, problems);
  return problems.lines();
}

bool has_line(const std::vector<std::string>& lines, const std::string& start) {
  for (const auto& l : lines) {
    if (l.rfind(start, 0) == 0) return true;
  }
  return false;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines)
    text += l + "\n";
  return text;
}

}  // namespace

TEST(GatewayConfig, AValidFileLoads) {
  sc::ProfinetGatewayConfig config;
  sc::Problems problems;
  sc::load_profinet_gateway_config(sc::Json::parse(R"({ "gateway": "gw1", "domain": 42, "watchdog": 0.1,
    "profinet": { "interface": "eth1", "ip": "192.168.0.1", "send_clock_factor": 64, "reduction_ratio": 2 },
    "devices": [ { "name": "axis1", "name_of_station": "drive-1", "ip": "192.168.0.10", "telegram": 3 } ] })"),
                                   config, problems);
  ASSERT_TRUE(problems.empty()) << joined(problems.lines());
  EXPECT_EQ(config.interface, "eth1");
  EXPECT_EQ(config.ip, (std::array<std::uint8_t, 4>{192, 168, 0, 1}));
  EXPECT_DOUBLE_EQ(config.cycle_time(), 0.004);  // 64 × 31.25 µs × 2
  ASSERT_EQ(config.devices.size(), 1u);
  EXPECT_EQ(config.devices[0].name_of_station, "drive-1");
  EXPECT_EQ(config.devices[0].device_config().drive_telegram, 3);
  EXPECT_TRUE(config.devices[0].modules.empty());  // the emulated drive's layout
}

TEST(GatewayConfig, EveryProblemNamesItsKey) {
  const auto lines = problems_of(R"({ "gateway": "gw1", "domain": 300,
    "profinet": { "interface": "eth1", "ip": "10.0.0", "send_clock_factor": 8, "speed": 1 },
    "devices": [ { "name": "axis1", "name_of_station": "Drive_1", "ip": "10.0.0.2", "telegram": 7 },
                 { "name": "axis1", "name_of_station": "d2", "ip": "10.0.0.3", "telegram": 3, "telgram": 1,
                   "modules": [ { "slot": 0, "ident": 1, "submodules": [ { "subslot": 1, "ident": 1 } ] },
                                { "slot": 1, "ident": "0x100", "submodules": [
                                  { "subslot": 2, "ident": 65539, "input_length": 18, "output_length": 8 } ] } ] },
                 { "name": "axis3", "ip": "10.0.0.4", "telegram": 1,
                   "modules": [ { "slot": 0, "ident": 1, "submodules": [ { "subslot": 1, "ident": 1 } ] } ] } ] })");
  const std::string all = joined(lines);
  EXPECT_TRUE(has_line(lines, "domain:")) << all;
  EXPECT_TRUE(has_line(lines, "profinet.ip: '10.0.0' is not an IPv4 address")) << all;
  EXPECT_TRUE(has_line(lines, "profinet.send_clock_factor:")) << all;  // RT_CLASS_1: 32..128
  EXPECT_TRUE(has_line(lines, "profinet.speed:")) << all;              // unknown key
  EXPECT_TRUE(has_line(lines, "devices[0].name_of_station: 'Drive_1': only a-z")) << all;
  EXPECT_TRUE(has_line(lines, "devices[0].telegram:")) << all;  // 7 is no PROFIdrive telegram here
  EXPECT_TRUE(has_line(lines, "devices[1].name: 'axis1' is defined twice")) << all;
  EXPECT_TRUE(has_line(lines, "devices[1].telgram:")) << all;
  // Telegram 3 sends 10 setpoint bytes (spec 06 §2.15): a submodule with 8 output bytes cannot carry it.
  EXPECT_TRUE(has_line(lines,
                       "devices[1].modules[1].submodules[0]: the telegram submodule has input_length 18 and "
                       "output_length 8; telegram 3 needs 18 and 10"))
      << all;
  EXPECT_TRUE(has_line(lines, "devices[2].name_of_station:")) << all;  // required
  EXPECT_TRUE(has_line(lines, "devices[2].modules: no submodule in slot 1 subslot 2")) << all;
}

TEST(GatewayConfig, TheCommandLineReportsAFileProblemWithItsKey) {
  const auto file =
      std::filesystem::temp_directory_path() / ("tomc17-bad-" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << R"({ "domain": 1, "profinet": { "interface": "eth1", "ip": "10.0.0.1" },
    "devices": [ { "name": "axis1", "name_of_station": "drive-1", "ip": "10.0.0.256", "telegram": 3 } ] })";
  const std::string command = std::string(TOMC_BINARY) + " gateway --config " + file.string() + " 2>&1";
  std::string output;
  int status = -1;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
      output += buffer;
    status = ::pclose(pipe);
  }
  std::filesystem::remove(file);
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_NE(output.find("devices[0].ip: '10.0.0.256' is not an IPv4 address"), std::string::npos) << output;
}

// ---- end to end in network namespaces ----

namespace {

constexpr int kDomain = 175;  // DDS tests use 140-174 (decision G13)
constexpr pn::Ipv4Address kGatewayIp{10, 218, 0, 1};
constexpr pn::Ipv4Address kDeviceIp{10, 218, 0, 2};
constexpr double kTarget = 10.0;  // mm

using pn::testing::enter;
using pn::testing::now_us;
using pn::testing::quiet;

// The drive's parameters exactly as the scenario gives the embedded simulated drive (defaults of a telegram-3
// drive at the scenario's cycle time), so that the two runs can be compared.
sc::DriveSettings drive_settings(int telegram) {
  sc::DriveSettings settings;
  sc::Problems problems;
  sc::load_drive(sc::Json::parse(R"({ "telegram": )" + std::to_string(telegram) + " }"), "drive", 0.001,
                 settings, problems);
  return settings;
}

// What the emulated device is: its drive telegram (the module it has) and the p0922 it answers (0: the
// telegram, a drive as configured; another number: a drive reconfigured without changing its module).
struct DeviceOptions {
  int telegram = 3;
  std::uint16_t p0922 = 0;
};

// The emulated IO device on its own thread in the device namespace: ProfinetDrive behind the sockets. Its
// drive application follows the controller's STW2 sign-of-life (isochronous: one drive cycle per servo cycle
// of tomc) and sends its input frame right after each drive cycle; without drive cycles for 5 ms the input
// frame goes out every 1 ms (the controller's watchdog must see frames).
//
// On request (any thread) the drive raises a fault (SINAMICS F07900 with OFF2: ZSW1 bit 3) and the device
// sends an alarm notification (diagnosis or process alarm of the telegram submodule); it counts the AlarmAcks
// the controller returns.
class DeviceHost {
 public:
  explicit DeviceHost(const std::string& ns, DeviceOptions options = {}) : options_(options) {
    thread_ = std::thread([this, ns] { run(ns); });
  }
  ~DeviceHost() {
    stop_ = true;
    thread_.join();
  }
  std::string error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
  }
  int ars() const { return ars_.load(); }
  void inject_fault() { fault_requested_ = true; }
  void send_alarm(std::uint16_t type) { alarm_requested_ = type; }
  int alarm_acks() const { return alarm_acks_.load(); }

 private:
  // An alarm notification of the telegram submodule to the AR's controller (IEC 61158-6-10 RTA DATA): a
  // diagnosis alarm with a ChannelDiagnosis (USI 0x8000, channel 0x8000, error 9), or a process alarm with a
  // manufacturer-specific USI 0x0001 and two bytes; low priority (FrameID 0xFE01).
  std::size_t alarm_frame(const pn::IoDevice& device, const pn::MacAddress& own, std::uint16_t type,
                          std::span<std::uint8_t> out) {
    pn::RtaFrame alarm;
    alarm.frame_id = pn::kFrameIdAlarmLow;
    alarm.destination_endpoint = device.connection().alarm_cr.local_alarm_reference;
    alarm.source_endpoint = 3;
    alarm.send_sequence = alarm_sequence_;
    alarm.ack_sequence = 0xFFFE;
    alarm.has_block = true;
    alarm.block.alarm_type = type;
    alarm.block.slot = tomc::drives::kDriveObjectSlot;
    alarm.block.subslot = tomc::drives::kTelegramSubslot;
    alarm.block.module_ident = tomc::drives::kDriveObjectIdent;
    alarm.block.submodule_ident =
        tomc::drives::telegram_submodule_ident(static_cast<std::uint16_t>(options_.telegram));
    alarm.block.specifier = static_cast<std::uint16_t>(0x2000 | (alarm_sequence_ & 0x07FF));
    const std::array<std::uint8_t, 6> channel{0x80, 0x00, 0x08, 0x00, 0x00, 0x09};
    alarm.block.user_structure_identifier = type == pn::alarm_type::kDiagnosis ? 0x8000 : 0x0001;
    alarm.block.payload_length = type == pn::alarm_type::kDiagnosis ? 6 : 2;
    std::copy_n(channel.begin(), alarm.block.payload_length, alarm.block.payload.begin());
    ++alarm_sequence_;
    std::size_t written = 0;
    const pn::EthernetHeader header{device.connection().ar.initiator_mac, own, pn::VlanTag{5, 0}};
    return pn::encode(header, alarm, out, written) == pn::ProfinetError::kNone ? written : 0;
  }

  void fail(const std::string& why) {
    std::lock_guard<std::mutex> lock(mutex_);
    error_ = why;
  }
  void run(const std::string& ns) {
    if (!enter(ns)) return fail("setns into the device namespace failed");
    pn::RawSocket raw;
    pn::UdpSocket udp;
    if (std::string e = raw.open("pn-e"); !e.empty()) return fail(e);
    if (std::string e = udp.open(kDeviceIp, pn::kPnioUdpPort); !e.empty()) return fail(e);
    pn::DeviceIdentity identity;
    identity.name_of_station = "drive-1";
    identity.mac = raw.mac();
    identity.ip = {kDeviceIp, {255, 255, 255, 0}, {}};
    identity.vendor_id = 0x002A;
    identity.device_id = 0x0C01;
    identity.vendor = "tomc emulated drive";
    const sc::DriveSettings settings = drive_settings(options_.telegram);
    tomc::drives::ProfinetDrive host(identity, settings.device_config(), settings.parameters);
    if (options_.p0922 != 0) host.set_p0922(options_.p0922);
    pn::IoDevice& device = host.device();
    std::array<std::uint8_t, 1518> frame{};
    std::uint64_t next_send = now_us();
    std::uint64_t last_step = now_us();
    pn::ArState last = pn::ArState::kNone;
    const auto send_input = [&] {
      if (const std::size_t n = device.next_input_frame(frame); n > 0) raw.send(std::span(frame).first(n));
    };
    while (!stop_) {
      if (const std::size_t n = raw.receive(frame, 200); n > 0) {
        const auto in = std::span(frame).first(n);
        const pn::FrameKind kind = pn::classify_frame_id(pn::peek_frame_id(in));
        if (kind == pn::FrameKind::kDcp) {
          if (const auto answer = device.on_dcp(in); !answer.empty()) raw.send(answer);
        } else if (kind == pn::FrameKind::kAlarm) {
          pn::RtaFrame rta;
          if (pn::decode_rta(in, rta) == pn::ProfinetError::kNone && rta.pdu_type == pn::RtaPduType::kData &&
              rta.has_block && rta.block.is_ack) {
            ++alarm_acks_;
          }
        } else if (device.on_cyclic(in, now_us()) && host.follow_controller()) {
          last_step = now_us();
          send_input();
        }
      }
      pn::testing::serve_device_rpc(device, udp, frame, kGatewayIp);
      if (device.state() == pn::ArState::kRunning && last != pn::ArState::kRunning) ++ars_;
      if (fault_requested_.exchange(false))
        host.drive().inject_fault(7900, tomc::drives::SimulatedDriveParameters::FaultReaction::kOff2);
      if (const std::uint16_t type = alarm_requested_.exchange(0);
          type != 0 && device.state() == pn::ArState::kRunning) {
        std::array<std::uint8_t, 256> alarm{};
        if (const std::size_t n = alarm_frame(device, raw.mac(), type, alarm); n > 0)
          raw.send(std::span(alarm).first(n));
      }
      last = device.state();
      const std::uint64_t now = now_us();
      if (now >= next_send) {
        next_send = now + 1000;
        // Without the controller's clock (no AR, or no setpoints for 50 ms) the drive runs on its own.
        if (now - last_step > 50'000) host.cycle();
        // While following the controller, every input frame answers a drive cycle; after 5 ms without one
        // (tomc waiting) the frame goes out every 1 ms again, for the controller's watchdog.
        if (device.state() != pn::ArState::kNone && now - last_step > 5'000) send_input();
        device.watchdog_expired(now);
      }
    }
  }

  DeviceOptions options_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<int> ars_{0};
  std::atomic<bool> fault_requested_{false};
  std::atomic<std::uint16_t> alarm_requested_{0};
  std::atomic<int> alarm_acks_{0};
  std::uint16_t alarm_sequence_ = 0;  // device thread only
  mutable std::mutex mutex_;
  std::string error_;
};

// A positioning axis on telegram 3: enable, home (mode 0 at 0), MC_MoveAbsolute to kTarget; with
// `reset_every`, an MC_Reset edge and a new MC_MoveVelocity edge every that many cycles instead of the move.
Json scenario(bool through_gateway, int cycles, int reset_every) {
  Json drive = {{"telegram", 3}};
  if (through_gateway) {
    drive["adapter"] = {{"type", "dds_gateway"},
                        {"domain", kDomain},
                        {"partition", "tomc-test-" + std::to_string(::getpid())},
                        {"device", "axis1"},
                        {"connect_timeout_s", 10.0},
                        {"answer_timeout_s", 0.02}};
  }
  Json doc;
  doc["cycle_time"] = 0.001;
  doc["cycles"] = cycles;
  doc["technology_objects"] = Json::array({Json{{"name", "Slide"},
                                                {"type", "TO_PositioningAxis"},
                                                {"config", {{"DynamicLimits.MaxJerk", 0.0}}},
                                                {"drive", drive}}});
  Json timeline = Json::array();
  timeline.push_back({{"cycle", 0},
                      {"instance", "power"},
                      {"instruction", "MC_Power"},
                      {"axis", "Slide"},
                      {"inputs", {{"Enable", true}, {"StartMode", 1}}}});
  timeline.push_back({{"cycle", 5},
                      {"instance", "home"},
                      {"instruction", "MC_Home"},
                      {"axis", "Slide"},
                      {"inputs", {{"Execute", true}, {"Mode", 0}, {"Position", 0.0}}}});
  if (reset_every == 0) {
    timeline.push_back({{"cycle", 20},
                        {"instance", "move"},
                        {"instruction", "MC_MoveAbsolute"},
                        {"axis", "Slide"},
                        {"inputs", {{"Execute", true}, {"Position", kTarget}, {"Velocity", 100.0}}}});
  } else {
    for (int c = 20; c < cycles; c += reset_every) {
      timeline.push_back({{"cycle", c},
                          {"instance", "reset"},
                          {"instruction", "MC_Reset"},
                          {"axis", "Slide"},
                          {"inputs", {{"Execute", true}}}});
      timeline.push_back({{"cycle", c + 5}, {"instance", "reset"}, {"inputs", {{"Execute", false}}}});
      timeline.push_back({{"cycle", c + 10},
                          {"instance", "move"},
                          {"instruction", "MC_MoveVelocity"},
                          {"axis", "Slide"},
                          {"inputs", {{"Execute", true}, {"Velocity", 20.0}}}});
      timeline.push_back({{"cycle", c + 15}, {"instance", "move"}, {"inputs", {{"Execute", false}}}});
    }
  }
  doc["timeline"] = timeline;
  doc["trace"] = {"Slide.ActualPosition",
                  "Slide.ActualVelocity",
                  "power.Status",
                  reset_every == 0 ? "move.Done" : "move.InVelocity",
                  "Slide.ErrorDetail.Number",
                  "Slide.StatusDrive.CommunicationOK"};
  return doc;
}

// A trace sink that hands each finished row to `on_row` (cycle, values) as the scenario writes it.
class RowBuffer : public std::stringbuf {
 public:
  explicit RowBuffer(std::function<void(int, const std::vector<double>&)> on_row)
      : on_row_(std::move(on_row)) {}
  std::vector<std::vector<double>> rows;

 protected:
  int sync() override { return 0; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i)
      put(s[i]);
    return n;
  }
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) put(static_cast<char>(c));
    return c;
  }

 private:
  void put(char c) {
    if (c != '\n') {
      line_ += c;
      return;
    }
    if (!header_seen_) {
      header_seen_ = true;
    } else {
      std::vector<double> values;
      std::istringstream cells(line_);
      for (std::string cell; std::getline(cells, cell, ',');)
        values.push_back(cell == "true" ? 1.0 : cell == "false" ? 0.0 : std::strtod(cell.c_str(), nullptr));
      rows.push_back(values);
      on_row_(static_cast<int>(values.empty() ? -1 : values[0]), values);
    }
    line_.clear();
  }
  std::function<void(int, const std::vector<double>&)> on_row_;
  std::string line_;
  bool header_seen_ = false;
};

// Runs the scenario; through the gateway it runs on a thread in the gateway namespace (its DDS participant
// and sockets live there). Columns: 0 cycle, 1 time, then the trace in scenario() order.
std::vector<std::vector<double>> run(const Json& doc, const std::string& ns,
                                     std::function<void(int, const std::vector<double>&)> on_row,
                                     std::string& failure) {
  RowBuffer buffer(std::move(on_row));
  std::thread runner([&] {
    if (!ns.empty() && !enter(ns)) return void(failure = "setns into the gateway namespace failed");
    auto loaded = sc::Scenario::load(sc::Json::parse(doc.dump()));
    if (!loaded.scenario) return void(failure = "scenario: " + joined(loaded.problems));
    std::ostream out(&buffer);
    const sc::RunResult result = loaded.scenario->run(&out);
    if (!result.runtime_errors.empty()) failure = joined(result.runtime_errors);
    if (!result.warnings.empty()) failure += "warnings: " + joined(result.warnings);
  });
  runner.join();
  return buffer.rows;
}

// The two hosts joined by the veth pair; "" or why the test must skip. Nothing is sent unless each namespace
// sees only lo and its own veth end (never the machine's interfaces): the caller asserts own_interfaces_only.
std::string make_hosts(pn::testing::Namespaces& hosts) {
  return hosts.make({"pn-g", "", "10.218.0.1/24"}, {"pn-e", "", "10.218.0.2/24"});
}
bool own_interfaces_only(const pn::testing::Namespaces& hosts) {
  return hosts.interfaces(hosts.first) == std::set<std::string>{"lo", "pn-g"} &&
         hosts.interfaces(hosts.second) == std::set<std::string>{"lo", "pn-e"} &&
         hosts.carrier(hosts.first, "pn-g");
}

// `tomc gateway` in the gateway namespace with device "axis1" (drive-1 at 10.218.0.2, telegram 3) and the
// given module keys; stopped (SIGTERM) by its PID, it dies with the test. Watchdog factor 20 (20 ms at 1 ms):
// the gateway's cyclic thread is not SCHED_FIFO here and shares two cores with builds (decision I7); the
// gateway's G6 watchdog 0.5 s: longer than any lock-step wait.
class GatewayHost {
 public:
  GatewayHost(const pn::testing::Namespaces& hosts, const std::string& module_keys)
      : dir_(std::filesystem::temp_directory_path() / ("tomc17-gw-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir_);
    std::ofstream(dir_ / "gateway.json")
        << R"({ "gateway": "gw-pn", "domain": )" << kDomain << R"(, "partition": "tomc-test-)" << ::getpid()
        << R"(", "watchdog": 0.5,
      "profinet": { "interface": "pn-g", "ip": "10.218.0.1", "send_clock_factor": 32, "watchdog_factor": 20 },
      "devices": [ { "name": "axis1", "name_of_station": "drive-1", "ip": "10.218.0.2", "telegram": 3)"
        << module_keys << " } ] }";
    process_ = std::make_unique<tomc::testing::GatewayProcess>(
        std::vector<std::string>{"ip", "netns", "exec", hosts.first, TOMC_BINARY, "gateway", "--config",
                                 (dir_ / "gateway.json").string()},
        dir_ / "gateway.log");
  }
  ~GatewayHost() {
    process_.reset();
    std::filesystem::remove_all(dir_);
  }
  std::string log() const { return process_->log(); }
  int terminate() { return process_->terminate(); }

 private:
  std::filesystem::path dir_;
  std::unique_ptr<tomc::testing::GatewayProcess> process_;
};

// The emulated drive's GSDML file with its drive object and the telegram-3 submodule (decision I18).
const std::string kGsdmlModules =
    R"(, "gsdml": ")" TOMC_GSDML_DIR R"(/GSDML-V2.35-tomc-EmulatedDrive-20261127.xml",
    "modules": [ { "slot": 1, "module": "DO_DRIVE", "submodules": [ { "subslot": 2, "submodule": "TEL3" } ] } ])";

// What tomc learns over DDS about device "axis1": the gateway's GatewayStatus entry and the link's diagnosis,
// from a controller-side GatewayLink made in the gateway namespace (its sockets live there) that sends no
// setpoints; it stays for the test, so that its discovery is done before it is asked.
struct SeenOverDds {
  tomc::drives::dds::GatewayLink::GatewayDevice device;
  std::string diagnosis;
};
class DdsObserver {
 public:
  explicit DdsObserver(const std::string& ns) {
    std::thread([&] {
      if (!enter(ns)) return;
      tomc::drives::dds::GatewayLinkConfig config;
      config.domain = kDomain;
      config.partition = "tomc-test-" + std::to_string(::getpid());
      link_ = tomc::drives::dds::GatewayLink::create(config);
      tomc::drives::DeviceConfig device;
      device.drive_telegram = 3;
      drive_ = link_->make_drive("axis1", device);
      link_->start();
    }).join();
  }
  // Polled until `done` or 5 s; the last seen otherwise.
  SeenOverDds until(const std::function<bool(const SeenOverDds&)>& done) const {
    SeenOverDds seen;
    for (const auto end = Clock::now() + std::chrono::seconds(5); link_ && Clock::now() < end;) {
      for (const auto& g : link_->gateways()) {
        for (const auto& d : g.devices) {
          if (d.name == "axis1") seen.device = d;
        }
      }
      const auto reports = link_->diagnose();
      seen.diagnosis = reports.empty() ? "" : reports[0].text;
      if (done(seen)) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return seen;
  }

 private:
  std::shared_ptr<tomc::drives::dds::GatewayLink> link_;
  std::unique_ptr<tomc::drives::dds::DdsGatewayDrive> drive_;
};

}  // namespace

// seed/issue 17: "a device with the wrong module (reported)" and the start-up check of p0922 (decision I16),
// through `tomc gateway` configured from the emulated drive's GSDML file, as tomc sees them over DDS.
TEST(GatewayNetns, AWrongModuleAndAWrongP0922AreReportedOverDds) {
  pn::testing::Namespaces hosts("tomc17g", "tomc17e");
  if (const std::string why = make_hosts(hosts); !why.empty()) GTEST_SKIP() << why;
  ASSERT_TRUE(own_interfaces_only(hosts));
  GatewayHost gateway(hosts, kGsdmlModules);
  const DdsObserver observer(hosts.first);
  const auto detail_has = [](const std::string& text) {
    return [text](const SeenOverDds& s) { return s.device.detail.find(text) != std::string::npos; };
  };
  {
    // A drive on telegram 2: its telegram submodule is 0x10002, the gateway expects 0x10003 (TEL3). The
    // device accepts the Connect with that submodule bad (IEC 61158-6-10 ModuleDiffBlock), its p0922 says 2:
    // the AR is released and the status names the difference first.
    DeviceHost device(hosts.second, {2, 0});
    const SeenOverDds seen = observer.until(detail_has("wrong submodule"));
    EXPECT_EQ(seen.device.state, "disconnected") << gateway.log();
    EXPECT_EQ(
        seen.device.detail,
        "module difference: slot 1 subslot 2: wrong submodule (ident 0x10002); p0922 is 2: the drive sends "
        "telegram 2, the file says 3");
    EXPECT_EQ(device.error(), "");
  }
  {
    // A drive with the right module (telegram 3) whose p0922 says 105: refused after the parameter access,
    // the AR released, retried every 200 ms; tomc's diagnosis names the configured-telegram error.
    DeviceHost device(hosts.second, {3, 105});
    const SeenOverDds seen = observer.until(detail_has("p0922 is 105"));
    EXPECT_EQ(seen.device.state, "disconnected") << gateway.log();
    EXPECT_EQ(seen.device.detail, "p0922 is 105: the drive sends telegram 105, the file says 3");
    EXPECT_EQ(
        seen.diagnosis,
        "gateway 'gw-pn' has no cyclic exchange with 'axis1': p0922 is 105: the drive sends telegram 105, "
        "the file says 3");
    EXPECT_GE(device.ars(), 1);  // the AR was built (ApplicationReady) before the check refused it
    EXPECT_EQ(device.error(), "");
  }
  EXPECT_EQ(gateway.terminate(), 0) << gateway.log();
}

// seed/issue 17: "a drive fault (ZSW1.3 → tomc's drive alarm), and an alarm acknowledged": tomc sim through
// the gateway; the emulated drive sends a diagnosis alarm at cycle 100, raises F07900 (OFF2, ZSW1 bit 3) and
// sends a process alarm at cycle 200. The axis gets alarm 401 (drive fault, docs/errors.md); both alarms are
// acknowledged (AlarmAck back at the device) and the last one is in the gateway's status over DDS.
TEST(GatewayNetns, ADriveFaultAndDeviceAlarmsReachTomc) {
  pn::testing::Namespaces hosts("tomc17g", "tomc17e");
  if (const std::string why = make_hosts(hosts); !why.empty()) GTEST_SKIP() << why;
  ASSERT_TRUE(own_interfaces_only(hosts));
  GatewayHost gateway(hosts, kGsdmlModules);
  DeviceHost device(hosts.second);
  const DdsObserver observer(hosts.first);
  constexpr int kCycles = 300;
  std::string failure;
  const auto start = Clock::now();
  const auto ms = [&] {
    return std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start).count();
  };
  const auto rows = run(
      scenario(true, kCycles, 0), hosts.first,
      [&](int cycle, const std::vector<double>&) {
        if (cycle == 100) device.send_alarm(pn::alarm_type::kDiagnosis);
        if (cycle == 200) {
          device.inject_fault();
          device.send_alarm(pn::alarm_type::kProcess);
        }
      },
      failure);
  ASSERT_EQ(failure, "") << gateway.log();
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kCycles)) << gateway.log();
  constexpr std::size_t kAlarm = 6;
  constexpr std::size_t kCommunication = 7;
  EXPECT_EQ(rows[199][kAlarm], 0.0);
  int alarm = -1;
  for (int c = 200; c < kCycles && alarm < 0; ++c)
    alarm = rows[static_cast<std::size_t>(c)][kAlarm] == 401.0 ? c : -1;
  EXPECT_GT(alarm, 200) << "no alarm 401 after the drive fault\n" << gateway.log();
  EXPECT_LE(alarm, 210);  // the fault's ZSW1 reaches tomc within a few cycles (lock-step, one cycle delay)
  // The drive fault stays the axis' alarm to the end: no link loss (405) follows, the exchange runs on
  // (StatusDrive.CommunicationOK is FALSE with a drive fault, seed L11468).
  EXPECT_EQ(rows.back()[kAlarm], 401.0);
  EXPECT_EQ(rows.back()[kCommunication], 0.0);
  const auto scenario_ms = ms();
  for (int i = 0; i < 100 && device.alarm_acks() < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(device.alarm_acks(), 2);
  const SeenOverDds seen = observer.until(
      [](const SeenOverDds& s) { return s.device.detail.find("alarm 2") != std::string::npos; });
  std::printf("gateway: scenario done after %lld ms, status over DDS after %lld ms\n",
              static_cast<long long>(scenario_ms), static_cast<long long>(ms()));
  EXPECT_EQ(seen.device.state, "faulted") << gateway.log();
  EXPECT_EQ(
      seen.device.detail,
      "ZSW1 bit 3: the drive reports a fault; alarm 2 acknowledged: process, slot 1 subslot 2, USI 0x0001");
  EXPECT_EQ(device.error(), "");
  EXPECT_EQ(gateway.terminate(), 0) << gateway.log();
}

TEST(GatewayNetns, SimMovesTheEmulatedDriveThroughTheGatewayAndRecoversFromACableCut) {
  pn::testing::Namespaces hosts("tomc17g", "tomc17e");
  if (const std::string why = make_hosts(hosts); !why.empty()) GTEST_SKIP() << why;
  ASSERT_TRUE(own_interfaces_only(hosts));
  DeviceHost device(hosts.second);
  GatewayHost gateway(hosts, "");
  const auto log = [&] { return gateway.log(); };

  // 1. A positioning move: the trace equals the embedded drive's within one cycle of transport delay.
  constexpr int kCycles = 400;
  std::string failure;
  const auto embedded = run(
      scenario(false, kCycles, 0), "", [](int, const std::vector<double>&) {}, failure);
  ASSERT_EQ(failure, "");
  const auto remote = run(
      scenario(true, kCycles, 0), hosts.first, [](int, const std::vector<double>&) {}, failure);
  ASSERT_EQ(failure, "") << log();
  ASSERT_EQ(device.error(), "");
  ASSERT_EQ(embedded.size(), static_cast<std::size_t>(kCycles));
  ASSERT_EQ(remote.size(), static_cast<std::size_t>(kCycles)) << log();
  constexpr std::size_t kPosition = 2;
  constexpr std::size_t kDone = 5;
  int exact = 0;
  for (std::size_t k = 1; k + 1 < embedded.size(); ++k) {
    const double p = remote[k][kPosition];
    const double low =
        std::min({embedded[k - 1][kPosition], embedded[k][kPosition], embedded[k + 1][kPosition]});
    const double high =
        std::max({embedded[k - 1][kPosition], embedded[k][kPosition], embedded[k + 1][kPosition]});
    EXPECT_TRUE(p >= low - 1e-6 && p <= high + 1e-6)
        << "cycle " << k << ": " << p << " through the gateway, embedded " << embedded[k][kPosition];
    exact += std::abs(p - embedded[k][kPosition]) < 1e-9 ? 1 : 0;
  }
  EXPECT_NEAR(remote.back()[kPosition], kTarget, 0.01);
  EXPECT_EQ(remote.back()[kDone], 1.0);
  std::printf("gateway: %d of %d cycles equal to the embedded drive's to 1e-9\n", exact, kCycles - 2);

  // 2. The cable cut: the gateway's veth goes down at cycle 300 and comes back 300 ms later. The scenario is
  // a new controller: the gateway takes it once the first has been silent for its watchdog (G1).
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  constexpr int kCutCycles = 1200;
  std::atomic<int> cut_at{-1};
  std::atomic<int> restored_at{-1};
  std::thread cutter;
  const auto rows = run(
      scenario(true, kCutCycles, 100), hosts.first,
      [&](int cycle, const std::vector<double>&) {
        if (cycle == 300) {
          cut_at = cycle;
          quiet("ip -n " + hosts.first + " link set pn-g down");  // named: never the host's namespace
          cutter = std::thread([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
            quiet("ip -n " + hosts.first + " link set pn-g up");
            restored_at = 1;
          });
        }
      },
      failure);
  if (cutter.joinable()) cutter.join();
  ASSERT_EQ(failure, "") << log();
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kCutCycles)) << log();
  ASSERT_EQ(cut_at, 300);
  constexpr std::size_t kAlarm = 6;
  constexpr std::size_t kCommunication = 7;
  constexpr std::size_t kPower = 4;
  int alarm = -1;
  for (int c = 300; c < kCutCycles && alarm < 0; ++c)
    alarm = rows[static_cast<std::size_t>(c)][kAlarm] == 405.0 ? c : -1;
  ASSERT_GT(alarm, 300) << "no alarm 405 after the cable cut\n" << log();
  EXPECT_EQ(rows[static_cast<std::size_t>(alarm)][kCommunication], 0.0);
  EXPECT_EQ(rows[299][kAlarm], 0.0);
  EXPECT_EQ(rows[299][kPower], 1.0);
  // Reconnected by the gateway, acknowledged by an MC_Reset edge, enabled and moving again at the end.
  EXPECT_EQ(rows.back()[kAlarm], 0.0) << log();
  EXPECT_EQ(rows.back()[kCommunication], 1.0);
  EXPECT_EQ(rows.back()[kPower], 1.0);
  EXPECT_NEAR(rows.back()[3], 20.0, 0.5);  // ActualVelocity mm/s
  EXPECT_GE(device.ars(), 2);              // the AR was rebuilt after the cut
  int recovered = -1;
  for (int c = alarm; c < kCutCycles && recovered < 0; ++c) {
    const auto& row = rows[static_cast<std::size_t>(c)];
    recovered = row[kAlarm] == 0.0 && row[kCommunication] == 1.0 && row[kPower] == 1.0 ? c : -1;
  }
  EXPECT_GT(recovered, alarm);
  std::printf("gateway: cut after cycle 300, alarm 405 in cycle %d, enabled again in cycle %d\n", alarm,
              recovered);
  EXPECT_EQ(gateway.terminate(), 0) << log();
}
