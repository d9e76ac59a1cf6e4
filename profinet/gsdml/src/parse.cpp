// Reading a GSDML file (gsdml.hpp) with tinyxml2: the elements of GSDML V2.x an IO controller needs.
#include <tinyxml2.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include "tomc/profinet/gsdml.hpp"

namespace tomc::profinet::gsdml {

namespace {

namespace xml = tinyxml2;
using Texts = std::map<std::string, std::string, std::less<>>;

constexpr std::size_t kMaxIoDataLength = 1440;  // C_SDU of one IOCR (IEC 61158-6-10)

// GSDML's namespace is the default one, but a file may prefix it ("gsdml:Name"): compare local names.
std::string_view local_name(const xml::XMLElement& e) {
  const std::string_view name = e.Name();
  const auto colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

// "<SubmoduleItem ID="TEL3">" for messages.
std::string describe(const xml::XMLElement& e) {
  std::string text = "<" + std::string(local_name(e));
  if (const char* id = e.Attribute("ID")) text += " ID=\"" + std::string(id) + "\"";
  return text + ">";
}

[[noreturn]] void fail(const xml::XMLElement& e, const std::string& what) {
  throw GsdmlError("GSDML line " + std::to_string(e.GetLineNum()) + ": " + describe(e) + ": " + what);
}

const xml::XMLElement* child(const xml::XMLElement& parent, std::string_view name) {
  for (const xml::XMLElement* c = parent.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (local_name(*c) == name) return c;
  }
  return nullptr;
}

const xml::XMLElement& required_child(const xml::XMLElement& parent, std::string_view name) {
  const xml::XMLElement* c = child(parent, name);
  if (c == nullptr) fail(parent, "no <" + std::string(name) + "> element");
  return *c;
}

template <typename Visit>
void for_each_child(const xml::XMLElement& parent, std::string_view name, Visit visit) {
  for (const xml::XMLElement* c = parent.FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
    if (local_name(*c) == name) visit(*c);
  }
}

// GSDML writes numbers as "0x0000002A" or in decimal.
std::uint64_t number(const xml::XMLElement& e, const char* attribute, std::string_view text,
                     std::uint64_t maximum) {
  int base = 10;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    text.remove_prefix(2);
    base = 16;
  }
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, base);
  if (error != std::errc() || end != text.data() + text.size() || value > maximum) {
    fail(e, std::string(attribute) + " \"" + std::string(e.Attribute(attribute)) +
                "\" is not a number in 0.." + std::to_string(maximum));
  }
  return value;
}

std::uint64_t number_attribute(const xml::XMLElement& e, const char* attribute, std::uint64_t maximum,
                               std::optional<std::uint64_t> fallback = std::nullopt) {
  const char* text = e.Attribute(attribute);
  if (text == nullptr) {
    if (fallback) return *fallback;
    fail(e, std::string("no ") + attribute);
  }
  return number(e, attribute, text, maximum);
}

std::string string_attribute(const xml::XMLElement& e, const char* attribute) {
  const char* text = e.Attribute(attribute);
  if (text == nullptr || *text == '\0') fail(e, std::string("no ") + attribute);
  return text;
}

// A ValueList: numbers and ranges "a..b" separated by spaces, each within 0..maximum.
ValueList value_list(const xml::XMLElement& e, const char* attribute, std::uint16_t maximum) {
  ValueList list;
  const char* text = e.Attribute(attribute);
  if (text == nullptr) return list;
  std::istringstream words{std::string(text)};
  for (std::string word; words >> word;) {
    const auto dots = word.find("..");
    const std::string first = word.substr(0, dots);
    const std::string last = dots == std::string::npos ? first : word.substr(dots + 2);
    const auto low = static_cast<std::uint16_t>(number(e, attribute, first, maximum));
    const auto high = static_cast<std::uint16_t>(number(e, attribute, last, maximum));
    if (low > high) fail(e, std::string(attribute) + " \"" + text + "\": the range " + word + " is empty");
    list.ranges.emplace_back(low, high);
  }
  if (list.empty()) fail(e, std::string(attribute) + " is empty");
  return list;
}

std::string name_of(const xml::XMLElement& item, const Texts& texts) {
  const xml::XMLElement* info = child(item, "ModuleInfo");
  const xml::XMLElement* name = info ? child(*info, "Name") : nullptr;
  const char* id = name ? name->Attribute("TextId") : nullptr;
  if (id == nullptr) return {};
  const auto found = texts.find(id);
  return found == texts.end() ? std::string{} : found->second;
}

// Bytes of one DataItem (GSDML V2.x data types; strings and octet strings take their Length).
std::size_t data_item_length(const xml::XMLElement& item) {
  static const std::map<std::string, std::size_t, std::less<>> kSizes = {
      {"Integer8", 1},
      {"Unsigned8", 1},
      {"Unsigned8_S", 1},
      {"Integer16", 2},
      {"Unsigned16", 2},
      {"Integer16_S", 2},
      {"Unsigned16_S", 2},
      {"N2", 2},
      {"V2", 2},
      {"L2", 2},
      {"R2", 2},
      {"T2", 2},
      {"D2", 2},
      {"E2", 2},
      {"X2", 2},
      {"Unipolar2.16", 2},
      {"Unsigned8+Unsigned8", 2},
      {"Integer32", 4},
      {"Unsigned32", 4},
      {"Float32", 4},
      {"N4", 4},
      {"T4", 4},
      {"C4", 4},
      {"X4", 4},
      {"TimeOfDay without date indication", 4},
      {"TimeDifference without date indication", 4},
      {"F_MessageTrailer4Byte", 4},
      {"Float32+Unsigned8", 5},
      {"Float32+Status8", 5},
      {"F_MessageTrailer5Byte", 5},
      {"TimeOfDay with date indication", 6},
      {"TimeDifference with date indication", 6},
      {"Date", 7},
      {"Integer64", 8},
      {"Unsigned64", 8},
      {"Float64", 8},
      {"NetworkTime", 8},
      {"NetworkTimeDifference", 8},
  };
  static const std::map<std::string, int, std::less<>> kWithLength = {
      {"OctetString", 0},    {"OctetString_S", 0}, {"VisibleString", 0},
      {"UnicodeString8", 0}, {"61131_STRING", 0},  {"61131_WSTRING", 0}};
  const std::string type = string_attribute(item, "DataType");
  if (const auto found = kSizes.find(type); found != kSizes.end()) return found->second;
  if (kWithLength.contains(type)) return number_attribute(item, "Length", kMaxIoDataLength);
  fail(item, "DataType \"" + type + "\" is not a GSDML data type of IO data");
}

std::uint16_t io_data_length(const xml::XMLElement& io_data, std::string_view direction) {
  const xml::XMLElement* list = child(io_data, direction);
  if (list == nullptr) return 0;
  std::size_t total = 0;
  for_each_child(*list, "DataItem", [&](const xml::XMLElement& item) { total += data_item_length(item); });
  if (total > kMaxIoDataLength) {
    fail(*list, std::to_string(total) + " bytes of IO data; one IOCR carries at most " +
                    std::to_string(kMaxIoDataLength));
  }
  return static_cast<std::uint16_t>(total);
}

// ---- RecordDataList/ParameterRecordDataItem (decision I34) ----

constexpr std::size_t kMaxRecordLength = 4096;  // as the gateway file's "records"
constexpr std::size_t kMaxRecordsPerSubmodule = 64;

// A signed or unsigned number in decimal or "0x" hex ("-5", "3000", "0x0BB8") within [low, high].
std::int64_t integer_value(const xml::XMLElement& e, const char* attribute, std::int64_t low,
                           std::int64_t high) {
  const std::string owned = string_attribute(e, attribute);
  std::string_view text = owned;
  const bool negative = !text.empty() && text.front() == '-';
  if (negative) text.remove_prefix(1);
  int base = 10;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    text.remove_prefix(2);
    base = 16;
  }
  std::uint64_t magnitude = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), magnitude, base);
  // The types here are at most 32 bits wide: a magnitude beyond 2^32 is out of range whatever its sign.
  const bool parsed = error == std::errc() && end == text.data() + text.size() && !text.empty() &&
                      magnitude <= (std::uint64_t{1} << 32);
  const std::int64_t value =
      negative ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
  if (!parsed || value < low || value > high) {
    fail(e, std::string(attribute) + " \"" + e.Attribute(attribute) + "\" is not a number in " +
                std::to_string(low) + ".." + std::to_string(high));
  }
  return value;
}

