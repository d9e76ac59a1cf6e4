#pragma once
// MC_Servo / MC_Interpolator of a group of axes as one TechnologyObject, optionally timed (steady_clock
// around the whole group, so the clock's own cost is paid twice per phase and cycle, not per axis). A
// callgrind workload routes the phases through its counted function: hook(group, clock, 0 servo / 1
// interpolator), which calls run(). A group of followers names their leader as its leading value, so that the
// runtime evaluates the leader first (spec 07 §6.1).
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::bench {

template <typename Axis>
class AxisGroupOf final : public techobjects::TechnologyObject {
 public:
  using Hook = void (*)(AxisGroupOf&, const techobjects::CycleClock&, int phase);

  explicit AxisGroupOf(std::string_view name, techobjects::TechnologyObject* leader = nullptr)
      : name_(name), leader_{{leader}} {}
  std::string_view name() const noexcept override { return name_; }
  std::span<techobjects::TechnologyObject* const> leaders() const noexcept override {
    return {leader_.data(), leader_[0] == nullptr ? 0u : 1u};
  }
  // The runtime attaches the group; each axis gets the runtime's alarm log (a source number of its own) and
  // hands its start values to the runtime's load memory, as if it had been added alone.
  void attach(techobjects::RuntimeServices& services) override {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      techobjects::RuntimeServices own = services;
      own.object_number = services.object_number * 100000u + static_cast<std::uint32_t>(i);
      axes[i]->attach(own);
    }
  }
  void servo(const techobjects::CycleClock& clock) noexcept override { phase(clock, 0); }
  void interpolate(const techobjects::CycleClock& clock) noexcept override { phase(clock, 1); }
  void run(const techobjects::CycleClock& clock, int phase) noexcept {
    if (phase == 0) {
      for (auto& a : axes)
        a->servo(clock);
    } else {
      for (auto& a : axes)
        a->interpolate(clock);
    }
  }

  std::vector<std::unique_ptr<Axis>> axes;
  bool timed = false;
  std::chrono::steady_clock::duration elapsed{};
  Hook hook = nullptr;

 private:
  void phase(const techobjects::CycleClock& clock, int phase) noexcept {
    const auto t0 = timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
    if (hook != nullptr) {
      hook(*this, clock, phase);
    } else {
      run(clock, phase);
    }
    if (timed) elapsed += std::chrono::steady_clock::now() - t0;
  }

  std::string_view name_;
  std::array<techobjects::TechnologyObject*, 1> leader_;
};

}  // namespace tomc::bench
