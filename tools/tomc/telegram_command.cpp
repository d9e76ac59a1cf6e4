// `tomc telegram decode|encode|layout`: the telegram library for commissioning engineers who captured a
// frame (e.g. with Wireshark) or want to build one by hand. JSON in, hex out and back.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_error.hpp"
#include "commands.hpp"
#include "tomc/telegrams/codec.hpp"
#include "tomc/telegrams/drive_state.hpp"
#include "tomc/telegrams/encoder.hpp"
#include "tomc/telegrams/normalisation.hpp"
#include "tomc/telegrams/word_fields.hpp"

namespace tomc::cli {
namespace {

namespace tg = tomc::telegrams;
using Json = nlohmann::ordered_json;

constexpr std::string_view kTelegramUsage =
    "usage:\n"
    "  tomc telegram decode --telegram N --direction setpoint|actual [options] HEX...\n"
    "  tomc telegram encode --telegram N --direction setpoint|actual [options] JSON\n"
    "  tomc telegram layout --telegram N --direction setpoint|actual [options]\n"
    "\n"
    "options:\n"
    "  --byte-order big|little-bytes|swapped-words|little   PZD byte order of the connection (default big)\n"
    "  --reference-speed X    reference speed (p2000) for NSOLL/NIST in physical units\n"
    "  --reference-torque X   reference torque (p2003) for MOMRED and telegram 750\n"
    "  --nist-b-offset 4|8|12 byte offset of NIST_B in telegram 83 (default 12)\n"
    "  --g1-stw W, --g2-stw W the encoder request last sent, to name what G1/G2_XIST2 hold\n"
    "  --pretty               indent the JSON output\n"
    "\n"
    "HEX: the frame bytes in transfer order, spaces/colons allowed (\"04 7F 20 00\" or 047f2000).\n"
    "JSON: an object of signals by name; a value is an integer, a \"0x..\" string, or an object:\n"
    "  words:   {\"value\": 0, \"On\": true, \"SignOfLife\": 5, ...} (named bits, see `decode`)\n"
    "  speeds:  {\"speed\": 1500} (needs --reference-speed) or {\"percent\": 50}\n"
    "  torques: {\"torque\": 2.5} (needs --reference-torque) or {\"percent\": 25}\n"
    "  MOMRED:  {\"reduction_percent\": 25} or {\"torque_limit\": 7.5};  KPC: {\"kv\": 500}\n";

struct Options {
  std::string verb;
  std::optional<int> telegram;
  std::optional<tg::Direction> direction;
  tg::CodecOptions codec;
  std::optional<double> reference_speed;
  std::optional<double> reference_torque;
  std::optional<std::uint16_t> g1_stw;
  std::optional<std::uint16_t> g2_stw;
  bool pretty = false;
  std::vector<std::string_view> operands;
};

std::string in_quotes(std::string_view s) {
  return "'" + std::string(s) + "'";
}

std::optional<long long> parse_integer(std::string_view text) {
  std::string_view digits = text;
  bool negative = false;
  if (!digits.empty() && (digits.front() == '-' || digits.front() == '+')) {
    negative = digits.front() == '-';
    digits.remove_prefix(1);
  }
  int base = 10;
  if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    base = 16;
    digits.remove_prefix(2);
  }
  if (digits.empty()) return std::nullopt;
  unsigned long long magnitude = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude, base);
  if (ec != std::errc{} || end != digits.data() + digits.size() || magnitude > (1ULL << 40))
    return std::nullopt;
  const auto value = static_cast<long long>(magnitude);
  return negative ? -value : value;
}

double parse_positive_number(std::string_view option, std::string_view text) {
  std::string s(text);
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || s.empty() || !std::isfinite(value) || value <= 0.0) {
    throw UsageError(std::string(option) + " needs a positive number, got " + in_quotes(text));
  }
  return value;
}

std::uint16_t parse_word(std::string_view option, std::string_view text) {
  const auto v = parse_integer(text);
  if (!v || *v < 0 || *v > 0xFFFF)
    throw UsageError(std::string(option) + " needs a 16-bit word, got " + in_quotes(text));
  return static_cast<std::uint16_t>(*v);
}