// Puts `bytes` big-endian bytes of `value` at `offset` of the record (checked against its Length).
void put_bytes(const xml::XMLElement& e, std::vector<std::uint8_t>& data, std::size_t offset,
               std::size_t bytes, std::uint64_t value) {
  if (offset + bytes > data.size()) {
    fail(e, "ByteOffset " + std::to_string(offset) + " + " + std::to_string(bytes) +
                " bytes is beyond the record's Length " + std::to_string(data.size()));
  }
  for (std::size_t k = 0; k < bytes; ++k)
    data[offset + k] = static_cast<std::uint8_t>(value >> (8 * (bytes - 1 - k)));
}

// A Ref: its DefaultValue in its DataType at ByteOffset (and BitOffset/BitLength for Bit and BitArea).
void apply_ref(const xml::XMLElement& ref, std::vector<std::uint8_t>& data) {
  struct IntegerType {
    const char* name;
    std::size_t bytes;
    bool is_signed;
  };
  static constexpr IntegerType kIntegers[] = {{"Integer8", 1, true},    {"Integer16", 2, true},
                                              {"Integer32", 4, true},   {"Unsigned8", 1, false},
                                              {"Unsigned16", 2, false}, {"Unsigned32", 4, false}};
  const std::string type = string_attribute(ref, "DataType");
  const auto offset = static_cast<std::size_t>(number_attribute(ref, "ByteOffset", kMaxRecordLength - 1));
  if (type == "Bit" || type == "BitArea") {
    // Bit 0 is the least significant bit of the byte at ByteOffset; a BitArea within that byte only.
    const auto bit = static_cast<unsigned>(number_attribute(ref, "BitOffset", 7, 0));
    const auto length = static_cast<unsigned>(type == "Bit" ? 1 : number_attribute(ref, "BitLength", 8, 1));
    if (length == 0 || bit + length > 8) {
      fail(ref, "BitOffset " + std::to_string(bit) + " and BitLength " + std::to_string(length) +
                    " leave the byte at ByteOffset (not supported)");
    }
    if (offset >= data.size()) {
      fail(ref, "ByteOffset " + std::to_string(offset) + " is beyond the record's Length " +
                    std::to_string(data.size()));
    }
    const auto value = static_cast<unsigned>(integer_value(ref, "DefaultValue", 0, (1 << length) - 1));
    const unsigned mask = ((1u << length) - 1) << bit;
    data[offset] = static_cast<std::uint8_t>((data[offset] & ~mask) | (value << bit));
    return;
  }
  for (const IntegerType& t : kIntegers) {
    if (type != t.name) continue;
    const std::int64_t bits = static_cast<std::int64_t>(8 * t.bytes);
    const std::int64_t low = t.is_signed ? -(std::int64_t{1} << (bits - 1)) : 0;
    const std::int64_t high =
        t.is_signed ? (std::int64_t{1} << (bits - 1)) - 1 : (std::int64_t{1} << bits) - 1;
    const std::int64_t value = integer_value(ref, "DefaultValue", low, high);
    put_bytes(ref, data, offset, t.bytes, static_cast<std::uint64_t>(value));
    return;
  }
  if (type == "Float32") {
    // The whole attribute must be one finite number: sscanf-like parsing would take "1.5abc", "nan", "inf".
    const char* text = ref.Attribute("DefaultValue");
    const std::string_view digits = text == nullptr ? std::string_view{} : std::string_view{text};
    float value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || error != std::errc{} || end != digits.data() + digits.size() || !std::isfinite(value))
      fail(ref, "DefaultValue \"" + std::string(digits) + "\" is not a finite Float32");
    put_bytes(ref, data, offset, 4, std::bit_cast<std::uint32_t>(value));
    return;
  }
  fail(ref,
       "DataType \"" + type +
           "\" of a parameter Ref is not supported (Bit, BitArea, Integer8..32, Unsigned8..32, Float32)");
}

