#pragma once
// The "Delayed" leading value of a leader (spec 07 §1.5, §6.1 item 2): the setpoint the leader gives its
// local followers with coupling type "Delayed", LocalLeadingValueDelayTime in the past, linearly interpolated
// between the two interpolator cycles around it (decision C26). A leader owns one only while a follower
// couples "Delayed" to it: the history is allocated at set-up, sized by the delay, and never resized; the
// cycle writes one sample and reads two.
#include <cstddef>
#include <vector>

#include "tomc/techobjects/motion/profiles.hpp"

namespace tomc::techobjects {

class DelayedLeadingValue {
 public:
  // A delay of at most this many interpolator cycles (C26: cross-PLC delays are a few application cycles per
  // cascade; 1,000 samples of 24 bytes bound the history at 24 KiB).
  static constexpr std::size_t kMaxDelayCycles = 1000;

  // Throws std::invalid_argument (the message names no key: the caller knows which one it read) for a
  // delay that is negative, not finite, or longer than kMaxDelayCycles interpolator cycles, or a cycle time
  // that is not positive.
  DelayedLeadingValue(double delay_s, double interpolator_cycle_s);

  // Once per MC_Interpolator, after the leader's setpoint of this cycle is final. The first call fills the
  // history with it (the leader stood before: no history exists before the first cycle).
  void push(const MotionState& setpoint) noexcept;
  // The setpoint delay_s before the last push, interpolated: (1 − f)·s[k − n] + f·s[k − n − 1] with
  // delay_s = (n + f)·T.
  const MotionState& value() const noexcept { return value_; }

  std::size_t heap_bytes() const noexcept { return history_.capacity() * sizeof(MotionState); }

 private:
  std::vector<MotionState> history_;  // ring of n + 2 samples, newest at newest_
  std::size_t newest_ = 0;
  std::size_t cycles_ = 0;  // n
  double fraction_ = 0.0;   // f
  bool filled_ = false;
  MotionState value_{};
};

}  // namespace tomc::techobjects
