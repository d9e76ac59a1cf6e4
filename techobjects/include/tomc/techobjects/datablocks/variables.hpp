#pragma once
// Reflection of the technology data blocks: one VariableInfo per leaf variable, found by its manual path
// ("DynamicDefaults.Velocity", "Actor.DriveParameter.ReferenceSpeed", "StatusWord"), with the manual's data
// type, access code (spec 04 §0.2), MC_WriteParameter number (spec 04 §0.3) and value range, and an accessor
// that reads and writes the member of the data block as a double (BOOL as 0/1, integers exactly).
//
// Users: the JSON configuration loader (unknown path, wrong type, out of range -> error naming the path:
// find_variable + check_write_access(kConfiguration) + write), the scenario `set` command (user-program
// semantics: check_write_access(kUserProgram)), MC_WriteParameter (find_by_write_parameter) and traces (read,
// find_bit). The type is the same for every TO; each TO type has its own table (speed_axis_variables() for
// TO_SpeedAxis).

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "tomc/techobjects/datablocks/speed_axis_data.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"

namespace tomc::techobjects {

// Elementary data types of the DB variables (spec 04 §0.4). A VREF is reflected as its four members.
enum class VariableType : std::uint8_t {
  kBool,   // BOOL
  kByte,   // BYTE
  kWord,   // WORD
  kDword,  // DWORD
  kInt,    // INT
  kUint,   // UINT
  kDint,   // DINT
  kUdint,  // UDINT
  kDbAny,  // DB_ANY (a DB number)
  kLreal,  // LREAL
};

// The "W" column (spec 04 §0.2, man. §10.1).
enum class Access : std::uint8_t {
  kRON,  // read only for the user program
  kDIR,  // direct: effective at the start of the next MC_Servo
  kCAL,  // on call: sampled when the next job starts (rising Execute edge)
  kRES,  // restart relevant: change the start value; effective after a TO restart
  kDL,   // only at Actor.MotorType (P): changed by download only (spec 04 §14 item 6)
};

// Configuration variables have a start value set by the project (download / JSON config); status variables
// are written by the TO runtime only (spec 04 §2, §4, §5).
enum class VariableRole : std::uint8_t { kConfiguration, kStatus };

// Who writes.
enum class WriteContext : std::uint8_t {
  kConfiguration,  // the project / download (JSON config): the start value of every configuration variable
  kStartValue,     // WRIT_DBL of a start value at runtime (effective after restart): RES, DIR, CAL
  kUserProgram,    // direct assignment by user code at runtime (scenario `set`): DIR and CAL only
};

enum class AccessError : std::uint8_t {
  kNone,
  kStatusVariable,  // a status variable: written by the TO runtime only
  kReadOnly,        // RON (or DL): not writable by the user program, nor as a runtime start value
  kStartValueOnly,  // RES: only its start value can be changed (effective after a TO restart)
};

enum class ValueError : std::uint8_t {
  kNone,
  kNotANumber,      // NaN
  kNotBoolean,      // BOOL needs 0 or 1
  kNotInteger,      // integer types need an integral value
  kOutOfRange,      // outside [minimum, maximum]
  kNotAllowed,      // inside the range but not one of the permitted values (e.g. RemoveEnableReaction 16#2)
  kWrongDataBlock,  // the VariableInfo belongs to another TO type's table
};

struct VariableInfo {
  std::string_view path;  // relative to <TO>, e.g. "Actor.DriveParameter.ReferenceSpeed"
  VariableType type;
  Access access;
  double minimum;  // the manual's range; where it gives none, the data-type limits (spec 04 §0.2)
  double maximum;
  std::span<const double> allowed_values;  // empty: every value in [minimum, maximum] is permitted
  VariableRole role;
  std::uint16_t write_parameter;  // MC_WriteParameter.ParameterNumber (spec 04 §0.3), 0 = none
  TechnologyObjectType owner;     // the data block the accessors work on
  double (*read_fn)(const void* data) noexcept;
  void (*write_fn)(void* data, double value) noexcept;  // unchecked: only with a value check_value() accepted

