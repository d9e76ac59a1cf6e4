#pragma once
// One data-block access mechanism for every TO (issue 14; spec 04 §0.2, §0.3): a user-program write takes
// DIR/CAL variables at once; a start-value write changes the load memory, and a RES value that now differs
// from the work memory waits for MC_Reset Restart with StatusWord.X3 (OnlineStartValuesChanged); a read
// gives any variable or status bit ("StatusWord.X5") as a number, NaN for an unknown path. The TO's own
// consequences of a write (re-configuring a monitor) stay with the TO.
#include <limits>
#include <optional>
#include <string_view>

#include "tomc/techobjects/axis/job_inputs.hpp"
#include "tomc/techobjects/datablocks/status_bits.hpp"
#include "tomc/techobjects/datablocks/variables.hpp"

namespace tomc::techobjects {

// The reflection lookups of one data-block type (variables.hpp, positioning_variables.hpp).
template <typename Data>
struct DataBlockTable {
  const VariableInfo* (*find_variable)(std::string_view path) noexcept;
  std::optional<BitReference> (*find_bit)(std::string_view path) noexcept;

  WriteResult write(Data& work, std::string_view path, double value) const noexcept {
    WriteResult r;
    const VariableInfo* v = find_variable(path);
    if (v == nullptr) return r;
    r.found = true;
    r.access = check_write_access(*v, WriteContext::kUserProgram);
    if (r.access == AccessError::kNone) r.value = v->write(work, value);
    return r;
  }

  WriteResult write_start_value(Data& load, Data& work, std::string_view path, double value) const noexcept {
    WriteResult r;
    const VariableInfo* v = find_variable(path);
    if (v == nullptr) return r;
    r.found = true;
    r.access = check_write_access(*v, WriteContext::kStartValue);
    if (r.access != AccessError::kNone) return r;
    r.value = v->write(load, value);
    if (r.value == ValueError::kNone && v->access == Access::kRES && v->read(load) != v->read(work)) {
      assign(work.StatusWord, StatusWordBit::kOnlineStartValuesChanged, true);
    }
    return r;
  }

  double read(const Data& work, std::string_view path) const noexcept {
    if (const VariableInfo* v = find_variable(path)) return v->read(work);
    if (const auto bit = find_bit(path)) return bit->read(work) ? 1.0 : 0.0;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

}  // namespace tomc::techobjects
