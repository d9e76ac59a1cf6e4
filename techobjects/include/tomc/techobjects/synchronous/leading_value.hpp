#pragma once
// A leading value (spec 07 §1.2–§1.4): what a positioning axis, a synchronous axis or an external encoder
// offers a following synchronous axis, read by the follower in the same MC_Interpolator cycle (the runtime
// runs leaders first). Positions are continuous (no modulo jump); the modulo range is given so that user
// inputs in leader coordinates (MasterSyncPosition) can be mapped onto them. No unit conversion happens
// between leader and follower (spec 07 §1.2).

#include <cstdint>
#include <stdexcept>

namespace tomc::techobjects {

// The type of coupling configured per interconnection (spec 07 §1.2).
enum class LeadingValueCoupling : std::uint8_t {
  kSetpoint,     // the leader's setpoint (spec 07 §1.3)
  kActualValue,  // the leader's extrapolated actual value (spec 07 §1.4)
  kDelayed,      // the leader's setpoint LocalLeadingValueDelayTime ago (spec 07 §1.5; local part only)
};

struct LeadingValue {
  double position = 0.0;  // continuous
  double velocity = 0.0;
  double acceleration = 0.0;
  bool valid = false;                // the source delivers values (actual value: encoder valid)
  bool position_controlled = false;  // the leader runs position-controlled (setpoint coupling needs it)
};

struct ModuloRange {
  bool enabled = false;
  double start = 0.0;
  double length = 360.0;
};

class LeadingValueSource {
 public:
  virtual ~LeadingValueSource() = default;
  virtual LeadingValue leading_value(LeadingValueCoupling coupling) const noexcept = 0;
  virtual ModuloRange leading_value_modulo() const noexcept = 0;
  // A following axis: the leading value its active synchronous job follows (spec 07 §1.2: a leader that
  // follows its own follower would close a loop, 16#8019). nullptr for every other source.
  virtual const LeadingValueSource* followed_leading_value() const noexcept { return nullptr; }
  // Called once by each synchronous axis that has this source among its possible leading values (the
  // interconnection of the configuration, spec 07 §1.3): a positioning axis takes the limit of spec 01 §8.6.
  virtual void set_possible_leading_value() noexcept {}
  // Called at set-up by each synchronous axis that couples "Delayed" to this source (spec 07 §1.5): from then
  // on the source keeps the history its delayed value needs (decision C26). Throws std::invalid_argument for
  // a source that cannot delay its value (an external encoder: not yet) or a delay it cannot hold.
  virtual void provide_delayed_leading_value(double interpolator_cycle_s) {
    (void)interpolator_cycle_s;
    throw std::invalid_argument(
        "this leading value cannot be coupled \"Delayed\" (only a positioning or "
        "synchronous axis can, decision C26)");
  }
};

}  // namespace tomc::techobjects
