// Typed JSON reading with JSON-path problems (json_reader.hpp) and the number formatting of config.hpp.
#include "json_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace tomc::scenario {

void Problems::add(std::string_view path, std::string_view message) {
  std::string line(path);
  line += ": ";
  line += message;
  lines_.push_back(std::move(line));
}

std::string format_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  std::string text(buffer, result.ptr);
  // to_chars writes "1e+13" and "2.5e-05"; users write "1e13" and "2.5e-5".
  if (const auto e = text.find('e'); e != std::string::npos) {
    std::string exponent = text.substr(e + 1);
    const bool negative = !exponent.empty() && exponent.front() == '-';
    if (!exponent.empty() && (exponent.front() == '+' || exponent.front() == '-')) exponent.erase(0, 1);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    text = text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  }
  return text;
}

std::string join_path(std::string_view base, std::string_view key) {
  std::string path(base);
  if (!path.empty() && !key.empty() && key.front() != '[') path += '.';
  path += key;
  return path;
}

namespace detail {

std::string_view type_name(const Json& value) noexcept {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
      return "a number";
    case Json::value_t::binary:
    case Json::value_t::discarded:
      break;
  }
  return "an unsupported value";
}

std::string out_of_range_message(double value, const Range& range) {
  constexpr double kUnbounded = std::numeric_limits<double>::max();
  const std::string v = format_number(value);
  if (range.minimum_exclusive) {
    std::string m = v + " out of range: must be greater than " + format_number(range.minimum);
    if (range.maximum != kUnbounded) m += " and at most " + format_number(range.maximum);
    return m;
  }
  if (range.maximum == kUnbounded)
    return v + " out of range: must be at least " + format_number(range.minimum);
  return v + " out of range " + format_number(range.minimum) + ".." + format_number(range.maximum);
}

std::optional<double> read_number(const Json& value, std::string_view path, Problems& problems) {
  if (!value.is_number()) {
    problems.add(path, "expected a number, got " + std::string(type_name(value)));
    return std::nullopt;
  }
  return value.get<double>();
}

std::optional<std::uint64_t> parse_hex_literal(std::string_view text) noexcept {
  if (text.starts_with("16#")) {
    text.remove_prefix(3);
  } else if (text.starts_with("0x") || text.starts_with("0X")) {
    text.remove_prefix(2);
  } else {
    return std::nullopt;
  }
  // TIA writes 16#FFFF_FFFF; the underscores only group digits.
  std::string digits;
  for (char c : text) {
    if (c != '_') digits += c;
  }
  if (digits.empty() || digits.size() > 16) return std::nullopt;
  std::uint64_t result = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), result, 16);
  if (ec != std::errc{} || end != digits.data() + digits.size()) return std::nullopt;
  return result;
}

std::optional<std::int64_t> read_integer(const Json& value, std::string_view path, std::int64_t minimum,
                                         std::int64_t maximum, bool allow_hex, Problems& problems) {
  const std::string range = std::to_string(minimum) + ".." + std::to_string(maximum);
  if (allow_hex && value.is_string()) {
    const auto hex = parse_hex_literal(value.get_ref<const std::string&>());
    if (!hex) {
      problems.add(path, "'" + value.get<std::string>() + "' is not a hex literal such as 16#7 or 0x7");
      return std::nullopt;
    }
    if (*hex > static_cast<std::uint64_t>(maximum) || static_cast<std::int64_t>(*hex) < minimum) {
      problems.add(path, value.get<std::string>() + " out of range " + range);
      return std::nullopt;
    }
    return static_cast<std::int64_t>(*hex);
  }
  if (!value.is_number()) {
    problems.add(path, std::string("expected an integer") + (allow_hex ? " or a 16#... literal" : "") +
                           ", got " + std::string(type_name(value)));
    return std::nullopt;
  }
  if (value.is_number_unsigned()) {
    const auto u = value.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(maximum) || static_cast<std::int64_t>(u) < minimum) {
      problems.add(path, std::to_string(u) + " out of range " + range);
      return std::nullopt;
    }
    return static_cast<std::int64_t>(u);
  }
  if (value.is_number_integer()) {
    const auto i = value.get<std::int64_t>();
    if (i < minimum || i > maximum) {
      problems.add(path, std::to_string(i) + " out of range " + range);
      return std::nullopt;
    }
    return i;
  }
  const double d = value.get<double>();
  if (std::trunc(d) != d) {
    problems.add(path, format_number(d) + " is not an integer");
    return std::nullopt;
  }
  if (d < static_cast<double>(minimum) || d > static_cast<double>(maximum)) {
    problems.add(path, format_number(d) + " out of range " + range);
    return std::nullopt;
  }
  return static_cast<std::int64_t>(d);
}

