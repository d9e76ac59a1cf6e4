// The PROFINET gateway's configuration file (profinet_gateway_config.hpp).
#include "tomc/scenario/profinet_gateway_config.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <map>
#include <optional>

#include "gateway_adapter_detail.hpp"
#include "json_reader.hpp"
#include "tomc/profinet/gsdml.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/layout.hpp"

namespace tomc::scenario {

using detail::ObjectReader;

namespace {

struct GsdmlFile {
  profinet::gsdml::Device device;
  std::string error;  // why the file cannot be used
};
using GsdmlFiles = std::map<std::filesystem::path, GsdmlFile>;

constexpr std::size_t kMaxStationName = 240;  // IEC 61158-6-10 NameOfStation

std::uint16_t telegram_bytes(std::uint16_t telegram, telegrams::Direction direction) {
  const auto codec = telegrams::TelegramCodec::create(telegram, direction);
  return codec ? static_cast<std::uint16_t>(codec->frame_size()) : 0;
}

// "a.b.c.d" with every part 0..255.
bool parse_ipv4(std::string_view text, std::array<std::uint8_t, 4>& out) {
  for (std::size_t i = 0; i < 4; ++i) {
    unsigned value = 256;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || value > 255 || end == text.data()) return false;
    out[i] = static_cast<std::uint8_t>(value);
    text.remove_prefix(static_cast<std::size_t>(end - text.data()));
    if (i < 3) {
      if (text.empty() || text.front() != '.') return false;
      text.remove_prefix(1);
    }
  }
  return text.empty();
}

void read_ipv4(ObjectReader& r, std::string_view key, std::array<std::uint8_t, 4>& target, bool required,
               Problems& problems) {
  if (const Json* v = r.get(key, required)) {
    if (auto text = detail::read_string(*v, r.path_of(key), problems); text && !parse_ipv4(*text, target)) {
      problems.add(r.path_of(key), "'" + *text + "' is not an IPv4 address (a.b.c.d)");
    }
  }
}

void read_modules(const Json& value, const std::string& path, ProfinetDeviceConfig& device,
                  Problems& problems) {
  if (!value.is_array() || value.empty() || value.size() > 64) {
    problems.add(path, "expected an array of 1..64 modules (the DAP in slot 0 first)");
    return;
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    ObjectReader m(value[i], path + "[" + std::to_string(i) + "]", problems);
    if (!m.valid()) continue;
    ProfinetModuleConfig module;
    m.integer("slot", module.slot, 0, 0x7FFF, false, true);
    m.integer("ident", module.ident, 0, 0xFFFFFFFF, true, true);
    if (const Json* subs = m.get("submodules", true)) {
      if (!subs->is_array() || subs->empty() || subs->size() > 64) {
        problems.add(m.path_of("submodules"), "expected an array of 1..64 submodules");
      } else {
        for (std::size_t k = 0; k < subs->size(); ++k) {
          ObjectReader s((*subs)[k], m.path_of("submodules") + "[" + std::to_string(k) + "]", problems);
          if (!s.valid()) continue;
          ProfinetSubmoduleConfig sub;
          s.integer("subslot", sub.subslot, 1, 0x9FFF, true, true);
          s.integer("ident", sub.ident, 0, 0xFFFFFFFF, true, true);
          s.integer("input_length", sub.input_length, 0, 1440);
          s.integer("output_length", sub.output_length, 0, 1440);
          s.finish();
          module.submodules.push_back(sub);
        }
      }
    }
    m.finish();
    device.modules.push_back(std::move(module));
  }
  if (device.modules.front().slot != 0)
    problems.add(path + "[0].slot", "the first module is the DAP in slot 0");
}

// "records": [ { "slot": 1, "subslot": 1, "index": "0xB02E", "data": "01 00 01 01 ..." } ], each record's
// data 1..kMaxRecordBytes bytes as hex digits.
constexpr std::size_t kMaxRecordBytes = 4096;

std::optional<std::vector<std::uint8_t>> hex_bytes(const std::string& text, std::string& why) {
  std::vector<std::uint8_t> bytes;
  int high = -1;
  for (const char c : text) {
    if (c == ' ') continue;
    const int digit = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
    if (digit < 0) {
      why = "'" + std::string(1, c) + "' is not a hex digit";
      return std::nullopt;
    }
    if (high < 0) {
      high = digit;
    } else {
      bytes.push_back(static_cast<std::uint8_t>(high << 4 | digit));
      high = -1;
    }
  }
  if (high >= 0)
    why = "an odd number of hex digits (two per byte)";
  else if (bytes.empty() || bytes.size() > kMaxRecordBytes)
    why = "1..4096 bytes expected";
  if (!why.empty()) return std::nullopt;
  return bytes;
}

void read_records(const Json& value, const std::string& path, ProfinetDeviceConfig& device,
                  Problems& problems) {
  if (!value.is_array() || value.size() > ProfinetDeviceConfig::kMaxRecords) {
    problems.add(path, "expected an array of at most 64 records");
    return;
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    ObjectReader r(value[i], path + "[" + std::to_string(i) + "]", problems);
    if (!r.valid()) continue;
    ProfinetRecordConfig record;
    r.integer("slot", record.slot, 0, 0x7FFF, false, true);
    r.integer("subslot", record.subslot, 1, 0x9FFF, true);
    r.integer("index", record.index, 0, 0xFFFF, true, true);
    if (const Json* d = r.get("data", true)) {
      if (auto text = detail::read_string(*d, r.path_of("data"), problems)) {
        std::string why;
        if (auto bytes = hex_bytes(*text, why)) {
          record.data = std::move(*bytes);
        } else {
          problems.add(r.path_of("data"), why);
        }
      }
    }
    r.finish();
    device.records.push_back(std::move(record));
  }
}

// "parameters": [ { "number": 2000, "subindex": 0, "value": 3000.0, "slot": 1 } ] (decision I33): number
// 1..65535, subindex 0..65535 (default 0), value a finite number (whether it fits the parameter's format is
// the drive's answer at start-up), slot optional.
void read_parameters(const Json& value, const std::string& path, ProfinetDeviceConfig& device,
                     Problems& problems) {
  if (!value.is_array() || value.size() > ProfinetDeviceConfig::kMaxParameters) {
    problems.add(path, "expected an array of at most 64 parameters");
    return;
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    ObjectReader r(value[i], path + "[" + std::to_string(i) + "]", problems);
    if (!r.valid()) continue;
    ProfinetParameterConfig parameter;
    r.integer("slot", parameter.slot, 1, 0x7FFF);
    r.integer("number", parameter.number, 1, 0xFFFF, false, true);
    r.integer("subindex", parameter.subindex, 0, 0xFFFF);
    r.real("value", parameter.value, detail::kAnyNumber, true);
    r.finish();
    for (const ProfinetParameterConfig& other : device.parameters) {
      if (other.slot == parameter.slot && other.number == parameter.number &&
          other.subindex == parameter.subindex) {
        problems.add(r.path(), "parameter " + std::to_string(parameter.number) + " subindex " +
                                   std::to_string(parameter.subindex) + " is written twice");
      }
    }
    device.parameters.push_back(parameter);
  }
}

// The keys of each contract slot's telegram and place: "<key>", "<key>_slot", "<key>_subslot" (the drive's
// are "telegram", "telegram_slot", ...), and what the messages call its submodule.
struct SlotKeys {
  const char* key;
  const char* submodule;
};
constexpr SlotKeys kSlotKeys[] = {{"telegram", "the telegram submodule"},
                                  {"supplementary", "the supplementary telegram submodule"},
                                  {"encoder", "the encoder telegram submodule"},
                                  {"encoder2", "the second encoder telegram submodule"}};
static_assert(std::size(kSlotKeys) == drives::kSlotCount);

// Each used slot's telegram submodule must carry the telegram: its lengths are the telegram's PZD bytes (spec
// 06 §2.15). `by_hand`: the modules are the file's "modules" array (the path names the entry); otherwise
// they come from the GSDML file and the message names the slot and subslot.
void check_telegram_submodule(const ProfinetDeviceConfig& device, std::size_t slot_index,
                              const std::string& path, bool by_hand, Problems& problems) {
  const auto slot = static_cast<drives::Slot>(slot_index);
  const std::uint16_t telegram = device.device_config().telegram(slot);
  const ProfinetTelegramPlace place = device.place(slot);
  if (telegram == 0 || place.subslot == 0 || device.modules.empty()) return;  // subslot 0: not read
  const std::uint16_t in = telegram_bytes(telegram, telegrams::Direction::kActual);
  const std::uint16_t out = telegram_bytes(telegram, telegrams::Direction::kSetpoint);
  for (std::size_t i = 0; i < device.modules.size(); ++i) {
    const ProfinetModuleConfig& module = device.modules[i];
    if (module.slot != place.slot) continue;
    for (std::size_t k = 0; k < module.submodules.size(); ++k) {
      const ProfinetSubmoduleConfig& sub = module.submodules[k];
      if (sub.subslot != place.subslot) continue;
      if (sub.input_length != in || sub.output_length != out) {
        problems.add(
            by_hand ? path + "[" + std::to_string(i) + "].submodules[" + std::to_string(k) + "]" : path,
            std::string(by_hand ? ""
                                : "slot " + std::to_string(module.slot) + " subslot " +
                                      std::to_string(sub.subslot) + ": ") +
                kSlotKeys[slot_index].submodule + " has input_length " + std::to_string(sub.input_length) +
                " and output_length " + std::to_string(sub.output_length) + "; telegram " +
                std::to_string(telegram) + " needs " + std::to_string(in) + " and " + std::to_string(out));
      }
      return;
    }
  }
  const std::string key = kSlotKeys[slot_index].key;
  problems.add(path, "no submodule in slot " + std::to_string(place.slot) + " subslot " +
                         std::to_string(place.subslot) + " (" + key + "_slot, " + key + "_subslot)");
}

// The emulated drive's layout (drives::telegram_place()).
ProfinetTelegramPlace default_place(const ProfinetDeviceConfig& device, drives::Slot slot) noexcept {
  return drives::telegram_place(device.device_config(), slot);
}

// The telegrams of the slots and where their submodules are: "telegram" (required unless "encoder_telegram"
// is given), "supplementary_telegram", "encoder_telegram", "encoder2_telegram" (only beside
// "encoder_telegram"), each with "<key>_slot" and "<key>_subslot".
void read_telegrams(ObjectReader& r, ProfinetDeviceConfig& device, Problems& problems) {
  r.integer("telegram", device.telegram, 1, 999, false, !r.has("encoder_telegram"));
  r.integer("supplementary_telegram", device.supplementary_telegram, 1, 999, false);
  r.integer("encoder_telegram", device.encoder_telegram, 1, 999, false);
  r.integer("encoder2_telegram", device.encoder2_telegram, 1, 999, false);
  const std::size_t before = problems.size();
  if (const std::string why = drives::validate(device.device_config()); !why.empty()) {
    const char* key = why.rfind("supplementary", 0) == 0          ? "supplementary_telegram"
                      : why.rfind("encoder_telegrams[1]", 0) == 0 ? "encoder2_telegram"
                      : why.rfind("encoder", 0) == 0              ? "encoder_telegram"
                                                                  : "telegram";
    // The file's key names the field: without drives::DeviceConfig's own field name ("encoder_telegrams[1]:
    // ").
    const std::size_t colon = why.find(": ");
    problems.add(r.path_of(key), colon == std::string::npos ? why : why.substr(colon + 2));
  }
  if (device.encoder2_telegram != 0 && device.encoder_telegram == 0)
    problems.add(r.path_of("encoder2_telegram"), "a second encoder needs a first one (encoder_telegram)");
  const bool valid = problems.size() == before;
  const std::array<std::uint16_t, drives::kSlotCount> numbers{
      device.telegram, device.supplementary_telegram, device.encoder_telegram, device.encoder2_telegram};
  for (std::size_t k = 0; k < drives::kSlotCount; ++k) {
    const std::string key = kSlotKeys[k].key;
    ProfinetTelegramPlace place = default_place(device, static_cast<drives::Slot>(k));
    r.integer(key + "_slot", place.slot, 0, 0x7FFF);
    r.integer(key + "_subslot", place.subslot, 1, 0x9FFF, true);
    if (numbers[k] != 0 && valid) device.places[k] = place;
  }
  static constexpr const char* kNames[] = {"drive", "supplementary", "encoder", "second encoder"};
  // Only for telegrams that passed validate(): the places of the others were never set.
  for (std::size_t a = 0; a < drives::kSlotCount && valid; ++a) {
    for (std::size_t b = a + 1; b < drives::kSlotCount; ++b) {
      if (numbers[a] != 0 && numbers[b] != 0 && device.places[a].slot == device.places[b].slot &&
          device.places[a].subslot == device.places[b].subslot)
        problems.add(r.path_of(std::string(kSlotKeys[b].key) + "_subslot"),
                     "slot " + std::to_string(device.places[b].slot) + " subslot " +
                         std::to_string(device.places[b].subslot) + " carries the " + kNames[a] +
                         " telegram already");
    }
  }
}

// "gsdml": the device's GSDML file (relative to the configuration file), "dap" (its ID; optional when the
// file has one) and "modules" chosen by their GSDML IDs:
//   "modules": [ { "slot": 1, "module": "DO_DRIVE", "submodules": [ { "subslot": 2, "submodule": "TEL3" } ] }
//   ]
// The idents and IO lengths come from the file. Files read once per configuration (several drives share one).
void read_gsdml_modules(ObjectReader& r, const std::filesystem::path& base, GsdmlFiles& files,
                        ProfinetDeviceConfig& device, Problems& problems) {
  namespace gsdml = profinet::gsdml;
  const auto file = detail::read_string(*r.get("gsdml"), r.path_of("gsdml"), problems);
  gsdml::Selection selection;
  if (const Json* v = r.get("dap")) {
    if (auto id = detail::read_string(*v, r.path_of("dap"), problems)) selection.access_point = *id;
  }
  const Json* list = r.get("modules");
  const std::string list_path = r.path_of("modules");
  if (list != nullptr && (!list->is_array() || list->size() > 64)) {
    problems.add(list_path, "expected an array of up to 64 modules chosen from the GSDML file");
    list = nullptr;
  }
  for (std::size_t i = 0; list != nullptr && i < list->size(); ++i) {
    ObjectReader m((*list)[i], list_path + "[" + std::to_string(i) + "]", problems);
    if (!m.valid()) continue;
    gsdml::ModuleChoice module;
    m.integer("slot", module.slot, 1, 0x7FFF, false, true);
    if (const Json* id = m.get("module", true)) {
      if (auto text = detail::read_string(*id, m.path_of("module"), problems)) module.id = *text;
    }
    if (const Json* subs = m.get("submodules")) {
      if (!subs->is_array() || subs->size() > 64) {
        problems.add(m.path_of("submodules"), "expected an array of up to 64 submodules");
      } else {
        for (std::size_t k = 0; k < subs->size(); ++k) {
          ObjectReader s((*subs)[k], m.path_of("submodules") + "[" + std::to_string(k) + "]", problems);
          if (!s.valid()) continue;
          gsdml::SubmoduleChoice sub;
          s.integer("subslot", sub.subslot, 1, 0x9FFF, true, true);
          if (const Json* id = s.get("submodule", true)) {
            if (auto text = detail::read_string(*id, s.path_of("submodule"), problems)) sub.id = *text;
          }
          s.finish();
          module.submodules.push_back(std::move(sub));
        }
      }
    }
    m.finish();
    selection.modules.push_back(std::move(module));
  }
  if (!file) return;
  const std::filesystem::path resolved = base / *file;
  auto cached = files.find(resolved);
  if (cached == files.end()) {
    GsdmlFile parsed;
    try {
      parsed.device = gsdml::parse_file(resolved);
    } catch (const gsdml::GsdmlError& e) {
      parsed.error = e.what();
    }
    cached = files.emplace(resolved, std::move(parsed)).first;
  }
  if (!cached->second.error.empty()) {
    problems.add(r.path_of("gsdml"), cached->second.error);
    return;
  }
  try {
    for (const profinet::ExpectedModule& m : gsdml::expected_modules(cached->second.device, selection)) {
      ProfinetModuleConfig module{m.api, m.slot, m.ident, {}};
      for (const profinet::ExpectedSubmodule& s : m.submodules)
        module.submodules.push_back({s.subslot, s.ident, s.input_length, s.output_length});
      device.modules.push_back(std::move(module));
    }
    // A record of the file goes to the API of the submodule plugged at its slot and subslot (a PROFIdrive
    // telegram's is 0x3A00, not 0; the expected modules are one entry per slot and API): a device refuses a
    // write addressed to another API (review of stop 33).
    for (ProfinetRecordConfig& own : device.records) {
      for (const ProfinetModuleConfig& m : device.modules) {
        const bool plugged = m.slot == own.slot && std::any_of(m.submodules.begin(), m.submodules.end(),
                                                               [&](const ProfinetSubmoduleConfig& sub) {
                                                                 return sub.subslot == own.subslot;
                                                               });
        if (plugged) own.api = m.api;
      }
    }
    // The plugged submodules' ParameterRecordDataItems go first (decision I34); a record of the file's own
    // "records" for the same place and index replaces the GSDML default (the file is the user's setting).
    std::vector<ProfinetRecordConfig> records;
    for (gsdml::PlacedRecord& placed : gsdml::parameter_records(cached->second.device, selection)) {
      const bool overridden = std::any_of(device.records.begin(), device.records.end(), [&](const auto& own) {
        return own.slot == placed.slot && own.subslot == placed.subslot && own.index == placed.index;
      });
      if (!overridden)
        records.push_back(
            {placed.slot, placed.subslot, placed.index, std::move(placed.data), placed.api, true});
    }
    records.insert(records.end(), device.records.begin(), device.records.end());
    device.records = std::move(records);
  } catch (const gsdml::GsdmlError& e) {
    problems.add(list != nullptr ? list_path : r.path_of("gsdml"), e.what());
  }
}

}  // namespace

