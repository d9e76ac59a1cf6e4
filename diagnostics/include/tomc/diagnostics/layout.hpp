#pragma once
// The diagnostics pages of the manual (spec 04 §9.1-§9.3, seed 004 ch. 8): per TO type, which indicators and
// values appear in which area of the pages "Status and error bits" and "Motion status". The page "PROFIdrive
// telegram" is built from the configured telegrams (ObjectView::telegram_channels()).
//
// An item's source is a small expression over the TO's data-block paths, resolved once against its
// reflection table:
//   indicator  one or more conditions joined by " | " (OR); a condition is a bit or BOOL path
//   ("StatusWord.X0",
//              "StatusDrive.InOperation"), optionally negated ("!StatusWord.X28"), or a comparison
//              ("StatusSensor[1].State=2");
//   value      one variable path ("Velocity").

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::diagnostics {

struct LayoutItem {
  std::string_view label;
  std::string_view source;
  bool value = false;  // false: an indicator (on/off), true: a number
};

struct LayoutArea {
  std::string_view page;  // "status" (Status and error bits) or "motion" (Motion status)
  std::string_view title;
  std::span<const LayoutItem> items;
};

std::span<const LayoutArea> diagnostics_layout(techobjects::TechnologyObjectType type) noexcept;

// An item resolved against a reflection table: indices into the table, so that a snapshot of the table's
// values (one double per row) evaluates it without any look-up.
struct ResolvedCondition {
  std::size_t variable = 0;
  int bit = -1;  // >= 0: a bit of the word
  bool negate = false;
  bool compare = false;
  double equals = 0.0;
};
struct ResolvedItem {
  std::vector<ResolvedCondition> any_of;  // indicator
  std::size_t variable = 0;               // value
  bool value = false;
  double evaluate(std::span<const double> values) const noexcept;  // indicator: 0/1
};
// nullopt and a message naming the part that does not resolve.
std::optional<ResolvedItem> resolve(const LayoutItem& item, std::span<const techobjects::VariableInfo> table,
                                    std::string* problem = nullptr);

}  // namespace tomc::diagnostics