Options parse_options(std::span<const std::string_view> args) {
  if (args.empty())
    throw UsageError("telegram: missing action decode|encode|layout (try: tomc telegram --help)");
  Options o;
  o.verb = std::string(args[0]);
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string_view a = args[i];
    auto value = [&]() -> std::string_view {
      if (i + 1 >= args.size()) throw UsageError(std::string(a) + " needs a value");
      return args[++i];
    };
    if (a == "--telegram") {
      const auto text = value();
      const auto n = parse_integer(text);
      if (!n || *n < 0 || *n > 65535)
        throw UsageError("--telegram needs a telegram number, got " + in_quotes(text));
      o.telegram = static_cast<int>(*n);
    } else if (a == "--direction") {
      const auto text = value();
      o.direction = tg::parse_direction(text);
      if (!o.direction) throw UsageError("--direction must be setpoint or actual, got " + in_quotes(text));
    } else if (a == "--byte-order") {
      const auto text = value();
      const auto order = tg::parse_byte_order(text);
      if (!order)
        throw UsageError("--byte-order must be big, little-bytes, swapped-words or little, got " +
                         in_quotes(text));
      o.codec.byte_order = *order;
    } else if (a == "--reference-speed") {
      o.reference_speed = parse_positive_number(a, value());
    } else if (a == "--reference-torque") {
      o.reference_torque = parse_positive_number(a, value());
    } else if (a == "--nist-b-offset") {
      const auto text = value();
      const auto n = parse_integer(text);
      if (!n || (*n != 4 && *n != 8 && *n != 12))
        throw UsageError("--nist-b-offset must be 4, 8 or 12, got " + in_quotes(text));
      o.codec.telegram83_nist_b_offset = static_cast<std::uint8_t>(*n);
    } else if (a == "--g1-stw") {
      o.g1_stw = parse_word(a, value());
    } else if (a == "--g2-stw") {
      o.g2_stw = parse_word(a, value());
    } else if (a == "--pretty") {
      o.pretty = true;
    } else if (a.size() > 2 && a.substr(0, 2) == "--") {
      throw UsageError("unknown option " + in_quotes(a));
    } else {
      o.operands.push_back(a);
    }
  }
  if (o.verb == "--help" || o.verb == "-h" || o.verb == "help") return o;
  if (!o.telegram) throw UsageError("telegram " + o.verb + ": missing --telegram N");
  if (!o.direction) throw UsageError("telegram " + o.verb + ": missing --direction setpoint|actual");
  return o;
}

tg::TelegramCodec make_codec(const Options& o) {
  auto codec = tg::TelegramCodec::create(*o.telegram, *o.direction, o.codec);
  if (!codec)
    throw UsageError("telegram " + std::to_string(*o.telegram) + ": " +
                     std::string(tg::describe(codec.error())));
  return codec.value();
}

std::vector<std::byte> parse_hex(const std::vector<std::string_view>& parts) {
  std::string digits;
  for (auto part : parts) {
    std::size_t i = 0;
    while (i < part.size()) {
      const char c = part[i];
      if (c == ' ' || c == ':' || c == '-' || c == '\t' || c == ',') {
        ++i;
      } else if (c == '0' && i + 1 < part.size() && (part[i + 1] == 'x' || part[i + 1] == 'X')) {
        i += 2;  // "0x" prefix of a byte or of the whole string
      } else if (std::isxdigit(static_cast<unsigned char>(c))) {
        digits.push_back(c);
        ++i;
      } else {
        throw UsageError("bad hex: unexpected character " + in_quotes(std::string(1, c)));
      }
    }
  }
  if (digits.empty()) throw UsageError("bad hex: no bytes given");
  if (digits.size() % 2 != 0)
    throw UsageError("bad hex: odd number of hex digits (" + std::to_string(digits.size()) + ")");
  std::vector<std::byte> bytes;
  for (std::size_t i = 0; i < digits.size(); i += 2) {
    bytes.push_back(static_cast<std::byte>(std::stoi(digits.substr(i, 2), nullptr, 16)));
  }
  return bytes;
}

std::string to_hex(std::span<const std::byte> bytes) {
  std::string out;
  char buf[4];
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%02X", static_cast<unsigned>(bytes[i]));
    if (i != 0) out.push_back(' ');
    out += buf;
  }
  return out;
}

std::string word_hex(std::uint32_t v, int digits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%0*X", digits, v);
  return buf;
}

bool is_speed(tg::Signal s) {
  return s == tg::Signal::NSOLL_A || s == tg::Signal::NSOLL_B || s == tg::Signal::NIST_A ||
         s == tg::Signal::NIST_B;
}
bool is_torque(tg::Signal s) {
  return s == tg::Signal::M_ADD1 || s == tg::Signal::M_LIMIT_POS || s == tg::Signal::M_LIMIT_NEG ||
         s == tg::Signal::M_ACT;
}