// A Const: Data ("0x01,0x02,...", one byte each) at ByteOffset (default 0).
void apply_const(const xml::XMLElement& c, std::vector<std::uint8_t>& data) {
  auto offset = static_cast<std::size_t>(number_attribute(c, "ByteOffset", kMaxRecordLength - 1, 0));
  const std::string text = string_attribute(c, "Data");
  std::istringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    const auto first = item.find_first_not_of(" \t\r\n");
    const auto last = item.find_last_not_of(" \t\r\n");
    if (first == std::string::npos) fail(c, "Data \"" + text + "\" has an empty byte");
    const std::string byte = item.substr(first, last - first + 1);
    put_bytes(c, data, offset++, 1, number(c, "Data", byte, 0xFF));
  }
}

std::vector<ParameterRecord> read_records(const xml::XMLElement& submodule) {
  std::vector<ParameterRecord> records;
  const xml::XMLElement* list = child(submodule, "RecordDataList");
  if (list == nullptr) return records;
  for_each_child(*list, "ParameterRecordDataItem", [&](const xml::XMLElement& item) {
    if (records.size() == kMaxRecordsPerSubmodule) fail(item, "more than 64 ParameterRecordDataItems");
    ParameterRecord r;
    r.line = item.GetLineNum();
    r.index = static_cast<std::uint16_t>(number_attribute(item, "Index", 0x7FFF));
    r.transfer_sequence = static_cast<std::uint32_t>(number_attribute(item, "TransferSequence", 0xFFFF, 0));
    const auto length = static_cast<std::size_t>(number_attribute(item, "Length", kMaxRecordLength));
    if (length == 0) fail(item, "Length 0");
    for (const ParameterRecord& other : records) {
      if (other.index == r.index) fail(item, "Index " + std::to_string(r.index) + " twice in one submodule");
    }
    r.data.assign(length, 0);
    // Const first, then Ref on top (GSDML: a Ref's DefaultValue is what a user has not changed).
    for_each_child(item, "Const", [&](const xml::XMLElement& c) { apply_const(c, r.data); });
    for_each_child(item, "Ref", [&](const xml::XMLElement& ref) { apply_ref(ref, r.data); });
    records.push_back(std::move(r));
  });
  std::stable_sort(records.begin(), records.end(), [](const ParameterRecord& a, const ParameterRecord& b) {
    return a.transfer_sequence < b.transfer_sequence;
  });
  return records;
}

