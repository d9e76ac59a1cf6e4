#pragma once
// Named bits and bit groups of every control/status word, for tools and diagnostics that show a word as
// named flags (the CLI's JSON, the web page). Single bits have width 1; counters and selectors are wider.

#include <span>
#include <string_view>

#include "tomc/telegrams/control_words.hpp"
#include "tomc/telegrams/signals.hpp"

namespace tomc::telegrams {

struct NamedField {
  std::string_view name;
  BitField field;
};

// Empty for signals that are not words (speeds, counts, ...).
std::span<const NamedField> word_fields(Signal signal) noexcept;

}  // namespace tomc::telegrams