// Wire bits -> signed integer as the signal's type reads it.
long long signed_value(tg::Signal s, std::uint32_t raw) {
  const auto& info = tg::info(s);
  if (tg::raw_minimum(s) < 0) {
    return info.bits == 16 ? static_cast<std::int16_t>(raw) : static_cast<std::int32_t>(raw);
  }
  return raw;
}

double percent_of(tg::Signal s, long long value) {
  return static_cast<double>(value) / (tg::info(s).bits == 16 ? tg::kN2Hundred : tg::kN4Hundred) * 100.0;
}

Json decode_word(tg::Signal s, std::uint32_t raw) {
  Json word;
  word["value"] = raw;
  word["hex"] = word_hex(raw, 4);
  Json bits = Json::object();
  for (const auto& f : tg::word_fields(s)) {
    const auto v = (raw & f.field.mask()) >> f.field.first_bit;
    if (f.field.width == 1) {
      bits[std::string(f.name)] = v != 0;
    } else {
      bits[std::string(f.name)] = v;
    }
  }
  word["bits"] = std::move(bits);
  return word;
}

template <typename Values>
Json decode_json(const Options& o, const tg::TelegramCodec& codec, const Values& values) {
  Json out;
  out["telegram"] = codec.telegram();
  out["direction"] = std::string(tg::to_string(codec.direction()));
  out["byte_order"] = std::string(tg::to_string(codec.byte_order()));
  out["length"] = codec.frame_size();
  Json signals = Json::object();
  Json derived = Json::object();
  for (const auto& f : codec.layout().fields()) {
    const tg::Signal s = f.signal;
    const std::string key(tg::name(s));
    const std::uint32_t raw = values.raw(s);
    if (tg::info(s).kind == tg::SignalKind::kWord) {
      signals[key] = decode_word(s, raw);
      continue;
    }
    const long long v = signed_value(s, raw);
    signals[key] = v;
    Json d = Json::object();
    if (is_speed(s) || is_torque(s)) {
      d["percent"] = percent_of(s, v);
      if (is_speed(s) && o.reference_speed) d["speed"] = percent_of(s, v) / 100.0 * *o.reference_speed;
      if (is_torque(s) && o.reference_torque) d["torque"] = percent_of(s, v) / 100.0 * *o.reference_torque;
    } else if (s == tg::Signal::MOMRED) {
      d["reduction_percent"] = static_cast<double>(raw) / tg::kN2Hundred * 100.0;
      if (o.reference_torque) {
        d["torque_limit"] =
            tg::torque_limit_from_momred(static_cast<std::uint16_t>(raw), *o.reference_torque);
      }
    } else if (s == tg::Signal::KPC) {
      d["kv"] = tg::kv_from_kpc(static_cast<std::int32_t>(raw));
    }
    if (!d.empty()) derived[key] = std::move(d);
  }
  if constexpr (std::is_same_v<Values, tg::ActualSignals>) {
    if (codec.carries(tg::Signal::ZSW1)) {
      const auto status = tg::decode_zsw1(values.ZSW1.value());
      derived["drive_state"] = std::string(tg::to_string(status.state));
      derived["control_requested"] = status.control_requested;
    }
    auto xist2 = [&](tg::Signal zsw, tg::Signal xist, std::optional<std::uint16_t> request, const char* key) {
      if (!codec.carries(zsw) || !codec.carries(xist)) return;
      const tg::EncoderStatusWord status{static_cast<std::uint16_t>(values.raw(zsw))};
      Json d;
      const auto content = tg::xist2_content(tg::EncoderControlWord{request.value_or(0)}, status);
      const bool value_without_request = !request && status.field(tg::kEncoderValuesAvailableField) != 0 &&
                                         !status.test(tg::EncoderStatusBit::kEncoderError);
      d["content"] = value_without_request
                         ? std::string("reference mark or measured value (give the G_STW sent)")
                         : std::string(tg::to_string(content));
      if (content == tg::Xist2Content::kErrorCode) {
        const auto code = tg::encoder_error_code(values.raw(xist));
        d["error_code"] = word_hex(code, 4);
        d["error"] = std::string(tg::describe_encoder_error(code));
      }
      derived[key] = std::move(d);
    };
    xist2(tg::Signal::G1_ZSW, tg::Signal::G1_XIST2, o.g1_stw, "G1_XIST2");
    xist2(tg::Signal::G2_ZSW, tg::Signal::G2_XIST2, o.g2_stw, "G2_XIST2");
  }
  out["signals"] = std::move(signals);
  if (!derived.empty()) out["derived"] = std::move(derived);
  return out;
}

// ---- encode: JSON -> values ----

