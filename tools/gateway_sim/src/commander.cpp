// Fault-injection commands over the command topic (commander.hpp).
#include "tomc/gateway_sim/commander.hpp"

#include <unistd.h>

#include <array>
#include <condition_variable>
#include <mutex>
#include <thread>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/participant.hpp"
#include "tomc/drives/dds/type_support.hpp"

namespace tomc::gateway_sim {

namespace dds = tomc::drives::dds;
namespace fdds = eprosima::fastdds::dds;
namespace gw = tomc::gateway;

namespace {

constexpr std::array<std::string_view, 8> kNames{"drop-answers", "delay-answers", "stop",       "resume",
                                                 "restart",      "drive-fault",   "disconnect", "connect"};

class StatusListener final : public fdds::DataReaderListener {
 public:
  void on_data_available(fdds::DataReader* reader) override {
    gw::GatewayStatus status;
    fdds::SampleInfo info;
    while (reader->take_next_sample(&status, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data || status.contract_version() != dds::kContractVersion) continue;
      {
        std::lock_guard<std::mutex> lock(mutex);
        applied.emplace_back(status.gateway().to_string(), status.command_number());
      }
      cv.notify_all();
    }
  }
  std::mutex mutex;
  std::condition_variable cv;
  std::vector<std::pair<std::string, std::uint64_t>> applied;  // (gateway, command number) seen
};

}  // namespace

std::optional<Command> parse_command(std::string_view text) noexcept {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == text) return static_cast<Command>(i);
  }
  return std::nullopt;
}

std::string_view to_string(Command command) noexcept {
  const auto i = static_cast<std::size_t>(command);
  return i < kNames.size() ? kNames[i] : "?";
}

struct GatewayCommander::Impl {
  StatusListener listener;  // before the participant: destroyed after it
  std::unique_ptr<dds::Participant> participant;
  fdds::TypeSupport command_type{new dds::GatewayCommandType()};
  fdds::TypeSupport status_type{new dds::GatewayStatusType()};
  fdds::DataWriter* writer = nullptr;
  std::uint64_t next_number = 0;
};

GatewayCommander::GatewayCommander(int domain, const std::string& partition,
                                   const drives::dds::NetworkSettings& network)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.participant = std::make_unique<dds::Participant>(domain, "tomc gateway commander", partition,
                                                     dds::resolve_network_or_throw(network, true));
  dds::Participant& p = *m.participant;
  m.writer = p.publisher().create_datawriter(&p.topic(dds::kCommandTopic, m.command_type),
                                             dds::command_writer_qos());
  fdds::DataReader* reader = p.subscriber().create_datareader(&p.topic(dds::kStatusTopic, m.status_type),
                                                              dds::status_reader_qos(), &m.listener);
  if (m.writer == nullptr || reader == nullptr) {
    throw std::runtime_error("Fast DDS could not create the command writer / status reader");
  }
  // Numbers distinct from any earlier commander's: the simulator echoes the last one it applied.
  m.next_number =
      (static_cast<std::uint64_t>(::getpid()) << 32) +
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count() & 0xFFFFFFF);
}

GatewayCommander::~GatewayCommander() {
  impl_->participant.reset();
}

bool GatewayCommander::wait_matched(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    fdds::PublicationMatchedStatus matched;
    impl_->writer->get_publication_matched_status(matched);
    if (matched.current_count > 0) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

std::uint64_t GatewayCommander::post(const std::string& gateway, Command command, std::uint64_t value,
                                     const std::string& device, std::chrono::milliseconds timeout) {
  Impl& m = *impl_;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  // The command topic is volatile: wait until a simulator's reader has matched, or the command is lost.
  for (;;) {
    fdds::PublicationMatchedStatus matched;
    m.writer->get_publication_matched_status(matched);
    if (matched.current_count > 0) break;
    if (std::chrono::steady_clock::now() >= deadline) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  gw::GatewayCommand c;
  c.gateway(gateway);
  c.number(++m.next_number);
  c.kind(static_cast<gw::CommandKind>(command));
  c.value(value);
  c.device(device);
  return m.writer->write(&c) ? c.number() : 0;
}

bool GatewayCommander::applied(std::uint64_t number, const std::string& gateway) const {
  std::lock_guard<std::mutex> lock(impl_->listener.mutex);
  for (const auto& [name, n] : impl_->listener.applied) {
    if (n == number && (gateway.empty() || name == gateway)) return true;
  }
  return false;
}

bool GatewayCommander::send(const std::string& gateway, Command command, std::uint64_t value,
                            const std::string& device, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  const std::uint64_t number = post(gateway, command, value, device, timeout);
  if (number == 0) return false;
  Impl& m = *impl_;
  std::unique_lock<std::mutex> lock(m.listener.mutex);
  return m.listener.cv.wait_until(lock, deadline, [&] {
    for (const auto& [name, n] : m.listener.applied) {
      if (n == number && (gateway.empty() || name == gateway)) return true;
    }
    return false;
  });
}

}  // namespace tomc::gateway_sim
