// The synchronous axis' and the cam's diagnostics views (synchronous_view.hpp).
#include "tomc/diagnostics/synchronous_view.hpp"

#include <array>
#include <vector>

#include "tomc/techobjects/datablocks/positioning_variables.hpp"
#include "tomc/techobjects/datablocks/variable_table_support.hpp"

namespace tomc::diagnostics {

namespace to = tomc::techobjects;

namespace {

using namespace to::detail;

// One row of StatusSynchronizedMotion (spec 07 §1.9): RON status, read from the axis' synchronous operation.
#define TOMC_SYNC_ROW(member, data_type, lo, hi)                                                           \
  TOMC_DB_ROW(to::StatusSynchronizedMotion, kSynchronousAxis, "StatusSynchronizedMotion." #member, member, \
              data_type, kRON, kStatus, lo, hi, kAny, 0)

constexpr double k1e12 = 1.0E12;

// clang-format off
const std::array kSynchronizedMotionRows{
    TOMC_SYNC_ROW(FunctionState, kDint, 0.0, 6.0),
    TOMC_SYNC_ROW(WaitingFunctionState, kDint, 0.0, 6.0),
    TOMC_SYNC_ROW(ActualMaster, kDbAny, 0.0, kWordMax),
    TOMC_SYNC_ROW(ActualCam, kDbAny, 0.0, kWordMax),
    TOMC_SYNC_ROW(PhaseShift, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(Offset, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(MasterOffset, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(MasterScaling, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(SlaveOffset, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(SlaveScaling, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(EffectiveLeadingValue.Position, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(EffectiveLeadingValue.Velocity, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(EffectiveLeadingValue.Acceleration, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(FunctionLeadingValue.Position, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(FunctionFollowingValue.Position, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(FunctionFollowingValue.Velocity, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(FunctionFollowingValue.Acceleration, kLreal, -k1e12, k1e12),
    TOMC_SYNC_ROW(StatusWord, kDword, 0.0, kUdintMax),
};
// clang-format on

#undef TOMC_SYNC_ROW

}  // namespace

std::span<const to::VariableInfo> synchronous_axis_variables() noexcept {
  // Built once: the positioning rows (man. §10.3) and then the synchronous ones, so that every path of the
  // positioning axis keeps its meaning.
  static const std::vector<to::VariableInfo> table = [] {
    std::vector<to::VariableInfo> rows(to::positioning_axis_variables().begin(),
                                       to::positioning_axis_variables().end());
    rows.insert(rows.end(), kSynchronizedMotionRows.begin(), kSynchronizedMotionRows.end());
    return rows;
  }();
  return table;
}

std::string_view function_state_name(std::int32_t state) noexcept {
  // spec 07 §1.9: 0 none, 1 GearIn, 2 GearInPos, 3 CamIn, 4 GearOut, 5 CamOut, 6 GearInVelocity.
  switch (state) {
    case 0:
      return "none";
    case 1:
      return "gearing (MC_GearIn)";
    case 2:
      return "gearing (MC_GearInPos)";
    case 3:
      return "camming (MC_CamIn)";
    case 4:
      return "desynchronizing (MC_GearOut)";
    case 5:
      return "desynchronizing (MC_CamOut)";
    case 6:
      return "velocity gearing (MC_GearInVelocity)";
  }
  return "?";
}

SynchronousAxisView::SynchronousAxisView(const to::SynchronousAxis& axis) : axis_(axis) {
  for (const to::LeadingValueInterconnection& c : axis.interconnections())
    leaders_.emplace_back(c.object != nullptr ? c.object->name() : std::string_view{"?"});
  resolve_telegrams();
}

}  // namespace tomc::diagnostics
