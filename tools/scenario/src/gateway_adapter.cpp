// The dds_gateway drive adapter in configuration files, and the links behind it (gateway_adapter.hpp).
#include "tomc/scenario/gateway_adapter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "gateway_adapter_detail.hpp"
#include "json_reader.hpp"
#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/gateway_link.hpp"
#include "tomc/drives/dds/participant.hpp"

namespace tomc::scenario {

namespace dds = tomc::drives::dds;
using detail::ObjectReader;

void load_gateway_adapter(const Json& adapter, std::string_view path, GatewayAdapterSettings& settings,
                          Problems& problems) {
  ObjectReader r(adapter, std::string(path), problems);
  if (!r.valid()) return;
  if (const Json* v = r.get("type", true)) {
    if (auto t = detail::read_string(*v, r.path_of("type"), problems); t && *t != "dds_gateway") {
      problems.add(r.path_of("type"), "'" + *t + "' is not a gateway adapter type (dds_gateway)");
    }
  }
  if (const Json* v = r.get("domain", true)) {
    if (auto d = detail::read_integer(*v, r.path_of("domain"), 0, dds::kMaxDomainId, false, problems)) {
      settings.domain = static_cast<int>(*d);
    }
  }
  if (const Json* v = r.get("device", true)) {
    if (auto d = detail::read_string(*v, r.path_of("device"), problems)) {
      if (d->empty() || d->size() > dds::kMaxNameLength) {
        problems.add(r.path_of("device"),
                     "a device name of 1.." + std::to_string(dds::kMaxNameLength) + " characters");
      } else {
        settings.device = *d;
      }
    }
  }
  if (const Json* v = r.get("partition")) {
    if (auto p = detail::read_string(*v, r.path_of("partition"), problems)) settings.partition = *p;
  }
  if (const Json* v = r.get("byte_order")) {
    if (auto c = detail::read_choice(*v, r.path_of("byte_order"),
                                     {"big", "little-bytes", "swapped-words", "little"}, problems)) {
      settings.byte_order = static_cast<telegrams::ByteOrder>(*c);
    }
  }
  detail::read_network(r, settings.network, true, problems);
  r.integer("max_answer_age_cycles", settings.max_answer_age_cycles, 0, 1000);
  r.real("connect_timeout_s", settings.connect_timeout_s, detail::Range{0.0, 600.0});
  r.real("answer_timeout_s", settings.answer_timeout_s, detail::Range{0.0, 10.0});
  r.finish();
}

GatewayLinks::GatewayLinks() = default;
GatewayLinks::~GatewayLinks() = default;

std::unique_ptr<drives::DriveAdapter> GatewayLinks::make_drive(const GatewayAdapterSettings& settings,
                                                               const drives::DeviceConfig& device,
                                                               double cycle_time_s) {
  std::size_t i = 0;
  for (; i < links_.size(); ++i) {
    const auto& c = links_[i]->config();
    if (c.domain == settings.domain && c.partition == settings.partition &&
        c.network.interface == settings.network.interface && c.network.peers == settings.network.peers &&
        c.network.multicast_discovery == settings.network.multicast_discovery)
      break;
  }
  if (i == links_.size()) {
    dds::GatewayLinkConfig config;
    config.domain = settings.domain;
    config.partition = settings.partition;
    config.network = settings.network;
    config.cycle_time_s = cycle_time_s;
    config.max_answer_age_cycles = settings.max_answer_age_cycles;
    links_.push_back(dds::GatewayLink::create(config));
    answer_timeouts_s_.push_back(settings.answer_timeout_s);
  }
  answer_timeouts_s_[i] = std::max(answer_timeouts_s_[i], settings.answer_timeout_s);
  connect_timeout_s_ = std::max(connect_timeout_s_, settings.connect_timeout_s);
  drives::DeviceConfig with_order = device;
  with_order.codec.byte_order = settings.byte_order;
  return links_[i]->make_drive(settings.device, with_order);
}

std::vector<std::string> GatewayLinks::connect() {
  std::vector<std::string> lines;
  const auto timeout =
      std::chrono::milliseconds(static_cast<std::int64_t>(std::llround(connect_timeout_s_ * 1000.0)));
  for (const auto& link : links_) {
    for (const auto& report : link->connect(timeout)) {
      if (report.diagnosis != dds::DeviceDiagnosis::kAnswering) {
        lines.push_back(report.device + ": " + dds::to_string(report.diagnosis) + ": " + report.text);
      }
    }
  }
  return lines;
}

void GatewayLinks::wait_for_answers() {
  for (std::size_t i = 0; i < links_.size(); ++i) {
    links_[i]->wait_for_answers(
        std::chrono::nanoseconds(static_cast<std::int64_t>(std::llround(answer_timeouts_s_[i] * 1e9))));
  }
}

}  // namespace tomc::scenario

namespace tomc::scenario::detail {

void read_network(ObjectReader& reader, drives::dds::NetworkSettings& network, bool require_peers,
                  Problems& problems) {
  const std::size_t before = problems.size();
  if (const Json* v = reader.get("interface")) {
    if (auto i = read_string(*v, reader.path_of("interface"), problems)) {
      if (i->empty()) {
        problems.add(reader.path_of("interface"), "an interface name or an IPv4 address of this host");
      } else {
        network.interface = *i;
      }
    }
  }
  if (const Json* v = reader.get("peers")) {
    if (!v->is_array()) {
      problems.add(reader.path_of("peers"),
                   "expected an array of IPv4 addresses, got " + std::string(type_name(*v)));
    } else {
      network.peers.clear();
      for (std::size_t i = 0; i < v->size(); ++i) {
        const std::string path = reader.path_of("peers[" + std::to_string(i) + "]");
        if (auto peer = read_string((*v)[i], path, problems)) network.peers.push_back(*peer);
      }
    }
  }
  reader.boolean("multicast_discovery", network.multicast_discovery);
  if (problems.size() != before) return;  // the host is asked only about well-formed settings
  drives::dds::ResolvedNetwork resolved;
  for (const auto& p : drives::dds::resolve_network(network, require_peers, resolved))
    problems.add(reader.path_of(p.setting), p.message);
}

void reject_simulated_drive_keys(const Json& drive, ObjectReader& reader, Problems& problems) {
  if (!reader.valid()) return;
  for (const auto& [key, value] : drive.items()) {
    if (key == "comment" || key == "adapter" || key == "telegram" || key == "supplementary_telegram" ||
        key == "encoder_telegram")
      continue;
    problems.add(
        reader.path_of(key),
        "a parameter of the simulated drive; with the dds_gateway adapter the drive is the gateway's "
        "(for the gateway simulator: its --config file)");
    reader.get(key);
  }
}

}  // namespace tomc::scenario::detail
