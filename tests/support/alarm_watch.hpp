#pragma once
// The technology alarms a TO raised since the last look, from its alarm log (fixed buffers, no allocation):
// the property tests check which alarms a cycle raised (spec 07 §6.8: none of 501…503 in synchronous travel).
#include <array>
#include <cstddef>
#include <cstdint>

#include "tomc/techobjects/axis/alarms.hpp"

namespace tomc::testing {

struct RaisedAlarms {
  std::array<std::uint32_t, 16> numbers{};
  std::array<std::uint32_t, 16> additional{};
  std::size_t n = 0;
  bool count(std::uint32_t x) const {
    for (std::size_t i = 0; i < n; ++i)
      if (numbers[i] == x) return true;
    return false;
  }
  // Raised with another additional value than `except`.
  bool count_except(std::uint32_t x, std::uint32_t except) const {
    for (std::size_t i = 0; i < n; ++i)
      if (numbers[i] == x && additional[i] != except) return true;
    return false;
  }
};

class AlarmWatch {
 public:
  // The alarms raised since the last call; `seen(event)` for each (e.g. to note it for a failure's printout).
  template <typename Seen>
  RaisedAlarms take(const techobjects::AlarmList& alarms, Seen&& seen) {
    RaisedAlarms r;
    const std::size_t n = alarms.log().copy_since(sequence_, events_);
    for (std::size_t i = 0; i < n; ++i) {
      sequence_ = events_[i].sequence;
      if (events_[i].kind == techobjects::AlarmEvent::Kind::kRaised && r.n < r.numbers.size()) {
        r.additional[r.n] = events_[i].additional_value;
        r.numbers[r.n++] = events_[i].number;
        seen(events_[i]);
      }
    }
    return r;
  }

 private:
  std::uint64_t sequence_ = 0;
  std::array<techobjects::AlarmEvent, techobjects::AlarmLog::kCapacity> events_{};
};

}  // namespace tomc::testing