// A SubmoduleItem, VirtualSubmoduleItem, InterfaceSubmoduleItem or PortSubmoduleItem.
Submodule read_submodule(const xml::XMLElement& e, const Texts& texts) {
  Submodule s;
  s.line = e.GetLineNum();
  if (const char* id = e.Attribute("ID")) s.id = id;
  s.name = name_of(e, texts);
  s.api = static_cast<std::uint32_t>(number_attribute(e, "API", 0xFFFFFFFF, 0));
  s.ident = static_cast<std::uint32_t>(number_attribute(e, "SubmoduleIdentNumber", 0xFFFFFFFF));
  if (const xml::XMLElement* io = child(e, "IOData")) {
    s.input_length = io_data_length(*io, "Input");
    s.output_length = io_data_length(*io, "Output");
  }
  s.records = read_records(e);
  return s;
}

std::vector<ItemRef> read_refs(const xml::XMLElement* list, std::string_view element, const char* target,
                               const char* allowed, const char* fixed, std::uint16_t maximum) {
  std::vector<ItemRef> refs;
  if (list == nullptr) return refs;
  for_each_child(*list, element, [&](const xml::XMLElement& e) {
    ItemRef ref;
    ref.line = e.GetLineNum();
    ref.target = string_attribute(e, target);
    ref.fixed = value_list(e, fixed, maximum);
    ref.allowed = value_list(e, allowed, maximum);
    if (ref.allowed.empty()) ref.allowed = ref.fixed;
    if (ref.allowed.empty()) fail(e, std::string("neither ") + allowed + " nor " + fixed);
    refs.push_back(std::move(ref));
  });
  return refs;
}

// The virtual submodules a module (or DAP) carries itself; FixedInSubslots defaults to 1.
void read_own_submodules(const xml::XMLElement& e, const Texts& texts, Module& module) {
  if (const xml::XMLElement* list = child(e, "VirtualSubmoduleList")) {
    for_each_child(*list, "VirtualSubmoduleItem", [&](const xml::XMLElement& item) {
      Submodule s = read_submodule(item, texts);
      s.fixed_in_subslots = value_list(item, "FixedInSubslots", 0x7FFF);
      if (s.fixed_in_subslots.empty()) s.fixed_in_subslots.ranges.emplace_back(1, 1);
      module.submodules.push_back(std::move(s));
    });
  }
}

// What a ModuleItem and a DeviceAccessPointItem share: ID, name, ident and their own submodules.
Module read_module_item(const xml::XMLElement& e, const Texts& texts) {
  Module m;
  m.line = e.GetLineNum();
  m.id = string_attribute(e, "ID");
  m.name = name_of(e, texts);
  m.ident = static_cast<std::uint32_t>(number_attribute(e, "ModuleIdentNumber", 0xFFFFFFFF));
  read_own_submodules(e, texts, m);
  return m;
}

Module read_module(const xml::XMLElement& e, const Texts& texts) {
  Module m = read_module_item(e, texts);
  m.useable = read_refs(child(e, "UseableSubmodules"), "SubmoduleItemRef", "SubmoduleItemTarget",
                        "AllowedInSubslots", "FixedInSubslots", 0x7FFF);
  return m;
}

