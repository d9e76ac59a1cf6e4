// The gateway simulator's configuration file (gateway_sim_config.hpp).
#include "tomc/scenario/gateway_sim_config.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "gateway_adapter_detail.hpp"
#include "json_reader.hpp"
#include "tomc/drives/dds/contract.hpp"
#include "tomc/drives/dds/participant.hpp"

namespace tomc::scenario {

namespace dds = tomc::drives::dds;
using detail::ObjectReader;

drives::DeviceConfig GatewaySimDevice::device_config() const {
  drives::DeviceConfig c = drive.device_config();
  c.codec.byte_order = byte_order;
  return c;
}

namespace detail {

void read_gateway_side(ObjectReader& root, std::string& gateway, int& domain, std::string& partition,
                       drives::dds::NetworkSettings& network, double& watchdog, Problems& problems) {
  if (const Json* v = root.get("gateway")) {
    if (auto g = read_string(*v, "gateway", problems)) {
      if (g->empty() || g->size() > dds::kMaxNameLength) {
        problems.add("gateway", "a name of 1.." + std::to_string(dds::kMaxNameLength) + " characters");
      } else {
        gateway = *g;
      }
    }
  }
  root.integer("domain", domain, 0, dds::kMaxDomainId, false, true);
  if (const Json* v = root.get("partition")) {
    if (auto p = read_string(*v, "partition", problems)) partition = *p;
  }
  read_network(root, network, false, problems);
  root.real("watchdog", watchdog, Range{0.0, 60.0, true});
}

bool check_gateway_devices(const Json& devices, Problems& problems) {
  if (!devices.is_array() || devices.empty()) {
    problems.add("devices", "expected a non-empty array of devices, got " +
                                std::string(devices.is_array() ? "an empty array" : type_name(devices)));
    return false;
  }
  if (devices.size() > dds::kMaxDevices) {
    problems.add("devices", std::to_string(devices.size()) + " devices; a gateway serves at most " +
                                std::to_string(dds::kMaxDevices));
    return false;
  }
  return true;
}

void read_gateway_device(ObjectReader& r, const std::vector<std::string>& taken, std::string& name,
                         telegrams::ByteOrder& byte_order, Problems& problems) {
  if (const Json* n = r.get("name", true)) {
    if (auto text = read_string(*n, r.path_of("name"), problems)) {
      if (text->empty() || text->size() > dds::kMaxNameLength) {
        problems.add(r.path_of("name"),
                     "a device name of 1.." + std::to_string(dds::kMaxNameLength) + " characters");
      } else {
        for (const auto& other : taken) {
          if (other == *text) problems.add(r.path_of("name"), "'" + *text + "' is defined twice");
        }
        name = *text;
      }
    }
  }
  if (const Json* b = r.get("byte_order")) {
    if (auto c = read_choice(*b, r.path_of("byte_order"), {"big", "little-bytes", "swapped-words", "little"},
                             problems)) {
      byte_order = static_cast<telegrams::ByteOrder>(*c);
    }
  }
}

bool read_json_file(const std::filesystem::path& file, Json& document, Problems& problems) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    problems.add(file.string(), std::string("cannot read: ") + std::strerror(errno));
    return false;
  }
  std::ostringstream text;
  text << in.rdbuf();
  try {
    document = Json::parse(text.str());
  } catch (const Json::exception& e) {  // parse_error, and out_of_range.406 for a number beyond a double
    std::string what = e.what();
    if (const auto close = what.find("] ");
        what.starts_with("[json.exception") && close != std::string::npos) {
      what.erase(0, close + 2);
    }
    problems.add(file.string(), "malformed JSON: " + what);
    return false;
  }
  return true;
}

}  // namespace detail

void load_gateway_sim_config(const Json& document, GatewaySimConfig& config, Problems& problems) {
  ObjectReader root(document, "", problems);
  if (!root.valid()) return;
  detail::read_gateway_side(root, config.gateway, config.domain, config.partition, config.network,
                            config.watchdog, problems);
  root.real("cycle_time", config.cycle_time, detail::Range{0.0, 1.0, true});
  root.integer("drop_every", config.drop_every, 0, 1'000'000);
  root.integer("delay_us", config.delay_us, 0, 10'000'000);
  if (const Json* v = root.get("devices", true)) {
    if (detail::check_gateway_devices(*v, problems)) {
      for (std::size_t i = 0; i < v->size(); ++i) {
        const std::string path = "devices[" + std::to_string(i) + "]";
        ObjectReader r((*v)[i], path, problems);
        if (!r.valid()) continue;
        GatewaySimDevice device;
        std::vector<std::string> names;
        for (const auto& other : config.devices)
          names.push_back(other.name);
        detail::read_gateway_device(r, names, device.name, device.byte_order, problems);
        if (const Json* d = r.get("drive", true)) {
          load_drive(*d, r.path_of("drive"), config.cycle_time, device.drive, problems);
          if (device.drive.gateway) {
            problems.add(r.path_of("drive") + ".adapter",
                         "a gateway simulator's device is a simulated drive, not another gateway");
          }
        }
        r.finish();
        config.devices.push_back(std::move(device));
      }
    }
  }
  root.finish();
}

void load_gateway_sim_config_file(const std::filesystem::path& file, GatewaySimConfig& config,
                                  Problems& problems) {
  Json document;
  if (detail::read_json_file(file, document, problems)) load_gateway_sim_config(document, config, problems);
}

}  // namespace tomc::scenario
