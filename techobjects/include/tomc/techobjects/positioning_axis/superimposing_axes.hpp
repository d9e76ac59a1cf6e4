#pragma once
// The possible superimposing axes of a positioning or synchronous axis ("Extended parameters > Superimposed
// axes", seed 004 §6.14.3.2): the axes whose setpoints MC_MotionInSuperimposedAxes may add to this axis'
// base motion. Configuration only (spec 04 §11: no data-block variable); held on the heap by the axes that
// have any, so that the others pay 8 bytes (8 KiB per axis TO, decision U10).
#include <array>
#include <cstddef>

#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::techobjects {

struct SuperimposingAxisTable {
  static constexpr std::size_t kCapacity = 8;
  std::array<TechnologyObject*, kCapacity> axes{};  // positioning or synchronous axes, in configured order
  std::size_t count = 0;
};

}  // namespace tomc::techobjects