// A name of station: lower-case labels of letters, digits and '-' separated by '.' (IEC 61158-6-10).
std::string station_name_problem(const std::string& name) {
  if (name.empty() || name.size() > kMaxStationName) return "1..240 characters";
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.';
    if (!ok) return "'" + name + "': only a-z, 0-9, '-' and '.' (DCP names are lower case)";
  }
  return {};
}

ProfinetTelegramPlace ProfinetDeviceConfig::place(drives::Slot s) const noexcept {
  const std::uint16_t numbers[] = {telegram, supplementary_telegram, encoder_telegram, encoder2_telegram};
  const auto i = static_cast<std::size_t>(s);
  if (numbers[i] == 0) return {};
  return places[i].subslot != 0 ? places[i] : default_place(*this, s);
}

drives::DeviceConfig ProfinetDeviceConfig::device_config() const {
  drives::DeviceConfig c;
  c.drive_telegram = telegram;
  c.supplementary_telegram = supplementary_telegram;
  c.encoder_telegrams[0] = encoder_telegram;
  c.encoder_telegrams[1] = encoder2_telegram;
  c.codec.byte_order = byte_order;
  return c;
}

std::vector<ProfinetEncoderErrorBit> ProfinetDeviceConfig::encoder_error_bits() const {
  const drives::DeviceConfig config = device_config();
  // The high byte of a 16-bit word is its second byte when every word is low byte first.
  const bool low_byte_first =
      byte_order == telegrams::ByteOrder::kLittleBytes || byte_order == telegrams::ByteOrder::kLittle;
  std::vector<ProfinetEncoderErrorBit> bits;
  const auto add = [&](drives::Slot slot, telegrams::Signal word, const char* name) {
    const auto layout = telegrams::find_layout(config.telegram(slot), telegrams::Direction::kActual);
    const int offset = layout ? layout->offset_of(word) : -1;
    if (offset < 0) return;
    bits.push_back({slot, static_cast<std::size_t>(offset) + (low_byte_first ? 1u : 0u), 0x80, name});
  };
  add(drives::Slot::kDrive, telegrams::Signal::G1_ZSW, "G1_ZSW of the drive telegram");
  add(drives::Slot::kDrive, telegrams::Signal::G2_ZSW, "G2_ZSW of the drive telegram");
  add(drives::Slot::kEncoder1, telegrams::Signal::G1_ZSW, "G1_ZSW of the encoder telegram");
  add(drives::Slot::kEncoder2, telegrams::Signal::G1_ZSW, "G1_ZSW of the second encoder telegram");
  return bits;
}