  // The current value; NaN if `data` is not the data block of `owner`.
  template <typename Data>
  double read(const Data& data) const noexcept {
    if (Data::kTechnologyObjectType != owner) return std::numeric_limits<double>::quiet_NaN();
    return read_fn(&data);
  }
  // Checks the value (check_value) and stores it; on an error the data block is left unchanged. Access rights
  // are the caller's business (check_write_access): the TO runtime and test harnesses may write status
  // variables.
  template <typename Data>
  ValueError write(Data& data, double value) const noexcept;
};

std::string_view to_string(VariableType type) noexcept;  // "LREAL", "DINT", ...
std::string_view to_string(Access access) noexcept;      // "RON", "DIR", ...
std::string_view to_string(AccessError error) noexcept;
std::string_view to_string(ValueError error) noexcept;

constexpr bool is_integer(VariableType type) noexcept {
  return type != VariableType::kBool && type != VariableType::kLreal;
}
// Number of bits of a bit-string type (BYTE, WORD, DWORD), else 0: only these are bit-addressable.
constexpr unsigned bit_width(VariableType type) noexcept {
  switch (type) {
    case VariableType::kByte:
      return 8;
    case VariableType::kWord:
      return 16;
    case VariableType::kDword:
      return 32;
    default:
      return 0;
  }
}

// Whether `value` may be stored in the variable (type, range and permitted values; not access).
ValueError check_value(const VariableInfo& info, double value) noexcept;
// Whether the writer of `context` may write the variable (spec 04 §0.2).
AccessError check_write_access(const VariableInfo& info, WriteContext context) noexcept;

template <typename Data>
ValueError VariableInfo::write(Data& data, double value) const noexcept {
  if (Data::kTechnologyObjectType != owner) return ValueError::kWrongDataBlock;
  const ValueError error = check_value(*this, value);
  if (error == ValueError::kNone) write_fn(&data, value);
  return error;
}

// Exact, case-sensitive lookup of a variable path; nullptr if unknown.
const VariableInfo* find_variable(std::span<const VariableInfo> table, std::string_view path) noexcept;
// The variable MC_WriteParameter writes with `parameter_number`; nullptr if the table has none.
const VariableInfo* find_by_write_parameter(std::span<const VariableInfo> table,
                                            std::uint16_t parameter_number) noexcept;

// ---- bit access "StatusWord.X5" (spec 04 §0.1; the SCL slice "StatusWord.%X5" is equivalent) ----

struct BitPath {
  std::string_view word;  // "StatusWord"
  std::uint8_t bit;       // 5
  friend constexpr bool operator==(const BitPath&, const BitPath&) noexcept = default;
};
// Splits "<word>.X<n>" or "<word>.%X<n>", n = 0...31 in decimal without leading zeros; nullopt otherwise.
// Purely syntactic: whether the word exists and is wide enough is checked by find_bit().
std::optional<BitPath> parse_bit_path(std::string_view path) noexcept;

struct BitReference {
  const VariableInfo* word;  // a BYTE/WORD/DWORD variable of the table
  std::uint8_t bit;          // < bit_width(word->type)

  template <typename Data>
  bool read(const Data& data) const noexcept {
    const double value = word->read(data);
    return !std::isnan(value) &&
           ((static_cast<std::uint32_t>(value) >> bit) & 1u) != 0;  // NaN: wrong data block
  }
  template <typename Data>
  ValueError write(Data& data, bool on) const noexcept {
    const double value = word->read(data);
    if (std::isnan(value)) return ValueError::kWrongDataBlock;
    auto raw = static_cast<std::uint32_t>(value);
    raw = on ? (raw | (std::uint32_t{1} << bit)) : (raw & ~(std::uint32_t{1} << bit));
    return word->write(data, static_cast<double>(raw));
  }
};
// Resolves "<word>.X<n>" against a table: the word must be a bit-string variable and n below its width.
std::optional<BitReference> find_bit(std::span<const VariableInfo> table, std::string_view path) noexcept;

// ---- TO_SpeedAxis (spec 04 §1 column S; man. §10.2) ----

// Every leaf variable of SpeedAxisData, in the order of the manual's chapter 10.2.
std::span<const VariableInfo> speed_axis_variables() noexcept;
const VariableInfo* find_speed_axis_variable(std::string_view path) noexcept;
std::optional<BitReference> find_speed_axis_bit(std::string_view path) noexcept;

}  // namespace tomc::techobjects