long long json_integer(const Json& v, const std::string& where) {
  if (v.is_number_integer()) return v.get<long long>();
  if (v.is_number_unsigned()) {
    const auto u = v.get<unsigned long long>();
    if (u > (1ULL << 40)) throw UsageError(where + ": value out of range");
    return static_cast<long long>(u);
  }
  if (v.is_string()) {
    const auto text = v.get<std::string>();
    if (const auto n = parse_integer(text)) return *n;
    throw UsageError(where + ": not an integer: " + in_quotes(text));
  }
  if (v.is_boolean()) return v.get<bool>() ? 1 : 0;
  throw UsageError(where + ": expected an integer or a \"0x..\" string");
}

double json_number(const Json& v, const std::string& where) {
  if (!v.is_number()) throw UsageError(where + ": expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw UsageError(where + ": expected a finite number");
  return d;
}

std::uint32_t checked_raw(tg::Signal s, long long value, const std::string& where) {
  if (value < tg::raw_minimum(s) || value > tg::raw_maximum(s)) {
    throw UsageError(where + ": value " + std::to_string(value) + " out of range " +
                     std::to_string(tg::raw_minimum(s)) + ".." + std::to_string(tg::raw_maximum(s)));
  }
  return static_cast<std::uint32_t>(value);
}

std::uint32_t word_from_object(tg::Signal s, const Json& obj, const std::string& where) {
  std::uint32_t word = 0;
  if (const auto it = obj.find("value"); it != obj.end())
    word = checked_raw(s, json_integer(*it, where + ".value"), where + ".value");
  for (const auto& item : obj.items()) {
    const std::string key = item.key();
    const Json& v = item.value();
    if (key == "value" || key == "hex") continue;
    const auto fields = tg::word_fields(s);
    const auto f =
        std::find_if(fields.begin(), fields.end(), [&](const tg::NamedField& nf) { return nf.name == key; });
    if (f == fields.end())
      throw UsageError(where + ": unknown bit " + in_quotes(key) + " of " + std::string(tg::name(s)));
    const long long max = (1LL << f->field.width) - 1;
    const long long n = json_integer(v, where + "." + key);
    if (n < 0 || n > max)
      throw UsageError(where + "." + key + ": value " + std::to_string(n) + " out of range 0.." +
                       std::to_string(max));
    word = (word & ~static_cast<std::uint32_t>(f->field.mask())) |
           (static_cast<std::uint32_t>(n) << f->field.first_bit);
  }
  return word;
}

std::uint32_t physical_to_raw(const Options& o, tg::Signal s, const Json& obj, const std::string& where) {
  if (obj.size() != 1)
    throw UsageError(where + ": give exactly one of the physical forms (see tomc telegram --help)");
  const auto first = obj.begin();
  const std::string key = first.key();
  const Json& v = first.value();
  const double x = json_number(v, where + "." + key);
  const bool n2 = tg::info(s).bits == 16;
  auto from_percent = [&](double percent) -> std::uint32_t {
    return n2 ? static_cast<std::uint16_t>(tg::speed_to_n2(percent, 100.0))
              : static_cast<std::uint32_t>(tg::speed_to_n4(percent, 100.0));
  };
  if ((is_speed(s) || is_torque(s)) && key == "percent") return from_percent(x);
  if (is_speed(s) && key == "speed") {
    if (!o.reference_speed) throw UsageError(where + ".speed needs --reference-speed");
    return from_percent(x / *o.reference_speed * 100.0);
  }
  if (is_torque(s) && key == "torque") {
    if (!o.reference_torque) throw UsageError(where + ".torque needs --reference-torque");
    return from_percent(x / *o.reference_torque * 100.0);
  }
  if (s == tg::Signal::MOMRED && key == "reduction_percent") {
    if (x < 0.0 || x > 100.0) throw UsageError(where + ".reduction_percent must be 0..100");
    return tg::momred_from_reduction_percent(x);
  }
  if (s == tg::Signal::MOMRED && key == "torque_limit") {
    if (!o.reference_torque) throw UsageError(where + ".torque_limit needs --reference-torque");
    if (x < 0.0 || x > *o.reference_torque)
      throw UsageError(where + ".torque_limit must be 0..reference torque");
    return tg::momred_from_torque_limit(x, *o.reference_torque);
  }
  if (s == tg::Signal::KPC && key == "kv") {
    if (x < 0.0 || x * 1000.0 > static_cast<double>(INT32_MAX)) throw UsageError(where + ".kv out of range");
    return static_cast<std::uint32_t>(tg::kpc_from_kv(x));
  }
  throw UsageError(where + ": " + in_quotes(key) + " is not a physical form of " + std::string(tg::name(s)));
}

template <typename Values>
Values values_from_json(const Options& o, const tg::TelegramCodec& codec, const Json& input) {
  if (!input.is_object()) throw UsageError("JSON: expected an object of signals by name");
  Values values;
  for (const auto& [key, v] : input.items()) {
    const auto signal = tg::parse_signal(key);
    const std::string where = "JSON ." + key;
    if (!signal) throw UsageError(where + ": unknown signal name");
    if (!codec.carries(*signal)) {
      throw UsageError(where + ": not a signal of telegram " + std::to_string(codec.telegram()) + " " +
                       std::string(tg::to_string(codec.direction())));
    }
    std::uint32_t raw = 0;
    if (v.is_object()) {
      raw = tg::info(*signal).kind == tg::SignalKind::kWord ? word_from_object(*signal, v, where)
                                                            : physical_to_raw(o, *signal, v, where);
    } else {
      raw = checked_raw(*signal, json_integer(v, where), where);
    }
    values.set_raw(*signal, raw);
  }
  return values;
}

std::string dump(const Json& j, bool pretty) {
  return pretty ? j.dump(2) : j.dump();
}

int decode(const Options& o, std::ostream& out) {
  const auto codec = make_codec(o);
  const auto bytes = parse_hex(o.operands);
  if (bytes.size() != codec.frame_size()) {
    throw UsageError("telegram " + std::to_string(codec.telegram()) + " " +
                     std::string(tg::to_string(codec.direction())) + " frame is " +
                     std::to_string(codec.frame_size()) + " bytes, got " + std::to_string(bytes.size()));
  }
  if (codec.direction() == tg::Direction::kSetpoint) {
    tg::SetpointSignals values;
    if (codec.decode(bytes, values) != tg::TelegramError::kNone)
      throw UsageError("frame could not be decoded");
    out << dump(decode_json(o, codec, values), o.pretty) << '\n';
  } else {
    tg::ActualSignals values;
    if (codec.decode(bytes, values) != tg::TelegramError::kNone)
      throw UsageError("frame could not be decoded");
    out << dump(decode_json(o, codec, values), o.pretty) << '\n';
  }
  return 0;
}

int encode(const Options& o, std::ostream& out) {
  const auto codec = make_codec(o);
  if (o.operands.size() != 1) throw UsageError("telegram encode: give exactly one JSON object argument");
  Json input;
  try {
    input = Json::parse(o.operands.front());
  } catch (const nlohmann::json::exception& e) {  // also out_of_range.406: a number beyond a double
    throw UsageError(std::string("JSON: ") + e.what());
  }
  std::vector<std::byte> frame(codec.frame_size());
  tg::TelegramError error = tg::TelegramError::kNone;
  if (codec.direction() == tg::Direction::kSetpoint) {
    error = codec.encode(values_from_json<tg::SetpointSignals>(o, codec, input), frame);
  } else {
    error = codec.encode(values_from_json<tg::ActualSignals>(o, codec, input), frame);
  }
  if (error != tg::TelegramError::kNone) throw UsageError(std::string(tg::describe(error)));
  out << to_hex(frame) << '\n';
  return 0;
}

int layout(const Options& o, std::ostream& out) {
  if (!o.operands.empty()) throw UsageError("telegram layout takes no operands");
  const auto codec = make_codec(o);
  Json j;
  j["telegram"] = codec.telegram();
  j["direction"] = std::string(tg::to_string(codec.direction()));
  j["length"] = codec.frame_size();
  Json fields = Json::array();
  for (const auto& f : codec.layout().fields()) {
    Json field;
    field["signal"] = std::string(tg::name(f.signal));
    field["pzd"] = f.offset / 2 + 1;
    field["offset"] = f.offset;
    field["bits"] = tg::info(f.signal).bits;
    fields.push_back(std::move(field));
  }
  j["fields"] = std::move(fields);
  out << dump(j, o.pretty) << '\n';
  return 0;
}

}  // namespace

int telegram_command(std::span<const std::string_view> args, std::ostream& out) {
  const Options o = parse_options(args);
  if (o.verb == "--help" || o.verb == "-h" || o.verb == "help") {
    out << kTelegramUsage;
    return 0;
  }
  if (o.verb == "decode") return decode(o, out);
  if (o.verb == "encode") return encode(o, out);
  if (o.verb == "layout") return layout(o, out);
  throw UsageError("telegram: unknown action " + in_quotes(o.verb) + " (decode, encode or layout)");
}

}  // namespace tomc::cli
