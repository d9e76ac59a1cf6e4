#pragma once
// Internal: typed reading of JSON objects with problems named by their JSON path. One ObjectReader per JSON
// object; every key the caller asks for is "known", finish() reports the keys nobody asked for (typos such as
// "cylces" must not be silently ignored).

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/scenario/config.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::scenario::detail {

// "number", "string", "boolean", "object", "array", "null" — how a user thinks of JSON values.
std::string_view type_name(const Json& value) noexcept;

struct Range {
  double minimum = std::numeric_limits<double>::lowest();
  double maximum = std::numeric_limits<double>::max();
  bool minimum_exclusive = false;  // "greater than" instead of "at least"
  bool contains(double v) const noexcept {
    return (minimum_exclusive ? v > minimum : v >= minimum) && v <= maximum;
  }
};
inline constexpr Range kAnyNumber{};
inline constexpr Range kPositive{0.0, std::numeric_limits<double>::max(), true};
inline constexpr Range kNonNegative{0.0, std::numeric_limits<double>::max(), false};

// "1e13 out of range 0..1e12", "0 out of range: must be greater than 0".
std::string out_of_range_message(double value, const Range& range);

// Reads a JSON number (integers included). nullopt with a problem for anything else.
std::optional<double> read_number(const Json& value, std::string_view path, Problems& problems);
// Reads an integer within [minimum, maximum]: a JSON integer, a float with an integral value, or (allow_hex)
// a "16#1F"/"0x1F" string as PLC programmers write bit strings.
std::optional<std::int64_t> read_integer(const Json& value, std::string_view path, std::int64_t minimum,
                                         std::int64_t maximum, bool allow_hex, Problems& problems);
std::optional<bool> read_bool(const Json& value, std::string_view path, Problems& problems);
std::optional<std::string> read_string(const Json& value, std::string_view path, Problems& problems);
// Parses "16#..." / "0x..." (hex) into a non-negative value; nullopt if the text is not such a literal.
std::optional<std::uint64_t> parse_hex_literal(std::string_view text) noexcept;

// One of `choices`; the problem lists them.
std::optional<std::size_t> read_choice(const Json& value, std::string_view path,
                                       const std::vector<std::string_view>& choices, Problems& problems);

// The JSON value for a data-block variable as a checked double (type, range, permitted values; not access):
// BOOL from true/false, integers from JSON numbers, bit strings also from "16#.."/"0x.." literals, LREAL from
// any number. The configuration loader and the scenario `set` share it so both speak alike.
std::optional<double> read_variable_value(const techobjects::VariableInfo& info, const Json& value,
                                          std::string_view path, Problems& problems);

class ObjectReader {
 public:
  // `value` must be an object; if it is not, a problem is reported and every read does nothing.
  ObjectReader(const Json& value, std::string path, Problems& problems);

  bool valid() const noexcept { return object_ != nullptr; }
  const std::string& path() const noexcept { return path_; }
  std::string path_of(std::string_view key) const { return join_path(path_, key); }
  bool has(std::string_view key) const;
  // Marks `key` as known and returns its value (nullptr if absent). `required` reports a missing key.
  const Json* get(std::string_view key, bool required = false);

  void real(std::string_view key, double& target, const Range& range = kAnyNumber, bool required = false);
  template <typename T>
  void integer(std::string_view key, T& target, std::int64_t minimum, std::int64_t maximum,
               bool allow_hex = false, bool required = false) {
    if (const Json* v = get(key, required)) {
      if (auto i = read_integer(*v, path_of(key), minimum, maximum, allow_hex, problems_)) {
        target = static_cast<T>(*i);
      }
    }
  }
  void boolean(std::string_view key, bool& target, bool required = false);
  // A number, or null for "none".
  void optional_real(std::string_view key, std::optional<double>& target);

  // Reports every key that no get()/real()/... asked for, and lists the known ones. "comment" is always
  // allowed.
  void finish();

 private:
  const Json* object_ = nullptr;
  std::string path_;
  Problems& problems_;
  std::vector<std::string> known_;
};

}  // namespace tomc::scenario::detail