Module read_access_point(const xml::XMLElement& e, const Texts& texts) {
  Module dap = read_module_item(e, texts);
  const ValueList slots = value_list(e, "FixedInSlots", 0x7FFF);
  dap.slot = slots.empty() ? 0 : slots.ranges.front().first;
  // The interface (0x8000 + 0x100 × interface) and its ports: submodules without IO data at fixed subslots.
  if (const xml::XMLElement* system = child(e, "SystemDefinedSubmoduleList")) {
    for (const char* kind : {"InterfaceSubmoduleItem", "PortSubmoduleItem"}) {
      for_each_child(*system, kind, [&](const xml::XMLElement& item) {
        Submodule s = read_submodule(item, texts);
        const auto subslot = static_cast<std::uint16_t>(number_attribute(item, "SubslotNumber", 0x9FFF));
        s.fixed_in_subslots.ranges.emplace_back(subslot, subslot);
        dap.submodules.push_back(std::move(s));
      });
    }
  }
  dap.useable = read_refs(child(e, "UseableModules"), "ModuleItemRef", "ModuleItemTarget", "AllowedInSlots",
                          "FixedInSlots", 0x7FFF);
  return dap;
}

Texts read_texts(const xml::XMLElement& application) {
  Texts texts;
  const xml::XMLElement* list = child(application, "ExternalTextList");
  const xml::XMLElement* primary = list ? child(*list, "PrimaryLanguage") : nullptr;
  if (primary == nullptr) return texts;
  for_each_child(*primary, "Text", [&](const xml::XMLElement& t) {
    const char* id = t.Attribute("TextId");
    const char* value = t.Attribute("Value");
    if (id != nullptr && value != nullptr) texts.emplace(id, value);
  });
  return texts;
}

}  // namespace

Device parse(std::string_view text) {
  xml::XMLDocument document;
  if (document.Parse(text.data(), text.size()) != xml::XML_SUCCESS) {
    throw GsdmlError("GSDML line " + std::to_string(document.ErrorLineNum()) + ": not well-formed XML (" +
                     document.ErrorName() + ")");
  }
  const xml::XMLElement* root = document.RootElement();
  if (root == nullptr || local_name(*root) != "ISO15745Profile") {
    throw GsdmlError("GSDML: the root element is not <ISO15745Profile> (is this a GSDML file?)");
  }
  const xml::XMLElement& body = required_child(*root, "ProfileBody");
  Device device;
  const xml::XMLElement& identity = required_child(body, "DeviceIdentity");
  device.vendor_id = static_cast<std::uint16_t>(number_attribute(identity, "VendorID", 0xFFFF));
  device.device_id = static_cast<std::uint16_t>(number_attribute(identity, "DeviceID", 0xFFFF));
  if (const xml::XMLElement* vendor = child(identity, "VendorName")) {
    if (const char* value = vendor->Attribute("Value")) device.vendor_name = value;
  }
  const xml::XMLElement& application = required_child(body, "ApplicationProcess");
  const Texts texts = read_texts(application);
  const xml::XMLElement& daps = required_child(application, "DeviceAccessPointList");
  for_each_child(daps, "DeviceAccessPointItem", [&](const xml::XMLElement& e) {
    device.access_points.push_back(read_access_point(e, texts));
  });
  if (device.access_points.empty()) fail(daps, "no <DeviceAccessPointItem> element");
  if (const xml::XMLElement* modules = child(application, "ModuleList")) {
    for_each_child(*modules, "ModuleItem",
                   [&](const xml::XMLElement& e) { device.modules.push_back(read_module(e, texts)); });
  }
  if (const xml::XMLElement* submodules = child(application, "SubmoduleList")) {
    for_each_child(*submodules, "SubmoduleItem", [&](const xml::XMLElement& e) {
      Submodule s = read_submodule(e, texts);
      if (s.id.empty()) fail(e, "no ID");
      device.submodules.push_back(std::move(s));
    });
  }
  return device;
}

Device parse_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw GsdmlError(file.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return parse(text.str());
  } catch (const GsdmlError& e) {
    throw GsdmlError(file.string() + ": " + e.what());
  }
}

bool ValueList::contains(std::uint32_t value) const noexcept {
  for (const auto& [low, high] : ranges) {
    if (value >= low && value <= high) return true;
  }
  return false;
}

std::string ValueList::text() const {
  std::string out;
  for (const auto& [low, high] : ranges) {
    if (!out.empty()) out += ' ';
    out += std::to_string(low);
    if (high != low) out += ".." + std::to_string(high);
  }
  return out;
}

}  // namespace tomc::profinet::gsdml