std::optional<bool> read_bool(const Json& value, std::string_view path, Problems& problems) {
  if (!value.is_boolean()) {
    problems.add(path, "expected true or false, got " + std::string(type_name(value)));
    return std::nullopt;
  }
  return value.get<bool>();
}

std::optional<std::string> read_string(const Json& value, std::string_view path, Problems& problems) {
  if (!value.is_string()) {
    problems.add(path, "expected a string, got " + std::string(type_name(value)));
    return std::nullopt;
  }
  return value.get<std::string>();
}

std::optional<std::size_t> read_choice(const Json& value, std::string_view path,
                                       const std::vector<std::string_view>& choices, Problems& problems) {
  const auto text = read_string(value, path, problems);
  if (!text) return std::nullopt;
  const auto it = std::find(choices.begin(), choices.end(), *text);
  if (it != choices.end()) return static_cast<std::size_t>(it - choices.begin());
  std::string list;
  for (const auto& c : choices)
    list += (list.empty() ? "" : ", ") + std::string(c);
  problems.add(path, "'" + *text + "' is not one of " + list);
  return std::nullopt;
}

ObjectReader::ObjectReader(const Json& value, std::string path, Problems& problems)
    : path_(std::move(path)), problems_(problems) {
  if (value.is_object()) {
    object_ = &value;
  } else {
    problems_.add(path_, "expected an object, got " + std::string(type_name(value)));
  }
}

bool ObjectReader::has(std::string_view key) const {
  return object_ != nullptr && object_->contains(std::string(key));
}

const Json* ObjectReader::get(std::string_view key, bool required) {
  known_.emplace_back(key);
  if (object_ == nullptr) return nullptr;
  const auto it = object_->find(std::string(key));
  if (it == object_->end()) {
    if (required) problems_.add(path_of(key), "missing");
    return nullptr;
  }
  return &*it;
}

void ObjectReader::real(std::string_view key, double& target, const Range& range, bool required) {
  if (const Json* v = get(key, required)) {
    if (auto d = read_number(*v, path_of(key), problems_)) {
      if (!range.contains(*d)) {
        problems_.add(path_of(key), out_of_range_message(*d, range));
      } else {
        target = *d;
      }
    }
  }
}

void ObjectReader::boolean(std::string_view key, bool& target, bool required) {
  if (const Json* v = get(key, required)) {
    if (auto b = read_bool(*v, path_of(key), problems_)) target = *b;
  }
}

void ObjectReader::optional_real(std::string_view key, std::optional<double>& target) {
  if (const Json* v = get(key)) {
    if (v->is_null()) {
      target.reset();
    } else if (auto d = read_number(*v, path_of(key), problems_)) {
      target = *d;
    }
  }
}

void ObjectReader::finish() {
  if (object_ == nullptr) return;
  for (const auto& [key, value] : object_->items()) {
    if (key == "comment") continue;
    if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
    std::string list;
    for (const auto& k : known_) {
      if (list.find("'" + k + "'") == std::string::npos) list += (list.empty() ? "'" : ", '") + k + "'";
    }
    problems_.add(path_of(key), "unknown key (known here: " + list + ")");
  }
}

}  // namespace detail
}  // namespace tomc::scenario