void load_profinet_gateway_config(const Json& document, ProfinetGatewayConfig& config, Problems& problems,
                                  const std::filesystem::path& base_directory) {
  GsdmlFiles gsdml_files;
  ObjectReader root(document, "", problems);
  if (!root.valid()) return;
  detail::read_gateway_side(root, config.gateway, config.domain, config.partition, config.network,
                            config.watchdog, problems);
  if (const Json* pn = root.get("profinet", true)) {
    ObjectReader p(*pn, "profinet", problems);
    if (p.valid()) {
      if (const Json* v = p.get("interface", true)) {
        if (auto name = detail::read_string(*v, p.path_of("interface"), problems)) {
          if (name->empty() || name->size() > 15) {
            problems.add(p.path_of("interface"), "an interface name of 1..15 characters (e.g. \"eth1\")");
          } else {
            config.interface = *name;
          }
        }
      }
      read_ipv4(p, "ip", config.ip, true, problems);
      // RT_CLASS_1 on Linux: send clock 1..4 ms (IEC 61158-6-10 SendClockFactor 32..128 × 31.25 µs).
      p.integer("send_clock_factor", config.send_clock_factor, 32, 128);
      p.integer("reduction_ratio", config.reduction_ratio, 1, 512);
      p.integer("watchdog_factor", config.watchdog_factor, 3, 255);
      p.integer("rta_timeout_factor", config.rta_timeout_factor, 1, 100);  // AlarmCRBlockReq (I35)
      p.integer("rta_retries", config.rta_retries, 3, 15);
      p.integer("fifo_priority", config.fifo_priority, 0, 99);
      p.integer("wake_margin_us", config.wake_margin_us, 0, 500);  // half the shortest send clock (1 ms)
      p.boolean("lock_memory", config.lock_memory);
      p.finish();
    }
  }
  if (const Json* v = root.get("devices", true);
      v != nullptr && detail::check_gateway_devices(*v, problems)) {
    for (std::size_t i = 0; i < v->size(); ++i) {
      ObjectReader r((*v)[i], "devices[" + std::to_string(i) + "]", problems);
      if (!r.valid()) continue;
      ProfinetDeviceConfig device;
      std::vector<std::string> names;
      for (const auto& other : config.devices)
        names.push_back(other.name);
      detail::read_gateway_device(r, names, device.name, device.byte_order, problems);
      if (const Json* n = r.get("name_of_station", true)) {
        if (auto name = detail::read_string(*n, r.path_of("name_of_station"), problems)) {
          if (const std::string why = station_name_problem(*name); !why.empty()) {
            problems.add(r.path_of("name_of_station"), why);
          } else {
            for (const auto& other : config.devices) {
              if (other.name_of_station == *name)
                problems.add(r.path_of("name_of_station"), "'" + *name + "' is used twice");
            }
            device.name_of_station = *name;
          }
        }
      }
      read_ipv4(r, "ip", device.ip, true, problems);
      read_ipv4(r, "netmask", device.netmask, false, problems);
      if (device.ip == config.ip && device.ip != std::array<std::uint8_t, 4>{})
        problems.add(r.path_of("ip"), "the same address as profinet.ip (the controller)");
      read_telegrams(r, device, problems);
      r.boolean("check_telegram", device.check_telegram);
      if (const Json* records = r.get("records"))
        read_records(*records, r.path_of("records"), device, problems);
      if (const Json* parameters = r.get("parameters"))
        read_parameters(*parameters, r.path_of("parameters"), device, problems);
      if (r.has("gsdml")) {
        read_gsdml_modules(r, base_directory, gsdml_files, device, problems);
      } else if (const Json* m = r.get("modules")) {
        read_modules(*m, r.path_of("modules"), device, problems);
      }
      for (std::size_t k = 0; k < drives::kSlotCount; ++k)
        check_telegram_submodule(device, k, r.path_of("modules"), !r.has("gsdml"), problems);
      r.finish();
      config.devices.push_back(std::move(device));
    }
  }
  root.finish();
}

void load_profinet_gateway_config_file(const std::filesystem::path& file, ProfinetGatewayConfig& config,
                                       Problems& problems) {
  Json document;
  if (detail::read_json_file(file, document, problems))
    load_profinet_gateway_config(document, config, problems, file.parent_path());
}

}  // namespace tomc::scenario
