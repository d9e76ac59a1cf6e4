#pragma once
// The newest value of something one thread produces and one other thread consumes, handed over without locks
// and without waiting on either side (a triple buffer, as cactus-rt's realtime_readable_value): the writer
// fills its own slot and publishes it with one atomic exchange; the reader takes the newest published slot
// with one atomic exchange. Neither side ever sees a slot the other is using, a value is never torn, and an
// older value is simply overwritten when the reader is slower than the writer — for cyclic data the newest
// value is the only one that matters.
//
// One producer thread, one consumer thread. T is default-constructed three times at construction; a T that
// owns memory (e.g. a vector sized at set-up) keeps it, so writing and reading never allocate.

#include <array>
#include <atomic>
#include <cstdint>

namespace tomc::drives::dds {

template <typename T>
class LatestValue {
 public:
  LatestValue() = default;
  LatestValue(const LatestValue&) = delete;
  LatestValue& operator=(const LatestValue&) = delete;

  // ---- set-up (no thread uses the buffer yet) ----
  template <typename F>
  void for_each_slot(F&& f) {
    for (auto& s : slots_)
      f(s);
  }

  // ---- producer ----
  T& write_slot() noexcept { return slots_[back_]; }
  // Makes the write slot the newest value; the producer continues in a slot the consumer does not hold.
  void publish() noexcept {
    const std::uint8_t previous =
        middle_.exchange(static_cast<std::uint8_t>(back_ | kNew), std::memory_order_acq_rel);
    back_ = static_cast<std::uint8_t>(previous & kIndex);
  }

  // ---- consumer ----
  // Takes the newest published value if there is one that the consumer has not taken yet; returns whether it
  // did. value() is the consumer's current value either way (default-constructed before the first publish).
  bool take() noexcept {
    if ((middle_.load(std::memory_order_relaxed) & kNew) == 0) return false;
    const std::uint8_t previous = middle_.exchange(front_, std::memory_order_acq_rel);
    front_ = static_cast<std::uint8_t>(previous & kIndex);
    return true;
  }
  const T& value() const noexcept { return slots_[front_]; }
  // Whether a value was published that take() has not taken yet (either thread may ask).
  bool pending() const noexcept { return (middle_.load(std::memory_order_acquire) & kNew) != 0; }

 private:
  static constexpr std::uint8_t kIndex = 0x3;
  static constexpr std::uint8_t kNew = 0x4;
  std::array<T, 3> slots_{};
  std::uint8_t back_ = 0;                // producer only
  std::atomic<std::uint8_t> middle_{1};  // shared: index | kNew
  std::uint8_t front_ = 2;               // consumer only
};

}  // namespace tomc::drives::dds
