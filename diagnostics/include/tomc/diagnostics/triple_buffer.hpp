#pragma once
// A triple buffer: the cycle writes a whole value into its back buffer and publishes it with one atomic
// exchange; the reader takes the newest published value with another. Neither side waits, and a value is
// never read while it is written (unlike a seqlock, this is free of data races in the C++ memory model).
// Values the reader did not take are overwritten by newer ones. One writer thread, one reader at a time.

#include <array>
#include <atomic>
#include <cstdint>

namespace tomc::diagnostics {

template <typename T>
class TripleBuffer {
 public:
  // ---- set-up ----
  template <typename F>
  void for_each(F&& f) {
    for (T& b : buffers_)
      f(b);
  }

  // ---- writer (the cycle) ----
  T& back() noexcept { return buffers_[back_]; }
  void publish() noexcept {
    back_ = middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel) & kIndex;
  }

  // ---- reader ----
  // True if a newer value was published since the last update(); front() is then the newest.
  bool update() noexcept {
    if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
    front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
    return true;
  }
  const T& front() const noexcept { return buffers_[front_]; }

 private:
  static constexpr std::uint8_t kIndex = 0x3;
  static constexpr std::uint8_t kFresh = 0x4;
  std::array<T, 3> buffers_{};
  std::atomic<std::uint8_t> middle_{1};
  std::uint8_t back_ = 0;   // writer's
  std::uint8_t front_ = 2;  // reader's
};

}  // namespace tomc::diagnostics
