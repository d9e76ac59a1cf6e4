// TO_SynchronousAxis: a positioning axis with its synchronous operation in the synchronous slot.
#include "tomc/techobjects/synchronous/synchronous_axis.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace tomc::techobjects {

SynchronousAxis::SynchronousAxis(std::string name, DeviceIo* device, const PositioningAxisData& start_values,
                                 std::vector<LeadingValueInterconnection> leaders,
                                 const DriveConnectionConfig& drive)
    : PositioningAxis(std::move(name), device, start_values, drive),
      operation_(FollowingAxis(*this), this->name(), mark_leaders(std::move(leaders))) {
  attach_synchronous(operation_);
}

std::vector<LeadingValueInterconnection> SynchronousAxis::mark_leaders(
    std::vector<LeadingValueInterconnection> leaders) noexcept {
  for (auto& l : leaders)
    if (l.source != nullptr) l.source->set_possible_leading_value();
  return leaders;
}

void SynchronousAxis::attach(RuntimeServices& services) {
  // Before the start values move to the runtime: a throw leaves nothing attached.
  const auto& leaders = operation_.interconnections();
  for (std::size_t i = 0; i < leaders.size(); ++i) {
    if (leaders[i].coupling != LeadingValueCoupling::kDelayed) continue;
    try {
      leaders[i].source->provide_delayed_leading_value(services.interpolator_cycle_s);
    } catch (const std::invalid_argument& e) {  // named as the machine file's key (decision C26)
      throw std::invalid_argument(std::string(name()) + ".LeadingValueInterconnections[" + std::to_string(i) +
                                  "] (\"Delayed\" to " + std::string(leaders[i].object->name()) +
                                  "): " + e.what());
    }
  }
  PositioningAxis::attach(services);
}

double SynchronousAxis::read(std::string_view path) const noexcept {
  constexpr std::string_view kPrefix = "StatusSynchronizedMotion.";
  return path.starts_with(kPrefix) ? operation_.read(path.substr(kPrefix.size()))
                                   : PositioningAxis::read(path);
}

std::optional<VariableType> SynchronousAxis::synchronized_motion_type(std::string_view path) const noexcept {
  constexpr std::string_view kPrefix = "StatusSynchronizedMotion.";
  if (!path.starts_with(kPrefix)) return std::nullopt;
  const std::string_view m = path.substr(kPrefix.size());
  if (std::isnan(operation_.read(m))) return std::nullopt;
  if (m == "FunctionState" || m == "WaitingFunctionState") return VariableType::kDint;
  if (m == "ActualMaster" || m == "ActualCam") return VariableType::kDbAny;
  if (m == "StatusWord") return VariableType::kDword;
  if (m.starts_with("StatusWord.X")) return VariableType::kBool;
  return VariableType::kLreal;
}

}  // namespace tomc::techobjects
