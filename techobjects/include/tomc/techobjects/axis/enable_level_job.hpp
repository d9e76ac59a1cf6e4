#pragma once
// One call of an Enable-level torque instruction (MC_TorqueLimiting, MC_TorqueAdditive, MC_TorqueRange; spec
// 03 L3: no Done, no CommandAborted), the rule the three share (decision F7): Enable FALSE ends the job and
// clears its error; with Enable TRUE `check()` decides on every call (0 = accepted) and `take()` takes the
// inputs; an error stays until Enable goes FALSE.
#include <cstdint>

namespace tomc::techobjects {

template <typename Check, typename Take>
void enable_level_call(bool enable, bool& active, std::uint16_t& error, Check check, Take take) noexcept {
  if (!enable) {
    active = false;
    error = 0;
    return;
  }
  if (error != 0) return;
  error = check();
  active = error == 0;
  if (active) take();
}

}  // namespace tomc::techobjects
